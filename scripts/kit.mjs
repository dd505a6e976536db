// The teacher's kit (`make single`, after scripts/single.mjs): one zip a static host serves,
// www/kli-teaching-kit.zip, for a lecture room without network, a USB stick or a course platform:
//   pages/      every page and the guided tour as one HTML file each (dist/single/), and the
//               mathematics, each working opened from file://
//   figures/    every figure of the tour as SVG, drawn by its module in Node as the tour opens
//               (the moving ones at t = 1, in mid-flow), 1200 × 900
//   element/    <kli-figure> as one script and its style sheet, for a teacher's own HTML notes
//   deck/       the lecture (www/examples/slides.html) with reveal.js and its notes plugin as
//               classic scripts and the element's one-file script: module scripts do not load
//               from file://, classic ones do
//   README.txt  what is where, and how to open it
// The figures are also written to dist/kit/figures/ to look at without unzipping.
import { mkdirSync, readFileSync, readdirSync, writeFileSync } from "node:fs";
import { join } from "node:path";
import { zipSync, strToU8 } from "fflate";
import { PAGES } from "../www/pages.js";

const root = new URL("../", import.meta.url).pathname;
const single = join(root, "dist/single");
export const KIT = "kli-teaching-kit.zip";
const [WIDTH, HEIGHT] = [1200, 900];
/** What a drawn SVG figure is made of, beside its background rectangle. */
const SHAPE = /<(?:path|polygon|polyline|line|circle|ellipse|text)\b/g;

/** The tour's figures as SVG files, by file name: every canvas of learn.html, at the tour's opening
 *  state, the clock at t = 1: the moving figures in mid-flow (by its span's middle, t = 6, KLI has
 *  arrived and its tangent part is too short to see). */
async function tourFigures() {
  const tour = PAGES.find((page) => page.name === "learn");
  if (!tour) throw new Error("www/pages.js has no page named learn");
  const module = await import(join(root, `www/pkg/${tour.name}_demo.js`));
  module.initSync({ module: readFileSync(join(root, `www/pkg/${tour.name}_demo_bg.wasm`)) });
  const run = tour.state.create(module, tour.state.defaults);
  try {
    const t = 1;
    const [azimuth, elevation] = module.defaultCamera();
    /** @type {Record<string, Uint8Array>} */
    const files = {};
    for (const view of Object.keys(tour.canvases)) {
      const svg = run.toSvg(view, { width: WIDTH, height: HEIGHT, pixelRatio: 1, t, azimuth, elevation, textScale: 1.25 });
      if (!svg.startsWith("<svg") || (svg.match(SHAPE) ?? []).length < 3) throw new Error(`the tour's ${view} figure drew nothing`);
      files[`tour-${view}.svg`] = strToU8(svg);
    }
    return files;
  } finally {
    run.free();
  }
}

const README = `kli: the teacher's kit
======================

Every page of the kli site, and its guided tour, as files that work with no network and no
installation: open them in a browser (Chrome, Edge, Firefox or Safari of 2023 or later) by
double-clicking. Nothing is fetched; every number is computed on your computer.

pages/learn.html      the guided tour: rotations, from a turn to the Kuramoto flow, with exercises
pages/index.html      KLI: two rotations, the paper's method beside SLERP
pages/keyframes.html  many rotations through keyframes
pages/swarm.html      the swarm: many rotations on S3 pulling on each other
pages/average.html    averaging rotations
pages/sync.html       synchronising rotations on a graph
pages/math.html       the mathematics, checked
deck/slides.html      the lecture: seventeen slides, a live figure on each; press S for the speaker
                      notes, F for full screen; to print it, add ?print-pdf to its address and print
figures/              every figure of the tour as SVG (vector: it scales to a poster and opens in
                      Inkscape, Illustrator, LibreOffice, PowerPoint or Keynote)
element/              <kli-figure>: live figures in your own HTML notes, e.g.
                        <link rel="stylesheet" href="kli-figure.css">
                        <script src="kli-figure.js"></script>
                        <kli-figure view="slerp" s="0.25"></kli-figure>

A handout: open pages/learn.html and print it (or save it as PDF). Each figure prints whole, as
vector, at the state on screen; the controls are left out; every exercise prints with its answer.

The paper: Zinaid Kapic and Aladin Crnkic, "Interpolating Rotations with Non-abelian Kuramoto
Model on the 3-Sphere", University of Bihac.
`;

/** The lecture deck as it works from a disk: the site's deck (examples/slides.html) with its module
 *  scripts swapped for classic ones beside it, and its links to the site's pages to the kit's. */
function deck() {
  let html = readFileSync(join(root, "www/examples/slides.html"), "utf8");
  const swap = (/** @type {string | RegExp} */ from, /** @type {string} */ to) => {
    const before = html;
    html = html.replace(from, to);
    if (html === before) throw new Error(`www/examples/slides.html: ${from} not found: the kit's deck needs it`);
  };
  swap('<link rel="stylesheet" href="vendor/reveal/reveal.css">', '<link rel="stylesheet" href="reveal/reveal.css">');
  swap('<link rel="stylesheet" href="vendor/reveal/theme/white.css">', '<link rel="stylesheet" href="reveal/white.css">');
  swap('<link rel="stylesheet" href="../kli-figure.css">', '<link rel="stylesheet" href="../element/kli-figure.css">');
  swap('<script type="module" src="../kli-figure.js"></script>', '<script src="../element/kli-figure.js"></script>');
  swap(/<script type="module">\n  import Reveal[^]*?<\/script>/, `<script src="reveal/reveal.js"></script>
<script src="reveal/notes.js"></script>
<script>
  // S opens the speaker notes (each slide's <aside class="notes">) in a window of their own.
  Reveal.initialize({ hash: true, width: 960, height: 700, transition: "none", plugins: [RevealNotes] });
</script>`);
  html = html.replace(/href="\.\.\/(learn|math)\.html/g, 'href="../pages/$1.html').replace(/href="\.\.\/teach\.html"/g, 'href="../README.txt"');
  if (/href="\.\.\/(?!pages\/|element\/|README)/.test(html)) throw new Error("the kit's deck links a page the kit has not");
  const reveal = join(root, "node_modules/reveal.js/dist");
  return {
    "deck/slides.html": strToU8(html),
    "deck/reveal/reveal.js": readFileSync(join(reveal, "reveal.js")),
    "deck/reveal/notes.js": readFileSync(join(reveal, "plugin/notes.js")),
    "deck/reveal/reveal.css": readFileSync(join(reveal, "reveal.css")),
    "deck/reveal/white.css": readFileSync(join(reveal, "theme/white.css")),
  };
}

/** The kit's files, by their path in the zip. */
async function kit() {
  /** @type {Record<string, Uint8Array>} */
  const files = { "kli-teaching-kit/README.txt": strToU8(README) };
  const pages = [...PAGES.map((page) => page.html), "math.html"];
  for (const page of pages) files[`kli-teaching-kit/pages/${page}`] = readFileSync(join(single, page));
  for (const name of ["kli-figure.js", "kli-figure.css"]) files[`kli-teaching-kit/element/${name}`] = readFileSync(join(single, name));
  for (const [name, bytes] of Object.entries(deck())) files[`kli-teaching-kit/${name}`] = bytes;
  const figures = await tourFigures();
  mkdirSync(join(root, "dist/kit/figures"), { recursive: true });
  for (const [name, svg] of Object.entries(figures)) {
    files[`kli-teaching-kit/figures/${name}`] = svg;
    writeFileSync(join(root, "dist/kit/figures", name), svg);
  }
  return files;
}

const files = await kit();
// Level 6: the pages are mostly base64 text, which compresses by a quarter either way.
const zip = zipSync(files, { level: 6, mtime: new Date("2026-01-01") });
writeFileSync(join(root, "www", KIT), zip);
const unexpected = readdirSync(single).filter((name) => name.endsWith(".html") && !Object.keys(files).some((path) => path.endsWith(`/${name}`)));
if (unexpected.length) throw new Error(`dist/single has pages the kit leaves out: ${unexpected.join(", ")}`);
console.log(`www/${KIT}: ${Object.keys(files).length} files, ${zip.length} bytes`);
