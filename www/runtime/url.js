// @ts-check
// Writing the page's state into the URL. Each page's schema (schema.js, in the page's descriptor)
// says which URL key holds which part of the state.

/**
 * `history.replaceState` at most once per `interval` ms, the last search winning: browsers
 * throttle navigation calls, and a long slider drag would otherwise trip them.
 * @param {(search: string) => void} [onWrite] told of each search written
 */
export function throttledUrl(interval = 400, onWrite = () => {}) {
  let pending = /** @type {string | null} */ (null);
  let timer = 0;
  let last = -Infinity;
  const flush = () => {
    timer = 0;
    if (pending === null) return;
    if (pending !== location.search) history.replaceState(null, "", pending);
    onWrite(pending);
    pending = null;
    last = performance.now();
  };
  return (/** @type {string} */ search) => {
    pending = search;
    if (timer) return;
    timer = setTimeout(flush, Math.max(0, last + interval - performance.now()));
  };
}
