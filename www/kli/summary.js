// @ts-check
// The run in words: Table 1 live, the final time, and notes on what the run did.

import { formatQuaternion } from "../runtime/numbers.js";

/** @typedef {import("../pkg/kli_demo.js").KliDemo} Demo */

/**
 * Table 1 at the paper's moments (integrated, closed form, and as the paper prints it), the line
 * about T, and in `notes` what the printed table gets wrong.
 * @param {Demo} demo
 * @param {HTMLTableSectionElement} body
 * @param {HTMLElement} finalLine
 * @param {HTMLUListElement} notes
 */
export function fillTable(demo, body, finalLine, notes) {
  body.replaceChildren();
  notes.replaceChildren();
  const { finalTime, steps, predictedTime } = demo.summary;
  for (const moment of demo.moments) {
    const row = body.insertRow();
    const exact = demo.exactAt(moment);
    const printed = demo.printedRow(moment);
    row.insertCell().textContent = moment === finalTime ? `T = ${moment.toFixed(2)}` : String(moment);
    row.insertCell().textContent = formatQuaternion(demo.integratedAt(moment));
    row.insertCell().textContent = formatQuaternion(exact);
    printedCell(row.insertCell(), printed);
    if (!printed) continue;
    const t = `t = ${moment === finalTime ? moment.toFixed(2) : moment}`;
    for (const note of printedNotes(t, printed, exact)) notes.append(Object.assign(document.createElement("li"), { textContent: note }));
  }
  finalLine.textContent =
    `T = ${finalTime.toFixed(2)} after ${steps} steps; the closed form predicts T* = ${predictedTime.toFixed(4)}.`;
}

const UNITS = ["", "i", "j", "k"];

/** The paper's printed row, its wrong numbers marked and its truncated ones underlined. */
function printedCell(/** @type {HTMLTableCellElement} */ cell, /** @type {import("../pkg/kli_demo.js").PrintedRow | undefined} */ row) {
  if (!row) {
    cell.textContent = "—";
    return;
  }
  row.verdicts.forEach((verdict, c) => {
    if (c > 0) cell.append(" + ");
    const text = `${row.printed[c].toFixed(2)}${UNITS[c]}`;
    if (verdict === "agrees") return cell.append(text);
    const span = document.createElement(verdict === "differs" ? "mark" : "span");
    span.className = verdict;
    span.textContent = text;
    const said = document.createElement("span");
    said.className = "visually-hidden";
    said.textContent = ` (${verdict === "differs" ? "wrong" : "truncated"})`;
    span.append(said);
    cell.append(span);
  });
}

/**
 * What a printed row of Table 1 gets wrong, in words.
 * @param {string} t the row's time, as "t = 0.2"
 * @param {import("../pkg/kli_demo.js").PrintedRow} row
 * @param {ArrayLike<number>} exact the closed form at that time
 * @returns {string[]}
 */
function printedNotes(t, row, exact) {
  const notes = [];
  if (row.repeats !== undefined) {
    notes.push(`${t}: the printed row is the t = ${row.repeats} row again; the closed form gives ${formatQuaternion(exact)}.`);
  } else if (row.verdicts.includes("differs")) {
    notes.push(`${t}: printed ${formatPrinted(row)}, computed ${formatQuaternion(exact)}.`);
  }
  const cut = row.verdicts.flatMap((verdict, c) => (verdict === "truncated" ? [c] : []));
  if (cut.length > 0) {
    const c = cut[0];
    notes.push(`${t}: ${row.printed[c].toFixed(2)} for ${exact[c].toFixed(4)}${cut.length > 1 ? ` (and ${cut.length - 1} more)` : ""}: cut after two decimals, where rounding gives ${exact[c].toFixed(2)}.`);
  }
  return notes;
}

function formatPrinted(/** @type {import("../pkg/kli_demo.js").PrintedRow} */ row) {
  return Array.from(row.printed, (x, c) => `${x.toFixed(2)}${UNITS[c]}`).join(" + ");
}

/** The moments at which the eq. 4 typo is shown. */
const TYPO_TIMES = [0, 0.5, 1, 2, 5, 10, 20, 40];

/**
 * Eq. 4 as printed, integrated from this run's p: |q| and the distance to the target over time.
 * @param {Demo} demo
 * @param {number} tolerance the run's ε
 * @param {HTMLTableSectionElement} body
 * @param {HTMLElement} summary
 */
export function fillTypo(demo, tolerance, body, summary) {
  const { finalTime } = demo.summary;
  body.replaceChildren();
  const values = demo.integrateAsPrinted(new Float64Array(TYPO_TIMES));
  TYPO_TIMES.forEach((t, i) => {
    const row = body.insertRow();
    row.insertCell().textContent = String(t);
    row.insertCell().textContent = values[2 * i].toFixed(6);
    row.insertCell().textContent = values[2 * i + 1].toFixed(6);
  });
  const last = TYPO_TIMES.length - 1;
  const golden = (Math.sqrt(5) - 1) / 2;
  summary.textContent = finalTime === 0
    ? "p is already at the target, where the printed field does not vanish either."
    : `By t = ${TYPO_TIMES[last]} the printed flow has settled at |q| = ${values[2 * last].toFixed(6)} ` +
      `((√5 − 1)/2 = ${golden.toFixed(6)}), ${values[2 * last + 1].toFixed(6)} from the target: ` +
      `never within ε = ${tolerance} of it, where the correct flow arrives at T = ${finalTime.toFixed(2)}.`;
}

/**
 * Notes on the run: where it goes, and why it may look odd.
 * @param {Demo} demo
 * @param {import("./form.js").State} state
 */
export function describeRun(demo, state) {
  const notes = [];
  const { finalTime, flipped } = demo.summary;
  if (finalTime === 0) {
    notes.push(`p is already within ε of the target: nothing to interpolate${flipped ? " (r ≈ −p is the same rotation as p)" : ""}.`);
  } else if (flipped) {
    notes.push("p·r < 0, so the flow goes to −r: the same rotation, by the shorter arc.");
  }
  if (!state.shortestPath && finalTime > 0) notes.push("Shortest path is off: the flow goes to r itself, possibly the long way round.");
  if (state.integrator === "euler") notes.push("Euler leaves S³: see the |q| drift plot.");
  return notes.join(" ");
}

/** The object view's text alternative at time t. */
export function describeFrame(/** @type {Demo} */ demo, /** @type {number} */ t) {
  return `The aircraft at t = ${t.toFixed(2)}: KLI rotation ${formatQuaternion(demo.integratedAt(t))}; ` +
    `SLERP at the same time (u = t/T) ${formatQuaternion(demo.slerpAt(t))}.`;
}
