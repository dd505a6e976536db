// End-to-end tests of the keyframes page (keyframes.html, made from www/keyframes/) in Debian's headless Chromium.
import { test } from "node:test";
import assert from "node:assert/strict";
import { axeViolations, canvasStats, keepShot, open, setup } from "./browser.mjs";

setup();

/** The measured figures table: { curve: [key error, jump, ∫|ω̇|², rotation, solve, evaluations] }. */
async function figures(page) {
  const rows = await page.$$eval("#figures tbody tr", (trs) => trs.map((tr) => Array.from(tr.cells, (c) => c.textContent)));
  return Object.fromEntries(rows.map(([name, ...values]) => [name, values.map(Number)]));
}

test("the keyframes page draws three curves through the keys and measures them", async () => {
  const { page, context, problems } = await open("keyframes.html");
  for (const selector of ["#keyframes-objects", "#keyframes-hopf", "#keyframes-plots"]) {
    assert.ok((await canvasStats(page, selector)).drawn > 3000, selector);
  }
  const f = await figures(page);
  const [chain, squad, slerp] = [f["Kuramoto–Lohe chain"], f["Squad"], f["piecewise SLERP"]];
  // Keys hit; ω continuous for the chain and Squad, jumping for SLERP; the chain bends least.
  assert.ok(chain[0] < 1e-12 && squad[0] < 1e-12 && slerp[0] < 1e-12, JSON.stringify(f));
  assert.ok(chain[1] < 0.05 && squad[1] < 0.05 && slerp[1] > 0.5, JSON.stringify(f));
  assert.ok(chain[2] < squad[2] && squad[2] < slerp[2], JSON.stringify(f));
  assert.match(await page.textContent("#solve"), /Newton steps to a residual of [\d.]+e-1[0-9]/);
  await keepShot(page, "keyframes.png");
  assert.deepEqual(problems, []);
  await context.close();
});

test("smoothness 0 makes the chain piecewise SLERP, and the URL keeps it", async () => {
  const { page, context, problems } = await open("keyframes.html");
  await page.$eval("[name=smoothness]", (slider) => {
    slider.value = "0";
    slider.dispatchEvent(new Event("input", { bubbles: true }));
  });
  const f = await figures(page);
  // The chain's samples are piecewise SLERP's: the same total rotation (to the corners its
  // evaluation rounds within one sample interval of each key), and bends far more than Squad.
  const [chain, squad, slerp] = [f["Kuramoto–Lohe chain"], f["Squad"], f["piecewise SLERP"]];
  assert.ok(Math.abs(chain[3] - slerp[3]) < 0.01 * slerp[3], JSON.stringify(f));
  assert.ok(chain[2] > 10 * squad[2], JSON.stringify(f));
  await page.waitForURL(/s=0(&|$)/, { timeout: 2000 });
  await page.reload();
  await page.waitForFunction(() => document.querySelector("#load-status").hidden);
  assert.equal(await page.inputValue("[name=smoothness]"), "0");
  assert.deepEqual(problems, []);
  await context.close();
});

test("bad keys and times show the module's message beside their field", async () => {
  const { page, context, problems } = await open("keyframes.html");
  await page.fill("[name=keys]", "1,0,0,0; 0,0,0,0; 0,1,0,0");
  assert.match(await page.textContent("#keys-error"), /^keys\[1\] must be a quaternion of 4 finite numbers \[w, x, y, z\], not all zero: it has zero length/);
  await page.fill("[name=keys]", "1,0,0,0; 0,1,0,0; 0,0,1,0");
  assert.equal(await page.textContent("#keys-error"), "");
  await page.fill("[name=times]", "0,2,1");
  assert.match(await page.textContent("#times-error"), /^times\[2\] must be greater than times\[1\]/);
  assert.equal(await page.getAttribute("[name=times]", "aria-invalid"), "true");
  assert.deepEqual(problems, []);
  await context.close();
});

test("keyframes: WCAG 2.2 AA, embedded, and at 390 px", async () => {
  const { page, context } = await open("keyframes.html");
  assert.deepEqual(await axeViolations(page), []);
  await context.close();
  const embed = await open("keyframes.html?embed=1", { viewport: { width: 640, height: 400 } });
  assert.equal(await embed.page.isVisible("#keyframes-inputs"), false);
  assert.deepEqual(await axeViolations(embed.page), []);
  await embed.context.close();
  const narrow = await open("keyframes.html", { viewport: { width: 390, height: 844 } });
  assert.ok(await narrow.page.evaluate(() => document.documentElement.scrollWidth <= 390), "no horizontal scrolling");
  // The measured table scrolls sideways here: a region the keyboard can reach and scroll.
  assert.deepEqual(await axeViolations(narrow.page), []);
  await keepShot(narrow.page, "keyframes-390px.png");
  await narrow.context.close();
});

test("a key edited as axis and angle, added, removed, and dragged on the sphere", async () => {
  const { page, context, problems } = await open("keyframes.html");
  await page.click("#play"); // pause
  const keys = async () => (await page.inputValue("[name=keys]")).split(";").map((k) => k.split(",").map(Number));
  // Key k1 as 90° about z: cos 45° + k sin 45°.
  await page.selectOption("[name=key]", "1");
  await page.fill("[name=key-ax]", "0");
  await page.fill("[name=key-ay]", "0");
  await page.fill("[name=key-az]", "1");
  await page.fill("[name=key-angle]", "90");
  const k1 = (await keys())[1];
  assert.ok(Math.abs(k1[0] - Math.SQRT1_2) < 1e-5 && Math.abs(k1[3] - Math.SQRT1_2) < 1e-5, JSON.stringify(k1));
  await page.fill("[name=key-angle]", "ninety");
  assert.match(await page.textContent("#key-error"), /^angle must be a finite number/);
  assert.equal(await page.getAttribute("[name=key-angle]", "aria-invalid"), "true");
  await page.fill("[name=key-angle]", "90");
  assert.equal(await page.textContent("#key-error"), "");
  // 3 to 10 keys.
  const count = (await keys()).length;
  await page.click("#add-key");
  assert.equal((await keys()).length, count + 1);
  for (let i = 0; i < 10; i++) if (!(await page.isDisabled("#remove-key"))) await page.click("#remove-key");
  assert.equal((await keys()).length, 3);
  // Drag the disc of a key in front: the key turns, its Hopf point follows the pointer.
  await page.locator("#keyframes-hopf").scrollIntoViewIfNeeded();
  const box = await page.locator("#keyframes-hopf").boundingBox();
  const points = await page.evaluate(async ([flat, width, height]) => {
    const { KeyframesDemo, defaultCamera } = await import("./pkg/keyframes_demo.js");
    const demo = new KeyframesDemo(new Float64Array(flat), new Float64Array(0), 1);
    const [azimuth, elevation] = defaultCamera();
    const points = Array.from(demo.keyPoints({ width, height, azimuth, elevation }));
    demo.free();
    return points;
  }, [(await keys()).flat(), box.width, box.height]);
  const index = [0, 1, 2].find((i) => points[3 * i + 2] === 1);
  assert.ok(index !== undefined, `a key in front: ${points}`);
  const point = points.slice(3 * index, 3 * index + 3);
  const before = (await keys())[index];
  await page.mouse.move(box.x + point[0], box.y + point[1]);
  await page.mouse.down();
  await page.mouse.move(box.x + point[0] + 30, box.y + point[1] + 20, { steps: 5 });
  await page.mouse.up();
  await page.waitForTimeout(100);
  const after = (await keys())[index];
  assert.ok(before.some((c, i) => Math.abs(c - after[i]) > 1e-3), `${before} → ${after}`);
  assert.deepEqual(problems, []);
  await context.close();
});
