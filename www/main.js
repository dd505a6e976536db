// @ts-check
// Wiring only: the module, the form, the clock, the views and the URL, joined up. Computing,
// checking and drawing are the module's (crates/kli-demo); each concern has its own file here.
import init, { Demo, axisAngle, defaultCamera, fromAxisAngle } from "./pkg/kli_demo.js";
import { Camera } from "./camera.js";
import { Clock } from "./clock.js";
import { saveAs, timeTag, wireSaving } from "./exports.js";
import { Figures } from "./figures.js";
import { page } from "./pages.js";
import { $ } from "./dom.js";
import { Form, stateKey } from "./form.js";
import { wireDragging, wireKeyboard } from "./input.js";
import { parseNumber } from "./numbers.js";
import { DEFAULTS, PRESETS, presetName, randomQuaternion } from "./presets.js";
import { buildAll } from "./runs.js";
import { describeFrame, describeRun, fillTable, fillTypo } from "./summary.js";
import { readQuery, throttledUrl, writeQuery } from "./url.js";

/** @typedef {import("./form.js").State} State */

const query = readQuery(location.search);
const form = new Form($("#inputs", HTMLFormElement));
const clock = new Clock();
const ui = {
  play: $("#play", HTMLButtonElement),
  time: $("#time", HTMLInputElement),
  readout: $("#readout", HTMLOutputElement),
  status: $("#time-status", HTMLElement),
  speed: $("#speed", HTMLSelectElement),
  share: $("#share", HTMLAnchorElement),
  note: $("#note", HTMLElement),
  load: $("#load-status", HTMLElement),
};
const figures = new Figures({
  object: $("#object-canvas", HTMLCanvasElement),
  hopf: $("#hopf-canvas", HTMLCanvasElement),
  filmstrip: $("#filmstrip-canvas", HTMLCanvasElement),
  plots: $("#plots-canvas", HTMLCanvasElement),
}, page("kli"));
const canvases = figures.canvases;
const writeUrl = throttledUrl(400, (search) => (ui.share.href = search));
const reducedMotion = () => matchMedia("(prefers-reduced-motion: reduce)").matches;

/** The run on show: its Demo and the state it was built from. */
const run = { demo: /** @type {Demo | null} */ (null), state: /** @type {State | null} */ (null) };

// ---- Runs ---------------------------------------------------------------------------------

/** The Demo for `candidate`, every refused argument taken from `fallback` (see runs.js). */
function build(/** @type {State} */ candidate, /** @type {State} */ fallback) {
  const create = (/** @type {State} */ { p, r, tolerance, step, integrator, shortestPath }) =>
    new Demo(p, r, { tolerance, step, integrator, shortestPath });
  const { run, state, errors } = buildAll(candidate, fallback, create, stateKey);
  return { demo: run, state, errors };
}

/** Shows a run: the views, the table, the notes, the URL. */
function show(/** @type {Demo} */ demo, /** @type {State} */ state) {
  run.demo?.free();
  run.demo = demo;
  run.state = state;
  clock.setSpan(0, demo.finalTime);
  ui.time.max = String(demo.finalTime);
  ui.time.step = String(state.step);
  figures.show(demo);
  fillTable(demo, $("#moments tbody", HTMLTableSectionElement), $("#final-time", HTMLElement), $("#printed-notes", HTMLUListElement));
  fillTypo(demo, state.tolerance, $("#typo tbody", HTMLTableSectionElement), $("#typo-summary", HTMLElement));
  ui.note.textContent = describeRun(demo, state);
  form.field("preset").value = presetName(PRESETS, state);
  showTime();
  requestDraw();
}

/** Applies the form's values when the module accepts them all; otherwise shows why not and
 *  keeps the run on show. Returns whether it applied them. */
function update() {
  const candidate = form.read();
  const { demo, state, errors } = build(candidate, run.state ?? DEFAULTS);
  form.clearErrors();
  if (errors.length > 0 || !demo || !state) {
    demo?.free();
    for (const error of errors) form.showError(error);
    return false;
  }
  show(demo, state);
  return true;
}

/** @param {Event} event */
function onFormInput(event) {
  const name = /** @type {HTMLInputElement} */ (event.target).name ?? "";
  if (name === "preset") return applyPreset(form.field("preset").value);
  const axisAngleField = /^([pr])-(ax|ay|az|angle)$/.exec(name);
  if (axisAngleField) {
    const which = /** @type {"p" | "r"} */ (axisAngleField[1]);
    const { axis, angle } = form.readAxisAngle(which);
    try {
      form.fillQuaternion(which, fromAxisAngle(axis, angle));
    } catch (error) {
      form.clearErrors();
      form.showError(error, which);
      return;
    }
  }
  if (update() && /^[pr]-[wxyz]$/.test(name) && run.state) {
    const which = /** @type {"p" | "r"} */ (name[0]);
    form.fillAxisAngle(which, axisAngle(run.state[which]));
  }
}

function applyPreset(/** @type {string} */ name) {
  const preset = name === "random" ? { ...DEFAULTS, p: randomQuaternion(), r: randomQuaternion() } : PRESETS[name] ?? DEFAULTS;
  form.fill(preset);
  fillAxisAngles(preset);
  clock.seek(0);
  if (update() && !reducedMotion()) play();
}

function fillAxisAngles(/** @type {State} */ state) {
  for (const which of /** @type {const} */ (["p", "r"])) {
    try {
      form.fillAxisAngle(which, axisAngle(state[which]));
    } catch {
      // Not a quaternion: its own message is shown already.
    }
  }
}

// ---- Time ---------------------------------------------------------------------------------

let announcement = 0;

/** After the time or the run changed: the slider, the readout, and while paused the object's
 *  text alternative, the URL and (a moment later, once it rests) an announcement. */
function showTime() {
  const demo = run.demo;
  if (!demo || !run.state) return;
  ui.time.value = String(clock.t);
  ui.readout.textContent = `t = ${clock.t.toFixed(2)} / T = ${demo.finalTime.toFixed(2)}`;
  writeUrl(writeQuery(run.state, { t: clock.playing ? undefined : clock.t, embed: query.embed }));
  if (clock.playing) return;
  canvases.object.setAttribute("aria-label", describeFrame(demo, clock.t));
  clearTimeout(announcement);
  announcement = setTimeout(() => (ui.status.textContent = ui.readout.textContent ?? ""), 300);
}

function play() {
  if (!run.demo) return;
  clock.play();
  ui.play.textContent = "Pause";
  showTime();
  requestDraw();
}

function pause() {
  clock.pause();
  ui.play.textContent = "Play";
  showTime();
}

function seek(/** @type {number} */ t) {
  clock.seek(t);
  showTime();
  requestDraw();
}

/** @type {import("./input.js").Actions} */
const actions = {
  togglePlay: () => (clock.playing ? pause() : play()),
  step: (by) => {
    pause();
    seek(clock.t + by * Math.max(run.state?.step ?? 0.01, clock.end / 200));
  },
  toStart: () => seek(0),
  toEnd: () => {
    pause();
    seek(clock.end);
  },
  speed: (by) => {
    ui.speed.selectedIndex = Math.min(Math.max(ui.speed.selectedIndex + by, 0), ui.speed.options.length - 1);
    clock.speed = Number(ui.speed.value);
  },
  turn: (azimuth, elevation) => {
    figures.turn(azimuth, elevation);
    requestDraw();
  },
};

// ---- Frames -------------------------------------------------------------------------------

let drawPending = false;
let lastReadout = "";

function requestDraw() {
  if (drawPending) return;
  drawPending = true;
  requestAnimationFrame(frame);
}

function frame(/** @type {number} */ now) {
  drawPending = false;
  const ended = clock.tick(now);
  draw();
  if (ended) pause();
  if (clock.playing) requestDraw();
}

/** Draws the live views at the clock's time; while playing, the slider and readout follow. */
function draw() {
  if (!figures.render(clock.t) || !run.demo) return;
  if (clock.playing) {
    const readout = `t = ${clock.t.toFixed(2)} / T = ${run.demo.finalTime.toFixed(2)}`;
    if (readout !== lastReadout) {
      ui.time.value = String(clock.t);
      ui.readout.textContent = lastReadout = readout;
    }
  }
  // For the DevTools timeline and `make bench`: when the first complete frame was drawn.
  if (performance.getEntriesByName("kli:first-frame").length === 0) performance.mark("kli:first-frame");
}

// ---- Saving -------------------------------------------------------------------------------

/** Saves a view as PNG or SVG, or the path as CSV or JSON, as it stands. */
function save(/** @type {string} */ what, /** @type {string} */ format) {
  const demo = run.demo;
  if (!demo) throw new Error("there is no run to save");
  if (what === "path") {
    return saveAs(`kli-path-T${demo.finalTime.toFixed(2)}`, format, { csv: () => demo.export("path", "csv"), json: () => demo.export("path", "json") });
  }
  const view = /** @type {keyof typeof canvases} */ (what);
  return figures.save(view, format, `kli-${view}${view === "filmstrip" ? "" : `-${timeTag(clock.t)}`}`, clock.t);
}

// ---- Start --------------------------------------------------------------------------------

function wire() {
  // Text fields, the checkbox and the selects all fire "input": one rebuild per change.
  form.form.addEventListener("input", onFormInput);
  form.form.addEventListener("submit", (event) => event.preventDefault());
  ui.play.addEventListener("click", actions.togglePlay);
  $("#restart", HTMLButtonElement).addEventListener("click", () => {
    seek(0);
    if (!reducedMotion()) play();
  });
  ui.time.addEventListener("input", () => {
    if (clock.playing) pause();
    seek(Number(ui.time.value));
  });
  ui.speed.addEventListener("input", () => (clock.speed = Number(ui.speed.value)));
  wireSaving($("#save", HTMLElement), save, $("#save-status", HTMLElement));
  wireKeyboard(canvases.hopf, actions);
  wireDragging(canvases.hopf, actions.turn);
}

/** The form as the URL gives it, over the defaults; a quaternion of the wrong length stays so,
 *  for the module to name. */
function startingState() {
  form.fill(DEFAULTS);
  const texts = (/** @type {"p" | "r"} */ which) => {
    const given = query[which];
    if (given) form.quaternionFields(which).forEach((field, i) => (field.value = given[i] ?? ""));
  };
  texts("p");
  texts("r");
  if (query.tolerance !== undefined) form.field("tolerance").value = query.tolerance;
  if (query.step !== undefined) form.field("step").value = query.step;
  if (query.integrator) form.field("integrator").value = query.integrator;
  if (query.shortestPath !== undefined) /** @type {HTMLInputElement} */ (form.field("shortestPath")).checked = query.shortestPath;
  const state = form.read();
  if (query.p) state.p = query.p.map(parseNumber);
  if (query.r) state.r = query.r.map(parseNumber);
  return state;
}

async function start() {
  try {
    await init();
  } catch (error) {
    ui.load.textContent = `The WebAssembly module could not be loaded: ${error instanceof Error ? error.message : error}`;
    ui.load.classList.add("error");
    return;
  }
  performance.mark("kli:wasm-ready");
  if (query.embed) document.body.classList.add("embed");
  figures.camera = new Camera(defaultCamera());
  wire();
  const candidate = startingState();
  // The clock runs before the first URL is written, so that a playing page's URL has no time.
  const paused = query.t !== undefined || reducedMotion();
  if (!paused) clock.play();
  // The URL's arguments that the module refuses are shown, and the paper's stand in for them.
  const { demo, state, errors } = build(candidate, DEFAULTS);
  if (demo && state) {
    show(demo, state);
    fillAxisAngles(state);
  }
  for (const error of errors) form.showError(error);
  if (!paused) play();
  else seek(query.t ?? 0);
  ui.load.textContent = "";
  ui.load.hidden = true;
  figures.observe(draw);
  // Offline support is registered once the page has settled, not on the way to the first frame.
  if ("serviceWorker" in navigator && location.protocol !== "file:") {
    const register = () => setTimeout(() => navigator.serviceWorker.register("sw.js").catch(() => {}));
    if (document.readyState === "complete") register();
    else addEventListener("load", register, { once: true });
  }
}

start();
