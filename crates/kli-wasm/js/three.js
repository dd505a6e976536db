// kli/three: smooth quaternion tracks for three.js (issue 16). three.js interpolates a
// QuaternionKeyframeTrack only linearly (piecewise SLERP: ω jumps at every key; InterpolateSmooth
// is "unsupported" for quaternions). These put the Kuramoto–Lohe chain of kli/spline through the
// same keys: `smoothTrack` resamples it into a plain track (for AnimationClip, toJSON, glTF
// export), `smoothInterpolation` evaluates it live in the mixer. Quaternions are scalar last, as
// three.js keeps them. Initialise kli/spline first (`await init()` from "kli/spline").
import { Interpolant, QuaternionKeyframeTrack } from "three";
import { isKliError } from "./spline.js";
import { chainThrough, readOptions, refuse, resample } from "./resample.js";

export { isKliError };

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

/**
 * A new QuaternionKeyframeTrack of the same name through the same keys, resampled from the chain
 * at `fps` samples a second (the keys' own times kept, so every key is hit), interpolated
 * linearly between samples by three.js: ready for AnimationClip, toJSON and glTF export.
 */
export function smoothTrack(track, options) {
  const keys = keysOf(track);
  const { fps, smoothness } = readOptions(options, 60);
  const sampled = resample(keys.times, keys.values, fps, smoothness);
  return sampled ? new QuaternionKeyframeTrack(track.name, sampled.times, sampled.values) : track.clone();
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
  const { smoothness } = readOptions(options, 60);
  const smooth = track.clone();
  const chain = chainThrough(keys.times, keys.values, smoothness);
  if (!chain) return smooth;
  smooth.createInterpolant = function (result) {
    return new ChainInterpolant(this.times, this.values, this.getValueSize(), result, chain);
  };
  chains.register(smooth, chain);
  return smooth;
}
