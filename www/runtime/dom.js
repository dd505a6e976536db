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
