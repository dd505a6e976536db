//! The `kli/spline` entry: curves through many keyframes, the Kuramoto–Lohe chain beside Squad
//! and piecewise SLERP, with one interface (`RotationSpline`) so they compare call for call.

use js_sys::Float64Array;
use kli::spline::{
    ChainOptions, Curve, Keys, KliSpline, MAX_SAMPLES_PER_SEGMENT, PiecewiseSlerp, Squad,
};
use kli::{ErrorKind, KliError, Requirement, require};
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;

use crate::error::JsResult;
use crate::options::Fields;
use crate::read::{Order, number_argument, quaternion_list};
use crate::typed::{F64Array, float64_length, numbers};

#[wasm_bindgen(typescript_custom_section)]
const TYPES: &'static str = r#"
/** Keyframes: 4m numbers (a Float64Array, a Float32Array such as a three.js track's or a glTF
 *  accessor's `values`, any typed array of numbers, or a flat array), or an array of m
 *  quaternions (each 4 numbers, or an object `{ x, y, z, w }` such as a THREE.Quaternion). */
export type KeysLike = ArrayLike<number> | ArrayLike<QuaternionLike>;

/** Options of squadSpline and slerpSpline. */
export interface SplineOptions {
  /** m strictly increasing finite times, one per key. Default 0, 1, …, m − 1. */
  times?: ArrayLike<number>;
  /** How the keys and the results lay each quaternion out. Default "wxyz". */
  order?: QuaternionOrder;
}

/** Options of kliSpline. */
export interface KliSplineOptions extends SplineOptions {
  /** 0: neighbour coupling only (piecewise SLERP); 1: bending only (the smoothest). Default 1. */
  smoothness?: number;
  /** Chain samples a segment, a whole number from 2 to 256, and at most 131072 in all
   *  ((keys − 1) × samplesPerSegment). Default 32. */
  samplesPerSegment?: number;
}

/** What kliSpline returns. */
export type KliSpline = RotationSpline;
"#;

#[wasm_bindgen]
extern "C" {
    #[wasm_bindgen(typescript_type = "KeysLike")]
    pub type KeysLike;
    #[wasm_bindgen(typescript_type = "SplineOptions")]
    pub type SplineOptionsObject;
    #[wasm_bindgen(typescript_type = "KliSplineOptions")]
    pub type KliSplineOptionsObject;
}

enum Kind {
    Chain(Box<KliSpline>),
    Squad(Squad),
    Slerp(PiecewiseSlerp),
}

/// A rotation as a function of time through keyframes; `t` outside the key times is clamped.
#[wasm_bindgen]
pub struct RotationSpline {
    kind: Kind,
    order: Order,
}

impl RotationSpline {
    fn curve(&self) -> &dyn Curve {
        match &self.kind {
            Kind::Chain(c) => c.as_ref(),
            Kind::Squad(c) => c,
            Kind::Slerp(c) => c,
        }
    }

    fn key_frames(&self) -> &Keys {
        match &self.kind {
            Kind::Chain(c) => c.keys(),
            Kind::Squad(c) => c.keys(),
            Kind::Slerp(c) => c.keys(),
        }
    }
}

/// A time argument: a finite number.
fn finite_time(name: &str, t: &JsValue) -> Result<f64, KliError> {
    let t = number_argument(name, t)?;
    require(name, t, Requirement::Finite)
}

/// `values` written into `out` (absent: a new Float64Array), which must be a Float64Array of
/// exactly their length; element by element, so nothing is allocated.
fn fill(out: &JsValue, values: &[f64]) -> Result<Float64Array, KliError> {
    if out.is_undefined() || out.is_null() {
        return Ok(Float64Array::from(values));
    }
    let got = float64_length("out", out)?;
    if got != values.len() {
        let kind = ErrorKind::WrongLength { expected: values.len(), got, per: String::new() };
        return Err(KliError::new("out", kind));
    }
    let out: &Float64Array = out.unchecked_ref();
    for (i, &x) in values.iter().enumerate() {
        // A genuine typed array's indexed write runs no code of the caller's and cannot throw.
        out.set_index(i as u32, x);
    }
    Ok(out.clone())
}

/// The most times (or keys) one call reads: 2^24.
const MAX_LENGTH: usize = 1 << 24;

#[wasm_bindgen]
impl RotationSpline {
    /// `q(t)`, in the spline's `order`: into `out` (a Float64Array of 4) when given, with no
    /// allocation (for a frame loop), else a new Float64Array(4); returns it.
    pub fn at(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] t: &JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "Float64Array | null")] out: &JsValue,
    ) -> JsResult<Float64Array> {
        let t = finite_time("t", t)?;
        let q = self.order.write(self.curve().at(t));
        fill(out, &q).map_err(Into::into)
    }

    /// `q` at each of `times` (Float64Array or array), into `out` (Float64Array(4n)) when given,
    /// else a new Float64Array(4n); returns it.
    pub fn sample(
        &self,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | ArrayLike<number>")] times: &JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "Float64Array | null")] out: &JsValue,
    ) -> JsResult<Float64Array> {
        let sample = || -> Result<Float64Array, KliError> {
            let times = numbers("times", times, MAX_LENGTH)?;
            for (k, &t) in times.iter().enumerate() {
                require(&format!("times[{k}]"), t, Requirement::Finite)?;
            }
            let out = match out.is_undefined() || out.is_null() {
                true => None,
                false => Some(F64Array::new("out", out)?),
            };
            if let Some(out) = out.as_ref().filter(|o| o.length != 4 * times.len()) {
                let (expected, got) = (4 * times.len(), out.length);
                let kind = ErrorKind::WrongLength { expected, got, per: "time".into() };
                return Err(KliError::new("out", kind));
            }
            let mut values = vec![0.0; 4 * times.len()];
            self.curve().sample_into(&times, &mut values);
            if self.order == Order::Xyzw {
                values.chunks_exact_mut(4).for_each(|q| q.rotate_left(1));
            }
            Ok(match out {
                Some(out) => {
                    out.write("out", 0, &values)?;
                    out.into_array()
                }
                None => Float64Array::from(&values[..]),
            })
        };
        sample().map_err(Into::into)
    }

    /// The world-frame angular velocity ω at `t` (`q' = ½ ω q`), as [x, y, z]: into `out` (a
    /// Float64Array of 3) when given, else a new Float64Array(3); returns it.
    #[wasm_bindgen(js_name = angularVelocity)]
    pub fn angular_velocity(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] t: &JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "Float64Array | null")] out: &JsValue,
    ) -> JsResult<Float64Array> {
        let t = finite_time("t", t)?;
        fill(out, &self.curve().angular_velocity(t).to_array()).map_err(Into::into)
    }

    /// The keys as used (normalised, signs made consistent), 4m numbers in the spline's `order`.
    #[wasm_bindgen(getter)]
    pub fn keys(&self) -> Float64Array {
        self.order.flat(self.key_frames().quaternions())
    }

    /// The key times.
    #[wasm_bindgen(getter)]
    pub fn times(&self) -> Float64Array {
        Float64Array::from(self.key_frames().times())
    }

    #[wasm_bindgen(getter, js_name = startTime)]
    pub fn start_time(&self) -> f64 {
        self.curve().start_time()
    }

    #[wasm_bindgen(getter, js_name = endTime)]
    pub fn end_time(&self) -> f64 {
        self.curve().end_time()
    }

    /// For kliSpline: the relative residual `max_j |g_j| / max_j |(Lx)_j|` its solve reached (0
    /// for a chain at rest, such as equal keys).
    #[wasm_bindgen(getter)]
    pub fn residual(&self) -> Option<f64> {
        if let Kind::Chain(c) = &self.kind { Some(c.residual()) } else { None }
    }

    /// For kliSpline: the Newton iterations its solve took.
    #[wasm_bindgen(getter)]
    pub fn iterations(&self) -> Option<usize> {
        if let Kind::Chain(c) = &self.kind { Some(c.iterations()) } else { None }
    }
}

/// The keys (4m numbers: a typed array or a flat array; or an array of m quaternions) in
/// `order`, and the options' `times`.
fn read_keys(value: &JsValue, times: Option<Vec<f64>>, order: Order) -> Result<Keys, KliError> {
    let quaternions = quaternion_list("keys", "key", value, order, MAX_LENGTH)?;
    Keys::new(&quaternions, times.as_deref()).map_err(|e| order.error(e))
}

/// The options' `times` and `order`.
fn read_times(fields: &Option<Fields>) -> Result<(Option<Vec<f64>>, Order), KliError> {
    let Some(fields) = fields else { return Ok((None, Order::Wxyz)) };
    let order = Order::parse(fields.name("order")?)?;
    match fields.value("times")? {
        Some(value) => Ok((Some(numbers("times", &value, MAX_LENGTH)?), order)),
        None => Ok((None, order)),
    }
}

/// The Kuramoto–Lohe chain through `keys` (MATH.md, "Many rotations").
#[wasm_bindgen(js_name = kliSpline)]
pub fn kli_spline(
    keys: &KeysLike,
    options: Option<KliSplineOptionsObject>,
) -> JsResult<RotationSpline> {
    let keys_and_options = || -> Result<RotationSpline, KliError> {
        let fields = Fields::new(
            options.map(JsValue::from),
            &["times", "smoothness", "samples_per_segment", "order"],
            "{ smoothness: 1 }",
        )?;
        let mut chain = ChainOptions::default();
        if let Some(f) = &fields {
            if let Some(v) = f.number("smoothness")? {
                chain.smoothness = v;
            }
            let most = MAX_SAMPLES_PER_SEGMENT as f64;
            if let Some(v) = f.whole("samples_per_segment", 2.0, most)? {
                chain.samples_per_segment = v as usize;
            }
        }
        let (times, order) = read_times(&fields)?;
        let keys = read_keys(keys, times, order)?;
        Ok(RotationSpline { kind: Kind::Chain(Box::new(KliSpline::new(keys, &chain)?)), order })
    };
    keys_and_options().map_err(Into::into)
}

/// The keys and the `{ times, order }` options of squadSpline and slerpSpline.
fn keys_and_times(
    keys: &KeysLike,
    options: Option<SplineOptionsObject>,
) -> Result<(Keys, Order), KliError> {
    let example = "{ times: [0, 1, 2] }";
    let fields = Fields::new(options.map(JsValue::from), &["times", "order"], example)?;
    let (times, order) = read_times(&fields)?;
    Ok((read_keys(keys, times, order)?, order))
}

/// Shoemake's Squad through `keys`, with helper points for uneven times.
#[wasm_bindgen(js_name = squadSpline)]
pub fn squad_spline(
    keys: &KeysLike,
    options: Option<SplineOptionsObject>,
) -> JsResult<RotationSpline> {
    let (keys, order) = keys_and_times(keys, options)?;
    Ok(RotationSpline { kind: Kind::Squad(Squad::new(keys)), order })
}

/// SLERP from key to key.
#[wasm_bindgen(js_name = slerpSpline)]
pub fn slerp_spline(
    keys: &KeysLike,
    options: Option<SplineOptionsObject>,
) -> JsResult<RotationSpline> {
    let (keys, order) = keys_and_times(keys, options)?;
    Ok(RotationSpline { kind: Kind::Slerp(PiecewiseSlerp::new(keys)), order })
}
