// @ts-check
// The synchronisation page: a descriptor for the page runtime (runtime.js), the sweep over the
// share of wrong edges, and a pose graph's map: the built-in one, or a user's own (opened or
// dropped). The problem, the solutions, the flow and all drawing are the module's
// (crates/kli-demo/src/sync/); each run is built unsolved and its solutions, like the sweep's
// points and a pose graph's optimum, come from the page's worker (runtime/offload.js).
import * as sync from "../pkg/sync_demo.js";
import { SyncDemo, SyncFile, SyncMap } from "../pkg/sync_demo.js";
import { $, whenNear } from "../runtime/dom.js";
import { download, timeTag } from "../runtime/exports.js";
import { wireDragging } from "../runtime/input.js";
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
/** The user's own pose graph's rotations alone, once one is read. */
const own = { file: /** @type {SyncFile | null} */ (null), name: "" };
/** The pose graph on the map: the built-in one until a file is opened; its text, its name, the
 *  seconds its solve took (in the worker, reading included), and when it was last turned. */
const shown = { map: /** @type {SyncMap | null} */ (null), text: "", name: "", file: false, seconds: "", turned: -Infinity };
/** The views' names in file names. */
const FILE_NAMES = /** @type {Record<string, string>} */ ({
  graph: "graph", hopf: "hopf", objects: "objects", plots: "plots", results: "residuals", sweep: "wrong-edge-sweep",
  file: "your-graph-residuals",
});
/** The map's files' names begin with its graph's: the file's without its extension, or the
 *  built-in one's. */
const mapName = () => (shown.file ? shown.name.replace(/\.[^.]*$/, "") : "kli-built-in-pose-graph");
/** What the map's place says until the built-in graph's answer comes from the worker. */
const SOLVING = "Solving the built-in robot's loop…";
/** A 3D map's turn a key press, radians. */
const TURN = (5 * Math.PI) / 180;
/** For this long (ms) after a turn the map is being turned, and is drawn whole. */
const TURNING = 500;

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
    map: {
      draw: (ctx, frame) => (shown.map ? drawMap(shown.map, ctx, frame) : SyncMap.drawWaiting(ctx, frame, SOLVING)),
      // Printed (or saved) before the worker answers: the words the canvas shows, not an Error.
      svg: (frame) => (shown.map ? shown.map.toSvg(frame) : SyncMap.waitingSvg(frame, SOLVING)),
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
  file: (run, view, t) => view === "map" ? `${mapName()}-map` :
    `kli-sync-${FILE_NAMES[view]}-${run.summary.count}${["sweep", "results", "file"].includes(view) ? "" : `-${timeTag(t)}`}`,
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
    wireMap(host);
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

/** The error's words. */
const words = (/** @type {unknown} */ error) => (error instanceof Error ? error.message : String(error));

/** A number for the tables, or a dash where there is none (a graph of one pose has no edge). */
const figure = (/** @type {number} */ x, /** @type {(x: number) => string} */ format) => (Number.isFinite(x) ? format(x) : "—");

/** The section's status line. */
const status = () => $("#file-status", HTMLOutputElement);

/** Which map solve is the latest: an older one that answers late is not shown. */
let solving = 0;

/** Solves pose graph `text` in the page's worker, its stages shown in the status as they begin
 *  (the page stays free meanwhile: 10,000 poses take seconds), then shows its map. True once
 *  shown; false when a newer graph superseded it, or it was refused (the status says why, with
 *  the line at fault). */
async function solveMap(/** @type {Host} */ host, /** @type {string} */ text, /** @type {string} */ name, /** @type {boolean} */ file) {
  const mine = ++solving;
  const start = performance.now();
  const seconds = () => ((performance.now() - start) / 1000).toFixed(1);
  status().textContent = `${name}: solving…`;
  /** @type {SyncMap} */
  let map;
  try {
    const answer = await offload.call("SyncMap", "solve", [text], "map", (stage) => {
      if (mine === solving) status().textContent = `${name}: ${stage}… (${seconds()} s)`;
    });
    if (!answer || mine !== solving) return false;
    map = SyncMap.solved(answer);
    if (!file) map.withTruth();
  } catch (error) {
    if (mine === solving) status().textContent = `${name}: ${words(error)}`;
    return false;
  }
  shown.map?.free();
  Object.assign(shown, { map, text, name, file, seconds: seconds() });
  showMap(host);
  return true;
}

/** Draws `map`'s first part, and returns the drawing of the next: a map of 10⁴ poses drawn
 *  whole kept the main thread 110 ms (the module's calls, then Chromium rasterising them), so a
 *  large one is drawn a part a task. The rest stops when another map is shown. A map being
 *  turned is drawn whole: in parts each move would show it half drawn. */
function drawMap(/** @type {SyncMap} */ map, /** @type {CanvasRenderingContext2D} */ ctx, /** @type {import("../runtime/figures.js").Frame} */ frame) {
  if (performance.now() - shown.turned < TURNING) return map.draw(ctx, frame);
  const parts = map.drawPart(ctx, frame, 0);
  let part = 1;
  /** @type {import("../runtime/figures.js").Part} */
  const next = () => {
    if (shown.map !== map || part >= parts) return;
    map.drawPart(ctx, frame, part++);
    return next;
  };
  return parts > 1 ? next : undefined;
}

/** The map on show: its table, its status, and a 3D map made turnable. */
function showMap(/** @type {Host} */ host) {
  if (!shown.map) return;
  const s = shown.map.summary;
  const exp = (/** @type {number} */ x) => x.toExponential(4);
  const certificate = s.certified
    ? `certified: λmin(S) = ${figure(s.lambdaMin, (x) => x.toExponential(1))} ≥ −${figure(s.tolerance, (x) => x.toExponential(1))}`
    : `not certified: λmin(S) = ${figure(s.lambdaMin, (x) => x.toExponential(1))} < −${figure(s.tolerance, (x) => x.toExponential(1))}`;
  fillTable("#map-table tbody", [
    ["Poses", `${s.poses} (${s.dimension}D)`],
    ["Edges", `${s.edges}, of which ${s.closures} ${s.closures === 1 ? "joins" : "join"} poses that are not consecutive (loop closures)`],
    ["Initial estimate", s.fromFile ? "the file's own (its VERTEX lines)" : "the odometry chained from pose 0"],
    ["Cost f: initial, optimum", `${figure(s.initialCost, exp)}, ${figure(s.cost, exp)}`],
    ["Certificate", certificate],
    ["Proven lower bound on the least cost", s.certified
      ? figure(s.lowerBound, exp)
      : `${figure(s.lowerBound, exp)}: this map is within ${figure(s.cost - s.lowerBound, exp)} of the best there is`],
    ["Rank of the staircase", String(s.rank)],
    ["Solver steps", String(s.iterations)],
    ["Median edge misfit", figure(s.medianMisfit, (x) => `${x.toFixed(2)} σ`)],
    ...(Number.isFinite(s.truthErrorOptimum)
      ? [["Distance from the true path (RMS): initial, optimum", `${s.truthErrorInitial.toFixed(2)} m, ${s.truthErrorOptimum.toFixed(2)} m`]]
      : []),
    ["Solved in", `${shown.seconds} s, in the page's worker (reading included)`],
  ]);
  const skipped = s.skipped ? ` (${s.skipped} other ${s.skipped === 1 ? "line" : "lines"} skipped: landmarks, priors)` : "";
  status().textContent = `${shown.name}: ${s.poses} poses, ${s.edges} edges${skipped}; ` +
    `${s.certified ? "the certified optimum" : "an optimum, not certified"}, solved in ${shown.seconds} s.`;
  const canvas = $("#sync-map", HTMLCanvasElement);
  const turnable = s.dimension === 3;
  canvas.classList.toggle("turnable", turnable);
  $("#map-views", HTMLElement).hidden = !turnable;
  canvas.style.touchAction = turnable ? "none" : "";
  if (turnable) {
    canvas.tabIndex = 0;
    canvas.setAttribute("role", "application");
    canvas.setAttribute("aria-roledescription", "turnable map");
    canvas.setAttribute("aria-label", "The pose graph's map in 3D: the initial estimate beside the optimum, each edge coloured by its misfit. Arrow keys turn it; dragging turns it too.");
  } else {
    canvas.removeAttribute("tabindex");
    canvas.setAttribute("role", "img");
    canvas.removeAttribute("aria-roledescription");
    canvas.setAttribute("aria-label", "The pose graph's map seen from above: the initial estimate beside the optimum, each edge coloured by its misfit");
  }
  host.redraw(["map"]);
}

/** Rows of `[heading, value]` into a table's body. */
function fillTable(/** @type {string} */ selector, /** @type {string[][]} */ rows) {
  const body = $(selector, HTMLTableSectionElement);
  body.replaceChildren();
  for (const [name, value] of rows) {
    const row = body.insertRow();
    const head = document.createElement("th");
    head.scope = "row";
    head.textContent = name;
    row.append(head);
    row.insertCell().textContent = value;
  }
}

/** The built-in pose graph as its form says, solved and shown (a refused value said in the
 *  status, by the module's words). */
function showWorld(/** @type {Host} */ host) {
  const form = $("#world-inputs", HTMLFormElement);
  const value = (/** @type {string} */ name) => Number(/** @type {HTMLInputElement} */ (form.elements.namedItem(name)).value);
  for (const name of ["noise", "closures"]) $(`#world-${name}-value`, HTMLOutputElement).textContent = String(value(name));
  own.file?.free();
  own.file = null;
  $("#file-figure", HTMLElement).hidden = true;
  let text;
  try {
    text = SyncMap.example({ noise: value("noise"), closures: value("closures"), seed: value("seed") });
  } catch (error) {
    status().textContent = `The built-in pose graph: ${words(error)}`;
    return;
  }
  solveMap(host, text, "The built-in robot's loop", false);
}

/** The map's own parts: the built-in graph's form, turning a 3D map, saving the optimum. */
function wireMap(/** @type {Host} */ host) {
  const form = $("#world-inputs", HTMLFormElement);
  form.addEventListener("submit", (event) => event.preventDefault());
  form.addEventListener("input", () => showWorld(host));
  $("#world-show", HTMLButtonElement).addEventListener("click", () => showWorld(host));
  const canvas = $("#sync-map", HTMLCanvasElement);
  const turn = (/** @type {number} */ azimuth, /** @type {number} */ elevation) => {
    if (!shown.map || shown.map.summary.dimension !== 3) return;
    shown.map.turn(azimuth, elevation);
    shown.turned = performance.now();
    host.redraw(["map"]);
  };
  wireDragging(canvas, turn);
  canvas.style.touchAction = "";
  canvas.addEventListener("keydown", (event) => {
    /** @type {Record<string, [number, number]>} */
    const keys = { ArrowLeft: [TURN, 0], ArrowRight: [-TURN, 0], ArrowUp: [0, TURN], ArrowDown: [0, -TURN] };
    const by = keys[event.key];
    if (!by || !shown.map || shown.map.summary.dimension !== 3) return;
    event.preventDefault();
    event.stopPropagation();
    turn(...by);
  });
  // From above with x to the right and y up; the oblique view the map opens with (map.rs).
  const look = (/** @type {number} */ azimuth, /** @type {number} */ elevation) => {
    shown.map?.look(azimuth, elevation);
    host.redraw(["map"]);
  };
  $("#map-above", HTMLButtonElement).addEventListener("click", () => look(-Math.PI / 2, Math.PI / 2));
  $("#map-oblique", HTMLButtonElement).addEventListener("click", () => look((-60 * Math.PI) / 180, (35 * Math.PI) / 180));
  $("#save-g2o", HTMLButtonElement).addEventListener("click", () => {
    if (!shown.map) return;
    try {
      download(`${mapName()}-optimum.g2o`, "text/plain", sync.writeG2o(sync.readG2o(shown.text), shown.map.poses));
    } catch (error) {
      status().textContent = `Could not save: ${words(error)}`;
    }
  });
  $("#save-poses-csv", HTMLButtonElement).addEventListener("click", () => {
    if (shown.map) download(`${mapName()}-optimum.csv`, "text/csv", shown.map.csv());
  });
}

/** Opening or dropping a pose graph: its map solved in the page's worker (a large graph takes
 *  seconds), then its rotations alone synchronised both ways, as the page above does. A file
 *  opened while one is being solved supersedes it. */
function wireFile(/** @type {Host} */ host) {
  const input = $("#file-input", HTMLInputElement);
  const zone = $("#file-section", HTMLElement);
  let opened = 0;
  const open = async (/** @type {File | undefined} */ file) => {
    if (!file) return;
    const mine = ++opened;
    status().textContent = `${file.name}: reading…`;
    const text = await file.text();
    if (mine !== opened || !(await solveMap(host, text, file.name, true)) || mine !== opened) return;
    status().textContent += " Its rotations alone: synchronising both ways…";
    let read = null;
    try {
      const solutions = await offload.call("SyncFile", "solve", [text], "file");
      if (!solutions || mine !== opened) return;
      read = SyncFile.solved(solutions);
    } catch (error) {
      if (mine === opened) status().textContent = `${file.name}: ${words(error)}`;
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

/** The user's graph's rotations alone: their figures' numbers and residuals, shown, and the
 *  status saying both the map's and their verdict. */
function showFile(/** @type {Host} */ host) {
  if (!own.file) return;
  const s = own.file.summary;
  const lambda = figure(s.lambdaMin, (x) => x.toExponential(1));
  fillTable("#file-table tbody", [
    ["Nodes", String(s.count)],
    ["Edges", String(s.edges)],
    ["Chordal cost f", figure(s.chordalCost, (x) => x.toPrecision(8))],
    ["Certificate", s.certified ? `certified (λmin(S) = ${lambda})` : `not proved optimal (λmin(S) = ${lambda})`],
    ["Median residual, chordal", figure(s.chordalMedianResidualDegrees, (x) => `${x.toFixed(3)}°`)],
    ["Median residual, robust", figure(s.robustMedianResidualDegrees, (x) => `${x.toFixed(3)}°`)],
    ["Edges the robust solution flags", String(s.flagged)],
  ]);
  const map = shown.map?.summary;
  const skipped = s.skipped ? ` (${s.skipped} other ${s.skipped === 1 ? "line" : "lines"} skipped: landmarks, priors)` : "";
  const poses = map ? `the map ${map.certified ? "certified" : "not certified"} (solved in ${shown.seconds} s); ` : "";
  status().textContent = `${own.name}: ${s.count} poses, ${s.edges} edges${skipped}; ${poses}` +
    `its rotations alone ${s.certified ? "certified" : "not proved optimal"}.`;
  $("#file-figure", HTMLElement).hidden = false;
  host.redraw(["file"]);
}

// Once the page is interactive, the sweep (a point a task, as the button runs it); the built-in
// pose graph's map as its section nears the screen, the page is printed, or 10 s have passed
// (made, read and drawn at load it was the longest work of the page's start, for a section below
// the fold; started later anyway, a page printed then holds the map, not "Solving…").
page.start().then((ready) => {
  if (!ready) return;
  setTimeout(() => runSweep(page.host));
  // Unless a file was opened first: its map is the one to keep.
  whenNear($("#file-section", HTMLElement), () => solving === 0 && showWorld(page.host), { after: 10000 });
});
