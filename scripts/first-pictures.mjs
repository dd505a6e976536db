// Each page's first picture, drawn at build time so that the page shows its figures before any
// script runs (and when the module cannot load, and printed): the page's default state at its
// first time, drawn by the page's own module in Node through the figure interface (`toSvg`), one
// SVG a canvas and a layout, at the size that canvas has in that layout. The HTML shows them in a
// <picture class="first-picture"> before each canvas; the runtime takes a picture away once its
// canvas is drawn (figures.js).
//
//   node scripts/first-pictures.mjs            writes www/pkg/first/<canvas id>-<layout>.svg (make www)
//   node scripts/first-pictures.mjs --measure  measures the canvases in Chromium into
//                                              www/first-pictures.json (after a change of style.css)
import { mkdirSync, readFileSync, writeFileSync } from "node:fs";
import { PAGES } from "../www/pages.js";

const at = (path) => new URL(`../${path}`, import.meta.url);
/** The layouts a page has a picture for: a wide screen (two columns of views, the widths fixed by
 *  `main`'s max-width) and a phone (one column, 390 px). Between them, the nearer picture is
 *  scaled to fit (`object-fit: contain`) until the live canvas takes over. */
export const LAYOUTS = [
  { name: "wide", viewport: { width: 1280, height: 900 }, media: null },
  { name: "phone", viewport: { width: 390, height: 844 }, media: "(max-width: 800px)" },
];
const SIZES = "www/first-pictures.json";

/** The markup of a canvas's first picture, as the HTML must have it right before the canvas. */
export function pictureMarkup(id, sizes) {
  const src = (layout) => `pkg/first/${id}-${layout}.svg`;
  const [wide, phone] = LAYOUTS;
  const [width, height] = sizes[wide.name][id].map(Math.round);
  return `<picture class="first-picture"><source media="${phone.media}" srcset="${src(phone.name)}">` +
    `<img src="${src(wide.name)}" alt="" width="${width}" height="${height}" decoding="sync" fetchpriority="high" elementtiming="kli-first-picture"></picture>`;
}

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
  let bytes = 0, count = 0;
  for (const page of PAGES) {
    const module = await import(at(`www/pkg/${page.name}_demo.js`).href);
    module.initSync({ module: readFileSync(at(`www/pkg/${page.name}_demo_bg.wasm`)) });
    const state = page.state;
    const run = state.create(module, state.defaults);
    const [azimuth, elevation] = module.defaultCamera();
    const html = readFileSync(at(`www/${page.html}`), "utf8");
    for (const [view, id] of drawn(page, run)) {
      for (const layout of LAYOUTS) {
        const size = sizes[layout.name][id];
        if (!size) throw new Error(`${SIZES} has no size of #${id}: run node scripts/first-pictures.mjs --measure`);
        const [width, height] = size;
        const svg = run.toSvg(view, { width, height, pixelRatio: 1, t: run.time, azimuth, elevation, textScale: 1 });
        writeFileSync(at(`www/pkg/first/${id}-${layout.name}.svg`), svg);
        bytes += svg.length;
        count++;
      }
      const markup = pictureMarkup(id, sizes);
      if (!new RegExp(`${escape(markup)}\\s*<canvas id="${id}"`).test(html)) {
        problems.push(`www/${page.html} must have, right before <canvas id="${id}">:\n  ${markup}`);
      }
    }
    run.free();
  }
  if (problems.length) throw new Error(`the first pictures are not where the pages show them:\n${problems.join("\n")}`);
  console.log(`www/pkg/first/: ${count} first pictures, ${bytes} bytes`);
}

const escape = (text) => text.replace(/[.*+?^${}()|[\]\\]/g, "\\$&");

if (import.meta.url === `file://${process.argv[1]}`) await (process.argv.includes("--measure") ? measure() : draw());
