// The npm package's size, entry by entry, beside the previous release's in the same run: each
// entry's JavaScript and WebAssembly gzipped (Node's zlib, level 9), as a bundler ships them. An
// entry that grows by more than 1% on the previous release is a miss (docs/performance.md).
//   node bench/size.mjs
import { existsSync, readFileSync } from "node:fs";
import { join } from "node:path";
import { gzipSync } from "node:zlib";
import { previous } from "./previous.mjs";
import { record } from "./targets.mjs";

const root = new URL("../", import.meta.url).pathname;
/** Each entry of the package and the files it loads (kli/three and kli/gltf are JavaScript over
 *  kli/spline and kli/average, counted alone). */
const ENTRIES = {
  kli: ["kli.js", "kli_bg.wasm"],
  "kli/spline": ["spline.js", "spline_bg.wasm"],
  "kli/swarm": ["swarm.js", "swarm_bg.wasm"],
  "kli/average": ["average.js", "average_bg.wasm"],
  "kli/sync": ["sync.js", "sync_bg.wasm"],
  "kli/three": ["three.js", "resample.js"],
  "kli/gltf": ["gltf.js", "resample.js"],
};

/** The gzipped bytes of `files` in `dir`, or null where an entry is not there (an older release). */
function gzipped(dir, files) {
  if (!files.every((file) => existsSync(join(dir, file)))) return null;
  return files.reduce((sum, file) => sum + gzipSync(readFileSync(join(dir, file)), { level: 9 }).length, 0);
}

const references = previous();
const here = join(root, "pkg");
console.log(`| entry | this build, gzipped | ${references.map((r) => `${r.name} (${r.commit})`).join(" | ")} | change on the previous release |`);
console.log(`| --- | --- | ${references.map(() => "---").join(" | ")} | --- |`);
for (const [entry, files] of Object.entries(ENTRIES)) {
  const now = gzipped(here, files);
  const then = references.map((reference) => gzipped(reference.dir, files));
  const change = then[0] === null || now === null ? null : now / then[0] - 1;
  const cell = (/** @type {number | null} */ bytes) => (bytes === null ? "—" : `${bytes.toLocaleString("en")} B`);
  const percent = change === null ? "new" : `${change >= 0 ? "+" : ""}${(100 * change).toFixed(2)}%`;
  console.log(`| \`${entry}\` | ${cell(now)} | ${then.map(cell).join(" | ")} | ${percent} |`);
  record(`\`${entry}\` gzipped grows ≤ 1% on the previous release`, cell(now), `${cell(then[0])} (${percent})`, change === null || change <= 0.01);
}
