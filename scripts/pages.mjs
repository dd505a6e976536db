// What follows from the pages' registry (www/pages.js):
//   node scripts/pages.mjs names   the pages' names, for the Makefile
//   node scripts/pages.mjs write   each page's HTML at its address (www/<html>) from its folder
//                                  (`compose`); each page's bundle (its
//                                  descriptor, www/<name>/page.js, and every module it imports,
//                                  minified: one request beside the .wasm module's glue instead of
//                                  a dozen) into www/pkg/<name>-page.js; and www/pkg/build.js, the
//                                  service worker's file list and cache name (a hash of those files)
//   node scripts/pages.mjs check   exits 1 when a page's folder lacks what its HTML is made from,
//                                  or a page's HTML on disk is not what `write` makes of it
import { createHash } from "node:crypto";
import { existsSync, readFileSync, writeFileSync } from "node:fs";
import { join, relative, resolve } from "node:path";
import { pathToFileURL } from "node:url";
import { EXAMPLES, MORE_LINKS, PAGES, bundle, script } from "../www/pages.js";
import { LAYOUTS, pictureLinks, pictureSheet } from "./first-pictures.mjs";

const command = process.argv[2];
// marked (documents.mjs) and esbuild only for `write` and `check`: `names` runs when the
// Makefile is read, before npm has installed them on a fresh clone.
const { DOCUMENTS, documentPage } = command === "names" ? { DOCUMENTS: [], documentPage: undefined } : await import("./documents.mjs");

const www = new URL("../www/", import.meta.url).pathname;

/** The pages' navigation as `page` (a page of the registry, or the address of another page at the
 *  site's root) shows it: every page of the registry, then the other links. */
function navigation(page) {
  const current = (/** @type {string} */ href) => (href === page?.html || href === page ? ' aria-current="page"' : "");
  const links = PAGES.map((other) => `<a href="${other.html}"${current(other.html)}>${other.title}</a>`);
  links.push(...MORE_LINKS.map((link) => `<a href="${link.href}"${current(link.href)}>${link.title}</a>`));
  return `<nav aria-label="Pages">${links.join(" · ")}</nav>`;
}

/** The pages' navigation as an example page (www/examples/) shows it: the same links, relative to
 *  its folder, and the example itself, current. */
function exampleNavigation(example) {
  const links = PAGES.map((page) => `<a href="../${page.html}">${page.title}</a>`);
  const more = MORE_LINKS.some((link) => link.href === example.href) ? MORE_LINKS : [...MORE_LINKS, example];
  links.push(...more.map((link) => {
    const href = link.href.startsWith("examples/") ? link.href.slice("examples/".length) : `../${link.href}`;
    return `<a href="${href}"${link.href === example.href ? ' aria-current="page"' : ""}>${link.title}</a>`;
  }));
  return `<nav aria-label="Pages">${links.join(" · ")}</nav>`;
}

/** An example page's HTML with its navigation as the registry makes it, or an Error. */
function composeExample(example) {
  const source = readFileSync(join(www, example.href), "utf8");
  const nav = /^  <nav aria-label="Pages">.*<\/nav>$/m;
  if (!nav.test(source)) throw new Error(`www/${example.href}: no <nav aria-label="Pages"> on a line of its own`);
  return source.replace(nav, `  ${exampleNavigation(example)}`);
}

/** The page's Save section: its own sentence, then each view as PNG and SVG and its data as CSV
 *  and JSON (the registry's `save`), and the status the runtime writes to. */
function saveSection(page, intro) {
  const items = Object.entries(page.save).map(([what, [label, noun]]) => {
    const formats = Object.hasOwn(page.canvases, what) ? ["png", "svg"] : ["csv", "json"];
    const [first, second] = formats.map((format) =>
      `<button type="button" data-save="${what}" data-format="${format}" aria-label="${noun} as ${format.toUpperCase()}">${format.toUpperCase()}</button>`);
    return `      <li>${label} ${first}\n        ${second}</li>\n`;
  }).join("");
  return `<section id="save" class="save" aria-labelledby="save-title">
    <h2 id="save-title">Save</h2>
${intro}    <ul>
${items}    </ul>
    <p id="save-status" class="visually-hidden" role="status"></p>
  </section>`;
}

/** One piece of the page's own HTML, or an Error saying what `www/<name>/page.html` lacks. */
function piece(source, page, pattern, what) {
  const found = pattern.exec(source);
  if (!found) throw new Error(`www/${page.name}/page.html: ${what}`);
  return found;
}

/** The English text of each page whose text lives apart from its markup, in www/<name>/strings/en.js
 *  (one file a language; the tour's): its `page`, each piece by key. */
const STRINGS = Object.fromEntries(await Promise.all(PAGES.map(async (page) => {
  const file = join(www, page.name, "strings", "en.js");
  return [page.name, existsSync(file) ? (await import(pathToFileURL(file).href)).page : undefined];
})));

/** `source` with each `{{key}}` replaced by the page's English piece of that key (its script puts
 *  another language's in place), or an Error naming a key the strings lack. */
function filled(source, page) {
  const strings = STRINGS[page.name];
  if (!strings) return source;
  return source.replace(/\{\{([\w.-]+)\}\}/g, (_, key) => {
    if (!Object.hasOwn(strings, key)) throw new Error(`www/${page.name}/page.html: {{${key}}} is not in strings/en.js`);
    return strings[key];
  });
}

/**
 * A page's HTML at its address, `www/<html>`, from its folder: `page.html` (its <title>, its
 * description, then its body: the header, <main> with `<section id="save">` holding only its
 * sentence, and the footer) and `style.css` (its own rules). Everything a page shares is written
 * here once: the head, the pages' navigation at the header's foot, the module's load status at
 * the top of <main>, the Save list (the registry's), and its first pictures' sheets (render-
 * blocking: the pictures come in the text's paint) and its bundle, with the module's glue
 * preloaded. Not its .wasm: the pictures are on screen before the module matters, and on
 * Lighthouse's slow phone network a preloaded .wasm (57–252 KB gzipped) competes with them: the
 * largest contentful paint came 0.4–1.4 s later with it, on every page (2026-11-26).
 */
export function compose(page) {
  const source = filled(readFileSync(join(www, page.name, "page.html"), "utf8"), page);
  const style = readFileSync(join(www, page.name, "style.css"), "utf8");
  const [title] = piece(source, page, /^<title>[^<]+<\/title>$/m, "no <title> on a line of its own");
  const [description] = piece(source, page, /^<meta name="description" content="[^"]+">$/m, 'no <meta name="description"> on a line of its own');
  const [body] = piece(source, page, /^<header class="page-header">$[^]*^<\/footer>$/m, 'no body from <header class="page-header"> to </footer>');
  piece(body, page, /^<\/header>$/m, "no </header> on a line of its own");
  piece(body, page, /^<main>$/m, "no <main> on a line of its own");
  const [, intro] = piece(body, page, /^  <section id="save">\n(    <p>[^]*?<\/p>\n)  <\/section>$/m,
    'no <section id="save"> holding its one sentence, <p>…</p>');
  return `<!doctype html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
${description}
<link rel="icon" href="data:,">
<link rel="stylesheet" href="style.css">
<style>
${style.trimEnd()}
</style>
${pictureLinks(page)}<link rel="modulepreload" href="pkg/${page.name}_demo.js">
${title}
</head>
<body>
${body
    .replace(/^<\/header>$/m, `  ${navigation(page)}\n</header>`)
    .replace(/^<main>$/m, '<main>\n  <p id="load-status" class="status" role="status">Loading the WebAssembly module…</p>\n')
    .replace(/^  <section id="save">\n[^]*?^  <\/section>$/m, () => `  ${saveSection(page, intro)}`)}
<script type="module" src="${bundle(page)}"></script>
</body>
</html>
`;
}

/** Every file the pages need offline, relative to www/: the element and its modules too. */
async function offlineFiles() {
  const element = await build({
    entryPoints: [join(www, "kli-figure.js")], bundle: true, write: false, metafile: true, format: "esm",
    external: ["./pkg/*"], logLevel: "error", plugins: [sharedModules],
  });
  const modules = Object.keys(element.metafile.inputs).map((input) => relative(www, resolve(input)));
  // The pages' worker (runtime/offload.js starts it as it is, unbundled).
  const files = new Set(["style.css", "kli-figure.css", "vendor/codecs.js", "runtime/worker.js", ...DOCUMENTS.map((doc) => doc.html), ...modules]);
  for (const page of PAGES) {
    files.add(page.html);
    files.add(bundle(page));
    files.add(`pkg/${page.name}_demo.js`);
    files.add(`pkg/${page.name}_demo_bg.wasm`);
    // Its first pictures (scripts/first-pictures.mjs).
    for (const layout of LAYOUTS) files.add(pictureSheet(page, layout));
  }
  return [...files].sort();
}

/** The .wasm modules' glue stays a module of its own beside the bundle (pkg/<name>_demo.js), so
 *  that the page and anything else on it (a test, the console) share one instance; the video
 *  codecs (vendor/codecs.js, 60 KB gzipped) stay a module of their own, loaded only to save a video. */
const sharedModules = {
  name: "shared-modules",
  setup(build) {
    build.onResolve({ filter: /\/pkg\/\w+_demo\.js$/ }, (args) => ({ path: `./${args.path.split("/").pop()}`, external: true }));
    build.onResolve({ filter: /\/vendor\/codecs\.js$/ }, () => ({ path: "../vendor/codecs.js", external: true }));
  },
};

const { build } = command === "write" ? await import("esbuild") : { build: undefined };
if (command === "names") {
  console.log(PAGES.map((page) => page.name).join(" "));
} else if (command === "write" || command === "check") {
  const stale = [];
  for (const page of PAGES) {
    const path = join(www, page.html);
    const wanted = compose(page);
    if (existsSync(path) && readFileSync(path, "utf8") === wanted) continue;
    if (command === "write") writeFileSync(path, wanted);
    // Not written yet is no fault: `make www` writes them.
    if (command === "write" || existsSync(path)) stale.push(page.html);
  }
  for (const doc of DOCUMENTS) {
    const wanted = documentPage(doc, navigation(doc.html));
    const path = join(www, doc.html);
    if (existsSync(path) && readFileSync(path, "utf8") === wanted) continue;
    if (command === "write") writeFileSync(path, wanted);
    if (command === "write" || existsSync(path)) stale.push(doc.html);
  }
  for (const example of EXAMPLES) {
    const wanted = composeExample(example);
    if (readFileSync(join(www, example.href), "utf8") === wanted) continue;
    if (command === "write") writeFileSync(join(www, example.href), wanted);
    stale.push(example.href);
  }
  if (command === "check") {
    if (stale.length) {
      console.error(`not as their folders and the registry make them: ${stale.join(", ")}: run node scripts/pages.mjs write`);
      process.exit(1);
    }
  } else {
    await Promise.all(PAGES.map((page) => build({
      entryPoints: [join(www, script(page))],
      bundle: true,
      format: "esm",
      minify: true,
      sourcemap: "linked",
      target: "es2022",
      outfile: join(www, bundle(page)),
      logLevel: "error",
      plugins: [sharedModules],
    })));
    const files = await offlineFiles();
    const missing = files.filter((file) => !existsSync(join(www, file)));
    if (missing.length) throw new Error(`files to cache that are not there: ${missing.join(", ")}`);
    const hash = createHash("sha256");
    for (const file of files) hash.update(file).update(readFileSync(join(www, file)));
    const build_ = `// Written by scripts/pages.mjs from www/pages.js: what the service worker caches, and under which name.
self.KLI_BUILD = ${JSON.stringify({ cache: `kli-${hash.digest("hex").slice(0, 12)}`, files: ["./", ...files] }, null, 1)};
`;
    const out = join(www, "pkg/build.js");
    if (!existsSync(out) || readFileSync(out, "utf8") !== build_) writeFileSync(out, build_);
    if (stale.length) console.log(`written from their folders and the registry: ${stale.join(", ")}`);
  }
} else {
  console.error("usage: node scripts/pages.mjs names | write | check");
  process.exit(2);
}
