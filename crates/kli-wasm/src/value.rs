//! JavaScript values, touched only in ways that cannot throw across Rust's stack: the few
//! operations both readers ([`crate::read`], values in; [`crate::typed`], typed arrays and
//! array-likes) need, and the description of a value for a message.
//!
//! A JavaScript exception thrown while Rust is on the stack skips Rust's destructors: borrow
//! flags stay set (the object is bricked) and externref slots leak until the module traps. So
//! every JavaScript operation here that can throw is an import marked `catch`.

use js_sys::Reflect;
use kli::KliError;
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;

use crate::error::number;

#[wasm_bindgen]
extern "C" {
    /// `Array.isArray`, which throws for a revoked Proxy.
    #[wasm_bindgen(catch, js_namespace = Array, js_name = isArray)]
    pub fn is_array(value: &JsValue) -> Result<bool, JsValue>;

    /// True for typed arrays and DataViews (their internal slot; never throws).
    #[wasm_bindgen(js_namespace = ArrayBuffer, js_name = isView)]
    pub fn is_view(value: &JsValue) -> bool;

    /// A caller's typed array, its properties read with every exception caught (an own
    /// property or a changed prototype can make them lie, or throw).
    #[wasm_bindgen(js_name = Float64Array)]
    pub type Caller;
    #[wasm_bindgen(catch, method, getter)]
    pub fn length(this: &Caller) -> Result<f64, JsValue>;
    #[wasm_bindgen(catch, method, getter, js_name = byteOffset)]
    pub fn byte_offset(this: &Caller) -> Result<f64, JsValue>;
    #[wasm_bindgen(catch, method, getter)]
    pub fn buffer(this: &Caller) -> Result<JsValue, JsValue>;
}

/// A typed array's length, for messages (its own `length` property, read with care).
#[inline(never)]
pub fn typed_length(value: &JsValue) -> Option<f64> {
    value.unchecked_ref::<Caller>().length().ok()
}

/// What a value whose getter or Proxy trap threw is said to be: "options could not be read (…)".
#[inline(never)]
pub fn unreadable(name: &str, thrown_value: &JsValue) -> KliError {
    KliError::invalid(name, format!("could not be read ({})", thrown(thrown_value)))
}

/// `value[key]`, or an Error naming `name` when reading it throws (a getter, a Proxy's trap).
#[inline(never)]
pub fn get(name: &str, value: &JsValue, key: &JsValue) -> Result<JsValue, KliError> {
    Reflect::get(value, key).map_err(|e| unreadable(name, &e))
}

/// What a caught exception says, for ours.
#[inline(never)]
pub fn thrown(e: &JsValue) -> String {
    let message = Reflect::get(e, &"message".into()).ok().and_then(|m| m.as_string());
    format!("it threw: {}", message.unwrap_or_else(|| describe(e)))
}

/// A short description of a JavaScript value for error messages. Nothing here can throw: an
/// array's `length` (a Proxy's trap) is read through a caught `Reflect.get`.
#[inline(never)]
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
    } else if is_view(value) {
        let length = typed_length(value).unwrap_or(f64::NAN);
        // Its constructor's name, read with care (only for the message).
        let kind = Reflect::get(value, &"constructor".into())
            .and_then(|c| Reflect::get(&c, &"name".into()))
            .ok()
            .and_then(|n| n.as_string())
            .unwrap_or_else(|| "typed array".into());
        let article = if matches!(kind.as_bytes().first(), Some(b'I' | b'U')) { "an" } else { "a" };
        format!("{article} {kind} of length {}", number(length))
    } else if is_array(value).unwrap_or(false) {
        match Reflect::get(value, &"length".into()).ok().and_then(|l| l.as_f64()) {
            Some(length) => format!("an array of length {}", number(length)),
            None => "an array".into(),
        }
    } else {
        format!("a value of type {}", value.js_typeof().as_string().unwrap_or_default())
    }
}
