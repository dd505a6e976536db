// @ts-check
// The preset runs of the form's Preset menu, in the page's state vocabulary.

/** @type {Record<string, import("./form.js").State>} */
export const PRESETS = {
  paper: { p: [0, 0, 0, 1], r: [0.5, 0.5, 0.5, 0.5], tolerance: 1e-5, step: 0.01, integrator: "rk4", shortestPath: true },
  antipodal: { p: [0, 0, 0, 1], r: [0, 0, 0, -1], tolerance: 1e-5, step: 0.01, integrator: "rk4", shortestPath: true },
  "long-way": { p: [1, 0, 0, 0], r: [-0.995, 0, 0, 0.0998], tolerance: 1e-5, step: 0.01, integrator: "rk4", shortestPath: false },
  "near-identical": { p: [0, 0, 0, 1], r: [0.001, 0, 0, 1], tolerance: 1e-5, step: 0.01, integrator: "rk4", shortestPath: true },
};

export const DEFAULTS = PRESETS.paper;

/** A uniformly random unit quaternion (normalised Gaussian), to 4 decimals. */
export function randomQuaternion() {
  const gaussian = () => Math.sqrt(-2 * Math.log(1 - Math.random())) * Math.cos(2 * Math.PI * Math.random());
  const q = [gaussian(), gaussian(), gaussian(), gaussian()];
  const length = Math.hypot(...q) || 1;
  return q.map((c) => Number((c / length).toFixed(4)));
}

/** The name of the preset equal to `state`, or "custom". */
export function presetName(/** @type {import("./form.js").State | null} */ state) {
  const found = Object.entries(PRESETS).find(([, preset]) => JSON.stringify(preset) === JSON.stringify(state));
  return found ? found[0] : "custom";
}
