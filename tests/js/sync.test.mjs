// kli/sync against GTSAM (tests/fixtures/sync.json, written by bench/sync_fixture.py: GTSAM's own
// optimum of the chordal cost on its pose3example-grid and two weighted random graphs, and NumPy's
// dense eigenvalues of the certificate), through the package as a user calls it: nested and flat
// edges, both quaternion orders, and a g2o file read with readG2o.
import { test } from "node:test";
import assert from "node:assert/strict";
import { readFileSync } from "node:fs";

const pkg = new URL("../../pkg/", import.meta.url);
const sync = await import(new URL("sync.js", pkg));
sync.initSync({ module: readFileSync(new URL("sync_bg.wasm", pkg)) });
const { synchronizeRotations, readG2o, SyncFlow, synchronizePoses, writeG2o } = sync;
const fixture = JSON.parse(readFileSync(new URL("../fixtures/sync.json", import.meta.url)));
const xyzw = ([w, x, y, z]) => [x, y, z, w];

test("the chordal optimum is GTSAM's to 1e-9, certified, in both orders and edge forms", () => {
  assert.ok(fixture.cases.length >= 3);
  for (const c of fixture.cases) {
    const nested = synchronizeRotations({ edges: c.edges, relative: c.relative, weights: c.weights, count: c.count });
    const flat = synchronizeRotations(
      { edges: new Uint32Array(c.edges.flat()), relative: new Float64Array(c.relative.map(xyzw).flat()), weights: new Float64Array(c.weights) },
      { order: "xyzw" },
    );
    for (const [result, order] of [[nested, "wxyz"], [flat, "xyzw"]]) {
      c.rotations.forEach((q, i) => {
        const want = order === "xyzw" ? xyzw(q) : q;
        const got = Array.from(result.rotations.subarray(4 * i, 4 * i + 4));
        const off = Math.max(...got.map((x, k) => Math.abs(x - want[k])));
        assert.ok(off < 1e-9, `${c.name} (${order}) node ${i}: ${got} vs GTSAM's ${want}`);
      });
      assert.ok(Math.abs(result.cost - c.cost) < 1e-9 * c.cost, `${c.name}: ${result.cost} vs ${c.cost}`);
      assert.equal(result.certificate.certified, true);
      assert.ok(Math.abs(result.certificate.gap - c.eigenvalues[3]) < 1e-7 * c.eigenvalues[3], `${c.name}: λ₄`);
      assert.equal(result.residuals.length, c.edges.length);
    }
  }
});

test("a g2o file read by readG2o synchronises to the same optimum", () => {
  const c = fixture.cases.find((c) => c.name === "pose3example-grid");
  // The fixture's graph written out as g2o lines (qx qy qz qw), with vertices and information.
  const info = "1 0 0 0 0 0 1 0 0 0 0 1 0 0 0 1 0 0 1 0 1";
  const lines = c.edges.map(([i, j], k) => `EDGE_SE3:QUAT ${i} ${j} 0 0 0 ${xyzw(c.relative[k]).join(" ")} ${info}`);
  const graph = readG2o(lines.join("\n"));
  assert.equal(graph.count, c.count);
  assert.deepEqual(Array.from(graph.edges), c.edges.flat());
  assert.equal(graph.initial, undefined);
  // The identity's information on every edge: κ = 3 / (2 tr I₃) = ½ (MATH.md, SE-Sync's
  // weights), so the same optimum at half the cost.
  assert.ok(graph.weights.every((w) => w === 0.5));
  const result = synchronizeRotations(graph);
  assert.ok(Math.abs(result.cost - c.cost / 2) < 1e-9 * c.cost);
  assert.equal(result.certificate.certified, true);
});

test("the flow settles on the certified optimum", () => {
  const c = fixture.cases.find((c) => c.name === "random-30");
  const flow = new SyncFlow({ edges: c.edges, relative: c.relative, weights: c.weights }, { seed: 4 });
  let last = flow.cost;
  for (let k = 0; k < 200; k++) {
    flow.step(0.02, 25);
    assert.ok(flow.cost <= last + 1e-12, "the flow never raises the cost");
    last = flow.cost;
  }
  assert.ok(Math.abs(flow.cost - c.cost) < 1e-9 * c.cost, `${flow.cost} vs ${c.cost}`);
  assert.equal(flow.hopfPoints().length, 3 * c.count);
  flow.free();
});

test("with every relative rotation the identity, the robust answer is consensus", () => {
  const n = 12;
  const edges = Array.from({ length: n }, (_, i) => [i, (i + 1) % n]);
  const result = synchronizeRotations({ edges, relative: edges.map(() => [1, 0, 0, 0]) }, { method: "robust" });
  for (let i = 0; i < n; i++) {
    const q = Array.from(result.rotations.subarray(4 * i, 4 * i + 4));
    assert.ok(Math.max(...q.map((x, k) => Math.abs(x - [1, 0, 0, 0][k]))) < 1e-15, `node ${i}: ${q}`);
  }
  assert.ok(result.cost < 1e-28, `${result.cost}`);
  assert.ok(result.outliers.every((o) => o === 0));
});

// Pose-graph files of each kind, as a user's files hold them: 3D with vertices and information,
// 2D g2o with landmarks, TORO 2D in both orders of its information, other kinds skipped or
// refused, and a bad line's number as the Error's `line`.
test("pose graphs of every kind are read and synchronised as they are", () => {
  // A 3D square (four quarter turns about z) with vertices and a rotation information
  // diag(400, 400, 400): κ = 3 / (2 tr Σ_R) = 3 / (2 · 3/400) = 200 on every edge.
  const info3 = "1 0 0 0 0 0 1 0 0 0 0 1 0 0 0 400 0 0 400 0 400";
  const r = Math.SQRT1_2;
  const square = [
    "# a square",
    ...[0, 1, 2, 3].map((i) => `VERTEX_SE3:QUAT ${i} 0 0 0 0 0 ${Math.sin((i * Math.PI) / 4)} ${Math.cos((i * Math.PI) / 4)}`),
    ...[0, 1, 2, 3].map((i) => `EDGE_SE3:QUAT ${i} ${(i + 1) % 4} 1 0 0 0 0 ${r} ${r} ${info3}`),
  ].join("\n");
  const graph = readG2o(square);
  assert.equal(graph.dimension, 3);
  assert.ok(Array.from(graph.weights).every((w) => Math.abs(w - 200) < 1e-12), `${graph.weights}`);
  const chordal = synchronizeRotations(graph);
  assert.ok(chordal.cost < 1e-20 && chordal.certificate.certified, "MATH.md's square: f = 0, certified");
  // The flow starts at the vertices, which agree with every edge: it is at rest at f = 0.
  const flow = new SyncFlow(graph);
  assert.ok(flow.cost < 1e-20, `${flow.cost}`);
  flow.free();

  // 2D, g2o, with landmarks among the poses' ids: poses 0, 2, 4 on a triangle with a 0.6 rad
  // loop error and rotation information 1, 2, 4. The chordal optimum balances κ sin θ (Lagrange).
  const planar = [
    "VERTEX_SE2 0 0 0 0", "VERTEX_XY 1 5 5", "VERTEX_SE2 2 1 0 0", "VERTEX_XY 3 6 6", "VERTEX_SE2 4 0 1 0",
    "EDGE_SE2 0 2 1 0 0.2 1 0 0 1 0 1", "EDGE_SE2_XY 0 1 5 5 1 0 1",
    "EDGE_SE2 2 4 -1 1 0.2 1 0 0 1 0 2", "EDGE_SE2_XY 2 3 5 6 1 0 1",
    "EDGE_SE2 4 0 0 -1 0.2 1 0 0 1 0 4", "EDGE_PRIOR_SE2 0 0 0 0 1 0 0 1 0 1",
  ].join("\n");
  const g2 = readG2o(planar);
  assert.equal(g2.dimension, 2);
  assert.deepEqual(Array.from(g2.ids), [0, 2, 4]);
  assert.deepEqual(Array.from(g2.edges), [0, 1, 1, 2, 2, 0]);
  assert.deepEqual(g2.skipped, { VERTEX_XY: 2, EDGE_SE2_XY: 2, EDGE_PRIOR_SE2: 1 });
  assert.deepEqual(Array.from(g2.weights), [1, 2, 4]);
  assert.deepEqual(Array.from(g2.translations.subarray(3, 6)), [-1, 1, 0]);
  const solved = synchronizeRotations(g2);
  const balance = Array.from(solved.residuals, (t, k) => g2.weights[k] * Math.sin(t));
  assert.ok(Math.max(...balance) - Math.min(...balance) < 1e-9, `${balance}`);
  assert.ok(Math.abs(solved.residuals.reduce((a, b) => a + b) - 0.6) < 1e-9);
  // Weights of the caller's own win.
  const even = synchronizeRotations({ ...g2, weights: [1, 1, 1] });
  assert.ok(Array.from(even.residuals).every((t) => Math.abs(t - 0.2) < 1e-9), `${even.residuals}`);

  // TORO's EDGE2, its information diag(3, 3, 5) written in g2o's order and in TORO's.
  for (const info of ["3 0 0 3 0 5", "3 0 3 5 0 0"]) {
    const g = readG2o(`VERTEX2 0 0 0 0\nVERTEX2 1 1 0 0\nEDGE2 0 1 1 0 0 ${info}`);
    assert.equal(g.weights[0], 5, info);
    assert.ok(Math.abs(g.translationWeights[0] - 3) < 1e-12, info);
  }

  // Strict refuses the landmark, by its line; every refusal carries the line.
  assert.throws(() => readG2o(planar, { strict: true }), (e) => e.kind === "invalid" && e.line === 2 && /^text line 2: "VERTEX_XY"/.test(e.message));
  assert.throws(() => readG2o("EDGE_SE2 0 1 0 0 0\nEDGE_SE3:QUAT 1 2 0 0 0 0 0 0 1"), (e) => e.line === 2 && /2D one/.test(e.message));
  assert.throws(() => readG2o("EDGE_SE2 0 1 0 0 0 1 0 0 1 0 -5"), (e) => e.line === 1 && /rotation block is not positive definite/.test(e.message));
  assert.throws(() => readG2o("LANDMARK 0 1 2 3\n"), (e) => e.line === undefined && /skipped were LANDMARK \(1\)/.test(e.message));
  assert.throws(() => readG2o(planar, { strict: "yes" }), (e) => e.argument === "strict");
});

test("the sync results are typed by method under tsc --strict: the README's code compiles", async () => {
  const { mkdtempSync, writeFileSync } = await import("node:fs");
  const { execFileSync } = await import("node:child_process");
  const { tmpdir } = await import("node:os");
  const { join } = await import("node:path");
  const dir = mkdtempSync(join(tmpdir(), "kli-sync-types-"));
  const from = new URL("sync.js", pkg).pathname;
  writeFileSync(join(dir, "use.ts"), `
    import { readG2o, synchronizeRotations, SyncFlow, synchronizePoses, writeG2o, isKliError, type PoseGraph, type PoseGraphInput, type SynchronizedPoses, type SyncMethod } from ${JSON.stringify(from)};
    declare const text: string;
    declare const method: SyncMethod;
    // The README's code, as written.
    const graph: PoseGraph = readG2o(text);
    const { rotations, certificate } = synchronizeRotations(graph);
    const certified: boolean = certificate.certified;
    const { outliers } = synchronizeRotations(graph, { method: "robust" });
    const flagged: number = outliers.reduce((a, b) => a + b, 0);
    const chordal: boolean = synchronizeRotations(graph, { method: "chordal", anchor: 3 }).certificate.certified;
    const flow = new SyncFlow(graph);
    const skipped: number | undefined = graph.skipped["VERTEX_XY"];
    try { readG2o(text); } catch (e) { if (isKliError(e)) { const line: number | undefined = e.line; void line; } }
    // @ts-expect-error: the spectral relaxation has no certificate
    synchronizeRotations(graph, { method: "spectral" }).certificate.certified;
    // @ts-expect-error: a method known only when run: the certificate may be absent
    synchronizeRotations(graph, { method }).certificate.certified;
    // @ts-expect-error: the chordal optimum flags no outliers
    synchronizeRotations(graph).outliers.length;
    // Pose graphs: a PoseGraph is their input as it is, a result their poses as it is.
    const poses = synchronizePoses(graph, { anchor: 0, maxRank: 10, order: "xyzw" });
    const poseCertified: boolean = poses.certificate.certified;
    const rank: number = poses.certificate.rank;
    const positions: Float64Array = poses.translations;
    const saved: string = writeG2o(graph, poses, { order: "xyzw" });
    const plain: PoseGraphInput = { dimension: 2, edges: [[0, 1]], relative: [[1, 0, 0, 0]], translations: [[1, 0, 0]] };
    const written: string = writeG2o(plain, { rotations: [[1, 0, 0, 0], [1, 0, 0, 0]], translations: [0, 0, 0, 1, 0, 0] });
    const typed: SynchronizedPoses = poses;
    // @ts-expect-error: the dimension is 2 or 3
    synchronizePoses({ ...plain, dimension: 4 });
    // @ts-expect-error: pose options have no method
    synchronizePoses(graph, { method: "robust" });
    // @ts-expect-error: the certificate has no gap
    poses.certificate.gap;
    void [rotations, certified, flagged, chordal, flow, skipped, poseCertified, rank, positions, saved, written, typed];
  `);
  writeFileSync(join(dir, "tsconfig.json"), JSON.stringify({
    compilerOptions: { strict: true, noEmit: true, module: "nodenext", moduleResolution: "nodenext", target: "es2022", lib: ["es2022"], types: [], skipLibCheck: false },
    files: ["use.ts"],
  }));
  const tsc = new URL("../../node_modules/.bin/tsc", import.meta.url).pathname;
  try {
    execFileSync(tsc, ["-p", "tsconfig.json"], { cwd: dir, encoding: "utf8" });
  } catch (e) {
    assert.fail(`tsc: ${e.stdout}${e.stderr}`);
  }
});

// Pose graphs (synchronizePoses, writeG2o) through the package: CSAIL to MATH.md's optimum, a 3D
// grid to bench/posegraph_reference.py's (src/sync/poses/tests.rs), certified; the README's
// square; a graph written and read back as it was; hostile input naming itself.
const posegraphs = new URL("../fixtures/posegraphs/", import.meta.url);
const fixtureText = (name) => readFileSync(new URL(name, posegraphs), "utf8");

test("synchronizePoses reaches CSAIL's and smallGrid3D's certified optima, z = 0 in 2D", () => {
  const csail = synchronizePoses(readG2o(fixtureText("CSAIL.g2o")));
  assert.ok(Math.abs(csail.cost - 31.70372) <= 1e-6 * 31.70372, `${csail.cost}`);
  assert.equal(csail.certificate.certified, true);
  assert.equal(csail.certificate.rank, 2);
  assert.equal(csail.rotations.length, 4 * 1045);
  assert.equal(csail.translations.length, 3 * 1045);
  for (let i = 0; i < 1045; i++) assert.equal(csail.translations[3 * i + 2], 0);
  const reference = 1025.39805563;
  const graph = readG2o(fixtureText("smallGrid3D.g2o"), { order: "xyzw" });
  const grid = synchronizePoses(graph, { order: "xyzw", anchor: 3 });
  assert.ok(Math.abs(grid.cost - reference) <= 1e-9 * reference, `${grid.cost}`);
  assert.equal(grid.certificate.certified, true);
  assert.deepEqual(Array.from(grid.rotations.subarray(12, 16)), [0, 0, 0, 1]);
  assert.deepEqual(Array.from(grid.translations.subarray(9, 12)), [0, 0, 0]);
  assert.equal(typeof grid.iterations, "number");
  assert.ok(grid.certificate.lambdaMin >= -grid.certificate.tolerance);
});

test("the README's square: four quarter turns a unit step apart, f = 0, certified", () => {
  const H = Math.SQRT1_2;
  const info = "1 0 0 0 0 0 1 0 0 0 0 1 0 0 0 400 0 0 400 0 400";
  const lines = [0, 1, 2, 3].map((i) => `VERTEX_SE3:QUAT ${i} 0 0 0 0 0 ${Math.sin((i * Math.PI) / 4)} ${Math.cos((i * Math.PI) / 4)}`);
  for (let i = 0; i < 4; i++) lines.push(`EDGE_SE3:QUAT ${i} ${(i + 1) % 4} 1 0 0 0 0 ${H} ${H} ${info}`);
  const { rotations, translations, cost, certificate } = synchronizePoses(readG2o(lines.join("\n")));
  assert.ok(cost < 1e-20 && certificate.certified, `${cost}`);
  const corners = [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0];
  assert.ok(corners.every((x, k) => Math.abs(translations[k] - x) < 1e-12), `${translations}`);
  assert.ok(Math.abs(rotations[4] - H) < 1e-12 && Math.abs(rotations[7] - H) < 1e-12, `${rotations}`);
});

test("writeG2o's file reads back as the graph it came from, the poses its vertices", () => {
  for (const [name, order] of [["CSAIL.g2o", "wxyz"], ["tinyGrid3D.g2o", "xyzw"]]) {
    const graph = readG2o(fixtureText(name), { order });
    const result = synchronizePoses(graph, { order });
    const text = writeG2o(graph, result, { order });
    const kind = graph.dimension === 2 ? "VERTEX_SE2 " : "VERTEX_SE3:QUAT ";
    assert.equal(text.split("\n").filter((l) => l.startsWith(kind)).length, graph.count);
    const again = readG2o(text, { order, strict: true });
    assert.equal(again.dimension, graph.dimension);
    assert.deepEqual(Array.from(again.ids), Array.from(graph.ids));
    assert.deepEqual(Array.from(again.edges), Array.from(graph.edges));
    assert.deepEqual(Array.from(again.translations), Array.from(graph.translations));
    const close = (key, a, b, tolerance) => a.forEach((x, k) => assert.ok(Math.abs(x - b[k]) <= tolerance * (1 + Math.abs(b[k])), `${name} ${key}[${k}]: ${x} vs ${b[k]}`));
    close("weights", again.weights, graph.weights, 1e-14);
    close("translationWeights", again.translationWeights, graph.translationWeights, 1e-14);
    close("relative", again.relative, graph.relative, 1e-14);
    close("initial", again.initial, result.rotations, 1e-14);
    assert.deepEqual(Array.from(again.positions), Array.from(result.translations));
    const resolved = synchronizePoses(again, { order });
    assert.ok(Math.abs(resolved.cost - result.cost) <= 1e-9 * result.cost, `${name}: ${resolved.cost} vs ${result.cost}`);
  }
});

test("hostile input to synchronizePoses and writeG2o is refused naming the argument", () => {
  const H = Math.SQRT1_2;
  const base = { dimension: 3, edges: [[0, 1], [1, 2]], relative: [[1, 0, 0, 0], [H, 0, 0, H]], translations: [[1, 0, 0], [0, 1, 0]] };
  assert.ok(synchronizePoses(base).certificate.certified);
  const refuses = (call, argument, kind = undefined) => assert.throws(call, (e) => {
    assert.ok(e instanceof Error, `${e}`);
    assert.equal(e.argument, argument, e.message);
    if (kind) assert.equal(e.kind, kind, e.message);
    assert.ok(e.message.startsWith(argument), e.message);
    return true;
  });
  refuses(() => synchronizePoses(7), "input");
  refuses(() => synchronizePoses([base]), "input");
  refuses(() => synchronizePoses({ ...base, extra: 1 }), "input");
  refuses(() => synchronizePoses({ ...base, dimension: "3" }), "dimension");
  refuses(() => synchronizePoses({ ...base, dimension: undefined }), "dimension");
  refuses(() => synchronizePoses({ ...base, translations: undefined }), "translations");
  refuses(() => synchronizePoses({ ...base, translations: [[1, 0, 0], [0, NaN, 0]] }), "translations[1]");
  refuses(() => synchronizePoses({ ...base, relative: [[1, 0, 0, 0], [NaN, 0, 0, 1]] }), "relative[1]", "not-finite");
  refuses(() => synchronizePoses({ ...base, relative: [[1, 0, 0, 0], [0, 0, 0, 0]] }), "relative[1]", "zero-length");
  refuses(() => synchronizePoses({ ...base, weights: [1, -1] }), "weights[1]", "out-of-range");
  refuses(() => synchronizePoses({ ...base, translationWeights: [Infinity, 1] }), "translationWeights[0]", "out-of-range");
  refuses(() => synchronizePoses({ ...base, edges: [[0, 1], [1, -2]] }), "edges[1]");
  refuses(() => synchronizePoses({ ...base, edges: [[0, 1], [2, 2]] }), "edges[1]");
  refuses(() => synchronizePoses({ ...base, count: 5 }), "edges");
  refuses(() => synchronizePoses({ ...base, edges: [[0, 1], [2, 3]] }), "edges");
  refuses(() => synchronizePoses(base, { anchor: 3 }), "anchor");
  refuses(() => synchronizePoses(base, { anchor: 0.5 }), "anchor");
  refuses(() => synchronizePoses(base, { maxRank: 1 }), "maxRank");
  refuses(() => synchronizePoses(base, { order: "zyxw" }), "order", "unknown-name");
  refuses(() => synchronizePoses(base, { method: "robust" }), "options");
  refuses(() => synchronizePoses({ ...base, dimension: 2, relative: [[1, 0, 0, 0], [H, H, 0, 0]] }), "relative[1]");
  const getter = { ...base, get relative() { throw new Error("no"); } };
  refuses(() => synchronizePoses(getter), "relative");
  const poses = synchronizePoses(base);
  refuses(() => writeG2o(base, null), "poses");
  refuses(() => writeG2o(base, { ...poses, rotations: poses.rotations.subarray(4) }), "rotations");
  refuses(() => writeG2o(base, { ...poses, translations: [0, 0, 0, 1, 0, 0, 1, 1, NaN] }), "translations[2]");
  refuses(() => writeG2o({ ...base, ids: [3, 2, 1] }, poses), "ids[1]");
  refuses(() => writeG2o({ ...base, count: 2 ** 32 - 1 }, poses), "rotations");
  refuses(() => writeG2o(base, poses, { strict: true }), "options");
  // The module keeps working after every refusal.
  assert.equal(writeG2o({ ...base, ids: [7, 8, 9] }, poses).split("\n")[0].split(" ")[1], "7");
});

test("synchronizePoses and writeG2o: 1,500 seeded hostile calls, each a result or an Error naming its argument, no trap", () => {
  let x = 41;
  const next = () => { x ^= x << 13; x ^= x >>> 17; x ^= x << 5; x >>>= 0; return x / 4294967296; };
  const H = Math.SQRT1_2;
  const base = { dimension: 3, edges: [[0, 1], [1, 2], [2, 0]], relative: [[1, 0, 0, 0], [H, 0, 0, H], [H, 0, 0, -H]], translations: [[1, 0, 0], [0, 1, 0], [-1, -1, 0]] };
  const { cost } = synchronizePoses(base);
  const poses = synchronizePoses(base);
  const revoked = (() => { const { proxy, revoke } = Proxy.revocable([], {}); revoke(); return proxy; })();
  const throwing = () => new Proxy({}, { get() { throw new Error("get trap"); }, has() { throw new Error("has trap"); }, ownKeys() { throw new Error("ownKeys trap"); } });
  const getterArray = () => { const a = [1, 0, 0, 0]; Object.defineProperty(a, 2, { get() { throw new Error("element getter"); } }); return a; };
  const values = [
    () => NaN, () => Infinity, () => -1, () => 1e308, () => 5e-324, () => -0, () => 2 ** 53, () => 2 ** 32, () => 0.5, () => 3, () => 2,
    () => 10n, () => Symbol("s"), () => "3", () => "", () => null, () => undefined, () => true, () => ({}), () => [],
    () => ({ length: Infinity }), () => ({ length: 1e9 }), () => ({ length: -1 }), () => ({ length: 3, 0: 1, 1: 0, 2: 0 }),
    () => throwing(), () => revoked, () => getterArray(), () => new DataView(new ArrayBuffer(32)), () => new BigInt64Array(4),
    () => new Int32Array([0, 1, 1, 2]), () => new Float32Array([1, 0, 0, 0]), () => new Float64Array(0), () => new Float64Array(9),
    () => [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]], () => [[0, 1], [1, 1e9]], () => [[1, 0, NaN], [0, 1, 0], [0, 0, 0]],
    () => [0, 0, 0, 0], () => [1, 2, 3], () => [1e300, 1e-300, 1], () => [-1, 1, 1], () => ({ x: 0, y: 0, z: 0, w: 1 }),
    () => new Proxy([0, 1], { get(t, k) { synchronizePoses(base); return Reflect.get(t, k); } }), () => function f() {}, () => [0, , 2],
  ];
  const hostile = () => values[Math.floor(next() * values.length)]();
  const keys = ["dimension", "edges", "relative", "translations", "weights", "translationWeights", "count", "ids", "initial", "information"];
  let errors = 0;
  for (let i = 0; i < 1500; i++) {
    const value = hostile();
    const key = keys[Math.floor(next() * keys.length)];
    const calls = [
      () => synchronizePoses(value), () => synchronizePoses(base, value), () => synchronizePoses({ ...base, [key]: value }),
      () => synchronizePoses(base, { anchor: value }), () => synchronizePoses(base, { maxRank: value }), () => synchronizePoses(base, { order: value }),
      () => writeG2o({ ...base, [key]: value }, poses), () => writeG2o(base, value), () => writeG2o(base, { ...poses, rotations: value }),
      () => writeG2o(base, { ...poses, translations: value }), () => writeG2o(base, poses, value),
    ];
    let result;
    try {
      result = calls[Math.floor(next() * calls.length)]();
    } catch (e) {
      assert.ok(e instanceof Error && !(e instanceof WebAssembly.RuntimeError), `call ${i}: ${e}`);
      if (typeof e.argument !== "string") continue; // a hostile getter's own Error, passed on
      assert.equal(typeof e.kind, "string", e.message);
      assert.ok(e.message.startsWith(e.argument), e.message);
      errors++;
      continue;
    }
    if (typeof result === "string") assert.match(result, /^VERTEX_SE3:QUAT \d+ /);
    else {
      assert.ok(Number.isFinite(result.cost) && result.cost >= 0, `${result.cost}`);
      assert.ok(result.rotations.every(Number.isFinite) && result.translations.every(Number.isFinite));
    }
  }
  assert.ok(errors > 500, `only ${errors} refusals`);
  assert.equal(synchronizePoses(base).cost, cost, "the module is still right");
});
