// @ts-check
// The tour (learn.html): a descriptor for the page runtime (runtime.js) whose one run holds every
// section's figure (crates/kli-demo/src/learn/), the text that quotes the figures' values as they
// change, the exercises' links that set a figure to the state they ask about, the clock started
// from 0 as each moving figure comes into view (never with reduced motion), and the live figures of the
// other pages (<kli-figure>), loaded only as their section nears the screen. Its words are in
// strings/ (en.js, bs.js: `?lang=bs`), put in place before the runtime reads the page.
import * as learn from "../pkg/learn_demo.js";
import { LearnDemo } from "../pkg/learn_demo.js";
import { $ } from "../runtime/dom.js";
import { page as registered } from "../pages.js";
import { Player } from "../runtime/player.js";
import { Page } from "../runtime/runtime.js";
import { lang, strings, translate } from "./strings/index.js";
import { LEARN } from "./state.js";

/** @typedef {import("./state.js").LearnState} LearnState */
/** @typedef {import("../runtime/runtime.js").Host<LearnState, LearnDemo>} Host */

const { live } = strings;
translate(strings, registered("learn"));
const SUPERSCRIPT = /** @type {Record<string, string>} */ ({ "-": "⁻", 0: "⁰", 1: "¹", 2: "²", 3: "³", 4: "⁴", 5: "⁵", 6: "⁶", 7: "⁷", 8: "⁸", 9: "⁹" });
const power = (/** @type {number} */ digits) => `10${`-${digits}`.replace(/./g, (c) => SUPERSCRIPT[c] ?? c)}`;
const fixed = (/** @type {number} */ x, /** @type {number} */ digits) => x.toFixed(digits).replace(/^-(?=0\.0*$)/, "").replace("-", "−");
/** [w, x, y, z] as "w + x i + y j + z k", three decimals. */
const quaternion = (/** @type {ArrayLike<number>} */ q) => {
  const part = (/** @type {number} */ x, /** @type {string} */ unit) => `${x < -5e-4 ? " − " : " + "}${Math.abs(x).toFixed(3)} ${unit}`;
  return `${fixed(q[0], 3)}${part(q[1], "i")}${part(q[2], "j")}${part(q[3], "k")}`;
};
const vector = (/** @type {ArrayLike<number>} */ v) => `(${Array.from(v, (c) => fixed(Math.abs(c) < 5e-4 ? 0 : c, 3)).join(", ")})`;

/** Each slider's value in words (strings' `live.values`), beside it and for a screen reader (`aria-valuetext`). */
const VALUES = /** @type {Record<string, (value: number, state: LearnState) => string>} */ ({
  yaw: (v) => live.values.yaw(String(v)),
  pitch: (v) => live.values.pitch(String(v)),
  bank: (v) => live.values.bank(String(v)),
  angle: (v, state) => live.values.angle(String(v), live.axes[/** @type {keyof typeof live.axes} */ (state.axis)] ?? state.axis),
  s: (v) => `s = ${v.toFixed(2)}`,
  roll: (v) => live.values.roll(String(v)),
  coupling: (v) => `K = ${v}`,
  lohe: (v) => `K = ${v}`,
  digits: (v) => `ε = ${power(v)}`,
  delta: (v) => `δ = ${v}`,
  step: (v) => `h = ${v}`,
  smoothness: (v) => live.figures.smoothness(String(v)),
});

/** The views whose canvas is near the screen (within 400 px). A view far from it keeps its first
 *  picture, which is that view at the tour's start, until it comes near: a long article sets up
 *  only the figures a reader is about to see (twelve views drawn at load were most of the load's
 *  work). Once the reader changes a control, the runtime draws every view again. */
const near = new Set();

/** @type {Page<LearnState, LearnDemo>} */
const page = new Page({
  entry: registered("learn"),
  module: learn,
  // The words the module draws, from the strings (English or Bosnian).
  create: (module, state) => new module.LearnDemo({ ...state, words: strings.canvas }),
  words: strings.runtime,
  message: (error) => (lang === "en" ? undefined : refused(error)),
  form: "#learn-inputs",
  readout: (run, t) => {
    quoteTime(run, t);
    return `t = ${t.toFixed(2)} / ${run.span[1].toFixed(2)}`;
  },
  labels: (run, t) => {
    const now = run.readings(t);
    const { finalTime, steps } = run.summary;
    const at = t.toFixed(2);
    return {
      phases: live.labels.phases({ t: at, order: now.order.toFixed(3) }),
      lohe: live.labels.lohe({ t: at, spread: now.spreadDegrees.toFixed(1) }),
      kli: live.labels.kli({ t: at, phi: now.phiDegrees.toFixed(2) }),
      clock: live.labels.clock({ t: at, s: now.s.toFixed(3) }),
      steps: live.labels.steps({ steps: String(steps), T: finalTime.toFixed(2) }),
    };
  },
  data: { file: (run) => `kli-tour-algorithm-1-eps-${run.summary.epsilon.toExponential(0)}` },
  file: (run, view, t) => `kli-tour-${view}${["phases", "lohe", "kli", "clock", "steps"].includes(view) ? `-t${t.toFixed(2)}` : ""}`,
  stride: () => 0.01,
  waiting: (run, view) => !near.has(view),
  video: {
    views: ["kli", "clock"],
    title: () => live.video,
    file: () => "kli-tour-kli",
  },
  shown: (host, run, state) => {
    showValues(host);
    quoteSummary(run, state);
    quoteTime(run, host.t);
    // The keyframes figure beside the turning rate shows the keys that rate is computed through
    // (the module's) at the same smoothness.
    const figure = document.getElementById("fig-keyframes");
    const keys = run.summary.rates.keys;
    const attributes = { keys: [0, 4, 8, 12].map((i) => keys.slice(i, i + 4).join(",")).join(";"), smoothness: String(state.smoothness) };
    for (const [name, value] of Object.entries(attributes)) if (figure?.getAttribute(name) !== value) figure?.setAttribute(name, value);
  },
  // The other pages' figures' sliders (section 9, no name) are theirs: the tour's run is not rebuilt.
  input: (host, name) => {
    if (!name) return true;
    showValues(host);
    return false;
  },
  wire: (host) => wireTour(host),
});

/** An Error of the module about a value of the URL, in the page's language (by the key it names; the
 *  value it got is the one in its message's "(got …)", or the runtime's own, already in the page's words);
 *  undefined for any other. */
function refused(/** @type {unknown} */ error) {
  const key = LEARN.keyOf(error);
  const got = /\((?:got|dato je) (.*)\)$/.exec(error instanceof Error ? error.message : "")?.[1] ?? "?";
  if (key === "axis" || key === "integrator" || key === "digits") return live.refused[key](got);
  const range = LEARN.schema.find((entry) => entry.key === key && "range" in entry);
  if (!range || !("range" in range)) return undefined;
  const [min, max] = range.range.map(String);
  const label = document.querySelector(`[name="${key}"]`)?.closest("label")?.querySelector("span")?.textContent ?? key;
  return `${label}: ${live.refused.number(min, max, got)}`;
}

/** The sliders' values beside them, and in words for a screen reader. */
function showValues(/** @type {Host} */ host) {
  const state = host.read();
  for (const [name, words] of Object.entries(VALUES)) {
    const field = host.field(name);
    const value = Number(field.value);
    const text = words(value, state);
    field.setAttribute("aria-valuetext", text);
    $(`#${name}-value`, HTMLOutputElement).textContent = text;
  }
}

/** The values the text quotes that follow the controls alone. */
function quoteSummary(/** @type {LearnDemo} */ run, /** @type {LearnState} */ state) {
  const s = run.summary;
  $("#lock-out", HTMLOutputElement).textContent = `${s.lockDegrees.toFixed(1)}°`;
  $("#turn-out", HTMLOutputElement).textContent = `q = ${quaternion(s.turn)}`;
  $("#cover-out", HTMLOutputElement).textContent = `θ = ${state.angle}°, q = ${quaternion(s.turn)}`;
  $("#slerp-out", HTMLOutputElement).textContent =
    live.slerp({ s: state.s.toFixed(2), slerp: s.slerpDegrees.toFixed(2), nlerp: s.nlerpDegrees.toFixed(2) });
  $("#hopf-out", HTMLOutputElement).textContent = live.hopf({ nose: vector(s.nose), wing: vector(s.wing) });
  const d = s.drift;
  const e = (/** @type {number} */ x) => x.toExponential(1);
  $("#drift-out", HTMLOutputElement).textContent =
    live.drift({ h: String(state.step), euler: e(d.euler), rk4: e(d.rk4), geodesic: e(d.geodesic) });
  const r = s.rates;
  const rates = {
    s: String(state.smoothness), key: String(r.jumpKey), jump: r.jump.toFixed(2), acceleration: r.acceleration.toFixed(1),
    slerpKey: String(r.slerpJumpKey), slerpJump: r.slerpJump.toFixed(2),
  };
  $("#rates-out", HTMLOutputElement).textContent = r.continuous ? live.rates.smooth(rates) : live.rates.jump(rates);
}

/** The values the text quotes that follow the clock. */
function quoteTime(/** @type {LearnDemo} */ run, /** @type {number} */ t) {
  const now = run.readings(t);
  const s = run.summary;
  const at = t.toFixed(2);
  $("#phases-out", HTMLOutputElement).textContent = live.phases({ t: at, order: now.order.toFixed(3) });
  $("#lohe-out", HTMLOutputElement).textContent =
    live.lohe({ t: at, order: now.swarmOrder.toFixed(3), spread: now.spreadDegrees.toFixed(1) });
  $("#kli-out", HTMLOutputElement).textContent =
    live.kli({ t: at, phi: now.phiDegrees.toFixed(2), s: now.s.toFixed(3), q: quaternion(now.q) });
  $("#steps-out", HTMLOutputElement).textContent = live.steps({
    n: String(now.step), t: now.stepTime.toFixed(2), distance: now.distance.toExponential(2),
    epsilon: power(Math.round(-Math.log10(s.epsilon))), delta: String(page.host.state.delta), steps: String(s.steps),
    T: s.finalTime.toFixed(2), predicted: s.predictedTime.toFixed(4),
  });
  $("#time", HTMLInputElement).setAttribute("aria-valuetext", live.time(at, String(run.span[1])));
}

/** Plays the clock from 0 (a reader's press: reduced motion asks only that nothing starts by itself). */
function playFromStart(/** @type {Host} */ host) {
  host.seek(0);
  if (!page.playing) page.play();
}

/** The last figure before `element` in its section, or null: walking back from it, a figure
 *  among the siblings or within one.
 *  @returns {Element | null} */
function figureBefore(/** @type {Element | null} */ element) {
  for (let at = element?.previousElementSibling; at; at = at.previousElementSibling) {
    if (at.matches("figure")) return at;
    const inside = at.querySelectorAll("figure");
    if (inside.length) return inside[inside.length - 1];
  }
  const parent = element?.parentElement;
  return parent && !parent.matches("section") ? figureBefore(parent) : null;
}

/** The exercises' links, the buttons of the clock, printing with the answers, and the figures'
 *  own start as they come into view. */
function wireTour(/** @type {Host} */ host) {
  for (const link of document.querySelectorAll("a.set")) {
    link.addEventListener("click", (event) => {
      const a = /** @type {HTMLAnchorElement} */ (link);
      event.preventDefault();
      const state = a.dataset.state ? JSON.parse(a.dataset.state) : {};
      if (Object.keys(state).length) host.apply({ ...host.state, ...state });
      if (a.dataset.t !== undefined) host.seek(Number(a.dataset.t));
      if (a.dataset.play) playFromStart(host);
      // An exercise's link changes the figure above it, often off screen by then: bring it in.
      const figure = a.closest("details.exercise") ? figureBefore(a.closest("details.exercise")) : null;
      const box = figure?.getBoundingClientRect();
      if (figure && box && (box.bottom < 0 || box.top > innerHeight)) {
        const still = matchMedia("(prefers-reduced-motion: reduce)").matches;
        figure.scrollIntoView({ block: "center", behavior: still ? "auto" : "smooth" });
      }
    });
  }
  for (const button of document.querySelectorAll("button.play-from")) {
    button.addEventListener("click", () => playFromStart(host));
  }
  const step = (/** @type {number} */ by) => host.seek(Math.round((host.t + by * host.state.delta) * 1e6) / 1e6);
  $("#step-on", HTMLButtonElement).addEventListener("click", () => step(1));
  $("#step-back", HTMLButtonElement).addEventListener("click", () => step(-1));
  // Printed as a handout: each exercise's question stays in its section (a closed <details> prints
  // its summary alone) and the answers come together at the end, numbered, so that a student can
  // predict before turning the page.
  /** @type {HTMLDetailsElement[]} */
  let closed = [];
  addEventListener("beforeprint", () => {
    document.querySelector("#print-answers")?.remove();
    closed = [...document.querySelectorAll("details.exercise[open]")].map((d) => /** @type {HTMLDetailsElement} */ (d));
    closed.forEach((d) => (d.open = false));
    const section = Object.assign(document.createElement("section"), { id: "print-answers", className: "print-answers" });
    const heading = Object.assign(document.createElement("h2"), { textContent: live.answers });
    const list = document.createElement("ol");
    for (const [index, exercise] of document.querySelectorAll("details.exercise").entries()) {
      const summary = exercise.querySelector("summary");
      if (summary) summary.dataset.number = `${index + 1}.`;
      const item = document.createElement("li");
      const question = Object.assign(document.createElement("p"), { className: "question", textContent: summary?.textContent ?? "" });
      item.append(question, ...[...exercise.children].filter((child) => child !== summary).map((child) => child.cloneNode(true)));
      // On paper the answer needs no press: its box gives way to what it holds.
      for (const box of item.querySelectorAll("details.answer")) {
        box.replaceWith(...[...box.children].filter((child) => child.tagName !== "SUMMARY"));
      }
      // The copies are for paper: no second set of ids, no controls.
      for (const node of item.querySelectorAll("[id]")) node.removeAttribute("id");
      for (const node of item.querySelectorAll("a.set, button")) node.remove();
      list.append(item);
    }
    section.append(heading, list);
    document.querySelector("main")?.append(section);
  });
  addEventListener("afterprint", () => {
    document.querySelector("#print-answers")?.remove();
    closed.forEach((d) => (d.open = true));
  });
  startOnArrival(host);
  loadOtherFigures();
}

/** A moving figure (the phases, the swarm on S³, KLI) starts the clock from 0 each time it comes
 *  into view after another of them was the last to start it, so the reader always meets it in
 *  mid-flow (the shared clock would otherwise have run on, in the section before, to its end);
 *  never with reduced motion. Coming back to the one that started last leaves the clock alone. */
function startOnArrival(/** @type {Host} */ host) {
  if (Player.reducedMotion()) return;
  /** @type {Element | null} */
  let last = null;
  const observer = new IntersectionObserver((entries) => {
    for (const entry of entries) {
      if (!entry.isIntersecting || entry.target === last) continue;
      last = entry.target;
      playFromStart(host);
    }
  }, { threshold: 0.6 });
  for (const id of ["#learn-phases", "#learn-lohe", "#learn-kli"]) observer.observe($(id, HTMLCanvasElement));
}

/** Where each of the other pages' figures stands with reduced motion: the swarm gathered; the
 *  keyframes between k2 and k3 (its keys at t = 0 … 3), where the three curves' points are apart
 *  (at its end they all sit on k3); the others at t = 4. */
const STILL_AT = /** @type {Record<string, string>} */ ({ "fig-swarm": "8", "fig-keyframes": "2.5" });

/** The other pages' figures (<kli-figure>, each loading its page's module) are defined only as
 *  their section nears the screen; each plays (and rests off screen) unless motion is reduced.
 *  Until then (and with no script) each shows a link to its page. */
function loadOtherFigures() {
  const section = $("#many", HTMLElement);
  // A single-file copy of the tour (make single) holds its own module alone: from file:// the
  // other pages' modules are not there to load, and their figures stay links to their pages.
  if (location.protocol === "file:") {
    section.querySelectorAll(".figure-control").forEach((control) => control.remove());
    return;
  }
  const observer = new IntersectionObserver((entries) => {
    if (!entries.some((entry) => entry.isIntersecting)) return;
    observer.disconnect();
    const still = Player.reducedMotion();
    for (const figure of section.querySelectorAll("kli-figure")) {
      if (still) figure.setAttribute("t", STILL_AT[figure.id] ?? "4");
      else figure.setAttribute("autoplay", "");
    }
    import("../kli-figure.js");
  }, { rootMargin: "600px" });
  observer.observe(section);
  const set = (/** @type {string} */ id, /** @type {string} */ attribute, /** @type {string} */ value) => {
    document.getElementById(id)?.setAttribute(attribute, value);
    const slider = /** @type {HTMLInputElement | null} */ (section.querySelector(`input[data-figure="${id}"]`));
    if (slider) {
      slider.value = value;
      const said = words(attribute, Number(value));
      slider.setAttribute("aria-valuetext", said);
      // The same words in sight, as every other slider of the tour shows its value.
      const shown = slider.closest("label")?.nextElementSibling;
      if (shown?.matches("output.figure-value")) shown.textContent = said;
    }
  };
  for (const slider of section.querySelectorAll("input[data-figure]")) {
    const input = /** @type {HTMLInputElement} */ (slider);
    input.addEventListener("input", () => set(String(input.dataset.figure), String(input.dataset.attribute), input.value));
  }
  for (const button of section.querySelectorAll("button.set-figure")) {
    const b = /** @type {HTMLButtonElement} */ (button);
    b.addEventListener("click", () => set(String(b.dataset.figure), String(b.dataset.attribute), String(b.dataset.value)));
  }
}

/** A figure control's value in words. */
function words(/** @type {string} */ attribute, /** @type {number} */ value) {
  if (attribute === "outliers") return live.figures.outliers(String(Math.round(value * 100)));
  if (attribute === "wrong") return live.figures.wrong(String(Math.round(value * 100)));
  if (attribute === "coupling") return `K = ${value}`;
  return live.figures.smoothness(String(value));
}

/** Each canvas that comes near the screen joins `near` and is drawn. */
const nearing = new IntersectionObserver((entries) => {
  const came = [];
  for (const entry of entries) {
    const view = /** @type {HTMLElement} */ (entry.target).dataset.view ?? "";
    if (entry.isIntersecting && !near.has(view)) {
      near.add(view);
      came.push(view);
    }
  }
  if (came.length && page.host.run) page.host.redraw(came);
}, { rootMargin: "400px" });
for (const [view, selector] of Object.entries(registered("learn").canvases)) {
  const canvas = $(selector, HTMLCanvasElement);
  canvas.dataset.view = view;
  nearing.observe(canvas);
}

// The runtime plays a page as it opens; the tour's clock waits until a moving figure is in view.
page.start().then((ready) => {
  if (ready) page.host.seek(0);
});
