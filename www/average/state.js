// @ts-check
// The averaging page's state, for its page and for <kli-figure> alike: the schema (each key's URL key and
// kind: runtime/schema.js), its presets and the one shown first, the module's run built from a
// state, and the key of the state an Error of the module is about (by `error.argument`, never by
// its text).
import { argumentOf } from "../runtime/runs.js";

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
