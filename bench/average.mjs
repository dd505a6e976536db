// kli/average against SciPy, in one run: the chordal mean of 10⁶ noisy quaternions (random
// signs) in wasm under Node and SciPy's Rotation.from_quat(q).mean() on the same data (SciPy in
// the bench's own virtual environment, bench/python.mjs); the median of 10⁵; and MATH.md's
// robustness table reproduced (100 measurements, Gaussian noise of 5° about each axis, a share
// replaced by uniform random rotations, the median over 20 seeded sets of the angle to the truth).
//   node bench/average.mjs [n] [rounds]
import { median, record } from "./targets.mjs";
import { readFileSync, writeFileSync, mkdirSync } from "node:fs";
import { cpus } from "node:os";
import { runPython, SCIPY } from "./python.mjs";

const root = new URL("../", import.meta.url).pathname;
const n = Number(process.argv[2] ?? 1e6);
const rounds = Number(process.argv[3] ?? 7);
const average = await import(`${root}pkg/average.js`);
average.initSync({ module: readFileSync(`${root}pkg/average_bg.wasm`) });
const { averageRotations } = average;

// xorshift32 and Box–Muller: the same data on every run.
let seed = 2026;
const uniform = () => {
  seed ^= seed << 13; seed ^= seed >>> 17; seed ^= seed << 5; seed >>>= 0;
  return (seed + 0.5) / 4294967296;
};
const gaussian = () => Math.sqrt(-2 * Math.log(uniform())) * Math.cos(2 * Math.PI * uniform());
const normalise = (q) => { const l = Math.hypot(...q); return q.map((c) => c / l); };
const randomRotation = () => normalise([gaussian(), gaussian(), gaussian(), gaussian()]);
/** q · exp(v) for the rotation vector v (radians), [w, x, y, z]. */
const turned = ([w, x, y, z], v) => {
  const angle = Math.hypot(...v);
  if (angle === 0) return [w, x, y, z];
  const s = Math.sin(angle / 2) / angle, c = Math.cos(angle / 2);
  const [a, b, d] = v.map((e) => e * s);
  return [w * c - x * a - y * b - z * d, w * a + x * c + y * d - z * b, w * b - x * d + y * c + z * a, w * d + x * b - y * a + z * c];
};
/** `count` measurements of `truth`: Gaussian noise of `sigma` radians about each axis, a share `outliers` random, random signs. */
const measurements = (truth, count, sigma, outliers) => Array.from({ length: count }, () => {
  const q = uniform() < outliers ? randomRotation() : turned(truth, [gaussian() * sigma, gaussian() * sigma, gaussian() * sigma]);
  return uniform() < 0.5 ? q.map((c) => -c) : q;
});
/** The rotation angle between a and b, degrees: 4 atan2(|a − b|, |a + b|) of the closer sign. */
const angleBetween = (a, b) => {
  const sign = a.reduce((s, c, k) => s + c * b[k], 0) < 0 ? -1 : 1;
  const minus = Math.hypot(...a.map((c, k) => c - sign * b[k])), plus = Math.hypot(...a.map((c, k) => c + sign * b[k]));
  return (4 * Math.atan2(minus, plus) * 180) / Math.PI;
};

// The chordal mean of n, against SciPy on the same bytes.
const truth = randomRotation();
const data = new Float64Array(measurements(truth, n, (5 * Math.PI) / 180, 0.1).flat());
mkdirSync(`${root}target`, { recursive: true });
const file = `${root}target/bench-average.bin`;
writeFileSync(file, Buffer.from(data.buffer));
const wasmTimes = [];
let ours;
for (let k = 0; k < rounds; k++) {
  const start = performance.now();
  ours = averageRotations(data).rotation;
  wasmTimes.push(performance.now() - start);
}
const scipy = JSON.parse(runPython("scipy_mean.py", { path: file, n, rounds }).toString());
const wasmMs = median(wasmTimes);
console.log(`Averaging, Node ${process.version}, SciPy ${SCIPY}, ${cpus()[0].model}:`);
console.log("| what | median ms | against SciPy |");
console.log("| --- | ---: | ---: |");
console.log(`| kli/average chordal mean of ${n.toLocaleString("en")} (wasm, Float64Array in) | ${wasmMs.toFixed(1)} | ${(scipy.ms / wasmMs).toFixed(2)}× faster |`);
console.log(`| SciPy Rotation.from_quat(q).mean(), same data | ${scipy.ms.toFixed(1)} | 1 |`);
const medianData = data.subarray(0, 4 * Math.min(n, 1e5));
const medianTimes = [];
let medianResult;
for (let k = 0; k < rounds; k++) {
  const start = performance.now();
  medianResult = averageRotations(medianData, { method: "median" });
  medianTimes.push(performance.now() - start);
}
console.log(`| kli/average median of ${(medianData.length / 4).toLocaleString("en")} (${medianResult.iterations} Weiszfeld steps) | ${median(medianTimes).toFixed(1)} | |`);
console.log(`The two chordal means agree to ${angleBetween(ours, scipy.mean).toExponential(1)}°; ` +
  `targets: faster than SciPy: ${wasmMs < scipy.ms ? "met" : "MISSED"}; the median of 10⁵ ≤ 300 ms: ${median(medianTimes) <= 300 ? "met" : "MISSED"}.`);

record(`the chordal mean of ${n.toLocaleString("en")} faster than SciPy's \`Rotation.from_quat(q).mean()\``, `${wasmMs.toFixed(1)} ms`,
  `SciPy ${SCIPY}: ${scipy.ms.toFixed(1)} ms`, wasmMs < scipy.ms);
record("the median of 10⁵ rotations ≤ 300 ms", `${median(medianTimes).toFixed(1)} ms`, "", median(medianTimes) <= 300);

// MATH.md's robustness table.
console.log("\nRobustness: 100 measurements, 5° of noise about each axis, random signs; median over 20 sets of the angle to the truth, degrees:");
console.log("| outliers | chordal | quaternion | geodesic (Karcher) | median |");
console.log("| ---: | ---: | ---: | ---: | ---: |");
for (const share of [0, 0.1, 0.3, 0.5]) {
  const errors = { chordal: [], quaternion: [], geodesic: [], median: [] };
  for (let set = 0; set < 20; set++) {
    const t = randomRotation();
    const q = new Float64Array(measurements(t, 100, (5 * Math.PI) / 180, share).flat());
    for (const method of Object.keys(errors)) errors[method].push(angleBetween(averageRotations(q, { method }).rotation, t));
  }
  console.log(`| ${share * 100}% | ${Object.values(errors).map((e) => median(e).toFixed(2)).join(" | ")} |`);
}
