// @ts-check
// The synchronisation page: a descriptor for the page runtime (runtime.js), the sweep over the
// share of wrong edges, and a user's own pose graph (opened or dropped). The problem, the
// solutions, the flow and all drawing are the module's (crates/kli-demo/src/sync/); each run is
// built unsolved and its solutions, like the sweep's points, come from the page's worker
// (runtime/offload.js).
import * as sync from "../pkg/sync_demo.js";
import { SyncDemo, SyncFile } from "../pkg/sync_demo.js";
import { $ } from "../runtime/dom.js";
import { timeTag } from "../runtime/exports.js";
import { page as registered } from "../pages.js";
import { Page } from "../runtime/runtime.js";
import { Sweep } from "../runtime/sweep.js";
import { Offload } from "../runtime/offload.js";

/** @typedef {import("./state.js").SyncState} SyncState */

/** How far the Step button moves the flow on (its time). */
const STEP = 0.5;
/** The shares of wrong edges the sweep visits. */
const SHARES = Array.from({ length: 11 }, (_, i) => i / 25);
const degrees = (/** @type {number} */ radians) => (radians * 180) / Math.PI;
/** The sweep: each solution's median error (radians) at each share, the share on show marked. */
const sweep = new Sweep({
  table: "#sweep-table tbody",
  status: "#sweep-status",
  redraw: () => page.host.redraw(["sweep"]),
  cells: (share, errors) => [String(share), ...errors.map((e) => degrees(e).toFixed(2))],
  done: (count) => `Done: ${count} shares.`,
});
/** The worker that solves each run and the sweep's points: started now, so it loads the module
 *  while the page does. */
const offload = new Offload(sync, new URL("../pkg/sync_demo.js", import.meta.url));
/** The user's own pose graph, once one is read. */
const own = { file: /** @type {SyncFile | null} */ (null), name: "" };
/** The views' names in file names. */
const FILE_NAMES = /** @type {Record<string, string>} */ ({
  graph: "graph", hopf: "hopf", objects: "objects", plots: "plots", results: "residuals", sweep: "wrong-edge-sweep",
  file: "your-graph-residuals",
});

/** @type {Page<SyncState, SyncDemo>} */
const page = new Page({
  entry: registered("sync"),
  module: sync,
  create: (module, state) => module.SyncDemo.unsolved(state),
  own: {
    sweep: {
      draw: (ctx, frame) => SyncDemo.drawSweep(ctx, frame, ...sweep.drawn),
      svg: (frame) => SyncDemo.sweepSvg(frame, ...sweep.drawn),
    },
    file: {
      draw: (ctx, frame) => own.file?.draw(ctx, frame),
      svg: (frame) => {
        if (!own.file) throw new Error("open a pose graph first");
        return own.file.toSvg(frame);
      },
    },
  },
  form: "#sync-inputs",
  readout: (run, t) => {
    const s = run.summary;
    return `t = ${t.toFixed(2)}   f = ${s.cost.toExponential(3)}   median error ${s.errorDegrees.toFixed(2)}°` +
      (s.arrived ? "   at the chordal optimum" : "");
  },
  note: (run) => {
    const s = run.summary;
    if (!s.solved) return `${s.count} nodes, ${s.edges} edges, ${s.wrong} wrong. Solving…`;
    const proof = s.certified
      ? `certified the global optimum (λmin(S) = ${s.lambdaMin.toExponential(1)})`
      : `not proved optimal: λmin(S) = ${s.lambdaMin.toExponential(1)} < 0, the relaxation is not tight here`;
    const robust = s.wrong > 0
      ? `flags ${s.flaggedWrong} of the ${s.wrong} wrong edges and ${s.flagged - s.flaggedWrong} good ones`
      : `flags ${s.flagged} edges`;
    return `${s.count} nodes, ${s.edges} edges, ${s.wrong} wrong. Chordal: ${s.chordalErrorDegrees.toFixed(2)}° median error, ${proof}. ` +
      `Robust: ${s.robustErrorDegrees.toFixed(2)}°, ${robust}.`;
  },
  data: { file: (run, t) => `kli-sync-${run.summary.count}-nodes-${timeTag(t)}` },
  file: (run, view, t) => `kli-sync-${FILE_NAMES[view]}-${run.summary.count}${["sweep", "results", "file"].includes(view) ? "" : `-${timeTag(t)}`}`,
  video: {
    views: ["graph", "hopf"],
    title: (run) => `${run.summary.count} rotations synchronising on a graph: the Lohe flow`,
    file: (run) => `kli-sync-${run.summary.count}-nodes`,
  },
  // Until its solutions come, the first run's results view keeps its first picture (the same
  // solutions, drawn by make www) rather than showing "Solving…".
  waiting: (run, view) => view === "results" && !run.summary.solved,
  shown: (host, run, state) => {
    sweep.current = state.wrong;
    showValues(host);
    host.redraw(["sweep"]);
    offload.call("SyncDemo", "solve", [state], "solve").then((solutions) => {
      if (!solutions || host.run !== run) return;
      run.takeSolutions(solutions);
      host.changed();
    }, (error) => host.showError(error));
  },
  input: (host) => {
    showValues(host);
    return false;
  },
  wire: (host) => {
    $("#step", HTMLButtonElement).addEventListener("click", () => host.seek(host.t + STEP));
    $("#reseed", HTMLButtonElement).addEventListener("click", () => host.apply({ ...host.state, seed: (host.state.seed + 1) % 1e9 }));
    $("#sweep", HTMLButtonElement).addEventListener("click", () => runSweep(host));
    wireFile(host);
  },
});

/** @typedef {import("../runtime/runtime.js").Host<SyncState, SyncDemo>} Host */

/** The sliders' values beside them; noise and wrong edges mean nothing for consensus. */
function showValues(/** @type {Host} */ host) {
  for (const name of ["count", "noise", "wrong"]) $(`#${name}-value`, HTMLOutputElement).textContent = host.field(name).value;
  const consensus = /** @type {HTMLInputElement} */ (host.field("consensus")).checked;
  host.field("noise").disabled = consensus;
  host.field("wrong").disabled = consensus;
}

/** The sweep's methods, in the order its figure draws them: a task each. */
const METHODS = ["spectral", "chordal", "robust"];

/** The sweep over the current recipe (at most 60 nodes). */
function runSweep(/** @type {Host} */ host) {
  const { count, graph, noise, seed } = host.state;
  offload.drop("sweepError");
  sweep.run(SHARES, (share, k) => offload.call("SyncDemo", "sweepError", [{ count, graph, noise, seed }, share, METHODS[k]]).then((error) => [error]), METHODS.length);
}

/** Opening or dropping a pose graph: synchronised in the page's worker (a large graph takes
 *  seconds), then read on the page with its solutions. A file opened while one is being
 *  synchronised supersedes it. */
function wireFile(/** @type {Host} */ host) {
  const input = $("#file-input", HTMLInputElement);
  const zone = $("#file-section", HTMLElement);
  const status = $("#file-status", HTMLOutputElement);
  let opened = 0;
  const open = async (/** @type {File | undefined} */ file) => {
    if (!file) return;
    const mine = ++opened;
    status.textContent = `Reading ${file.name}…`;
    const text = await file.text();
    if (mine !== opened) return;
    status.textContent = `Synchronising ${file.name}…`;
    let read = null;
    try {
      const solutions = await offload.call("SyncFile", "solve", [text], "file");
      if (!solutions || mine !== opened) return;
      read = SyncFile.solved(text, solutions);
    } catch (error) {
      if (mine === opened) status.textContent = `${file.name}: ${error instanceof Error ? error.message : String(error)}`;
      return;
    }
    own.file?.free();
    own.file = read;
    own.name = file.name;
    showFile(host);
  };
  input.addEventListener("change", () => open(input.files?.[0]));
  zone.addEventListener("dragover", (event) => {
    event.preventDefault();
    zone.classList.add("dropping");
  });
  zone.addEventListener("dragleave", () => zone.classList.remove("dropping"));
  zone.addEventListener("drop", (event) => {
    event.preventDefault();
    zone.classList.remove("dropping");
    open(event.dataTransfer?.files[0]);
  });
}

/** The user's graph: its figures' numbers and its residuals, shown. */
function showFile(/** @type {Host} */ host) {
  if (!own.file) return;
  const s = own.file.summary;
  const rows = [
    ["Nodes", String(s.count)],
    ["Edges", String(s.edges)],
    ["Chordal cost f", s.chordalCost.toPrecision(8)],
    ["Certificate", s.certified ? `certified (λmin(S) = ${s.lambdaMin.toExponential(1)})` : `not proved optimal (λmin(S) = ${s.lambdaMin.toExponential(1)})`],
    ["Median residual, chordal", `${s.chordalMedianResidualDegrees.toFixed(3)}°`],
    ["Median residual, robust", `${s.robustMedianResidualDegrees.toFixed(3)}°`],
    ["Edges the robust solution flags", String(s.flagged)],
  ];
  const body = $("#file-table tbody", HTMLTableSectionElement);
  body.replaceChildren();
  for (const [name, value] of rows) {
    const row = body.insertRow();
    const head = document.createElement("th");
    head.scope = "row";
    head.textContent = name;
    row.append(head);
    row.insertCell().textContent = value;
  }
  const skipped = s.skipped ? ` (${s.skipped} other ${s.skipped === 1 ? "line" : "lines"} skipped: landmarks, priors)` : "";
  $("#file-status", HTMLOutputElement).textContent = `${own.name}: ${s.count} nodes, ${s.edges} edges${skipped}, ${s.certified ? "certified" : "not proved optimal"}.`;
  $("#file-figure", HTMLElement).hidden = false;
  host.redraw(["file"]);
}

// The sweep fills itself once the page is interactive (a point a task, as the button runs it):
// no empty figure on screen or on paper.
page.start().then((ready) => ready && setTimeout(() => runSweep(page.host)));
