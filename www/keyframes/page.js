// @ts-check
// The keyframes page: a descriptor for the page runtime (runtime.js), the key editor, dragging a
// key on the sphere, and the table's timings. The curves, their figures and their drawing are
// the module's KeyframesDemo (crates/kli-demo/src/keyframes/); the timings use the
// package's kliSpline, squadSpline and slerpSpline.
import * as keyframes from "../pkg/keyframes_demo.js";
import { kliSpline, slerpSpline, squadSpline } from "../pkg/keyframes_demo.js";
import { $ } from "../runtime/dom.js";
import { timeTag } from "../runtime/exports.js";
import { grabPoint } from "../runtime/input.js";
import { formatNumber, parseNumber } from "../runtime/numbers.js";
import { randomQuaternion } from "../runtime/presets.js";
import { argumentOf, clearErrors } from "../runtime/runs.js";
import { page as registered } from "../pages.js";
import { Page } from "../runtime/runtime.js";

/** @typedef {{ keys: number[][], times: number[], smoothness: number }} KeyframesState */

/** The views' names in file names. */
const FILE_NAMES = /** @type {Record<string, string>} */ ({ objects: "objects", hopf: "hopf", plots: "angular-velocity-plots" });
const KEY_FIELDS = ["key-ax", "key-ay", "key-az", "key-angle"];

/** @type {Page<KeyframesState, keyframes.KeyframesDemo>} */
const page = new Page({
  entry: registered("keyframes"),
  module: keyframes,
  form: "#keyframes-inputs",
  // The key editor's axis and angle: their own message.
  route: (host, error) => {
    const argument = argumentOf(error);
    if (argument !== "axis" && argument !== "angle") return undefined;
    const names = argument === "angle" ? ["key-angle"] : ["key-ax", "key-ay", "key-az"];
    return { output: "key", fields: names.map((name) => host.field(name)) };
  },
  readout: (run, t) => `t = ${t.toFixed(2)} / ${run.span[1].toFixed(2)}`,
  data: { file: (run) => `kli-keyframes-curves-${keyCount(run)}-keys` },
  file: (run, view, t) => `kli-keyframes-${FILE_NAMES[view]}-${keyCount(run)}-keys-${timeTag(t)}`,
  video: {
    views: ["objects", "hopf"],
    title: (run) => `Through ${keyCount(run)} keys: the Kuramoto–Lohe chain, Squad and piecewise SLERP`,
    file: (run) => `kli-keyframes-${keyCount(run)}-keys`,
  },
  shown: (host, run, state) => {
    $("#smoothness-value", HTMLOutputElement).textContent = String(state.smoothness);
    fillFigures(run, state);
    fillKeyEditor(host, run);
  },
  input: (host, name) => {
    $("#smoothness-value", HTMLOutputElement).textContent = host.field("smoothness").value;
    if (name === "key" && host.run) fillKeyEditor(host, host.run);
    else if (KEY_FIELDS.includes(name)) editKey(host);
    else return false;
    return true;
  },
  wire: (host) => {
    $("#random", HTMLButtonElement).addEventListener("click", () => {
      host.apply({ keys: Array.from({ length: 6 }, randomQuaternion), times: [], smoothness: host.state.smoothness });
    });
    $("#add-key", HTMLButtonElement).addEventListener("click", () => {
      const keys = host.state.keys;
      if (keys.length >= 10) return;
      // A new key a quarter turn about z from the last: [w, x, y, z] · (cos 45°, 0, 0, sin 45°).
      const [w, x, y, z] = keys[keys.length - 1];
      const c = Math.SQRT1_2;
      withKeys(host, [...keys, [c * (w - z), c * (x + y), c * (y - x), c * (z + w)].map((v) => Number(v.toFixed(4)))]);
    });
    $("#remove-key", HTMLButtonElement).addEventListener("click", () => {
      if (host.state.keys.length > 3) withKeys(host, host.state.keys.slice(0, -1));
    });
  },
  grab: grabKey,
});

/** @typedef {import("../runtime/runtime.js").Host<KeyframesState, keyframes.KeyframesDemo>} Host */

/** How many keys a run has. */
const keyCount = (/** @type {keyframes.KeyframesDemo} */ run) => run.keys.length / 4;

/** Keys as rows of 4 from the module's flat Float64Array. */
const rows = (/** @type {Float64Array} */ flat) =>
  Array.from({ length: flat.length / 4 }, (_, i) => Array.from(flat.subarray(4 * i, 4 * i + 4), (c) => Number(c.toPrecision(6))));

/** Rebuilds with new keys (the times kept only while their count still matches). */
function withKeys(/** @type {Host} */ host, /** @type {number[][]} */ keys) {
  const times = host.state.times.length === keys.length ? host.state.times : [];
  host.apply({ keys, times, smoothness: host.state.smoothness });
}

/** The key selector and the selected key's axis and angle. */
function fillKeyEditor(/** @type {Host} */ host, /** @type {keyframes.KeyframesDemo} */ run) {
  const select = /** @type {HTMLSelectElement} */ (host.field("key"));
  const count = keyCount(run);
  const selected = Math.min(Number(select.value) || 0, count - 1);
  select.replaceChildren(...Array.from({ length: count }, (_, i) => new Option(`k${i}`, String(i))));
  select.value = String(selected);
  const [x, y, z, angle] = run.keyAxisAngle(selected);
  [x, y, z, (angle * 180) / Math.PI].forEach((value, i) => (host.field(KEY_FIELDS[i]).value = formatNumber(value)));
  $("#add-key", HTMLButtonElement).disabled = count >= 10;
  $("#remove-key", HTMLButtonElement).disabled = count <= 3;
}

/** The selected key replaced by the rotation its axis and angle fields give. */
function editKey(/** @type {Host} */ host) {
  const run = host.run;
  if (!run) return;
  const index = Number(host.field("key").value);
  const [x, y, z, degrees] = KEY_FIELDS.map((name) => parseNumber(host.field(name).value));
  try {
    withKeys(host, rows(run.keysWithAxisAngle(index, new Float64Array([x, y, z]), (degrees * Math.PI) / 180)));
  } catch (error) {
    clearErrors(host.form);
    host.showError(error);
  }
}

/**
 * A key's disc under the pointer (the nearest in front within 12 px) is grabbed: moving the
 * pointer then turns that key so that its Hopf point follows (once a frame).
 * @param {Host} host
 * @param {number} x
 * @param {number} y
 */
function grabKey(host, x, y) {
  const run = host.run;
  const frame = host.frame("hopf");
  if (!run || !frame) return null;
  return grabPoint(run.keyPoints(frame), x, y, (key, x, y) => {
    const run = host.run;
    const frame = host.frame("hopf");
    if (!run || !frame) return;
    const moved = run.keysWithKeyAt(key, frame, x, y);
    if (moved.length) {
      host.field("key").value = String(key);
      withKeys(host, rows(moved));
    }
  });
}

let timing = 0;

/** The table: the run's measures at once, and a moment after the last change (not on every
 *  move of a dragged key) the solve and evaluation times, measured here. */
function fillFigures(/** @type {keyframes.KeyframesDemo} */ run, /** @type {KeyframesState} */ state) {
  const { curves, iterations, residual } = run.summary;
  const body = $("#figures tbody", HTMLTableSectionElement);
  body.replaceChildren();
  for (const curve of curves) {
    const row = body.insertRow();
    const cells = [curve.name, curve.keyError.toExponential(1), curve.largestJump.toFixed(3), curve.bending.toFixed(3),
      curve.totalAngle.toFixed(3), "…", "…"];
    for (const text of cells) row.insertCell().textContent = text;
  }
  const [chain, squad] = curves;
  $("#solve", HTMLElement).textContent = `The chain: ${iterations} Newton steps to a residual of ${residual.toExponential(1)}; ` +
    (squad.bending > 0 ? `its ∫|ω̇|² is ${(chain.bending / squad.bending).toFixed(3)} of Squad's.` :
      `its ∫|ω̇|² is ${chain.bending.toPrecision(3)}; Squad's is 0 (no turn between the keys), so there is no ratio.`);
  clearTimeout(timing);
  const [start, end] = run.span;
  timing = setTimeout(() => fillTimes(start, end, state), 300);
}

/** The last two columns: each curve built from the package's API and sampled at 10⁴ times, a
 *  curve a task (the three in one task were the page's longest task at load: some 300 ms on
 *  Lighthouse's phone), each row filled as its curve is timed; a newer change stops the rest. */
function fillTimes(/** @type {number} */ start, /** @type {number} */ end, /** @type {KeyframesState} */ state) {
  const keys = new Float64Array(state.keys.flat());
  const options = state.times.length ? { times: state.times } : {};
  const timed = (/** @type {() => any} */ f) => {
    const begin = performance.now();
    const value = f();
    return { value, ms: performance.now() - begin };
  };
  const times = Float64Array.from({ length: 1e4 }, (_, k) => start + ((end - start) * k) / (1e4 - 1));
  const builders = [
    () => kliSpline(keys, { ...options, smoothness: state.smoothness }),
    () => squadSpline(keys, options),
    () => slerpSpline(keys, options),
  ];
  const tableRows = $("#figures tbody", HTMLTableSectionElement).rows;
  const row = (/** @type {number} */ i) => {
    const curve = timed(builders[i]);
    const evaluation = timed(() => curve.value.sample(times));
    curve.value.free();
    tableRows[i].cells[5].textContent = curve.ms.toFixed(2);
    tableRows[i].cells[6].textContent = evaluation.ms.toFixed(2);
    if (i + 1 < builders.length) timing = setTimeout(() => row(i + 1));
  };
  row(0);
}

page.start();
