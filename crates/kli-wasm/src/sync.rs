//! The `kli/sync` entry: synchronising rotations on a graph ([`kli::sync`]): `synchronizeRotations`,
//! `readG2o` and the steppable `SyncFlow` (MATH.md, "Synchronising rotations on a graph").

use glam::DQuat;
use js_sys::{Float64Array, Uint8Array, Uint32Array};
use kli::sync::{Graph, Method, OtherLines, SyncFlow, SyncOptions, read_g2o, synchronize};
use kli::{KliError, Requirement, require};
use wasm_bindgen::prelude::*;

use crate::error::JsResult;
use crate::options::Fields;
use crate::read::{Order, number_argument, quaternion_list, whole_steps};
use crate::typed::numbers;
use crate::value::{describe, get, is_array, is_view};

/// The most edges a graph may have (2²⁴: 16.7 million, 512 MB of relative rotations).
pub(crate) const MAX_EDGES: usize = 1 << 24;
/// Node ids and counts are below 2³², the range of the `Uint32Array` `readG2o` returns.
pub(crate) const MAX_ID: f64 = 4_294_967_295.0;

#[wasm_bindgen(typescript_custom_section)]
const TYPES: &'static str = r#"
/** Many quaternions: 4n numbers (any typed array, or a flat array), or an array of n
 *  quaternions (arrays or `{ x, y, z, w }` objects). */
export type QuaternionsLike = ArrayLike<number> | ArrayLike<QuaternionLike>;

/** The measurements: the edges `(i, j)` of a connected graph on nodes `0 … count − 1`, and on
 *  each the relative rotation `R_ij = R_iᵀ R_j` (`q_ij ≈ q̄_i q_j`: GTSAM's `BetweenFactor<Rot3>`,
 *  g2o's `EDGE_SE3:QUAT`), any sign. A `PoseGraph` from `readG2o` is one as it is. */
export interface SyncInput {
  /** `[[i, j], …]`, or 2m numbers flat (an Array, `Uint32Array` or `Int32Array`): whole numbers
   *  from 0, no self-loops. Parallel edges add up. */
  edges: ArrayLike<number> | ArrayLike<ArrayLike<number>>;
  /** One quaternion an edge, in the options' `order`. */
  relative: QuaternionsLike;
  /** One weight an edge, each finite and > 0. Default: all 1. */
  weights?: ArrayLike<number>;
  /** The number of nodes. Default: one more than the largest id. Every node must be joined. */
  count?: number;
  /** Each node's rotation, an estimate: where `SyncFlow` starts (unless its `start` is given).
   *  `synchronizeRotations` does not need one (its answer is the certified optimum from any
   *  start) and does not read it. */
  initial?: QuaternionsLike;
  /** A `PoseGraph`'s other keys are accepted and not read. */
  dimension?: 2 | 3;
  ids?: ArrayLike<number>;
  translations?: ArrayLike<number>;
  translationWeights?: ArrayLike<number>;
  information?: ArrayLike<number>;
  positions?: ArrayLike<number>;
  skipped?: Record<string, number>;
}

/** How to synchronise: the certified global minimum of the chordal cost (the default), the
 *  robust solution for graphs with wrong edges, or the spectral relaxation alone. */
export type SyncMethod = "chordal" | "robust" | "spectral";

/** Options of `synchronizeRotations`; every key is optional and unknown keys are rejected. */
export interface SyncOptions {
  /** Default "chordal". */
  method?: SyncMethod;
  /** The node held at the identity. Default 0. */
  anchor?: number;
  /** For "robust": the residual scale σ in radians (> 0): an edge beyond 3σ is an outlier.
   *  Default: measured from the residuals. */
  scale?: number;
  /** How quaternion arrays are laid out, in and out. Default "wxyz". */
  order?: QuaternionOrder;
}

/** Whether a solution is provably the global minimum: `S = L − Λ ⪰ 0` (MATH.md). */
export interface SyncCertificate {
  /** The smallest eigenvalue of S (0 to rounding at a certified optimum). */
  lambdaMin: number;
  /** The smallest eigenvalue of S apart from the gauge's three zeros: > 0, the optimum is also
   *  unique; < 0, a local optimum, not the global one. */
  gap: number;
  /** Certified means λ_min(S) ≥ −tolerance (1e-9 × the largest weighted degree). */
  tolerance: number;
  certified: boolean;
}

/** What `synchronizeRotations` found, whatever the method. */
export interface SynchronizedBase {
  /** 4n numbers: each node's rotation in the call's order, the anchor's the identity, w ≥ 0. */
  rotations: Float64Array;
  /** The chordal cost Σ w_ij ‖R_i R_ij − R_j‖²_F with the caller's weights. */
  cost: number;
  /** Each edge's residual angle, radians. */
  residuals: Float64Array;
  /** Newton steps taken (all rounds, for "robust"), or Lanczos steps for "spectral". */
  iterations: number;
}

/** The chordal optimum (`method: "chordal"`, the default) and its certificate. */
export interface ChordalSynchronized extends SynchronizedBase {
  certificate: SyncCertificate;
}

/** The robust solution (`method: "robust"`). */
export interface RobustSynchronized extends SynchronizedBase {
  /** Each edge's final weight: the caller's times the robust factor, ≤ it (1 or 0 for an edge
   *  kept or set aside, when a few edges far off were set aside and the rest solved by least
   *  squares). */
  weights: Float64Array;
  /** 1 for each edge treated as wrong, else 0: beyond 3σ for a given `scale`; by default beyond
   *  10 typical residuals of the least-squares fit, or, with many edges wrong, 6 median residuals
   *  of the L1 rounds. */
  outliers: Uint8Array;
  /** The residual scale σ found or given, radians. */
  scale: number;
}

/** What `synchronizeRotations` found: its type follows `options.method`. */
export type Synchronized = ChordalSynchronized | RobustSynchronized | SynchronizedBase;

/** The chordal method's options (`method` absent or "chordal"). */
export type ChordalSyncOptions = SyncOptions & { method?: "chordal" };

export function synchronizeRotations(
  input: SyncInput,
  options?: ChordalSyncOptions | null,
): ChordalSynchronized;
export function synchronizeRotations(
  input: SyncInput,
  options: SyncOptions & { method: "robust" },
): RobustSynchronized;
export function synchronizeRotations(
  input: SyncInput,
  options: SyncOptions & { method: "spectral" },
): SynchronizedBase;
export function synchronizeRotations(input: SyncInput, options?: SyncOptions | null): Synchronized;

/** A pose graph read from a file (`readG2o`): the poses numbered from 0 in the order of their
 *  ids, each edge's measured rotation and translation, and its weights from its information
 *  matrix as SE-Sync reads them. It is a `SyncInput` as it is, weighted by κ. */
export interface PoseGraph {
  /** 2 for planar poses (`EDGE_SE2`, `EDGE2`: rotations about z), 3 for poses in space. */
  dimension: 2 | 3;
  /** The number of poses. */
  count: number;
  /** Each pose's id in the file, ascending: pose k is `ids[k]` (ids need not be consecutive:
   *  landmarks' ids are left out). Exact up to 2^53. */
  ids: Float64Array;
  /** 2m pose numbers (from 0, as `ids` orders them), the edges in the file's order. */
  edges: Uint32Array;
  /** 4m numbers: each edge's relative rotation in the call's order. */
  relative: Float64Array;
  /** Each edge's rotation weight κ (3D: 3 / (2 tr Σ_R), Σ_R in g2o's half-angle units, an
   *  `EDGE3` line's angle information times 4; 2D: I_θθ; the identity's without information:
   *  ½ on `EDGE_SE3:QUAT`, 2 on `EDGE3`, 1 in 2D), which `synchronizeRotations` uses. */
  weights: Float64Array;
  /** 3m numbers: each edge's measured translation in its first pose's frame (z = 0 in 2D). */
  translations: Float64Array;
  /** Each edge's translation weight τ (3 / tr Σ_t in 3D, 2 / tr Σ_t in 2D; 1 without
   *  information). */
  translationWeights: Float64Array;
  /** Each edge's information matrix as the file gave it, in g2o's order and units (what
   *  `writeG2o` writes back): its upper triangle row by row, 6 numbers an edge in 2D (x, y, θ),
   *  21 in 3D (the translation, then the error quaternion's vector part). An `EDGE2` line's TORO
   *  order is rearranged, an `EDGE3` line's rotation rows are scaled from angles to half-angles
   *  (×4, the coupling ×2), and a line without one has the identity's in its own units. */
  information: Float64Array;
  /** 4·count numbers: each pose's rotation from its vertex line, when every pose has one. */
  initial?: Float64Array;
  /** 3·count numbers: each pose's position from its vertex line, when every pose has one. */
  positions?: Float64Array;
  /** The lines of other kinds (landmarks, priors, parameters), skipped: how many of each,
   *  by their first word, e.g. `{ VERTEX_XY: 120, EDGE_SE2_XY: 400 }`. */
  skipped: Record<string, number>;
}

/** Options of `readG2o`. */
export interface ReadG2oOptions {
  /** How `relative` and `initial` are laid out. Default "wxyz". */
  order?: QuaternionOrder;
  /** Refuse a line of a kind other than the pose lines (with its `line`), instead of skipping
   *  and counting it. Default false. */
  strict?: boolean;
}

/** Options of `new SyncFlow(input, options)`; every key is optional and unknown keys are
 *  rejected. */
export interface SyncFlowOptions {
  /** Where the flow starts: 4·count numbers or count quaternions. Default: the input's
   *  `initial` when it has one (a pose graph's vertices), else uniform on S³. */
  start?: QuaternionsLike;
  /** For the random start: a whole number from 0 to 2^53 − 1. Default 1. */
  seed?: number;
  /** How `start`, `relative` and `rotations` are laid out. Default "wxyz". */
  order?: QuaternionOrder;
}
"#;

#[wasm_bindgen]
extern "C" {
    #[wasm_bindgen(typescript_type = "SyncInput")]
    pub type SyncInputObject;

    #[wasm_bindgen(typescript_type = "SyncOptions")]
    pub type SyncOptionsObject;

    #[wasm_bindgen(typescript_type = "ReadG2oOptions")]
    pub type ReadG2oOptionsObject;

    #[wasm_bindgen(typescript_type = "SyncFlowOptions")]
    pub type SyncFlowOptionsObject;
}

/// Edge `k`'s ids from the numbers read, each a whole number from 0 to 2³² − 1.
fn edge_ids(k: usize, pair: &[f64]) -> Result<[usize; 2], KliError> {
    let name = format!("edges[{k}]");
    let ok = |x: f64| (0.0..=MAX_ID).contains(&x) && x.fract() == 0.0;
    match pair {
        [i, j] if ok(*i) && ok(*j) => Ok([*i as usize, *j as usize]),
        [i, j] => {
            let bad = if ok(*i) { *j } else { *i };
            let problem = format!(
                "must hold two node ids, whole numbers from 0 (got {})",
                crate::error::number(bad)
            );
            Err(KliError::invalid(name, problem))
        }
        _ => Err(KliError::invalid(name, format!("must hold two node ids (got {})", pair.len()))),
    }
}

/// `edges`: nested `[[i, j], …]`, or 2m numbers flat.
pub(crate) fn read_edges(value: &JsValue) -> Result<Vec<[usize; 2]>, KliError> {
    let array = is_array(value).unwrap_or(false);
    let flat = is_view(value) || (array && get("edges", value, &0.into())?.as_f64().is_some());
    if flat {
        let flat = numbers("edges", value, 2 * MAX_EDGES)?;
        if flat.len() % 2 != 0 {
            let problem = format!("must hold 2 numbers per edge (got {})", flat.len());
            return Err(KliError::invalid("edges", problem));
        }
        return flat.chunks_exact(2).enumerate().map(|(k, pair)| edge_ids(k, pair)).collect();
    }
    if !array {
        let problem =
            format!("must be an array of [i, j] pairs or of 2m numbers (got {})", describe(value));
        return Err(KliError::invalid("edges", problem));
    }
    let length = get("edges", value, &"length".into())?.as_f64().unwrap_or(0.0) as usize;
    if length > MAX_EDGES {
        let problem = format!("may hold at most {MAX_EDGES} edges (got {length})");
        return Err(KliError::invalid("edges", problem));
    }
    (0..length)
        .map(|k| {
            let name = format!("edges[{k}]");
            let pair = get(&name, value, &(k as u32).into())?;
            edge_ids(k, &numbers(&name, &pair, 2)?)
        })
        .collect()
}

/// The keys of a [`SyncInput`](read_graph) that are read.
const READ: [&str; 5] = ["edges", "relative", "weights", "count", "initial"];
/// A `PoseGraph`'s other keys: accepted, so that `readG2o`'s result is an input as it is, and
/// not read.
const POSE_GRAPH: [&str; 7] = [
    "dimension",
    "ids",
    "translations",
    "translation_weights",
    "information",
    "positions",
    "skipped",
];

/// Reads `{ edges, relative, weights, count }` into a checked [`Graph`], and `initial` when
/// present (unread: `None`) and `with_initial`.
fn read_graph(
    input: &JsValue,
    order: Order,
    with_initial: bool,
) -> Result<(Graph, Option<Vec<DQuat>>), KliError> {
    let example = "{ edges: [[0, 1], [1, 2]], relative: [q01, q12] }";
    let mut keys = READ.to_vec();
    keys.extend(POSE_GRAPH);
    let Some(fields) = Fields::named("input", Some(input.clone()), &keys, example)? else {
        let problem = format!("must be an object like {example} (got {})", describe(input));
        return Err(KliError::invalid("input", problem));
    };
    let required =
        |key: &str| fields.value(key)?.ok_or_else(|| KliError::invalid(key, "is required"));
    let edges = read_edges(&required("edges")?)?;
    let relative =
        quaternion_list("relative", "edge", &required("relative")?, order, 4 * MAX_EDGES)?;
    let weights = match fields.value("weights")? {
        Some(value) => Some(numbers("weights", &value, MAX_EDGES)?),
        None => None,
    };
    let count = fields.whole("count", 1.0, MAX_ID)?.map(|c| c as usize);
    let graph =
        Graph::new(count, &edges, &relative, weights.as_deref()).map_err(|e| order.error(e))?;
    let initial = match fields.value("initial")? {
        Some(value) if with_initial => {
            let max = 4 * graph.count();
            Some(quaternion_list("initial", "node", &value, order, max)?)
        }
        _ => None,
    };
    Ok((graph, initial))
}

pub(crate) fn set(object: &js_sys::Object, key: &str, value: JsValue) {
    let _ = js_sys::Reflect::set(object, &key.into(), &value);
}

/// Synchronises the rotations of a graph from its relative measurements: the certified chordal
/// optimum by default (`method: "robust"` for graphs with wrong edges).
#[wasm_bindgen(js_name = synchronizeRotations, unchecked_return_type = "Synchronized")]
pub fn synchronize_rotations(
    #[wasm_bindgen(unchecked_param_type = "SyncInput")] input: &JsValue,
    options: Option<SyncOptionsObject>,
) -> JsResult<JsValue> {
    let keys = ["method", "anchor", "scale", "order"];
    let fields = Fields::new(options.map(JsValue::from), &keys, "{ method: \"robust\" }")?;
    let mut order = Order::Wxyz;
    let mut options = SyncOptions::default();
    if let Some(fields) = &fields {
        order = Order::parse(fields.name("order")?)?;
        if let Some(name) = fields.name("method")? {
            options.method = name.parse::<Method>()?;
        }
        if let Some(anchor) = fields.whole("anchor", 0.0, MAX_ID)? {
            options.anchor = anchor as usize;
        }
        if let Some(scale) = fields.number("scale")? {
            options.scale = Some(require("scale", scale, Requirement::Positive)?);
        }
    }
    let (graph, _) = read_graph(input, order, false)?;
    let result = synchronize(&graph, &options)?;
    let out = js_sys::Object::new();
    set(&out, "rotations", order.flat(&result.rotations).into());
    set(&out, "cost", result.cost.into());
    set(&out, "residuals", Float64Array::from(&result.residuals[..]).into());
    set(&out, "iterations", (result.iterations as f64).into());
    if let Some(c) = result.certificate {
        let certificate = js_sys::Object::new();
        set(&certificate, "lambdaMin", c.lambda_min.into());
        set(&certificate, "gap", c.gap.into());
        set(&certificate, "tolerance", c.tolerance.into());
        set(&certificate, "certified", c.certified.into());
        set(&out, "certificate", certificate.into());
    }
    if let Some(weights) = &result.weights {
        set(&out, "weights", Float64Array::from(&weights[..]).into());
    }
    if let Some(outliers) = &result.outliers {
        let flags: Vec<u8> = outliers.iter().map(|&o| o as u8).collect();
        set(&out, "outliers", Uint8Array::from(&flags[..]).into());
    }
    if let Some(scale) = result.scale {
        set(&out, "scale", scale.into());
    }
    Ok(out.into())
}

/// Reads a pose-graph file, 2D or 3D: g2o (`EDGE_SE3:QUAT`, `EDGE_SE2` and their vertices) or
/// TORO/GTSAM (`EDGE3`, `EDGE2`, `VERTEX3`, `VERTEX2`), each edge weighted by its information
/// matrix; lines of other kinds skipped and counted (refused with `strict: true`). A bad line is
/// an Error with its number as `line`.
#[wasm_bindgen(js_name = readG2o, unchecked_return_type = "PoseGraph")]
pub fn read_g2o_text(
    #[wasm_bindgen(unchecked_param_type = "string")] text: &JsValue,
    options: Option<ReadG2oOptionsObject>,
) -> JsResult<JsValue> {
    let fields =
        Fields::new(options.map(JsValue::from), &["order", "strict"], "{ order: \"xyzw\" }")?;
    let (mut order, mut others) = (Order::Wxyz, OtherLines::Skip);
    if let Some(fields) = &fields {
        order = Order::parse(fields.name("order")?)?;
        if fields.boolean("strict")? == Some(true) {
            others = OtherLines::Refuse;
        }
    }
    let Some(text) = text.as_string() else {
        let problem = format!("must be a string (got {})", describe(text));
        return Err(KliError::invalid("text", problem).into());
    };
    let graph = read_g2o(&text, others)?;
    let floats = |x: &[f64]| JsValue::from(Float64Array::from(x));
    let vectors = |v: &[glam::DVec3]| {
        let flat: Vec<f64> = v.iter().flat_map(|t| t.to_array()).collect();
        floats(&flat)
    };
    let out = js_sys::Object::new();
    set(&out, "dimension", (graph.dimension as f64).into());
    set(&out, "count", (graph.count as f64).into());
    let ids: Vec<f64> = graph.ids.iter().map(|&id| id as f64).collect();
    set(&out, "ids", floats(&ids));
    let edges: Vec<u32> = graph.edges.iter().flatten().map(|&i| i as u32).collect();
    set(&out, "edges", Uint32Array::from(&edges[..]).into());
    set(&out, "relative", order.flat(&graph.relative).into());
    set(&out, "weights", floats(&graph.rotation_weights));
    set(&out, "translations", vectors(&graph.translations));
    set(&out, "translationWeights", floats(&graph.translation_weights));
    set(&out, "information", floats(&graph.information));
    if let Some(initial) = &graph.initial {
        set(&out, "initial", order.flat(initial).into());
    }
    if let Some(positions) = &graph.positions {
        set(&out, "positions", vectors(positions));
    }
    let skipped = js_sys::Object::new();
    for (kind, n) in &graph.skipped {
        set(&skipped, kind, (*n as f64).into());
    }
    set(&out, "skipped", skipped.into());
    Ok(out.into())
}

/// The paper's model on a graph, steppable: every node pulled towards its neighbours'
/// predictions, `q_i' = 2 Σ_j w_ij c_ij (x_ij − c_ij q_i)` (MATH.md), from a start.
#[wasm_bindgen(js_name = SyncFlow)]
pub struct JsSyncFlow {
    flow: SyncFlow,
    order: Order,
}

#[wasm_bindgen(js_class = SyncFlow)]
impl JsSyncFlow {
    /// The flow on the graph `input` (as `synchronizeRotations` takes it) from `options.start`,
    /// else from `input.initial` (a pose graph's vertices), else from a random start drawn from
    /// `options.seed`.
    #[wasm_bindgen(constructor)]
    pub fn new(
        #[wasm_bindgen(unchecked_param_type = "SyncInput")] input: &JsValue,
        options: Option<SyncFlowOptionsObject>,
    ) -> JsResult<JsSyncFlow> {
        let keys = ["start", "seed", "order"];
        let fields = Fields::new(options.map(JsValue::from), &keys, "{ seed: 7 }")?;
        let (mut order, mut seed, mut start) = (Order::Wxyz, 1, None);
        if let Some(fields) = &fields {
            order = Order::parse(fields.name("order")?)?;
            if let Some(value) = fields.seed("seed")? {
                seed = value;
            }
            start = fields.value("start")?;
        }
        let (graph, initial) = read_graph(input, order, start.is_none())?;
        let start = match start {
            Some(value) => {
                let max = 4 * graph.count();
                Some(("start", quaternion_list("start", "node", &value, order, max)?))
            }
            None => initial.map(|q| ("initial", q)),
        };
        let flow = match start {
            Some((name, start)) => {
                SyncFlow::starting(graph, &start, name).map_err(|e| order.error(e))?
            }
            None => SyncFlow::random(graph, seed),
        };
        Ok(JsSyncFlow { flow, order })
    }

    /// `steps` (default 1, a whole number up to 1e6) Euler steps of `dt` (finite, > 0), each
    /// projected back to S³.
    pub fn step(
        &mut self,
        #[wasm_bindgen(unchecked_param_type = "number")] dt: &JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "number")] steps: &JsValue,
    ) -> JsResult<()> {
        let dt = number_argument("dt", dt)?;
        let steps = whole_steps(steps)?;
        self.flow.step(dt, steps).map_err(Into::into)
    }

    /// The time flowed.
    #[wasm_bindgen(getter)]
    pub fn time(&self) -> f64 {
        self.flow.time()
    }

    /// The number of nodes.
    #[wasm_bindgen(getter)]
    pub fn count(&self) -> usize {
        self.flow.graph().count()
    }

    /// The chordal cost now.
    #[wasm_bindgen(getter)]
    pub fn cost(&self) -> f64 {
        self.flow.cost()
    }

    /// A copy of the 4n numbers of every node's rotation, in the flow's order (not anchored: the
    /// flow leaves the common rotation where its start put it).
    #[wasm_bindgen(getter)]
    pub fn rotations(&self) -> Float64Array {
        self.order.flat(self.flow.rotations())
    }

    /// Each edge's residual angle now, radians.
    pub fn residuals(&self) -> Float64Array {
        Float64Array::from(&self.flow.residuals()[..])
    }

    /// The 3n coordinates of each node's Hopf image on S².
    #[wasm_bindgen(js_name = hopfPoints)]
    pub fn hopf_points(&self) -> Float64Array {
        let flat: Vec<f64> =
            self.flow.rotations().iter().flat_map(|&q| kli::hopf(q).to_array()).collect();
        Float64Array::from(&flat[..])
    }
}
