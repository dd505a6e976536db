// Hostile input for every entry of the package (issue 17): seeded fuzzing of every call and
// object with every kind of JavaScript value (BigInt, Symbol, Proxies whose traps throw or call
// back into the object, getters that throw, array-likes of any length, typed arrays of every
// element type, forged typed arrays), then the reproducers of the issue one by one. The
// contract: each call returns finite, well-formed results or throws an Error with `argument`
// and `kind`; the module never traps and leaks no externref slot however many errors it has
// thrown; an object stays usable after any refused call, and free() always frees.
import { test } from "node:test";
import assert from "node:assert/strict";
import { readFileSync } from "node:fs";

const pkg = new URL("../../pkg/", import.meta.url);
const load = async (name) => {
  const module = await import(new URL(`${name}.js`, pkg));
  const exports = module.initSync({ module: readFileSync(new URL(`${name}_bg.wasm`, pkg)) });
  return { module, table: () => exports.__wbindgen_externrefs.length };
};
// KLI_FUZZ_SCALE=50 runs 50 times as many calls (about 5×10⁵; not part of make test).
const SCALE = Number(process.env.KLI_FUZZ_SCALE ?? 1);
const kli = await load("kli");
const spline = await load("spline");
const swarm = await load("swarm");
const average = await load("average");
const sync = await load("sync");

// xorshift32: the same hostile values on every run.
function random(seed) {
  let x = seed >>> 0 || 1;
  return () => {
    x ^= x << 13; x ^= x >>> 17; x ^= x << 5; x >>>= 0;
    return x / 4294967296;
  };
}

const revoked = (() => { const { proxy, revoke } = Proxy.revocable([], {}); revoke(); return proxy; })();
const lyingLength = () => { const a = new Float64Array(4); Object.defineProperty(a, "length", { value: 8 }); return a; };

// How many times a hostile getter or trap threw: each costs one externref slot (see the last test).
let thrown = 0;
const throwing = (what) => new Proxy({}, { get() { thrown++; throw new Error(`${what} trap`); }, has() { thrown++; throw new Error("has trap"); }, ownKeys() { thrown++; throw new Error("ownKeys trap"); } });
const getterArray = () => { const a = [1, 0, 0, 0]; Object.defineProperty(a, 2, { get() { thrown++; throw new Error("element getter"); } }); return a; };
const forgedLength = () => { const a = new Float64Array(4); Object.defineProperty(a, "length", { get() { thrown++; throw new Error("length getter"); } }); return a; };

/** The table may grow by the slots of the exceptions caught, rounded up to its growth step. */
function assertNoLeak(table, before, caught) {
  assert.ok(table <= Math.max(before, 2 * (before + caught)), `externref slots leaked: ${before} → ${table} with ${caught} caught exceptions`);
  if (caught === 0) assert.equal(table, before, "externref slots leaked");
}

/** A hostile value; `callback` is called by some of them (re-entrancy into the object). */
function hostile(next, callback = () => {}) {
  const values = [
    () => NaN, () => Infinity, () => -Infinity, () => 1e308, () => -1e308, () => 5e-324, () => -0, () => 2 ** 53,
    () => 10n, () => Symbol("s"), () => "1", () => "", () => null, () => undefined, () => true, () => ({}), () => [],
    () => ({ length: Infinity }), () => ({ length: 1e9 }), () => ({ length: -1 }), () => ({ length: 2 ** 32 + 4 }),
    () => ({ length: 4, 0: 1, 1: 0, 2: 0, 3: 0 }), () => throwing("get"), () => revoked, () => getterArray(),
    () => forgedLength(), () => lyingLength(), () => Object.create(Float64Array.prototype), () => new DataView(new ArrayBuffer(32)),
    () => new Int32Array(8), () => new Float32Array([1, 0, 0, 0]), () => new BigInt64Array(4), () => new Uint8ClampedArray(4),
    () => new Float64Array(0), () => new Float64Array(4), () => new Float64Array([1, 0, 0, 0, 0, 1, 0, 0]),
    () => [1, 0, 0, 0], () => [[1, 0, 0, 0], [0, 1, 0, 0]], () => [1, 2, 3], () => [NaN, 0, 0, 1], () => [0, 0, 0, 0],
    () => ({ x: 0, y: 0, z: 0, w: 1 }), () => ({ w: 1n, x: 0, y: 0, z: 0 }), () => [0, 1, 1e9],
    () => new Proxy([0, 1], { get(t, k) { callback(); return Reflect.get(t, k); } }),
    () => new Proxy({}, { get(t, k) { callback(); return undefined; }, ownKeys() { callback(); return []; } }),
    () => function f() {}, () => new Date(0), () => Object.freeze([0.5]), () => [0, , 2],
  ];
  return values[Math.floor(next() * values.length)]();
}

/** Calls `call`; returns "ok" or checks the Error and returns its kind. */
function attempt(call, check = () => {}) {
  let result;
  try {
    result = call();
  } catch (e) {
    assert.ok(e instanceof Error, `not an Error: ${String(e)}`);
    assert.equal(typeof e.argument, "string", `no argument: ${e.message}`);
    assert.equal(typeof e.kind, "string", `no kind: ${e.message}`);
    assert.ok([kli, spline, swarm, average, sync].every((m) => m.module.isKliError(e)));
    assert.doesNotMatch(e.message, /unreachable|table index|memory access|null pointer passed|recursive use of|is not a function|Cannot convert/);
    return e.kind;
  }
  check(result);
  return "ok";
}

/** Every number in a result is finite; quaternions (groups of 4) are unit. */
function wellFormed(result, unit = false) {
  if (result === undefined || typeof result === "number") {
    if (typeof result === "number") assert.ok(Number.isFinite(result), `result ${result}`);
    return;
  }
  if (!(result instanceof Float64Array)) return;
  for (const x of result) assert.ok(Number.isFinite(x), `non-finite ${x}`);
  if (unit) {
    for (let i = 0; i < result.length; i += 4) {
      const length = Math.hypot(result[i], result[i + 1], result[i + 2], result[i + 3]);
      assert.ok(Math.abs(length - 1) < 1e-12, `|q| = ${length}`);
    }
  }
}

const KEYS = [[1, 0, 0, 0], [0.5, 0.5, 0.5, 0.5], [0, 0, 1, 0], [0.5, -0.5, 0.5, 0.5]];
test("kli/average: 3,000 seeded hostile calls, no trap, no leak, the module still right", () => {
  const { averageRotations, blendRotations } = average.module;
  const next = random(23);
  const before = average.table(), caught = thrown;
  const methods = ["chordal", "quaternion", "geodesic", "median"];
  let errors = 0;
  for (let i = 0; i < 3000 * SCALE; i++) {
    const value = hostile(next, () => averageRotations(KEYS));
    const other = hostile(next);
    const out = new Float64Array(8);
    const calls = [
      () => averageRotations(value), () => averageRotations(KEYS, value), () => averageRotations(KEYS, { weights: value }),
      () => averageRotations(KEYS, { method: value }), () => averageRotations(value, { method: methods[i % 4], order: other }),
      () => averageRotations(KEYS, { weights: [1, 2, value, 1], method: methods[i % 4] }),
      () => blendRotations(value, [1, 1], out), () => blendRotations(KEYS.flat(), value, out),
      () => blendRotations(KEYS.flat(), [1, 1], value), () => blendRotations(KEYS.flat(), [1, 1], out, value),
      () => blendRotations(value, other, out),
    ];
    const kind = attempt(calls[Math.floor(next() * calls.length)], (r) => {
      if (r instanceof Float64Array) wellFormed(r, true);
      else if (r) {
        wellFormed(r.rotation, true);
        for (const key of ["iterations", "residual", "dispersion"]) wellFormed(r[key]);
        if (r.weights) wellFormed(r.weights);
      }
    });
    if (kind !== "ok") errors++;
  }
  assert.ok(errors > 1500 * SCALE, `only ${errors} refusals: the fuzz is not hostile enough`);
  assertNoLeak(average.table(), before, thrown - caught);
  // Still right: p and r weighted equally meet halfway, (p + r)/√3.
  const { rotation } = averageRotations([[0, 0, 0, 1], [0.5, 0.5, 0.5, 0.5]]);
  for (const [got, want] of [...rotation].map((c, k) => [c, [0.288675134594813, 0.288675134594813, 0.288675134594813, 0.866025403784439][k]])) {
    assert.ok(Math.abs(got - want) < 1e-14, `${rotation}`);
  }
});

const TRIANGLE = { edges: [[0, 1], [1, 2], [0, 2]], relative: [[1, 0, 0, 0], [1, 0, 0, 0], [0.8660254037844387, 0.5, 0, 0]] };
test("kli/sync: 3,000 seeded hostile calls, no trap, no leak, the module and a flow still right", () => {
  const { synchronizeRotations, readG2o, SyncFlow } = sync.module;
  const next = random(29);
  const before = sync.table(), caught = thrown;
  const methods = ["chordal", "robust", "spectral"];
  const flow = new SyncFlow(TRIANGLE, { seed: 2 });
  let errors = 0;
  for (let i = 0; i < 3000 * SCALE; i++) {
    const value = hostile(next, () => synchronizeRotations(TRIANGLE));
    const other = hostile(next, () => flow.step(0.01));
    const calls = [
      () => synchronizeRotations(value), () => synchronizeRotations(TRIANGLE, value),
      () => synchronizeRotations({ ...TRIANGLE, edges: value }), () => synchronizeRotations({ ...TRIANGLE, relative: value }),
      () => synchronizeRotations({ ...TRIANGLE, weights: value }, { method: methods[i % 3] }),
      () => synchronizeRotations({ ...TRIANGLE, count: value }), () => synchronizeRotations(TRIANGLE, { anchor: value, order: other }),
      () => synchronizeRotations(TRIANGLE, { method: "robust", scale: value }),
      () => synchronizeRotations({ edges: [[0, 1], [1, value]], relative: [[1, 0, 0, 0], other] }),
      () => readG2o(value), () => readG2o(`EDGE3 0 1 0 0 0 ${typeof value === "number" ? value : "x"} 0 0`, other),
      () => new SyncFlow(value), () => new SyncFlow(TRIANGLE, value), () => new SyncFlow(TRIANGLE, { start: value }),
      () => flow.step(value, other), () => flow.step(0.01, value),
    ];
    const kind = attempt(calls[Math.floor(next() * calls.length)], (r) => {
      if (r instanceof SyncFlow) { wellFormed(r.rotations, true); r.free(); return; }
      if (!r || r.rotations === undefined) return;
      wellFormed(r.rotations, true);
      wellFormed(r.residuals);
      wellFormed(r.cost);
    });
    if (kind !== "ok") errors++;
  }
  assert.ok(errors > 1000 * SCALE, `only ${errors} refusals: the fuzz is not hostile enough`);
  assertNoLeak(sync.table(), before, thrown - caught);
  // Still right: MATH.md's triangle, and the flow still steps on S³.
  const { cost } = synchronizeRotations(TRIANGLE);
  assert.ok(Math.abs(cost - 0.723688550569099) < 1e-12, `${cost}`);
  flow.step(0.05, 10);
  wellFormed(flow.rotations, true);
  flow.free();
});

test("isKliError: true for kli's Errors, false for anything else", () => {
  for (const { module } of [kli, spline, swarm]) {
    assert.equal(module.isKliError(new Error("x")), false);
    assert.equal(module.isKliError({ message: "m", argument: "a", kind: "invalid" }), false);
    assert.equal(module.isKliError(undefined), false);
    assert.equal(module.isKliError(Object.assign(new TypeError("t"), { argument: "a", kind: "invalid" })), true);
  }
  try { kli.module.slerp([1, 0, 0, 0], [0, 0, 0, 0], 0.5); assert.fail("accepted"); } catch (e) { assert.ok(swarm.module.isKliError(e)); }
});

test("kli/spline: 4,000 seeded hostile calls, no trap, no leak, every object still usable", () => {
  const { kliSpline, squadSpline, slerpSpline } = spline.module;
  const next = random(17);
  const makers = [kliSpline, squadSpline, slerpSpline];
  const objects = makers.map((make) => make(KEYS, { times: [0, 1, 2, 4] }));
  const before = spline.table(), caught = thrown;
  let errors = 0;
  for (let i = 0; i < 4000 * SCALE; i++) {
    const s = objects[i % 3];
    const value = hostile(next, () => { s.at(0.5); s.free?.call({ __wbg_ptr: 0, __destroy_into_raw: () => 0 }); });
    const other = hostile(next);
    const calls = [
      () => s.at(value), () => s.angularVelocity(value), () => s.sample(value), () => s.sample([0, 1], value),
      () => s.at(0.5, value), () => s.angularVelocity(1.5, value), () => s.at(value, other),
      () => s.sample(value, other), () => makers[i % 3](value), () => makers[i % 3](KEYS, value),
      () => makers[i % 3](KEYS, { times: value }), () => kliSpline(KEYS, { samplesPerSegment: value }),
      () => kliSpline(KEYS, { smoothness: value }), () => makers[i % 3](value, { order: other }),
    ];
    const kind = attempt(calls[Math.floor(next() * calls.length)], (r) => {
      if (r instanceof Float64Array && r.length % 4 === 0) wellFormed(r, true);
      else if (r && typeof r.free === "function") { wellFormed(r.at(r.startTime), true); r.free(); }
      else wellFormed(r);
    });
    if (kind !== "ok") errors++;
  }
  assert.ok(errors > 2000 * SCALE, `only ${errors} refusals: the fuzz is not hostile enough`);
  assertNoLeak(spline.table(), before, thrown - caught);
  // Each object still gives the keys at the key times (the first key exactly).
  for (const s of objects) {
    assert.deepEqual([...s.at(0)], KEYS[0]);
    const q = s.at(4);
    assert.ok(Math.abs(q[0] - 0.5) < 1e-12 && Math.abs(q[1] + 0.5) < 1e-12, `${q}`);
    s.free();
  }
});

test("kli/swarm: 3,000 seeded hostile calls, no trap, no leak, every swarm still usable", () => {
  const { LoheSwarm } = swarm.module;
  const next = random(29);
  const swarms = [new LoheSwarm({ count: 20, seed: 3 }), new LoheSwarm({ count: 8, graph: "ring", order: "xyzw" })];
  const before = swarm.table(), caught = thrown;
  let errors = 0;
  for (let i = 0; i < 3000 * SCALE; i++) {
    const s = swarms[i % 2];
    const value = hostile(next, () => s.step(0.01));
    const other = hostile(next, () => s.free());
    const key = ["count", "coupling", "graph", "leaders", "frequencySpread", "startSpread", "seed", "order"][Math.floor(next() * 8)];
    const calls = [
      () => s.step(value), () => s.step(0.01, value), () => s.step(value, other), () => s.setQuaternions(value),
      () => new LoheSwarm(value), () => new LoheSwarm({ [key]: value }), () => new LoheSwarm({ count: 5, [key]: other }),
    ];
    const kind = attempt(calls[Math.floor(next() * calls.length)], (r) => {
      if (r instanceof LoheSwarm) {
        r.step(0.05, 3);
        wellFormed(r.quaternions, true);
        for (const x of [r.orderParameter, r.rotationOrder, r.potential, r.time]) assert.ok(Number.isFinite(x));
        r.free();
      }
    });
    if (kind !== "ok") errors++;
  }
  assert.ok(errors > 1500 * SCALE, `only ${errors} refusals`);
  assertNoLeak(swarm.table(), before, thrown - caught);
  for (const s of swarms) {
    s.step(0.05, 10);
    wellFormed(s.quaternions, true);
    s.free();
  }
});

test("kli: 3,000 seeded hostile calls into the main entry, no trap, no leak", () => {
  const m = kli.module;
  const next = random(41);
  const p = [0, 0, 0, 1], r = [0.5, 0.5, 0.5, 0.5];
  const path = m.kli(p, r);
  const before = kli.table(), caught = thrown;
  for (let i = 0; i < 3000 * SCALE; i++) {
    const value = hostile(next), other = hostile(next);
    const calls = [
      () => m.kliExact(p, r, value), () => m.kliExact(value, r, 1, other), () => m.slerp(p, r, value, other),
      () => m.kliReachTime(p, r, value), () => m.kliToSlerpParameter(value, other, 1), () => m.hopf(value),
      () => m.axisAngle(value, other), () => m.fromAxisAngle(value, other), () => path.exactAt(value),
      () => m.kliSample(p, r, value, other), () => m.slerpBatch(value, value, value, other),
      () => m.kliExactBatch(new Float64Array(p), new Float64Array(r), value, other), () => new m.Float64Buffer(value),
      () => m.kli(p, r, { tolerance: value, step: other }),
    ];
    attempt(calls[Math.floor(next() * calls.length)], (result) => {
      if (result instanceof m.KliPath) { assert.ok(Number.isFinite(result.finalTime)); result.free(); }
      else if (result instanceof m.Float64Buffer) result.free();
      else wellFormed(result);
    });
  }
  assertNoLeak(kli.table(), before, thrown - caught);
  assert.equal(m.kli(p, r).finalTime, 11.66);
  assert.equal(path.steps, 1166);
});

test("the reproducers: 2,000 refusals in a row, and the object after each", () => {
  const { squadSpline } = spline.module;
  const { LoheSwarm } = swarm.module;
  const s = squadSpline([[1, 0, 0, 0], [0, 1, 0, 0]]);
  const before = spline.table();
  for (let i = 0; i < 2000; i++) assert.equal(attempt(() => s.sample({ length: Infinity })), "invalid");
  for (let i = 0; i < 500; i++) attempt(() => s.sample([0, 1], [0, 0, 0, 0, 0, 0, 0, 0]));
  for (let i = 0; i < 500; i++) attempt(() => s.sample([0, 1n]));
  assert.equal(spline.table(), before);
  assert.deepEqual([...s.at(0)], [1, 0, 0, 0]);
  // `out` must be a Float64Array of 4n numbers; an Int32Array is refused, not truncated.
  const refused = (call) => { try { call(); } catch (e) { return [e.argument, e.kind, e.message]; } return ["accepted"]; };
  assert.deepEqual(refused(() => s.sample([0, 1], new Int32Array(8))).slice(0, 2), ["out", "invalid"]);
  assert.deepEqual(refused(() => s.sample([0, 1], [0, 0, 0, 0, 0, 0, 0, 0])).slice(0, 2), ["out", "invalid"]);
  assert.deepEqual(refused(() => s.sample([0, 1], lyingLength())).slice(0, 2), ["out", "invalid"]);
  assert.deepEqual(refused(() => s.at(10n)).slice(0, 2), ["t", "invalid"]);
  assert.deepEqual(refused(() => s.at(Symbol())).slice(0, 2), ["t", "invalid"]);
  const out = new Float64Array(8);
  assert.equal(s.sample(new Float32Array([0, 1]), out), out);
  assert.deepEqual([...out], [1, 0, 0, 0, 0, 1, 0, 0]);

  const w = new LoheSwarm({ count: 4 });
  for (let i = 0; i < 1200; i++) attempt(() => w.setQuaternions({ length: Infinity }));
  for (let i = 0; i < 1200; i++) attempt(() => new LoheSwarm({ count: 10n }));
  assert.deepEqual(refused(() => w.step(10n)).slice(0, 2), ["dt", "invalid"]);
  w.step(0.1);
  assert.ok(Math.abs(w.time - 0.1) < 1e-15);
  // free() frees; a freed object says so; a second free() does nothing.
  w.free();
  assert.deepEqual(refused(() => w.step(0.1)).slice(0, 2), ["this", "freed"]);
  assert.deepEqual(refused(() => w.quaternions).slice(0, 2), ["this", "freed"]);
  assert.doesNotThrow(() => w.free());
  s.free();
  assert.deepEqual(refused(() => s.sample([0], new Float64Array(4))).slice(0, 2), ["this", "freed"]);
  // A Proxy that calls back into the object mid-call: the inner call is refused ("busy"), the
  // outer goes on; free() from inside a call is refused and the object stays alive.
  const v = new LoheSwarm({ count: 2 });
  let inner;
  const sneaky = new Proxy([1, 0, 0, 0, 1, 0, 0, 0], { get(t, k) { if (k === "0") { try { v.free(); } catch (e) { inner = e; } } return Reflect.get(t, k); } });
  v.setQuaternions(sneaky);
  assert.equal(inner?.kind, "busy");
  assert.deepEqual([...v.quaternions], [1, 0, 0, 0, 1, 0, 0, 0]);
  v.free();
});

test("a getter that throws: refused by name, and 20,000 of them leave the module working", () => {
  // Known and left: wasm-bindgen 0.2.130 drops the return slot of a `catch` import that threw,
  // so each caught exception costs one slot of the externref table (it grows, it does not
  // trap). Every other refusal costs nothing (the tests above).
  const { kli: run } = kli.module;
  const p = [0, 0, 0, 1], r = [0.5, 0.5, 0.5, 0.5];
  const options = { get tolerance() { throw new Error("no"); } };
  let error;
  for (let i = 0; i < 20000; i++) try { run(p, r, options); } catch (e) { error = e; }
  assert.equal(error.argument, "tolerance");
  assert.equal(error.message, "tolerance could not be read (it threw: no)");
  assert.equal(run(p, r).finalTime, 11.66);
});

test("options the model cannot honour are refused up front, with ranges that are true", () => {
  const { LoheSwarm } = swarm.module;
  const { kliSpline, slerpSpline, squadSpline } = spline.module;
  const refused = (call) => { try { call(); } catch (e) { return [e.argument, e.message]; } return ["accepted"]; };
  assert.deepEqual(refused(() => new LoheSwarm({ count: 0 })), ["count", "count must be a whole number from 1 to 1000000 (got 0)"]);
  assert.equal(refused(() => new LoheSwarm({ count: 5, startSpread: 1e200 }))[0], "startSpread");
  assert.equal(refused(() => new LoheSwarm({ coupling: 1e12 }))[0], "coupling");
  assert.equal(refused(() => new LoheSwarm({ coupling: -1e308 }))[0], "coupling");
  assert.equal(refused(() => new LoheSwarm({ frequencySpread: 1e200 }))[0], "frequencySpread");
  assert.equal(refused(() => new LoheSwarm().step(1e308, 2))[0], "dt");
  assert.deepEqual(refused(() => kliSpline(KEYS, { samplesPerSegment: 1e9 })),
    ["samplesPerSegment", "samplesPerSegment must be a whole number from 2 to 256 (got 1000000000)"]);
  assert.equal(refused(() => kliSpline(KEYS, { samplesPerSegment: 1 }))[0], "samplesPerSegment");
  const many = Array.from({ length: 600 }, (_, i) => [Math.cos(i), Math.sin(i), 0.3, 0.1]);
  assert.match(refused(() => kliSpline(many, { samplesPerSegment: 256 }))[1], /at most 131072 chain samples/);
  assert.equal(refused(() => slerpSpline(KEYS.slice(0, 2), { times: [0, 5e-324] }))[0], "times[1]");
  assert.equal(refused(() => squadSpline(KEYS.slice(0, 2), { times: [-1e308, 1e308] }))[0], "times[0]");
  assert.equal(refused(() => kliSpline(KEYS, { times: [0, 1e-320, 2e-320, 3e-320] }))[0], "times[1]");
  assert.match(refused(() => kliSpline(KEYS.slice(0, 2), { times: [-1e308, 1e308] }))[1], /^times\[0\] must be a finite number from -1000000000000000 to 1000000000000000 \(got -1e\+308\)/);

  // What is accepted stays finite and on the sphere: the extremes of every range.
  for (const options of [
    { count: 50, coupling: 1e6 }, { count: 50, coupling: -1e6 }, { count: 50, frequencySpread: 1e6 },
    { count: 50, startSpread: 1000 }, { count: 50, frequencySpread: 2 }, { count: 3, graph: "leader", leaders: 3, coupling: 1e6, frequencySpread: 1e6 },
  ]) {
    const s = new LoheSwarm(options);
    for (let k = 0; k < 20; k++) s.step(k % 2 ? 100 : 0.5, 5);
    wellFormed(s.quaternions, true);
    for (const x of [s.orderParameter, s.rotationOrder, s.potential, s.time]) assert.ok(Number.isFinite(x), JSON.stringify(options));
    s.free();
  }
  // The README's promise, σ = 2 and dt = 0.5 (|q| fell to 0.043 before).
  const fast = new LoheSwarm({ frequencySpread: 2 });
  fast.step(0.5, 50);
  wellFormed(fast.quaternions, true);
  fast.free();
  // Splines at the edges of the time ranges: finite, unit, and the solve meets its residual.
  for (const times of [[0, 1e-9, 2.5e-9, 4e-9], [-1e15, -1e14, 1e14, 1e15], [0, 1, 1 + 1e-8, 3]]) {
    for (const make of [kliSpline, squadSpline, slerpSpline]) {
      const c = make(KEYS, { times });
      const at = [...times, (times[0] + times[1]) / 2, times[3] * 2];
      for (const t of at) { wellFormed(c.at(t), true); wellFormed(c.angularVelocity(t)); }
      if (c.residual !== undefined) assert.ok(c.residual <= 1e-10, `residual ${c.residual} at ${times}`);
      c.free();
    }
  }
  const chain = kliSpline(KEYS.concat(KEYS, KEYS), { samplesPerSegment: 256 });
  assert.ok(chain.residual <= 1e-10, `residual ${chain.residual}`);
  chain.free();
});
