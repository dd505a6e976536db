// @ts-check
// The averaging page: a descriptor for the page runtime (runtime.js), dragging a measurement on
// the sphere, the means' table and the outlier sweep, its points computed by the page's worker
// (runtime/offload.js). The measurements, the means, the flow and all drawing are the module's
// (crates/kli-demo/src/average/).
import * as average from "../pkg/average_demo.js";
import { AverageDemo } from "../pkg/average_demo.js";
import { $ } from "../runtime/dom.js";
import { timeTag } from "../runtime/exports.js";
import { grabPoint } from "../runtime/input.js";
import { Offload } from "../runtime/offload.js";
import { page as registered } from "../pages.js";
import { Page } from "../runtime/runtime.js";
import { Sweep } from "../runtime/sweep.js";

/** @typedef {{ count: number, noise: number, outliers: number, seed: number, moved: number[][] }} AverageState */

/** The shares the sweep visits. */
const SHARES = Array.from({ length: 11 }, (_, i) => i / 20);
const degrees = (/** @type {number} */ radians) => (radians * 180) / Math.PI;
/** The sweep: each mean's error (radians) at each share, the share on show marked. */
const sweep = new Sweep({
  table: "#sweep-table tbody",
  status: "#sweep-status",
  redraw: () => page.host.redraw(["sweep"]),
  cells: (share, errors) => [String(share), ...errors.map((e) => (Number.isFinite(e) ? degrees(e).toFixed(2) : "—"))],
  done: (count) => `Done: ${count} shares, 15 sets each.`,
});
/** The views' names in file names. */
const FILE_NAMES = /** @type {Record<string, string>} */ ({ hopf: "hopf", objects: "objects", means: "means", sweep: "outlier-sweep" });

/** @type {Page<AverageState, AverageDemo>} */
const page = new Page({
  entry: registered("average"),
  module: average,
  own: {
    sweep: {
      draw: (ctx, frame) => AverageDemo.drawSweep(ctx, frame, ...sweep.drawn),
      svg: (frame) => AverageDemo.sweepSvg(frame, ...sweep.drawn),
    },
  },
  form: "#average-inputs",
  readout: (run, t) => {
    const chordal = run.summary.means[0];
    return `t = ${t.toFixed(2)} / ${run.span[1].toFixed(2)}   the chordal mean: ${chordal.errorDegrees.toFixed(2)}° from the truth`;
  },
  note: (run) => {
    const { count, wild, marked, means } = run.summary;
    const median = means[3];
    return `${count} measurements, ${wild} wild; the median weighs ${marked} of them least and lies ${median.errorDegrees.toFixed(2)}° from the truth.`;
  },
  data: { file: (run) => `kli-average-${run.summary.count}-measurements` },
  file: (run, view, t) => `kli-average-${FILE_NAMES[view]}-${run.summary.count}${view === "hopf" || view === "objects" ? `-${timeTag(t)}` : ""}`,
  video: {
    views: ["hopf", "objects"],
    title: (run) => `The follower settles on the mean of ${run.summary.count} measured rotations`,
    file: (run) => `kli-average-${run.summary.count}-measurements`,
  },
  shown: (host, run, state) => {
    sweep.current = state.outliers;
    showValues(host);
    fillMeans(run);
    $("#unmove", HTMLButtonElement).disabled = state.moved.length === 0;
    host.redraw(["sweep"]);
  },
  input: (host) => {
    showValues(host);
    return false;
  },
  wire: (host) => {
    $("#reseed", HTMLButtonElement).addEventListener("click", () => {
      host.apply({ ...host.state, seed: (host.state.seed + 1) % 1e9, moved: [] });
    });
    $("#unmove", HTMLButtonElement).addEventListener("click", () => host.apply({ ...host.state, moved: [] }));
    $("#sweep", HTMLButtonElement).addEventListener("click", () => runSweep(host));
  },
  grab: grabMeasurement,
});

/** @typedef {import("../runtime/runtime.js").Host<AverageState, AverageDemo>} Host */

/** The sliders' values beside them. */
function showValues(/** @type {Host} */ host) {
  for (const name of ["count", "noise", "outliers"]) $(`#${name}-value`, HTMLOutputElement).textContent = host.field(name).value;
}

/** The means' table: each mean's angle to the truth, its dispersion and its iterations. */
function fillMeans(/** @type {AverageDemo} */ run) {
  const body = $("#means tbody", HTMLTableSectionElement);
  body.replaceChildren();
  for (const mean of run.summary.means) {
    const row = body.insertRow();
    for (const text of [mean.name, mean.errorDegrees.toFixed(2), mean.dispersionDegrees.toFixed(2), String(mean.iterations)]) {
      row.insertCell().textContent = text;
    }
  }
}

/**
 * A measurement's dot under the pointer (the nearest in front within 12 px) is grabbed: moving
 * the pointer then turns it so that its Hopf point follows (once a frame), and it counts as wild.
 * @param {Host} host
 * @param {number} x
 * @param {number} y
 */
function grabMeasurement(host, x, y) {
  const run = host.run;
  const frame = host.frame("hopf");
  if (!run || !frame) return null;
  return grabPoint(run.measurementPoints(frame), x, y, (index, x, y) => {
    const run = host.run;
    const frame = host.frame("hopf");
    if (!run || !frame) return;
    const entry = run.movedTo(index, frame, x, y);
    if (!entry.length) return;
    const moved = host.state.moved.filter((m) => m[0] !== index);
    host.apply({ ...host.state, moved: [...moved, Array.from(entry, (c) => Number(c.toPrecision(8)))] });
  });
}

/** The sweep's points are computed in a worker: started now, so it loads the module while the
 *  page does. */
const offload = new Offload(average, new URL("../pkg/average_demo.js", import.meta.url));

/** The sweep over the current measurements' recipe. */
function runSweep(/** @type {Host} */ host) {
  const { count, noise, seed } = host.state;
  offload.drop("sweepPoint");
  sweep.run(SHARES, (share) => offload.call("AverageDemo", "sweepPoint", [{ count, noise, seed }, share]));
}

// The sweep fills itself once the page is interactive (a point a task, as the button runs it):
// no empty figure on screen or on paper.
page.start().then((ready) => ready && setTimeout(() => runSweep(page.host)));
