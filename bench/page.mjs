// The page's weight and speed in headless Chromium: the size of kli_bg.wasm (raw and gzipped),
// the time from navigation to the first drawn frame, and the script time per animation frame.
//   node bench/page.mjs [loads]
import { readFileSync } from "node:fs";
import { gzipSync } from "node:zlib";
import { join } from "node:path";
import { chromium } from "playwright-core";
import { CHROMIUM, serve } from "../scripts/static-server.mjs";

const root = new URL("../", import.meta.url).pathname;
const loads = Number(process.argv[2] ?? 7);
const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];

const wasm = readFileSync(join(root, "www/pkg/kli_bg.wasm"));
const gzipped = gzipSync(wasm, { level: 9 }).length;
console.log(`kli_bg.wasm: ${wasm.length} bytes, ${gzipped} gzipped (${(gzipped / 1024).toFixed(1)} KiB; target ≤ 40 KiB)`);

const server = await serve(join(root, "www"));
const browser = await chromium.launch(CHROMIUM);
try {
  // Navigation to the first complete frame (all views drawn), each load in a fresh context so
  // nothing is cached.
  const firstFrames = [];
  for (let k = 0; k < loads; k++) {
    const context = await browser.newContext({ viewport: { width: 1280, height: 900 } });
    const page = await context.newPage();
    await page.goto(`${server.origin}/`);
    await page.waitForFunction(() => performance.getEntriesByName("kli:first-frame").length > 0);
    firstFrames.push(await page.evaluate(() => performance.getEntriesByName("kli:first-frame")[0].startTime));
    await context.close();
  }
  console.log(`first frame after navigation: median ${median(firstFrames).toFixed(0)} ms over ${loads} cold loads (min ${Math.min(...firstFrames).toFixed(0)}, max ${Math.max(...firstFrames).toFixed(0)}; target ≤ 300 ms)`);

  // Script time per animation frame while playing: Chromium's own ScriptDuration over a count
  // of frames, at 1× speed (the path lasts 11.66 s, longer than the window).
  const context = await browser.newContext({ viewport: { width: 1280, height: 900 } });
  const page = await context.newPage();
  const cdp = await context.newCDPSession(page);
  await cdp.send("Performance.enable");
  await page.goto(`${server.origin}/`);
  await page.waitForFunction(() => performance.getEntriesByName("kli:first-frame").length > 0);
  await page.evaluate(() => {
    window.__frames = 0;
    const count = () => { window.__frames++; requestAnimationFrame(count); };
    requestAnimationFrame(count);
  });
  const metric = async (name) => (await cdp.send("Performance.getMetrics")).metrics.find((m) => m.name === name).value;
  await page.waitForTimeout(500);
  const [script0, frames0] = [await metric("ScriptDuration"), await page.evaluate(() => window.__frames)];
  await page.waitForTimeout(3000);
  const [script1, frames1] = [await metric("ScriptDuration"), await page.evaluate(() => window.__frames)];
  const playing = (await page.textContent("#play")) === "Pause";
  const perFrame = ((script1 - script0) * 1000) / (frames1 - frames0);
  console.log(`script per animation frame: ${perFrame.toFixed(2)} ms over ${frames1 - frames0} frames (${playing ? "playing" : "NOT playing"}; target ≤ 2 ms)`);
  // The same work timed inside the page: one frame's three canvas draws.
  const drawMs = await page.evaluate(async () => {
    const times = [];
    for (let k = 0; k < 60; k++) {
      await new Promise((resolve) => requestAnimationFrame(resolve));
      const start = performance.now();
      document.querySelector("#time").dispatchEvent(new Event("input"));
      await new Promise((resolve) => requestAnimationFrame(resolve));
      times.push(performance.now() - start);
    }
    return times;
  });
  await context.close();
  void drawMs;
} finally {
  await browser.close();
  server.close();
}
