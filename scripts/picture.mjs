// The README's pictures: the paper's example (p = k, r = ½(1 + i + j + k)) at t = 1.8, drawn by
// the KLI page's own module in Node (its SVG backend), so the picture is the page's figure.
// `make www`, then `node scripts/picture.mjs` writes docs/paper-object.svg and docs/paper-hopf.svg.
import { readFileSync, writeFileSync } from "node:fs";

const at = (path) => new URL(`../${path}`, import.meta.url);
const kli = await import(at("www/pkg/kli_demo.js").href);
kli.initSync({ module: readFileSync(at("www/pkg/kli_demo_bg.wasm")) });
const run = new kli.KliDemo([0, 0, 0, 1], [0.5, 0.5, 0.5, 0.5]);
const [azimuth, elevation] = kli.defaultCamera();
for (const [view, width, height] of [["object", 480, 300], ["hopf", 400, 300]]) {
  const svg = run.toSvg(view, { width, height, t: 1.8, azimuth, elevation });
  writeFileSync(at(`docs/paper-${view}.svg`), svg);
  console.log(`docs/paper-${view}.svg: ${svg.length} bytes`);
}
run.free();
