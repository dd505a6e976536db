//! The batch calls: arrays in, results written into the caller's Float64Array `out`. Float64Arrays
//! that live in the module's own memory ([`crate::Float64Buffer`] views) are used in place, with
//! no copy at all; other Float64Arrays are copied in and out a chunk at a time, so a call of any
//! size needs only a few hundred KB of wasm memory. Other inputs (a Float32Array from three.js or
//! glTF, any typed array or array of numbers) are first copied into a Float64Array in JavaScript.

use js_sys::{Float64Array, WebAssembly};
use kli::KliError;
use kli::batch::{BatchKind, check_lengths, kli_sample_into, run_batch};
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;

use crate::error::JsResult;
use crate::options::{KliOptionsObject, pair_and_options, read_options};
use crate::read::{Order, QuaternionLike};
use crate::typed::{F64Array, numbers};

/// Pairs per chunk: 4096 × 13 numbers × 8 bytes = 416 KB of scratch.
const CHUNK: usize = 4096;

/// The most times one call samples: 2^24, a 512 MiB result.
pub const MAX_TIMES: usize = 1 << 24;

/// The byte range `[start, end)` of `array` in the module's memory, if it is a view of it.
fn in_wasm_memory(array: &F64Array) -> Option<(usize, usize)> {
    let memory: WebAssembly::Memory = wasm_bindgen::memory().unchecked_into();
    let (buffer, start, end) = array.range();
    let size = memory.buffer().unchecked_into::<js_sys::ArrayBuffer>().byte_length() as usize;
    // A view's own facts are trusted only when they fit the memory (they could be forged).
    (*buffer == memory.buffer() && start % 8 == 0 && end <= size).then_some((start, end))
}

/// The four arrays in place, when all are views of the module's memory and `out` overlaps no
/// input (overlapping `&` and `&mut` slices would be undefined behaviour).
fn in_place(arrays: [&F64Array; 4]) -> Option<[(usize, usize); 4]> {
    let ranges = [
        in_wasm_memory(arrays[0])?,
        in_wasm_memory(arrays[1])?,
        in_wasm_memory(arrays[2])?,
        in_wasm_memory(arrays[3])?,
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
) -> Result<F64Array, KliError> {
    let parameter_name = kind.parameter_name();
    let input = |name, value| F64Array::input(name, value, 4 * MAX_TIMES);
    let (starts, ends) = (input("starts", starts)?, input("ends", ends)?);
    let (parameters, out) = (input(parameter_name, parameters)?, F64Array::new("out", out)?);
    let n = parameters.length;
    check_lengths(starts.length, ends.length, n, out.length, parameter_name)?;
    if let Some([s, e, x, o]) = in_place([&starts, &ends, &parameters, &out]) {
        let slice = |(a, b): (usize, usize)| -> &[f64] {
            // SAFETY: a live Float64Array view of our memory: aligned, in bounds, and (checked
            // above) not overlapping `out`, which no other Rust reference touches during the call.
            unsafe { std::slice::from_raw_parts(a as *const f64, (b - a) / 8) }
        };
        // SAFETY: as above; `out` is disjoint from the three inputs.
        let q = unsafe { std::slice::from_raw_parts_mut(o.0 as *mut f64, (o.1 - o.0) / 8) };
        run_batch(kind, slice(s), slice(e), slice(x), q, 0, shortest_path)?;
        return Ok(out);
    }
    let chunk = CHUNK.min(n);
    let (mut p, mut r) = (Scratch::beside(&starts, 4 * chunk), Scratch::beside(&ends, 4 * chunk));
    let (mut x, mut q) = (Scratch::beside(&parameters, chunk), Scratch::beside(&out, 4 * chunk));
    let (p, r, x, q) = (p.slice(), r.slice(), x.slice(), q.slice());
    for first in (0..n).step_by(CHUNK.max(1)) {
        let m = CHUNK.min(n - first);
        starts.read("starts", 4 * first, &mut p[..4 * m])?;
        ends.read("ends", 4 * first, &mut r[..4 * m])?;
        parameters.read(parameter_name, first, &mut x[..m])?;
        run_batch(kind, &p[..4 * m], &r[..4 * m], &x[..m], &mut q[..4 * m], first, shortest_path)?;
        out.write("out", 4 * first, &q[..4 * m])?;
    }
    Ok(out)
}

/// A chunk's scratch space in the module's memory for one of the caller's arrays, placed half
/// a page away from it: at an address that differs from the array's byte offset by 2048 modulo
/// 4096. Each chunk is copied between the two by one `memmove`, and glibc's (Node on x86-64)
/// runs about 7× slower when source and destination lie a multiple of 4 KiB apart to within 16
/// bytes ("4K aliasing"), as they do when both start near a page boundary: large ArrayBuffers
/// do, and so did this scratch (`node bench/batch.mjs`: copying 10⁶ results out took 12.5 ms
/// where it takes 1.8, docs/performance.md). Half a page away keeps clear of it for any
/// buffer that starts within 2 KB of a page boundary.
struct Scratch {
    data: Vec<f64>,
    start: usize,
}

impl Scratch {
    fn beside(array: &F64Array, length: usize) -> Scratch {
        // Room to start anywhere in a page; only what is used is written (a call of one pair
        // should not zero 16 KB of scratch).
        let mut data = Vec::with_capacity(length + 511);
        let (_, offset, _) = array.range();
        let start = half_page_apart(data.as_ptr() as usize, offset);
        // Within the capacity: the allocation, and so `start`, stays where it is.
        data.resize(start + length, 0.0);
        Scratch { data, start }
    }

    fn slice(&mut self) -> &mut [f64] {
        &mut self.data[self.start..]
    }
}

/// The element (of `f64`s from byte `address`, below 512) that lies 2048 bytes modulo 4096 from
/// the byte `offset`.
fn half_page_apart(address: usize, offset: usize) -> usize {
    (2048 + offset).wrapping_sub(address) % 4096 / 8
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
    let (options, order) = read_options(options)?;
    let shortest_path = kind == BatchKind::Nlerp || options.shortest_path;
    let out = run_arrays(kind, starts, ends, parameters, out, shortest_path)
        .map_err(|e| order.batch_error(e))?;
    Ok(out.into_array())
}

/// `out[4i..4i+4] = Slerp(starts[i], ends[i]; s[i])` for n pairs (arrays of 4n, 4n, n, 4n
/// numbers, scalar first or, with `order: "xyzw"`, last, read in place either way); returns
/// `out`. Same checks as `slerp`; errors name the element.
#[wasm_bindgen(js_name = slerpBatch)]
pub fn slerp_batch(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | ArrayLike<number>")] starts: &JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array | ArrayLike<number>")] ends: &JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array | ArrayLike<number>")] s: &JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array")] out: &JsValue,
    options: Option<KliOptionsObject>,
) -> JsResult<Float64Array> {
    run(BatchKind::Slerp, starts, ends, s, out, options)
}

/// `out[4i..4i+4] = q(t[i])`, the exact KLI solution from `starts[i]` towards `ends[i]`, for n
/// pairs; returns `out`. Same checks as `kliExact`; errors name the element.
#[wasm_bindgen(js_name = kliExactBatch)]
pub fn kli_exact_batch(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | ArrayLike<number>")] starts: &JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array | ArrayLike<number>")] ends: &JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array | ArrayLike<number>")] t: &JsValue,
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
    #[wasm_bindgen(unchecked_param_type = "Float64Array | ArrayLike<number>")] starts: &JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array | ArrayLike<number>")] ends: &JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array | ArrayLike<number>")] s: &JsValue,
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
    let (p, r, options, order) = pair_and_options(p, r, options)?;
    let times = numbers("times", times, MAX_TIMES)?;
    let mut out = vec![0.0; 4 * times.len()];
    kli_sample_into(p, r, &times, &mut out, options.shortest_path)?;
    if order == Order::Xyzw {
        out.chunks_exact_mut(4).for_each(|q| q.rotate_left(1));
    }
    Ok(Float64Array::from(&out[..]))
}

#[cfg(test)]
mod tests {
    use super::half_page_apart;

    #[test]
    fn scratch_lies_half_a_page_from_the_array() {
        for address in [8, 4096, 4104, 65536 + 2040, 1 << 20, usize::MAX - 7] {
            for offset in [0, 8, 16, 2048, 4088, 123_456] {
                let start = half_page_apart(address, offset);
                assert!(start < 512, "{address} {offset}: {start}");
                let apart = (address.wrapping_add(8 * start)).wrapping_sub(offset) % 4096;
                assert_eq!(apart, 2048, "{address} {offset}");
            }
        }
    }
}
