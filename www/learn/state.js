// @ts-check
// The tour's state (learn.html), for its page and for <kli-figure> alike: every section's control
// with its URL key and kind (runtime/schema.js), the one preset (the tour as it opens), the
// module's run built from a state, and the key of the state an Error of the module is about (by
// `error.argument`, never by its text).
import { argumentOf } from "../runtime/runs.js";

/**
 * @typedef {{ yaw: number, pitch: number, bank: number, axis: string, angle: number, s: number, roll: number,
 *   coupling: number, lohe: number, digits: number, delta: number, integrator: string, step: number,
 *   smoothness: number }} LearnState
 */

/** The tour as it opens: the paper's ε = 1e-5 and δ = 0.01, a quarter turn about z, the keyframe
 *  chain at its smoothest. */
const START = /** @type {LearnState} */ ({
  yaw: 30, pitch: 40, bank: 0, axis: "z", angle: 90, s: 0.5, roll: 0, coupling: 1.5, lohe: 3, digits: 5, delta: 0.01,
  integrator: "euler", step: 0.5, smoothness: 1,
});

/** The tour (learn.html): `?axis=z&angle=90&s=0.5&roll=0&K=1.5&digits=5&delta=0.01&int=euler&h=0.5&smooth=1…`. */
export const LEARN = {
  schema: /** @type {const} */ ([
    { key: "yaw", url: "yaw", kind: "number", range: [-180, 180] },
    { key: "pitch", url: "pitch", kind: "number", range: [-90, 90] },
    { key: "bank", url: "bank", kind: "number", range: [-180, 180] },
    { key: "axis", url: "axis", kind: "word" },
    { key: "angle", url: "angle", kind: "number", range: [0, 720] },
    { key: "s", url: "s", kind: "number", range: [0, 1] },
    { key: "roll", url: "roll", kind: "number", range: [-180, 180] },
    { key: "coupling", url: "K", kind: "number", range: [0, 4] },
    { key: "lohe", url: "K3", kind: "number", range: [0, 4] },
    { key: "digits", url: "digits", kind: "number", range: [1, 10] },
    { key: "delta", url: "delta", kind: "number", range: [0.001, 0.5] },
    { key: "integrator", url: "int", kind: "word" },
    { key: "step", url: "h", kind: "number", range: [0.01, 1] },
    { key: "smoothness", url: "smooth", kind: "number", range: [0, 1] },
  ]),
  presets: { start: START },
  defaults: START,
  /** @param {any} module @param {LearnState} state */
  create: (module, state) => new module.LearnDemo(state),
  keyOf: (/** @type {unknown} */ error) => LEARN.schema.find((entry) => entry.key === argumentOf(error))?.key,
};
