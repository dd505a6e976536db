// @ts-check
// Keyboard and pointer: keys to the page's actions, dragging to turning the sphere.

/**
 * What the keys do.
 * @typedef {object} Actions
 * @property {() => void} togglePlay
 * @property {(by: number) => void} step move the time by `by` strides (negative: back)
 * @property {() => void} toStart
 * @property {() => void} toEnd
 * @property {(by: number) => void} speed one speed up (1) or down (-1)
 * @property {(azimuth: number, elevation: number) => void} turn
 */

const TURN = (5 * Math.PI) / 180;

/**
 * The page-wide keys (Space, ← →, Home, End, + −), and the arrows on the focused sphere. A key
 * that the focused control uses itself keeps its meaning: Space and Enter press a button or
 * follow a link, typing goes into fields, Space toggles a checkbox.
 * @param {HTMLElement} sphere
 * @param {Actions} actions
 */
export function wireKeyboard(sphere, actions) {
  document.addEventListener("keydown", (event) => {
    const target = event.target;
    if (event.ctrlKey || event.metaKey || event.altKey) return;
    const pressable = target instanceof HTMLButtonElement || target instanceof HTMLAnchorElement || (target instanceof HTMLElement && target.tagName === "SUMMARY");
    if (pressable && (event.key === " " || event.key === "Enter")) return;
    if (target instanceof HTMLSelectElement || target instanceof HTMLTextAreaElement) return;
    const slider = target instanceof HTMLInputElement && target.type === "range";
    if (target instanceof HTMLInputElement && !slider) return;
    // The time slider steps itself with the arrows; the page adds Space, Home and End.
    if (slider && !(event.key === " " || event.key === "Home" || event.key === "End")) return;
    const onSphere = target === sphere;
    const stride = event.shiftKey ? 10 : 1;
    /** @type {Record<string, () => void>} */
    const keys = {
      " ": actions.togglePlay,
      Home: actions.toStart,
      End: actions.toEnd,
      ArrowLeft: () => (onSphere ? actions.turn(TURN, 0) : actions.step(-stride)),
      ArrowRight: () => (onSphere ? actions.turn(-TURN, 0) : actions.step(stride)),
      ArrowUp: () => onSphere && actions.turn(0, TURN),
      ArrowDown: () => onSphere && actions.turn(0, -TURN),
      "+": () => actions.speed(1),
      "=": () => actions.speed(1),
      "-": () => actions.speed(-1),
    };
    const action = keys[event.key];
    if (!action || ((event.key === "ArrowUp" || event.key === "ArrowDown") && !onSphere)) return;
    event.preventDefault();
    action();
  });
}

/**
 * Dragging on a canvas: where `grab` claims the pointer (a key's disc, say), the pointer moves
 * what it grabbed; anywhere else dragging turns the view. Only a draggable canvas takes
 * `touch-action: none`, so that a swipe over any other figure scrolls the page on a phone.
 * @param {HTMLElement} canvas
 * @param {Actions["turn"]} turn
 * @param {(x: number, y: number) => ((x: number, y: number) => void) | null} [grab] points in CSS pixels from the canvas's corner
 */
export function wireDragging(canvas, turn, grab = () => null) {
  canvas.style.touchAction = "none";
  /** @type {{ x: number, y: number, move: ((x: number, y: number) => void) | null } | null} */
  let drag = null;
  const local = (/** @type {PointerEvent} */ event) => {
    const box = canvas.getBoundingClientRect();
    return { x: event.clientX - box.left, y: event.clientY - box.top };
  };
  canvas.addEventListener("pointerdown", (event) => {
    const { x, y } = local(event);
    drag = { x: event.clientX, y: event.clientY, move: grab(x, y) };
    canvas.setPointerCapture(event.pointerId);
  });
  canvas.addEventListener("pointermove", (event) => {
    if (!drag) return;
    if (drag.move) {
      const { x, y } = local(event);
      drag.move(x, y);
      return;
    }
    turn(-(event.clientX - drag.x) * 0.01, (event.clientY - drag.y) * 0.01);
    drag.x = event.clientX;
    drag.y = event.clientY;
  });
  const end = () => (drag = null);
  canvas.addEventListener("pointerup", end);
  canvas.addEventListener("pointercancel", end);
}

/**
 * Grabbing a point of the Hopf sphere, for a page's `grab`: of `points` (`[x, y, inFront]` a
 * point, in CSS pixels, as the module's run gives them), the nearest in front within 12 px of
 * the pointer at `(x, y)` is grabbed; moving the pointer then calls `move(index, x, y)` with the
 * grabbed point's index and the pointer's last place, once a frame. Null when no point is near.
 * @param {ArrayLike<number>} points
 * @param {number} x
 * @param {number} y
 * @param {(index: number, x: number, y: number) => void} move
 * @returns {((x: number, y: number) => void) | null}
 */
export function grabPoint(points, x, y, move) {
  let index = -1;
  let nearest = 12;
  for (let i = 0; i < points.length / 3; i++) {
    const distance = Math.hypot(points[3 * i] - x, points[3 * i + 1] - y);
    if (points[3 * i + 2] === 1 && distance < nearest) [index, nearest] = [i, distance];
  }
  if (index < 0) return null;
  let pending = false;
  let to = { x, y };
  return (x, y) => {
    to = { x, y };
    if (pending) return;
    pending = true;
    requestAnimationFrame(() => {
      pending = false;
      move(index, to.x, to.y);
    });
  };
}
