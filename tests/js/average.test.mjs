// kli/average against means computed without kli (tests/fixtures/average.json, written by
// bench/average_fixture.py: SciPy's Rotation.mean with weights in both quaternion orders, and the
// Karcher mean and the L1 median iterated on SciPy's rotation vectors). Random sets of 1 to 300
// rotations with random signs, noise of 1° to 60°, some with outliers, half weighted.
// Regenerate with `make fixtures`.
import { test } from "node:test";
import assert from "node:assert/strict";
import { readFileSync } from "node:fs";

const pkg = new URL("../../pkg/", import.meta.url);
const average = await import(new URL("average.js", pkg));
average.initSync({ module: readFileSync(new URL("average_bg.wasm", pkg)) });
const { averageRotations } = average;
const fixture = JSON.parse(readFileSync(new URL("../fixtures/average.json", import.meta.url)));

/** The rotation angle between a and b (either sign), radians: 4 atan2(|a − b|, |a + b|). */
function angle(a, b) {
  const sign = a.reduce((s, c, k) => s + c * b[k], 0) < 0 ? -1 : 1;
  const minus = Math.hypot(...a.map((c, k) => c - sign * b[k]));
  const plus = Math.hypot(...a.map((c, k) => c + sign * b[k]));
  return 4 * Math.atan2(minus, plus);
}
const xyzw = ([w, x, y, z]) => [x, y, z, w];

test("the fixture holds sets of every size, weighted and not", () => {
  const sizes = fixture.sets.map((s) => s.quaternions.length);
  assert.ok(fixture.sets.length >= 10 && Math.min(...sizes) === 1 && Math.max(...sizes) >= 300);
  assert.ok(fixture.sets.some((s) => s.weights) && fixture.sets.some((s) => !s.weights));
});

test("the chordal mean is SciPy's Rotation.mean, with weights, in both orders", () => {
  for (const [k, set] of fixture.sets.entries()) {
    const options = set.weights ? { weights: set.weights } : undefined;
    const first = averageRotations(set.quaternions, options).rotation;
    assert.ok(angle([...first], set.chordal.wxyz) < 1e-13, `set ${k}: ${angle([...first], set.chordal.wxyz)}`);
    const last = averageRotations(new Float64Array(set.quaternions.map(xyzw).flat()), { ...options, order: "xyzw" }).rotation;
    assert.ok(angle([...last], set.chordal.xyzw) < 1e-13, `set ${k}, xyzw`);
    // The data's order is not the mean's business.
    const reversed = averageRotations([...set.quaternions].reverse(), set.weights ? { weights: [...set.weights].reverse() } : undefined);
    assert.ok(angle([...reversed.rotation], [...first]) < 1e-13, `set ${k}, reversed`);
  }
});

test("the Karcher mean and the median are a second implementation's", () => {
  for (const [k, set] of fixture.sets.entries()) {
    const weights = set.weights ? { weights: set.weights } : {};
    const geodesic = averageRotations(set.quaternions, { ...weights, method: "geodesic" });
    assert.ok(angle([...geodesic.rotation], set.geodesic) < 1e-13, `set ${k}: Karcher off by ${angle([...geodesic.rotation], set.geodesic)}`);
    if (!set.median) continue;
    const median = averageRotations(set.quaternions, { ...weights, method: "median" });
    assert.ok(angle([...median.rotation], set.median) < 1e-12, `set ${k}: median off by ${angle([...median.rotation], set.median)}`);
  }
});
