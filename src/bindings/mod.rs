//! The JavaScript boundary: converts and validates arguments, calls the plain-Rust core, and turns
//! every [`KliError`] into a JavaScript `Error` whose message names the argument. Nothing here may
//! panic: a panic would trap and kill the module for the page.
//!
//! Quaternions cross as 4 numbers, scalar first `[w, x, y, z]`; results are `Float64Array`s.

use glam::{DQuat, DVec3};
use js_sys::{Array, Float64Array, Object, Reflect};
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;

use crate::quaternion::{from_wxyz, to_wxyz};
// JavaScript's `String(x)`: keeps Rust's float formatting out of the module.
pub(crate) use crate::render::pen::number;

mod batch;
mod demo;
use crate::{Integrator, KliError, KliOptions};
pub use batch::{Float64Buffer, kli_exact_batch, kli_sample, nlerp_batch, slerp_batch};
pub use demo::Demo;

#[wasm_bindgen(typescript_custom_section)]
const TYPES: &'static str = r#"
/** A quaternion as 4 finite numbers, scalar first: `[w, x, y, z]` (the paper's a + bi + cj + dk).
 *  An Array or a typed array; it is normalised, and must not be all zero. */
export type QuaternionLike = ArrayLike<number>;

/** A 3-vector as 3 finite numbers `[x, y, z]`: an Array or a typed array. */
export type Vector3Like = ArrayLike<number>;

/** How Algorithm 1 takes a step: classical Runge–Kutta, explicit Euler (drifts off S³), or the
 *  RK4 step taken along a great circle (stays on S³). */
export type Integrator = "rk4" | "euler" | "geodesic";

/** Options of every call; every key is optional and unknown keys are rejected. */
export interface KliOptions {
  /** ε: Algorithm 1 stops once ||target − q(T)|| < ε. Finite, > 0. Default 1e-5. */
  tolerance?: number;
  /** δ: the time step of Algorithm 1. Finite, > 0. Default 0.01. */
  step?: number;
  /** Algorithm 1 fails with an Error past this time. Finite, > 0. Default 100. */
  maxTime?: number;
  /** Default "rk4". */
  integrator?: Integrator;
  /** When true (default) and p·r < 0, go to −r: the same rotation, the shorter arc. When false,
   *  go to r the long way round; p = −r is then an equilibrium and an Error. */
  shortestPath?: boolean;
}
"#;

#[wasm_bindgen]
extern "C" {
    #[wasm_bindgen(typescript_type = "QuaternionLike")]
    pub type QuaternionLike;

    #[wasm_bindgen(typescript_type = "KliOptions")]
    pub type KliOptionsObject;

    #[wasm_bindgen(typescript_type = "Vector3Like")]
    pub type Vector3Like;
}

fn error(e: KliError) -> JsError {
    JsError::new(&e.message_with(&number))
}

/// A short description of a JavaScript value for error messages.
fn describe(value: &JsValue) -> String {
    if let Some(n) = value.as_f64() {
        number(n)
    } else if let Some(s) = value.as_string() {
        format!("\"{s}\", a string")
    } else if let Some(b) = value.as_bool() {
        format!("{b}")
    } else if value.is_null() {
        "null".into()
    } else if value.is_undefined() {
        "undefined".into()
    } else if Array::is_array(value) {
        format!("an array of length {}", Array::from(value).length())
    } else {
        format!("a value of type {}", value.js_typeof().as_string().unwrap_or_default())
    }
}

fn invalid(name: &str, problem: String) -> KliError {
    KliError::InvalidArgument { name: name.into(), problem }
}

/// Reads exactly `N` numbers from an Array or typed array; `shape` names them in messages,
/// e.g. "[w, x, y, z]".
fn numbers<const N: usize>(name: &str, value: &JsValue, shape: &str) -> Result<[f64; N], KliError> {
    let mut out = [0.0; N];
    if let Some(array) = value.dyn_ref::<Float64Array>() {
        if array.length() as usize != N {
            return Err(invalid(
                name,
                format!("must hold {N} numbers {shape} (got {})", array.length()),
            ));
        }
        array.copy_to(&mut out);
        return Ok(out);
    }
    let length = if value.is_object() {
        Reflect::get(value, &"length".into()).ok().and_then(|l| l.as_f64())
    } else {
        None
    };
    if length != Some(N as f64) {
        return Err(invalid(
            name,
            format!("must be an array of {N} numbers {shape} (got {})", describe(value)),
        ));
    }
    for (i, slot) in out.iter_mut().enumerate() {
        let element = Reflect::get_u32(value, i as u32).unwrap_or(JsValue::UNDEFINED);
        *slot = element.as_f64().ok_or_else(|| {
            invalid(
                name,
                format!("must hold {N} numbers {shape}: element {i} is {}", describe(&element)),
            )
        })?;
    }
    Ok(out)
}

/// Reads a quaternion `[w, x, y, z]` and normalises it.
pub(crate) fn quaternion(name: &'static str, value: &JsValue) -> Result<DQuat, KliError> {
    crate::quaternion::unit(name, from_wxyz(numbers(name, value, "[w, x, y, z]")?))
}

fn to_array(q: DQuat) -> Vec<f64> {
    to_wxyz(q).to_vec()
}

const OPTION_KEYS: [&str; 5] = ["tolerance", "step", "maxTime", "integrator", "shortestPath"];

/// Reads the options object (absent, `undefined` or `null` give the defaults).
fn options(value: Option<KliOptionsObject>) -> Result<KliOptions, KliError> {
    let mut options = KliOptions::default();
    let Some(object) = value.map(JsValue::from).filter(|v| !v.is_undefined() && !v.is_null())
    else {
        return Ok(options);
    };
    if !object.is_object() || Array::is_array(&object) {
        return Err(invalid(
            "options",
            format!("must be an object like {{ tolerance: 1e-5 }} (got {})", describe(&object)),
        ));
    }
    for key in Object::keys(object.unchecked_ref::<Object>()).iter() {
        let key = key.as_string().unwrap_or_default();
        if !OPTION_KEYS.contains(&key.as_str()) {
            return Err(invalid(
                "options",
                format!("has an unknown key \"{key}\"; the keys are {}", OPTION_KEYS.join(", ")),
            ));
        }
    }
    let field = |key: &str| Reflect::get(&object, &key.into()).unwrap_or(JsValue::UNDEFINED);
    let number = |key: &str| -> Result<Option<f64>, KliError> {
        let v = field(key);
        if v.is_undefined() {
            return Ok(None);
        }
        v.as_f64()
            .map(Some)
            .ok_or_else(|| invalid(key, format!("must be a number (got {})", describe(&v))))
    };
    if let Some(v) = number("tolerance")? {
        options.tolerance = v;
    }
    if let Some(v) = number("step")? {
        options.step = v;
    }
    if let Some(v) = number("maxTime")? {
        options.max_time = v;
    }
    let integrator = field("integrator");
    if !integrator.is_undefined() {
        let name = integrator.as_string().unwrap_or_else(|| describe(&integrator));
        options.integrator = name.parse::<Integrator>()?;
    }
    let shortest_path = field("shortestPath");
    if !shortest_path.is_undefined() {
        options.shortest_path = shortest_path.as_bool().ok_or_else(|| {
            invalid(
                "shortestPath",
                format!("must be true or false (got {})", describe(&shortest_path)),
            )
        })?;
    }
    options.validate()?;
    Ok(options)
}

/// The path of Algorithm 1: samples at `0, δ, …, T` and the exact solution beside them.
#[wasm_bindgen(js_name = KliPath)]
pub struct JsKliPath {
    path: crate::KliPath,
}

#[wasm_bindgen(js_class = KliPath)]
impl JsKliPath {
    /// T: the first time on the grid `nδ` at which ||target − q(T)|| < tolerance.
    #[wasm_bindgen(getter, js_name = finalTime)]
    pub fn final_time(&self) -> f64 {
        self.path.final_time()
    }

    /// n, the number of steps; the path holds n + 1 samples.
    #[wasm_bindgen(getter)]
    pub fn steps(&self) -> usize {
        self.path.steps()
    }

    /// The n + 1 sample times 0, δ, …, T.
    #[wasm_bindgen(getter)]
    pub fn times(&self) -> Vec<f64> {
        self.path.times().to_vec()
    }

    /// 4·(n + 1) numbers: q at each sample time, scalar first, as integrated.
    #[wasm_bindgen(getter)]
    pub fn quaternions(&self) -> Vec<f64> {
        self.path.quaternions().iter().flat_map(|&q| to_wxyz(q)).collect()
    }

    /// 3·(n + 1) numbers: the Hopf image of each sample on S² (the body x-axis).
    #[wasm_bindgen(getter, js_name = hopfCurve)]
    pub fn hopf_curve(&self) -> Vec<f64> {
        self.path.hopf_curve().iter().flat_map(|v| v.to_array()).collect()
    }

    /// The end actually used: r, or −r when shortestPath and p·r < 0.
    #[wasm_bindgen(getter)]
    pub fn target(&self) -> Vec<f64> {
        to_array(self.path.target())
    }

    /// The integrator the path was computed with.
    #[wasm_bindgen(getter, unchecked_return_type = "Integrator")]
    pub fn integrator(&self) -> String {
        self.path.options().integrator.name().into()
    }

    /// The exact q(t) (closed form) for any finite t ≥ 0.
    pub fn at(&self, t: f64) -> Result<Vec<f64>, JsError> {
        self.path.at(t).map(to_array).map_err(error)
    }
}

/// Runs the KLI algorithm (paper, Algorithm 1) from p towards r.
#[wasm_bindgen]
pub fn kli(
    p: &QuaternionLike,
    r: &QuaternionLike,
    options: Option<KliOptionsObject>,
) -> Result<JsKliPath, JsError> {
    let options = self::options(options).map_err(error)?;
    let (p, r) = (quaternion("p", p).map_err(error)?, quaternion("r", r).map_err(error)?);
    crate::kli(p, r, &options).map(|path| JsKliPath { path }).map_err(error)
}

/// The exact KLI solution q(t) for finite t ≥ 0 (closed form; only `shortestPath` is used).
#[wasm_bindgen(js_name = kliExact)]
pub fn kli_exact(
    p: &QuaternionLike,
    r: &QuaternionLike,
    t: f64,
    options: Option<KliOptionsObject>,
) -> Result<Vec<f64>, JsError> {
    let options = self::options(options).map_err(error)?;
    let (p, r) = (quaternion("p", p).map_err(error)?, quaternion("r", r).map_err(error)?);
    crate::kli_exact(p, r, t, options.shortest_path).map(to_array).map_err(error)
}

/// The SLERP parameter s(t) ∈ [0, 1) with kliExact(p, r, t) = slerp(p, r, s(t)).
#[wasm_bindgen(js_name = kliToSlerpParameter)]
pub fn kli_to_slerp_parameter(
    p: &QuaternionLike,
    r: &QuaternionLike,
    t: f64,
    options: Option<KliOptionsObject>,
) -> Result<f64, JsError> {
    let options = self::options(options).map_err(error)?;
    let (p, r) = (quaternion("p", p).map_err(error)?, quaternion("r", r).map_err(error)?);
    crate::kli_to_slerp_parameter(p, r, t, options.shortest_path).map_err(error)
}

/// T* = ln(tan(φ0/2) / tan(arcsin(ε/2))): the exact first time ||target − q(t)|| < tolerance.
#[wasm_bindgen(js_name = kliReachTime)]
pub fn kli_reach_time(
    p: &QuaternionLike,
    r: &QuaternionLike,
    tolerance: f64,
    options: Option<KliOptionsObject>,
) -> Result<f64, JsError> {
    let options = self::options(options).map_err(error)?;
    let (p, r) = (quaternion("p", p).map_err(error)?, quaternion("r", r).map_err(error)?);
    crate::kli_reach_time(p, r, tolerance, options.shortest_path).map_err(error)
}

/// Slerp(p, r; s) (Shoemake); s outside [0, 1] extrapolates along the same great circle.
#[wasm_bindgen]
pub fn slerp(
    p: &QuaternionLike,
    r: &QuaternionLike,
    s: f64,
    options: Option<KliOptionsObject>,
) -> Result<Vec<f64>, JsError> {
    let options = self::options(options).map_err(error)?;
    let (p, r) = (quaternion("p", p).map_err(error)?, quaternion("r", r).map_err(error)?);
    crate::slerp(p, r, s, options.shortest_path).map(to_array).map_err(error)
}

/// The Hopf map of paper eq. 5: the point (x, y, z) of S² where q sends the body x-axis.
#[wasm_bindgen]
pub fn hopf(q: &QuaternionLike) -> Result<Vec<f64>, JsError> {
    let q = quaternion("q", q).map_err(error)?;
    Ok(crate::hopf(q).to_array().to_vec())
}

/// The polar form q = cos(θ/2) + U sin(θ/2) as [Ux, Uy, Uz, θ], θ ∈ [0, 2π].
#[wasm_bindgen(js_name = axisAngle)]
pub fn axis_angle(q: &QuaternionLike) -> Result<Vec<f64>, JsError> {
    let q = quaternion("q", q).map_err(error)?;
    let (axis, angle) = crate::axis_angle(q).map_err(error)?;
    Ok(vec![axis.x, axis.y, axis.z, angle])
}

/// The unit quaternion [w, x, y, z] of a rotation by `angle` radians about `axis` ([x, y, z]).
#[wasm_bindgen(js_name = fromAxisAngle)]
pub fn from_axis_angle(axis: &Vector3Like, angle: f64) -> Result<Vec<f64>, JsError> {
    let axis = DVec3::from_array(numbers("axis", axis, "[x, y, z]").map_err(error)?);
    crate::from_axis_angle(axis, angle).map(to_array).map_err(error)
}
