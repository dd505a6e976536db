// Seeded hostile URLs on every page: random keys of each page's schema given hostile values
// (hostile-urls.mjs). Each load must show no error outside the refused fields' messages, no NaN
// or Infinity in what the page computed (its readouts, tables and status), run no injected script,
// and hang on nothing. How long its tasks take beside the previous release's is the benchmark's
// (bench/long-tasks.mjs).
import { describe, test } from "node:test";
import assert from "node:assert/strict";
import { setup, blank, visit } from "./browser.mjs";
import { HANG, seededQueries, watchLongTasks } from "./hostile-urls.mjs";
import { PAGES } from "../../www/pages.js";

setup();

// Two pages at a time, each in a context of its own: a load waits on its worker and for the 300 ms
// after it, so one page at a time left a core idle (alone: 32 s for 25 core-seconds, against 19 s
// for 27 two at a time), in `make test` beside the Rust lane's wasm tests, themselves mostly on
// one core.
describe("each page", { concurrency: 2 }, () => {
  for (const page of PAGES) {
    test(`${page.html}: 10 seeded hostile URLs, each shown or refused by name, nothing else`, async () => {
      // One context for the page's ten URLs, each a document of its own: the module comes from the
      // context's cache after the first, which no answer here depends on (the six pages took 89 s
      // with a fresh context a URL, 54 s so).
      const { page: tab, context, problems } = await blank({ init: watchLongTasks });
      try {
        for (const query of seededQueries(page)) {
          // The last document's requests, cut off by leaving it, are not this URL's problems.
          await tab.goto("about:blank");
          problems.length = 0;
          await visit(tab, query);
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
        }
      } finally {
        await context.close();
      }
    });
  }
});
