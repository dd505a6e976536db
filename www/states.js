// @ts-check
// Each page's state, for its page and for <kli-figure> alike: the schema (each key's URL key and
// kind: schema.js), the module's run built from a state, and the key of the state an Error of the
// module is about (by `error.argument`, never by its text).
import { PRESETS as KLI_PRESETS } from "./presets.js";
import { argumentOf } from "./runs.js";

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
  presets: KLI_PRESETS,
  /** What the page shows first: the paper's example. */
  defaults: KLI_PRESETS.paper,
  /** @param {any} module @param {import("./form.js").State} state */
  create: (module, { p, r, tolerance, step, integrator, shortestPath }) =>
    new module.Demo(p, r, { tolerance, step, integrator, shortestPath }),
  /** @returns {keyof import("./form.js").State | undefined} */
  keyOf: (/** @type {unknown} */ error) => {
    const argument = argumentOf(error);
    return Object.hasOwn(KLI_KEYS, argument) ? KLI_KEYS[/** @type {keyof typeof KLI_KEYS} */ (argument)] : undefined;
  },
};

/** @type {Record<string, { keys: number[][], times: number[], smoothness: number }>} */
const KEYFRAMES_PRESETS = {
  tumble: {
    keys: [[1, 0, 0, 0], [0.8, 0.6, 0, 0], [0.5, 0.5, 0.5, 0.5], [0, 0.6, 0.8, 0], [-0.3, 0.1, 0.7, 0.64], [0.2, -0.6, 0.3, 0.72]],
    times: [], smoothness: 1,
  },
  uneven: {
    keys: [[1, 0, 0, 0], [0.6, 0, 0.8, 0], [0, 0, 0.6, 0.8], [0.36, 0.48, 0.48, 0.64], [0.8, 0, 0, 0.6]],
    times: [0, 0.5, 2, 2.4, 4], smoothness: 1,
  },
  hard: { keys: [[1, 0, 0, 0], [1, 0, 0, 0], [0, 1, 0, 0], [-0.6, 0, -0.8, 0], [0.6, 0, 0.8, 0], [1, 0, 0, 0]], times: [], smoothness: 1 },
};

/** Many rotations (keyframes.html, and the keyframes figure): keys separated by ";", their
 *  times, the chain's smoothness, `?keys=1,0,0,0;0.8,0.6,0,0;…&times=0,1,2&s=1`. */
export const KEYFRAMES = {
  schema: /** @type {const} */ ([
    { key: "keys", url: "keys", kind: "quaternions" },
    { key: "times", url: "times", kind: "numbers" },
    { key: "smoothness", url: "s", kind: "number", range: [0, 1] },
  ]),
  presets: KEYFRAMES_PRESETS,
  defaults: KEYFRAMES_PRESETS.tumble,
  /** @param {any} module @param {{ keys: number[][], times: number[], smoothness: number }} state */
  create: (module, state) => new module.KeyframesDemo(new Float64Array(state.keys.flat()), new Float64Array(state.times), state.smoothness),
  keyOf: (/** @type {unknown} */ error) => {
    const argument = argumentOf(error);
    return argument.startsWith("keys") ? "keys" : argument.startsWith("times") ? "times" : argument === "smoothness" ? "smoothness" : undefined;
  },
};

/** @typedef {Required<Omit<import("./pkg/swarm_demo.js").SwarmOptions, "startSpread" | "order">> & { startSpread?: number }} SwarmState */
/** @type {Record<string, SwarmState>} */
const SWARM_PRESETS = {
  synchronise: { coupling: 1, count: 500, graph: "all", leaders: 1, frequencySpread: 0, seed: 1 },
  balance: { coupling: -1, count: 500, graph: "all", leaders: 1, frequencySpread: 0, seed: 1 },
  frequencies: { coupling: 2, count: 500, graph: "all", leaders: 1, frequencySpread: 1, seed: 1 },
  kli: { coupling: 2, count: 2, graph: "leader", leaders: 1, frequencySpread: 0, startSpread: 1.5, seed: 3 },
};

/** The swarm (swarm.html, and the swarm figure): the LoheSwarm options,
 *  `?K=1&n=500&graph=all&leaders=1&w=0&seed=1&spread=0.5` (`spread` absent: a uniform start). */
export const SWARM = {
  schema: /** @type {const} */ ([
    { key: "coupling", url: "K", kind: "number", range: [-3, 6] },
    { key: "count", url: "n", kind: "number", range: [2, 2000] },
    { key: "graph", url: "graph", kind: "word" },
    { key: "leaders", url: "leaders", kind: "number" },
    { key: "frequencySpread", url: "w", kind: "number", range: [0, 2] },
    { key: "seed", url: "seed", kind: "number" },
    { key: "startSpread", url: "spread", kind: "number", range: [0, 3], optional: { flag: "uniform", shown: 0.5 } },
  ]),
  presets: SWARM_PRESETS,
  defaults: SWARM_PRESETS.synchronise,
  /** @param {any} module @param {object} state */
  create: (module, state) => new module.SwarmDemo(state),
  keyOf: (/** @type {unknown} */ error) => SWARM.schema.find((entry) => entry.key === argumentOf(error))?.key,
};

/** @type {Record<string, { count: number, noise: number, outliers: number, seed: number, moved: number[][] }>} */
const AVERAGE_PRESETS = {
  clean: { count: 40, noise: 5, outliers: 0, seed: 1, moved: [] },
  some: { count: 40, noise: 5, outliers: 0.2, seed: 1, moved: [] },
  many: { count: 100, noise: 5, outliers: 0.4, seed: 3, moved: [] },
};

/** Averaging (average.html, and the average figure): the measurements' recipe and the ones moved
 *  by hand (index, w, x, y, z each), `?n=40&noise=5&out=0.2&seed=1&moved=3,0.5,0.5,0.5,0.5`. */
export const AVERAGE = {
  schema: /** @type {const} */ ([
    { key: "count", url: "n", kind: "number", range: [3, 500] },
    { key: "noise", url: "noise", kind: "number", range: [0, 30] },
    { key: "outliers", url: "out", kind: "number", range: [0, 0.5] },
    { key: "seed", url: "seed", kind: "number" },
    { key: "moved", url: "moved", kind: "quaternions" },
  ]),
  presets: AVERAGE_PRESETS,
  defaults: AVERAGE_PRESETS.some,
  /** @param {any} module @param {{ count: number, noise: number, outliers: number, seed: number, moved: number[][] }} state */
  create: (module, state) => new module.AverageDemo({ ...state, moved: new Float64Array(state.moved.flat()) }),
  keyOf: (/** @type {unknown} */ error) => AVERAGE.schema.find((entry) => entry.key === argumentOf(error))?.key,
};

/** Each page's state, by the page's name (pages.js). */
export const STATES = { kli: KLI, keyframes: KEYFRAMES, swarm: SWARM, average: AVERAGE };
