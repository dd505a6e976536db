//! The `KliPath` class: the samples of Algorithm 1 and the exact solution beside them.

use js_sys::Float64Array;
use wasm_bindgen::prelude::*;

use crate::error::JsResult;
use crate::read::{Order, number_argument};

/// The path of Algorithm 1: samples at `0, δ, …, T` and the exact solution beside them.
/// Quaternions come out in the `order` the path was asked for.
#[wasm_bindgen(js_name = KliPath)]
pub struct JsKliPath {
    path: kli::KliPath,
    order: Order,
}

impl JsKliPath {
    pub fn new(path: kli::KliPath, order: Order) -> Self {
        Self { path, order }
    }
}

#[wasm_bindgen(js_class = KliPath)]
impl JsKliPath {
    /// T: the first time on the grid `nδ` at which ||target − q(T)|| < tolerance.
    #[wasm_bindgen(getter, js_name = finalTime)]
    pub fn final_time(&self) -> f64 {
        self.path.final_time()
    }

    /// n, the number of steps; the path holds n + 1 samples.
    #[wasm_bindgen(getter)]
    pub fn steps(&self) -> usize {
        self.path.steps()
    }

    /// The n + 1 sample times 0, δ, …, T.
    #[wasm_bindgen(getter)]
    pub fn times(&self) -> Float64Array {
        Float64Array::from(self.path.times())
    }

    /// 4·(n + 1) numbers: q at each sample time, as integrated.
    #[wasm_bindgen(getter)]
    pub fn quaternions(&self) -> Float64Array {
        self.order.flat(self.path.quaternions())
    }

    /// 3·(n + 1) numbers: the Hopf image of each sample on S² (the body x-axis).
    #[wasm_bindgen(getter, js_name = hopfCurve)]
    pub fn hopf_curve(&self) -> Float64Array {
        let flat: Vec<f64> = self.path.hopf_curve().iter().flat_map(|v| v.to_array()).collect();
        Float64Array::from(&flat[..])
    }

    /// The end actually used: r, or −r when shortestPath and p·r < 0.
    #[wasm_bindgen(getter)]
    pub fn target(&self) -> Float64Array {
        self.order.array(self.path.target())
    }

    /// The integrator the path was computed with.
    #[wasm_bindgen(getter, unchecked_return_type = "Integrator")]
    pub fn integrator(&self) -> String {
        self.path.options().integrator.name().into()
    }

    /// The exact q(t) of the closed form, for any finite t ≥ 0 (the integrated samples are
    /// `quaternions`).
    #[wasm_bindgen(js_name = exactAt)]
    pub fn exact_at(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] t: &JsValue,
    ) -> JsResult<Float64Array> {
        let t = number_argument("t", t)?;
        self.path.exact_at(t).map(|q| self.order.array(q)).map_err(Into::into)
    }
}
