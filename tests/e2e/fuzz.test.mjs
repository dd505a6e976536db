// Seeded hostile URLs on every page: random keys of each page's schema given hostile values
// (hostile-urls.mjs). Each load must show no error outside the refused fields' messages, no NaN
// or Infinity in what the page computed (its readouts, tables and status), run no injected script,
// and hang on nothing. How long its tasks take beside the previous release's is the benchmark's
// (bench/long-tasks.mjs).
import { test } from "node:test";
import assert from "node:assert/strict";
import { setup, open } from "./browser.mjs";
import { HANG, seededQueries, watchLongTasks } from "./hostile-urls.mjs";
import { PAGES } from "../../www/pages.js";

setup();

for (const page of PAGES) {
  test(`${page.html}: 10 seeded hostile URLs, each shown or refused by name, nothing else`, async () => {
    for (const query of seededQueries(page)) {
      const { page: tab, context, problems } = await open(query, { init: watchLongTasks, reducedMotion: "reduce" });
      try {
        await tab.waitForTimeout(300);
        const found = await tab.evaluate(() => {
          // What the page computed: everything but the refused fields' messages and the fields.
          const clone = document.body.cloneNode(true);
          for (const node of clone.querySelectorAll("[id$='-error'], input, textarea, select, script, style")) node.remove();
          return { text: clone.innerText, pwned: window.__pwned, worst: Math.max(0, ...window.__longTasks) };
        });
        assert.doesNotMatch(found.text, /\bNaN\b|\bInfinity\b/, query);
        assert.equal(found.pwned, undefined, query);
        assert.deepEqual(problems, [], query);
        assert.ok(found.worst <= HANG, `${query}: a task of ${found.worst} ms`);
      } finally {
        await context.close();
      }
    }
  });
}
