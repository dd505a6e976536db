// @ts-check
// The page runtime: what every page does, written once. A page is a descriptor (its module, its
// figures, its state's schema, its presets, what its run is and how it reads out); this file
// loads the module, keeps form, state and URL in step, builds runs (every refused value shown
// beside its field at once, from the form and from the URL, the last valid run kept), plays the
// run (player.js), draws the figures, and wires keys, dragging, presets and saving. A page's
// hooks get a Host: the few things of the page they may use.
//
// The page's elements, by id: #load-status, #play, #readout, #share, #save and #save-status;
// where present: #time (slider), #restart, #speed, #status (announced once the time rests),
// #note. The runtime adds the video panel to #save and a text size choice beside #speed (or to
// #save); `?text=1.5` scales the figures' text, `?print=1.8` the time the figures print at
// (else the time on show), as SVG.
import { Camera } from "./camera.js";
import { $, say } from "./dom.js";
import { download, saveAs, wireSaving } from "./exports.js";
import { Figures } from "./figures.js";
import { wireDragging, wireKeyboard } from "./input.js";
import { parseNumber } from "./numbers.js";
import { Player } from "./player.js";
import { presetName } from "./presets.js";
import { buildAll, clearErrors, messageOf, showFieldError } from "./runs.js";
import { Schema } from "./schema.js";
import { throttledUrl } from "./url.js";
import { wirePrinting } from "./print.js";
import { videoPanel } from "./video/panel.js";

/**
 * What the module's page classes have: the run contract (figures.js, player.js), `export`, `free`.
 * @typedef {import("./figures.js").Figure & import("./player.js").Timed & { free(): void, export(kind: string, format: string): string }} Run
 */

/**
 * The page's module: its init and its sphere views' default camera.
 * @typedef {{ default: () => Promise<unknown>, defaultCamera: () => ArrayLike<number> }} Module
 */

/**
 * What a descriptor's hooks may use of their page.
 * @template {Record<string, any>} State
 * @template {Run} R
 * @typedef {object} Host
 * @property {R | null} run the run on show
 * @property {State} state its state
 * @property {number} t the time on show
 * @property {HTMLFormElement} form the page's form
 * @property {(name: string) => HTMLInputElement | HTMLSelectElement} field a form field by name
 * @property {(key: string) => (HTMLInputElement | HTMLSelectElement)[]} fields a state key's fields (a quaternion's four)
 * @property {() => State} read the state the form holds
 * @property {(state: State) => boolean} rebuild builds and shows `state` (false, with the refusals shown, when refused)
 * @property {(state: State) => boolean} apply fills the form with `state`, then rebuilds
 * @property {(error: unknown) => void} showError shows an Error of the module beside its fields
 * @property {(t: number) => void} seek pauses and moves to `t`
 * @property {(views?: string[]) => void} redraw draws again (the named views' still parts too)
 * @property {() => void} changed the run on show changed in place (its solutions came): its note, readout and every
 *   view drawn again
 * @property {(view: string) => import("./figures.js").Frame | null} frame a view's frame at the time on show
 */

/**
 * A page: its own parts. Time, play, frames, saving, printing, video, text size, URL and
 * keyboard are the runtime's, the same on every page.
 * @template {Record<string, any>} State
 * @template {Run} R
 * @typedef {object} Descriptor
 * @property {import("../pages.js").Page} entry the page's entry in the registry (www/pages.js): its canvases, its Save
 *   list and its state (schema, presets, defaults, the module's run for a state, the key an Error is about)
 * @property {Module} module
 * @property {(module: any, state: State) => R} [create] the page's run for a state, when not its state's `create` (the
 *   synchronisation page builds its runs unsolved and solves them in a worker; <kli-figure> keeps the state's)
 * @property {Record<string, { draw: import("./figures.js").Painter, svg: (frame: import("./figures.js").Frame) => string }>} [own]
 *   views the page draws itself (with the module's static drawing functions), and their SVG
 * @property {string} form the form's selector
 * @property {Record<string, string>} [aliases] URL keys of old links, still read: old → new
 * @property {() => State} [random] the "random" preset
 * @property {(host: Host<State, R>, error: unknown) => { output: string, fields: Element[] } | undefined} [route]
 *   where an Error shows, when not beside its key's fields
 * @property {(run: R, t: number) => string} readout the line under the figures
 * @property {(run: R, t: number) => Record<string, string>} [labels] canvases' text alternatives once the time rests, by view
 * @property {(run: R, state: State) => string} [note] the line in #note about a run
 * @property {{ file: (run: R, t: number) => string }} data the file name of what the page saves as CSV and JSON (the
 *   registry's Save list names it)
 * @property {(run: R, view: string, t: number) => string} file a saved view's file name
 * @property {(state: State) => number} [stride] the smallest step of ← and → and the slider (else 1/200 of the span)
 * @property {boolean} [timeInUrl] whether a paused page writes its time into the URL
 * @property {(host: Host<State, R>, run: R, state: State) => void} [shown] what the page adds when a run is shown
 * @property {(run: R, view: string) => boolean} [waiting] whether `run` has yet to compute `view` (until `changed`): the
 *   view keeps its first picture meanwhile
 * @property {(host: Host<State, R>, name: string) => boolean} [input] a form field the page handles itself
 * @property {(host: Host<State, R>) => void} [wire] the page's own buttons
 * @property {(host: Host<State, R>, x: number, y: number) => ((x: number, y: number) => void) | null} [grab]
 *   dragging on the sphere that moves something
 * @property {{ views: readonly string[], title: (run: R) => string, file: (run: R) => string }} video the figures of the
 *   page's clip by default (the paper's video: object and Hopf sphere), its title line and its file name's stem
 * @property {Readonly<Record<string, string>>} [words] the runtime's words in the page's language, by their English
 *   (dom.js `say`; the tour's Bosnian): none, English
 * @property {(error: unknown) => string | undefined} [message] an Error of the module in the page's language (the
 *   tour's Bosnian): none, or undefined, its own message
 */

/**
 * Marks "kli:first-frame" when the page's complete first picture was seen: the moment the last
 * of the first pictures on screen was painted (Element Timing reports each: their
 * `elementtiming` attribute), or the first draw of the canvases if that was sooner. Returns
 * what the first draw calls with its time. Reports come after the paint they time, so the
 * mark waits for them (a second at most); where no picture is on screen (or the browser has no
 * Element Timing), the first draw marks it at once.
 */
function markFirstPictures() {
  const mark = (/** @type {number} */ startTime) => {
    if (performance.getEntriesByName("kli:first-frame").length === 0) performance.mark("kli:first-frame", { startTime });
  };
  const onScreen = [...document.querySelectorAll(".first-picture")].filter((picture) => {
    const box = picture.getBoundingClientRect();
    return box.width > 0 && box.bottom > 0 && box.top < innerHeight;
  }).length;
  if (onScreen === 0 || !PerformanceObserver.supportedEntryTypes.includes("element")) return mark;
  let drawn = Infinity;
  /** @type {Map<string, number>} each picture's paint, by its element's id */
  const painted = new Map();
  const take = (/** @type {PerformanceEntryList} */ entries) => {
    for (const entry of /** @type {any[]} */ (entries)) {
      if (entry.identifier === "kli-first-picture") painted.set(entry.id, entry.renderTime || entry.loadTime);
    }
    if (painted.size < onScreen) return;
    observer.disconnect();
    mark(Math.min(Math.max(...painted.values()), drawn));
  };
  const observer = new PerformanceObserver((list) => take(list.getEntries()));
  observer.observe({ type: "element", buffered: true });
  return (/** @type {number} */ time) => {
    drawn = Math.min(drawn, time);
    setTimeout(() => {
      take(observer.takeRecords());
      observer.disconnect();
      mark(drawn);
    }, 1000);
  };
}

/**
 * Loads the page's module; on failure says why in `status` and resolves to false.
 * @param {() => Promise<unknown>} init
 * @param {HTMLElement} status
 * @param {Readonly<Record<string, string>>} [words] the page's words (dom.js `say`)
 */
async function loadModule(init, status, words) {
  try {
    await init();
    return true;
  } catch (error) {
    status.textContent = say(words, "The WebAssembly module could not be loaded: {error}", { error: messageOf(error) });
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
    const state = d.entry.state;
    /** The page's state, from its state.js through the registry. */
    this.s = {
      /** @type {readonly import("./schema.js").Entry[]} */ schema: state.schema,
      /** @type {Record<string, State>} */ presets: state.presets,
      /** @type {State} */ defaults: /** @type {State} */ (state.defaults),
      /** the module's run for a state (its constructor checks it) */
      create: (/** @type {State} */ s) => /** @type {R} */ ((d.create ?? state.create)(d.module, s)),
      /** the state key an Error is about */
      keyOf: (/** @type {unknown} */ error) => /** @type {(keyof State & string) | undefined} */ (state.keyOf(error)),
    };
    this.form = $(d.form, HTMLFormElement);
    /** @type {Schema<State>} */
    this.schema = new Schema(this.s.schema, this.form);
    const canvases = Object.fromEntries(Object.entries(d.entry.canvases).map(([view, selector]) => [view, $(selector, HTMLCanvasElement)]));
    const painters = Object.fromEntries(Object.entries(d.own ?? {}).map(([view, { draw }]) => [view, draw]));
    this.figures = new Figures(canvases, painters);
    // While playing, a view comes back into the frames as it nears the screen.
    this.figures.watch(() => this.requestDraw());
    this.figures.waiting = (name) => this.run !== null && (this.d.waiting?.(this.run, name) ?? false);
    this.player = new Player({ draw: () => this.draw(), changed: () => this.playChanged() });
    this.waitForReader();
    /** @type {R | null} */
    this.run = null;
    /** @type {State} */
    this.state = this.s.defaults;
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
    /** @type {Host<State, R>} */
    this.host = this.makeHost();
    /** Called at the first draw with its time: marks the first frame (markFirstPictures). */
    this.firstDrawn = /** @type {((time: number) => void) | null} */ (markFirstPictures());
  }

  /** What the descriptor's hooks get. */
  makeHost() {
    const page = this;
    /** @type {Host<State, R>} */
    const host = {
      get run() { return page.run; },
      get state() { return page.state; },
      get t() { return page.t; },
      form: this.form,
      field: (name) => this.schema.field(name),
      fields: (key) => this.schema.fields(key),
      read: () => this.schema.read(),
      rebuild: (state) => this.rebuild(state),
      apply: (state) => {
        this.schema.fill(state);
        return this.rebuild(state);
      },
      showError: (error) => this.showError(error),
      seek: (t) => {
        this.player.pause();
        this.seek(t);
      },
      redraw: (views) => {
        if (views) this.figures.invalidate(views);
        this.requestDraw();
      },
      frame: (view) => this.figures.frame(view, this.t),
      changed: () => {
        if (!this.run) return;
        if (this.ui.note && this.d.note) this.ui.note.textContent = this.d.note(this.run, this.state);
        this.figures.invalidate();
        this.showTime();
        this.requestDraw();
      },
    };
    return host;
  }

  /** The time on show: the run's own. */
  get t() {
    return this.player.t;
  }

  get playing() {
    return this.player.playing;
  }

  // ---- Runs ----------------------------------------------------------------------------------

  /** Builds the run for `candidate` when the module accepts all of it; otherwise shows every
   *  refused value beside its field and keeps the run on show. Returns whether it applied it. */
  rebuild(/** @type {State} */ candidate) {
    const { run, errors } = buildAll(candidate, this.state, this.s.create, this.s.keyOf);
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
    const message = this.d.message?.(error) ?? messageOf(error);
    const routed = this.d.route?.(this.host, error);
    if (routed) return showFieldError(this.form, routed.output, routed.fields, message);
    const key = this.s.keyOf(error) ?? this.s.schema[0].key;
    showFieldError(this.form, key, this.schema.fields(key), message);
  }

  /** Shows a run: its figures, the page's own parts, the preset it is, the URL. */
  show(/** @type {R} */ run, /** @type {State} */ state) {
    const old = this.run;
    this.player.show(run);
    old?.free();
    this.run = run;
    this.state = state;
    this.figures.show(run);
    const [start, end] = this.player.span;
    if (this.ui.time && this.player.spanned) {
      this.ui.time.min = String(start);
      this.ui.time.max = String(end);
      if (this.d.stride) this.ui.time.step = String(this.d.stride(state));
    }
    const preset = this.form.elements.namedItem("preset");
    if (preset instanceof HTMLSelectElement) preset.value = presetName(this.s.presets, state);
    if (this.ui.note && this.d.note) this.ui.note.textContent = this.d.note(run, state);
    this.d.shown?.(this.host, run, state);
    this.video?.fill();
    this.showTime();
    this.requestDraw();
  }

  /** Applies a preset (or "random"): fills the form, builds it, and plays it from the start. */
  applyPreset(/** @type {string} */ name) {
    const preset = name === "random" && this.d.random ? this.d.random() : this.s.presets[name];
    if (!preset) return;
    this.schema.fill(preset);
    if (!this.rebuild(preset)) return;
    this.run?.seek(this.player.span[0]);
    if (this.player.spanned && !Player.reducedMotion()) this.play();
    else this.showTime();
  }

  // ---- Time ----------------------------------------------------------------------------------

  /** After the time or the run changed: the slider, the readout and, while paused, the URL,
   *  the figures' text alternatives and (a moment later, once the time rests) an announcement. */
  showTime() {
    const run = this.run;
    if (!run) return;
    if (this.ui.time) this.ui.time.value = String(this.t);
    this.ui.readout.textContent = this.lastReadout = this.d.readout(run, this.t);
    // Waiting for the reader to start it, the page is as good as playing: no time in its address.
    const paused = this.d.timeInUrl && !this.playing && !this.pending ? this.t.toFixed(2) : undefined;
    // `?lang=` (the tour's language) is kept as the page was opened with it.
    const lang = this.query.get("lang") ?? undefined;
    this.writeUrl(this.schema.toUrl(this.state, { t: paused, embed: this.embed ? "1" : undefined, lang }));
    if (this.playing) return;
    for (const [view, label] of Object.entries(this.d.labels?.(run, this.t) ?? {})) {
      this.figures.canvases[view]?.setAttribute("aria-label", label);
    }
    const status = this.ui.status;
    if (!status) return;
    clearTimeout(this.announcement);
    this.announcement = setTimeout(() => (status.textContent = this.ui.readout.textContent ?? ""), 300);
  }

  /** The play button and the time's readouts follow the player. */
  playChanged() {
    // Played or paused by the reader (or the page at their word): no motion is waiting any more.
    this.pending = false;
    this.ui.play.textContent = say(this.d.words, this.playing ? "Pause" : "Play");
    this.showTime();
    // Paused, every view shows the time on show (playing, those off screen were left).
    if (!this.playing) this.requestDraw();
  }

  play() {
    this.player.play();
  }

  pause() {
    this.player.pause();
  }

  seek(/** @type {number} */ t) {
    // The reader took the time: the motion waiting for them does not start over their choice.
    this.pending = false;
    const done = this.player.seek(t);
    this.showTime();
    // A run that computes its way there (the swarm) arrives tasks later.
    done.then((arrived) => arrived && !this.player.spanned && this.showTime());
  }

  // ---- Frames --------------------------------------------------------------------------------

  /** Draws once in the next frame (while playing, the player draws every frame). */
  requestDraw() {
    if (this.drawPending || this.playing) return;
    this.drawPending = true;
    requestAnimationFrame(() => {
      this.drawPending = false;
      this.draw();
    });
  }

  /** Draws the figures at the time on show; while playing, the slider and readout follow. */
  draw() {
    const run = this.run;
    if (!run || !this.figures.render(this.t, this.playing)) return;
    if (this.playing) {
      const readout = this.d.readout(run, this.t);
      if (readout !== this.lastReadout) {
        if (this.ui.time) this.ui.time.value = String(this.t);
        this.ui.readout.textContent = this.lastReadout = readout;
      }
    }
    // For the DevTools timeline and `make bench`: when the first complete frame was seen, the
    // first pictures' or this one.
    this.firstDrawn?.(performance.now());
    this.firstDrawn = null;
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
    // The one thing in the Save list that is no canvas: the run's data.
    if (Object.hasOwn(this.d.entry.save, what) && !Object.hasOwn(this.d.entry.canvases, what)) {
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
      if (this.d.input?.(this.host, name)) return;
      if (name === "preset") return this.applyPreset(/** @type {HTMLSelectElement} */ (event.target).value);
      this.rebuild(this.schema.read());
    });
    this.ui.play.addEventListener("click", () => this.player.toggle());
    document.querySelector("#restart")?.addEventListener("click", () => {
      this.seek(this.player.span[0]);
      if (!Player.reducedMotion()) this.play();
    });
    const time = this.ui.time;
    time?.addEventListener("input", () => {
      const t = Number(time.value);
      this.pause();
      this.seek(t);
    });
    const speed = this.ui.speed;
    speed?.addEventListener("input", () => (this.player.speed = Number(speed.value)));
    wireSaving($("#save", HTMLElement), (what, format) => this.save(what, format), $("#save-status", HTMLElement), this.d.words);
    const hopf = this.figures.canvases.hopf;
    const spanned = () => this.player.spanned;
    /** @type {import("./input.js").Actions} */
    const actions = {
      togglePlay: () => this.player.toggle(),
      step: (by) => {
        if (!spanned()) return;
        this.pause();
        const [start, end] = this.player.span;
        this.seek(this.t + by * Math.max(this.d.stride?.(this.state) ?? 0, (end - start) / 200));
      },
      toStart: () => (spanned() ? this.seek(this.player.span[0]) : this.rebuild(this.state)),
      toEnd: () => {
        if (!spanned()) return;
        this.pause();
        this.seek(this.player.span[1]);
      },
      speed: (by) => {
        if (!speed) return;
        speed.selectedIndex = Math.min(Math.max(speed.selectedIndex + by, 0), speed.options.length - 1);
        this.player.speed = Number(speed.value);
      },
      turn: (azimuth, elevation) => this.turn(azimuth, elevation),
    };
    if (hopf) {
      wireKeyboard(hopf, actions);
      const grab = this.d.grab;
      wireDragging(hopf, actions.turn, grab && ((x, y) => grab(this.host, x, y)));
    }
    this.wireFigureChoices();
    this.d.wire?.(this.host);
  }

  /** The video panel, the text size, and printing as SVG: for every page, here once. */
  wireFigureChoices() {
    const save = $("#save", HTMLElement);
    const svgs = Object.fromEntries(Object.entries(this.d.own ?? {}).map(([view, { svg }]) => [view, svg]));
    this.video = videoPanel(save, {
      figures: this.figures,
      player: this.player,
      views: Object.keys(this.figures.canvases),
      chosen: this.d.video.views,
      title: () => (this.run ? this.d.video.title(this.run) : ""),
      file: () => (this.run ? this.d.video.file(this.run) : "kli"),
    }, (name, blob) => download(name, blob.type, blob), this.d.words);
    const sizes = [["1", "normal"], ["1.5", "large (1.5×)"], ["2", "projector (2×)"], ["3", "hall (3×)"]];
    const label = Object.assign(document.createElement("label"), { className: "text-size" });
    label.append(`${say(this.d.words, "Text size")} `);
    const select = document.createElement("select");
    select.name = "text-size";
    select.innerHTML = sizes.map(([value, name]) => `<option value="${value}">${say(this.d.words, name)}</option>`).join("");
    label.append(select);
    const asked = parseNumber(this.query.get("text") ?? "1");
    this.figures.scaleText(asked);
    if (!sizes.some(([value]) => Number(value) === this.figures.textScale)) {
      select.append(new Option(`${this.figures.textScale}×`, String(this.figures.textScale)));
    }
    select.value = String(this.figures.textScale);
    // In the Save section, built with it (in the time controls it would move them once loaded).
    save.prepend(label);
    select.addEventListener("input", () => {
      this.figures.scaleText(Number(select.value));
      this.requestDraw();
    });
    // `?print=` that is not a number prints the time on show, as no `?print=` does.
    const printAt = parseNumber(this.query.get("print") ?? "");
    wirePrinting(() => this.figures, () => (Number.isFinite(printAt) ? printAt : this.t), svgs);
  }

  /**
   * The page moves once its reader is there: at their first input (the pointer moving over the
   * page, a touch, a key, a wheel, a scroll), not at load, which would be a stream of frames before
   * anyone has done anything: on a slow phone each frame of the synchronisation page took 60–160 ms
   * of the main thread (drawing, then compositing the canvases without a GPU), and Lighthouse's
   * total blocking time was 7 s. Until then the page shows its first frame, playing-to-be (its
   * address has no time). The listeners are set before the module loads, so an input while it
   * loads counts.
   */
  waitForReader() {
    /** A play waiting for the reader's first input. */
    this.pending = false;
    this.readerHere = false;
    const inputs = ["pointermove", "pointerdown", "keydown", "wheel", "touchstart", "scroll"];
    const here = () => {
      for (const input of inputs) removeEventListener(input, here, true);
      this.readerHere = true;
      // After the input's own handlers and the click that follows a touch: a reader who pressed
      // Play or a key has taken the controls (playChanged, seek): the page does not start it again.
      setTimeout(() => this.pending && this.play(), 250);
    };
    for (const input of inputs) addEventListener(input, here, { capture: true, passive: true });
  }

  /** Plays now if the reader is here, or at their first input (`waitForReader`). */
  playWithReader() {
    if (this.readerHere) return this.play();
    this.pending = true;
    this.showTime();
  }

  /** Loads the module, then shows the URL's state: the values the module refuses are shown
   *  beside their fields (their text kept there, to mend) and the defaults stand in for them.
   *  True once the page is interactive; false when the module could not be loaded. */
  async start() {
    if (!(await loadModule(this.d.module.default, this.ui.load, this.d.words))) {
      // The first pictures show the default state: where the URL asks for another, they go.
      const asked = [...this.s.schema.map((entry) => entry.url), "t"].some((key) => this.query.has(key));
      if (asked) document.querySelectorAll(".first-picture").forEach((picture) => picture.remove());
      return false;
    }
    performance.mark("kli:wasm-ready");
    if (this.embed) document.body.classList.add("embed");
    this.figures.camera = new Camera(this.d.module.defaultCamera());
    const { state: candidate, texts } = this.schema.fromUrl(location.search, this.s.defaults, this.d.aliases);
    const t = this.query.get("t");
    const paused = (this.d.timeInUrl && t !== null) || Player.reducedMotion();
    // A number beyond its slider is refused here, as the slider would refuse it.
    const beyond = this.schema.outOfRange(candidate).map(({ key, min, max, value }) => {
      /** @type {Record<string, any>} */ (candidate)[key] = this.s.defaults[key];
      const message = say(this.d.words, "{key} must be from {min} to {max} on this page, as its slider (got {value})", { key, min, max, value });
      return Object.assign(new Error(message),
        { argument: key, kind: "out-of-range" });
    });
    const { run, state, errors } = buildAll(candidate, this.s.defaults, this.s.create, this.s.keyOf);
    errors.unshift(...beyond);
    // The form first: what the page shows beside it (a slider's value) reads the form.
    this.schema.fill(state ?? this.s.defaults);
    this.show(run ?? this.s.create(this.s.defaults), state ?? this.s.defaults);
    // Wired once the first run is shown: the video panel asks it whether runs have a span.
    this.wire();
    this.schema.keepTexts(texts, errors.map((error) => this.s.keyOf(error)));
    errors.forEach((error) => this.showError(error));
    // In the same task as the first show: the first URL written is the playing page's, with no time.
    if (!paused) this.playWithReader();
    else if (t !== null) this.seek(parseNumber(t));
    this.ui.load.textContent = "";
    this.ui.load.hidden = true;
    this.figures.observe(() => this.draw());
    performance.mark("kli:interactive");
    // Offline support is registered once the page has settled, not on the way to the first frame.
    if ("serviceWorker" in navigator && location.protocol !== "file:") {
      const register = () => setTimeout(() => navigator.serviceWorker.register("sw.js").catch(() => {}));
      if (document.readyState === "complete") register();
      else addEventListener("load", register, { once: true });
    }
    return true;
  }
}
