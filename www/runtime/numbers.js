// @ts-check
// Numbers as the page reads and writes them.

/** A decimal number typed or given in the URL; anything else ("", "abc", "1,5") is NaN, which
 *  the module then names in its message. */
export function parseNumber(/** @type {string} */ text) {
  const trimmed = String(text).trim();
  return /^[+-]?(\d+\.?\d*|\.\d+)(e[+-]?\d+)?$/i.test(trimmed) ? Number(trimmed) : NaN;
}

/** The shortest text that reads back as the same number, to 6 significant digits. */
export function formatNumber(/** @type {number} */ x) {
  return String(Number(x.toPrecision(6)));
}

/** `a + bi + cj + dk` to 4 decimals, without "−0.0000" for rounding-level negatives. */
export function formatQuaternion(/** @type {ArrayLike<number>} */ q) {
  const c = Array.from(q, (x) => (Math.abs(x) < 5e-5 ? 0 : x));
  const terms = ["i", "j", "k"].map((unit, i) => `${c[i + 1] < 0 ? "−" : "+"} ${Math.abs(c[i + 1]).toFixed(4)}${unit}`);
  return `${c[0] < 0 ? "−" : ""}${Math.abs(c[0]).toFixed(4)} ${terms.join(" ")}`;
}
