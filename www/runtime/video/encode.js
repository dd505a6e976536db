// @ts-check
// A clip encoded in the browser, frame by frame: MP4 (H.264) and WebM (VP9) through WebCodecs,
// muxed by mediabunny; an animated GIF by gifenc. Each frame is drawn for its own time by the
// caller (`draw(ctx, k)`), never captured from the screen, so the clip is smooth whatever the
// machine. The page stays responsive: the loop yields to it between frames, and the encoder
// works off the main thread.

/** The formats: their file extension, MIME type and WebCodecs codec (mediabunny's name). */
export const FORMATS = /** @type {const} */ ({
  mp4: { label: "MP4 (H.264)", extension: "mp4", type: "video/mp4", codec: "avc" },
  webm: { label: "WebM (VP9)", extension: "webm", type: "video/webm", codec: "vp9" },
  gif: { label: "animated GIF", extension: "gif", type: "image/gif", codec: null },
});
/** @typedef {keyof typeof FORMATS} Format */

/** The sizes offered, in pixels. */
export const SIZES = /** @type {const} */ ({ "720p": [1280, 720], "1080p": [1920, 1080] });
/** @typedef {keyof typeof SIZES} Size */

/** A GIF's frame delay is in hundredths of a second and browsers slow any below 2: GIFs are
 *  made at 25 frames a second (4 hundredths each), whatever rate is asked for the videos. */
export const GIF_RATE = 25;

/**
 * The part of gifenc (which ships no types) used here.
 * @typedef {object} Gifenc
 * @property {() => { writeFrame(index: Uint8Array, width: number, height: number, options: { palette: number[][], delay: number }): void,
 *   finish(): void, bytes(): Uint8Array<ArrayBuffer> }} GIFEncoder
 * @property {(rgba: Uint8ClampedArray, colours: number) => number[][]} quantize
 * @property {(rgba: Uint8ClampedArray, palette: number[][]) => Uint8Array} applyPalette
 */
/** mediabunny and gifenc, as `make www` bundles them from ./codecs.js (www/vendor is built). */
const codecs = () => /** @type {Promise<typeof import("mediabunny") & Gifenc>} */ (/** @type {unknown} */ (
  import("../../vendor/codecs.js")));

/**
 * Whether this browser can encode each format at `width` × `height` and `fps`.
 * @param {number} width
 * @param {number} height
 * @param {number} fps
 * @returns {Promise<Record<Format, boolean>>}
 */
export async function supported(width, height, fps) {
  const { canEncodeVideo } = await codecs();
  const can = async (/** @type {"avc" | "vp9"} */ codec) => {
    if (typeof VideoEncoder !== "function") return false;
    return canEncodeVideo(codec, { width, height, frameRate: fps }).catch(() => false);
  };
  const [mp4, webm] = await Promise.all([can("avc"), can("vp9")]);
  return { mp4, webm, gif: true };
}

/**
 * Encodes `frames` frames, each drawn by `draw(ctx, k)` onto a `width` × `height` canvas.
 * @param {object} options
 * @param {Format} options.format
 * @param {number} options.width
 * @param {number} options.height
 * @param {number} options.fps frames a second (the GIF's is GIF_RATE)
 * @param {number} options.frames how many
 * @param {(ctx: CanvasRenderingContext2D, k: number) => void} options.draw draws frame k
 * @param {(done: number) => void} [options.progress] after each frame, the frames done
 * @param {AbortSignal} [options.signal] cancels: the promise rejects with an AbortError
 * @returns {Promise<Blob>}
 */
export async function encode({ format, width, height, fps, frames, draw, progress, signal }) {
  const canvas = document.createElement("canvas");
  canvas.width = width;
  canvas.height = height;
  const ctx = canvas.getContext("2d", { willReadFrequently: format === "gif" });
  if (!ctx) throw new Error("this browser cannot draw on a canvas");
  const sink = format === "gif" ? gifSink(await codecs(), ctx) : await videoSink(await codecs(), canvas, format, fps);
  const stop = () => {
    if (signal?.aborted) throw new DOMException("the video was cancelled", "AbortError");
  };
  try {
    for (let k = 0; k < frames; k++) {
      stop();
      draw(ctx, k);
      await sink.add(k);
      progress?.(k + 1);
      await new Promise((resolve) => setTimeout(resolve)); // the page's turn
    }
    stop();
    return await sink.finish();
  } catch (error) {
    await sink.cancel();
    throw error;
  }
}

/**
 * Where the frames go: `add(k)` takes the canvas as frame k.
 * @typedef {{ add(k: number): Promise<void> | void, finish(): Promise<Blob>, cancel(): Promise<void> }} Sink
 */

/**
 * An animated GIF: each frame quantised to 256 colours of its own.
 * @param {Awaited<ReturnType<typeof codecs>>} m
 * @param {CanvasRenderingContext2D} ctx
 * @returns {Sink}
 */
function gifSink(m, ctx) {
  const gif = m.GIFEncoder();
  const { width, height } = ctx.canvas;
  return {
    add() {
      const { data } = ctx.getImageData(0, 0, width, height);
      const palette = m.quantize(data, 256);
      gif.writeFrame(m.applyPalette(data, palette), width, height, { palette, delay: 1000 / GIF_RATE });
    },
    async finish() {
      gif.finish();
      return new Blob([gif.bytes()], { type: FORMATS.gif.type });
    },
    async cancel() {},
  };
}

/**
 * An MP4 or WebM track through WebCodecs, muxed by mediabunny.
 * @param {Awaited<ReturnType<typeof codecs>>} m
 * @param {HTMLCanvasElement} canvas
 * @param {"mp4" | "webm"} format
 * @param {number} fps
 * @returns {Promise<Sink>}
 */
async function videoSink(m, canvas, format, fps) {
  const { codec, type } = FORMATS[format];
  const output = new m.Output({
    format: format === "mp4" ? new m.Mp4OutputFormat({ fastStart: "in-memory" }) : new m.WebMOutputFormat(),
    target: new m.BufferTarget(),
  });
  const source = new m.CanvasSource(canvas, { codec: /** @type {"avc" | "vp9"} */ (codec), bitrate: m.QUALITY_HIGH });
  output.addVideoTrack(source, { frameRate: fps });
  await output.start();
  return {
    add: (k) => source.add(k / fps, 1 / fps),
    async finish() {
      await output.finalize();
      return new Blob([/** @type {ArrayBuffer} */ (output.target.buffer)], { type });
    },
    cancel: () => output.cancel().catch(() => {}),
  };
}
