// What follows from the pages' registry (www/pages.js):
//   node scripts/pages.mjs names   the pages' names, for the Makefile
//   node scripts/pages.mjs write   in each page's HTML: the pages' navigation, its Save list and its
//                                  script tag pointing at its bundle; each page's bundle (its
//                                  descriptor, www/<name>/page.js, and every module it imports,
//                                  minified: one request beside the .wasm module's glue instead of
//                                  a dozen) into www/pkg/<name>-page.js; and www/pkg/build.js, the
//                                  service worker's file list and cache name (a hash of those files)
//   node scripts/pages.mjs check   exits 1 when a page's HTML is not what `write` makes of it
import { createHash } from "node:crypto";
import { existsSync, readFileSync, writeFileSync } from "node:fs";
import { join, relative, resolve } from "node:path";
import { MORE_LINKS, PAGES, bundle, script } from "../www/pages.js";
import { LAYOUTS, pictureLinks, pictureSheet } from "./first-pictures.mjs";

const www = new URL("../www/", import.meta.url).pathname;
const SCRIPT = /<script type="module" src="[^"]*"><\/script>/;

const NAV = /<nav aria-label="Pages">.*<\/nav>/;
const SAVE_LIST = /(<section id="save"[^]*?<ul>\n)[^]*?(    <\/ul>)/;

/** The pages' navigation as `page` shows it: every page of the registry, then the examples. */
function navigation(page) {
  const links = PAGES.map((other) =>
    `<a href="${other.html}"${other === page ? ' aria-current="page"' : ""}>${other.title}</a>`);
  links.push(...MORE_LINKS.map((link) => `<a href="${link.href}">${link.title}</a>`));
  return `<nav aria-label="Pages">${links.join(" · ")}</nav>`;
}

/** The page's Save list: each view as PNG and SVG, its data as CSV and JSON (the registry's `save`). */
function saveList(page) {
  return Object.entries(page.save).map(([what, [label, noun]]) => {
    const formats = Object.hasOwn(page.canvases, what) ? ["png", "svg"] : ["csv", "json"];
    const [first, second] = formats.map((format) =>
      `<button type="button" data-save="${what}" data-format="${format}" aria-label="${noun} as ${format.toUpperCase()}">${format.toUpperCase()}</button>`);
    return `      <li>${label} ${first}\n        ${second}</li>\n`;
  }).join("");
}

/** The page's HTML with the registry's navigation and Save list. */
function withRegistry(html, page) {
  if (!NAV.test(html)) throw new Error(`${page.html}: no <nav aria-label="Pages"> on one line to fill`);
  if (!SAVE_LIST.test(html)) throw new Error(`${page.html}: no <section id="save"> with a <ul> to fill`);
  return html.replace(NAV, navigation(page)).replace(SAVE_LIST, (_, start, end) => start + saveList(page) + end);
}

/** The page's HTML loading its first pictures' sheets (render-blocking: the pictures come in the
 *  text's paint) and its bundle, with the module's glue preloaded. Not its .wasm: the pictures
 *  are on screen before the module matters, and on Lighthouse's slow phone network a preloaded
 *  .wasm (57–252 KB gzipped) competes with them: the largest contentful paint came 0.4–1.4 s
 *  later with it, on every page (2026-11-26). */
function withBundle(html, page) {
  if (!SCRIPT.test(html)) throw new Error(`${page.html}: no <script type="module" src="…"> to point at the bundle`);
  const anchor = '<link rel="stylesheet" href="style.css">\n';
  if (!html.includes(anchor)) throw new Error(`${page.html}: no ${anchor.trim()} to put the preload after`);
  const preload = pictureLinks(page) + `<link rel="modulepreload" href="pkg/${page.name}_demo.js">\n`;
  return html
    .replace(/^<link rel="(modulepreload|preload)"[^>]*>\n/gm, "")
    .replace(/^<link rel="stylesheet" href="pkg\/first\/[^>]*>\n/gm, "")
    .replace(anchor, anchor + preload)
    .replace(SCRIPT, `<script type="module" src="${bundle(page)}"></script>`);
}

/** Every file the pages need offline, relative to www/: the element and its modules too. */
async function offlineFiles() {
  const element = await build({
    entryPoints: [join(www, "kli-figure.js")], bundle: true, write: false, metafile: true, format: "esm",
    external: ["./pkg/*"], logLevel: "error", plugins: [sharedModules],
  });
  const modules = Object.keys(element.metafile.inputs).map((input) => relative(www, resolve(input)));
  // The pages' worker (runtime/offload.js starts it as it is, unbundled).
  const files = new Set(["style.css", "kli-figure.css", "vendor/codecs.js", "runtime/worker.js", ...modules]);
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

const command = process.argv[2];
// esbuild only for `write`: `names` runs when the Makefile is read, before npm has installed it.
const { build } = command === "write" ? await import("esbuild") : { build: undefined };
if (command === "names") {
  console.log(PAGES.map((page) => page.name).join(" "));
} else if (command === "write" || command === "check") {
  const stale = [];
  for (const page of PAGES) {
    const path = join(www, page.html);
    const html = readFileSync(path, "utf8");
    const wanted = withBundle(withRegistry(html, page), page);
    if (wanted === html) continue;
    if (command === "write") writeFileSync(path, wanted);
    stale.push(page.html);
  }
  if (command === "check") {
    if (stale.length) {
      console.error(`not as the registry makes them (navigation, Save list, bundle): ${stale.join(", ")}: run node scripts/pages.mjs write`);
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
    if (stale.length) console.log(`navigation, Save lists and script tags written from the registry in ${stale.join(", ")}`);
  }
} else {
  console.error("usage: node scripts/pages.mjs names | write | check");
  process.exit(2);
}
