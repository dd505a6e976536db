// Every JavaScript block of the README, run as written, in order, as a reader would paste them into
// a Node project that has kli installed (a folder whose node_modules/kli is the built package):
// each block one module, after a prelude that defines only the names the block uses without
// defining them (a mesh, a track, a pose graph file, …). Blocks run in one process, so an entry
// initialised by an earlier block is initialised for a later one, as on the page.
import { test } from "node:test";
import assert from "node:assert/strict";
import { execFileSync } from "node:child_process";
import { mkdirSync, mkdtempSync, readFileSync, symlinkSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";

const root = new URL("../../", import.meta.url).pathname;
const readme = readFileSync(join(root, "README.md"), "utf8");
const blocks = [...readme.matchAll(/^```js\n([\s\S]*?)^```$/gm)].map((m) => m[1]);

// What a block may use without defining it, and how the test defines it. A block that names one
// of these gets its definition first, unless it imports or declares the name itself.
const H = Math.SQRT1_2;
const GIVEN = {
  THREE: `import * as THREE from "three";`,
  kliExact: `import { kliExact } from "kli";`,
  slerpBatch: `import { slerpBatch } from "kli";`,
  kli: `import { kli } from "kli";`,
  blendRotations: `import { blendRotations } from "kli/average";`,
  mesh: `const mesh = new THREE.Mesh();`,
  p: `const p = [0, 0, 1, 0];`,
  r: `const r = [0.5, 0.5, 0.5, 0.5];`,
  t: `const t = 1.8;`,
  starts: `const starts = new Float64Array([0, 0, 0, 1, 0, 0, 0, 1]);`,
  ends: `const ends = new Float32Array([0, 0, 1, 0, ${H}, 0, 0, ${H}]);`,
  s: `const s = [0.5, 0.25];`,
  out: `const out = new Float64Array(8);`,
  track: `const track = new THREE.QuaternionKeyframeTrack(".quaternion", [0, 1, 2], [0, 0, 0, 1, 0, 0, ${H}, ${H}, 0, 0, 1, 0]);`,
  document: `import { Document } from "@gltf-transform/core";
    const document = new Document();
    { const buffer = document.createBuffer();
      const node = document.createNode("bone");
      const times = document.createAccessor().setType("SCALAR").setArray(new Float32Array([0, 1, 2])).setBuffer(buffer);
      const keys = document.createAccessor().setType("VEC4").setArray(new Float32Array([0, 0, 0, 1, 0, 0, ${H}, ${H}, 0, 0, 1, 0])).setBuffer(buffer);
      const sampler = document.createAnimationSampler().setInput(times).setOutput(keys).setInterpolation("LINEAR");
      const channel = document.createAnimationChannel().setTargetNode(node).setTargetPath("rotation").setSampler(sampler);
      document.createAnimation("turn").addSampler(sampler).addChannel(channel); }`,
  measurements: `const measurements = [[1, 0, 0, 0], [0.999, 0.04, 0, 0], [0.999, 0, 0.04, 0], [-0.999, 0, 0, -0.04], [0, 1, 0, 0]];`,
  poses: `const poses = new Float64Array([1, 0, 0, 0, ${H}, ${H}, 0, 0, ${H}, 0, ${H}, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0]);`,
  bone: `const bone = new THREE.Bone();`,
  walk: `const walk = new THREE.Quaternion(0, 0, 0, 1);`,
  run: `const run = new THREE.Quaternion(0, ${H}, 0, ${H});`,
  limp: `const limp = new THREE.Quaternion(${H}, 0, 0, ${H});`,
  walkTrack: `const walkTrack = new THREE.QuaternionKeyframeTrack(".quaternion", [0, 1], [0, 0, 0, 1, 0, 0, ${H}, ${H}]);`,
  runTrack: `const runTrack = new THREE.QuaternionKeyframeTrack(".quaternion", [0, 1], [0, ${H}, 0, ${H}, 0, 0, 1, 0]);`,
  step: `const step = -0.01;`,
  show: `const show = (message) => globalThis.shown.push(message);`,
};

/** The names `code` uses as words (not as properties after a dot, not inside comments). */
function uses(code, name) {
  const bare = code.replace(/\/\/.*$/gm, "").replace(/"[^"\n]*"/g, '""');
  return new RegExp(`(?<![.\\w$])${name.replace("$", "\\$")}(?![\\w$])`).test(bare);
}

/** Whether `code` imports or declares `name` itself. */
function defines(code, name) {
  const word = `(?<![\\w$])${name}(?![\\w$])`;
  return new RegExp(`^\\s*import\\b[^;]*${word}[^;]*from`, "m").test(code)
    || new RegExp(`\\b(const|let|var)\\s+(\\{[^}]*${word}[^}]*\\}|${word})`).test(code);
}

function prelude(code) {
  const wanted = Object.keys(GIVEN).filter((name) => uses(code, name) && !defines(code, name));
  // A definition may use another given name (a mesh needs THREE).
  for (const name of [...wanted]) {
    for (const other of Object.keys(GIVEN)) {
      if (other !== name && uses(GIVEN[name], other) && !wanted.includes(other) && !defines(code, other)) wanted.push(other);
    }
  }
  const order = Object.keys(GIVEN).filter((name) => wanted.includes(name));
  return order.map((name) => GIVEN[name]).join("\n");
}

// A small 3D pose graph with vertices and information, saved under the name the README reads:
// four poses a quarter turn apart about z, consistent, so that the optimum is certified.
function poseGraph() {
  const info = "1 0 0 0 0 0 1 0 0 0 0 1 0 0 0 400 0 0 400 0 400";
  const lines = [0, 1, 2, 3].map((i) => `VERTEX_SE3:QUAT ${i} 0 0 0 0 0 ${Math.sin((i * Math.PI) / 4)} ${Math.cos((i * Math.PI) / 4)}`);
  for (let i = 0; i < 4; i++) lines.push(`EDGE_SE3:QUAT ${i} ${(i + 1) % 4} 1 0 0 0 0 ${H} ${H} ${info}`);
  return `${lines.join("\n")}\n`;
}

test("the README has the blocks this test knows how to run", () => {
  assert.ok(blocks.length >= 11, `${blocks.length} blocks`);
  assert.ok(blocks.some((b) => b.includes("readG2o(await readFile(")), "the sync block reads a file");
});

test("every JavaScript block of the README runs as written, in order, in Node", () => {
  const dir = mkdtempSync(join(tmpdir(), "kli-readme-"));
  mkdirSync(join(dir, "node_modules"));
  symlinkSync(join(root, "pkg"), join(dir, "node_modules/kli"));
  symlinkSync(join(root, "node_modules/three"), join(dir, "node_modules/three"));
  symlinkSync(join(root, "node_modules/@gltf-transform"), join(dir, "node_modules/@gltf-transform"));
  writeFileSync(join(dir, "package.json"), JSON.stringify({ type: "module" }));
  writeFileSync(join(dir, "sphere2500.txt"), poseGraph());
  const files = blocks.map((code, k) => {
    const file = `block-${k}.mjs`;
    writeFileSync(join(dir, file), `${prelude(code)}\n// README block ${k + 1}\n${code}`);
    return file;
  });
  // The runner: each block in turn; then what the blocks left behind, for the asserts below.
  writeFileSync(join(dir, "run.mjs"), `
    globalThis.shown = [];
    for (const file of ${JSON.stringify(files)}) {
      try { await import("./" + file); }
      catch (e) { console.error(file + ": " + (e && e.stack || e)); process.exit(1); }
    }
    console.log(JSON.stringify({ shown: globalThis.shown }));
  `);
  let output;
  try {
    output = execFileSync(process.execPath, ["run.mjs"], { cwd: dir, encoding: "utf8", stdio: ["ignore", "pipe", "pipe"] });
  } catch (e) {
    const failed = /^block-(\d+)\.mjs/.exec(e.stderr)?.[1];
    assert.fail(`README block ${failed === undefined ? "?" : Number(failed) + 1}:\n${failed === undefined ? "" : blocks[failed]}\n${e.stderr}`);
  }
  // The errors block shows the message of the refused step.
  const { shown } = JSON.parse(output.trim().split("\n").pop());
  assert.equal(shown.length, 1);
  assert.match(shown[0], /^step must be/);
});

test("the prelude defines what a block uses and nothing it defines", () => {
  assert.equal(prelude(`mesh.quaternion.fromArray(kliExact(p, r, t));`).split("\n").length, 6);
  assert.ok(prelude(`mesh.quaternion.fromArray(x);`).startsWith(`import * as THREE from "three";`));
  assert.equal(prelude(`import { kliExact } from "kli";\nconst p = 1;\nkliExact(p);`), "");
  assert.equal(prelude(`const { rotation } = f(); rotation.length; // measurements`), "");
  assert.equal(prelude(`swarm.step(0.05, 400);`), "");
});
