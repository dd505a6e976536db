//! JavaScript values in: numbers, quaternions and vectors from Arrays or typed arrays, in the
//! caller's [`Order`]. Argument names are the Rust names ([`crate::error`] turns them into
//! JavaScript's).

use glam::{DQuat, DVec3};
use js_sys::{Float64Array, Reflect};
use kli::quaternion::{from_wxyz, to_wxyz, unit};
use kli::{ErrorKind, KliError, Shape};
use wasm_bindgen::prelude::*;

use crate::typed::{Refused, read_numbers};
use crate::value::{describe, get, is_array, is_view};

#[wasm_bindgen]
extern "C" {
    /// `[w, x, y, z]`: an Array or typed array of 4 numbers.
    #[wasm_bindgen(typescript_type = "QuaternionLike")]
    pub type QuaternionLike;

    /// `[x, y, z]`: an Array or typed array of 3 numbers.
    #[wasm_bindgen(typescript_type = "Vector3Like")]
    pub type Vector3Like;
}

/// A number argument: a JavaScript number (not a string, a BigInt or an object), finite or not
/// (whether it may be infinite is the core's to check).
#[inline(never)]
pub fn number_argument(name: &str, value: &JsValue) -> Result<f64, KliError> {
    value.as_f64().ok_or_else(|| {
        KliError::invalid(name, format!("must be a number (got {})", describe(value)))
    })
}

/// `steps` as a count: absent is 1, else a whole number from 0 to 1e6 (the classes' `step`).
pub fn whole_steps(steps: &JsValue) -> Result<usize, KliError> {
    if steps.is_undefined() {
        return Ok(1);
    }
    Ok(crate::options::whole("steps", number_argument("steps", steps)?, 0.0, 1e6)? as usize)
}

/// Reads exactly `N` numbers from a typed array or an array-like; `shape` names them in
/// messages, e.g. "[w, x, y, z]". Whether they are finite is the core's to check.
pub fn numbers<const N: usize>(
    name: &str,
    value: &JsValue,
    shape: &str,
) -> Result<[f64; N], KliError> {
    let mut out = [0.0; N];
    exactly(name, value, shape, &mut out)?;
    Ok(out)
}

/// [`numbers`] for any `N` (one copy of the code, not one a length).
#[inline(never)]
fn exactly(name: &str, value: &JsValue, shape: &str, out: &mut [f64]) -> Result<(), KliError> {
    let n = out.len();
    // Read past `n` (up to 2^16 numbers), so that a wrong length is told as one: "p must hold 4
    // numbers (got 3)", kind "wrong-length", as the batch calls say it.
    let problem = match read_numbers(name, value, 1 << 16) {
        Ok(numbers) if numbers.len() == n => {
            out.copy_from_slice(&numbers);
            return Ok(());
        }
        Ok(numbers) => {
            let kind =
                ErrorKind::WrongLength { expected: n, got: numbers.len(), per: String::new() };
            return Err(KliError::new(name, kind));
        }
        // "p must hold 4 numbers [w, x, y, z]: element 0 is …"
        Err(Refused::Element { index, got }) => {
            format!("must hold {n} numbers {shape}: element {index} is {got}")
        }
        Err(Refused::Unreadable(e)) => return Err(e),
        Err(Refused::Shape(_)) => {
            format!("must be an array of {n} numbers {shape} (got {})", describe(value))
        }
    };
    Err(KliError::invalid(name, problem))
}

/// How the caller lays quaternions out in arrays: scalar first `[w, x, y, z]` (the paper's
/// a + bi + cj + dk, the default) or scalar last `[x, y, z, w]` (three.js, gl-matrix, glTF).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub enum Order {
    #[default]
    Wxyz,
    Xyzw,
}

impl Order {
    const NAMES: &'static [&'static str] = &["wxyz", "xyzw"];

    /// The option `order`: `None` (absent) is `"wxyz"`.
    pub fn parse(name: Option<String>) -> Result<Order, KliError> {
        match name.as_deref() {
            None | Some("wxyz") => Ok(Order::Wxyz),
            Some("xyzw") => Ok(Order::Xyzw),
            Some(got) => {
                let kind = ErrorKind::UnknownName { got: got.into(), allowed: Self::NAMES };
                Err(KliError::new("order", kind))
            }
        }
    }

    /// Four numbers in this order as a quaternion.
    pub fn read(self, [a, b, c, d]: [f64; 4]) -> DQuat {
        match self {
            Order::Wxyz => from_wxyz([a, b, c, d]),
            Order::Xyzw => DQuat::from_xyzw(a, b, c, d),
        }
    }

    /// A quaternion as four numbers in this order.
    #[inline(never)]
    pub fn write(self, q: DQuat) -> [f64; 4] {
        match self {
            Order::Wxyz => to_wxyz(q),
            Order::Xyzw => q.to_array(),
        }
    }

    /// One quaternion as a `Float64Array` in this order.
    #[inline(never)]
    pub fn array(self, q: DQuat) -> Float64Array {
        Float64Array::from(&self.write(q)[..])
    }

    /// Quaternions one after another in a `Float64Array`, each in this order.
    #[inline(never)]
    pub fn flat(self, qs: &[DQuat]) -> Float64Array {
        let flat: Vec<f64> = qs.iter().flat_map(|&q| self.write(q)).collect();
        Float64Array::from(&flat[..])
    }

    /// `e` about an argument read in this order (the core checks `[w, x, y, z]`): its component
    /// is named, and numbered, as the caller laid it out.
    pub fn error(self, e: KliError) -> KliError {
        self.relabel(e, |i| (i + 3) % 4)
    }

    /// `e` from a batch kernel, which reads the caller's arrays as they are laid out (its
    /// formulas treat the four components alike): its index is already the caller's.
    pub fn batch_error(self, e: KliError) -> KliError {
        self.relabel(e, |i| i)
    }

    #[inline(never)]
    fn relabel(self, e: KliError, position: impl Fn(usize) -> usize) -> KliError {
        if self == Order::Wxyz {
            return e;
        }
        let kind = match *e.kind() {
            ErrorKind::NotFinite { shape: Shape::Quaternion, index, value } => {
                ErrorKind::NotFinite { shape: Shape::QuaternionXyzw, index: position(index), value }
            }
            ErrorKind::ZeroLength { shape: Shape::Quaternion } => {
                ErrorKind::ZeroLength { shape: Shape::QuaternionXyzw }
            }
            _ => return e,
        };
        KliError::new(e.argument(), kind)
    }

    fn shape(self) -> &'static str {
        if self == Order::Wxyz { "[w, x, y, z]" } else { "[x, y, z, w]" }
    }
}

/// Reads a quaternion and normalises it: 4 numbers in `order`, or an object with number
/// properties `x`, `y`, `z`, `w` (a `THREE.Quaternion`, a glTF-style `{ x, y, z, w }`).
#[inline(never)]
pub fn quaternion(name: &str, value: &JsValue, order: Order) -> Result<DQuat, KliError> {
    if value.is_object() && Reflect::has(value, &"w".into()).unwrap_or(false) {
        let mut xyzw = [0.0; 4];
        for (slot, key) in xyzw.iter_mut().zip(["x", "y", "z", "w"]) {
            let element = get(name, value, &key.into())?;
            *slot = element.as_f64().ok_or_else(|| {
                let problem =
                    format!("must have numbers x, y, z, w: {key} is {}", describe(&element));
                KliError::invalid(name, problem)
            })?;
        }
        return unit(name, Order::Xyzw.read(xyzw)).map_err(|e| Order::Xyzw.error(e));
    }
    let numbers = numbers(name, value, order.shape())?;
    unit(name, order.read(numbers)).map_err(|e| order.error(e))
}

/// Reads a 3-vector `[x, y, z]`.
pub fn vector3(name: &str, value: &JsValue) -> Result<DVec3, KliError> {
    Ok(DVec3::from_array(numbers(name, value, "[x, y, z]")?))
}

/// A list of quaternions in `order`: 4n numbers (a typed array, such as a three.js track's or a
/// glTF accessor's `Float32Array`, or a flat array of numbers), or an array of n quaternions
/// (each as [`quaternion`] reads it, `{ x, y, z, w }` objects too). At most `max` numbers; `each`
/// names one in messages ("key", "rotation"). Not normalised: the core checks each.
pub fn quaternion_list(
    name: &str,
    each: &str,
    value: &JsValue,
    order: Order,
    max: usize,
) -> Result<Vec<DQuat>, KliError> {
    let flat = quaternion_numbers(name, each, value, order, max)?;
    Ok(flat.chunks_exact(4).map(|q| order.read([q[0], q[1], q[2], q[3]])).collect())
}

/// [`quaternion_list`]'s numbers, 4 a quaternion in `order`, not yet read as quaternions: a
/// typed array's are its own, copied once (for a million quaternions a second copy costs more
/// than the mean).
pub fn quaternion_numbers(
    name: &str,
    each: &str,
    value: &JsValue,
    order: Order,
    max: usize,
) -> Result<Vec<f64>, KliError> {
    let array = is_array(value).unwrap_or(false);
    // A flat array of numbers is a three.js track's `values` as an Array.
    let flat = is_view(value) || (array && get(name, value, &0.into())?.as_f64().is_some());
    if flat {
        let flat = crate::typed::numbers(name, value, max)?;
        if flat.len() % 4 != 0 {
            let problem = format!("must hold 4 numbers per {each} (got {})", flat.len());
            return Err(KliError::invalid(name, problem));
        }
        return Ok(flat);
    }
    if !array {
        let problem =
            format!("must be a typed array or an array of quaternions (got {})", describe(value));
        return Err(KliError::invalid(name, problem));
    }
    let length = get(name, value, &"length".into())?.as_f64().unwrap_or(0.0) as usize;
    if length > max / 4 {
        let problem = format!("may hold at most {} {each}s (got {length})", max / 4);
        return Err(KliError::invalid(name, problem));
    }
    let one = |i: usize| {
        let element = format!("{name}[{i}]");
        let q = quaternion(&element, &get(&element, value, &(i as u32).into())?, order)?;
        // `quaternion` normalises; a list is checked (and normalised) by the core, which names
        // the element the same way.
        Ok(order.write(q))
    };
    let mut flat = Vec::with_capacity(4 * length);
    for i in 0..length {
        flat.extend(one(i)?);
    }
    Ok(flat)
}
