// Issue 16's C² targets: the chain (smoothness 1) against SciPy's RotationSpline (a C² cubic in
// rotation vectors, the scientific-Python reference) on the same 24 random key sets, and the
// chain of the previous release (C¹: Squad through its samples) beside it, all measured from
// samples alike (bench/measures.mjs):
//   - ∫|ω̇|² (256 samples a unit of time): the chain's at most 0.97 of SciPy's, mean over the sets;
//   - the largest step of ω̇ between evaluations 1e-4 apart, over its largest |ω̇|: at most 1e-2.
// SciPy runs in a virtual environment the bench makes itself (bench/python.mjs).
//   node bench/smoothness.mjs
import { record } from "./targets.mjs";
import { bending, grid, randomKeys, stepTimes, steps, uniform } from "./measures.mjs";
import { load, previous } from "./previous.mjs";
import { SCIPY, python, runPython } from "./python.mjs";

const current = await load(new URL("../pkg", import.meta.url).pathname, "spline");
const release = previous()[0];
const old = await load(release.dir, "spline");

// 24 sets: 6 and 10 keys, steps of 20–120°, even times and uneven (spans 0.4–1.6).
const sets = [];
for (const m of [6, 10]) {
  for (const uneven of [false, true]) {
    for (let k = 0; k < 6; k++) {
      const keys = randomKeys(m, 120, 20);
      const times = [0];
      for (let i = 1; i < m; i++) times.push(times[i - 1] + (uneven ? 0.4 + 1.2 * uniform() : 1));
      sets.push({ keys, times, uneven });
    }
  }
}

const PER_UNIT = 256, H = 1e-4;
/** The two grids of a set: for ∫|ω̇|², and for the steps of ω̇ (a grid of H/10). */
const grids = ({ times }) => {
  const [start, end] = [times[0], times[times.length - 1]];
  return { energy: grid(start, end, Math.round((end - start) * PER_UNIT)), steps: stepTimes(start, end, H) };
};

// SciPy: one Python run for every set and both grids.
const request = sets.flatMap((set) => {
  const g = grids(set);
  return [{ keys: set.keys, times: set.times, at: [...g.energy] }, { keys: set.keys, times: set.times, at: [...g.steps] }];
});
python(); // made first, so its install is not in the time below
const started = performance.now();
const bytes = runPython("scipy_spline.py", request);
const scipyMs = performance.now() - started;
const all = new Float64Array(bytes.buffer, bytes.byteOffset, bytes.byteLength / 8);
let offset = 0;
const take = (n) => all.subarray(offset, (offset += 4 * n));

const rows = [];
for (const set of sets) {
  const g = grids(set);
  const scipy = { energy: take(g.energy.length), steps: take(g.steps.length) };
  const measure = (module) => {
    const spline = module.kliSpline(set.keys, { times: set.times });
    const result = { energy: bending(spline.sample(g.energy), g.energy[1] - g.energy[0]), steps: steps(spline.sample(g.steps)) };
    spline.free();
    return result;
  };
  const dt = g.energy[1] - g.energy[0];
  rows.push({
    set,
    kli: measure(current),
    old: measure(old),
    scipy: { energy: bending(scipy.energy, dt), steps: steps(scipy.steps) },
  });
}

const mean = (xs) => xs.reduce((a, b) => a + b, 0) / xs.length;
const range = (xs) => `${Math.min(...xs).toFixed(3)}–${Math.max(...xs).toFixed(3)}`;
const ratios = (who) => rows.map((r) => r[who].energy / r.scipy.energy);
console.log(`\nSmoothness on ${sets.length} random key sets (6 and 10 keys, 20–120° apart, even and uneven times), against SciPy ${SCIPY}'s RotationSpline (${scipyMs.toFixed(0)} ms in Python):`);
console.log("| curve | ∫\\|ω̇\\|² / SciPy's, mean (range) | largest step of ω̇ at h = 1e-4 / largest \\|ω̇\\|, worst set |");
console.log("| --- | ---: | ---: |");
console.log(`| kliSpline, this build (C²) | ${mean(ratios("kli")).toFixed(3)} (${range(ratios("kli"))}) | ${Math.max(...rows.map((r) => r.kli.steps)).toExponential(1)} |`);
console.log(`| kliSpline, ${release.name} ${release.commit} (C¹) | ${mean(ratios("old")).toFixed(3)} (${range(ratios("old"))}) | ${Math.max(...rows.map((r) => r.old.steps)).toExponential(1)} |`);
console.log(`| SciPy RotationSpline | 1 | ${Math.max(...rows.map((r) => r.scipy.steps)).toExponential(1)} |`);
const kliMean = mean(ratios("kli")), kliSteps = Math.max(...rows.map((r) => r.kli.steps));
record("the chain's `∫|ω̇|²` ≤ 0.97 of SciPy's `RotationSpline`, `ω̇`'s steps ≤ 1e-2", `${kliMean.toFixed(3)}, ${kliSteps.toExponential(1)}`,
  `SciPy ${SCIPY}: 1`, kliMean <= 0.97 && kliSteps <= 1e-2);
console.log(`targets: ∫|ω̇|² ≤ 0.97 of SciPy's: ${kliMean <= 0.97 ? "met" : "MISSED"} (${kliMean.toFixed(3)}); ` +
  `ω̇ step ≤ 1e-2: ${kliSteps <= 1e-2 ? "met" : "MISSED"} (${kliSteps.toExponential(1)})`);
