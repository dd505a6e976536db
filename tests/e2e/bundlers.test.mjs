// The packed npm package in real bundlers, run in headless Chromium: an app built with esbuild
// (the README's code and one line: the .wasm as a file) and one built with Vite 8 (the README's
// code unchanged), each computing with all three entries.
import { test, before, after } from "node:test";
import assert from "node:assert/strict";
import { execFileSync } from "node:child_process";
import { mkdtempSync, mkdirSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { chromium } from "playwright-core";
import { CHROMIUM, serve } from "../../scripts/static-server.mjs";

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
  browser = await chromium.launch(CHROMIUM);
});

after(async () => {
  await browser?.close();
});

/** Serves `dir`, opens it in Chromium, and returns the app's result (and any problem). */
async function runApp(dir) {
  const server = await serve(dir);
  const context = await browser.newContext();
  const tab = await context.newPage();
  const problems = [];
  tab.on("pageerror", (error) => problems.push(error.message));
  tab.on("response", (response) => response.status() >= 400 && problems.push(`${response.status()} ${response.url()}`));
  await tab.goto(`${server.origin}/`);
  await tab.waitForFunction(() => document.body.dataset.result, null, { timeout: 10000 }).catch(() => {});
  const result = await tab.evaluate(() => document.body.dataset.result);
  await context.close();
  server.close();
  return { result: result && JSON.parse(result), problems };
}

const expected = { T: 11.66, count: 5, key: 1 };

test("esbuild: the README's code, and the .wasm files imported with its file loader", async () => {
  const dir = join(project, "esbuild-app");
  mkdirSync(dir);
  writeFileSync(join(dir, "main.js"), app(`
import wasm from "kli/kli_bg.wasm";
import swarmWasm from "kli/swarm_bg.wasm";
import splineWasm from "kli/spline_bg.wasm";
await Promise.all([init({ module_or_path: wasm }), initSwarm({ module_or_path: swarmWasm }), initSpline({ module_or_path: splineWasm })]);`));
  execFileSync(bin("esbuild"), [join(dir, "main.js"), "--bundle", "--format=esm", "--platform=browser", "--loader:.wasm=file",
    `--outdir=${join(dir, "dist")}`, "--log-level=warning"], { cwd: project, stdio: "pipe" });
  writeFileSync(join(dir, "dist/index.html"), page);
  const { result, problems } = await runApp(join(dir, "dist"));
  assert.deepEqual(problems, []);
  assert.deepEqual(result, expected);
});

test("Vite 8: the README's code unchanged (vite build)", async () => {
  const dir = join(project, "vite-app");
  mkdirSync(dir);
  writeFileSync(join(dir, "main.js"), app(`await Promise.all([init(), initSwarm(), initSpline()]);`));
  writeFileSync(join(dir, "index.html"), page);
  execFileSync(bin("vite"), ["build", "--logLevel", "error"], { cwd: dir, stdio: "pipe" });
  const { result, problems } = await runApp(join(dir, "dist"));
  assert.deepEqual(problems, []);
  assert.deepEqual(result, expected);
});
