// Seeded hostile URLs on every page (issue 17): random keys of each page's schema given hostile
// values. Each load must show no error outside the refused fields' messages, no NaN or Infinity
// in what the page computed (its readouts, tables and status), run no injected script, and add
// no long task beyond the page's own (browser.mjs, budgetOf).
import { test } from "node:test";
import assert from "node:assert/strict";
import { setup, openWithinBudget, budgetOf } from "./browser.mjs";
import { PAGES } from "../../www/pages.js";

setup();

const HOSTILE = ["NaN", "Infinity", "-Infinity", "1e308", "-1e308", "0", "-0", "1e-320", "abc", "", "0x10", "1,2",
  ";;;", "1,0,0,0;", "%00", "<img src=x onerror=window.__pwned=1>", "1".repeat(400), "9".repeat(20), "-1", "2.5",
  "1e9", "0,0,0,0", "1,0,0,0;0,0,0,0", "1,0,0,0;1,0,0,0;1,0,0,0", "0,1,1,2", "5,4,3"];

function random(seed) {
  let x = seed >>> 0 || 1;
  return () => {
    x ^= x << 13; x ^= x >>> 17; x ^= x << 5; x >>>= 0;
    return x / 4294967296;
  };
}


for (const { name, html, state } of PAGES) {
  test(`${html}: 10 seeded hostile URLs, each shown or refused by name, nothing else`, async () => {
    const next = random(name.length * 7919);
    // The page's state keys, and the runtime's own: the time, the text size, the printed time.
    const keys = [...state.schema.map((entry) => entry.url), "t", "text", "print"];
    const budget = budgetOf(html);
    for (let k = 0; k < 10; k++) {
      const params = new URLSearchParams();
      const count = 1 + Math.floor(next() * 3);
      for (let i = 0; i < count; i++) params.set(keys[Math.floor(next() * keys.length)], HOSTILE[Math.floor(next() * HOSTILE.length)]);
      const query = `${html}?${params}`;
      const { page, context, problems, worst, budget: held } = await openWithinBudget(query, budget, 300, { reducedMotion: "reduce" });
      try {
        const found = await page.evaluate(() => {
          // What the page computed: everything but the refused fields' messages and the fields.
          const clone = document.body.cloneNode(true);
          for (const node of clone.querySelectorAll("[id$='-error'], input, textarea, select, script, style")) node.remove();
          return { text: clone.innerText, pwned: window.__pwned };
        });
        assert.doesNotMatch(found.text, /\bNaN\b|\bInfinity\b/, query);
        assert.equal(found.pwned, undefined, query);
        assert.deepEqual(problems, [], query);
      } finally {
        await context.close();
      }
      assert.ok(worst <= held, `${query}: a task of ${worst} ms on each of three loads (budget ${held} ms)`);
    }
  });
}
