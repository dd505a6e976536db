// @ts-check
// A page's figures, for every page and <kli-figure>: its canvases sized to the pixels they cover,
// the camera of its sphere views, and one drawing path through the run contract
// (`views`, `draw(view, ctx, frame, layer)`, `toSvg(view, frame)`: crates/kli-demo/src/figure.rs),
// each view drawn as its kind says (whole each frame, a kept still layer with the moving part
// over it, or only when it changes), and saving a view as PNG or SVG.
import { Camera } from "./camera.js";
import { Canvases } from "./canvases.js";
import { png, saveAs } from "./exports.js";

/**
 * What the module's page classes (a run of each page: pages.js) have in common for drawing.
 * @typedef {object} Figure
 * @property {readonly { name: string, title: string, kind: Kind }[]} views
 * @property {(view: string, ctx: CanvasRenderingContext2D, frame: Frame, layer?: "whole" | "still" | "moving") => void} draw
 * @property {(view: string, frame: Frame) => string} toSvg
 */
/** @typedef {{ width: number, height: number, pixelRatio: number, t: number, azimuth: number, elevation: number, textScale?: number }} Frame */
/**
 * A view the page draws itself. A view too large to draw in one task (the synchronisation page's
 * map of 10⁴ poses) returns the drawing of its next part, which returns the one after it, until
 * one returns nothing.
 * @typedef {(ctx: CanvasRenderingContext2D, frame: Frame) => Part | void} Painter
 */
/** @typedef {() => Part | void} Part the next part of a view drawn a task at a time */
/** @typedef {"moving" | "layered" | "still"} Kind how a view follows the time */

/**
 * @template {string} Name
 */
export class Figures {
  /**
   * @param {Record<Name, HTMLCanvasElement>} canvases a canvas for each view, by the view's name
   * @param {Partial<Record<Name, Painter>>} [painters] views the page draws itself (drawn as still views)
   */
  constructor(canvases, painters = {}) {
    this.canvases = canvases;
    this.painters = painters;
    /** @type {Partial<Record<string, Kind>>} each view's kind, as the run says */
    this.kinds = {};
    /** @type {Figure | null} */
    this.figure = null;
    this.camera = new Camera([0, 0]);
    /** Every label's size is multiplied by this (0.5 to 4): larger text for a projector. */
    this.textScale = 1;
    /** @type {Partial<Record<Name, import("./canvases.js").Size>>} */
    this.sizes = {};
    /** @type {Map<Name, HTMLCanvasElement>} the still layers, offscreen */
    this.layers = new Map();
    /** @type {Set<Name>} views whose still part must be drawn again */
    this.stale = new Set();
    /** @type {Map<Name, number>} the time each moving view's canvas shows, while it is not stale */
    this.shown = new Map();
    /** @type {Set<Name>} still views to be drawn in the next task */
    this.later = new Set();
    /** @type {Map<Name, object>} views being drawn a part a task, each by its drawing's token */
    this.drawing = new Map();
    /** @type {Canvases<Name> | null} */
    this.sizing = null;
    /** @type {Set<Name> | null} the views near the screen, once `watch` has been told (null: draw every view) */
    this.near = null;
    /** @type {Map<Name, Element>} each canvas's first picture (scripts/first-pictures.mjs), until the canvas is drawn */
    this.pictures = new Map();
    /** Whether the run on show has yet to compute view `name` (the synchronisation page's
     *  solutions come from a worker): meanwhile the view keeps its first picture, which shows it
     *  complete, rather than being drawn waiting. */
    this.waiting = (/** @type {Name} */ name) => false;
    for (const name of /** @type {Name[]} */ (Object.keys(canvases))) {
      const picture = canvases[name].previousElementSibling;
      if (picture?.classList.contains("first-picture")) this.pictures.set(name, picture);
    }
  }

  /** Takes away view `name`'s first picture once its canvas shows the view. */
  uncover(/** @type {Name} */ name) {
    this.pictures.get(name)?.remove();
    this.pictures.delete(name);
  }

  /** Shows a new run (a new module object): every still part is drawn again. */
  show(/** @type {Figure} */ figure) {
    // The first pictures show the first run: one a waiting view kept goes with it.
    if (this.figure) for (const name of [...this.pictures.keys()]) this.uncover(name);
    this.figure = figure;
    this.kinds = Object.fromEntries(figure.views.map(({ name, kind }) => [name, kind]));
    this.invalidate();
  }

  /** A view's kind: the run's word for it; a view the page draws itself is still. */
  kind(/** @type {Name} */ name) {
    return this.painters[name] ? "still" : this.kinds[name] ?? "moving";
  }

  /** After a change that the time does not explain (a new run, camera or size). */
  invalidate(/** @type {readonly Name[]} */ names = /** @type {Name[]} */ (Object.keys(this.canvases))) {
    for (const name of names) {
      this.stale.add(name);
      // Its parts still to come would draw what is no longer so (over a resized canvas, too).
      this.drawing.delete(name);
    }
  }

  /** Scales the figures' text (clamped to 0.5–4; anything not a number is 1). */
  scaleText(/** @type {number} */ scale) {
    this.textScale = Number.isFinite(scale) ? Math.min(Math.max(scale, 0.5), 4) : 1;
    this.invalidate();
  }

  /**
   * Each laid-out view as its SVG at time `t` (for printing): a view the page draws itself uses
   * its own SVG maker from `svgs`.
   * @param {number} t
   * @param {Partial<Record<Name, (frame: Frame) => string>>} [svgs]
   * @returns {[Name, string][]}
   */
  svgs(t, svgs = {}) {
    return /** @type {Name[]} */ (Object.keys(this.canvases)).flatMap((name) => {
      const frame = this.frame(name, t);
      return frame && this.figure ? [[name, this.svgOf(name, frame, svgs[name])]] : [];
    });
  }

  /**
   * View `name` at `frame` as an SVG document: the module's, or `own`'s for a view the page draws.
   * @param {Name} name
   * @param {Frame} frame
   * @param {(frame: Frame) => string} [own]
   */
  svgOf(name, frame, own) {
    return own ? own(frame) : /** @type {Figure} */ (this.figure).toSvg(name, frame);
  }

  /** Turns the sphere views by (azimuth, elevation) radians. */
  turn(/** @type {number} */ azimuth, /** @type {number} */ elevation) {
    this.camera.turn(azimuth, elevation);
    this.invalidate();
  }

  /**
   * The frame of view `name` at time `t`: its CSS size, the ratio to draw at, the camera.
   * @param {Name} name
   * @param {number} t
   * @param {import("./canvases.js").Size} [size] another size (a PNG at twice the ratio)
   * @returns {Frame | null}
   */
  frame(name, t, size = this.sizes[name]) {
    if (!size) return null;
    const { azimuth, elevation } = this.camera;
    return { width: size.width, height: size.height, pixelRatio: size.ratio, t, azimuth, elevation, textScale: this.textScale };
  }

  /**
   * Draws view `name` whole onto `ctx` at `frame` (a canvas of the page, or a PNG being saved).
   * @param {Name} name
   * @param {CanvasRenderingContext2D} ctx
   * @param {Frame} frame
   */
  paint(name, ctx, frame) {
    const painter = this.painters[name];
    if (!painter) return this.figure?.draw(name, ctx, frame);
    for (let part = painter(ctx, frame); part; part = part());
  }

  /**
   * As `paint`, but a view the page draws in parts is drawn a part a task (the first now), so
   * that the page can answer between them; a later drawing of the view stops the rest.
   * @param {Name} name
   * @param {CanvasRenderingContext2D} ctx
   * @param {Frame} frame
   */
  paintInParts(name, ctx, frame) {
    const painter = this.painters[name];
    if (!painter) return this.paint(name, ctx, frame);
    const token = {};
    this.drawing.set(name, token);
    let part = painter(ctx, frame);
    const next = () => {
      if (this.drawing.get(name) !== token || !part) return;
      part = part();
      if (part) setTimeout(next);
      else this.drawing.delete(name);
    };
    if (part) setTimeout(next);
    else this.drawing.delete(name);
  }

  /**
   * From now on, while the page plays, a view far from the screen is not drawn (its canvas keeps
   * its frame, a still view that changed stays due) until it comes near, when `near` is called:
   * a phone shows about one view at a time, and drawing the others each frame was most of a
   * frame's work (the synchronisation page, 412 px wide: 18.5 ms a frame with every view, 4.7 ms
   * with none, software canvas). Paused, every view is drawn.
   * @param {() => void} near
   */
  watch(near) {
    const names = new Map(Object.entries(this.canvases).map(([name, canvas]) => [canvas, /** @type {Name} */ (name)]));
    const observer = new IntersectionObserver((entries) => {
      const seen = this.near ?? new Set();
      let came = false;
      for (const entry of entries) {
        const name = /** @type {Name} */ (names.get(/** @type {HTMLCanvasElement} */ (entry.target)));
        if (!entry.isIntersecting) seen.delete(name);
        else if (!seen.has(name)) {
          seen.add(name);
          came = true;
        }
      }
      this.near = seen;
      if (came) near();
    }, { rootMargin: "200px" });
    for (const canvas of names.keys()) observer.observe(canvas);
  }

  /** Draws every laid-out view at time `t` (while `playing`, those near the screen: `watch`);
   *  returns whether anything was drawn. */
  render(/** @type {number} */ t, playing = false) {
    if (!this.figure) return false;
    let drawn = false;
    for (const name of /** @type {Name[]} */ (Object.keys(this.canvases))) {
      const frame = this.frame(name, t);
      if (!frame) continue;
      drawn = true;
      // While playing, a view far from the screen waits till it nears, once it has been drawn
      // for its run (stale: a new run, size or camera; every canvas shows its figure).
      if (playing && this.near && !this.near.has(name) && !this.stale.has(name)) continue;
      if (this.pictures.has(name) && this.waiting(name)) continue;
      // A view that shows this time already, and nothing else changed (`invalidate`), is left as
      // it is: a sweep filling itself asked for a frame at each of its 33 results, and every view
      // of the synchronisation page was drawn again each time (a long task at each, on a phone).
      if (!this.stale.has(name) && this.shown.get(name) === t) continue;
      const ctx = context(this.canvases[name]);
      const kind = this.kind(name);
      // A still view, and while paused one more than a screen away, is drawn in a task of its own
      // after this frame: at load every view is due at once, and drawing them all in one task
      // was the pages' longest task (keyframes: 300 ms on Lighthouse's phone).
      if (kind === "still" || (!playing && this.stale.has(name) && offScreen(this.canvases[name]) > innerHeight)) {
        if (this.stale.has(name)) this.paintLater(name, t);
        continue;
      }
      if (kind === "layered") this.layered(name, ctx, frame);
      else this.paint(name, ctx, frame);
      this.shown.set(name, t);
      this.stale.delete(name);
      this.uncover(name);
    }
    return drawn;
  }

  /**
   * Draws a still view in a task of its own after this frame: it waits for nothing that moves,
   * and the frame (the first one above all) is not held up by it. One view a task: the keyframes
   * page's four still views in one task were its longest task at load (157 ms on a phone's
   * throttled CPU), and a phone's reader can touch the page between any two.
   * @param {Name} name
   * @param {number} t
   */
  paintLater(name, t) {
    this.stale.delete(name);
    this.later.add(name);
    if (this.later.size > 1) return;
    const next = () => {
      // The view nearest the screen first: the one the reader just moved comes before the rest.
      const [view] = [...this.later].sort((a, b) => offScreen(this.canvases[a]) - offScreen(this.canvases[b]));
      if (view === undefined) return;
      this.later.delete(view);
      const frame = this.frame(view, t);
      if (frame) {
        this.paintInParts(view, context(this.canvases[view]), frame);
        this.uncover(view);
      }
      if (this.later.size > 0) setTimeout(next);
    };
    setTimeout(next);
  }

  /**
   * Copies the still layer of a view (drawn again first when stale) and draws the moving part
   * over it.
   * @param {Name} name
   * @param {CanvasRenderingContext2D} ctx
   * @param {Frame} frame
   */
  layered(name, ctx, frame) {
    const figure = /** @type {Figure} */ (this.figure);
    const canvas = this.canvases[name];
    let layer = this.layers.get(name);
    if (!layer) this.layers.set(name, (layer = document.createElement("canvas")));
    if (this.stale.has(name) || layer.width !== canvas.width || layer.height !== canvas.height) {
      layer.width = canvas.width;
      layer.height = canvas.height;
      figure.draw(name, context(layer), frame, "still");
    }
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.drawImage(layer, 0, 0);
    figure.draw(name, ctx, frame, "moving");
  }

  /**
   * Sizes every canvas to the pixels it covers, now and on every change, and calls `draw` in
   * the same rendering update (so that a view never shows blank).
   * @param {(resized: Name[]) => void} draw
   */
  observe(draw) {
    this.sizing = new Canvases(this.canvases, (resized) => {
      this.invalidate(resized);
      draw(resized);
    });
    this.sizes = this.sizing.sizes;
    return this.sizing;
  }

  /**
   * Saves view `name` at time `t` as `file`.png (twice the screen's resolution) or .svg.
   * @param {Name} name
   * @param {string} format
   * @param {string} file the file name without its extension
   * @param {number} t
   * @param {(frame: Frame) => string} [svg] the SVG of a view the page draws itself
   */
  save(name, format, file, t, svg) {
    const figure = this.figure;
    const frame = this.frame(name, t);
    if (!figure || !frame) throw new Error(`the ${name} view is not laid out`);
    return saveAs(file, format, {
      svg: () => this.svgOf(name, frame, svg),
      png: () => png(frame, (ctx, ratio) => this.paint(name, ctx, { ...frame, pixelRatio: ratio })),
    });
  }
}

/** How far `canvas` is above or below the screen, in CSS pixels (0 on it). */
function offScreen(/** @type {HTMLCanvasElement} */ canvas) {
  const box = canvas.getBoundingClientRect();
  return Math.max(0, box.top - innerHeight, -box.bottom);
}

/** The 2D context of a canvas (a page whose canvases cannot draw has nothing to show). */
export function context(/** @type {HTMLCanvasElement} */ canvas) {
  const ctx = canvas.getContext("2d");
  if (!ctx) throw new Error("this browser cannot draw on a canvas");
  return ctx;
}
