// End-to-end tests of the demo page (www/) in Debian's headless Chromium, driven by
// playwright-core. Screenshots for a person to look at go to test-artifacts/ with KLI_SHOTS=1.
import { test } from "node:test";
import assert from "node:assert/strict";
import { readFileSync } from "node:fs";
import { join } from "node:path";
import { axeViolations, canvasStats, engage, keepShot, open, root, setup } from "./browser.mjs";

setup();

const KLI_ORANGE = [194, 65, 12]; // crates/kli-demo/src/palette.rs
const WING_RED = [224, 49, 49];
const WING_GREEN = [47, 158, 68];
const readout = (page) => page.textContent("#readout");
/** The time the page shows, once the frame that a key or click asked for has been drawn. */
const currentTime = async (page) => {
  await page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));
  return Number((await readout(page)).match(/t = ([\d.]+)/)[1]);
};

test("loads cleanly and draws every canvas with the paper's example", async () => {
  const { page, context, problems } = await open();
  await page.waitForTimeout(400);
  await keepShot(page, "page.png");
  const object = await canvasStats(page, "#object-canvas", { red: WING_RED, green: WING_GREEN });
  const sphere = await canvasStats(page, "#hopf-canvas", { orange: KLI_ORANGE });
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

test("the paper's printed Table 1 beside the live one: the copied row marked, truncations underlined, explained", async () => {
  const { page, context, problems } = await open();
  const printed = await page.$$eval("#moments tbody tr", (trs) => trs.map((tr) => ({
    t: tr.cells[0].textContent,
    text: tr.cells[3].textContent.replace(/ \((wrong|truncated)\)/g, ""),
    wrong: tr.cells[3].querySelectorAll("mark.differs").length,
    cut: tr.cells[3].querySelectorAll("span.truncated").length,
  })));
  const row = (t) => printed.find((r) => r.t === t);
  // The paper's Table 1 as printed (MATH.md), and what is wrong with it.
  assert.equal(row("1.8").text, "0.37 + 0.37i + 0.37j + 0.76k");
  assert.equal(row("1.8").wrong, 4);
  assert.equal(row("1.2").text, "0.37 + 0.37i + 0.37j + 0.76k");
  assert.equal(row("1.2").wrong + row("1.2").cut, 0);
  assert.deepEqual([row("0.2").cut, row("0.85").cut, row("T = 11.66").cut], [1, 1, 3]);
  assert.equal(printed.reduce((sum, r) => sum + r.wrong, 0), 4);
  const notes = await page.$$eval("#printed-notes li", (lis) => lis.map((li) => li.textContent));
  assert.ok(notes.includes("t = 1.8: the printed row is the t = 1.2 row again; the closed form gives 0.4364 + 0.4364i + 0.4364j + 0.6548k."), notes.join("\n"));
  assert.ok(notes.some((n) => n.startsWith("t = 0.2: 0.98 for 0.9866") && n.endsWith("rounding gives 0.99.")), notes.join("\n"));
  // Eq. 4 as printed, integrated on the page: |q| settles at (√5 − 1)/2, 1 − 0.618 from r.
  const typo = await page.$$eval("#typo tbody tr", (trs) => trs.map((tr) => Array.from(tr.cells, (c) => Number(c.textContent))));
  assert.deepEqual(typo[0], [0, 1, 1]);
  const [t, norm, distance] = typo.at(-1);
  assert.equal(t, 40);
  assert.equal(norm.toFixed(6), ((Math.sqrt(5) - 1) / 2).toFixed(6));
  assert.equal(distance.toFixed(6), (1 - (Math.sqrt(5) - 1) / 2).toFixed(6));
  assert.match(await page.locator("#typo-summary").textContent(), /settled at \|q\| = 0\.618034 .* never within ε = 0\.00001 of it/);
  // Another pair: no printed values to compare with.
  await page.selectOption("select[name=preset]", "near-identical");
  await page.waitForFunction(() => document.querySelector("#moments tbody tr td:nth-child(4)").textContent === "—");
  assert.equal(await page.locator("#printed-notes li").count(), 0);
  assert.deepEqual(problems, []);
  await context.close();
});

test("the animation advances, then stops at T", async () => {
  const { page, context, problems } = await open("", { moving: true });
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
  const before = await canvasStats(page, "#hopf-canvas", { orange: KLI_ORANGE });
  for (const [axis, value] of [["w", "0.2"], ["x", "0.9"], ["y", "-0.3"], ["z", "0.2"]]) await page.fill(`[name=r-${axis}]`, value);
  await page.waitForTimeout(100);
  const after = await canvasStats(page, "#hopf-canvas", { orange: KLI_ORANGE });
  assert.notEqual(before.hash, after.hash);
  // URL writes are throttled (at most one per 400 ms): wait for the last one.
  await page.waitForURL(/r=0\.2%2C0\.9%2C-0\.3%2C0\.2/, { timeout: 2000 });
  assert.equal(await page.inputValue("[name=preset]"), "custom");
  assert.notEqual(await page.inputValue("[name=r-angle]"), "120", "axis–angle fields follow");
  assert.deepEqual(problems, []);
  await context.close();
});

test("a URL with parameters reproduces its state", async () => {
  const query = "?p=1,0,0,0&r=0,1,0,0&eps=1e-4&step=0.02&int=geodesic&short=0&t=0.5";
  const { page, context, problems } = await open(query);
  assert.deepEqual(await Promise.all(["p-w", "p-x", "r-w", "r-x", "tolerance", "step"].map((n) => page.inputValue(`[name=${n}]`))), ["1", "0", "0", "1", "1e-4", "0.02"]);
  assert.equal(await page.inputValue("[name=integrator]"), "geodesic");
  assert.equal(await page.isChecked("[name=shortestPath]"), false);
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
  // The messages are the module's own (crates/kli-wasm): the page checks nothing itself.
  const quaternion = (which, c) => `${which} must be a quaternion of 4 finite numbers [w, x, y, z], not all zero: its ${c} component is NaN`;
  const cases = [
    ["p-w", "abc", "#p-error", quaternion("p", "w")],
    ["p-x", "", "#p-error", quaternion("p", "x")],
    ["tolerance", "0", "#tolerance-error", "tolerance must be a finite number > 0 (got 0)"],
    ["tolerance", "-1e-5", "#tolerance-error", "tolerance must be a finite number > 0 (got -0.00001)"],
    ["tolerance", "1e-30", "#tolerance-error", "tolerance 1e-30 not reached"],
    ["step", "x", "#step-error", "step must be a finite number > 0 (got NaN)"],
    ["step", "1e-9", "#step-error", "step is too small for maxTime"],
    ["r-angle", "ninety", "#r-error", "r: angle must be a finite number (got NaN)"],
  ];
  for (const [name, text, output, message] of cases) {
    const original = await page.inputValue(`[name=${name}]`);
    await page.fill(`[name=${name}]`, text);
    await page.waitForTimeout(50);
    assert.ok((await page.textContent(output)).startsWith(message), `${name} = ${JSON.stringify(text)}: ${await page.textContent(output)}`);
    // The last valid state stays: the paper's T, and the canvases still drawn.
    assert.match(await readout(page), /T = 11\.66$/);
    assert.ok((await canvasStats(page, "#hopf-canvas")).drawn > 20000);
    await page.fill(`[name=${name}]`, original);
    await page.waitForTimeout(50);
    assert.equal(await page.textContent(output), "", `${name}: message cleared`);
  }
  // All zero r, then r = −p the long way round.
  for (const axis of ["w", "x", "y", "z"]) await page.fill(`[name=r-${axis}]`, "0");
  assert.equal(await page.textContent("#r-error"), "r must be a quaternion of 4 finite numbers [w, x, y, z], not all zero: it has zero length");
  await page.fill("[name=r-z]", "-2");
  await page.uncheck("[name=shortestPath]");
  assert.match(await page.textContent("#shortestPath-error"), /^p and r are antipodal and shortestPath is false/);
  await keepShot(page, "errors.png");
  await page.check("[name=shortestPath]");
  assert.equal(await page.textContent("#shortestPath-error"), "");
  assert.match(await page.textContent("#note"), /nothing to interpolate/);
  assert.deepEqual(problems, []);
  await context.close();
});

test("bad URL values show messages, are never HTML, and fall back to the paper", async () => {
  const query = "?p=%3Cimg%20src%3Dx%20onerror%3Dwindow.hacked%3D1%3E,0,0,1&eps=-1&int=<b>x</b>";
  const { page, context, problems } = await open(query);
  assert.equal(await page.textContent("#p-error"), "p must be a quaternion of 4 finite numbers [w, x, y, z], not all zero: its w component is NaN");
  assert.equal(await page.textContent("#tolerance-error"), "tolerance must be a finite number > 0 (got -1)");
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
  const before = await canvasStats(page, "#hopf-canvas");
  await page.focus("#hopf-canvas");
  await page.keyboard.press("ArrowLeft");
  await page.waitForTimeout(50);
  assert.notEqual((await canvasStats(page, "#hopf-canvas")).hash, before.hash);
  assert.deepEqual(problems, []);
  await context.close();
});

test("dragging turns the sphere", async () => {
  const { page, context } = await open("?t=2");
  const box = await page.locator("#hopf-canvas").boundingBox();
  const before = await canvasStats(page, "#hopf-canvas");
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width / 2 + 60, box.y + box.height / 2 + 20, { steps: 4 });
  await page.mouse.up();
  await page.waitForTimeout(50);
  assert.notEqual((await canvasStats(page, "#hopf-canvas")).hash, before.hash);
  await context.close();
});

test("embed=1 is compact; reduced motion does not autoplay; high-DPI is crisp", async () => {
  const embed = await open("?embed=1", { viewport: { width: 640, height: 360 } });
  assert.equal(await embed.page.isVisible("#inputs"), false);
  assert.equal(await embed.page.isVisible("#plots-canvas"), false);
  assert.equal(await embed.page.isVisible("#hopf-canvas"), true);
  await embed.page.waitForTimeout(200);
  await keepShot(embed.page, "embed.png", { fullPage: false });
  assert.deepEqual(embed.problems, []);
  await embed.context.close();

  const calm = await open(""); // prefers reduced motion, as every page not `moving`
  await calm.page.waitForTimeout(300);
  assert.equal(await currentTime(calm.page), 0);
  assert.equal(await calm.page.textContent("#play"), "Play");
  await calm.context.close();

  const sharp = await open("?t=1", { deviceScaleFactor: 2 });
  const stats = await canvasStats(sharp.page, "#hopf-canvas");
  assert.ok(Math.abs(stats.width - 2 * stats.clientWidth) <= 2, `${stats.width} for ${stats.clientWidth} CSS px`);
  await sharp.page.setViewportSize({ width: 700, height: 900 });
  await sharp.page.waitForTimeout(200);
  const narrow = await canvasStats(sharp.page, "#hopf-canvas");
  assert.ok(narrow.width !== stats.width && narrow.drawn > 10000, "redrawn at the new size");
  await keepShot(sharp.page, "narrow.png");
  assert.deepEqual(sharp.problems, []);
  await sharp.context.close();
});

test("works offline once loaded", async () => {
  const { page, context } = await open("?t=1", { serviceWorkers: "allow" });
  await page.evaluate(() => navigator.serviceWorker.ready);
  await page.reload();
  await page.waitForFunction(() => navigator.serviceWorker.controller !== null);
  await context.setOffline(true);
  await page.reload();
  await page.waitForFunction(() => document.querySelector("#load-status").hidden);
  assert.match(await readout(page), /T = 11\.66$/);
  assert.ok((await canvasStats(page, "#hopf-canvas")).drawn > 20000);
  // One cache, named by the build (a hash of the files, written by make www from www/pages.js).
  const build = readFileSync(join(root, "www/pkg/build.js"), "utf8");
  const name = /"cache": "(kli-[0-9a-f]{12})"/.exec(build)?.[1];
  assert.ok(name, build.slice(0, 200));
  assert.deepEqual(await page.evaluate(() => caches.keys()), [name]);
  await context.close();
});

// ---- The defects of issue 7, each found in an audit or a soak run ----------------------------

/** The time the URL holds, or undefined while it holds none. */
const urlTime = (page) => new URL(page.url()).searchParams.get("t") ?? undefined;

test("Space on a focused button presses it: Restart restarts rather than pausing", async () => {
  const { page, context, problems } = await open("?t=5", { moving: true });
  await page.focus("#restart");
  await page.keyboard.press(" ");
  // Restart goes to 0 and plays (no reduced motion here); a page-wide Space would have played
  // from 5 instead.
  await page.waitForFunction(() => document.querySelector("#play").textContent === "Pause");
  assert.ok((await currentTime(page)) < 2, "restarted from 0");
  // Enter on Play presses Play, once.
  await page.focus("#play");
  await page.keyboard.press("Enter");
  assert.equal(await page.textContent("#play"), "Play");
  assert.deepEqual(problems, []);
  await context.close();
});

test("keyboard and slider time changes update the object's label and the URL at once", async () => {
  const { page, context, problems } = await open("?t=1");
  const label = () => page.getAttribute("#object-canvas", "aria-label");
  await page.locator("body").press("End");
  assert.match(await label(), /^The aircraft at t = 11\.66:/);
  await page.waitForFunction(() => new URL(location.href).searchParams.get("t") === "11.66", null, { timeout: 2000 });
  await page.locator("body").press("Home");
  assert.match(await label(), /^The aircraft at t = 0\.00:/);
  await page.waitForFunction(() => new URL(location.href).searchParams.get("t") === "0.00", null, { timeout: 2000 });
  await page.locator("body").press("ArrowRight");
  const stepped = await currentTime(page);
  assert.match(await label(), new RegExp(`^The aircraft at t = ${stepped.toFixed(2)}:`));
  // The slider, moved while paused, updates the label too.
  await page.$eval("#time", (slider) => {
    slider.value = "3.3";
    slider.dispatchEvent(new Event("input", { bubbles: true }));
  });
  assert.match(await label(), /^The aircraft at t = 3\.30:/);
  await page.waitForFunction(() => new URL(location.href).searchParams.get("t") === "3.30", null, { timeout: 2000 });
  // …and the time is announced once it rests.
  await page.waitForFunction(() => document.querySelector("#status").textContent === "t = 3.30 / T = 11.66");
  assert.deepEqual(problems, []);
  await context.close();
});

test("the first load while playing writes no time into the URL", async () => {
  const { page, context, problems } = await open("", { moving: true });
  await page.waitForTimeout(600);
  assert.equal(await page.textContent("#play"), "Pause");
  assert.equal(urlTime(page), undefined, page.url());
  assert.match(page.url(), /eps=0\.00001/);
  // A reload of that URL plays again once its reader is there, and writes no time while it waits.
  await page.reload();
  await page.waitForFunction(() => document.querySelector("#load-status").hidden);
  await page.waitForTimeout(300);
  assert.equal(urlTime(page), undefined, page.url());
  await engage(page);
  await page.waitForTimeout(600);
  assert.equal(await page.textContent("#play"), "Pause");
  assert.deepEqual(problems, []);
  await context.close();
});

test("a long slider drag writes the URL a few times, not once per move", async () => {
  const { page, context } = await open("?t=0");
  await page.evaluate(() => {
    window.__urlWrites = 0;
    const replace = history.replaceState.bind(history);
    history.replaceState = (...args) => {
      window.__urlWrites++;
      return replace(...args);
    };
  });
  // 240 moves, one every 16 ms or so: 4 s of dragging at 60 moves a second on a quiet machine,
  // longer on a busy one. The URL may be written once per 400 ms of the drag's own duration,
  // so the test holds on a machine of any speed.
  const { moves, ms } = await page.evaluate(async () => {
    const slider = document.querySelector("#time");
    const start = performance.now();
    let count = 0;
    for (; count < 240; count++) {
      slider.value = String((11.66 * count) / 240);
      slider.dispatchEvent(new Event("input", { bubbles: true }));
      await new Promise((resolve) => setTimeout(resolve, 16));
    }
    return { moves: count, ms: performance.now() - start };
  });
  await page.waitForTimeout(500);
  const writes = await page.evaluate(() => window.__urlWrites);
  assert.ok(writes <= ms / 400 + 2, `${writes} URL writes for ${moves} moves in ${Math.round(ms)} ms`);
  assert.ok(writes >= 5, `${writes} URL writes: the URL still follows`);
  await context.close();
});

test("a step too large is blamed on the step, and ε = 2 says nothing false about −p", async () => {
  const { page, context, problems } = await open("?t=1");
  await page.fill("[name=step]", "5");
  assert.match(await page.textContent("#step-error"), /^step 5 is too large for integrator rk4: q left the sphere S³/);
  assert.equal(await page.textContent("#shortestPath-error"), "");
  assert.equal(await page.getAttribute("[name=step]", "aria-invalid"), "true");
  await page.fill("[name=step]", "0.01");
  assert.equal(await page.textContent("#step-error"), "");
  await page.fill("[name=tolerance]", "2");
  assert.equal(await page.textContent("#note"), "p is already within ε of the target: nothing to interpolate.");
  // With r = −p (the antipodal preset) the parenthesis is true, and said.
  await page.selectOption("[name=preset]", "antipodal");
  assert.match(await page.textContent("#note"), /nothing to interpolate \(r ≈ −p is the same rotation as p\)/);
  assert.deepEqual(problems, []);
  await context.close();
});

test("only the bad field is marked, and a corrected axis is unmarked", async () => {
  const { page, context, problems } = await open("?t=1");
  const invalid = async (names) => (await Promise.all(names.map((n) => page.getAttribute(`[name=${n}]`, "aria-invalid")))).map((v) => v === "true");
  await page.fill("[name=p-y]", "oops");
  assert.deepEqual(await invalid(["p-w", "p-x", "p-y", "p-z"]), [false, false, true, false]);
  await page.fill("[name=p-y]", "0");
  await page.fill("[name=r-ay]", "why");
  assert.equal(await page.getAttribute("[name=r-ay]", "aria-invalid"), "true");
  assert.notEqual(await page.getAttribute("[name=r-ax]", "aria-invalid"), "true");
  assert.match(await page.textContent("#r-error"), /^r: axis must be 3 finite numbers \[x, y, z\], not all zero: its y component is NaN/);
  await page.fill("[name=r-ay]", "1");
  assert.deepEqual(await invalid(["r-ax", "r-ay", "r-az", "r-angle"]), [false, false, false, false]);
  assert.equal(await page.textContent("#r-error"), "");
  // Every field points to its message.
  const described = await page.$$eval("#inputs input, #inputs select", (fields) =>
    fields.filter((f) => f.name !== "preset").map((f) => [f.name, document.getElementById(f.getAttribute("aria-describedby") ?? "") !== null]));
  assert.deepEqual(described.filter(([, ok]) => !ok), []);
  assert.deepEqual(problems, []);
  await context.close();
});

test("the checkbox and the integrator select each rebuild once", async () => {
  const { page, context, problems } = await open("?t=1");
  const rebuilds = async (action) => {
    await page.evaluate(() => {
      window.__rebuilds = 0;
      window.__observer?.disconnect();
      window.__observer = new MutationObserver((records) => (window.__rebuilds += records.filter((r) => r.removedNodes.length > 0).length));
      window.__observer.observe(document.querySelector("#moments tbody"), { childList: true });
    });
    await action();
    await page.waitForTimeout(100);
    return page.evaluate(() => window.__rebuilds);
  };
  assert.equal(await rebuilds(() => page.uncheck("[name=shortestPath]")), 1);
  assert.equal(await rebuilds(() => page.selectOption("[name=integrator]", "geodesic")), 1);
  assert.deepEqual(problems, []);
  await context.close();
});

test("at 390 px the filmstrip's labels do not overlap and the page fits", async () => {
  const { page, context, problems } = await open("?t=1", { viewport: { width: 390, height: 844 } });
  await page.waitForTimeout(300);
  // Columns of the label band that hold ink, in runs separated by at least 5 blank columns (the
  // renderer keeps labels 6 px apart; a space inside "T 11.66" is narrower).
  const runs = await page.evaluate(() => {
    const canvas = document.querySelector("#filmstrip-canvas");
    const ratio = canvas.width / canvas.clientWidth;
    const ctx = canvas.getContext("2d");
    const top = Math.round(canvas.height - 16 * ratio);
    const band = ctx.getImageData(0, top, canvas.width, Math.round(14 * ratio)).data;
    const inked = Array.from({ length: canvas.width }, (_, x) => {
      for (let y = 0; y < band.length / 4 / canvas.width; y++) {
        const i = 4 * (y * canvas.width + x);
        if (band[i] < 200 || band[i + 1] < 200 || band[i + 2] < 200) return true;
      }
      return false;
    });
    const found = [];
    let gap = Infinity;
    inked.forEach((ink, x) => {
      if (ink) {
        if (gap >= 5 * ratio) found.push([x, x]);
        else found[found.length - 1][1] = x;
        gap = 0;
      } else gap++;
    });
    return { found, width: canvas.width, ratio };
  });
  assert.equal(runs.found.length, 8, JSON.stringify(runs));
  assert.ok(runs.found[0][0] > 0 && runs.found[7][1] < runs.width - 1, "labels inside the canvas");
  assert.ok(await page.evaluate(() => document.documentElement.scrollWidth <= 390), "no horizontal scrolling");
  await keepShot(page, "390px.png");
  assert.deepEqual(problems, []);
  await context.close();
});

test("WCAG 2.2 AA: axe finds nothing on the page, with errors showing, and embedded", async () => {
  const { page, context } = await open("?t=1");
  assert.deepEqual(await axeViolations(page), []);
  await page.fill("[name=p-x]", "abc");
  await page.fill("[name=step]", "0");
  assert.deepEqual(await axeViolations(page), []);
  // Empty error outputs are rendered (in the accessibility tree), so that new text is announced.
  assert.equal(await page.$eval("#r-error", (o) => getComputedStyle(o).display !== "none"), true);
  // The sphere says what it does with keys: not a still picture.
  assert.notEqual(await page.getAttribute("#hopf-canvas", "role"), "img");
  // The focus ring stands out from the white controls' background by at least 3:1 (WCAG 1.4.11).
  await page.focus("#play");
  const ring = await page.$eval("#play", (b) => getComputedStyle(b).outlineColor);
  const luminance = (rgb) => {
    const [r, g, b] = rgb.match(/\d+/g).slice(0, 3).map((c) => {
      const v = Number(c) / 255;
      return v <= 0.04045 ? v / 12.92 : ((v + 0.055) / 1.055) ** 2.4;
    });
    return 0.2126 * r + 0.7152 * g + 0.0722 * b;
  };
  const contrast = (1 + 0.05) / (luminance(ring) + 0.05);
  assert.ok(contrast >= 3, `focus ring ${ring}: ${contrast.toFixed(2)}:1`);
  await context.close();

  const embed = await open("?embed=1&t=1", { viewport: { width: 640, height: 360 } });
  assert.deepEqual(await axeViolations(embed.page), []);
  assert.equal(await embed.page.$$eval("h1", (h) => h.length), 1);
  await embed.context.close();
});

test("memory, wasm memory and the DOM stay flat over rebuilds and playing", async () => {
  const { page, context, problems } = await open("?t=1");
  const cdp = await context.newCDPSession(page);
  const measure = async () => {
    await cdp.send("HeapProfiler.collectGarbage");
    return page.evaluate(() => ({
      heap: performance.memory.usedJSHeapSize,
      nodes: document.getElementsByTagName("*").length,
      wasm: window.__kliMemory(),
    }));
  };
  // The module's memory, read through an empty Float64Buffer's view of it (the page's module
  // instance: the same URL imports the same module).
  await page.evaluate(async () => {
    const { Float64Buffer } = await import("./pkg/kli_demo.js");
    window.__kliMemory = () => {
      const probe = new Float64Buffer(0);
      const bytes = probe.view.buffer.byteLength;
      probe.free();
      return bytes;
    };
  });
  const rebuild = (n) => page.evaluate(async (n) => {
    const field = document.querySelector("[name=step]");
    for (let k = 0; k < n; k++) {
      field.value = k % 2 ? "0.01" : "0.02";
      field.dispatchEvent(new Event("input", { bubbles: true }));
      if (k % 50 === 0) await new Promise((resolve) => requestAnimationFrame(resolve));
    }
  }, n);
  await rebuild(300);
  const before = await measure();
  await rebuild(1200);
  await page.selectOption("#speed", "4");
  await page.click("#play");
  await page.waitForTimeout(3000);
  const after = await measure();
  assert.equal(after.nodes, before.nodes, "DOM nodes");
  assert.equal(after.wasm, before.wasm, "wasm memory");
  assert.ok(after.heap < before.heap * 1.25 + 1e6, `JS heap ${before.heap} → ${after.heap}`);
  assert.deepEqual(problems, []);
  await context.close();
});

test("a first look for students: what they see and what to try comes before the formulas; the paper's figures say they are the paper's", async () => {
  const { page, context, problems } = await open("");
  try {
    const header = await page.locator("header").innerText();
    const look = header.indexOf("An aircraft turns"), formula = header.indexOf("q′ = r − (q·r) q");
    assert.ok(look >= 0 && formula > look, "the first look comes before the formula");
    assert.match(header, /Press Play/);
    // "Fig. 1", "eq. 5" and "Table 1" say whose they are, wherever they are named.
    const text = await page.locator("main").innerText();
    for (const name of ["Fig. 1", "Fig. 2", "eq. 5", "Table 1"]) {
      const bare = [...text.matchAll(new RegExp(`(.{0,12})${name.replace(".", "\\.")}`, "g"))].filter((m) => !/paper's (\w+ )?$/.test(m[1]));
      assert.deepEqual(bare.map((m) => m[0]), [], `${name} named without "the paper's"`);
    }
    // The link to try another end goes to the End r fields.
    await page.locator("#first-look a[href='#end-r']").click();
    assert.equal(await page.evaluate(() => location.hash), "#end-r");
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});
