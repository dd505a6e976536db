// The figure contract (issue 14): what every page and <kli-figure> do alike, and the defects
// found using them as teachers and students do (a deck, a projector, a phone), one test each.
import { test } from "node:test";
import assert from "node:assert/strict";
import { execFileSync } from "node:child_process";
import { readFileSync } from "node:fs";
import { setup, open, root } from "./browser.mjs";
import { PAGES } from "../../www/pages.js";

setup();

/** A figure's canvas: its backing store, its layout width, and the figure's time. */
const figureCanvas = (page, selector) => page.evaluate((selector) => {
  const figure = document.querySelector(selector);
  const canvas = figure.shadowRoot.querySelector("canvas");
  return { width: canvas.width, height: canvas.height, layoutWidth: canvas.offsetWidth, t: figure.t };
}, selector);

test("<kli-figure autoplay> reads the latest visibility entry: hidden then shown at once, it animates", async () => {
  // A browser may deliver two entries in one callback (a slide shown: hidden, then visible); the
  // first is stale. This IntersectionObserver delivers exactly that, as reveal.js's first slide got.
  const init = () => {
    window.IntersectionObserver = class {
      constructor(callback) { this.callback = callback; }
      observe(target) {
        setTimeout(() => this.callback([{ target, isIntersecting: false }, { target, isIntersecting: true }], this));
      }
      unobserve() {}
      disconnect() {}
    };
  };
  const { page, context, problems } = await open("examples/figures.html", { moving: true, init });
  try {
    await page.waitForFunction(() => document.querySelector("#hopf").run);
    const t0 = (await figureCanvas(page, "#hopf")).t;
    await page.waitForTimeout(400);
    const t1 = (await figureCanvas(page, "#hopf")).t;
    assert.ok(t1 > t0 + 0.1, `the figure animates: t ${t0} → ${t1}`);
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});

test("<kli-figure> scaled by its host (as reveal.js scales a slide) renders at the pixels it covers", async () => {
  const { page, context, problems } = await open("examples/figures.html", { deviceScaleFactor: 2 });
  try {
    await page.evaluate(() => document.querySelector("article").insertAdjacentHTML("afterbegin", `
      <div id="slide" style="width: 400px; transform: scale(1.48); transform-origin: 0 0">
        <kli-figure id="scaled" view="hopf" style="width: 400px; height: 300px"></kli-figure>
      </div>`));
    await page.waitForFunction(() => document.querySelector("#scaled").run && document.querySelector("#scaled").shadowRoot.querySelector("canvas").width > 1000);
    const scaled = await figureCanvas(page, "#scaled");
    // 398 CSS px (the figure's border inside its 400) × 1.48 (the host) × 2 (the screen).
    const [width, height] = await page.evaluate(() => {
      const canvas = document.querySelector("#scaled").shadowRoot.querySelector("canvas");
      return [canvas.clientWidth, canvas.clientHeight];
    });
    assert.equal(scaled.layoutWidth, width);
    assert.equal(scaled.width, Math.round(width * 1.48 * 2));
    assert.equal(scaled.height, Math.round(height * 1.48 * 2));
    // The host rescales (a new window size): the figure follows with the window's resize event.
    await page.evaluate(() => (document.querySelector("#slide").style.transform = "scale(0.5)"));
    await page.setViewportSize({ width: 1200, height: 900 });
    await page.waitForFunction((width) => document.querySelector("#scaled").shadowRoot.querySelector("canvas").width === width, width);
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});

/** A finger drawn 200 px up the screen from (x, y). */
async function swipeUp(cdp, x, y) {
  await cdp.send("Input.dispatchTouchEvent", { type: "touchStart", touchPoints: [{ x, y }] });
  for (let i = 1; i <= 10; i++) await cdp.send("Input.dispatchTouchEvent", { type: "touchMove", touchPoints: [{ x, y: y - 20 * i }] });
  await cdp.send("Input.dispatchTouchEvent", { type: "touchEnd", touchPoints: [] });
}

test("touch-action: none only on the canvases that can be dragged, so a swipe elsewhere scrolls", async () => {
  // On every page the Hopf sphere turns under a finger (and a point on it may be dragged).
  for (const [url, draggable] of PAGES.map((page) => [page.html, [page.canvases.hopf.slice(1)]])) {
    const { page, context, problems } = await open(url, { viewport: { width: 390, height: 844 }, hasTouch: true, isMobile: true });
    try {
      const actions = await page.evaluate(() => Array.from(document.querySelectorAll("canvas"), (c) => [c.id, getComputedStyle(c).touchAction]));
      assert.ok(actions.length >= 3, url);
      for (const [id, action] of actions) assert.equal(action, draggable.includes(id) ? "none" : "auto", `${url} #${id}`);
      // A swipe up over a figure that is not draggable scrolls the page.
      const id = actions.find(([id]) => !draggable.includes(id))[0];
      await page.locator(`#${id}`).scrollIntoViewIfNeeded();
      const box = await page.locator(`#${id}`).boundingBox();
      const before = await page.evaluate(() => scrollY);
      await swipeUp(await context.newCDPSession(page), box.x + box.width / 2, box.y + box.height / 2);
      assert.ok((await page.evaluate(() => scrollY)) > before + 50, `${url}: a swipe over #${id} scrolls`);
      assert.deepEqual(problems, []);
    } finally {
      await context.close();
    }
  }
});

test("embedded figures reserve their box before their module loads: no layout shift", async () => {
  // The element's script is held back for a while, as on a slow network: the figures must hold
  // their place from the first paint (www/kli-figure.css), not jump when the element is defined.
  const init = () => {
    window.__shifts = 0;
    new PerformanceObserver((list) => {
      for (const entry of list.getEntries()) if (!entry.hadRecentInput) window.__shifts += entry.value;
    }).observe({ type: "layout-shift", buffered: true });
  };
  const prepare = (context) => context.route(/kli-figure\.js$/, async (route) => {
    await new Promise((resolve) => setTimeout(resolve, 600));
    await route.continue();
  });
  const { page, context, problems } = await open("examples/figures.html", { init, prepare });
  try {
    await page.waitForFunction(() => Array.from(document.querySelectorAll("kli-figure"), (f) => f.run).every(Boolean));
    await page.waitForTimeout(300);
    const shift = await page.evaluate(() => window.__shifts);
    assert.ok(shift <= 0.1, `cumulative layout shift ${shift}`);
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});

test("make: nothing to build when nothing changed, so make demo serves at once", () => {
  // `make -q` exits 0 only when every target named is up to date (the test run built them).
  execFileSync("make", ["-q", "pkg/.built", "www/pkg/.built", "www/vendor/codecs.js", "www/examples/vendor/.built"], { cwd: root, stdio: "pipe" });
  // The page list and the pages' modulepreload links agree (scripts/pages.mjs writes them).
  execFileSync("node", ["scripts/pages.mjs", "check"], { cwd: root, stdio: "pipe" });
});

test("every page shows every refused URL value beside its field at once, and runs on valid values", async () => {
  /** Each page's refused query, and the message each of its fields shows. */
  const REFUSED = {
    kli: ["?eps=-1&step=0", { tolerance: /tolerance/, step: /step/ }],
    swarm: ["?K=abc&n=0", { coupling: /coupling/, count: /count/ }],
    average: ["?n=1&noise=abc", { count: /count/, noise: /noise/ }],
    sync: ["?n=2&wrong=abc&graph=star", { count: /count/, wrong: /wrong/, graph: /graph/ }],
    keyframes: ["?keys=1,0,0,0;nan,0,0,1;0,1,0,0&s=5", { keys: /keys\[1\]/, smoothness: /smoothness/ }],
    learn: ["?angle=800&axis=w&delta=abc", { angle: /angle/, axis: /axis/, delta: /delta/ }],
  };
  assert.deepEqual(Object.keys(REFUSED).sort(), PAGES.map((page) => page.name).sort(), "a refused query for every page of the registry");
  for (const [url, refused] of PAGES.map((page) => [page.html + REFUSED[page.name][0], REFUSED[page.name][1]])) {
    const { page, context, problems } = await open(url);
    try {
      const marked = await page.evaluate(() => Array.from(document.querySelectorAll("[aria-invalid=true]"), (f) => f.getAttribute("name")));
      for (const [name, message] of Object.entries(refused)) {
        assert.match(await page.textContent(`#${name}-error`), message, `${url}: ${name}`);
        assert.ok(marked.some((m) => m === name || m.startsWith(`${name}`)), `${url}: ${name} marked (${marked})`);
      }
      // A valid run is on show: its figures are drawn, and no readout shows the refused value.
      const text = await page.evaluate(() => {
        const copy = /** @type {HTMLElement} */ (document.body.cloneNode(true));
        copy.querySelectorAll(".field-error").forEach((message) => message.remove());
        return copy.textContent;
      });
      assert.doesNotMatch(text, /NaN|Infinity/, url);
      if (url.startsWith("keyframes")) assert.equal(await page.textContent("#smoothness-value"), "1");
      assert.deepEqual(problems, []);
    } finally {
      await context.close();
    }
  }
});

test("two SLERP parameters, two names: SLERP's clock u = t/T in the object view, KLI's s(t) in the plots and the path", async () => {
  const { page, context, problems } = await open("index.html?t=1.8");
  try {
    const svgs = await page.evaluate(async () => {
      const { KliDemo } = await import("./pkg/kli_demo.js");
      const demo = new KliDemo([0, 0, 0, 1], [0.5, 0.5, 0.5, 0.5]);
      const frame = { width: 600, height: 300, t: 1.8 };
      const result = { object: demo.toSvg("object", frame), plots: demo.toSvg("plots", frame), csv: demo.export("path", "csv") };
      demo.free();
      return result;
    });
    // MATH.md: at t = 1.8 KLI sits at s = 0.818; SLERP's clock is 1.8 / 11.66 = 0.154.
    assert.match(svgs.object, /u = t\/T = 0\.154/);
    assert.doesNotMatch(svgs.object + svgs.plots, /s = t\/T/);
    assert.match(svgs.plots, /KLI, s\(t\)/);
    assert.match(svgs.plots, /SLERP, u = t\/T/);
    const row = svgs.csv.split("\n").find((line) => line.startsWith("1.8,"));
    assert.ok(Math.abs(Number(row.split(",")[5]) - 0.818) < 1e-3, row);
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});

test("a URL number beyond its slider is refused as the slider would refuse it (no swarm of 10⁶, no K = 1e308)", async () => {
  const { page, context, problems } = await open("swarm.html?n=1000000&K=1e308");
  try {
    assert.match(await page.textContent("#count-error"), /^count must be from 2 to 2000 on this page, as its slider \(got 1000000\)/);
    assert.match(await page.textContent("#coupling-error"), /^coupling must be from -3 to 6 on this page/);
    // The preset's values stand in, and the sliders, the readout and the run agree.
    assert.equal(await page.inputValue("[name=count]"), "500");
    assert.equal(await page.evaluate(() => document.querySelector("#count-value").textContent), "500");
    const readout = await page.textContent("#readout");
    assert.match(readout, /R = 0\.\d{3}/);
    assert.doesNotMatch(readout, /NaN|Infinity/);
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});

test("the figure interface under hostile input: every call draws with defaults or throws a named Error; 2,500 refusals leave every object working", async () => {
  const { page, context, problems } = await open("index.html");
  try {
    const result = await page.evaluate(async () => {
      const modules = {
        kli: await import("./pkg/kli_demo.js"),
        keyframes: await import("./pkg/keyframes_demo.js"),
        swarm: await import("./pkg/swarm_demo.js"),
        average: await import("./pkg/average_demo.js"),
        sync: await import("./pkg/sync_demo.js"),
        learn: await import("./pkg/learn_demo.js"),
      };
      await modules.keyframes.default();
      await modules.swarm.default();
      await modules.average.default();
      await modules.sync.default();
      await modules.learn.default();
      const figures = [
        [new modules.kli.KliDemo([0, 0, 0, 1], [0.5, 0.5, 0.5, 0.5]), ["object", "hopf", "filmstrip", "plots"], "path"],
        [new modules.keyframes.KeyframesDemo(new Float64Array([1, 0, 0, 0, 0.8, 0.6, 0, 0, 0.6, 0, 0.8, 0]), new Float64Array(0), 1), ["objects", "hopf", "plots"], "curves"],
        [new modules.swarm.SwarmDemo({ count: 20 }), ["hopf", "objects", "plots"], "swarm"],
        [new modules.average.AverageDemo({ count: 20 }), ["hopf", "objects", "means"], "measurements"],
        [new modules.sync.SyncDemo({ count: 20 }), ["graph", "hopf", "objects", "plots", "results"], "edges"],
        [new modules.learn.LearnDemo({}), ["euler", "turn", "cover", "slerp", "hopf", "rolled", "phases", "lohe", "kli", "clock", "steps", "drift", "rates"], "tour"],
      ];
      const ctx = document.createElement("canvas").getContext("2d");
      const hostileFrames = [null, undefined, 0, "frame", {}, { width: NaN, height: Infinity, pixelRatio: -1, t: "x" },
        { width: 1e300, height: -5, t: 1e308, azimuth: -Infinity, elevation: 1e9 },
        new Proxy({}, { get() { throw new Error("trap"); } }),
        { get width() { throw new Error("getter"); }, height: 50 }, { width: 10n }, { width: Symbol("w") }];
      const unnamed = [];
      let refusals = 0;
      const refused = (f) => {
        try { f(); } catch (error) {
          refusals++;
          if (!error?.argument || !error?.kind) unnamed.push(String(error));
          return true;
        }
        return false;
      };
      // A hundred rounds of refusals, each of which throws while Rust is on the stack; the hostile
      // frames draw (with defaults) in the first three: a borrow flag left set shows in the next.
      for (let round = 0; round < 100; round++) {
        for (const [figure, views, kind] of figures) {
          for (const frame of round < 3 ? hostileFrames : []) {
            for (const view of views) {
              figure.draw(view, ctx, frame);
              figure.draw(view, ctx, frame, "still");
              if (!figure.toSvg(view, frame).startsWith("<svg")) unnamed.push(`toSvg ${view}`);
            }
          }
          refused(() => figure.draw("nope", ctx, {}));
          refused(() => figure.draw(views[0], ctx, {}, "sideways"));
          refused(() => figure.toSvg("", {}));
          refused(() => figure.export("everything", "csv"));
          refused(() => figure.export(kind, "xml"));
          if (round === 0 && !figure.export(kind, "json").startsWith("{")) unnamed.push(`export ${kind}`);
        }
      }
      // The run contract: the views are the ones drawn; any time asked for leaves the run's
      // time a number within its span, and the summary's numbers finite.
      const contract = [];
      const times = [NaN, Infinity, -Infinity, -1, 0, 1e-300, 0.5, 3, 1e308, "x", null, undefined, {}];
      for (const [figure, views] of figures) {
        if (figure.views.map((v) => v.name).join() !== views.join()) contract.push(`views ${figure.views.map((v) => v.name)}`);
        if (!figure.views.every((v) => ["moving", "layered", "still"].includes(v.kind) && v.title)) contract.push("a view's kind or title");
        for (const t of times) {
          for (const call of [() => figure.seek(t), () => figure.advance(t)]) {
            const [start, end] = figure.span;
            if (typeof call() !== "boolean") contract.push(`not a boolean for ${t}`);
            if (!(figure.time >= start && figure.time <= end && Number.isFinite(figure.time))) contract.push(`time ${figure.time} for ${t}`);
          }
        }
        const numbers = JSON.stringify(figure.summary).match(/-?[\d.e+-]+|null/g) ?? [];
        if (numbers.includes("null")) contract.push(`summary ${JSON.stringify(figure.summary)}`);
      }
      // Still working: a real frame draws, and the SVG holds numbers, never NaN.
      const svgs = figures.map(([figure, views]) => figure.toSvg(views[1], { width: 300, height: 200, t: 1 }));
      for (const [figure] of figures) figure.free();
      return { refusals, unnamed, contract, nan: svgs.filter((svg) => /NaN|Infinity/.test(svg)).length };
    });
    assert.equal(result.refusals, 100 * 6 * 5);
    assert.deepEqual(result.unnamed, []);
    assert.deepEqual(result.contract, []);
    assert.equal(result.nan, 0);
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});

test("printed, every page shows no control and keeps each figure whole on one page", async () => {
  for (const { html } of PAGES) {
    const { page, context, problems } = await open(html);
    try {
      await page.emulateMedia({ media: "print" });
      const printed = await page.evaluate(() => ({
        controls: Array.from(document.querySelectorAll("button, input, select, textarea"))
          .filter((element) => element.checkVisibility()).map((element) => element.id || element.getAttribute("name") || element.tagName),
        // A figure not shown (the synchronisation page's, before a file is opened) is not printed.
        figures: Array.from(document.querySelectorAll("figure")).filter((figure) => figure.checkVisibility()).map((figure) => ({
          id: figure.querySelector("canvas")?.id, breaks: getComputedStyle(figure).breakInside,
          height: figure.getBoundingClientRect().height,
        })),
      }));
      assert.deepEqual(printed.controls, [], `${html}: controls on paper`);
      assert.ok(printed.figures.length >= 3, html);
      // An A4 page at 96 px an inch, less the browser's margins, holds about 1,000 px.
      for (const figure of printed.figures) {
        assert.equal(figure.breaks, "avoid", `${html} #${figure.id}`);
        assert.ok(figure.height > 20 && figure.height < 1000, `${html} #${figure.id}: ${figure.height} px`);
      }
      assert.deepEqual(problems, []);
    } finally {
      await context.close();
    }
  }
});

test("no empty figure: a page's sweep fills itself once the page is interactive, in the page's worker, and its button runs it again", async () => {
  // The pages whose HTML has a sweep (www/<page>/page.html): loading the others only to find none
  // cost three page loads.
  const swept = PAGES.filter(({ name }) => readFileSync(`${root}www/${name}/page.html`, "utf8").includes('id="sweep"'));
  assert.deepEqual(swept.map(({ name }) => name), ["swarm", "average", "sync"]);
  for (const { html } of swept) {
    const { page, context, problems } = await open(html);
    try {
      const done = () => page.waitForFunction(() => document.querySelector("#sweep-status")?.textContent.startsWith("Done"),
        undefined, { timeout: 60000 });
      await done();
      const rows = await page.locator("#sweep-table tbody tr").count();
      assert.ok(rows >= 10, `${html}: ${rows} sweep points with no click`);
      // Its points are computed in the page's worker (runtime/offload.js), off the page's tasks.
      assert.deepEqual(page.workers().map((worker) => new URL(worker.url()).pathname), ["/runtime/worker.js"], html);
      // The button starts the sweep afresh in its click's own task (a short sweep may finish
      // before a poll would see it running).
      const started = await page.evaluate(() => {
        /** @type {HTMLButtonElement} */ (document.querySelector("#sweep")).click();
        return document.querySelector("#sweep-status")?.textContent;
      });
      assert.match(started ?? "", /^Sweeping: 1 of /, html);
      await done();
      assert.equal(await page.locator("#sweep-table tbody tr").count(), rows, html);
      assert.deepEqual(problems, []);
    } finally {
      await context.close();
    }
  }
});

test("a page moves once its reader is there: still at load (its first frame, no time in its address), moving at the first input; a first press of Play or Space plays", async () => {
  const { engage, withoutShellPointer } = await import("./browser.mjs");
  /** The page's time and its Play button's word, a moment apart. */
  const now = (page) => page.evaluate(() => ({ t: Number(document.querySelector("#readout").textContent.match(/t = ([\d.]+)/)?.[1]),
    play: document.querySelector("#play").textContent, address: location.search }));
  for (const { html } of PAGES.filter((page) => page.name !== "learn")) {
    const { page, context, problems } = await open(html, { moving: true, still: true, init: withoutShellPointer });
    try {
      await page.waitForTimeout(800);
      const still = await now(page);
      assert.equal(still.t, 0, `${html}: the time moved with no input`);
      assert.equal(still.play, "Play", html);
      assert.doesNotMatch(still.address, /[?&]t=/, `${html}: waiting to play, its address has no time`);
      await engage(page);
      await page.waitForFunction(() => Number(document.querySelector("#readout").textContent.match(/t = ([\d.]+)/)?.[1]) > 0, null, { timeout: 5000 });
      assert.equal((await now(page)).play, "Pause", `${html}: playing once the pointer moved`);
      assert.deepEqual(problems, [], html);
    } finally {
      await context.close();
    }
  }
  // The first input is the reader taking the controls: it plays, and the wait does not undo it.
  for (const press of [(page) => page.click("#play"), (page) => page.keyboard.press("Space")]) {
    const { page, context } = await open("sync.html", { moving: true, still: true, init: withoutShellPointer });
    try {
      await press(page);
      await page.waitForTimeout(600);
      assert.equal((await now(page)).play, "Pause", "a first press of Play (or Space) plays");
    } finally {
      await context.close();
    }
  }
});
