// @ts-check
// <kli-figure>: one figure of the demo in any page, configured in the markup and sized by CSS.
//
//   <script type="module" src="kli-figure.js"></script>
//   <kli-figure view="hopf" p="0,0,0,1" r="0.5,0.5,0.5,0.5" autoplay></kli-figure>
//
// Views: "object", "hopf", "plots", "filmstrip" (KLI from p to r), "keyframes" (the three curves
// through `keys`), "swarm" (a LoheSwarm's Hopf points). Each page module is loaded once, when the
// first figure that needs it appears, and shared by every figure on the page. Every attribute is
// live: change one and the figure is rebuilt. Computing, checking and drawing are the modules'.

import { Camera } from "./camera.js";
import { Figures } from "./figures.js";
import { parseNumber } from "./numbers.js";
import { DEFAULTS as KLI_DEFAULTS } from "./presets.js";
import { parseText } from "./schema.js";
import { STATES } from "./states.js";
import { PAGES, pageOfView } from "./pages.js";
import { wirePrinting } from "./print.js";
import { record } from "./video/panel.js";

const VIEWS = PAGES.flatMap((page) => Object.keys(page.views));
/** A state key as an attribute: `shortestPath` → `shortest-path`. */
const attributeName = (/** @type {string} */ key) => key.replace(/[A-Z]/g, (c) => `-${c.toLowerCase()}`);
/** The figure's own attributes, then each page state's keys (states.js), read as the pages read
 *  their URL (schema.js). */
const ATTRIBUTES = ["view", "t", "autoplay", "speed", "label", "text-scale", "print-t",
  ...new Set(Object.values(STATES).flatMap((state) => state.schema.map((entry) => attributeName(entry.key))))];
/** What a figure shows when its attributes do not say. */
const DEFAULTS = {
  kli: KLI_DEFAULTS,
  keyframes: { keys: [[1, 0, 0, 0], [0.8, 0.6, 0, 0], [0.6, 0, 0.8, 0], [0, 0, 0.6, 0.8]], times: [], smoothness: 1 },
  swarm: { count: 200, coupling: 1, seed: 1 },
};
const SWARM_DT = 0.02;
/** Oscillator steps a task may take (about 45 ms in Chromium, all to all): a swarm figure
 *  reaches its `t` in tasks of this size, and plays at most this much a frame. */
const SWARM_WORK = 5e5;
/** The largest `t` and `speed` a figure takes. */
const MAX_T = 1e6, MAX_SPEED = 1000;

/** Each page's module, loaded when the first figure that needs it appears: one static import
 *  each, so that bundlers (`make single`) find them; one a page of pages.js. */
const MODULES = {
  kli: () => import("./pkg/kli_demo.js"),
  keyframes: () => import("./pkg/keyframes_demo.js"),
  swarm: () => import("./pkg/swarm_demo.js"),
};
/** @type {Map<string, Promise<any>>} each page module, initialised once for the whole page */
const loaded = new Map();
function load(/** @type {keyof typeof MODULES} */ name) {
  let module = loaded.get(name);
  if (!module) {
    module = MODULES[name]().then(async (m) => {
      await m.default();
      return m;
    });
    loaded.set(name, module);
  }
  return module;
}


const STYLE = `
:host { display: block; position: relative; aspect-ratio: 4 / 3; min-height: 120px; contain: content; }
:host([view="filmstrip"]) { aspect-ratio: 5 / 1; }
:host([view="plots"]) { aspect-ratio: 3 / 1; }
canvas { display: block; width: 100%; height: 100%; }
.print-figure { height: 100%; }
p { position: absolute; inset: auto 0 0 0; margin: 0; padding: 4px 8px; font: .85rem system-ui, sans-serif;
    color: #a61e1e; background: #fff; }
p:empty { display: none; }`;

export class KliFigure extends HTMLElement {
  static observedAttributes = ATTRIBUTES;

  constructor() {
    super();
    const root = this.attachShadow({ mode: "open" });
    const style = document.createElement("style");
    style.textContent = STYLE;
    this.canvas = document.createElement("canvas");
    this.canvas.setAttribute("role", "img");
    this.message = document.createElement("p");
    this.message.setAttribute("role", "status");
    root.append(style, this.canvas, this.message);
    this.root = root;
    /** @type {any} the module's Demo, KeyframesDemo or SwarmDemo */
    this.demo = null;
    this.t = 0;
    this.speed = 1;
    /** Swarm steps still to take to reach `t` (catchUp). */
    this.pending = 0;
    /** @type {Figures<string> | null} */
    this.figures = null;
    this.frame = 0;
    this.last = 0;
    this.visible = true;
    this.built = 0;
    /** A pending look at whether a figure hidden by style can be seen again. */
    this.recheck = 0;
    /** @type {{ show(): void, remove(): void, dispose(): void } | null} printing as SVG, while connected */
    this.printing = null;
    // Off screen, an animated figure stops asking for frames. The browser may deliver several
    // entries at once (hidden, then shown, on a slide that appears): the last one is the news.
    this.intersection = new IntersectionObserver((entries) => {
      this.visible = entries[entries.length - 1].isIntersecting;
      if (this.visible) this.figures?.sizing?.refit(false);
      this.schedule();
    });
  }

  connectedCallback() {
    this.intersection.observe(this);
    this.rebuild();
  }

  disconnectedCallback() {
    clearTimeout(this.recheck);
    this.printing?.dispose();
    this.printing = null;
    this.figures?.sizing?.disconnect();
    this.figures = null;
    this.intersection.disconnect();
    cancelAnimationFrame(this.frame);
    this.frame = 0;
    this.demo?.free();
    this.demo = null;
  }

  attributeChangedCallback() {
    if (this.isConnected) this.rebuild();
  }

  /** The `view` attribute, checked. */
  get kind() {
    return this.getAttribute("view") ?? "hopf";
  }

  get playing() {
    return this.hasAttribute("autoplay") && !matchMedia("(prefers-reduced-motion: reduce)").matches;
  }

  /** Builds the figure's run from its attributes; a refused attribute is shown in the figure. */
  async rebuild() {
    const build = ++this.built;
    const view = this.kind;
    const page = pageOfView(view);
    if (!page) return this.fail(`view must be one of ${VIEWS.join(", ")} (got "${view}")`);
    let module;
    try {
      module = await load(/** @type {keyof typeof MODULES} */ (page.name));
    } catch (error) {
      return this.fail(`the WebAssembly module could not be loaded: ${error instanceof Error ? error.message : error}`);
    }
    if (build !== this.built || !this.isConnected) return; // a newer rebuild is under way
    let demo;
    try {
      demo = this.create(module, /** @type {keyof typeof STATES} */ (page.name));
    } catch (error) {
      return this.fail(error instanceof Error ? error.message : String(error));
    }
    this.demo?.free();
    this.demo = demo;
    /** @type {number | undefined} */
    this.finalTime = undefined;
    this.figures?.sizing?.disconnect();
    const moduleView = page.views[view];
    this.figures = new Figures({ [moduleView]: this.canvas }, { layered: page.layered, still: page.still });
    this.figures.camera = new Camera(module.defaultCamera());
    const scale = this.getAttribute("text-scale");
    this.figures.scaleText(scale === null ? 1 : parseNumber(scale));
    // Printed (or a deck's PDF): the figure as vector, at `print-t` (else its time now).
    this.printing ??= wirePrinting(() => this.figures, () => this.printTime, {}, this.root);
    this.figures.show(demo);
    this.figures.observe(() => this.draw());
    this.message.textContent = "";
    const t = this.getAttribute("t"), speed = this.getAttribute("speed");
    this.t = t === null ? 0 : parseNumber(t);
    this.speed = speed === null ? 1 : parseNumber(speed);
    if (!(this.t >= 0 && this.t <= MAX_T)) return this.fail(`t must be a number from 0 to ${MAX_T} (got "${t}")`);
    if (!(this.speed >= 0 && this.speed <= MAX_SPEED)) return this.fail(`speed must be a number from 0 to ${MAX_SPEED} (got "${speed}")`);
    this.describe();
    // A swarm runs to its `t` in tasks of bounded work, drawn when it gets there.
    this.pending = view === "swarm" ? Math.round(this.t / SWARM_DT) : 0;
    if (this.pending > 0) {
      setTimeout(() => this.catchUp(build));
      return;
    }
    this.draw();
    this.schedule();
  }

  /** The swarm's steps towards its `t`, a task at a time (each at most SWARM_WORK oscillator
   *  steps), saying how far it has got. */
  catchUp(/** @type {number} */ build) {
    if (build !== this.built || !this.demo) return;
    const steps = Math.min(this.pending, this.swarmSteps(Infinity));
    if (!this.stepSwarm(steps)) return;
    this.pending -= steps;
    if (this.pending > 0) {
      this.message.textContent = `Running the swarm to t = ${this.t}: ${Math.floor(100 * (1 - this.pending * SWARM_DT / this.t))}%`;
      this.figures?.render(this.demo.time); // where it has got to
      setTimeout(() => this.catchUp(build));
      return;
    }
    this.message.textContent = "";
    this.t = this.demo.time;
    this.draw();
    this.schedule();
  }

  /** Steps for a swarm frame of `dt`, at most SWARM_WORK oscillator steps. */
  swarmSteps(/** @type {number} */ dt) {
    const budget = Math.max(1, Math.floor(SWARM_WORK / this.demo.count));
    return Math.min(budget, Math.max(1, Math.round(dt / SWARM_DT)));
  }

  /** `steps` swarm steps; a refusal is shown in the figure (false), never thrown each frame. */
  stepSwarm(/** @type {number} */ steps) {
    try {
      this.demo.step(SWARM_DT, steps);
      return true;
    } catch (error) {
      this.fail(error instanceof Error ? error.message : String(error));
      return false;
    }
  }

  /** The module's object for the page `name`, from the attributes over the defaults, read as
   *  the page reads its URL (its constructor checks them). */
  create(/** @type {any} */ module, /** @type {keyof typeof STATES} */ name) {
    /** @type {Record<string, any>} */
    const state = { ...DEFAULTS[name] };
    for (const { key, kind } of STATES[name].schema) {
      const text = this.getAttribute(attributeName(key));
      if (text !== null) state[key] = parseText(kind, text);
    }
    return STATES[name].create(module, /** @type {any} */ (state));
  }

  fail(/** @type {string} */ text) {
    this.demo?.free();
    this.demo = null;
    this.figures?.sizing?.disconnect();
    this.figures = null;
    this.message.textContent = `kli-figure: ${text}`;
    this.canvas.setAttribute("aria-label", this.message.textContent);
    const context = this.canvas.getContext("2d");
    context?.clearRect(0, 0, this.canvas.width, this.canvas.height);
    this.dispatchEvent(new CustomEvent("kli-error", { detail: text }));
  }

  /** The time a printed figure shows: `print-t`, else the figure's time now. */
  get printTime() {
    // A `print-t` that is not a number prints the time now, as no `print-t` does.
    const asked = parseNumber(this.getAttribute("print-t") ?? "");
    return Math.min(Number.isFinite(asked) ? asked : this.t, this.end);
  }

  /**
   * The figure as an SVG document at time `t` (default: its time now).
   * @param {number} [t]
   */
  toSvg(t = this.t) {
    const [entry] = this.figures?.svgs(Math.min(t, this.end)) ?? [];
    if (!entry) throw new Error("kli-figure: the figure is not built or not laid out yet");
    return entry[1];
  }

  /**
   * The figure's animation as a video (MP4 H.264, WebM VP9) or animated GIF, each frame drawn
   * for its own time: over [from, to] (default: the whole run) in `seconds` (default: the run's
   * span at 1×, 1 to 60 s), at 720p or 1080p and 30 or 60 frames a second.
   * @param {{ format?: "mp4" | "webm" | "gif", size?: "720p" | "1080p", fps?: number, from?: number, to?: number,
   *   seconds?: number, title?: string, signal?: AbortSignal, progress?: (done: number, total: number) => void }} [options]
   * @returns {Promise<{ blob: Blob, name: string, frames: number }>}
   */
  async toVideo(options = {}) {
    const figures = this.figures, demo = this.demo;
    if (!figures || !demo) throw new Error("kli-figure: the figure is not built yet");
    const [view] = Object.keys(figures.canvases);
    const swarm = this.kind === "swarm";
    const start = this.kind === "keyframes" ? demo.startTime : 0;
    const span = /** @type {[number, number] | null} */ (swarm ? null : [start, this.end]);
    const seconds = options.seconds ?? (span ? Math.min(60, Math.max(1, span[1] - span[0])) : 10);
    return record({
      figures, views: [view], chosen: [view], spanned: !swarm, span: () => span,
      advance: () => this.stepSwarm(this.swarmSteps(SWARM_DT * 2)),
      now: () => (swarm ? demo.time : this.t),
      title: () => options.title ?? this.getAttribute("label") ?? this.canvas.getAttribute("aria-label") ?? "",
      file: () => `kli-${this.kind}`,
      textScale: () => figures.textScale,
    }, { format: options.format ?? "mp4", size: options.size ?? "720p", fps: options.fps ?? 30, views: [view],
      from: options.from, to: options.to, seconds, signal: options.signal, progress: options.progress });
  }

  /** The canvas's text alternative: the `label` attribute, or what the figure shows. */
  describe() {
    const view = this.kind;
    const label = this.getAttribute("label");
    const what = {
      object: "The object turning from p to r under KLI and under SLERP",
      hopf: "The Hopf curves of KLI and SLERP on the sphere S²",
      plots: "Distance to r, KLI's SLERP parameter s(t) beside SLERP's u = t/T, and the drift of |q| over time",
      filmstrip: "The object at the moments of the paper's Table 1",
      keyframes: "The Hopf curves of the Kuramoto–Lohe chain, Squad and piecewise SLERP through the keys",
      swarm: "The swarm's oscillators as points on the sphere S²",
    }[view];
    this.canvas.setAttribute("aria-label", label ?? what ?? view);
  }

  /** The time span of the figure's animation. */
  get end() {
    const demo = this.demo;
    if (!demo) return 0;
    if (this.kind === "keyframes") return demo.endTime;
    if (this.kind === "swarm") return Infinity;
    // A KLI run's T, read once from its path.
    if (this.finalTime === undefined) {
      const path = demo.path;
      this.finalTime = path.finalTime;
      path.free();
    }
    return this.finalTime;
  }

  schedule() {
    if (this.frame || !this.demo || this.pending > 0 || !this.playing || !this.visible || this.kind === "filmstrip") return;
    this.last = performance.now();
    this.frame = requestAnimationFrame((now) => this.tick(now));
  }

  /** Whether the figure can be seen: in the viewport (the IntersectionObserver) and not made
   *  invisible by a host (reveal.js keeps the slides beside the current one laid out at opacity 0). */
  get seen() {
    return this.visible && (typeof this.checkVisibility !== "function" || this.checkVisibility({ opacityProperty: true, visibilityProperty: true }));
  }

  tick(/** @type {number} */ now) {
    this.frame = 0;
    if (!this.demo || !this.playing || !this.visible) return;
    if (!this.seen) {
      // Hidden by style, which no observer reports: look again in a quarter of a second.
      clearTimeout(this.recheck);
      this.recheck = setTimeout(() => this.schedule(), 250);
      return;
    }
    const dt = (Math.min(Math.max(now - this.last, 0), 100) / 1000) * this.speed;
    this.last = now;
    if (this.kind === "swarm") {
      if (dt > 0 && !this.stepSwarm(this.swarmSteps(dt))) return;
      this.t = this.demo.time;
    } else {
      const start = this.kind === "keyframes" ? this.demo.startTime : 0;
      this.t = this.t + dt > this.end ? start : this.t + dt;
    }
    // A host may have scaled the figure since the last frame (reveal.js, on a new slide size).
    if (this.figures?.sizing?.refit(false).length === 0) this.draw();
    this.frame = requestAnimationFrame((later) => this.tick(later));
  }

  /** Draws the figure at its time, at the pixels it covers on screen. */
  draw() {
    this.figures?.render(Math.min(this.t, this.end));
  }
}

if (!customElements.get("kli-figure")) customElements.define("kli-figure", KliFigure);
