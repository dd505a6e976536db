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
  assert.deepEqual(refused(() => chain.at(1, new Float64Array(3))), ["out", "out must hold 4 numbers (got 3)"]);
  assert.deepEqual(refused(() => chain.at(1, new Float32Array(4))), ["out", "out must be a Float64Array (got a Float32Array of length 4)"]);
  assert.deepEqual(refused(() => chain.angularVelocity(1, [0, 0, 0])), ["out", "out must be a Float64Array (got an array of length 3)"]);
  assert.deepEqual(refused(() => kliSpline([1, 0, 0, 0, 0, 1, 0])), ["keys", "keys must hold 4 numbers per key (got 7)"]);
  chain.free();
});

test("the batch calls take a Float32Array, any typed array or a flat number[] as well as a Float64Array", async () => {
  const kli = await import(new URL("kli.js", pkg));
  kli.initSync({ module: readFileSync(new URL("kli_bg.wasm", pkg)) });
  // 64 pairs of random unit quaternions (seeded), scalar last, and parameters.
  let seed = 7;
  const random = () => ((seed = (seed * 16807) % 2147483647) / 2147483647) * 2 - 1;
  const unit = () => { const q = [random(), random(), random(), random()]; const n = Math.hypot(...q); return q.map((c) => c / n); };
  const n = 64;
  const [starts, ends] = [0, 1].map(() => Array.from({ length: n }, unit).flat());
  const s = Array.from({ length: n }, () => (random() + 1) / 2);
  for (const [call, parameter] of [[kli.slerpBatch, s], [kli.kliExactBatch, s.map((x) => 4 * x)], [kli.nlerpBatch, s]]) {
    const exact = call(Float64Array.from(starts), Float64Array.from(ends), Float64Array.from(parameter), new Float64Array(4 * n), { order: "xyzw" });
    // The same numbers rounded to float32, given as a Float32Array and as the float64 values.
    const f32 = [starts, ends, parameter].map((a) => Float32Array.from(a));
    const fromFloat32 = call(...f32, new Float64Array(4 * n), { order: "xyzw" });
    const fromRounded = call(...f32.map((a) => Float64Array.from(a)), new Float64Array(4 * n), { order: "xyzw" });
    assert.deepEqual([...fromFloat32], [...fromRounded], `${call.name}: Float32Array against its values as float64`);
    const worst = Math.max(...fromFloat32.map((x, i) => Math.abs(x - exact[i])));
    assert.ok(worst < 1e-6, `${call.name}: float32 input within float32's rounding (${worst})`);
    // A flat number[] and another typed array (of the float64 values) give the float64 result.
    const flat = call(starts, ends, parameter, new Float64Array(4 * n), { order: "xyzw" });
    assert.deepEqual([...flat], [...exact], `${call.name}: number[]`);
    // Each one's result agrees with the single call on the same (float32) values.
    for (const i of [0, 17, 63]) {
      const single = call === kli.nlerpBatch ? null : (call === kli.slerpBatch ? kli.slerp : kli.kliExact)(
        [...f32[0].subarray(4 * i, 4 * i + 4)], [...f32[1].subarray(4 * i, 4 * i + 4)], f32[2][i], { order: "xyzw" });
      if (single) assert.ok(Math.max(...single.map((x, c) => Math.abs(x - fromFloat32[4 * i + c]))) < 1e-12, `${call.name} pair ${i}`);
    }
  }
  const refused = (call) => { try { call(); } catch (e) { return [e.argument, e.message]; } return ["accepted"]; };
  const q = new Float64Array(4);
  assert.deepEqual(refused(() => kli.slerpBatch("abcd", q, [0], q)), ["starts", "starts must be a typed array or an array of numbers (got \"abcd\", a string)"]);
  assert.deepEqual(refused(() => kli.slerpBatch(q, [1, 0, 0, "0"], [0], q)), ["ends", "ends must hold numbers: element 3 is \"0\", a string"]);
  assert.deepEqual(refused(() => kli.slerpBatch(new BigInt64Array(4), q, [0], q)), ["starts", "starts must be a typed array or an array of numbers (got a BigInt64Array of length 4)"]);
  assert.deepEqual(refused(() => kli.slerpBatch(q, q, [0], new Float32Array(4))), ["out", "out must be a Float64Array (got a Float32Array of length 4)"]);
  assert.deepEqual(refused(() => kli.slerpBatch(new Float32Array([1, 0, 0, NaN]), q, [0], q)), ["starts[0]", "starts[0] must be a quaternion of 4 finite numbers [w, x, y, z], not all zero: its z component is NaN"]);
});

test("keys as { x, y, z, w } objects (THREE.Quaternion) agree with the Float32Array and flat keys to 1e-7", () => {
  const objects = XYZW.map(([x, y, z, w]) => ({ x, y, z, w }));
  const a = kliSpline(objects, { times, order: "xyzw" });
  const b = kliSpline(new Float32Array(XYZW.flat()), { times, order: "xyzw" });
  for (const t of [0, 0.5, 1.7, 3.3, 4]) {
    const [p, r] = [a.at(t), b.at(t)];
    assert.ok(Math.max(...p.map((x, c) => Math.abs(x - r[c]))) < 1e-7, `t = ${t}`);
  }
  a.free(); b.free();
});
