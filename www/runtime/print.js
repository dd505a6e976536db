// @ts-check
// Printing, for every page and <kli-figure>: when the browser prints (or a deck exports to PDF),
// each figure is put in as its SVG (vector paths and text) drawn at a chosen time, in place of
// the canvas, a bitmap at whatever moment the animation had reached. Taken out again after.

/**
 * @template {string} Name
 * @param {() => import("./figures.js").Figures<Name> | null} figuresOf the figures (a figure rebuilds its own)
 * @param {() => number} time the time to print the figures at
 * @param {Partial<Record<Name, (frame: import("./figures.js").Frame) => string>>} [svgs] SVG makers of views drawn by the page
 * @param {Document | ShadowRoot} [root] where the figures are (a figure's shadow root)
 */
export function wirePrinting(figuresOf, time, svgs = {}, root = document) {
  const style = Object.assign(document.createElement("style"), { textContent: PRINT_STYLE });
  (root instanceof Document ? root.head : root).append(style);
  const remove = () => root.querySelectorAll(".print-figure").forEach((element) => element.remove());
  const show = () => {
    remove();
    const figures = figuresOf();
    if (!figures) return;
    for (const [name, svg] of figures.svgs(time(), svgs)) {
      const holder = document.createElement("div");
      holder.className = "print-figure";
      holder.innerHTML = svg;
      figures.canvases[name].after(holder);
    }
  };
  const print = matchMedia("print");
  const change = () => (print.matches ? show() : remove());
  addEventListener("beforeprint", show);
  addEventListener("afterprint", remove);
  print.addEventListener("change", change);
  /** Stops printing as SVG (a figure taken out of its page). */
  const dispose = () => {
    removeEventListener("beforeprint", show);
    removeEventListener("afterprint", remove);
    print.removeEventListener("change", change);
    remove();
    style.remove();
  };
  return { show, remove, dispose };
}

/** The style that swaps the canvases for their SVGs in print. */
const PRINT_STYLE = `
.print-figure { display: none; }
@media print {
  canvas { display: none !important; }
  .print-figure { display: block; }
  .print-figure svg { display: block; width: 100%; height: auto; }
}`;
