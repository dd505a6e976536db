// kli/sync beside GTSAM, Theia and COLMAP on the same graphs, in one run (the anchors in the
// bench's own Python environment, bench/python.mjs; kli in wasm under Node):
// - GTSAM's sphere2500 (2,500 nodes, 4,949 edges): the chordal optimum, certified, against GTSAM's
//   chordal initialisation + Levenberg–Marquardt, Shonan averaging and Theia's Lagrange dual;
// - synthetic graphs in the style of Chatterjee and Govindu (100 and 1,000 nodes, about 10
//   neighbours a node, σ = 2° and 5°, 10/20/30% of the edges replaced by random rotations):
//   `method: "robust"` against Theia's L1-IRLS and hybrid, COLMAP 4's rotation averaging and
//   GTSAM's GNC-TLS and Shonan: the median and mean error to the truth, and the outlier flags.
//   node bench/sync.mjs
import { readFileSync } from "node:fs";
import { gzipSync } from "node:zlib";
import { median, record } from "./targets.mjs";
import { runPython } from "./python.mjs";

const root = new URL("../", import.meta.url).pathname;
const sync = await import(`${root}pkg/sync.js`);
sync.initSync({ module: readFileSync(`${root}pkg/sync_bg.wasm`) });
const { synchronizeRotations } = sync;

const { graphs } = JSON.parse(runPython("sync_anchors.py", { mode: "graphs" }).toString());

/** kli's result and its median time over `rounds` runs (after one unmeasured run). */
function timed(graph, options, rounds) {
  const input = { edges: graph.edges, relative: graph.relative, count: graph.count };
  let result = synchronizeRotations(input, options);
  const times = [];
  for (let k = 0; k < rounds; k++) {
    const start = performance.now();
    result = synchronizeRotations(input, options);
    times.push(performance.now() - start);
  }
  return { result, seconds: median(times) / 1000 };
}

const kli = {};
for (const graph of graphs) {
  const sphere = graph.name === "sphere2500";
  const methods = sphere ? ["chordal"] : ["robust", "chordal", "spectral"];
  kli[graph.name] = {};
  for (const method of methods) {
    const { result, seconds } = timed(graph, { method }, sphere ? 7 : 3);
    kli[graph.name][`kli ${method}`] = {
      seconds, rotations: Array.from(result.rotations), certificate: result.certificate,
      outliers: result.outliers && Array.from(result.outliers),
    };
  }
}
const { versions, rows } = JSON.parse(runPython("sync_anchors.py", { mode: "anchors", graphs, kli }).toString());
console.log(`anchors: GTSAM ${versions.gtsam}, pycolmap ${versions.pycolmap}, pytheia ${versions.pytheia}; kli in wasm under Node ${process.version}`);

const ms = (s) => `${(1000 * s).toFixed(s < 0.1 ? 1 : 0)} ms`;
for (const row of rows) {
  console.log(`\n${row.name}\n| method | time | chordal cost | median error | mean error |\n| --- | --- | --- | --- | --- |`);
  for (const [name, m] of Object.entries(row.methods)) {
    if (m.error) { console.log(`| ${name} | failed: ${m.error} | | | |`); continue; }
    const error = (x) => (x === undefined ? "" : `${x.toFixed(2)}°`);
    console.log(`| ${name} | ${ms(m.seconds)} | ${m.cost.toFixed(6)} | ${error(m.median)} | ${error(m.mean)}${m.missing ? ` (${m.missing} nodes lost)` : ""} |`);
  }
}

// sphere2500: the optimum, certified, and faster than GTSAM's chordal + LM.
const sphere = rows.find((r) => r.name === "sphere2500").methods;
const ours = sphere["kli chordal"];
const certificate = kli.sphere2500["kli chordal"].certificate;
const best = Math.min(...Object.values(sphere).filter((m) => !m.error).map((m) => m.cost));
const lm = sphere["GTSAM chordal + LM"], shonan = sphere["GTSAM Shonan"];
record("sphere2500 chordal: cost ≤ the optimum + 1e-6 (relative), certified",
  `${ours.cost.toFixed(7)}, ${certificate.certified ? "certified" : "not certified"} (λ₄ = ${certificate.gap.toExponential(3)})`,
  `best of all ${best.toFixed(7)}; GTSAM LM ${lm.cost?.toFixed(7)}, Shonan ${shonan.cost?.toFixed(7)}`,
  ours.cost <= best * (1 + 1e-6) && certificate.certified);
record("sphere2500 chordal, wasm under Node: faster than GTSAM chordal + LM",
  ms(ours.seconds), `GTSAM chordal + LM ${ms(lm.seconds)}, Shonan ${shonan.seconds ? ms(shonan.seconds) : "failed"}`,
  ours.seconds < lm.seconds);

// Robust, on the 1,000-node graphs: errors within 5% (median) and 10% (mean) of the best anchor,
// the far-off edges flagged, and faster than Theia's L1-IRLS at 30%.
const ROBUST_ANCHORS = ["Theia L1-IRLS", "Theia hybrid", "GTSAM GNC-TLS", "COLMAP"];
for (const row of rows.filter((r) => r.name.startsWith("1000 nodes"))) {
  const m = row.methods["kli robust"];
  const anchors = ROBUST_ANCHORS.map((name) => [name, row.methods[name]]).filter(([, a]) => a && !a.error && !a.missing);
  const bestMedian = Math.min(...anchors.map(([, a]) => a.median)), bestMean = Math.min(...anchors.map(([, a]) => a.mean));
  const who = (key, value) => anchors.find(([, a]) => a[key] === value)?.[0];
  record(`${row.name}, robust: median error ≤ 1.05 × the best anchor's, mean ≤ 1.10 ×`,
    `${m.median.toFixed(2)}°, mean ${m.mean.toFixed(2)}°`,
    `${bestMedian.toFixed(2)}° (${who("median", bestMedian)}), mean ${bestMean.toFixed(2)}° (${who("mean", bestMean)})`,
    m.median <= 1.05 * bestMedian && m.mean <= 1.1 * bestMean);
  record(`${row.name}, robust: ≥ 95% of the edges > 15° off flagged, ≤ 1% of the flagged within 10°`,
    `${(100 * m.far_flagged).toFixed(1)}% flagged, ${(100 * m.good_among_flagged).toFixed(2)}% of them good`, "",
    m.far_flagged >= 0.95 && m.good_among_flagged <= 0.01);
  if (row.name.endsWith("σ 5°, 30% wrong")) {
    const theia = row.methods["Theia L1-IRLS"];
    record(`${row.name}, robust: faster than Theia's L1-IRLS`, ms(m.seconds), `Theia L1-IRLS ${ms(theia.seconds)}`, m.seconds < theia.seconds);
  }
}

const bytes = ["sync.js", "sync_bg.wasm"].reduce((sum, f) => sum + gzipSync(readFileSync(`${root}pkg/${f}`), { level: 9 }).length, 0);
console.log(`\nkli/sync, gzipped: ${bytes.toLocaleString("en")} B (sync.js + sync_bg.wasm)`);
