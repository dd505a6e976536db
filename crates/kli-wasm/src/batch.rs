//! The batch calls: Float64Arrays in, results written into the caller's `out`. Arrays that live in
//! the module's own memory ([`crate::Float64Buffer`] views) are used in place, with no copy at all;
//! others are copied in and out a chunk at a time, so a call of any size needs only a few hundred
//! KB of wasm memory and no allocation on the JavaScript side.

use js_sys::{Float64Array, WebAssembly};
use kli::KliError;
use kli::batch::{BatchKind, check_lengths, kli_sample_into, run_batch};
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;

use crate::error::{JsResult, throw};
use crate::options::{KliOptionsObject, read_options};
use crate::read::{Order, QuaternionLike, describe, float64_array, quaternion};

/// Pairs per chunk: 4096 × 13 numbers × 8 bytes = 416 KB of scratch.
const CHUNK: usize = 4096;

/// The byte range `[start, end)` of `array` in the module's memory, if it is a view of it.
fn in_wasm_memory(array: &Float64Array) -> Option<(usize, usize)> {
    let memory: WebAssembly::Memory = wasm_bindgen::memory().unchecked_into();
    let start = array.byte_offset() as usize;
    (JsValue::from(array.buffer()) == memory.buffer())
        .then_some((start, start + 8 * array.length() as usize))
}

/// The four arrays in place, when all are views of the module's memory and `out` overlaps no
/// input (overlapping `&` and `&mut` slices would be undefined behaviour).
fn in_place(
    starts: &Float64Array,
    ends: &Float64Array,
    parameters: &Float64Array,
    out: &Float64Array,
) -> Option<[(usize, usize); 4]> {
    let ranges = [
        in_wasm_memory(starts)?,
        in_wasm_memory(ends)?,
        in_wasm_memory(parameters)?,
        in_wasm_memory(out)?,
    ];
    let (o_start, o_end) = ranges[3];
    let disjoint = ranges[..3].iter().all(|&(a, b)| b <= o_start || o_end <= a || a == b);
    disjoint.then_some(ranges)
}

fn run_arrays(
    kind: BatchKind,
    starts: &JsValue,
    ends: &JsValue,
    parameters: &JsValue,
    out: &JsValue,
    shortest_path: bool,
) -> Result<(), KliError> {
    let parameter_name = kind.parameter_name();
    let (starts, ends) = (float64_array("starts", starts)?, float64_array("ends", ends)?);
    let (parameters, out) =
        (float64_array(parameter_name, parameters)?, float64_array("out", out)?);
    let n = parameters.length() as usize;
    check_lengths(
        starts.length() as usize,
        ends.length() as usize,
        n,
        out.length() as usize,
        parameter_name,
    )?;
    if let Some([s, e, x, o]) = in_place(starts, ends, parameters, out) {
        let slice = |(a, b): (usize, usize)| -> &[f64] {
            // SAFETY: a live Float64Array view of our memory: aligned, in bounds, and (checked
            // above) not overlapping `out`, which no other Rust reference touches during the call.
            unsafe { std::slice::from_raw_parts(a as *const f64, (b - a) / 8) }
        };
        // SAFETY: as above; `out` is disjoint from the three inputs.
        let out = unsafe { std::slice::from_raw_parts_mut(o.0 as *mut f64, (o.1 - o.0) / 8) };
        return run_batch(kind, slice(s), slice(e), slice(x), out, 0, shortest_path);
    }
    let chunk = CHUNK.min(n);
    let (mut p, mut r, mut x, mut q) =
        (vec![0.0; 4 * chunk], vec![0.0; 4 * chunk], vec![0.0; chunk], vec![0.0; 4 * chunk]);
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

/// A batch call: the options (`order`, and `shortestPath` but for nlerp, which always takes the
/// shorter arc), the arrays, and errors naming components as the caller laid them out.
fn run(
    kind: BatchKind,
    starts: &JsValue,
    ends: &JsValue,
    parameters: &JsValue,
    out: &JsValue,
    options: Option<KliOptionsObject>,
) -> JsResult<Float64Array> {
    let (options, order) = read_options(options).map_err(throw)?;
    let shortest_path = kind == BatchKind::Nlerp || options.shortest_path;
    run_arrays(kind, starts, ends, parameters, out, shortest_path)
        .map_err(|e| throw(order.batch_error(e)))?;
    Ok(out.clone().unchecked_into())
}

/// `out[4i..4i+4] = Slerp(starts[i], ends[i]; s[i])` for n pairs (arrays of 4n, 4n, n, 4n
/// numbers, scalar first or, with `order: "xyzw"`, last, read in place either way); returns
/// `out`. Same checks as `slerp`; errors name the element.
#[wasm_bindgen(js_name = slerpBatch)]
pub fn slerp_batch(
    #[wasm_bindgen(unchecked_param_type = "Float64Array")] starts: &JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array")] ends: &JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array")] s: &JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array")] out: &JsValue,
    options: Option<KliOptionsObject>,
) -> JsResult<Float64Array> {
    run(BatchKind::Slerp, starts, ends, s, out, options)
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
) -> JsResult<Float64Array> {
    run(BatchKind::KliExact, starts, ends, t, out, options)
}

/// Normalised linear interpolation (shorter arc) for n pairs, into `out`: the cheapest possible
/// interpolation, not constant speed; the benchmarks' baseline. Of the options only `order`
/// matters (always the shorter arc).
#[wasm_bindgen(js_name = nlerpBatch)]
pub fn nlerp_batch(
    #[wasm_bindgen(unchecked_param_type = "Float64Array")] starts: &JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array")] ends: &JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array")] s: &JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array")] out: &JsValue,
    options: Option<KliOptionsObject>,
) -> JsResult<Float64Array> {
    run(BatchKind::Nlerp, starts, ends, s, out, options)
}

/// One KLI path from p towards r sampled at each of `times` (finite, ≥ 0): Float64Array(4n).
/// Evenly spaced times are cheapest: the sample advances by a fixed factor of e^(−δ).
#[wasm_bindgen(js_name = kliSample)]
pub fn kli_sample(
    p: &QuaternionLike,
    r: &QuaternionLike,
    #[wasm_bindgen(unchecked_param_type = "Float64Array | ArrayLike<number>")] times: &JsValue,
    options: Option<KliOptionsObject>,
) -> JsResult<Float64Array> {
    let (options, order) = read_options(options).map_err(throw)?;
    let p = quaternion("p", p, order).map_err(throw)?;
    let r = quaternion("r", r, order).map_err(throw)?;
    let times: Vec<f64> = if let Some(array) = times.dyn_ref::<Float64Array>() {
        array.to_vec()
    } else if times.is_object() {
        Float64Array::new(times).to_vec()
    } else {
        let problem =
            format!("must be a Float64Array or an array of numbers (got {})", describe(times));
        return Err(throw(KliError::invalid("times", problem)));
    };
    let mut out = vec![0.0; 4 * times.len()];
    kli_sample_into(p, r, &times, &mut out, options.shortest_path).map_err(throw)?;
    if order == Order::Xyzw {
        out.chunks_exact_mut(4).for_each(|q| q.rotate_left(1));
    }
    Ok(Float64Array::from(&out[..]))
}
