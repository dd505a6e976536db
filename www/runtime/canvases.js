// @ts-check
// Sizing canvases, for every page and <kli-figure>: each canvas's backing store is the number of
// device pixels it covers on screen, so figures stay sharp on high-DPI screens and when a host
// scales them (reveal.js scales a 960×700 slide by 1.48 on a 1920×1080 screen, with a CSS
// transform that leaves the layout size, and so ResizeObserver, unchanged).

/** @typedef {{ width: number, height: number, ratio: number }} Size CSS pixels, and device pixels per CSS pixel */

/**
 * How much larger than its layout box `element` is drawn on screen: 1 unless an ancestor is
 * transformed (or zoomed) to scale it.
 * @param {HTMLElement} element
 */
export function hostScale(element) {
  const layout = element.offsetWidth;
  const screen = element.getBoundingClientRect().width;
  return layout > 0 && screen > 0 ? screen / layout : 1;
}

/**
 * Sizes each canvas to its box, now and whenever the box, the pixel ratio or a host's scale
 * changes, and calls `draw` after (in the same rendering update, so a view never shows blank).
 * `sizes` is filled with each canvas's CSS size and the ratio to draw it at.
 * @template {string} Name
 */
export class Canvases {
  /**
   * @param {Record<Name, HTMLCanvasElement>} canvases
   * @param {(resized: Name[]) => void} draw
   */
  constructor(canvases, draw) {
    this.canvases = canvases;
    this.draw = draw;
    /** @type {Partial<Record<Name, Size>>} */
    this.sizes = {};
    /** @type {Partial<Record<Name, { width: number, height: number }>>} layout sizes, from the ResizeObserver */
    this.boxes = {};
    this.observer = new ResizeObserver((entries) => {
      for (const entry of entries) {
        const name = this.nameOf(entry.target);
        // A canvas taken out of the layout (printing hides them) keeps its last size: sized to
        // nothing, the printed SVG drawn from it would be square.
        const { width, height } = entry.contentRect;
        if (name && width > 0 && height > 0) this.boxes[name] = { width, height };
      }
      this.refit(true);
    });
    // A host's new scale or a new pixel ratio comes with a window resize (reveal.js rescales its
    // slides then), but the host's own handler may run after this one: look again a frame later.
    this.onResize = () => requestAnimationFrame(() => this.refit(false));
    for (const canvas of Object.values(canvases)) this.observer.observe(/** @type {HTMLCanvasElement} */ (canvas));
    addEventListener("resize", this.onResize);
  }

  /** @returns {Name | undefined} */
  nameOf(/** @type {Element} */ target) {
    return /** @type {Name[]} */ (Object.keys(this.canvases)).find((name) => this.canvases[name] === target);
  }

  /**
   * Sets every laid-out canvas's backing store to the device pixels it covers; calls `draw` with
   * the canvases that changed (or always, when `always`). Returns the names that changed.
   * @param {boolean} always
   */
  refit(always) {
    /** @type {Name[]} */
    const resized = [];
    for (const name of /** @type {Name[]} */ (Object.keys(this.canvases))) {
      const box = this.boxes[name];
      if (!box) continue;
      const canvas = this.canvases[name];
      const ratio = (devicePixelRatio || 1) * hostScale(canvas);
      const width = Math.max(1, Math.round(box.width * ratio));
      const height = Math.max(1, Math.round(box.height * ratio));
      const old = this.sizes[name];
      if (old && old.width === box.width && old.height === box.height && old.ratio === ratio && canvas.width === width) continue;
      this.sizes[name] = { width: box.width, height: box.height, ratio };
      canvas.width = width;
      canvas.height = height;
      resized.push(name);
    }
    if (resized.length > 0 || always) this.draw(resized);
    return resized;
  }

  disconnect() {
    this.observer.disconnect();
    removeEventListener("resize", this.onResize);
  }
}
