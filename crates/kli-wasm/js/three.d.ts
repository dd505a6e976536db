import type { Quaternion, QuaternionKeyframeTrack } from "three";
export { isKliError } from "./spline.js";

/** Options of smoothTrack and smoothInterpolation. */
export interface SmoothTrackOptions {
  /** Samples a second of smoothTrack's result, 1 to 1000. Default 60. */
  fps?: number;
  /** The chain's smoothness, 0 (piecewise SLERP) to 1 (the smoothest). Default 1. */
  smoothness?: number;
}

/** A new QuaternionKeyframeTrack of the same name through the same keys, resampled from the
 *  Kuramoto–Lohe chain at `fps` (the keys' own times kept): for AnimationClip, toJSON, glTF. */
export function smoothTrack(track: QuaternionKeyframeTrack, options?: SmoothTrackOptions): QuaternionKeyframeTrack;

/** A copy of `track` that the mixer evaluates on the chain itself (no resampling); its module
 *  memory is freed with the track. For playback; to serialise, use smoothTrack. */
export function smoothInterpolation(track: QuaternionKeyframeTrack, options?: Pick<SmoothTrackOptions, "smoothness">): QuaternionKeyframeTrack;

/** Poses blended a bone at a time by the weighted chordal mean (kli/average; initialise it
 *  first), whatever their order: one THREE.Quaternion a pose, an array of them (a bone each), or a
 *  track's `values` (4 numbers a key, scalar last). `weights` one a pose, each ≥ 0, not all 0.
 *  The result goes into `out` if given. */
export function blendRotations(poses: Quaternion[], weights: ArrayLike<number>, out?: Quaternion): Quaternion;
export function blendRotations(poses: Quaternion[][], weights: ArrayLike<number>, out?: Quaternion[]): Quaternion[];
export function blendRotations<T extends Float32Array | Float64Array | number[] = Float64Array>(
  poses: ArrayLike<number>[],
  weights: ArrayLike<number>,
  out?: T,
): T;
