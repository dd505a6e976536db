// @ts-check
// The swarm page's state, for its page and for <kli-figure> alike: the schema (each key's URL key and
// kind: runtime/schema.js), its presets and the one shown first, the module's run built from a
// state, and the key of the state an Error of the module is about (by `error.argument`, never by
// its text).
import { argumentOf } from "../runtime/runs.js";

/** @typedef {Required<Omit<import("../pkg/swarm_demo.js").SwarmOptions, "startSpread" | "order">> & { startSpread?: number }} SwarmState */
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

/** A <kli-figure view="swarm"> without attributes: 200 oscillators, lighter than the page's 500. */
export const FIGURE_DEFAULTS = { count: 200, coupling: 1, seed: 1 };
