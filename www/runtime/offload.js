// @ts-check
// Where a page runs its long static calls (a run's solutions, a sweep's points): in a worker
// (worker.js) that loads the page's module, so that the page never waits for them (the
// synchronisation page's solutions took 230 ms on the page itself, some 900 ms on Lighthouse's
// phone, in one task); where no worker can start (a page opened from file://), on the page, a
// call a task. Calls go one at a time, in order, but for a call marked `latest`, which goes
// first and answers `null` to any earlier one of its kind that has not started: a run's solve
// that a newer run made pointless is never run.

/** @typedef {{ target: string, call: string, args: any[], latest?: string, progress?: (words: string) => void, resolve: (value: any) => void, reject: (error: Error) => void }} Job */

export class Offload {
  /**
   * @param {Record<string, any>} glue the page's module (its classes by name), for calls on the page
   * @param {URL} address the module's address, for the worker to load
   */
  constructor(glue, address) {
    this.glue = glue;
    this.address = address.href;
    /** @type {Job[]} waiting to be sent */
    this.queue = [];
    /** @type {Job | null} the job being run */
    this.running = null;
    this.id = 0;
    /** @type {Worker | null} */
    this.worker = null;
    try {
      this.worker = new Worker(new URL("../runtime/worker.js", import.meta.url), { type: "module" });
      this.worker.onmessage = (event) => this.answered(event.data);
      // The worker could not load (or failed): the page runs the calls from here on, the one in
      // hand too.
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

  /**
   * `glue[target][call](...args)`, off the page; with `latest`, before the calls waiting, and
   * any earlier call of that kind not yet started answers `null`. With `progress`, the call is
   * given one more argument, a function it calls with words on how far it is (a pose graph's
   * stages), which reach `progress` on the page while the call runs.
   * @param {string} target @param {string} call @param {any[]} args @param {string} [latest]
   * @param {(words: string) => void} [progress]
   * @returns {Promise<any>}
   */
  call(target, call, args, latest, progress) {
    if (latest) this.dropWhere((job) => job.latest === latest);
    return new Promise((resolve, reject) => {
      const job = { target, call, args, latest, progress, resolve, reject };
      if (latest) this.queue.unshift(job);
      else this.queue.push(job);
      this.pump();
    });
  }

  /** Answers `null` to every call of `call` not yet started, and drops them (a sweep run again). */
  drop(/** @type {string} */ call) {
    this.dropWhere((job) => job.call === call);
  }

  /** Answers `null` to the waiting calls `which` picks, and drops them. */
  dropWhere(/** @type {(job: Job) => boolean} */ which) {
    for (const job of this.queue.filter(which)) job.resolve(null);
    this.queue = this.queue.filter((job) => !which(job));
  }

  /** Starts the next job when none is running. */
  pump() {
    if (this.running || this.queue.length === 0) return;
    const job = /** @type {Job} */ (this.queue.shift());
    this.running = job;
    const id = ++this.id;
    if (this.worker) {
      this.worker.postMessage({ id, module: this.address, target: job.target, call: job.call, args: job.args, progress: Boolean(job.progress) });
      return;
    }
    setTimeout(() => {
      try {
        const args = job.progress ? [...job.args, job.progress] : job.args;
        this.answered({ id, value: this.glue[job.target][job.call](...args) });
      } catch (error) {
        this.answered({ id, error: /** @type {any} */ (error) });
      }
    });
  }

  /** @param {{ id: number, value?: any, error?: { message: string, argument?: string }, progress?: string }} answer */
  answered(answer) {
    const job = this.running;
    if (!job || answer.id !== this.id) return;
    // Words on the way, not the answer.
    if (answer.progress !== undefined) return job.progress?.(answer.progress);
    this.running = null;
    if (answer.error) job.reject(Object.assign(new Error(answer.error.message), { argument: answer.error.argument }));
    else job.resolve(answer.value);
    this.pump();
  }
}
