//! The `KliDemo` class: one per choice of `p`, `r` and options, holding the computed [`Scene`] and
//! drawing its views onto canvas contexts the page passes in.

pub mod paper;

use std::cell::OnceCell;

use js_sys::{Array, Float64Array, Object, Reflect};
use kli::quaternion::to_wxyz;
use kli_wasm::error::JsResult;
use kli_wasm::options::{KliOptionsObject, pair_and_options};
use kli_wasm::read::{Order, QuaternionLike};
use wasm_bindgen::prelude::*;

use self::paper::{PAPER_P, PAPER_R};
use crate::aircraft::{Face, aircraft};
use crate::camera::Viewport;
use crate::clock::Clock;
use crate::figure::{Figure, Frame, Layer, Motion, Record, View, finite, names};
use crate::format::{Json, csv_table, fixed, number};
use crate::object_view::{draw_object, object_camera};
use crate::palette::{INK, KLI, MUTED, SLERP};
use crate::pen::Pen;
use crate::plots::{draw_plot_cursors, draw_plots};
use crate::provenance::{Provenance, Value};
use crate::scene::Scene;
use crate::sphere_view::{draw_sphere, draw_sphere_cursor};

/// The KLI run behind the demo page, and its canvas views.
#[wasm_bindgen]
pub struct KliDemo {
    scene: Scene,
    mesh: Vec<Face>,
    flipped: bool,
    /// How quaternions go in and out, as in the package's calls.
    order: Order,
    /// The time on show, in `[0, T]`.
    clock: Clock,
    /// The summary, made at its first read (a readout asks for it every frame).
    summary: OnceCell<JsValue>,
}

#[wasm_bindgen]
impl KliDemo {
    /// Runs KLI from p to r with the same arguments, checks and errors as `kli`.
    #[wasm_bindgen(constructor)]
    pub fn new(
        p: &QuaternionLike,
        r: &QuaternionLike,
        options: Option<KliOptionsObject>,
    ) -> JsResult<KliDemo> {
        let (p, r, options, order) = pair_and_options(p, r, options)?;
        let path = kli::kli(p, r, &options)?;
        // The target is r or -r bit for bit, so this is the core's own choice, not a re-derivation.
        let flipped = path.target() != r;
        let clock = Clock::new(0.0, path.final_time());
        let scene = Scene::new(path);
        Ok(KliDemo { scene, mesh: aircraft(), flipped, order, clock, summary: OnceCell::new() })
    }

    /// The exact q(t) of this run's flow (closed form), as the package's `KliPath.exactAt`; a
    /// time that is not finite is t = 0. The run hands out no path object of its own: the
    /// package's `kli(p, r, options)` is the path, to keep and free.
    #[wasm_bindgen(js_name = exactAt)]
    pub fn exact_at(&self, t: f64) -> JsResult<Vec<f64>> {
        let q = self.scene.path().exact_at(finite(t))?;
        Ok(self.order.write(q).to_vec())
    }

    /// Table 1's moments that lie before T, then T.
    #[wasm_bindgen(getter)]
    pub fn moments(&self) -> Vec<f64> {
        self.scene.moments()
    }

    /// The integrated q at t (between samples by normalised linear interpolation).
    #[wasm_bindgen(js_name = integratedAt)]
    pub fn integrated_at(&self, t: f64) -> Vec<f64> {
        self.order.write(self.scene.integrated_at(finite(t).max(0.0))).to_vec()
    }

    /// SLERP on the same clock, at its parameter u = t / T.
    #[wasm_bindgen(js_name = slerpAt)]
    pub fn slerp_at(&self, t: f64) -> Vec<f64> {
        self.order.write(self.scene.slerp_at(finite(t).max(0.0))).to_vec()
    }
}

impl KliDemo {
    /// Whether this run is the paper's example (`p = k`, `r = ½(1 + i + j + k)`), whose Table 1
    /// the paper prints.
    fn is_paper_example(&self) -> bool {
        let path = self.scene.path();
        to_wxyz(path.quaternions()[0]) == PAPER_P && to_wxyz(path.target()) == PAPER_R
    }
}

#[wasm_bindgen]
impl KliDemo {
    /// The paper's printed Table 1 row at `t` beside this run, or `undefined` when the run is not
    /// the paper's example or Table 1 has no row at `t`: `{ printed: [w, x, y, z], verdicts:
    /// ["agrees" | "truncated" | "differs", …], repeats?: t }`, the verdicts against the closed
    /// form, `repeats` the time of the row above when this row is printed the same as it.
    #[wasm_bindgen(js_name = printedRow, unchecked_return_type = "PrintedRow | undefined")]
    pub fn printed_row(&self, t: f64) -> JsValue {
        let (Some((index, printed)), true) = (paper::printed_row(t), self.is_paper_example())
        else {
            return JsValue::UNDEFINED;
        };
        let Ok(exact) = self.scene.path().exact_at(t) else { return JsValue::UNDEFINED };
        let exact = to_wxyz(exact);
        let verdicts: Array =
            (0..4).map(|c| JsValue::from(paper::verdict(printed[c], exact[c]).name())).collect();
        let row = Object::new();
        let set = |key: &str, value: JsValue| {
            let _ = Reflect::set(&row, &key.into(), &value);
        };
        set("printed", Float64Array::from(&printed[..]).into());
        set("verdicts", verdicts.into());
        if let Some(above) = paper::repeats_row_above(index) {
            set("repeats", above.into());
        }
        row.into()
    }

    /// The paper's eq. 4 as printed (the typo), integrated from this run's `p` towards its target
    /// by RK4 with δ = 0.01: `[|q|, ‖target − q‖]` at each of `times` (sorted, finite, ≥ 0;
    /// others are dropped).
    #[wasm_bindgen(js_name = integrateAsPrinted)]
    pub fn integrate_as_printed(&self, times: &[f64]) -> Vec<f64> {
        let mut times: Vec<f64> =
            times.iter().copied().filter(|t| t.is_finite() && *t >= 0.0 && *t <= 1e4).collect();
        times.sort_by(f64::total_cmp);
        let path = self.scene.path();
        let (p, r) = (path.quaternions()[0], path.target());
        // The times were filtered and sorted above and the run's ends are units, so this cannot
        // fail; an empty answer stands in should it ever.
        kli::model::integrate_as_printed(p, r, 0.01, &times)
            .unwrap_or_default()
            .into_iter()
            .flat_map(|q| [q.length(), (r - q).length()])
            .collect()
    }
}

crate::clock::clocked!(KliDemo);

crate::figure::figure_class!(KliDemo, "KliSummary");

/// The KLI page's views: Fig. 2 live (the object), Fig. 1 (the Hopf curves), the filmstrip of
/// Fig. 2, and the plots; its time, the flow's from 0 to T; its data, the path.
impl Figure for KliDemo {
    const VIEWS: &'static [View] = &[
        View {
            name: "object",
            title: "The object under KLI and under SLERP",
            motion: Motion::Moving,
        },
        View {
            name: "hopf",
            title: "The Hopf curves of KLI and SLERP on S²",
            motion: Motion::Layered,
        },
        View {
            name: "filmstrip",
            title: "The object at the moments of the paper's Table 1",
            motion: Motion::Still,
        },
        View {
            name: "plots",
            title: "Distance to the target, KLI's SLERP parameter s(t) beside SLERP's u = t/T, the drift of |q|",
            motion: Motion::Layered,
        },
    ];
    const NAMES: &'static [&'static str] = &names::<4>(Self::VIEWS);
    const EXPORT: &'static str = "path";

    /// `{ finalTime, steps, predictedTime, flipped, paperExample }`: T, the steps taken, the
    /// closed form's T* for the same tolerance, whether the flow goes to −r (shortestPath and
    /// p·r < 0, the same rotation as r), and whether this is the paper's example
    /// (`p = k`, `r = ½(1 + i + j + k)`), whose Table 1 the paper prints.
    fn summary(&self) -> JsValue {
        let make = || {
            let path = self.scene.path();
            Record::new()
                .set("finalTime", path.final_time())
                .set("steps", path.steps() as f64)
                .set("predictedTime", self.scene.predicted_time())
                .set("flipped", self.flipped)
                .set("paperExample", self.is_paper_example())
                .end()
        };
        self.summary.get_or_init(make).clone()
    }

    fn paint(&self, view: &View, layer: Layer, pen: &Pen, frame: &Frame) {
        let (width, height, t) = (frame.width, frame.height, frame.t.max(0.0));
        match view.name {
            "object" => self.paint_object(pen, width, height, t),
            "hopf" => {
                let viewport = frame.sphere_viewport();
                if layer.still() {
                    draw_sphere(pen, &viewport, &frame.camera, &self.scene);
                }
                if layer != Layer::Still {
                    draw_sphere_cursor(pen, &viewport, &frame.camera, &self.scene, t);
                }
            }
            "filmstrip" => {
                if layer.still() {
                    self.paint_filmstrip(pen, width, height)
                }
            }
            _ => {
                if layer.still() {
                    draw_plots(pen, width, height, &self.scene);
                }
                if layer != Layer::Still {
                    draw_plot_cursors(pen, width, height, &self.scene, t);
                }
            }
        }
    }

    /// The path, a row a sample: `t`, the integrated quaternion `w, x, y, z`, KLI's SLERP
    /// parameter s(t) it sits at (not SLERP's clock u = t/T), the distance `‖target − q‖`, and its Hopf point. JSON adds the
    /// run (`p`, `target`, `finalTime`, `steps`).
    fn export(&self, csv: bool) -> String {
        const COLUMNS: [&str; 11] = [
            "t",
            "w",
            "x",
            "y",
            "z",
            "slerpParameter",
            "distance",
            "angleToTarget",
            "hopfX",
            "hopfY",
            "hopfZ",
        ];
        let rows: Vec<[f64; 11]> = self.rows().collect();
        let provenance = self.provenance();
        if csv {
            let table = csv_table(&COLUMNS, rows.iter().map(|r| &r[..]));
            return provenance.csv_comments() + &table;
        }
        let path = self.scene.path();
        let samples = rows.iter().map(|r| {
            Json::object()
                .number("t", r[0])
                .list("quaternion", &r[1..5])
                .number("slerpParameter", r[5])
                .number("distance", r[6])
                .number("angleToTarget", r[7])
                .list("hopf", &r[8..11])
        });
        provenance
            .json(Json::object())
            .list("p", &to_wxyz(path.quaternions()[0]))
            .list("target", &to_wxyz(path.target()))
            .number("finalTime", path.final_time())
            .number("steps", path.steps() as f64)
            .objects("samples", samples)
            .document()
    }
}

/// The angle in degrees of the rotation taking `q` to `target`: `2·φ` for the angle `φ` between
/// them on S³ (of the closer sign), by `φ = 2 atan2(|q − r|, |q + r|)`, accurate at both ends.
fn rotation_angle_degrees(q: glam::DQuat, target: glam::DQuat) -> f64 {
    let r = if q.dot(target) < 0.0 { -target } else { target };
    let phi = 2.0 * (q - r).length().atan2((q + r).length());
    (2.0 * phi).to_degrees()
}

impl KliDemo {
    /// The exported rows: t, w, x, y, z, s, distance, angle to the target (degrees), Hopf x, y,
    /// z (every number finite).
    fn rows(&self) -> impl Iterator<Item = [f64; 11]> + '_ {
        let s = &self.scene;
        let path = s.path();
        // The Hopf points as the package computes them (the scene's are of normalised samples).
        let hopf = path.hopf_curve();
        let target = path.target();
        path.times().iter().zip(path.quaternions()).zip(hopf).enumerate().map(
            move |(i, ((&t, &q), h))| {
                let [w, x, y, z] = to_wxyz(q);
                let angle = rotation_angle_degrees(q, target);
                [t, w, x, y, z, s.warp()[i], s.distances()[i], angle, h.x, h.y, h.z]
            },
        )
    }

    /// The run's parameters and the columns' units, for both exports.
    fn provenance(&self) -> Provenance {
        let path = self.scene.path();
        let options = path.options();
        let r = if self.flipped { -path.target() } else { path.target() };
        let rule = if options.shortest_path {
            "shortest path: the flow goes to -r when p·r < 0 (the same rotation, the shorter arc)"
        } else {
            "as given: the flow goes to r even when p·r < 0"
        };
        Provenance {
            what: "KLI (Kuramoto–Lohe interpolation, Kapić and Crnkić): the path q(t) from p towards r, integrated until |target - q| < epsilon",
            parameters: vec![
                ("p", Value::List(to_wxyz(path.quaternions()[0]).to_vec())),
                ("r", Value::List(to_wxyz(r).to_vec())),
                ("target", Value::List(to_wxyz(path.target()).to_vec())),
                ("epsilon", Value::Number(options.tolerance)),
                ("delta", Value::Number(options.step)),
                ("integrator", Value::Text(options.integrator.name().into())),
                ("shortestPath", Value::Flag(options.shortest_path)),
                ("rule", Value::Text(rule.into())),
                ("finalTime", Value::Number(path.final_time())),
            ],
            units: &[
                ("quaternions", "[w, x, y, z], scalar first, unit"),
                ("t", "the flow's time (the paper's t, dimensionless), not seconds"),
                ("slerpParameter", "s(t) with q(t) = slerp(p, target; s), from 0 to 1"),
                ("distance", "|target - q| in R^4 (the paper's stopping test), not an angle"),
                ("angleToTarget", "degrees: the rotation from q(t) to the target"),
                (
                    "hopf",
                    "the point of the unit sphere S^2 the body's x-axis points to (paper eq. 5)",
                ),
            ],
        }
    }

    fn paint_object(&self, pen: &Pen, width: f64, height: f64, t: f64) {
        let camera = object_camera();
        let side_by_side = width >= height;
        let (w, h) = if side_by_side { (width / 2.0, height) } else { (width, height / 2.0) };
        let panels = [
            (self.scene.integrated_at(t), KLI, format!("KLI  t = {}", fixed(t, 2))),
            (
                self.scene.slerp_at(t),
                SLERP,
                format!("SLERP  u = t/T = {}", fixed(self.scene.clock_fraction(t), 3)),
            ),
        ];
        for (i, (q, color, label)) in panels.iter().enumerate() {
            let (left, top) = if side_by_side { (i as f64 * w, 0.0) } else { (0.0, i as f64 * h) };
            let viewport = Viewport::fitting(left, top + 10.0, w, h - 10.0, 1.6);
            draw_object(pen, &viewport, &camera, &self.mesh, *q, true);
            pen.text(label, (left + 10.0, top + 14.0), color, 13.0, "left");
        }
    }

    fn paint_filmstrip(&self, pen: &Pen, width: f64, height: f64) {
        let camera = object_camera();
        let moments = self.scene.moments();
        let cell = width / moments.len() as f64;
        let last = moments.len() - 1;
        let labels = |short: bool| -> Vec<String> {
            let t = |i: usize, m: f64| if i == last { fixed(m, 2) } else { number(m) };
            let names = if short { ("", "T ") } else { ("t = ", "T = ") };
            let name = |i: usize| if i == last { names.1 } else { names.0 };
            moments.iter().enumerate().map(|(i, &m)| format!("{}{}", name(i), t(i, m))).collect()
        };
        let fits = |labels: &[String], size: f64| {
            labels.iter().all(|l| pen.text_width(l, size) <= cell - 6.0)
        };
        let (labels, size) = [(false, 12.0), (true, 12.0), (true, 10.0), (true, 8.0)]
            .into_iter()
            .map(|(short, size)| (labels(short), size))
            .find(|(labels, size)| fits(labels, *size))
            .unwrap_or_else(|| (labels(true), 8.0));
        for (i, &t) in moments.iter().enumerate() {
            let left = i as f64 * cell;
            let viewport = Viewport::fitting(left, 0.0, cell, height - 16.0, 1.6);
            draw_object(pen, &viewport, &camera, &self.mesh, self.scene.integrated_at(t), false);
            let colour = if i == last { INK } else { MUTED };
            pen.text(&labels[i], (left + 0.5 * cell, height - 9.0), colour, size, "center");
        }
    }
}

#[wasm_bindgen(typescript_custom_section)]
const TYPES: &'static str = r#"
/** A row of the paper's printed Table 1, judged against the closed form. */
export interface PrintedRow {
  printed: Float64Array;
  verdicts: ("agrees" | "truncated" | "differs")[];
  repeats?: number;
}
"#;
