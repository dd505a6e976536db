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

/**
 * Calls `start` once, when `element` comes within `margin` of the screen or the page is printed,
 * whichever is first: work a reader far from the element never sees waits until they near it
 * (a page's load stays short), and paper never gets a figure that was not started.
 * @param {Element} element
 * @param {() => void} start
 * @param {string} [margin] how far off screen counts as near (CSS, as IntersectionObserver's rootMargin)
 */
export function whenNear(element, start, margin = "600px") {
  const print = matchMedia("print");
  let started = false;
  const go = () => {
    if (started) return;
    started = true;
    observer.disconnect();
    removeEventListener("beforeprint", go);
    print.removeEventListener("change", onPrint);
    start();
  };
  const onPrint = () => print.matches && go();
  const observer = new IntersectionObserver((entries) => entries.some((entry) => entry.isIntersecting) && go(), { rootMargin: margin });
  observer.observe(element);
  addEventListener("beforeprint", go);
  print.addEventListener("change", onPrint);
}
