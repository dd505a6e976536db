// kli/gltf: a glTF-Transform transform that smooths rotation animations (issue 16). glTF
// interpolates a LINEAR rotation sampler by SLERP from key to key (ω turns abruptly at every
// key), and its CUBICSPLINE for rotations is a normalised 4-D Hermite that wobbles
// (KhronosGroup/glTF#2008). `smoothRotations` replaces every LINEAR rotation sampler with the
// Kuramoto–Lohe chain through the same keys, resampled (the keys' own times kept), still LINEAR:
// every glTF viewer plays it. STEP and CUBICSPLINE samplers, and everything not a rotation, are
// left alone. It uses only the document it is given: any @gltf-transform/core from 3 on.
// Initialise kli/spline first (`await init()` from "kli/spline").
import { isKliError, lent, readOptions, resample } from "./resample.js";

const CALLER = "kli/gltf's smoothRotations";

export { isKliError };

/**
 * The transform: `await document.transform(smoothRotations({ fps: 60 }))`. Options: `fps`
 * (samples a second, 1 to 1000, default 60), `smoothness` (the chain's, default 1).
 */
export function smoothRotations(options) {
  const { fps, smoothness } = readOptions(options, 60);
  return function smoothRotations(document) {
    lent("kli/spline", CALLER);
    const done = new Set();
    for (const animation of document.getRoot().listAnimations()) {
      const samplers = animation.listSamplers();
      for (const channel of animation.listChannels()) {
        const sampler = channel.getSampler();
        if (channel.getTargetPath() !== "rotation" || !sampler || done.has(sampler)) continue;
        done.add(sampler);
        const input = sampler.getInput(), output = sampler.getOutput();
        if (sampler.getInterpolation() !== "LINEAR" || !input || !output) continue;
        // The keys as numbers (a normalised integer output is read as its quaternion).
        const n = input.getCount();
        const times = new Float32Array(n), values = new Float32Array(4 * n), q = [0, 0, 0, 0];
        for (let i = 0; i < n; i++) {
          times[i] = input.getScalar(i);
          values.set(output.getElement(i, q), 4 * i);
        }
        // An Error about a key names its animation and sampler, as the file does.
        const where = `animation "${animation.getName()}", sampler ${samplers.indexOf(sampler)}, `;
        const sampled = resample(times, values, fps, smoothness, { argument: "document", where, caller: CALLER });
        if (!sampled) continue;
        sampler
          .setInput(document.createAccessor(input.getName()).setType("SCALAR").setArray(sampled.times).setBuffer(input.getBuffer()))
          .setOutput(document.createAccessor(output.getName()).setType("VEC4").setArray(sampled.values).setBuffer(output.getBuffer()));
        // The keys' accessors, unless something else still uses them.
        for (const old of [input, output]) if (old.listParents().every((parent) => parent === document.getRoot())) old.dispose();
      }
    }
  };
}
