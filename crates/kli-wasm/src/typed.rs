//! Typed arrays and array-likes read so that no JavaScript exception can cross Rust's stack
//! (every operation that can throw is a caught import: [`crate::value`]). Numbers are read
//! from a typed array by copying it (`new Float64Array(source)`, which reads its internal slots:
//! an own `length` property or a changed prototype cannot make it lie), and the caller's
//! Float64Arrays are written through fresh views of their buffer, which fail (an Error, not a
//! trap) if their claimed facts are not their own.

use js_sys::Float64Array;
use kli::KliError;
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;

use crate::value::{Caller, describe, get, is_view, typed_length, unreadable};

#[wasm_bindgen]
extern "C" {
    /// A Float64Array made here, so none of its properties can be the caller's.
    #[wasm_bindgen(js_name = Float64Array)]
    type Fresh;

    /// `new Float64Array(typedArray)`: a copy read through the source's internal slots.
    #[wasm_bindgen(catch, constructor, js_class = "Float64Array")]
    fn copy_of(source: &JsValue) -> Result<Fresh, JsValue>;

    /// `new Float64Array(buffer, byteOffset, length)`: a fresh view, so no species lookup.
    #[wasm_bindgen(catch, constructor, js_class = "Float64Array")]
    fn view_of(buffer: &JsValue, byte_offset: f64, length: f64) -> Result<Fresh, JsValue>;
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

/// "must be …" with what was received.
#[inline(never)]
fn refused(name: &str, wanted: &str, value: &JsValue) -> KliError {
    KliError::invalid(name, format!("must be {wanted} (got {})", describe(value)))
}

/// Why [`read_numbers`] refused a value, said where it arose so that a caller can word it for
/// its own argument (a quaternion's "must hold 4 numbers [w, x, y, z]: element 2 is …").
pub enum Refused {
    /// Element `index` is not a number; `got` describes it.
    Element { index: u32, got: String },
    /// Reading the value threw (a getter, a Proxy's trap): the Error to pass on as it is.
    Unreadable(KliError),
    /// Not a typed array or array-like of numbers, or longer than allowed.
    Shape(KliError),
}

impl Refused {
    /// The Error, worded for any list of numbers.
    #[inline(never)]
    pub fn error(self, name: &str) -> KliError {
        match self {
            Refused::Element { index, got } => {
                KliError::invalid(name, format!("must hold numbers: element {index} is {got}"))
            }
            Refused::Unreadable(e) | Refused::Shape(e) => e,
        }
    }
}

/// Up to `max` numbers from any typed array of numbers (Float64Array, Float32Array, Int32Array…,
/// converted exactly) or array-like of numbers (an Array, `{ length, 0: … }`, a Proxy). Whether
/// they are finite is the caller's to check.
#[inline(never)]
pub fn numbers(name: &str, value: &JsValue, max: usize) -> Result<Vec<f64>, KliError> {
    read_numbers(name, value, max).map_err(|refused| refused.error(name))
}

/// [`numbers`], with why it refused as a [`Refused`].
#[inline(never)]
pub fn read_numbers(name: &str, value: &JsValue, max: usize) -> Result<Vec<f64>, Refused> {
    let wanted = "a typed array or an array of numbers";
    let shape = |e: KliError| Refused::Shape(e);
    if is_view(value) {
        // Its own length first, so a huge array is refused before it is copied.
        if let Some(length) = typed_length(value).filter(|&n| n > max as f64) {
            return Err(shape(too_long(name, length, max)));
        }
        if value.is_instance_of::<Float64Array>() {
            // Read through a fresh view into the module's memory: one copy, not two.
            let array = F64Array::new(name, value).map_err(shape)?;
            if array.length > max {
                return Err(shape(too_long(name, array.length as f64, max)));
            }
            return array.to_vec(name).map_err(Refused::Unreadable);
        }
        let Some(copy) = copy(value) else { return Err(shape(refused(name, wanted, value))) };
        if copy.length() as usize > max {
            return Err(shape(too_long(name, copy.length() as f64, max)));
        }
        return Ok(copy.to_vec());
    }
    if !value.is_object() {
        return Err(shape(refused(name, wanted, value)));
    }
    let length = get(name, value, &"length".into()).map_err(Refused::Unreadable)?;
    let n = length.as_f64().filter(|n| n.fract() == 0.0 && *n >= 0.0);
    let Some(n) = n else { return Err(shape(refused(name, wanted, value))) };
    if n > max as f64 {
        return Err(shape(too_long(name, n, max)));
    }
    let mut out = Vec::with_capacity(n as usize);
    for index in 0..n as u32 {
        let element = get(name, value, &index.into()).map_err(Refused::Unreadable)?;
        let Some(x) = element.as_f64() else {
            return Err(Refused::Element { index, got: describe(&element) });
        };
        out.push(x);
    }
    Ok(out)
}

#[inline(never)]
fn too_long(name: &str, length: f64, max: usize) -> KliError {
    let problem = format!("may hold at most {max} numbers (got {})", crate::error::number(length));
    KliError::invalid(name, problem)
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
            Err(e) => Err(unreadable(name, &e)),
        }
    }

    /// All its elements, copied once into the module's memory.
    pub fn to_vec(&self, name: &str) -> Result<Vec<f64>, KliError> {
        let view = self.view(name, 0, self.length)?;
        if view.length() as usize != self.length {
            return Err(KliError::invalid(name, "is shorter than its length says"));
        }
        Ok(view.to_vec())
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
