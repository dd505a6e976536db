// Lighthouse (mobile: its default, a mid-range phone on a slow 4G network, simulated) on every
// page and both examples, served as a static host serves them (gzip, caching): performance,
// accessibility and best practices, and the cumulative layout shift. Targets (issue 14):
// performance ≥ 0.95, accessibility 1.0, best practices 1.0, CLS ≤ 0.1; the previous release's
// pages (bench/previous.mjs) run alternately with ours, their scores the reference.
//   node bench/lighthouse.mjs [--runs=3] [page …]     (every page and example, or the ones named)
// Lighthouse is installed on first use into target/bench-tools (not a dev dependency: it is large
// and only the benchmark needs it).
import { record } from "./targets.mjs";
import { execFile, execFileSync } from "node:child_process";
import { promisify } from "node:util";
import { existsSync, readFileSync } from "node:fs";
import { PAGES as REGISTRY } from "../www/pages.js";
import { join } from "node:path";
import { serve } from "../scripts/static-server.mjs";
import { previousPages } from "./previous.mjs";

const root = new URL("../", import.meta.url).pathname;
const tools = join(root, "target/bench-tools");
const bin = join(tools, "node_modules/.bin/lighthouse");
if (!existsSync(bin)) {
  console.log("installing lighthouse 12 into target/bench-tools (once)");
  execFileSync("npm", ["install", "--prefix", tools, "--no-audit", "--no-fund", "--silent", "lighthouse@12"], { stdio: "inherit" });
}

// Every page of the registry, and the examples.
const ALL = [...REGISTRY.map((page) => page.html), "examples/figures.html", "examples/three.html"];
const args = process.argv.slice(2);
// A single run's performance score moves by ±0.05 here, and the machine's speed from hour to
// hour moves it by more (swarm.html: 0.80 and 0.98 ten minutes apart), so each page runs several
// times alternating with the previous release's page, and the report of each is the run of
// median performance: the reference measured beside it.
const RUNS = Number(args.find((a) => a.startsWith("--runs="))?.slice(7) ?? 3);
const named = args.filter((a) => !a.startsWith("--"));
const PAGES = named.length > 0 ? named : ALL;
const release = previousPages();
const sites = [
  { label: "ours", server: await serve(join(root, "www"), { hosted: true }) },
  { label: `${release.name}, ${release.commit}`, server: await serve(release.www, { hosted: true }) },
];

/** Lighthouse on `url`: its report. */
async function lighthouse(url, out) {
  // Asynchronously: the server answering Lighthouse runs in this process.
  await promisify(execFile)(bin, [url, "--quiet", "--output=json", `--output-path=${out}`,
    "--only-categories=performance,accessibility,best-practices",
    "--chrome-flags=--headless --no-sandbox --disable-gpu --disable-background-networking --disable-component-update --disable-sync"],
  { env: { ...process.env, CHROME_PATH: "/usr/bin/chromium" } });
  return JSON.parse(readFileSync(out, "utf8"));
}

/** The report of median performance among `reports`. */
const median = (reports) =>
  [...reports].sort((a, b) => a.categories.performance.score - b.categories.performance.score)[Math.floor(reports.length / 2)];

try {
  for (const page of PAGES) {
    const reports = sites.map(() => []);
    // A page newer than the previous release is measured alone.
    const measured = existsSync(join(release.www, page)) ? sites : sites.slice(0, 1);
    for (let run = 0; run < RUNS; run++) {
      for (const [k, { server }] of measured.entries()) {
        const out = join(tools, `lighthouse-${k}-${page.replace(/\W/g, "-")}-${run}.json`);
        reports[k].push(await lighthouse(`${server.origin}/${page}`, out));
      }
    }
    const [report, reference] = reports.map((r) => (r.length ? median(r) : undefined));
    const score = (name, r = report) => r.categories[name].score.toFixed(2);
    const audit = (name) => report.audits[name].displayValue;
    const met = report.categories.performance.score >= 0.95 && report.categories.accessibility.score === 1 &&
      report.categories["best-practices"].score === 1 && report.audits["cumulative-layout-shift"].numericValue <= 0.1;
    const runs = (k) => reports[k].map((r) => r.categories.performance.score.toFixed(2)).join(", ");
    record(`Lighthouse mobile on ${page}: performance ≥ 0.95, accessibility and best practices 1, CLS ≤ 0.1`,
      `${score("performance")}, ${score("accessibility")}, ${score("best-practices")}, CLS ${audit("cumulative-layout-shift")}`,
      reference ? `${sites[1].label}: performance ${score("performance", reference)} (medians of ${RUNS} alternating runs)` : `${sites[1].label}: no such page`, met);
    console.log(`lighthouse ${page}: performance ${score("performance")}, accessibility ${score("accessibility")}, ` +
      `best practices ${score("best-practices")}, CLS ${audit("cumulative-layout-shift")} ` +
      `(FCP ${audit("first-contentful-paint")}, LCP ${audit("largest-contentful-paint")}, TBT ${audit("total-blocking-time")}; ` +
      `performance in ${RUNS} runs: ${runs(0)}; ${sites[1].label}: ${runs(1)}): ` +
      `${met ? "met" : "MISSED"} (targets ≥ 0.95, 1, 1, ≤ 0.1)`);
  }
} finally {
  for (const { server } of sites) server.close();
}
