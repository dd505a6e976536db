//! The batch calls: Float64Arrays in, results written into the caller's `out`. Pairs are copied
//! into wasm memory a chunk at a time, so a call of any size needs only a few hundred KB of wasm
//! memory and no allocation on the JavaScript side.

use js_sys::Float64Array;
use wasm_bindgen::prelude::*;

use super::{KliOptionsObject, QuaternionLike, describe, error, invalid, options, quaternion};
use crate::batch::{BatchKind, check_lengths, kli_sample_into, run_batch};
use crate::KliError;

/// Pairs per chunk: 4096 × 13 numbers × 8 bytes = 416 KB of scratch.
const CHUNK: usize = 4096;

fn float64_array<'a>(name: &str, value: &'a JsValue) -> Result<&'a Float64Array, KliError> {
    value.dyn_ref::<Float64Array>().ok_or_else(|| invalid(name, format!("must be a Float64Array (got {})", describe(value))))
}

fn run(kind: BatchKind, starts: &JsValue, ends: &JsValue, parameters: &JsValue, out: &JsValue, shortest_path: bool) -> Result<(), KliError> {
    let parameter_name = kind.parameter_name();
    let (starts, ends) = (float64_array("starts", starts)?, float64_array("ends", ends)?);
    let (parameters, out) = (float64_array(parameter_name, parameters)?, float64_array("out", out)?);
    let n = parameters.length() as usize;
    check_lengths(starts.length() as usize, ends.length() as usize, n, out.length() as usize, parameter_name)?;
    let chunk = CHUNK.min(n);
    let (mut p, mut r, mut x, mut q) = (vec![0.0; 4 * chunk], vec![0.0; 4 * chunk], vec![0.0; chunk], vec![0.0; 4 * chunk]);
    for first in (0..n).step_by(CHUNK.max(1)) {
        let m = CHUNK.min(n - first);
        let (a, b) = ((4 * first) as u32, (4 * (first + m)) as u32);
        starts.subarray(a, b).copy_to(&mut p[..4 * m]);
        ends.subarray(a, b).copy_to(&mut r[..4 * m]);
        parameters.subarray(first as u32, (first + m) as u32).copy_to(&mut x[..m]);
        run_batch(kind, &p[..4 * m], &r[..4 * m], &x[..m], &mut q[..4 * m], first, shortest_path)?;
        out.subarray(a, b).copy_from(&q[..4 * m]);
    }
    Ok(())
}

/// `out[4i..4i+4] = Slerp(starts[i], ends[i]; s[i])` for n pairs (arrays of 4n, 4n, n, 4n
/// numbers, scalar first); returns `out`. Same checks as `slerp`; errors name the element.
#[wasm_bindgen(js_name = slerpBatch)]
pub fn slerp_batch(
    #[wasm_bindgen(unchecked_param_type = "Float64Array")] starts: &JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array")] ends: &JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array")] s: &JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array")] out: &JsValue,
    options: Option<KliOptionsObject>,
) -> Result<Float64Array, JsError> {
    let shortest_path = self::options(options).map_err(error)?.shortest_path;
    run(BatchKind::Slerp, starts, ends, s, out, shortest_path).map_err(error)?;
    Ok(out.clone().unchecked_into())
}

/// `out[4i..4i+4] = q(t[i])`, the exact KLI solution from `starts[i]` towards `ends[i]`, for n
/// pairs; returns `out`. Same checks as `kliExact`; errors name the element.
#[wasm_bindgen(js_name = kliExactBatch)]
pub fn kli_exact_batch(
    #[wasm_bindgen(unchecked_param_type = "Float64Array")] starts: &JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array")] ends: &JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array")] t: &JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array")] out: &JsValue,
    options: Option<KliOptionsObject>,
) -> Result<Float64Array, JsError> {
    let shortest_path = self::options(options).map_err(error)?.shortest_path;
    run(BatchKind::KliExact, starts, ends, t, out, shortest_path).map_err(error)?;
    Ok(out.clone().unchecked_into())
}

/// Normalised linear interpolation (shorter arc) for n pairs, into `out`: the cheapest possible
/// interpolation, not constant speed; the benchmarks' baseline.
#[wasm_bindgen(js_name = nlerpBatch)]
pub fn nlerp_batch(
    #[wasm_bindgen(unchecked_param_type = "Float64Array")] starts: &JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array")] ends: &JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array")] s: &JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array")] out: &JsValue,
) -> Result<Float64Array, JsError> {
    run(BatchKind::Nlerp, starts, ends, s, out, true).map_err(error)?;
    Ok(out.clone().unchecked_into())
}

/// One KLI path from p towards r sampled at each of `times` (finite, ≥ 0): Float64Array(4n).
/// Evenly spaced times are cheapest: the sample advances by a fixed factor of e^(−δ).
#[wasm_bindgen(js_name = kliSample)]
pub fn kli_sample(
    p: &QuaternionLike,
    r: &QuaternionLike,
    #[wasm_bindgen(unchecked_param_type = "Float64Array | ArrayLike<number>")] times: &JsValue,
    options: Option<KliOptionsObject>,
) -> Result<Vec<f64>, JsError> {
    let shortest_path = self::options(options).map_err(error)?.shortest_path;
    let (p, r) = (quaternion("p", p).map_err(error)?, quaternion("r", r).map_err(error)?);
    let times: Vec<f64> = if let Some(array) = times.dyn_ref::<Float64Array>() {
        array.to_vec()
    } else if times.is_object() {
        Float64Array::new(times).to_vec()
    } else {
        return Err(error(invalid("times", format!("must be a Float64Array or an array of numbers (got {})", describe(times)))));
    };
    let mut out = vec![0.0; 4 * times.len()];
    kli_sample_into(p, r, &times, &mut out, shortest_path).map_err(error)?;
    Ok(out)
}
