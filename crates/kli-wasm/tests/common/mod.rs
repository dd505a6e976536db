//! What the `kli/sync` suites (`sync.rs`, `poses.rs`) share: plain objects and arrays built from
//! Rust, fields read back, and a thrown Error taken apart.
// Each suite that uses this module uses a part of it.
#![allow(dead_code)]

use js_sys::{Array, Float64Array, Object, Reflect};
use wasm_bindgen::{JsCast, JsValue};

/// A plain object from key–value pairs.
pub fn object(entries: &[(&str, JsValue)]) -> JsValue {
    let object = Object::new();
    for (key, value) in entries {
        Reflect::set(&object, &(*key).into(), value).unwrap();
    }
    object.into()
}

/// `value[key]`.
pub fn field(value: &JsValue, key: &str) -> JsValue {
    Reflect::get(value, &key.into()).unwrap()
}

/// `value[key]`, a `Float64Array`, as a vector.
pub fn floats(value: &JsValue, key: &str) -> Vec<f64> {
    field(value, key).unchecked_into::<Float64Array>().to_vec()
}

/// An array of `Float64Array`s, one a row.
pub fn nested(rows: &[&[f64]]) -> JsValue {
    rows.iter().map(|r| JsValue::from(Float64Array::from(*r))).collect::<Array>().into()
}

/// The `argument`, `kind` and message of a thrown Error.
pub fn refused(result: Result<impl Sized, impl Into<JsValue>>) -> (String, String, String) {
    let Err(error) = result else { panic!("expected an Error") };
    let error: JsValue = error.into();
    let get = |key: &str| Reflect::get(&error, &key.into()).unwrap().as_string().unwrap();
    (get("argument"), get("kind"), get("message"))
}
