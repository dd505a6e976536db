// End-to-end tests of the demo page (www/) in Debian's headless Chromium, driven by
// playwright-core. Screenshots go to test-artifacts/.
import { test, before, after } from "node:test";
import assert from "node:assert/strict";
import { mkdir } from "node:fs/promises";
import { join } from "node:path";
import { chromium } from "playwright-core";
import { CHROMIUM, serve } from "../../scripts/static-server.mjs";

const root = new URL("../../", import.meta.url).pathname;
const artifacts = join(root, "test-artifacts");

let server;
let origin;
let browser;

before(async () => {
  await mkdir(artifacts, { recursive: true });
  server = await serve(join(root, "www"));
  origin = server.origin;
  browser = await chromium.launch(CHROMIUM);
});

after(async () => {
  await browser?.close();
  server?.close();
});

/** A fresh page that records problems: console errors, page errors, failed or foreign requests. */
async function open(query = "", options = {}) {
  const context = await browser.newContext({ viewport: { width: 1280, height: 900 }, deviceScaleFactor: 1, ...options });
  const page = await context.newPage();
  const problems = [];
  page.on("console", (message) => message.type() === "error" && problems.push(`console: ${message.text()}`));
  page.on("pageerror", (error) => problems.push(`pageerror: ${error.message}`));
  page.on("requestfailed", (request) => problems.push(`failed: ${request.url()}`));
  page.on("request", (request) => {
    if (!request.url().startsWith(origin) && !request.url().startsWith("data:")) problems.push(`foreign request: ${request.url()}`);
  });
  page.on("response", (response) => response.status() >= 400 && problems.push(`${response.status()}: ${response.url()}`));
  await page.goto(`${origin}/${query}`);
  await page.waitForFunction(() => document.querySelector("#load-status").hidden);
  return { page, context, problems };
}

/** Pixel statistics of a canvas: how many are not white, and how many are near a colour. */
function canvasStats(page, selector, colours = {}) {
  return page.evaluate(([selector, colours]) => {
    const canvas = document.querySelector(selector);
    const data = canvas.getContext("2d").getImageData(0, 0, canvas.width, canvas.height).data;
    const result = { drawn: 0, width: canvas.width, height: canvas.height, clientWidth: canvas.clientWidth, hash: 0 };
    for (const name of Object.keys(colours)) result[name] = 0;
    for (let i = 0; i < data.length; i += 4) {
      const [r, g, b] = [data[i], data[i + 1], data[i + 2]];
      if (r < 250 || g < 250 || b < 250) result.drawn++;
      result.hash = (result.hash * 31 + r + 7 * g + 13 * b) % 1000000007;
      for (const [name, [cr, cg, cb]] of Object.entries(colours)) {
        if (Math.abs(r - cr) < 40 && Math.abs(g - cg) < 40 && Math.abs(b - cb) < 40) result[name]++;
      }
    }
    return result;
  }, [selector, colours]);
}

const KLI_ORANGE = [232, 89, 12];
const WING_RED = [224, 49, 49];
const WING_GREEN = [47, 158, 68];
const readout = (page) => page.textContent("#time-readout");
/** The time the page shows, once the frame that a key or click asked for has been drawn. */
const currentTime = async (page) => {
  await page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));
  return Number((await readout(page)).match(/t = ([\d.]+)/)[1]);
};

test("loads cleanly and draws every canvas with the paper's example", async () => {
  const { page, context, problems } = await open();
  await page.waitForTimeout(400);
  await page.screenshot({ path: join(artifacts, "page.png"), fullPage: true });
  const object = await canvasStats(page, "#object-canvas", { red: WING_RED, green: WING_GREEN });
  const sphere = await canvasStats(page, "#sphere-canvas", { orange: KLI_ORANGE });
  const film = await canvasStats(page, "#filmstrip-canvas", { red: WING_RED });
  const plots = await canvasStats(page, "#plots-canvas", { orange: KLI_ORANGE });
  assert.ok(object.red > 500 && object.green > 500, `object: ${JSON.stringify(object)}`);
  assert.ok(sphere.drawn > 20000 && sphere.orange > 200, `sphere: ${JSON.stringify(sphere)}`);
  assert.ok(film.red > 300, `filmstrip: ${JSON.stringify(film)}`);
  assert.ok(plots.orange > 500, `plots: ${JSON.stringify(plots)}`);
  assert.deepEqual(problems, []);
  await context.close();
});

test("the table shows Table 1 (corrected row) and T = 11.66", async () => {
  const { page, context } = await open();
  const rows = await page.$$eval("#moments tbody tr", (trs) => trs.map((tr) => Array.from(tr.cells, (c) => c.textContent)));
  const byTime = Object.fromEntries(rows.map(([t, integrated, exact]) => [t, { integrated, exact }]));
  // MATH.md, "The paper's example".
  const expected = {
    "0": "0.0000 + 0.0000i + 0.0000j + 1.0000k",
    "0.2": "0.0943 + 0.0943i + 0.0943j + 0.9866k",
    "0.4": "0.1754 + 0.1754i + 0.1754j + 0.9527k",
    "0.55": "0.2270 + 0.2270i + 0.2270j + 0.9195k",
    "0.85": "0.3083 + 0.3083i + 0.3083j + 0.8455k",
    "1.2": "0.3732 + 0.3732i + 0.3732j + 0.7630k",
    "1.8": "0.4364 + 0.4364i + 0.4364j + 0.6548k",
    "T = 11.66": "0.5000 + 0.5000i + 0.5000j + 0.5000k",
  };
  for (const [t, q] of Object.entries(expected)) {
    assert.equal(byTime[t]?.integrated, q, `t = ${t}`);
    assert.equal(byTime[t]?.exact, q, `t = ${t} (closed form)`);
  }
  assert.match(await page.textContent("#final-time"), /^T = 11\.66 after 1166 steps; the closed form predicts T\* = 11\.6568\./);
  await context.close();
});

test("the animation advances, then stops at T", async () => {
  const { page, context, problems } = await open();
  await page.selectOption("#speed", "4");
  const first = await canvasStats(page, "#object-canvas");
  await page.waitForTimeout(300);
  const second = await canvasStats(page, "#object-canvas");
  assert.notEqual(first.hash, second.hash, "two frames are the same");
  assert.ok((await currentTime(page)) > 0);
  await page.waitForFunction(() => document.querySelector("#play").textContent === "Play", null, { timeout: 8000 });
  assert.equal(await readout(page), "t = 11.66 / T = 11.66");
  const rest = await canvasStats(page, "#object-canvas");
  await page.waitForTimeout(200);
  assert.equal((await canvasStats(page, "#object-canvas")).hash, rest.hash, "still drawing after T");
  assert.match(page.url(), /t=11\.66/);
  assert.deepEqual(problems, []);
  await context.close();
});

test("changing r changes the curve and the URL", async () => {
  const { page, context, problems } = await open("?t=1");
  const before = await canvasStats(page, "#sphere-canvas", { orange: KLI_ORANGE });
  for (const [axis, value] of [["w", "0.2"], ["x", "0.9"], ["y", "-0.3"], ["z", "0.2"]]) await page.fill(`[name=r-${axis}]`, value);
  await page.waitForTimeout(100);
  const after = await canvasStats(page, "#sphere-canvas", { orange: KLI_ORANGE });
  assert.notEqual(before.hash, after.hash);
  assert.match(page.url(), /r=0\.2%2C0\.9%2C-0\.3%2C0\.2/);
  assert.equal(await page.inputValue("[name=preset]"), "custom");
  assert.notEqual(await page.inputValue("[name=r-angle]"), "120", "axis–angle fields follow");
  assert.deepEqual(problems, []);
  await context.close();
});

test("a URL with parameters reproduces its state", async () => {
  const query = "?p=1,0,0,0&r=0,1,0,0&eps=1e-4&step=0.02&int=geodesic&short=0&t=0.5";
  const { page, context, problems } = await open(query);
  assert.deepEqual(await Promise.all(["p-w", "p-x", "r-w", "r-x", "eps", "step"].map((n) => page.inputValue(`[name=${n}]`))), ["1", "0", "0", "1", "1e-4", "0.02"]);
  assert.equal(await page.inputValue("[name=integrator]"), "geodesic");
  assert.equal(await page.isChecked("[name=shortest]"), false);
  // The axis–angle fields follow the URL's quaternions: r = i is a half turn about x.
  assert.deepEqual(await Promise.all(["r-ax", "r-ay", "r-az", "r-angle"].map((n) => page.inputValue(`[name=${n}]`))), ["1", "0", "0", "180"]);
  assert.equal(await currentTime(page), 0.5);
  // p·r = 0, φ0 = π/2: T* = ln(tan(π/4)/tan(arcsin(ε/2))), T the first multiple of δ past it.
  const star = Math.log(1 / Math.tan(Math.asin(5e-5)));
  const T = Math.ceil(star / 0.02) * 0.02;
  assert.match(await page.textContent("#final-time"), new RegExp(`^T = ${T.toFixed(2)} after ${Math.round(T / 0.02)} steps; the closed form predicts T\\* = ${star.toFixed(4)}`));
  assert.match(await readout(page), new RegExp(`T = ${T.toFixed(2)}$`));
  // The page shows it still: the URL asked for t, so it does not play.
  await page.waitForTimeout(200);
  assert.equal(await currentTime(page), 0.5);
  assert.deepEqual(problems, []);
  await context.close();
});

test("every bad input shows its message and the page keeps working", async () => {
  const { page, context, problems } = await open("?t=1");
  const cases = [
    ["p-w", "abc", "#p-error", "p: the w component must be a number."],
    ["p-x", "", "#p-error", "p: the x component must be a number."],
    ["eps", "0", "#eps-error", "ε must be a number greater than 0."],
    ["eps", "-1e-5", "#eps-error", "ε must be a number greater than 0."],
    ["eps", "1e-30", "#eps-error", "tolerance 1e-30 not reached"],
    ["step", "x", "#step-error", "δ must be a number greater than 0."],
    ["step", "1e-9", "#step-error", "step is too small for maxTime"],
    ["r-angle", "ninety", "#r-error", "r: the angle must be a number."],
  ];
  for (const [name, text, output, message] of cases) {
    const original = await page.inputValue(`[name=${name}]`);
    await page.fill(`[name=${name}]`, text);
    await page.waitForTimeout(50);
    assert.ok((await page.textContent(output)).startsWith(message), `${name} = ${JSON.stringify(text)}: ${await page.textContent(output)}`);
    // The last valid state stays: the paper's T, and the canvases still drawn.
    assert.match(await readout(page), /T = 11\.66$/);
    assert.ok((await canvasStats(page, "#sphere-canvas")).drawn > 20000);
    await page.fill(`[name=${name}]`, original);
    await page.waitForTimeout(50);
    assert.equal(await page.textContent(output), "", `${name}: message cleared`);
  }
  // All zero r, then r = −p the long way round.
  for (const axis of ["w", "x", "y", "z"]) await page.fill(`[name=r-${axis}]`, "0");
  assert.equal(await page.textContent("#r-error"), "r must not be all zero.");
  await page.fill("[name=r-z]", "-2");
  await page.uncheck("[name=shortest]");
  assert.match(await page.textContent("#shortest-error"), /^p and r are antipodal/);
  await page.screenshot({ path: join(artifacts, "errors.png"), fullPage: true });
  await page.check("[name=shortest]");
  assert.equal(await page.textContent("#shortest-error"), "");
  assert.match(await page.textContent("#note"), /nothing to interpolate/);
  assert.deepEqual(problems, []);
  await context.close();
});

test("bad URL values show messages, are never HTML, and fall back to the paper", async () => {
  const query = "?p=%3Cimg%20src%3Dx%20onerror%3Dwindow.hacked%3D1%3E,0,0,1&eps=-1&int=<b>x</b>";
  const { page, context, problems } = await open(query);
  assert.equal(await page.textContent("#p-error"), "p: the w component must be a number.");
  assert.equal(await page.textContent("#eps-error"), "ε must be a number greater than 0.");
  assert.equal(await page.inputValue("[name=integrator]"), "rk4");
  assert.equal(await page.$$eval("img", (images) => images.length), 0);
  assert.equal(await page.evaluate(() => window.hacked), undefined);
  assert.match(await readout(page), /T = 11\.66$/);
  assert.deepEqual(problems, []);
  await context.close();
});

test("keyboard: space plays and pauses, End jumps to T, Home restarts", async () => {
  const { page, context, problems } = await open("?t=0");
  await page.locator("body").press(" ");
  assert.equal(await page.textContent("#play"), "Pause");
  await page.waitForTimeout(150);
  await page.locator("body").press(" ");
  assert.equal(await page.textContent("#play"), "Play");
  const paused = await currentTime(page);
  assert.ok(paused > 0);
  await page.locator("body").press("ArrowRight");
  assert.ok((await currentTime(page)) > paused);
  await page.locator("body").press("End");
  assert.equal(await currentTime(page), 11.66);
  await page.locator("body").press("Home");
  assert.equal(await currentTime(page), 0);
  // Arrow keys on the focused sphere turn it.
  const before = await canvasStats(page, "#sphere-canvas");
  await page.focus("#sphere-canvas");
  await page.keyboard.press("ArrowLeft");
  await page.waitForTimeout(50);
  assert.notEqual((await canvasStats(page, "#sphere-canvas")).hash, before.hash);
  assert.deepEqual(problems, []);
  await context.close();
});

test("dragging turns the sphere", async () => {
  const { page, context } = await open("?t=2");
  const box = await page.locator("#sphere-canvas").boundingBox();
  const before = await canvasStats(page, "#sphere-canvas");
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width / 2 + 60, box.y + box.height / 2 + 20, { steps: 4 });
  await page.mouse.up();
  await page.waitForTimeout(50);
  assert.notEqual((await canvasStats(page, "#sphere-canvas")).hash, before.hash);
  await context.close();
});

test("embed=1 is compact; reduced motion does not autoplay; high-DPI is crisp", async () => {
  const embed = await open("?embed=1", { viewport: { width: 640, height: 360 } });
  assert.equal(await embed.page.isVisible("#inputs"), false);
  assert.equal(await embed.page.isVisible("#plots-canvas"), false);
  assert.equal(await embed.page.isVisible("#sphere-canvas"), true);
  await embed.page.waitForTimeout(200);
  await embed.page.screenshot({ path: join(artifacts, "embed.png") });
  assert.deepEqual(embed.problems, []);
  await embed.context.close();

  const calm = await open("", { reducedMotion: "reduce" });
  await calm.page.waitForTimeout(300);
  assert.equal(await currentTime(calm.page), 0);
  assert.equal(await calm.page.textContent("#play"), "Play");
  await calm.context.close();

  const sharp = await open("?t=1", { deviceScaleFactor: 2 });
  const stats = await canvasStats(sharp.page, "#sphere-canvas");
  assert.ok(Math.abs(stats.width - 2 * stats.clientWidth) <= 2, `${stats.width} for ${stats.clientWidth} CSS px`);
  await sharp.page.setViewportSize({ width: 700, height: 900 });
  await sharp.page.waitForTimeout(200);
  const narrow = await canvasStats(sharp.page, "#sphere-canvas");
  assert.ok(narrow.width !== stats.width && narrow.drawn > 10000, "redrawn at the new size");
  await sharp.page.screenshot({ path: join(artifacts, "narrow.png"), fullPage: true });
  assert.deepEqual(sharp.problems, []);
  await sharp.context.close();
});

test("works offline once loaded", async () => {
  const { page, context } = await open("?t=1");
  await page.evaluate(() => navigator.serviceWorker.ready);
  await page.reload();
  await page.waitForFunction(() => navigator.serviceWorker.controller !== null);
  await context.setOffline(true);
  await page.reload();
  await page.waitForFunction(() => document.querySelector("#load-status").hidden);
  assert.match(await readout(page), /T = 11\.66$/);
  assert.ok((await canvasStats(page, "#sphere-canvas")).drawn > 20000);
  await context.close();
});
