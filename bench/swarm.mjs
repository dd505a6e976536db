// The swarm benchmark: one geodesic RK4 step of LoheSwarm in wasm under Node, for 10⁴
// oscillators all-to-all (the target: ≤ 1 ms), on a ring, and for the page's 2,000.
//   node bench/swarm.mjs [rounds]
import { median, record } from "./targets.mjs";
import { readFileSync } from "node:fs";
import { performance } from "node:perf_hooks";
import { LoheSwarm, initSync } from "../pkg/swarm.js";

initSync({ module: readFileSync(new URL("../pkg/swarm_bg.wasm", import.meta.url)) });
const rounds = Number(process.argv[2] ?? 15);

console.log(`LoheSwarm.step, median over ${rounds} rounds of 20 steps, Node ${process.version}:`);
console.log("| oscillators | graph | ms per step |");
console.log("| ---: | --- | ---: |");
for (const [count, graph] of [[10000, "all"], [10000, "ring"], [2000, "all"]]) {
  const swarm = new LoheSwarm({ count, graph, frequencySpread: 0.5, seed: 1 });
  swarm.step(0.01, 20); // warm up
  const times = [];
  for (let k = 0; k < rounds; k++) {
    const start = performance.now();
    swarm.step(0.01, 20);
    times.push((performance.now() - start) / 20);
  }
  // The result is used, so nothing is optimised away.
  if (!(swarm.orderParameter >= 0)) throw new Error("R is not a number");
  console.log(`| ${count} | ${graph} | ${median(times).toFixed(3)} |`);
  if (count === 10000 && graph === "all") record("one swarm step, 10⁴ oscillators all to all, ≤ 1 ms", `${median(times).toFixed(3)} ms`, "", median(times) <= 1);
  swarm.free();
}
