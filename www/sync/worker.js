// @ts-check
// The synchronisation page's worker: it loads the page's module once and answers each call the
// page sends, `{ id, call, args }` with `call` "solve" (both solutions of a problem, the long
// part of a run) or "sweepError" (a point of the sweep), with `{ id, value }` or `{ id, error }`
// (the Error's message and argument). See solver.js, the page's side.
import init, { SyncDemo } from "../pkg/sync_demo.js";

const ready = init();
const CALLS = { solve: SyncDemo.solve, sweepError: SyncDemo.sweepError };

/** @param {MessageEvent<{ id: number, call: "solve" | "sweepError", args: any[] }>} event */
onmessage = async (event) => {
  const { id, call, args } = event.data;
  /** @type {(message: any, transfer?: Transferable[]) => void} */
  const reply = (message, transfer = []) => self.postMessage(message, { transfer });
  try {
    await ready;
    const value = /** @type {(...args: any[]) => any} */ (CALLS[call])(...args);
    reply({ id, value }, value instanceof Float64Array ? [value.buffer] : []);
  } catch (error) {
    const { message, argument } = /** @type {{ message?: string, argument?: string }} */ (error ?? {});
    reply({ id, error: { message: message ?? String(error), argument } });
  }
};
