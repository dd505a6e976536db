// The longest task each page runs on hostile input (the URLs and figures of
// tests/e2e/hostile-urls.mjs, which the tests check for what they show), beside the previous
// release's pages in the same run, alternating. The target: no task over 200 ms, or over 1.5
// times the longest task of the page's own plain load where that is more (a cold load of a page
// has one task of 110–240 ms on this 2-core machine: the browser's parsing, style and layout).
// Each figure is the median over `loads` cold loads of the longest task of a load, read from a
// trace of the page's main thread (bench/main-thread.mjs; until 2026-11-28 from Chromium's
// long-task timing, which leaves out the rasterising of the canvases a task drew to).
//   node bench/long-tasks.mjs [loads]
import { median, record } from "./targets.mjs";
import { existsSync } from "node:fs";
import { join } from "node:path";
import { chromium } from "playwright-core";
import { CHROMIUM } from "../scripts/static-server.mjs";
import { servePages } from "./previous.mjs";
import { PAGES } from "../www/pages.js";
import { FIGURES, FIGURES_DONE, HEAVY, seededQueries } from "../tests/e2e/hostile-urls.mjs";
import { TRACED, tasksOver } from "./main-thread.mjs";
import { engage } from "../tests/e2e/browser.mjs";

const loads = Number(process.argv[2] ?? 3);
const FLOOR = 200;

const browser = await chromium.launch(CHROMIUM);
const { builds, close } = await servePages();

/** The longest task of one cold load of `path` from `origin`, ms; `figures` puts FIGURES into
 *  the page and waits for them. */
async function longest(origin, path, { settle = 300, figures = false } = {}) {
  const context = await browser.newContext({ viewport: { width: 1280, height: 900 }, reducedMotion: "reduce" });
  try {
    const page = await context.newPage();
    await browser.startTracing(page, { categories: TRACED });
    await page.goto(`${origin}/${path}`);
    // The reader arrives (a page's motion waits for its pointer), as in the tests.
    await engage(page);
    if (figures) {
      await page.evaluate((html) => document.querySelector("article").insertAdjacentHTML("afterbegin", html), FIGURES);
      await page.waitForFunction(FIGURES_DONE, null, { timeout: 60000 });
    }
    await page.waitForTimeout(settle);
    return Math.max(0, ...tasksOver(await browser.stopTracing(), 0).tasks.map((task) => task.ms));
  } finally {
    await context.close();
  }
}

/** The median over `loads` loads of `path`'s longest task, for each build that has the page. */
async function measure(path, options) {
  const runs = builds.map(() => []);
  for (let k = 0; k < loads; k++) {
    for (const [b, [, origin, dir]] of builds.entries()) {
      if (!existsSync(join(dir, path.split("?")[0]))) continue;
      // The previous release may lack what a newer test asks of its page (a figure's property):
      // it is then reported as having no such page, never holding up ours.
      try {
        runs[b].push(await longest(origin, path, options));
      } catch (error) {
        if (b === 0) throw error;
      }
    }
  }
  return runs.map((xs) => (xs.length ? median(xs) : undefined));
}

const ms = (x) => (x === undefined ? "no such page" : `${x} ms`);
try {
  for (const page of PAGES) {
    const [plain, plainThen] = await measure(page.html);
    const budget = Math.max(FLOOR, Math.round(1.5 * plain));
    let worst = 0, worstQuery = "", then = 0;
    for (const query of seededQueries(page)) {
      const [ours, theirs] = await measure(query);
      if (ours >= worst) [worst, worstQuery] = [ours, query];
      if (theirs !== undefined) then = Math.max(then, theirs);
    }
    const reference = plainThen === undefined ? "no such page" : `${then} ms (plain load ${plainThen} ms)`;
    console.log(`${page.html}, 10 seeded hostile URLs: longest task ${worst} ms (${worstQuery}); plain load ${plain} ms; ` +
      `budget ${budget} ms; ${builds[1][0]} ${reference}`);
    record(`${page.html}: no task over ${budget} ms on 10 hostile URLs (200 ms, or 1.5 × its plain load's ${plain} ms)`,
      `${worst} ms`, `${builds[1][0]}: ${reference}`, worst <= budget);
  }
  for (const [query] of HEAVY) {
    const html = query.split("?")[0];
    const [[plain], [ours, theirs]] = [await measure(html), await measure(query, { settle: 1500 })];
    const budget = Math.max(FLOOR, Math.round(1.5 * plain));
    console.log(`${query.slice(0, 60)}: longest task ${ours} ms; budget ${budget} ms; ${builds[1][0]} ${ms(theirs)}`);
    record(`${query.slice(0, 60)}: no task over ${budget} ms`, `${ours} ms`, `${builds[1][0]}: ${ms(theirs)}`, ours <= budget);
  }
  const [plain] = await measure("examples/figures.html");
  const [ours, theirs] = await measure("examples/figures.html", { settle: 500, figures: true });
  const budget = Math.max(FLOOR, Math.round(1.5 * plain));
  console.log(`<kli-figure>, hostile attributes and far times: longest task ${ours} ms; budget ${budget} ms; ${builds[1][0]} ${ms(theirs)}`);
  record(`<kli-figure> with hostile attributes and far times: no task over ${budget} ms`, `${ours} ms`, `${builds[1][0]}: ${ms(theirs)}`, ours <= budget);
} finally {
  await browser.close();
  close();
}
