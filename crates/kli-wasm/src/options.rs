//! The options object of every call (TypeScript `KliOptions`): absent, `undefined` or `null`
//! give the defaults, unknown keys are refused, and each key is checked for its type here and
//! for its value by the core ([`kli::KliOptions::validate`]).

use js_sys::{Array, Object, Reflect};
use kli::{Integrator, KliError, KliOptions};
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;

use crate::error::js_name;
use crate::read::describe;

#[wasm_bindgen]
extern "C" {
    /// `{ tolerance, step, maxTime, integrator, shortestPath }`, each optional.
    #[wasm_bindgen(typescript_type = "KliOptions")]
    pub type KliOptionsObject;
}

/// The fields of [`KliOptions`], by their Rust names; JavaScript's keys are their camelCase.
const KEYS: [&str; 5] = ["tolerance", "step", "max_time", "integrator", "shortest_path"];

/// Reads the options object into checked [`KliOptions`].
pub fn read_options(value: Option<KliOptionsObject>) -> Result<KliOptions, KliError> {
    let mut options = KliOptions::default();
    let Some(object) = value.map(JsValue::from).filter(|v| !v.is_undefined() && !v.is_null())
    else {
        return Ok(options);
    };
    check_keys(&object)?;
    let field =
        |key: &str| Reflect::get(&object, &js_name(key).into()).unwrap_or(JsValue::UNDEFINED);
    if let Some(v) = read_number("tolerance", field("tolerance"))? {
        options.tolerance = v;
    }
    if let Some(v) = read_number("step", field("step"))? {
        options.step = v;
    }
    if let Some(v) = read_number("max_time", field("max_time"))? {
        options.max_time = v;
    }
    let integrator = field("integrator");
    if !integrator.is_undefined() {
        let name = integrator.as_string().unwrap_or_else(|| describe(&integrator));
        options.integrator = name.parse::<Integrator>()?;
    }
    let shortest_path = field("shortest_path");
    if !shortest_path.is_undefined() {
        options.shortest_path = shortest_path.as_bool().ok_or_else(|| {
            let problem = format!("must be true or false (got {})", describe(&shortest_path));
            KliError::invalid("shortest_path", problem)
        })?;
    }
    options.validate()?;
    Ok(options)
}

/// Only the keys of [`KEYS`], on a plain object.
fn check_keys(object: &JsValue) -> Result<(), KliError> {
    if !object.is_object() || Array::is_array(object) {
        let problem =
            format!("must be an object like {{ tolerance: 1e-5 }} (got {})", describe(object));
        return Err(KliError::invalid("options", problem));
    }
    for key in Object::keys(object.unchecked_ref::<Object>()).iter() {
        let key = key.as_string().unwrap_or_default();
        if !KEYS.iter().any(|k| js_name(k) == key) {
            let mut problem = format!("has an unknown key \"{key}\"; the keys are ");
            for (i, k) in KEYS.iter().enumerate() {
                problem.push_str(if i == 0 { "" } else { ", " });
                problem.push_str(&js_name(k));
            }
            return Err(KliError::invalid("options", problem));
        }
    }
    Ok(())
}

/// A number option, or `None` when it is `undefined`.
fn read_number(name: &str, value: JsValue) -> Result<Option<f64>, KliError> {
    if value.is_undefined() {
        return Ok(None);
    }
    let problem = || format!("must be a number (got {})", describe(&value));
    value.as_f64().map(Some).ok_or_else(|| KliError::invalid(name, problem()))
}
