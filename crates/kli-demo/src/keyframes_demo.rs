//! The `KeyframesDemo` class: the keyframes page's three curves through the same keys (the
//! Kuramoto–Lohe chain, Squad, piecewise SLERP), their measured figures, and their views.

use glam::{DQuat, DVec3};
use js_sys::Float64Array;
use kli::KliError;
use kli::hopf::hopf;
use kli::quaternion::{from_wxyz, to_wxyz};
use kli::spline::{ChainOptions, Curve, Keys, KliSpline, PiecewiseSlerp, Squad};
use kli_wasm::error::{JsResult, throw};
use wasm_bindgen::prelude::*;

use crate::aircraft::{Face, aircraft};
use crate::camera::Viewport;
use crate::figure::{Figure, Frame, Layer, finite};
use crate::format::{Json, joined, number};
use crate::legend::{Entry, Mark, draw_legend, draw_legend_row, grouped_labels, legend_row_width};
use crate::object_view::{draw_object, object_camera};
use crate::palette::{INK, KLI, MUTED, SLERP};
use crate::pen::Pen;
use crate::plots::{Panel, inset, trim};
use crate::provenance::{Provenance, Value};
use crate::sphere_view::{Side, View, draw_globe, draw_grid_back, draw_grid_front, grid};

/// Samples a unit of time for the series and the figures (as in MATH.md's measurements).
const PER_UNIT: f64 = 256.0;

/// The most samples a curve's plots and Hopf curve hold, whatever the time range: a range of
/// 100,000 at [`PER_UNIT`] would take 2.6e7 samples a curve (26 s, then out of memory).
const MAX_PLOT_SAMPLES: f64 = 4096.0;

/// The most keys the page takes: the three curves, their figures and the key editor stay
/// within a frame's budget (1,000 keys took 9 s).
const MAX_KEYS: usize = 256;
const NAMES: [&str; 3] = ["Kuramoto–Lohe chain", "Squad", "piecewise SLERP"];
const COLOURS: [&str; 3] = [KLI, SLERP, INK];

/// One curve's precomputed views: sample times, Hopf points, |ω| and |ω̇|.
struct Series {
    hopf: Vec<DVec3>,
    speed: Vec<f64>,
    acceleration: Vec<f64>,
}

/// The three curves through one set of keys.
#[wasm_bindgen]
pub struct KeyframesDemo {
    keys: Keys,
    smoothness: f64,
    chain: KliSpline,
    squad: Squad,
    slerp: PiecewiseSlerp,
    times: Vec<f64>,
    series: Vec<Series>,
    figures: Vec<f64>,
    mesh: Vec<Face>,
}

fn series(curve: &dyn Curve, times: &[f64]) -> Series {
    let dt = times[1] - times[0];
    let omega: Vec<DVec3> = times.iter().map(|&t| curve.angular_velocity(t)).collect();
    let acceleration = (0..omega.len())
        .map(|k| {
            let (a, b) = (k.saturating_sub(1), (k + 1).min(omega.len() - 1));
            ((omega[b] - omega[a]) / ((b - a) as f64 * dt)).length()
        })
        .collect();
    Series {
        hopf: times.iter().map(|&t| hopf(curve.at(t))).collect(),
        speed: omega.iter().map(|w| w.length()).collect(),
        acceleration,
    }
}

/// `[key error, largest jump of ω at a key, ∫|ω̇|², total rotation angle ∫|ω|]` of a curve.
fn figures(curve: &dyn Curve, keys: &Keys, s: &Series, dt: f64) -> [f64; 4] {
    let key_error = keys
        .quaternions()
        .iter()
        .zip(keys.times())
        .map(|(&k, &t)| (curve.at(t) - k).length().min((curve.at(t) + k).length()))
        .fold(0.0, f64::max);
    let h = 1e-4;
    let jump = keys.times()[1..keys.len() - 1]
        .iter()
        .map(|&t| (curve.angular_velocity(t + h) - curve.angular_velocity(t - h)).length())
        .fold(0.0, f64::max);
    let bending = s.acceleration.iter().map(|a| a * a * dt).sum();
    let angle = s.speed.iter().map(|w| w * dt).sum();
    [key_error, jump, bending, angle]
}

#[wasm_bindgen]
impl KeyframesDemo {
    /// The three curves through `keys` (4m numbers, scalar first) at `times` (m numbers, or
    /// empty for 0, 1, …), the chain with `smoothness`; errors as kliSpline's.
    #[wasm_bindgen(constructor)]
    pub fn new(keys: &[f64], times: &[f64], smoothness: f64) -> JsResult<KeyframesDemo> {
        Self::build(keys, times, smoothness).map_err(throw)
    }

    fn build(flat: &[f64], times: &[f64], smoothness: f64) -> Result<KeyframesDemo, KliError> {
        if flat.len() % 4 != 0 {
            return Err(KliError::invalid(
                "keys",
                format!("must hold 4 numbers per key (got {})", flat.len()),
            ));
        }
        if flat.len() > 4 * MAX_KEYS {
            let problem = format!("may hold at most {MAX_KEYS} keys here (got {})", flat.len() / 4);
            return Err(KliError::invalid("keys", problem));
        }
        let q: Vec<DQuat> =
            flat.chunks_exact(4).map(|c| from_wxyz([c[0], c[1], c[2], c[3]])).collect();
        let keys = Keys::new(&q, (!times.is_empty()).then_some(times))?;
        let chain =
            KliSpline::new(keys.clone(), &ChainOptions { smoothness, ..Default::default() })?;
        let (squad, slerp) = (Squad::new(keys.clone()), PiecewiseSlerp::new(keys.clone()));
        let (start, end) = (keys.times()[0], keys.times()[keys.len() - 1]);
        let n = ((end - start) * PER_UNIT).ceil().clamp(16.0, MAX_PLOT_SAMPLES) as usize;
        let sample_times: Vec<f64> =
            (0..=n).map(|k| start + (end - start) * k as f64 / n as f64).collect();
        let dt = sample_times[1] - sample_times[0];
        let curves: [&dyn Curve; 3] = [&chain, &squad, &slerp];
        let series: Vec<Series> = curves.iter().map(|c| series(*c, &sample_times)).collect();
        let figures =
            curves.iter().zip(&series).flat_map(|(c, s)| figures(*c, &keys, s, dt)).collect();
        Ok(KeyframesDemo {
            keys,
            smoothness,
            chain,
            squad,
            slerp,
            times: sample_times,
            series,
            figures,
            mesh: aircraft(),
        })
    }

    /// For each curve (chain, Squad, piecewise SLERP): key error, largest jump of |ω| at a key,
    /// ∫|ω̇|² dt and the total rotation angle ∫|ω| dt: 12 numbers.
    #[wasm_bindgen(getter)]
    pub fn figures(&self) -> Float64Array {
        Float64Array::from(&self.figures[..])
    }

    /// The keys as used (signs consistent), 4m numbers.
    #[wasm_bindgen(getter)]
    pub fn keys(&self) -> Float64Array {
        let flat: Vec<f64> = self.keys.quaternions().iter().flat_map(|&q| to_wxyz(q)).collect();
        Float64Array::from(&flat[..])
    }

    #[wasm_bindgen(getter, js_name = keyTimes)]
    pub fn key_times(&self) -> Float64Array {
        Float64Array::from(self.keys.times())
    }

    #[wasm_bindgen(getter, js_name = endTime)]
    pub fn end_time(&self) -> f64 {
        self.chain.end_time()
    }

    #[wasm_bindgen(getter, js_name = startTime)]
    pub fn start_time(&self) -> f64 {
        self.chain.start_time()
    }

    #[wasm_bindgen(getter)]
    pub fn residual(&self) -> f64 {
        self.chain.residual()
    }

    #[wasm_bindgen(getter)]
    pub fn iterations(&self) -> usize {
        self.chain.iterations()
    }

    /// The three curves' rotations at `t`, 12 numbers (chain, Squad, piecewise SLERP).
    pub fn at(&self, t: f64) -> Float64Array {
        let curves: [&dyn Curve; 3] = [&self.chain, &self.squad, &self.slerp];
        let flat: Vec<f64> = curves.iter().flat_map(|c| to_wxyz(c.at(finite(t)))).collect();
        Float64Array::from(&flat[..])
    }

    /// Where each key's Hopf point is drawn in the "hopf" view at `frame`: `3m` numbers, `x`,
    /// `y` (CSS pixels) and 1 when in front, 0 when behind.
    #[wasm_bindgen(js_name = keyPoints)]
    pub fn key_points(
        &self,
        #[wasm_bindgen(unchecked_param_type = "Frame")] frame: &JsValue,
    ) -> Float64Array {
        let frame = Frame::read(frame);
        let (viewport, camera) = (frame.sphere_viewport(), frame.camera);
        let flat: Vec<f64> = self
            .keys
            .quaternions()
            .iter()
            .flat_map(|&k| {
                let p = camera.project(hopf(k));
                let (x, y) = viewport.pixel(p);
                [x, y, if p.depth >= 0.0 { 1.0 } else { 0.0 }]
            })
            .collect();
        Float64Array::from(&flat[..])
    }

    /// The keys (`4m` numbers) with key `index` turned so that its Hopf point lands where the
    /// pointer is, at CSS pixel `(x, y)` of the "hopf" view drawn at `frame`: the turn is the
    /// shortest rotation taking the old point to the new (`h(R q) = R h(q)`). Empty when the
    /// pointer is off the sphere.
    #[wasm_bindgen(js_name = keysWithKeyAt)]
    pub fn keys_with_key_at(
        &self,
        index: usize,
        #[wasm_bindgen(unchecked_param_type = "Frame")] frame: &JsValue,
        x: f64,
        y: f64,
    ) -> Float64Array {
        let frame = Frame::read(frame);
        let (sx, sy) = frame.sphere_viewport().unpixel((x, y));
        let target = frame.camera.unproject_on_sphere(sx, sy);
        let keys = self.keys.quaternions();
        let (Some(target), Some(&key)) = (target, keys.get(index)) else {
            return Float64Array::new_with_length(0);
        };
        let turn = DQuat::from_rotation_arc(hopf(key), target);
        let flat: Vec<f64> = keys
            .iter()
            .enumerate()
            .flat_map(|(i, &k)| to_wxyz(if i == index { (turn * k).normalize() } else { k }))
            .collect();
        Float64Array::from(&flat[..])
    }

    /// Key `index` in polar form, `[Ux, Uy, Uz, θ]` (`θ` in radians, as `axisAngle`).
    #[wasm_bindgen(js_name = keyAxisAngle)]
    pub fn key_axis_angle(&self, index: usize) -> JsResult<Float64Array> {
        let key = self.keys.quaternions().get(index).copied().ok_or_else(|| {
            throw(KliError::invalid(
                "index",
                format!("must be below the number of keys ({})", self.keys.len()),
            ))
        })?;
        let (axis, angle) = kli::axis_angle(key).map_err(throw)?;
        Ok(Float64Array::from(&[axis.x, axis.y, axis.z, angle][..]))
    }

    /// The keys (`4m` numbers) with key `index` replaced by the rotation by `angle` radians about
    /// `axis`; errors as `fromAxisAngle`'s (naming `axis` or `angle`).
    #[wasm_bindgen(js_name = keysWithAxisAngle)]
    pub fn keys_with_axis_angle(
        &self,
        index: usize,
        axis: &[f64],
        angle: f64,
    ) -> JsResult<Float64Array> {
        let axis = match axis {
            [x, y, z] => DVec3::new(*x, *y, *z),
            _ => {
                return Err(throw(KliError::invalid(
                    "axis",
                    format!("must hold 3 numbers (got {})", axis.len()),
                )));
            }
        };
        let key = kli::from_axis_angle(axis, angle).map_err(throw)?;
        let flat: Vec<f64> = self
            .keys
            .quaternions()
            .iter()
            .enumerate()
            .flat_map(|(i, &k)| to_wxyz(if i == index { key } else { k }))
            .collect();
        Ok(Float64Array::from(&flat[..]))
    }
}

crate::figure_class!(KeyframesDemo);

/// The keyframes page's views: the object under each curve, the three Hopf curves through the
/// keys, and |ω|, |ω̇| plotted; its data, the three curves sampled.
impl Figure for KeyframesDemo {
    const VIEWS: &'static [&'static str] = &["objects", "hopf", "plots"];
    const TITLES: &'static [&'static str] = &[
        "The object under each curve",
        "The three curves' Hopf images on S²",
        "|ω(t)| and |ω̇(t)| of the three curves",
    ];
    const EXPORT: &'static str = "curves";

    fn paint(&self, view: usize, layer: Layer, pen: &Pen, frame: &Frame) {
        let (width, height, t) = (frame.width, frame.height, frame.t);
        match view {
            0 if layer.still() => self.paint_objects(pen, width, height, t),
            0 => {}
            1 => self.paint_sphere(pen, frame, layer),
            _ => self.paint_plots(pen, width, height, t, layer),
        }
    }

    /// CSV: a row a curve and sample time, `t`, the curve ("chain", "squad", "slerp"), its
    /// quaternion `w, x, y, z`, |ω| and its Hopf point, after the run's parameters as `#`
    /// lines. JSON: the parameters, `keys` ([w, x, y, z] each), `keyTimes`, and each curve's
    /// `samples`, `{ t, quaternion, angularSpeed, hopf }`.
    fn export(&self, csv: bool) -> String {
        let provenance = self.provenance();
        if csv {
            let mut text = provenance.csv_comments();
            text.push_str("t,curve,w,x,y,z,angularSpeed,hopfX,hopfY,hopfZ\n");
            for (name, curve, s) in self.named_curves() {
                for (k, &t) in self.times.iter().enumerate() {
                    let [w, x, y, z] = to_wxyz(curve.at(t));
                    let h = s.hopf[k];
                    let fields = joined(&[w, x, y, z, s.speed[k], h.x, h.y, h.z], ",");
                    text.push_str(&format!("{},{name},{fields}\n", number(t)));
                }
            }
            return text;
        }
        let keys: Vec<f64> = self.keys.quaternions().iter().flat_map(|&q| to_wxyz(q)).collect();
        let mut curves = Json::object();
        for (name, curve, s) in self.named_curves() {
            let samples = self.times.iter().enumerate().map(|(k, &t)| {
                Json::object()
                    .number("t", t)
                    .list("quaternion", &to_wxyz(curve.at(t)))
                    .number("angularSpeed", s.speed[k])
                    .list("hopf", &s.hopf[k].to_array())
            });
            curves = curves.objects(name, samples);
        }
        provenance
            .json(Json::object())
            .lists("keys", keys.chunks(4))
            .list("keyTimes", self.keys.times())
            .raw("curves", &curves.end())
            .document()
    }
}

impl KeyframesDemo {
    /// The keys, their times and the chain's options, and the columns' units.
    fn provenance(&self) -> Provenance {
        let keys = self.keys.quaternions().iter().map(|&q| to_wxyz(q).to_vec()).collect();
        Provenance {
            what: "three curves through the same keyframes: the Kuramoto–Lohe chain (chain), Shoemake's Squad (squad), piecewise SLERP (slerp)",
            parameters: vec![
                ("keys", Value::Lists(keys)),
                ("keyTimes", Value::List(self.keys.times().to_vec())),
                ("smoothness", Value::Number(self.smoothness)),
                (
                    "samplesPerSegment",
                    Value::Number(ChainOptions::default().samples_per_segment as f64),
                ),
            ],
            units: &[
                (
                    "quaternions",
                    "[w, x, y, z], scalar first, unit; the keys as used (signs made consistent)",
                ),
                ("t", "the keys' time unit (the page's seconds)"),
                (
                    "angularSpeed",
                    "|omega| in radians per unit of t (world frame, q' = omega q / 2)",
                ),
                (
                    "hopf",
                    "the point of the unit sphere S^2 the body's x-axis points to (paper eq. 5)",
                ),
            ],
        }
    }

    /// Each curve with its export name and its series.
    fn named_curves(&self) -> impl Iterator<Item = (&'static str, &dyn Curve, &Series)> {
        let curves: [&dyn Curve; 3] = [&self.chain, &self.squad, &self.slerp];
        ["chain", "squad", "slerp"]
            .into_iter()
            .zip(curves)
            .zip(&self.series)
            .map(|((n, c), s)| (n, c, s))
    }

    fn paint_objects(&self, pen: &Pen, width: f64, height: f64, t: f64) {
        let camera = object_camera();
        let curves: [&dyn Curve; 3] = [&self.chain, &self.squad, &self.slerp];
        let wide = width >= height;
        let (w, h) = if wide { (width / 3.0, height) } else { (width, height / 3.0) };
        for (i, curve) in curves.iter().enumerate() {
            let (left, top) = if wide { (i as f64 * w, 0.0) } else { (0.0, i as f64 * h) };
            let viewport = Viewport::fitting(left, top + 14.0, w, h - 14.0, 1.6);
            draw_object(pen, &viewport, &camera, &self.mesh, curve.at(t), false);
            pen.text(NAMES[i], (left + 0.5 * w, top + 10.0), COLOURS[i], 12.0, "center");
        }
    }

    /// The curves and the keys (the still part), and each curve's point at t (the moving part).
    fn paint_sphere(&self, pen: &Pen, frame: &Frame, layer: Layer) {
        let viewport = frame.sphere_viewport();
        let view = View { pen, viewport: &viewport, camera: &frame.camera };
        if layer.still() {
            self.paint_curves(&view);
        }
        if layer != Layer::Still {
            let curves: [&dyn Curve; 3] = [&self.chain, &self.squad, &self.slerp];
            for (curve, colour) in curves.iter().zip(COLOURS) {
                let point = view.at(hopf(curve.at(frame.t)));
                pen.disc(point, 5.0, Some(colour), Some(("#ffffff", 1.5)));
            }
        }
    }

    fn paint_curves(&self, view: &View) {
        let pen = view.pen;
        let grid = grid();
        let dashes: [&[f64]; 3] = [&[], &[6.0, 4.0], &[2.0, 3.0]];
        draw_grid_back(view, &grid);
        for (s, (colour, dash)) in self.series.iter().zip(COLOURS.iter().zip(dashes)) {
            view.polyline_on(&s.hopf, Side::Back, (colour, 2.0, dash));
        }
        pen.alpha(1.0);
        draw_globe(view);
        draw_grid_front(view, &grid);
        for (s, (colour, dash)) in self.series.iter().zip(COLOURS.iter().zip(dashes)) {
            view.polyline_on(&s.hopf, Side::Front, (colour, 2.5, dash));
        }
        let points: Vec<DVec3> = self.keys.quaternions().iter().map(|&k| hopf(k)).collect();
        for &p in &points {
            pen.alpha(if view.in_front(p) { 1.0 } else { 0.4 });
            pen.disc(view.at(p), 5.5, Some("#ffffff"), Some((INK, 2.0)));
        }
        pen.alpha(1.0);
        // Keys whose points coincide (a turn about the body's x-axis) share one label.
        let pixels: Vec<(f64, f64)> = points.iter().map(|&p| view.at(p)).collect();
        let names: Vec<String> = (0..points.len()).map(|i| format!("k{i}")).collect();
        for (label, (x, y)) in grouped_labels(&pixels, &names, 14.0) {
            pen.text(&label, (x + 9.0, y - 9.0), INK, 11.0, "left");
        }
        let entries = [
            Entry { mark: Mark::Line(KLI, 2.5, &[]), label: NAMES[0] },
            Entry { mark: Mark::Line(SLERP, 2.5, &[6.0, 4.0]), label: NAMES[1] },
            Entry { mark: Mark::Line(INK, 2.5, &[2.0, 3.0]), label: NAMES[2] },
            Entry { mark: Mark::Disc(Some("#ffffff"), INK), label: "k0, k1, …: the keys" },
        ];
        draw_legend(pen, view.viewport, &entries, None);
        // Along the top, where it has the figure's whole width.
        if let Some(i) = self.hidden_turn() {
            let note = format!("k{i} → k{}: turns about the body's x-axis: not seen here", i + 1);
            let v = view.viewport;
            pen.text(&note, (v.left + 8.0, v.top + 12.0), MUTED, 11.0, "left");
        }
    }

    /// The first pair of consecutive keys that differ (by more than 0.5°) but have the same
    /// Hopf point: the turn between them is about the body's x-axis, invisible on the sphere.
    fn hidden_turn(&self) -> Option<usize> {
        let k = self.keys.quaternions();
        (0..k.len().saturating_sub(1)).find(|&i| {
            let turn = 2.0 * k[i].dot(k[i + 1]).abs().min(1.0).acos();
            turn > 0.5f64.to_radians() && (hopf(k[i]) - hopf(k[i + 1])).length() < 1e-6
        })
    }

    /// The two panels and their curves (the still part), and the time t on each (the moving part).
    fn paint_plots(&self, pen: &Pen, width: f64, height: f64, t: f64, layer: Layer) {
        let wide = width >= 1.5 * height;
        let (cell_w, cell_h) = if wide { (width / 2.0, height) } else { (width, height / 2.0) };
        let (start, end) = (self.start_time(), self.end_time());
        let panels = [("|ω(t)|, rad per unit time", 0), ("|ω̇(t)|", 1)];
        for (index, (title, which)) in panels.into_iter().enumerate() {
            let values = |s: &Series| -> Vec<f64> {
                if which == 0 { s.speed.clone() } else { s.acceleration.clone() }
            };
            // The scale of the continuous curves (the chain's and Squad's): piecewise SLERP's
            // |ω̇| is a spike at every key, left off the top.
            let largest = self.series[..2].iter().flat_map(&values).fold(0.0_f64, f64::max);
            let top_value = largest.max(1e-9) * 1.08;
            let (col, row) = if wide { (index as f64, 0.0) } else { (0.0, index as f64) };
            let area = (col * cell_w, row * cell_h, cell_w, cell_h);
            let (left, top, width, height) = inset(area, pen.text_scale(), 52.0);
            let panel = Panel {
                left,
                top,
                width,
                height,
                x_min: start,
                x_max: end,
                y_min: 0.0,
                y_max: top_value,
            };
            let ticks: Vec<(f64, String)> =
                [0.0, 0.5, 1.0].iter().map(|&f| (f * top_value, trim(f * top_value))).collect();
            if layer.still() {
                panel.frame_with(pen, title, &ticks, "t");
                for (s, colour) in self.series.iter().zip(COLOURS).rev() {
                    panel.series(pen, &self.times, values(s).into_iter(), colour, 1.8, &[]);
                }
                if index == 0 {
                    let entries: Vec<Entry> = ["chain", "Squad", "SLERP"]
                        .iter()
                        .zip(COLOURS)
                        .map(|(label, colour)| Entry { mark: Mark::Line(colour, 2.0, &[]), label })
                        .collect();
                    // Beside the title when there is room, else inside the panel's top (the
                    // curves reach 1/1.08 of its height).
                    let room = panel.width - pen.text_width(title, 12.5) - 12.0;
                    let y = if legend_row_width(pen, &entries) <= room {
                        panel.top - 14.0 * pen.text_scale()
                    } else {
                        panel.top + 8.0 * pen.text_scale()
                    };
                    draw_legend_row(pen, (panel.left + panel.width - 4.0, y), &entries);
                }
            }
            if layer != Layer::Still {
                let (x, _) = panel.at(t.max(start).min(end), 0.0);
                pen.line((x, panel.top), (x, panel.top + panel.height), MUTED, 1.0, &[2.0, 3.0]);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The largest second difference of a plotted series (a step or a saw shows in it, a
    /// smooth curve's is of order dt²), over the series' largest value.
    fn roughness(values: &[f64]) -> f64 {
        let largest = values.iter().fold(0.0_f64, |m, v| m.max(*v));
        values.windows(3).map(|w| (w[2] - 2.0 * w[1] + w[0]).abs()).fold(0.0, f64::max) / largest
    }

    #[test]
    fn the_chains_angular_acceleration_plot_has_no_saw() {
        // Four tumbling keys at uneven times. Measured: the chain (C²) 0.015; the chain evaluated
        // as before, Squad through its samples (C¹, a step of ω̇ at each sample), 0.051; Squad
        // through the keys 0.13 (steps at the keys).
        let s = std::f64::consts::FRAC_1_SQRT_2;
        let keys = [1.0, 0.0, 0.0, 0.0, s, s, 0.0, 0.0, 0.5, 0.5, 0.5, 0.5, 0.0, 0.0, s, s];
        let demo = KeyframesDemo::build(&keys, &[0.0, 1.0, 1.6, 3.0], 1.0).unwrap();
        let chain = roughness(&demo.series[0].acceleration);
        assert!(chain < 0.025, "chain {chain}");
        let squad = roughness(&demo.series[1].acceleration);
        assert!(squad > 0.1, "Squad {squad}");
    }
}
