// Writes pkg/package.json for the ES module that wasm-bindgen generated in pkg/, taking the
// name, version, description and licence from Cargo.toml so the two can never disagree.
import { readFileSync, writeFileSync, existsSync } from "node:fs";

const cargo = readFileSync(new URL("../Cargo.toml", import.meta.url), "utf8");
const field = (name) => {
  const match = cargo.match(new RegExp(`^${name}\\s*=\\s*"([^"]*)"`, "m"));
  if (!match) throw new Error(`Cargo.toml has no ${name}`);
  return match[1];
};

const files = ["kli.js", "kli.d.ts", "kli_bg.wasm", "kli_bg.wasm.d.ts", "README.md"];
for (const file of files) {
  if (!existsSync(new URL(`../pkg/${file}`, import.meta.url))) throw new Error(`pkg/${file} is missing`);
}

const manifest = {
  name: field("name"),
  version: field("version"),
  description: field("description"),
  license: field("license"),
  type: "module",
  main: "kli.js",
  module: "kli.js",
  types: "kli.d.ts",
  exports: {
    ".": { types: "./kli.d.ts", default: "./kli.js" },
    "./kli_bg.wasm": "./kli_bg.wasm",
    "./package.json": "./package.json",
  },
  files,
  sideEffects: false,
  keywords: ["quaternion", "rotation", "slerp", "interpolation", "kuramoto", "hopf", "wasm"],
};
writeFileSync(new URL("../pkg/package.json", import.meta.url), JSON.stringify(manifest, null, 2) + "\n");
console.log(`pkg/package.json: ${manifest.name}@${manifest.version}`);
