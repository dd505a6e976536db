// End-to-end tests of the averaging page (average.html, made from www/average/) in Debian's headless Chromium.
import { test } from "node:test";
import assert from "node:assert/strict";
import { axeViolations, canvasStats, keepShot, open, setup } from "./browser.mjs";

setup();

/** The means' table as { name: [errorDegrees, dispersionDegrees, iterations] }. */
const means = (page) => page.$$eval("#means tbody tr", (trs) =>
  Object.fromEntries(trs.map((tr) => [tr.cells[0].textContent, Array.from(tr.cells, (c) => Number(c.textContent)).slice(1)])));

test("the averaging page draws, the follower flows to the chordal mean, the median resists the wild ones", async () => {
  const { page, context, problems } = await open("average.html");
  const sphere = await canvasStats(page, "#average-hopf", { blue: [24, 100, 171], orange: [232, 89, 12] });
  assert.ok(sphere.drawn > 20000 && sphere.blue > 30 && sphere.orange > 10, JSON.stringify(sphere));
  assert.ok((await canvasStats(page, "#average-objects")).drawn > 3000);
  assert.ok((await canvasStats(page, "#average-means")).drawn > 2000);
  // 40 measurements, 20% wild, 5° of noise: the median within 2.5°, the Karcher mean dragged furthest.
  const m = await means(page);
  assert.deepEqual(Object.keys(m), ["chordal", "quaternion", "geodesic (Karcher)", "median"]);
  assert.ok(m.median[0] < 2.5 && m.median[0] < m.chordal[0] && m.chordal[0] < m["geodesic (Karcher)"][0], JSON.stringify(m));
  assert.match(await page.textContent("#note"), /^40 measurements, \d+ wild; the median weighs \d+ of them least/);
  // At its end (End: the time the follower's flow is drawn to), the follower is the chordal mean:
  // the object's label says how far from the truth. The follower is a function of the time
  // (model.rs, `follower`), so the end reached by a key is the end a play reaches; that a play
  // runs to its end and stops is the runtime's, tested on the KLI page (page.test.mjs). Played
  // here, the page's 15 s of frames were three quarters of this file's CPU.
  await page.keyboard.press("End");
  const readout = await page.textContent("#readout");
  const [, t, end] = readout.match(/t = ([\d.]+) \/ ([\d.]+)/).map(Number);
  assert.equal(t, end, readout);
  assert.match(readout, new RegExp(`the chordal mean: ${m.chordal[0].toFixed(2)}° from the truth`));
  await keepShot(page, "average.png");
  assert.match(page.url(), /n=40&noise=5&out=0.2&seed=1/);
  assert.deepEqual(problems, []);
  await context.close();
});

test("the URL restores the measurements; a bad one is refused beside its field; moving one makes it wild", async () => {
  const { page, context, problems } = await open("average.html?n=60&noise=3&out=0&seed=7");
  assert.equal(await page.inputValue("[name=preset]"), "custom");
  const clean = await means(page);
  // Without wild ones the four means agree to a fraction of the noise.
  for (const [error] of Object.values(clean)) assert.ok(error < 1.5, JSON.stringify(clean));
  assert.match(await page.textContent("#note"), /^60 measurements, 0 wild/);
  await page.fill("[name=seed]", "-1");
  assert.match(await page.textContent("#seed-error"), /^seed must be a whole number from 0 to/);
  await page.fill("[name=seed]", "7");
  assert.equal(await page.textContent("#seed-error"), "");
  // Drag a measurement in front across the sphere: it becomes wild, and the URL keeps where it went.
  await page.locator("#average-hopf").scrollIntoViewIfNeeded();
  const box = await page.locator("#average-hopf").boundingBox();
  const points = await page.evaluate(async ([width, height]) => {
    const { AverageDemo, defaultCamera } = await import("./pkg/average_demo.js");
    const demo = new AverageDemo({ count: 60, noise: 3, outliers: 0, seed: 7 });
    const [azimuth, elevation] = defaultCamera();
    const points = Array.from(demo.measurementPoints({ width, height, azimuth, elevation }));
    demo.free();
    return points;
  }, [box.width, box.height]);
  const index = Array.from({ length: 60 }, (_, i) => i).find((i) => points[3 * i + 2] === 1);
  assert.ok(index !== undefined, "a measurement in front");
  const [x, y] = points.slice(3 * index, 3 * index + 2);
  await page.mouse.move(box.x + x, box.y + y);
  await page.mouse.down();
  await page.mouse.move(box.x + x + 40, box.y + y + 30, { steps: 6 });
  await page.mouse.up();
  await page.waitForURL(new RegExp(`moved=${index}%2C`), { timeout: 3000 });
  assert.match(await page.textContent("#note"), /^60 measurements, 1 wild/);
  assert.equal(await page.isDisabled("#unmove"), false);
  await page.click("#unmove");
  assert.match(await page.textContent("#note"), /^60 measurements, 0 wild/);
  assert.deepEqual(problems, []);
  await context.close();
});

test("the sweep plots each mean's error against the share of wild ones", async () => {
  const { page, context, problems } = await open("average.html?n=60&noise=5&out=0.3&seed=2");
  await page.click("#play");
  await page.click("#sweep");
  await page.waitForFunction(() => document.querySelector("#sweep-status").textContent.startsWith("Done"), null, { timeout: 60000 });
  const rows = await page.$$eval("#sweep-table tbody tr", (trs) => trs.map((tr) => Array.from(tr.cells, (c) => Number(c.textContent))));
  assert.equal(rows.length, 11);
  const at = (share) => rows.find(([s]) => Math.abs(s - share) < 1e-9).slice(1);
  // No wild ones: all four within the noise; at 30%: the median least dragged, Karcher most (MATH.md's table).
  assert.ok(at(0).every((e) => e < 2), JSON.stringify(rows));
  const [chordal, , geodesic, median] = at(0.3);
  assert.ok(median < chordal && chordal < geodesic, JSON.stringify(rows));
  const stats = await canvasStats(page, "#average-sweep", { blue: [25, 113, 194] });
  assert.ok(stats.blue > 50, JSON.stringify(stats));
  assert.deepEqual(problems, []);
  await context.close();
});

test("WCAG 2.2 AA, embedded, and at 390 px", async () => {
  const { page, context } = await open("average.html");
  assert.deepEqual(await axeViolations(page), []);
  await context.close();
  const narrow = await open("average.html", { viewport: { width: 390, height: 844 } });
  assert.ok(await narrow.page.evaluate(() => document.documentElement.scrollWidth <= 390), "no horizontal scrolling");
  assert.deepEqual(await axeViolations(narrow.page), []);
  await keepShot(narrow.page, "average-390px.png");
  await narrow.context.close();
});
