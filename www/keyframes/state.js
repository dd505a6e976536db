// @ts-check
// The keyframes page's state, for its page and for <kli-figure> alike: the schema (each key's URL key and
// kind: runtime/schema.js), its presets and the one shown first, the module's run built from a
// state, and the key of the state an Error of the module is about (by `error.argument`, never by
// its text).
import { argumentOf } from "../runtime/runs.js";

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

/** A <kli-figure view="keyframes"> without attributes: four keys, lighter than the page's six. */
export const FIGURE_DEFAULTS = { keys: [[1, 0, 0, 0], [0.8, 0.6, 0, 0], [0.6, 0, 0.8, 0], [0, 0, 0.6, 0.8]], times: [], smoothness: 1 };
