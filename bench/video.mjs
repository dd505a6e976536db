// Issue 15's measure: the time to encode the paper's example (p = k, r = ½(1 + i + j + k), the
// whole path to T = 11.66 at 1×) as a video from the KLI page in headless Chromium, each frame
// drawn for its own time; beside it the clip's own length (real time), the reference that
// says whether a teacher waits longer than the clip plays.
//   node bench/video.mjs
import { join } from "node:path";
import { chromium } from "playwright-core";
import { CHROMIUM, serve } from "../scripts/static-server.mjs";

const root = new URL("../", import.meta.url).pathname;
const server = await serve(join(root, "www"));
const browser = await chromium.launch(CHROMIUM);
const cases = [
  { format: "mp4", size: "1080p", fps: 60 },
  { format: "webm", size: "1080p", fps: 60 },
  { format: "mp4", size: "720p", fps: 30 },
  { format: "gif", size: "720p", fps: 30 },
];
console.log(`The paper's example as a video (0 ≤ t ≤ 11.66 in 11.66 s), object and Hopf sphere, Chromium ${browser.version()}:`);
console.log("| format | size | frames | encoding, s | × the clip's length | file, MB |");
console.log("| --- | --- | ---: | ---: | ---: | ---: |");
try {
  for (const c of cases) {
    const page = await browser.newPage();
    await page.goto(`${server.origin}/?t=0`);
    await page.waitForFunction(() => document.querySelector("#load-status")?.hidden);
    await page.evaluate(() => document.querySelector("#play").textContent === "Pause" && document.querySelector("#play").click());
    const panel = page.locator("fieldset.video");
    await panel.locator('[name="video-format"]').selectOption(c.format);
    await panel.locator('[name="video-size"]').selectOption(c.size);
    await panel.locator('[name="video-fps"]').selectOption(String(c.fps));
    await panel.locator('[name="video-seconds"]').fill("11.66");
    const start = Date.now();
    const [download] = await Promise.all([page.waitForEvent("download", { timeout: 600000 }), panel.locator(".video-start").click()]);
    await download.path();
    const seconds = (Date.now() - start) / 1000;
    const status = await panel.locator(".video-status").textContent();
    const [, frames, megabytes] = status.match(/: (\d+) frames, ([\d.]+) MB/) ?? [];
    console.log(`| ${c.format} | ${c.size} | ${frames} | ${seconds.toFixed(1)} | ${(seconds / 11.66).toFixed(2)} | ${megabytes} |`);
    await page.close();
  }
} finally {
  await browser.close();
  server.close();
}
