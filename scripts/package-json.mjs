// Finishes pkg/ for npm around the ES modules that wasm-bindgen generated: a Node entry for each
// module (so `await init()` reads the .wasm from disk there, where fetch cannot), type
// declarations that compile with `lib: es2022`, and package.json, with the npm name, version,
// description and licence from the Cargo manifests so they never disagree.
import { readFileSync, writeFileSync, existsSync, copyFileSync } from "node:fs";
import { gzipSync } from "node:zlib";

const at = (path) => new URL(`../${path}`, import.meta.url);
const manifest = (path) => readFileSync(at(path), "utf8");
const field = (toml, name) => {
  const match = toml.match(new RegExp(`^${name}\\s*=\\s*"([^"]*)"`, "m"));
  if (!match) throw new Error(`no ${name} in the Cargo manifest`);
  return match[1];
};
const workspace = manifest("Cargo.toml").split("[workspace.package]")[1];
const crate = manifest("crates/kli-wasm/Cargo.toml");

// Entries with a module each: `kli` (two rotations), `kli/swarm` (LoheSwarm), `kli/spline` (many
// keyframes), `kli/average` (the mean of many rotations), `kli/sync` (rotations on a graph).
const modules = ["kli", "swarm", "spline", "average", "sync"];
/** The name an app imports a module by: `kli`, `kli/swarm`, … */
const entryName = (m) => (m === "kli" ? "kli" : `kli/${m}`);
for (const m of modules) {
  for (const file of [`${m}.js`, `${m}.d.ts`, `${m}_bg.wasm`, `${m}_bg.wasm.d.ts`]) {
    if (!existsSync(at(`pkg/${file}`))) throw new Error(`pkg/${file} is missing`);
  }
  // The classes declare [Symbol.dispose] (for `using`): the reference lets `lib: es2022` projects
  // compile the declarations without adding esnext.disposable themselves. No DOM: a Node project
  // that imports kli must not get `document` as a global, so init's types (RequestInfo, URL,
  // Response, BufferSource, WebAssembly.*) become the environment's own where its types declare
  // them (the DOM library, @types/node) and plain ones where not (domFree).
  const types = manifest(`pkg/${m}.d.ts`);
  if (!types.startsWith("/// <reference lib")) writeFileSync(at(`pkg/${m}.d.ts`), `/// <reference lib="esnext.disposable" />\n${domFree(types, `pkg/${m}.d.ts`)}`);
  // What a bundler's file loader gives for \`import wasm from "kli/kli_bg.wasm"\` (esbuild's
  // --loader:.wasm=file, the README's line): the file's URL, for init({ module_or_path }).
  const raw = manifest(`pkg/${m}_bg.wasm.d.ts`);
  if (!raw.includes("export default")) {
    writeFileSync(at(`pkg/${m}_bg.wasm.d.ts`), `${domFree(raw, `pkg/${m}_bg.wasm.d.ts`)}
/** With a bundler's file loader (esbuild's \`--loader:.wasm=file\`): the file's URL, for
 *  \`init({ module_or_path: url })\`. The named exports above are the module's raw exports. */
declare const url: string;
export default url;
`);
  }
  // isKliError, a type guard for `catch (e)`, in every entry: plain JavaScript, so it costs the
  // .wasm nothing.
  const glue = manifest(`pkg/${m}.js`);
  if (!glue.includes("export function isKliError(")) {
    writeFileSync(at(`pkg/${m}.js`), `${glue}
/**
 * True for every Error kli throws (from any entry): an Error with the string properties
 * \`argument\` and \`kind\`. A type guard: \`catch (e) { if (isKliError(e)) e.argument }\`.
 * @param {unknown} value
 * @returns {value is KliError}
 */
export function isKliError(value) {
    return value instanceof Error && typeof value.argument === "string" && typeof value.kind === "string";
}
`);
    writeFileSync(at(`pkg/${m}.d.ts`), `${manifest(`pkg/${m}.d.ts`)}
/** True for every Error kli throws (from any entry): an Error with the string properties
 *  \`argument\` and \`kind\`. A type guard: \`catch (e) { if (isKliError(e)) e.argument }\`. */
export function isKliError(value: unknown): value is KliError;
`);
  }
  // Zero configuration: init() with no argument fetches the .wasm beside the glue; where a
  // bundler left the file out (esbuild without a loader: 404) or served something else in its
  // place (Vite 7's dev server: index.html), it falls back to the module inlined, gzipped and
  // base64-encoded, in a file of its own loaded only then (a dynamic import: a separate chunk
  // for bundlers that split, so their apps never download it).
  const inline = `${m}_bg.inline.js`;
  writeFileSync(at(`pkg/${inline}`), `// ${m}_bg.wasm, gzipped and base64-encoded: what init() falls back to when the .wasm file
// itself cannot be fetched (see ${m}.js, __kliFallback). Loaded only then.
export default "${gzipSync(readFileSync(at(`pkg/${m}_bg.wasm`)), { level: 9 }).toString("base64")}";
`);
  const fetchLine = `module_or_path = new URL('${m}_bg.wasm', import.meta.url);`;
  // The fetched response is the .wasm: both loaders' test (a dev server's fallback serves HTML).
  const usable = "        if (response.ok && !(response.headers.get('Content-Type') || '').includes('text/html')) return response;\n";
  const fallback = `
/**
 * The response for the .wasm at \`url\`, or, where it cannot be had (fetch failed, an error
 * status, or HTML served in its place by a dev server's fallback), the module's inlined copy.
 * @param {URL} url
 * @param {() => Promise<{ default: string }>} inline
 */
async function __kliFallback(url, inline) {
    try {
        const response = await fetch(url);
${usable}    } catch {
        // file: URLs, offline, a bundler's missing file: the inlined copy below
    }
    const { default: base64 } = await inline();
    const gzipped = Uint8Array.from(atob(base64), (c) => c.charCodeAt(0));
    const stream = new Blob([gzipped]).stream().pipeThrough(new DecompressionStream('gzip'));
    return new Uint8Array(await new Response(stream).arrayBuffer());
}
`;
  const glueNow = manifest(`pkg/${m}.js`);
  if (!glueNow.includes("__kliFallback")) {
    if (!glueNow.includes(fetchLine)) throw new Error(`pkg/${m}.js: wasm-bindgen's default path changed shape (no "${fetchLine}")`);
    writeFileSync(at(`pkg/${m}.js`), `${glueNow.replace(fetchLine,
      `module_or_path = await __kliFallback(new URL('${m}_bg.wasm', import.meta.url), () => import('./${inline}'));`)}${fallback}`);
  }
  // kli/three and kli/gltf reach kli/spline and kli/average through the registry, never by
  // importing them (crates/kli-wasm/js/resample.js): each registers what it lends when imported.
  const lends = { spline: "kliSpline", average: "blendRotations" }[m];
  const glueLent = manifest(`pkg/${m}.js`);
  if (lends && !glueLent.includes("./resample.js")) {
    if (!glueLent.includes("const unready = ")) throw new Error(`pkg/${m}.js: not mended by scripts/glue.mjs (no unready)`);
    writeFileSync(at(`pkg/${m}.js`), `${glueLent}
import { entries as __kliEntries } from './resample.js';
__kliEntries['kli/${m}'] = { ${lends}, ready: () => wasm !== unready };
`);
  }
  // A production build (Vite's and webpack's, which resolve the export condition `production`)
  // emits the .wasm beside its scripts, so the inlined copy would only be dead weight in its
  // output (54 KB for kli/spline): this glue has no fallback, and where the file cannot be
  // fetched init() says which file, from where, and what to do. Each glue holds only its own
  // loader (with the other's code too, every entry's JavaScript grew by about 200 B gzipped).
  const full = manifest(`pkg/${m}.js`);
  const withFallback = `__kliFallback(new URL('${m}_bg.wasm', import.meta.url), () => import('./${inline}'))`;
  if (!full.includes(withFallback) || !full.includes(fallback)) throw new Error(`pkg/${m}.js: no fallback to replace for ${m}.production.js`);
  const fetchOnly = `
/**
 * The response for the .wasm at \`url\`; where it cannot be had (fetch failed, an error status,
 * or HTML served in its place), an Error that says which file, from where, and what to do.
 * @param {URL} url
 */
async function __kliFetch(url) {
    let failure;
    try {
        const response = await fetch(url);
${usable}        failure = response.ok ? 'HTML was served in its place' : \`status \${response.status}\`;
    } catch (error) {
        failure = String(error?.message ?? error);
    }
    throw Object.assign(new Error(\`${entryName(m)} could not load its WebAssembly from \${url} (\${failure}): serve ${m}_bg.wasm there (a production build emits it beside its scripts), or pass its URL or bytes as init({ module_or_path })\`), { argument: "${entryName(m)}", kind: "not-initialised" });
}
`;
  writeFileSync(at(`pkg/${m}.production.js`), `// ${m}.js without the inlined .wasm (the export condition \`production\`: a bundler's production build,
// which emits the .wasm beside its scripts). Generated by scripts/package-json.mjs.
${full.replace(withFallback, `__kliFetch(new URL('${m}_bg.wasm', import.meta.url))`).replace(fallback, fetchOnly)}`);
  writeFileSync(at(`pkg/${m}.node.js`), `// Node (and SSR, Vitest): the same module, with init() reading the .wasm beside this file
// from disk when given nothing, where the browser entry would fetch it (fetch cannot read file:).
import init from "./${m}.js";
import { readFile } from "node:fs/promises";

export * from "./${m}.js";
export { initSync } from "./${m}.js";

export default async function initNode(input) {
  if (input === undefined) input = { module_or_path: await readFile(new URL("./${m}_bg.wasm", import.meta.url)) };
  return init(input);
}
`);
}
copyFileSync(at("LICENSE"), at("pkg/LICENSE"));

/**
 * wasm-bindgen's declarations without the DOM library: each DOM type they name becomes the
 * environment's own where its types declare that global (the DOM library, @types/node, a worker's
 * lib), else what it is made of (a URL as a string, bytes as an ArrayBuffer or a view of one) or
 * `object`. So the package adds no global of its own to a project, and needs none.
 */
function domFree(types, file) {
  // Code lines only: wasm-bindgen's JSDoc of init names the DOM's types, and keeps them.
  const replaced = types.split("\n").map((line) => /^\s*(\*|\/\*|\/\/)/.test(line) ? line : line
    .replace(/\bRequestInfo \| URL \| Response \| BufferSource \| WebAssembly\.Module\b/g,
      'string | KliGlobal<"Request"> | KliGlobal<"URL"> | KliGlobal<"Response"> | ArrayBuffer | ArrayBufferView | KliWasm<"Module">')
    .replace(/\bBufferSource \| WebAssembly\.Module\b/g, 'ArrayBuffer | ArrayBufferView | KliWasm<"Module">')
    .replace(/\bWebAssembly\.Memory\b/g, 'KliWasm<"Memory", { readonly buffer: ArrayBuffer }>')
    .replace(/\bWebAssembly\.(Table|Global|Module|Instance)\b/g, 'KliWasm<"$1">')).join("\n");
  const code = replaced.replace(/\/\*[\s\S]*?\*\//g, "").replace(/\/\/.*$/gm, "");
  const left = code.match(/(?<![\w"])(RequestInfo|BufferSource|Request|Response|URL|WebAssembly\.\w+|HTML\w+|Window|Document)(?![\w"])/);
  if (left) throw new Error(`${file}: a DOM type is left (${left[0]}); update domFree in scripts/package-json.mjs`);
  if (replaced === types) return types;
  return `${replaced}
/** The type of \`globalThis[Name]\`'s instances where the project's types declare that global (the
 *  DOM library, @types/node), else \`Else\`: the package's types need no DOM library. */
type KliGlobal<Name extends string, Else = never> =
  typeof globalThis extends { readonly [K in Name]: { prototype: infer T } } ? T : Else;
/** The same for \`WebAssembly[Name]\`. */
type KliWasm<Name extends string, Else = object> =
  typeof globalThis extends { readonly WebAssembly: { readonly [K in Name]: { prototype: infer T } } } ? T : Else;
`;
}

// `production` after `node`: a server-side build for Node keeps reading the .wasm from disk.
const entry = (m) => ({ types: `./${m}.d.ts`, node: `./${m}.node.js`, production: `./${m}.production.js`, default: `./${m}.js` });
const json = {
  name: field(crate.split("[package.metadata.npm]")[1], "name"),
  version: field(workspace, "version"),
  description: field(crate, "description"),
  license: field(workspace, "license"),
  type: "module",
  main: "kli.js",
  module: "kli.js",
  types: "kli.d.ts",
  // Where both `import` and `require` work: require() of an ES module is unflagged from Node
  // 20.19 and 22.12 (tests/js/package.test.mjs requires every entry).
  engines: { node: ">=20.19.0 <21 || >=22.12.0" },
  exports: {
    ".": entry("kli"),
    "./swarm": entry("swarm"),
    "./spline": entry("spline"),
    "./average": entry("average"),
    "./sync": entry("sync"),
    // Plain JavaScript over kli/spline (the same module instance in Node and in bundlers).
    "./three": { types: "./three.d.ts", default: "./three.js" },
    "./gltf": { types: "./gltf.d.ts", default: "./gltf.js" },
    ...Object.fromEntries(modules.map((m) => [`./${m}_bg.wasm`, { types: `./${m}_bg.wasm.d.ts`, default: `./${m}_bg.wasm` }])),
    "./package.json": "./package.json",
  },
  files: [...modules.flatMap((m) => [`${m}.js`, `${m}.node.js`, `${m}.production.js`, `${m}.d.ts`, `${m}_bg.wasm`, `${m}_bg.wasm.d.ts`, `${m}_bg.inline.js`]), "three.js", "three.d.ts", "gltf.js", "gltf.d.ts", "resample.js", "README.md", "LICENSE"],
  // Only kli/three needs three.js, and it uses what every three.js since r150 has.
  peerDependencies: { three: ">=0.150.0" },
  peerDependenciesMeta: { three: { optional: true } },
  sideEffects: false,
  keywords: ["quaternion", "rotation", "slerp", "interpolation", "kuramoto", "hopf", "wasm"],
};
// The repository's address and the home page come from Cargo.toml's [workspace.package]
// `repository` and `homepage` when they are set there (crates.io reads the same fields); this
// repository has no public address yet.
const repository = workspace.match(/^repository\s*=\s*"([^"]*)"/m)?.[1];
if (repository) json.repository = { type: "git", url: `git+${repository.replace(/\.git$/, "")}.git` };
const homepage = workspace.match(/^homepage\s*=\s*"([^"]*)"/m)?.[1] ?? repository;
if (homepage) json.homepage = homepage;
writeFileSync(at("pkg/package.json"), JSON.stringify(json, null, 2) + "\n");
console.log(`pkg/package.json: ${json.name}@${json.version}${repository ? "" : " (no repository: set it in Cargo.toml)"}`);
