export { isKliError } from "./spline.js";

/** Options of smoothRotations. */
export interface SmoothRotationsOptions {
  /** Samples a second, 1 to 1000. Default 60. */
  fps?: number;
  /** The chain's smoothness, 0 (piecewise SLERP) to 1 (the smoothest). Default 1. */
  smoothness?: number;
}

/** A glTF-Transform transform (`await document.transform(smoothRotations({ fps: 60 }))`) that
 *  replaces every LINEAR rotation sampler with the Kuramoto–Lohe chain through the same keys,
 *  resampled at `fps` with the keys' own times kept; STEP and CUBICSPLINE are left alone. The
 *  document is typed loosely so any @gltf-transform/core from 3 on fits. */
export function smoothRotations(options?: SmoothRotationsOptions): (document: any) => void;
