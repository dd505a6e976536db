//! The `LoheSwarm` class: the many-oscillator Kuramoto–Lohe model on S³ (`kli::swarm`).

use glam::DQuat;
use js_sys::Float64Array;
use kli::swarm::{Graph, MAX_COUNT, Swarm, SwarmOptions};
use kli::{ErrorKind, KliError};
use wasm_bindgen::prelude::*;

use crate::error::JsResult;
use crate::options::Fields;
use crate::read::{Order, number_argument, whole_steps};
use crate::typed::numbers;

#[wasm_bindgen(typescript_custom_section)]
const TYPES: &'static str = r#"
/** Who is coupled to whom in a LoheSwarm: everyone, ring neighbours, or everyone with the first
 *  `leaders` oscillators pinned. */
export type Graph = "all" | "ring" | "leader";

/** Options of `new LoheSwarm(options)`; every key is optional and unknown keys are rejected. */
export interface SwarmOptions {
  /** N, a whole number from 1 to 1e6. Default 200. */
  count?: number;
  /** K: > 0 synchronises, < 0 balances. Finite. Default 1. */
  coupling?: number;
  /** Default "all". */
  graph?: Graph;
  /** For graph "leader": how many of the first oscillators are pinned, 1 to count. Default 1. */
  leaders?: number;
  /** Standard deviation of each component of the natural frequencies w_i. ≥ 0. Default 0. */
  frequencySpread?: number;
  /** Absent: a start uniform on S³. A number σ ≥ 0: near the identity, σ radians of spread. */
  startSpread?: number;
  /** A whole number from 0 to 2^53 − 1; the same seed gives the same swarm. Default 1. */
  seed?: number;
  /** How `quaternions` and `setQuaternions` lay each quaternion out. Default "wxyz". */
  order?: QuaternionOrder;
}
"#;

#[wasm_bindgen]
extern "C" {
    /// `{ count, coupling, graph, leaders, frequencySpread, startSpread, seed }`, each optional.
    #[wasm_bindgen(typescript_type = "SwarmOptions")]
    pub type SwarmOptionsObject;
}

/// The fields of [`SwarmOptions`] and `order`, by their Rust names.
const KEYS: [&str; 8] =
    ["count", "coupling", "graph", "leaders", "frequency_spread", "start_spread", "seed", "order"];

/// Reads the options object of `new LoheSwarm(options)` into checked [`SwarmOptions`] and the
/// caller's quaternion [`Order`].
pub fn read_swarm_options(value: &JsValue) -> Result<(SwarmOptions, Order), KliError> {
    let mut options = SwarmOptions::default();
    let example = "{ count: 500, coupling: 1 }";
    let Some(fields) = Fields::new(Some(value.clone()), &KEYS, example)? else {
        return Ok((options, Order::Wxyz));
    };
    let order = Order::parse(fields.name("order")?)?;
    if let Some(v) = fields.whole("count", 1.0, MAX_COUNT as f64)? {
        options.count = v as usize;
    }
    if let Some(v) = fields.number("coupling")? {
        options.coupling = v;
    }
    if let Some(name) = fields.name("graph")? {
        options.graph = name.parse::<Graph>()?;
    }
    if let Some(v) = fields.whole("leaders", 1.0, MAX_COUNT as f64)? {
        options.leaders = v as usize;
    }
    if let Some(v) = fields.number("frequency_spread")? {
        options.frequency_spread = v;
    }
    if let Some(v) = fields.number("start_spread")? {
        options.start_spread = Some(v);
    }
    if let Some(v) = fields.seed("seed")? {
        options.seed = v;
    }
    options.validate()?;
    Ok((options, order))
}

/// N oscillators on S³ under `q_i' = w_i q_i + (K/N) Σ_j a_ij (q_j − (q_i·q_j) q_i)`.
#[wasm_bindgen(js_name = LoheSwarm)]
pub struct JsLoheSwarm {
    swarm: Swarm,
    order: Order,
}

#[wasm_bindgen(js_class = LoheSwarm)]
impl JsLoheSwarm {
    /// A swarm from its options (all optional; the same seed gives the same swarm).
    #[wasm_bindgen(constructor)]
    pub fn new(
        #[wasm_bindgen(unchecked_optional_param_type = "SwarmOptions | null")] options: &JsValue,
    ) -> JsResult<JsLoheSwarm> {
        let (options, order) = read_swarm_options(options)?;
        Ok(Self { swarm: Swarm::new(&options)?, order })
    }

    /// `steps` (default 1, a whole number up to 1e6) geodesic RK4 steps of `dt` (> 0, at most
    /// 100).
    pub fn step(
        &mut self,
        #[wasm_bindgen(unchecked_param_type = "number")] dt: &JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "number")] steps: &JsValue,
    ) -> JsResult<()> {
        let dt = number_argument("dt", dt)?;
        let steps = whole_steps(steps)?;
        self.swarm.step(dt, steps).map_err(Into::into)
    }

    /// The time run so far.
    #[wasm_bindgen(getter)]
    pub fn time(&self) -> f64 {
        self.swarm.time()
    }

    /// N.
    #[wasm_bindgen(getter)]
    pub fn count(&self) -> usize {
        self.swarm.len()
    }

    /// A copy of the 4N numbers `q_i`, in the swarm's `order`.
    #[wasm_bindgen(getter)]
    pub fn quaternions(&self) -> Float64Array {
        self.order.flat(self.swarm.quaternions())
    }

    /// Replaces every `q_i` with 4N numbers, a Float64Array or an array (in the swarm's `order`;
    /// each is normalised, none may be all zero). The time is kept.
    #[wasm_bindgen(js_name = setQuaternions)]
    pub fn set_quaternions(
        &mut self,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | ArrayLike<number>")] values: &JsValue,
    ) -> JsResult<()> {
        let values = numbers("quaternions", values, 4 * self.swarm.len())?;
        if values.len() != 4 * self.swarm.len() {
            let (expected, got) = (4 * self.swarm.len(), values.len());
            let kind = ErrorKind::WrongLength { expected, got, per: "oscillator".into() };
            return Err(KliError::new("quaternions", kind).into());
        }
        let quaternions: Vec<DQuat> =
            values.chunks_exact(4).map(|q| self.order.read([q[0], q[1], q[2], q[3]])).collect();
        self.swarm.set_quaternions(&quaternions).map_err(|e| self.order.error(e).into())
    }

    /// `R = |m|`, the length of the mean quaternion, in [0, 1].
    #[wasm_bindgen(getter, js_name = orderParameter)]
    pub fn order_parameter(&self) -> f64 {
        self.swarm.order_parameter()
    }

    /// `λ_max(Q)`, `Q = (1/N) Σ q qᵀ`: the sign-blind order, in [1/4, 1].
    #[wasm_bindgen(getter, js_name = rotationOrder)]
    pub fn rotation_order(&self) -> f64 {
        self.swarm.rotation_order()
    }

    /// `(K N/2)|m|²`, which the flow of identical oscillators all-to-all never lowers.
    #[wasm_bindgen(getter)]
    pub fn potential(&self) -> f64 {
        self.swarm.potential()
    }

    /// The 3N coordinates of each oscillator's Hopf image on S².
    #[wasm_bindgen(js_name = hopfPoints)]
    pub fn hopf_points(&self) -> Float64Array {
        let flat: Vec<f64> = self.swarm.hopf_points().iter().flat_map(|p| p.to_array()).collect();
        Float64Array::from(&flat[..])
    }
}
