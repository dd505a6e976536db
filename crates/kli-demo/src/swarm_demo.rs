//! The `SwarmDemo` class: the swarm page's run, a [`Swarm`] with its history, drawing its views
//! onto canvas contexts the page passes in.

use kli::quaternion::to_wxyz;
use kli::swarm::{Graph, Swarm, SwarmOptions};
use kli_wasm::error::{JsResult, throw};
use kli_wasm::swarm::{SwarmOptionsObject, read_swarm_options, whole_steps};
use wasm_bindgen::prelude::*;
use web_sys::CanvasRenderingContext2d;

use crate::aircraft::{Face, aircraft};
use crate::camera::{Camera, Viewport};
use crate::format::{fixed, joined, json_list, number};
use crate::palette::BACKGROUND;
use crate::pen::{Pen, size, svg_document, unknown_view};
use crate::swarm_plots::{History, draw_history, draw_sweep};
use crate::swarm_view::{draw_swarm_objects, draw_swarm_sphere};

/// How many oscillators the page draws as whole objects.
const OBJECTS: usize = 3;

/// The swarm behind the swarm page, and its views.
#[wasm_bindgen]
pub struct SwarmDemo {
    swarm: Swarm,
    options: SwarmOptions,
    history: History,
    mesh: Vec<Face>,
}

#[wasm_bindgen]
impl SwarmDemo {
    /// A swarm from the options of `new LoheSwarm(options)`, with the same checks and errors.
    #[wasm_bindgen(constructor)]
    pub fn new(options: Option<SwarmOptionsObject>) -> JsResult<SwarmDemo> {
        let (options, _) = read_swarm_options(options).map_err(throw)?;
        let swarm = Swarm::new(&options).map_err(throw)?;
        let mut demo = SwarmDemo { swarm, options, history: History::default(), mesh: aircraft() };
        demo.record();
        Ok(demo)
    }

    fn record(&mut self) {
        let s = &self.swarm;
        self.history.push(s.time(), s.order_parameter(), s.rotation_order(), s.potential());
    }

    /// `steps` geodesic RK4 steps of `dt`, then one sample of the history.
    pub fn step(&mut self, dt: f64, steps: f64) -> JsResult<()> {
        let steps = whole_steps(steps).map_err(throw)?;
        self.swarm.step(dt, steps).map_err(throw)?;
        self.record();
        Ok(())
    }

    #[wasm_bindgen(getter)]
    pub fn time(&self) -> f64 {
        self.swarm.time()
    }

    #[wasm_bindgen(getter)]
    pub fn count(&self) -> usize {
        self.swarm.len()
    }

    #[wasm_bindgen(getter, js_name = orderParameter)]
    pub fn order_parameter(&self) -> f64 {
        self.swarm.order_parameter()
    }

    #[wasm_bindgen(getter, js_name = rotationOrder)]
    pub fn rotation_order(&self) -> f64 {
        self.swarm.rotation_order()
    }

    #[wasm_bindgen(getter)]
    pub fn potential(&self) -> f64 {
        self.swarm.potential()
    }

    /// Whether this is KLI: one pinned leader and one follower (MATH.md, "The swarm").
    #[wasm_bindgen(getter, js_name = isKli)]
    pub fn is_kli(&self) -> bool {
        self.options.graph == Graph::Leader && self.swarm.len() == 2 && self.options.leaders == 1
    }

    /// The follower's KLI clock `τ = K t / 2` (meaningful when `isKli`).
    #[wasm_bindgen(getter, js_name = kliTime)]
    pub fn kli_time(&self) -> f64 {
        0.5 * self.options.coupling * self.swarm.time()
    }

    /// The oscillators' Hopf points on S², seen from (azimuth, elevation) in radians.
    #[wasm_bindgen(js_name = drawSphere)]
    pub fn draw_sphere(
        &self,
        ctx: &CanvasRenderingContext2d,
        width: f64,
        height: f64,
        pixel_ratio: f64,
        azimuth: f64,
        elevation: f64,
    ) {
        self.paint_sphere(
            &Pen::begin(ctx, width, height, pixel_ratio, BACKGROUND),
            width,
            height,
            azimuth,
            elevation,
        );
    }

    /// The first oscillators as whole objects; in the KLI case, the leader and the follower.
    #[wasm_bindgen(js_name = drawObjects)]
    pub fn draw_objects(
        &self,
        ctx: &CanvasRenderingContext2d,
        width: f64,
        height: f64,
        pixel_ratio: f64,
    ) {
        self.paint_objects(&Pen::begin(ctx, width, height, pixel_ratio, BACKGROUND), width, height);
    }

    /// `R(t)`, `λ_max(t)` and the potential over the recent history.
    #[wasm_bindgen(js_name = drawPlots)]
    pub fn draw_plots(
        &self,
        ctx: &CanvasRenderingContext2d,
        width: f64,
        height: f64,
        pixel_ratio: f64,
    ) {
        self.paint_plots(&Pen::begin(ctx, width, height, pixel_ratio, BACKGROUND), width, height);
    }

    /// One figure as an SVG document (vector): `view` is "sphere" (seen from azimuth and
    /// elevation, radians), "objects" or "plots", `width` × `height` CSS pixels.
    #[wasm_bindgen(js_name = toSvg)]
    pub fn to_svg(
        &self,
        view: &str,
        width: f64,
        height: f64,
        azimuth: f64,
        elevation: f64,
    ) -> JsResult<String> {
        let (width, height) = (size(width), size(height));
        let (title, paint): (&str, &dyn Fn(&Pen)) = match view {
            "sphere" => ("The swarm's Hopf points on S²", &|pen| {
                self.paint_sphere(pen, width, height, azimuth, elevation)
            }),
            "objects" => {
                ("The first oscillators as objects", &|pen| self.paint_objects(pen, width, height))
            }
            "plots" => ("R, λmax and the potential over time", &|pen| {
                self.paint_plots(pen, width, height)
            }),
            other => return Err(throw(unknown_view(other, &["sphere", "objects", "plots"]))),
        };
        Ok(svg_document(width, height, title, paint))
    }

    /// The sweep as an SVG document (see `drawSweep`).
    #[wasm_bindgen(js_name = sweepSvg)]
    pub fn sweep_svg(
        width: f64,
        height: f64,
        couplings: &[f64],
        orders: &[f64],
        current: f64,
    ) -> String {
        let (width, height) = (size(width), size(height));
        let title = "The order parameter R against the coupling K";
        svg_document(width, height, title, &|pen| {
            draw_sweep(pen, width, height, couplings, orders, current)
        })
    }

    /// The swarm now as CSV, a row an oscillator: `t`, its index, its quaternion `w, x, y, z`,
    /// its Hopf point.
    #[wasm_bindgen(js_name = swarmCsv)]
    pub fn swarm_csv(&self) -> String {
        let mut csv = String::from("t,oscillator,w,x,y,z,hopfX,hopfY,hopfZ\n");
        let t = self.swarm.time();
        for (i, (&q, h)) in
            self.swarm.quaternions().iter().zip(self.swarm.hopf_points()).enumerate()
        {
            let [w, x, y, z] = to_wxyz(q);
            csv.push_str(&joined(&[t, i as f64, w, x, y, z, h.x, h.y, h.z], ","));
            csv.push('\n');
        }
        csv
    }

    /// The swarm now as JSON: `t`, `orderParameter`, `rotationOrder`, `potential`, and each
    /// oscillator `{ quaternion: [w, x, y, z], hopf: [x, y, z] }`.
    #[wasm_bindgen(js_name = swarmJson)]
    pub fn swarm_json(&self) -> String {
        let s = &self.swarm;
        let oscillators: Vec<String> = s
            .quaternions()
            .iter()
            .zip(s.hopf_points())
            .map(|(&q, h)| {
                let (q, h) = (json_list(&to_wxyz(q)), json_list(&h.to_array()));
                format!("{{\"quaternion\":{q},\"hopf\":{h}}}")
            })
            .collect();
        format!(
            "{{\"t\":{},\"orderParameter\":{},\"rotationOrder\":{},\"potential\":{},\"oscillators\":[\n{}\n]}}\n",
            number(s.time()),
            number(s.order_parameter()),
            number(s.rotation_order()),
            number(s.potential()),
            oscillators.join(",\n")
        )
    }

    /// The order parameter a swarm with these options but coupling `coupling` reaches: `R`
    /// averaged over the last fifth of a run to `time` (steps of 0.05). One point of the sweep.
    #[wasm_bindgen(js_name = sweepOrder)]
    pub fn sweep_order(
        options: Option<SwarmOptionsObject>,
        coupling: f64,
        time: f64,
    ) -> JsResult<f64> {
        let options = SwarmOptions { coupling, ..read_swarm_options(options).map_err(throw)?.0 };
        let mut swarm = Swarm::new(&options).map_err(throw)?;
        let steps = whole_steps((time / 0.05).round()).map_err(throw)?;
        let settle = steps - steps / 5;
        swarm.step(0.05, settle).map_err(throw)?;
        let mut sum = 0.0;
        for _ in settle..steps {
            swarm.step(0.05, 1).map_err(throw)?;
            sum += swarm.order_parameter();
        }
        Ok(if steps > settle { sum / (steps - settle) as f64 } else { swarm.order_parameter() })
    }

    /// The sweep so far: final `R` at each coupling, and the current coupling marked.
    #[wasm_bindgen(js_name = drawSweep)]
    #[allow(clippy::too_many_arguments)]
    pub fn draw_sweep(
        ctx: &CanvasRenderingContext2d,
        width: f64,
        height: f64,
        pixel_ratio: f64,
        couplings: &[f64],
        orders: &[f64],
        current: f64,
    ) {
        draw_sweep(
            &Pen::begin(ctx, width, height, pixel_ratio, BACKGROUND),
            width,
            height,
            couplings,
            orders,
            current,
        );
    }
}

/// The views, drawn with any [`Pen`]: the canvas methods and `toSvg` share them.
impl SwarmDemo {
    fn paint_sphere(&self, pen: &Pen, width: f64, height: f64, azimuth: f64, elevation: f64) {
        let viewport = Viewport::fitting(0.0, 0.0, width, height, 1.22);
        draw_swarm_sphere(
            pen,
            &viewport,
            &Camera::orbit(azimuth, elevation),
            &self.swarm.hopf_points(),
        );
        pen.text(
            &format!("t = {}", fixed(self.swarm.time(), 2)),
            (8.0, 12.0),
            crate::palette::MUTED,
            12.0,
            "left",
        );
    }

    fn paint_objects(&self, pen: &Pen, width: f64, height: f64) {
        let q = self.swarm.quaternions();
        let objects: Vec<_> = if self.is_kli() {
            let clock = format!("follower: KLI at τ = Kt/2 = {}", fixed(self.kli_time(), 2));
            vec![(q[0], "leader r (pinned)".to_owned()), (q[1], clock)]
        } else {
            q.iter()
                .take(OBJECTS)
                .enumerate()
                .map(|(i, &q)| (q, format!("oscillator {}", i + 1)))
                .collect()
        };
        draw_swarm_objects(pen, width, height, &self.mesh, &objects);
    }

    fn paint_plots(&self, pen: &Pen, width: f64, height: f64) {
        draw_history(pen, width, height, &self.history);
    }
}
