// @ts-check
// The KLI page's form beyond its schema: p and r also as axis and angle, and where the module's
// Errors show (routed by `error.argument` and `error.component`, never by the message's text).

import { formatNumber, parseNumber } from "../runtime/numbers.js";
import { KLI } from "./state.js";

/**
 * The KLI page's state: the KliDemo's arguments, in the JavaScript API's names.
 * @typedef {object} State
 * @property {number[]} p
 * @property {number[]} r
 * @property {number} tolerance
 * @property {number} step
 * @property {import("../pkg/kli_demo.js").Integrator} integrator
 * @property {boolean} shortestPath
 */

/** @typedef {"p" | "r"} Which */

const COMPONENTS = ["w", "x", "y", "z"];
const AXIS_ANGLE = ["ax", "ay", "az", "angle"];

/**
 * Where an Error shows: its output and the fields it marks (one component of a quaternion when
 * the Error names it; the axis or the angle of `group` when its axis–angle fields were read).
 * @param {HTMLFormElement} form
 * @param {unknown} error
 * @param {Which} [group]
 */
export function errorPlace(form, error, group) {
  const { argument, component } = /** @type {Partial<import("../pkg/kli_demo.js").KliError>} */ (error ?? {});
  const field = (/** @type {string} */ name) => /** @type {HTMLInputElement} */ (form.elements.namedItem(name));
  if (group && (argument === "axis" || argument === "angle")) {
    const axis = AXIS_ANGLE.map((c) => field(`${group}-${c}`));
    return { output: group, fields: argument === "angle" ? [axis[3]] : component === undefined ? axis.slice(0, 3) : [axis[component]] };
  }
  if (argument === "p" || argument === "r") {
    const components = COMPONENTS.map((c) => field(`${argument}-${c}`));
    return { output: argument, fields: component === undefined ? components : [components[component]] };
  }
  const key = KLI.keyOf(error);
  // An Error about nothing the form holds shows under the last fieldset, marking nothing.
  return key ? { output: key, fields: [field(key)] } : { output: "shortestPath", fields: [] };
}

/** The axis (3 numbers) and angle (radians) typed for `which`. */
export function readAxisAngle(/** @type {HTMLFormElement} */ form, /** @type {Which} */ which) {
  const [x, y, z, degrees] = AXIS_ANGLE.map((c) => parseNumber(/** @type {HTMLInputElement} */ (form.elements.namedItem(`${which}-${c}`)).value));
  return { axis: [x, y, z], angle: (degrees * Math.PI) / 180 };
}

/** Fills the axis and angle fields of `which` from [x, y, z, radians]. */
export function fillAxisAngle(/** @type {HTMLFormElement} */ form, /** @type {Which} */ which, /** @type {ArrayLike<number>} */ axisAngle) {
  const values = [axisAngle[0], axisAngle[1], axisAngle[2], (axisAngle[3] * 180) / Math.PI];
  AXIS_ANGLE.forEach((c, i) => (/** @type {HTMLInputElement} */ (form.elements.namedItem(`${which}-${c}`)).value = formatNumber(values[i])));
}
