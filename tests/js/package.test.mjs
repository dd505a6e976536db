// The built package (pkg/) as its users get it: packed with `npm pack`, installed into an empty
// project, imported by name in Node with initSync, bundled with esbuild, and type-checked with tsc.
import { test, before } from "node:test";
import assert from "node:assert/strict";
import { gunzipSync } from "node:zlib";
import { execFileSync } from "node:child_process";
import { mkdtempSync, writeFileSync, readFileSync, readdirSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";

const root = new URL("../../", import.meta.url).pathname;
const bin = (name) => join(root, "node_modules/.bin", name);
let project;

// `node file` prints one JSON line; returns it parsed.
const run = (file) => JSON.parse(execFileSync("node", [file], { cwd: project, encoding: "utf8" }));

before(() => {
  project = mkdtempSync(join(tmpdir(), "kli-package-"));
  const tarball = execFileSync("npm", ["pack", "--silent", "--pack-destination", project], {
    cwd: join(root, "pkg"),
    encoding: "utf8",
  }).trim().split("\n").pop();
  writeFileSync(join(project, "package.json"), JSON.stringify({ name: "consumer", private: true, type: "module" }));
  execFileSync("npm", ["install", "--no-audit", "--no-fund", "--offline", join(project, tarball)], { cwd: project, stdio: "ignore" });
});

test("the tarball holds every file the package needs, and only those", () => {
  const installed = readdirSync(join(project, "node_modules/kli")).sort();
  const entry = (m) => [`${m}.d.ts`, `${m}.js`, `${m}.node.js`, `${m}.production.js`, `${m}_bg.inline.js`, `${m}_bg.wasm`, `${m}_bg.wasm.d.ts`];
  assert.deepEqual(installed, ["LICENSE", "README.md", ...entry("kli"), "package.json", ...entry("spline"), ...entry("swarm"), ...entry("average"), ...entry("sync"), "three.d.ts", "three.js", "gltf.d.ts", "gltf.js", "resample.js"].sort());
  const manifest = JSON.parse(readFileSync(join(project, "node_modules/kli/package.json"), "utf8"));
  const cargo = readFileSync(join(root, "Cargo.toml"), "utf8");
  assert.equal(manifest.version, cargo.match(/^version = "(.*)"/m)[1]);
  assert.equal(manifest.type, "module");
  assert.equal(manifest.types, "kli.d.ts");
  assert.equal(manifest.sideEffects, false);
  assert.equal(manifest.license, "MIT");
  assert.match(readFileSync(join(project, "node_modules/kli/LICENSE"), "utf8"), /^MIT License/);
  assert.equal(manifest.engines.node, ">=20.19.0 <21 || >=22.12.0");
  // The repository, when Cargo.toml names one (and only then: never an invented address).
  const repository = cargo.split("[workspace.package]")[1].match(/^repository\s*=\s*"([^"]*)"/m)?.[1];
  assert.deepEqual(manifest.repository, repository && { type: "git", url: `git+${repository.replace(/\.git$/, "")}.git` });
});

test("each entry's inlined copy is its .wasm byte for byte, and init() uses it where the file cannot be fetched", async () => {
  const dir = join(project, "node_modules/kli");
  for (const m of ["kli", "swarm", "spline", "average", "sync"]) {
    const { default: base64 } = await import(join(dir, `${m}_bg.inline.js`));
    const bytes = gunzipSync(Buffer.from(base64, "base64"));
    assert.ok(bytes.equals(readFileSync(join(dir, `${m}_bg.wasm`))), m);
  }
  // The browser entry in Node: fetch cannot read file: URLs, so init() takes the inlined copy.
  writeFileSync(join(project, "fallback.mjs"), `
    import init, { kli } from "./node_modules/kli/kli.js";
    import initSpline, { kliSpline } from "./node_modules/kli/spline.js";
    await Promise.all([init(), initSpline()]);
    console.log(JSON.stringify([kli([0, 0, 0, 1], [0.5, 0.5, 0.5, 0.5]).finalTime, kliSpline([[1, 0, 0, 0], [0, 1, 0, 0]]).at(1)[1]]));
  `);
  assert.deepEqual(JSON.parse(execFileSync("node", ["fallback.mjs"], { cwd: project, encoding: "utf8" })), [11.66, 1]);
});

test("the production glue has no inlined copy: where the .wasm cannot be fetched, init() names the entry, the file and the way out", async () => {
  const dir = join(project, "node_modules/kli");
  const manifest = JSON.parse(readFileSync(join(dir, "package.json"), "utf8"));
  for (const m of ["kli", "swarm", "spline", "average", "sync"]) {
    const name = m === "kli" ? "kli" : `kli/${m}`;
    const conditions = manifest.exports[m === "kli" ? "." : `./${m}`];
    // Node keeps its own entry first; a production bundle gets the glue without the copy.
    assert.deepEqual(Object.keys(conditions), ["types", "node", "production", "default"], name);
    assert.equal(conditions.production, `./${m}.production.js`);
    const glue = readFileSync(join(dir, `${m}.production.js`), "utf8");
    assert.ok(!/import\(['"][^'"]*inline/.test(glue), `${m}.production.js imports an inlined copy`);
    // The same module otherwise: every export of the full glue, byte for byte but the loader's
    // call and the loader itself (the fallback to the inlined copy in the one, the refusal by
    // name in the other: each glue holds only its own).
    const loader = /\n\/\*\*\n \* The response for the \.wasm[^]*?\nasync function (__kli\w+)[^]*?\n\}\n/;
    const fullText = readFileSync(join(dir, `${m}.js`), "utf8");
    assert.equal(fullText.match(loader)?.[1], "__kliFallback", m);
    assert.equal(glue.match(loader)?.[1], "__kliFetch", m);
    const full = fullText.replace(loader, "\n").split("\n");
    const lean = glue.replace(loader, "\n").split("\n").slice(2);
    assert.equal(lean.length, full.length, m);
    assert.equal(lean.filter((line, i) => line !== full[i]).length, 1, m);
    assert.ok(!fullText.includes("could not load its WebAssembly"), `${m}.js holds the production glue's refusal`);
    // In Node fetch cannot read file: URLs: the browser's production glue refuses, by name.
    const { default: init } = await import(join(dir, `${m}.production.js`));
    await assert.rejects(init(), (error) => {
      assert.equal(error.kind, "not-initialised");
      assert.equal(error.argument, name);
      assert.ok(error.message.startsWith(`${name} could not load its WebAssembly from file://`), error.message);
      assert.match(error.message, new RegExp(`${m}_bg\\.wasm.*init\\(\\{ module_or_path \\}\\)`));
      return true;
    }, name);
  }
});

test("imports by name in Node with initSync and gives T = 11.66", () => {
  writeFileSync(join(project, "node.mjs"), `
    import { readFileSync } from "node:fs";
    import { initSync, kli, kliReachTime } from "kli";
    initSync({ module: readFileSync(new URL(import.meta.resolve("kli/kli_bg.wasm"))) });
    const path = kli([0, 0, 0, 1], [0.5, 0.5, 0.5, 0.5]);
    console.log(JSON.stringify({ T: path.finalTime, steps: path.steps, star: kliReachTime([0, 0, 0, 1], [0.5, 0.5, 0.5, 0.5], 1e-5) }));
  `);
  const { T, steps, star } = run("node.mjs");
  assert.ok(Math.abs(T - 11.66) < 1e-9, `T = ${T}`);
  assert.equal(steps, 1166);
  assert.ok(Math.abs(star - 11.6568) < 5e-5, `T* = ${star}`);
});

test("require() works for every entry in Node, as engines promises", () => {
  writeFileSync(join(project, "require.cjs"), `
    const { readFileSync } = require("node:fs");
    const out = {};
    for (const [entry, call] of [["kli", (m) => m.kli([0, 0, 0, 1], [0.5, 0.5, 0.5, 0.5]).finalTime],
      ["kli/swarm", (m) => new m.LoheSwarm({ count: 3 }).count], ["kli/spline", (m) => m.kliSpline([[1, 0, 0, 0], [0, 1, 0, 0]]).endTime],
      ["kli/average", (m) => m.averageRotations([[1, 0, 0, 0], [1, 0, 0, 0]]).rotation[0]],
      ["kli/sync", (m) => m.synchronizeRotations({ edges: [[0, 1]], relative: [[1, 0, 0, 0]] }).rotations.length]]) {
      const m = require(entry);
      const wasm = { kli: "kli/kli_bg.wasm", "kli/swarm": "kli/swarm_bg.wasm", "kli/spline": "kli/spline_bg.wasm", "kli/average": "kli/average_bg.wasm", "kli/sync": "kli/sync_bg.wasm" }[entry];
      m.initSync({ module: readFileSync(require.resolve(wasm)) });
      out[entry] = call(m);
    }
    console.log(JSON.stringify(out));
  `);
  const out = JSON.parse(execFileSync("node", ["require.cjs"], { cwd: project, encoding: "utf8" }));
  assert.deepEqual(out, { kli: 11.66, "kli/swarm": 3, "kli/spline": 1, "kli/average": 1, "kli/sync": 8 });
});

test("await init() works in Node for every entry, with no argument (the node export condition)", () => {
  writeFileSync(join(project, "init.mjs"), `
    import init, { kli } from "kli";
    import initSwarm, { LoheSwarm } from "kli/swarm";
    import initSpline, { kliSpline } from "kli/spline";
    await Promise.all([init(), initSwarm(), initSpline()]);
    const swarm = new LoheSwarm({ count: 3 });
    console.log(JSON.stringify({ T: kli([0, 0, 0, 1], [0.5, 0.5, 0.5, 0.5]).finalTime, count: swarm.count,
      hit: kliSpline([[1, 0, 0, 0], [0, 1, 0, 0]]).at(1)[1] }));
  `);
  assert.deepEqual(run("init.mjs"), { T: 11.66, count: 3, hit: 1 });
});

test("the kli/swarm entry loads its own module and synchronises a swarm", () => {
  writeFileSync(join(project, "swarm.mjs"), `
    import { readFileSync } from "node:fs";
    import { initSync, LoheSwarm } from "kli/swarm";
    import * as api from "kli";
    initSync({ module: readFileSync(new URL(import.meta.resolve("kli/swarm_bg.wasm"))) });
    const swarm = new LoheSwarm({ count: 300, coupling: 1, seed: 3 });
    const start = swarm.orderParameter;
    swarm.step(0.05, 600);
    let error;
    try { new LoheSwarm({ graph: "star" }); } catch (e) { error = { argument: e.argument, kind: e.kind }; }
    console.log(JSON.stringify({ start, end: swarm.orderParameter, time: swarm.time, points: swarm.hopfPoints().length,
      error, separate: !("LoheSwarm" in api) && !("kli" in (await import("kli/swarm"))) }));
  `);
  const { start, end, time, points, error, separate } = run("swarm.mjs");
  assert.ok(start < 0.3, `a uniform start: R = ${start}`);
  assert.ok(end > 1 - 1e-9, `synchronised: R = ${end}`);
  assert.ok(Math.abs(time - 30) < 1e-9, `time ${time}`);
  assert.equal(points, 900);
  assert.deepEqual(error, { argument: "graph", kind: "unknown-name" });
  assert.ok(separate, "each entry holds only its own API");
});

test("the kli/spline entry: the chain, Squad and piecewise SLERP through the same keys", () => {
  writeFileSync(join(project, "spline.mjs"), `
    import { readFileSync } from "node:fs";
    import { initSync, kliSpline, squadSpline, slerpSpline } from "kli/spline";
    initSync({ module: readFileSync(new URL(import.meta.resolve("kli/spline_bg.wasm"))) });
    const keys = [[1, 0, 0, 0], [0.8, 0.6, 0, 0], [0.6, 0, 0.8, 0], [0, 0, 0.6, 0.8]];
    const curves = [kliSpline(keys), squadSpline(keys), slerpSpline(keys)];
    const hit = curves.map((c) => keys.every((k, i) => Array.from(c.at(i)).every((x, j) => Math.abs(x - k[j]) < 1e-12)));
    const samples = curves[0].sample([0, 1.5, 3]).length;
    // A hold: the same key three times, the curve at rest.
    const hold = kliSpline([keys[1], keys[1], keys[1]], { times: [0, 0.7, 2] });
    const held = Array.from(hold.sample([0, 0.3, 1.1, 2])).every((x, i) => Math.abs(x - keys[1][i % 4]) < 1e-15);
    console.log(JSON.stringify({ hit, samples, residual: curves[0].residual, squadResidual: curves[1].residual ?? null,
      hold: { iterations: hold.iterations, residual: hold.residual, held } }));
  `);
  const { hit, samples, residual, squadResidual, hold } = run("spline.mjs");
  assert.deepEqual(hit, [true, true, true]);
  assert.equal(samples, 12);
  assert.ok(residual <= 1e-10, `residual ${residual}`);
  assert.equal(squadResidual, null);
  assert.deepEqual(hold, { iterations: 0, residual: 0, held: true });
});

test("errors thrown through the generated glue are Errors, and the module keeps working", () => {
  writeFileSync(join(project, "errors.mjs"), `
    import { readFileSync } from "node:fs";
    import { initSync, kli, kliExact, slerp } from "kli";
    initSync({ module: readFileSync(new URL(import.meta.resolve("kli/kli_bg.wasm"))) });
    const p = [0, 0, 0, 1], r = [0.5, 0.5, 0.5, 0.5];
    const attempts = [
      () => kli(p, [0, 0, 0, 0]),
      () => kli(p, r, { tolerance: -1 }),
      () => kli(p, r, { integrator: "rk5" }),
      () => kliExact(p, r, -1),
      () => slerp(p, [0, 0, 0, -1], 0.5, { shortestPath: false }),
      () => kli("abcd", r),
      () => kli(p, r, { step: undefined, tolerence: 1 }),
    ];
    const thrown = attempts.map((attempt) => {
      try { attempt(); return { message: "no error" }; } catch (e) { return { message: (e instanceof Error ? "" : "not an Error: ") + e.message, argument: e.argument, kind: e.kind }; }
    });
    const messages = thrown.map((t) => t.message);
    const arguments_ = thrown.map((t) => [t.argument, t.kind]);
    console.log(JSON.stringify({ messages, arguments_, T: kli(p, r, undefined).finalTime, T2: kli(p, r, null).finalTime }));
  `);
  const { messages, arguments_, T, T2 } = run("errors.mjs");
  const starts = ["r must be a quaternion", "tolerance must be a finite number > 0 (got -1)", "integrator must be",
    "t must be a finite number ≥ 0 (got -1)", "p and r are antipodal", "p must be an array of 4 numbers",
    'options has an unknown key "tolerence"'];
  messages.forEach((message, i) => assert.ok(message.startsWith(starts[i]), `${message} !~ ${starts[i]}`));
  // The same facts as properties, for code: the argument (in JavaScript's names) and the kind.
  assert.deepEqual(arguments_, [["r", "zero-length"], ["tolerance", "out-of-range"], ["integrator", "unknown-name"],
    ["t", "out-of-range"], ["shortestPath", "antipodal"], ["p", "invalid"], ["options", "invalid"]]);
  assert.equal(T, 11.66);
  assert.equal(T2, 11.66);
});

test("three.js and gl-matrix quaternions go in and come out as they are, scalar last", () => {
  // three.js and gl-matrix from the dev dependencies, the package from the tarball.
  writeFileSync(join(project, "three.mjs"), `
    import * as THREE from ${JSON.stringify(join(root, "node_modules/three/build/three.module.js"))};
    import { quat } from ${JSON.stringify(join(root, "node_modules/gl-matrix/esm/index.js"))};
    import init, { kli, kliExact, slerp, slerpBatch } from "kli";
    await init();
    const order = "xyzw";
    const p = new THREE.Quaternion(0, 0, 0, 1).setFromAxisAngle(new THREE.Vector3(0, 0, 1), Math.PI / 2);
    const r = new THREE.Quaternion(0.5, 0.5, 0.5, 0.5);
    const path = kli(p, r, { order });
    // kli's answer straight into three.js, and three.js's own slerp beside kli's.
    const mesh = new THREE.Object3D();
    mesh.quaternion.fromArray(kliExact(p, r, 2, { order }));
    const three = p.clone().slerp(r, 0.3).toArray();
    const ours = Array.from(slerp(p, r, 0.3, { order }));
    // gl-matrix's quat is a Float32Array [x, y, z, w].
    const a = quat.setAxisAngle(quat.create(), [1, 0, 0], 1), b = quat.setAxisAngle(quat.create(), [0, 1, 0], 2);
    const gl = Array.from(quat.slerp(quat.create(), a, b, 0.4));
    const batch = Array.from(slerpBatch(new Float64Array(a), new Float64Array(b), new Float64Array([0.4]), new Float64Array(4), { order }));
    const plain = Array.from(kliExact([p.w, p.x, p.y, p.z], [r.w, r.x, r.y, r.z], 2));
    console.log(JSON.stringify({ T: path.finalTime, target: Array.from(path.target), mesh: mesh.quaternion.toArray(), plain, three, ours, gl, batch }));
  `);
  const { T, target, mesh, plain, three, ours, gl, batch } = run("three.mjs");
  // The same pair as the paper's up to a turn of p: T is finite and the target is r, scalar last.
  assert.ok(T > 0 && T < 20, `T = ${T}`);
  assert.deepEqual(target, [0.5, 0.5, 0.5, 0.5]);
  assert.deepEqual(mesh, [plain[1], plain[2], plain[3], plain[0]]);
  three.forEach((c, i) => assert.ok(Math.abs(c - ours[i]) < 1e-6, `three.js ${three} vs kli ${ours}`));
  // gl-matrix works in float32.
  gl.forEach((c, i) => assert.ok(Math.abs(c - batch[i]) < 1e-6, `gl-matrix ${gl} vs kli ${batch}`));
});

test("kli/three: smoothTrack and smoothInterpolation put the chain through a three.js track", () => {
  // three.js is an optional peer: the project has it as an app would (here, the dev dependency).
  execFileSync("ln", ["-sfn", join(root, "node_modules/three"), join(project, "node_modules/three")]);
  writeFileSync(join(project, "three-smooth.mjs"), `
    import * as THREE from "three";
    import initSpline, { kliSpline } from "kli/spline";
    import { smoothTrack, smoothInterpolation, isKliError } from "kli/three";
    await initSpline();
    const q = (axis, angle) => new THREE.Quaternion().setFromAxisAngle(new THREE.Vector3(...axis).normalize(), angle);
    const keys = [q([1, 0, 0], 0), q([1, 0, 0], 1.2), q([0, 1, 0], 2.0), q([1, 1, 0], 0.5), q([0, 0, 1], 2.5)];
    const times = [0, 0.8, 1.5, 2.7, 3.2];
    const linear = new THREE.QuaternionKeyframeTrack(".quaternion", times, keys.flatMap((k) => [k.x, k.y, k.z, k.w]));
    const smooth = smoothTrack(linear, { fps: 60 });
    const live = smoothInterpolation(linear);
    const sampler = (track) => { const i = track.createInterpolant(new Float32Array(4)); return (t) => new THREE.Quaternion().fromArray(i.evaluate(t)); };
    // ω over [t, t + h] from two samples: 2 log(q(t + h) q(t)⁻¹) / h.
    const omega = (f, t, h) => {
      const d = f(t + h).multiply(f(t).invert());
      if (d.w < 0) d.set(-d.x, -d.y, -d.z, -d.w);
      const s = Math.hypot(d.x, d.y, d.z), angle = 2 * Math.atan2(s, d.w);
      return s === 0 ? [0, 0, 0] : [d.x, d.y, d.z].map((c) => (c / s) * angle / h);
    };
    // The jump of ω across each inner key.
    const jumps = (track, h = 1e-3) => { const f = sampler(track); return times.slice(1, -1).map((k) => { const b = omega(f, k - 2 * h, h), a = omega(f, k + h, h); return Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]); }); };
    // Every key hit (as q or −q), within single precision.
    const hit = times.map((t, i) => { const v = sampler(smooth)(t); return Math.abs(Math.abs(v.dot(keys[i])) - 1) < 1e-6 && Array.from(smooth.times).includes(Math.fround(t)); });
    const clip = new THREE.AnimationClip("tumble", -1, [smooth]);
    const parsed = THREE.AnimationClip.parse(THREE.AnimationClip.toJSON(clip));
    // The mixer on the live track gives the chain itself.
    const object = new THREE.Object3D(), mixer = new THREE.AnimationMixer(object);
    mixer.clipAction(new THREE.AnimationClip("live", -1, [live])).play();
    mixer.update(1.1);
    const chain = kliSpline(linear.values, { times: linear.times, order: "xyzw" });
    const expected = Array.from(chain.at(1.1));
    let refused;
    try { smoothTrack(linear, { fps: 0 }); } catch (e) { refused = [isKliError(e), e.argument, e.message]; }
    console.log(JSON.stringify({ linear: jumps(linear), smooth: jumps(smooth), live: jumps(live), hit, valid: smooth.validate(),
      name: smooth.name, samples: smooth.times.length, parsed: parsed.tracks[0].times.length, mixed: object.quaternion.toArray(), expected, refused }));
  `);
  const r = run("three-smooth.mjs");
  assert.deepEqual(r.hit, [true, true, true, true, true]);
  assert.equal(r.valid, true);
  assert.equal(r.name, ".quaternion");
  // 3.2 s at 60 a second, the keys' times among them: 193 samples, kept through toJSON and parse.
  assert.equal(r.samples, 193);
  assert.equal(r.parsed, 193);
  // three's linear track turns ω abruptly at each key (3.9–5.2 rad/s); the chain does not: at 60 fps
  // its resampled track jumps by about ω̇/60 at any sample (20× less), and live by the finite
  // difference's own ω̇·h (about 100× less).
  r.linear.forEach((j, k) => {
    assert.ok(j > 1, `linear jump ${j}`);
    assert.ok(r.smooth[k] < j / 20, `smoothTrack jump ${r.smooth[k]} against ${j}`);
    assert.ok(r.live[k] < j / 50, `smoothInterpolation jump ${r.live[k]} against ${j}`);
  });
  r.mixed.forEach((c, i) => assert.ok(Math.abs(c - r.expected[i]) < 1e-12, `mixer ${r.mixed} vs chain ${r.expected}`));
  assert.deepEqual(r.refused, [true, "fps", "fps must be a number from 1 to 1000 (got 0)"]);
});

test("kli/three: blendRotations blends THREE.Quaternions, arrays of them and tracks' values by the weighted chordal mean, in any order", () => {
  execFileSync("ln", ["-sfn", join(root, "node_modules/three"), join(project, "node_modules/three")]);
  writeFileSync(join(project, "three-blend.mjs"), `
    import * as THREE from "three";
    import initAverage, { averageRotations } from "kli/average";
    import { blendRotations, isKliError } from "kli/three";
    await initAverage();
    const q = (axis, angle) => new THREE.Quaternion().setFromAxisAngle(new THREE.Vector3(...axis).normalize(), angle);
    // Three poses of two bones; the second pose's first bone with the other sign (the same rotation).
    const poses = [[q([1, 0, 0], 0.4), q([0, 1, 0], 1.0)], [q([0, 1, 0], 0.9), q([1, 1, 0], 0.2)], [q([0, 0, 1], 1.3), q([0, 1, 1], 2.0)]];
    poses[1][0].set(-poses[1][0].x, -poses[1][0].y, -poses[1][0].z, -poses[1][0].w);
    const weights = [0.5, 0.3, 0.2];
    const bones = blendRotations(poses, weights);
    const reordered = blendRotations([poses[2], poses[0], poses[1]], [0.2, 0.5, 0.3]);
    const mean = (b) => Array.from(averageRotations(poses.map((p) => p[b].toArray()), { weights, order: "xyzw" }).rotation);
    const one = blendRotations(poses.map((p) => p[1]), weights, new THREE.Quaternion());
    // A key at a time: two tracks of three keys, the values scalar last as three.js keeps them.
    const track = (k) => new THREE.QuaternionKeyframeTrack(".quaternion", [0, 1, 2], [q([1, 0, 0], k), q([0, 1, 0], 2 * k), q([0, 0, 1], 3 * k)].flatMap((r) => r.toArray()));
    const [a, b] = [track(0.3), track(0.9)];
    const values = blendRotations([a.values, b.values], [1, 3], new Float32Array(12));
    const blended = new THREE.QuaternionKeyframeTrack(".quaternion", a.times, values);
    const keyMean = (k) => Array.from(averageRotations([a.values.slice(4 * k, 4 * k + 4), b.values.slice(4 * k, 4 * k + 4)], { weights: [1, 3], order: "xyzw" }).rotation);
    const refusals = [];
    for (const call of [() => blendRotations([], []), () => blendRotations([poses[0], poses[1][0]], [1, 1]), () => blendRotations(poses, [1, 1]),
      () => blendRotations(poses, [0, 0, 0]), () => blendRotations([a.values, b.values], [1, 1], new Float64Array(3)), () => blendRotations([[NaN, 0, 0, 1]], [1])]) {
      try { call(); refusals.push(null); } catch (e) { refusals.push([isKliError(e), e.argument]); }
    }
    console.log(JSON.stringify({ bones: bones.map((r) => r.toArray()), isQuaternion: bones.every((r) => r.isQuaternion), reordered: reordered.map((r) => r.toArray()),
      means: [mean(0), mean(1)], one: one.toArray(), values: Array.from(values), keyMeans: [0, 1, 2].flatMap(keyMean), valid: blended.validate(), refusals }));
  `);
  const r = run("three-blend.mjs");
  const same = (got, want, tolerance, what) => {
    const dot = got.reduce((s, c, i) => s + c * want[i], 0);
    assert.ok(Math.abs(Math.abs(dot) - 1) < tolerance, `${what}: ${got} against ${want}`);
  };
  assert.equal(r.isQuaternion, true);
  r.bones.forEach((bone, b) => {
    same(bone, r.means[b], 1e-15, `bone ${b} against averageRotations`);
    same(bone, r.reordered[b], 1e-15, `bone ${b} with the poses reordered`);
  });
  same(r.one, r.means[1], 1e-15, "one THREE.Quaternion a pose");
  for (let k = 0; k < 3; k++) same(r.values.slice(4 * k, 4 * k + 4), r.keyMeans.slice(4 * k, 4 * k + 4), 1e-7, `key ${k}`);
  assert.equal(r.valid, true);
  assert.deepEqual(r.refusals, [[true, "poses"], [true, "poses[1]"], [true, "poses"], [true, "weights"], [true, "out"], [true, "poses[0] (bone 0)"]]);
});

test("kli/gltf: smoothRotations replaces LINEAR rotation samplers with the chain, leaves the rest, survives a .glb", () => {
  const core = JSON.stringify(join(root, "node_modules/@gltf-transform/core/dist/index.js"));
  writeFileSync(join(project, "gltf-smooth.mjs"), `
    import { Document, NodeIO } from ${core};
    import * as THREE from "three";
    import initSpline from "kli/spline";
    import { smoothRotations, isKliError } from "kli/gltf";
    import { smoothTrack } from "kli/three";
    await initSpline();
    const q = (axis, angle) => new THREE.Quaternion().setFromAxisAngle(new THREE.Vector3(...axis).normalize(), angle).toArray();
    const keys = [q([1, 0, 0], 0), q([1, 0, 0], 1.2), q([0, 1, 0], 2.0), q([1, 1, 0], 0.5), q([0, 0, 1], 2.5)];
    const times = [0, 0.8, 1.5, 2.7, 3.2];
    const document = new Document();
    const buffer = document.createBuffer();
    const accessor = (type, array) => document.createAccessor().setType(type).setArray(array).setBuffer(buffer);
    const input = accessor("SCALAR", new Float32Array(times));
    const rotations = accessor("VEC4", new Float32Array(keys.flat()));
    const [a, b, c] = ["a", "b", "c"].map((name) => document.createNode(name));
    document.createScene().addChild(a).addChild(b).addChild(c);
    const sampler = (interpolation, output) => document.createAnimationSampler().setInput(input).setOutput(output).setInterpolation(interpolation);
    const linear = sampler("LINEAR", rotations), step = sampler("STEP", rotations);
    const moves = sampler("LINEAR", accessor("VEC3", new Float32Array(15)));
    document.createAnimation("tumble")
      .addSampler(linear).addSampler(step).addSampler(moves)
      .addChannel(document.createAnimationChannel().setTargetNode(a).setTargetPath("rotation").setSampler(linear))
      .addChannel(document.createAnimationChannel().setTargetNode(b).setTargetPath("rotation").setSampler(step))
      .addChannel(document.createAnimationChannel().setTargetNode(c).setTargetPath("translation").setSampler(moves));
    await document.transform(smoothRotations({ fps: 30 }));
    const smoothTimes = Array.from(linear.getInput().getArray()), smoothValues = Array.from(linear.getOutput().getArray());
    // The same resampling as kli/three's smoothTrack at 30 fps, bit for bit.
    const track = smoothTrack(new THREE.QuaternionKeyframeTrack(".quaternion", times, keys.flat()), { fps: 30 });
    const io = new NodeIO();
    const again = await io.readBinary(await io.writeBinary(document));
    const [reread] = again.getRoot().listAnimations()[0].listSamplers().filter((s) => s.getInterpolation() === "LINEAR" && s.getOutput().getType() === "VEC4");
    let refused;
    try { smoothRotations({ fps: 5000 }); } catch (e) { refused = [isKliError(e), e.argument]; }
    console.log(JSON.stringify({
      count: smoothTimes.length, keysKept: times.every((t) => smoothTimes.includes(Math.fround(t))),
      sameAsThree: JSON.stringify(smoothTimes) === JSON.stringify(Array.from(track.times)) && JSON.stringify(smoothValues) === JSON.stringify(Array.from(track.values)),
      stepKept: step.getInput() === input && step.getOutput() === rotations && step.getInterpolation() === "STEP",
      movesKept: moves.getInput() === input && moves.getOutput().getCount() === 5,
      interpolation: linear.getInterpolation(),
      rereadCount: reread.getInput().getCount(),
      rereadFirst: Array.from(reread.getOutput().getElement(0, [0, 0, 0, 0])),
      accessors: document.getRoot().listAccessors().length,
      refused,
    }));
  `);
  const r = run("gltf-smooth.mjs");
  // 3.2 s at 30 a second, every key on the grid: 97 samples.
  assert.equal(r.count, 97);
  assert.equal(r.keysKept, true);
  assert.equal(r.sameAsThree, true);
  assert.equal(r.stepKept, true);
  assert.equal(r.movesKept, true);
  assert.equal(r.interpolation, "LINEAR");
  assert.equal(r.rereadCount, 97);
  assert.deepEqual(r.rereadFirst, [0, 0, 0, 1]);
  // The keys' times and values are still used (by STEP and the translation): kept; two new ones.
  assert.equal(r.accessors, 5);
  assert.deepEqual(r.refused, [true, "fps"]);
});

test("bundles with esbuild and runs", () => {
  writeFileSync(join(project, "entry.mjs"), `
    import init, { initSync, kli } from "kli";
    import { readFileSync } from "node:fs";
    initSync({ module: readFileSync(process.argv[2]) });
    console.log(JSON.stringify({ T: kli([0, 0, 0, 1], [0.5, 0.5, 0.5, 0.5]).finalTime, init: typeof init }));
  `);
  execFileSync(bin("esbuild"), ["entry.mjs", "--bundle", "--format=esm", "--platform=node", "--outfile=bundle.mjs"], { cwd: project, stdio: "pipe" });
  const out = JSON.parse(execFileSync("node", ["bundle.mjs", join(project, "node_modules/kli/kli_bg.wasm")], { cwd: project, encoding: "utf8" }));
  assert.deepEqual(out, { T: 11.66, init: "function" });
});

test("the TypeScript types are precise: right use compiles, wrong use does not", () => {
  writeFileSync(join(project, "use.ts"), `
    import { kli, slerp, hopf, axisAngle, isKliError, type KliOptions, type KliPath, type Integrator, type KliError, type KliErrorKind } from "kli";
    import { LoheSwarm, isKliError as isSwarmError, type SwarmOptions } from "kli/swarm";
    import { kliSpline, isKliError as isSplineError, type KliSpline } from "kli/spline";
    // The .wasm subpath has types too (its raw exports, for bundlers that import wasm).
    import type { memory } from "kli/kli_bg.wasm";
    const raw: typeof memory | undefined = undefined;
    void raw;
    // The README's esbuild line: the .wasm's URL from a file loader, given to init.
    import init from "kli";
    import wasm from "kli/kli_bg.wasm";
    const url: string = wasm;
    void init({ module_or_path: url });
    const options: KliOptions = { tolerance: 1e-5, step: 0.01, maxTime: 100, integrator: "geodesic", shortestPath: true };
    const path: KliPath = kli([0, 0, 0, 1], new Float64Array([0.5, 0.5, 0.5, 0.5]), options);
    const T: number = path.finalTime;
    const q: Float64Array = path.exactAt(T);
    try {
      kli([0, 0, 0, 1], [0, 0, 0, 0]);
    } catch (e) {
      const error = e as KliError;
      const argument: string = error.argument;
      const kind: KliErrorKind = error.kind;
      const component: number | undefined = error.component;
      // @ts-expect-error: not a kind
      const wrong: KliErrorKind = "bad";
      void [argument, kind, component, wrong];
    }
    // The type guard, from every entry, narrows unknown to KliError.
    try {
      kli([0, 0, 0, 1], [0, 0, 0, 0]);
    } catch (e: unknown) {
      if (isKliError(e) && isSwarmError(e) && isSplineError(e)) {
        const kind: KliErrorKind = e.kind;
        void kind;
      }
      // @ts-expect-error: unknown until narrowed
      void e.argument;
    }
    const which: Integrator = path.integrator;
    const s: Float64Array = slerp([1, 0, 0, 0], [0, 1, 0, 0], 0.5);
    const h: Float64Array = hopf(q);
    const a: Float64Array = axisAngle(s);
    // @ts-expect-error: not an integrator
    kli([0, 0, 0, 1], [1, 0, 0, 0], { integrator: "rk5" });
    // @ts-expect-error: tolerance is a number
    kli([0, 0, 0, 1], [1, 0, 0, 0], { tolerance: "small" });
    // @ts-expect-error: unknown option
    kli([0, 0, 0, 1], [1, 0, 0, 0], { tolerence: 1e-3 });
    // @ts-expect-error: a quaternion is numbers
    kli("abcd", [1, 0, 0, 0]);
    // @ts-expect-error: finalTime is read-only
    path.finalTime = 3;
    // Scalar last, and { x, y, z, w } objects (a THREE.Quaternion's shape).
    const last: Float64Array = slerp({ x: 0, y: 0, z: 0, w: 1 }, [0, 1, 0, 0], 0.5, { order: "xyzw" });
    // @ts-expect-error: not an order
    slerp([1, 0, 0, 0], [0, 1, 0, 0], 0.5, { order: "zyxw" });
    // @ts-expect-error: an object needs all four
    hopf({ x: 0, y: 0, z: 1 });
    void last;
    const spline: KliSpline = kliSpline([[1, 0, 0, 0], [0, 1, 0, 0]], { smoothness: 0.5, times: [0, 2] });
    const w: Float64Array = spline.angularVelocity(1);
    const residual: number | undefined = spline.residual;
    // @ts-expect-error: smoothness is a number
    kliSpline([[1, 0, 0, 0], [0, 1, 0, 0]], { smoothness: "high" });
    void [w, residual];
    const swarm: LoheSwarm = new LoheSwarm({ count: 10, graph: "ring", startSpread: 0.3 } satisfies SwarmOptions);
    swarm.step(0.1, 5);
    const r: number = swarm.orderParameter;
    // @ts-expect-error: not a graph
    new LoheSwarm({ graph: "star" });
    // @ts-expect-error: unknown option
    new LoheSwarm({ colour: 1 });
    void r;
    export { T, q, which, h, a };
  `);
  writeFileSync(join(project, "tsconfig.json"), JSON.stringify({
    compilerOptions: { strict: true, noEmit: true, module: "nodenext", moduleResolution: "nodenext", target: "es2022", lib: ["esnext", "dom"], skipLibCheck: false },
    files: ["use.ts"],
  }));
  // With the newest library, and with es2022 (whose lib has no Symbol.dispose: the declarations
  // reference esnext.disposable themselves).
  for (const lib of [["esnext", "dom"], ["es2022", "dom"], ["es2022"]]) {
    writeFileSync(join(project, "tsconfig.json"), JSON.stringify({
      compilerOptions: { strict: true, noEmit: true, module: "nodenext", moduleResolution: "nodenext", target: "es2022", lib, skipLibCheck: false },
      files: ["use.ts"],
    }));
    try {
      execFileSync(bin("tsc"), ["-p", "tsconfig.json"], { cwd: project, encoding: "utf8" });
    } catch (e) {
      assert.fail(`tsc with lib ${lib}: ${e.stdout}${e.stderr}`);
    }
  }
});
