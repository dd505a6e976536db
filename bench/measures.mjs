// What the spline benchmarks measure, from samples of a curve only (so kli, its previous release
// and SciPy are measured alike): seeded random keys, ∫|ω̇|², and the largest step of ω̇.

// xorshift128+ and Gaussians: the same keys on every run.
let s0 = 0x9e3779b9, s1 = 0x243f6a88;
export const uniform = () => {
  let x = s0; const y = s1;
  s0 = y; x ^= x << 23; x ^= x >>> 17; x ^= y ^ (y >>> 26); s1 = x;
  return ((s0 + s1) >>> 0) / 4294967296;
};
const gaussian = () => Math.sqrt(-2 * Math.log(1 - uniform())) * Math.cos(2 * Math.PI * uniform());
export const multiply = ([aw, ax, ay, az], [bw, bx, by, bz]) => [
  aw * bw - ax * bx - ay * by - az * bz, aw * bx + ax * bw + ay * bz - az * by,
  aw * by - ax * bz + ay * bw + az * bx, aw * bz + ax * by - ay * bx + az * bw,
];

/** m keys, [w, x, y, z], each a rotation of `minDegrees`–`maxDegrees` (uniform) from the last. */
export function randomKeys(m, maxDegrees, minDegrees = 0) {
  const g = [gaussian(), gaussian(), gaussian(), gaussian()];
  const keys = [g.map((c) => c / Math.hypot(...g))];
  while (keys.length < m) {
    const axis = [gaussian(), gaussian(), gaussian()];
    const n = Math.hypot(...axis);
    const half = (((minDegrees + (maxDegrees - minDegrees) * uniform()) * Math.PI) / 180) / 2;
    const step = [Math.cos(half), ...axis.map((c) => (Math.sin(half) * c) / n)];
    keys.push(multiply(keys[keys.length - 1], step));
  }
  return keys;
}

/** Evenly spaced times from `start` to `end`, `n` intervals. */
export const grid = (start, end, n) => Float64Array.from({ length: n + 1 }, (_, k) => start + ((end - start) * k) / n);

/** Samples [w, x, y, z] with signs made consecutive (q and −q are one rotation). */
function consecutive(q) {
  for (let k = 4; k < q.length; k += 4) {
    let dot = 0;
    for (let c = 0; c < 4; c++) dot += q[k + c] * q[k - 4 + c];
    if (dot < 0) for (let c = 0; c < 4; c++) q[k + c] = -q[k + c];
  }
  return q;
}

/** `ω = 2 q' q̄` at sample k of `q` by central differences over ±`d` samples, spaced `dt`. */
function omega(q, k, d, dt) {
  const derivative = [0, 1, 2, 3].map((c) => (q[4 * (k + d) + c] - q[4 * (k - d) + c]) / (2 * d * dt));
  return multiply(derivative, [q[4 * k], -q[4 * k + 1], -q[4 * k + 2], -q[4 * k + 3]]).slice(1).map((x) => 2 * x);
}

/** ∫|ω̇|² from samples `dt` apart: ω by central differences, ω̇ by differences of ω. */
export function bending(samples, dt) {
  const q = consecutive(Float64Array.from(samples));
  const n = q.length / 4 - 1;
  let sum = 0, previous = omega(q, 1, 1, dt);
  for (let k = 2; k < n; k++) {
    const w = omega(q, k, 1, dt);
    sum += [0, 1, 2].reduce((s, c) => s + ((w[c] - previous[c]) / dt) ** 2, 0) * dt;
    previous = w;
  }
  return sum;
}

/** The times at which `steps` needs samples over [start, end] for evaluations `h` apart, ω by
 *  central differences over ±`h/10`: a grid of step h/10. */
export const stepTimes = (start, end, h) => grid(start, end, Math.round((end - start) / (h / 10)));

/** The largest step of ω̇ between evaluations h apart, over its largest |ω̇|, from samples at
 *  `stepTimes(start, end, h)`. */
export function steps(samples) {
  const q = consecutive(Float64Array.from(samples));
  const n = q.length / 4 - 1;
  const w = [];
  for (let k = 1; k + 1 <= n; k += 10) w.push(omega(q, k, 1, 1));
  // ω here is per grid step; ω̇ per evaluation step (10 grid steps): both scale out of the ratio.
  const dw = w.slice(1).map((v, i) => v.map((c, j) => c - w[i][j]));
  const largest = Math.max(...dw.map((v) => Math.hypot(...v)));
  let step = 0;
  for (let i = 1; i < dw.length; i++) step = Math.max(step, Math.hypot(...dw[i].map((c, j) => c - dw[i - 1][j])));
  return step / largest;
}
