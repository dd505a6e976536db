// @ts-nocheck: three.js comes through the import map of the page that imports this.
// The scene both three.js examples draw: two aircraft side by side, lit, seen from the front
// right with z up (as the demo page's object view), on a renderer sized to its canvas.
import * as THREE from "three";

/** An aircraft of boxes: nose along x, red port wing along y, fin along z (as on the demo page). */
function aircraft(colour) {
  const group = new THREE.Group();
  const part = (size, position, color) => {
    const mesh = new THREE.Mesh(new THREE.BoxGeometry(...size), new THREE.MeshLambertMaterial({ color }));
    mesh.position.set(...position);
    group.add(mesh);
  };
  part([2.4, 0.36, 0.36], [0, 0, 0], colour);
  part([0.5, 1.2, 0.08], [0.1, 0.75, 0], 0xc92a2a);
  part([0.5, 1.2, 0.08], [0.1, -0.75, 0], colour);
  part([0.35, 0.08, 0.6], [-1.0, 0, 0.4], 0x1971c2);
  part([0.3, 0.3, 0.3], [1.35, 0, 0], 0x343a40);
  return group;
}

/**
 * Two aircraft of the given colours on `canvas`: resolves to `{ left, right, renderer, render }`,
 * where `render()` fits the renderer to the canvas's size and draws, once the scene's shaders
 * are compiled (off the main thread where the browser can, `KHR_parallel_shader_compile`), so
 * the first frame does not compile them in one long task (Lighthouse's total blocking time
 * counted it). If the browser cannot draw WebGL, `status` says so and this rejects.
 */
export async function twoAircraft(canvas, status, leftColour, rightColour) {
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xffffff);
  scene.add(new THREE.AmbientLight(0xffffff, 1.6));
  const sun = new THREE.DirectionalLight(0xffffff, 2.2);
  sun.position.set(3, -4, 6);
  scene.add(sun);
  const left = aircraft(leftColour), right = aircraft(rightColour);
  left.position.x = -1.9;
  right.position.x = 1.9;
  scene.add(left, right);
  const camera = new THREE.PerspectiveCamera(35, 2, 0.1, 100);
  camera.up.set(0, 0, 1);
  camera.position.set(3, -9, 4);
  camera.lookAt(0, 0, 0);
  let renderer;
  try {
    // The drawing buffer is not preserved between frames (three.js's default): keeping it cost
    // a copy of every frame (docs/performance.md, Lighthouse).
    renderer = new THREE.WebGLRenderer({ canvas, antialias: true });
  } catch (error) {
    status.textContent = `This browser cannot draw WebGL: ${error.message}`;
    throw error;
  }
  const render = () => {
    const { clientWidth: width, clientHeight: height } = canvas;
    if (canvas.width !== Math.round(width * devicePixelRatio) || canvas.height !== Math.round(height * devicePixelRatio)) {
      renderer.setPixelRatio(devicePixelRatio);
      renderer.setSize(width, height, false);
      camera.aspect = width / height;
      camera.updateProjectionMatrix();
    }
    renderer.render(scene, camera);
  };
  // In a task of its own: creating the WebGL context is long enough already.
  await new Promise((resolve) => setTimeout(resolve));
  await renderer.compileAsync(scene, camera);
  return { left, right, renderer, render };
}

/**
 * The Play/Pause button and the time slider of both examples: `clock.t` is the time shown,
 * `clock.playing` whether it runs, `clock.advance(now, end)` moves it to a frame's timestamp
 * (looping over [0, end)); dragging the slider pauses at its value.
 */
export function transport(play, time) {
  let last = performance.now();
  const clock = {
    t: 0,
    playing: !matchMedia("(prefers-reduced-motion: reduce)").matches,
    advance(now, end) {
      if (clock.playing) {
        // A frame may be stamped before the first `last`: never step back.
        clock.t = (clock.t + Math.min(Math.max(now - last, 0), 100) / 1000) % end;
        time.value = String(clock.t);
      }
      last = now;
      return clock.t;
    },
  };
  const label = () => (play.textContent = clock.playing ? "Pause" : "Play");
  play.addEventListener("click", () => {
    clock.playing = !clock.playing;
    label();
  });
  time.addEventListener("input", () => {
    clock.playing = false;
    label();
    clock.t = Number(time.value);
  });
  label();
  return clock;
}
