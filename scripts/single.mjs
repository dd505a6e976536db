// `make single`: each page of the demo as one self-contained HTML file in dist/single/ (and the
// <kli-figure> element as one self-contained script), for a
// course platform that takes an uploaded file or a USB stick opened with no server: the page's
// scripts bundled by esbuild, its module's .wasm inlined (base64) and handed to init(), the style
// sheet inlined. Opened from file://, such a page fetches nothing.
import { build } from "esbuild";
import { mkdir, readFile, writeFile } from "node:fs/promises";
import { join } from "node:path";
import { MORE_LINKS, PAGES, bundle as bundleOf, script as scriptOf } from "../www/pages.js";
import { DOCUMENTS } from "./documents.mjs";
import { LAYOUTS, pictureSheet } from "./first-pictures.mjs";

const root = new URL("../", import.meta.url).pathname;
const www = join(root, "www");
const out = join(root, "dist/single");

/** Serves `./pkg/<name>_demo.js` as a module whose default `init()` is given the inlined .wasm. */
const inlineWasm = {
  name: "inline-wasm",
  setup(build) {
    build.onResolve({ filter: /\/pkg\/\w+_demo\.js$/ }, (args) =>
      args.pluginData === "glue" ? undefined : { path: join(args.resolveDir, args.path), namespace: "inline-wasm" });
    build.onLoad({ filter: /.*/, namespace: "inline-wasm" }, (args) => ({
      resolveDir: www,
      pluginData: "glue",
      contents: `
        import init from ${JSON.stringify(args.path)};
        import wasm from ${JSON.stringify(args.path.replace(/\.js$/, "_bg.wasm"))};
        export * from ${JSON.stringify(args.path)};
        export default (input) => init(input ?? { module_or_path: wasm });`,
    }));
    // The glue's own import of itself must reach the real file.
    build.onResolve({ filter: /.*/ }, (args) => (args.pluginData === "glue" && args.path.endsWith(".js") ? { path: args.path } : undefined));
  },
};

/** A page's own module is inside it; the registry's loaders of the other pages' modules (for
 *  <kli-figure>) stay as they are, never called on the page. */
const otherPages = {
  name: "other-pages",
  setup(build) {
    build.onResolve({ filter: /\/pkg\/\w+_demo\.js$/ }, (args) => (args.kind === "dynamic-import" ? { path: args.path, external: true } : undefined));
  },
};

/** The links of the navigation that lead out of the one-file pages removed: the examples (they need
 *  the site's import map and vendored files) and the documents `make single` does not write. */
function withoutOtherLinks(html, page) {
  const kept = new Set(DOCUMENTS.filter((doc) => doc.single).map((doc) => doc.html));
  for (const link of MORE_LINKS.filter((link) => !kept.has(link.href))) {
    const before = html;
    html = html.replace(` · <a href="${link.href}">${link.title}</a>`, "");
    if (html === before) throw new Error(`${page}: no link to ${link.href} in its navigation`);
  }
  return html;
}

/** A document of the site (scripts/documents.mjs) with its style sheet inside. */
async function singleDocument(doc) {
  const css = await readFile(join(www, "style.css"), "utf8");
  const html = (await readFile(join(www, doc.html), "utf8"))
    .replace('<link rel="stylesheet" href="style.css">', () => `<style>\n${css}</style>`);
  if (html.includes('href="style.css"')) throw new Error(`${doc.html}: its style sheet was not inlined`);
  await writeFile(join(out, doc.html), withoutOtherLinks(html, doc.html));
  return html.length;
}

/** The page's HTML with its style sheet and bundled script inside, and nothing to fetch. */
async function single(entry) {
  const [page, script] = [entry.html, scriptOf(entry)];
  const bundle = await build({
    entryPoints: [join(www, script)],
    bundle: true,
    format: "esm",
    minify: true,
    write: false,
    loader: { ".wasm": "binary" },
    plugins: [otherPages, inlineWasm],
    logLevel: "silent",
  });
  const code = bundle.outputFiles[0].text;
  if (code.includes("</script")) throw new Error(`${script}: the bundle holds "</script" and cannot be inlined`);
  const css = await readFile(join(www, "style.css"), "utf8");
  let html = await readFile(join(www, page), "utf8");
  const replace = (pattern, replacement) => {
    const before = html;
    html = html.replace(pattern, replacement);
    if (html === before) throw new Error(`${page}: ${pattern} not found`);
  };
  replace(/^<link rel="(modulepreload|preload)"[^>]*>\n/gm, "");
  replace('<link rel="stylesheet" href="style.css">', () => `<style>\n${css}</style>`);
  replace(`<script type="module" src="${bundleOf(entry)}"></script>`, () => `<script type="module">\n${code}</script>`);
  html = withoutOtherLinks(html, page);
  // The first pictures' sheets (scripts/first-pictures.mjs) inside: their pictures are data:
  // addresses already.
  for (const layout of LAYOUTS) {
    const sheet = await readFile(join(www, pictureSheet(entry, layout)), "utf8");
    replace(`<link rel="stylesheet" href="${pictureSheet(entry, layout)}" media="${layout.media}">`,
      () => `<style media="${layout.media}">\n${sheet}</style>`);
  }
  await writeFile(join(out, page), html);
  return html.length;
}

await mkdir(out, { recursive: true });
for (const page of PAGES) {
  const bytes = await single(page);
  console.log(`dist/single/${page.html}: ${bytes} bytes`);
}
for (const doc of DOCUMENTS.filter((doc) => doc.single)) console.log(`dist/single/${doc.html}: ${await singleDocument(doc)} bytes`);

// <kli-figure> as one classic script with every page's module inside: `<script src="kli-figure.js">`
// works in documentation sites and slide decks, and from file:// (where module scripts do not).
const element = await build({
  entryPoints: [join(www, "kli-figure.js")],
  bundle: true,
  format: "iife",
  minify: true,
  outfile: join(out, "kli-figure.js"),
  loader: { ".wasm": "binary" },
  plugins: [inlineWasm],
  logLevel: "error",
  // The glue's default .wasm URL (import.meta.url) is never used: every init is given the bytes.
  logOverride: { "empty-import-meta": "silent" },
  metafile: true,
});
console.log(`dist/single/kli-figure.js: ${Object.values(element.metafile.outputs)[0].bytes} bytes`);
// The figures' boxes before the script runs (no layout shift), for pages that embed them.
await writeFile(join(out, "kli-figure.css"), await readFile(join(www, "kli-figure.css")));
