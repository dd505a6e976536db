// @ts-check
// The input form: its fields to a candidate state and back, and the module's Errors shown beside
// the fields they are about, routed by `error.argument` (never by the message's text). Checking
// values is the module's job: the form only turns text into numbers (NaN when it is not one).

import { formatNumber, parseNumber } from "./numbers.js";
import { clearErrors, showFieldError } from "./runs.js";

/**
 * The page's state: the Demo's arguments, in the JavaScript API's names.
 * @typedef {object} State
 * @property {number[]} p
 * @property {number[]} r
 * @property {number} tolerance
 * @property {number} step
 * @property {import("./pkg/kli_demo.js").Integrator} integrator
 * @property {boolean} shortestPath
 */

/** @typedef {"p" | "r"} Which */

const COMPONENTS = ["w", "x", "y", "z"];
const AXIS_ANGLE = ["ax", "ay", "az", "angle"];
/** The error output of each argument the page can get wrong; `maxTime` is the step's business. */
const OUTPUTS = { p: "p", r: "r", tolerance: "tolerance", step: "step", maxTime: "step", integrator: "integrator", shortestPath: "shortestPath" };

/** The key of the state an Error's argument belongs to (`maxTime` to the step), if any. */
export function stateKey(/** @type {unknown} */ error) {
  const argument = /** @type {{ argument?: string }} */ (error ?? {}).argument;
  return argument && argument in OUTPUTS ? /** @type {keyof State} */ (OUTPUTS[/** @type {keyof typeof OUTPUTS} */ (argument)]) : undefined;
}

export class Form {
  /** @param {HTMLFormElement} form */
  constructor(form) {
    this.form = form;
  }

  /** @param {string} name */
  field(name) {
    const field = this.form.elements.namedItem(name);
    if (!(field instanceof HTMLInputElement || field instanceof HTMLSelectElement)) throw new Error(`no field ${name}`);
    return field;
  }

  /** @param {Which} which */
  quaternionFields(which) {
    return COMPONENTS.map((c) => this.field(`${which}-${c}`));
  }

  /** @param {Which} which */
  axisAngleFields(which) {
    return AXIS_ANGLE.map((c) => this.field(`${which}-${c}`));
  }

  /** The form as a candidate state: numbers (NaN where the text is not one), for the module to check.
   *  @returns {State} */
  read() {
    const numbers = (/** @type {Which} */ which) => this.quaternionFields(which).map((f) => parseNumber(f.value));
    return {
      p: numbers("p"),
      r: numbers("r"),
      tolerance: parseNumber(this.field("tolerance").value),
      step: parseNumber(this.field("step").value),
      integrator: /** @type {State["integrator"]} */ (this.field("integrator").value),
      shortestPath: /** @type {HTMLInputElement} */ (this.field("shortestPath")).checked,
    };
  }

  /** The axis (3 numbers) and angle (radians) typed for `which`. */
  readAxisAngle(/** @type {Which} */ which) {
    const [x, y, z, degrees] = this.axisAngleFields(which).map((f) => parseNumber(f.value));
    return { axis: [x, y, z], angle: (degrees * Math.PI) / 180 };
  }

  /** @param {State} state */
  fill(state) {
    this.fillQuaternion("p", state.p);
    this.fillQuaternion("r", state.r);
    this.field("tolerance").value = String(state.tolerance);
    this.field("step").value = String(state.step);
    this.field("integrator").value = state.integrator;
    /** @type {HTMLInputElement} */ (this.field("shortestPath")).checked = state.shortestPath;
  }

  /** @param {Which} which @param {ArrayLike<number>} q */
  fillQuaternion(which, q) {
    this.quaternionFields(which).forEach((f, i) => (f.value = formatNumber(q[i])));
  }

  /** @param {Which} which @param {ArrayLike<number>} axisAngle [x, y, z, radians] */
  fillAxisAngle(which, axisAngle) {
    const values = [axisAngle[0], axisAngle[1], axisAngle[2], (axisAngle[3] * 180) / Math.PI];
    this.axisAngleFields(which).forEach((f, i) => (f.value = formatNumber(values[i])));
  }

  /** Empties every message and unmarks every field. */
  clearErrors() {
    clearErrors(this.form);
  }

  /**
   * Shows an Error of the module beside the fields it is about, and marks those fields.
   * @param {unknown} error
   * @param {Which} [group] the quaternion whose axis–angle fields were being read
   */
  showError(error, group) {
    const { argument, component, message } = /** @type {Partial<import("./pkg/kli_demo.js").KliError>} */ (error ?? {});
    let output = "shortestPath";
    /** @type {(HTMLInputElement | HTMLSelectElement)[]} */
    let fields = [];
    if (group && (argument === "axis" || argument === "angle")) {
      output = group;
      const axis = this.axisAngleFields(group);
      fields = argument === "angle" ? [axis[3]] : component === undefined ? axis.slice(0, 3) : [axis[component]];
    } else if (argument === "p" || argument === "r") {
      output = argument;
      const components = this.quaternionFields(argument);
      fields = component === undefined ? components : [components[component]];
    } else if (argument && argument in OUTPUTS) {
      output = OUTPUTS[/** @type {keyof typeof OUTPUTS} */ (argument)];
      fields = [this.field(output)];
    }
    showFieldError(this.form, output, fields, group && output === group ? `${group}: ${message}` : String(message ?? error));
  }
}
