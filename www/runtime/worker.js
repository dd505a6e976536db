// @ts-check
// A page's worker: it loads the page's module once (the address its first call names) and runs
// the static calls the page sends it, `{ id, module, target, call, args, progress }`, answering
// `{ id, value }` or `{ id, error }` (the Error's message and argument): the long computations
// (a run's solutions, a sweep's points) off the page, which stays free to draw and answer. A call
// with `progress` is given a last argument that sends `{ id, progress: words }` as it goes.
// See offload.js, the page's side.

/** @type {Promise<any> | null} the page's module, initialised */
let loaded = null;

/** @param {MessageEvent<{ id: number, module: string, target: string, call: string, args: any[], progress?: boolean }>} event */
onmessage = async (event) => {
  const { id, module, target, call, args, progress } = event.data;
  /** @type {(message: any, transfer?: Transferable[]) => void} */
  const reply = (message, transfer = []) => self.postMessage(message, { transfer });
  try {
    loaded ??= import(module).then(async (glue) => {
      await glue.default();
      return glue;
    });
    const told = progress ? [...args, (/** @type {string} */ words) => reply({ id, progress: words })] : args;
    const value = (await loaded)[target][call](...told);
    reply({ id, value }, value instanceof Float64Array ? [value.buffer] : []);
  } catch (error) {
    const { message, argument } = /** @type {{ message?: string, argument?: string }} */ (error ?? {});
    reply({ id, error: { message: message ?? String(error), argument } });
  }
};
