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
const { synchronizeRotations, readG2o, SyncFlow } = sync;
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
