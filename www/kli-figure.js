// @ts-check
// <kli-figure>: one figure of the demo in any page, configured in the markup and sized by CSS.
//
//   <script type="module" src="kli-figure.js"></script>
//   <kli-figure view="hopf" p="0,0,0,1" r="0.5,0.5,0.5,0.5" autoplay></kli-figure>
//
// Views: "object", "hopf", "plots", "filmstrip" (KLI from p to r), "keyframes" (the three curves
// through `keys`), "swarm" (a LoheSwarm's Hopf points). Each page module is loaded once, when the
// first figure that needs it appears, and shared by every figure on the page. Every attribute is
// live: change one and the figure is rebuilt. Computing, checking and drawing are the modules'.

const KLI_VIEWS = ["object", "hopf", "plots", "filmstrip"];
const VIEWS = [...KLI_VIEWS, "keyframes", "swarm"];
const ATTRIBUTES = ["view", "p", "r", "tolerance", "step", "integrator", "shortest-path", "t", "autoplay", "speed",
  "keys", "times", "smoothness", "count", "coupling", "graph", "seed", "label"];
const SWARM_DT = 0.02;

/** Each page module, initialised once for the whole page. */
const modules = {
  kli: () => import("./pkg/kli_demo.js"),
  spline: () => import("./pkg/spline_demo.js"),
  swarm: () => import("./pkg/swarm_demo.js"),
};
/** @type {Map<string, Promise<any>>} */
const loaded = new Map();
function load(/** @type {keyof typeof modules} */ name) {
  let module = loaded.get(name);
  if (!module) {
    module = modules[name]().then(async (m) => {
      await m.default();
      return m;
    });
    loaded.set(name, module);
  }
  return module;
}

/** "0,0,0,1" → [0, 0, 0, 1]; a word that is not a number stays NaN, for the module to name. */
const numbers = (/** @type {string} */ text) => text.split(",").map((x) => (x.trim() === "" ? NaN : Number(x)));
/** "1,0,0,0; 0,1,0,0" → [[1, 0, 0, 0], [0, 1, 0, 0]]. */
const quaternions = (/** @type {string} */ text) => text.split(";").map(numbers);

const STYLE = `
:host { display: block; position: relative; aspect-ratio: 4 / 3; min-height: 120px; contain: content; }
:host([view="filmstrip"]) { aspect-ratio: 5 / 1; }
:host([view="plots"]) { aspect-ratio: 3 / 1; }
canvas { display: block; width: 100%; height: 100%; }
p { position: absolute; inset: auto 0 0 0; margin: 0; padding: 4px 8px; font: .85rem system-ui, sans-serif;
    color: #a61e1e; background: #fff; }
p:empty { display: none; }`;

export class KliFigure extends HTMLElement {
  static observedAttributes = ATTRIBUTES;

  constructor() {
    super();
    const root = this.attachShadow({ mode: "open" });
    const style = document.createElement("style");
    style.textContent = STYLE;
    this.canvas = document.createElement("canvas");
    this.canvas.setAttribute("role", "img");
    this.message = document.createElement("p");
    this.message.setAttribute("role", "status");
    root.append(style, this.canvas, this.message);
    /** @type {any} the module's Demo, SplineDemo or SwarmDemo */
    this.demo = null;
    this.size = { width: 0, height: 0 };
    this.t = 0;
    this.view = [0, 0];
    this.frame = 0;
    this.last = 0;
    this.visible = true;
    this.built = 0;
    this.resize = new ResizeObserver(([entry]) => {
      this.size = { width: entry.contentRect.width, height: entry.contentRect.height };
      const ratio = devicePixelRatio || 1;
      this.canvas.width = Math.max(1, Math.round(this.size.width * ratio));
      this.canvas.height = Math.max(1, Math.round(this.size.height * ratio));
      this.draw();
    });
    // Off screen, an animated figure stops asking for frames.
    this.intersection = new IntersectionObserver(([entry]) => {
      this.visible = entry.isIntersecting;
      this.schedule();
    });
  }

  connectedCallback() {
    this.resize.observe(this.canvas);
    this.intersection.observe(this);
    this.rebuild();
  }

  disconnectedCallback() {
    this.resize.disconnect();
    this.intersection.disconnect();
    cancelAnimationFrame(this.frame);
    this.frame = 0;
    this.demo?.free();
    this.demo = null;
  }

  attributeChangedCallback() {
    if (this.isConnected) this.rebuild();
  }

  /** The `view` attribute, checked. */
  get kind() {
    return this.getAttribute("view") ?? "hopf";
  }

  get playing() {
    return this.hasAttribute("autoplay") && !matchMedia("(prefers-reduced-motion: reduce)").matches;
  }

  /** Builds the figure's run from its attributes; a refused attribute is shown in the figure. */
  async rebuild() {
    const build = ++this.built;
    const view = this.kind;
    if (!VIEWS.includes(view)) return this.fail(`view must be one of ${VIEWS.join(", ")} (got "${view}")`);
    const name = KLI_VIEWS.includes(view) ? "kli" : view === "keyframes" ? "spline" : "swarm";
    let module;
    try {
      module = await load(name);
    } catch (error) {
      return this.fail(`the WebAssembly module could not be loaded: ${error instanceof Error ? error.message : error}`);
    }
    if (build !== this.built || !this.isConnected) return; // a newer rebuild is under way
    let demo;
    try {
      demo = this.create(module, view);
    } catch (error) {
      return this.fail(error instanceof Error ? error.message : String(error));
    }
    this.demo?.free();
    this.demo = demo;
    this.view = Array.from(module.defaultSphereView());
    this.message.textContent = "";
    const t = this.getAttribute("t");
    this.t = t === null ? 0 : Math.max(0, Number(t) || 0);
    if (view === "swarm" && this.t > 0) demo.step(SWARM_DT, Math.min(Math.round(this.t / SWARM_DT), 1e5));
    this.describe();
    this.draw();
    this.schedule();
  }

  /** The module's object for `view`, from the attributes (its constructor checks them). */
  create(/** @type {any} */ module, /** @type {string} */ view) {
    const attr = (/** @type {string} */ name) => this.getAttribute(name);
    const number = (/** @type {string} */ name) => (attr(name) === null ? undefined : Number(attr(name)));
    if (view === "keyframes") {
      const keys = quaternions(attr("keys") ?? "1,0,0,0; 0.8,0.6,0,0; 0.6,0,0.8,0; 0,0,0.6,0.8");
      const times = attr("times") ? numbers(attr("times") ?? "") : [];
      return new module.SplineDemo(new Float64Array(keys.flat()), new Float64Array(times), number("smoothness") ?? 1);
    }
    if (view === "swarm") {
      const options = { count: number("count") ?? 200, coupling: number("coupling") ?? 1, seed: number("seed") ?? 1 };
      return new module.SwarmDemo(attr("graph") ? { ...options, graph: attr("graph") } : options);
    }
    const options = Object.fromEntries(Object.entries({
      tolerance: number("tolerance"),
      step: number("step"),
      integrator: attr("integrator") ?? undefined,
      shortestPath: attr("shortest-path") === null ? undefined : attr("shortest-path") !== "false",
    }).filter(([, value]) => value !== undefined));
    return new module.Demo(numbers(attr("p") ?? "0,0,0,1"), numbers(attr("r") ?? "0.5,0.5,0.5,0.5"), options);
  }

  fail(/** @type {string} */ text) {
    this.demo?.free();
    this.demo = null;
    this.message.textContent = `kli-figure: ${text}`;
    this.canvas.setAttribute("aria-label", this.message.textContent);
    const context = this.canvas.getContext("2d");
    context?.clearRect(0, 0, this.canvas.width, this.canvas.height);
    this.dispatchEvent(new CustomEvent("kli-error", { detail: text }));
  }

  /** The canvas's text alternative: the `label` attribute, or what the figure shows. */
  describe() {
    const view = this.kind;
    const label = this.getAttribute("label");
    const what = {
      object: "The object turning from p to r under KLI and under SLERP",
      hopf: "The Hopf curves of KLI and SLERP on the sphere S²",
      plots: "Distance to r, the SLERP parameter s(t) and the drift of |q| over time",
      filmstrip: "The object at the moments of the paper's Table 1",
      keyframes: "The Hopf curves of the Kuramoto–Lohe chain, Squad and piecewise SLERP through the keys",
      swarm: "The swarm's oscillators as points on the sphere S²",
    }[view];
    this.canvas.setAttribute("aria-label", label ?? what ?? view);
  }

  /** The time span of the figure's animation. */
  get end() {
    const demo = this.demo;
    if (!demo) return 0;
    return this.kind === "keyframes" ? demo.endTime : this.kind === "swarm" ? Infinity : demo.finalTime;
  }

  schedule() {
    if (this.frame || !this.demo || !this.playing || !this.visible || this.kind === "filmstrip") return;
    this.last = performance.now();
    this.frame = requestAnimationFrame((now) => this.tick(now));
  }

  tick(/** @type {number} */ now) {
    this.frame = 0;
    if (!this.demo || !this.playing || !this.visible) return;
    const dt = (Math.min(Math.max(now - this.last, 0), 100) / 1000) * (Number(this.getAttribute("speed")) || 1);
    this.last = now;
    if (this.kind === "swarm") {
      this.demo.step(SWARM_DT, Math.max(1, Math.round(dt / SWARM_DT)));
      this.t = this.demo.time;
    } else {
      const start = this.kind === "keyframes" ? this.demo.startTime : 0;
      this.t = this.t + dt > this.end ? start : this.t + dt;
    }
    this.draw();
    this.frame = requestAnimationFrame((later) => this.tick(later));
  }

  /** Draws the figure at its time, at the device's pixel ratio. */
  draw() {
    const { demo, size } = this;
    const ctx = this.canvas.getContext("2d");
    if (!demo || !ctx || size.width === 0) return;
    const ratio = devicePixelRatio || 1;
    const { width, height } = size;
    const [azimuth, elevation] = this.view;
    const t = Math.min(this.t, this.end);
    switch (this.kind) {
      case "object": return demo.drawObject(ctx, width, height, ratio, t);
      case "filmstrip": return demo.drawFilmstrip(ctx, width, height, ratio);
      case "plots":
        demo.drawPlots(ctx, width, height, ratio);
        return demo.drawPlotsTime(ctx, width, height, ratio, t);
      case "hopf":
        demo.drawSphere(ctx, width, height, ratio, azimuth, elevation);
        return demo.drawSphereTime(ctx, width, height, ratio, t, azimuth, elevation);
      case "keyframes": return demo.drawSphere(ctx, width, height, ratio, azimuth, elevation, t);
      case "swarm": return demo.drawSphere(ctx, width, height, ratio, azimuth, elevation);
    }
  }
}

if (!customElements.get("kli-figure")) customElements.define("kli-figure", KliFigure);
