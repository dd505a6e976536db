// @ts-check
// The one player of a run, for every page, <kli-figure> and the video recorder: the frame loop,
// play and pause, speed, reduced motion and whether the figures can be seen. The run owns its
// time (its span, `seek`, `advance`: the run contract, crates/kli-demo/src/figure.rs); the
// player only tells it how much of the page's clock has passed.

/**
 * What the player needs of a run: the run contract's time.
 * @typedef {object} Timed
 * @property {Float64Array | number[]} span `[start, end]`, end `Infinity` for a run with none
 * @property {number} time the time on show
 * @property {(t: number) => boolean} seek moves towards `t`; true once there (bounded work a call)
 * @property {(seconds: number) => boolean} advance moves on by seconds at speed 1; true at the end
 */

/** The longest frame the clock counts (ms): after a stall the run goes on, it does not jump. */

/** A task later. */
const nextTask = () => new Promise((resolve) => setTimeout(resolve));
const LONGEST_FRAME = 100;

export class Player {
  /**
   * @param {object} hooks
   * @param {() => void} hooks.draw draws the figures at the run's time
   * @param {(playing: boolean) => void} [hooks.changed] after play or pause
   * @param {() => boolean} [hooks.seen] whether the figures can be seen now (else no frames are asked for)
   * @param {boolean} [hooks.loop] at the end, start again (else pause there)
   */
  constructor({ draw, changed = () => {}, seen = () => true, loop = false }) {
    this.hooks = { draw, changed, seen };
    this.loop = loop;
    /** @type {Timed | null} */
    this.run = null;
    this.speed = 1;
    this.playing = false;
    this.frame = 0;
    /** @type {number | null} the previous frame's timestamp while playing */
    this.last = null;
    this.recheck = 0;
    /** Bumped by every `show` and `stop`: a `seek` under way for an older run gives up. */
    this.generation = 0;
  }

  static reducedMotion() {
    return matchMedia("(prefers-reduced-motion: reduce)").matches;
  }

  /** The time on show (0 before the first run). */
  get t() {
    return this.run?.time ?? 0;
  }

  /** `[start, end]` of the run on show. */
  get span() {
    const [start, end] = this.run?.span ?? [0, 0];
    return /** @type {[number, number]} */ ([start, end]);
  }

  /** Whether the run has an end (the swarm has none). */
  get spanned() {
    return Number.isFinite(this.span[1]);
  }

  /** Shows a new run. A run with a span takes the time on show when it still fits. */
  show(/** @type {Timed} */ run) {
    const t = this.run && this.spanned ? this.t : null;
    this.generation++;
    this.run = run;
    if (t !== null && Number.isFinite(run.span[1])) run.seek(t);
  }

  /** Runs from the time on show, or from the start when at the end. */
  play() {
    if (!this.run) return;
    const [start, end] = this.span;
    if (this.t >= end) this.run.seek(start);
    this.playing = true;
    this.last = null;
    this.hooks.changed(true);
    this.schedule();
  }

  pause() {
    if (!this.playing) return;
    this.playing = false;
    this.hooks.changed(false);
  }

  toggle() {
    if (this.playing) this.pause();
    else this.play();
  }

  /**
   * Moves the run to `t` (NaN is the start) and draws it. A run that computes its way there
   * (the swarm) gets there a task at a time; `progress` hears how far, and the promise
   * resolves to false if another run was shown before it got there.
   * @param {number} t
   * @param {(t: number) => void} [progress]
   */
  async seek(t, progress) {
    const run = this.run;
    if (!run) return false;
    const generation = this.generation;
    const target = Number.isNaN(t) ? this.span[0] : t;
    // A bounded piece of work a task. A run with no end computes its way there, so its first
    // piece waits for a task of its own too: the task that asked (a figure being made, a click)
    // does not carry it.
    for (let piece = 0; ; piece++) {
      if (piece > 0 || !this.spanned) {
        await nextTask();
        if (generation !== this.generation) return false;
      }
      if (run.seek(target)) break;
      progress?.(run.time);
      this.hooks.draw();
    }
    this.hooks.draw();
    return true;
  }

  /** Asks for a frame while playing and seen; while unseen (hidden by style, which no observer
   *  reports), looks again in a quarter of a second, asking for no frame. */
  schedule() {
    if (this.frame || !this.playing || !this.run) return;
    clearTimeout(this.recheck);
    if (!this.hooks.seen()) {
      this.last = null;
      this.recheck = setTimeout(() => this.schedule(), 250);
      return;
    }
    this.frame = requestAnimationFrame((now) => this.tick(now));
  }

  /** Stops, and lets go of the run (about to be freed: the figure is gone or failed). */
  stop() {
    cancelAnimationFrame(this.frame);
    clearTimeout(this.recheck);
    this.frame = 0;
    this.generation++;
    this.playing = false;
    this.run = null;
  }

  tick(/** @type {number} */ now) {
    this.frame = 0;
    const run = this.run;
    if (!run || !this.playing) return;
    if (!this.hooks.seen()) return this.schedule();
    const seconds = this.last === null ? 0 : (Math.min(Math.max(now - this.last, 0), LONGEST_FRAME) / 1000) * this.speed;
    this.last = now;
    const ended = seconds > 0 && run.advance(seconds);
    if (ended && this.loop) run.seek(this.span[0]);
    this.hooks.draw();
    if (ended && !this.loop) this.pause();
    else this.schedule();
  }
}
