// @ts-check
// What the swarm and keyframes pages share about their canvases and their module: sizing every
// canvas to its box at the device's pixel ratio, and loading the module with a message on
// failure. (The KLI page keeps still layers, views.js.)

/**
 * Sizes each canvas to its box (CSS pixels in `sizes`, backing store at the pixel ratio), now
 * and on every resize, and calls `draw` in the same rendering update.
 * @param {Record<string, HTMLCanvasElement>} canvases
 * @param {Record<string, { width: number, height: number }>} sizes
 * @param {() => void} draw
 */
export function observeCanvases(canvases, sizes, draw) {
  const observer = new ResizeObserver((entries) => {
    const ratio = devicePixelRatio || 1;
    for (const entry of entries) {
      const name = Object.keys(canvases).find((key) => canvases[key] === entry.target);
      if (!name) continue;
      const { width, height } = entry.contentRect;
      sizes[name] = { width, height };
      const canvas = canvases[name];
      canvas.width = Math.max(1, Math.round(width * ratio));
      canvas.height = Math.max(1, Math.round(height * ratio));
    }
    draw();
  });
  for (const canvas of Object.values(canvases)) observer.observe(canvas);
}

/**
 * Loads the page's module; on failure says why in `status` and resolves to false.
 * @param {() => Promise<unknown>} init
 * @param {HTMLElement} status
 */
export async function loadModule(init, status) {
  try {
    await init();
    return true;
  } catch (error) {
    status.textContent = `The WebAssembly module could not be loaded: ${error instanceof Error ? error.message : error}`;
    status.classList.add("error");
    return false;
  }
}
