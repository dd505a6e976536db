// @ts-check
// The page's state in the URL. The page, its form and the JavaScript API all name the options
// alike (tolerance, step, integrator, shortestPath); URL_KEYS is the one place where the URL's
// short keys are defined. Values are only ever parsed as numbers or one of a fixed set of words,
// and written into form fields' values, never into the page as HTML.

import { formatNumber, parseNumber } from "./numbers.js";

/** The URL key of each piece of state: `?p=0,0,0,1&r=…&eps=1e-5&step=0.01&int=rk4&short=1&t=2`. */
export const URL_KEYS = Object.freeze({
  p: "p",
  r: "r",
  tolerance: "eps",
  step: "step",
  integrator: "int",
  shortestPath: "short",
  t: "t",
  embed: "embed",
});

/** The swarm page's URL keys (`swarm.html?K=1&n=500&graph=all&w=0.5&spread=0.4&seed=3`): the
 *  LoheSwarm options by their short keys; `spread` absent means a uniform start. */
export const SWARM_URL_KEYS = Object.freeze({
  coupling: "K",
  count: "n",
  graph: "graph",
  leaders: "leaders",
  frequencySpread: "w",
  startSpread: "spread",
  seed: "seed",
  embed: "embed",
});

/** The keyframes page's URL keys (`keyframes.html?keys=1,0,0,0;0.8,0.6,0,0;…&times=0,1,2&s=1`):
 *  keys as quaternions separated by ";", their times, and the chain's smoothness. */
export const KEYFRAMES_URL_KEYS = Object.freeze({ keys: "keys", times: "times", smoothness: "s", embed: "embed" });

export const INTEGRATORS = /** @type {const} */ (["rk4", "euler", "geodesic"]);

/**
 * What the URL asks for, as texts for the form to read like typed input.
 * @typedef {object} Query
 * @property {string[]} [p] the texts of p's components
 * @property {string[]} [r]
 * @property {string} [tolerance]
 * @property {string} [step]
 * @property {import("./pkg/kli_demo.js").Integrator} [integrator]
 * @property {boolean} [shortestPath]
 * @property {number} [t] the time to show, paused; absent while playing
 * @property {boolean} embed
 */

/**
 * @param {string} search `location.search`
 * @returns {Query}
 */
export function readQuery(search) {
  const query = new URLSearchParams(search);
  const get = (/** @type {keyof typeof URL_KEYS} */ name) => query.get(URL_KEYS[name]) ?? undefined;
  const integrator = INTEGRATORS.find((name) => name === get("integrator"));
  const shortest = get("shortestPath");
  const t = get("t");
  return {
    p: get("p")?.split(","),
    r: get("r")?.split(","),
    tolerance: get("tolerance"),
    step: get("step"),
    integrator,
    shortestPath: shortest === undefined ? undefined : !["0", "false"].includes(shortest),
    t: t === undefined ? undefined : parseNumber(t),
    embed: get("embed") === "1",
  };
}

/**
 * The query string of a state; `t` only when given (the page gives it while paused).
 * @param {import("./form.js").State} state
 * @param {{ t?: number, embed?: boolean }} extra
 */
export function writeQuery(state, { t, embed } = {}) {
  const query = new URLSearchParams();
  query.set(URL_KEYS.p, state.p.map(formatNumber).join(","));
  query.set(URL_KEYS.r, state.r.map(formatNumber).join(","));
  query.set(URL_KEYS.tolerance, String(state.tolerance));
  query.set(URL_KEYS.step, String(state.step));
  query.set(URL_KEYS.integrator, state.integrator);
  query.set(URL_KEYS.shortestPath, state.shortestPath ? "1" : "0");
  if (t !== undefined && Number.isFinite(t)) query.set(URL_KEYS.t, t.toFixed(2));
  if (embed) query.set(URL_KEYS.embed, "1");
  return "?" + query.toString();
}

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
