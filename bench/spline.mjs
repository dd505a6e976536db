// The spline benchmark (issue 8's targets): how much the chain's smooth end bends against Squad
// (∫|ω̇|², measured from samples), the solve time for 10 keys, and the throughput of `.sample`
// against gl-matrix's quat.sqlerp (helper points computed once) and three.js's
// QuaternionKeyframeTrack interpolant, on the same keys.
//   node bench/spline.mjs [rounds]
import { median, record } from "./targets.mjs";
import { readFileSync } from "node:fs";
import { performance } from "node:perf_hooks";
import { QuaternionKeyframeTrack } from "three";
import { quat } from "gl-matrix";
import { initSync, kliSpline, slerpSpline, squadSpline } from "../pkg/spline.js";
import { bending, grid, randomKeys, uniform } from "./measures.mjs";
import { load, previous } from "./previous.mjs";

const release = previous()[0];
const old = await load(release.dir, "spline");

initSync({ module: readFileSync(new URL("../pkg/spline_bg.wasm", import.meta.url)) });
const rounds = Number(process.argv[2] ?? 9);

/** ∫|ω̇|² of a curve from 256 samples a unit of time (bench/measures.mjs). */
function bendingOf(curve) {
  const [start, end] = [curve.startTime, curve.endTime];
  const times = grid(start, end, Math.round((end - start) * 256));
  return bending(curve.sample(times), times[1] - times[0]);
}

// 1. The smooth end against Squad: 20 random sets of 6 keys, up to 120° apart, even times.
const ratios = [];
let worstKey = 0;
for (let set = 0; set < 20; set++) {
  const keys = randomKeys(6, 120);
  const [chain, squad] = [kliSpline(keys), squadSpline(keys)];
  ratios.push(bendingOf(chain) / bendingOf(squad));
  const used = chain.keys;
  for (let i = 0; i < 6; i++) {
    const q = chain.at(i);
    for (let c = 0; c < 4; c++) worstKey = Math.max(worstKey, Math.abs(q[c] - used[4 * i + c]));
  }
  chain.free(); squad.free();
}
const mean = ratios.reduce((a, b) => a + b, 0) / ratios.length;
console.log(`∫|ω̇|² of kliSpline (smoothness 1) / Squad's, 20 sets of 6 keys: mean ${mean.toFixed(3)} ` +
  `(${Math.min(...ratios).toFixed(3)}–${Math.max(...ratios).toFixed(3)}; target ≤ 0.85); keys hit to ${worstKey.toExponential(1)}`);
record("the chain's `∫|ω̇|²` ≤ 0.85 of Squad's", mean.toFixed(3), "Squad: 1", mean <= 0.85);

// 2. The solve: 10 keys at the default density (32 samples a segment), alternating with the
// previous release's (its C¹ evaluation needed no solve of its own).
const ten = randomKeys(10, 120);
const solves = { current: [], old: [] }, iterations = [];
let residual = 0;
for (let k = 0; k < 50; k++) {
  for (const [who, module] of [["current", { kliSpline }], ["old", old]]) {
    const start = performance.now();
    const spline = module.kliSpline(ten);
    solves[who].push(performance.now() - start);
    if (who === "current") {
      residual = Math.max(residual, spline.residual);
      iterations.push(spline.iterations);
    }
    spline.free();
  }
}
console.log(`kliSpline of 10 keys: median ${median(solves.current).toFixed(2)} ms per solve (${iterations[0]} Newton steps, ` +
  `residual ≤ ${residual.toExponential(1)}; target ≤ 2 ms, ≤ 1e-10); ${release.name} ${release.commit}: ${median(solves.old).toFixed(2)} ms`);
record("solve 10 keys ≤ 2 ms, residual ≤ 1e-10", `${median(solves.current).toFixed(2)} ms, ${residual.toExponential(1)}`,
  `${release.name}: ${median(solves.old).toFixed(2)} ms`, median(solves.current) <= 2 && residual <= 1e-10);

// 3. .sample of 10⁶ times on the same 10 keys, against gl-matrix's sqlerp and three.js.
const n = 1e6;
const times = Float64Array.from({ length: n }, () => 9 * uniform());
const out = new Float64Array(4 * n);
const xyzw = ten.map(([w, x, y, z]) => [x, y, z, w]);
// Shoemake's helper points (even times) for gl-matrix: a_i = q_i exp(−(log(q_i⁻¹q_{i+1}) + log(q_i⁻¹q_{i−1}))/4).
const helpers = xyzw.map((q, i) => {
  if (i === 0 || i === xyzw.length - 1) return quat.clone(q);
  const inverse = quat.invert(quat.create(), q);
  const log = (other) => quat.ln(quat.create(), quat.multiply(quat.create(), inverse, other));
  const [a, b] = [log(xyzw[i + 1]), log(xyzw[i - 1])];
  const sum = quat.scale(quat.create(), quat.add(quat.create(), a, b), -0.25);
  return quat.multiply(quat.create(), q, quat.exp(quat.create(), sum));
});
const glOut = quat.create();
const track = new QuaternionKeyframeTrack(".quaternion", [0, 1, 2, 3, 4, 5, 6, 7, 8, 9], xyzw.flat());
const interpolant = track.createInterpolant();
const curves = { kli: kliSpline(ten), old: old.kliSpline(ten), squad: squadSpline(ten), slerp: slerpSpline(ten) };
const methods = {
  "kliSpline .sample (wasm)": () => curves.kli.sample(times, out),
  [`kliSpline .sample, ${release.name} ${release.commit}`]: () => curves.old.sample(times, out),
  "squadSpline .sample (wasm)": () => curves.squad.sample(times, out),
  "slerpSpline .sample (wasm)": () => curves.slerp.sample(times, out),
  "gl-matrix quat.sqlerp (helpers once)": () => {
    for (let k = 0; k < n; k++) {
      const t = times[k], i = Math.min(Math.floor(t), 8);
      quat.sqlerp(glOut, xyzw[i], helpers[i], helpers[i + 1], xyzw[i + 1], t - i);
      out[4 * k] = glOut[3];
    }
  },
  "three.js QuaternionKeyframeTrack interpolant": () => {
    for (let k = 0; k < n; k++) out[4 * k] = interpolant.evaluate(times[k])[3];
  },
};
const results = Object.fromEntries(Object.keys(methods).map((name) => [name, []]));
for (let round = 0; round < rounds; round++) {
  for (const [name, run] of Object.entries(methods)) {
    const start = performance.now();
    run();
    results[name].push(performance.now() - start);
  }
}
console.log(`\n.sample of 10⁶ random times on 10 keys, median of ${rounds} alternating rounds, Node ${process.version}:`);
console.log("| method | ms | ns per time |");
console.log("| --- | ---: | ---: |");
for (const [name, times] of Object.entries(results)) {
  console.log(`| ${name} | ${median(times).toFixed(1)} | ${(median(times) * 1e6 / n).toFixed(1)} |`);
}
const perTime = (name) => (median(results[name]) * 1e6) / n;
const [ours, glMatrix, before] = ["kliSpline .sample (wasm)", "gl-matrix quat.sqlerp (helpers once)", `kliSpline .sample, ${release.name} ${release.commit}`].map(perTime);
record("`.sample` at least as fast as gl-matrix's `sqlerp`", `${ours.toFixed(1)} ns a time`,
  `gl-matrix ${glMatrix.toFixed(1)}; ${release.name} ${before.toFixed(1)}`, ours <= glMatrix);
