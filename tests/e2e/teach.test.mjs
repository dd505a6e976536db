// Figures that teach on their own (issue 15): the legends and labels are in the figures (so in
// their SVG, PNG and video), labels of coinciding keys do not overlap and a turn the sphere
// cannot show is said; the text scales for a projector; printing puts each figure in as its SVG
// at the chosen time; a <kli-figure> whose script cannot run says so in its box.
import { test } from "node:test";
import assert from "node:assert/strict";
import { chromium } from "playwright-core";
import { TEST_CHROMIUM } from "../../scripts/static-server.mjs";
import { setup, open, root } from "./browser.mjs";

setup();

/** The texts of a view's SVG as the page's module draws it now, and their font sizes. */
const svgTexts = (page, view) => page.evaluate(async (view) => {
  const [download] = await Promise.all([
    new Promise((resolve) => {
      const original = URL.createObjectURL;
      URL.createObjectURL = (blob) => {
        URL.createObjectURL = original;
        resolve(blob.text());
        return original(blob);
      };
    }),
    document.querySelector(`button[data-save="${view}"][data-format="svg"]`).click(),
  ]);
  const doc = new DOMParser().parseFromString(await download, "image/svg+xml");
  return Array.from(doc.querySelectorAll("text"), (t) => ({ text: t.textContent, size: Number(t.getAttribute("font-size")) }));
}, view);

test("KLI page: the Hopf figure's legend says which curve is which, in its SVG too; labels h(p) and h(r)", async () => {
  const { page, context, problems } = await open("?t=1.8");
  try {
    const texts = (await svgTexts(page, "hopf")).map((t) => t.text);
    for (const wanted of ["KLI", "SLERP", "h(p), the start", "h(r), the end", "Table 1's times (the paper's)", "KLI and SLERP: one arc, two speeds", "h(p)", "h(r)"]) {
      assert.ok(texts.includes(wanted), `${wanted} in ${texts.join(" | ")}`);
    }
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});

test("keyframes page with the README's keys: k0 and k1 share a label, the hidden turn is said, the curves have a legend", async () => {
  const { page, context, problems } = await open("keyframes.html?keys=1,0,0,0;0.8,0.6,0,0;0.6,0,0.8,0;0,0,0.6,0.8");
  try {
    const texts = (await svgTexts(page, "hopf")).map((t) => t.text);
    assert.ok(texts.includes("k0, k1"), texts.join(" | "));
    assert.ok(!texts.includes("k0") && !texts.includes("k1"), "no label drawn over another");
    // Said in lines that keep clear of the axis labels.
    assert.ok(texts.join(" ").includes("k0 → k1: turns about the body's x-axis: not seen here"), texts.join(" | "));
    for (const wanted of ["Kuramoto–Lohe chain", "Squad", "piecewise SLERP", "k0, k1, …: the keys"]) assert.ok(texts.includes(wanted), wanted);
    const plots = (await svgTexts(page, "plots")).map((t) => t.text);
    // The curves have one name each, in every figure.
    for (const wanted of ["Kuramoto–Lohe chain", "Squad", "piecewise SLERP"]) assert.ok(plots.includes(wanted), `${wanted} in the plots' legend`);
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});

test("text size: ?text=2 doubles every label, the page's choice sets it back, and the swarm's figures scale too", async () => {
  const { page, context, problems } = await open("?t=1.8&text=2");
  try {
    const size = async () => (await svgTexts(page, "hopf")).find((t) => t.text === "h(p)").size;
    assert.equal(await page.locator('select[name="text-size"]').inputValue(), "2");
    assert.equal(await size(), 24);
    await page.locator('select[name="text-size"]').selectOption("1");
    assert.equal(await size(), 12);
    await page.locator('select[name="text-size"]').selectOption("3");
    assert.equal(await size(), 36);
    // The plots' margins grow with the text: at 2× every right-aligned tick label (0.56 em a
    // character, the SVG's own estimate) still starts inside the figure.
    await page.locator('select[name="text-size"]').selectOption("2");
    const ticks = await page.evaluate(async () => {
      const demo = await import("./pkg/kli_demo.js");
      const run = new demo.KliDemo([0, 0, 0, 1], [0.5, 0.5, 0.5, 0.5]);
      const svg = run.toSvg("plots", { width: 1200, height: 300, textScale: 2 });
      run.free();
      const doc = new DOMParser().parseFromString(svg, "image/svg+xml");
      return Array.from(doc.querySelectorAll('text[text-anchor="end"]'), (t) =>
        Number(t.getAttribute("x")) - 0.56 * Number(t.getAttribute("font-size")) * t.textContent.length);
    });
    assert.ok(ticks.length > 10 && ticks.every((left) => left >= 0), ticks.join(", "));
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
  const swarm = await open("swarm.html?n=20&text=1.5");
  try {
    const texts = await svgTexts(swarm.page, "hopf");
    assert.equal(texts.find((t) => t.text === "x").size, 19.5);
    assert.deepEqual(swarm.problems, []);
  } finally {
    await swarm.context.close();
  }
});

test("print: every figure of the page as its SVG at ?print=, the canvases hidden, taken out after", async () => {
  const { page, context, problems } = await open("?t=5&print=1.8");
  try {
    await page.emulateMedia({ media: "print" });
    await page.evaluate(() => dispatchEvent(new Event("beforeprint")));
    const printed = await page.evaluate(() => Array.from(document.querySelectorAll(".print-figure svg"), (svg) => ({
      title: svg.querySelector("title").textContent, text: svg.textContent, shown: getComputedStyle(svg.parentElement).display,
    })));
    assert.equal(printed.length, 4);
    assert.ok(printed.every((p) => p.shown === "block"));
    assert.match(printed.find((p) => /Hopf/.test(p.title)).text, /t = 1\.80/);
    assert.equal(await page.evaluate(() => getComputedStyle(document.querySelector("#hopf-canvas")).display), "none");
    await page.evaluate(() => dispatchEvent(new Event("afterprint")));
    await page.emulateMedia({ media: "screen" });
    assert.equal(await page.evaluate(() => document.querySelectorAll(".print-figure").length), 0);
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
  // A ?print= that is no number prints the time on show.
  const other = await open("?t=5&print=soon");
  try {
    await other.page.evaluate(() => dispatchEvent(new Event("beforeprint")));
    const hopf = await other.page.evaluate(() => Array.from(document.querySelectorAll(".print-figure svg"))
      .find((svg) => /Hopf/.test(svg.querySelector("title").textContent)).textContent);
    assert.match(hopf, /t = 5\.00/);
    assert.deepEqual(other.problems, []);
  } finally {
    await other.context.close();
  }
});

test("a <kli-figure> whose script cannot run (module scripts from file://) says so in its box", async () => {
  const browser = await chromium.launch(TEST_CHROMIUM);
  try {
    const page = await browser.newPage();
    await page.goto(`file://${root}www/examples/figures.html`);
    await page.waitForTimeout(500);
    const figure = await page.evaluate(() => {
      const element = document.querySelector("kli-figure");
      const box = element.getBoundingClientRect();
      return { defined: Boolean(customElements.get("kli-figure")), height: box.height, message: getComputedStyle(element, "::before").content };
    });
    assert.equal(figure.defined, false);
    assert.ok(figure.height > 100, `${figure.height} px tall`);
    assert.match(figure.message, /the figure's script did not run: module scripts do not load from file:\/\//);
  } finally {
    await browser.close();
  }
});
