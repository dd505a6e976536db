//! Pose graphs in the `kli/sync` entry: `synchronizePoses`, the certified global minimum of a pose
//! graph's cost ([`kli::sync::synchronize_poses`], SE-Sync; MATH.md, "Pose graphs"), and
//! `writeG2o`, a graph's edges and the poses found written back as a g2o file.
//!
//! A graph is read as `readG2o` returns it (every key it has is accepted) or from a plain object
//! with the same keys: `dimension`, `edges`, `relative`, `translations`, `weights` (κ),
//! `translationWeights` (τ), `count`, `ids`, `information` (what `writeG2o` writes).

use std::fmt::Write;

use glam::{DQuat, DVec3};
use js_sys::Float64Array;
use kli::quaternion::unit;
use kli::sync::{PoseGraph, PoseOptions, synchronize_poses};
use kli::{KliError, Requirement, require};
use wasm_bindgen::prelude::*;

use crate::error::JsResult;
use crate::options::{Fields, MAX_SEED};
use crate::read::{Order, quaternion_list};
use crate::sync::{MAX_EDGES, MAX_ID, read_edges, set};
use crate::typed::numbers;
use crate::value::{describe, get, is_array, is_view};

#[wasm_bindgen(typescript_custom_section)]
const TYPES: &'static str = r#"
/** Many 3-vectors: 3n numbers (any typed array, or a flat array), or an array of n `[x, y, z]`. */
export type Vectors3Like = ArrayLike<number> | ArrayLike<ArrayLike<number>>;

/** A pose graph as `synchronizePoses` and `writeG2o` take it: a `PoseGraph` from `readG2o` as it
 *  is, or a plain object with the same keys. Each edge `(i, j)` measures `T_i⁻¹ T_j`: the
 *  rotation `R_iᵀ R_j` (`q_ij ≈ q̄_i q_j`) and the translation `R_iᵀ (t_j − t_i)`. */
export interface PoseGraphInput {
  /** 2 for planar poses (rotations about z, translations with z = 0), 3 for poses in space. */
  dimension: 2 | 3;
  /** `[[i, j], …]`, or 2m numbers flat: poses numbered from 0, no self-loops, connected. */
  edges: ArrayLike<number> | ArrayLike<ArrayLike<number>>;
  /** One quaternion an edge, in the options' `order`, any sign. */
  relative: QuaternionsLike;
  /** One translation an edge, in its first pose's frame (z = 0 in 2D). */
  translations: Vectors3Like;
  /** Each edge's rotation weight κ, finite and > 0. Default: all 1. */
  weights?: ArrayLike<number>;
  /** Each edge's translation weight τ, finite and > 0. Default: all 1. */
  translationWeights?: ArrayLike<number>;
  /** The number of poses. Default: one more than the largest pose named by an edge. */
  count?: number;
  /** For `writeG2o`: each pose's id in the file, ascending whole numbers (up to 2^53 − 1).
   *  Default 0, 1, … `synchronizePoses` does not read it. */
  ids?: ArrayLike<number>;
  /** For `writeG2o`: each edge's information, its upper triangle row by row in g2o's order and
   *  units (6 numbers an edge in 2D, 21 in 3D; finite), as `readG2o` gives it. Default: the
   *  diagonal information of κ and τ. `synchronizePoses` checks it and does not read it. */
  information?: ArrayLike<number>;
  /** A `PoseGraph`'s other keys are accepted and not read. */
  initial?: QuaternionsLike;
  positions?: ArrayLike<number>;
  skipped?: Record<string, number>;
}

/** Options of `synchronizePoses`; every key is optional and unknown keys are rejected. */
export interface PoseOptions {
  /** The pose held at the identity and the origin. Default 0. */
  anchor?: number;
  /** The highest rank of the Riemannian staircase: from the dimension to 64. Default 10. */
  maxRank?: number;
  /** How `relative` and `rotations` are laid out. Default "wxyz". */
  order?: QuaternionOrder;
}

/** Whether the poses are provably the global minimum (SE-Sync's certificate, MATH.md). */
export interface PoseCertificate {
  /** The smallest eigenvalue of S = Q − Λ at the rotations returned (0 to rounding at a
   *  certified optimum), with the caller's weights. */
  lambdaMin: number;
  /** Certified means λ_min(S) ≥ −tolerance (1e-9 of Q's scale). */
  tolerance: number;
  certified: boolean;
  /** The rank of the Riemannian staircase's last level (the dimension when the first was
   *  certified). */
  rank: number;
  /** A proven lower bound on the global minimum of the cost (the relaxation's dual bound):
   *  the cost less a tolerance's share when certified; when not certified but the relaxation
   *  was at a higher rank (it is not tight), its optimum, so the poses are within
   *  `cost − lowerBound` of the global minimum; 0 when no level was certified. */
  lowerBound: number;
}

/** What `synchronizePoses` found. */
export interface SynchronizedPoses {
  /** 4n numbers: each pose's rotation in the call's order, w ≥ 0, the anchor's the identity
   *  (about z in 2D). */
  rotations: Float64Array;
  /** 3n numbers: each pose's translation, the anchor's the origin (z = 0 in 2D). */
  translations: Float64Array;
  /** Σ κ_ij ‖R_j − R_i R̃_ij‖²_F + τ_ij ‖t_j − t_i − R_i t̃_ij‖² with the caller's weights
   *  (SE-Sync's cost, no ½). */
  cost: number;
  /** Steps taken (Newton's and the trust region's), at every level of the staircase. */
  iterations: number;
  certificate: PoseCertificate;
}

/** Poses for `writeG2o`: a `SynchronizedPoses` as it is, or `{ rotations, translations }`. */
export interface PosesInput {
  /** One quaternion a pose, in the options' `order` (about z in 2D). */
  rotations: QuaternionsLike;
  /** One position a pose (z = 0 in 2D). */
  translations: Vectors3Like;
  /** A `SynchronizedPoses`' other keys are accepted and not read. */
  cost?: number;
  iterations?: number;
  certificate?: PoseCertificate;
}

/** Options of `writeG2o`. */
export interface WriteG2oOptions {
  /** How `relative` and `rotations` are laid out. Default "wxyz". */
  order?: QuaternionOrder;
}
"#;

#[wasm_bindgen]
extern "C" {
    #[wasm_bindgen(typescript_type = "PoseOptions")]
    pub type PoseOptionsObject;

    #[wasm_bindgen(typescript_type = "WriteG2oOptions")]
    pub type WriteG2oOptionsObject;
}

/// The keys of a pose graph that are read.
const READ: [&str; 9] = [
    "dimension",
    "count",
    "edges",
    "relative",
    "translations",
    "weights",
    "translation_weights",
    "information",
    "ids",
];
/// A `PoseGraph`'s other keys: accepted, so that `readG2o`'s result is an input as it is.
const UNREAD: [&str; 3] = ["initial", "positions", "skipped"];

/// `n` 3-vectors: 3n numbers flat (a typed array or an array of numbers), or n `[x, y, z]`.
/// Not checked for finiteness.
fn vectors(name: &str, value: &JsValue, max: usize) -> Result<Vec<DVec3>, KliError> {
    let array = is_array(value).unwrap_or(false);
    let flat = is_view(value) || (array && get(name, value, &0.into())?.as_f64().is_some());
    if flat {
        let flat = numbers(name, value, max.saturating_mul(3))?;
        if flat.len() % 3 != 0 {
            let problem = format!("must hold 3 numbers [x, y, z] each (got {})", flat.len());
            return Err(KliError::invalid(name, problem));
        }
        return Ok(flat.chunks_exact(3).map(|v| DVec3::new(v[0], v[1], v[2])).collect());
    }
    if !array {
        let problem = format!(
            "must be a typed array of 3n numbers or an array of [x, y, z] (got {})",
            describe(value)
        );
        return Err(KliError::invalid(name, problem));
    }
    let length = get(name, value, &"length".into())?.as_f64().unwrap_or(0.0) as usize;
    if length > max {
        let problem = format!("may hold at most {max} vectors (got {length})");
        return Err(KliError::invalid(name, problem));
    }
    (0..length)
        .map(|k| {
            let element = format!("{name}[{k}]");
            let v = numbers(&element, &get(&element, value, &(k as u32).into())?, 3)?;
            if v.len() != 3 {
                let problem = format!("must hold 3 numbers [x, y, z] (got {})", v.len());
                return Err(KliError::invalid(element, problem));
            }
            Ok(DVec3::new(v[0], v[1], v[2]))
        })
        .collect()
}

/// `values`' length is `n`, one per `each`, or an Error naming `name`.
fn one_per(name: &str, len: usize, n: usize, each: &str) -> Result<(), KliError> {
    if len == n {
        return Ok(());
    }
    Err(KliError::invalid(name, format!("must hold one value per {each}: {n} (got {len})")))
}

/// A rotation `name` read in `order`: unit, and about z in 2D (as the core checks a relative
/// rotation).
fn rotation(name: &str, q: DQuat, dimension: usize, order: Order) -> Result<DQuat, KliError> {
    let q = unit(name, q).map_err(|e| order.error(e))?;
    if dimension == 2 && (q.x.abs() > 1e-12 || q.y.abs() > 1e-12) {
        let problem = format!(
            "must be a rotation about z in a 2D graph (its x and y components are {} and {})",
            crate::error::number(q.x),
            crate::error::number(q.y)
        );
        return Err(KliError::invalid(name, problem));
    }
    Ok(q)
}

/// A translation `name`: finite, and z = 0 in 2D.
fn translation(name: &str, t: DVec3, dimension: usize) -> Result<DVec3, KliError> {
    for (c, x) in ["x", "y", "z"].iter().zip(t.to_array()) {
        if !x.is_finite() {
            let problem = format!(
                "must be 3 finite numbers: its {c} component is {}",
                crate::error::number(x)
            );
            return Err(KliError::invalid(name, problem));
        }
    }
    if dimension == 2 && t.z != 0.0 {
        let problem = format!(
            "must lie in the plane in a 2D graph: z = 0 (got {})",
            crate::error::number(t.z)
        );
        return Err(KliError::invalid(name, problem));
    }
    Ok(t)
}

/// Reads a pose graph (`name`: the argument, `input` or `graph`) and checks every edge: lengths,
/// pose numbers below `count`, unit relative rotations (about z in 2D), finite translations (z = 0
/// in 2D), finite weights > 0. Its `ids` are left empty; their value, when given, is returned to
/// read once the poses' count is known to be right.
fn read_pose_graph(
    name: &str,
    input: &JsValue,
    order: Order,
) -> Result<(PoseGraph, Option<JsValue>), KliError> {
    let example = "{ dimension: 2, edges: [[0, 1]], relative: [q01], translations: [[1, 0, 0]] }";
    let mut keys = READ.to_vec();
    keys.extend(UNREAD);
    let Some(fields) = Fields::named(name, Some(input.clone()), &keys, example)? else {
        let problem = format!("must be an object like {example} (got {})", describe(input));
        return Err(KliError::invalid(name, problem));
    };
    let required =
        |key: &str| fields.value(key)?.ok_or_else(|| KliError::invalid(key, "is required"));
    let Some(dimension) = fields.whole("dimension", 2.0, 3.0)? else {
        return Err(KliError::invalid("dimension", "is required: 2 or 3"));
    };
    let dimension = dimension as usize;
    let edges = read_edges(&required("edges")?)?;
    let m = edges.len();
    let relative =
        quaternion_list("relative", "edge", &required("relative")?, order, 4 * MAX_EDGES)?;
    one_per("relative", relative.len(), m, "edge")?;
    let relative = relative
        .into_iter()
        .enumerate()
        .map(|(k, q)| rotation(&format!("relative[{k}]"), q, dimension, order))
        .collect::<Result<Vec<_>, _>>()?;
    let translations = vectors("translations", &required("translations")?, MAX_EDGES)?;
    one_per("translations", translations.len(), m, "edge")?;
    for (k, &t) in translations.iter().enumerate() {
        translation(&format!("translations[{k}]"), t, dimension)?;
    }
    let weights = |key: &str| -> Result<Vec<f64>, KliError> {
        let Some(value) = fields.value(key)? else { return Ok(vec![1.0; m]) };
        let values = numbers(key, &value, MAX_EDGES)?;
        one_per(key, values.len(), m, "edge")?;
        for (k, &w) in values.iter().enumerate() {
            require(&format!("{key}[{k}]"), w, Requirement::Positive)?;
        }
        Ok(values)
    };
    let rotation_weights = weights("weights")?;
    let translation_weights = weights("translation_weights")?;
    // Only `writeG2o` writes it; checked here so that no call takes a malformed one.
    let information = match fields.value("information")? {
        None => Vec::new(),
        Some(value) => {
            let per = if dimension == 2 { 6 } else { 21 };
            let values = numbers("information", &value, MAX_EDGES.saturating_mul(per))?;
            if values.len() != m.saturating_mul(per) {
                let size = if dimension == 2 { 3 } else { 6 };
                let problem = format!(
                    "must hold {per} numbers an edge, the upper triangle of its {size}×{size} \
                     information ({} for {m} edges; got {})",
                    per * m,
                    values.len(),
                );
                return Err(KliError::invalid("information", problem));
            }
            for (k, &x) in values.iter().enumerate() {
                require(&format!("information[{k}]"), x, Requirement::Finite)?;
            }
            values
        }
    };
    let largest = edges.iter().flatten().map(|&i| i + 1).max().unwrap_or(0);
    let count = match fields.whole("count", 1.0, MAX_ID)? {
        Some(count) => count as usize,
        None => largest,
    };
    if let Some((k, &[i, j])) = edges.iter().enumerate().find(|(_, e)| e[0].max(e[1]) >= count) {
        let problem = format!(
            "must name poses below count, {count} (got {})",
            if i >= count { i } else { j }
        );
        return Err(KliError::invalid(format!("edges[{k}]"), problem));
    }
    let ids = fields.value("ids")?;
    let graph = PoseGraph {
        dimension,
        count,
        ids: Vec::new(),
        edges,
        relative,
        translations,
        rotation_weights,
        translation_weights,
        information,
        initial: None,
        positions: None,
        skipped: Vec::new(),
    };
    Ok((graph, ids))
}

/// The certified global minimum of a pose graph's cost (SE-Sync): every pose's rotation and
/// translation from the edges' measured relative poses, the anchor at the identity and the origin.
#[wasm_bindgen(js_name = synchronizePoses, unchecked_return_type = "SynchronizedPoses")]
pub fn synchronize_poses_js(
    #[wasm_bindgen(unchecked_param_type = "PoseGraphInput")] input: &JsValue,
    options: Option<PoseOptionsObject>,
) -> JsResult<JsValue> {
    let keys = ["anchor", "max_rank", "order"];
    let fields = Fields::new(options.map(JsValue::from), &keys, "{ anchor: 0 }")?;
    let mut order = Order::Wxyz;
    let mut options = PoseOptions::default();
    if let Some(fields) = &fields {
        order = Order::parse(fields.name("order")?)?;
        if let Some(anchor) = fields.whole("anchor", 0.0, MAX_ID)? {
            options.anchor = anchor as usize;
        }
        if let Some(rank) = fields.whole("max_rank", 0.0, MAX_ID)? {
            options.max_rank = rank as usize;
        }
    }
    let (graph, _) = read_pose_graph("input", input, order)?;
    let result = synchronize_poses(&graph, &options).map_err(|e| match e.argument() {
        // The core's name for the whole graph is the caller's `input`.
        "graph" => e.renamed("input"),
        _ => e,
    })?;
    let out = js_sys::Object::new();
    set(&out, "rotations", order.flat(&result.rotations).into());
    let flat: Vec<f64> = result.translations.iter().flat_map(|t| t.to_array()).collect();
    set(&out, "translations", Float64Array::from(&flat[..]).into());
    set(&out, "cost", result.cost.into());
    set(&out, "iterations", (result.iterations as f64).into());
    let c = result.certificate;
    let certificate = js_sys::Object::new();
    set(&certificate, "lambdaMin", c.lambda_min.into());
    set(&certificate, "tolerance", c.tolerance.into());
    set(&certificate, "certified", c.certified.into());
    set(&certificate, "rank", (c.rank as f64).into());
    set(&certificate, "lowerBound", c.lower_bound.into());
    set(&out, "certificate", certificate.into());
    Ok(out.into())
}

/// A number as g2o files write it, exactly (the shortest text that reads back as the same f64):
/// plain between 1e-5 and 1e16, else in exponent form (`1e300`, `2.5e-8`).
fn write_number(out: &mut String, x: f64) {
    let a = x.abs();
    let _ = if a == 0.0 {
        // −0 too, so that a zero reads back with its sign.
        out.push_str(if x.is_sign_negative() { " -0" } else { " 0" });
        Ok(())
    } else if (1e-5..1e16).contains(&a) {
        write!(out, " {x}")
    } else {
        write!(out, " {x:e}")
    };
}

/// The angle θ of a rotation about z, in (−π, π].
fn angle(q: DQuat) -> f64 {
    let q = if q.w < 0.0 { -q } else { q };
    2.0 * q.z.atan2(q.w)
}

/// The text of a g2o file holding `poses` and the graph's edges: one `VERTEX_SE2 id x y θ` (2D)
/// or `VERTEX_SE3:QUAT id x y z qx qy qz qw` (3D) line a pose, under the graph's `ids` (0, 1, …
/// without), then each edge as an `EDGE_SE2 i j dx dy dθ` or `EDGE_SE3:QUAT i j x y z qx qy qz
/// qw` line with its measurement, in the graph's order. Every number is written exactly (it reads
/// back as the same f64).
///
/// Each edge's information is the graph's `information` where it has one (a `PoseGraph` read by
/// `readG2o` keeps the file's, in g2o's order and units: another tool reading the file written
/// weighs its errors as it weighed the original's); otherwise the diagonal information that
/// `readG2o` reads back as the graph's κ and τ — `diag(τ, τ, κ)` in 2D, `diag(τ, τ, τ, 2κ, 2κ,
/// 2κ)` in 3D (κ = 3 / (2 tr Σ_R), τ = 3 / tr Σ_t) — so the file's cost, and its optimum, are the
/// graph's.
#[wasm_bindgen(js_name = writeG2o, unchecked_return_type = "string")]
pub fn write_g2o(
    #[wasm_bindgen(unchecked_param_type = "PoseGraphInput")] graph: &JsValue,
    #[wasm_bindgen(unchecked_param_type = "PosesInput")] poses: &JsValue,
    options: Option<WriteG2oOptionsObject>,
) -> JsResult<String> {
    let fields = Fields::new(options.map(JsValue::from), &["order"], "{ order: \"xyzw\" }")?;
    let order = match &fields {
        Some(fields) => Order::parse(fields.name("order")?)?,
        None => Order::Wxyz,
    };
    let (graph, ids) = read_pose_graph("graph", graph, order)?;
    let (d, n) = (graph.dimension, graph.count);
    let keys = ["rotations", "translations", "cost", "iterations", "certificate"];
    let example = "{ rotations, translations } (a synchronizePoses result)";
    let Some(fields) = Fields::named("poses", Some(poses.clone()), &keys, example)? else {
        let problem = format!("must be an object like {example} (got {})", describe(poses));
        return Err(KliError::invalid("poses", problem).into());
    };
    let required =
        |key: &str| fields.value(key)?.ok_or_else(|| KliError::invalid(key, "is required"));
    // `4n` saturates: a count of 2³² − 1 is 4n beyond wasm32's usize.
    let rotations =
        quaternion_list("rotations", "pose", &required("rotations")?, order, n.saturating_mul(4))?;
    one_per("rotations", rotations.len(), n, "pose")?;
    let rotations = rotations
        .into_iter()
        .enumerate()
        .map(|(k, q)| rotation(&format!("rotations[{k}]"), q, d, order))
        .collect::<Result<Vec<_>, _>>()?;
    let positions = vectors("translations", &required("translations")?, n)?;
    one_per("translations", positions.len(), n, "pose")?;
    for (k, &t) in positions.iter().enumerate() {
        translation(&format!("translations[{k}]"), t, d)?;
    }
    let ids: Vec<u64> = match ids {
        None => (0..n as u64).collect(),
        Some(value) => {
            let ids = numbers("ids", &value, n)?;
            one_per("ids", ids.len(), n, "pose")?;
            for (k, &id) in ids.iter().enumerate() {
                let ascending = k == 0 || id > ids[k - 1];
                if !(0.0..=MAX_SEED).contains(&id) || id.fract() != 0.0 || !ascending {
                    let problem = format!(
                        "must be whole numbers from 0 to 2^53 − 1, ascending (got {})",
                        crate::error::number(id)
                    );
                    return Err(KliError::invalid(format!("ids[{k}]"), problem).into());
                }
            }
            ids.into_iter().map(|id| id as u64).collect()
        }
    };
    let mut out = String::with_capacity(
        n.saturating_mul(64).saturating_add(graph.edges.len().saturating_mul(160)),
    );
    for (k, (&q, &t)) in rotations.iter().zip(&positions).enumerate() {
        if d == 2 {
            let _ = write!(out, "VERTEX_SE2 {}", ids[k]);
            [t.x, t.y, angle(q)].into_iter().for_each(|x| write_number(&mut out, x));
        } else {
            let _ = write!(out, "VERTEX_SE3:QUAT {}", ids[k]);
            [t.x, t.y, t.z, q.x, q.y, q.z, q.w].into_iter().for_each(|x| write_number(&mut out, x));
        }
        out.push('\n');
    }
    for (k, &[i, j]) in graph.edges.iter().enumerate() {
        let (q, t) = (graph.relative[k], graph.translations[k]);
        let (kappa, tau) = (graph.rotation_weights[k], graph.translation_weights[k]);
        let size = if d == 2 { 3 } else { 6 };
        let per = size * (size + 1) / 2;
        let information = match graph.information.get(k * per..(k + 1) * per) {
            Some(file) => file.to_vec(),
            // The upper triangle, row by row, of diag(τ, τ, κ) (2D: κ = I33, τ = 2 / tr Σ_t)
            // or diag(τ, τ, τ, 2κ, 2κ, 2κ) (3D).
            None => (0..size)
                .flat_map(|r| (r..size).map(move |c| (r, c)))
                .map(|(r, c)| match (r == c, r + 1 == size && d == 2, r < 3) {
                    (false, ..) => 0.0,
                    (true, true, _) => kappa,
                    (true, false, true) => tau,
                    (true, false, false) => 2.0 * kappa,
                })
                .collect(),
        };
        if d == 2 {
            let _ = write!(out, "EDGE_SE2 {} {}", ids[i], ids[j]);
            [t.x, t.y, angle(q)].into_iter().for_each(|x| write_number(&mut out, x));
        } else {
            let _ = write!(out, "EDGE_SE3:QUAT {} {}", ids[i], ids[j]);
            [t.x, t.y, t.z, q.x, q.y, q.z, q.w].into_iter().for_each(|x| write_number(&mut out, x));
        }
        information.into_iter().for_each(|x| write_number(&mut out, x));
        out.push('\n');
    }
    Ok(out)
}
