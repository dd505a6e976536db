// No link on the site leads nowhere: every address in every page's HTML (the registry's pages, the
// mathematics, the examples, the slides) names a file `make www` puts in www/, and every `#part`
// an element of the page it points to. Read from disk, as a static host would serve it: a 404 here
// is a 404 for a reader.
import { test } from "node:test";
import assert from "node:assert/strict";
import { existsSync, readFileSync, readdirSync, statSync } from "node:fs";
import { dirname, join, normalize, relative } from "node:path";
import { EXAMPLES, MORE_LINKS, PAGES } from "../../www/pages.js";

const www = new URL("../../www/", import.meta.url).pathname;
const SITE = [...PAGES.map((page) => page.html), ...MORE_LINKS.map((link) => link.href),
  ...EXAMPLES.map((example) => example.href), "examples/slides.html"];
/** Pages outside the navigation: one figure for an iframe (teach.html links it). */
const FRAMES = ["figure/index.html"];

/** Every `href` and `src` of `html`'s tags, outside scripts (whose text is code, not links; and
 *  markup shown as text, `&lt;script src=…`, is no tag). */
const addresses = (/** @type {string} */ html) =>
  [...html.replace(/(<script\b[^>]*>)[^]*?<\/script>/g, "$1").matchAll(/<[a-z][^>]*>/gi)]
    .flatMap(([tag]) => [...tag.matchAll(/\s(?:href|src)="([^"]*)"/g)].map((found) => found[1].replace(/&amp;/g, "&")));

/** The ids of `html`'s elements (and the names of its anchors). */
const ids = (/** @type {string} */ html) => new Set([...html.matchAll(/\s(?:id|name)="([^"]+)"/g)].map((found) => found[1]));

test("every page of the site is there, and every link on it names a file and a part that are", () => {
  const broken = [];
  let checked = 0;
  for (const page of [...SITE, ...FRAMES]) {
    const path = join(www, page);
    assert.ok(existsSync(path), `${page} is linked from the navigation but make www does not write it`);
    const html = readFileSync(path, "utf8");
    for (const address of addresses(html)) {
      if (/^(?:[a-z]+:|\/\/)/i.test(address)) continue; // another site, data:, mailto:
      const [file, part] = address.split("#");
      const name = file.split("?")[0];
      const target = name === "" ? path : normalize(join(dirname(path), name));
      checked += 1;
      if (!target.startsWith(www) || !existsSync(target)) {
        broken.push(`${page}: ${address} (no ${relative(www, target)})`);
        continue;
      }
      const isFolder = statSync(target).isDirectory();
      // A folder is served as its index.html, as static hosts do.
      if (isFolder && !existsSync(join(target, "index.html"))) {
        broken.push(`${page}: ${address} (a folder with no index.html)`);
        continue;
      }
      if (part && !isFolder && target.endsWith(".html") && !ids(readFileSync(target, "utf8")).has(decodeURIComponent(part))) {
        broken.push(`${page}: ${address} (no id "${part}" there)`);
      }
    }
  }
  assert.deepEqual(broken, [], `links that lead nowhere:\n${broken.join("\n")}`);
  assert.ok(checked > 100, `only ${checked} links checked: is the site built?`);
});

test("every page links to the tour and to the mathematics", () => {
  for (const page of SITE) {
    const html = readFileSync(join(www, page), "utf8");
    const here = page.startsWith("examples/") ? "../" : "";
    for (const wanted of [`${here}learn.html`, `${here}math.html`]) {
      assert.ok(addresses(html).some((address) => address.split("#")[0] === wanted) || page === wanted.replace("../", ""),
        `${page} has no link to ${wanted}`);
    }
  }
});

test("the check finds a broken link and a missing part (it can fail)", () => {
  const html = '<a href="nowhere.html">x</a><a href="#missing">y</a><script>const s = "<a href=\\"x\\">";</script>' +
    '<pre>&lt;script src="shown.js"&gt;</pre>';
  assert.deepEqual(addresses(html), ["nowhere.html", "#missing"]);
  assert.equal(ids('<p id="a"></p><a name="b"></a>').has("missing"), false);
  assert.ok(readdirSync(www).includes("math.html"));
});
