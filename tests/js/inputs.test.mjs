// kli/spline takes the arrays animation code has (issue 16, part 1 and 2): a three.js track's or a
// glTF accessor's Float32Array of x, y, z, w, a flat number[], and evaluates into the caller's
// array with no allocation.
import { test } from "node:test";
import assert from "node:assert/strict";
import { readFileSync } from "node:fs";

const pkg = new URL("../../pkg/", import.meta.url);
const spline = await import(new URL("spline.js", pkg));
spline.initSync({ module: readFileSync(new URL("spline_bg.wasm", pkg)) });
const { kliSpline, squadSpline, slerpSpline } = spline;

// Four keys, scalar last as three.js and glTF keep them, each already a float32 value.
const XYZW = [[0, 0, 0, 1], [0.6, 0, 0, 0.8], [0, 0.8, 0, 0.6], [0.48, 0.6, 0, 0.64]].map((q) => q.map(Math.fround));
const times = [0, 1, 2.5, 4];

test("a Float32Array, a flat number[] and an array of quaternions give the same curve, bit for bit", () => {
  for (const make of [kliSpline, squadSpline, slerpSpline]) {
    const nested = make(XYZW, { times, order: "xyzw" });
    const flat = make(XYZW.flat(), { times, order: "xyzw" });
    const float32 = make(new Float32Array(XYZW.flat()), { times: new Float32Array(times), order: "xyzw" });
    for (const t of [0, 0.3, 1, 2.2, 3.9, 4]) {
      const q = [...nested.at(t)];
      assert.deepEqual([...flat.at(t)], q);
      assert.deepEqual([...float32.at(t)], q);
    }
    // The keys are hit (the first exactly: it is unit in f64 as given).
    assert.deepEqual([...nested.at(0)], XYZW[0]);
    for (const c of [nested, flat, float32]) c.free();
  }
});

test("at(t, out) and angularVelocity(t, out) fill the caller's array and return it", () => {
  const chain = kliSpline(XYZW, { times, order: "xyzw" });
  const q = new Float64Array(4), w = new Float64Array(3);
  for (const t of [0, 0.7, 2, 3.5]) {
    assert.equal(chain.at(t, q), q);
    assert.deepEqual([...q], [...chain.at(t)]);
    assert.equal(chain.angularVelocity(t, w), w);
    assert.deepEqual([...w], [...chain.angularVelocity(t)]);
    // ω from the curve itself: q' = ½ ω q, so ω = 2 q' q̄ (central difference, scalar last).
    const h = 1e-6, a = chain.at(t + h), b = chain.at(Math.max(t - h, 0));
    const step = t + h - Math.max(t - h, 0);
    const d = [0, 1, 2, 3].map((c) => (a[c] - b[c]) / step);
    const [x, y, z, s] = q; // q̄ = (-x, -y, -z, s)
    const omega = [
      2 * (d[3] * -x + d[0] * s + d[1] * -z - d[2] * -y),
      2 * (d[3] * -y + d[1] * s + d[2] * -x - d[0] * -z),
      2 * (d[3] * -z + d[2] * s + d[0] * -y - d[1] * -x),
    ];
    for (let c = 0; c < 3; c++) assert.ok(Math.abs(omega[c] - w[c]) < 1e-5, `t = ${t}: ω ${w} vs ${omega}`);
  }
  const refused = (call) => { try { call(); } catch (e) { return [e.argument, e.message]; } return ["accepted"]; };
  assert.deepEqual(refused(() => chain.at(1, new Float64Array(3))), ["out", "out must be a Float64Array of 4 (got a Float64Array of length 3)"]);
  assert.deepEqual(refused(() => chain.at(1, new Float32Array(4))), ["out", "out must be a Float64Array (got a Float32Array of length 4)"]);
  assert.deepEqual(refused(() => chain.angularVelocity(1, [0, 0, 0])), ["out", "out must be a Float64Array (got an array of length 3)"]);
  assert.deepEqual(refused(() => kliSpline([1, 0, 0, 0, 0, 1, 0])), ["keys", "keys must hold 4 numbers per key (got 7)"]);
  chain.free();
});
