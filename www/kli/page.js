// @ts-check
// The KLI page: a descriptor for the page runtime (runtime.js), p and r as axis and angle, and
// the tables. Computing, checking and drawing are the module's KliDemo (crates/kli-demo/src/kli/).
import * as kli from "../pkg/kli_demo.js";
import { axisAngle, fromAxisAngle } from "../pkg/kli_demo.js";
import { $ } from "../runtime/dom.js";
import { timeTag } from "../runtime/exports.js";
import { errorPlace, fillAxisAngle, readAxisAngle } from "./form.js";
import { formatNumber } from "../runtime/numbers.js";
import { randomQuaternion } from "../runtime/presets.js";
import { clearErrors, messageOf, showFieldError } from "../runtime/runs.js";
import { page as registered } from "../pages.js";
import { Page } from "../runtime/runtime.js";
import { DEFAULTS } from "./state.js";
import { describeFrame, describeRun, fillTable, fillTypo } from "./summary.js";

/** @typedef {import("./form.js").State} State */

const AXIS_ANGLE_FIELD = /^([pr])-(ax|ay|az|angle)$/;
/** Whether the axis–angle fields are being typed in (then the run does not refill them). */
let typingAxisAngle = false;

/** @type {Page<State, kli.KliDemo>} */
const page = new Page({
  entry: registered("kli"),
  module: kli,
  form: "#inputs",
  random: () => ({ ...DEFAULTS, p: randomQuaternion(), r: randomQuaternion() }),
  route: (host, error) => errorPlace(host.form, error),
  readout: (run, t) => `t = ${t.toFixed(2)} / T = ${run.summary.finalTime.toFixed(2)}`,
  labels: (run, t) => ({ object: describeFrame(run, t) }),
  note: (run, state) => describeRun(run, state),
  stride: (state) => state.step,
  timeInUrl: true,
  data: { file: (run) => `kli-path-T${run.summary.finalTime.toFixed(2)}` },
  file: (_, view, t) => `kli-${view}${view === "filmstrip" ? "" : `-${timeTag(t)}`}`,
  // The paper's video: the object turning beside its Hopf curve.
  video: {
    views: ["object", "hopf"],
    title: (run) => (run.summary.paperExample ? "The paper's example: KLI from p to r, and its Hopf curve on S²" : "KLI from p to r, and its Hopf curve on S²"),
    file: (run) => (run.summary.paperExample ? "kli-paper-example" : `kli-path-T${run.summary.finalTime.toFixed(2)}`),
  },
  shown: (host, run, state) => {
    fillTable(run, $("#moments tbody", HTMLTableSectionElement), $("#final-time", HTMLElement), $("#printed-notes", HTMLUListElement));
    fillTypo(run, state.tolerance, $("#typo tbody", HTMLTableSectionElement), $("#typo-summary", HTMLElement));
    if (!typingAxisAngle) fillAxisAngles(host.form, state);
  },
  input: (host, name) => {
    const axisAngleField = AXIS_ANGLE_FIELD.exec(name);
    if (!axisAngleField) return false;
    const which = /** @type {"p" | "r"} */ (axisAngleField[1]);
    const { axis, angle } = readAxisAngle(host.form, which);
    let q;
    try {
      q = fromAxisAngle(axis, angle);
    } catch (error) {
      clearErrors(host.form);
      const { output, fields } = errorPlace(host.form, error, which);
      showFieldError(host.form, output, fields, `${which}: ${messageOf(error)}`);
      return true;
    }
    host.fields(which).forEach((field, i) => (field.value = formatNumber(q[i])));
    typingAxisAngle = true;
    host.rebuild(host.read());
    typingAxisAngle = false;
    return true;
  },
});

/** p's and r's axis and angle fields from the state (a value that is no quaternion is left:
 *  its own message is shown already). */
function fillAxisAngles(/** @type {HTMLFormElement} */ form, /** @type {State} */ state) {
  for (const which of /** @type {const} */ (["p", "r"])) {
    try {
      fillAxisAngle(form, which, axisAngle(state[which]));
    } catch {
      // Not a quaternion.
    }
  }
}

page.start();
