// @ts-check
// Finding the page's elements, typed: a missing or mistyped element fails loudly at start-up.

/**
 * The element `selector` finds, checked to be a `type`.
 * @template {Element} T
 * @param {string} selector
 * @param {{ new (): T }} type
 * @returns {T}
 */
export function $(selector, type) {
  const element = document.querySelector(selector);
  if (!(element instanceof type)) throw new Error(`the page has no ${type.name} ${selector}`);
  return element;
}

/**
 * `english` in the page's language: its entry in `words` (a page's words, keyed by their English;
 * none on an English page), each `{name}` filled from `values`.
 * @param {Readonly<Record<string, string>> | undefined} words
 * @param {string} english
 * @param {Record<string, string | number>} [values]
 */
export function say(words, english, values = {}) {
  return (words?.[english] ?? english).replace(/\{(\w+)\}/g, (all, name) => (Object.hasOwn(values, name) ? String(values[name]) : all));
}
