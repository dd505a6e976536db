// Shared by kli/three and kli/gltf: the registry through which they reach kli/spline and
// kli/average, and the Kuramoto–Lohe chain through rotation keys resampled for animation formats
// (quaternions scalar last; times in seconds). kli/spline and kli/average register what they lend
// when imported (scripts/package-json.mjs): kli/three and kli/gltf never import them, so a bundle
// holds only the entries the app imports (smoothTrack alone: no kli/average, nor its .wasm).

/** By entry ("kli/spline"), what it lends and `ready()`, whether its init() has run. */
export const entries = {};

/** True for every Error kli throws: an Error with the string properties `argument` and `kind`. */
export function isKliError(value) {
  return value instanceof Error && typeof value.argument === "string" && typeof value.kind === "string";
}

/** A kli Error (argument, kind), as the wasm entries throw them. */
export function refuse(argument, problem, kind = "invalid") {
  const error = new Error(`${argument} ${problem}`);
  error.argument = argument;
  error.kind = kind;
  return error;
}

/** What `entry` lends, for `caller`; before its init(), an Error that names both. */
export function lent(entry, caller) {
  const functions = entries[entry];
  if (functions?.ready()) return functions;
  throw refuse(entry, `is not initialised: ${caller} uses it, so call \`await init()\` from "${entry}" first`, "not-initialised");
}

/** The options `{ fps, smoothness }`, checked; `fps` from 1 to 1000. */
export function readOptions(options, fps = 60) {
  if (options === undefined || options === null) return { fps, smoothness: 1 };
  if (typeof options !== "object") throw refuse("options", "must be an object like { fps: 60, smoothness: 1 }");
  for (const key of Object.keys(options)) {
    if (key !== "fps" && key !== "smoothness") throw refuse("options", `has an unknown key "${key}"; the keys are fps, smoothness`);
  }
  const chosen = { fps: options.fps ?? fps, smoothness: options.smoothness ?? 1 };
  if (!(typeof chosen.fps === "number" && chosen.fps >= 1 && chosen.fps <= 1000)) {
    throw refuse("fps", `must be a number from 1 to 1000 (got ${String(chosen.fps)})`);
  }
  return chosen;
}

/** kliSpline's Error about `keys[i]` or `times[i]` (of a flat array the caller never saw), about
 *  the keys' owner instead (`{ argument, where }`): "track key 1 (at 0.8 s) must be …". */
function renamed(e, owner, times) {
  const at = isKliError(e) && /^(keys|times)(?:\[(\d+)\])?(?= )/.exec(e.message);
  if (!at) return e;
  const [whole, what, i] = at;
  const which = i === undefined ? what : what === "keys" ? `key ${i} (at ${times[i]} s)` : `times[${i}]`;
  const error = refuse(owner.argument, `${owner.where}${which}${e.message.slice(whole.length)}`, e.kind);
  if (e.component !== undefined) error.component = e.component;
  return error;
}

/** The chain through the keys (4 values a key, scalar last), or null for fewer than 2 keys;
 *  `owner.caller` ("kli/three's smoothTrack") needs kli/spline. */
export function chainThrough(times, values, smoothness, owner) {
  const { kliSpline } = lent("kli/spline", owner.caller);
  if (times.length < 2) return null;
  try {
    return kliSpline(values, { times, order: "xyzw", smoothness });
  } catch (e) {
    throw renamed(e, owner, times);
  }
}

/** The most samples a resampling writes: 10⁷ (40 MB of values). */
const MAX_SAMPLES = 1e7;

/**
 * The chain through the keys sampled at `fps` a second, the keys' own times kept (so every key
 * is hit): `{ times, values }` as Float32Arrays (the precision of three.js tracks and glTF
 * accessors), or null for fewer than 2 keys.
 */
export function resample(keyTimes, keyValues, fps, smoothness, owner) {
  const chain = chainThrough(keyTimes, keyValues, smoothness, owner);
  if (!chain) return null;
  try {
    const first = keyTimes[0], last = keyTimes[keyTimes.length - 1];
    if ((last - first) * fps > MAX_SAMPLES) {
      throw refuse("fps", `gives more than ${MAX_SAMPLES} samples over ${last - first} s: lower it`);
    }
    // The keys' times and a grid of 1/fps between them, merged in order; a grid time within a
    // quarter frame of a key, or not after the previous time in single precision, is left out.
    const times = [];
    const push = (t) => {
      if (times.length === 0 || Math.fround(t) > times[times.length - 1]) times.push(Math.fround(t));
    };
    let k = 0;
    for (let i = 0; i < keyTimes.length; i++) {
      const key = Math.fround(keyTimes[i]);
      for (; first + k / fps < key - 0.25 / fps; k++) push(first + k / fps);
      while (first + k / fps <= key + 0.25 / fps) k++;
      if (times.length > 0 && times[times.length - 1] >= key) times.pop();
      push(key);
    }
    const values = new Float32Array(4 * times.length);
    const q = new Float64Array(4);
    for (let i = 0; i < times.length; i++) values.set(chain.at(times[i], q), 4 * i);
    return { times: Float32Array.from(times), values };
  } finally {
    chain.free();
  }
}
