// Each page's first picture, drawn at build time so that the page shows its figures in the same
// paint as its text: the page's default state at its first time, drawn by the page's own module in
// Node through the figure interface (`toSvg`), a picture a canvas and a layout, at the size that
// canvas has in that layout. Each page has a style sheet a layout, www/pkg/first/<page>-<layout>.css,
// that gives each canvas's `<div class="first-picture">` (right before the canvas) its picture as a
// data: address: the layout's sheet blocks rendering, so the first paint has the pictures with the
// text (a separate image is fetched and decoded after the text is painted, 40–250 ms later here);
// the other layout's sheet is fetched without blocking. The runtime takes a picture away once its
// canvas is drawn (figures.js). Each polyline is simplified to within 0.1 px first (the
// pictures are only seen until the canvas draws): half the bytes.
//
//   node scripts/first-pictures.mjs            writes www/pkg/first/<page>-<layout>.css (make www)
//   node scripts/first-pictures.mjs --measure  measures the canvases in Chromium into
//                                              www/first-pictures.json (after a change of the styles)
import { mkdirSync, readFileSync, writeFileSync } from "node:fs";
import { PAGES } from "../www/pages.js";

const at = (path) => new URL(`../${path}`, import.meta.url);
/** The layouts a page has pictures for: a wide screen (two columns of views, the widths fixed by
 *  `main`'s max-width) and a phone (one column, 390 px), each with the media its sheet applies
 *  to. Between them, the picture is scaled to fit (`background-size: contain`) until the live
 *  canvas takes over. */
export const LAYOUTS = [
  { name: "wide", viewport: { width: 1280, height: 900 }, media: "not all and (max-width: 800px)" },
  { name: "phone", viewport: { width: 390, height: 844 }, media: "(max-width: 800px)" },
];
const SIZES = "www/first-pictures.json";
/** How far a simplified polyline may be from the drawn one, px. */
const TOLERANCE = 0.1;

/** The markup of a canvas's first picture, as the HTML must have it right before the canvas. */
export const pictureMarkup = (id) => `<div class="first-picture" id="${id}-first" elementtiming="kli-first-picture"></div>`;

/** A page's first-picture style sheet in `layout`, its address in www/. */
export const pictureSheet = (page, layout) => `pkg/first/${page.name}-${layout.name}.css`;

/** The links to a page's first-picture style sheets, as its HTML has them after style.css. */
export const pictureLinks = (page) =>
  LAYOUTS.map((layout) => `<link rel="stylesheet" href="${pictureSheet(page, layout)}" media="${layout.media}">\n`).join("");

/** `points` (x,y pairs) with each point dropped that is within `tolerance` of the line through
 *  the kept points either side (Ramer–Douglas–Peucker). */
export function simplify(points, tolerance) {
  const n = points.length;
  if (n < 3) return points;
  const keep = new Uint8Array(n);
  keep[0] = keep[n - 1] = 1;
  const spans = [[0, n - 1]];
  while (spans.length > 0) {
    const [a, b] = /** @type {[number, number]} */ (spans.pop());
    const [ax, ay] = points[a], [bx, by] = points[b];
    const [dx, dy] = [bx - ax, by - ay];
    const length = Math.hypot(dx, dy);
    let [far, worst] = [-1, tolerance];
    for (let i = a + 1; i < b; i++) {
      const [px, py] = points[i];
      const d = length > 0 ? Math.abs(dy * (px - ax) - dx * (py - ay)) / length : Math.hypot(px - ax, py - ay);
      if (d > worst) [far, worst] = [i, d];
    }
    if (far >= 0) {
      keep[far] = 1;
      spans.push([a, far], [far, b]);
    }
  }
  return points.filter((_, i) => keep[i] === 1);
}

/** The SVG with every polyline simplified to within `tolerance`. */
const simplified = (svg, tolerance) => svg.replace(/ points="([^"]*)"/g, (_, list) => {
  const points = list.trim().split(/\s+/).map((pair) => pair.split(",").map(Number));
  return ` points="${simplify(points, tolerance).map((point) => point.join(",")).join(" ")}"`;
});

/** `svg` as a data: address inside a single-quoted CSS string: what would end the string, the
 *  line or the address escaped, and everything outside printable ASCII as its UTF-8 bytes. */
const dataAddress = (svg) =>
  `data:image/svg+xml,${svg.replace(/[^ -~]|[%#'\\<>]/gu, (c) => (c === "'" ? "%27" : encodeURIComponent(c)))}`;

/** The canvases whose first picture the module draws: each page's canvases of its runs' views. */
function drawn(page, run) {
  const views = new Set(Array.from(run.views, (view) => view.name));
  return Object.entries(page.canvases).filter(([view]) => views.has(view)).map(([view, selector]) => [view, selector.slice(1)]);
}

async function measure() {
  const { chromium } = await import("playwright-core");
  const { CHROMIUM, serve } = await import("./static-server.mjs");
  const server = await serve(at("www").pathname.replace(/\/$/, ""));
  const browser = await chromium.launch(CHROMIUM);
  const sizes = {};
  try {
    for (const layout of LAYOUTS) {
      sizes[layout.name] = {};
      const context = await browser.newContext({ viewport: layout.viewport });
      const tab = await context.newPage();
      // The layout as HTML and CSS make it, before any script: the canvases' boxes.
      await tab.route(/\.js$/, (route) => route.abort());
      for (const page of PAGES) {
        await tab.goto(`${server.origin}/${page.html}`);
        for (const selector of Object.values(page.canvases)) {
          const box = await tab.$eval(selector, (canvas) => {
            const { width, height } = canvas.getBoundingClientRect();
            return [width, height];
          });
          sizes[layout.name][selector.slice(1)] = box;
        }
      }
      await context.close();
    }
  } finally {
    await browser.close();
    server.close();
  }
  const lines = (layout) => Object.entries(layout).map(([id, size]) => `    ${JSON.stringify(id)}: ${JSON.stringify(size)}`).join(",\n");
  const text = Object.entries(sizes).map(([name, layout]) => `  ${JSON.stringify(name)}: {\n${lines(layout)}\n  }`).join(",\n");
  writeFileSync(at(SIZES), `{\n${text}\n}\n`);
  console.log(`${SIZES}: the canvases of ${PAGES.length} pages in ${LAYOUTS.length} layouts`);
}

async function draw() {
  const sizes = JSON.parse(readFileSync(at(SIZES), "utf8"));
  mkdirSync(at("www/pkg/first"), { recursive: true });
  const problems = [];
  let drawnBytes = 0, bytes = 0, count = 0;
  for (const page of PAGES) {
    const module = await import(at(`www/pkg/${page.name}_demo.js`).href);
    module.initSync({ module: readFileSync(at(`www/pkg/${page.name}_demo_bg.wasm`)) });
    const state = page.state;
    const run = state.create(module, state.defaults);
    const [azimuth, elevation] = module.defaultCamera();
    const html = readFileSync(at(`www/${page.name}/page.html`), "utf8");
    const sheets = Object.fromEntries(LAYOUTS.map((layout) => [layout.name, [`/* ${page.html}'s first pictures, ${layout.name} (scripts/first-pictures.mjs) */`]]));
    for (const [view, id] of drawn(page, run)) {
      for (const layout of LAYOUTS) {
        const size = sizes[layout.name][id];
        if (!size) throw new Error(`${SIZES} has no size of #${id}: run node scripts/first-pictures.mjs --measure`);
        const [width, height] = size;
        const svg = run.toSvg(view, { width, height, pixelRatio: 1, t: run.time, azimuth, elevation, textScale: 1 });
        const picture = simplified(svg, TOLERANCE);
        // Printed without the module, the picture sizes its own box (on screen the canvas does).
        sheets[layout.name].push(`#${id}-first { background-image: url('${dataAddress(picture)}'); }`,
          `@media print { #${id}-first { aspect-ratio: ${width} / ${height}; } }`);
        drawnBytes += svg.length;
        bytes += picture.length;
        count++;
      }
      const markup = pictureMarkup(id);
      if (!new RegExp(`${escape(markup)}\\s*<canvas id="${id}"`).test(html)) {
        problems.push(`www/${page.name}/page.html must have, right before <canvas id="${id}">:\n  ${markup}`);
      }
    }
    for (const layout of LAYOUTS) writeFileSync(at(`www/${pictureSheet(page, layout)}`), `${sheets[layout.name].join("\n")}\n`);
    run.free();
  }
  if (problems.length) throw new Error(`the first pictures are not where the pages show them:\n${problems.join("\n")}`);
  console.log(`www/pkg/first/: ${count} first pictures, ${drawnBytes} bytes of SVG drawn, ${bytes} simplified`);
}

const escape = (text) => text.replace(/[.*+?^${}()|[\]\\]/g, "\\$&");

if (import.meta.url === `file://${process.argv[1]}`) await (process.argv.includes("--measure") ? measure() : draw());
