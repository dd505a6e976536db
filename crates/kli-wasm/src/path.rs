//! The `KliPath` class: the samples of Algorithm 1 and the exact solution beside them.

use js_sys::Float64Array;
use kli::quaternion::to_wxyz;
use wasm_bindgen::prelude::*;

use crate::error::{JsResult, throw};

/// The path of Algorithm 1: samples at `0, δ, …, T` and the exact solution beside them.
#[wasm_bindgen(js_name = KliPath)]
pub struct JsKliPath {
    path: kli::KliPath,
}

impl From<kli::KliPath> for JsKliPath {
    fn from(path: kli::KliPath) -> Self {
        Self { path }
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

    /// 4·(n + 1) numbers: q at each sample time, scalar first, as integrated.
    #[wasm_bindgen(getter)]
    pub fn quaternions(&self) -> Float64Array {
        let flat: Vec<f64> = self.path.quaternions().iter().flat_map(|&q| to_wxyz(q)).collect();
        Float64Array::from(&flat[..])
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
        Float64Array::from(&to_wxyz(self.path.target())[..])
    }

    /// The integrator the path was computed with.
    #[wasm_bindgen(getter, unchecked_return_type = "Integrator")]
    pub fn integrator(&self) -> String {
        self.path.options().integrator.name().into()
    }

    /// The exact q(t) of the closed form, for any finite t ≥ 0 (the integrated samples are
    /// `quaternions`).
    #[wasm_bindgen(js_name = exactAt)]
    pub fn exact_at(&self, t: f64) -> JsResult<Float64Array> {
        let q = self.path.exact_at(t).map_err(throw)?;
        Ok(Float64Array::from(&to_wxyz(q)[..]))
    }
}
