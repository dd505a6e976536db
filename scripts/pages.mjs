// What follows from the page list (www/pages.js):
//   node scripts/pages.mjs names   the pages' names, for the Makefile
//   node scripts/pages.mjs write   each page's modulepreload links (its script's static imports)
//                                  and www/pkg/build.js, the service worker's file list and cache
//                                  name (a hash of those files' contents)
//   node scripts/pages.mjs check   exits 1 when a page's links are not what `write` would write
import { createHash } from "node:crypto";
import { existsSync, readFileSync, writeFileSync } from "node:fs";
import { dirname, join, normalize, relative } from "node:path";
import { MODULES, PAGES } from "../www/pages.js";

const www = new URL("../www/", import.meta.url).pathname;

/** The files a module script imports statically, itself first, relative to www/. */
function importClosure(/** @type {string} */ script) {
  const seen = new Set();
  const visit = (file) => {
    if (seen.has(file)) return;
    seen.add(file);
    const path = join(www, file);
    if (!existsSync(path)) return; // a module not built yet (www/pkg): listed, not read
    const text = readFileSync(path, "utf8");
    for (const [, target] of text.matchAll(/^\s*(?:import|export)\s[^;]*?from\s*"(\.{1,2}\/[^"]+)"/gms)) {
      visit(normalize(relative(www, join(dirname(path), target))));
    }
  };
  visit(script);
  return [...seen];
}

/** The page's HTML with its modulepreload links in place of the old ones. */
function withPreloads(html, page) {
  const links = importClosure(page.script).map((file) => `<link rel="modulepreload" href="${file}">\n`).join("");
  const stripped = html.replace(/^<link rel="modulepreload"[^>]*>\n/gm, "");
  const anchor = '<link rel="stylesheet" href="style.css">\n';
  if (!stripped.includes(anchor)) throw new Error(`${page.html}: no ${anchor.trim()} to put the links after`);
  return stripped.replace(anchor, anchor + links);
}

/** Every file a page needs offline, relative to www/. */
function offlineFiles() {
  const files = new Set(["style.css", "pages.js", "kli-figure.js"]);
  for (const page of PAGES) {
    files.add(page.html);
    for (const file of importClosure(page.script)) files.add(file);
    files.add(`pkg/${page.name}_demo.js`);
    files.add(`pkg/${page.name}_demo_bg.wasm`);
  }
  for (const file of importClosure("kli-figure.js")) files.add(file);
  return [...files].sort();
}

const command = process.argv[2];
if (JSON.stringify(Object.keys(MODULES).sort()) !== JSON.stringify(PAGES.map((p) => p.name).sort())) {
  throw new Error("www/pages.js: MODULES must have one loader a page, under the page's name");
}
if (command === "names") {
  console.log(PAGES.map((page) => page.name).join(" "));
} else if (command === "write" || command === "check") {
  let stale = [];
  for (const page of PAGES) {
    const path = join(www, page.html);
    const html = readFileSync(path, "utf8");
    const wanted = withPreloads(html, page);
    if (wanted === html) continue;
    if (command === "write") writeFileSync(path, wanted);
    stale.push(page.html);
  }
  if (command === "check") {
    if (stale.length) {
      console.error(`modulepreload links out of date in ${stale.join(", ")}: run node scripts/pages.mjs write`);
      process.exit(1);
    }
  } else {
    const files = offlineFiles();
    const hash = createHash("sha256");
    for (const file of files) hash.update(file).update(existsSync(join(www, file)) ? readFileSync(join(www, file)) : "");
    const build = `// Written by scripts/pages.mjs from www/pages.js: what the service worker caches, and under which name.
self.KLI_BUILD = ${JSON.stringify({ cache: `kli-${hash.digest("hex").slice(0, 12)}`, files: ["./", ...files] }, null, 1)};
`;
    const out = join(www, "pkg/build.js");
    if (!existsSync(out) || readFileSync(out, "utf8") !== build) writeFileSync(out, build);
    if (stale.length) console.log(`modulepreload links written in ${stale.join(", ")}`);
  }
} else {
  console.error("usage: node scripts/pages.mjs names | write | check");
  process.exit(2);
}
