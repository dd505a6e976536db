// kli/three: smooth quaternion tracks for three.js (issue 16). three.js interpolates a
// QuaternionKeyframeTrack only linearly (piecewise SLERP: ω jumps at every key; InterpolateSmooth
// is "unsupported" for quaternions). These put the Kuramoto–Lohe chain of kli/spline through the
// same keys: `smoothTrack` resamples it into a plain track (for AnimationClip, toJSON, glTF
// export), `smoothInterpolation` evaluates it live in the mixer. Quaternions are scalar last, as
// three.js keeps them. Initialise kli/spline first (`await init()` from "kli/spline").
import { Interpolant, QuaternionKeyframeTrack } from "three";
import { isKliError, kliSpline } from "./spline.js";

export { isKliError };

/** A kli Error (argument, kind), as the wasm entries throw them. */
function refuse(argument, problem) {
  const error = new Error(`${argument} ${problem}`);
  error.argument = argument;
  error.kind = "invalid";
  return error;
}

/** The track's keys, checked: a QuaternionKeyframeTrack (or its shape) with 4 values a time. */
function keysOf(track) {
  const ok = track !== null && typeof track === "object" && typeof track.name === "string" &&
    ArrayBuffer.isView(track.times) && ArrayBuffer.isView(track.values);
  if (!ok) throw refuse("track", "must be a THREE.QuaternionKeyframeTrack (name, times, values)");
  if (track.values.length !== 4 * track.times.length) {
    throw refuse("track", `must hold 4 values a time: ${4 * track.times.length} (got ${track.values.length})`);
  }
  return { times: track.times, values: track.values };
}

/** The options, checked: `fps` (1 to 1000, default 60) and the chain's `smoothness`. */
function optionsOf(options, fps) {
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

/** The chain through the track's keys (scalar last), or null for fewer than 2 keys. */
function chainOf(keys, smoothness) {
  if (keys.times.length < 2) return null;
  return kliSpline(keys.values, { times: keys.times, order: "xyzw", smoothness });
}

/** The most samples smoothTrack writes: 10⁷ (40 MB of values). */
const MAX_SAMPLES = 1e7;

/**
 * A new QuaternionKeyframeTrack of the same name through the same keys, resampled from the chain
 * at `fps` samples a second (the keys' own times kept, so every key is hit), interpolated
 * linearly between samples by three.js: ready for AnimationClip, toJSON and glTF export.
 */
export function smoothTrack(track, options) {
  const keys = keysOf(track);
  const { fps, smoothness } = optionsOf(options, 60);
  const chain = chainOf(keys, smoothness);
  if (!chain) return track.clone();
  try {
    const first = keys.times[0], last = keys.times[keys.times.length - 1];
    if ((last - first) * fps > MAX_SAMPLES) {
      throw refuse("fps", `gives more than ${MAX_SAMPLES} samples over the track's ${last - first} s: lower it`);
    }
    // The keys' times and a grid of 1/fps between them, merged in order; a grid time within a
    // quarter frame of a key, or not after the previous time in single precision (three.js keeps
    // times as Float32Array), is left out.
    const times = [];
    const push = (t) => {
      if (times.length === 0 || Math.fround(t) > times[times.length - 1]) times.push(Math.fround(t));
    };
    let k = 0;
    for (let i = 0; i < keys.times.length; i++) {
      const key = keys.times[i];
      for (; first + k / fps < key - 0.25 / fps; k++) push(first + k / fps);
      while (first + k / fps <= key + 0.25 / fps) k++;
      if (times.length > 0 && times[times.length - 1] >= key) times.pop();
      push(key);
    }
    const values = new Float32Array(4 * times.length);
    const q = new Float64Array(4);
    for (let i = 0; i < times.length; i++) values.set(chain.at(times[i], q), 4 * i);
    return new QuaternionKeyframeTrack(track.name, times, values);
  } finally {
    chain.free();
  }
}

/** three.js's interpolant contract, evaluated by the chain: the mixer calls interpolate_ between
 *  keys (and copies the end keys outside them). */
class ChainInterpolant extends Interpolant {
  constructor(times, values, size, result, chain) {
    super(times, values, size, result);
    this.chain = chain;
    this.q = new Float64Array(4);
  }

  interpolate_(i1, t0, t) {
    const q = this.chain.at(t, this.q), result = this.resultBuffer;
    result[0] = q[0];
    result[1] = q[1];
    result[2] = q[2];
    result[3] = q[3];
    return result;
  }
}

/** Frees a track's chain when the track is collected. */
const chains = new FinalizationRegistry((chain) => chain.free());

/**
 * A copy of `track` that the mixer evaluates on the chain itself, with no resampling: exact
 * between keys at any frame rate. Its module memory is freed with the track. For playback; to
 * serialise or export, use smoothTrack.
 */
export function smoothInterpolation(track, options) {
  const keys = keysOf(track);
  const { smoothness } = optionsOf(options, 60);
  const smooth = track.clone();
  const chain = chainOf(keys, smoothness);
  if (!chain) return smooth;
  smooth.createInterpolant = function (result) {
    return new ChainInterpolant(this.times, this.values, this.getValueSize(), result, chain);
  };
  chains.register(smooth, chain);
  return smooth;
}
