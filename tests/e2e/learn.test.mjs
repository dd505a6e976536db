// End-to-end tests of the tour (learn.html, made from www/learn/) in Debian's headless Chromium:
// its figures drawn, the clock started only as a moving figure is scrolled to (never with reduced
// motion), the other pages' figures loaded only as their section nears, the text quoting values
// that MATH.md gives or that this file computes afresh (the Kuramoto phases integrated here, the
// closed form, T* from its formula), an exercise setting its figure, printing with the answers,
// WCAG 2.2 AA and 390 px.
import { test } from "node:test";
import assert from "node:assert/strict";
import { readFile } from "node:fs/promises";
import { axeViolations, canvasStats, keepShot, open, painted, setup } from "./browser.mjs";

setup();

const CANVASES = ["euler", "turn", "cover", "slerp", "hopf", "rolled", "phases", "lohe", "kli", "clock", "steps", "drift", "rates"];
const text = (page, selector) => page.textContent(selector).then((t) => t.trim());

/** The Kuramoto figure's phases computed here, apart from the module: 20 natural frequencies evenly
 *  spread on [−0.5, 0.5], phases started at multiples of the golden angle, RK4 at step 0.01 on
 *  θᵢ′ = ωᵢ + (K/N) Σⱼ sin(θⱼ − θᵢ) (summed pair by pair, not through the order parameter);
 *  returns R at time t. */
function kuramotoOrder(coupling, t) {
  const n = 20;
  const omega = Array.from({ length: n }, (_, i) => 0.5 * ((2 * (i + 0.5)) / n - 1));
  const golden = Math.PI * (3 - Math.sqrt(5));
  let theta = Array.from({ length: n }, (_, i) => (i * golden) % (2 * Math.PI));
  const rate = (th) => th.map((ti, i) => omega[i] + (coupling / n) * th.reduce((sum, tj) => sum + Math.sin(tj - ti), 0));
  const h = 0.01;
  for (let k = 0; k < Math.round(t / h); k++) {
    const add = (a, b, f) => a.map((x, i) => x + f * b[i]);
    const k1 = rate(theta), k2 = rate(add(theta, k1, h / 2)), k3 = rate(add(theta, k2, h / 2)), k4 = rate(add(theta, k3, h));
    theta = theta.map((x, i) => x + (h / 6) * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]));
  }
  const [s, c] = theta.reduce(([s, c], x) => [s + Math.sin(x), c + Math.cos(x)], [0, 0]);
  return Math.hypot(s, c) / n;
}

/** The turning rate of piecewise SLERP through `keys` (the tour's keyframes figure's, at times 0,
 *  1, 2, 3), from the keys alone: the piece from a to b turns by θ = 2 acos w about u, where
 *  b ā = cos(θ/2) + sin(θ/2) u (w ≥ 0), so its ω = θ u per unit time; the jump at key k is
 *  |ω_k − ω_(k−1)|. Returns [jump at k1, jump at k2]. */
function slerpJumps(keys) {
  const mul = ([a, b, c, d], [e, f, g, h]) =>
    [a * e - b * f - c * g - d * h, a * f + b * e + c * h - d * g, a * g - b * h + c * e + d * f, a * h + b * g - c * f + d * e];
  const rates = keys.slice(1).map((b, i) => {
    const [a0, ...av] = keys[i];
    let d = mul(b, [a0, ...av.map((x) => -x)]);
    if (d[0] < 0) d = d.map((x) => -x);
    const angle = 2 * Math.acos(Math.min(1, d[0]));
    return d.slice(1).map((x) => (x / Math.sin(angle / 2)) * angle);
  });
  return [1, 2].map((k) => Math.hypot(...rates[k].map((x, i) => x - rates[k - 1][i])));
}

/** Section 9's swarm computed here, apart from the page's module: its 200 starting rotations (seed 1,
 *  uniform on S³) taken from the package, then q_i′ = K(m − (q_i·m) q_i), m the mean (MATH.md, "The
 *  swarm", all-to-all), by plain RK4 at step 0.01, each q_i normalised after a step. Returns R = |m| at
 *  the start and at time `t`, and the largest turn (degrees) of any rotation from its start. */
async function swarm(coupling, t) {
  const kli = await import("../../pkg/swarm.node.js");
  await kli.default();
  const start = new kli.LoheSwarm({ count: 200, coupling, seed: 1 });
  const q0 = [...start.quaternions];
  start.free();
  const n = q0.length / 4;
  const mean = (x) => [0, 1, 2, 3].map((k) => x.reduce((sum, _, i) => (i % 4 === k ? sum + x[i] : sum), 0) / n);
  const field = (x) => {
    const m = mean(x);
    return x.map((_, i) => {
      const j = i - (i % 4);
      const dot = x[j] * m[0] + x[j + 1] * m[1] + x[j + 2] * m[2] + x[j + 3] * m[3];
      return coupling * (m[i % 4] - dot * x[i]);
    });
  };
  const h = 0.01;
  let q = q0.slice();
  for (let step = 0; step < Math.round(t / h); step++) {
    const k1 = field(q);
    const k2 = field(q.map((x, i) => x + (h / 2) * k1[i]));
    const k3 = field(q.map((x, i) => x + (h / 2) * k2[i]));
    const k4 = field(q.map((x, i) => x + h * k3[i]));
    q = q.map((x, i) => x + (h / 6) * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]));
    for (let j = 0; j < q.length; j += 4) {
      const length = Math.hypot(q[j], q[j + 1], q[j + 2], q[j + 3]);
      for (let k = 0; k < 4; k++) q[j + k] /= length;
    }
  }
  let turn = 0;
  for (let j = 0; j < q.length; j += 4) {
    const dot = Math.abs(q[j] * q0[j] + q[j + 1] * q0[j + 1] + q[j + 2] * q0[j + 2] + q[j + 3] * q0[j + 3]);
    turn = Math.max(turn, (2 * Math.acos(Math.min(1, dot)) * 180) / Math.PI);
  }
  return { start: Math.hypot(...mean(q0)), end: Math.hypot(...mean(q)), turn };
}

/** Moves a slider as a reader does: its value, then an input event. */
const slide = (page, selector, value) => page.evaluate(([selector, value]) => {
  const input = /** @type {HTMLInputElement} */ (document.querySelector(selector));
  input.value = value;
  input.dispatchEvent(new Event("input", { bubbles: true }));
}, [selector, value]);

/** MATH.md's closed form on the paper's example: φ(t) with tan(φ/2) = tan(φ₀/2) e^−t, φ₀ = π/3. */
const phiDegrees = (t) => (2 * Math.atan(Math.tan(Math.PI / 6) * Math.exp(-t)) * 180) / Math.PI;
/** MATH.md's T* = ln(tan(φ₀/2) / tan(arcsin(ε/2))). */
const predicted = (epsilon) => Math.log(Math.tan(Math.PI / 6) / Math.tan(Math.asin(epsilon / 2)));

test("the tour draws every figure and quotes MATH.md's values; the clock starts only as a moving figure is reached", async () => {
  const { page, context, problems } = await open("learn.html", { moving: true });
  // A figure far down the tour is not set up at load: its canvas is blank behind its first
  // picture; scrolled to, it is drawn.
  const painted = (selector) => page.evaluate((selector) => {
    const canvas = /** @type {HTMLCanvasElement} */ (document.querySelector(selector));
    const data = canvas.getContext("2d").getImageData(0, 0, canvas.width, canvas.height).data;
    return data.some((value, i) => i % 4 === 3 && value > 0);
  }, selector);
  await page.waitForTimeout(500);
  assert.equal(await painted("#learn-drift"), false, "the drift figure drawn at load");
  assert.equal(await page.locator("#learn-drift-first").count(), 1);
  for (const name of ["euler", "turn", "cover", "slerp"]) {
    await page.locator(`#learn-${name}`).scrollIntoViewIfNeeded();
    await page.waitForFunction((id) => !document.getElementById(`${id}-first`), `learn-${name}`, { timeout: 5000 });
    assert.ok((await canvasStats(page, `#learn-${name}`)).drawn > 2000, name);
  }
  assert.equal(await painted("#learn-euler"), true);
  await page.evaluate(() => scrollTo(0, 0));
  // The section of section 7: the paper's example, ε = 1e-5, δ = 0.01: T = 11.66 and T* = 11.6568.
  const steps = await text(page, "#steps-out");
  assert.match(steps, /stops after 1166 steps, at T = 11\.66; T\* = 11\.6568\./);
  assert.equal(predicted(1e-5).toFixed(4), "11.6568");
  // A quarter turn about z: cos 45° + sin 45° k; the nose (x) goes to y (MATH.md's h(r) = (0, 1, 0) too).
  assert.equal(await text(page, "#turn-out"), "q = 0.707 + 0.000 i + 0.000 j + 0.707 k");
  assert.equal(await text(page, "#hopf-out"), "The nose points to (0.000, 1.000, 0.000); a wing to (−1.000, 0.000, 0.000).");
  // The yaw and bank axes at pitch 40° are 90° − 40° apart.
  assert.equal(await text(page, "#lock-out"), "50.0°");
  // Nothing plays while the moving figures are off screen.
  await page.waitForTimeout(800);
  assert.equal(await text(page, "#play"), "Play");
  assert.equal(await text(page, "#readout"), "t = 0.00 / 12.00");
  // The other pages' figures are not loaded yet.
  assert.equal(await page.evaluate(() => customElements.get("kli-figure")), undefined);
  // Scrolled to the phases, the clock starts from 0 and the text follows it.
  await page.locator("#learn-phases").scrollIntoViewIfNeeded();
  await page.waitForFunction(() => document.querySelector("#play").textContent === "Pause", null, { timeout: 5000 });
  await page.waitForFunction(() => /At t = [1-9]/.test(document.querySelector("#phases-out").textContent), null, { timeout: 10000 });
  // Let section 6 run on, then come to section 7: the clock starts again from 0 there, so KLI's
  // figure is seen in mid-flow (not at its end with φ = 0), and again each time another moving
  // figure comes into view.
  const shownTime = () => page.evaluate(() => Number(document.querySelector("#readout").textContent.match(/^t = ([\d.]+)/)[1]));
  await page.waitForFunction(() => /At t = ([3-9]|1\d)\./.test(document.querySelector("#phases-out").textContent), null, { timeout: 15000 });
  assert.ok((await shownTime()) >= 3);
  await page.locator("#learn-kli").scrollIntoViewIfNeeded();
  await page.waitForFunction(() => Number(document.querySelector("#kli-out").textContent.match(/^At t = ([\d.]+)/)[1]) < 1.5, null, { timeout: 3000 });
  assert.ok((await shownTime()) < 2, `t = ${await shownTime()} in section 7`);
  assert.equal(await text(page, "#play"), "Pause");
  await page.waitForFunction(() => /At t = [1-9]/.test(document.querySelector("#kli-out").textContent), null, { timeout: 10000 });
  await page.locator("#learn-phases").scrollIntoViewIfNeeded();
  await page.waitForFunction(() => Number(document.querySelector("#phases-out").textContent.match(/^At t = ([\d.]+)/)[1]) < 1, null, { timeout: 3000 });
  for (const name of ["phases", "lohe", "kli", "clock", "steps", "drift", "hopf", "rolled"]) {
    await page.locator(`#learn-${name}`).scrollIntoViewIfNeeded();
    await page.waitForFunction((id) => !document.getElementById(`${id}-first`), `learn-${name}`, { timeout: 5000 });
    assert.ok((await canvasStats(page, `#learn-${name}`)).drawn > 2000, name);
  }
  // Paused at a time, the phases' R is the one computed here, and KLI's φ the closed form's.
  await page.click("#play");
  await page.evaluate(() => {
    const time = /** @type {HTMLInputElement} */ (document.querySelector("#time"));
    time.value = "6";
    time.dispatchEvent(new Event("input", { bubbles: true }));
  });
  const phases = await text(page, "#phases-out");
  const [, r] = phases.match(/^At t = 6\.00, R = ([\d.]+)\.$/);
  assert.ok(Math.abs(Number(r) - kuramotoOrder(1.5, 6)) < 2e-3, `${phases} against ${kuramotoOrder(1.5, 6)}`);
  assert.match(await text(page, "#kli-out"), new RegExp(`^At t = 6\\.00, φ = ${phiDegrees(6).toFixed(2)}°`));
  // The many rotations: the other pages' figures come as their section nears, and draw.
  await page.locator("#many").scrollIntoViewIfNeeded();
  await page.waitForFunction(() => customElements.get("kli-figure") !== undefined, null, { timeout: 10000 });
  await page.locator("#fig-average").scrollIntoViewIfNeeded();
  await page.waitForFunction(() => {
    const canvas = document.querySelector("#fig-average")?.shadowRoot?.querySelector("canvas");
    return canvas && canvas.width > 300;
  }, null, { timeout: 20000 });
  await keepShot(page, "learn.png");
  assert.deepEqual(problems, []);
  await context.close();
});

test("an exercise opens, sets its figure, and its answer is the one the figure then shows", async () => {
  const { page, context, problems } = await open("learn.html");
  // One more digit of ε: T* grows by about ln 10.
  const digits = page.locator("details.exercise", { hasText: "one more digit" });
  await digits.locator(":scope > summary").click();
  await digits.locator("a.set").click();
  await page.waitForURL(/digits=6/);
  const want = predicted(1e-6);
  assert.equal(want.toFixed(4), "13.9594");
  assert.match(await text(page, "#steps-out"), new RegExp(`at T = 13\\.96; T\\* = ${want.toFixed(4)}\\.`));
  assert.equal(await page.inputValue("[name=digits]"), "6");
  assert.equal(await page.getAttribute("[name=digits]", "aria-valuetext"), "ε = 10⁻⁶");
  // The clock (and the plots' axes) now run past that stop, to 15, so T and T* are on show.
  assert.match(await text(page, "#readout"), / \/ 15\.00$/);
  assert.equal(await page.getAttribute("#time", "max"), "15");
  // Halfway along the arc: φ = 30° at t = ln(tan 30° / tan 15°) = 0.768.
  const half = page.locator("details.exercise", { hasText: "halfway along the arc" });
  await half.locator(":scope > summary").click();
  await half.locator("a.set").click();
  assert.equal(await text(page, "#readout"), "t = 0.77 / 15.00");
  assert.equal(Math.log(Math.tan(Math.PI / 6) / Math.tan(Math.PI / 12)).toFixed(3), "0.768");
  assert.match(await text(page, "#kli-out"), new RegExp(`^At t = 0\\.77, φ = ${phiDegrees(0.77).toFixed(2)}°, s = 0\\.50`));
  // Gimbal lock: the axes 0° apart; a full turn: q = −1; NLERP behind SLERP at s = 0.25.
  await page.locator("details.exercise", { hasText: "pitch 90°" }).locator(":scope > summary").click();
  await page.locator("details.exercise", { hasText: "pitch 90°" }).locator("a.set").click();
  assert.equal(await text(page, "#lock-out"), "0.0°");
  await page.click("a.set[href='?angle=360#cover']");
  assert.equal(await text(page, "#cover-out"), "θ = 360°, q = −1.000 + 0.000 i + 0.000 j + 0.000 k");
  assert.equal(await page.getAttribute("[name=angle]", "aria-valuetext"), "360° about z");
  // A turn by 120° about the diagonal, which the figure does not show at load (a quarter turn
  // about z, tested above): cos 60° + sin 60° (i + j + k)/√3, each part 0.5.
  // Opening the question does not give its answer away: that takes a second press.
  const turn = page.locator("details.exercise", { hasText: "120° about the diagonal" });
  await turn.locator(":scope > summary").click();
  const answer = turn.locator("details.answer p");
  assert.equal(await answer.isVisible(), false, "the answer shows as the question opens");
  // Its link sets the figure above, off screen once the question is read, and brings it in.
  await page.evaluate(() => document.querySelector("#turn details.exercise")?.scrollIntoView({ block: "start" }));
  const figureOut = () => page.evaluate(() => {
    const box = document.querySelector("#turn figure")?.getBoundingClientRect();
    return !box || box.bottom < 0 || box.top > innerHeight;
  });
  assert.equal(await figureOut(), true, "the figure should be off screen before the link");
  await turn.locator("a.set").click();
  await page.waitForFunction(() => {
    const box = document.querySelector("#turn figure")?.getBoundingClientRect();
    return box && box.bottom > 0 && box.top < innerHeight;
  });
  const part = (Math.sin(Math.PI / 3) / Math.sqrt(3)).toFixed(3);
  assert.equal(await text(page, "#turn-out"), `q = ${Math.cos(Math.PI / 3).toFixed(3)} + ${part} i + ${part} j + ${part} k`);
  await turn.locator("details.answer > summary").click();
  assert.match(await answer.textContent(), /q = 0\.5 \+ 0\.5 i \+ 0\.5 j \+ 0\.5 k/);
  assert.equal(await answer.isVisible(), true);
  await page.locator("details.exercise", { hasText: "s = 0.25" }).locator(":scope > summary").click();
  await page.locator("details.exercise", { hasText: "s = 0.25" }).locator("a.set").click();
  const nlerp = (Math.atan2(0.25 * Math.sin(Math.PI / 3), 0.75 + 0.25 * Math.cos(Math.PI / 3)) * 180) / Math.PI;
  assert.equal(await text(page, "#slerp-out"), `At s = 0.25 SLERP is 15.00° along the arc, NLERP ${nlerp.toFixed(2)}°.`);
  // A roll leaves the Hopf point where it was.
  const before = await text(page, "#hopf-out");
  await page.locator("details.exercise", { hasText: "roll by 180°" }).locator(":scope > summary").click();
  await page.locator("details.exercise", { hasText: "roll by 180°" }).locator("a.set").click();
  const after = await text(page, "#hopf-out");
  assert.equal(after.slice(0, after.indexOf(";")), before.slice(0, before.indexOf(";")));
  assert.notEqual(after, before);
  // Printed as a handout: each question numbered in its section with its answer hidden there, the
  // answers together at the end in the same order, and no control on paper.
  await page.emulateMedia({ media: "print" });
  await page.evaluate(() => dispatchEvent(new Event("beforeprint")));
  const printed = await page.evaluate(() => {
    const exercises = [...document.querySelectorAll("details.exercise")];
    const answers = [...document.querySelectorAll("#print-answers li")];
    const main = document.querySelector("main");
    return {
      count: exercises.length,
      hiddenInPlace: exercises.every((d) => !d.open && d.querySelector("p")?.checkVisibility() === false),
      numbered: exercises.map((d) => getComputedStyle(d.querySelector("summary"), "::before").content),
      answers: answers.map((li) => ({ question: li.querySelector(".question")?.textContent, shown: li.checkVisibility(), text: li.textContent.length })),
      questions: exercises.map((d) => d.querySelector("summary")?.textContent),
      atEnd: main?.lastElementChild?.id,
      controls: [...document.querySelectorAll(".transport, .contents, button, input")].filter((e) => e.checkVisibility()).length,
      duplicateIds: [...document.querySelectorAll("#print-answers [id]")].length,
    };
  });
  assert.ok(printed.count >= 9, JSON.stringify(printed));
  assert.ok(printed.hiddenInPlace, "an answer prints in its section");
  assert.deepEqual(printed.numbered, printed.questions.map((_, i) => `"${i + 1}. "`));
  assert.equal(printed.atEnd, "print-answers");
  assert.deepEqual(printed.answers.map((a) => a.question), printed.questions);
  assert.ok(printed.answers.every((a) => a.shown && a.text > (a.question?.length ?? 0) + 20), JSON.stringify(printed.answers));
  assert.equal(printed.controls, 0, "no control on paper");
  assert.equal(printed.duplicateIds, 0);
  // After printing, the page is as it was.
  await page.evaluate(() => dispatchEvent(new Event("afterprint")));
  assert.equal(await page.locator("#print-answers").count(), 0);
  assert.deepEqual(problems, []);
  await context.close();
});

test("the turning rate through the keyframes: drawn, quoted as the smoothness slider moves, and its exercise", async () => {
  const { page, context, problems } = await open("learn.html");
  // The keys the figure beside the plot draws: the module gives it those its rate is computed
  // through (were they another's, the jumps quoted below would not be these keys').
  const shown = (await page.getAttribute("#fig-keyframes", "keys")).split(";").map((key) => key.split(",").map(Number));
  const [k1, k2] = slerpJumps(shown);
  // The keys' own numbers: a 73.7° turn about x, then 122.6° turns whose axes are 72.6° apart.
  assert.equal(k1.toFixed(2), "2.92");
  assert.equal(k2.toFixed(2), "2.53");
  await page.locator("#learn-rates").scrollIntoViewIfNeeded();
  await page.waitForFunction(() => !document.getElementById("learn-rates-first"), null, { timeout: 5000 });
  assert.ok((await painted(page, "#learn-rates", 3000)) > 3000, "the turning rate drawn");
  const picture = () => page.$eval("#learn-rates", (canvas) => /** @type {HTMLCanvasElement} */ (canvas).toDataURL());
  const smooth = await picture();
  // Smoothness 1: no jump, a finite |ω̇|; piecewise SLERP's largest jump, at k1, as computed here.
  const quoted = (s) => new RegExp(`^At smoothness ${s} ω has no jump at any key; its largest rate of change \\|ω̇\\| is ` +
    `([\\d.]+) rad per unit time²\\. Piecewise SLERP jumps by ${k1.toFixed(2)} rad per unit time at k1\\.$`);
  const one = (await text(page, "#rates-out")).match(quoted(1));
  assert.ok(one, await text(page, "#rates-out"));
  // The slider: at 0 the chain is piecewise SLERP and ω jumps, by the keys' own difference; the
  // keyframes figure beside it follows, and so does the URL.
  await slide(page, "[name=smoothness]", "0");
  assert.equal(await text(page, "#rates-out"),
    `At smoothness 0 the chain is piecewise SLERP: at k1 ω jumps by ${k1.toFixed(2)} rad per unit time in an instant, an unbounded angular acceleration.`);
  assert.equal(await page.getAttribute("#fig-keyframes", "smoothness"), "0");
  assert.equal(await page.getAttribute("[name=smoothness]", "aria-valuetext"), "smoothness 0");
  await page.waitForURL(/smooth=0/);
  assert.ok((await painted(page, "#learn-rates", 3000)) > 3000);
  // A still view is drawn in a task of its own after the frame: wait for it (up to 5 s).
  await page.waitForFunction((before) => document.querySelector("#learn-rates").toDataURL() !== before, smooth, { timeout: 5000 }).catch(() => {});
  assert.notEqual(await picture(), smooth, "the figure follows the slider");
  // Less smoothness, more angular acceleration near the keys.
  await slide(page, "[name=smoothness]", "0.05");
  const little = (await text(page, "#rates-out")).match(quoted(0.05));
  assert.ok(little && Number(little[1]) > Number(one[1]), `${little?.[1]} against ${one[1]}`);
  // Saved from the Save section as SVG: the figure as it stands, its words in it.
  const [download] = await Promise.all([page.waitForEvent("download"), page.click('button[data-save="rates"][data-format="svg"]')]);
  assert.equal(download.suggestedFilename(), "kli-tour-rates.svg");
  const svg = await readFile(await download.path(), "utf8");
  assert.match(svg, /^<svg[^]*\|ω\(t\)\|, the turning rate[^]*KLI chain, smoothness 0\.05/);
  // The exercise: predict the jump at k2, where |ω| is the same on both sides; its link sets 0.
  const exercise = page.locator("details.exercise", { hasText: "Does ω jump at k2" });
  await exercise.locator(":scope > summary").click();
  await exercise.locator("a.set").click();
  await page.waitForURL(/smooth=0(&|#|$)/);
  assert.equal(await page.inputValue("[name=smoothness]"), "0");
  assert.equal(await page.getAttribute("#fig-keyframes", "smoothness"), "0");
  assert.match(await text(page, "#rates-out"), /^At smoothness 0 the chain is piecewise SLERP/);
  assert.match(await exercise.textContent(), new RegExp(`Yes, by ${k2.toFixed(2)} rad per unit time`));
  assert.deepEqual(problems, []);
  await context.close();
  // The same view as a <kli-figure> for a course page (figure/), with its own smoothness.
  const figure = await open("figure/?view=rates&smoothness=0&title=The%20turning%20rate");
  assert.ok((await painted(figure.page, "kli-figure", 3000)) > 3000, "the rates figure on its own");
  assert.deepEqual(figure.problems, []);
  await figure.context.close();
});

test("the swarm: 200 rotations gather at K = 1; its exercise's push, K = −1, barely moves them", async () => {
  const [pull, push] = [await swarm(1, 8), await swarm(-1, 8)];
  // The paragraph: one dot by t = 8 at K = 1. The answer: R = 0.034 at the start, 0.000 at t = 8,
  // the farthest turn about 5°.
  assert.ok(pull.end > 0.99, String(pull.end));
  assert.equal(push.start.toFixed(3), "0.034");
  assert.equal(push.end.toFixed(3), "0.000");
  assert.equal(Math.round(push.turn), 5);
  const { page, context, problems } = await open("learn.html");
  await page.locator("#many-swarm").scrollIntoViewIfNeeded();
  await page.waitForFunction(() => customElements.get("kli-figure") !== undefined, null, { timeout: 10000 });
  // With reduced motion the figure stands at t = 8: its own R is the one computed here.
  const figure = (coupling) => page.waitForFunction((coupling) => {
    const f = /** @type {any} */ (document.querySelector("#fig-swarm"));
    return f?.getAttribute("coupling") === coupling && f.run && Math.abs(f.t - 8) < 1e-9 && { order: f.run.summary.orderParameter };
  }, coupling, { timeout: 30000 }).then((handle) => handle.jsonValue()).then((v) => v.order);
  const gathered = await figure("1");
  assert.ok(Math.abs(gathered - pull.end) < 2e-3, `${gathered} against ${pull.end}`);
  const exercise = page.locator("details.exercise", { hasText: "Do they fly apart" });
  await exercise.locator(":scope > summary").click();
  await exercise.locator("button.set-figure").click();
  const balanced = await figure("-1");
  assert.ok(Math.abs(balanced - push.end) < 1e-3, `${balanced} against ${push.end}`);
  assert.equal(await page.inputValue('input[data-figure="fig-swarm"]'), "-1");
  assert.equal(await page.getAttribute('input[data-figure="fig-swarm"]', "aria-valuetext"), "K = -1");
  assert.equal(await text(page, "#many output.figure-value"), "K = -1", "the value in sight beside its slider");
  const answer = await exercise.textContent();
  assert.match(answer, new RegExp(`the farthest by a turn of about ${Math.round(push.turn)}°`));
  assert.match(answer, new RegExp(`R = ${push.start.toFixed(3)} at the start`));
  assert.match(answer, new RegExp(`R is ${push.end.toFixed(3)} by t = 8`));
  assert.deepEqual(problems, []);
  await context.close();
});

test("reduced motion: nothing plays by itself, not even as a moving figure is reached", async () => {
  const { page, context, problems } = await open("learn.html");
  await page.locator("#learn-phases").scrollIntoViewIfNeeded();
  await page.waitForTimeout(1200);
  assert.equal(await text(page, "#play"), "Play");
  assert.equal(await text(page, "#readout"), "t = 0.00 / 12.00");
  // The reader's own press plays it.
  await page.click("button.play-from[data-figure=phases]");
  await page.waitForFunction(() => document.querySelector("#readout").textContent !== "t = 0.00 / 12.00", null, { timeout: 5000 });
  await page.click("#play");
  // KLI's path has its own press beside it, which starts the motion from t = 0 where it is read.
  await page.locator("#learn-kli").scrollIntoViewIfNeeded();
  await page.click("button.play-from[data-figure=kli-path]");
  await page.waitForFunction(() => /^t = 0\.[0-9]{2} \//.test(document.querySelector("#readout").textContent) && document.querySelector("#play").textContent !== "Play", null, { timeout: 5000 });
  await page.click("#play");
  // The other pages' figures come still, at a time of their own, never autoplaying.
  await page.locator("#many").scrollIntoViewIfNeeded();
  await page.waitForFunction(() => customElements.get("kli-figure") !== undefined, null, { timeout: 10000 });
  assert.deepEqual(await page.$$eval("kli-figure", (all) => all.filter((f) => f.hasAttribute("autoplay")).length), 0);
  // The keyframes stand where the text says the three curves' points are apart: between k2 (t = 2)
  // and k3, the end (where all three sit on k3).
  await page.waitForFunction(() => {
    const figure = /** @type {any} */ (document.querySelector("#fig-keyframes"));
    return figure.end === 3 && figure.t > 2 && figure.t < figure.end;
  }, null, { timeout: 10000 });
  assert.deepEqual(problems, []);
  await context.close();
});

test("WCAG 2.2 AA and 390 px, every control in words", async () => {
  const { page, context } = await open("learn.html");
  // Every slider of the tour says its value in words.
  const sliders = await page.$$eval("input[type=range]", (all) => all.map((s) => [s.name || s.id || s.dataset.attribute, s.getAttribute("aria-valuetext")]));
  assert.ok(sliders.length >= 16);
  for (const [name, words] of sliders) assert.ok(words && /[a-zθεδ°%=]/.test(words), `${name}: ${words}`);
  assert.equal(await page.getAttribute("[name=angle]", "aria-valuetext"), "90° about z");
  // Every canvas is described in words.
  for (const name of CANVASES) assert.ok(((await page.getAttribute(`#learn-${name}`, "aria-label")) ?? "").length > 40, name);
  // The glossary: each term links to where the tour explains it.
  const glossary = await page.$$eval("#glossary dd a", (links) => links.map((a) => a.getAttribute("href")));
  assert.ok(glossary.length >= 20);
  for (const href of glossary) assert.ok(await page.$(href), href);
  await page.locator("#many").scrollIntoViewIfNeeded();
  await page.waitForFunction(() => customElements.get("kli-figure") !== undefined, null, { timeout: 10000 });
  // Each of the other pages' figures says what it shows once its module has built it.
  await page.waitForFunction(() => [...document.querySelectorAll("kli-figure")]
    .every((f) => f.shadowRoot?.querySelector("canvas")?.getAttribute("aria-label")), null, { timeout: 30000 });
  assert.deepEqual(await axeViolations(page), []);
  await context.close();
  const narrow = await open("learn.html", { viewport: { width: 390, height: 844 } });
  assert.ok(await narrow.page.evaluate(() => document.documentElement.scrollWidth <= 390), "no horizontal scrolling");
  for (const name of ["euler", "cover", "hopf", "phases", "kli"]) {
    await narrow.page.locator(`#learn-${name}`).scrollIntoViewIfNeeded();
    await narrow.page.waitForFunction((id) => !document.getElementById(`${id}-first`), `learn-${name}`, { timeout: 5000 });
    assert.ok((await canvasStats(narrow.page, `#learn-${name}`)).drawn > 1500, name);
  }
  assert.deepEqual(await axeViolations(narrow.page), []);
  await keepShot(narrow.page, "learn-390px.png");
  assert.deepEqual(narrow.problems, []);
  await narrow.context.close();
});
