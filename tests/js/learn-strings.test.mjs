// The tour's text in its two languages (www/learn/strings/en.js and bs.js): the same keys in both,
// none empty, the same markup in each piece (ids, links, classes and tags: only the words are
// translated), the same `{name}` slots in each template, and every piece placed: each key of the
// article is where www/learn/page.html puts one, and the module's words are the ones
// crates/kli-demo/src/learn/words.rs reads.
import { test } from "node:test";
import assert from "node:assert/strict";
import { readFileSync } from "node:fs";
import * as en from "../../www/learn/strings/en.js";
import * as bs from "../../www/learn/strings/bs.js";

const root = new URL("../../", import.meta.url);
const LANGUAGES = { en, bs };
const PARTS = ["page", "live", "canvas", "runtime"];

/** Every leaf of a strings object by its dotted path: strings and functions. */
function leaves(value, path = "") {
  if (typeof value === "string" || typeof value === "function") return [[path, value]];
  assert.equal(typeof value, "object", `${path}: neither text, a function nor a table`);
  return Object.entries(value).flatMap(([key, inner]) => leaves(inner, path ? `${path}.${key}` : key));
}

/** A function's text for sample arguments: each argument a word, or a record of words. */
const sample = (f) => f(new Proxy({}, {
  get: (_, name) => (name === Symbol.toPrimitive ? () => "‹1›" : `‹${String(name)}›`),
}), "‹2›");

test("the two languages have exactly the same keys, and no value is empty", () => {
  for (const part of PARTS) {
    const [english, bosnian] = [en, bs].map((strings) => leaves(strings[part]));
    const keys = (list) => list.map(([key]) => key).sort();
    assert.deepEqual(keys(bosnian), keys(english), `${part}: keys differ between en.js and bs.js`);
    for (const [lang, list] of [["en", english], ["bs", bosnian]]) {
      for (const [key, value] of list) {
        const text = typeof value === "function" ? sample(value) : value;
        assert.ok(typeof text === "string" && text.trim().length > 0, `${lang}: ${part}.${key} is empty`);
      }
    }
  }
});

test("each piece has the same markup in both languages (ids, links, classes, tags), only the words differ", () => {
  // A title of a work published in English is marked so in Bosnian (<span lang="en">).
  const markup = (html) => [...html.replace(/<span lang="en">([^]*?)<\/span>/g, "$1").matchAll(/<\/?([a-z]+)|\s(id|href|class|data-[a-z-]+)="([^"]*)"|\s(data-[a-z-]+)='([^']*)'/g)]
    .map((m) => m[1] ?? `${m[2] ?? m[4]}=${m[3] ?? m[5]}`).sort();
  for (const [key, english] of Object.entries(en.page)) {
    assert.deepEqual(markup(bs.page[key]), markup(english), `page.${key}`);
  }
  // The text that goes into an attribute has no markup and no quote.
  for (const [lang, strings] of Object.entries(LANGUAGES)) {
    for (const [key, text] of Object.entries(strings.page)) {
      if (/\.(aria|role|figure|valuetext)\d+$|^(title|description|languages\.aria)$/.test(key)) {
        assert.doesNotMatch(text, /["<>&]/, `${lang}: page.${key} goes into an attribute`);
      }
    }
  }
});

test("each template has the same {name} slots in both languages", () => {
  const slots = (text) => [...text.matchAll(/\{(\w+)\}/g)].map((m) => m[1]).sort();
  for (const part of ["canvas", "runtime"]) {
    for (const [key, english] of Object.entries(en[part])) {
      assert.deepEqual(slots(bs[part][key]), slots(english), `${part}.${key}`);
    }
  }
  for (const [key, english] of leaves(en.live)) {
    const bosnian = leaves(bs.live).find(([other]) => other === key)[1];
    if (typeof english !== "function") continue;
    const values = (text) => [...text.matchAll(/‹(\w+)›/g)].map((m) => m[1]).sort();
    assert.deepEqual(values(sample(bosnian)), values(sample(english)), `live.${key} quotes the same values`);
  }
  // The English runtime words are their own keys.
  for (const [key, text] of Object.entries(en.runtime)) assert.equal(text, key);
});

test("every piece of the article has its place in page.html, and every place its piece", () => {
  const html = readFileSync(new URL("www/learn/page.html", root), "utf8");
  const placed = [...html.matchAll(/\{\{([\w.-]+)\}\}/g)].map((m) => m[1]);
  assert.deepEqual([...new Set(placed)].sort(), Object.keys(en.page).sort());
  // The runtime finds each again by its mark (data-i18n, or data-i18n-<attribute>), but for the title,
  // the description and the Save section's sentence, which it finds by where they are.
  const marked = [...html.matchAll(/\sdata-i18n(?:-[a-z-]+)?="([\w.-]+)"/g)].map((m) => m[1]);
  const unmarked = Object.keys(en.page).filter((key) => !marked.includes(key)).sort();
  assert.deepEqual(unmarked, ["description", "save.intro", "title"]);
});

test("the module's words are the ones it reads (crates/kli-demo/src/learn/words.rs), English its own", () => {
  const rust = readFileSync(new URL("crates/kli-demo/src/learn/words.rs", root), "utf8");
  const table = rust.slice(rust.indexOf("words! {"));
  const words = Object.fromEntries([...table.matchAll(/^\s+\w+ "(\w+)" "([^"]*)",$/gm)].map((m) => [m[1], m[2]]));
  assert.deepEqual(Object.keys(en.canvas).sort(), Object.keys(words).sort());
  assert.deepEqual(en.canvas, Object.fromEntries(Object.keys(en.canvas).map((key) => [key, words[key]])));
});
