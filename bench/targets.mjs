// The targets of every benchmark in one table: each benchmark records what it measured against
// its target (and its reference in the same run) with `record`; `make bench` empties the record
// first and prints the table last, the table docs/performance.md carries.
//   node bench/targets.mjs          prints the table of what the benchmarks recorded
//   node bench/targets.mjs --reset  forgets it (the start of `make bench`)
import { appendFileSync, existsSync, mkdirSync, readFileSync, rmSync } from "node:fs";
import { join } from "node:path";

const root = new URL("../", import.meta.url).pathname;
const file = join(root, "target/bench/targets.jsonl");

/** The middle of `xs` (the upper middle of an even count): the figure a benchmark reports of its runs. */
export const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];

/**
 * Records one target: what it asks, what was measured, the reference measured in the same run
 * (the peer or the previous release; "" where there is none), and whether it was met.
 * @param {string} target
 * @param {string} measured
 * @param {string} reference
 * @param {boolean} met
 */
export function record(target, measured, reference, met) {
  mkdirSync(join(root, "target/bench"), { recursive: true });
  appendFileSync(file, `${JSON.stringify({ target, measured, reference, met, at: new Date().toISOString().slice(0, 10) })}\n`);
}

if (import.meta.url === `file://${process.argv[1]}`) {
  if (process.argv.includes("--reset")) {
    rmSync(file, { force: true });
  } else {
    const rows = existsSync(file) ? readFileSync(file, "utf8").trim().split("\n").filter(Boolean).map((line) => JSON.parse(line)) : [];
    const cell = (text) => String(text).replaceAll("|", "\\|");
    console.log("\n| target | measured | reference, same run | |\n| --- | --- | --- | --- |");
    for (const { target, measured, reference, met } of rows) {
      console.log(`| ${cell(target)} | ${cell(measured)} | ${cell(reference)} | ${met ? "met" : "missed"} |`);
    }
    const missed = rows.filter((row) => !row.met).length;
    console.log(`\n${rows.length} targets, ${rows.length - missed} met, ${missed} missed (${rows[0]?.at ?? "nothing recorded"}).`);
  }
}
