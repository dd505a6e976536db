// @ts-check
// A sweep: a figure of one run's measure at many settings (the swarm's R against K, the means'
// and the solvers' errors against the share of wrong data), computed one point a task so the page
// stays responsive, its table (for screen readers) and its status filled as it goes. The page
// fills it once it is interactive, and its button runs it again: no empty figure.
import { $ } from "./dom.js";

export class Sweep {
  /**
   * @param {object} parts
   * @param {string} parts.table the selector of the table's body (a row a point)
   * @param {string} parts.status the selector of its status line
   * @param {() => void} parts.redraw draws the figure again (a point has arrived)
   * @param {(x: number, values: number[]) => string[]} parts.cells a point's table cells
   * @param {(count: number) => string} parts.done the status once every point is in
   */
  constructor(parts) {
    this.parts = parts;
    /** @type {number[]} the settings visited so far */
    this.xs = [];
    /** @type {number[]} their values, as many a point as `compute` returns */
    this.values = [];
    /** the page's own setting, marked on the figure */
    this.current = 0;
    this.timer = 0;
    /** which run of the sweep is current: a point of an earlier one that comes late is dropped */
    this.generation = 0;
  }

  /**
   * Computes `compute(x, k)` for each of `xs` and each part `k` below `parts`, a task each (so a
   * point of many costly parts keeps every task short), or elsewhere (`compute` may answer with
   * a promise: a worker's), replacing what was there.
   * @param {readonly number[]} xs
   * @param {(x: number, part: number) => ArrayLike<number> | Promise<ArrayLike<number>>} compute
   * @param {number} [parts]
   */
  run(xs, compute, parts = 1) {
    const { table, status, redraw, cells, done } = this.parts;
    clearTimeout(this.timer);
    const generation = ++this.generation;
    this.xs = [];
    this.values = [];
    const body = $(table, HTMLTableSectionElement);
    const line = $(status, HTMLOutputElement);
    body.replaceChildren();
    const next = (/** @type {number} */ i, /** @type {number} */ part, /** @type {number[]} */ values) => {
      if (i === xs.length) {
        line.textContent = done(xs.length);
        return;
      }
      if (part === 0) line.textContent = `Sweeping: ${i + 1} of ${xs.length}`;
      const value = compute(xs[i], part);
      if (value instanceof Promise) {
        value.then((got) => generation === this.generation && take(i, part, values, got), (error) => {
          if (generation === this.generation) line.textContent = `The sweep stopped: ${error instanceof Error ? error.message : String(error)}`;
        });
      } else {
        take(i, part, values, value);
      }
    };
    const take = (/** @type {number} */ i, /** @type {number} */ part, /** @type {number[]} */ values, /** @type {ArrayLike<number>} */ got) => {
      values.push(...Array.from(got));
      if (part + 1 < parts) {
        this.timer = setTimeout(() => next(i, part + 1, values));
        return;
      }
      this.xs.push(xs[i]);
      this.values.push(...values);
      const row = body.insertRow();
      for (const text of cells(xs[i], values)) row.insertCell().textContent = text;
      redraw();
      this.timer = setTimeout(() => next(i + 1, 0, []));
    };
    next(0, 0, []);
  }

  /** What the module's drawing takes: the settings, their values and the page's setting. */
  get drawn() {
    return /** @type {const} */ ([new Float64Array(this.xs), new Float64Array(this.values), this.current]);
  }
}
