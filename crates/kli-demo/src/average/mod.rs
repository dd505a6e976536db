//! The `AverageDemo` class: the averaging page's run. Its `model` (the measurements, the four
//! means and the follower's flow), its pictures (`view`) and its data (`export`) are modules of
//! their own; this file is the class, its options, the drag of a measurement and the run
//! contract.

mod export;
mod model;
mod view;

use std::cell::OnceCell;

use js_sys::Float64Array;
use kli::KliError;
use kli::quaternion::{from_wxyz, to_wxyz};
use kli_wasm::error::JsResult;
use kli_wasm::options::Fields;
use kli_wasm::typed::numbers;
use wasm_bindgen::prelude::*;
use web_sys::CanvasRenderingContext2d;

use crate::aircraft::{Face, aircraft};
use crate::clock::Clock;
use crate::figure::{Figure, Frame, Layer, Motion, Record, View, names};
use crate::hopf_drag;
use crate::palette::BACKGROUND;
use crate::pen::{Pen, svg_document};
use model::{Model, Options, STYLES};

/// The most measurements a run takes (the page's slider stops at 500).
const MAX_COUNT: f64 = 10_000.0;

/// How many seeded sets each point of the sweep takes the median over.
const SWEEP_SETS: usize = 15;

/// n noisy measurements of a true rotation, their four means, the follower's flow, the time on
/// show, and the views.
#[wasm_bindgen]
pub struct AverageDemo {
    model: Model,
    clock: Clock,
    mesh: Vec<Face>,
    summary: OnceCell<JsValue>,
}

#[wasm_bindgen(typescript_custom_section)]
const TYPES: &'static str = r#"
/** How the averaging page's measurements are made; every key is optional. */
export interface AverageDemoOptions {
  /** How many measurements, 1 to 10,000. Default 40. */
  count?: number;
  /** The noise about each axis, degrees, 0 to 180. Default 5. */
  noise?: number;
  /** The share replaced by uniformly random rotations, 0 to 1. Default 0.2. */
  outliers?: number;
  /** The seed of the measurements (and of the truth), a whole number. Default 1. */
  seed?: number;
  /** Measurements moved by hand, 5 numbers each: index, then [w, x, y, z]. Default none. */
  moved?: ArrayLike<number>;
}
/** One mean of the measurements. */
export interface MeanSummary {
  /** "chordal", "quaternion", "geodesic" or "median". */
  method: string;
  /** The page's name for it. */
  name: string;
  /** [w, x, y, z]. */
  rotation: number[];
  /** Its angle to the truth, degrees. */
  errorDegrees: number;
  /** The RMS angle from it to the measurements, degrees. */
  dispersionDegrees: number;
  iterations: number;
}
/** What an averaging run sums up to: the count, how many are wild, how many the median marks,
 *  the truth, the four means, and the follower's flow time. */
export interface AverageSummary {
  count: number;
  wild: number;
  marked: number;
  truth: number[];
  means: MeanSummary[];
  flowTime: number;
}
"#;

#[wasm_bindgen]
extern "C" {
    #[wasm_bindgen(typescript_type = "AverageDemoOptions")]
    pub type AverageDemoOptions;
}

#[wasm_bindgen]
impl AverageDemo {
    /// The measurements the options describe, their means and the follower's flow; an Error
    /// naming the option that is out of range.
    #[wasm_bindgen(constructor)]
    pub fn new(options: Option<AverageDemoOptions>) -> JsResult<AverageDemo> {
        let model = Model::new(read_options(options.map(JsValue::from))?)?;
        let clock = Clock::new(0.0, model.end_time());
        Ok(AverageDemo { model, clock, mesh: aircraft(), summary: OnceCell::new() })
    }

    /// Where each measurement's Hopf point is drawn in the "hopf" view at `frame`: `3n`
    /// numbers, `x`, `y` (CSS pixels) and 1 when in front, 0 when behind.
    #[wasm_bindgen(js_name = measurementPoints)]
    pub fn measurement_points(
        &self,
        #[wasm_bindgen(unchecked_param_type = "Frame")] frame: &JsValue,
    ) -> Float64Array {
        hopf_drag::points_on_screen(&Frame::read(frame), &self.model.data)
    }

    /// Measurement `index` turned so that its Hopf point lands where the pointer is, at CSS
    /// pixel `(x, y)` of the "hopf" view drawn at `frame`: `[index, w, x, y, z]`, an entry of
    /// `moved` (the shortest turn taking the old point to the new, `h(R q) = R h(q)`). Empty when
    /// the pointer is off the sphere or there is no such measurement.
    #[wasm_bindgen(js_name = movedTo)]
    pub fn moved_to(
        &self,
        index: usize,
        #[wasm_bindgen(unchecked_param_type = "Frame")] frame: &JsValue,
        x: f64,
        y: f64,
    ) -> Float64Array {
        let frame = Frame::read(frame);
        let moved = self.model.data.get(index).and_then(|&q| hopf_drag::turned_to(&frame, q, x, y));
        let Some(moved) = moved else { return Float64Array::new_with_length(0) };
        let [w, x, y, z] = to_wxyz(moved);
        Float64Array::from(&[index as f64, w, x, y, z][..])
    }

    /// One point of the sweep: each mean's angle to the truth (radians), the median over 15
    /// seeded sets of measurements with these options but the outlier share `outliers`, in the
    /// order chordal, quaternion, geodesic, median.
    #[wasm_bindgen(js_name = sweepPoint)]
    pub fn sweep_point(options: Option<AverageDemoOptions>, outliers: f64) -> JsResult<Vec<f64>> {
        let options = read_options(options.map(JsValue::from))?;
        let outliers = kli_wasm::options::share("outliers", outliers)?;
        Ok(model::sweep_point(&options, outliers, SWEEP_SETS)?.to_vec())
    }

    /// The sweep so far (`shares`, and 4 errors a share in radians, as `sweepPoint` gives them),
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
        view::draw_sweep(&pen, (frame.width, frame.height), shares, errors, current);
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
        let title = "Each mean's error against the share of outliers";
        svg_document(frame.width, frame.height, title, &|pen| {
            pen.scale_text(frame.text_scale);
            view::draw_sweep(pen, (frame.width, frame.height), shares, errors, current)
        })
    }
}

/// The options, checked: an Error names the option.
fn read_options(value: Option<JsValue>) -> Result<Options, KliError> {
    let example = "{ count: 40, noise: 5, outliers: 0.2, seed: 1 }";
    let keys = ["count", "noise", "outliers", "seed", "moved"];
    let mut options = Options { count: 40, noise: 5.0, outliers: 0.2, seed: 1, moved: Vec::new() };
    let Some(fields) = Fields::new(value, &keys, example)? else { return Ok(options) };
    if let Some(count) = fields.whole("count", 1.0, MAX_COUNT)? {
        options.count = count as usize;
    }
    if let Some(noise) = fields.degrees("noise")? {
        options.noise = noise;
    }
    if let Some(outliers) = fields.share("outliers")? {
        options.outliers = outliers;
    }
    if let Some(seed) = fields.seed("seed")? {
        options.seed = seed;
    }
    if let Some(moved) = fields.value("moved")? {
        let flat = numbers("moved", &moved, 5 * MAX_COUNT as usize)?;
        if flat.len() % 5 != 0 {
            let problem = format!(
                "must hold 5 numbers a measurement: index, w, x, y, z (got {})",
                flat.len()
            );
            return Err(KliError::invalid("moved", problem));
        }
        for entry in flat.chunks_exact(5) {
            let index = kli_wasm::options::whole("moved", entry[0], 0.0, MAX_COUNT - 1.0)?;
            let q = from_wxyz([entry[1], entry[2], entry[3], entry[4]]);
            options.moved.push((index as usize, q));
        }
    }
    Ok(options)
}

impl AverageDemo {
    fn make_summary(&self) -> JsValue {
        let model = &self.model;
        let means: js_sys::Array = model
            .means
            .iter()
            .zip(&STYLES)
            .zip(model.errors())
            .map(|((mean, style), error)| {
                let rotation: js_sys::Array =
                    to_wxyz(mean.rotation).iter().map(|&c| JsValue::from(c)).collect();
                Record::new()
                    .set("method", style.method.name())
                    .set("name", style.name)
                    .set("rotation", rotation)
                    .set("errorDegrees", error.to_degrees())
                    .set("dispersionDegrees", mean.dispersion.to_degrees())
                    .set("iterations", mean.iterations as f64)
                    .end()
            })
            .collect();
        let truth: js_sys::Array = to_wxyz(model.truth).iter().map(|&c| JsValue::from(c)).collect();
        Record::new()
            .set("count", model.data.len() as f64)
            .set("wild", model.wild.iter().filter(|&&w| w).count() as f64)
            .set("marked", model.marked().iter().filter(|&&m| m).count() as f64)
            .set("truth", truth)
            .set("means", means)
            .set("flowTime", model.end_time())
            .end()
    }
}

crate::clock::clocked!(AverageDemo);

crate::figure::figure_class!(AverageDemo, "AverageSummary");

/// The averaging page's views: the measurements and the means on the Hopf sphere with the
/// follower's flow, the follower beside the truth, and the means' errors; its time, the flow's;
/// its data, the measurements and the means.
impl Figure for AverageDemo {
    const VIEWS: &'static [View] = &[
        View {
            name: "hopf",
            title: "The measurements, the four means and the follower on S²",
            motion: Motion::Layered,
        },
        View { name: "objects", title: "The follower beside the truth", motion: Motion::Moving },
        View { name: "means", title: "Each mean's angle to the truth", motion: Motion::Still },
    ];
    const NAMES: &'static [&'static str] = &names::<3>(Self::VIEWS);
    const EXPORT: &'static str = "measurements";

    /// `{ count, wild, marked, truth, means, flowTime }`: how many measurements, how many are
    /// wild, how many the median marks, the truth `[w, x, y, z]`, each mean as `{ method, name,
    /// rotation, errorDegrees, dispersionDegrees, iterations }`, and the flow's span.
    fn summary(&self) -> JsValue {
        self.summary.get_or_init(|| self.make_summary()).clone()
    }

    fn paint(&self, which: &View, layer: Layer, pen: &Pen, frame: &Frame) {
        let size = (frame.width, frame.height);
        match which.name {
            "hopf" => view::draw_sphere(pen, &self.model, frame, layer),
            "objects" if layer.still() => {
                view::draw_objects(pen, &self.model, &self.mesh, size, frame.t)
            }
            "objects" => {}
            _ if layer.still() => view::draw_means(pen, &self.model, size),
            _ => {}
        }
    }

    fn export(&self, csv: bool) -> String {
        export::export(&self.model, csv)
    }
}

#[cfg(test)]
mod tests;
