//! Synchronising rotations on a graph (MATH.md, "Synchronising rotations on a graph"): `n`
//! unknown rotations `q_1 … q_n` and, on the edges `(i, j)` of a connected graph, measured
//! relative rotations `q_ij ≈ q̄_i q_j` (`R_ij = R_iᵀ R_j`, GTSAM's `BetweenFactor<Rot3>` and g2o's
//! `EDGE_SE3:QUAT`), any signs, weights `w_ij > 0`. The rotation step of structure from motion and
//! pose-graph SLAM; with every `q_ij = 1`, consensus.
//!
//! The cost is chordal, `f = Σ w_ij ‖R_i R_ij − R_j‖²_F = Σ 8 w_ij sin²(θ_ij/2)` (`θ_ij` the
//! edge's residual angle), blind to the sign of every quaternion. The answer is defined up to one
//! rotation of all nodes (the gauge), fixed by holding the `anchor` at the identity.
//!
//! - [`Method::Chordal`]: the certified global minimum. Spectral start ([`Method::Spectral`]),
//!   Riemannian Newton with sparse Cholesky solves, and the [`Certificate`] `S = L − Λ ⪰ 0`.
//! - [`Method::Robust`]: for graphs with wrong edges. The least-squares optimum when no edge is
//!   far off from it, or of the edges kept when a few are; iteratively reweighted least squares
//!   (L1, then Geman–McClure) when many are. Reports each edge's weight and whether it is an
//!   outlier.
//! - [`Method::Spectral`]: the spectral relaxation alone, rounded.
//! - [`SyncFlow`]: the paper's Lohe model on the graph, steppable: the picture, which settles on
//!   the same minimum.
//!
//! [`read_g2o`] reads g2o and TORO/GTSAM pose-graph files, 2D and 3D: each edge's relative
//! rotation, translation and weights from its information matrix.

mod blocks;
mod certificate;
mod cost;
mod flow;
mod g2o;
#[cfg(test)]
mod g2o_tests;
mod graph;
mod lanczos;
mod newton;
mod poses;
mod robust;
mod sparse;
mod spectral;
#[cfg(test)]
mod tests;

pub use certificate::Certificate;
pub use flow::{MAX_STEPS, SyncFlow};
pub use g2o::{OtherLines, PoseGraph, read_g2o};
pub use graph::Graph;
pub use poses::{
    MAX_RANK, PoseCertificate, PoseOptions, PoseStage, SynchronizedPoses, anchor_poses,
    synchronize_poses, synchronize_poses_observed,
};

use glam::DQuat;

use crate::error::{ErrorKind, KliError, Requirement, require};

/// Which solution [`synchronize`] computes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Method {
    /// The global minimum of the chordal cost, with its certificate.
    #[default]
    Chordal,
    /// Iteratively reweighted least squares, robust to wrong edges.
    Robust,
    /// The spectral relaxation, rounded: the start of the other two.
    Spectral,
}

impl Method {
    pub const NAMES: &'static [&'static str] = &["chordal", "robust", "spectral"];

    pub fn name(self) -> &'static str {
        Self::NAMES[self as usize]
    }
}

impl std::str::FromStr for Method {
    type Err = KliError;

    fn from_str(name: &str) -> Result<Method, KliError> {
        [Method::Chordal, Method::Robust, Method::Spectral]
            .into_iter()
            .find(|m| m.name() == name)
            .ok_or_else(|| {
                KliError::new(
                    "method",
                    ErrorKind::UnknownName { got: name.into(), allowed: Self::NAMES },
                )
            })
    }
}

/// The options of [`synchronize`].
#[derive(Debug, Clone, PartialEq)]
pub struct SyncOptions {
    pub method: Method,
    /// The node held at the identity (0 by default).
    pub anchor: usize,
    /// For [`Method::Robust`]: the residual scale `σ` in radians (an edge beyond `3σ` is an
    /// outlier; the Geman–McClure scale of the reweighted rounds), or `None` to measure it from
    /// the residuals.
    pub scale: Option<f64>,
}

impl Default for SyncOptions {
    fn default() -> Self {
        SyncOptions { method: Method::Chordal, anchor: 0, scale: None }
    }
}

/// What [`synchronize`] found.
#[derive(Debug, Clone, PartialEq)]
pub struct Synchronized {
    /// One unit quaternion a node, the anchor's the identity, each with `w ≥ 0`.
    pub rotations: Vec<DQuat>,
    /// The chordal cost `f` with the caller's weights.
    pub cost: f64,
    /// Each edge's residual angle `θ_ij`, radians.
    pub residuals: Vec<f64>,
    /// Newton steps taken (all rounds, for the robust method), or Lanczos steps for the spectral.
    pub iterations: usize,
    /// For [`Method::Chordal`]: whether the result is provably the global minimum.
    pub certificate: Option<Certificate>,
    /// For [`Method::Robust`]: each edge's final weight (the caller's times the robust factor: 1
    /// or 0 for an edge kept or set aside from least squares).
    pub weights: Option<Vec<f64>>,
    /// For [`Method::Robust`]: whether each edge was treated as wrong.
    pub outliers: Option<Vec<bool>>,
    /// For [`Method::Robust`]: the Geman–McClure scale used, radians.
    pub scale: Option<f64>,
}

/// Every rotation moved by the gauge that puts `anchor` at the identity, signs `w ≥ 0`.
pub(crate) fn anchored(q: &[DQuat], anchor: usize) -> Vec<DQuat> {
    let gauge = q[anchor].conjugate();
    let mut out: Vec<DQuat> = q
        .iter()
        .map(|&q| {
            let q = (gauge * q).normalize();
            if q.w < 0.0 { -q } else { q }
        })
        .collect();
    // Exactly, not to rounding.
    out[anchor] = DQuat::IDENTITY;
    out
}

/// Synchronises `graph` by `options.method`. Refused: an `anchor` that is not a node, a `scale`
/// that is not finite and `> 0`.
pub fn synchronize(graph: &Graph, options: &SyncOptions) -> Result<Synchronized, KliError> {
    let anchor = options.anchor;
    if anchor >= graph.count() {
        return Err(KliError::invalid(
            "anchor",
            format!("must be a node, from 0 to {} (got {anchor})", graph.count() - 1),
        ));
    }
    if let Some(scale) = options.scale {
        require("scale", scale, Requirement::Positive)?;
    }
    // The solution does not change when every weight is scaled; the solvers see the largest as 1,
    // so no sum of weights overflows (1e308) or underflows (subnormals).
    let unit = graph.weights().iter().copied().fold(0.0, f64::max);
    let caller = graph;
    let graph = &graph.reweighted(graph.weights().iter().map(|w| w / unit).collect());
    let full = blocks::Pattern::new(graph, None);
    let (start, lanczos_steps) = spectral::spectral(graph, &full);
    let mut result = Synchronized {
        rotations: Vec::new(),
        cost: 0.0,
        residuals: Vec::new(),
        iterations: lanczos_steps,
        certificate: None,
        weights: None,
        outliers: None,
        scale: None,
    };
    let q = match options.method {
        Method::Spectral => start,
        Method::Chordal => {
            let reduced = blocks::Pattern::new(graph, Some(anchor));
            let refined = newton::refine(
                graph,
                &reduced,
                start,
                newton::MAX_ITERATIONS,
                newton::Accuracy::Full,
            );
            result.iterations = refined.iterations;
            let c = certificate::certify(graph, &full, &refined.q);
            // In the caller's units: S scales with the weights.
            result.certificate = Some(Certificate {
                lambda_min: c.lambda_min * unit,
                gap: c.gap * unit,
                tolerance: c.tolerance * unit,
                ..c
            });
            refined.q
        }
        Method::Robust => {
            let reduced = blocks::Pattern::new(graph, Some(anchor));
            let robust = robust::robust(graph, &reduced, start, options.scale);
            result.iterations = robust.iterations;
            result.weights =
                Some(caller.weights().iter().zip(&robust.factors).map(|(w, f)| w * f).collect());
            result.outliers = Some(robust.outliers);
            result.scale = Some(robust.scale);
            robust.q
        }
    };
    result.rotations = anchored(&q, anchor);
    result.cost = cost::cost(caller, &result.rotations);
    result.residuals = cost::residuals(caller, &result.rotations);
    Ok(result)
}

/// The best gauge `g` that takes `truth` onto `q` (maximising `Σ ⟨q_i, g t_i⟩²`: the chordal mean
/// of the `q_i t̄_i`), and each node's angle to the truth after it, radians (MATH.md, "Aligning to
/// a truth"). For tests and figures.
pub fn errors_to_truth(q: &[DQuat], truth: &[DQuat]) -> Vec<f64> {
    let products: Vec<DQuat> = q.iter().zip(truth).map(|(&q, &t)| q * t.conjugate()).collect();
    let mut m = [[0.0; 4]; 4];
    for p in &products {
        let v = crate::quaternion::to_wxyz(*p);
        for r in 0..4 {
            for c in 0..4 {
                m[r][c] += v[r] * v[c];
            }
        }
    }
    let (_, vectors) = crate::average::eigen(m);
    let g = crate::quaternion::from_wxyz(vectors[0]);
    q.iter()
        .zip(truth)
        .map(|(&q, &t)| {
            let e = (g * t).conjugate() * q;
            2.0 * glam::DVec3::new(e.x, e.y, e.z).length().atan2(e.w.abs())
        })
        .collect()
}
