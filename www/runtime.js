// @ts-check
// The page runtime: what every page does, written once. A page is a descriptor (its module, its
// figures, its state's schema, its presets, what its run is and how it reads out); this file
// loads the module, keeps form, state and URL in step, builds runs (every refused value shown
// beside its field at once, from the form and from the URL, the last valid run kept), runs the
// clock, draws the figures, and wires keys, dragging, presets and saving.
//
// The page's elements, by id: #load-status, #play, #readout, #share, #save and #save-status;
// where present: #time (slider), #restart, #speed, #status (announced once the time rests),
// #note. The runtime adds the video panel to #save and a text size choice beside #speed (or to
// #save); `?text=1.5` scales the figures' text, `?print=1.8` the time the figures print at
// (else the time on show), as SVG.
import { Camera } from "./camera.js";
import { Clock } from "./clock.js";
import { $ } from "./dom.js";
import { download, saveAs, timeTag, wireSaving } from "./exports.js";
import { Figures } from "./figures.js";
import { wireDragging, wireKeyboard } from "./input.js";
import { page as pageNamed } from "./pages.js";
import { parseNumber } from "./numbers.js";
import { presetName } from "./presets.js";
import { buildAll, clearErrors, messageOf, showFieldError } from "./runs.js";
import { Schema } from "./schema.js";
import { throttledUrl } from "./url.js";
import { wirePrinting } from "./print.js";
import { videoPanel } from "./video/panel.js";

/**
 * What the module's page classes have: the figure interface, and `free`.
 * @typedef {import("./figures.js").Figure & { free(): void, export(kind: string, format: string): string }} Run
 */

/**
 * @template {Record<string, any>} State
 * @template {Run} R
 * @typedef {object} Descriptor
 * @property {string} name the page's name in pages.js
 * @property {() => Promise<unknown>} init the module's init
 * @property {() => ArrayLike<number>} camera the module's default camera
 * @property {Record<string, string>} canvases each view's canvas (a selector), by the view's name
 * @property {Record<string, { draw: import("./figures.js").Painter, svg: (frame: import("./figures.js").Frame) => string }>} [own]
 *   views the page draws itself (with the module's static drawing functions), and their SVG
 * @property {string} form the form's selector
 * @property {readonly import("./schema.js").Entry[]} schema
 * @property {Record<string, string>} [aliases] URL keys of old links, still read: old → new
 * @property {Record<string, State>} presets
 * @property {State} defaults
 * @property {() => State} [random] the "random" preset
 * @property {(state: State) => R} create the module's run for a state (its constructor checks it)
 * @property {(error: unknown) => (keyof State & string) | undefined} keyOf the state key an Error is about
 * @property {(error: unknown) => { output: string, fields: Element[] } | undefined} [route] where an Error
 *   shows, when not beside its key's fields
 * @property {(run: R) => [number, number]} [span] the clock's span; without it the run keeps its own time
 * @property {(run: R) => void} [advance] one frame of a run that keeps its own time
 * @property {(run: R) => number} [time] a run's own time
 * @property {(page: Page<State, R>, t: number) => string} readout
 * @property {{ kind: string, file: (run: R, t: number) => string }} data what the page saves as CSV and JSON
 * @property {(run: R, view: string, t: number) => string} file a saved view's file name
 * @property {(state: State) => number} [stride] the smallest step of ← and → (else 1/200 of the span)
 * @property {boolean} [timeInUrl] whether a paused page writes its time into the URL
 * @property {(page: Page<State, R>, run: R, state: State) => void} [shown] what the page adds when a run is shown
 * @property {(page: Page<State, R>, name: string) => boolean} [input] a form field the page handles itself
 * @property {(page: Page<State, R>) => void} [wire] the page's own buttons
 * @property {(page: Page<State, R>) => void} [drawn] after each frame
 * @property {(page: Page<State, R>) => void} [rested] when the time comes to rest (paused, or moved while paused)
 * @property {(x: number, y: number) => ((x: number, y: number) => void) | null} [grab] dragging on the sphere that moves something
 * @property {{ views: readonly string[], title: (run: R) => string, file: (run: R) => string }} video the figures of the
 *   page's clip by default (the paper's video: object and Hopf sphere), its title line and its file name's stem
 */

/**
 * Loads the page's module; on failure says why in `status` and resolves to false.
 * @param {() => Promise<unknown>} init
 * @param {HTMLElement} status
 */
async function loadModule(init, status) {
  try {
    await init();
    return true;
  } catch (error) {
    status.textContent = `The WebAssembly module could not be loaded: ${messageOf(error)}`;
    status.classList.add("error");
    return false;
  }
}

/**
 * @template {Record<string, any>} State
 * @template {Run} R
 */
export class Page {
  /** @param {Descriptor<State, R>} descriptor */
  constructor(descriptor) {
    const d = descriptor;
    this.d = d;
    this.form = $(d.form, HTMLFormElement);
    /** @type {Schema<State>} */
    this.schema = new Schema(d.schema, this.form);
    const canvases = Object.fromEntries(Object.entries(d.canvases).map(([view, selector]) => [view, $(selector, HTMLCanvasElement)]));
    const painters = Object.fromEntries(Object.entries(d.own ?? {}).map(([view, { draw }]) => [view, draw]));
    this.figures = new Figures(canvases, { ...pageNamed(d.name), painters });
    this.clock = new Clock();
    /** @type {R | null} */
    this.run = null;
    /** @type {State} */
    this.state = d.defaults;
    const optional = (/** @type {string} */ selector) => /** @type {HTMLElement | null} */ (document.querySelector(selector));
    this.ui = {
      load: $("#load-status", HTMLElement),
      play: $("#play", HTMLButtonElement),
      readout: $("#readout", HTMLElement),
      share: $("#share", HTMLAnchorElement),
      time: /** @type {HTMLInputElement | null} */ (optional("#time")),
      speed: /** @type {HTMLSelectElement | null} */ (optional("#speed")),
      status: optional("#status"),
      note: optional("#note"),
    };
    this.query = new URLSearchParams(location.search);
    this.embed = this.query.get("embed") === "1";
    this.writeUrl = throttledUrl(400, (search) => (this.ui.share.href = search));
    this.drawPending = false;
    this.announcement = 0;
    this.lastReadout = "";
    /** @type {{ fill(): void, check(): Promise<void> } | undefined} */
    this.video = undefined;
  }

  static reducedMotion() {
    return matchMedia("(prefers-reduced-motion: reduce)").matches;
  }

  /** The time on show: the clock's, or the run's own. */
  get t() {
    return this.d.time && this.run ? this.d.time(this.run) : this.clock.t;
  }

  get playing() {
    return this.clock.playing;
  }

  // ---- Runs ----------------------------------------------------------------------------------

  /** Builds the run for `candidate` when the module accepts all of it; otherwise shows every
   *  refused value beside its field and keeps the run on show. Returns whether it applied it. */
  rebuild(/** @type {State} */ candidate) {
    const { run, errors } = buildAll(candidate, this.state, this.d.create, this.d.keyOf);
    clearErrors(this.form);
    if (errors.length > 0 || !run) {
      run?.free();
      errors.forEach((error) => this.showError(error));
      return false;
    }
    this.show(run, candidate);
    return true;
  }

  /** Shows an Error of the module beside the fields it is about (routed by `error.argument`). */
  showError(/** @type {unknown} */ error) {
    const routed = this.d.route?.(error);
    if (routed) return showFieldError(this.form, routed.output, routed.fields, messageOf(error));
    const key = this.d.keyOf(error) ?? this.d.schema[0].key;
    showFieldError(this.form, key, this.schema.fields(key), messageOf(error));
  }

  /** Shows a run: its figures, the page's own parts, the preset it is, the URL. */
  show(/** @type {R} */ run, /** @type {State} */ state) {
    this.run?.free();
    this.run = run;
    this.state = state;
    this.figures.show(run);
    if (this.d.span) {
      const [start, end] = this.d.span(run);
      this.clock.setSpan(start, end);
      if (this.ui.time) {
        this.ui.time.min = String(start);
        this.ui.time.max = String(end);
      }
    } else {
      this.clock.setSpan(0, Infinity);
    }
    const preset = this.form.elements.namedItem("preset");
    if (preset instanceof HTMLSelectElement) preset.value = presetName(this.d.presets, state);
    this.d.shown?.(this, run, state);
    this.video?.fill();
    this.showTime();
    this.requestDraw();
  }

  /** Applies a preset (or "random"): fills the form, builds it, and plays it from the start. */
  applyPreset(/** @type {string} */ name) {
    const preset = name === "random" && this.d.random ? this.d.random() : this.d.presets[name];
    if (!preset) return;
    this.schema.fill(preset);
    this.clock.seek(this.clock.start);
    if (this.rebuild(preset) && this.d.span && !Page.reducedMotion()) this.play();
  }

  // ---- Time ----------------------------------------------------------------------------------

  /** After the time or the run changed: the slider, the readout and, while paused, the URL and
   *  (a moment later, once the time rests) an announcement. */
  showTime() {
    if (!this.run) return;
    if (this.ui.time) this.ui.time.value = String(this.t);
    this.ui.readout.textContent = this.lastReadout = this.d.readout(this, this.t);
    const paused = this.d.timeInUrl && !this.playing ? this.clock.t.toFixed(2) : undefined;
    this.writeUrl(this.schema.toUrl(this.state, { t: paused, embed: this.embed ? "1" : undefined }));
    if (this.playing) return;
    this.d.rested?.(this);
    const status = this.ui.status;
    if (!status) return;
    clearTimeout(this.announcement);
    this.announcement = setTimeout(() => (status.textContent = this.ui.readout.textContent ?? ""), 300);
  }

  play() {
    if (!this.run) return;
    this.clock.play();
    this.ui.play.textContent = "Pause";
    this.showTime();
    this.requestDraw();
  }

  pause() {
    this.clock.pause();
    this.ui.play.textContent = "Play";
    this.showTime();
  }

  togglePlay() {
    if (this.playing) this.pause();
    else this.play();
  }

  seek(/** @type {number} */ t) {
    this.clock.seek(t);
    this.showTime();
    this.requestDraw();
  }

  // ---- Frames --------------------------------------------------------------------------------

  requestDraw() {
    if (this.drawPending) return;
    this.drawPending = true;
    requestAnimationFrame((now) => this.frame(now));
  }

  frame(/** @type {number} */ now) {
    this.drawPending = false;
    const ended = this.clock.tick(now);
    if (this.playing && this.run && this.d.advance) this.d.advance(this.run);
    this.draw();
    if (ended) this.pause();
    if (this.playing) this.requestDraw();
  }

  /** Draws the figures at the time on show; while playing, the slider and readout follow. */
  draw() {
    if (!this.run || !this.figures.render(this.t)) return;
    if (this.playing) {
      const readout = this.d.readout(this, this.t);
      if (readout !== this.lastReadout) {
        if (this.ui.time) this.ui.time.value = String(this.t);
        this.ui.readout.textContent = this.lastReadout = readout;
      }
    }
    this.d.drawn?.(this);
    // For the DevTools timeline and `make bench`: when the first complete frame was drawn.
    if (performance.getEntriesByName("kli:first-frame").length === 0) performance.mark("kli:first-frame");
  }

  /** Turns the sphere views. */
  turn(/** @type {number} */ azimuth, /** @type {number} */ elevation) {
    this.figures.turn(azimuth, elevation);
    this.requestDraw();
  }

  // ---- Saving --------------------------------------------------------------------------------

  /** Saves a view as PNG or SVG, or the page's data as CSV or JSON, as it stands. */
  save(/** @type {string} */ what, /** @type {string} */ format) {
    const run = this.run;
    if (!run) throw new Error("there is nothing to save yet");
    const t = this.t;
    if (what === this.d.data.kind) {
      const make = (/** @type {string} */ f) => () => run.export(what, f);
      return saveAs(this.d.data.file(run, t), format, { csv: make("csv"), json: make("json") });
    }
    if (!Object.hasOwn(this.figures.canvases, what)) throw new Error(`there is no ${what} view`);
    return this.figures.save(what, format, this.d.file(run, what, t), t, this.d.own?.[what]?.svg);
  }

  // ---- Start ---------------------------------------------------------------------------------

  wire() {
    this.form.addEventListener("submit", (event) => event.preventDefault());
    this.form.addEventListener("input", (event) => {
      const name = /** @type {HTMLInputElement} */ (event.target).name ?? "";
      if (this.d.input?.(this, name)) return;
      if (name === "preset") return this.applyPreset(/** @type {HTMLSelectElement} */ (event.target).value);
      this.rebuild(this.schema.read());
    });
    this.ui.play.addEventListener("click", () => this.togglePlay());
    document.querySelector("#restart")?.addEventListener("click", () => {
      this.seek(this.clock.start);
      if (!Page.reducedMotion()) this.play();
    });
    const time = this.ui.time;
    time?.addEventListener("input", () => {
      if (this.playing) this.pause();
      this.seek(Number(time.value));
    });
    const speed = this.ui.speed;
    speed?.addEventListener("input", () => (this.clock.speed = Number(speed.value)));
    wireSaving($("#save", HTMLElement), (what, format) => this.save(what, format), $("#save-status", HTMLElement));
    const hopf = this.figures.canvases.hopf;
    /** @type {import("./input.js").Actions} */
    const actions = {
      togglePlay: () => this.togglePlay(),
      step: (by) => {
        if (!this.d.span) return;
        this.pause();
        const span = this.clock.end - this.clock.start;
        this.seek(this.clock.t + by * Math.max(this.d.stride?.(this.state) ?? 0, span / 200));
      },
      toStart: () => (this.d.span ? this.seek(this.clock.start) : this.rebuild(this.state)),
      toEnd: () => {
        if (!this.d.span) return;
        this.pause();
        this.seek(this.clock.end);
      },
      speed: (by) => {
        if (!speed) return;
        speed.selectedIndex = Math.min(Math.max(speed.selectedIndex + by, 0), speed.options.length - 1);
        this.clock.speed = Number(speed.value);
      },
      turn: (azimuth, elevation) => this.turn(azimuth, elevation),
    };
    if (hopf) {
      wireKeyboard(hopf, actions);
      wireDragging(hopf, actions.turn, this.d.grab);
    }
    this.wireFigureChoices();
    this.d.wire?.(this);
  }

  /** The video panel, the text size, and printing as SVG: for every page, here once. */
  wireFigureChoices() {
    const save = $("#save", HTMLElement);
    const svgs = Object.fromEntries(Object.entries(this.d.own ?? {}).map(([view, { svg }]) => [view, svg]));
    this.video = videoPanel(save, {
      figures: this.figures,
      views: Object.keys(this.figures.canvases),
      chosen: this.d.video.views,
      spanned: Boolean(this.d.span),
      span: () => (this.d.span && this.run ? this.d.span(this.run) : null),
      advance: () => this.run && this.d.advance?.(this.run),
      now: () => this.t,
      title: () => (this.run ? this.d.video.title(this.run) : ""),
      file: () => (this.run ? this.d.video.file(this.run) : "kli"),
      textScale: () => this.figures.textScale,
      svgs,
    }, (name, blob) => download(name, blob.type, blob));
    const sizes = [["1", "normal"], ["1.5", "large (1.5×)"], ["2", "projector (2×)"], ["3", "hall (3×)"]];
    const label = Object.assign(document.createElement("label"), { className: "text-size" });
    label.append("Text size ");
    const select = document.createElement("select");
    select.name = "text-size";
    select.innerHTML = sizes.map(([value, name]) => `<option value="${value}">${name}</option>`).join("");
    label.append(select);
    const asked = parseNumber(this.query.get("text") ?? "1");
    this.figures.scaleText(asked);
    if (!sizes.some(([value]) => Number(value) === this.figures.textScale)) {
      select.append(new Option(`${this.figures.textScale}×`, String(this.figures.textScale)));
    }
    select.value = String(this.figures.textScale);
    const speed = this.ui.speed?.closest("label");
    if (speed) speed.after(label);
    else save.prepend(label);
    select.addEventListener("input", () => {
      this.figures.scaleText(Number(select.value));
      this.requestDraw();
    });
    // `?print=` that is not a number prints the time on show, as no `?print=` does.
    const printAt = parseNumber(this.query.get("print") ?? "");
    wirePrinting(() => this.figures, () => (Number.isFinite(printAt) ? printAt : this.t), svgs);
  }

  /** Loads the module, then shows the URL's state: the values the module refuses are shown
   *  beside their fields (their text kept there, to mend) and the defaults stand in for them. */
  async start() {
    if (!(await loadModule(this.d.init, this.ui.load))) return;
    performance.mark("kli:wasm-ready");
    if (this.embed) document.body.classList.add("embed");
    this.figures.camera = new Camera(this.d.camera());
    this.wire();
    const { state: candidate, texts } = this.schema.fromUrl(location.search, this.d.defaults, this.d.aliases);
    const t = this.query.get("t");
    const paused = (this.d.timeInUrl && t !== null) || Page.reducedMotion();
    // The clock runs before the first URL is written, so that a playing page's URL has no time.
    if (!paused && this.d.span) this.clock.play();
    // A number beyond its slider is refused here, as the slider would refuse it.
    const beyond = this.schema.outOfRange(candidate).map(({ key, min, max, value }) => {
      /** @type {Record<string, any>} */ (candidate)[key] = this.d.defaults[key];
      return Object.assign(new Error(`${key} must be from ${min} to ${max} on this page, as its slider (got ${value})`),
        { argument: key, kind: "out-of-range" });
    });
    const { run, state, errors } = buildAll(candidate, this.d.defaults, this.d.create, this.d.keyOf);
    errors.unshift(...beyond);
    // The form first: what the page shows beside it (a slider's value) reads the form.
    this.schema.fill(state ?? this.d.defaults);
    this.show(run ?? this.d.create(this.d.defaults), state ?? this.d.defaults);
    this.schema.keepTexts(texts, errors.map((error) => this.d.keyOf(error)));
    errors.forEach((error) => this.showError(error));
    if (!paused) this.play();
    else this.seek(t === null ? this.clock.start : parseNumber(t));
    this.ui.load.textContent = "";
    this.ui.load.hidden = true;
    this.figures.observe(() => this.draw());
    // Offline support is registered once the page has settled, not on the way to the first frame.
    if ("serviceWorker" in navigator && location.protocol !== "file:") {
      const register = () => setTimeout(() => navigator.serviceWorker.register("sw.js").catch(() => {}));
      if (document.readyState === "complete") register();
      else addEventListener("load", register, { once: true });
    }
  }
}
