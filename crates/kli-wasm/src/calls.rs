//! The single calls: one pair of rotations (or one rotation) in, one answer out.

use glam::DQuat;
use js_sys::Float64Array;
use kli::KliError;
use wasm_bindgen::prelude::*;

use crate::error::JsResult;
use crate::options::{KliOptionsObject, pair_and_options, read_options};
use crate::path::JsKliPath;
use crate::read::{Order, QuaternionLike, Vector3Like, number_argument, quaternion, vector3};
use crate::value::get;

/// The options' `order`, then `q` in it.
fn one(q: &QuaternionLike, options: Option<KliOptionsObject>) -> JsResult<(DQuat, Order)> {
    let (_, order) = read_options(options)?;
    Ok((quaternion("q", q, order)?, order))
}

/// Runs the KLI algorithm (paper, Algorithm 1) from p towards r. The last sample is within the
/// tolerance of the target, or the call throws.
#[wasm_bindgen]
pub fn kli(
    p: &QuaternionLike,
    r: &QuaternionLike,
    options: Option<KliOptionsObject>,
) -> JsResult<JsKliPath> {
    let (p, r, options, order) = pair_and_options(p, r, options)?;
    let path = kli::kli(p, r, &options)?;
    Ok(JsKliPath::new(path, order))
}

/// The exact KLI solution q(t) for finite t ≥ 0 (closed form; only `shortestPath` is used).
#[wasm_bindgen(js_name = kliExact)]
pub fn kli_exact(
    p: &QuaternionLike,
    r: &QuaternionLike,
    #[wasm_bindgen(unchecked_param_type = "number")] t: &JsValue,
    options: Option<KliOptionsObject>,
) -> JsResult<Float64Array> {
    let (p, r, options, order) = pair_and_options(p, r, options)?;
    let t = number_argument("t", t)?;
    kli::kli_exact(p, r, t, options.shortest_path).map(|q| order.array(q)).map_err(Into::into)
}

/// The SLERP parameter s(t) ∈ [0, 1) with kliExact(p, r, t) = slerp(p, r, s(t)).
#[wasm_bindgen(js_name = kliToSlerpParameter)]
pub fn kli_to_slerp_parameter(
    p: &QuaternionLike,
    r: &QuaternionLike,
    #[wasm_bindgen(unchecked_param_type = "number")] t: &JsValue,
    options: Option<KliOptionsObject>,
) -> JsResult<f64> {
    let (p, r, options, _) = pair_and_options(p, r, options)?;
    let t = number_argument("t", t)?;
    kli::kli_to_slerp_parameter(p, r, t, options.shortest_path).map_err(Into::into)
}

/// T* = ln(tan(φ0/2) / tan(arcsin(ε/2))): the exact first time ||target − q(t)|| < tolerance.
/// The tolerance is the argument, or, when it is `undefined`, the options' `tolerance` (default
/// 1e-5); given both ways it is refused, so that neither is silently ignored.
#[wasm_bindgen(js_name = kliReachTime)]
pub fn kli_reach_time(
    p: &QuaternionLike,
    r: &QuaternionLike,
    #[wasm_bindgen(unchecked_param_type = "number | undefined")] tolerance: &JsValue,
    options: Option<KliOptionsObject>,
) -> JsResult<f64> {
    let in_options = match &options {
        Some(object) if !tolerance.is_undefined() && object.is_object() => {
            !get("options", object, &"tolerance".into())?.is_undefined()
        }
        _ => false,
    };
    let (p, r, options, _) = pair_and_options(p, r, options)?;
    if in_options {
        let problem = "is given twice: as the argument and as options.tolerance (give one)";
        return Err(KliError::invalid("tolerance", problem).into());
    }
    let tolerance = match tolerance.is_undefined() {
        true => options.tolerance,
        false => number_argument("tolerance", tolerance)?,
    };
    Ok(kli::kli_reach_time(p, r, tolerance, options.shortest_path)?)
}

/// Slerp(p, r; s) (Shoemake); s outside [0, 1] extrapolates along the same great circle, up to
/// |s| ≤ 1e6. Unit inputs come back exactly at s = 0 and s = 1.
#[wasm_bindgen]
pub fn slerp(
    p: &QuaternionLike,
    r: &QuaternionLike,
    #[wasm_bindgen(unchecked_param_type = "number")] s: &JsValue,
    options: Option<KliOptionsObject>,
) -> JsResult<Float64Array> {
    let (p, r, options, order) = pair_and_options(p, r, options)?;
    let s = number_argument("s", s)?;
    kli::slerp(p, r, s, options.shortest_path).map(|q| order.array(q)).map_err(Into::into)
}

/// The Hopf map of paper eq. 5: the point (x, y, z) of S² where q sends the body x-axis.
#[wasm_bindgen]
pub fn hopf(q: &QuaternionLike, options: Option<KliOptionsObject>) -> JsResult<Float64Array> {
    let (q, _) = one(q, options)?;
    Ok(Float64Array::from(&kli::hopf(q).to_array()[..]))
}

/// The polar form q = cos(θ/2) + U sin(θ/2) as [Ux, Uy, Uz, θ], θ ∈ [0, 2π].
#[wasm_bindgen(js_name = axisAngle)]
pub fn axis_angle(q: &QuaternionLike, options: Option<KliOptionsObject>) -> JsResult<Float64Array> {
    let (q, _) = one(q, options)?;
    let (axis, angle) = kli::axis_angle(q)?;
    Ok(Float64Array::from(&[axis.x, axis.y, axis.z, angle][..]))
}

/// The unit quaternion (in the options' `order`) of a rotation by `angle` radians about `axis`
/// ([x, y, z]).
#[wasm_bindgen(js_name = fromAxisAngle)]
pub fn from_axis_angle(
    axis: &Vector3Like,
    #[wasm_bindgen(unchecked_param_type = "number")] angle: &JsValue,
    options: Option<KliOptionsObject>,
) -> JsResult<Float64Array> {
    let (_, order) = read_options(options)?;
    let axis = vector3("axis", axis)?;
    let angle = number_argument("angle", angle)?;
    kli::from_axis_angle(axis, angle).map(|q| order.array(q)).map_err(Into::into)
}
