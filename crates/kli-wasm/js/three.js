// kli/three: smooth quaternion tracks for three.js (issue 16). three.js interpolates a
// QuaternionKeyframeTrack only linearly (piecewise SLERP: ω jumps at every key; InterpolateSmooth
// is "unsupported" for quaternions). These put the Kuramoto–Lohe chain of kli/spline through the
// same keys: `smoothTrack` resamples it into a plain track (for AnimationClip, toJSON, glTF
// export), `smoothInterpolation` evaluates it live in the mixer. `blendRotations` blends poses
// by kli/average's weighted chordal mean, whatever their order. Quaternions are scalar last, as
// three.js keeps them. Initialise kli/spline first (`await init()` from "kli/spline") for the
// tracks, kli/average for the blend; neither is imported here (resample.js, the registry), so an
// app that only smooths never bundles kli/average, one that only blends never kli/spline.
import { Interpolant, Quaternion, QuaternionKeyframeTrack } from "three";
import { chainThrough, isKliError, lent, readOptions, refuse, resample } from "./resample.js";

export { isKliError };

/** The track's keys, checked: a QuaternionKeyframeTrack (or its shape), 4 values a key. */
function keysOf(track) {
  const ok = track !== null && typeof track === "object" && typeof track.name === "string" &&
    ArrayBuffer.isView(track.times) && ArrayBuffer.isView(track.values);
  if (!ok) throw refuse("track", "must be a THREE.QuaternionKeyframeTrack (name, times, values)");
  // Another kind of track (positions, morph weights) is named as three.js names it.
  const type = track.ValueTypeName;
  if (typeof type === "string" && type !== "quaternion") {
    throw refuse("track", `must be a THREE.QuaternionKeyframeTrack: "${track.name}" is a ${type} track, and only rotations are smoothed`);
  }
  const keys = track.times.length;
  if (track.values.length !== 4 * keys) {
    throw refuse("track", `must hold 4 values (a quaternion) per key: ${4 * keys} for its ${keys} key${keys === 1 ? "" : "s"} (got ${track.values.length})`, "wrong-length");
  }
  return { times: track.times, values: track.values };
}

/** The owner of a track's keys, for Errors (resample.js). */
const owner = (caller) => ({ argument: "track", where: "", caller: `kli/three's ${caller}` });

/**
 * A new QuaternionKeyframeTrack of the same name through the same keys, resampled from the chain
 * at `fps` samples a second (the keys' own times kept, so every key is hit), interpolated
 * linearly between samples by three.js: ready for AnimationClip, toJSON and glTF export.
 */
export function smoothTrack(track, options) {
  const keys = keysOf(track);
  const { fps, smoothness } = readOptions(options, 60);
  const sampled = resample(keys.times, keys.values, fps, smoothness, owner("smoothTrack"));
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
  const chain = chainThrough(keys.times, keys.values, smoothness, owner("smoothInterpolation"));
  if (!chain) return smooth;
  smooth.createInterpolant = function (result) {
    return new ChainInterpolant(this.times, this.values, this.getValueSize(), result, chain);
  };
  chains.register(smooth, chain);
  return smooth;
}

const isQuaternion = (q) => q !== null && typeof q === "object" && q.isQuaternion === true;

/** How a pose is given: one THREE.Quaternion, an array of them (a bone each), or 4 numbers a bone
 *  scalar last (a track's `values`: a key each); and how many bones it has. */
function shapeOf(pose, name) {
  if (isQuaternion(pose)) return { kind: "quaternion", bones: 1 };
  if (Array.isArray(pose) && pose.length > 0 && pose.every(isQuaternion)) return { kind: "quaternions", bones: pose.length };
  const numbers = ArrayBuffer.isView(pose) || Array.isArray(pose);
  if (numbers && typeof pose.length === "number" && pose.length > 0 && pose.length % 4 === 0) {
    return { kind: "values", bones: pose.length / 4 };
  }
  return refused(name, "must be a THREE.Quaternion, an array of them (a bone each), or a track's values (4 numbers a key, scalar last)");
}

function refused(name, problem) {
  throw refuse(name, problem);
}

/**
 * The poses blended a bone at a time by the weighted chordal mean (kli/average), which does not
 * depend on the order of the poses (slerping one pose into the next does). Each pose is a
 * THREE.Quaternion, an array of them, or a track's `values` (4 numbers a key, scalar last), all of
 * one shape; `weights` one a pose, each ≥ 0 and not all 0. The result goes into `out` (a
 * Quaternion, an array of them, an array of numbers) or a new one (a Float64Array for values).
 */
export function blendRotations(poses, weights, out) {
  const { blendRotations: blendFlat } = lent("kli/average", "kli/three's blendRotations");
  if (!Array.isArray(poses) || poses.length === 0) {
    refused("poses", "must be a non-empty array of poses (THREE.Quaternions, arrays of them, or tracks' values)");
  }
  const { kind, bones } = shapeOf(poses[0], "poses[0]");
  const flat = new Float64Array(4 * bones * poses.length);
  poses.forEach((pose, p) => {
    const shape = shapeOf(pose, `poses[${p}]`);
    if (shape.kind !== kind || shape.bones !== bones) {
      const shape = kind === "values" ? `${4 * bones} numbers, 4 a key` : kind === "quaternion" ? "one THREE.Quaternion" : `an array of ${bones} THREE.Quaternion${bones === 1 ? "" : "s"}`;
      refused(`poses[${p}]`, `must have the shape of poses[0] (${shape})`);
    }
    const at = 4 * bones * p;
    if (kind === "values") flat.set(pose, at);
    else [pose].flat().forEach((q, b) => flat.set([q.x, q.y, q.z, q.w], at + 4 * b));
  });
  const blended = blendFlat(flat, weights, new Float64Array(4 * bones), { order: "xyzw" });
  if (kind === "values") {
    const target = out ?? new Float64Array(4 * bones);
    if (!(ArrayBuffer.isView(target) || Array.isArray(target)) || target.length !== 4 * bones) {
      refused("out", `must be an array of ${4 * bones} numbers`);
    }
    for (let k = 0; k < blended.length; k++) target[k] = blended[k];
    return target;
  }
  const quaternion = (b, q) => (q ?? new Quaternion()).set(blended[4 * b], blended[4 * b + 1], blended[4 * b + 2], blended[4 * b + 3]);
  if (kind === "quaternion") {
    if (out !== undefined && !isQuaternion(out)) refused("out", "must be a THREE.Quaternion");
    return quaternion(0, out);
  }
  if (out !== undefined && !(Array.isArray(out) && out.length === bones && out.every(isQuaternion))) {
    refused("out", `must be an array of ${bones} THREE.Quaternion${bones === 1 ? "" : "s"}`);
  }
  const target = out ?? [];
  for (let b = 0; b < bones; b++) target[b] = quaternion(b, target[b]);
  return target;
}
