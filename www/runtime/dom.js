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
 * Calls `start` once, when `element` comes within `margin` of the screen, the page is printed, or
 * `after` milliseconds have passed, whichever is first: work for a part of the page far from the
 * reader waits until they near it or the page has long finished loading (its load stays short),
 * and a page printed later holds the finished figure.
 * @param {Element} element
 * @param {() => void} start
 * @param {{ margin?: string, after?: number }} [when] how far off screen counts as near (CSS, as
 *   IntersectionObserver's rootMargin; 600px), and the time after which to start anyway (none)
 */
export function whenNear(element, start, { margin = "600px", after = Infinity } = {}) {
  const print = matchMedia("print");
  let started = false;
  const timer = Number.isFinite(after) ? setTimeout(() => go(), after) : undefined;
  const go = () => {
    if (started) return;
    started = true;
    clearTimeout(timer);
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
