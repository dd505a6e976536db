// @ts-nocheck: three.js and the package come through the import map (see three.html).
// The README's three.js example, running: kli turns two objects of a three.js scene.
import * as THREE from "three";
import init, { kli, kliExact, slerp } from "kli";
import { transport, twoAircraft } from "./scene.js";

const status = document.querySelector("#load-status");
const canvas = document.querySelector("#scene");
const time = document.querySelector("#time");
const readout = document.querySelector("#readout");
const rotation = document.querySelector("#rotation");
const play = document.querySelector("#play");

await init();
const order = "xyzw";
const p = new THREE.Quaternion(0, 0, 1, 0);
const r = new THREE.Quaternion(0.5, 0.5, 0.5, 0.5);
const T = kli(p, r).finalTime;
time.max = String(T);

const { left: kliMesh, right: slerpMesh, renderer, render } = await twoAircraft(canvas, status, 0xc2410c, 0x7048e8);

const clock = transport(play, time);
const fmt = (q) => `(${q.toArray().map((c) => c.toFixed(4)).join(", ")})`;

function frame(now) {
  const t = clock.advance(now, T);
  kliMesh.quaternion.fromArray(kliExact(p, r, t, { order }));
  slerpMesh.quaternion.fromArray(slerp(p, r, t / T, { order }));
  render();
  readout.textContent = `t = ${t.toFixed(2)} / T = ${T.toFixed(2)}`;
  if (!clock.playing) {
    rotation.textContent = `At t = ${t.toFixed(2)}: KLI [x, y, z, w] = ${fmt(kliMesh.quaternion)}; SLERP ${fmt(slerpMesh.quaternion)}.`;
  }
}

renderer.setAnimationLoop(frame);
status.hidden = true;
