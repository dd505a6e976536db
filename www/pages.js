// @ts-check
// The demo's pages, in one place. The Makefile (which modules to build), the pages' bundles and
// their script tags (scripts/pages.mjs), `make single` (which pages to inline), the service
// worker (what to cache, and its cache name) and <kli-figure> (which module draws which view)
// all read this list.

/**
 * @typedef {object} Page
 * @property {string} name the page's word, also its module's (`<name>_demo`) and its Cargo feature's (`<name>-page`)
 * @property {string} html
 * @property {string} script the page's module script (bundled by `make www` into pkg/<name>-page.js)
 * @property {string} title the link text in the pages' navigation
 * @property {Readonly<Record<string, string>>} views each <kli-figure> view its module draws: the module's name for it
 *   (how each view follows the time is the module's to say: its runs' `views`)
 * @property {Readonly<Record<string, string>>} canvases each view's canvas on the page (a selector), by the view's
 *   name: the page runtime draws into them, and `make www` draws each first picture (scripts/first-pictures.mjs)
 */

/** @type {readonly Page[]} */
export const PAGES = [
  {
    name: "kli", html: "index.html", script: "main.js", title: "KLI: two rotations",
    views: { object: "object", hopf: "hopf", plots: "plots", filmstrip: "filmstrip" },
    canvases: { object: "#object-canvas", hopf: "#hopf-canvas", filmstrip: "#filmstrip-canvas", plots: "#plots-canvas" },
  },
  {
    name: "keyframes", html: "keyframes.html", script: "keyframes.js", title: "Many rotations",
    views: { keyframes: "hopf" },
    canvases: { objects: "#keyframes-objects", hopf: "#keyframes-hopf", plots: "#keyframes-plots" },
  },
  {
    name: "swarm", html: "swarm.html", script: "swarm.js", title: "The swarm",
    views: { swarm: "hopf" },
    canvases: { hopf: "#swarm-hopf", objects: "#swarm-objects", plots: "#swarm-plots", sweep: "#swarm-sweep" },
  },
  {
    name: "average", html: "average.html", script: "average.js", title: "Averaging",
    views: { average: "hopf" },
    canvases: { hopf: "#average-hopf", objects: "#average-objects", means: "#average-means", sweep: "#average-sweep" },
  },
];

/** The page whose module draws `view`, if any. */
export const pageOfView = (/** @type {string} */ view) => PAGES.find((page) => Object.hasOwn(page.views, view));

/** A page's bundle, which its HTML loads. */
export const bundle = (/** @type {Page} */ page) => `pkg/${page.name}-page.js`;

/** A page by name. */
export const page = (/** @type {string} */ name) => /** @type {Page} */ (PAGES.find((p) => p.name === name));
