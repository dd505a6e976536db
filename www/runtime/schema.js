// @ts-check
// A page's state between its form, the URL and the module, from one schema: each key of the
// state with its URL key and its kind. Texts only become numbers (NaN where they are not one),
// lists or words here; checking them is the module's job, so that a value refused in the URL is
// named exactly as one typed into the form. Values are never written into the page as HTML.

import { formatNumber, parseNumber } from "./numbers.js";

/**
 * - `number`: an input (text or range); `?eps=1e-5`
 * - `word`: a select; `?int=rk4`
 * - `flag`: a checkbox; `?short=1` (`0` or `false` for off)
 * - `quaternion`: four inputs `<key>-w` … `<key>-z`; `?p=0,0,0,1`
 * - `quaternions`: one input `w,x,y,z; …`; `?keys=1,0,0,0;0.8,0.6,0,0`
 * - `numbers`: one input `a,b,c`; `?times=0,1,2` (absent when empty)
 * @typedef {"number" | "word" | "flag" | "quaternion" | "quaternions" | "numbers"} Kind
 */

/**
 * @typedef {object} Entry
 * @property {string} key the state's key, the JavaScript API's name, and the form field's name
 * @property {string} url the URL's key
 * @property {Kind} kind
 * @property {{ flag: string, shown: number }} [optional] a checkbox (`flag`) that, checked,
 *   leaves the key out of the state; `shown` fills the field meanwhile
 * @property {readonly [number, number]} [range] a number's bounds on its page (its slider's, set
 *   from here) and in <kli-figure>: each keeps its work within a frame
 */

const COMPONENTS = ["w", "x", "y", "z"];
const quaternionText = (/** @type {ArrayLike<number>} */ q) => Array.from(q, formatNumber).join(",");

/** Text to value, for every kind: from the URL and from the form alike. */
const PARSE = {
  number: parseNumber,
  word: (/** @type {string} */ text) => text,
  flag: (/** @type {string} */ text) => !["0", "false"].includes(text),
  quaternion: (/** @type {string} */ text) => text.split(",").map(parseNumber),
  quaternions: (/** @type {string} */ text) => text.split(";").filter((k) => k.trim()).map((k) => k.split(",").map(parseNumber)),
  numbers: (/** @type {string} */ text) => (text.trim() ? text.split(",").map(parseNumber) : []),
};

/** A text (from the URL, the form or an element's attribute) as a value of `kind`. */
export const parseText = (/** @type {Kind} */ kind, /** @type {string} */ text) => PARSE[kind](text);

/** Value to the URL's text (undefined: left out). */
const URL_TEXT = {
  number: (/** @type {number} */ x) => String(x),
  word: (/** @type {string} */ word) => word,
  flag: (/** @type {boolean} */ on) => (on ? "1" : "0"),
  quaternion: quaternionText,
  quaternions: (/** @type {number[][]} */ keys) => keys.map(quaternionText).join(";"),
  numbers: (/** @type {number[]} */ xs) => (xs.length ? xs.map(formatNumber).join(",") : undefined),
};

/**
 * @template {Record<string, any>} State
 */
export class Schema {
  /**
   * @param {readonly Entry[]} entries
   * @param {HTMLFormElement} form
   */
  constructor(entries, form) {
    this.entries = entries;
    this.form = form;
    for (const { key, range } of entries) {
      const [field] = range ? this.fields(key) : [];
      if (range && field instanceof HTMLInputElement && field.type === "range") [field.min, field.max] = range.map(String);
    }
  }

  /** The form's element named `name`. */
  field(/** @type {string} */ name) {
    const field = this.form.elements.namedItem(name);
    if (!(field instanceof HTMLInputElement || field instanceof HTMLSelectElement)) throw new Error(`no field ${name}`);
    return field;
  }

  /** The fields of a key (a quaternion's four). */
  fields(/** @type {string} */ key) {
    const entry = this.entries.find((e) => e.key === key);
    if (!entry) return [];
    return entry.kind === "quaternion" ? COMPONENTS.map((c) => this.field(`${key}-${c}`)) : [this.field(key)];
  }

  /** The form as a candidate state. @returns {State} */
  read() {
    /** @type {Record<string, any>} */
    const state = {};
    for (const { key, kind, optional } of this.entries) {
      if (optional && /** @type {HTMLInputElement} */ (this.field(optional.flag)).checked) continue;
      const fields = this.fields(key);
      if (kind === "quaternion") state[key] = fields.map((f) => parseNumber(f.value));
      else if (kind === "flag") state[key] = /** @type {HTMLInputElement} */ (fields[0]).checked;
      else state[key] = PARSE[kind](fields[0].value);
    }
    return /** @type {State} */ (state);
  }

  /** Fills the form with `state`. */
  fill(/** @type {State} */ state) {
    for (const { key, kind, optional } of this.entries) {
      const value = state[key];
      const fields = this.fields(key);
      if (optional) {
        /** @type {HTMLInputElement} */ (this.field(optional.flag)).checked = value === undefined;
        fields[0].value = String(value ?? optional.shown);
      } else if (kind === "quaternion") fields.forEach((f, i) => (f.value = formatNumber(value[i])));
      else if (kind === "flag") /** @type {HTMLInputElement} */ (fields[0]).checked = value;
      else if (kind === "quaternions") fields[0].value = value.map(quaternionText).join("; ");
      else if (kind === "numbers") fields[0].value = value.map(formatNumber).join(",");
      else fields[0].value = String(value);
    }
  }

  /**
   * The URL's state over `defaults`, and the texts the URL gave for each key it set (to show a
   * refused text in its field, for mending).
   * @param {string} search `location.search`
   * @param {State} defaults
   * @param {Record<string, string>} [aliases] old URL keys still read: old key → new key
   */
  fromUrl(search, defaults, aliases = {}) {
    const query = new URLSearchParams(search);
    for (const [old, key] of Object.entries(aliases)) if (query.has(old) && !query.has(key)) query.set(key, query.get(old) ?? "");
    /** @type {Record<string, any>} */
    const state = { ...defaults };
    /** @type {Record<string, string>} */
    const texts = {};
    for (const { key, url, kind } of this.entries) {
      const text = query.get(url);
      if (text === null) continue;
      state[key] = PARSE[kind](text);
      texts[key] = text;
    }
    return { state: /** @type {State} */ (state), texts, query };
  }

  /**
   * Puts the URL's own texts back into the text fields: a number as it was written ("1e-4"), and
   * a refused list or quaternion, to mend (a slider or a select cannot hold a text).
   * @param {Record<string, string>} texts what the URL gave, by key (see `fromUrl`)
   * @param {(string | undefined)[]} refused the keys the module refused
   */
  keepTexts(texts, refused) {
    for (const { key, kind } of this.entries) {
      const text = texts[key];
      if (text === undefined) continue;
      const fields = this.fields(key);
      if (kind === "number" && fields[0].type !== "range") fields[0].value = text;
      else if (kind === "quaternion" && refused.includes(key)) fields.forEach((field, i) => (field.value = text.split(",")[i] ?? ""));
      else if ((kind === "quaternions" || kind === "numbers") && refused.includes(key)) fields[0].value = text;
    }
  }

  /**
   * The numbers of `state` outside their slider's range: a URL may ask for any number, but the
   * page takes what its sliders take (a swarm of 10⁶ would block the page for seconds).
   * @param {State} state
   * @returns {{ key: string, min: number, max: number, value: number }[]}
   */
  outOfRange(state) {
    return outOfRange(this.entries, state);
  }

  /**
   * The URL's query for `state`, then `extra` (already texts; undefined left out).
   * @param {State} state
   * @param {Record<string, string | undefined>} [extra]
   */
  toUrl(state, extra = {}) {
    const query = new URLSearchParams();
    for (const { key, url, kind } of this.entries) {
      if (state[key] === undefined) continue;
      const text = /** @type {(value: any) => string | undefined} */ (URL_TEXT[kind])(state[key]);
      if (text !== undefined) query.set(url, text);
    }
    for (const [key, text] of Object.entries(extra)) if (text !== undefined) query.set(key, text);
    return "?" + query.toString();
  }
}

/**
 * The numbers of `state` beyond their entry's range.
 * @param {readonly Entry[]} entries
 * @param {Record<string, any>} state
 * @returns {{ key: string, min: number, max: number, value: number }[]}
 */
export function outOfRange(entries, state) {
  return entries.flatMap(({ key, range }) => {
    const value = state[key];
    if (!range || typeof value !== "number" || !Number.isFinite(value)) return [];
    const [min, max] = range;
    return value < min || value > max ? [{ key, min, max, value }] : [];
  });
}
