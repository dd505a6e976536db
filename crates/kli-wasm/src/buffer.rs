//! `Float64Buffer`: an f64 array in the module's own memory, which the batch calls read and write
//! in place.

use js_sys::Float64Array;
use kli::KliError;
use wasm_bindgen::prelude::*;

use crate::error::{JsResult, Thrown, number};
use crate::read::number_argument;

/// An f64 array in the module's own memory: pass its `view` to the batch calls and they read and
/// write it in place, with no copy. A view is valid until the module's memory grows (any call
/// may grow it), so read `view` again before each use rather than keeping it.
#[wasm_bindgen]
pub struct Float64Buffer {
    data: Vec<f64>,
}

/// The largest buffer: 2^27 numbers, 1 GiB.
const MAX_BUFFER: usize = 1 << 27;

#[wasm_bindgen]
impl Float64Buffer {
    /// `length` zeros.
    #[wasm_bindgen(constructor)]
    pub fn new(
        #[wasm_bindgen(unchecked_param_type = "number")] length: &JsValue,
    ) -> JsResult<Float64Buffer> {
        let length = number_argument("length", length)?;
        if !(length.is_finite()
            && length >= 0.0
            && length.fract() == 0.0
            && length <= MAX_BUFFER as f64)
        {
            let problem =
                format!("must be a whole number from 0 to {MAX_BUFFER} (got {})", number(length));
            return Err(KliError::invalid("length", problem).into());
        }
        let mut data = Vec::new();
        data.try_reserve_exact(length as usize).map_err(|_| {
            let problem = format!("{} numbers do not fit in the module's memory", number(length));
            Thrown::from(KliError::invalid("length", problem))
        })?;
        data.resize(length as usize, 0.0);
        Ok(Float64Buffer { data })
    }

    /// A Float64Array over the buffer, in the module's memory.
    #[wasm_bindgen(getter)]
    pub fn view(&self) -> Float64Array {
        // SAFETY: the view is handed to JavaScript, which may write through it; Rust never holds
        // a reference to `data` across a call, and the view dies with a memory growth.
        unsafe { Float64Array::view(&self.data) }
    }

    /// The number of f64 values.
    #[wasm_bindgen(getter)]
    pub fn length(&self) -> usize {
        self.data.len()
    }
}
