// Hostile input to the pages, written once for the tests that check what it shows
// (fuzz.test.mjs, hostile-load.test.mjs: no NaN on screen, refused by name, nothing hangs) and
// the benchmark that times it against the previous release (bench/long-tasks.mjs: no task over
// 200 ms). How long a task takes depends on the machine and on what runs beside it, so the
// tests hold each page only to HANG; the 200 ms target is the benchmark's.

/** The longest task a test accepts: a freeze a reader would take for a hang. The pages' own
 *  tasks stay near 200 ms on this machine when it is quiet (bench/long-tasks.mjs), and the tests
 *  run beside cargo's builds, which can stretch a task several times over; work that grows with
 *  a hostile number (a million oscillators built at once) runs far past this. */
export const HANG = 5000;

/** Records every long task (> 50 ms) from the first script on, into window.__longTasks. */
export const watchLongTasks = () => {
  window.__longTasks = [];
  new PerformanceObserver((list) => {
    for (const entry of list.getEntries()) window.__longTasks.push(Math.round(entry.duration));
  }).observe({ type: "longtask", buffered: true });
};

/** Values a URL's field may be given by mistake or on purpose. */
export const HOSTILE = ["NaN", "Infinity", "-Infinity", "1e308", "-1e308", "0", "-0", "1e-320", "abc", "", "0x10", "1,2",
  ";;;", "1,0,0,0;", "%00", "<img src=x onerror=window.__pwned=1>", "1".repeat(400), "9".repeat(20), "-1", "2.5",
  "1e9", "0,0,0,0", "1,0,0,0;0,0,0,0", "1,0,0,0;1,0,0,0;1,0,0,0", "0,1,1,2", "5,4,3"];

function random(seed) {
  let x = seed >>> 0 || 1;
  return () => {
    x ^= x << 13; x ^= x >>> 17; x ^= x << 5; x >>>= 0;
    return x / 4294967296;
  };
}

/** Ten seeded URLs of a page (an entry of www/pages.js): one to three of its state's keys, or
 *  the runtime's own (the time, the text size, the printed time), each given a hostile value. */
export function seededQueries({ name, html, state }) {
  const next = random(name.length * 7919);
  const keys = [...state.schema.map((entry) => entry.url), "t", "text", "print"];
  const queries = [];
  for (let k = 0; k < 10; k++) {
    const params = new URLSearchParams();
    const count = 1 + Math.floor(next() * 3);
    for (let i = 0; i < count; i++) params.set(keys[Math.floor(next() * keys.length)], HOSTILE[Math.floor(next() * HOSTILE.length)]);
    queries.push(`${html}?${params}`);
  }
  return queries;
}

// 600 keys (1,000 took 9 s): as many as a URL the static server takes holds.
const manyKeys = Array.from({ length: 600 }, (_, i) => [Math.cos(i), Math.sin(i), 0.3, 0.1].map((x) => x.toFixed(1)).join(",")).join(";");

/** URLs that ask a page for much work, each with what the page must then say (or null). */
export const HEAVY = [
  ["keyframes.html?times=0,1,2,3,4,100000", /Newton steps/],
  [`keyframes.html?keys=${manyKeys}`, /keys may hold at most 256 keys here \(got 600\)/],
  ["keyframes.html?keys=1,0,0,0;-1,0,0,0;1,0,0,0", /Squad's is 0/],
  ["swarm.html?n=1000000&K=-1e308&w=1e200&spread=1e200", null],
];

/** Figures asked for much work or given hostile attributes, put at the top of
 *  examples/figures.html; `FIGURES_DONE` is true in the page once the slow ones have finished. */
export const FIGURES = `
  <kli-figure id="far" view="swarm" count="2000" t="100" style="width: 300px; height: 200px"></kli-figure>
  <kli-figure id="fast" view="swarm" autoplay speed="1e9" style="width: 300px; height: 200px"></kli-figure>
  <kli-figure id="never" view="swarm" count="2000" t="1e9" style="width: 300px; height: 200px"></kli-figure>
  <kli-figure id="wide" view="keyframes" times="0,1,100000" keys="1,0,0,0;0,1,0,0;0,0,1,0" style="width: 300px; height: 200px"></kli-figure>
  <kli-figure id="strong" view="swarm" coupling="1e308" style="width: 300px; height: 200px"></kli-figure>`;
export const FIGURES_DONE = () => document.querySelector("#far").run?.time >= 99.99 && Boolean(document.querySelector("#wide").run);
