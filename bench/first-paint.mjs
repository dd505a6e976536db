// Where the KLI page's first paint goes: the page's HTML without its scripts, and parts of it,
// each loaded cold (a fresh context, nothing cached) with Chromium's trace on, alternating; for
// each, the medians of its first contentful paint and of the main thread's work before it (HTML
// parsing, style, layout, paint), of the raster threads' work before it, and of two costs inside
// those: the synchronous requests for a font's rendering settings, one for each new font face
// and size ("fonts": in a fresh renderer each is a round trip to the browser's font service),
// and the setting up of each SVG image as a document of its own ("svg documents"). The variants:
//   bare          bench/bare/: one canvas drawn by a script (the first-frame baseline)
//   line          the page's head and style sheet, one line of text
//   header        the page's head and its header (title, two paragraphs, navigation)
//   top           the page down to the figures below the time controls, no first pictures
//   no-pictures   the whole page without its first pictures
//   page          the whole page with its first pictures (what a reader gets before any script)
//   node bench/first-paint.mjs [loads]
import { cpSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { chromium } from "playwright-core";
import { CHROMIUM, serve } from "../scripts/static-server.mjs";
import { median } from "./targets.mjs";

const root = new URL("../", import.meta.url).pathname;
const loads = Number(process.argv[2] ?? 7);
const site = mkdtempSync(join(tmpdir(), "kli-first-paint-"));
cpSync(join(root, "www/style.css"), join(site, "style.css"));
cpSync(join(root, "www/pkg/first"), join(site, "pkg/first"), { recursive: true });
cpSync(join(root, "bench/bare/index.html"), join(site, "bare.html"));

const cut = (html, pattern) => {
  const out = html.replace(pattern, "");
  if (out === html) throw new Error(`www/index.html no longer matches ${pattern}`);
  return out;
};
const page = cut(cut(readFileSync(join(root, "www/index.html"), "utf8"), /<script[^]*?<\/script>/g),
  /<link rel="(modulepreload|preload)"[^>]*>/g);
const head = page.slice(0, page.indexOf("<body>") + "<body>".length);
const noPictures = cut(cut(page, /<div class="first-picture"[^>]*><\/div>/g), /<link rel="stylesheet" href="pkg\/first\/[^>]*>/g);
const variants = {
  line: `${head}<p>One line of text.</p></body></html>`,
  header: `${head}${page.match(/<header[^]*?<\/header>/)[0]}</body></html>`,
  top: cut(noPictures, /<section class="controls"[^]*<\/main>/),
  "no-pictures": noPictures,
  page,
};
for (const [name, html] of Object.entries(variants)) writeFileSync(join(site, `${name}.html`), html);
const names = ["bare", ...Object.keys(variants)];

const server = await serve(site);
const browser = await chromium.launch(CHROMIUM);
const rows = Object.fromEntries(names.map((name) => [name, []]));
try {
  for (let k = 0; k < loads; k++) {
    for (const name of names) {
      const context = await browser.newContext({ viewport: { width: 1280, height: 900 } });
      const tab = await context.newPage();
      await browser.startTracing(tab, { categories: ["devtools.timeline", "loading", "disabled-by-default-devtools.timeline", "blink", "fonts"] });
      await tab.goto(`${server.origin}/${name}.html`);
      const fcp = await tab.evaluate(() => new Promise((resolve) => new PerformanceObserver((list) => {
        const entry = list.getEntries().find((e) => e.name === "first-contentful-paint");
        if (entry) resolve(entry.startTime);
      }).observe({ type: "paint", buffered: true })));
      await tab.waitForTimeout(200);
      const events = JSON.parse((await browser.stopTracing()).toString()).traceEvents;
      const painted = events.find((e) => e.name === "firstContentfulPaint")?.ts ?? Infinity;
      const before = (...kinds) => events
        .filter((e) => e.ph === "X" && kinds.includes(e.name) && e.ts < painted)
        .reduce((sum, e) => sum + e.dur / 1000, 0);
      rows[name].push({
        fcp,
        parse: before("ParseHTML"),
        style: before("UpdateLayoutTree"),
        layout: before("Layout"),
        paint: before("Paint"),
        raster: before("RasterTask"),
        fonts: before("WebSandboxSupportLinux::GetWebFontRenderStyleForStrike"),
        "svg documents": before("IsolatedSVGDocumentHost::IsolatedSVGDocumentHost"),
      });
      await context.close();
    }
  }
} finally {
  await browser.close();
  server.close();
  rmSync(site, { recursive: true, force: true });
}

const columns = ["fcp", "parse", "style", "layout", "paint", "raster", "fonts", "svg documents"];
console.log(`medians of ${loads} cold loads each, alternating, ms (work summed before the first contentful paint)\n`);
console.log(`| variant | ${columns.join(" | ")} |\n| --- |${" ---: |".repeat(columns.length)}`);
for (const name of names) {
  console.log(`| ${name} | ${columns.map((c) => median(rows[name].map((r) => r[c])).toFixed(c === "fcp" ? 0 : 1)).join(" | ")} |`);
}
