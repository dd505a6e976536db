// @ts-check
// The swarm page: a descriptor for the page runtime (runtime.js), and the K sweep, its points
// computed by the page's worker (runtime/offload.js). The model, its checks and all drawing are
// the module's (crates/kli-demo/src/swarm/).
import * as swarm from "../pkg/swarm_demo.js";
import { SwarmDemo } from "../pkg/swarm_demo.js";
import { $ } from "../runtime/dom.js";
import { timeTag } from "../runtime/exports.js";
import { page as registered } from "../pages.js";
import { Page } from "../runtime/runtime.js";
import { Offload } from "../runtime/offload.js";
import { Sweep } from "../runtime/sweep.js";

/** @typedef {import("./state.js").SwarmState} SwarmState */

/** How far the Step button moves the swarm on (model time). */
const STEP = 0.2;
const SWEEP = Array.from({ length: 19 }, (_, i) => -1 + i / 2);
/** The sweep: the final R at each coupling, the coupling on show marked. */
const sweep = new Sweep({
  table: "#sweep-table tbody",
  status: "#sweep-status",
  redraw: () => page.host.redraw(["sweep"]),
  cells: (coupling, [order]) => [String(Number(coupling.toFixed(4))), order.toFixed(3)],
  done: (count) => `Done: R at t = 30 for ${count} couplings.`,
});
/** The views' names in file names. */
const FILE_NAMES = /** @type {Record<string, string>} */ ({ hopf: "hopf", objects: "objects", plots: "order-plots", sweep: "coupling-sweep" });

/** @type {Page<SwarmState, SwarmDemo>} */
const page = new Page({
  entry: registered("swarm"),
  module: swarm,
  own: {
    sweep: {
      draw: (ctx, frame) => SwarmDemo.drawSweep(ctx, frame, ...sweep.drawn),
      svg: (frame) => SwarmDemo.sweepSvg(frame, ...sweep.drawn),
    },
  },
  form: "#swarm-inputs",
  readout: (run, t) => {
    const s = run.summary;
    return `t = ${t.toFixed(2)}   R = ${s.orderParameter.toFixed(3)}   λmax = ${s.rotationOrder.toFixed(3)}` +
      (s.kli ? `   τ = Kt/2 = ${s.kliTime.toFixed(2)}` : "");
  },
  note: (run) => (run.summary.kli
    ? "One pinned leader and one follower: the follower obeys q′ = (K/2)(r − (q·r) q), the KLI flow at the clock τ = Kt/2."
    : ""),
  data: { file: (run, t) => `kli-swarm-${run.summary.count}-oscillators-${timeTag(t)}` },
  file: (_, view, t) => `kli-swarm-${FILE_NAMES[view]}${view === "sweep" ? "" : `-${timeTag(t)}`}`,
  video: {
    views: ["hopf", "objects"],
    title: (run) => `A Lohe swarm of ${run.summary.count} oscillators on S³, through the Hopf map`,
    file: (run) => `kli-swarm-${run.summary.count}-oscillators`,
  },
  shown: (host, _, state) => {
    sweep.current = state.coupling;
    showValues(host);
    host.redraw(["sweep"]); // its marker follows K; otherwise it changes only while a sweep runs
  },
  input: (host, name) => {
    showValues(host);
    if (name === "uniform") host.rebuild(host.read());
    return name === "uniform";
  },
  wire: (host) => {
    $("#step", HTMLButtonElement).addEventListener("click", () => host.seek(host.t + STEP));
    $("#reseed", HTMLButtonElement).addEventListener("click", () => {
      host.field("seed").value = String((host.state.seed + 1) % 1e9);
      host.rebuild(host.read());
    });
    $("#sweep", HTMLButtonElement).addEventListener("click", () => runSweep(host));
  },
});

/** @typedef {import("../runtime/runtime.js").Host<SwarmState, SwarmDemo>} Host */

/** The sliders' values beside them. */
function showValues(/** @type {Host} */ host) {
  for (const name of ["coupling", "count", "frequencySpread", "startSpread"]) {
    $(`#${name}-value`, HTMLOutputElement).textContent = host.field(name).value;
  }
  host.field("startSpread").disabled = /** @type {HTMLInputElement} */ (host.field("uniform")).checked;
}

/** The sweep's points are computed in a worker: started now, so it loads the module while the
 *  page does. */
const offload = new Offload(swarm, new URL("../pkg/swarm_demo.js", import.meta.url));

/** The sweep over the current swarm (at most 200 oscillators). */
function runSweep(/** @type {Host} */ host) {
  const options = { ...host.state, count: Math.min(host.state.count, 200) };
  offload.drop("sweepOrder");
  sweep.run(SWEEP, (coupling) => offload.call("SwarmDemo", "sweepOrder", [options, coupling, 30]).then((order) => [order]));
}

// The sweep fills itself once the page is interactive (a point a task, as the button runs it):
// no empty figure on screen or on paper.
page.start().then((ready) => ready && setTimeout(() => runSweep(page.host)));
