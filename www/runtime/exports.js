// @ts-check
// Saving what a page shows: a figure as PNG (twice the screen's resolution) or SVG (the module's
// vector drawing), the numbers behind it as CSV or JSON. The drawing and the data are the module's.
import { say } from "./dom.js";

/**
 * Offers `content` as a file named `name`.
 * @param {string} name
 * @param {string} type MIME type
 * @param {BlobPart} content
 */
export function download(name, type, content) {
  const url = URL.createObjectURL(new Blob([content], { type }));
  const link = Object.assign(document.createElement("a"), { href: url, download: name });
  document.body.append(link);
  link.click();
  link.remove();
  setTimeout(() => URL.revokeObjectURL(url), 10_000);
}

/**
 * A figure drawn at twice the screen's resolution, as a PNG.
 * @param {{ width: number, height: number }} size CSS pixels
 * @param {(ctx: CanvasRenderingContext2D, ratio: number) => void} draw draws the figure at `ratio`
 * @returns {Promise<Blob>}
 */
export function png(size, draw) {
  const ratio = 2 * (devicePixelRatio || 1);
  const canvas = document.createElement("canvas");
  canvas.width = Math.max(1, Math.round(size.width * ratio));
  canvas.height = Math.max(1, Math.round(size.height * ratio));
  const ctx = canvas.getContext("2d");
  if (!ctx) return Promise.reject(new Error("this browser cannot draw on a canvas"));
  draw(ctx, ratio);
  return new Promise((resolve, reject) => canvas.toBlob((blob) => (blob ? resolve(blob) : reject(new Error("no PNG"))), "image/png"));
}

const TYPES = { csv: "text/csv", json: "application/json", svg: "image/svg+xml", png: "image/png" };

/**
 * Saves `name`.`format`, made by the maker for that format.
 * @param {string} name the file name without its extension
 * @param {string} format "csv", "json", "svg" or "png"
 * @param {Partial<Record<"csv" | "json" | "svg" | "png", () => BlobPart | Promise<BlobPart>>>} makers
 */
export async function saveAs(name, format, makers) {
  const kind = /** @type {keyof typeof TYPES} */ (format);
  const make = Object.hasOwn(TYPES, kind) ? makers[kind] : undefined;
  if (!make) throw new Error(`${name} cannot be saved as ${format}`);
  download(`${name}.${format}`, TYPES[kind], await make());
}

/**
 * Wires the page's save buttons: each has `data-save="<figure or data>"` and `data-format`
 * ("png", "svg", "csv" or "json"); `save` does the rest. A failure is said in `status`.
 * @param {HTMLElement} container
 * @param {(what: string, format: string) => Promise<void> | void} save
 * @param {HTMLElement} status
 * @param {Readonly<Record<string, string>>} [words] the page's words (dom.js `say`)
 */
export function wireSaving(container, save, status, words) {
  container.addEventListener("click", async (event) => {
    const button = /** @type {HTMLElement} */ (event.target).closest("button[data-save]");
    if (!(button instanceof HTMLButtonElement)) return;
    const { save: what = "", format = "" } = button.dataset;
    try {
      await save(what, format);
      status.textContent = say(words, "Saved {what}.", { what: button.getAttribute("aria-label") ?? what });
    } catch (error) {
      status.textContent = say(words, "Could not save: {error}", { error: error instanceof Error ? error.message : String(error) });
    }
  });
}

/** Time in a file name: "t1.80". */
export const timeTag = (/** @type {number} */ t) => `t${t.toFixed(2)}`;
