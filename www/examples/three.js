// @ts-nocheck: three.js and the package come through the import map (see three.html).
// The README's three.js example, running: kli turns two objects of a three.js scene.
import * as THREE from "three";
import init, { kli, kliExact, slerp } from "kli";

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

/** An aircraft of boxes: nose along x, red port wing along y, fin along z (as on the demo page). */
function aircraft(colour) {
  const group = new THREE.Group();
  const part = (size, position, color) => {
    const mesh = new THREE.Mesh(new THREE.BoxGeometry(...size), new THREE.MeshLambertMaterial({ color }));
    mesh.position.set(...position);
    group.add(mesh);
  };
  part([2.4, 0.36, 0.36], [0, 0, 0], colour);
  part([0.5, 1.2, 0.08], [0.1, 0.75, 0], 0xc92a2a);
  part([0.5, 1.2, 0.08], [0.1, -0.75, 0], colour);
  part([0.35, 0.08, 0.6], [-1.0, 0, 0.4], 0x1971c2);
  part([0.3, 0.3, 0.3], [1.35, 0, 0], 0x343a40);
  return group;
}

const scene = new THREE.Scene();
scene.background = new THREE.Color(0xffffff);
scene.add(new THREE.AmbientLight(0xffffff, 1.6));
const sun = new THREE.DirectionalLight(0xffffff, 2.2);
sun.position.set(3, -4, 6);
scene.add(sun);
const kliMesh = aircraft(0xc2410c);
const slerpMesh = aircraft(0x7048e8);
kliMesh.position.x = -1.9;
slerpMesh.position.x = 1.9;
scene.add(kliMesh, slerpMesh);
// z up, seen from the front right, as the demo page's object view.
const camera = new THREE.PerspectiveCamera(35, 2, 0.1, 100);
camera.up.set(0, 0, 1);
camera.position.set(3, -9, 4);
camera.lookAt(0, 0, 0);

let renderer;
try {
  // preserveDrawingBuffer: the picture stays readable between frames (right-click save, tests).
  renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
} catch (error) {
  status.textContent = `This browser cannot draw WebGL: ${error.message}`;
  throw error;
}

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
  const { clientWidth: width, clientHeight: height } = canvas;
  if (canvas.width !== Math.round(width * devicePixelRatio) || canvas.height !== Math.round(height * devicePixelRatio)) {
    renderer.setPixelRatio(devicePixelRatio);
    renderer.setSize(width, height, false);
    camera.aspect = width / height;
    camera.updateProjectionMatrix();
  }
  renderer.render(scene, camera);
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
