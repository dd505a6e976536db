// The tour in Bosnian (learn.html?lang=bs) in Debian's headless Chromium: <html lang="bs">, no
// English left on the page (no text and no aria-label, aria-valuetext or title holding a common
// English word, but in what is marked lang="en": the titles of works published in English), the
// live text and the sliders' values in Bosnian as they move, `lang=bs` kept in the URL the runtime
// rewrites and in the tour's links, the module drawing the Bosnian words, 390 px without
// overflow; and learn.html itself as it was: English, with no script too.
import { test } from "node:test";
import assert from "node:assert/strict";
import { readFileSync } from "node:fs";
import { join } from "node:path";
import { address, axeViolations, blank, keepShot, open, root, setup } from "./browser.mjs";
import * as bs from "../../www/learn/strings/bs.js";
import * as en from "../../www/learn/strings/en.js";
import { LEARN } from "../../www/learn/state.js";

setup();

/** Common English words, none of them a Bosnian word ("to", "a", "on", "one", "do", "no" are). */
const ENGLISH = ["the", "and", "of", "is", "with", "this", "that", "which", "from", "its", "are", "not", "when", "each",
  "turn", "turns", "turned", "at", "by", "for", "as", "it", "an", "or", "be", "but", "into", "than", "then", "there",
  "what", "where", "how", "has", "have", "was", "will", "can", "only", "two", "all", "every", "about", "after", "before",
  "below", "above", "here", "now", "same", "time", "point", "circle", "sphere", "angle", "axis", "nose", "wing", "roll",
  "bank", "pitch", "yaw", "drift", "answer", "guess", "set", "play", "pause", "save", "size", "link", "view", "page",
  "step", "steps", "along", "figure", "slider", "rotation", "rotations", "loading", "module", "frames", "second",
  "cancel", "your", "you", "we", "our", "they", "their", "would", "could", "should", "between", "through", "over",
  "under", "back", "start", "again", "once", "twice", "half", "quarter", "third", "great", "far", "near", "left", "right"];
const ENGLISH_WORD = new RegExp(`(^|[^\\p{L}])(${ENGLISH.join("|")})(?![\\p{L}])`, "iu");

/** Every piece of text on the page a reader or a screen reader meets, with where it is: text
 *  nodes (but scripts and styles), the title, the description, and the attributes read aloud;
 *  but what is marked lang="en" (a title of a work published in English). */
const pageText = (page) => page.evaluate(() => {
  const found = [["title", document.title], ["description", document.querySelector('meta[name="description"]')?.getAttribute("content") ?? ""]];
  const english = (/** @type {Element | null} */ element) => element?.closest("[lang]")?.getAttribute("lang") === "en";
  const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
  for (let node = walker.nextNode(); node; node = walker.nextNode()) {
    const parent = node.parentElement;
    if (!parent || parent.closest("script, style, noscript") || english(parent)) continue;
    if (node.textContent?.trim()) found.push([`${parent.tagName.toLowerCase()}#${parent.id}`, node.textContent.trim()]);
  }
  for (const element of document.body.querySelectorAll("*")) {
    if (english(element)) continue;
    for (const name of ["aria-label", "aria-valuetext", "aria-roledescription", "title", "label", "alt", "placeholder"]) {
      const value = element.getAttribute(name);
      if (value) found.push([`${element.tagName.toLowerCase()}#${element.id}[${name}]`, value]);
    }
  }
  return found;
});

/** Moves a slider as a reader does: its value, then an input event. */
const slide = (page, selector, value) => page.evaluate(([selector, value]) => {
  const input = /** @type {HTMLInputElement} */ (document.querySelector(selector));
  input.value = value;
  input.dispatchEvent(new Event("input", { bubbles: true }));
}, [selector, value]);

/** The pieces of `found` that hold an English word. */
const englishIn = (found) => found.filter(([, text]) => ENGLISH_WORD.test(text)).map(([where, text]) => `${where}: ${text}`);

test("learn.html?lang=bs is Bosnian from title to footer, and stays so as a slider moves", async () => {
  const { page, context, problems } = await open("learn.html?lang=bs");
  assert.equal(await page.getAttribute("html", "lang"), "bs");
  assert.equal(await page.evaluate(() => document.documentElement.classList.contains("translating")), false, "the page is shown");
  assert.equal(await page.title(), bs.page.title);
  // The other pages' figures loaded too: their labels come from the tour's strings.
  await page.locator("#many").scrollIntoViewIfNeeded();
  await page.waitForFunction(() => [...document.querySelectorAll("kli-figure")]
    .every((f) => f.shadowRoot?.querySelector("canvas")?.getAttribute("aria-label")), null, { timeout: 30000 });
  await page.evaluate(() => scrollTo(0, 0));
  const found = await pageText(page);
  assert.ok(found.length > 300, `${found.length} pieces of text`);
  assert.deepEqual(englishIn(found), [], "English on the Bosnian page");
  // Every piece of the article is the Bosnian one.
  assert.equal((await page.textContent("#care-title")).trim(), "1 Zašto je s rotacijama potreban oprez");
  assert.equal(await page.textContent("#play"), "Pusti");
  assert.equal(await page.getAttribute("[name=angle]", "aria-valuetext"), "90° oko z");
  assert.equal((await page.textContent("#save-title")).trim(), "Sačuvaj");
  assert.equal(await page.getAttribute('#save button[data-save="euler"][data-format="png"]', "aria-label"), "slika Eulerovih uglova kao PNG");
  // The glossary in Bosnian alphabetical order, each term with its definition.
  const terms = await page.$$eval("#glossary dt", (all) => all.map((dt) => dt.textContent ?? ""));
  assert.deepEqual(terms, [...terms].sort((a, b) => a.localeCompare(b, "bs")));
  assert.equal(await page.$eval("#g-fibre + dd a", (a) => a.getAttribute("href")), "#def-fibre");
  // The exercises' links keep the language.
  assert.equal(await page.getAttribute('#care a.set', "href"), "?pitch=90&lang=bs#care");
  // A slider moved: its value, the text that quotes it and the URL, all still Bosnian.
  await slide(page, "[name=pitch]", "60");
  await page.waitForFunction(() => document.querySelector("#lock-out")?.textContent === "30.0°");
  assert.equal(await page.textContent("#pitch-value"), "propinjanje 60°");
  assert.equal(await page.getAttribute("[name=pitch]", "aria-valuetext"), "propinjanje 60°");
  await slide(page, "[name=s]", "0.25");
  await page.waitForFunction(() => /^Pri s = 0\.25 SLERP je 15\.00° duž luka, NLERP 13\.90°\.$/.test(document.querySelector("#slerp-out")?.textContent ?? ""));
  await page.locator("[name=axis]").selectOption("diagonal");
  await page.waitForFunction(() => document.querySelector("[name=angle]")?.getAttribute("aria-valuetext") === "90° oko dijagonale (1, 1, 1)");
  await page.waitForFunction(() => /[?&]pitch=60(&|$)/.test(location.search) && /[?&]s=0\.25(&|$)/.test(location.search), null, { timeout: 5000 });
  assert.match(await page.evaluate(() => location.search), /[?&]lang=bs(&|$)/);
  assert.match(await page.getAttribute("#share", "href"), /[?&]lang=bs(&|$)/);
  // The clock moved: the readouts and the figures' labels once it rests.
  await slide(page, "#time", "2");
  await page.waitForFunction(() => (document.querySelector("#phases-out")?.textContent ?? "").startsWith("Pri t = 2.00"));
  assert.match(await page.getAttribute("#time", "aria-valuetext"), /^t = 2\.00 od /);
  assert.match(await page.getAttribute("#learn-steps", "aria-label"), /^Udaljenost Algoritma 1/);
  assert.deepEqual(englishIn(await pageText(page)), [], "English on the Bosnian page after the changes");
  assert.deepEqual(await axeViolations(page), []);
  // The switch to English keeps the state, in English.
  await Promise.all([page.waitForURL(/learn\.html\?/), page.click('nav.languages a[hreflang="en"]')]);
  await page.waitForFunction(() => document.querySelector("#load-status")?.hidden);
  assert.doesNotMatch(page.url(), /lang=/);
  assert.match(page.url(), /pitch=60/);
  assert.equal(await page.getAttribute("html", "lang"), "en");
  assert.equal(await page.textContent("#pitch-value"), "60° pitch");
  assert.deepEqual(problems, []);
  await context.close();
});

test("?lang=bs: the values of the URL the tour refuses are refused in Bosnian, beside their fields", async () => {
  const { page, context, problems } = await open("learn.html?lang=bs&axis=w&int=foo&digits=2.5&yaw=999&h=abc");
  const errors = Object.fromEntries(await page.$$eval(".field-error", (all) => all.map((o) => [o.id, o.textContent ?? ""]).filter(([, t]) => t)));
  assert.deepEqual(Object.keys(errors).sort(), ["axis-error", "digits-error", "integrator-error", "step-error", "yaw-error"]);
  assert.equal(errors["axis-error"], 'osa mora biti x, y, z ili diagonal (dato je "w")');
  assert.equal(errors["step-error"], "Korak h: mora biti broj od 0.01 do 1 (dato je NaN)");
  assert.equal(errors["yaw-error"], "Skretanje: mora biti broj od -180 do 180 (dato je 999)");
  assert.deepEqual(englishIn(Object.entries(errors)), []);
  assert.deepEqual(problems, []);
  await context.close();
});

test("learn.html is English as it was, with no script too; ?lang=bs with no script is English and shown", async () => {
  const { page, context, problems } = await open("learn.html");
  assert.equal(await page.getAttribute("html", "lang"), "en");
  assert.equal(await page.title(), en.page.title);
  assert.equal((await page.textContent("#care-title")).trim(), "1 Why rotations need care");
  assert.equal(await page.textContent("#play"), "Play");
  assert.equal(await page.getAttribute("#care a.set", "href"), "?pitch=90#care");
  assert.equal(await page.getAttribute('nav.languages a[aria-current]', "hreflang"), "en");
  assert.deepEqual(problems, []);
  await context.close();
  // Without script: the English of the HTML, never hidden.
  const still = await blank({ javaScriptEnabled: false });
  await still.page.goto(`${address()}/learn.html?lang=bs`);
  assert.equal(await still.page.getAttribute("html", "lang"), "en");
  assert.equal(await still.page.evaluate(() => getComputedStyle(document.body).visibility), "visible");
  assert.equal((await still.page.textContent("#care-title")).trim(), "1 Why rotations need care");
  await still.context.close();
});

test("the module draws the tour's words in the language given (every view, no English word left)", async () => {
  const module = await import(join(root, "www/pkg/learn_demo.js"));
  module.initSync({ module: readFileSync(join(root, "www/pkg/learn_demo_bg.wasm")) });
  const [azimuth, elevation] = module.defaultCamera();
  const views = ["euler", "turn", "cover", "slerp", "hopf", "rolled", "phases", "lohe", "kli", "clock", "steps", "drift", "rates"];
  const drawn = (words, state = {}) => {
    const run = new module.LearnDemo({ ...LEARN.defaults, ...state, words });
    const text = views.map((view) => run.toSvg(view, { width: 600, height: 360, pixelRatio: 1, t: 2, azimuth, elevation, textScale: 1 }))
      .join("\n").match(/<text[^>]*>[^<]*<\/text>/g).map((t) => t.replace(/<[^>]+>/g, ""));
    run.free();
    return text;
  };
  for (const state of [{}, { pitch: 90, axis: "diagonal", integrator: "geodesic", smoothness: 0 }]) {
    const words = drawn(bs.canvas, state);
    assert.ok(words.some((w) => w.includes("skretanje")), words.join(" | "));
    const english = words.filter((w) => ENGLISH_WORD.test(w));
    assert.deepEqual(english, [], `English drawn with the Bosnian words (${JSON.stringify(state)})`);
    // With none given, or the English, the module draws as it always did.
    assert.deepEqual(drawn(en.canvas, state), drawn(undefined, state));
  }
});

test("390 px in both languages: nothing overflows", async () => {
  for (const lang of ["en", "bs"]) {
    const { page, context, problems } = await open(`learn.html${lang === "bs" ? "?lang=bs" : ""}`,
      { viewport: { width: 390, height: 844 } });
    assert.ok(await page.evaluate(() => document.documentElement.scrollWidth <= 390), `${lang}: no horizontal scrolling`);
    // No element of the text wider than the screen (a long Bosnian word in a narrow box).
    const wide = await page.evaluate(() => [...document.querySelectorAll("main *, header *, footer *")]
      .filter((e) => e.getBoundingClientRect().right > 390.5 && getComputedStyle(e).position !== "fixed" && !e.closest(".equation"))
      .map((e) => `${e.tagName}#${e.id}.${e.className}`));
    assert.deepEqual(wide, [], `${lang}: past the right edge`);
    // The language switch does not cover the title.
    const [languages, title] = await Promise.all(["nav.languages", "h1"].map((s) => page.locator(s).boundingBox()));
    assert.ok(languages.y + languages.height <= title.y + 8, `${lang}: the switch over the title`);
    await keepShot(page, `learn-390px-${lang}.png`);
    assert.deepEqual(problems, []);
    await context.close();
  }
});
