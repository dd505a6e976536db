// End-to-end tests of the synchronisation page (sync.html, made from www/sync/) in Debian's headless Chromium;
// its pose-graph section's are poses.test.mjs's.
import { test } from "node:test";
import assert from "node:assert/strict";
import { join } from "node:path";
import { axeViolations, canvasStats, keepShot, open, painted, setup } from "./browser.mjs";

setup();

/** The residual classes' colours (crates/kli-demo/src/sync/view.rs): under 2°, and 45° or more. */
const CLASSES = { blue: [59, 91, 219], red: [201, 42, 42] };
const atOptimum = (page) => page.waitForFunction(() => document.querySelector("#readout").textContent.includes("at the chordal optimum"),
  undefined, { timeout: 60000 });
const number = (text, pattern) => Number(text.match(pattern)?.[1]);
/** Waits for the run's solutions (a worker computes them) and returns the note they fill. */
const solved = async (page) => {
  await page.waitForFunction(() => !document.querySelector("#note").textContent.endsWith("Solving…"), undefined, { timeout: 60000 });
  return page.textContent("#note");
};

test("the flow turns a random start into agreement, on the certified chordal optimum", async () => {
  const { page, context, problems } = await open("sync.html?n=60&graph=random&noise=1&wrong=0&seed=3");
  // At the random start nearly every edge is far off: red edges, hardly a blue one.
  assert.match(await page.textContent("#readout"), /^t = 0\.00 /);
  const start = await canvasStats(page, "#sync-graph", CLASSES);
  assert.ok(start.red > 4 * start.blue && start.red > 2000, JSON.stringify(start));
  for (const selector of ["#sync-hopf", "#sync-plots", "#sync-objects"]) {
    assert.ok((await canvasStats(page, selector)).drawn > 3000, selector);
  }
  const note = await solved(page);
  // The results view is drawn from the worker's solutions (until then its first picture shows,
  // the canvas blank: the test below), so only once they have come.
  assert.ok(await painted(page, "#sync-results", 3000), "#sync-results");
  assert.match(note, /^60 nodes, \d+ edges, 0 wrong\. Chordal: [\d.]+° median error, certified the global optimum/);
  await page.click("#play");
  await atOptimum(page);
  await page.click("#play");
  // Where the flow arrived, its error to the truth is the chordal solution's (computed apart, by
  // Newton's method), and its edges are within the noise: blue.
  const readout = await page.textContent("#readout");
  const flow = number(readout, /median error ([\d.]+)°/);
  const chordal = number(note, /Chordal: ([\d.]+)°/);
  assert.ok(Math.abs(flow - chordal) < 0.05, `${readout} / ${note}`);
  assert.ok(chordal < 1.5, note);
  const end = await canvasStats(page, "#sync-graph", CLASSES);
  assert.ok(end.blue > 4 * end.red && end.blue > 2000, JSON.stringify(end));
  await keepShot(page, "sync.png");
  assert.deepEqual(problems, []);
  await context.close();
});

test("with wrong edges the robust solution sets them aside and is nearer the truth; consensus agrees", async () => {
  const { page, context, problems } = await open("sync.html");
  assert.equal(await page.inputValue("[name=preset]"), "wrong");
  assert.match(page.url(), /n=100&graph=random&noise=5&wrong=0\.1&seed=1/);
  const note = await solved(page);
  const [wrong, caught, good] = [/(\d+) wrong\./, /flags (\d+) of the/, /and (\d+) good ones/].map((p) => number(note, p));
  assert.ok(wrong > 40 && caught >= 0.9 * wrong && good <= 3, note);
  assert.ok(number(note, /Robust: ([\d.]+)°/) < number(note, /Chordal: ([\d.]+)°/), note);
  // Consensus: every measurement 1, the noise and the share moot; the flow agrees on one rotation.
  await page.selectOption("[name=preset]", "consensus");
  await page.waitForURL(/consensus=1/);
  assert.equal(await page.isDisabled("[name=noise]"), true);
  assert.match(await solved(page), /, 0 wrong\. Chordal: 0\.00° median error/);
  await page.click("#play");
  await atOptimum(page);
  // Arrived is f ≤ 1e-6: about 0.002° an edge, summed along the grid's slowest mode.
  const agreed = await page.textContent("#readout");
  assert.ok(number(agreed, /median error ([\d.]+)°/) < 0.05, agreed);
  // A refused value stays beside its field.
  await page.fill("[name=seed]", "1.5");
  assert.match(await page.textContent("#seed-error"), /^seed must be a whole number/);
  assert.deepEqual(problems, []);
  await context.close();
});

test("until its solutions come, the first run's results view keeps its first picture; a new run takes it away", async () => {
  // The worker's script held back until released: the first run waits for its solutions.
  /** @type {() => void} */
  let release = () => {};
  const held = new Promise((resolve) => { release = () => resolve(undefined); });
  const { page, context, problems } = await open("sync.html", {
    prepare: (context) => context.route(/\/runtime\/worker\.js$/, async (route) => { await held; await route.continue(); }),
  });
  try {
    assert.match(await page.textContent("#note"), /Solving…$/);
    // The views that need no solutions are drawn, and their pictures gone; the results' stays.
    await page.waitForFunction(() => !document.querySelector("#sync-graph-first"));
    await page.evaluate(() => new Promise((resolve) => setTimeout(resolve, 200)));
    assert.equal(await page.locator("#sync-results-first").count(), 1, "the results' first picture while solving");
    const covered = await page.evaluate(() => {
      const canvas = /** @type {HTMLCanvasElement} */ (document.querySelector("#sync-results"));
      return canvas.getContext("2d")?.getImageData(0, 0, canvas.width, canvas.height).data.some((value, i) => i % 4 === 3 && value > 0);
    });
    assert.equal(covered, false, "nothing drawn over it");
    // Printed meanwhile, the map's place says that it is being solved (it threw before).
    await page.emulateMedia({ media: "print" });
    // The figures' SVGs come in the print query's change event, a task after the switch.
    await page.waitForFunction(() => document.querySelectorAll(".print-figure svg").length > 0);
    const titles = await page.evaluate(() => Array.from(document.querySelectorAll(".print-figure svg title"), (title) => title.textContent));
    assert.ok(titles.includes("Solving the built-in robot's loop…"), titles.join(" | "));
    await page.emulateMedia({ media: "screen" });
    assert.deepEqual(problems, []);
    release();
    await solved(page);
    await page.waitForFunction(() => !document.querySelector("#sync-results-first"));
    assert.ok((await canvasStats(page, "#sync-results")).drawn > 3000, "the solutions drawn");
  } finally {
    release();
    await context.close();
  }
  // A new run before the first one's solutions: the picture (of the first run) goes at once.
  let again = () => {};
  const heldAgain = new Promise((resolve) => { again = () => resolve(undefined); });
  const second = await open("sync.html", {
    prepare: (context) => context.route(/\/runtime\/worker\.js$/, async (route) => { await heldAgain; await route.continue(); }),
  });
  try {
    assert.equal(await second.page.locator("#sync-results-first").count(), 1);
    await second.page.fill("[name=seed]", "9");
    await second.page.waitForURL(/seed=9/);
    await second.page.waitForFunction(() => !document.querySelector("#sync-results-first"));
    again();
    assert.match(await solved(second.page), /nodes/);
    assert.deepEqual([...problems, ...second.problems], []);
  } finally {
    again();
    await second.context.close();
  }
});

test("each run is solved in a worker while the flow runs, the sweep too; without a worker, on the page, alike", async () => {
  const notes = [];
  for (const worker of [true, false]) {
    const { page, context, problems } = await open("sync.html?n=150&graph=random&noise=4&wrong=0.2&seed=5", {
      init: () => {
        // What the page saw before its solutions came: the note, the results view's state.
        window.__early = [];
        new MutationObserver(() => window.__early.push(document.querySelector("#note")?.textContent ?? "")).observe(document, { subtree: true, childList: true, characterData: true });
      },
      prepare: (context) => context.route(/\/runtime\/worker\.js$/, (route) => (worker ? route.continue() : route.abort())),
    });
    const note = await solved(page);
    if (worker) assert.deepEqual(page.workers().map((w) => new URL(w.url()).pathname), ["/runtime/worker.js"]);
    // The run was on show, unsolved, before its solutions came.
    assert.ok(await page.evaluate(() => window.__early.some((text) => text.endsWith("wrong. Solving…"))), "the note said Solving… first");
    assert.match(note, /^150 nodes, \d+ edges, \d+ wrong\. Chordal: [\d.]+° median error, (certified|not proved)/);
    notes.push(note);
    // The sweep fills itself the same way.
    await page.waitForFunction(() => document.querySelector("#sweep-status").textContent.startsWith("Done"), undefined, { timeout: 120000 });
    assert.equal(await page.locator("#sweep-table tbody tr").count(), 11);
    assert.ok((await canvasStats(page, "#sync-results")).drawn > 3000, "the solutions drawn");
    // A new run supersedes the one being solved: only its solutions are shown.
    await page.fill("[name=seed]", "6");
    await page.fill("[name=seed]", "7");
    await page.waitForURL(/seed=7/);
    assert.match(await solved(page), /^150 nodes/);
    const expected = worker ? [] : [problems.find((p) => /failed: .*worker\.js/.test(p))];
    assert.deepEqual(problems, expected.filter(Boolean));
    await context.close();
  }
  assert.equal(notes[0], notes[1], "the worker's solutions are the page's own");
  // What a run takes as its solutions, hostile: each refused by name, the run still working.
  const { page, context } = await open("sync.html?n=20&graph=ring&noise=1&wrong=0&seed=1");
  const refusals = await page.evaluate(async () => {
    const { SyncDemo, SyncFile } = await import("./pkg/sync_demo.js");
    const run = SyncDemo.unsolved({ count: 20, graph: "ring" });
    const good = SyncDemo.solve({ count: 20, graph: "ring" });
    const trap = new Proxy([], { get() { throw new Error("trap"); } });
    const other = Float64Array.from(good, (x, i) => (i === 0 ? 21 : x));
    const bad = [null, "abc", trap, [1, 2], new Float64Array(good.length).fill(NaN), other, new Float64Array(good.length + 1)];
    const arguments_ = [];
    for (let k = 0; k < 700; k++) {
      try { run.takeSolutions(bad[k % bad.length]); arguments_.push("taken"); } catch (error) { arguments_.push(error instanceof Error ? error.argument : "not an Error"); }
    }
    // A user's pose graph from its numbers likewise (a ring of 20: SyncFile.solve's numbers).
    const ring = Array.from({ length: 20 }, (_, i) => `EDGE_SE3:QUAT ${i} ${(i + 1) % 20} 0 0 0 0 0 0.0523359562 0.9986295348 ${"1 0 0 0 0 0 1 0 0 0 0 1 0 0 0 1 0 0 1 0 1"}`).join("\n");
    const fileGood = SyncFile.solve(ring);
    // Its own kinds of wrong too: a count of skipped lines not whole, the count left out.
    const fileBad = [...bad, Float64Array.from(fileGood, (x, i) => (i === 0 ? 0.5 : x)), fileGood.slice(1)];
    for (let k = 0; k < 90; k++) {
      try { SyncFile.solved(fileBad[k % fileBad.length]).free(); arguments_.push("taken"); } catch (error) { arguments_.push(error instanceof Error ? error.argument : "not an Error"); }
    }
    // Its text must be a string: anything else refused naming text (a number or an object
    // trapped in the glue's string copy before).
    const texts = new Set();
    for (let k = 0; k < 400; k++) {
      const text = [null, 42, {}, trap][k % 4];
      for (const call of [() => SyncFile.solve(text), () => new SyncFile(text)]) {
        try { call(); texts.add("taken"); } catch (error) { texts.add(error instanceof Error ? error.argument : "not an Error"); }
      }
    }
    const file = SyncFile.solved(fileGood);
    const fileSolved = file.summary.certified && file.summary.count === 20;
    file.free();
    run.takeSolutions(good);
    run.advance(0.5);
    const s = run.summary;
    run.free();
    return { arguments: [...new Set(arguments_)], solved: s.solved, certified: s.certified, moved: s.time > 0, fileSolved, texts: [...texts] };
  });
  assert.deepEqual(refusals, { arguments: ["solutions"], solved: true, certified: true, moved: true, fileSolved: true, texts: ["text"] });
  await context.close();
});

test("WCAG 2.2 AA, and at 390 px", async () => {
  const { page, context } = await open("sync.html");
  assert.deepEqual(await axeViolations(page), []);
  await context.close();
  const narrow = await open("sync.html", { viewport: { width: 390, height: 844 } });
  assert.ok(await narrow.page.evaluate(() => document.documentElement.scrollWidth <= 390), "no horizontal scrolling");
  assert.deepEqual(await axeViolations(narrow.page), []);
  await keepShot(narrow.page, "sync-390px.png");
  await narrow.context.close();
});

test("<kli-figure view=\"sync\">: the page's graph in any page, its state as attributes, a refused one named", async () => {
  const { page, context, problems } = await open("examples/figures.html");
  const drawn = await page.evaluate(async () => {
    const figure = document.createElement("kli-figure");
    figure.setAttribute("view", "sync");
    figure.setAttribute("count", "30");
    figure.setAttribute("graph", "grid");
    figure.setAttribute("t", "2");
    figure.style.width = "360px";
    document.body.append(figure);
    const started = performance.now();
    while (!(figure.run && Math.abs(figure.t - 2) < 1e-9) && performance.now() - started < 20000) await new Promise((r) => setTimeout(r, 50));
    const canvas = figure.shadowRoot.querySelector("canvas");
    const data = canvas.getContext("2d").getImageData(0, 0, canvas.width, canvas.height).data;
    let drawn = 0;
    for (let i = 0; i < data.length; i += 4) if (data[i] < 250 || data[i + 1] < 250 || data[i + 2] < 250) drawn++;
    const refused = new Promise((resolve) => figure.addEventListener("kli-error", (event) => resolve(event.detail?.message ?? String(event.detail)), { once: true }));
    figure.setAttribute("wrong", "2");
    return { drawn, count: figure.run.summary.count, edges: figure.run.summary.edges, t: figure.t, refused: await refused };
  });
  // A 30-node grid (6 × 5): 5 · 5 across and 6 · 4 down.
  assert.equal(drawn.count, 30);
  assert.equal(drawn.edges, 49);
  assert.ok(Math.abs(drawn.t - 2) < 1e-9, `t = ${drawn.t}`); // a sum of steps of 0.1/d_max
  assert.ok(drawn.drawn > 3000, JSON.stringify(drawn));
  assert.match(drawn.refused, /wrong/);
  assert.deepEqual(problems, []);
  await context.close();
});

test("the complete graph is refused past 120 nodes (7,140 edges), beside the count", async () => {
  const { page, context, problems } = await open("sync.html?n=200&graph=complete");
  assert.match(await page.textContent("#count-error"), /^count must be at most 120 for the complete graph \(7140 edges; got 200\)/);
  assert.match(await page.textContent("#note"), /^100 nodes, \d+ edges/, "the preset's run stands in");
  assert.deepEqual(problems, []);
  await context.close();
});
