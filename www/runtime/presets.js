// @ts-check
// Presets for every page's Preset menu: which preset a state is, and random rotations.

/** A standard normal number (Box–Muller). */
const gaussian = () => Math.sqrt(-2 * Math.log(1 - Math.random())) * Math.cos(2 * Math.PI * Math.random());

/** A uniformly random unit quaternion (normalised Gaussian), to 4 decimals. */
export function randomQuaternion() {
  const q = [gaussian(), gaussian(), gaussian(), gaussian()];
  const length = Math.hypot(...q) || 1;
  return q.map((c) => Number((c / length).toFixed(4)));
}

/**
 * Whether two states hold the same values (numbers, strings, booleans, arrays, objects; the
 * order of an object's keys and keys set to undefined do not count).
 * @param {unknown} a
 * @param {unknown} b
 * @returns {boolean}
 */
export function sameState(a, b) {
  if (a === b) return true;
  if (typeof a !== "object" || typeof b !== "object" || a === null || b === null) return false;
  if (Array.isArray(a) !== Array.isArray(b)) return false;
  const keys = (/** @type {object} */ o) => Object.keys(o).filter((k) => /** @type {any} */ (o)[k] !== undefined);
  const [ka, kb] = [keys(a), keys(b)];
  return ka.length === kb.length && ka.every((k) => sameState(/** @type {any} */ (a)[k], /** @type {any} */ (b)[k]));
}

/**
 * The name of the preset equal to `state`, or "custom".
 * @template T
 * @param {Record<string, T>} presets
 * @param {T | null} state
 */
export function presetName(presets, state) {
  const found = Object.entries(presets).find(([, preset]) => sameState(preset, state));
  return found ? found[0] : "custom";
}
