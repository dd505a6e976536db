// @ts-check
// The synchronisation page's state, for its page and for <kli-figure> alike: the schema (each key's
// URL key and kind: runtime/schema.js), its presets and the one shown first, the module's run
// built from a state, and the key of the state an Error of the module is about (by
// `error.argument`, never by its text).
import { argumentOf } from "../runtime/runs.js";

/** @typedef {{ count: number, graph: string, noise: number, wrong: number, seed: number, consensus: boolean }} SyncState */

/** @type {Record<string, SyncState>} */
const SYNC_PRESETS = {
  noise: { count: 100, graph: "random", noise: 5, wrong: 0, seed: 1, consensus: false },
  wrong: { count: 100, graph: "random", noise: 5, wrong: 0.1, seed: 1, consensus: false },
  many: { count: 200, graph: "random", noise: 2, wrong: 0.3, seed: 2, consensus: false },
  ring: { count: 40, graph: "ring", noise: 5, wrong: 0, seed: 1, consensus: false },
  consensus: { count: 60, graph: "grid", noise: 0, wrong: 0, seed: 1, consensus: true },
};

/** Synchronising rotations (sync.html, and the sync figure): the problem's recipe,
 *  `?n=100&graph=random&noise=5&wrong=0.1&seed=1&consensus=0`. */
export const SYNC = {
  schema: /** @type {const} */ ([
    { key: "count", url: "n", kind: "number", range: [3, 300] },
    { key: "graph", url: "graph", kind: "word" },
    { key: "noise", url: "noise", kind: "number", range: [0, 30] },
    { key: "wrong", url: "wrong", kind: "number", range: [0, 0.4] },
    { key: "seed", url: "seed", kind: "number" },
    { key: "consensus", url: "consensus", kind: "flag" },
  ]),
  presets: SYNC_PRESETS,
  defaults: SYNC_PRESETS.wrong,
  /** @param {any} module @param {SyncState} state */
  create: (module, state) => new module.SyncDemo(state),
  keyOf: (/** @type {unknown} */ error) => SYNC.schema.find((entry) => entry.key === argumentOf(error))?.key,
};

/** A <kli-figure view="sync"> without attributes: the page's problem. */
export const FIGURE_DEFAULTS = SYNC_PRESETS.wrong;
