// Calls before init(), errors that agree, and types without the DOM (the built pkg/, as `make pkg`
// writes it). Each check that needs a module not yet initialised runs in a Node of its own.
import { test, before } from "node:test";
import assert from "node:assert/strict";
import { execFileSync } from "node:child_process";
import { mkdtempSync, mkdirSync, writeFileSync, readFileSync, readdirSync, symlinkSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";

const root = new URL("../../", import.meta.url).pathname;
const bin = (name) => join(root, "node_modules/.bin", name);
const WASM = { kli: "kli", "kli/spline": "spline", "kli/swarm": "swarm", "kli/average": "average", "kli/sync": "sync" };
let project;

// `node file` in the project prints one JSON line; returns it parsed.
function run(name, source) {
  writeFileSync(join(project, name), source);
  return JSON.parse(execFileSync("node", [name], { cwd: project, encoding: "utf8" }));
}

// A project that depends on the package (node_modules/kli is pkg/) and on three.js, as an app would.
before(() => {
  project = mkdtempSync(join(tmpdir(), "kli-init-"));
  writeFileSync(join(project, "package.json"), JSON.stringify({ name: "consumer", private: true, type: "module" }));
  mkdirSync(join(project, "node_modules"));
  symlinkSync(join(root, "pkg"), join(project, "node_modules/kli"));
  symlinkSync(join(root, "node_modules/three"), join(project, "node_modules/three"));
});

// What a call throws, as data: its class, kind, argument and message.
const CAUGHT = `
  const caught = (call) => {
    try { call(); return "no error"; } catch (e) {
      return { error: e instanceof Error, kind: e.kind, argument: e.argument, message: e.message };
    }
  };
`;

test("every function, constructor and method of each wasm entry throws kind \"not-initialised\" naming the entry before its init()", () => {
  for (const [entry, file] of Object.entries(WASM)) {
    const out = run(`before-${file}.mjs`, `
      import * as m from ${JSON.stringify(entry)};
      import { readFileSync } from "node:fs";
      ${CAUGHT}
      const calls = {};
      for (const [name, value] of Object.entries(m)) {
        if (typeof value !== "function" || ["default", "initSync", "isKliError"].includes(name)) continue;
        if (/^[A-Z]/.test(name)) {
          // A class with a constructor of its own (one without makes an empty object: no call).
          if (/^\\s*constructor\\(/m.test(value.toString())) calls["new " + name] = caught(() => new value());
          // A method, on an object that no call made (no call can before init()).
          const method = Object.getOwnPropertyNames(value.prototype).find((key) => !["constructor", "free"].includes(key) && !key.startsWith("__") && typeof Object.getOwnPropertyDescriptor(value.prototype, key).value === "function");
          if (method) calls[name + ".prototype." + method] = caught(() => value.prototype[method].call(Object.create(value.prototype), 0));
        } else {
          calls[name] = caught(() => value());
        }
      }
      m.initSync({ module: readFileSync(new URL(import.meta.resolve(${JSON.stringify(`kli/${file}_bg.wasm`)}))) });
      console.log(JSON.stringify({ calls, after: caught(() => m.isKliError(new Error())) }));
    `);
    const names = Object.keys(out.calls);
    assert.ok(names.length >= 2, `${entry}: only ${names}`);
    for (const [name, thrown] of Object.entries(out.calls)) {
      assert.deepEqual(thrown, {
        error: true,
        kind: "not-initialised",
        argument: entry,
        message: `${entry} is not initialised: call \`await init()\` from "${entry}" first`,
      }, `${entry}: ${name}`);
    }
  }
});

test("after init() the same calls work, and isKliError knows the Error", () => {
  const out = run("after.mjs", `
    import init, { slerp, isKliError } from "kli";
    import initSwarm, { LoheSwarm } from "kli/swarm";
    ${CAUGHT}
    let before;
    try { slerp([1, 0, 0, 0], [0, 1, 0, 0], 0.5); } catch (e) { before = isKliError(e); }
    await Promise.all([init(), initSwarm()]);
    console.log(JSON.stringify({ before, slerp: Array.from(slerp([1, 0, 0, 0], [0, 1, 0, 0], 1)), count: new LoheSwarm({ count: 3 }).count,
      again: caught(() => slerp([1, 0, 0, 0], [0, 1, 0, 0], 1)) === "no error" }));
  `);
  assert.deepEqual(out, { before: true, slerp: [0, 1, 0, 0], count: 3, again: true });
});

test("kli/three and kli/gltf before kli/spline's or kli/average's init() name the entry they use", async () => {
  const core = JSON.stringify(join(root, "node_modules/@gltf-transform/core/dist/index.js"));
  const out = run("three-before.mjs", `
    import * as THREE from "three";
    import { Document } from ${core};
    import { smoothTrack, smoothInterpolation, blendRotations } from "kli/three";
    import { smoothRotations } from "kli/gltf";
    ${CAUGHT}
    const track = new THREE.QuaternionKeyframeTrack(".quaternion", [0, 1], [0, 0, 0, 1, 0, 0, 1, 0]);
    const q = new THREE.Quaternion();
    const transform = smoothRotations({ fps: 30 });
    const never = { smoothTrack: caught(() => smoothTrack(track)), blend: caught(() => blendRotations([q, q], [1, 1])),
      gltf: caught(() => transform(new Document())) };
    // Imported, not initialised: the entry's own check, worded for the caller.
    const spline = await import("kli/spline"), average = await import("kli/average");
    const imported = { smoothTrack: caught(() => smoothTrack(track)), live: caught(() => smoothInterpolation(track)),
      oneKey: caught(() => smoothTrack(new THREE.QuaternionKeyframeTrack(".quaternion", [0], [0, 0, 0, 1]))),
      blend: caught(() => blendRotations([q, q], [1, 1])) };
    await spline.default();
    await average.default();
    console.log(JSON.stringify({ never, imported, after: [smoothTrack(track).times.length, blendRotations([q, q], [1, 1]).w] }));
  `);
  const expected = (entry, caller) => ({
    error: true, kind: "not-initialised", argument: entry,
    message: `${entry} is not initialised: ${caller} uses it, so call \`await init()\` from "${entry}" first`,
  });
  assert.deepEqual(out.never, {
    smoothTrack: expected("kli/spline", "kli/three's smoothTrack"),
    blend: expected("kli/average", "kli/three's blendRotations"),
    gltf: expected("kli/spline", "kli/gltf's smoothRotations"),
  });
  assert.deepEqual(out.imported, {
    smoothTrack: expected("kli/spline", "kli/three's smoothTrack"),
    live: expected("kli/spline", "kli/three's smoothInterpolation"),
    oneKey: expected("kli/spline", "kli/three's smoothTrack"),
    blend: expected("kli/average", "kli/three's blendRotations"),
  });
  assert.deepEqual(out.after, [61, 1]);
});

test("a bundle of kli/three's smoothTrack holds no kli/average (nor its .wasm), and one of blendRotations no kli/spline", () => {
  for (const [name, use, absent] of [
    ["tracks", `import initSpline from "kli/spline"; import { smoothTrack } from "kli/three"; await initSpline(); console.log(smoothTrack);`, "average"],
    ["blend", `import initAverage from "kli/average"; import { blendRotations } from "kli/three"; await initAverage(); console.log(blendRotations);`, "spline"],
  ]) {
    writeFileSync(join(project, `${name}.mjs`), use);
    // esbuild, splitting as an app's build would (the inlined .wasm is a chunk of its own).
    execFileSync(bin("esbuild"), [`${name}.mjs`, "--bundle", "--format=esm", "--splitting", `--outdir=esbuild-${name}`, "--platform=browser", "--external:three"], { cwd: project, stdio: "pipe" });
    const files = readdirSync(join(project, `esbuild-${name}`));
    assert.ok(files.some((f) => f.startsWith(`${name === "tracks" ? "spline" : "average"}_bg.inline`)), `esbuild ${name}: ${files}`);
    assert.deepEqual(files.filter((f) => f.includes(absent)), [], `esbuild ${name}: ${files}`);
    const code = files.map((f) => readFileSync(join(project, `esbuild-${name}`, f), "utf8")).join("\n");
    assert.ok(!code.includes(`kli/${absent}`), `esbuild ${name}: kli/${absent}'s code is in the bundle`);
    // Vite, which emits the .wasm of every module in the graph (its new URL(…, import.meta.url)),
    // even of one whose code it then shakes out: a static import of kli/average was enough.
    const app = join(project, `vite-${name}`);
    mkdirSync(app);
    writeFileSync(join(app, "index.html"), `<script type="module" src="./main.mjs"></script>`);
    writeFileSync(join(app, "main.mjs"), use);
    execFileSync("node", [join(root, "node_modules/vite/bin/vite.js"), "build", app, "--logLevel", "silent", "--outDir", join(app, "dist")],
      { cwd: project, stdio: "pipe" });
    const assets = readdirSync(join(app, "dist/assets"));
    assert.ok(assets.some((f) => f.startsWith(name === "tracks" ? "spline_bg" : "average_bg")), `vite ${name}: ${assets}`);
    assert.deepEqual(assets.filter((f) => f.includes(absent)), [], `vite ${name}: ${assets}`);
  }
});

test("the wrong-length kinds agree: a single call's quaternion and a batch call's arrays, and kli/three's tracks", () => {
  const out = run("lengths.mjs", `
    import * as THREE from "three";
    import init, { slerp, hopf, fromAxisAngle, slerpBatch, kli } from "kli";
    import initSpline, { kliSpline } from "kli/spline";
    import { smoothTrack } from "kli/three";
    await Promise.all([init(), initSpline()]);
    ${CAUGHT}
    const q = [1, 0, 0, 0];
    console.log(JSON.stringify({
      short: caught(() => slerp([0, 0, 1], q, 0.5)),
      long: caught(() => slerp(q, new Float32Array(5), 0.5)),
      vector: caught(() => fromAxisAngle([0, 1], 1)),
      object: caught(() => hopf({ length: 2, 0: 1, 1: 0 })),
      batch: caught(() => slerpBatch(new Float64Array(4), new Float64Array(8), new Float64Array(1), new Float64Array(4))),
      out: caught(() => kliSpline([q, [0, 1, 0, 0]]).at(0.5, new Float64Array(3))),
      notArray: caught(() => kli("abcd", q)),
      vectorTrack: caught(() => smoothTrack(new THREE.VectorKeyframeTrack(".position", [0, 1], [0, 0, 0, 1, 1, 1]))),
      shortTrack: caught(() => smoothTrack({ name: ".quaternion", times: new Float32Array(2), values: new Float32Array(7) })),
      nanKey: caught(() => smoothTrack(new THREE.QuaternionKeyframeTrack(".quaternion", [0, 0.8, 2], [0, 0, 0, 1, NaN, 0, 0, 1, 0, 0, 1, 0]))),
    }));
  `);
  const error = (kind, argument, message) => ({ error: true, kind, argument, message });
  assert.deepEqual(out.short, error("wrong-length", "p", "p must hold 4 numbers (got 3)"));
  assert.deepEqual(out.long, error("wrong-length", "r", "r must hold 4 numbers (got 5)"));
  assert.deepEqual(out.vector, error("wrong-length", "axis", "axis must hold 3 numbers (got 2)"));
  assert.deepEqual(out.object, error("wrong-length", "q", "q must hold 4 numbers (got 2)"));
  assert.deepEqual(out.batch, error("wrong-length", "ends", "ends must hold 4 numbers per s value: 4 for 1 s value (got 8)"));
  assert.deepEqual(out.out, error("wrong-length", "out", "out must hold 4 numbers (got 3)"));
  // Not an array at all: not a length.
  assert.equal(out.notArray.kind, "invalid");
  // kli/three names a track's type and counts its keys, never "4 values a time".
  assert.deepEqual(out.vectorTrack, error("invalid", "track",
    'track must be a THREE.QuaternionKeyframeTrack: ".position" is a vector track, and only rotations are smoothed'));
  assert.deepEqual(out.shortTrack, error("wrong-length", "track", "track must hold 4 values (a quaternion) per key: 8 for its 2 keys (got 7)"));
  // A bad key is the track's, by its index and time: never kliSpline's keys[1], which the caller never passed.
  assert.equal(out.nanKey.kind, "not-finite");
  assert.equal(out.nanKey.argument, "track");
  assert.match(out.nanKey.message, /^track key 1 \(at 0\.8\d* s\) must be a quaternion of 4 finite numbers \[x, y, z, w\], not all zero: its x component is NaN$/);
});

test("the types need no DOM: a Node project (lib es2022, no @types) imports every entry, and `document` is an error there", () => {
  // three.js's own types, as @types/three would give them, without the DOM.
  writeFileSync(join(project, "three-types.d.ts"), `
    declare module "three" {
      export class Quaternion { x: number; y: number; z: number; w: number; }
      export class QuaternionKeyframeTrack { constructor(name: string, times: ArrayLike<number>, values: ArrayLike<number>); name: string; times: Float32Array; values: Float32Array; }
    }
  `);
  writeFileSync(join(project, "node.ts"), `
    import init, { initSync, slerp, type InitInput, type KliErrorKind } from "kli";
    import initSwarm, { LoheSwarm } from "kli/swarm";
    import initSpline, { kliSpline } from "kli/spline";
    import initAverage, { averageRotations } from "kli/average";
    import initSync_, { synchronizeRotations } from "kli/sync";
    import { smoothTrack, blendRotations, isKliError } from "kli/three";
    import { smoothRotations } from "kli/gltf";
    import wasm, { memory } from "kli/kli_bg.wasm";
    const bytes = new Uint8Array(0);
    void init({ module_or_path: bytes });
    initSync({ module: bytes.buffer });
    const input: InitInput = "kli_bg.wasm";
    // @ts-expect-error: not an input (the DOM's WebAssembly.Module is an empty interface, which takes anything; here it is an object)
    void init(42);
    const kind: KliErrorKind = "not-initialised";
    const url: string = wasm;
    void [initSwarm, initSpline, initAverage, initSync_, LoheSwarm, kliSpline, averageRotations, synchronizeRotations, smoothTrack, blendRotations, isKliError, smoothRotations, slerp, input, kind, url, memory.buffer];
    // @ts-expect-error: no DOM in a Node project, and kli adds none
    void document.title;
    // @ts-expect-error: nor its other globals
    void window;
  `);
  // A page's project (the DOM library): its own URL, Response and WebAssembly.Module are taken.
  writeFileSync(join(project, "page.ts"), `
    import init, { initSync } from "kli";
    import initSpline from "kli/spline";
    void init(new URL("kli_bg.wasm", import.meta.url));
    void initSpline({ module_or_path: fetch("spline_bg.wasm") });
    void init(new Response(new Uint8Array(0)));
    initSync({ module: new WebAssembly.Module(new Uint8Array(0)) });
    void document.title;
  `);
  for (const [file, lib, types] of [["node.ts", ["es2022"], []], ["page.ts", ["es2022", "dom"], []], ["page.ts", ["esnext", "dom"], []]]) {
    writeFileSync(join(project, "tsconfig.json"), JSON.stringify({
      compilerOptions: { strict: true, noEmit: true, module: "nodenext", moduleResolution: "nodenext", target: "es2022", lib, types, skipLibCheck: false },
      files: [file, "three-types.d.ts"],
    }));
    try {
      execFileSync(bin("tsc"), ["-p", "tsconfig.json"], { cwd: project, encoding: "utf8" });
    } catch (e) {
      assert.fail(`tsc ${file} with lib ${lib}: ${e.stdout}${e.stderr}`);
    }
  }
  // And the declarations say so: no reference to the DOM library is left in any of them.
  for (const file of readdirSync(join(root, "pkg")).filter((f) => f.endsWith(".d.ts"))) {
    assert.ok(!readFileSync(join(root, "pkg", file), "utf8").includes('lib="dom"'), file);
  }
});
