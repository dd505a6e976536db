//! Typed arrays and array-likes read so that no JavaScript exception can cross Rust's stack.
//!
//! A JavaScript exception thrown while Rust is on the stack skips Rust's destructors: borrow
//! flags stay set (the object is bricked) and externref slots leak until the module traps. So
//! every JavaScript operation here that can throw is an import marked `catch`. Numbers are read
//! from a typed array by copying it (`new Float64Array(source)`, which reads its internal slots:
//! an own `length` property or a changed prototype cannot make it lie), and the caller's
//! Float64Arrays are written through fresh views of their buffer, which fail (an Error, not a
//! trap) if their claimed facts are not their own.

use js_sys::{Float64Array, Reflect};
use kli::KliError;
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;

use crate::read::describe;

#[wasm_bindgen]
extern "C" {
    /// True for typed arrays and DataViews (their internal slot; never throws).
    #[wasm_bindgen(js_namespace = ArrayBuffer, js_name = isView)]
    pub fn is_view(value: &JsValue) -> bool;

    /// A Float64Array made here, so none of its properties can be the caller's.
    #[wasm_bindgen(js_name = Float64Array)]
    type Fresh;

    /// `new Float64Array(typedArray)`: a copy read through the source's internal slots.
    #[wasm_bindgen(catch, constructor, js_class = "Float64Array")]
    fn copy_of(source: &JsValue) -> Result<Fresh, JsValue>;

    /// `new Float64Array(buffer, byteOffset, length)`: a fresh view, so no species lookup.
    #[wasm_bindgen(catch, constructor, js_class = "Float64Array")]
    fn view_of(buffer: &JsValue, byte_offset: f64, length: f64) -> Result<Fresh, JsValue>;

    /// The caller's Float64Array, its properties read with every exception caught.
    #[wasm_bindgen(js_name = Float64Array)]
    type Caller;
    #[wasm_bindgen(catch, method, getter)]
    fn length(this: &Caller) -> Result<f64, JsValue>;
    #[wasm_bindgen(catch, method, getter, js_name = byteOffset)]
    fn byte_offset(this: &Caller) -> Result<f64, JsValue>;
    #[wasm_bindgen(catch, method, getter)]
    fn buffer(this: &Caller) -> Result<JsValue, JsValue>;
}

/// A copy of the typed array `value` (any element type but BigInt), or `None` if it is not one.
#[inline(never)]
pub fn copy(value: &JsValue) -> Option<Float64Array> {
    if !is_view(value) {
        return None;
    }
    // A DataView is copied as an empty array-like; a BigInt64Array throws (caught): neither is
    // a typed array of numbers.
    let copy: Float64Array = Fresh::copy_of(value).ok()?.unchecked_into();
    (copy.length() > 0 || typed_length(value) == Some(0.0)).then_some(copy)
}

/// A typed array's length, for messages (its own `length` property, read with care).
#[inline(never)]
pub fn typed_length(value: &JsValue) -> Option<f64> {
    value.unchecked_ref::<Caller>().length().ok()
}

/// "must be …" with what was received.
#[inline(never)]
fn refused(name: &str, wanted: &str, value: &JsValue) -> KliError {
    KliError::invalid(name, format!("must be {wanted} (got {})", describe(value)))
}

/// Up to `max` numbers from any typed array of numbers (Float64Array, Float32Array, Int32Array…,
/// converted exactly) or array-like of numbers (an Array, `{ length, 0: … }`, a Proxy). Whether
/// they are finite is the caller's to check.
#[inline(never)]
pub fn numbers(name: &str, value: &JsValue, max: usize) -> Result<Vec<f64>, KliError> {
    let wanted = "a typed array or an array of numbers";
    if is_view(value) {
        // Its own length first, so a huge array is refused before it is copied.
        if let Some(length) = typed_length(value).filter(|&n| n > max as f64) {
            return Err(too_long(name, length, max));
        }
        let Some(copy) = copy(value) else { return Err(refused(name, wanted, value)) };
        if copy.length() as usize > max {
            return Err(too_long(name, copy.length() as f64, max));
        }
        return Ok(copy.to_vec());
    }
    if !value.is_object() {
        return Err(refused(name, wanted, value));
    }
    let length = get(name, value, &"length".into())?;
    let n = length.as_f64().filter(|n| n.fract() == 0.0 && *n >= 0.0);
    let Some(n) = n else { return Err(refused(name, wanted, value)) };
    if n > max as f64 {
        return Err(too_long(name, n, max));
    }
    let mut out = Vec::with_capacity(n as usize);
    for i in 0..n as u32 {
        let element = get(name, value, &i.into())?;
        let Some(x) = element.as_f64() else {
            let problem = format!("{ELEMENT}{i} is {}", describe(&element));
            return Err(KliError::invalid(name, problem));
        };
        out.push(x);
    }
    Ok(out)
}

/// How a value whose getter or Proxy trap threw is described: "options could not be read (…)".
pub const UNREADABLE: &str = "could not be read ";

/// How an element that is not a number is named: "times must hold numbers: element 2 is …".
pub const ELEMENT: &str = "must hold numbers: element ";

#[inline(never)]
fn too_long(name: &str, length: f64, max: usize) -> KliError {
    let problem = format!("may hold at most {max} numbers (got {})", crate::error::number(length));
    KliError::invalid(name, problem)
}

/// `value[key]`, or an Error naming `name` when reading it throws (a getter, a Proxy's trap).
#[inline(never)]
pub fn get(name: &str, value: &JsValue, key: &JsValue) -> Result<JsValue, KliError> {
    Reflect::get(value, key)
        .map_err(|e| KliError::invalid(name, format!("{UNREADABLE}({})", thrown(&e))))
}

/// What a caught exception says, for ours.
#[inline(never)]
pub fn thrown(e: &JsValue) -> String {
    let message = Reflect::get(e, &"message".into()).ok().and_then(|m| m.as_string());
    format!("it threw: {}", message.unwrap_or_else(|| describe(e)))
}

/// The length of `value` if it is a Float64Array, else an Error naming what it is: the cheap
/// check (three calls into JavaScript) of an `out` written element by element.
pub fn float64_length(name: &str, value: &JsValue) -> Result<usize, KliError> {
    let length = value.unchecked_ref::<Caller>().length();
    match length {
        Ok(n) if is_view(value) && value.is_instance_of::<Float64Array>() => Ok(n as usize),
        _ => Err(refused(name, "a Float64Array", value)),
    }
}

/// A caller's Float64Array: read and written through its slots, a chunk at a time if need be.
pub struct F64Array {
    array: JsValue,
    buffer: JsValue,
    byte_offset: f64,
    pub length: usize,
}

impl F64Array {
    /// `value` if it is a Float64Array, else an Error naming what it is.
    pub fn new(name: &str, value: &JsValue) -> Result<F64Array, KliError> {
        let caller: &Caller = value.unchecked_ref();
        let facts = (caller.length(), caller.byte_offset(), caller.buffer());
        match facts {
            (Ok(length), Ok(byte_offset), Ok(buffer))
                if is_view(value) && value.is_instance_of::<Float64Array>() =>
            {
                Ok(F64Array { array: value.clone(), buffer, byte_offset, length: length as usize })
            }
            _ => Err(refused(name, "a Float64Array", value)),
        }
    }

    /// An input array: a Float64Array as is (used in place when it lives in the module's
    /// memory); any other typed array of numbers (a Float32Array from three.js or glTF) or
    /// array-like of numbers copied into a fresh Float64Array first, at most `max` numbers.
    pub fn input(name: &str, value: &JsValue, max: usize) -> Result<F64Array, KliError> {
        if is_view(value) && value.is_instance_of::<Float64Array>() {
            return F64Array::new(name, value);
        }
        let copy: Float64Array = match copy(value) {
            Some(copy) if copy.length() as usize <= max => copy,
            Some(copy) => return Err(too_long(name, copy.length() as f64, max)),
            None => Float64Array::from(&numbers(name, value, max)?[..]),
        };
        Ok(F64Array {
            length: copy.length() as usize,
            buffer: copy.buffer().into(),
            byte_offset: 0.0,
            array: copy.into(),
        })
    }

    /// The array's buffer and the byte range it covers in it.
    pub fn range(&self) -> (&JsValue, usize, usize) {
        let start = self.byte_offset as usize;
        (&self.buffer, start, start + 8 * self.length)
    }

    /// A fresh view of elements `[start, start + length)`.
    fn view(&self, name: &str, start: usize, length: usize) -> Result<Float64Array, KliError> {
        let offset = self.byte_offset + 8.0 * start as f64;
        // A fresh view of a range checked against the array's own length fails only if its
        // facts were forged (own `buffer`, `byteOffset` or `length` properties): an Error.
        match Fresh::view_of(&self.buffer, offset, length as f64) {
            Ok(view) => Ok(view.unchecked_into()),
            Err(e) => Err(KliError::invalid(name, format!("{UNREADABLE}({})", thrown(&e)))),
        }
    }

    /// Copies elements `[start, start + into.len())` into `into`.
    pub fn read(&self, name: &str, start: usize, into: &mut [f64]) -> Result<(), KliError> {
        let view = self.view(name, start, into.len())?;
        if view.length() as usize != into.len() {
            return Err(KliError::invalid(name, "is shorter than its length says"));
        }
        view.copy_to(into);
        Ok(())
    }

    /// Copies `from` into elements `[start, start + from.len())`. The copy is made in
    /// JavaScript straight from the module's memory (`copy_from`): a view of it held across a
    /// call could be detached by the memory growing under it.
    pub fn write(&self, name: &str, start: usize, from: &[f64]) -> Result<(), KliError> {
        let view = self.view(name, start, from.len())?;
        if view.length() as usize != from.len() {
            return Err(KliError::invalid(name, "is shorter than its length says"));
        }
        // A fresh view exactly as long as `from`, and no code of the caller's runs: `set`
        // cannot throw.
        view.copy_from(from);
        Ok(())
    }

    /// The caller's array, to return.
    pub fn into_array(self) -> Float64Array {
        self.array.unchecked_into()
    }
}
