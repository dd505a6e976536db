// The synchronisation page's map of a 10⁴-pose file: the longest main-thread task from opening
// the file to its map drawn, and the solve's time, beside the previous release in the same run.
// The target: no main-thread task over 50 ms. The file is GTSAM's
// w10000.graph (10,000 poses, 64,311 edges, 2D), from the wheel in the bench's Python
// environment, opened as a reader opens one (the file input); each figure is the median over
// `loads` cold loads (5 by default). The tasks counted run from the file's opening to its map
// drawn, and on until the page has synchronised the file's rotations alone (both ways, in its
// worker) and drawn them, read from a trace of the page's main thread (bench/main-thread.mjs:
// Chromium's long-task timing gave 56 ms for the map's task where the main thread was busy 110).
//   node bench/map-tasks.mjs [loads] [commit]   (commit: the pages measured beside ours, if not
//                                               the previous release's, which have no map)
import { execFileSync } from "node:child_process";
import { existsSync } from "node:fs";
import { join } from "node:path";
import { chromium } from "playwright-core";
import { CHROMIUM } from "../scripts/static-server.mjs";
import { median, record } from "./targets.mjs";
import { python } from "./python.mjs";
import { servePages } from "./previous.mjs";
import { TRACED, tasksOver } from "./main-thread.mjs";
import { engage } from "../tests/e2e/browser.mjs";

const loads = Number(process.argv[2] ?? 5);
const BUDGET = 50;
const NAME = "w10000.graph";

const path = execFileSync(python(), ["-c", `import gtsam; print(gtsam.findExampleDataFile('${NAME}'))`], { encoding: "utf8" }).trim();

const browser = await chromium.launch(CHROMIUM);
const { builds, close } = await servePages(process.argv[3] ? { name: "commit", commit: process.argv[3] } : undefined);

/** One cold load of sync.html from `origin` with the file opened once the built-in map is
 *  shown: `{ longest, tasks, map, after, seconds }`, the longest task over 50 ms (0: none)
 *  from the file's opening to its rotations alone shown, those tasks (ms), those up to the map
 *  drawn and after it, and the map's solve time as the page says it; null when the build's page
 *  has no map. */
async function openFile(origin) {
  const context = await browser.newContext({ viewport: { width: 1280, height: 900 }, reducedMotion: "reduce" });
  try {
    const page = await context.newPage();
    await page.goto(`${origin}/sync.html`);
    await engage(page);
    if (!(await page.$("#sync-map"))) return null;
    // The map's section starts the built-in graph when it comes near the screen.
    await page.locator("#file-section").scrollIntoViewIfNeeded();
    const solved = (name) => page.waitForFunction((name) => {
      const status = document.querySelector("#file-status").textContent;
      return status.startsWith(`${name}:`) && /solved in/.test(status);
    }, name, { timeout: 300000 });
    await solved("The built-in robot's loop");
    await page.waitForTimeout(500);
    await browser.startTracing(page, { categories: TRACED });
    // By its path, as a reader picks a file: the browser makes the File (a buffer would be
    // decoded by the driver's script in the page, a task of its own the page never runs).
    await page.setInputFiles("#file-input", path);
    await solved(NAME);
    // The map is drawn in the tasks after its status (a large one a part a task): a second on,
    // it is whole.
    await page.waitForTimeout(1000);
    await page.evaluate(() => performance.mark("kli-map-drawn"));
    const seconds = Number((await page.textContent("#file-status")).match(/solved in ([\d.]+) s/)[1]);
    // Then the file's rotations alone, synchronised both ways in the worker and drawn.
    await page.waitForFunction(() => !document.querySelector("#file-figure").hidden, null, { timeout: 600000 });
    await page.waitForTimeout(500);
    const { tasks, mark } = tasksOver(await browser.stopTracing(), BUDGET, "kli-map-drawn");
    const [map, after] = [tasks.filter((t) => t.at < mark), tasks.filter((t) => t.at >= mark)].map((ts) => ts.map((t) => t.ms));
    return { longest: Math.max(0, ...map, ...after), tasks: [...map, ...after], map, after, seconds };
  } finally {
    await context.close();
  }
}

try {
  const runs = builds.map(() => []);
  for (let k = 0; k < loads; k++) {
    for (const [b, [, origin, dir]] of builds.entries()) {
      if (!existsSync(join(dir, "sync.html"))) continue;
      const run = await openFile(origin);
      if (run) runs[b].push(run);
      console.log(`${builds[b][0]}, load ${k + 1}: ${run ? `tasks over 50 ms: to the map ${run.map.join(", ") || "none"}, then ${run.after.join(", ") || "none"}; solved in ${run.seconds} s` : "no map"}`);
    }
  }
  // Only tasks over 50 ms are kept: 0 is a load with none.
  const longest = (ms) => (ms === 0 ? "no task over 50 ms" : `longest task ${ms} ms`);
  const summary = (xs) => (xs.length
    ? `${longest(median(xs.map((x) => x.longest)))}, solved in ${median(xs.map((x) => x.seconds))} s (medians of ${xs.length})`
    : "no map on its page");
  const ours = median(runs[0].map((x) => x.longest));
  console.log(`${NAME} on sync.html: ours ${summary(runs[0])}; ${builds[1][0]} ${summary(runs[1])}`);
  record(`sync.html: a 10⁴-pose file (${NAME}) mapped with no main-thread task over ${BUDGET} ms`,
    `${summary(runs[0])}; each load's tasks over 50 ms: ${runs[0].map((x) => x.tasks.join(" and ") || "none").join("; ")}`,
    `${builds[1][0]}: ${summary(runs[1])}`, ours <= BUDGET);
} finally {
  await browser.close();
  close();
}
