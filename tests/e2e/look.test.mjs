// The pages at rest look as they did: a screenshot of each page (reduced motion, so at its first
// time), against the committed one in tests/e2e/look/, within a small pixel tolerance. A
// refactor of the runtime, the player or the run contract must not change what a reader sees.
// `KLI_LOOK=write node --test tests/e2e/look.test.mjs` records new screenshots (after a change
// meant to be seen: look at them before committing).
import { test } from "node:test";
import assert from "node:assert/strict";
import { readFile, writeFile, mkdir } from "node:fs/promises";
import { join } from "node:path";
import { artifacts, compare, open, root, setup } from "./browser.mjs";
import { PAGES } from "../../www/pages.js";

setup();

const LOOK = join(root, "tests/e2e/look");
/** What changes from load to load on a page at rest: the keyframes table's measured times, and
 *  the time the synchronisation page's map took to solve (its status and its table's last row). */
const MOVING = {
  "keyframes.html": ["#figures td:nth-child(6)", "#figures td:nth-child(7)"],
  "sync.html": ["#file-status", "#map-table tr:last-child td"],
};

/** What a page starts only as the reader nears it: the synchronisation page's built-in map. */
const NEARED = {
  "sync.html": async (page) => {
    await page.locator("#file-section").scrollIntoViewIfNeeded();
    await page.waitForFunction(() => /solved in/.test(document.querySelector("#file-status").textContent), undefined, { timeout: 60000 });
    await page.evaluate(() => scrollTo(0, 0));
  },
};

for (const { html } of PAGES) {
  test(`${html} at rest looks as it did (screenshot within tolerance)`, async () => {
    const { page, context, problems } = await open(html);
    try {
      // Everything drawn: the still views are painted in a task after the first frame, and a
      // sweep fills itself a point a task.
      await page.waitForFunction(() => !document.querySelector("#sweep-status") ||
        document.querySelector("#sweep-status").textContent.startsWith("Done"), undefined, { timeout: 60000 });
      await NEARED[html]?.(page);
      await page.waitForTimeout(600);
      const mask = (MOVING[html] ?? []).map((selector) => page.locator(selector));
      const shot = await page.screenshot({ fullPage: true, mask, animations: "disabled" });
      const file = join(LOOK, html.replace(".html", ".png"));
      if (process.env.KLI_LOOK === "write") {
        await mkdir(LOOK, { recursive: true });
        await writeFile(file, shot);
        return;
      }
      await writeFile(join(artifacts, `look-${html.replace(".html", ".png")}`), shot);
      const difference = await compare(page, shot, await readFile(file));
      assert.equal(difference.size, undefined, `the page's size changed: ${difference.size}`);
      assert.ok(difference.mean < 1.5 && difference.far < 0.01,
        `${html}: mean difference ${difference.mean.toFixed(3)}, ${(100 * difference.far).toFixed(2)}% of pixels far off ` +
        `(see test-artifacts/look-${html.replace(".html", ".png")})`);
      assert.deepEqual(problems, []);
    } finally {
      await context.close();
    }
  });
}
