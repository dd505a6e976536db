// Each page shows its figures before any script has drawn them: the first pictures `make www`
// draws (scripts/first-pictures.mjs). With the page's .wasm held back, each module-drawn canvas
// already shows its first picture, and it is the picture the live page shows at rest, within a
// small pixel tolerance; the handover from the pictures to the live page moves nothing (no layout
// shift); with the module gone for good the pictures stay, and print. On a wide screen and on a
// phone.
import { test } from "node:test";
import assert from "node:assert/strict";
import { readFileSync } from "node:fs";
import { join } from "node:path";
import { address, artifacts, blank, compare, root, setup } from "./browser.mjs";
import { PAGES } from "../../www/pages.js";
import { LAYOUTS } from "../../scripts/first-pictures.mjs";

setup();

/** How far a first picture may be from the live canvas, the best of its alignments up to a pixel
 *  off (the canvas is snapped to whole pixels, the picture can sit a fraction off): the SVG is
 *  laid out without the font to measure its labels (crates/kli-demo/src/pen.rs, em_width), so a
 *  label can sit a pixel off; measured at most 4.6 of 255 (the averaging page's bars on a phone),
 *  0.4–3.0 elsewhere. A blank box or another state is far beyond. */
const TOLERANCE = { mean: 6.5, far: 0.05 };

/** The canvases that have a first picture, by the page's HTML. */
const pictured = (page) => Object.values(page.canvases).filter((selector) =>
  readFileSync(join(root, "www", page.html), "utf8").includes(`id="${selector.slice(1)}-first"`));

/** Opens `html` with its .wasm held until `release()` (reduced motion: the live page rests at
 *  its first time, as the picture shows it). */
async function held(html, viewport) {
  let release;
  const gate = new Promise((resolve) => (release = resolve));
  const phone = viewport.width < 500;
  const { page, context, problems } = await blank({
    viewport, ...(phone ? { hasTouch: true, isMobile: true } : {}),
    prepare: (context) => context.route(/\.wasm$/, async (route) => {
      await gate;
      await route.continue();
    }),
    init: () => {
      window.__shifts = [];
      new PerformanceObserver((list) => {
        for (const entry of list.getEntries()) {
          const sources = entry.sources.map((source) => `${source.node?.id || source.node?.nodeName} ${JSON.stringify(source.previousRect)} → ${JSON.stringify(source.currentRect)}`);
          window.__shifts.push({ at: entry.startTime, text: `${entry.value.toFixed(4)} at ${entry.startTime.toFixed(0)} ms: ${sources.join("; ")}` });
        }
      }).observe({ type: "layout-shift", buffered: true });
    },
  });
  await page.goto(`${address()}/${html}`);
  return { page, context, problems, release };
}

/** Whether the first pictures were painted in the first contentful paint (Element Timing). */
async function samePaint(page) {
  await page.waitForFunction(() => performance.getEntriesByName("kli:first-frame").length > 0);
  return page.evaluate(() => performance.getEntriesByName("kli:first-frame")[0].startTime
    === performance.getEntriesByName("first-contentful-paint")[0]?.startTime);
}

/** A screenshot of each canvas's box, scrolled into view (a full-page screenshot would lay the
 *  page out at another size for a moment: a layout shift, and on a wide screen the phone's
 *  pictures fetched). With `live`, each once its canvas has taken over from its picture: the
 *  tour (learn.html) draws a figure only as it nears the screen. */
async function shots(page, selectors, live = false) {
  const result = [];
  for (const selector of selectors) {
    if (live) {
      await page.locator(selector).scrollIntoViewIfNeeded();
      await page.waitForFunction((id) => !document.getElementById(`${id}-first`), selector.slice(1), { timeout: 10000 });
    }
    result.push(await page.locator(selector).screenshot({ animations: "disabled" }));
  }
  return result;
}

for (const layout of LAYOUTS) {
  for (const page of PAGES) {
    test(`${page.html} (${layout.name}): the first picture before the module, equal to the live one at rest, no shift`, async () => {
      const selectors = pictured(page);
      assert.ok(selectors.length >= 2, `${page.html} has first pictures`);
      // The paint is the browser's to schedule: on a busy machine it may decode a picture a frame
      // late once (2 loads of 36 in one day). The page loads again, up to twice; the last load is
      // held to it.
      let opened = await held(page.html, layout.viewport);
      for (let attempt = 1; attempt < 3 && !(await samePaint(opened.page)); attempt++) {
        opened.release();
        await opened.context.close();
        opened = await held(page.html, layout.viewport);
      }
      const { page: tab, context, problems, release } = opened;
      try {
        // Every picture shown while the module is still held back, and in the text's paint: its
        // sheet blocks rendering, so the first contentful paint is the pictures' (Element Timing).
        assert.ok(await tab.evaluate(() => [...document.querySelectorAll(".first-picture")].every((picture) =>
          getComputedStyle(picture).backgroundImage.startsWith('url("data:image/svg+xml'))), "each picture from its sheet");
        await tab.waitForFunction(() => performance.getEntriesByName("kli:first-frame").length > 0);
        assert.equal(await tab.evaluate(() => performance.getEntriesByName("kli:wasm-ready").length), 0, "the module was held back");
        const [painted, text] = await tab.evaluate(() => ["kli:first-frame", "first-contentful-paint"].map((name) => performance.getEntriesByName(name)[0].startTime));
        assert.equal(painted, text, "the pictures came in the text's paint");
        const before = await shots(tab, selectors);
        const readout = await tab.textContent("#readout");
        // The handover is watched on the screen the page opens with, as a reader sees it (and as
        // CLS counts it): back at the top, two frames on, the shifts count from here (a loaded
        // machine can paint the page once before its style sheet has arrived: not the
        // handover's doing).
        await tab.evaluate(() => window.scrollTo(0, 0));
        await tab.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));
        const handover = await tab.evaluate(() => performance.now());
        release();
        await tab.waitForFunction(() => performance.getEntriesByName("kli:interactive").length > 0);
        // The still views are painted in a task after the first frame; a view whose run is still
        // computing it (the synchronisation page's solutions, from its worker) keeps its picture
        // till then.
        await tab.waitForTimeout(600);
        const after = await shots(tab, selectors, true);
        await tab.waitForFunction(() => document.querySelectorAll(".first-picture").length === 0, null, { timeout: 20000 })
          .catch(() => {});
        assert.equal(await tab.locator(".first-picture").count(), 0, "the live canvases took over");
        const shifts = await tab.evaluate((from) => window.__shifts.filter((shift) => shift.at >= from).map((shift) => shift.text), handover);
        assert.equal(await tab.textContent("#readout"), readout, "the HTML's readout is the live one at rest");
        for (const [i, selector] of selectors.entries()) {
          const difference = await compare(tab, before[i], after[i], { slack: 1 });
          const name = `first-${layout.name}-${selector.slice(1)}`;
          if (process.env.KLI_FIRST_REPORT) console.log(`${name}: mean ${difference.mean.toFixed(2)}, far ${(100 * difference.far).toFixed(2)}%`);
          if (!(difference.mean < TOLERANCE.mean && difference.far < TOLERANCE.far)) {
            const { writeFileSync } = await import("node:fs");
            writeFileSync(join(artifacts, `${name}-picture.png`), before[i]);
            writeFileSync(join(artifacts, `${name}-live.png`), after[i]);
          }
          assert.equal(difference.size, undefined, `${selector}: the size changed`);
          assert.ok(difference.mean < TOLERANCE.mean && difference.far < TOLERANCE.far,
            `${selector}: mean difference ${difference.mean.toFixed(2)}, ${(100 * difference.far).toFixed(2)}% of pixels far off (test-artifacts/${name}-*.png)`);
        }
        const [first, interactive] = await tab.evaluate(() => ["kli:first-frame", "kli:interactive"].map((name) => performance.getEntriesByName(name)[0].startTime));
        assert.ok(first < interactive, `the first picture (${first} ms) before the page is interactive (${interactive} ms)`);
        assert.deepEqual(shifts, [], "no layout shift at the handover");
        assert.deepEqual(problems, []);
      } finally {
        await context.close();
      }
    });
  }
}

test("with no module, the first pictures stay, and print; a URL asking for another state takes them away", async () => {
  for (const [query, kept] of [["average.html", true], ["average.html?n=12", false]]) {
    const { page, context } = await blank({ prepare: (context) => context.route(/\.wasm$/, (route) => route.abort()) });
    try {
      await page.goto(`${address()}/${query}`);
      await page.waitForFunction(() => document.querySelector("#load-status")?.classList.contains("error"));
      assert.equal(await page.locator(".first-picture").count(), kept ? 3 : 0, query);
      if (!kept) continue;
      await page.emulateMedia({ media: "print" });
      const box = await page.locator(".first-picture").first().boundingBox();
      assert.ok(box && box.height > 100, `printed: ${JSON.stringify(box)}`);
    } finally {
      await context.close();
    }
  }
});
