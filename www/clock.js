// @ts-check
// The animation clock: the time t in [start, end], whether it runs, and at what speed.

export class Clock {
  constructor() {
    this.t = 0;
    this.start = 0;
    this.end = 0;
    this.playing = false;
    this.speed = 1;
    /** @type {number | null} the previous frame's timestamp while playing */
    this.last = null;
  }

  /** Runs from the current time, or from the start when at the end. */
  play() {
    if (this.t >= this.end) this.t = this.start;
    this.playing = true;
    this.last = null;
  }

  pause() {
    this.playing = false;
  }

  /** Moves to `t`, kept within [start, end] (NaN counts as the start). */
  seek(/** @type {number} */ t) {
    this.t = Math.min(Math.max(Number.isNaN(t) ? this.start : t, this.start), this.end);
  }

  /** A new span (a new run); the time stays where it was when it still fits. */
  setSpan(/** @type {number} */ start, /** @type {number} */ end) {
    this.start = start;
    this.end = end;
    this.seek(this.t);
  }

  /** Advances to the frame at `now` (ms); returns true when this frame reached the end. */
  tick(/** @type {number} */ now) {
    if (!this.playing) return false;
    if (this.last !== null) this.t += ((now - this.last) / 1000) * this.speed;
    this.last = now;
    if (this.t < this.end) return false;
    this.t = this.end;
    this.playing = false;
    return true;
  }
}
