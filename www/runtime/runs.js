// @ts-check
// Building a page's run from a candidate state, alike on every page: when the module refuses an
// argument, that argument is taken from the fallback (the last valid state, or the defaults) and
// the build is tried again, so that every refused argument is reported at once and the page
// still gets a valid run. Errors are routed by `error.argument`, never by their text.
import { sameState } from "./presets.js";

/**
 * @template {object} State
 * @template {{ free(): void }} Run
 * @param {State} candidate
 * @param {State} fallback
 * @param {(state: State) => Run} create the module's constructor, which checks the state
 * @param {(error: unknown) => keyof State | undefined} keyOf the key of the state an Error is about
 * @returns {{ run: Run | null, state: State | null, errors: unknown[] }} the run and the state it was
 *   built from (null when no fallback helps), and every Error on the way
 */
export function buildAll(candidate, fallback, create, keyOf) {
  const errors = /** @type {unknown[]} */ ([]);
  let attempt = { ...candidate };
  for (;;) {
    try {
      return { run: create(attempt), state: attempt, errors };
    } catch (error) {
      errors.push(error);
      const key = keyOf(error);
      if (key === undefined || sameState(attempt[key], fallback[key])) return { run: null, state: null, errors };
      attempt = { ...attempt, [key]: fallback[key] };
    }
  }
}

/** The argument an Error of the module names ("" when it is not one of the module's). */
export const argumentOf = (/** @type {unknown} */ error) =>
  String(/** @type {{ argument?: unknown }} */ (error ?? {}).argument ?? "");

/** The message of an Error of the module. */
export const messageOf = (/** @type {unknown} */ error) =>
  error instanceof Error ? error.message : String(error);

/** Empties every message of `form` and unmarks every field. */
export function clearErrors(/** @type {HTMLElement} */ form) {
  for (const output of form.querySelectorAll(".field-error")) output.textContent = "";
  for (const field of form.querySelectorAll("[aria-invalid=true]")) field.setAttribute("aria-invalid", "false");
}

/**
 * Shows `message` in the output `#<output>-error` of `form` (after any message already there, so
 * that two refused arguments about one output both show) and marks `fields` invalid.
 * @param {HTMLElement} form
 * @param {string} output
 * @param {Element[]} fields
 * @param {string} message
 */
export function showFieldError(form, output, fields, message) {
  const box = form.querySelector(`#${output}-error`);
  if (box) box.textContent = box.textContent ? `${box.textContent} ${message}` : message;
  for (const field of fields) field.setAttribute("aria-invalid", "true");
}
