//! The `kli/spline` entry: curves through many keyframes, the Kuramoto–Lohe chain beside Squad
//! and piecewise SLERP, with one interface (`RotationSpline`) so they compare call for call.

use glam::DQuat;
use js_sys::{Array, Float64Array};
use kli::KliError;
use kli::spline::{ChainOptions, Curve, Keys, KliSpline, PiecewiseSlerp, Squad};
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;

use crate::error::{JsResult, throw};
use crate::options::Fields;
use crate::read::{Order, describe, quaternion};

#[wasm_bindgen(typescript_custom_section)]
const TYPES: &'static str = r#"
/** Keyframes: a Float64Array of 4m numbers, or an array of m quaternions (each 4 numbers, or an
 *  object `{ x, y, z, w }` such as a THREE.Quaternion). */
export type KeysLike = Float64Array | ArrayLike<QuaternionLike>;

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
  /** Chain samples a segment, a whole number from 2 to 4096. Default 32. */
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
    Chain(KliSpline),
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
            Kind::Chain(c) => c,
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

fn finite_time(name: &str, t: f64) -> Result<f64, KliError> {
    if t.is_finite() {
        Ok(t)
    } else {
        Err(KliError::invalid(
            name,
            format!("must be a finite number (got {})", describe(&t.into())),
        ))
    }
}

/// Numbers from a Float64Array or an array-like of numbers.
fn float64s(name: &str, value: &JsValue) -> Result<Vec<f64>, KliError> {
    if let Some(array) = value.dyn_ref::<Float64Array>() {
        return Ok(array.to_vec());
    }
    if value.is_object() {
        return Ok(Float64Array::new(value).to_vec());
    }
    Err(KliError::invalid(
        name,
        format!("must be a Float64Array or an array of numbers (got {})", describe(value)),
    ))
}

#[wasm_bindgen]
impl RotationSpline {
    /// `q(t)`, in the spline's `order`.
    pub fn at(&self, t: f64) -> JsResult<Float64Array> {
        let t = finite_time("t", t).map_err(throw)?;
        Ok(self.order.array(self.curve().at(t)))
    }

    /// `q` at each of `times` (Float64Array or array), into `out` (Float64Array(4n)) when given,
    /// else a new Float64Array(4n); returns it.
    pub fn sample(
        &self,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | ArrayLike<number>")] times: &JsValue,
        out: Option<Float64Array>,
    ) -> JsResult<Float64Array> {
        let times = float64s("times", times).map_err(throw)?;
        if let Some(k) = times.iter().position(|t| !t.is_finite()) {
            return Err(throw(finite_time(&format!("times[{k}]"), times[k]).unwrap_err()));
        }
        let mut values = vec![0.0; 4 * times.len()];
        self.curve().sample_into(&times, &mut values);
        if self.order == Order::Xyzw {
            values.chunks_exact_mut(4).for_each(|q| q.rotate_left(1));
        }
        match out {
            Some(out) if out.length() as usize == values.len() => {
                out.copy_from(&values);
                Ok(out)
            }
            Some(out) => {
                let problem = format!(
                    "must hold 4 numbers per time: {} (got {})",
                    values.len(),
                    out.length()
                );
                Err(throw(KliError::invalid("out", problem)))
            }
            None => Ok(Float64Array::from(&values[..])),
        }
    }

    /// The world-frame angular velocity ω at `t` (`q' = ½ ω q`), as [x, y, z].
    #[wasm_bindgen(js_name = angularVelocity)]
    pub fn angular_velocity(&self, t: f64) -> JsResult<Float64Array> {
        let t = finite_time("t", t).map_err(throw)?;
        Ok(Float64Array::from(&self.curve().angular_velocity(t).to_array()[..]))
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

    /// For kliSpline: the relative residual `max_j |g_j| / max_j |(Lx)_j|` its solve reached.
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

/// The keys (Float64Array(4m) or an array of m quaternions) in `order`, and the options' `times`.
fn read_keys(value: &JsValue, times: Option<Vec<f64>>, order: Order) -> Result<Keys, KliError> {
    let quaternions: Vec<DQuat> = if let Some(array) = value.dyn_ref::<Float64Array>() {
        if array.length() % 4 != 0 {
            let problem = format!("must hold 4 numbers per key (got {})", array.length());
            return Err(KliError::invalid("keys", problem));
        }
        array.to_vec().chunks_exact(4).map(|q| order.read([q[0], q[1], q[2], q[3]])).collect()
    } else if Array::is_array(value) {
        let array = Array::from(value);
        let key = |(i, key): (usize, JsValue)| quaternion(&format!("keys[{i}]"), &key, order);
        array.iter().enumerate().map(key).collect::<Result<_, _>>()?
    } else {
        let problem =
            format!("must be a Float64Array or an array of quaternions (got {})", describe(value));
        return Err(KliError::invalid("keys", problem));
    };
    Keys::new(&quaternions, times.as_deref()).map_err(|e| order.error(e))
}

/// The options' `times` and `order`.
fn read_times(fields: &Option<Fields>) -> Result<(Option<Vec<f64>>, Order), KliError> {
    let order = Order::parse(fields.as_ref().and_then(|f| f.name("order")))?;
    match fields.as_ref().and_then(|f| f.value("times")) {
        Some(value) => Ok((Some(float64s("times", &value)?), order)),
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
            if let Some(v) = f.whole("samples_per_segment", 4096.0)? {
                chain.samples_per_segment = v as usize;
            }
        }
        let (times, order) = read_times(&fields)?;
        let keys = read_keys(keys, times, order)?;
        Ok(RotationSpline { kind: Kind::Chain(KliSpline::new(keys, &chain)?), order })
    };
    keys_and_options().map_err(throw)
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
    let (keys, order) = keys_and_times(keys, options).map_err(throw)?;
    Ok(RotationSpline { kind: Kind::Squad(Squad::new(keys)), order })
}

/// SLERP from key to key.
#[wasm_bindgen(js_name = slerpSpline)]
pub fn slerp_spline(
    keys: &KeysLike,
    options: Option<SplineOptionsObject>,
) -> JsResult<RotationSpline> {
    let (keys, order) = keys_and_times(keys, options).map_err(throw)?;
    Ok(RotationSpline { kind: Kind::Slerp(PiecewiseSlerp::new(keys)), order })
}
