//! JavaScript values in: numbers, quaternions and vectors from Arrays or typed arrays, and short
//! descriptions of values for messages. Argument names are the Rust names ([`crate::error`]
//! turns them into JavaScript's).

use glam::{DQuat, DVec3};
use js_sys::{Array, Float64Array, Reflect};
use kli::KliError;
use kli::quaternion::{from_wxyz, unit};
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;

use crate::error::number;

#[wasm_bindgen]
extern "C" {
    /// `[w, x, y, z]`: an Array or typed array of 4 numbers.
    #[wasm_bindgen(typescript_type = "QuaternionLike")]
    pub type QuaternionLike;

    /// `[x, y, z]`: an Array or typed array of 3 numbers.
    #[wasm_bindgen(typescript_type = "Vector3Like")]
    pub type Vector3Like;
}

/// A short description of a JavaScript value for error messages.
pub fn describe(value: &JsValue) -> String {
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

/// Reads exactly `N` numbers from an Array or typed array; `shape` names them in messages,
/// e.g. "[w, x, y, z]". Whether they are finite is the core's to check.
pub fn numbers<const N: usize>(
    name: &str,
    value: &JsValue,
    shape: &str,
) -> Result<[f64; N], KliError> {
    let mut out = [0.0; N];
    if let Some(array) = value.dyn_ref::<Float64Array>() {
        if array.length() as usize != N {
            let problem = format!("must hold {N} numbers {shape} (got {})", array.length());
            return Err(KliError::invalid(name, problem));
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
        let problem = format!("must be an array of {N} numbers {shape} (got {})", describe(value));
        return Err(KliError::invalid(name, problem));
    }
    for (i, slot) in out.iter_mut().enumerate() {
        let element = Reflect::get_u32(value, i as u32).unwrap_or(JsValue::UNDEFINED);
        *slot = element.as_f64().ok_or_else(|| {
            let problem =
                format!("must hold {N} numbers {shape}: element {i} is {}", describe(&element));
            KliError::invalid(name, problem)
        })?;
    }
    Ok(out)
}

/// Reads a quaternion `[w, x, y, z]` and normalises it.
pub fn quaternion(name: &str, value: &JsValue) -> Result<DQuat, KliError> {
    unit(name, from_wxyz(numbers(name, value, "[w, x, y, z]")?))
}

/// Reads a 3-vector `[x, y, z]`.
pub fn vector3(name: &str, value: &JsValue) -> Result<DVec3, KliError> {
    Ok(DVec3::from_array(numbers(name, value, "[x, y, z]")?))
}

/// `value` as a `Float64Array`.
pub fn float64_array<'a>(name: &str, value: &'a JsValue) -> Result<&'a Float64Array, KliError> {
    value.dyn_ref::<Float64Array>().ok_or_else(|| {
        KliError::invalid(name, format!("must be a Float64Array (got {})", describe(value)))
    })
}
