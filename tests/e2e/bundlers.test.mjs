// The packed npm package in real bundlers, run in headless Chromium, each app computing with all
// three entries and the README's code unchanged: esbuild (with no loader it leaves the .wasm out:
// init() falls back to the inlined copy; with the README's optional line the .wasm is a file),
// Vite 8 (build and dev server), webpack 5 (no configuration) and Vite 7's dev server (it serves
// index.html for the .wasm: the fallback again; its optional line serves the file itself).
import { test, before, after } from "node:test";
import assert from "node:assert/strict";
import { execFileSync } from "node:child_process";
import { mkdtempSync, mkdirSync, readFileSync, readdirSync, rmSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { chromium } from "playwright-core";
import { TEST_CHROMIUM, serve } from "../../scripts/static-server.mjs";

const root = new URL("../../", import.meta.url).pathname;
const bin = (name) => join(root, "node_modules/.bin", name);
let project;
let browser;

/** The app: every entry initialised, one number from each, written where the test reads it. */
const app = (initLines) => `
import init, { kli } from "kli";
import initSwarm, { LoheSwarm } from "kli/swarm";
import initSpline, { kliSpline } from "kli/spline";
${initLines}
const swarm = new LoheSwarm({ count: 5, seed: 2 });
document.body.dataset.result = JSON.stringify({
  T: kli([0, 0, 0, 1], [0.5, 0.5, 0.5, 0.5]).finalTime,
  count: swarm.count,
  key: kliSpline([[1, 0, 0, 0], [0, 1, 0, 0]]).at(1)[1],
});
`;
const page = `<!doctype html><html lang="en"><head><meta charset="utf-8"><link rel="icon" href="data:,"><title>app</title></head>
<body><script type="module" src="./main.js"></script></body></html>`;

before(async () => {
  project = mkdtempSync(join(tmpdir(), "kli-bundlers-"));
  const tarball = execFileSync("npm", ["pack", "--silent", "--pack-destination", project], { cwd: join(root, "pkg"), encoding: "utf8" })
    .trim().split("\n").pop();
  writeFileSync(join(project, "package.json"), JSON.stringify({ name: "apps", private: true, type: "module" }));
  execFileSync("npm", ["install", "--no-audit", "--no-fund", "--offline", join(project, tarball)], { cwd: project, stdio: "ignore" });
  browser = await chromium.launch(TEST_CHROMIUM);
});

after(async () => {
  await browser?.close();
  if (project) rmSync(project, { recursive: true, force: true });
});

/** Serves `dir` (or uses a running server's `origin`), opens it in Chromium, and returns the
 *  app's result (and any problem). */
async function runApp(dir, running) {
  const server = running ?? (await serve(dir));
  const context = await browser.newContext();
  const tab = await context.newPage();
  const problems = [];
  tab.on("pageerror", (error) => problems.push(error.message));
  tab.on("response", (response) => response.status() >= 400 && problems.push(`${response.status()} ${response.url()}`));
  await tab.goto(`${server.origin}/`);
  await tab.waitForFunction(() => document.body.dataset.result, null, { timeout: 10000 }).catch(() => {});
  const result = await tab.evaluate(() => document.body.dataset.result);
  const files = await tab.evaluate(loaded);
  await context.close();
  if (!running) server.close();
  return { result: result && JSON.parse(result), problems, loaded: files };
}

const expected = { T: 11.66, count: 5, key: 1 };

/** The app's requests for .wasm files and for the inlined copies, from the page's own view. */
const loaded = () => performance.getEntriesByType("resource").map((e) => e.name.split("?")[0].split("/").pop()).filter((n) => /wasm|inline/.test(n));
/** Whether the app loaded the three .wasm files themselves (not the inlined copies). */
const wasmFiles = (files) => files.filter((n) => n.endsWith(".wasm")).length === 3 && !files.some((n) => n.includes("inline"));

test("esbuild: the README's code unchanged, no configuration (the inlined fallback)", async () => {
  const dir = join(project, "esbuild-plain");
  mkdirSync(dir);
  writeFileSync(join(dir, "main.js"), app(`await Promise.all([init(), initSwarm(), initSpline()]);`));
  execFileSync(bin("esbuild"), [join(dir, "main.js"), "--bundle", "--format=esm", "--platform=browser",
    `--outdir=${join(dir, "dist")}`, "--log-level=warning"], { cwd: project, stdio: "pipe" });
  writeFileSync(join(dir, "dist/index.html"), page);
  // esbuild leaves the .wasm out: each init() gets a 404, then uses the inlined copy.
  const { result, problems } = await runApp(join(dir, "dist"));
  assert.deepEqual(problems.filter((p) => !/^404 .*_bg\.wasm$/.test(p)), []);
  assert.equal(problems.length, 3, problems.join("\n"));
  assert.deepEqual(result, expected);
});

test("esbuild: the README's optional lines, the .wasm files imported with its file loader", async () => {
  const dir = join(project, "esbuild-app");
  mkdirSync(dir);
  writeFileSync(join(dir, "main.js"), app(`
import wasm from "kli/kli_bg.wasm";
import swarmWasm from "kli/swarm_bg.wasm";
import splineWasm from "kli/spline_bg.wasm";
await Promise.all([init({ module_or_path: wasm }), initSwarm({ module_or_path: swarmWasm }), initSpline({ module_or_path: splineWasm })]);`));
  const args = (out) => [join(dir, "main.js"), "--bundle", "--format=esm", "--platform=browser", "--splitting",
    "--loader:.wasm=file", `--outdir=${out}`, "--log-level=warning"];
  execFileSync(bin("esbuild"), args(join(dir, "dist")), { cwd: project, stdio: "pipe" });
  writeFileSync(join(dir, "dist/index.html"), page);
  const { result, problems, loaded: files } = await runApp(join(dir, "dist"));
  assert.deepEqual(problems, []);
  assert.deepEqual(result, expected);
  // Without the condition the inlined copies are chunks of their own, in dist but never
  // downloaded; with `--conditions=production` (the glue without them) they are not built at all.
  assert.ok(wasmFiles(files), files.join(", "));
  assert.equal(inlined(join(dir, "dist")).length, 3);
  const lean = join(dir, "production");
  execFileSync(bin("esbuild"), [...args(lean), "--conditions=production"], { cwd: project, stdio: "pipe" });
  writeFileSync(join(lean, "index.html"), page);
  const production = await runApp(lean);
  assert.deepEqual(production.problems, []);
  assert.deepEqual(production.result, expected);
  assert.deepEqual(inlined(lean), []);
});

/** The files of a build's output that hold an inlined .wasm: each entry's `_bg.inline` chunk, or
 *  any script with a long base64 run (a bundler may rename or merge the chunk). */
function inlined(dir) {
  return readdirSync(dir, { recursive: true }).map(String)
    .filter((n) => n.includes(".inline") || (/\.m?js$/.test(n) && /[A-Za-z0-9+\/]{20000}/.test(readFileSync(join(dir, n), "utf8"))));
}

test("Vite 8: the README's code unchanged (vite build)", async () => {
  const dir = join(project, "vite-app");
  mkdirSync(dir);
  writeFileSync(join(dir, "main.js"), app(`await Promise.all([init(), initSwarm(), initSpline()]);`));
  writeFileSync(join(dir, "index.html"), page);
  execFileSync(bin("vite"), ["build", "--logLevel", "error"], { cwd: dir, stdio: "pipe" });
  const { result, problems, loaded: files } = await runApp(join(dir, "dist"));
  assert.deepEqual(problems, []);
  assert.deepEqual(result, expected);
  assert.ok(wasmFiles(files), files.join(", "));
  // The export condition `production`: the glue without the inlined copies, none in dist.
  assert.deepEqual(inlined(join(dir, "dist")), []);
});

test("webpack 5: the README's code unchanged (webpack --mode production)", async () => {
  const dir = join(project, "webpack-app");
  mkdirSync(join(dir, "src"), { recursive: true });
  writeFileSync(join(dir, "src/index.js"), app(`await Promise.all([init(), initSwarm(), initSpline()]);`));
  // No configuration: webpack's defaults (src/index.js to dist/main.js, top-level await on).
  execFileSync("node", [join(root, "node_modules/webpack-cli/bin/cli.js"), "--mode", "production", "--no-stats"], { cwd: dir, stdio: "pipe" });
  writeFileSync(join(dir, "dist/index.html"), page.replace('type="module" src="./main.js"', 'src="./main.js"'));
  const { result, problems, loaded: files } = await runApp(join(dir, "dist"));
  assert.deepEqual(problems, []);
  assert.deepEqual(result, expected);
  assert.ok(wasmFiles(files), files.join(", "));
  assert.deepEqual(inlined(join(dir, "dist")), []);
});

/** Runs an app under a Vite dev server (the version given by its module), as `npm run dev` does. */
async function viteDev(name, viteModule, config) {
  const dir = join(project, name);
  mkdirSync(dir);
  writeFileSync(join(dir, "main.js"), app(`await Promise.all([init(), initSwarm(), initSpline()]);`));
  writeFileSync(join(dir, "index.html"), page);
  const { createServer } = await import(viteModule);
  const server = await createServer({ root: dir, configFile: false, logLevel: process.env.VITE_LOG ?? "silent", server: { port: 0, host: "127.0.0.1" }, ...config });
  await server.listen();
  const address = server.httpServer.address();
  try {
    return await runApp(dir, { origin: `http://127.0.0.1:${address.port}` });
  } finally {
    await server.close();
  }
}

const vite = (module) => join(root, "node_modules", module, "dist/node/index.js");

/** Vite 7, installed into the test's project from the registry: not a dev dependency, because
 *  the registry mirror here lacks most of rollup's platform packages and `npm ci` then refuses
 *  a lock file that names them. Its rollup is rollup's WebAssembly build at a pinned version:
 *  the native build's platform package is an optional dependency, and when the mirror has a
 *  new rollup before its platform packages npm installs rollup without it and Vite fails. */
function installVite7() {
  const manifest = JSON.parse(readFileSync(join(project, "package.json"), "utf8"));
  manifest.overrides = { rollup: "npm:@rollup/wasm-node@4.68.4" };
  writeFileSync(join(project, "package.json"), JSON.stringify(manifest));
  execFileSync("npm", ["install", "--no-audit", "--no-fund", "--no-save", "vite@7.3.8"], { cwd: project, stdio: "ignore" });
  return join(project, "node_modules/vite/dist/node/index.js");
}

test("Vite 8 dev server: the README's code unchanged", async () => {
  const { result, problems, loaded: files } = await viteDev("vite8-dev", vite("vite"), {});
  assert.deepEqual(problems, []);
  assert.deepEqual(result, expected);
  assert.ok(wasmFiles(files), files.join(", "));
});

// Vite 7's dev server pre-bundles dependencies into node_modules/.vite and loses the .wasm files
// beside them (it serves index.html in their place): init() sees HTML and uses the inlined copy,
// so the README's code runs unchanged; the optional line, optimizeDeps.exclude, serves the
// package as it is, and then the .wasm files themselves are loaded.
test("Vite 7 dev server: the README's code unchanged (the inlined fallback); with the optional line, the .wasm files", async () => {
  const vite7 = installVite7();
  const plain = await viteDev("vite7-dev-plain", vite7, {});
  assert.deepEqual(plain.problems, []);
  assert.deepEqual(plain.result, expected);
  // Its pre-bundler makes each inlined copy a chunk of its own (a hashed name).
  const chunks = plain.loaded.filter((n) => n.includes("inline")).map((n) => n.split(".inline")[0]).sort();
  assert.deepEqual(chunks, ["kli_bg", "spline_bg", "swarm_bg"]);
  const { result, problems, loaded } = await viteDev("vite7-dev", vite7, { optimizeDeps: { exclude: ["kli"] } });
  assert.deepEqual(problems, []);
  assert.deepEqual(result, expected);
  assert.deepEqual(loaded.filter((n) => n.includes("inline")), []);
});
