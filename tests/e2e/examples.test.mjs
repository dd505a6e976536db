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
    // Both objects are drawn: their colours are on the WebGL canvas.
    const seen = await page.evaluate(() => {
      const canvas = document.querySelector("#scene");
      const copy = document.createElement("canvas");
      copy.width = canvas.width;
      copy.height = canvas.height;
      const ctx = copy.getContext("2d");
      ctx.drawImage(canvas, 0, 0);
      const data = ctx.getImageData(0, 0, copy.width, copy.height).data;
      let kli = 0, slerp = 0;
      for (let i = 0; i < data.length; i += 4) {
        const [r, g, b] = [data[i], data[i + 1], data[i + 2]];
        if (r > 150 && g < 120 && b < 80) kli++;
        if (r > 70 && r < 170 && g < 120 && b > 180) slerp++;
      }
      return { kli, slerp };
    });
    assert.ok(seen.kli > 500 && seen.slerp > 500, JSON.stringify(seen));
    assert.deepEqual(await axeViolations(page), []);
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});
