// The batch benchmark: n = 10⁶ random unit pairs and parameters, built once; every method runs
// on the same data, in alternating order, several rounds; the table gives medians and the
// throughput relative to three.js's Quaternion.slerpFlat. Every method's output is checked
// against the others (or an independent formula) before anything is timed. The package as built
// from the references of bench/previous.json (the previous release, the commit before the
// split) runs its batch calls in the same rounds, so a regression shows as a ratio.
//   node bench/batch.mjs [n] [rounds]
import { readFileSync } from "node:fs";
import { cpus } from "node:os";
import { performance } from "node:perf_hooks";
import { Quaternion } from "three";
import { quat } from "gl-matrix";
import { Float64Buffer, initSync, kli, kliExactBatch, kliSample, nlerpBatch, slerpBatch } from "../pkg/kli.js";
import { load, previous } from "./previous.mjs";
import { median, record } from "./targets.mjs";

initSync({ module: readFileSync(new URL("../pkg/kli_bg.wasm", import.meta.url)) });
// Each reference's own module instance.
const references = [];
for (const { name, commit, dir } of previous()) {
  references.push({ name: `${name}, ${commit}`, module: await load(dir, "kli", commit) });
}

const n = Number(process.argv[2] ?? 1e6);
const rounds = Number(process.argv[3] ?? 11);

// xorshift128+: the same data on every run.
let s0 = 0x9e3779b9, s1 = 0x243f6a88;
function uniform() {
  let x = s0, y = s1;
  s0 = y; x ^= x << 23; x ^= x >>> 17; x ^= y ^ (y >>> 26); s1 = x;
  return ((s0 + s1) >>> 0) / 4294967296;
}
function gaussian() {
  return Math.sqrt(-2 * Math.log(1 - uniform())) * Math.cos(2 * Math.PI * uniform());
}

const starts = new Float64Array(4 * n), ends = new Float64Array(4 * n);
const s = new Float64Array(n), t = new Float64Array(n);
for (const array of [starts, ends]) {
  for (let i = 0; i < n; i++) {
    const q = [gaussian(), gaussian(), gaussian(), gaussian()];
    const length = Math.hypot(...q);
    for (let c = 0; c < 4; c++) array[4 * i + c] = q[c] / length;
  }
}
for (let i = 0; i < n; i++) {
  s[i] = uniform();
  t[i] = 12 * uniform();
}
// One path sampled at n even times over [0, 12], as the page's animation does per frame.
const times = Float64Array.from({ length: n }, (_, k) => (12 * k) / (n - 1));
const p0 = [0, 0, 0, 1], r0 = [0.5, 0.5, 0.5, 0.5];

// The KLI clock mapped onto SLERP's parameter, for three.js to follow KLI: s(t) = 1 − φ(t)/φ0.
const warped = new Float64Array(n);
for (let i = 0; i < n; i++) {
  let dot = 0, d = 0, e = 0;
  for (let c = 0; c < 4; c++) dot += starts[4 * i + c] * ends[4 * i + c];
  const sign = dot < 0 ? -1 : 1;
  for (let c = 0; c < 4; c++) {
    d += (starts[4 * i + c] - sign * ends[4 * i + c]) ** 2;
    e += (starts[4 * i + c] + sign * ends[4 * i + c]) ** 2;
  }
  const u0 = Math.sqrt(d / e);
  warped[i] = u0 === 0 ? 1 : 1 - Math.atan(u0 * Math.exp(-t[i])) / Math.atan(u0);
}

// The same data in the module's memory, for the in-place (zero-copy) calls.
const inWasm = {};
for (const [name, array] of Object.entries({ starts, ends, s, t, out: new Float64Array(4 * n) })) {
  inWasm[name] = new Float64Buffer(array.length);
  inWasm[name].view.set(array);
}
const views = () => Object.fromEntries(Object.entries(inWasm).map(([name, buffer]) => [name, buffer.view]));

const outputs = {};
const buffer = (name) => (outputs[name] ??= new Float64Array(4 * n));
const a = new Float64Array(4), b = new Float64Array(4), o = new Float64Array(4);

const methods = {
  "slerpBatch (wasm)": () => slerpBatch(starts, ends, s, buffer("slerpBatch (wasm)")),
  "kliExactBatch (wasm)": () => kliExactBatch(starts, ends, t, buffer("kliExactBatch (wasm)")),
  "kliSample (wasm), one path": () => kliSample(p0, r0, times),
  "nlerpBatch (wasm), baseline": () => nlerpBatch(starts, ends, s, buffer("nlerpBatch (wasm), baseline")),
  "slerpBatch (wasm, in place)": () => { const v = views(); return slerpBatch(v.starts, v.ends, v.s, v.out); },
  "kliExactBatch (wasm, in place)": () => { const v = views(); return kliExactBatch(v.starts, v.ends, v.t, v.out); },
  "nlerpBatch (wasm, in place), baseline": () => { const v = views(); return nlerpBatch(v.starts, v.ends, v.s, v.out); },
  ...Object.fromEntries(references.flatMap(({ name, module }) => [
    [`slerpBatch (${name})`, () => module.slerpBatch(starts, ends, s, buffer(`slerpBatch (${name})`))],
    [`kliExactBatch (${name})`, () => module.kliExactBatch(starts, ends, t, buffer(`kliExactBatch (${name})`))],
  ])),
  "three.js slerpFlat": () => {
    const out = buffer("three.js slerpFlat");
    for (let i = 0; i < n; i++) Quaternion.slerpFlat(out, 4 * i, starts, 4 * i, ends, 4 * i, s[i]);
    return out;
  },
  "gl-matrix quat.slerp": () => {
    const out = buffer("gl-matrix quat.slerp");
    for (let i = 0; i < n; i++) {
      for (let c = 0; c < 4; c++) { a[c] = starts[4 * i + c]; b[c] = ends[4 * i + c]; }
      quat.slerp(o, a, b, s[i]);
      for (let c = 0; c < 4; c++) out[4 * i + c] = o[c];
    }
    return out;
  },
};

// ---- Agreement, before timing ----------------------------------------------------------------
for (const [name, run] of Object.entries(methods)) outputs[name] = run().slice();
const maxDifference = (x, y) => {
  let worst = 0;
  for (let i = 0; i < x.length; i++) worst = Math.max(worst, Math.abs(x[i] - y[i]));
  return worst;
};
const threeKli = new Float64Array(4 * n);
for (let i = 0; i < n; i++) Quaternion.slerpFlat(threeKli, 4 * i, starts, 4 * i, ends, 4 * i, warped[i]);
const nlerpReference = new Float64Array(4 * n);
for (let i = 0; i < n; i++) {
  let dot = 0;
  for (let c = 0; c < 4; c++) dot += starts[4 * i + c] * ends[4 * i + c];
  const sign = dot < 0 ? -1 : 1;
  let length = 0;
  for (let c = 0; c < 4; c++) {
    const q = starts[4 * i + c] + s[i] * (sign * ends[4 * i + c] - starts[4 * i + c]);
    nlerpReference[4 * i + c] = q;
    length += q * q;
  }
  for (let c = 0; c < 4; c++) nlerpReference[4 * i + c] /= Math.sqrt(length);
}
const sampleReference = new Float64Array(4 * n);
{
  const phi0 = Math.PI / 3;
  for (let k = 0; k < n; k++) {
    const phi = 2 * Math.atan(Math.tan(phi0 / 2) * Math.exp(-times[k]));
    for (let c = 0; c < 4; c++) sampleReference[4 * k + c] = (Math.sin(phi) * p0[c] + Math.sin(phi0 - phi) * r0[c]) / Math.sin(phi0);
  }
}
const checks = [
  ["slerpBatch vs three.js slerpFlat", maxDifference(outputs["slerpBatch (wasm)"], outputs["three.js slerpFlat"]), 1e-9],
  ["slerpBatch vs gl-matrix quat.slerp", maxDifference(outputs["slerpBatch (wasm)"], outputs["gl-matrix quat.slerp"]), 1e-6],
  ["kliExactBatch vs three.js slerpFlat at s(t)", maxDifference(outputs["kliExactBatch (wasm)"], threeKli), 1e-9],
  ["kliSample vs the closed form with atan/sin", maxDifference(outputs["kliSample (wasm), one path"], sampleReference), 1e-12],
  ["nlerpBatch vs a plain JS nlerp", maxDifference(outputs["nlerpBatch (wasm), baseline"], nlerpReference), 1e-12],
  ["slerpBatch in place vs copied", maxDifference(outputs["slerpBatch (wasm, in place)"], outputs["slerpBatch (wasm)"]), 0],
  ["kliExactBatch in place vs copied", maxDifference(outputs["kliExactBatch (wasm, in place)"], outputs["kliExactBatch (wasm)"]), 0],
  ["nlerpBatch in place vs copied", maxDifference(outputs["nlerpBatch (wasm, in place), baseline"], outputs["nlerpBatch (wasm), baseline"]), 0],
  ...references.flatMap(({ name }) => [
    [`slerpBatch vs ${name}`, maxDifference(outputs["slerpBatch (wasm)"], outputs[`slerpBatch (${name})`]), 1e-12],
    [`kliExactBatch vs ${name}`, maxDifference(outputs["kliExactBatch (wasm)"], outputs[`kliExactBatch (${name})`]), 1e-12],
  ]),
];
console.log(`Agreement on ${n.toLocaleString("en")} pairs (max |difference| of a component):`);
let agreed = true;
for (const [what, difference, bound] of checks) {
  const ok = difference <= bound;
  agreed &&= ok;
  console.log(`  ${ok ? "ok  " : "FAIL"} ${what}: ${difference.toExponential(1)} (bound ${bound})`);
}

// ---- Timing ----------------------------------------------------------------------------------
const names = Object.keys(methods);
const samples = Object.fromEntries(names.map((name) => [name, []]));
for (let round = 0; round < rounds; round++) {
  // Rotate the order each round so no method always runs first or after the same neighbour.
  for (let k = 0; k < names.length; k++) {
    const name = names[(k + round) % names.length];
    const start = performance.now();
    methods[name]();
    samples[name].push(performance.now() - start);
  }
}
const medians = Object.fromEntries(names.map((name) => [name, median(samples[name])]));
const three = medians["three.js slerpFlat"];
console.log(`\n${n.toLocaleString("en")} interpolations, median of ${rounds} alternating rounds, Node ${process.version}, ${cpus()[0].model}:`);
console.log("| method | median ms | ns per item | throughput vs three.js slerpFlat |");
console.log("| --- | ---: | ---: | ---: |");
for (const name of names) {
  const ms = medians[name];
  console.log(`| ${name} | ${ms.toFixed(1)} | ${((ms * 1e6) / n).toFixed(1)} | ${(three / ms).toFixed(2)}× |`);
}
const ratio = (x, y) => medians[y] / medians[x];
for (const { name } of references) {
  console.log(`Against ${name}, same run: slerpBatch ${ratio("slerpBatch (wasm)", `slerpBatch (${name})`).toFixed(2)}× its speed,` +
    ` kliExactBatch ${ratio("kliExactBatch (wasm)", `kliExactBatch (${name})`).toFixed(2)}× (its own: slerpBatch` +
    ` ${ratio(`slerpBatch (${name})`, "three.js slerpFlat").toFixed(2)}×, kliExactBatch ${ratio(`kliExactBatch (${name})`, "three.js slerpFlat").toFixed(2)}× three.js)`);
}
console.log(`\nTargets: kliExactBatch ≥ 3.5× three.js: ${ratio("kliExactBatch (wasm)", "three.js slerpFlat").toFixed(2)}×;` +
  ` slerpBatch ≥ 1.8×: ${ratio("slerpBatch (wasm)", "three.js slerpFlat").toFixed(2)}×;` +
  ` kliExactBatch within 2× of nlerpBatch: ${(medians["kliExactBatch (wasm)"] / medians["nlerpBatch (wasm), baseline"]).toFixed(2)}×`);

const release = references.find(({ name }) => name.startsWith("previous release"));
for (const [method, goal] of [["kliExactBatch", 3.5], ["slerpBatch", 1.8]]) {
  const ours = ratio(`${method} (wasm)`, "three.js slerpFlat");
  const theirs = release && ratio(`${method} (wasm)`, `${method} (${release.name})`);
  record(`\`${method}\` ≥ ${goal}× three.js \`slerpFlat\`, 10⁶ copied pairs, and not slower than the previous release`,
    `${ours.toFixed(2)}× (in place ${ratio(`${method} (wasm, in place)`, "three.js slerpFlat").toFixed(2)}×)`,
    release ? `${release.name}: ${ratio(`${method} (${release.name})`, "three.js slerpFlat").toFixed(2)}×; ours ${theirs.toFixed(2)}× its speed` : "",
    ours >= goal && (!release || theirs >= 0.97));
}

// ---- The paper's example, solved ---------------------------------------------------------------
for (const integrator of ["rk4", "geodesic", "euler"]) {
  const runs = [];
  for (let k = 0; k < 300; k++) {
    const start = performance.now();
    const path = kli(p0, r0, { integrator });
    runs.push(performance.now() - start);
    path.free();
  }
  console.log(`kli(paper's example, ${integrator}): median ${(median(runs) * 1000).toFixed(1)} µs per solve (300 runs, including building the path object)`);
}
if (!agreed) {
  console.error("Results disagree: the timings above do not compare like with like.");
  process.exit(1);
}
