// @ts-check
// Where the synchronisation page solves: in a worker (worker.js), so that neither building a run
// nor the sweep ever holds the page up (a run's solutions took 230 ms on the page itself, some
// 900 ms on Lighthouse's phone, in one task); where no worker can start (a page opened from
// file://), on the page, a call a task. Calls go one at a time, the newest run's solve first;
// a solve that a newer one makes pointless before it starts is answered `null` and never run.
import { SyncDemo } from "../pkg/sync_demo.js";

/** @typedef {"solve" | "sweepError"} Call */
/** @typedef {{ call: Call, args: any[], resolve: (value: any) => void, reject: (error: Error) => void }} Job */

export class Solver {
  constructor() {
    /** @type {Job[]} waiting to be sent */
    this.queue = [];
    /** @type {Job | null} the job the worker is on */
    this.running = null;
    this.id = 0;
    /** @type {Worker | null} */
    this.worker = null;
    try {
      this.worker = new Worker(new URL("../sync/worker.js", import.meta.url), { type: "module" });
      this.worker.onmessage = (event) => this.answered(event.data);
      // The worker could not load (or failed): the page solves from here on, the job in hand too.
      this.worker.onerror = (event) => {
        event.preventDefault();
        this.worker?.terminate();
        this.worker = null;
        if (this.running) this.queue.unshift(this.running);
        this.running = null;
        this.pump();
      };
    } catch {
      this.worker = null;
    }
  }

  /** Both solutions of the problem `state` makes (SyncDemo.solve), or `null` when a newer
   *  solve came before this one started. */
  solve(/** @type {any} */ state) {
    for (const job of this.queue.filter((job) => job.call === "solve")) job.resolve(null);
    this.queue = this.queue.filter((job) => job.call !== "solve");
    return /** @type {Promise<Float64Array | null>} */ (this.send("solve", [state], true));
  }

  /** One point of the sweep (SyncDemo.sweepError). */
  sweepError(/** @type {any} */ options, /** @type {number} */ wrong, /** @type {string} */ method) {
    return /** @type {Promise<number>} */ (this.send("sweepError", [options, wrong, method], false));
  }

  /** @param {Call} call @param {any[]} args @param {boolean} first */
  send(call, args, first) {
    return new Promise((resolve, reject) => {
      const job = { call, args, resolve, reject };
      if (first) this.queue.unshift(job);
      else this.queue.push(job);
      this.pump();
    });
  }

  /** Starts the next job when none is running. */
  pump() {
    if (this.running || this.queue.length === 0) return;
    const job = /** @type {Job} */ (this.queue.shift());
    this.running = job;
    if (this.worker) {
      this.worker.postMessage({ id: ++this.id, call: job.call, args: job.args });
      return;
    }
    setTimeout(() => {
      try {
        this.answered({ id: this.id, value: /** @type {(...args: any[]) => any} */ (SyncDemo[job.call])(...job.args) });
      } catch (error) {
        this.answered({ id: this.id, error: /** @type {any} */ (error) });
      }
    });
  }

  /** @param {{ id: number, value?: any, error?: { message: string, argument?: string } }} answer */
  answered(answer) {
    const job = this.running;
    this.running = null;
    if (job && answer.id === this.id) {
      if (answer.error) job.reject(Object.assign(new Error(answer.error.message), { argument: answer.error.argument }));
      else job.resolve(answer.value);
    }
    this.pump();
  }
}
