// End-to-end tests of the swarm page (swarm.html, made from www/swarm/) in Debian's headless Chromium.
import { test } from "node:test";
import assert from "node:assert/strict";
import { axeViolations, canvasStats, keepShot, open, setup } from "./browser.mjs";

setup();

/** The readout's numbers: { t, R, λ } (and τ in the KLI case). */
async function readout(page) {
  const text = await page.textContent("#readout");
  const number = (name) => Number(text.match(new RegExp(`${name} = (-?[\\d.]+)`))?.[1]);
  return { t: number("t"), R: number("R"), lambda: number("λmax"), tau: number("τ = Kt/2") };
}

test("the swarm page draws, plays, and identical oscillators synchronise", async () => {
  const { page, context, problems } = await open("swarm.html", { moving: true });
  const start = await readout(page);
  await page.waitForFunction(() => Number(document.querySelector("#readout").textContent.match(/R = ([\d.]+)/)[1]) > 0.999,
    null, { timeout: 20000 });
  const later = await readout(page);
  // λmax ≥ R² (Q ≥ m mᵀ): both near 1 (the readout rounds to 3 decimals).
  assert.ok(later.t > start.t && later.R > 0.999 && later.lambda >= 0.999, JSON.stringify({ start, later }));
  const sphere = await canvasStats(page, "#swarm-hopf", { blue: [24, 100, 171] });
  assert.ok(sphere.drawn > 20000 && sphere.blue > 5, JSON.stringify(sphere));
  assert.ok((await canvasStats(page, "#swarm-objects")).drawn > 3000);
  assert.ok((await canvasStats(page, "#swarm-plots")).drawn > 3000);
  await keepShot(page, "swarm.png");
  // A playing page's URL holds the options, and reproduces the run.
  assert.match(page.url(), /K=1&n=500&graph=all/);
  assert.deepEqual(problems, []);
  await context.close();
});

test("negative coupling balances, the KLI preset shows its clock, the URL restores both", async () => {
  const { page, context, problems } = await open("swarm.html?K=-1&n=200&w=0&seed=4", { moving: true });
  assert.equal(await page.inputValue("[name=preset]"), "custom");
  await page.waitForFunction(() => Number(document.querySelector("#readout").textContent.match(/R = ([\d.]+)/)[1]) < 0.01,
    null, { timeout: 20000 });
  await page.selectOption("[name=preset]", "kli");
  assert.match(await page.textContent("#note"), /the KLI flow at the clock τ = Kt\/2/);
  await page.waitForTimeout(300);
  const { t, tau } = await readout(page);
  // K = 2 in the preset: τ = Kt/2 = t (to the readout's two decimals).
  assert.ok(Math.abs(tau - t) <= 0.011, JSON.stringify({ t, tau }));
  await page.waitForURL(/graph=leader/, { timeout: 2000 });
  assert.match(page.url(), /K=2&n=2&graph=leader&leaders=1/);
  assert.deepEqual(problems, []);
  await context.close();
});

test("bad options show the module's message beside their field, and the run goes on", async () => {
  const { page, context, problems } = await open("swarm.html", { moving: true });
  await page.fill("[name=seed]", "-3");
  assert.match(await page.textContent("#seed-error"), /^seed must be a whole number from 0 to/);
  assert.equal(await page.getAttribute("[name=seed]", "aria-invalid"), "true");
  await page.fill("[name=seed]", "2");
  assert.equal(await page.textContent("#seed-error"), "");
  await page.selectOption("[name=graph]", "leader");
  await page.fill("[name=leaders]", "900");
  assert.match(await page.textContent("#leaders-error"), /^leaders must be a whole number from 1 to count \(500\)/);
  const before = (await readout(page)).t;
  await page.waitForTimeout(300);
  assert.ok((await readout(page)).t > before, "still playing the last good run");
  assert.deepEqual(problems, []);
  await context.close();
});

test("the sweep plots the final R against K: low for weak coupling, high for strong", async () => {
  const { page, context, problems } = await open("swarm.html?K=2&n=200&w=1&seed=5");
  await page.click("#play"); // pause: the sweep does not need the animation
  await page.click("#sweep");
  await page.waitForFunction(() => document.querySelector("#sweep-status").textContent.startsWith("Done"), null, { timeout: 60000 });
  const orange = await canvasStats(page, "#swarm-sweep", { orange: [194, 65, 12] });
  assert.ok(orange.orange > 100, JSON.stringify(orange));
  // The same values as a table (the figure's text alternative): frequencies of spread 1 need
  // coupling to lock; negative coupling leaves the swarm balanced.
  const rows = await page.$$eval("#sweep-table tbody tr", (trs) => trs.map((tr) => Array.from(tr.cells, (c) => Number(c.textContent))));
  assert.equal(rows.length, 19);
  const at = (k) => rows.find(([coupling]) => Math.abs(coupling - k) < 1e-9)[1];
  assert.ok(at(-1) < 0.2 && at(0) < 0.3, JSON.stringify(rows));
  assert.ok(at(8) > 0.9, JSON.stringify(rows));
  assert.deepEqual(problems, []);
  await context.close();
});

test("WCAG 2.2 AA, embedded, and at 390 px", async () => {
  const { page, context } = await open("swarm.html");
  assert.deepEqual(await axeViolations(page), []);
  await context.close();
  const embed = await open("swarm.html?embed=1", { viewport: { width: 640, height: 400 } });
  assert.equal(await embed.page.isVisible("#swarm-inputs"), false);
  assert.equal(await embed.page.isVisible("#swarm-hopf"), true);
  assert.deepEqual(await axeViolations(embed.page), []);
  await embed.context.close();
  const narrow = await open("swarm.html", { viewport: { width: 390, height: 844 } });
  assert.ok(await narrow.page.evaluate(() => document.documentElement.scrollWidth <= 390), "no horizontal scrolling");
  await keepShot(narrow.page, "swarm-390px.png");
  await narrow.context.close();
});
