// @ts-nocheck: three.js and the package come through the import map (see three.html).
// The README's three.js example, running: kli turns two objects of a three.js scene.
import * as THREE from "three";
import init, { kli, kliExact, slerp } from "kli";
import { twoAircraft } from "./scene.js";

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

const { left: kliMesh, right: slerpMesh, renderer, render } = twoAircraft(canvas, status, 0xc2410c, 0x7048e8);

let t = 0;
let playing = !matchMedia("(prefers-reduced-motion: reduce)").matches;
let last = performance.now();
const fmt = (q) => `(${q.toArray().map((c) => c.toFixed(4)).join(", ")})`;

function frame(now) {
  if (playing) {
    // A frame may be stamped before the first `last`: never step back.
    t = (t + Math.min(Math.max(now - last, 0), 100) / 1000) % T;
    time.value = String(t);
  }
  last = now;
  kliMesh.quaternion.fromArray(kliExact(p, r, t, { order }));
  slerpMesh.quaternion.fromArray(slerp(p, r, t / T, { order }));
  render();
  readout.textContent = `t = ${t.toFixed(2)} / T = ${T.toFixed(2)}`;
  if (!playing) {
    rotation.textContent = `At t = ${t.toFixed(2)}: KLI [x, y, z, w] = ${fmt(kliMesh.quaternion)}; SLERP ${fmt(slerpMesh.quaternion)}.`;
  }
}

play.addEventListener("click", () => {
  playing = !playing;
  play.textContent = playing ? "Pause" : "Play";
});
time.addEventListener("input", () => {
  playing = false;
  play.textContent = "Play";
  t = Number(time.value);
});
play.textContent = playing ? "Pause" : "Play";
renderer.setAnimationLoop(frame);
status.hidden = true;
