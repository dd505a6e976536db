// @ts-nocheck: three.js and the package come through the import map (see animation.html).
// kli/three running: the same keyframed tumble played linearly by three.js and smoothly by the
// Kuramoto–Lohe chain, with |ω(t)| under each.
import * as THREE from "three";
import initSpline from "kli/spline";
import { smoothInterpolation } from "kli/three";
import { transport, twoAircraft } from "./scene.js";

const status = document.querySelector("#load-status");
const canvas = document.querySelector("#scene");
const time = document.querySelector("#time");
const readout = document.querySelector("#readout");
const play = document.querySelector("#play");

await initSpline();

// Six keys of a tumble (axis, angle), at uneven times, scalar last as three.js keeps them.
const turn = (axis, angle) => new THREE.Quaternion().setFromAxisAngle(new THREE.Vector3(...axis).normalize(), angle);
const keys = [turn([1, 0, 0], 0), turn([1, 0, 0], 1.4), turn([0, 1, 0], 2.2), turn([1, 1, 0], 0.6), turn([0, 0, 1], 2.6), turn([1, 0, 1], 0.2)];
const times = [0, 1, 1.6, 3, 3.6, 5];
const linear = new THREE.QuaternionKeyframeTrack(".quaternion", times, keys.flatMap((k) => k.toArray()));
const smooth = smoothInterpolation(linear);
const end = times[times.length - 1];
time.max = String(end);

const { left, right, renderer, render } = await twoAircraft(canvas, status, 0x7048e8, 0xc2410c);

// One mixer an object, each playing its track; the page sets their time.
const mixers = [[left, linear], [right, smooth]].map(([object, track]) => {
  const mixer = new THREE.AnimationMixer(object);
  mixer.clipAction(new THREE.AnimationClip("tumble", end, [track])).play();
  return mixer;
});

/** |ω(t)| of a track at n + 1 times over [0, end]: 2·angle(q(t + h) q(t)⁻¹)/h from its own
 *  interpolant (three's, or the chain), h = 1 ms. */
function speeds(track, n) {
  const interpolant = track.createInterpolant(new Float64Array(4));
  const at = (t) => new THREE.Quaternion().fromArray(interpolant.evaluate(Math.min(Math.max(t, 0), end)));
  const h = 1e-3;
  return Array.from({ length: n + 1 }, (_, k) => {
    const t = Math.min((end * k) / n, end - h);
    return at(t + h).angleTo(at(t)) / h;
  });
}
const N = 600;
const curves = { linear: speeds(linear, N), smooth: speeds(smooth, N) };
const top = Math.max(...curves.linear, ...curves.smooth) * 1.1;

/** The largest change of |ω| across a key within ±2 ms: how abruptly the turn changes there. */
function jump(track) {
  const interpolant = track.createInterpolant(new Float64Array(4));
  const at = (t) => new THREE.Quaternion().fromArray(interpolant.evaluate(t));
  const h = 1e-3;
  return Math.max(...times.slice(1, -1).map((k) => Math.abs(at(k + 2 * h).angleTo(at(k + h)) - at(k - h).angleTo(at(k - 2 * h))) / h));
}
const jumps = { linear: jump(linear), smooth: jump(smooth) };
document.querySelector("#jumps").textContent = `Across the keys, |ω| changes by up to ${jumps.linear.toFixed(2)} rad/s ` +
  `within 2 ms under three.js's linear track, and by ${jumps.smooth.toFixed(3)} rad/s under the chain.`;

function plot(id, values, colour, t) {
  const speed = document.getElementById(id);
  const ratio = devicePixelRatio;
  const [width, height] = [Math.round(speed.clientWidth * ratio), Math.round(speed.clientHeight * ratio)];
  if (speed.width !== width || speed.height !== height) [speed.width, speed.height] = [width, height];
  const ctx = speed.getContext("2d");
  const x = (s) => 8 * ratio + ((width - 16 * ratio) * s) / end;
  const y = (w) => height - 6 * ratio - ((height - 12 * ratio) * w) / top;
  ctx.clearRect(0, 0, width, height);
  ctx.setLineDash([3 * ratio, 3 * ratio]);
  ctx.strokeStyle = "#868e96";
  ctx.lineWidth = ratio;
  for (const key of times) {
    ctx.beginPath();
    ctx.moveTo(x(key), 0);
    ctx.lineTo(x(key), height);
    ctx.stroke();
  }
  ctx.setLineDash([]);
  // The scale, shared by both plots.
  ctx.fillStyle = "#495057";
  ctx.font = `${12 * ratio}px system-ui, sans-serif`;
  ctx.textBaseline = "top";
  ctx.fillText(`${top.toFixed(1)} rad/s`, 12 * ratio, 4 * ratio);
  ctx.textBaseline = "bottom";
  ctx.fillText("0", 12 * ratio, height - 2 * ratio);
  ctx.strokeStyle = colour;
  ctx.lineWidth = 2 * ratio;
  ctx.beginPath();
  values.forEach((w, k) => (k ? ctx.lineTo : ctx.moveTo).call(ctx, x((end * k) / N), y(w)));
  ctx.stroke();
  ctx.fillStyle = "#212529";
  ctx.beginPath();
  ctx.arc(x(t), y(values[Math.round((t / end) * N)]), 4 * ratio, 0, 2 * Math.PI);
  ctx.fill();
}

const clock = transport(play, time);

function frame(now) {
  const t = clock.advance(now, end);
  for (const mixer of mixers) mixer.setTime(t);
  render();
  plot("linear-speed", curves.linear, "#7048e8", t);
  plot("smooth-speed", curves.smooth, "#c2410c", t);
  readout.textContent = `t = ${t.toFixed(2)} s of ${end.toFixed(2)}`;
}

renderer.setAnimationLoop(frame);
status.hidden = true;
