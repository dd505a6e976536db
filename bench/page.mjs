// The page's weight and speed in headless Chromium, as ratios taken within one run: the first
// complete frame of the demo page against a bare page that draws one canvas (bench/bare/),
// loaded the same way from the same server, alternating; the script time per animation frame
// while playing; and the sizes of the two modules.
//   node bench/page.mjs [loads]
import { record } from "./targets.mjs";
import { readFileSync } from "node:fs";
import { gzipSync } from "node:zlib";
import { join } from "node:path";
import { chromium } from "playwright-core";
import { CHROMIUM, serve } from "../scripts/static-server.mjs";

const root = new URL("../", import.meta.url).pathname;
const loads = Number(process.argv[2] ?? 9);
const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];
const size = (path) => {
  const bytes = readFileSync(join(root, path));
  return `${bytes.length} bytes, ${gzipSync(bytes, { level: 9 }).length} gzipped`;
};
console.log(`pkg/kli_bg.wasm (the npm package's main entry): ${size("pkg/kli_bg.wasm")} (target ≤ 32768 gzipped)`);
const kliGzipped = gzipSync(readFileSync(join(root, "pkg/kli_bg.wasm")), { level: 9 }).length;
record("`kli_bg.wasm` ≤ 32 KiB gzipped (Node's zlib, level 9)", `${kliGzipped.toLocaleString("en")} bytes`, "", kliGzipped <= 32768);
for (const entry of ["swarm", "spline"]) console.log(`pkg/${entry}_bg.wasm (kli/${entry}): ${size(`pkg/${entry}_bg.wasm`)}`);
for (const [page, module] of [["index.html", "kli_demo"], ["swarm.html", "swarm_demo"], ["keyframes.html", "keyframes_demo"]]) {
  console.log(`www/pkg/${module}_bg.wasm (${page}'s module): ${size(`www/pkg/${module}_bg.wasm`)}`);
}

const www = await serve(join(root, "www"));
const bare = await serve(join(root, "bench/bare"));
const browser = await chromium.launch(CHROMIUM);
try {
  /** Navigation to the page's "kli:first-frame" mark, in a fresh context (nothing cached). */
  const firstFrame = async (origin) => {
    const context = await browser.newContext({ viewport: { width: 1280, height: 900 } });
    const page = await context.newPage();
    await page.goto(`${origin}/`);
    await page.waitForFunction(() => performance.getEntriesByName("kli:first-frame").length > 0);
    const ms = await page.evaluate(() => performance.getEntriesByName("kli:first-frame")[0].startTime);
    await context.close();
    return ms;
  };
  const demo = [], baseline = [];
  for (let k = 0; k < loads; k++) {
    baseline.push(await firstFrame(bare.origin));
    demo.push(await firstFrame(www.origin));
  }
  const [d, b] = [median(demo), median(baseline)];
  console.log(`first frame: demo median ${d.toFixed(0)} ms (${Math.min(...demo).toFixed(0)}–${Math.max(...demo).toFixed(0)}), ` +
    `bare canvas page ${b.toFixed(0)} ms (${Math.min(...baseline).toFixed(0)}–${Math.max(...baseline).toFixed(0)}), ` +
    `${loads} cold loads each, alternating: ratio ${(d / b).toFixed(2)} (target ≤ 1.5)`);
  record("the KLI page's first complete frame ≤ 1.5× a bare canvas page", `${(d / b).toFixed(2)}× (${d.toFixed(0)} ms)`,
    `bare page: ${b.toFixed(0)} ms`, d / b <= 1.5);

  // Script time per animation frame while playing: Chromium's own ScriptDuration over a count
  // of frames, at 1× speed (the path lasts 11.66 s, longer than the window).
  const context = await browser.newContext({ viewport: { width: 1280, height: 900 } });
  const page = await context.newPage();
  const cdp = await context.newCDPSession(page);
  await cdp.send("Performance.enable");
  await page.goto(`${www.origin}/`);
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
  record("≤ 2 ms of script a frame, the KLI page playing", `${perFrame.toFixed(2)} ms${playing ? "" : " (NOT playing)"}`, "", playing && perFrame <= 2);
  await context.close();

  // The swarm page with 2,000 oscillators all-to-all, playing (two steps a frame).
  const swarmContext = await browser.newContext({ viewport: { width: 1280, height: 900 } });
  const swarmPage = await swarmContext.newPage();
  const swarmCdp = await swarmContext.newCDPSession(swarmPage);
  await swarmCdp.send("Performance.enable");
  await swarmPage.goto(`${www.origin}/swarm.html?K=1&n=2000&graph=all&w=0.5&seed=1`);
  await swarmPage.waitForFunction(() => document.querySelector("#load-status").hidden);
  await swarmPage.evaluate(() => {
    window.__frames = 0;
    const count = () => { window.__frames++; requestAnimationFrame(count); };
    requestAnimationFrame(count);
  });
  const swarmMetric = async () => (await swarmCdp.send("Performance.getMetrics")).metrics.find((m) => m.name === "ScriptDuration").value;
  await swarmPage.waitForTimeout(500);
  const [s0, f0] = [await swarmMetric(), await swarmPage.evaluate(() => window.__frames)];
  await swarmPage.waitForTimeout(3000);
  const [s1, f1] = [await swarmMetric(), await swarmPage.evaluate(() => window.__frames)];
  const swarmPlaying = (await swarmPage.textContent("#play")) === "Pause";
  const swarmPerFrame = ((s1 - s0) * 1000) / (f1 - f0);
  console.log(`swarm page, 2,000 oscillators: ${swarmPerFrame.toFixed(2)} ms of script per frame over ${f1 - f0} frames (${swarmPlaying ? "playing" : "NOT playing"}; target ≤ 4 ms)`);
  record("≤ 4 ms of script a frame, the swarm page at 2,000 oscillators", `${swarmPerFrame.toFixed(2)} ms${swarmPlaying ? "" : " (NOT playing)"}`, "", swarmPlaying && swarmPerFrame <= 4);
  await swarmContext.close();
} finally {
  await browser.close();
  www.close();
  bare.close();
}
