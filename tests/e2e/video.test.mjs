// Saving the animation as a video (issue 15, item 1), as a teacher does: choose, click, get a
// file; then the file decoded back in Chromium (mediabunny's demuxer and WebCodecs' decoder,
// ImageDecoder for the GIF): codec, size, frame count = rate × length, and the first and last
// frames against the figures drawn by the module at the first and last time.
import { test, before } from "node:test";
import assert from "node:assert/strict";
import { readFile } from "node:fs/promises";
import { buildSync } from "esbuild";
import { setup, open, root } from "./browser.mjs";

setup();

/** mediabunny's reading side, as one classic script for the page (the pages ship only the writing side). */
let reader;
before(() => {
  reader = buildSync({
    stdin: { contents: 'export { Input, BufferSource, ALL_FORMATS, CanvasSink } from "mediabunny";', resolveDir: root },
    bundle: true, format: "iife", globalName: "MediabunnyReader", write: false, minify: true, logLevel: "error",
  }).outputFiles[0].text;
});

/** The page's problems but the warning mediabunny gives when the test's reader (a second copy)
 *  is added beside the page's writer. */
const real = (problems) => problems.filter((p) => !/Mediabunny was loaded twice/.test(p));

/** Fills the video panel's choices and saves; returns the download's name and bytes. */
async function saveVideo(page, { format, size, fps, from, to, seconds, views }) {
  const panel = page.locator("fieldset.video");
  await panel.locator('[name="video-format"]').selectOption(format);
  await panel.locator('[name="video-size"]').selectOption(size);
  await panel.locator('[name="video-fps"]').selectOption(String(fps));
  if (from !== undefined) await panel.locator('[name="video-from"]').fill(String(from));
  if (to !== undefined) await panel.locator('[name="video-to"]').fill(String(to));
  await panel.locator('[name="video-seconds"]').fill(String(seconds));
  if (views) {
    for (const box of await panel.locator('input[name="video-view"]').all()) {
      await box.setChecked(views.includes(await box.getAttribute("value")));
    }
  }
  const [download] = await Promise.all([page.waitForEvent("download", { timeout: 120000 }), panel.locator(".video-start").click()]);
  return { name: download.suggestedFilename(), bytes: await readFile(await download.path()), status: () => panel.locator(".video-status").textContent() };
}

/**
 * Decodes `bytes` in the page and compares its first and last frames with the frame composed by
 * the module's drawing at `times` (the page's module, the default camera).
 */
async function decode(page, bytes, { module, make, views, title, times }) {
  await page.addScriptTag({ content: reader });
  return page.evaluate(async ({ base64, module, make, views, title, times }) => {
    const bytes = Uint8Array.from(atob(base64), (c) => c.charCodeAt(0));
    const { Input, BufferSource, ALL_FORMATS, CanvasSink } = window.MediabunnyReader;
    const input = new Input({ source: new BufferSource(bytes), formats: ALL_FORMATS });
    const track = await input.getPrimaryVideoTrack();
    const frames = [];
    for await (const { canvas } of new CanvasSink(track).canvases()) frames.push(canvas);
    const pixels = (canvas) => canvas.getContext("2d").getImageData(0, 0, canvas.width, canvas.height).data;
    // The reference: the same composition (title line, views side by side) of the module's drawing.
    const m = await import(module);
    const { composeFrame } = await import("./runtime/video/compose.js");
    const demo = new Function("m", `return ${make}`)(m);
    const [azimuth, elevation] = m.defaultCamera();
    const figures = { camera: { azimuth, elevation }, paint: (view, ctx, frame) => demo.draw(view, ctx, frame) };
    const reference = (t) => {
      const canvas = Object.assign(document.createElement("canvas"), { width: track.displayWidth, height: track.displayHeight });
      composeFrame(figures, canvas.getContext("2d"), canvas.width, canvas.height, t, { views, title, caption: `t = ${t.toFixed(2)}` });
      return pixels(canvas);
    };
    const difference = (a, b) => {
      let sum = 0;
      for (let i = 0; i < a.length; i += 4) sum += Math.abs(a[i] - b[i]) + Math.abs(a[i + 1] - b[i + 1]) + Math.abs(a[i + 2] - b[i + 2]);
      return sum / (a.length / 4) / 3;
    };
    const [first, last] = [pixels(frames[0]), pixels(frames[frames.length - 1])];
    const [start, end] = times.map(reference);
    // Where the figure moves between the two times (the markers, the caption): there a frame must
    // be its own time's, not the other's.
    const moving = (a, b, c) => {
      let own = 0, other = 0, n = 0;
      for (let i = 0; i < a.length; i += 4) {
        if (Math.abs(b[i] - c[i]) + Math.abs(b[i + 1] - c[i + 1]) + Math.abs(b[i + 2] - c[i + 2]) < 60) continue;
        own += Math.abs(a[i] - b[i]) + Math.abs(a[i + 1] - b[i + 1]) + Math.abs(a[i + 2] - b[i + 2]);
        other += Math.abs(a[i] - c[i]) + Math.abs(a[i + 1] - c[i + 1]) + Math.abs(a[i + 2] - c[i + 2]);
        n++;
      }
      return { own: own / n / 3, other: other / n / 3, pixels: n };
    };
    return {
      codec: track.codec, width: track.displayWidth, height: track.displayHeight, frames: frames.length,
      first: difference(first, start), last: difference(last, end),
      firstMoving: moving(first, start, end), lastMoving: moving(last, end, start),
    };
  }, { base64: bytes.toString("base64"), module, make, views, title, times });
}

test("KLI page: the paper's video as MP4 (H.264), decoded back: codec, 1280×720, 30 × 1 s frames, first and last at t = 0 and 2", async () => {
  const { page, context, problems } = await open("?t=0");
  try {
    const saved = await saveVideo(page, { format: "mp4", size: "720p", fps: 30, from: 0, to: 2, seconds: 1 });
    assert.equal(saved.name, "kli-paper-example-720p30.mp4");
    assert.match(await saved.status(), /^Saved kli-paper-example-720p30\.mp4: 30 frames, [\d.]+ MB, encoded in [\d.]+ s\.$/);
    const result = await decode(page, saved.bytes, {
      module: "./pkg/kli_demo.js", make: "new m.KliDemo([0, 0, 0, 1], [0.5, 0.5, 0.5, 0.5])", views: ["object", "hopf"],
      title: "The paper's example: KLI from p to r, and its Hopf curve on S²", times: [0, 2],
    });
    assert.equal(result.codec, "avc");
    assert.deepEqual([result.width, result.height, result.frames], [1280, 720, 30]);
    // Lossy, so a small mean difference (0–255 a channel), and far below the other end's.
    assert.ok(result.first < 3 && result.last < 3, JSON.stringify(result));
    for (const moving of [result.firstMoving, result.lastMoving]) {
      assert.ok(moving.pixels > 500 && moving.own < moving.other / 4, JSON.stringify(result));
    }
    assert.deepEqual(real(problems), []);
  } finally {
    await context.close();
  }
});

test("keyframes page: WebM (VP9) of one view at 60 frames a second, decoded back", async () => {
  const { page, context, problems } = await open("keyframes.html?t=0");
  try {
    const keys = await page.evaluate(() => document.querySelector("input[name=keys]").value);
    const count = keys.split(";").length;
    const saved = await saveVideo(page, { format: "webm", size: "720p", fps: 60, from: 0, to: 3, seconds: 0.5, views: ["hopf"] });
    assert.equal(saved.name, `kli-keyframes-${count}-keys-720p60.webm`);
    const result = await decode(page, saved.bytes, {
      module: "./pkg/keyframes_demo.js", views: ["hopf"],
      make: `new m.KeyframesDemo(new Float64Array(${JSON.stringify(keys.split(";").flatMap((k) => k.split(",").map(Number)))}), new Float64Array(0), 1)`,
      title: `Through ${count} keys: the Kuramoto–Lohe chain, Squad and piecewise SLERP`, times: [0, 3],
    });
    assert.equal(result.codec, "vp9");
    assert.deepEqual([result.width, result.height, result.frames], [1280, 720, 30]);
    assert.ok(result.first < 3 && result.last < 3, JSON.stringify(result));
    for (const moving of [result.firstMoving, result.lastMoving]) {
      assert.ok(moving.pixels > 100 && moving.own < moving.other / 4, JSON.stringify(result));
    }
    assert.deepEqual(real(problems), []);
  } finally {
    await context.close();
  }
});

test("an animated GIF at 25 frames a second has rate × length frames; Cancel stops an encoding", async () => {
  const { page, context, problems } = await open("?t=0");
  try {
    const saved = await saveVideo(page, { format: "gif", size: "720p", fps: 60, from: 0, to: 11.66, seconds: 0.8 });
    assert.equal(saved.name, "kli-paper-example-720p25.gif");
    const gif = await page.evaluate(async (base64) => {
      const data = Uint8Array.from(atob(base64), (c) => c.charCodeAt(0));
      const decoder = new ImageDecoder({ data, type: "image/gif" });
      await decoder.tracks.ready;
      const { image } = await decoder.decode({ frameIndex: 0 });
      return { frames: decoder.tracks.selectedTrack.frameCount, width: image.displayWidth, height: image.displayHeight };
    }, saved.bytes.toString("base64"));
    assert.deepEqual(gif, { frames: 20, width: 1280, height: 720 });
    // A long clip, cancelled at once: no file, the panel says so, and the page still plays.
    const panel = page.locator("fieldset.video");
    await panel.locator('[name="video-format"]').selectOption("mp4");
    await panel.locator('[name="video-seconds"]').fill("60");
    let downloaded = false;
    page.on("download", () => (downloaded = true));
    await panel.locator(".video-start").click();
    await panel.locator(".video-cancel").click();
    await page.waitForFunction(() => /cancelled/.test(document.querySelector(".video-status").textContent));
    assert.equal(downloaded, false);
    assert.equal(await panel.locator(".video-start").isDisabled(), false);
    // A refused choice is said, not attempted.
    await panel.locator('[name="video-from"]').fill("5");
    await panel.locator('[name="video-to"]').fill("1");
    await panel.locator(".video-start").click();
    assert.match(await panel.locator(".video-status").textContent(), /^Cannot save the video: the times must satisfy 0 ≤ from < to ≤ 11\.66\.$/);
    assert.deepEqual(real(problems), []);
  } finally {
    await context.close();
  }
});

test("<kli-figure>.toVideo(): a WebM of the figure, its frame count, and the GIF of a swarm", async () => {
  const { page, context, problems } = await open("examples/figures.html");
  try {
    const result = await page.evaluate(async () => {
      const figure = document.querySelector("kli-figure");
      await new Promise((resolve) => setTimeout(resolve, 300));
      const { blob, name, frames } = await figure.toVideo({ format: "webm", size: "720p", fps: 30, seconds: 0.5 });
      // Whatever a program passes ends in a clear Error.
      const refused = [];
      for (const options of [{ format: "avi" }, { size: "4k" }, { fps: 0 }, { seconds: 1e9 }, { from: 5, to: 1 }, { fps: NaN }]) {
        refused.push(await figure.toVideo(options).then(() => "accepted", (e) => e.message));
      }
      return { name, frames, type: blob.type, size: blob.size, svg: figure.toSvg(1).startsWith("<svg"), refused };
    });
    assert.deepEqual(result.refused, [
      "kli video: format must be one of mp4, webm, gif (got avi)",
      "kli video: size must be one of 720p, 1080p (got 4k)",
      "kli video: fps must be a number from 1 to 120 (got 0)",
      "kli video: the length must be from 0.1 to 600 seconds (got 1000000000)",
      `kli video: the times must satisfy 0 ≤ from < to ≤ 11.66`,
      "kli video: fps must be a number from 1 to 120 (got NaN)",
    ]);
    assert.equal(result.frames, 15);
    assert.match(result.name, /^kli-\w+-720p30\.webm$/);
    assert.equal(result.type, "video/webm");
    assert.ok(result.size > 1000 && result.svg, JSON.stringify(result));
    assert.deepEqual(real(problems), []);
  } finally {
    await context.close();
  }
});

test("swarm page: a run that keeps its own time is recorded forward from now (no time range), frames = rate × length", async () => {
  const { page, context, problems } = await open("swarm.html?n=60&seed=4");
  try {
    assert.equal(await page.locator('[name="video-from"]').count(), 0, "no time range for a swarm");
    const saved = await saveVideo(page, { format: "webm", size: "720p", fps: 30, seconds: 0.4 });
    assert.equal(saved.name, "kli-swarm-60-oscillators-720p30.webm");
    assert.match(await saved.status(), /: 12 frames,/);
    assert.deepEqual(real(problems), []);
  } finally {
    await context.close();
  }
});
