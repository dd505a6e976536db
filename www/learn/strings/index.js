// @ts-check
// The tour's language: English, or Bosnian with `?lang=bs` (the authors' own), kept in the URL
// (the runtime writes `lang` back as it rewrites the address; the exercises' links and the
// language switch carry it). learn.html is written in English (scripts/pages.mjs fills page.html
// from en.js), so with no script, in print and before the bundle runs the page is English, as it
// always was; with `?lang=bs`, page.html's first script hides the page until `translate` below
// has put the Bosnian in place, in the bundle's first task, before the runtime reads the page.
// Both files are in the bundle (the Bosnian some 17 KB gzipped): a module of its own would be one
// more request before the Bosnian page shows, and one more file for the single-file copy and the
// offline list. English needs only en.js's `live`, `canvas` and `runtime` (its `page` is in the
// HTML already, and is left out of the bundle).
import { canvas as enCanvas, live as enLive, runtime as enRuntime } from "./en.js";
import * as bs from "./bs.js";

/**
 * One language's text: en.js and bs.js each export these four, with the same keys.
 * @typedef {object} Strings
 * @property {Record<string, string>} [page] each piece of the article by its key in page.html (HTML)
 * @property {typeof enLive} live the text page.js writes as the figures change
 * @property {typeof enCanvas} canvas the words the module draws on the figures
 * @property {Record<string, string>} runtime the shared runtime's words, by their English
 */

/** The languages, by their `lang` code. */
export const LANGUAGES = /** @type {const} */ (["en", "bs"]);

/** The language the URL asks for: `?lang=bs`, else English. */
export const lang = new URLSearchParams(location.search).get("lang") === "bs" ? "bs" : "en";

/** @type {Strings} */
export const strings = lang === "bs" ? bs : { live: enLive, canvas: enCanvas, runtime: enRuntime };

/** `search` (a URL's query) with the page's language: `lang=bs`, or none for English. */
export function withLang(/** @type {string} */ search, /** @type {string} */ language = lang) {
  const query = new URLSearchParams(search);
  if (language === "en") query.delete("lang");
  else query.set("lang", language);
  const text = query.toString();
  return text ? `?${text}` : "?";
}

/**
 * Puts the language's text in place: every element marked `data-i18n="key"` gets the piece of that
 * key, every `data-i18n-<attribute>="key"` that attribute; the title, the description and the parts
 * the shared page writes (the navigation, the Save section's list, the load status) by their
 * English; the first pictures (drawn in English) go; the exercises' links keep `lang`. Then shows
 * the page (page.html hid it).
 * @param {Strings} text
 * @param {import("../../pages.js").Page} entry the tour's entry in the registry (its Save list)
 */
export function translate(text, entry) {
  const root = document.documentElement;
  const page = text.page;
  if (page) {
    root.lang = lang;
    // A piece the language lacks stays English, and says so in the console (the tests fail on both).
    const piece = (/** @type {string} */ key, /** @type {string} */ english) => {
      if (Object.hasOwn(page, key)) return page[key];
      console.error(`learn: no text for ${key} in ${lang}`);
      return english;
    };
    document.title = piece("title", document.title);
    const description = document.querySelector('meta[name="description"]');
    description?.setAttribute("content", piece("description", description.getAttribute("content") ?? ""));
    for (const element of document.querySelectorAll("[data-i18n]")) {
      element.innerHTML = piece(/** @type {HTMLElement} */ (element).dataset.i18n ?? "", element.innerHTML);
    }
    for (const element of document.querySelectorAll("*")) {
      for (const { name, value } of [...element.attributes]) {
        if (!name.startsWith("data-i18n-")) continue;
        const attribute = name.slice("data-i18n-".length);
        element.setAttribute(attribute, piece(value, element.getAttribute(attribute) ?? ""));
      }
    }
    // The parts the shared page writes (scripts/pages.mjs), by their English.
    const say = (/** @type {string} */ english) => text.runtime[english] ?? english;
    for (const link of document.querySelectorAll('nav[aria-label="Pages"] a')) link.textContent = say(link.textContent ?? "");
    document.querySelector('nav[aria-label="Pages"]')?.setAttribute("aria-label", say("Pages"));
    const load = document.getElementById("load-status");
    if (load?.textContent) load.textContent = say(load.textContent);
    const title = document.getElementById("save-title");
    if (title) title.textContent = say("Save");
    const intro = title?.nextElementSibling;
    if (intro instanceof HTMLParagraphElement) intro.innerHTML = piece("save.intro", intro.innerHTML);
    for (const item of document.querySelectorAll("#save li")) {
      const button = item.querySelector("button[data-save]");
      const what = button instanceof HTMLElement ? button.dataset.save ?? "" : "";
      const [label, noun] = entry.save[what] ?? ["", ""];
      if (item.firstChild?.nodeType === Node.TEXT_NODE) item.firstChild.textContent = `${say(label)} `;
      for (const format of item.querySelectorAll("button[data-save]")) {
        const kind = /** @type {HTMLElement} */ (format).dataset.format?.toUpperCase() ?? "";
        format.setAttribute("aria-label", (text.runtime["{noun} as {format}"] ?? "").replace("{noun}", say(noun)).replace("{format}", kind));
      }
    }
    // The glossary in the language's alphabetical order (each term with its definition).
    const glossary = document.querySelector("#glossary dl");
    if (glossary) {
      const terms = [...glossary.querySelectorAll("dt")].map((dt) => ({ dt, dd: dt.nextElementSibling }));
      terms.sort((a, b) => (a.dt.textContent ?? "").localeCompare(b.dt.textContent ?? "", lang));
      for (const { dt, dd } of terms) glossary.append(dt, ...(dd ? [dd] : []));
    }
    // The first pictures were drawn with the English words (at build time, scripts/first-pictures.mjs):
    // they go, as the runtime's do when the URL asks for another state, and each figure shows once
    // the module has drawn it in this language.
    document.querySelectorAll(".first-picture").forEach((picture) => picture.remove());
    // Within the tour, the links keep the language.
    for (const link of document.querySelectorAll("a.set")) {
      const a = /** @type {HTMLAnchorElement} */ (link);
      const [search, hash = ""] = (a.getAttribute("href") ?? "").split("#");
      a.setAttribute("href", `${withLang(search)}${hash ? `#${hash}` : ""}`);
    }
  }
  // The language switch: each link keeps the state of the URL, in its own language.
  for (const link of document.querySelectorAll("nav.languages a")) {
    const a = /** @type {HTMLAnchorElement} */ (link);
    if (a.hreflang === lang) a.setAttribute("aria-current", "true");
    else a.removeAttribute("aria-current");
    a.addEventListener("click", () => (a.href = `learn.html${withLang(location.search, a.hreflang)}${location.hash}`));
  }
  root.classList.remove("translating");
}
