// End-to-end tests of the synchronisation page's pose-graph section, "Your own pose graph"
// (sync.html, made from www/sync/): a user's file opened or dropped, the map of the built-in
// graph and of files, its saves, and a 10,000-pose graph solved in the worker, in Debian's headless
// Chromium. A file of its own beside sync.test.mjs (the page's rotations), so that the two run
// side by side: together they were the longest file of the suite.
import { test } from "node:test";
import assert from "node:assert/strict";
import { readFile } from "node:fs/promises";
import { join } from "node:path";
import { canvasStats, open, painted, root, setup } from "./browser.mjs";

setup();

/** Four nodes a quarter turn apart about z: every edge's relative rotation is the same quarter
 *  turn, and the truth costs 0 (MATH.md's square). */
const SQUARE = [[0, 1], [1, 2], [2, 3], [3, 0]]
  .map(([i, j]) => `EDGE_SE3:QUAT ${i} ${j} 1 0 0 0 0 ${Math.SQRT1_2} ${Math.SQRT1_2} ${"1 0 0 0 0 0 1 0 0 0 0 1 0 0 0 1 0 0 1 0 1"}`)
  .join("\n");

test("a user's own pose graph, opened or dropped, is synchronised in the page's worker, with its certificate and residuals", async () => {
  const { page, context, problems } = await open("sync.html", {
    // The calls the page sends its worker (runtime/offload.js), by name.
    init: () => {
      window.__sent = [];
      const post = Worker.prototype.postMessage;
      Worker.prototype.postMessage = function (message, ...rest) {
        window.__sent.push(`${message?.target}.${message?.call}`);
        return post.call(this, message, ...rest);
      };
    },
  });
  assert.equal(await page.isHidden("#file-figure"), true, "no empty figure before a file");
  await page.setInputFiles("#file-input", { name: "square.g2o", mimeType: "text/plain", buffer: Buffer.from(SQUARE) });
  await page.waitForFunction(() => document.querySelector("#file-status").textContent.includes("rotations alone certified"));
  assert.match(await page.textContent("#file-status"), /^square\.g2o: 4 poses, 4 edges; the map certified \(solved in [\d.]+ s\); its rotations alone certified\.$/);
  const rows = Object.fromEntries(await page.$$eval("#file-table tr", (trs) => trs.map((tr) => [tr.cells[0].textContent, tr.cells[1].textContent])));
  assert.ok(Math.abs(Number(rows["Chordal cost f"])) < 1e-20, JSON.stringify(rows));
  assert.match(rows.Certificate, /^certified/);
  assert.ok((await canvasStats(page, "#sync-file")).drawn > 3000);
  assert.ok(await page.evaluate(() => window.__sent.includes("SyncFile.solve") && window.__sent.includes("SyncMap.solve")), "solved in the worker");
  // A 2D graph with landmarks: poses 0, 2, 4 (ids past the landmarks' 1 and 3), the landmark lines
  // set aside and counted.
  const planar = [
    "VERTEX_SE2 0 0 0 0", "VERTEX_XY 1 5 5", "VERTEX_SE2 2 1 0 0", "VERTEX_XY 3 6 6", "VERTEX_SE2 4 0 1 0",
    "EDGE_SE2 0 2 1 0 0.2 1 0 0 1 0 1", "EDGE_SE2_XY 0 1 5 5 1 0 1", "EDGE_SE2 2 4 -1 1 0.2 1 0 0 1 0 2", "EDGE_SE2 4 0 0 -1 0.2 1 0 0 1 0 4",
  ].join("\n");
  await page.setInputFiles("#file-input", { name: "planar.g2o", mimeType: "text/plain", buffer: Buffer.from(planar) });
  await page.waitForFunction(() => /^planar\.g2o: .*rotations alone certified/.test(document.querySelector("#file-status").textContent));
  assert.match(await page.textContent("#file-status"), /^planar\.g2o: 3 poses, 3 edges \(3 other lines skipped: landmarks, priors\); the map certified/);
  // Dropped: a bad line is refused with its number, and the graph on show stays.
  await page.evaluate(() => {
    const data = new DataTransfer();
    data.items.add(new File(["# a comment\nEDGE_SE3:QUAT 0 1 0 0\n"], "bad.g2o"));
    document.querySelector("#file-section").dispatchEvent(new DragEvent("drop", { dataTransfer: data, bubbles: true, cancelable: true }));
  });
  await page.waitForFunction(() => /^bad\.g2o: .*line/.test(document.querySelector("#file-status").textContent));
  assert.match(await page.textContent("#file-status"), /^bad\.g2o: .*line 2/);
  assert.equal(await page.isHidden("#file-figure"), false);
  assert.deepEqual(problems, []);
  await context.close();
});

/** The map's table, heading → value. */
const mapTable = async (page) => Object.fromEntries(await page.$$eval("#map-table tr", (trs) => trs.map((tr) => [tr.cells[0].textContent, tr.cells[1].textContent])));
/** Waits for the map of `name` (a status that starts with it and says how long it took). */
const mapOf = (page, name) => page.waitForFunction((name) => {
  const status = document.querySelector("#file-status").textContent;
  return status.startsWith(`${name}:`) && /solved in/.test(status);
}, name, { timeout: 120000 });
/** Scrolls to the map's section, which starts the built-in graph there (not at load), and waits
 *  for its map. */
const builtIn = async (page) => {
  await page.locator("#file-section").scrollIntoViewIfNeeded();
  await mapOf(page, "The built-in robot's loop");
};
/** Clicks a save button of the map and returns the download's name and text. */
async function savedMap(page, selector) {
  const [download] = await Promise.all([page.waitForEvent("download"), page.click(selector)]);
  return { name: download.suggestedFilename(), text: (await readFile(await download.path())).toString("utf8") };
}
/** Waits until the map's picture (a hash of its pixels, as canvasStats makes it) passes
 *  `which(hash, value)`, and returns that hash (or the last one, after 10 s). */
const mapPicture = (page, which, value) => page.waitForFunction(([which, value]) => {
  const canvas = document.querySelector("#sync-map");
  const data = canvas.getContext("2d").getImageData(0, 0, canvas.width, canvas.height).data;
  let hash = 0;
  for (let i = 0; i < data.length; i += 4) hash = (hash * 31 + data[i] + 7 * data[i + 1] + 13 * data[i + 2]) % 1000000007;
  return new Function(`return (${which})`)()(hash, value) && hash;
}, [which.toString(), value], { timeout: 10000 }).then((handle) => handle.jsonValue(), () => NaN);
const fixture = (name) => readFile(join(root, "tests/fixtures/posegraphs", name));

test("the map: the built-in robot's loop solved before any file, a 2D and a 3D file, the certificate, the .g2o and CSV saves", async () => {
  const { page, context, problems } = await open("sync.html");
  // Never an empty figure: the words saying it is solving, or the map.
  assert.ok(await painted(page, "#sync-map", 50), "the map's canvas says something from the start");
  // The built-in graph is made and solved as its section nears the screen (the other tests
  // scroll there), or, never reached, 10 s after the page's start: not at load.
  const began = await page.evaluate(() => new Promise((resolve) => {
    const status = document.querySelector("#file-status");
    if (status.textContent) resolve(-performance.now());
    new MutationObserver(() => resolve(performance.now())).observe(status, { childList: true, characterData: true, subtree: true });
  }));
  assert.ok(began >= 10000, `the built-in graph started ${began} ms after navigation`);
  // Before any file: the built-in pose graph, solved in the worker, drawn, certified. Its size
  // is its route's (24 blocks of 8 m, a pose a metre: 192 poses, 191 odometry edges) and the
  // loop closures asked for (8).
  await mapOf(page, "The built-in robot's loop");
  assert.ok(await painted(page, "#sync-map", 5000), "the map is drawn");
  let rows = await mapTable(page);
  assert.equal(rows.Poses, "192 (2D)");
  assert.match(rows.Edges, /^199, of which 8 join/);
  assert.match(rows.Certificate, /^certified: λmin\(S\) = /);
  assert.equal(rows["Initial estimate"], "the odometry chained from pose 0");
  const [initial, optimum] = rows["Cost f: initial, optimum"].split(", ").map(Number);
  assert.ok(optimum > 0 && initial > 10 * optimum, rows["Cost f: initial, optimum"]);
  // Certified: the proven lower bound is the cost, to the certificate's tolerance.
  const bound = Number(rows["Proven lower bound on the least cost"]);
  assert.ok(bound <= optimum && bound > 0.99 * optimum, `${bound} against ${optimum}`);
  // The built-in graph's truth is known: the loop closures bring the map nearer it.
  const [far, near] = rows["Distance from the true path (RMS): initial, optimum"].split(", ").map(parseFloat);
  assert.ok(near < far, rows["Distance from the true path (RMS): initial, optimum"]);
  // The map in the Save list: vector drawing with both panels and the key, named for its graph.
  const svg = await savedMap(page, 'button[data-save="map"][data-format="svg"]');
  assert.equal(svg.name, "kli-built-in-pose-graph-map.svg");
  assert.match(svg.text, /^<svg[^]*initial: the odometry chained[^]*the certified optimum[^]*edge misfit/);
  assert.ok((svg.text.match(/<path /g) ?? []).length >= 4 && !/NaN/.test(svg.text));
  const png = await savedMap(page, 'button[data-save="map"][data-format="png"]');
  assert.equal(png.name, "kli-built-in-pose-graph-map.png");
  // No loop closures: a chain, which the odometry fits exactly (cost 0 to rounding).
  await page.fill("#world-closures", "0");
  await page.waitForFunction(() => document.querySelector("#map-table").textContent.includes("191, of which 0"));
  rows = await mapTable(page);
  assert.ok(Number(rows["Cost f: initial, optimum"].split(", ")[1]) < 1e-9, rows["Cost f: initial, optimum"]);
  // CSAIL (2D, 1,045 poses): SE-Sync's optimum, 31.70372 (MATH.md, by NumPy's LM), certified.
  await page.setInputFiles("#file-input", { name: "CSAIL.g2o", mimeType: "text/plain", buffer: await fixture("CSAIL.g2o") });
  await mapOf(page, "CSAIL.g2o");
  rows = await mapTable(page);
  assert.equal(rows.Poses, "1045 (2D)");
  assert.equal(rows["Distance from the true path (RMS): initial, optimum"], undefined, "a file's truth is not known");
  assert.equal(rows["Initial estimate"], "the odometry chained from pose 0", "CSAIL.g2o has no VERTEX lines");
  const csail = Number(rows["Cost f: initial, optimum"].split(", ")[1]);
  assert.ok(Math.abs(csail - 31.70372) < 1e-3, rows["Cost f: initial, optimum"]);
  assert.match(rows.Certificate, /^certified/);
  // The optimum saved as .g2o: the file's edges and the optimum's VERTEX lines, which, opened
  // again, are the initial estimate at the optimum's cost.
  const g2o = await savedMap(page, "#save-g2o");
  assert.equal(g2o.name, "CSAIL-optimum.g2o");
  assert.equal(g2o.text.split("\n").filter((line) => line.startsWith("VERTEX_SE2 ")).length, 1045);
  await page.setInputFiles("#file-input", { name: "again.g2o", mimeType: "text/plain", buffer: Buffer.from(g2o.text) });
  await mapOf(page, "again.g2o");
  rows = await mapTable(page);
  assert.equal(rows["Initial estimate"], "the file's own (its VERTEX lines)");
  const [before, after] = rows["Cost f: initial, optimum"].split(", ").map(Number);
  assert.ok(Math.abs(before - csail) < 1e-3 && Math.abs(after - csail) < 1e-3, rows["Cost f: initial, optimum"]);
  // The CSV: a header and a row a pose, pose 0 at the origin.
  const csv = await savedMap(page, "#save-poses-csv");
  const lines = csv.text.trim().split("\n").filter((line) => !line.startsWith("#"));
  assert.equal(lines[0], "id,x,y,z,qx,qy,qz,qw");
  assert.equal(lines.length, 1046);
  assert.deepEqual(lines[1].split(",").map(Number), [0, 0, 0, 0, 0, 0, 0, 1]);
  // A 3D grid: turnable, by the keys too (the picture changes), certified.
  const previous = await mapPicture(page, () => true, 0);
  await page.setInputFiles("#file-input", { name: "tinyGrid3D.g2o", mimeType: "text/plain", buffer: await fixture("tinyGrid3D.g2o") });
  await mapOf(page, "tinyGrid3D.g2o");
  rows = await mapTable(page);
  assert.match(rows.Poses, /\(3D\)$/);
  assert.match(rows.Certificate, /^certified/);
  assert.equal(await page.getAttribute("#sync-map", "role"), "application");
  assert.equal(await page.isHidden("#map-views"), false, "a 3D map's views are offered");
  // The grid's own first picture (not the graph's before it, still on the canvas for a frame).
  const first = await mapPicture(page, (hash, previous) => hash !== previous, previous);
  await page.focus("#sync-map");
  await page.keyboard.press("ArrowLeft");
  await page.keyboard.press("ArrowUp");
  const turned = await mapPicture(page, (hash, first) => hash !== first, first);
  assert.equal(await page.textContent("#readout").then((text) => text.startsWith("t = 0.00")), true, "the keys turned the map, not the time");
  // From above: the grid's floor plan, a picture of its own; back to the oblique view it opened with.
  await page.click("#map-above");
  const above = await mapPicture(page, (hash, turned) => hash !== turned, turned);
  await page.click("#map-oblique");
  assert.ok(Number.isFinite(turned) && Number.isFinite(above), "the keys and 'From above' turned the map");
  assert.equal(await mapPicture(page, (hash, first) => hash === first, first), first, "oblique is the first view again");
  // No NaN anywhere in the section's words.
  assert.doesNotMatch(await page.textContent("#file-section"), /NaN|undefined|Infinity/);
  assert.deepEqual(problems, []);
  await context.close();
});

/** A 10,000-pose 2D graph: a robot mowing a 100 m × 100 m field in rows a metre apart (a pose a
 *  metre, 9,999 odometry edges), with a loop closure to the row before every 4 m (2,475), each
 *  measurement off by seeded noise (0.5° and 2 cm). No VERTEX lines: the odometry chained is its
 *  initial estimate. */
function mowedField() {
  let seed = 7;
  const uniform = () => {
    seed = (seed + 0x6d2b79f5) | 0;
    let t = Math.imul(seed ^ (seed >>> 15), 1 | seed);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
  const noise = (scale) => scale * (uniform() + uniform() + uniform() - 1.5);
  const poses = [];
  for (let row = 0; row < 100; row++) {
    for (let k = 0; k < 100; k++) {
      const east = row % 2 === 0;
      // The row's last pose turns north, to the next row's first (a metre up).
      const heading = k === 99 ? Math.PI / 2 : east ? 0 : Math.PI;
      poses.push([east ? k : 99 - k, row, heading]);
    }
  }
  const between = ([xa, ya, ta], [xb, yb, tb]) => {
    const [c, s, dx, dy] = [Math.cos(ta), Math.sin(ta), xb - xa, yb - ya];
    return [c * dx + s * dy, -s * dx + c * dy, Math.atan2(Math.sin(tb - ta), Math.cos(tb - ta))];
  };
  const edges = poses.slice(1).map((_, i) => [i, i + 1]);
  for (let row = 1; row < 100; row++) {
    for (let x = 2; x < 100; x += 4) {
      const at = (r) => r * 100 + (r % 2 === 0 ? x : 99 - x);
      edges.push([at(row - 1), at(row)]);
    }
  }
  const lines = edges.map(([i, j]) => {
    const [x, y, t] = between(poses[i], poses[j]);
    return `EDGE_SE2 ${i} ${j} ${x + noise(0.02)} ${y + noise(0.02)} ${t + noise(0.009)} 2500 0 0 2500 0 13000`;
  });
  return { text: lines.join("\n"), edges: edges.length };
}

test("a 10,000-pose graph solves in the worker, its stages in the status, the page answering meanwhile", async () => {
  const { page, context, problems } = await open("sync.html");
  await builtIn(page);
  const field = mowedField();
  assert.equal(field.edges, 9999 + 2475);
  // Every word the status says, the page's long tasks, and the frames' longest gap (for the
  // message) while the worker solves.
  await page.evaluate(() => {
    const status = document.querySelector("#file-status");
    Object.assign(window, { __said: [], __gap: 0, __done: false, __from: 0, __to: 0, __tasks: [] });
    new PerformanceObserver((list) => window.__tasks.push(...list.getEntries().map((t) => [t.startTime, t.duration])))
      .observe({ type: "longtask" });
    new MutationObserver(() => {
      window.__said.push(status.textContent);
      if (!window.__from) window.__from = performance.now();
      // The worker's last stage: from here the page reads the answer and draws the map.
      if (!window.__done && /the translations|solved in/.test(status.textContent)) {
        window.__done = true;
        window.__to = performance.now();
      }
    }).observe(status, { childList: true, characterData: true, subtree: true });
    let last = performance.now();
    const tick = (now) => {
      if (window.__done) return;
      window.__gap = Math.max(window.__gap, now - last);
      last = now;
      requestAnimationFrame(tick);
    };
    requestAnimationFrame(tick);
  });
  await page.setInputFiles("#file-input", { name: "field.g2o", mimeType: "text/plain", buffer: Buffer.from(field.text) });
  await mapOf(page, "field.g2o");
  const { said, gap, solve, longest } = await page.evaluate(() => ({
    said: window.__said, gap: window.__gap, solve: window.__to - window.__from,
    longest: Math.max(0, ...window.__tasks.filter(([start]) => start >= window.__from && start < window.__to).map(([, d]) => d)),
  }));
  for (const stage of [/: reading…/, /: the chordal start/, /: trust region at rank 2, step 1…/, /: the certificate at rank 2…/]) {
    assert.ok(said.some((words) => stage.test(words)), `${stage} in ${JSON.stringify(said)}`);
  }
  // The page's own tasks stay short while the worker solves: none as long as half the solve
  // (solved on the page instead, one task was the whole solve). Its tasks, not its frames: with
  // the solve down to 0.4 s, a busy machine (two test files at once) once left a 733 ms gap
  // between frames, and with the worker taken away the gap was 100 ms of a 292 ms solve on the
  // page, where its longest task was 275 ms. Not a fixed budget either: a busy machine
  // stretches every task (the page's own reading of the answer and drawing of the map, after,
  // are not counted).
  assert.ok(solve > 0 && longest < solve / 2,
    `the longest task of the page's while solving: ${longest} ms of ${solve} ms (longest frame gap ${gap} ms)`);
  const rows = await mapTable(page);
  assert.equal(rows.Poses, "10000 (2D)");
  assert.match(rows.Edges, /^12474, of which 2475 join/);
  assert.match(rows.Certificate, /^certified/);
  assert.ok(await painted(page, "#sync-map", 5000), "the map is drawn");
  // Its 24,948 segments (its two panels) are more than the page draws in one task: they are
  // drawn in parts, a task each, the key under the map in the last. The key's dark text comes,
  // so the drawing was not left half done.
  const key = await page.waitForFunction(() => {
    const canvas = /** @type {HTMLCanvasElement} */ (document.querySelector("#sync-map"));
    const strip = Math.round(24 * devicePixelRatio);
    const data = canvas.getContext("2d").getImageData(0, canvas.height - strip, canvas.width, strip).data;
    let ink = 0;
    for (let i = 0; i < data.length; i += 4) if (data[i] < 90 && data[i + 1] < 90 && data[i + 2] < 90 && data[i + 3] > 0) ink++;
    return ink > 100 && ink;
  }, null, { timeout: 10000 }).then((handle) => handle.jsonValue(), () => 0);
  assert.ok(key > 100, `the key under the map is drawn: ${key} dark pixels`);
  // The parts after the first drew over it: the left panel's trajectory, drawn in the first
  // parts, is still there once the last is drawn.
  const left = await page.evaluate(() => {
    const canvas = /** @type {HTMLCanvasElement} */ (document.querySelector("#sync-map"));
    const [w, h] = [Math.round(canvas.width / 2), Math.round(canvas.height * 0.8)];
    const data = canvas.getContext("2d").getImageData(0, Math.round(canvas.height * 0.1), w, h - Math.round(canvas.height * 0.1)).data;
    let ink = 0;
    for (let i = 0; i < data.length; i += 4) if (data[i] < 200 || data[i + 1] < 200 || data[i + 2] < 200) ink++;
    return ink;
  });
  assert.ok(left > 2000, `the left panel keeps its drawing: ${left} pixels`);
  assert.deepEqual(problems, []);
  await context.close();
});
