// @ts-check
// <kli-figure>: one figure of the demo in any page, configured in the markup and sized by CSS.
//
//   <script type="module" src="kli-figure.js"></script>
//   <kli-figure view="hopf" p="0,0,0,1" r="0.5,0.5,0.5,0.5" autoplay></kli-figure>
//
// Views: each page's in the registry (pages.js: "object", "hopf", "plots", "filmstrip" of the KLI
// page, "keyframes", "swarm", "average"). Each page module is loaded once, when the
// first figure that needs it appears, and shared by every figure on the page. Every attribute is
// live: change one and the figure is rebuilt. Computing, checking and drawing are the modules'.

import { Camera } from "./runtime/camera.js";
import { Figures } from "./runtime/figures.js";
import { parseNumber } from "./runtime/numbers.js";
import { Player } from "./runtime/player.js";
import { outOfRange, parseText } from "./runtime/schema.js";
import { PAGES, pageOfView } from "./pages.js";
import { wirePrinting } from "./runtime/print.js";
import { record } from "./runtime/video/panel.js";

const VIEWS = PAGES.flatMap((page) => Object.keys(page.views));
/** A state key as an attribute: `shortestPath` → `shortest-path`. */
const attributeName = (/** @type {string} */ key) => key.replace(/[A-Z]/g, (c) => `-${c.toLowerCase()}`);
/** The figure's own attributes, then each page's state keys (its state.js), read as the pages
 *  read their URL (runtime/schema.js). */
const ATTRIBUTES = ["view", "t", "autoplay", "speed", "label", "text-scale", "print-t",
  ...new Set(PAGES.flatMap((page) => page.state.schema.map((entry) => attributeName(entry.key))))];
/** The largest `t` and `speed` a figure takes. */
const MAX_T = 1e6, MAX_SPEED = 1000;

/** @type {Map<string, Promise<any>>} each page module (the registry's `module`), loaded when the
 *  first figure that needs it appears and initialised once for the whole page */
const loaded = new Map();
function load(/** @type {import("./pages.js").Page} */ page) {
  let module = loaded.get(page.name);
  if (!module) {
    module = page.module().then(async (m) => {
      await m.default();
      return m;
    });
    loaded.set(page.name, module);
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
    /** @type {any} the module's run: a KliDemo, KeyframesDemo, SwarmDemo or AverageDemo */
    this.run = null;
    /** The module's name for this figure's view. */
    this.view = "";
    /** @type {Figures<string> | null} */
    this.figures = null;
    this.player = new Player({ draw: () => this.draw(), seen: () => this.seen, loop: true });
    this.visible = true;
    this.built = 0;
    /** @type {{ show(): void, remove(): void, dispose(): void } | null} printing as SVG, while connected */
    this.printing = null;
    // Off screen, an animated figure stops asking for frames. The browser may deliver several
    // entries at once (hidden, then shown, on a slide that appears): the last one is the news.
    this.intersection = new IntersectionObserver((entries) => {
      this.visible = entries[entries.length - 1].isIntersecting;
      if (this.visible) this.figures?.sizing?.refit(false);
      this.player.schedule();
    });
  }

  connectedCallback() {
    this.nameWhileLoading();
    this.intersection.observe(this);
    this.rebuild();
  }

  disconnectedCallback() {
    this.printing?.dispose();
    this.printing = null;
    this.figures?.sizing?.disconnect();
    this.figures = null;
    this.intersection.disconnect();
    this.player.stop();
    this.run?.free();
    this.run = null;
  }

  /** Until its module has built the run (which names it by its title), the canvas says what it
   *  will be: never an unnamed image. */
  nameWhileLoading() {
    if (!this.run) this.canvas.setAttribute("aria-label", this.getAttribute("label") ?? `A kli figure (${this.kind}), loading`);
  }

  attributeChangedCallback() {
    this.nameWhileLoading();
    if (this.isConnected) this.rebuild();
  }

  /** The `view` attribute. */
  get kind() {
    return this.getAttribute("view") ?? "hopf";
  }

  /** Builds the figure's run from its attributes; a refused attribute is shown in the figure. */
  async rebuild() {
    const build = ++this.built;
    const page = pageOfView(this.kind);
    if (!page) return this.fail(`view must be one of ${VIEWS.join(", ")} (got "${this.kind}")`);
    let module;
    try {
      module = await load(page);
    } catch (error) {
      return this.fail(`the WebAssembly module could not be loaded: ${error instanceof Error ? error.message : error}`);
    }
    if (build !== this.built || !this.isConnected) return; // a newer rebuild is under way
    const t = this.getAttribute("t"), speed = this.getAttribute("speed");
    const [at, pace] = [t === null ? NaN : parseNumber(t), speed === null ? 1 : parseNumber(speed)];
    if (t !== null && !(at >= 0 && at <= MAX_T)) return this.fail(`t must be a number from 0 to ${MAX_T} (got "${t}")`);
    if (!(pace >= 0 && pace <= MAX_SPEED)) return this.fail(`speed must be a number from 0 to ${MAX_SPEED} (got "${speed}")`);
    let run;
    try {
      run = this.create(module, page);
    } catch (error) {
      return this.fail(error instanceof Error ? error.message : String(error));
    }
    this.player.stop();
    this.player.show(run);
    this.run?.free();
    this.run = run;
    this.view = page.views[this.kind];
    this.figures?.sizing?.disconnect();
    this.figures = new Figures({ [this.view]: this.canvas });
    this.figures.camera = new Camera(module.defaultCamera());
    const scale = this.getAttribute("text-scale");
    this.figures.scaleText(scale === null ? 1 : parseNumber(scale));
    // Printed (or a deck's PDF): the figure as vector, at `print-t` (else its time now).
    this.printing ??= wirePrinting(() => this.figures, () => this.printTime, {}, this.root);
    this.figures.show(run);
    this.figures.observe(() => this.draw());
    this.message.textContent = "";
    this.player.speed = pace;
    this.describe();
    // A run that computes its way to `t` (the swarm) gets there a task at a time, saying how far.
    if (t !== null) {
      const reached = await this.player.seek(at, (now) => {
        this.message.textContent = `Running to t = ${at}: ${Math.floor((100 * now) / at)}%`;
      });
      if (!reached || build !== this.built) return;
      this.message.textContent = "";
    }
    this.draw();
    // A still view has nothing to animate.
    if (this.playing && this.figures.kind(this.view) !== "still") this.player.play();
  }

  /** The figure's time now. */
  get t() {
    return this.player.t;
  }

  /** Whether the `autoplay` attribute asks for motion that the reader allows. */
  get playing() {
    return this.hasAttribute("autoplay") && !Player.reducedMotion();
  }

  /** The module's run for the page `name`, from the attributes over the defaults, read as the
   *  pages read their URL, within the bounds of the pages' fields (its constructor checks the rest). */
  create(/** @type {any} */ module, /** @type {import("./pages.js").Page} */ page) {
    /** @type {Record<string, any>} */
    const state = { ...page.figure };
    for (const { key, kind } of page.state.schema) {
      const text = this.getAttribute(attributeName(key));
      if (text !== null) state[key] = parseText(kind, text);
    }
    const [beyond] = outOfRange(page.state.schema, state);
    if (beyond) {
      const { key, min, max, value } = beyond;
      throw new Error(`${attributeName(key)} must be from ${min} to ${max}, as on its page (got ${value})`);
    }
    return page.state.create(module, state);
  }

  fail(/** @type {string} */ text) {
    this.player.stop();
    this.run?.free();
    this.run = null;
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
    return Math.min(Number.isFinite(asked) ? asked : this.player.t, this.end);
  }

  /**
   * The figure as an SVG document at time `t` (default: its time now).
   * @param {number} [t]
   */
  toSvg(t = this.player.t) {
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
    const figures = this.figures;
    if (!figures || !this.run) throw new Error("kli-figure: the figure is not built yet");
    const [start, end] = this.player.span;
    const seconds = options.seconds ?? (this.player.spanned ? Math.min(60, Math.max(1, end - start)) : 10);
    return record({
      figures, player: this.player, views: [this.view], chosen: [this.view],
      title: () => options.title ?? this.getAttribute("label") ?? this.canvas.getAttribute("aria-label") ?? "",
      file: () => `kli-${this.kind}`,
    }, { format: options.format ?? "mp4", size: options.size ?? "720p", fps: options.fps ?? 30, views: [this.view],
      from: options.from, to: options.to, seconds, signal: options.signal, progress: options.progress });
  }

  /** The canvas's text alternative: the `label` attribute, or the run's title of the view. */
  describe() {
    const title = this.run?.views.find((/** @type {{ name: string }} */ v) => v.name === this.view)?.title;
    this.canvas.setAttribute("aria-label", this.getAttribute("label") ?? title ?? this.kind);
  }

  /** The end of the figure's time (Infinity for a run with none). */
  get end() {
    return this.player.span[1];
  }

  /** Whether the figure can be seen: in the viewport (the IntersectionObserver) and not made
   *  invisible by a host (reveal.js keeps the slides beside the current one laid out at opacity 0). */
  get seen() {
    return this.visible && (typeof this.checkVisibility !== "function" || this.checkVisibility({ opacityProperty: true, visibilityProperty: true }));
  }

  /** Draws the figure at its time, at the pixels it covers on screen; a host may have scaled it
   *  since the last frame (reveal.js, on a new slide size): refitting draws. */
  draw() {
    if (this.figures?.sizing?.refit(false).length === 0) this.figures.render(this.player.t);
  }
}

if (!customElements.get("kli-figure")) customElements.define("kli-figure", KliFigure);
