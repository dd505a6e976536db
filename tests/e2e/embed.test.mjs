// One figure for an iframe (www/figure/index.html, listed on teach.html): the address names the
// view, the figure's attributes and a title; the frame shows the title and the figure drawn, and
// says what is wrong with an address it cannot show instead of an empty box. Nothing but the
// element's own attributes can be set from the address. The site's documents (math.html, teach.html)
// are checked here too: axe and 390 px.
import { test } from "node:test";
import assert from "node:assert/strict";
import { axeViolations, painted, setup, open } from "./browser.mjs";

setup();

/** The figure's painted pixels, once it shows a drawing. */
const figureDrawn = (page) => painted(page, "kli-figure", 2000);

test("a tour figure in a frame: its title, the figure drawn at its attributes, named for a screen reader, filling the frame", async () => {
  const { page, context, problems } = await open("figure/?view=slerp&s=0.25&title=SLERP%20a%20quarter%20of%20the%20way",
    { viewport: { width: 640, height: 480 } });
  try {
    assert.equal(await page.locator("h1").textContent(), "SLERP a quarter of the way");
    assert.equal(await page.title(), "SLERP a quarter of the way");
    assert.ok(await figureDrawn(page) > 2000);
    const figure = await page.evaluate(() => {
      const element = document.querySelector("kli-figure");
      const box = element.getBoundingClientRect();
      return { s: element.getAttribute("s"), label: element.shadowRoot.querySelector("canvas").getAttribute("aria-label"), height: box.height };
    });
    assert.equal(figure.s, "0.25");
    assert.equal(figure.label, "SLERP a quarter of the way");
    assert.ok(figure.height > 300, `the figure fills the frame (${figure.height} px of 480)`);
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});

test("an address the frame cannot show says why: an unknown view, an attribute the element does not have, a value out of range", async () => {
  for (const [query, said] of [
    ["?view=nope", /No figure named "nope".*slerp/],
    ["?view=slerp&onclick=alert(1)", /"onclick" is not an attribute of a kli figure/],
  ]) {
    const { page, context } = await open(`figure/${query}`);
    try {
      await page.waitForFunction(() => !document.getElementById("problem").hidden);
      assert.match(await page.locator("#problem").textContent(), said);
      assert.equal(await page.locator("kli-figure").count(), 0, `${query}: no empty figure beside the message`);
      assert.equal(await page.evaluate(() => document.querySelectorAll("[onclick]").length), 0);
    } finally {
      await context.close();
    }
  }
  // A value the figure refuses: the figure itself says so, as everywhere it is used.
  const { page, context } = await open("figure/?view=slerp&s=5");
  try {
    await page.waitForFunction(() => document.querySelector("kli-figure")?.message?.textContent);
    assert.match(await page.evaluate(() => document.querySelector("kli-figure").message.textContent), /\bs\b.*from 0 to 1/);
  } finally {
    await context.close();
  }
});

test("the site's documents and the frame meet WCAG 2.2 AA (axe) and fit 390 px", async () => {
  for (const address of ["math.html", "teach.html", "figure/?view=cover&angle=360&title=A%20full%20turn"]) {
    const { page, context, problems } = await open(address, { viewport: { width: 390, height: 800 } });
    try {
      await page.waitForLoadState("load");
      if (address.startsWith("figure/")) await figureDrawn(page);
      assert.deepEqual(await axeViolations(page), [], `${address}: axe`);
      assert.ok(await page.evaluate(() => document.documentElement.scrollWidth <= innerWidth), `${address} is wider than 390 px`);
      assert.deepEqual(problems, [], address);
    } finally {
      await context.close();
    }
  }
});

test("a figure is named for a screen reader while its module is still on its way", async () => {
  let release = () => {};
  const held = new Promise((resolve) => (release = resolve));
  const { page, context, problems } = await open("figure/?view=slerp&title=SLERP", {
    prepare: (context) => context.route(/learn_demo_bg\.wasm$/, async (route) => {
      await held;
      await route.continue();
    }),
  });
  try {
    await page.waitForFunction(() => document.querySelector("kli-figure")?.shadowRoot?.querySelector("canvas"));
    assert.equal(await page.evaluate(() => document.querySelector("kli-figure").run), null, "the module is held back");
    assert.equal(await page.evaluate(() => document.querySelector("kli-figure").shadowRoot.querySelector("canvas").getAttribute("aria-label")), "SLERP");
    release();
    assert.ok(await figureDrawn(page) > 2000);
    assert.deepEqual(problems, []);
  } finally {
    release();
    await context.close();
  }
});
