// The example deck (www/examples/slides.html): reveal.js from the dev dependencies, served
// locally, a lecture in the tour's order with a <kli-figure> and speaker notes on each slide. As a
// teacher uses it: a figure animates on its slide
// and stops off it, stays sharp when reveal.js scales the deck, and the deck's PDF (reveal.js's
// print-pdf mode, printed by Chromium) holds the figures as vector paths, not images.
import { test } from "node:test";
import assert from "node:assert/strict";
import { inflateSync } from "node:zlib";
import { open, painted, setup } from "./browser.mjs";

setup();

/** A hash of a figure's canvas pixels (in its shadow root). */
const canvasHash = (page, id) => page.evaluate((id) => {
  const canvas = document.getElementById(id).shadowRoot.querySelector("canvas");
  const data = canvas.getContext("2d").getImageData(0, 0, canvas.width, canvas.height).data;
  let hash = 0;
  for (let i = 0; i < data.length; i += 16) hash = (hash * 31 + data[i]) | 0;
  return hash;
}, id);

const figureReady = (page, id) => page.waitForFunction((id) => {
  const figure = document.getElementById(id);
  return figure?.shadowRoot && figure.run && figure.shadowRoot.querySelector("canvas").width > 10;
}, id);

test("a figure animates on its slide, stops off it, and is drawn at the pixels it covers when the deck scales", async () => {
  const { page, context, problems } = await open("examples/slides.html#/slide-hopf", { moving: true, viewport: { width: 1500, height: 1000 } });
  try {
    await figureReady(page, "hopf");
    const first = await canvasHash(page, "hopf");
    await page.waitForTimeout(400);
    assert.notEqual(await canvasHash(page, "hopf"), first, "the Hopf figure moves on its slide");
    // Sharp: reveal.js scales the 960 × 700 slide to the window; the canvas has the pixels it covers.
    const fit = await page.evaluate(() => {
      const canvas = document.getElementById("hopf").shadowRoot.querySelector("canvas");
      const box = canvas.getBoundingClientRect();
      return { width: canvas.width, height: canvas.height, box: [box.width, box.height], scale: window.Reveal?.getScale?.() };
    });
    assert.ok(Math.abs(fit.width - fit.box[0]) <= 2 && Math.abs(fit.height - fit.box[1]) <= 2, JSON.stringify(fit));
    // Another slide: the figure stops asking for frames.
    await page.evaluate(() => window.location.hash = "#/0");
    await page.waitForTimeout(300);
    const away = await canvasHash(page, "hopf");
    await page.waitForTimeout(400);
    assert.equal(await canvasHash(page, "hopf"), away, "no frames off its slide");
    assert.equal(await page.evaluate(() => document.getElementById("hopf").player.frame), 0);
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});

test("the deck's PDF holds the figures as vector paths and no images", async () => {
  const { page, context, problems } = await open("examples/slides.html?print-pdf", { viewport: { width: 1280, height: 900 } });
  try {
    for (const id of ["hopf", "object", "keyframes"]) await figureReady(page, id);
    await page.emulateMedia({ media: "print" });
    // What the browser does before it prints: each figure swaps its canvas for its SVG.
    await page.evaluate(() => dispatchEvent(new Event("beforeprint")));
    const svgs = await page.evaluate(() => ["hopf", "object", "keyframes"].map((id) =>
      document.getElementById(id).shadowRoot.querySelectorAll(".print-figure svg").length));
    assert.deepEqual(svgs, [1, 1, 1]);
    // The printed time: print-t="1.8" on the Hopf figure.
    assert.match(await page.evaluate(() => document.getElementById("hopf").shadowRoot.querySelector(".print-figure svg").textContent), /t = 1\.80/);
    const pdf = await page.pdf({ width: "960px", height: "700px", printBackground: true });
    const text = pdf.toString("latin1");
    assert.equal((text.match(/\/Subtype\s*\/Image/g) ?? []).length, 0, "no image objects");
    // The page content streams, inflated: the figures' curves are many path segments.
    let segments = 0;
    for (const match of text.matchAll(/stream\r?\n([\s\S]*?)\r?\nendstream/g)) {
      try {
        const content = inflateSync(Buffer.from(match[1], "latin1")).toString("latin1");
        segments += (content.match(/ l\n| c\n/g) ?? []).length;
      } catch {
        // not a deflated stream (a font, say)
      }
    }
    assert.ok(segments > 1000, `${segments} path segments`);
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});

test("the lecture: every slide has speaker notes, the notes plugin is on, and every figure draws on its slide", async () => {
  const { page, context, problems } = await open("examples/slides.html", { viewport: { width: 1280, height: 900 } });
  try {
    await page.waitForFunction(() => window.Reveal?.isReady?.());
    const slides = await page.evaluate(() => Array.from(document.querySelectorAll(".slides > section"), (section) => ({
      notes: section.querySelector("aside.notes")?.textContent.trim().length ?? 0,
      figures: Array.from(section.querySelectorAll("kli-figure"), (figure) => figure.id),
    })));
    assert.ok(slides.length >= 15, `${slides.length} slides: a lecture follows the tour`);
    slides.forEach(({ notes }, i) => assert.ok(notes > 80, `slide ${i} has no speaker notes`));
    assert.ok(await page.evaluate(() => Boolean(window.Reveal.getPlugin("notes"))), "the speaker notes plugin is registered (S opens them)");
    // The tour's views, each drawn: painted, non-white pixels in its canvas once its slide shows.
    for (const [index, { figures }] of slides.entries()) {
      if (figures.length === 0) continue;
      await page.evaluate((index) => window.Reveal.slide(index), index);
      for (const id of figures) {
        // A refused attribute is written in the figure (and the figure never gets a run).
        const refused = await page.waitForFunction((id) => document.getElementById(id).message?.textContent || document.getElementById(id).run,
          id, { timeout: 10000 }).then(() => page.evaluate((id) => document.getElementById(id).message?.textContent ?? "", id));
        assert.equal(refused, "", `slide ${index}: the figure #${id} refused an attribute`);
        await figureReady(page, id);
        assert.ok(await painted(page, `#${id}`, 2000) > 2000, `slide ${index}: the figure #${id} is blank`);
      }
    }
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});
