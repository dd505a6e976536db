// Issue 17's page part: no task a page or <kli-figure> runs blocks for more than 200 ms (Chromium's
// long-task timing), whatever the URL or the attributes, and no NaN or Infinity reaches the screen.
// A page's own plain load is the floor (browser.mjs, budgetOf).
import { test } from "node:test";
import assert from "node:assert/strict";
import { setup, open, openWithinBudget, budgetOf, watchLongTasks as longTasks } from "./browser.mjs";

setup();


const BUDGET = 200;
// 600 keys (the 1,000 took 9 s): as many as a URL the static server takes holds.
const manyKeys = Array.from({ length: 600 }, (_, i) => [Math.cos(i), Math.sin(i), 0.3, 0.1].map((x) => x.toFixed(1)).join(",")).join(";");

for (const [query, expect] of [
  ["keyframes.html?times=0,1,2,3,4,100000", /Newton steps/],
  [`keyframes.html?keys=${manyKeys}`, null],
  ["keyframes.html?keys=1,0,0,0;-1,0,0,0;1,0,0,0", /Squad's is 0/],
  ["swarm.html?n=1000000&K=-1e308&w=1e200&spread=1e200", null],
]) {
  test(`${query.slice(0, 60)}: no task over ${BUDGET} ms, no NaN on screen`, async () => {
    const { page, context, problems, worst, budget } = await openWithinBudget(query, budgetOf(query.split("?")[0]), 1500);
    try {
      assert.ok(worst <= budget, `a task of ${worst} ms on each of three loads (budget ${budget} ms)`);
      const text = await page.evaluate(() => document.body.innerText);
      assert.doesNotMatch(text, /NaN|Infinity/);
      if (expect) assert.match(text, expect);
      if (query.includes("keys=") && !expect) assert.match(await page.textContent("#keys-error"), /keys may hold at most 256 keys here \(got 600\)/);
      assert.deepEqual(problems, []);
    } finally {
      await context.close();
    }
  });
}

test("<kli-figure>: a far swarm time runs in pieces, a hostile speed or time is refused in the figure, nothing blocks or throws", async () => {
  const budgetFor = budgetOf("examples/figures.html");
  const { page, context, problems } = await open("examples/figures.html", { init: longTasks });
  try {
    await page.evaluate(() => document.querySelector("article").insertAdjacentHTML("afterbegin", `
      <kli-figure id="far" view="swarm" count="2000" t="100" style="width: 300px; height: 200px"></kli-figure>
      <kli-figure id="fast" view="swarm" autoplay speed="1e9" style="width: 300px; height: 200px"></kli-figure>
      <kli-figure id="never" view="swarm" count="2000" t="1e9" style="width: 300px; height: 200px"></kli-figure>
      <kli-figure id="wide" view="keyframes" times="0,1,100000" keys="1,0,0,0;0,1,0,0;0,0,1,0" style="width: 300px; height: 200px"></kli-figure>
      <kli-figure id="strong" view="swarm" coupling="1e308" style="width: 300px; height: 200px"></kli-figure>`));
    const message = (id) => page.evaluate((id) => document.querySelector(id).shadowRoot.textContent, id);
    await page.waitForFunction(() => document.querySelector("#far").run?.time >= 99.99, null, { timeout: 20000 });
    await page.waitForFunction(() => document.querySelector("#wide").run);
    await page.waitForTimeout(500);
    const tasks = await page.evaluate(() => window.__longTasks);
    const budget = Math.max(0, ...tasks) <= BUDGET ? BUDGET : await budgetFor();
    assert.ok(Math.max(0, ...tasks) <= budget, `long tasks: ${tasks.join(", ")} ms (budget ${budget} ms)`);
    assert.match(await message("#fast"), /speed must be a number from 0 to 1000 \(got "1e9"\)/);
    assert.match(await message("#never"), /t must be a number from 0 to 1000000 \(got "1e9"\)/);
    // Bounded as the swarm page's slider is, so that no figure blocks its page.
    assert.match(await message("#strong"), /coupling must be from -3 to 6, as on its page \(got 1e\+308\)/);
    assert.doesNotMatch(await message("#far"), /Running|NaN/);
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});
