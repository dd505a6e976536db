// What the end-to-end tests share: a local server for www/, Debian's headless Chromium, pages
// that record every problem, pixel statistics of canvases, and axe-core's WCAG checks.
// `setup()` registers the server and the browser with the calling test file.
import { before, after } from "node:test";
import { mkdir } from "node:fs/promises";
import { readFileSync } from "node:fs";
import { join } from "node:path";
import { chromium } from "playwright-core";
import { TEST_CHROMIUM, serve } from "../../scripts/static-server.mjs";

export const root = new URL("../../", import.meta.url).pathname;
export const artifacts = join(root, "test-artifacts");

let server;
let origin;
let browser;

/** Starts the server and the browser before the file's tests, and stops them after. */
export function setup() {
  before(async () => {
    await mkdir(artifacts, { recursive: true });
    server = await serve(join(root, "www"));
    origin = server.origin;
    browser = await chromium.launch(TEST_CHROMIUM);
  });
  after(async () => {
    await browser?.close();
    server?.close();
  });
}

/** A fresh page that records problems: console errors, page errors, failed or foreign requests.
 *  `init` runs in the page before any of its scripts; `prepare(context)` before it loads. */
export async function open(query = "", { still = false, ...options } = {}) {
  const { page, context, problems } = await blank(options);
  await visit(page, query, { still });
  return { page, context, problems };
}

/** Loads `query` into `page` (from `blank` or `open`) and waits until it is ready, as `open`. */
export async function visit(page, query, { still = false } = {}) {
  await page.goto(`${origin}/${query}`);
  // A page moves once its reader is there (runtime.js, waitForReader): the pointer moving over
  // it, as a reader's would, before the module is ready; `still` leaves the page as Lighthouse
  // sees it, with no input.
  if (!still) await engage(page);
  // Pages with a load status are ready when it hides; others (the examples) once loaded.
  await page.waitForFunction(() => document.querySelector("#load-status")?.hidden ?? document.readyState === "complete");
  // The canvases are sized (a ResizeObserver's callback) and drawn in the frames after that:
  // a cold machine once read a canvas still at its default 300 × 150, blank.
  await page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));
}

/** For a test of what a page does with no input at all, as `init`: the headless shell
 *  (TEST_CHROMIUM) sends a new page a pointer move at (0, 0) as it loads (its cursor resting over
 *  the page; the whole browser sends none), which a page takes for its reader arriving. This
 *  holds back, ahead of the page's own listeners, the pointer and mouse events at (0, 0), where
 *  no test points. */
export const withoutShellPointer = () => {
  for (const type of ["pointerover", "pointerenter", "pointermove", "mouseover", "mouseenter", "mousemove"]) {
    addEventListener(type, (event) => event.clientX === 0 && event.clientY === 0 && event.stopImmediatePropagation(), { capture: true });
  }
};

/** The reader arrives: the pointer moves over the page (a page's motion waits for it). */
export const engage = async (page) => {
  // Two moves: a pointer already at the first point (a reload) would send no event.
  await page.mouse.move(2, 2);
  await page.mouse.move(6, 6);
};

/** As `open`, but the page is left blank: the caller loads what it wants, from `origin()`.
 *  The page prefers reduced motion, so it plays only when told to, unless `moving`: a playing
 *  page costs Chromium here about a core of software rasterising, and most tests read a page
 *  that need not move. Service workers are blocked unless a test allows them
 *  (`serviceWorkers: "allow"`, the offline test's): each page registers www/sw.js once loaded,
 *  which fetches and caches the whole site (65 files, 3.9 MB) in every fresh context, 18% of
 *  page.test.mjs's CPU (40.5 against 33.1 s). */
export async function blank({ init, prepare, moving = false, ...options } = {}) {
  const reducedMotion = moving ? "no-preference" : "reduce";
  const context = await browser.newContext({ viewport: { width: 1280, height: 900 }, deviceScaleFactor: 1, reducedMotion, serviceWorkers: "block", ...options });
  if (init) await context.addInitScript(init);
  if (prepare) await prepare(context);
  const page = await context.newPage();
  const problems = [];
  page.on("console", (message) => message.type() === "error" && problems.push(`console: ${message.text()}`));
  page.on("pageerror", (error) => problems.push(`pageerror: ${error.message}`));
  page.on("requestfailed", (request) => problems.push(`failed: ${request.url()}`));
  page.on("request", (request) => {
    if (!request.url().startsWith(origin) && !request.url().startsWith("data:")) problems.push(`foreign request: ${request.url()}`);
  });
  page.on("response", (response) => response.status() >= 400 && problems.push(`${response.status()}: ${response.url()}`));
  return { page, context, problems };
}

/** Keeps a screenshot of `page` in test-artifacts/ for a person to look at, with KLI_SHOTS=1
 *  only: no test reads them, and the fifteen full-page ones cost about 7 core-seconds a run (the
 *  tour's alone 1.3, a 3.4 MB PNG). */
export async function keepShot(page, name, { fullPage = true } = {}) {
  if (process.env.KLI_SHOTS) await page.screenshot({ path: join(artifacts, name), fullPage });
}

/** The address of the server for www/. */
export const address = () => origin;

/**
 * The mean difference of two PNGs (0 to 255 a channel) and the share of pixels that differ by
 * more than 48 in a channel, decoded by the browser; `{ size }` when their sizes differ. With
 * `slack`, `b` may sit up to that many pixels off in each direction: the best alignment's figures,
 * over the pixels both cover (for an image beside a canvas, which the browser snaps to whole
 * pixels where the image can sit a fraction off).
 */
export function compare(page, a, b, { slack = 0 } = {}) {
  return page.evaluate(async ([a, b, slack]) => {
    const decode = async (base64) => {
      const bitmap = await createImageBitmap(await (await fetch(`data:image/png;base64,${base64}`)).blob());
      const canvas = new OffscreenCanvas(bitmap.width, bitmap.height);
      const ctx = canvas.getContext("2d");
      ctx.drawImage(bitmap, 0, 0);
      return ctx.getImageData(0, 0, bitmap.width, bitmap.height);
    };
    const [x, y] = await Promise.all([decode(a), decode(b)]);
    if (x.width !== y.width || x.height !== y.height) return { size: [x.width, x.height, y.width, y.height] };
    const { width, height } = x;
    const aligned = (dx, dy) => {
      let sum = 0, far = 0, pixels = 0;
      for (let row = slack; row < height - slack; row++) {
        for (let column = slack; column < width - slack; column++) {
          const [i, j] = [4 * (row * width + column), 4 * ((row + dy) * width + column + dx)];
          let worst = 0;
          for (let c = 0; c < 3; c++) {
            const d = Math.abs(x.data[i + c] - y.data[j + c]);
            sum += d;
            worst = Math.max(worst, d);
          }
          if (worst > 48) far++;
          pixels++;
        }
      }
      return { mean: sum / (3 * pixels), far: far / pixels };
    };
    let best = aligned(0, 0);
    for (let dy = -slack; dy <= slack; dy++) {
      for (let dx = -slack; dx <= slack; dx++) {
        const other = aligned(dx, dy);
        if (other.mean < best.mean) best = other;
      }
    }
    return best;
  }, [a.toString("base64"), b.toString("base64"), slack]);
}

/**
 * Waits until the canvas `selector` matches (or the canvas in the shadow root of the
 * <kli-figure> it matches) has more than `least` painted, non-white pixels, and returns how many;
 * 0 when it has not within `timeout` ms. A canvas starts transparent, (0, 0, 0, 0): no drawing.
 * @param {import("playwright-core").Page} page
 * @param {string} selector
 */
export const painted = (page, selector, least = 0, timeout = 10000) => page.waitForFunction(([selector, least]) => {
  const found = document.querySelector(selector);
  const canvas = found?.shadowRoot?.querySelector("canvas") ?? found;
  if (!(canvas instanceof HTMLCanvasElement) || canvas.width < 10) return false;
  const data = /** @type {CanvasRenderingContext2D} */ (canvas.getContext("2d")).getImageData(0, 0, canvas.width, canvas.height).data;
  let count = 0;
  for (let i = 0; i < data.length; i += 4) if (data[i + 3] > 0 && (data[i] < 250 || data[i + 1] < 250 || data[i + 2] < 250)) count++;
  return count > least && count;
}, /** @type {[string, number]} */ ([selector, least]), { timeout }).then((handle) => handle.jsonValue()).then(Number, () => 0);

/** Pixel statistics of a canvas: how many are painted and not white, and how many are near a colour. */
export function canvasStats(page, selector, colours = {}) {
  return page.evaluate(([selector, colours]) => {
    const canvas = document.querySelector(selector);
    const data = canvas.getContext("2d").getImageData(0, 0, canvas.width, canvas.height).data;
    const result = { drawn: 0, width: canvas.width, height: canvas.height, clientWidth: canvas.clientWidth, hash: 0 };
    for (const name of Object.keys(colours)) result[name] = 0;
    for (let i = 0; i < data.length; i += 4) {
      const [r, g, b, a] = [data[i], data[i + 1], data[i + 2], data[i + 3]];
      // Painted and not white: a canvas starts transparent, (0, 0, 0, 0), which is not a drawing.
      if (a > 0 && (r < 250 || g < 250 || b < 250)) result.drawn++;
      result.hash = (result.hash * 31 + r + 7 * g + 13 * b) % 1000000007;
      for (const [name, [cr, cg, cb]] of Object.entries(colours)) {
        if (Math.abs(r - cr) < 40 && Math.abs(g - cg) < 40 && Math.abs(b - cb) < 40) result[name]++;
      }
    }
    return result;
  }, [selector, colours]);
}

const AXE = readFileSync(join(root, "node_modules/axe-core/axe.min.js"), "utf8");

/** axe-core's WCAG 2.2 AA violations on the page as it stands. */
export async function axeViolations(page) {
  await page.addScriptTag({ content: AXE });
  const result = await page.evaluate(() =>
    window.axe.run(document, { runOnly: { type: "tag", values: ["wcag2a", "wcag2aa", "wcag21a", "wcag21aa", "wcag22aa"] } }));
  return result.violations.map((v) => `${v.id}: ${v.nodes.map((n) => n.target.join(" ")).join(", ")}`);
}
