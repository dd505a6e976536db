// The pages' registry (www/pages.js) against what is on disk: a page is one folder a side (its
// run class in crates/kli-demo/src/<name>/, its descriptor and state in www/<name>/), its
// Cargo feature, its HTML (www/<name>/page.html and style.css, which `make www` makes into the page
// at its address) and one entry. A page on disk that the registry does
// not name fails here, and so does an entry with nothing on disk; so do the pages' navigation
// and Save lists when they are not what the registry makes, and docs/architecture.md's lists of
// pages and crates when they drift.
import { test } from "node:test";
import assert from "node:assert/strict";
import { execFileSync } from "node:child_process";
import { existsSync, readdirSync, readFileSync, statSync } from "node:fs";
import { join } from "node:path";
import { PAGES, script } from "../../www/pages.js";
import { DOCUMENTS } from "../../scripts/documents.mjs";

const root = new URL("../../", import.meta.url).pathname;
const sorted = (/** @type {string[]} */ list) => [...list].sort();
const names = sorted(PAGES.map((page) => page.name));
const folders = (/** @type {string} */ dir) =>
  readdirSync(join(root, dir)).filter((entry) => statSync(join(root, dir, entry)).isDirectory());

test("every page on disk is in the registry, and every entry is on disk", () => {
  // www/: each folder with a descriptor is a page; the runtime, the examples and built files are not.
  const www = folders("www").filter((dir) => ["page.js", "page.html"].some((file) => existsSync(join(root, "www", dir, file))));
  assert.deepEqual(sorted(www), names, "www/<name>/ with page.js or page.html");
  for (const page of PAGES) {
    assert.ok(existsSync(join(root, "www", script(page))), `www/${script(page)}`);
    for (const file of ["state.js", "page.html", "style.css"]) {
      assert.ok(existsSync(join(root, "www", page.name, file)), `www/${page.name}/${file}`);
    }
  }
  // The pages' HTML at the top of www/ is built, at the addresses first published: none there is
  // a source (git tracks none), and none there is a page the registry does not name.
  const tracked = execFileSync("git", ["ls-files", "www/*.html"], { cwd: root, encoding: "utf8" }).split("\n")
    .filter((file) => file && !file.includes("/", "www/".length));
  assert.deepEqual(tracked, [], "www/*.html tracked by git");
  const html = readdirSync(join(root, "www")).filter((file) => file.endsWith(".html"));
  // The documents (docs/*.md rendered by scripts/documents.mjs) are the others written there.
  const addresses = [...PAGES.map((page) => page.html), ...DOCUMENTS.map((doc) => doc.html)];
  assert.deepEqual(html.filter((file) => !addresses.includes(file)), [], "www/*.html that no page or document has as its address");
  // crates/kli-demo/src/: a folder a page, named as the page.
  assert.deepEqual(sorted(folders("crates/kli-demo/src")), names, "crates/kli-demo/src/<name>/");
  // Its Cargo feature, `<name>-page`, and nothing else of that form.
  const cargo = readFileSync(join(root, "crates/kli-demo/Cargo.toml"), "utf8");
  const features = [...cargo.matchAll(/^([\w-]+)-page = /gm)].map(([, name]) => name);
  assert.deepEqual(sorted(features), names, "crates/kli-demo/Cargo.toml features");
  // The default features build every page.
  const defaults = /^default = \[(.*)\]$/m.exec(cargo)?.[1] ?? "";
  assert.deepEqual(sorted([...defaults.matchAll(/"([\w-]+)-page"/g)].map(([, name]) => name)), names, "default features");
});

test("each entry says what its page shows: views, canvases and a Save list that covers them", () => {
  for (const page of PAGES) {
    assert.ok(Object.keys(page.views).length > 0, `${page.name}: views`);
    const canvases = Object.keys(page.canvases);
    const saved = Object.keys(page.save);
    // Every canvas can be saved, in the order it is shown; then one kind of data.
    assert.deepEqual(saved.slice(0, canvases.length), canvases, `${page.name}: the Save list's views`);
    assert.equal(saved.length, canvases.length + 1, `${page.name}: one kind of data`);
    // Each <kli-figure> view is drawn by a view of the run that has a canvas on the page.
    for (const drawn of Object.values(page.views)) assert.ok(canvases.includes(drawn), `${page.name}: ${drawn}`);
    // A page's own views are in its HTML.
    const html = readFileSync(join(root, "www", page.name, "page.html"), "utf8");
    for (const selector of Object.values(page.canvases)) assert.match(html, new RegExp(`<canvas id="${selector.slice(1)}"`), `${page.name}/page.html ${selector}`);
  }
  // The <kli-figure> views are unique across pages.
  const views = PAGES.flatMap((page) => Object.keys(page.views));
  assert.equal(new Set(views).size, views.length, "a view belongs to one page");
});

test("each page's HTML is made from its folder and the registry (navigation, Save list, head)", () => {
  execFileSync("node", ["scripts/pages.mjs", "check"], { cwd: root, stdio: "pipe" });
});

test("every example page with the pages' navigation is in the registry's EXAMPLES, which writes it", async () => {
  const { EXAMPLES } = await import("../../www/pages.js");
  const folder = join(root, "www/examples");
  const withNav = readdirSync(folder).filter((file) => file.endsWith(".html"))
    .filter((file) => readFileSync(join(folder, file), "utf8").includes('<nav aria-label="Pages">'));
  assert.deepEqual(sorted(withNav.map((file) => `examples/${file}`)), sorted(EXAMPLES.map((e) => e.href)));
  // Each lists every page, the synchronisation page among them.
  for (const { href } of EXAMPLES) {
    const html = readFileSync(join(root, "www", href), "utf8");
    for (const page of PAGES) assert.ok(html.includes(`<a href="../${page.html}">${page.title}</a>`), `${href}: ${page.html}`);
  }
});

test("docs/architecture.md lists the registry's pages and the workspace's crates", () => {
  const doc = readFileSync(join(root, "docs/architecture.md"), "utf8");
  const section = (/** @type {string} */ heading) => {
    const start = doc.indexOf(`\n## ${heading}\n`);
    assert.ok(start >= 0, `a section "## ${heading}"`);
    const end = doc.indexOf("\n## ", start + 1);
    return doc.slice(start, end < 0 ? undefined : end);
  };
  const pages = [...section("The pages").matchAll(/^- `(\w+)` \(`([\w.]+)`\): (.+)$/gm)];
  assert.deepEqual(pages.map(([, name, html, title]) => [name, html, title]),
    PAGES.map((page) => [page.name, page.html, page.title]), "## The pages: - `name` (`html`): title, in the registry's order");
  const crates = [...section("The crates").matchAll(/^\| `([\w-]+)` /gm)].map(([, name]) => name);
  const members = /^members = \[(.*)\]$/m.exec(readFileSync(join(root, "Cargo.toml"), "utf8"))?.[1] ?? "";
  const published = [...members.matchAll(/"([^"]+)"/g)].map(([, path]) => path).filter((path) => path !== "bench/native");
  const crateNames = published.map((path) => {
    const toml = readFileSync(join(root, path, "Cargo.toml"), "utf8");
    return /^name = "([\w-]+)"$/m.exec(toml)?.[1];
  });
  assert.deepEqual(sorted(crates), sorted(/** @type {string[]} */ (crateNames)), "## The crates: a row a crate of the workspace");
});
