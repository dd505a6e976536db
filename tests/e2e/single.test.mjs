// `make single`'s pages opened as a teacher opens them from a USB stick: from file://, with every
// request other than the file itself refused, each page must load its module and draw.
import { test, before, after } from "node:test";
import assert from "node:assert/strict";
import { existsSync } from "node:fs";
import { copyFile, mkdtemp, writeFile } from "node:fs/promises";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { pathToFileURL } from "node:url";
import { chromium } from "playwright-core";
import { CHROMIUM } from "../../scripts/static-server.mjs";
import { root } from "./browser.mjs";
import { PAGES } from "../../www/pages.js";

let browser;
before(async () => (browser = await chromium.launch(CHROMIUM)));
after(async () => browser?.close());

/** Non-blank pixels of each canvas on the page. */
const drawn = (page) => page.evaluate(() => Array.from(document.querySelectorAll("canvas"), (canvas) => {
  const data = canvas.getContext("2d").getImageData(0, 0, canvas.width, canvas.height).data;
  let count = 0;
  for (let i = 0; i < data.length; i += 4) if (data[i] < 250 || data[i + 1] < 250 || data[i + 2] < 250) count++;
  return { id: canvas.id, count };
}));

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
    <p>Keys:</p><kli-figure view="keyframes" style="width: 320px"></kli-figure></body></html>`);
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
    const drawn = await page.evaluate(() => Array.from(document.querySelectorAll("kli-figure"), (f) => {
      const canvas = f.shadowRoot.querySelector("canvas");
      const data = canvas.getContext("2d").getImageData(0, 0, canvas.width, canvas.height).data;
      let count = 0;
      for (let i = 0; i < data.length; i += 4) if (data[i] < 250 || data[i + 1] < 250 || data[i + 2] < 250) count++;
      return count;
    }));
    drawn.forEach((count, i) => assert.ok(count > 1000, `figure ${i} is blank`));
    assert.ok(await page.evaluate(() => Math.abs(document.querySelector("kli-figure").end - 11.66) < 1e-9));
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});
