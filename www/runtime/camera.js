// @ts-check
// Where the sphere views are seen from: azimuth and elevation in radians, turned by dragging and
// by the arrow keys. The elevation stops short of the poles (±89°), where the azimuth would lose
// its meaning.

const MAX_ELEVATION = 1.55;

export class Camera {
  /** @param {ArrayLike<number>} view the module's default [azimuth, elevation] */
  constructor(view) {
    this.azimuth = view[0];
    this.elevation = view[1];
  }

  /** Turns by (azimuth, elevation) radians. */
  turn(/** @type {number} */ azimuth, /** @type {number} */ elevation) {
    this.azimuth += azimuth;
    this.elevation = Math.min(Math.max(this.elevation + elevation, -MAX_ELEVATION), MAX_ELEVATION);
  }
}
