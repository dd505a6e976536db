// @ts-check
// The keyframes page, wiring only: the keys and options to the module's KeyframesDemo (the three
// curves, their figures and their views) and to kliSpline/squadSpline/slerpSpline for timing.
import init, { KeyframesDemo, defaultCamera, kliSpline, slerpSpline, squadSpline } from "./pkg/keyframes_demo.js";
import { Camera } from "./camera.js";
import { Clock } from "./clock.js";
import { loadModule } from "./canvases.js";
import { Figures } from "./figures.js";
import { page } from "./pages.js";
import { $ } from "./dom.js";
import { presetName, randomQuaternion } from "./presets.js";
import { argumentOf, buildAll, clearErrors, messageOf, showFieldError } from "./runs.js";
import { saveAs, timeTag, wireSaving } from "./exports.js";
import { wireDragging, wireKeyboard } from "./input.js";
import { formatNumber, parseNumber } from "./numbers.js";
import { KEYFRAMES_URL_KEYS as KEYS, throttledUrl } from "./url.js";

/** @typedef {{ keys: number[][], times: number[], smoothness: number }} SplineState */

/** @type {Record<string, SplineState>} */
const PRESETS = {
  tumble: {
    keys: [[1, 0, 0, 0], [0.8, 0.6, 0, 0], [0.5, 0.5, 0.5, 0.5], [0, 0.6, 0.8, 0], [-0.3, 0.1, 0.7, 0.64], [0.2, -0.6, 0.3, 0.72]],
    times: [], smoothness: 1,
  },
  uneven: {
    keys: [[1, 0, 0, 0], [0.6, 0, 0.8, 0], [0, 0, 0.6, 0.8], [0.36, 0.48, 0.48, 0.64], [0.8, 0, 0, 0.6]],
    times: [0, 0.5, 2, 2.4, 4], smoothness: 1,
  },
  hard: { keys: [[1, 0, 0, 0], [1, 0, 0, 0], [0, 1, 0, 0], [-0.6, 0, -0.8, 0], [0.6, 0, 0.8, 0], [1, 0, 0, 0]], times: [], smoothness: 1 },
};

const form = $("#keyframes-inputs", HTMLFormElement);
const field = (/** @type {string} */ name) => /** @type {HTMLInputElement} */ (form.elements.namedItem(name));
const figures = new Figures({
  objects: $("#keyframes-objects", HTMLCanvasElement),
  hopf: $("#keyframes-hopf", HTMLCanvasElement),
  plots: $("#keyframes-plots", HTMLCanvasElement),
}, page("keyframes"));
const canvases = figures.canvases;
const ui = {
  play: $("#play", HTMLButtonElement),
  time: $("#time", HTMLInputElement),
  readout: $("#readout", HTMLOutputElement),
  share: $("#share", HTMLAnchorElement),
  note: $("#note", HTMLElement),
  load: $("#load-status", HTMLElement),
  solve: $("#solve", HTMLElement),
};
const query = new URLSearchParams(location.search);
const embed = query.get(KEYS.embed) === "1";
const writeUrl = throttledUrl(400, (search) => (ui.share.href = search));
const run = {
  demo: /** @type {KeyframesDemo | null} */ (null),
  state: PRESETS.tumble,
  clock: new Clock(),
};

// ---- State ----------------------------------------------------------------------------------

const keysText = (/** @type {number[][]} */ keys) => keys.map((q) => q.map(formatNumber).join(",")).join("; ");
/** Text to numbers only (NaN where not a number): the module checks the keys. */
const parseKeys = (/** @type {string} */ text) => text.split(";").filter((k) => k.trim()).map((k) => k.split(",").map(parseNumber));
const parseTimes = (/** @type {string} */ text) => (text.trim() ? text.split(",").map(parseNumber) : []);

/** The key selector and the selected key's axis and angle. */
function fillKeyEditor() {
  const demo = run.demo;
  if (!demo) return;
  const select = /** @type {HTMLSelectElement} */ (form.elements.namedItem("key"));
  const count = demo.keys.length / 4;
  const selected = Math.min(Number(select.value) || 0, count - 1);
  select.replaceChildren(...Array.from({ length: count }, (_, i) => new Option(`k${i}`, String(i))));
  select.value = String(selected);
  const [x, y, z, angle] = demo.keyAxisAngle(selected);
  for (const [name, value] of /** @type {const} */ ([["key-ax", x], ["key-ay", y], ["key-az", z], ["key-angle", (angle * 180) / Math.PI]])) {
    field(name).value = formatNumber(value);
  }
  $("#add-key", HTMLButtonElement).disabled = count >= 10;
  $("#remove-key", HTMLButtonElement).disabled = count <= 3;
}

/** Keys as rows of 4 from the module's flat Float64Array. */
const rows = (/** @type {Float64Array} */ flat) => Array.from({ length: flat.length / 4 }, (_, i) => Array.from(flat.subarray(4 * i, 4 * i + 4), (c) => Number(c.toPrecision(6))));

/** Rebuilds with new keys (times kept only when their count still matches). */
function withKeys(/** @type {number[][]} */ keys) {
  const times = run.state.times.length === keys.length ? run.state.times : [];
  const state = { keys, times, smoothness: run.state.smoothness };
  fillForm(state);
  rebuild(state);
}

function fillForm(/** @type {SplineState} */ state) {
  field("keys").value = keysText(state.keys);
  field("times").value = state.times.map(formatNumber).join(",");
  field("smoothness").value = String(state.smoothness);
  $("#smoothness-value", HTMLOutputElement).textContent = String(state.smoothness);
}

function readForm() {
  return { keys: parseKeys(field("keys").value), times: parseTimes(field("times").value), smoothness: parseNumber(field("smoothness").value) };
}

function stateFromUrl() {
  const state = { ...PRESETS.tumble };
  if (query.has(KEYS.keys)) state.keys = parseKeys(query.get(KEYS.keys) ?? "");
  if (query.has(KEYS.times)) state.times = parseTimes(query.get(KEYS.times) ?? "");
  if (query.has(KEYS.smoothness)) state.smoothness = parseNumber(query.get(KEYS.smoothness) ?? "");
  return state;
}

function urlOf(/** @type {SplineState} */ state) {
  const search = new URLSearchParams();
  search.set(KEYS.keys, state.keys.map((q) => q.map(formatNumber).join(",")).join(";"));
  if (state.times.length) search.set(KEYS.times, state.times.map(formatNumber).join(","));
  search.set(KEYS.smoothness, String(state.smoothness));
  if (embed) search.set(KEYS.embed, "1");
  return "?" + search.toString();
}

// ---- Runs -----------------------------------------------------------------------------------

/** The part of the state an Error is about. */
const keyOf = (/** @type {unknown} */ error) => {
  const argument = argumentOf(error);
  return argument.startsWith("keys") ? "keys" : argument.startsWith("times") ? "times" : argument === "smoothness" ? "smoothness" : undefined;
};
const create = (/** @type {SplineState} */ state) =>
  new KeyframesDemo(new Float64Array(state.keys.flat()), new Float64Array(state.times), state.smoothness);

/** Builds the three curves when the module accepts the whole state; otherwise shows every
 *  refused part beside its field and keeps the run on show. */
function rebuild(/** @type {SplineState} */ state) {
  const { run: demo, errors } = buildAll(state, run.state, create, keyOf);
  clearErrors(form);
  if (errors.length > 0 || !demo) {
    demo?.free();
    errors.forEach((error) => showError(error));
    return false;
  }
  show(demo, state);
  return true;
}

/** Shows a run: the views, the table, the key editor, the URL. */
function show(/** @type {KeyframesDemo} */ demo, /** @type {SplineState} */ state) {
  run.demo?.free();
  run.demo = demo;
  figures.show(demo);
  run.state = state;
  run.clock.setSpan(demo.startTime, demo.endTime);
  ui.time.min = String(demo.startTime);
  ui.time.max = String(demo.endTime);
  /** @type {HTMLSelectElement} */ (form.elements.namedItem("preset")).value = presetName(PRESETS, state);
  fillFigures(demo, state);
  fillKeyEditor();
  writeUrl(urlOf(state));
  draw();
}

function showError(/** @type {unknown} */ error) {
  const argument = argumentOf(error);
  const name = keyOf(error) ?? (argument === "axis" || argument === "angle" ? "key" : "smoothness");
  const marked = name !== "key" ? [name] : argument === "angle" ? ["key-angle"] : ["key-ax", "key-ay", "key-az"];
  showFieldError(form, name, marked.map(field), messageOf(error));
}

/** The table: the module's figures at once, and a moment after the last change (not on every
 *  move of a dragged key) the solve and evaluation times, measured here. */
function fillFigures(/** @type {KeyframesDemo} */ demo, /** @type {SplineState} */ state) {
  const figures = demo.figures;
  const body = $("#figures tbody", HTMLTableSectionElement);
  body.replaceChildren();
  ["Kuramoto–Lohe chain", "Squad", "piecewise SLERP"].forEach((name, i) => {
    const row = body.insertRow();
    const cells = [name, figures[4 * i].toExponential(1), figures[4 * i + 1].toFixed(3), figures[4 * i + 2].toFixed(3),
      figures[4 * i + 3].toFixed(3), "…", "…"];
    for (const text of cells) row.insertCell().textContent = text;
  });
  ui.solve.textContent = `The chain: ${demo.iterations} Newton steps to a residual of ${demo.residual.toExponential(1)}; ` +
    `its ∫|ω̇|² is ${(figures[2] / figures[6]).toFixed(3)} of Squad's.`;
  clearTimeout(timing);
  timing = setTimeout(() => fillTimes(demo.startTime, demo.endTime, state), 300);
}

let timing = 0;

/** The last two columns: each curve built from the package's API and sampled at 10⁴ times. */
function fillTimes(/** @type {number} */ start, /** @type {number} */ end, /** @type {SplineState} */ state) {
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
  const rows = $("#figures tbody", HTMLTableSectionElement).rows;
  builders.forEach((build, i) => {
    const curve = timed(build);
    const evaluation = timed(() => curve.value.sample(times));
    curve.value.free();
    rows[i].cells[5].textContent = curve.ms.toFixed(2);
    rows[i].cells[6].textContent = evaluation.ms.toFixed(2);
  });
}

// ---- Frames ---------------------------------------------------------------------------------

let pending = false;
function requestDraw() {
  if (pending) return;
  pending = true;
  requestAnimationFrame((now) => {
    pending = false;
    if (run.clock.tick(now)) pause();
    draw();
    if (run.clock.playing) requestDraw();
  });
}

/** The views' names in file names. */
const FILE_NAMES = { objects: "objects", hopf: "hopf", plots: "angular-velocity-plots" };

/** Saves a view as PNG or SVG, or the three curves' samples as CSV or JSON. */
function save(/** @type {string} */ what, /** @type {string} */ format) {
  const demo = run.demo;
  if (!demo) throw new Error("there are no curves to save");
  const keys = `${demo.keys.length / 4}-keys`;
  if (what === "curves") {
    return saveAs(`kli-keyframes-curves-${keys}`, format, { csv: () => demo.export("curves", "csv"), json: () => demo.export("curves", "json") });
  }
  const view = /** @type {keyof typeof FILE_NAMES} */ (what);
  if (!Object.hasOwn(FILE_NAMES, view)) throw new Error(`there is no ${what} view`);
  return figures.save(view, format, `kli-keyframes-${FILE_NAMES[view]}-${keys}-${timeTag(run.clock.t)}`, run.clock.t);
}

function draw() {
  const demo = run.demo;
  if (!demo) return;
  figures.render(run.clock.t);
  ui.time.value = String(run.clock.t);
  ui.readout.textContent = `t = ${run.clock.t.toFixed(2)} / ${demo.endTime.toFixed(2)}`;
}

function play() {
  run.clock.play();
  ui.play.textContent = "Pause";
  requestDraw();
}

function pause() {
  run.clock.pause();
  ui.play.textContent = "Play";
}

// ---- Start ----------------------------------------------------------------------------------

const randomKeys = () => Array.from({ length: 6 }, randomQuaternion);

function wire() {
  form.addEventListener("submit", (event) => event.preventDefault());
  form.addEventListener("input", (event) => {
    const name = /** @type {HTMLInputElement} */ (event.target).name;
    $("#smoothness-value", HTMLOutputElement).textContent = field("smoothness").value;
    if (name === "key") return fillKeyEditor();
    if (name.startsWith("key-")) {
      const demo = run.demo;
      if (!demo) return;
      const index = Number(field("key").value);
      const [x, y, z, degrees] = ["key-ax", "key-ay", "key-az", "key-angle"].map((n) => parseNumber(field(n).value));
      try {
        withKeys(rows(demo.keysWithAxisAngle(index, new Float64Array([x, y, z]), (degrees * Math.PI) / 180)));
      } catch (error) {
        clearErrors(form);
        showError(error);
      }
      return;
    }
    if (name === "preset") {
      const preset = PRESETS[/** @type {HTMLSelectElement} */ (form.elements.namedItem("preset")).value];
      if (!preset) return;
      fillForm(preset);
      rebuild(preset);
      return;
    }
    rebuild(readForm());
  });
  $("#random", HTMLButtonElement).addEventListener("click", () => {
    const state = { keys: randomKeys(), times: [], smoothness: run.state.smoothness };
    fillForm(state);
    rebuild(state);
  });
  ui.play.addEventListener("click", () => (run.clock.playing ? pause() : play()));
  wireSaving($("#save", HTMLElement), save, $("#save-status", HTMLElement));
  ui.time.addEventListener("input", () => {
    pause();
    run.clock.seek(Number(ui.time.value));
    draw();
  });
  const turn = (/** @type {number} */ azimuth, /** @type {number} */ elevation) => {
    figures.turn(azimuth, elevation);
    if (!run.clock.playing) draw();
  };
  wireDragging(canvases.hopf, turn, grabKey);
  $("#add-key", HTMLButtonElement).addEventListener("click", () => {
    const keys = run.state.keys;
    if (keys.length >= 10) return;
    // A new key a quarter turn about z from the last: [w, x, y, z] · (cos 45°, 0, 0, sin 45°).
    const [w, x, y, z] = keys[keys.length - 1];
    const c = Math.SQRT1_2;
    withKeys([...keys, [c * (w - z), c * (x + y), c * (y - x), c * (z + w)].map((v) => Number(v.toFixed(4)))]);
  });
  $("#remove-key", HTMLButtonElement).addEventListener("click", () => {
    if (run.state.keys.length > 3) withKeys(run.state.keys.slice(0, -1));
  });
  wireKeyboard(canvases.hopf, {
    togglePlay: () => (run.clock.playing ? pause() : play()),
    step: () => {},
    toStart: () => { run.clock.seek(run.clock.start); draw(); },
    toEnd: () => { run.clock.seek(run.clock.end); draw(); },
    speed: () => {},
    turn,
  });
}

/**
 * A key's disc under the pointer (the nearest in front within 12 px) is grabbed: moving the
 * pointer then turns that key so that its Hopf point follows (once a frame).
 * @param {number} x
 * @param {number} y
 */
function grabKey(x, y) {
  const demo = run.demo;
  const frame = figures.frame("hopf", run.clock.t);
  if (!demo || !frame) return null;
  const points = demo.keyPoints(frame);
  let key = -1;
  let nearest = 12;
  for (let i = 0; i < points.length / 3; i++) {
    const distance = Math.hypot(points[3 * i] - x, points[3 * i + 1] - y);
    if (points[3 * i + 2] === 1 && distance < nearest) [key, nearest] = [i, distance];
  }
  if (key < 0) return null;
  let pending = false;
  let to = { x, y };
  return (/** @type {number} */ x, /** @type {number} */ y) => {
    to = { x, y };
    if (pending) return;
    pending = true;
    requestAnimationFrame(() => {
      pending = false;
      const demo = run.demo;
      const frame = figures.frame("hopf", run.clock.t);
      if (!demo || !frame) return;
      const moved = demo.keysWithKeyAt(key, frame, to.x, to.y);
      if (moved.length) {
        /** @type {HTMLSelectElement} */ (form.elements.namedItem("key")).value = String(key);
        withKeys(rows(moved));
      }
    });
  };
}

async function start() {
  if (!(await loadModule(init, ui.load))) return;
  if (embed) document.body.classList.add("embed");
  figures.camera = new Camera(defaultCamera());
  wire();
  // The URL's parts that the module refuses are shown (their text kept in the field, to mend),
  // and the preset's stand in for them.
  const { run: demo, state, errors } = buildAll(stateFromUrl(), PRESETS.tumble, create, keyOf);
  show(demo ?? create(PRESETS.tumble), state ?? PRESETS.tumble);
  fillForm(run.state);
  for (const error of errors) {
    const key = keyOf(error);
    if ((key === "keys" || key === "times") && query.has(KEYS[key])) field(key).value = query.get(KEYS[key]) ?? "";
    showError(error);
  }
  ui.load.textContent = "";
  ui.load.hidden = true;
  figures.observe(draw);
  if (!matchMedia("(prefers-reduced-motion: reduce)").matches) play();
}

start();
