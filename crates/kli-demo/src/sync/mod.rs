//! The `SyncDemo` class: the synchronisation page's run. Its `model` (the graph, the
//! measurements, both solutions and the flow), its pictures (`view`), its data (`export`), a
//! user's own file (`file`, its rotations; `map`, the whole pose graph drawn as a map by
//! `map_view`, from its `initial` estimate) and the built-in pose graph (`world`) are modules of
//! their own; this file is the class, its options, its time and the sweep.

mod export;
mod file;
mod initial;
mod map;
pub mod map_view;
mod model;
mod solutions;
mod view;
mod world;

use kli::KliError;
use kli::sync::Method;
use kli_wasm::error::JsResult;
use kli_wasm::options::Fields;
use kli_wasm::typed::numbers;
use wasm_bindgen::prelude::*;
use web_sys::CanvasRenderingContext2d;

pub use self::file::SyncFile;
pub use self::map::SyncMap;
use self::model::{Model, Options, Problem, Shape};
use self::solutions::Solutions;
use crate::aircraft::{Face, aircraft};
use crate::figure::{Figure, Frame, Layer, Motion, Record, View, names};
use crate::palette::{BACKGROUND, INK, KLI, SLERP};
use crate::pen::{Pen, svg_document};
use crate::stepped::{Stepped, stepped};
use crate::sweep::{Curve, draw_error_sweep};

/// The most nodes a run takes (the page's slider stops at 300).
const MAX_COUNT: f64 = 2000.0;

/// Flow steps a second of the page's clock at speed 1 (50 a 60 Hz frame), before the bound.
const PACE: f64 = 3000.0;

/// The most edge visits (`edges × steps`) one `advance` takes: about 1 ms in Chromium, so a
/// frame keeps its budget whatever the graph (the flow slows down rather than falls behind).
const FRAME_WORK: f64 = 5e4;

/// The most edge visits one `seek` takes, a task at a time.
const TASK_WORK: f64 = 1e6;

/// The most nodes a sweep's problems have.
const SWEEP_COUNT: usize = 60;

/// The most nodes of the complete graph (7,140 edges): at 300 its solutions took 1.8 s.
const MAX_COMPLETE: usize = 120;

/// The sweep's curves, in the order the page asks for them.
const CURVES: [Curve; 3] = [
    Curve { name: "spectral", colour: INK },
    Curve { name: "chordal", colour: KLI },
    Curve { name: "robust", colour: SLERP },
];

/// A graph of `n` rotations with measured relative rotations, both solutions, and the Lohe flow
/// from a random start with its history.
#[wasm_bindgen]
pub struct SyncDemo {
    model: Model,
    mesh: Vec<Face>,
    /// Steps owed to the clock: a frame's share of a step carries over to the next.
    owed: f64,
}

#[wasm_bindgen(typescript_custom_section)]
const TYPES: &'static str = r#"
/** How the synchronisation page's problem is made; every key is optional. */
export interface SyncDemoOptions {
  /** How many nodes, 3 to 2,000 (120 for the complete graph). Default 100. */
  count?: number;
  /** "random" (nearest neighbours in a square), "ring", "grid" or "complete". Default "random". */
  graph?: string;
  /** The standard deviation of each measurement's angle of noise, degrees, 0 to 180. Default 5. */
  noise?: number;
  /** The share of edges measured as uniformly random rotations, 0 to 1. Default 0.1. */
  wrong?: number;
  /** The seed of the graph, the truth, the measurements and the flow's start. Default 1. */
  seed?: number;
  /** Every measurement the identity: consensus (noise and wrong ignored). Default false. */
  consensus?: boolean;
}
/** What a synchronisation run sums up to: the graph, the flow now, and both solutions (errors in
 *  degrees, after the best gauge). */
export interface SyncSummary {
  count: number;
  edges: number;
  wrong: number;
  time: number;
  cost: number;
  errorDegrees: number;
  arrived: boolean;
  chordalCost: number;
  chordalErrorDegrees: number;
  certified: boolean;
  lambdaMin: number;
  robustErrorDegrees: number;
  flagged: number;
  flaggedWrong: number;
  /** Whether the solutions are in (a run made by `SyncDemo.unsolved` takes them later); until
   *  then the solutions' numbers are NaN and `certified` and `arrived` false. */
  solved: boolean;
}
"#;

#[wasm_bindgen]
extern "C" {
    #[wasm_bindgen(typescript_type = "SyncDemoOptions")]
    pub type SyncDemoOptions;
}

#[wasm_bindgen]
impl SyncDemo {
    /// The problem the options describe, solved both ways, and the flow at its start; an Error
    /// naming the option that is out of range.
    #[wasm_bindgen(constructor)]
    pub fn new(options: Option<SyncDemoOptions>) -> JsResult<SyncDemo> {
        let model = Model::new(read_options(options.map(JsValue::from))?)?;
        Ok(SyncDemo { model, mesh: aircraft(), owed: 0.0 })
    }

    /// The problem the options describe and the flow at its start, not yet solved (a few
    /// milliseconds): its solutions come from `SyncDemo.solve` with the same options, run
    /// elsewhere (a worker), through `takeSolutions`. Until then the views draw the flow alone.
    pub fn unsolved(options: Option<SyncDemoOptions>) -> JsResult<SyncDemo> {
        let model = Model::unsolved(read_options(options.map(JsValue::from))?)?;
        Ok(SyncDemo { model, mesh: aircraft(), owed: 0.0 })
    }

    /// Both solutions of the problem the options describe, as numbers for `takeSolutions` (the
    /// long part of `new`: run it in a worker).
    pub fn solve(options: Option<SyncDemoOptions>) -> JsResult<Vec<f64>> {
        let problem = Problem::new(&read_options(options.map(JsValue::from))?)?;
        Ok(Solutions::of(&problem)?.pack())
    }

    /// Takes the solutions `SyncDemo.solve` computed for this run's options; an Error naming
    /// `solutions` when they are not that call's numbers for a problem of this size.
    #[wasm_bindgen(js_name = takeSolutions)]
    pub fn take_solutions(
        &mut self,
        #[wasm_bindgen(unchecked_param_type = "Float64Array")] solutions: &JsValue,
    ) -> JsResult<()> {
        let p = &self.model.problem;
        let (n, m) = (p.truth.len(), p.graph.edges().len());
        // Read through the input layer, so a Proxy, null or a string is refused by name too.
        let data = numbers("solutions", solutions, Solutions::length(n, m))?;
        self.model.solutions = Some(Solutions::unpack(&data, n, m)?);
        Ok(())
    }

    /// One value of the sweep: the median error to the truth (radians) of `method`'s solution
    /// ("spectral", "chordal" or "robust") of the problem these options make with the share
    /// `wrong` of wrong edges, on at most 60 nodes. A call a task keeps each task
    /// short (a few milliseconds): the sweep fills itself while the page is in use.
    #[wasm_bindgen(js_name = sweepError)]
    pub fn sweep_error(
        options: Option<SyncDemoOptions>,
        wrong: f64,
        method: &str,
    ) -> JsResult<f64> {
        let mut options = read_options(options.map(JsValue::from))?;
        options.wrong = kli_wasm::options::share("wrong", wrong)?;
        options.count = options.count.min(SWEEP_COUNT);
        let method: Method = method.parse()?;
        let problem = Problem::new(&options)?;
        Ok(problem.median_error(&problem.solve(method)?.rotations))
    }

    /// The sweep so far (`shares`, and 3 errors a share in radians: spectral, chordal, robust),
    /// the page's share marked.
    #[wasm_bindgen(js_name = drawSweep)]
    pub fn draw_sweep(
        ctx: &CanvasRenderingContext2d,
        #[wasm_bindgen(unchecked_param_type = "Frame")] frame: &JsValue,
        shares: &[f64],
        errors: &[f64],
        current: f64,
    ) {
        let frame = Frame::read(frame);
        let pen = Pen::begin(ctx, frame.width, frame.height, frame.pixel_ratio, BACKGROUND);
        pen.scale_text(frame.text_scale);
        sweep(&pen, (frame.width, frame.height), shares, errors, current);
    }

    /// The sweep as an SVG document (see `drawSweep`).
    #[wasm_bindgen(js_name = sweepSvg)]
    pub fn sweep_svg(
        #[wasm_bindgen(unchecked_param_type = "Frame")] frame: &JsValue,
        shares: &[f64],
        errors: &[f64],
        current: f64,
    ) -> String {
        let frame = Frame::read(frame);
        let title = "Each solution's median error against the share of wrong edges";
        svg_document(frame.width, frame.height, title, &|pen| {
            pen.scale_text(frame.text_scale);
            sweep(pen, (frame.width, frame.height), shares, errors, current)
        })
    }
}

fn sweep(pen: &Pen, size: (f64, f64), shares: &[f64], errors: &[f64], current: f64) {
    let title = "median error against the share of wrong edges";
    draw_error_sweep(pen, size, title, &CURVES, 0.4, (shares, errors), current);
}

/// The options, checked: an Error names the option.
fn read_options(value: Option<JsValue>) -> Result<Options, KliError> {
    let example = "{ count: 100, graph: \"random\", noise: 5, wrong: 0.1, seed: 1 }";
    let keys = ["count", "graph", "noise", "wrong", "seed", "consensus"];
    let mut options = Options {
        count: 100,
        shape: Shape::Random,
        noise: 5.0,
        wrong: 0.1,
        seed: 1,
        consensus: false,
    };
    let Some(fields) = Fields::new(value, &keys, example)? else { return Ok(options) };
    if let Some(count) = fields.whole("count", 3.0, MAX_COUNT)? {
        options.count = count as usize;
    }
    if let Some(name) = fields.name("graph")? {
        options.shape = Shape::from_name(&name).ok_or_else(|| {
            KliError::new("graph", kli::ErrorKind::UnknownName { got: name, allowed: Shape::NAMES })
        })?;
    }
    if options.shape == Shape::Complete && options.count > MAX_COMPLETE {
        let problem = format!(
            "must be at most {MAX_COMPLETE} for the complete graph ({} edges; got {})",
            MAX_COMPLETE * (MAX_COMPLETE - 1) / 2,
            options.count
        );
        return Err(KliError::invalid("count", problem));
    }
    if let Some(noise) = fields.degrees("noise")? {
        options.noise = noise;
    }
    if let Some(wrong) = fields.share("wrong")? {
        options.wrong = wrong;
    }
    if let Some(seed) = fields.seed("seed")? {
        options.seed = seed;
    }
    if let Some(consensus) = fields.boolean("consensus")? {
        options.consensus = consensus;
    }
    Ok(options)
}

crate::figure::figure_class!(SyncDemo, "SyncSummary");

/// The flow's time, in steps of `0.1 / d_max`, with no end.
impl Stepped for SyncDemo {
    const PACE: f64 = PACE;
    const FRAME_WORK: f64 = FRAME_WORK;
    const TASK_WORK: f64 = TASK_WORK;

    /// A visit of each edge.
    fn step_work(&self) -> f64 {
        self.model.problem.graph.edges().len() as f64
    }

    fn dt(&self) -> f64 {
        self.model.dt
    }

    fn now(&self) -> f64 {
        self.model.flow.time()
    }

    fn owed(&mut self) -> &mut f64 {
        &mut self.owed
    }

    /// False if the flow refused (it does not: its step is valid and the count bounded).
    fn steps(&mut self, steps: f64) -> bool {
        self.model.step(steps as usize).is_ok()
    }
}

stepped!(SyncDemo);

/// The synchronisation page's views: the graph, the Hopf sphere, the first nodes, the flow's
/// plots, and the two solutions side by side; its data, the graph, the truth and the solutions.
impl Figure for SyncDemo {
    const VIEWS: &'static [View] = &[
        View {
            name: "graph",
            title: "The graph: edges by residual, nodes by error",
            motion: Motion::Moving,
        },
        View { name: "hopf", title: "Every node and its truth on S²", motion: Motion::Moving },
        View { name: "objects", title: "The first nodes over their truth", motion: Motion::Moving },
        View {
            name: "plots",
            title: "The flow's cost and error over time",
            motion: Motion::Moving,
        },
        View {
            name: "results",
            title: "The chordal and robust solutions' residuals",
            motion: Motion::Still,
        },
    ];
    const NAMES: &'static [&'static str] = &names::<5>(Self::VIEWS);
    const EXPORT: &'static str = "edges";

    /// `{ count, edges, wrong, time, cost, errorDegrees, arrived, chordalCost,
    /// chordalErrorDegrees, certified, lambdaMin, robustErrorDegrees, flagged, flaggedWrong,
    /// solved }`.
    fn summary(&self) -> JsValue {
        let m = &self.model;
        let p = &m.problem;
        let solved = m.solutions.as_ref();
        let certificate = solved.and_then(|s| s.chordal.certificate);
        let flags = solved.and_then(|s| s.robust.outliers.as_deref()).unwrap_or(&[]);
        let error = |q: &[glam::DQuat]| p.median_error(q).to_degrees();
        Record::new()
            .set("count", p.truth.len() as f64)
            .set("edges", p.graph.edges().len() as f64)
            .set("wrong", p.wrong.iter().filter(|&&w| w).count() as f64)
            .set("time", m.flow.time())
            .set("cost", m.flow.cost())
            .set("errorDegrees", error(m.flow.rotations()))
            .set("arrived", m.arrived())
            .set("chordalCost", solved.map_or(f64::NAN, |s| s.chordal.cost))
            .set("chordalErrorDegrees", solved.map_or(f64::NAN, |s| error(&s.chordal.rotations)))
            .set("certified", certificate.is_some_and(|c| c.certified))
            .set("lambdaMin", certificate.map_or(f64::NAN, |c| c.lambda_min))
            .set("robustErrorDegrees", solved.map_or(f64::NAN, |s| error(&s.robust.rotations)))
            .set("flagged", flags.iter().filter(|&&f| f).count() as f64)
            .set(
                "flaggedWrong",
                flags.iter().zip(&p.wrong).filter(|&(&f, &w)| f && w).count() as f64,
            )
            .set("solved", solved.is_some())
            .end()
    }

    fn paint(&self, which: &View, layer: Layer, pen: &Pen, frame: &Frame) {
        if !layer.still() {
            return;
        }
        let size = (frame.width, frame.height);
        match which.name {
            "graph" => view::draw_graph(pen, &self.model, size),
            "hopf" => view::draw_sphere(pen, &self.model, &frame.sphere_viewport(), &frame.camera),
            "objects" => view::draw_objects(pen, &self.model, &self.mesh, size),
            "plots" => view::draw_plots(pen, &self.model, size),
            _ => view::draw_results(pen, &self.model, size),
        }
    }

    fn export(&self, csv: bool) -> String {
        export::export(&self.model, csv)
    }
}

#[cfg(test)]
mod tests;
