// @ts-check
// The pages' registry: a page is its folder (www/<name>/: page.js, its descriptor; state.js, its
// state; the Rust run class in crates/kli-demo/src/<name>/, built with the Cargo feature
// `<name>-page` into www/pkg/<name>_demo.js) and one entry here. Everything else reads this list:
// the Makefile (which modules to build), scripts/pages.mjs (each page's bundle, script tag and
// navigation, its Save list, the service worker's files), `make single`, the first pictures,
// <kli-figure> (which module draws which view, and its state) and every end-to-end suite.
// tests/js/registry.test.mjs fails on a page that is on disk and not here, or the reverse.
import { AVERAGE } from "./average/state.js";
import { FIGURE_DEFAULTS as KEYFRAMES_FIGURE, KEYFRAMES } from "./keyframes/state.js";
import { KLI } from "./kli/state.js";
import { LEARN } from "./learn/state.js";
import { FIGURE_DEFAULTS as SWARM_FIGURE, SWARM } from "./swarm/state.js";
import { FIGURE_DEFAULTS as SYNC_FIGURE, SYNC } from "./sync/state.js";

/**
 * @typedef {object} State what a page's state module exports (www/<name>/state.js)
 * @property {readonly import("./runtime/schema.js").Entry[]} schema each state key with its URL key and kind
 * @property {Record<string, any>} presets
 * @property {Record<string, any>} defaults what the page shows first
 * @property {(module: any, state: any) => any} create the module's run from a state
 * @property {(error: unknown) => string | undefined} keyOf the key of the state an Error is about
 */

/**
 * @typedef {object} Page
 * @property {string} name the page's word: its folders, its module (`<name>_demo`), its Cargo feature (`<name>-page`)
 * @property {string} html its address (kept as first published, so shared links keep working)
 * @property {string} title the link text in the pages' navigation
 * @property {State} state its state (www/<name>/state.js)
 * @property {Record<string, any>} figure what a <kli-figure> of this page shows without attributes
 * @property {() => Promise<any>} module its WebAssembly module's glue, loaded on demand
 * @property {Readonly<Record<string, string>>} views each <kli-figure> view its module draws: the module's name for it
 *   (how each view follows the time is the module's to say: its runs' `views`)
 * @property {Readonly<Record<string, string>>} canvases each view's canvas on the page (a selector), by the view's
 *   name: the page runtime draws into them, and `make www` draws each first picture (scripts/first-pictures.mjs)
 * @property {Readonly<Record<string, readonly [string, string]>>} save its Save section, in order: each canvas's view
 *   (PNG and SVG), then its data (CSV and JSON, under the name the run's `export` takes), each with its label and
 *   its name in a sentence ("the Hopf sphere as PNG")
 */

/** @type {readonly Page[]} */
export const PAGES = [
  {
    name: "kli", html: "index.html", title: "KLI: two rotations", state: KLI, figure: KLI.defaults,
    module: () => import("./pkg/kli_demo.js"),
    views: { object: "object", hopf: "hopf", plots: "plots", filmstrip: "filmstrip" },
    canvases: { object: "#object-canvas", hopf: "#hopf-canvas", filmstrip: "#filmstrip-canvas", plots: "#plots-canvas" },
    save: {
      object: ["Object", "the object view"], hopf: ["Hopf sphere", "the Hopf sphere"], filmstrip: ["Filmstrip", "the filmstrip"],
      plots: ["Plots", "the plots"], path: ["The path", "the path"],
    },
  },
  {
    name: "keyframes", html: "keyframes.html", title: "Many rotations", state: KEYFRAMES, figure: KEYFRAMES_FIGURE,
    module: () => import("./pkg/keyframes_demo.js"),
    views: { keyframes: "hopf" },
    canvases: { objects: "#keyframes-objects", hopf: "#keyframes-hopf", plots: "#keyframes-plots" },
    save: {
      objects: ["Objects", "the objects"], hopf: ["Hopf sphere", "the Hopf sphere"], plots: ["Plots", "the plots"],
      curves: ["The curves", "the three curves"],
    },
  },
  {
    name: "swarm", html: "swarm.html", title: "The swarm", state: SWARM, figure: SWARM_FIGURE,
    module: () => import("./pkg/swarm_demo.js"),
    views: { swarm: "hopf" },
    canvases: { hopf: "#swarm-hopf", objects: "#swarm-objects", plots: "#swarm-plots", sweep: "#swarm-sweep" },
    save: {
      hopf: ["Hopf sphere", "the Hopf sphere"], objects: ["Objects", "the objects"], plots: ["Plots", "the plots"],
      sweep: ["Sweep", "the coupling sweep"], swarm: ["The swarm", "the swarm"],
    },
  },
  {
    name: "average", html: "average.html", title: "Averaging", state: AVERAGE, figure: AVERAGE.defaults,
    module: () => import("./pkg/average_demo.js"),
    views: { average: "hopf" },
    canvases: { hopf: "#average-hopf", objects: "#average-objects", means: "#average-means", sweep: "#average-sweep" },
    save: {
      hopf: ["Hopf sphere", "the Hopf sphere"], objects: ["Objects", "the objects"], means: ["Means", "the means"],
      sweep: ["Sweep", "the outlier sweep"], measurements: ["The measurements", "the measurements"],
    },
  },
  {
    name: "sync", html: "sync.html", title: "Synchronising rotations", state: SYNC, figure: SYNC_FIGURE,
    module: () => import("./pkg/sync_demo.js"),
    views: { sync: "graph" },
    canvases: {
      graph: "#sync-graph", hopf: "#sync-hopf", plots: "#sync-plots", results: "#sync-results", objects: "#sync-objects",
      sweep: "#sync-sweep", map: "#sync-map", file: "#sync-file",
    },
    save: {
      graph: ["Graph", "the graph"], hopf: ["Hopf sphere", "the Hopf sphere"], plots: ["Plots", "the plots"],
      results: ["Solutions", "the two solutions"], objects: ["Objects", "the objects"], sweep: ["Sweep", "the wrong-edge sweep"],
      map: ["Map", "the pose graph's map"], file: ["Your pose graph's rotations", "your pose graph's rotation residuals"], edges: ["The edges and nodes", "every edge and node"],
    },
  },
  {
    name: "learn", html: "learn.html", title: "Learn: a guided tour", state: LEARN, figure: LEARN.defaults,
    module: () => import("./pkg/learn_demo.js"),
    views: { turn: "turn", cover: "cover", slerp: "slerp", rolled: "rolled", phases: "phases", lohe: "lohe", tangent: "kli", rates: "rates" },
    canvases: {
      euler: "#learn-euler", turn: "#learn-turn", cover: "#learn-cover", slerp: "#learn-slerp", hopf: "#learn-hopf",
      rolled: "#learn-rolled", phases: "#learn-phases", lohe: "#learn-lohe", kli: "#learn-kli", clock: "#learn-clock",
      steps: "#learn-steps", drift: "#learn-drift", rates: "#learn-rates",
    },
    save: {
      euler: ["Euler angles", "the Euler angles figure"], turn: ["Turn", "the turn"], cover: ["Double cover", "the double cover"],
      slerp: ["SLERP", "the SLERP figure"], hopf: ["Hopf sphere", "the Hopf sphere"], rolled: ["Rolled object", "the rolled object"],
      phases: ["Phases", "the Kuramoto phases"], lohe: ["Swarm on S³", "the swarm on S³"], kli: ["KLI", "the KLI figure"],
      clock: ["Time warp", "the time warp"], steps: ["Algorithm 1", "Algorithm 1's steps"], drift: ["Drift", "the drift"],
      rates: ["Turning rate", "the turning rate"], tour: ["Algorithm 1's path", "Algorithm 1's path"],
    },
  },
];

/** Links in the pages' navigation after the pages: the site's documents (docs/*.md rendered by
 *  scripts/documents.mjs) and the examples. */
export const MORE_LINKS = [
  { href: "math.html", title: "The mathematics" },
  { href: "teach.html", title: "For teachers" },
  { href: "examples/three.html", title: "With three.js" },
];

/** The example pages (www/examples/), each with the pages' navigation as the registry makes it
 *  (scripts/pages.mjs writes their `<nav>`): every page, the links after them, and the example
 *  itself where it is not among those links. */
export const EXAMPLES = [
  { href: "examples/three.html", title: "With three.js" },
  { href: "examples/animation.html", title: "Smooth tracks" },
  { href: "examples/figures.html", title: "Figures in a text" },
];

/** The page whose module draws `view`, if any. */
export const pageOfView = (/** @type {string} */ view) => PAGES.find((page) => Object.hasOwn(page.views, view));

/** A page's bundle, which its HTML loads. */
export const bundle = (/** @type {Page} */ page) => `pkg/${page.name}-page.js`;

/** A page's descriptor, the module its bundle is made from. */
export const script = (/** @type {Page} */ page) => `${page.name}/page.js`;

/** A page by name. */
export const page = (/** @type {string} */ name) => /** @type {Page} */ (PAGES.find((p) => p.name === name));
