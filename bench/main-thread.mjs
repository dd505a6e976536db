// A page's main-thread tasks, read from a Chromium trace as Lighthouse reads them: the renderer's
// top-level tasks (`RunTask`). Not Chromium's long-task timing (PerformanceObserver "longtask"),
// which leaves out the work done at a task's end for the canvases the task drew to, their
// rasterising: for the synchronisation page's map of w10000.graph it gave 56 ms where the main
// thread was busy for 110 ms (57 ms of script, then 53 ms of `CanvasRenderingContext2D::
// FinalizeFrame`).
//   await browser.startTracing(page, { categories: TRACED }); … ;
//   const { tasks, mark } = tasksOver(await browser.stopTracing(), 50, "my-mark");

/** The categories to trace: the tasks (their events are in the timeline's disabled-by-default
 *  category) and the page's `performance.mark`s. */
export const TRACED = ["devtools.timeline", "disabled-by-default-devtools.timeline", "blink.user_timing"];

/** The page's main-thread tasks in Chromium's trace `buffer` over `budget` ms, as
 *  `{ at, ms }` (at: the trace's microseconds), and the time of its user-timing mark `mark`. The
 *  page's main thread is the renderer's main thread that ran the most. */
export function tasksOver(buffer, budget, mark) {
  const events = JSON.parse(buffer.toString("utf8")).traceEvents;
  const mains = new Set(events.filter((e) => e.name === "thread_name" && e.args?.name === "CrRendererMain").map((e) => `${e.pid}:${e.tid}`));
  const busy = new Map();
  for (const e of events) {
    const thread = `${e.pid}:${e.tid}`;
    if (e.name === "RunTask" && e.ph === "X" && mains.has(thread)) busy.set(thread, (busy.get(thread) ?? 0) + e.dur);
  }
  const main = [...busy].sort((a, b) => b[1] - a[1])[0]?.[0];
  // Nested RunTasks (a task running another's) are counted once, as the outer one.
  const tasks = events.filter((e) => e.name === "RunTask" && e.ph === "X" && `${e.pid}:${e.tid}` === main).sort((a, b) => a.ts - b.ts);
  const top = [];
  for (const e of tasks) if (!top.length || e.ts >= top.at(-1).ts + top.at(-1).dur) top.push(e);
  const at = events.find((e) => e.name === mark)?.ts ?? Infinity;
  return { tasks: top.filter((e) => e.dur > budget * 1000).map((e) => ({ at: e.ts, ms: Math.round(e.dur / 1000) })), mark: at };
}

