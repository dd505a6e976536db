//! The `KeyframesDemo` class: the keyframes page's run. Its `model` (the three curves through
//! the keys and their measures), its pictures (`view`, `plots`) and its data (`export`)
//! are modules of their own; this file is the class, the key editor's calls and the run contract.

mod export;
mod model;
mod plots;
mod view;

use std::cell::OnceCell;

use glam::{DQuat, DVec3};
use js_sys::Float64Array;
use kli::KliError;
use kli::quaternion::to_wxyz;
use kli_wasm::error::{JsResult, Thrown};
use wasm_bindgen::prelude::*;

use crate::aircraft::{Face, aircraft};
use crate::clock::Clock;
use crate::figure::{Figure, Frame, Layer, Motion, Record, View, finite, names};
use crate::hopf_drag;
use crate::pen::Pen;
use model::{Model, STYLES};

/// The three curves through one set of keys, the time on show, and the views.
#[wasm_bindgen]
pub struct KeyframesDemo {
    model: Model,
    clock: Clock,
    mesh: Vec<Face>,
    /// The summary, made at its first read.
    summary: OnceCell<JsValue>,
}

#[wasm_bindgen]
impl KeyframesDemo {
    /// The three curves through `keys` (4m numbers, scalar first) at `times` (m numbers, or
    /// empty for 0, 1, …), the chain with `smoothness`; errors as kliSpline's.
    #[wasm_bindgen(constructor)]
    pub fn new(keys: &[f64], times: &[f64], smoothness: f64) -> JsResult<KeyframesDemo> {
        let model = Model::new(keys, times, smoothness)?;
        let clock = Clock::new(model.start_time(), model.end_time());
        Ok(KeyframesDemo { model, clock, mesh: aircraft(), summary: OnceCell::new() })
    }

    /// The keys as used (signs consistent), 4m numbers.
    #[wasm_bindgen(getter)]
    pub fn keys(&self) -> Float64Array {
        let flat: Vec<f64> =
            self.model.keys.quaternions().iter().flat_map(|&q| to_wxyz(q)).collect();
        Float64Array::from(&flat[..])
    }

    #[wasm_bindgen(getter, js_name = keyTimes)]
    pub fn key_times(&self) -> Float64Array {
        Float64Array::from(self.model.keys.times())
    }

    /// The three curves' rotations at `t`, 12 numbers (chain, Squad, piecewise SLERP).
    pub fn at(&self, t: f64) -> Float64Array {
        let curves = self.model.curves();
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
        hopf_drag::points_on_screen(&Frame::read(frame), self.model.keys.quaternions())
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
        let key = self.model.keys.quaternions().get(index);
        match key.and_then(|&key| hopf_drag::turned_to(&frame, key, x, y)) {
            Some(turned) => self.keys_with(index, turned),
            None => Float64Array::new_with_length(0),
        }
    }

    /// Key `index` in polar form, `[Ux, Uy, Uz, θ]` (`θ` in radians, as `axisAngle`).
    #[wasm_bindgen(js_name = keyAxisAngle)]
    pub fn key_axis_angle(&self, index: usize) -> JsResult<Float64Array> {
        let keys = &self.model.keys;
        let key = keys.quaternions().get(index).copied().ok_or_else(|| {
            let problem = format!("must be below the number of keys ({})", keys.len());
            Thrown::from(KliError::invalid("index", problem))
        })?;
        let (axis, angle) = kli::axis_angle(key)?;
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
        let &[x, y, z] = axis else {
            let problem = format!("must hold 3 numbers (got {})", axis.len());
            return Err(KliError::invalid("axis", problem).into());
        };
        let key = kli::from_axis_angle(DVec3::new(x, y, z), angle)?;
        Ok(self.keys_with(index, key))
    }
}

impl KeyframesDemo {
    fn make_summary(&self) -> JsValue {
        let model = &self.model;
        let curves: js_sys::Array = STYLES
            .iter()
            .zip(&model.measures)
            .map(|(style, m)| {
                Record::new()
                    .set("id", style.id)
                    .set("name", style.name)
                    .set("keyError", m.key_error)
                    .set("largestJump", m.largest_jump)
                    .set("bending", m.bending)
                    .set("totalAngle", m.total_angle)
                    .end()
            })
            .collect();
        Record::new()
            .set("iterations", model.chain.iterations() as f64)
            .set("residual", model.chain.residual())
            .set("curves", curves)
            .end()
    }

    /// The keys, flat, with key `index` replaced by `key`.
    fn keys_with(&self, index: usize, key: DQuat) -> Float64Array {
        let keys = self.model.keys.quaternions().iter().enumerate();
        let flat: Vec<f64> =
            keys.flat_map(|(i, &k)| to_wxyz(if i == index { key } else { k })).collect();
        Float64Array::from(&flat[..])
    }
}

crate::clock::clocked!(KeyframesDemo);

crate::figure::figure_class!(KeyframesDemo, "KeyframesSummary");

/// The keyframes page's views: the object under each curve, the three Hopf curves through the
/// keys, and |ω|, |ω̇| plotted; its time, the keys' span; its data, the three curves sampled.
impl Figure for KeyframesDemo {
    const VIEWS: &'static [View] = &[
        View { name: "objects", title: "The object under each curve", motion: Motion::Moving },
        View {
            name: "hopf",
            title: "The three curves' Hopf images on S²",
            motion: Motion::Layered,
        },
        View {
            name: "plots",
            title: "|ω(t)| and |ω̇(t)| of the three curves",
            motion: Motion::Layered,
        },
    ];
    const NAMES: &'static [&'static str] = &names::<3>(Self::VIEWS);
    const EXPORT: &'static str = "curves";

    /// `{ iterations, residual, curves }`: the chain's Newton steps and its residual, and each
    /// curve (chain, Squad, piecewise SLERP) as `{ id, name, keyError, largestJump, bending,
    /// totalAngle }` (MATH.md, "Smoothness").
    fn summary(&self) -> JsValue {
        self.summary.get_or_init(|| self.make_summary()).clone()
    }

    fn paint(&self, which: &View, layer: Layer, pen: &Pen, frame: &Frame) {
        let (size, t) = ((frame.width, frame.height), frame.t);
        match which.name {
            "objects" if layer.still() => view::draw_objects(pen, &self.model, &self.mesh, size, t),
            "objects" => {}
            "hopf" => view::draw_sphere(pen, &self.model, frame, layer),
            _ => plots::draw_plots(pen, &self.model, size, t, layer),
        }
    }

    fn export(&self, csv: bool) -> String {
        export::export(&self.model, csv)
    }
}

#[wasm_bindgen(typescript_custom_section)]
const TYPES: &'static str = r#"
/** What the page measures of one curve through the keys (MATH.md, "Smoothness"). */
export interface CurveMeasures {
  /** "chain", "squad" or "slerp": its word in exports. */
  id: string;
  /** "Kuramoto–Lohe chain", "Squad" or "piecewise SLERP". */
  name: string;
  /** The largest distance from a key at its time. */
  keyError: number;
  /** The largest jump of ω across a key. */
  largestJump: number;
  /** ∫|ω̇|² dt. */
  bending: number;
  /** The total rotation angle ∫|ω| dt, radians. */
  totalAngle: number;
}
/** What a keyframes run sums up to: the chain's Newton steps and residual, and the three curves
 *  (chain, Squad, piecewise SLERP) measured. */
export interface KeyframesSummary {
  iterations: number;
  residual: number;
  curves: CurveMeasures[];
}
"#;
