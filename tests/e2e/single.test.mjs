// `make single`'s pages opened as a teacher opens them from a USB stick: from file://, with every
// request other than the file itself refused, each page must load its module and draw.
import { test, before, after } from "node:test";
import assert from "node:assert/strict";
import { existsSync } from "node:fs";
import { copyFile, mkdir, mkdtemp, readFile, writeFile } from "node:fs/promises";
import { tmpdir } from "node:os";
import { dirname, join } from "node:path";
import { pathToFileURL } from "node:url";
import { chromium } from "playwright-core";
import { TEST_CHROMIUM } from "../../scripts/static-server.mjs";
import { painted, root } from "./browser.mjs";
import { PAGES } from "../../www/pages.js";

let browser;
before(async () => (browser = await chromium.launch(TEST_CHROMIUM)));
after(async () => browser?.close());

/** Drawn pixels of each visible canvas on the page: painted (not transparent, as a canvas starts) and
 *  not white. A figure that sets itself up as it nears the screen (the tour's) is scrolled to
 *  first. */
const drawn = async (page) => {
  // Not a figure hidden until it has something to show (the synchronisation page's own file).
  const ids = await page.evaluate(() => Array.from(document.querySelectorAll("canvas"))
    .filter((canvas) => canvas.checkVisibility()).map((canvas) => canvas.id));
  const counts = [];
  for (const id of ids) {
    await page.locator(`canvas#${id}`).scrollIntoViewIfNeeded();
    counts.push({ id, count: await painted(page, `canvas#${id}`, 0, 5000) });
  }
  return counts;
};

for (const { html: name } of PAGES) {
  test(`dist/single/${name} works from file:// with no server and no network`, async () => {
    const file = join(root, "dist/single", name);
    assert.ok(existsSync(file), `${file} is missing: run make single`);
    const context = await browser.newContext({ viewport: { width: 1280, height: 900 } });
    const page = await context.newPage();
    const problems = [];
    const url = pathToFileURL(file).href;
    await context.route("**/*", (route) => {
      if (route.request().url() === url) return route.continue();
      problems.push(`request: ${route.request().url()}`);
      return route.abort();
    });
    page.on("console", (m) => m.type() === "error" && problems.push(`console: ${m.text()}`));
    page.on("pageerror", (e) => problems.push(`pageerror: ${e.message}`));
    try {
      await page.goto(url);
      await page.waitForFunction(() => document.querySelector("#load-status").hidden, null, { timeout: 10000 });
      await page.waitForTimeout(300);
      for (const { id, count } of await drawn(page)) assert.ok(count > 100, `${name}: canvas #${id} is blank`);
      if (name === "index.html") {
        // The paper's example, computed in the file: T = 11.66 and Table 1's corrected row.
        assert.match(await page.locator("#final-time").textContent(), /^T = 11\.66 after 1166 steps/);
        assert.match(await page.locator("#moments").textContent(), /0\.4364 \+ 0\.4364i \+ 0\.4364j \+ 0\.6548k/);
      }
      assert.deepEqual(problems, []);
    } finally {
      await context.close();
    }
  });
}

test("dist/single/kli-figure.js: one classic script, the element with every module inside, works from file://", async () => {
  const script = join(root, "dist/single/kli-figure.js");
  assert.ok(existsSync(script), `${script} is missing: run make single`);
  // A course note on a USB stick: an HTML file beside the script, opened from file://.
  const dir = await mkdtemp(join(tmpdir(), "kli-figure-"));
  await copyFile(script, join(dir, "kli-figure.js"));
  await writeFile(join(dir, "note.html"), `<!doctype html><html lang="en"><head><meta charset="utf-8"><link rel="icon" href="data:,">
    <title>note</title><script src="kli-figure.js"></script></head><body>
    <p>KLI on S²:</p><kli-figure view="hopf" style="width: 320px"></kli-figure>
    <p>A swarm:</p><kli-figure view="swarm" count="60" t="2" style="width: 320px"></kli-figure>
    <p>Keys:</p><kli-figure view="keyframes" style="width: 320px"></kli-figure>
    <p>The tour's SLERP, as teach.html shows it:</p><kli-figure view="slerp" s="0.25" style="width: 320px"></kli-figure></body></html>`);
  const context = await browser.newContext();
  const page = await context.newPage();
  const problems = [];
  const allowed = [pathToFileURL(join(dir, "note.html")).href, pathToFileURL(join(dir, "kli-figure.js")).href];
  await context.route("**/*", (route) => (allowed.includes(route.request().url()) ? route.continue() : (problems.push(route.request().url()), route.abort())));
  page.on("pageerror", (e) => problems.push(`pageerror: ${e.message}`));
  page.on("console", (m) => m.type() === "error" && problems.push(`console: ${m.text()}`));
  try {
    await page.goto(allowed[0]);
    await page.waitForFunction(() => Array.from(document.querySelectorAll("kli-figure"), (f) => f.run).every(Boolean), null, { timeout: 10000 });
    const figures = await page.locator("kli-figure").count();
    for (let i = 1; i <= figures; i++) assert.ok(await painted(page, `kli-figure:nth-of-type(${i})`, 1000) > 1000, `figure ${i} is blank`);
    assert.ok(await page.evaluate(() => Math.abs(document.querySelector("kli-figure").end - 11.66) < 1e-9));
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});

test("the teacher's kit: one zip with every one-file page, the mathematics, the tour's figures as SVG, the element and the lecture; its tour and its deck work from file://", async () => {
  const { unzipSync, strFromU8 } = await import("fflate");
  const zip = join(root, "www/kli-teaching-kit.zip");
  assert.ok(existsSync(zip), `${zip} is missing: run make single`);
  const files = unzipSync(await readFile(zip));
  const names = Object.keys(files).map((name) => name.replace(/^kli-teaching-kit\//, ""));
  for (const { html } of PAGES) {
    assert.ok(names.includes(`pages/${html}`), `the kit has no pages/${html}`);
    // The one-file pages themselves (the tests above open each).
    assert.ok(Buffer.from(files[`kli-teaching-kit/pages/${html}`]).equals(await readFile(join(root, "dist/single", html))), `pages/${html} is not make single's`);
  }
  for (const name of ["pages/math.html", "element/kli-figure.js", "element/kli-figure.css", "README.txt", "deck/slides.html",
    "deck/reveal/reveal.js", "deck/reveal/notes.js"]) assert.ok(names.includes(name), `the kit has no ${name}`);
  const tour = PAGES.find((page) => page.name === "learn");
  for (const view of Object.keys(tour.canvases)) {
    const svg = strFromU8(files[`kli-teaching-kit/figures/tour-${view}.svg`] ?? new Uint8Array());
    assert.match(svg, /^<svg[^>]*width="1200"[^>]*height="900"/, `figures/tour-${view}.svg is not the tour's ${view} figure at 1200 × 900`);
    assert.ok((svg.match(/<(?:path|polygon|polyline|line|circle|ellipse|text)\b/g) ?? []).length >= 10, `figures/tour-${view}.svg draws almost nothing`);
  }
  // Unzipped on a disk: the mathematics reads with its style inside; the tour draws its figures.
  const dir = await mkdtemp(join(tmpdir(), "kli-kit-"));
  for (const [name, bytes] of Object.entries(files)) {
    await mkdir(dirname(join(dir, name)), { recursive: true });
    await writeFile(join(dir, name), bytes);
  }
  const context = await browser.newContext({ viewport: { width: 390, height: 800 } });
  const page = await context.newPage();
  const problems = [];
  const folder = pathToFileURL(join(dir, "kli-teaching-kit/")).href;
  await context.route("**/*", (route) => (route.request().url().startsWith(folder) ? route.continue() : (problems.push(route.request().url()), route.abort())));
  page.on("pageerror", (e) => problems.push(`pageerror: ${e.message}`));
  try {
    await page.goto(`${folder}pages/math.html`);
    // The site's style sheet is inside (its header rule: at most 1200 px wide).
    assert.equal(await page.evaluate(() => getComputedStyle(document.querySelector(".page-header")).maxWidth), "1200px");
    await page.click('a[href="learn.html"] >> nth=0');
    await page.waitForFunction(() => document.querySelector("#load-status")?.hidden, null, { timeout: 10000 });
    for (const { id, count } of await drawn(page)) assert.ok(count > 100, `the kit's learn.html: canvas #${id} is blank`);
    // The lecture from the disk: reveal.js, its notes and the element as classic scripts; the
    // first figure's slide shows it drawn.
    await page.goto(pathToFileURL(join(dir, "kli-teaching-kit/deck/slides.html")).href + "#/slide-turn");
    await page.waitForFunction(() => window.Reveal?.isReady?.() && window.Reveal.getPlugin("notes"), null, { timeout: 10000 });
    assert.ok(await painted(page, "#turn", 1000) > 1000, "the kit's deck: the first figure is blank");
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});
