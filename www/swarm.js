// @ts-check
// The swarm page, wiring only: the form and the URL to the module's SwarmDemo, the animation,
// the canvases and the sweep. The model, its checks and all drawing are the module's
// (crates/kli-demo/src/swarm_demo.rs).
import init, { SwarmDemo, defaultCamera } from "./pkg/swarm_demo.js";
import { Camera } from "./camera.js";
import { loadModule } from "./canvases.js";
import { Figures } from "./figures.js";
import { page } from "./pages.js";
import { $ } from "./dom.js";
import { presetName } from "./presets.js";
import { argumentOf, buildAll, clearErrors, messageOf, showFieldError } from "./runs.js";
import { saveAs, timeTag, wireSaving } from "./exports.js";
import { wireDragging, wireKeyboard } from "./input.js";
import { parseNumber } from "./numbers.js";
import { SWARM_URL_KEYS as KEYS, throttledUrl } from "./url.js";

/** @typedef {import("./pkg/swarm_demo.js").SwarmOptions} SwarmOptions */
/** @typedef {Required<Omit<SwarmOptions, "startSpread" | "order">> & { startSpread?: number }} SwarmState */

/** @type {Record<string, SwarmState>} */
const PRESETS = {
  synchronise: { coupling: 1, count: 500, graph: "all", leaders: 1, frequencySpread: 0, seed: 1 },
  balance: { coupling: -1, count: 500, graph: "all", leaders: 1, frequencySpread: 0, seed: 1 },
  frequencies: { coupling: 2, count: 500, graph: "all", leaders: 1, frequencySpread: 1, seed: 1 },
  kli: { coupling: 2, count: 2, graph: "leader", leaders: 1, frequencySpread: 0, startSpread: 1.5, seed: 3 },
};
const DT = 0.02;
const STEPS_PER_FRAME = 2;
const SWEEP = Array.from({ length: 19 }, (_, i) => -1 + i / 2);

const form = $("#swarm-inputs", HTMLFormElement);
const field = (/** @type {string} */ name) => {
  const element = form.elements.namedItem(name);
  if (!(element instanceof HTMLInputElement || element instanceof HTMLSelectElement)) throw new Error(`no field ${name}`);
  return element;
};
/** The sweep's points so far, drawn by the module. */
const sweepPoints = () => /** @type {const} */ ([new Float64Array(run.sweep.couplings), new Float64Array(run.sweep.orders), run.state.coupling]);
const figures = new Figures({
  hopf: $("#swarm-hopf", HTMLCanvasElement),
  objects: $("#swarm-objects", HTMLCanvasElement),
  plots: $("#swarm-plots", HTMLCanvasElement),
  sweep: $("#swarm-sweep", HTMLCanvasElement),
}, { ...page("swarm"), painters: { sweep: (ctx, frame) => SwarmDemo.drawSweep(ctx, frame, ...sweepPoints()) } });
const canvases = figures.canvases;
const ui = {
  play: $("#play", HTMLButtonElement),
  readout: $("#readout", HTMLOutputElement),
  status: $("#status", HTMLElement),
  note: $("#note", HTMLElement),
  share: $("#share", HTMLAnchorElement),
  load: $("#load-status", HTMLElement),
  sweepStatus: $("#sweep-status", HTMLOutputElement),
};
const query = new URLSearchParams(location.search);
const embed = query.get(KEYS.embed) === "1";
const writeUrl = throttledUrl(400, (search) => (ui.share.href = search));

/** The page's run: the module's SwarmDemo, the state it was built from, the view, the sweep. */
const run = {
  demo: /** @type {SwarmDemo | null} */ (null),
  state: /** @type {SwarmState} */ (PRESETS.synchronise),
  playing: false,
  sweep: { couplings: /** @type {number[]} */ ([]), orders: /** @type {number[]} */ ([]), timer: 0 },
};

// ---- State: form, URL -----------------------------------------------------------------------

/** The form as a state; numbers only turned from text (the module checks them). */
function readForm() {
  const number = (/** @type {string} */ name) => parseNumber(field(name).value);
  /** @type {SwarmState} */
  const state = {
    coupling: number("coupling"),
    count: number("count"),
    graph: /** @type {SwarmState["graph"]} */ (field("graph").value),
    leaders: number("leaders"),
    frequencySpread: number("frequencySpread"),
    seed: number("seed"),
  };
  if (!(/** @type {HTMLInputElement} */ (field("uniform")).checked)) state.startSpread = number("startSpread");
  return state;
}

function fillForm(/** @type {SwarmState} */ state) {
  for (const name of /** @type {const} */ (["coupling", "count", "graph", "leaders", "frequencySpread", "seed"])) {
    field(name).value = String(state[name]);
  }
  /** @type {HTMLInputElement} */ (field("uniform")).checked = state.startSpread === undefined;
  field("startSpread").value = String(state.startSpread ?? 0.5);
  showValues();
}

/** The sliders' values beside them. */
function showValues() {
  for (const name of ["coupling", "count", "frequencySpread", "startSpread"]) {
    $(`#${name}-value`, HTMLOutputElement).textContent = field(name).value;
  }
  field("startSpread").disabled = /** @type {HTMLInputElement} */ (field("uniform")).checked;
}

/** The URL's state over a preset; values are read as numbers or one of three words only. */
function stateFromUrl() {
  const state = { ...PRESETS.synchronise };
  const number = (/** @type {keyof typeof KEYS} */ key) => (query.has(KEYS[key]) ? parseNumber(query.get(KEYS[key]) ?? "") : undefined);
  for (const key of /** @type {const} */ (["coupling", "count", "leaders", "frequencySpread", "seed"])) {
    const value = number(key);
    if (value !== undefined) state[key] = value;
  }
  const graph = query.get(KEYS.graph);
  if (graph === "all" || graph === "ring" || graph === "leader") state.graph = graph;
  const spread = number("startSpread");
  if (spread !== undefined) state.startSpread = spread;
  return state;
}

function urlOf(/** @type {SwarmState} */ state) {
  const search = new URLSearchParams();
  for (const key of /** @type {const} */ (["coupling", "count", "graph", "leaders", "frequencySpread", "seed"])) {
    search.set(KEYS[key], String(state[key]));
  }
  if (state.startSpread !== undefined) search.set(KEYS.startSpread, String(state.startSpread));
  if (embed) search.set(KEYS.embed, "1");
  return "?" + search.toString();
}

// ---- Runs -----------------------------------------------------------------------------------

/** The options of the state an Error is about ("options" itself: the coupling's field). */
const keyOf = (/** @type {unknown} */ error) => {
  const argument = argumentOf(error);
  return /** @type {(keyof SwarmState)[]} */ (["coupling", "count", "graph", "leaders", "frequencySpread", "startSpread", "seed"])
    .find((key) => key === argument);
};
const create = (/** @type {SwarmState} */ state) => new SwarmDemo(state);

/** Builds the swarm for `state` when the module accepts all of it; otherwise shows every refused
 *  option beside its field and keeps the run on show. */
function rebuild(/** @type {SwarmState} */ state) {
  const { run: demo, errors } = buildAll(state, run.state, create, keyOf);
  clearErrors(form);
  if (errors.length > 0 || !demo) {
    demo?.free();
    errors.forEach(showError);
    return false;
  }
  show(demo, state);
  return true;
}

/** Shows a run: the views, the note, the URL. */
function show(/** @type {SwarmDemo} */ demo, /** @type {SwarmState} */ state) {
  run.demo?.free();
  run.demo = demo;
  figures.show(demo);
  run.state = state;
  field("preset").value = presetName(PRESETS, state);
  ui.note.textContent = demo.isKli
    ? "One pinned leader and one follower: the follower obeys q′ = (K/2)(r − (q·r) q), the KLI flow at the clock τ = Kt/2."
    : "";
  writeUrl(urlOf(state));
  draw();
  drawSweep(); // its marker follows K; otherwise it changes only while a sweep runs
}

function showError(/** @type {unknown} */ error) {
  const name = keyOf(error) ?? "coupling";
  showFieldError(form, name, [field(name)], messageOf(error));
}

// ---- Frames ---------------------------------------------------------------------------------

let pending = false;
function requestDraw() {
  if (pending) return;
  pending = true;
  requestAnimationFrame(() => {
    pending = false;
    if (run.playing && run.demo) run.demo.step(DT, STEPS_PER_FRAME);
    draw();
    if (run.playing) requestDraw();
  });
}

function draw() {
  const demo = run.demo;
  if (!demo) return;
  figures.render(demo.time);
  ui.readout.textContent = `t = ${demo.time.toFixed(2)}   R = ${demo.orderParameter.toFixed(3)}   λmax = ${demo.rotationOrder.toFixed(3)}` +
    (demo.isKli ? `   τ = Kt/2 = ${demo.kliTime.toFixed(2)}` : "");
  if (!run.playing) ui.status.textContent = ui.readout.textContent ?? "";
}

function drawSweep() {
  figures.invalidate(["sweep"]);
  figures.render(run.demo?.time ?? 0);
}

/** The views' names in file names. */
const FILE_NAMES = { hopf: "hopf", objects: "objects", plots: "order-plots", sweep: "coupling-sweep" };

/** Saves a view as PNG or SVG, or the swarm as CSV or JSON, as it stands now. */
function save(/** @type {string} */ what, /** @type {string} */ format) {
  const demo = run.demo;
  if (!demo) throw new Error("there is no swarm to save");
  const tag = timeTag(demo.time);
  if (what === "swarm") {
    return saveAs(`kli-swarm-${demo.count}-oscillators-${tag}`, format, { csv: () => demo.export("swarm", "csv"), json: () => demo.export("swarm", "json") });
  }
  const view = /** @type {keyof typeof FILE_NAMES} */ (what);
  if (!Object.hasOwn(FILE_NAMES, view)) throw new Error(`there is no ${what} view`);
  const name = `kli-swarm-${FILE_NAMES[view]}${view === "sweep" ? "" : `-${tag}`}`;
  return figures.save(view, format, name, demo.time, view === "sweep" ? (frame) => SwarmDemo.sweepSvg(frame, ...sweepPoints()) : undefined);
}

/** One sweep point per task, so the page stays responsive. */
function sweep() {
  clearTimeout(run.sweep.timer);
  run.sweep.couplings = [];
  run.sweep.orders = [];
  const table = $("#sweep-table tbody", HTMLTableSectionElement);
  table.replaceChildren();
  const options = { ...run.state, count: Math.min(run.state.count, 200) };
  const next = (/** @type {number} */ i) => {
    if (i === SWEEP.length) {
      ui.sweepStatus.textContent = `Done: R at t = 30 for ${SWEEP.length} couplings.`;
      return;
    }
    run.sweep.couplings.push(SWEEP[i]);
    run.sweep.orders.push(SwarmDemo.sweepOrder(options, SWEEP[i], 30));
    const row = table.insertRow();
    row.insertCell().textContent = String(Number(SWEEP[i].toFixed(4)));
    row.insertCell().textContent = run.sweep.orders[i].toFixed(3);
    ui.sweepStatus.textContent = `Sweeping: ${i + 1} of ${SWEEP.length}`;
    drawSweep();
    run.sweep.timer = setTimeout(() => next(i + 1));
  };
  next(0);
}

function play() {
  run.playing = true;
  ui.play.textContent = "Pause";
  requestDraw();
}

function pause() {
  run.playing = false;
  ui.play.textContent = "Play";
  draw();
}

// ---- Start ----------------------------------------------------------------------------------


function wire() {
  form.addEventListener("submit", (event) => event.preventDefault());
  form.addEventListener("input", (event) => {
    const name = /** @type {HTMLInputElement} */ (event.target).name;
    showValues();
    if (name === "preset") {
      const preset = PRESETS[field("preset").value];
      if (preset) fillForm(preset);
      if (preset) rebuild(preset);
      return;
    }
    rebuild(readForm());
  });
  ui.play.addEventListener("click", () => (run.playing ? pause() : play()));
  $("#step", HTMLButtonElement).addEventListener("click", () => {
    pause();
    run.demo?.step(DT, 10);
    draw();
  });
  $("#reseed", HTMLButtonElement).addEventListener("click", () => {
    field("seed").value = String((run.state.seed + 1) % 1e9);
    rebuild(readForm());
  });
  $("#sweep", HTMLButtonElement).addEventListener("click", sweep);
  wireSaving($("#save", HTMLElement), save, $("#save-status", HTMLElement));
  const turn = (/** @type {number} */ azimuth, /** @type {number} */ elevation) => {
    figures.turn(azimuth, elevation);
    if (!run.playing) draw();
  };
  wireDragging(canvases.hopf, turn);
  wireKeyboard(canvases.hopf, {
    togglePlay: () => (run.playing ? pause() : play()),
    step: () => {},
    toStart: () => rebuild(run.state),
    toEnd: () => {},
    speed: () => {},
    turn,
  });
}

async function start() {
  if (!(await loadModule(init, ui.load))) return;
  if (embed) document.body.classList.add("embed");
  figures.camera = new Camera(defaultCamera());
  wire();
  // The URL's options that the module refuses are shown, and the preset's stand in for them.
  const { run: demo, state, errors } = buildAll(stateFromUrl(), PRESETS.synchronise, create, keyOf);
  show(demo ?? create(PRESETS.synchronise), state ?? PRESETS.synchronise);
  fillForm(run.state);
  errors.forEach(showError);
  ui.load.textContent = "";
  ui.load.hidden = true;
  figures.observe(draw);
  if (!matchMedia("(prefers-reduced-motion: reduce)").matches) play();
}

start();
