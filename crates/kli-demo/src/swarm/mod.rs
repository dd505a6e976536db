//! The `SwarmDemo` class: the swarm page's run, a [`Swarm`] with its history, drawing its views
//! onto canvas contexts the page passes in.

pub mod plots;
pub mod view;

use kli::quaternion::to_wxyz;
use kli::swarm::{Graph, Swarm, SwarmOptions};
use kli_wasm::error::JsResult;
use kli_wasm::read::whole_steps;
use kli_wasm::swarm::{SwarmOptionsObject, read_swarm_options};
use wasm_bindgen::prelude::*;
use web_sys::CanvasRenderingContext2d;

use self::plots::{History, draw_history, draw_sweep};
use self::view::{draw_swarm_objects, draw_swarm_sphere};
use crate::aircraft::{Face, aircraft};
use crate::figure::{Figure, Frame, Layer, Motion, Record, View, names};
use crate::format::{Json, csv_table, fixed};
use crate::palette::BACKGROUND;
use crate::pen::{Pen, svg_document};
use crate::provenance::{Provenance, Value};
use crate::stepped::{Stepped, stepped};

/// How many oscillators the page draws as whole objects.
const OBJECTS: usize = 3;

/// The swarm's step: geodesic RK4 steps of this much model time.
const DT: f64 = 0.02;

/// Model time a second of the page's clock at speed 1: two steps a 60 Hz frame.
const PACE: f64 = 2.4;

/// The most oscillator steps (`count × steps`) one `advance` takes: about 9 ms in Chromium, all
/// to all, so a frame keeps its budget whatever the count and the speed.
const FRAME_WORK: f64 = 1e5;

/// The most oscillator steps one `seek` takes (about 45 ms): a run to a far time is a task of
/// this size at a time, the page responsive between them.
const TASK_WORK: f64 = 5e5;

/// The swarm behind the swarm page, and its views.
#[wasm_bindgen]
pub struct SwarmDemo {
    swarm: Swarm,
    options: SwarmOptions,
    history: History,
    mesh: Vec<Face>,
    /// Steps owed to the clock: a frame's share of a step carries over to the next.
    owed: f64,
}

#[wasm_bindgen]
impl SwarmDemo {
    /// A swarm from the options of `new LoheSwarm(options)`, with the same checks and errors.
    #[wasm_bindgen(constructor)]
    pub fn new(options: Option<SwarmOptionsObject>) -> JsResult<SwarmDemo> {
        let (options, _) = read_swarm_options(&JsValue::from(options))?;
        let swarm = Swarm::new(&options)?;
        let mut demo =
            SwarmDemo { swarm, options, history: History::default(), mesh: aircraft(), owed: 0.0 };
        demo.record();
        Ok(demo)
    }

    /// The sweep (the final `R` at each coupling, the current coupling marked) as an SVG
    /// document (see `drawSweep`).
    #[wasm_bindgen(js_name = sweepSvg)]
    pub fn sweep_svg(
        #[wasm_bindgen(unchecked_param_type = "Frame")] frame: &JsValue,
        couplings: &[f64],
        orders: &[f64],
        current: f64,
    ) -> String {
        let frame = Frame::read(frame);
        let title = "The order parameter R against the coupling K";
        svg_document(frame.width, frame.height, title, &|pen| {
            pen.scale_text(frame.text_scale);
            draw_sweep(pen, frame.width, frame.height, couplings, orders, current)
        })
    }

    /// The order parameter a swarm with these options but coupling `coupling` reaches: `R`
    /// averaged over the last fifth of a run to `time` (steps of 0.05). One point of the sweep.
    #[wasm_bindgen(js_name = sweepOrder)]
    pub fn sweep_order(
        options: Option<SwarmOptionsObject>,
        coupling: f64,
        time: f64,
    ) -> JsResult<f64> {
        let read = read_swarm_options(&JsValue::from(options))?.0;
        let options = SwarmOptions { coupling, ..read };
        let mut swarm = Swarm::new(&options)?;
        let steps = whole_steps(&(time / 0.05).round().into())?;
        let settle = steps - steps / 5;
        swarm.step(0.05, settle)?;
        let mut sum = 0.0;
        for _ in settle..steps {
            swarm.step(0.05, 1)?;
            sum += swarm.order_parameter();
        }
        Ok(if steps > settle { sum / (steps - settle) as f64 } else { swarm.order_parameter() })
    }

    /// The sweep so far: final `R` at each coupling, and the current coupling marked.
    #[wasm_bindgen(js_name = drawSweep)]
    pub fn draw_sweep(
        ctx: &CanvasRenderingContext2d,
        #[wasm_bindgen(unchecked_param_type = "Frame")] frame: &JsValue,
        couplings: &[f64],
        orders: &[f64],
        current: f64,
    ) {
        let frame = Frame::read(frame);
        let (width, height) = (frame.width, frame.height);
        let pen = Pen::begin(ctx, width, height, frame.pixel_ratio, BACKGROUND);
        pen.scale_text(frame.text_scale);
        draw_sweep(&pen, width, height, couplings, orders, current);
    }
}

crate::figure::figure_class!(SwarmDemo, "SwarmSummary");

/// The swarm's time: the model's, in steps of [`DT`], with no end.
impl Stepped for SwarmDemo {
    const PACE: f64 = PACE / DT;
    const FRAME_WORK: f64 = FRAME_WORK;
    const TASK_WORK: f64 = TASK_WORK;

    /// An oscillator's step each.
    fn step_work(&self) -> f64 {
        self.swarm.len() as f64
    }

    fn dt(&self) -> f64 {
        DT
    }

    fn now(&self) -> f64 {
        self.swarm.time()
    }

    fn owed(&mut self) -> &mut f64 {
        &mut self.owed
    }

    /// False if the swarm refused (it does not: [`DT`] is a valid step).
    fn steps(&mut self, steps: f64) -> bool {
        let done = self.swarm.step(DT, steps as usize).is_ok();
        self.record();
        done
    }
}

stepped!(SwarmDemo);

/// The swarm page's views: the oscillators' Hopf points, the first oscillators as objects, and
/// the history of R, λmax and the potential; its time, the model's, with no end; its data, the
/// swarm now.
impl Figure for SwarmDemo {
    const VIEWS: &'static [View] = &[
        View { name: "hopf", title: "The swarm's Hopf points on S²", motion: Motion::Moving },
        View { name: "objects", title: "The first oscillators as objects", motion: Motion::Moving },
        View {
            name: "plots",
            title: "R, λmax and the potential over time",
            motion: Motion::Moving,
        },
    ];
    const NAMES: &'static [&'static str] = &names::<3>(Self::VIEWS);
    const EXPORT: &'static str = "swarm";

    /// `{ count, orderParameter, rotationOrder, potential, kli, kliTime }`: the order
    /// parameter R, λmax, the potential, whether this is KLI (one pinned leader and one
    /// follower: MATH.md, "The swarm"), and then the follower's KLI clock `τ = K t / 2`.
    fn summary(&self) -> JsValue {
        let s = &self.swarm;
        Record::new()
            .set("count", s.len() as f64)
            .set("orderParameter", s.order_parameter())
            .set("rotationOrder", s.rotation_order())
            .set("potential", s.potential())
            .set("kli", self.is_kli())
            .set("kliTime", self.kli_time())
            .end()
    }

    fn paint(&self, view: &View, layer: Layer, pen: &Pen, frame: &Frame) {
        if !layer.still() {
            return;
        }
        let (width, height) = (frame.width, frame.height);
        match view.name {
            "hopf" => self.paint_sphere(pen, frame),
            "objects" => self.paint_objects(pen, width, height),
            _ => draw_history(pen, width, height, &self.history),
        }
    }

    /// CSV: a row an oscillator, `t`, its index, its quaternion `w, x, y, z`, its Hopf point.
    /// JSON: `t`, `orderParameter`, `rotationOrder`, `potential`, and each oscillator
    /// `{ quaternion: [w, x, y, z], hopf: [x, y, z] }`.
    fn export(&self, csv: bool) -> String {
        let s = &self.swarm;
        let t = s.time();
        let rows = s.quaternions().iter().zip(s.hopf_points()).enumerate().map(|(i, (&q, h))| {
            let [w, x, y, z] = to_wxyz(q);
            [t, i as f64, w, x, y, z, h.x, h.y, h.z]
        });
        let provenance = self.provenance();
        if csv {
            let columns = ["t", "oscillator", "w", "x", "y", "z", "hopfX", "hopfY", "hopfZ"];
            let rows: Vec<[f64; 9]> = rows.collect();
            return provenance.csv_comments() + &csv_table(&columns, rows.iter().map(|r| &r[..]));
        }
        let oscillators =
            rows.map(|r| Json::object().list("quaternion", &r[2..6]).list("hopf", &r[6..9]));
        provenance
            .json(Json::object())
            .number("t", t)
            .number("orderParameter", s.order_parameter())
            .number("rotationOrder", s.rotation_order())
            .number("potential", s.potential())
            .objects("oscillators", oscillators)
            .document()
    }
}

impl SwarmDemo {
    fn record(&mut self) {
        let s = &self.swarm;
        self.history.push(s.time(), s.order_parameter(), s.rotation_order(), s.potential());
    }

    fn is_kli(&self) -> bool {
        self.options.graph == Graph::Leader && self.swarm.len() == 2 && self.options.leaders == 1
    }

    fn kli_time(&self) -> f64 {
        0.5 * self.options.coupling * self.swarm.time()
    }

    /// The swarm's options and seed, and the columns' units.
    fn provenance(&self) -> Provenance {
        let o = &self.options;
        let start = match o.start_spread {
            Some(spread) => Value::Number(spread),
            None => Value::Text("uniform on S^3".into()),
        };
        Provenance {
            what: "a swarm of the non-abelian Kuramoto (Lohe) model on S^3: each oscillator's rotation at time t",
            parameters: vec![
                ("count", Value::Number(o.count as f64)),
                ("coupling", Value::Number(o.coupling)),
                ("graph", Value::Text(o.graph.name().into())),
                ("leaders", Value::Number(o.leaders as f64)),
                ("frequencySpread", Value::Number(o.frequency_spread)),
                ("startSpread", start),
                ("seed", Value::Number(o.seed as f64)),
                ("dt", Value::Number(DT)),
                ("integrator", Value::Text("geodesic RK4".into())),
            ],
            units: &[
                ("quaternions", "[w, x, y, z], scalar first, unit"),
                ("t", "the model's time (dimensionless)"),
                ("oscillator", "index, from 0 (the leaders first)"),
                ("orderParameter", "R = |mean of q|, from 0 to 1"),
                (
                    "rotationOrder",
                    "largest eigenvalue of mean(q qT), from 1/4 to 1 (blind to the sign of q)",
                ),
                (
                    "hopf",
                    "the point of the unit sphere S^2 the body's x-axis points to (paper eq. 5)",
                ),
            ],
        }
    }

    fn paint_sphere(&self, pen: &Pen, frame: &Frame) {
        let viewport = frame.sphere_viewport();
        draw_swarm_sphere(pen, &viewport, &frame.camera, &self.swarm.hopf_points());
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
}

#[wasm_bindgen(typescript_custom_section)]
const TYPES: &'static str = r#"
/** What a swarm sums up to now: its count, the order parameter R (0 to 1), λmax (1/4 to 1), the
 *  potential, whether it is KLI (one pinned leader, one follower) and the follower's clock
 *  τ = Kt/2. */
export interface SwarmSummary {
  count: number;
  orderParameter: number;
  rotationOrder: number;
  potential: number;
  kli: boolean;
  kliTime: number;
}
"#;
