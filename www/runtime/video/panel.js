// @ts-check
// The "Save a video" part of a page's Save section (and what <kli-figure>.toVideo uses): the
// choices (format, size, rate, the figures in the clip, the time range or the length), a
// progress bar and Cancel. Formats this browser cannot encode are marked so and disabled.
import { composeFrame } from "./compose.js";
import { FORMATS, GIF_RATE, SIZES, encode, supported } from "./encode.js";
import { say } from "../dom.js";

/**
 * What a page gives its video panel.
 * @typedef {object} Source
 * @property {import("../figures.js").Figures<string>} figures
 * @property {import("../player.js").Player} player the run on show, through the run contract
 * @property {readonly string[]} views the page's views, in order
 * @property {readonly string[]} chosen the views of the default clip (the paper's video: object and Hopf)
 * @property {() => string} title the clip's title line
 * @property {() => string} file the file name's stem ("kli-paper-example")
 */

/**
 * The run's span, or null before the first run and for a run with no end (a clip of it is
 * recorded forward from now, each frame a frame's advance of the run).
 * @param {Source} source
 * @returns {[number, number] | null}
 */
const spanOf = (source) => (source.player.run && source.player.spanned ? source.player.span : null);

/**
 * The frames of a clip over [from, to] lasting `seconds` at `fps`: their count and times, the
 * first at `from`, the last at `to`.
 * @param {number} from
 * @param {number} to
 * @param {number} seconds
 * @param {number} fps
 */
function frameTimes(from, to, seconds, fps) {
  const frames = Math.max(2, Math.round(seconds * fps));
  return Array.from({ length: frames }, (_, k) => from + ((to - from) * k) / (frames - 1));
}

/**
 * What is wrong with a clip's choice, or "" (every choice a program can make ends in a clear
 * Error, not a trap or an endless encoding).
 * @param {Source} source
 * @param {{ format: string, size: string, fps: number, views: readonly string[], from?: number, to?: number, seconds: number }} c
 */
export function refusal(source, c) {
  const span = spanOf(source);
  const from = c.from ?? span?.[0], to = c.to ?? span?.[1];
  if (!Object.hasOwn(FORMATS, c.format)) return `format must be one of ${Object.keys(FORMATS).join(", ")} (got ${String(c.format)})`;
  if (!Object.hasOwn(SIZES, c.size)) return `size must be one of ${Object.keys(SIZES).join(", ")} (got ${String(c.size)})`;
  if (!(c.fps >= 1 && c.fps <= 120)) return `fps must be a number from 1 to 120 (got ${String(c.fps)})`;
  if (!(c.seconds >= 0.1 && c.seconds <= 600)) return `the length must be from 0.1 to 600 seconds (got ${String(c.seconds)})`;
  if (Array.isArray(c.views) && c.views.length === 0) return "choose at least one figure";
  if (!Array.isArray(c.views) || !c.views.every((v) => source.views.includes(v))) {
    return `the figures must be some of ${source.views.join(", ")}`;
  }
  if (span && !(Number.isFinite(from) && Number.isFinite(to) && /** @type {number} */ (from) >= span[0] && /** @type {number} */ (to) <= span[1] && /** @type {number} */ (from) < /** @type {number} */ (to))) {
    return `the times must satisfy ${span[0]} ≤ from < to ≤ ${span[1].toFixed(2)}`;
  }
  return "";
}

/**
 * Records a clip.
 * @param {Source} source
 * @param {{ format: import("./encode.js").Format, size: import("./encode.js").Size, fps: number, views: readonly string[],
 *   from?: number, to?: number, seconds: number, signal?: AbortSignal, progress?: (done: number, total: number) => void }} choice
 * @returns {Promise<{ blob: Blob, name: string, frames: number }>}
 */
export async function record(source, choice) {
  const problem = refusal(source, choice);
  if (problem) throw new Error(`kli video: ${problem}`);
  const [width, height] = SIZES[choice.size];
  const fps = choice.format === "gif" ? GIF_RATE : choice.fps;
  const span = spanOf(source);
  // A run with a span: each frame at its own time; one with none: a frame's advance each.
  const times = span ? frameTimes(choice.from ?? span[0], choice.to ?? span[1], choice.seconds, fps) : null;
  const frames = times?.length ?? Math.max(2, Math.round(choice.seconds * fps));
  const title = source.title();
  const blob = await encode({
    format: choice.format, width, height, fps, frames, signal: choice.signal,
    progress: (done) => choice.progress?.(done, frames),
    draw: (ctx, k) => {
      if (!times && k > 0) source.player.run?.advance(1 / fps);
      const t = times ? times[k] : source.player.t;
      composeFrame(source.figures, ctx, width, height, t, {
        views: choice.views, title, caption: `t = ${t.toFixed(2)}`, textScale: source.figures.textScale,
      });
    },
  });
  const name = `${source.file()}-${choice.size}${fps}.${FORMATS[choice.format].extension}`;
  return { blob, name, frames };
}

/**
 * Builds the panel into `container` and wires it.
 * @param {HTMLElement} container
 * @param {Source} source
 * @param {(name: string, blob: Blob) => void} download
 * @param {Readonly<Record<string, string>>} [words] the page's words, by their English (dom.js `say`)
 */
export function videoPanel(container, source, download, words) {
  const w = (/** @type {string} */ english, /** @type {Record<string, string | number>} */ values = {}) => say(words, english, values);
  const section = document.createElement("fieldset");
  section.className = "video";
  const spanned = source.player.spanned;
  const views = source.views.map((view) => `<label><input type="checkbox" name="video-view" value="${view}"${source.chosen.includes(view) ? " checked" : ""}> ${w(view)}</label>`).join(" ");
  const hint = "Each frame drawn for its own time (not filmed from the screen): smooth on any machine. MP4 and WebM play in " +
    "PowerPoint, Keynote and Google Slides; GIF goes anywhere ({rate} frames a second).";
  section.innerHTML = `<legend>${w("Save a video")}</legend>
    <p class="hint">${w(hint, { rate: GIF_RATE })}</p>
    <div class="video-choices">
      <label>${w("Format")} <select name="video-format">${Object.entries(FORMATS).map(([key, f]) => `<option value="${key}">${w(f.label)}</option>`).join("")}</select></label>
      <label>${w("Size")} <select name="video-size">${Object.keys(SIZES).map((s) => `<option value="${s}"${s === "1080p" ? " selected" : ""}>${s}</option>`).join("")}</select></label>
      <label>${w("Frames a second")} <select name="video-fps"><option value="30">30</option><option value="60" selected>60</option></select></label>
      ${spanned ? `<label>${w("From t =")} <input name="video-from" type="number" step="any" min="0" inputmode="decimal"></label>
      <label>${w("to t =")} <input name="video-to" type="number" step="any" min="0" inputmode="decimal"></label>` : ""}
      <label>${w("Length, seconds")} <input name="video-seconds" type="number" step="any" min="0.1" max="600" value="" inputmode="decimal"></label>
    </div>
    <p class="video-views">${w("Figures in the clip:")} ${views}</p>
    <p><button type="button" class="video-start">${w("Save video")}</button>
      <button type="button" class="video-cancel" hidden>${w("Cancel")}</button>
      <progress class="video-progress" max="1" value="0" hidden aria-label="${w("Video progress")}"></progress></p>
    <p class="video-status" role="status" aria-live="polite"></p>`;
  container.append(section);
  const field = (/** @type {string} */ name) => /** @type {HTMLInputElement & HTMLSelectElement} */ (section.querySelector(`[name="${name}"]`));
  const [start, cancel] = [".video-start", ".video-cancel"].map((s) => /** @type {HTMLButtonElement} */ (section.querySelector(s)));
  const bar = /** @type {HTMLProgressElement} */ (section.querySelector(".video-progress"));
  const status = /** @type {HTMLElement} */ (section.querySelector(".video-status"));
  /** The run's span in the fields, and the length it plays in at 1× (the page's clock). */
  const fill = () => {
    const span = spanOf(source);
    if (span) {
      field("video-from").value = String(span[0]);
      field("video-to").value = String(span[1]);
    }
    if (!field("video-seconds").value) field("video-seconds").value = span ? String(Math.min(60, Math.max(1, span[1] - span[0]))) : "10";
  };
  /** Marks the formats this browser cannot encode at the chosen size and rate. */
  const check = async () => {
    const [width, height] = SIZES[/** @type {import("./encode.js").Size} */ (field("video-size").value)];
    const can = await supported(width, height, Number(field("video-fps").value)).catch(() => ({ mp4: false, webm: false, gif: true }));
    for (const option of field("video-format").options) {
      const key = /** @type {import("./encode.js").Format} */ (option.value);
      option.disabled = !can[key];
      const label = w(FORMATS[key].label);
      option.textContent = can[key] ? label : w("{format} (this browser cannot encode it)", { format: label });
    }
    if (field("video-format").selectedOptions[0]?.disabled) field("video-format").value = "gif";
  };
  field("video-size").addEventListener("input", check);
  field("video-fps").addEventListener("input", check);
  /** @type {AbortController | null} */
  let running = null;
  start.addEventListener("click", async () => {
    if (running) return;
    const chosen = [...section.querySelectorAll('input[name="video-view"]:checked')].map((i) => /** @type {HTMLInputElement} */ (i).value);
    const choice = {
      format: /** @type {import("./encode.js").Format} */ (field("video-format").value),
      size: /** @type {import("./encode.js").Size} */ (field("video-size").value),
      fps: Number(field("video-fps").value), views: chosen, seconds: Number(field("video-seconds").value),
      from: spanned ? Number(field("video-from").value) : undefined,
      to: spanned ? Number(field("video-to").value) : undefined,
    };
    const problem = refusal(source, choice);
    if (problem) {
      status.textContent = w("Cannot save the video: {problem}.", { problem });
      return;
    }
    running = new AbortController();
    start.disabled = true;
    cancel.hidden = false;
    bar.hidden = false;
    bar.value = 0;
    status.textContent = w("Encoding the video…");
    const began = performance.now();
    try {
      const { blob, name, frames } = await record(source, {
        ...choice, signal: running.signal, progress: (done, total) => (bar.value = done / total),
      });
      download(name, blob);
      const took = ((performance.now() - began) / 1000).toFixed(1);
      status.textContent = w("Saved {name}: {frames} frames, {size} MB, encoded in {took} s.",
        { name, frames, size: (blob.size / 1e6).toFixed(1), took });
    } catch (error) {
      status.textContent = error instanceof DOMException && error.name === "AbortError"
        ? w("The video was cancelled.") : w("Could not save the video: {error}", { error: error instanceof Error ? error.message : String(error) });
    } finally {
      running = null;
      start.disabled = false;
      cancel.hidden = true;
      bar.hidden = true;
    }
  });
  cancel.addEventListener("click", () => running?.abort());
  fill();
  // The codecs (60 KB gzipped) load when the panel is first used, not with the page.
  const firstUse = () => {
    section.removeEventListener("focusin", firstUse);
    section.removeEventListener("pointerenter", firstUse);
    check();
  };
  section.addEventListener("focusin", firstUse);
  section.addEventListener("pointerenter", firstUse);
  return { fill, check };
}
