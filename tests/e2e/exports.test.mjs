// Saving from the pages as a teacher does: click, get a file. The SVG is real vector drawing
// that holds the curve; the PNG is twice the screen's resolution; the CSV and JSON rows are the
// package API's own values.
import { test } from "node:test";
import assert from "node:assert/strict";
import { readFile } from "node:fs/promises";
import { setup, open } from "./browser.mjs";

setup();

/** Clicks the save button and returns the download's file name and bytes. */
async function saved(page, what, format) {
  const [download] = await Promise.all([
    page.waitForEvent("download"),
    page.click(`button[data-save="${what}"][data-format="${format}"]`),
  ]);
  return { name: download.suggestedFilename(), bytes: await readFile(await download.path()) };
}

/** A CSV's provenance (its leading "# key = value" lines) and its table's lines. */
function readCsv(bytes) {
  const lines = bytes.toString("utf8").trim().split("\n");
  const comments = lines.filter((line) => line.startsWith("# "));
  const parameters = Object.fromEntries(comments.filter((line) => !line.startsWith("# unit of "))
    .map((line) => line.slice(2).split(" = ")).filter((kv) => kv.length === 2));
  return { comments, parameters, lines: lines.filter((line) => !line.startsWith("#")) };
}

/** A PNG's width and height, from its IHDR chunk. */
const pngSize = (bytes) => ({ width: bytes.readUInt32BE(16), height: bytes.readUInt32BE(20) });

/** Parses an SVG in the page: its root, its polylines' point counts and stroke colours. */
const parseSvg = (page, text) => page.evaluate((text) => {
  const doc = new DOMParser().parseFromString(text, "image/svg+xml");
  const error = doc.querySelector("parsererror");
  return {
    error: error ? error.textContent : null,
    root: doc.documentElement.localName,
    title: doc.querySelector("title")?.textContent,
    images: doc.querySelectorAll("image").length,
    polylines: Array.from(doc.querySelectorAll("polyline"), (p) => ({
      stroke: p.getAttribute("stroke"),
      points: p.getAttribute("points").trim().split(/\s+/).map((xy) => xy.split(",").map(Number)),
    })),
    circles: doc.querySelectorAll("circle").length,
    texts: Array.from(doc.querySelectorAll("text"), (t) => t.textContent),
  };
}, text);

test("KLI page: SVG of the Hopf sphere is vector and holds the curve; PNG at 2×; the path's CSV and JSON are the API's values", async () => {
  const { page, context, problems } = await open("?t=1.8", { deviceScaleFactor: 1 });
  try {
    // SVG: parses, no bitmap inside, the KLI curve as a polyline of many points inside the figure.
    const svg = await saved(page, "hopf", "svg");
    assert.equal(svg.name, "kli-hopf-t1.80.svg");
    const doc = await parseSvg(page, svg.bytes.toString("utf8"));
    assert.equal(doc.error, null);
    assert.equal(doc.root, "svg");
    assert.equal(doc.images, 0);
    const box = await page.locator("#hopf-canvas").boundingBox();
    const kli = doc.polylines.filter((p) => p.stroke === "#c2410c");
    const points = kli.flatMap((p) => p.points);
    assert.ok(points.length > 200, `${points.length} points of the KLI curve`);
    assert.ok(points.every(([x, y]) => x >= 0 && x <= box.width && y >= 0 && y <= box.height));
    // The curve runs from h(p) to h(r): the same figure drawn on the canvas has the KLI colour
    // along it (the SVG is not a different picture).
    const object = await parseSvg(page, (await saved(page, "object", "svg")).bytes.toString("utf8"));
    assert.ok(object.texts.includes("KLI  t = 1.80"), object.texts.join(" | "));
    const plots = await parseSvg(page, (await saved(page, "plots", "svg")).bytes.toString("utf8"));
    assert.ok(plots.polylines.length >= 4 && plots.error === null);
    // PNG: twice the CSS size.
    const png = await saved(page, "hopf", "png");
    assert.equal(png.name, "kli-hopf-t1.80.png");
    assert.deepEqual(pngSize(png.bytes), { width: Math.round(box.width * 2), height: Math.round(box.height * 2) });
    const film = await saved(page, "filmstrip", "png");
    assert.equal(film.name, "kli-filmstrip.png");
    // CSV and JSON against the package's own calls on the same pair.
    const csv = (await saved(page, "path", "csv"));
    assert.equal(csv.name, "kli-path-T11.66.csv");
    const { lines: rows, parameters, comments } = readCsv(csv.bytes);
    assert.equal(rows[0], "t,w,x,y,z,slerpParameter,distance,angleToTarget,hopfX,hopfY,hopfZ");
    const json = JSON.parse((await saved(page, "path", "json")).bytes.toString("utf8"));
    // Provenance: the run's parameters as the page was given them (its defaults here), and units.
    assert.deepEqual({ ...json.parameters, rule: undefined },
      { p: [0, 0, 0, 1], r: [0.5, 0.5, 0.5, 0.5], target: [0.5, 0.5, 0.5, 0.5], epsilon: 1e-5, delta: 0.01,
        integrator: "rk4", shortestPath: true, finalTime: 11.66, rule: undefined });
    assert.deepEqual(parameters, { p: "[0, 0, 0, 1]", r: "[0.5, 0.5, 0.5, 0.5]", target: "[0.5, 0.5, 0.5, 0.5]", epsilon: "0.00001",
      delta: "0.01", integrator: "rk4", shortestPath: "true", rule: parameters.rule, finalTime: "11.66" });
    assert.match(json.units.t, /flow's time/);
    assert.match(json.units.distance, /not an angle/);
    assert.match(json.units.angleToTarget, /degrees/);
    assert.ok(comments.some((line) => /^# unit of angleToTarget: degrees/.test(line)), comments.join("\n"));
    assert.match(json.source, /^kli \d+\.\d+\.\d+/);
    const api = await page.evaluate(async () => {
      const { kli, kliToSlerpParameter } = await import("./pkg/kli_demo.js");
      const p = [0, 0, 0, 1], r = [0.5, 0.5, 0.5, 0.5];
      const path = kli(p, r);
      const times = Array.from(path.times);
      return { times, quaternions: Array.from(path.quaternions), hopf: Array.from(path.hopfCurve), s: times.map((t) => kliToSlerpParameter(p, r, t)) };
    });
    assert.equal(rows.length - 1, api.times.length);
    assert.equal(json.samples.length, api.times.length);
    assert.equal(json.finalTime, 11.66);
    for (const k of [0, 1, 180, 500, api.times.length - 1]) {
      const row = rows[k + 1].split(",").map(Number);
      assert.equal(row[0], api.times[k]);
      assert.deepEqual(row.slice(1, 5), api.quaternions.slice(4 * k, 4 * k + 4));
      assert.deepEqual(row.slice(8, 11), api.hopf.slice(3 * k, 3 * k + 3));
      hopf(row.slice(1, 5)).forEach((c, j) => assert.ok(Math.abs(c - row[8 + j]) < 1e-12, "eq. 5 by hand"));
      // The angle to the target: twice the angle on S³ (acos of |q·r|), in degrees; 120° at t = 0.
      const dot = Math.abs(row.slice(1, 5).reduce((sum, c) => sum + c * 0.5, 0));
      const angle = (2 * Math.acos(Math.min(1, dot)) * 180) / Math.PI;
      assert.ok(Math.abs(row[7] - angle) < 1e-5, `angle at row ${k}: ${row[7]} vs ${angle}`);
      assert.equal(json.samples[k].angleToTarget, row[7]);
      assert.ok(Math.abs(row[5] - api.s[k]) < 1e-12, `s at row ${k}: ${row[5]} vs ${api.s[k]}`);
      const q = row.slice(1, 5), target = [0.5, 0.5, 0.5, 0.5];
      assert.ok(Math.abs(row[6] - Math.hypot(...q.map((c, i) => target[i] - c))) < 1e-15);
      assert.deepEqual(json.samples[k].quaternion, row.slice(1, 5));
      assert.equal(json.samples[k].t, row[0]);
    }
    assert.match(await page.locator("#save-status").textContent(), /^Saved the path as JSON\.$/);
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});

/** h(q) of paper eq. 5, [w, x, y, z] → S²: an independent reference. */
const hopf = ([a, b, c, d]) => [a * a + b * b - c * c - d * d, 2 * (a * d + b * c), 2 * (b * d - a * c)];

test("swarm page: every view as SVG, the sweep too; the swarm's CSV and JSON hold each oscillator", async () => {
  const { page, context, problems } = await open("swarm.html?n=40&seed=3");
  try {
    await page.click("#play");
    const sphere = await saved(page, "hopf", "svg");
    assert.match(sphere.name, /^kli-swarm-hopf-t\d+\.\d\d\.svg$/);
    const svg = sphere.bytes.toString("utf8");
    const doc = await parseSvg(page, svg);
    assert.equal(doc.error, null);
    assert.equal(doc.images, 0);
    // The oscillators' dots: one arc pair each, in one or two paths (front and back).
    assert.ok((svg.match(/a[\d.]+,[\d.]+ 0 1 0/g) ?? []).length >= 2 * 40, "the dots are vector arcs");
    for (const view of ["objects", "plots", "sweep"]) {
      const file = await saved(page, view, "svg");
      assert.equal((await parseSvg(page, file.bytes.toString("utf8"))).error, null, view);
    }
    const png = await saved(page, "objects", "png");
    const box = await page.locator("#swarm-objects").boundingBox();
    assert.deepEqual(pngSize(png.bytes), { width: Math.round(box.width * 2), height: Math.round(box.height * 2) });
    const csv = await saved(page, "swarm", "csv");
    assert.match(csv.name, /^kli-swarm-40-oscillators-t\d+\.\d\d\.csv$/);
    const table = readCsv(csv.bytes);
    const rows = table.lines.slice(1).map((r) => r.split(",").map(Number));
    assert.equal(rows.length, 40);
    assert.equal(table.parameters.count, "40");
    assert.equal(table.parameters.seed, "3");
    for (const [, i, w, x, y, z, hx, hy, hz] of rows) {
      assert.ok(Math.abs(Math.hypot(w, x, y, z) - 1) < 1e-12, `|q_${i}|`);
      hopf([w, x, y, z]).forEach((c, k) => assert.ok(Math.abs(c - [hx, hy, hz][k]) < 1e-12));
    }
    const json = JSON.parse((await saved(page, "swarm", "json")).bytes.toString("utf8"));
    assert.equal(json.oscillators.length, 40);
    // The swarm's options as the URL gave them, the page's defaults for the rest.
    assert.equal(json.parameters.count, 40);
    assert.equal(json.parameters.seed, 3);
    assert.equal(json.parameters.graph, "all");
    assert.ok(json.parameters.dt > 0, "the page's step");
    assert.ok(json.orderParameter >= 0 && json.orderParameter <= 1);
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});

test("keyframes page: the views as SVG; the curves' CSV rows are kliSpline's, squadSpline's and slerpSpline's values", async () => {
  const { page, context, problems } = await open("keyframes.html");
  try {
    for (const view of ["objects", "hopf", "plots"]) {
      const file = await saved(page, view, "svg");
      assert.match(file.name, new RegExp(`^kli-keyframes-.*-\\d+-keys-t\\d+\\.\\d\\d\\.svg$`));
      const doc = await parseSvg(page, file.bytes.toString("utf8"));
      assert.equal(doc.error, null, view);
      assert.equal(doc.images, 0, view);
    }
    const csv = await saved(page, "curves", "csv");
    const { lines, parameters } = readCsv(csv.bytes);
    assert.equal(lines[0], "t,curve,w,x,y,z,angularSpeed,hopfX,hopfY,hopfZ");
    const json = JSON.parse((await saved(page, "curves", "json")).bytes.toString("utf8"));
    const form = await page.evaluate(() => ({
      keys: document.querySelector("input[name=keys]").value.split(";").map((key) => key.split(",").map(Number)),
      smoothness: Number(document.querySelector("input[name=smoothness]").value),
    }));
    // The keys as given (unit, signs consistent here), their times (0, 1, … by default), smoothness.
    assert.equal(json.parameters.keys.length, form.keys.length);
    json.parameters.keys.forEach((key, i) => key.forEach((c, j) => assert.ok(Math.abs(c - form.keys[i][j] / Math.hypot(...form.keys[i])) < 1e-15)));
    assert.deepEqual(json.parameters.keyTimes, form.keys.map((_, i) => i));
    assert.equal(json.parameters.smoothness, form.smoothness);
    assert.equal(parameters.smoothness, String(form.smoothness));
    assert.match(json.units.angularSpeed, /radians/);
    const rows = lines.slice(1).map((line) => line.split(","));
    const picks = [0, 7, 300, rows.length / 3 - 1].flatMap((k) => [k, k + rows.length / 3, k + (2 * rows.length) / 3]);
    const expected = await page.evaluate(async (asked) => {
      const { kliSpline, squadSpline, slerpSpline } = await import("./pkg/keyframes_demo.js");
      const field = (name) => /** @type {HTMLInputElement} */ (document.querySelector(`input[name=${name}]`)).value;
      const keys = field("keys").split(";").map((key) => key.split(",").map(Number));
      // Empty times: the keys at 0, 1, 2, … (the default).
      const times = field("times").trim() ? { times: field("times").split(",").map(Number) } : {};
      const smoothness = Number(field("smoothness"));
      const curves = { chain: kliSpline(keys, { ...times, smoothness }), squad: squadSpline(keys, times), slerp: slerpSpline(keys, times) };
      return asked.map(([t, curve]) => Array.from(curves[curve].at(t)));
    }, picks.map((k) => [Number(rows[k][0]), rows[k][1]]));
    picks.forEach((k, i) => {
      const q = rows[k].slice(2, 6).map(Number);
      q.forEach((c, j) => assert.ok(Math.abs(c - expected[i][j]) < 1e-12, `${rows[k][1]} at t = ${rows[k][0]}: ${q} vs ${expected[i]}`));
      hopf(q).forEach((c, j) => assert.ok(Math.abs(c - Number(rows[k][7 + j])) < 1e-12));
    });
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});
