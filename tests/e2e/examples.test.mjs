// The examples as a reader opens them: the three.js page (www/examples/three.html), with the
// package and three.js served locally through an import map.
import { test } from "node:test";
import assert from "node:assert/strict";
import { setup, open, axeViolations } from "./browser.mjs";

setup();

/** Slerp(p, r; s) by Shoemake's formula, [x, y, z, w]: an independent reference. */
function slerpXyzw(p, r, s) {
  const cos = p.reduce((sum, c, i) => sum + c * r[i], 0);
  const angle = Math.acos(cos);
  const [a, b] = [Math.sin((1 - s) * angle) / Math.sin(angle), Math.sin(s * angle) / Math.sin(angle)];
  return p.map((c, i) => a * c + b * r[i]);
}

test("three.js example: kli turns the scene's objects, THREE.Quaternion in, [x, y, z, w] out", async () => {
  const { page, context, problems } = await open("examples/three.html");
  try {
    const time = page.locator("#time");
    await time.fill("1.8");
    await page.waitForFunction(() => document.querySelector("#rotation").textContent.includes("t = 1.80"));
    const text = await page.locator("#rotation").textContent();
    const [kli, slerp] = [...text.matchAll(/\(([^)]*)\)/g)].map((m) => m[1].split(", ").map(Number));
    // MATH.md, Table 1 corrected: q(1.8) = 0.4364 + 0.4364i + 0.4364j + 0.6548k, here scalar last.
    assert.deepEqual(kli, [0.4364, 0.4364, 0.6548, 0.4364]);
    const T = Number(await time.getAttribute("max"));
    assert.ok(Math.abs(T - 11.66) < 1e-9, `T = ${T}`);
    slerpXyzw([0, 0, 1, 0], [0.5, 0.5, 0.5, 0.5], 1.8 / T).forEach((c, i) => assert.ok(Math.abs(c - slerp[i]) < 6e-5, `${slerp} vs ${c}`));
    // Both objects are drawn: their colours are on the screen, where the WebGL canvas shows
    // them (its drawing buffer is not kept between frames, so the test reads the screen).
    const shot = (await page.locator("#scene").screenshot()).toString("base64");
    const seen = await page.evaluate(async (png) => {
      const bytes = Uint8Array.from(atob(png), (c) => c.charCodeAt(0));
      const image = await createImageBitmap(new Blob([bytes], { type: "image/png" }));
      const copy = document.createElement("canvas");
      copy.width = image.width;
      copy.height = image.height;
      const ctx = copy.getContext("2d");
      ctx.drawImage(image, 0, 0);
      const data = ctx.getImageData(0, 0, copy.width, copy.height).data;
      let kli = 0, slerp = 0;
      for (let i = 0; i < data.length; i += 4) {
        const [r, g, b] = [data[i], data[i + 1], data[i + 2]];
        if (r > 150 && g < 120 && b < 80) kli++;
        if (r > 70 && r < 170 && g < 120 && b > 180) slerp++;
      }
      return { kli, slerp };
    }, shot);
    assert.ok(seen.kli > 500 && seen.slerp > 500, JSON.stringify(seen));
    assert.deepEqual(await axeViolations(page), []);
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});

/** Each <kli-figure>'s canvas: non-blank pixels, a hash of them, its text alternative and message. */
const figures = (page) => page.evaluate(() => Array.from(document.querySelectorAll("kli-figure"), (figure) => {
  const canvas = figure.shadowRoot.querySelector("canvas");
  const data = canvas.getContext("2d").getImageData(0, 0, canvas.width, canvas.height).data;
  let drawn = 0, hash = 0;
  for (let i = 0; i < data.length; i += 4) {
    if (data[i] < 250 || data[i + 1] < 250 || data[i + 2] < 250) drawn++;
    hash = (hash * 31 + data[i] + 7 * data[i + 1] + 13 * data[i + 2]) % 1000000007;
  }
  const box = figure.getBoundingClientRect();
  return { id: figure.id, drawn, hash, width: box.width, canvasWidth: canvas.width, label: canvas.getAttribute("aria-label"), message: figure.shadowRoot.querySelector("p").textContent };
}));

test("<kli-figure>: three figures in running text, one module shared, sized by CSS, attributes live", async () => {
  const { page, context, problems } = await open("examples/figures.html");
  try {
    await page.waitForFunction(() => Array.from(document.querySelectorAll("kli-figure"), (f) => f.run).every(Boolean));
    await page.waitForTimeout(100);
    const before = await figures(page);
    assert.deepEqual(before.map((f) => f.id), ["hopf", "object", "keyframes"]);
    for (const f of before) assert.ok(f.drawn > 1000, `${f.id} is blank`);
    // Sized by CSS: the floated one is narrower; the backing store follows the box.
    const [hopf, object] = before;
    assert.ok(object.width < hopf.width * 0.6, `${object.width} vs ${hopf.width}`);
    assert.equal(object.canvasWidth, Math.round(object.width - 2));
    assert.equal(object.label, "The aircraft at t = 1.8 under KLI (left) and SLERP (right)");
    // One module for the two KLI figures, one for the keyframes, none for the swarm.
    const wasm = await page.evaluate(() => performance.getEntriesByType("resource").map((e) => e.name.split("/").pop()).filter((n) => n.endsWith(".wasm")).sort());
    assert.deepEqual(wasm, ["keyframes_demo_bg.wasm", "kli_demo_bg.wasm"]);
    // Live attributes: the long way round redraws the first figure; a new view, another picture.
    await page.click("#long-way");
    await page.waitForFunction((hash) => {
      const canvas = document.querySelector("#hopf").shadowRoot.querySelector("canvas");
      const data = canvas.getContext("2d").getImageData(0, 0, canvas.width, canvas.height).data;
      let h = 0;
      for (let i = 0; i < data.length; i += 4) h = (h * 31 + data[i] + 7 * data[i + 1] + 13 * data[i + 2]) % 1000000007;
      return h !== hash;
    }, hopf.hash);
    assert.equal(await page.evaluate(() => document.querySelector("#hopf").run.summary.flipped), false);
    assert.ok(Math.abs(await page.evaluate(() => document.querySelector("#hopf").end) - 11.66) > 0.5, "the long way takes longer");
    await page.evaluate(() => {
      document.querySelector("#object").removeAttribute("label");
      document.querySelector("#object").setAttribute("view", "plots");
    });
    await page.waitForFunction(() => document.querySelector("#object").shadowRoot.querySelector("canvas").getAttribute("aria-label").startsWith("Distance to the target"));
    // A refused attribute is named in the figure, and a corrected one clears it.
    await page.evaluate(() => document.querySelector("#object").setAttribute("p", "1,2"));
    await page.waitForFunction(() => document.querySelector("#object").shadowRoot.querySelector("p").textContent !== "");
    assert.match((await figures(page))[1].message, /^kli-figure: p must hold 4 numbers \(got 2\)/);
    await page.evaluate(() => document.querySelector("#object").setAttribute("p", "1,0,0,0"));
    await page.waitForFunction(() => document.querySelector("#object").shadowRoot.querySelector("p").textContent === "");
    assert.deepEqual(await axeViolations(page), []);
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});

test("<kli-figure> at 390 px: the page fits, the floated figure goes full width; autoplay animates", async () => {
  const { page, context, problems } = await open("examples/figures.html", { moving: true, viewport: { width: 390, height: 844 } });
  try {
    await page.waitForFunction(() => Array.from(document.querySelectorAll("kli-figure"), (f) => f.run).every(Boolean));
    assert.ok(await page.evaluate(() => document.documentElement.scrollWidth <= 390));
    const [hopf, object] = await figures(page);
    assert.ok(Math.abs(object.width - hopf.width) < 1, `${object.width} vs ${hopf.width}`);
    const t0 = await page.evaluate(() => document.querySelector("#hopf").t);
    await page.waitForTimeout(300);
    assert.ok(await page.evaluate(() => document.querySelector("#hopf").t) > t0, "autoplay advances the time");
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});

test("animation example: three.js's linear track beside kli/three's smooth one, |ω| under each", async () => {
  const { page, context, problems } = await open("examples/animation.html");
  try {
    const text = await page.locator("#jumps").textContent();
    const [linear, smooth] = [...text.matchAll(/([\d.]+) rad\/s/g)].map((m) => Number(m[1]));
    // three's track turns abruptly at the keys; the chain's |ω| is continuous there.
    assert.ok(linear > 1 && smooth < linear / 20, text);
    // Scrubbing moves both objects, and the two differ between keys (linear ≠ smooth).
    await page.locator("#time").fill("2.3");
    await page.waitForFunction(() => document.querySelector("#readout").textContent.startsWith("t = 2.30"));
    // Both plots are drawn in their colours.
    const drawn = await page.evaluate(() => ["#linear-speed", "#smooth-speed"].map((id) => {
      const canvas = document.querySelector(id);
      const data = canvas.getContext("2d").getImageData(0, 0, canvas.width, canvas.height).data;
      let coloured = 0;
      for (let i = 0; i < data.length; i += 4) if (data[i + 3] > 0 && Math.abs(data[i] - data[i + 2]) > 60) coloured++;
      return coloured;
    }));
    assert.ok(drawn.every((n) => n > 300), `plots ${drawn}`);
    assert.deepEqual(await axeViolations(page), []);
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});
