// Wiring only: form and URL to the wasm Demo, the animation loop, and the canvases.
// All computing and drawing happens in Rust (src/bindings/demo.rs, src/render/).
import init, { Demo, axisAngle, fromAxisAngle } from "./pkg/kli.js";
import { DEFAULTS, PRESETS, formatNumber, parseNumber, randomQuaternion, readQuery, writeQuery } from "./state.js";

const $ = (selector) => document.querySelector(selector);
const form = $("#inputs");
const field = (name) => form.elements.namedItem(name);
const AXES = ["w", "x", "y", "z"];

const canvases = {
  object: $("#object-canvas"),
  sphere: $("#sphere-canvas"),
  filmstrip: $("#filmstrip-canvas"),
  plots: $("#plots-canvas"),
};
const sizes = {};
// The sphere and the plots change only with the scene, the size or the view: each is drawn once
// into an offscreen layer, which every frame copies before drawing the current time over it.
const layers = { sphere: { canvas: document.createElement("canvas"), stale: true }, plots: { canvas: document.createElement("canvas"), stale: true } };
const refreshLayers = (...names) => names.forEach((name) => (layers[name].stale = true));

let demo = null;
let state = null; // the last valid inputs
let t = 0;
let playing = false;
let lastFrame = null;
let drawPending = false;
let view = null; // sphere [azimuth, elevation]
const query = readQuery(location.search);

// ---- Form <-> state -------------------------------------------------------------------------

function showError(id, message, inputs = []) {
  $(`#${id}-error`).textContent = message;
  for (const input of inputs) input.setAttribute("aria-invalid", message ? "true" : "false");
}

const quaternionInputs = (which) => AXES.map((a) => field(`${which}-${a}`));
const axisAngleInputs = (which) => ["ax", "ay", "az", "angle"].map((a) => field(`${which}-${a}`));

/** Reads one quaternion group; returns numbers or a message. */
function readQuaternion(which) {
  const values = quaternionInputs(which).map((input) => parseNumber(input.value));
  const bad = values.findIndex((v) => !Number.isFinite(v));
  if (bad >= 0) return { message: `${which}: the ${AXES[bad]} component must be a number.` };
  if (values.every((v) => v === 0)) return { message: `${which} must not be all zero.` };
  return { value: values };
}

function readPositive(name, label) {
  const value = parseNumber(field(name).value);
  if (!Number.isFinite(value) || value <= 0) return { message: `${label} must be a number greater than 0.` };
  return { value };
}

/** The form as a candidate state, or null after showing what is wrong. */
function readForm() {
  const p = readQuaternion("p");
  const r = readQuaternion("r");
  const eps = readPositive("eps", "ε");
  const step = readPositive("step", "δ");
  showError("p", p.message ?? "", quaternionInputs("p"));
  showError("r", r.message ?? "", quaternionInputs("r"));
  showError("eps", eps.message ?? "", [field("eps")]);
  showError("step", step.message ?? "", [field("step")]);
  showError("shortest", "");
  if (p.message || r.message || eps.message || step.message) return null;
  return {
    p: p.value, r: r.value, eps: eps.value, step: step.value,
    integrator: field("integrator").value, shortest: field("shortest").checked,
  };
}

function fillQuaternion(which, q) {
  quaternionInputs(which).forEach((input, i) => (input.value = formatNumber(q[i])));
}

function fillAxisAngle(which, q) {
  try {
    const [x, y, z, angle] = axisAngle(q);
    const values = [x, y, z, (angle * 180) / Math.PI];
    axisAngleInputs(which).forEach((input, i) => (input.value = formatNumber(values[i])));
  } catch {
    // q was checked already; nothing to show otherwise.
  }
}

function fillForm(s) {
  fillQuaternion("p", s.p);
  fillQuaternion("r", s.r);
  fillAxisAngle("p", s.p);
  fillAxisAngle("r", s.r);
  field("eps").value = String(s.eps);
  field("step").value = String(s.step);
  field("integrator").value = s.integrator;
  field("shortest").checked = s.shortest;
}

/** Where the module's message about a rejected state belongs. */
function errorTarget(message) {
  if (/^p and r are antipodal|^p is so close to -r|left the sphere/.test(message)) return ["shortest", []];
  if (/^p\b/.test(message)) return ["p", quaternionInputs("p")];
  if (/^r\b/.test(message)) return ["r", quaternionInputs("r")];
  if (/^tolerance/.test(message)) return ["eps", [field("eps")]];
  if (/^(step|maxTime)/.test(message)) return ["step", [field("step")]];
  return ["shortest", []];
}

/** Builds the Demo for a candidate; keeps the last valid one when the module refuses it. */
function apply(candidate) {
  let next;
  try {
    next = new Demo(candidate.p, candidate.r, {
      tolerance: candidate.eps, step: candidate.step, integrator: candidate.integrator, shortestPath: candidate.shortest,
    });
  } catch (error) {
    const [id, inputs] = errorTarget(error.message);
    showError(id, error.message, inputs);
    return false;
  }
  demo?.free();
  demo = next;
  refreshLayers("sphere", "plots");
  state = candidate;
  t = Math.min(t, demo.finalTime);
  $("#time").max = String(demo.finalTime);
  $("#time").step = String(candidate.step);
  updateUrl();
  describeRun();
  drawFilmstrip();
  fillTable();
  requestDraw();
  return true;
}

function describeRun() {
  const notes = [];
  const flipped = state.shortest && state.p.reduce((sum, c, i) => sum + c * state.r[i], 0) < 0;
  if (demo.finalTime === 0) notes.push("p is already within ε of the target: nothing to interpolate (r = −p is the same rotation as p).");
  else if (flipped) notes.push("p·r < 0, so the flow goes to −r: the same rotation, by the shorter arc.");
  if (!state.shortest && demo.finalTime > 0) notes.push("Shortest path is off: the flow goes to r itself, possibly the long way round.");
  if (state.integrator === "euler") notes.push("Euler leaves S³: see the |q| drift plot.");
  $("#note").textContent = notes.join(" ");
}

function onFormInput(event) {
  const name = event.target.name ?? "";
  const group = name.slice(0, 2);
  if (name === "preset") return applyPreset(event.target.value);
  field("preset").value = "custom";
  if ((group === "p-" || group === "r-") && /-(ax|ay|az|angle)$/.test(name)) {
    const which = name[0];
    const values = axisAngleInputs(which).map((input) => parseNumber(input.value));
    const bad = values.findIndex((v) => !Number.isFinite(v));
    if (bad >= 0) return showError(which, `${which}: the ${["axis x", "axis y", "axis z", "angle"][bad]} must be a number.`, axisAngleInputs(which));
    try {
      fillQuaternion(which, fromAxisAngle(values.slice(0, 3), (values[3] * Math.PI) / 180));
    } catch (error) {
      return showError(which, `${which}: ${error.message}`, axisAngleInputs(which));
    }
    showError(which, "", axisAngleInputs(which));
  }
  const candidate = readForm();
  if (!candidate) return;
  if (/-(w|x|y|z)$/.test(name)) fillAxisAngle(name[0], candidate[name[0]]);
  apply(candidate);
}

function applyPreset(name) {
  const preset = name === "random"
    ? { ...DEFAULTS, p: randomQuaternion(), r: randomQuaternion() }
    : PRESETS[name] ?? DEFAULTS;
  fillForm(preset);
  const candidate = readForm();
  t = 0;
  if (candidate && apply(candidate) && !reducedMotion()) play();
}

// ---- URL ------------------------------------------------------------------------------------

function updateUrl() {
  if (!state) return;
  const search = writeQuery(state, { t: playing ? undefined : t, embed: query.embed });
  history.replaceState(null, "", search);
  $("#share").href = search;
}

// ---- Time -----------------------------------------------------------------------------------

const reducedMotion = () => matchMedia("(prefers-reduced-motion: reduce)").matches;

function setTime(value) {
  if (!demo) return;
  t = Math.min(Math.max(Number.isNaN(value) ? 0 : value, 0), demo.finalTime);
  requestDraw();
}

function play() {
  if (!demo) return;
  if (t >= demo.finalTime) t = 0;
  playing = true;
  lastFrame = null;
  $("#play").textContent = "Pause";
  requestDraw();
}

function pause() {
  playing = false;
  $("#play").textContent = "Play";
  updateUrl();
  describeFrame();
}

function changeSpeed(direction) {
  const select = $("#speed");
  select.selectedIndex = Math.min(Math.max(select.selectedIndex + direction, 0), select.options.length - 1);
}

// ---- Drawing --------------------------------------------------------------------------------

function requestDraw() {
  if (!drawPending) {
    drawPending = true;
    requestAnimationFrame(frame);
  }
}

function frame(now) {
  drawPending = false;
  if (!demo) return;
  if (playing) {
    if (lastFrame !== null) t += ((now - lastFrame) / 1000) * Number($("#speed").value);
    lastFrame = now;
    if (t >= demo.finalTime) {
      t = demo.finalTime;
      pause();
    }
  }
  render();
  if (playing) requestDraw();
}

/** Draws the views at the current time. */
function render() {
  if (!demo) return;
  const ratio = devicePixelRatio || 1;
  if (sizes.object) demo.drawObject(canvases.object.getContext("2d"), sizes.object.width, sizes.object.height, ratio, t);
  drawLayered("sphere", ratio, (ctx, w, h, k) => demo.drawSphere(ctx, w, h, k, view[0], view[1]),
    (ctx, w, h, k) => demo.drawSphereTime(ctx, w, h, k, t, view[0], view[1]));
  drawLayered("plots", ratio, (ctx, w, h, k) => demo.drawPlots(ctx, w, h, k), (ctx, w, h, k) => demo.drawPlotsTime(ctx, w, h, k, t));
  $("#time").value = String(t);
  $("#time-readout").textContent = `t = ${t.toFixed(2)} / T = ${demo.finalTime.toFixed(2)}`;
  // For the DevTools timeline and `make bench`: when the first complete frame was drawn.
  if (sizes.object && performance.getEntriesByName("kli:first-frame").length === 0) performance.mark("kli:first-frame");
}

/** Copies the still layer of a view (redrawn first if stale) and draws the moving part over it. */
function drawLayered(name, ratio, still, moving) {
  const size = sizes[name];
  if (!size) return;
  const canvas = canvases[name];
  const layer = layers[name];
  if (layer.stale || layer.canvas.width !== canvas.width || layer.canvas.height !== canvas.height) {
    layer.canvas.width = canvas.width;
    layer.canvas.height = canvas.height;
    still(layer.canvas.getContext("2d"), size.width, size.height, ratio);
    layer.stale = false;
  }
  const ctx = canvas.getContext("2d");
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  ctx.drawImage(layer.canvas, 0, 0);
  moving(ctx, size.width, size.height, ratio);
}

function drawFilmstrip() {
  if (demo && sizes.filmstrip) {
    const { width, height } = sizes.filmstrip;
    demo.drawFilmstrip(canvases.filmstrip.getContext("2d"), width, height, devicePixelRatio || 1);
  }
}

/** `a + bi + cj + dk` to 4 decimals, without "−0.0000" for rounding-level negatives. */
function formatQuaternion(q) {
  const rounded = Array.from(q, (c) => (Math.abs(c) < 5e-5 ? 0 : c));
  const terms = ["i", "j", "k"].map((unit, i) => `${rounded[i + 1] < 0 ? "−" : "+"} ${Math.abs(rounded[i + 1]).toFixed(4)}${unit}`);
  return `${rounded[0] < 0 ? "−" : ""}${Math.abs(rounded[0]).toFixed(4)} ${terms.join(" ")}`;
}

function fillTable() {
  const body = $("#moments tbody");
  body.replaceChildren();
  for (const moment of demo.moments) {
    const row = body.insertRow();
    row.insertCell().textContent = moment === demo.finalTime ? `T = ${moment.toFixed(2)}` : String(moment);
    row.insertCell().textContent = formatQuaternion(demo.kliAt(moment));
    row.insertCell().textContent = formatQuaternion(demo.exactAt(moment));
  }
  $("#final-time").textContent =
    `T = ${demo.finalTime.toFixed(2)} after ${demo.steps} steps; the closed form predicts T* = ${demo.predictedTime.toFixed(4)}.`;
}

/** Text for screen readers, refreshed when the animation rests. */
function describeFrame() {
  if (!demo) return;
  canvases.object.setAttribute("aria-label", `The aircraft at t = ${t.toFixed(2)}: KLI rotation ${formatQuaternion(demo.kliAt(t))}; SLERP at the same time ${formatQuaternion(demo.slerpAt(t))}.`);
}

function observeSizes() {
  const observer = new ResizeObserver((entries) => {
    const ratio = devicePixelRatio || 1;
    for (const entry of entries) {
      const canvas = entry.target;
      const name = Object.keys(canvases).find((key) => canvases[key] === canvas);
      const { width, height } = entry.contentRect;
      sizes[name] = { width, height };
      canvas.width = Math.max(1, Math.round(width * ratio));
      canvas.height = Math.max(1, Math.round(height * ratio));
      // The filmstrip is still: it can wait one task, after the first frame of the live views.
      if (name === "filmstrip") setTimeout(drawFilmstrip);
    }
    // Draw now, in the same rendering update as the layout that sized the canvases, rather than
    // a frame later: the first view appears one frame sooner and a resize never shows blank.
    render();
  });
  Object.values(canvases).forEach((canvas) => observer.observe(canvas));
}

// ---- Input devices --------------------------------------------------------------------------

/** Turns the sphere view by (azimuth, elevation) radians; elevation stays within ±89°. */
function turnSphere(azimuth, elevation) {
  view[0] += azimuth;
  view[1] = Math.min(Math.max(view[1] + elevation, -1.55), 1.55);
  refreshLayers("sphere");
  requestDraw();
}

function wireControls() {
  form.addEventListener("input", onFormInput);
  form.addEventListener("change", (event) => {
    if (event.target.type === "checkbox" || event.target.tagName === "SELECT") onFormInput(event);
  });
  form.addEventListener("submit", (event) => event.preventDefault());
  $("#play").addEventListener("click", () => (playing ? pause() : play()));
  $("#restart").addEventListener("click", () => {
    t = 0;
    reducedMotion() ? requestDraw() : play();
  });
  $("#time").addEventListener("input", (event) => {
    if (playing) pause();
    setTime(Number(event.target.value));
    updateUrl();
  });

  document.addEventListener("keydown", (event) => {
    const tag = event.target.tagName;
    if ((tag === "INPUT" && event.target.type !== "range") || tag === "SELECT" || tag === "TEXTAREA" || event.ctrlKey || event.metaKey || event.altKey) return;
    const sphereFocused = event.target === canvases.sphere;
    const stride = (event.shiftKey ? 10 : 1) * Math.max(state?.step ?? 0.01, demo ? demo.finalTime / 200 : 0.05);
    const turn = (5 * Math.PI) / 180;
    const actions = {
      " ": () => (playing ? pause() : play()),
      Home: () => { t = 0; requestDraw(); },
      End: () => { pause(); setTime(Infinity); },
      ArrowLeft: () => (sphereFocused ? turnSphere(turn, 0) : (pause(), setTime(t - stride))),
      ArrowRight: () => (sphereFocused ? turnSphere(-turn, 0) : (pause(), setTime(t + stride))),
      ArrowUp: () => sphereFocused && turnSphere(0, turn),
      ArrowDown: () => sphereFocused && turnSphere(0, -turn),
      "+": () => changeSpeed(1),
      "=": () => changeSpeed(1),
      "-": () => changeSpeed(-1),
    };
    const action = actions[event.key];
    if (!action || (tag === "INPUT" && !(event.key in { " ": 1, Home: 1, End: 1 }))) return;
    event.preventDefault();
    action();
    requestDraw();
  });

  let drag = null;
  canvases.sphere.addEventListener("pointerdown", (event) => {
    drag = { x: event.clientX, y: event.clientY };
    canvases.sphere.setPointerCapture(event.pointerId);
  });
  canvases.sphere.addEventListener("pointermove", (event) => {
    if (!drag) return;
    turnSphere(-(event.clientX - drag.x) * 0.01, (event.clientY - drag.y) * 0.01);
    drag = { x: event.clientX, y: event.clientY };
  });
  const endDrag = () => (drag = null);
  canvases.sphere.addEventListener("pointerup", endDrag);
  canvases.sphere.addEventListener("pointercancel", endDrag);
}

// ---- Start ----------------------------------------------------------------------------------

/** The URL's values in the form; groups that are missing come from the defaults. */
function startingForm() {
  fillForm(DEFAULTS);
  if (query.p) quaternionInputs("p").forEach((input, i) => (input.value = query.p[i] ?? ""));
  if (query.r) quaternionInputs("r").forEach((input, i) => (input.value = query.r[i] ?? ""));
  if (query.eps !== undefined) field("eps").value = query.eps;
  if (query.step !== undefined) field("step").value = query.step;
  if (query.integrator) field("integrator").value = query.integrator;
  if (query.shortest !== undefined) field("shortest").checked = query.shortest;
  if (query.p?.length > 4 || query.r?.length > 4) {
    if (query.p?.length > 4) showError("p", "p: the URL gives more than 4 numbers.", quaternionInputs("p"));
    if (query.r?.length > 4) showError("r", "r: the URL gives more than 4 numbers.", quaternionInputs("r"));
  }
  const fromUrl = readForm();
  if (fromUrl) {
    fillAxisAngle("p", fromUrl.p);
    fillAxisAngle("r", fromUrl.r);
  }
  const matches = Object.entries(PRESETS).find(([, preset]) => JSON.stringify(preset) === JSON.stringify(fromUrl ?? {}));
  field("preset").value = matches ? matches[0] : "custom";
}

async function start() {
  try {
    await init();
  } catch (error) {
    $("#load-status").textContent = `The WebAssembly module could not be loaded: ${error.message}`;
    $("#load-status").classList.add("error");
    return;
  }
  performance.mark("kli:wasm-ready");
  if (query.embed) document.body.classList.add("embed");
  view = Array.from(Demo.defaultSphereView());
  wireControls();
  startingForm();
  const fromUrl = readForm();
  const tooLong = query.p?.length > 4 || query.r?.length > 4;
  if (!fromUrl || tooLong || !apply(fromUrl)) {
    // Show the messages, and the paper's example beside them.
    const messages = ["p", "r", "eps", "step", "shortest"].map((id) => [id, $(`#${id}-error`).textContent]);
    apply(DEFAULTS);
    for (const [id, message] of messages) if (message) $(`#${id}-error`).textContent = message;
  }
  $("#load-status").textContent = "";
  $("#load-status").hidden = true;
  observeSizes();
  if (Number.isFinite(query.t)) setTime(query.t);
  else if (!reducedMotion()) play();
  describeFrame();
  // Offline support is registered once the page has settled, not on the way to the first frame.
  if ("serviceWorker" in navigator && location.protocol !== "file:") {
    const register = () => setTimeout(() => navigator.serviceWorker.register("sw.js").catch(() => {}));
    if (document.readyState === "complete") register();
    else addEventListener("load", register, { once: true });
  }
}

start();
