// @ts-check
// One frame of a clip: a title line over the chosen views side by side, each painted by the
// module for the frame's own time (the figures' drawing path, as on the page), at a layout of
// 960 CSS pixels across scaled to the clip's pixels, so labels and lines keep their proportions
// at 720p and 1080p.

/** The layout's width in CSS pixels, and the title line's height. */
export const LAYOUT_WIDTH = 960;
const TITLE = 40;

/** @type {Map<string, HTMLCanvasElement>} scratch canvases by size, reused frame to frame */
const scratch = new Map();
function canvasOf(/** @type {number} */ width, /** @type {number} */ height) {
  const key = `${width}x${height}`;
  let canvas = scratch.get(key);
  if (!canvas) {
    scratch.clear();
    canvas = Object.assign(document.createElement("canvas"), { width, height });
    scratch.set(key, canvas);
  }
  return canvas;
}

/**
 * Draws the frame at time `t` onto `ctx`, `width` × `height` pixels.
 * @template {string} Name
 * @param {import("../figures.js").Figures<Name>} figures
 * @param {CanvasRenderingContext2D} ctx
 * @param {number} width
 * @param {number} height
 * @param {number} t
 * @param {{ views: readonly Name[], title: string, caption: string, textScale?: number }} what
 */
export function composeFrame(figures, ctx, width, height, t, { views, title, caption, textScale = 1 }) {
  const ratio = width / LAYOUT_WIDTH;
  const cssHeight = height / ratio;
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  ctx.fillStyle = "#ffffff";
  ctx.fillRect(0, 0, width, height);
  ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
  ctx.fillStyle = "#1f2933";
  ctx.textBaseline = "middle";
  ctx.font = `600 ${Math.round(17 * textScale)}px system-ui, sans-serif`;
  ctx.textAlign = "left";
  ctx.fillText(title, 14, TITLE / 2, LAYOUT_WIDTH - 150);
  ctx.font = `${Math.round(15 * textScale)}px system-ui, sans-serif`;
  ctx.textAlign = "right";
  ctx.fillText(caption, LAYOUT_WIDTH - 14, TITLE / 2);
  const cell = { width: LAYOUT_WIDTH / views.length, height: cssHeight - TITLE };
  const { azimuth, elevation } = figures.camera;
  views.forEach((view, i) => {
    const [w, h] = [Math.round(cell.width * ratio), Math.round(cell.height * ratio)];
    const canvas = canvasOf(w, h);
    const context = /** @type {CanvasRenderingContext2D} */ (canvas.getContext("2d"));
    figures.paint(view, context, { width: cell.width, height: cell.height, pixelRatio: ratio, t, azimuth, elevation, textScale });
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.drawImage(canvas, Math.round(i * cell.width * ratio), Math.round(TITLE * ratio));
  });
}
