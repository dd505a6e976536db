// The page's state as text: the presets, the defaults, and the URL query that reproduces a view.
// URL values are only ever parsed as numbers (or one of a fixed set of words) and written into
// input fields' values, never into the page as HTML.

export const PRESETS = {
  paper: { p: [0, 0, 0, 1], r: [0.5, 0.5, 0.5, 0.5], eps: 1e-5, step: 0.01, integrator: "rk4", shortest: true },
  antipodal: { p: [0, 0, 0, 1], r: [0, 0, 0, -1], eps: 1e-5, step: 0.01, integrator: "rk4", shortest: true },
  "long-way": { p: [1, 0, 0, 0], r: [-0.995, 0, 0, 0.0998], eps: 1e-5, step: 0.01, integrator: "rk4", shortest: false },
  "near-identical": { p: [0, 0, 0, 1], r: [0.001, 0, 0, 1], eps: 1e-5, step: 0.01, integrator: "rk4", shortest: true },
};

export const DEFAULTS = PRESETS.paper;
export const INTEGRATORS = ["rk4", "euler", "geodesic"];

/** A uniformly random unit quaternion (normalised Gaussian), to 4 decimals. */
export function randomQuaternion() {
  const gaussian = () => Math.sqrt(-2 * Math.log(1 - Math.random())) * Math.cos(2 * Math.PI * Math.random());
  const q = [gaussian(), gaussian(), gaussian(), gaussian()];
  const length = Math.hypot(...q) || 1;
  return q.map((c) => Number((c / length).toFixed(4)));
}

/** Strictly a decimal number: "" and "abc" are NaN, unlike Number(""). */
export function parseNumber(text) {
  const trimmed = String(text).trim();
  return /^[+-]?(\d+\.?\d*|\.\d+)(e[+-]?\d+)?$/i.test(trimmed) ? Number(trimmed) : NaN;
}

/** The shortest text that reads back as the same number, up to 6 significant digits. */
export function formatNumber(x) {
  return String(Number(x.toPrecision(6)));
}

/**
 * The raw texts of the URL's parameters, for the form to validate like typed input:
 * { p: [4 texts] | undefined, r, eps, step, integrator, shortest, t, embed }.
 */
export function readQuery(search) {
  const query = new URLSearchParams(search);
  const list = (name) => (query.has(name) ? query.get(name).split(",") : undefined);
  const word = (name, allowed) => (allowed.includes(query.get(name)) ? query.get(name) : undefined);
  return {
    p: list("p"),
    r: list("r"),
    eps: query.get("eps") ?? undefined,
    step: query.get("step") ?? undefined,
    integrator: word("int", INTEGRATORS),
    shortest: query.has("short") ? !["0", "false"].includes(query.get("short")) : undefined,
    t: query.has("t") ? parseNumber(query.get("t")) : undefined,
    embed: query.get("embed") === "1",
  };
}

/** The query string of a state (and the time, when given). */
export function writeQuery(state, { t, embed } = {}) {
  const query = new URLSearchParams({
    p: state.p.map(formatNumber).join(","),
    r: state.r.map(formatNumber).join(","),
    eps: String(state.eps),
    step: String(state.step),
    int: state.integrator,
    short: state.shortest ? "1" : "0",
  });
  if (Number.isFinite(t)) query.set("t", t.toFixed(2));
  if (embed) query.set("embed", "1");
  return "?" + query.toString();
}
