//! The `kli/average` entry: the mean of many rotations ([`kli::average`]) and an
//! order-independent blend of poses (MATH.md, "Averaging rotations").

use glam::DQuat;
use js_sys::Float64Array;
use kli::average::{Method, average};
use kli::{KliError, Requirement, require};
use wasm_bindgen::prelude::*;

use crate::error::JsResult;
use crate::options::Fields;
use crate::read::{Order, quaternion_numbers};
use crate::typed::{F64Array, numbers};
use crate::value::describe;

/// The most numbers a list may hold (2²⁴ quaternions' worth: 512 MB of f64 in all).
const MAX_LENGTH: usize = 1 << 26;

#[wasm_bindgen(typescript_custom_section)]
const TYPES: &'static str = r#"
/** Many quaternions: 4n numbers (any typed array, or a flat array), or an array of n
 *  quaternions (arrays or `{ x, y, z, w }` objects). */
export type QuaternionsLike = ArrayLike<number> | ArrayLike<QuaternionLike>;

/** Which mean: the chordal L2 mean (SciPy's `Rotation.mean`; the default), the quaternion mean
 *  (signs aligned to one hemisphere), the geodesic (Karcher) mean, or the geodesic L1 median
 *  (robust to outliers). */
export type AverageMethod = "chordal" | "quaternion" | "geodesic" | "median";

/** Options of `averageRotations`; every key is optional and unknown keys are rejected. */
export interface AverageOptions {
  /** One weight a rotation, each finite and > 0. Default: all 1. */
  weights?: ArrayLike<number>;
  /** Default "chordal". */
  method?: AverageMethod;
  /** How quaternion arrays are laid out, in and out. Default "wxyz". */
  order?: QuaternionOrder;
}

/** A mean of many rotations, and how it was reached. */
export interface Average {
  /** The mean, a unit quaternion in the call's order. */
  rotation: Float64Array;
  /** Iterations taken (0 for a closed form). */
  iterations: number;
  /** How far from settled: the eigen-residual (chordal), the last step in radians (geodesic,
   *  median), 0 (quaternion). */
  residual: number;
  /** The weighted RMS angle from the mean to the data, radians. */
  dispersion: number;
  /** For the median: each rotation's final weight (summing to 1); an outlier's is small. */
  weights?: Float64Array;
}

/** Options of `blendRotations`. */
export interface BlendOptions {
  /** How the poses and `out` are laid out. Default "wxyz". */
  order?: QuaternionOrder;
}
"#;

#[wasm_bindgen]
extern "C" {
    #[wasm_bindgen(typescript_type = "QuaternionsLike")]
    pub type QuaternionsLike;

    #[wasm_bindgen(typescript_type = "AverageOptions")]
    pub type AverageOptionsObject;

    #[wasm_bindgen(typescript_type = "BlendOptions")]
    pub type BlendOptionsObject;
}

/// The mean of `quaternions` (any signs) with the options' `weights`, by its `method`: chordal
/// by default. A mean that is not unique (`1` and `i`) is an Error of kind `"not-unique"`.
#[wasm_bindgen(js_name = averageRotations, unchecked_return_type = "Average")]
pub fn average_rotations(
    quaternions: &QuaternionsLike,
    options: Option<AverageOptionsObject>,
) -> JsResult<JsValue> {
    let fields = Fields::new(
        options.map(JsValue::from),
        &["weights", "method", "order"],
        "{ method: \"median\" }",
    )?;
    let (mut order, mut method, mut weights) = (Order::Wxyz, Method::Chordal, None);
    if let Some(fields) = &fields {
        order = Order::parse(fields.name("order")?)?;
        if let Some(name) = fields.name("method")? {
            method = name.parse()?;
        }
        if let Some(value) = fields.value("weights")? {
            weights = Some(numbers("weights", &value, MAX_LENGTH / 4)?);
        }
    }
    let flat = quaternion_numbers("quaternions", "rotation", quaternions, order, MAX_LENGTH)?;
    let rotations = flat.chunks_exact(4).map(|q| order.read([q[0], q[1], q[2], q[3]]));
    let mean = average(rotations, weights.as_deref(), method).map_err(|e| order.error(e))?;
    let result = js_sys::Object::new();
    let set = |key: &str, value: JsValue| {
        let _ = js_sys::Reflect::set(&result, &key.into(), &value);
    };
    set("rotation", order.array(mean.rotation).into());
    set("iterations", (mean.iterations as f64).into());
    set("residual", mean.residual.into());
    set("dispersion", mean.dispersion.into());
    if let Some(weights) = &mean.weights {
        set("weights", Float64Array::from(&weights[..]).into());
    }
    Ok(result.into())
}

/// The weighted chordal mean of each bone over `poses`: P poses of B bones each, pose after
/// pose (4·B·P numbers), `weights` P numbers (each ≥ 0, not all 0: a pose of weight 0 is left
/// out), written into `out` (a Float64Array of 4·B) and returned. The order of the poses does
/// not change the result (to rounding). A bone whose mean is not unique is an Error naming it
/// (`bones[3]`). Each bone's mean is on the hemisphere of the first pose of weight > 0.
#[wasm_bindgen(js_name = blendRotations)]
pub fn blend_rotations(
    #[wasm_bindgen(unchecked_param_type = "ArrayLike<number>")] poses: &JsValue,
    #[wasm_bindgen(unchecked_param_type = "ArrayLike<number>")] weights: &JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array")] out: &JsValue,
    options: Option<BlendOptionsObject>,
) -> JsResult<Float64Array> {
    let fields = Fields::new(options.map(JsValue::from), &["order"], "{ order: \"xyzw\" }")?;
    let order = match &fields {
        Some(fields) => Order::parse(fields.name("order")?)?,
        None => Order::Wxyz,
    };
    let weights = numbers("weights", weights, MAX_LENGTH / 4)?;
    for (p, &w) in weights.iter().enumerate() {
        require(&format!("weights[{p}]"), w, Requirement::NonNegative)?;
    }
    let kept: Vec<usize> = (0..weights.len()).filter(|&p| weights[p] > 0.0).collect();
    if kept.is_empty() {
        return Err(KliError::invalid("weights", "must hold at least one weight > 0").into());
    }
    let target = F64Array::new("out", out)?;
    if target.length % 4 != 0 || target.length == 0 {
        let problem = format!("must be a Float64Array of 4 numbers a bone (got {})", describe(out));
        return Err(KliError::invalid("out", problem).into());
    }
    let bones = target.length / 4;
    let flat = numbers("poses", poses, MAX_LENGTH)?;
    if flat.len() != 4 * bones * weights.len() {
        let problem = format!(
            "must hold {} numbers: 4 for each of {bones} bones (out's length / 4) in each of {} poses (got {})",
            4 * bones * weights.len(),
            weights.len(),
            flat.len()
        );
        return Err(KliError::invalid("poses", problem).into());
    }
    let kept_weights: Vec<f64> = kept.iter().map(|&p| weights[p]).collect();
    let mut blended = vec![0.0; 4 * bones];
    let mut pose = vec![DQuat::IDENTITY; kept.len()];
    for bone in 0..bones {
        for (slot, &p) in pose.iter_mut().zip(&kept) {
            let at = 4 * (p * bones + bone);
            *slot = order.read([flat[at], flat[at + 1], flat[at + 2], flat[at + 3]]);
        }
        let mean = average(&pose, Some(&kept_weights), Method::Chordal).map_err(|e| {
            // The core names an element of its own list: here, the pose it came from.
            let index = e.argument().strip_prefix("quaternions[").and_then(|i| i.strip_suffix(']'));
            let argument = match index.and_then(|i| i.parse::<usize>().ok()) {
                Some(j) => format!("poses[{}] (bone {bone})", kept[j]),
                None => format!("bones[{bone}]"),
            };
            order.error(e.renamed(argument))
        })?;
        // On the hemisphere of the first pose that counts, so a bone's sign does not flip.
        let rotation =
            if mean.rotation.dot(pose[0]) < 0.0 { -mean.rotation } else { mean.rotation };
        blended[4 * bone..4 * bone + 4].copy_from_slice(&order.write(rotation));
    }
    target.write("out", 0, &blended)?;
    Ok(target.into_array())
}
