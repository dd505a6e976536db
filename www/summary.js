// @ts-check
// The run in words: Table 1 live, the final time, and notes on what the run did.

import { formatQuaternion } from "./numbers.js";

/** @typedef {import("./pkg/kli_demo.js").Demo} Demo */

/**
 * Table 1 at the paper's moments, integrated and closed form, and the line about T.
 * @param {Demo} demo
 * @param {HTMLTableSectionElement} body
 * @param {HTMLElement} finalLine
 */
export function fillTable(demo, body, finalLine) {
  body.replaceChildren();
  const finalTime = demo.finalTime;
  for (const moment of demo.moments) {
    const row = body.insertRow();
    row.insertCell().textContent = moment === finalTime ? `T = ${moment.toFixed(2)}` : String(moment);
    row.insertCell().textContent = formatQuaternion(demo.integratedAt(moment));
    row.insertCell().textContent = formatQuaternion(demo.exactAt(moment));
  }
  finalLine.textContent =
    `T = ${finalTime.toFixed(2)} after ${demo.steps} steps; the closed form predicts T* = ${demo.predictedTime.toFixed(4)}.`;
}

/**
 * Notes on the run: where it goes, and why it may look odd.
 * @param {Demo} demo
 * @param {import("./form.js").State} state
 */
export function describeRun(demo, state) {
  const notes = [];
  if (demo.finalTime === 0) {
    notes.push(`p is already within ε of the target: nothing to interpolate${demo.flipped ? " (r ≈ −p is the same rotation as p)" : ""}.`);
  } else if (demo.flipped) {
    notes.push("p·r < 0, so the flow goes to −r: the same rotation, by the shorter arc.");
  }
  if (!state.shortestPath && demo.finalTime > 0) notes.push("Shortest path is off: the flow goes to r itself, possibly the long way round.");
  if (state.integrator === "euler") notes.push("Euler leaves S³: see the |q| drift plot.");
  return notes.join(" ");
}

/** The object view's text alternative at time t. */
export function describeFrame(/** @type {Demo} */ demo, /** @type {number} */ t) {
  return `The aircraft at t = ${t.toFixed(2)}: KLI rotation ${formatQuaternion(demo.integratedAt(t))}; ` +
    `SLERP at the same time ${formatQuaternion(demo.slerpAt(t))}.`;
}
