// docs/api.md against the package's TypeScript declarations (pkg/*.d.ts, as `make pkg` writes
// them): every export, class member, option and error kind is documented, in its entry's section
// where it belongs to one; and every export the page's tables name exists.
import { test } from "node:test";
import assert from "node:assert/strict";
import { readFileSync } from "node:fs";

const at = (path) => new URL(`../../${path}`, import.meta.url);
const doc = readFileSync(at("docs/api.md"), "utf8");
const ENTRIES = { kli: "kli", spline: "kli/spline", swarm: "kli/swarm", average: "kli/average", sync: "kli/sync", three: "kli/three", gltf: "kli/gltf" };
/** wasm-bindgen's own loading exports, documented once under Conventions. */
const LOADING = new Set(["InitInput", "InitOutput", "SyncInitInput", "initSync", "__wbg_init"]);

/** The section of the page about `entry` (from its `## \`entry\`` heading to the next). */
function section(entry) {
  const start = doc.indexOf(`## \`${entry}\``);
  assert.ok(start >= 0, `docs/api.md has no section for ${entry}`);
  const end = doc.indexOf("\n## ", start + 1);
  return doc.slice(start, end < 0 ? undefined : end);
}

/** Whether `text` names `name` in code (between backticks, as a whole word). */
const names = (text, name) => new RegExp("`[^`\\n]*\\b" + name.replace(/\$/g, "\\$") + "\\b[^`\\n]*`").test(text);

/** What one entry's declarations export: functions and classes, types, class members, option keys. */
function declarations(file) {
  const dts = readFileSync(at(`pkg/${file}.d.ts`), "utf8");
  const exports = [...dts.matchAll(/^export (?:declare )?(function|class|interface|type) (\w+)/gm)]
    .map(([, kind, name]) => ({ kind, name }))
    .filter(({ name }) => !LOADING.has(name));
  const members = [];
  for (const [, name, body] of dts.matchAll(/^export class (\w+)[^{]*\{([\s\S]*?)^\}/gm)) {
    for (const [, member] of body.matchAll(/^\s+(?:readonly )?(\w+)[(:?]/gm)) {
      if (!["constructor", "free"].includes(member)) members.push(`${name}.${member}`);
    }
  }
  const options = [];
  for (const [, name, body] of dts.matchAll(/^export interface (\w*Options) [^{]*\{([\s\S]*?)^\}/gm)) {
    for (const [, key] of body.matchAll(/^\s+(\w+)\??:/gm)) options.push(`${name}.${key}`);
  }
  const kinds = [...(dts.match(/export type KliErrorKind =([\s\S]*?);/)?.[1] ?? "").matchAll(/"([\w-]+)"/g)].map(([, kind]) => kind);
  return { exports, members, options, kinds };
}

for (const [file, entry] of Object.entries(ENTRIES)) {
  test(`docs/api.md documents every export of ${entry}`, () => {
    const { exports, members, options, kinds } = declarations(file);
    assert.ok(exports.length > 0, `no exports read from pkg/${file}.d.ts`);
    const own = section(entry);
    const missing = [];
    for (const { kind, name } of exports) {
      // Functions and classes belong to their entry's section; shared types anywhere.
      const where = kind === "function" || kind === "class" ? own : doc;
      if (name !== "isKliError" && !names(where, name)) missing.push(`${kind} ${name}`);
    }
    for (const member of members) if (!names(doc, member.split(".")[1])) missing.push(`member ${member}`);
    for (const option of options) if (!names(doc, option.split(".")[1])) missing.push(`option ${option}`);
    for (const kind of kinds) if (!doc.includes(`"${kind}"`)) missing.push(`error kind "${kind}"`);
    assert.deepEqual(missing, [], `in pkg/${file}.d.ts but not in docs/api.md`);
  });
}

test("every export docs/api.md's tables name is exported by its entry", () => {
  const unknown = [];
  for (const [file, entry] of Object.entries(ENTRIES)) {
    const exported = new Set(declarations(file).exports.map(({ name }) => name));
    for (const [, name] of section(entry).matchAll(/^\| `(?:new )?(\w+)\(/gm)) {
      if (!exported.has(name)) unknown.push(`${entry}: ${name}`);
    }
  }
  assert.deepEqual(unknown, []);
});
