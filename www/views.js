// @ts-check
// The four canvases: their sizes, the still layers of the sphere and the plots, and drawing a
// frame at time t. All drawing is the module's (crates/kli-demo).

/** @typedef {import("./pkg/kli_demo.js").Demo} Demo */
/** @typedef {"object" | "sphere" | "filmstrip" | "plots"} ViewName */

export class Views {
  /**
   * @param {Record<ViewName, HTMLCanvasElement>} canvases
   * @param {number[]} view the sphere's [azimuth, elevation] in radians
   */
  constructor(canvases, view) {
    this.canvases = canvases;
    this.view = view;
    /** @type {Partial<Record<ViewName, { width: number, height: number }>>} CSS sizes, once laid out */
    this.sizes = {};
    /** @type {Demo | null} */
    this.demo = null;
    // The sphere and the plots change only with the run, the size or the view: each is drawn
    // once into an offscreen layer, which every frame copies before drawing the time over it.
    this.layers = {
      sphere: { canvas: document.createElement("canvas"), stale: true },
      plots: { canvas: document.createElement("canvas"), stale: true },
    };
  }

  /** Shows a new run. */
  show(/** @type {Demo} */ demo) {
    this.demo = demo;
    this.layers.sphere.stale = this.layers.plots.stale = true;
    this.drawFilmstrip();
  }

  /** Turns the sphere by (azimuth, elevation) radians; the elevation stays within ±89°. */
  turn(/** @type {number} */ azimuth, /** @type {number} */ elevation) {
    this.view[0] += azimuth;
    this.view[1] = Math.min(Math.max(this.view[1] + elevation, -1.55), 1.55);
    this.layers.sphere.stale = true;
  }

  /** Draws the live views at time t; returns whether anything was drawn. */
  render(/** @type {number} */ t) {
    const demo = this.demo;
    if (!demo) return false;
    const ratio = devicePixelRatio || 1;
    const [azimuth, elevation] = this.view;
    const object = this.sizes.object;
    if (object) demo.drawObject(context(this.canvases.object), object.width, object.height, ratio, t);
    this.layered("sphere",
      (ctx, w, h) => demo.drawSphere(ctx, w, h, ratio, azimuth, elevation),
      (ctx, w, h) => demo.drawSphereTime(ctx, w, h, ratio, t, azimuth, elevation));
    this.layered("plots",
      (ctx, w, h) => demo.drawPlots(ctx, w, h, ratio),
      (ctx, w, h) => demo.drawPlotsTime(ctx, w, h, ratio, t));
    return object !== undefined;
  }

  /**
   * Copies the still layer of a view (redrawn first if stale) and draws the moving part over it.
   * @param {"sphere" | "plots"} name
   * @param {(ctx: CanvasRenderingContext2D, width: number, height: number) => void} still
   * @param {(ctx: CanvasRenderingContext2D, width: number, height: number) => void} moving
   */
  layered(name, still, moving) {
    const size = this.sizes[name];
    if (!size) return;
    const canvas = this.canvases[name];
    const layer = this.layers[name];
    if (layer.stale || layer.canvas.width !== canvas.width || layer.canvas.height !== canvas.height) {
      layer.canvas.width = canvas.width;
      layer.canvas.height = canvas.height;
      still(context(layer.canvas), size.width, size.height);
      layer.stale = false;
    }
    const ctx = context(canvas);
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.drawImage(layer.canvas, 0, 0);
    moving(ctx, size.width, size.height);
  }

  /**
   * Draws one view whole (its still and moving parts) onto `ctx` at `ratio`: for saving it.
   * @param {ViewName} name
   * @param {CanvasRenderingContext2D} ctx
   * @param {{ width: number, height: number }} size CSS pixels
   * @param {number} ratio
   * @param {number} t
   */
  drawInto(name, ctx, { width, height }, ratio, t) {
    const demo = this.demo;
    if (!demo) return;
    const [azimuth, elevation] = this.view;
    if (name === "object") demo.drawObject(ctx, width, height, ratio, t);
    if (name === "filmstrip") demo.drawFilmstrip(ctx, width, height, ratio);
    if (name === "sphere") {
      demo.drawSphere(ctx, width, height, ratio, azimuth, elevation);
      demo.drawSphereTime(ctx, width, height, ratio, t, azimuth, elevation);
    }
    if (name === "plots") {
      demo.drawPlots(ctx, width, height, ratio);
      demo.drawPlotsTime(ctx, width, height, ratio, t);
    }
  }

  drawFilmstrip() {
    const size = this.sizes.filmstrip;
    if (this.demo && size) {
      this.demo.drawFilmstrip(context(this.canvases.filmstrip), size.width, size.height, devicePixelRatio || 1);
    }
  }

  /** Sizes every canvas to its box at the device's pixel ratio, now and on every resize, and
   *  calls `draw` in the same rendering update, so a view never shows blank. */
  observe(/** @type {() => void} */ draw) {
    const names = /** @type {ViewName[]} */ (Object.keys(this.canvases));
    const observer = new ResizeObserver((entries) => {
      const ratio = devicePixelRatio || 1;
      for (const entry of entries) {
        const name = names.find((key) => this.canvases[key] === entry.target);
        if (!name) continue;
        const { width, height } = entry.contentRect;
        this.sizes[name] = { width, height };
        const canvas = this.canvases[name];
        canvas.width = Math.max(1, Math.round(width * ratio));
        canvas.height = Math.max(1, Math.round(height * ratio));
        // The filmstrip is still: it can wait one task, after the first frame of the live views.
        if (name === "filmstrip") setTimeout(() => this.drawFilmstrip());
      }
      draw();
    });
    for (const canvas of Object.values(this.canvases)) observer.observe(canvas);
  }
}

/** The 2D context of a canvas (a page whose canvases cannot draw has nothing to show). */
function context(/** @type {HTMLCanvasElement} */ canvas) {
  const ctx = canvas.getContext("2d");
  if (!ctx) throw new Error("this browser cannot draw on a canvas");
  return ctx;
}
