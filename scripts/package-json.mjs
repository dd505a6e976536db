// Writes pkg/package.json for the ES module that wasm-bindgen generated in pkg/, taking the npm
// name, the version, description and licence from the Cargo manifests so they never disagree.
import { readFileSync, writeFileSync, existsSync } from "node:fs";

const manifest = (path) => readFileSync(new URL(`../${path}`, import.meta.url), "utf8");
const field = (toml, name) => {
  const match = toml.match(new RegExp(`^${name}\\s*=\\s*"([^"]*)"`, "m"));
  if (!match) throw new Error(`no ${name} in the Cargo manifest`);
  return match[1];
};
const workspace = manifest("Cargo.toml").split("[workspace.package]")[1];
const crate = manifest("crates/kli-wasm/Cargo.toml");

// Entries with a module each: `kli` (two rotations), `kli/swarm` (LoheSwarm), `kli/spline` (many
// keyframes).
const modules = ["kli", "swarm", "spline"];
const files = [...modules.flatMap((m) => [`${m}.js`, `${m}.d.ts`, `${m}_bg.wasm`, `${m}_bg.wasm.d.ts`]), "README.md"];
for (const file of files) {
  if (!existsSync(new URL(`../pkg/${file}`, import.meta.url))) throw new Error(`pkg/${file} is missing`);
}

const json = {
  name: field(crate.split("[package.metadata.npm]")[1], "name"),
  version: field(workspace, "version"),
  description: field(crate, "description"),
  license: field(workspace, "license"),
  type: "module",
  main: "kli.js",
  module: "kli.js",
  types: "kli.d.ts",
  exports: {
    ".": { types: "./kli.d.ts", default: "./kli.js" },
    "./kli_bg.wasm": "./kli_bg.wasm",
    "./swarm": { types: "./swarm.d.ts", default: "./swarm.js" },
    "./swarm_bg.wasm": "./swarm_bg.wasm",
    "./spline": { types: "./spline.d.ts", default: "./spline.js" },
    "./spline_bg.wasm": "./spline_bg.wasm",
    "./package.json": "./package.json",
  },
  files,
  sideEffects: false,
  keywords: ["quaternion", "rotation", "slerp", "interpolation", "kuramoto", "hopf", "wasm"],
};
writeFileSync(new URL("../pkg/package.json", import.meta.url), JSON.stringify(json, null, 2) + "\n");
console.log(`pkg/package.json: ${json.name}@${json.version}`);
