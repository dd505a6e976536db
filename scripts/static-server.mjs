// A static file server for www/ on 127.0.0.1 and a free port, for the page tests and benchmarks.
import { createServer } from "node:http";
import { readFile } from "node:fs/promises";
import { extname, join, normalize } from "node:path";
import { gzipSync } from "node:zlib";

const TYPES = { ".html": "text/html", ".svg": "image/svg+xml", ".js": "text/javascript", ".css": "text/css", ".wasm": "application/wasm", ".json": "application/json" };

/** Serves `root`; resolves to { origin, close }. With `hosted`, it answers as a static host does
 *  (gzip for clients that take it, and a day's caching), for page-speed measurements. */
export async function serve(root, { hosted = false } = {}) {
  const server = createServer(async (request, response) => {
    const path = normalize(decodeURIComponent(new URL(request.url, "http://x").pathname));
    const file = join(root, path.endsWith("/") ? path + "index.html" : path);
    try {
      if (!file.startsWith(root)) throw new Error("outside the root");
      const body = await readFile(file);
      const headers = { "content-type": TYPES[extname(file)] ?? "application/octet-stream" };
      if (hosted) {
        headers["cache-control"] = "public, max-age=86400";
        if (/\bgzip\b/.test(request.headers["accept-encoding"] ?? "")) {
          headers["content-encoding"] = "gzip";
          response.writeHead(200, headers);
          return response.end(gzipSync(body));
        }
      }
      response.writeHead(200, headers);
      response.end(body);
    } catch {
      response.writeHead(404).end();
    }
  });
  await new Promise((resolve) => server.listen(0, "127.0.0.1", resolve));
  return { origin: `http://127.0.0.1:${server.address().port}`, close: () => server.close() };
}

/** Debian's Chromium, headless, with no network of its own: the browser a reader runs, so the
 *  benchmarks' (long tasks, first paint, Lighthouse). */
export const CHROMIUM = {
  executablePath: "/usr/bin/chromium",
  args: ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking", "--disable-component-update", "--disable-sync", "--no-first-run"],
};

/** The tests' browser: Debian's `chromium-headless-shell`, the same Chromium build (its Blink
 *  and V8) without the browser's own user interface, which Playwright too runs headless. The
 *  end-to-end files took 43% less of the machine's CPU in it (page.test.mjs: 33 against 57 s),
 *  on a suite bound by its CPU. `KLI_CHROMIUM=/usr/bin/chromium` runs them in the whole browser
 *  (the screenshots in tests/e2e/look/ are the shell's: its text is hinted a pixel apart). */
export const TEST_CHROMIUM = {
  ...CHROMIUM,
  executablePath: process.env.KLI_CHROMIUM ?? "/usr/lib/chromium/chromium-headless-shell",
};
