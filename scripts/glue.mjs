// Mends the JavaScript glue wasm-bindgen generates, for the package's entries and the pages'
// modules alike, so that no JavaScript exception ever crosses a wasm frame. One that does skips
// the frame's epilogue: the externref stack (1,024 slots) and the shadow stack are not popped,
// and after about a thousand such errors every call traps ("table index is out of bounds"). The
// Rust code catches every exception of its own imports; what is left are wasm-bindgen's own
// checks, thrown from inside its shims, so they are made here, in JavaScript, before the call:
// - every call into the module is guarded: a method of a freed object (its pointer is 0) throws
//   kind "freed", and a call made while another is running (a getter or Proxy of the caller's
//   that calls back into the module) throws kind "busy", both with `argument: "this"`;
// - the Errors its runtime would throw anyway get the same message, `argument` and `kind`;
// - `free()` is idempotent (a second call, or `using` after an explicit free, does nothing), and
//   a `free()` refused because a call is running leaves the object alive and usable;
// - before `init()`, every call (a function, a constructor, a method) throws kind
//   "not-initialised" with `argument` the entry to initialise ("kli/spline"), where the glue
//   would throw "Cannot read properties of undefined": the module's exports are a Proxy until
//   then, whose every property throws.
// Every pattern must match: a wasm-bindgen upgrade that changes the glue fails the build here
// rather than losing the mends silently.
//   node scripts/glue.mjs file.js…
import { readFileSync, writeFileSync } from "node:fs";

const THROW = /(__wbg___wbindgen_throw_[0-9a-f]+: function\(arg0, arg1\) \{\s*)throw new Error\(getStringFromWasm0\(arg0, arg1\)\);/;
const EXPORTS = /(\n\s*)wasm = instance\.exports;/;
const FREE = /free\(\) \{\n(\s*)const ptr = this\.__destroy_into_raw\(\);\n\s*(wasm\.__wbg_\w+_free\(ptr, 0\);)/g;
const DECLARED = /\n(let (?:\w+, )*)wasm;\n/;
const LOADED = /if \(wasm !== undefined\) return wasm;/g;

const KNOWN = `
// kli: wasm-bindgen's own checks, as kli Errors (scripts/glue.mjs).
function rustError(message) {
    const known = {
        "null pointer passed to rust": ["freed", "this object was freed (free() was called on it): make a new one"],
        "recursive use of an object detected which would lead to unsafe aliasing in rust": ["busy", "kli is in the middle of a call (a getter or Proxy of its arguments called back into it): call it after that call returns"],
        "attempted to take ownership of Rust value while it was borrowed": ["busy", "this object cannot be freed in the middle of one of its calls (a getter or Proxy called free()): free it after that call returns"],
    }[message];
    return known ? kliError(known[1], "this", known[0]) : new Error(message);
}

function kliError(message, argument, kind) {
    const error = new Error(message);
    error.argument = argument;
    error.kind = kind;
    return error;
}

// kli: every call into the module checked before it enters (scripts/glue.mjs).
function guard(exports, methods) {
    let depth = 0;
    const guarded = {};
    for (const [name, value] of Object.entries(exports)) {
        if (typeof value !== "function" || /^__(wbindgen|externref)_/.test(name)) {
            guarded[name] = value;
            continue;
        }
        if (value.length > 8) throw new Error(\`kli: the export \${name} takes more than 8 arguments\`);
        const method = methods.has(name);
        guarded[name] = function (a, b, c, d, e, f, g, h) {
            if (depth !== 0) throw rustError("recursive use of an object detected which would lead to unsafe aliasing in rust");
            if (method && a === 0) throw rustError("null pointer passed to rust");
            depth++;
            try {
                return value(a, b, c, d, e, f, g, h);
            } finally {
                depth--;
            }
        };
    }
    return guarded;
}
`;

/** How a module's users import it: "kli/spline" for pkg/spline.js, "kli" for pkg/kli.js, and a
 *  page's module (www/pkg/kli_demo.js) by its file, "./kli_demo.js". */
export function entryOf(file) {
  const name = file.split("/").pop().replace(/\.js$/, "");
  if (name.endsWith("_demo")) return `./${name}.js`;
  return name === "kli" ? "kli" : `kli/${name}`;
}

export function mend(source, file = "glue", entry = entryOf(file)) {
  if (source.includes("function rustError(")) return source;
  if (!EXPORTS.test(source)) throw new Error(`${file}: wasm-bindgen's exports assignment not found; update scripts/glue.mjs`);
  if (!DECLARED.test(source)) throw new Error(`${file}: wasm-bindgen's \`let wasm;\` not found; update scripts/glue.mjs`);
  if ((source.match(LOADED) ?? []).length !== 2) throw new Error(`${file}: init's and initSync's \`wasm !== undefined\` checks not found; update scripts/glue.mjs`);
  const methods = [...new Set([...source.matchAll(/wasm\.(\w+)\(this\.__wbg_ptr/g)].map((m) => m[1]))];
  if (!THROW.test(source)) throw new Error(`${file}: wasm-bindgen's throw intrinsic not found; update scripts/glue.mjs`);
  let frees = 0;
  const mended = source
    .replace(THROW, "$1throw rustError(getStringFromWasm0(arg0, arg1));")
    .replace(EXPORTS, `$1wasm = guard(instance.exports, new Set(${JSON.stringify(methods)}));`)
    .replace(DECLARED, `\nconst unready = new Proxy({}, { get() { throw kliError(${JSON.stringify(`${entry} is not initialised: call \`await init()\` from "${entry}" first`)}, ${JSON.stringify(entry)}, "not-initialised"); } });
$1wasm = unready;\n`)
    .replace(LOADED, "if (wasm !== unready) return wasm;")
    .replace(FREE, (_, indent, call) => {
      frees += 1;
      return `free() {\n${indent}const ptr = this.__destroy_into_raw();\n${indent}if (ptr === 0) return;\n` +
        `${indent}try { ${call} } catch (e) { this.__wbg_ptr = ptr; throw e; }`;
    });
  if (/\bfree\(\) \{/.test(source) && frees === 0) throw new Error(`${file}: no free() mended; update scripts/glue.mjs`);
  return mended + KNOWN;
}

if (import.meta.url === `file://${process.argv[1]}`) {
  for (const file of process.argv.slice(2)) writeFileSync(file, mend(readFileSync(file, "utf8"), file));
}
