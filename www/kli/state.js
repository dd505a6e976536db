// @ts-check
// The KLI page's state, for its page and for <kli-figure> alike: the schema (each key's URL key and
// kind: runtime/schema.js), its presets and the one shown first, the module's run built from a
// state, and the key of the state an Error of the module is about (by `error.argument`, never by
// its text).
import { argumentOf } from "../runtime/runs.js";

/** @type {Record<string, import("./form.js").State>} */
export const PRESETS = {
  paper: { p: [0, 0, 0, 1], r: [0.5, 0.5, 0.5, 0.5], tolerance: 1e-5, step: 0.01, integrator: "rk4", shortestPath: true },
  antipodal: { p: [0, 0, 0, 1], r: [0, 0, 0, -1], tolerance: 1e-5, step: 0.01, integrator: "rk4", shortestPath: true },
  "long-way": { p: [1, 0, 0, 0], r: [-0.995, 0, 0, 0.0998], tolerance: 1e-5, step: 0.01, integrator: "rk4", shortestPath: false },
  "near-identical": { p: [0, 0, 0, 1], r: [0.001, 0, 0, 1], tolerance: 1e-5, step: 0.01, integrator: "rk4", shortestPath: true },
};

/** What the page shows first: the paper's example. */
export const DEFAULTS = PRESETS.paper;

/** The KLI page's key of each argument the module can refuse; `maxTime` is the step's business. */
const KLI_KEYS = /** @type {const} */ ({ p: "p", r: "r", tolerance: "tolerance", step: "step", maxTime: "step", integrator: "integrator", shortestPath: "shortestPath" });

/** Two rotations (index.html, and the figures object, hopf, plots, filmstrip):
 *  `?p=0,0,0,1&r=…&eps=1e-5&step=0.01&int=rk4&short=1`. */
export const KLI = {
  schema: /** @type {const} */ ([
    { key: "p", url: "p", kind: "quaternion" },
    { key: "r", url: "r", kind: "quaternion" },
    { key: "tolerance", url: "eps", kind: "number" },
    { key: "step", url: "step", kind: "number" },
    { key: "integrator", url: "int", kind: "word" },
    { key: "shortestPath", url: "short", kind: "flag" },
  ]),
  presets: PRESETS,
  defaults: DEFAULTS,
  /** @param {any} module @param {import("./form.js").State} state */
  create: (module, { p, r, tolerance, step, integrator, shortestPath }) =>
    new module.KliDemo(p, r, { tolerance, step, integrator, shortestPath }),
  /** @returns {keyof import("./form.js").State | undefined} */
  keyOf: (/** @type {unknown} */ error) => {
    const argument = argumentOf(error);
    return Object.hasOwn(KLI_KEYS, argument) ? KLI_KEYS[/** @type {keyof typeof KLI_KEYS} */ (argument)] : undefined;
  },
};
