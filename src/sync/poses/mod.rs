//! Pose-graph synchronisation, certifiably: SE-Sync (Rosen, Carlone, Bandeira and Leonard,
//! "SE-Sync: a certifiably correct algorithm for synchronization over the special Euclidean
//! group", IJRR 2019; MATH.md, "Pose graphs").
//!
//! `n` poses `T_i = (R_i, t_i)` in SE(d), d = 2 or 3, and on each edge `(i, j)` a measurement
//! `T̃_ij ≈ T_i⁻¹ T_j` (`R̃_ij ≈ R_iᵀ R_j`, `t̃_ij ≈ R_iᵀ (t_j − t_i)`) with weights `κ_ij`
//! (rotation) and `τ_ij` (translation). The cost (SE-Sync Problem 1, no ½):
//!
//! `f = Σ κ_ij ‖R_j − R_i R̃_ij‖²_F + τ_ij ‖t_j − t_i − R_i t̃_ij‖²₂`.
//!
//! [`synchronize_poses`] finds its global minimum and certifies it:
//! 1. the translations are eliminated in closed form, leaving `tr(R Q Rᵀ)` (`reduced`);
//! 2. the chordal start (`chordal`);
//! 3. the rank-`r` relaxation on `St(d, r)ⁿ` (`stiefel`), minimised by a Riemannian trust region
//!    with truncated conjugate gradients (`trust`), from `r = d`; in 2D at ranks 2 and 3 by
//!    Newton's method with the translations kept (`newton`: a sparse factorisation a step), the
//!    trust region going on from there only if it did not converge;
//! 4. the certificate `λ_min(Q − Λ) ≥ −tol`, and where it fails the Riemannian staircase: rank
//!    `r + 1` and a step along the eigenvector of `λ_min` (`staircase`);
//! 5. rounding to `SO(d)ⁿ`, a last pass at rank `d` (as in 3), the translations
//!    `T = R Vᵀ L_τ†`, and the gauge that puts the anchor at the identity and the origin.

// The d × d blocks are indexed as the formulas write them (rows a, columns b).
#![allow(clippy::needless_range_loop)]

mod chordal;
mod newton;
mod reduced;
mod staircase;
mod stiefel;
#[cfg(test)]
mod tests;
mod trust;

use glam::{DMat3, DQuat, DVec3};

use super::g2o::PoseGraph;
use super::graph::Graph;
use crate::error::{KliError, Requirement, require};
use crate::quaternion::unit;
use reduced::{Edge, Reduced};
use stiefel::Stack;

/// The options of [`synchronize_poses`].
#[derive(Debug, Clone, PartialEq)]
pub struct PoseOptions {
    /// The pose held at the identity and the origin (0 by default).
    pub anchor: usize,
    /// The highest rank of the Riemannian staircase (from the graph's dimension to
    /// [`MAX_RANK`]; 10 by default, SE-Sync's).
    pub max_rank: usize,
}

impl Default for PoseOptions {
    fn default() -> Self {
        PoseOptions { anchor: 0, max_rank: 10 }
    }
}

/// Whether a pose-graph solution is provably the global minimum (SE-Sync §4.2.1, Theorem 7).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PoseCertificate {
    /// The smallest eigenvalue of `S = Q − Λ` at the rotations returned (0 to rounding at a
    /// certified optimum: the gauge's `d` directions are in its kernel), in the caller's units.
    /// An estimate by Lanczos, converged to a relative residual of 1e-8.
    pub lambda_min: f64,
    /// The tolerance: certified means `λ_min(S) ≥ −tolerance`; `10⁻⁹` of `Q`'s scale (the largest
    /// diagonal entry of `L(G̃^ρ) + Σ̃`), rounding's.
    pub tolerance: f64,
    /// Whether `S + tolerance · I` is positive definite: the poses are the global minimum.
    pub certified: bool,
    /// The rank `r` of the staircase's last level: where the relaxation was certified (the
    /// dimension when the first level was); where it never was, where the staircase stopped
    /// (`max_rank`, or below it if no step along the eigenvector of `λ_min` lowered the cost).
    pub rank: usize,
    /// A proven lower bound on the global minimum of the cost, from the last level whose
    /// relaxation was certified (SE-Sync §4.2.1, the dual of the semidefinite relaxation): at
    /// its point `Y`, `S Yᵀ = 0` and `S ⪰ −tolerance · I`, so every feasible `Z` (its `d × d`
    /// diagonal blocks the identity, trace `dn`) has `tr(Q Z) ≥ tr(Q YᵀY) − tolerance · dn`.
    /// Certified: the cost less `tolerance · dn` (the cost is the minimum). Not certified but the
    /// relaxation was at a higher rank (it is not tight there: its optimum lies below every set
    /// of rotations): the poses are within `cost − lower_bound` of the global minimum, SE-Sync's
    /// suboptimality bound. No level certified: 0, the cost's own floor.
    pub lower_bound: f64,
}

/// What [`synchronize_poses`] found.
#[derive(Debug, Clone, PartialEq)]
pub struct SynchronizedPoses {
    /// Each pose's rotation, a unit quaternion with `w ≥ 0` (about z in 2D); the anchor's is the
    /// identity.
    pub rotations: Vec<DQuat>,
    /// Each pose's translation (z = 0 in 2D); the anchor's is the origin.
    pub translations: Vec<DVec3>,
    /// The cost `f` of these poses, with the caller's weights.
    pub cost: f64,
    /// The steps taken (Newton's and the trust region's), at every level of the staircase.
    pub iterations: usize,
    pub certificate: PoseCertificate,
}

/// Where [`synchronize_poses_observed`] is: each stage is announced as it begins, so that a long
/// solve (10⁴ poses take seconds) can say what it is doing. Observing changes nothing solved.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PoseStage {
    /// Eliminating the translations (one sparse factorisation) and the chordal start.
    Chordal,
    /// Minimising the rank-`rank` relaxation, after `iterations` steps at lower ranks.
    Optimising { rank: usize, iterations: usize },
    /// A step (Newton's or the trust region's) at rank `rank`, the `iterations`-th of the whole
    /// solve (each level's and the last pass's counted together, as
    /// [`SynchronizedPoses::iterations`] counts them).
    Step { rank: usize, iterations: usize },
    /// The certificate `λ_min(Q − Λ)` at rank `rank` (Lanczos).
    Certifying { rank: usize },
    /// Rounding a higher-rank solution to rotations and the last pass at the dimension's rank.
    Rounding,
    /// The translations from the rotations, and the anchor's gauge.
    Translations,
}

/// The largest [`PoseOptions::max_rank`] taken (each level adds a column to the iterate).
pub const MAX_RANK: usize = 64;

/// The certificate's tolerance over `Q`'s scale.
const TOLERANCE: f64 = 1e-9;

/// The gradient tolerance of the trust region over `Q`'s scale and `√(dn)`.
const GRADIENT: f64 = 1e-13;

/// The global minimum of the pose graph's cost, certified where the certificate holds. The
/// graph is taken as [`read_g2o`](super::read_g2o) gives it, or as built by the caller: its
/// `dimension`, `count`, `edges`, `relative`, `translations`, `rotation_weights` and
/// `translation_weights` are read (`ids`, `initial`, `positions` and `skipped` are not).
///
/// Refused, naming the field or option at fault: a `dimension` other than 2 or 3; no pose; an
/// `anchor` that is not a pose; a `max_rank` below the dimension or above [`MAX_RANK`]; fields of other lengths than
/// `edges`; an edge naming a pose beyond `count` or joining a pose to itself; a relative rotation
/// that is not a finite non-zero quaternion (or, in 2D, not a rotation about z); a translation
/// that is not finite (or, in 2D, off the plane); a weight that is not finite and `> 0`; poses
/// that the edges do not connect (the error names the poses cut off from pose 0); weights and
/// translations so far apart in scale that the problem cannot be solved in f64.
pub fn synchronize_poses(
    graph: &PoseGraph,
    options: &PoseOptions,
) -> Result<SynchronizedPoses, KliError> {
    synchronize_poses_observed(graph, options, &mut |_| {})
}

/// [`synchronize_poses`], telling `observe` each [`PoseStage`] as it begins (a page's progress);
/// the answer is the same, bit for bit.
pub fn synchronize_poses_observed(
    graph: &PoseGraph,
    options: &PoseOptions,
    observe: &mut dyn FnMut(PoseStage),
) -> Result<SynchronizedPoses, KliError> {
    let d = graph.dimension;
    if d != 2 && d != 3 {
        return Err(KliError::invalid("dimension", format!("must be 2 or 3 (got {d})")));
    }
    let n = graph.count;
    if n == 0 {
        return Err(KliError::invalid("count", "must be at least 1: a pose graph needs a pose"));
    }
    let anchor = options.anchor;
    if anchor >= n {
        return Err(KliError::invalid(
            "anchor",
            format!("must be a pose, from 0 to {} (got {anchor})", n - 1),
        ));
    }
    if options.max_rank < d || options.max_rank > MAX_RANK {
        return Err(KliError::invalid(
            "max_rank",
            format!("must be from the dimension, {d}, to {MAX_RANK} (got {})", options.max_rank),
        ));
    }
    let m = graph.edges.len();
    for (name, len) in [
        ("relative", graph.relative.len()),
        ("translations", graph.translations.len()),
        ("rotation_weights", graph.rotation_weights.len()),
        ("translation_weights", graph.translation_weights.len()),
    ] {
        if len != m {
            return Err(KliError::invalid(
                name,
                format!("must hold one value per edge: {m} (got {len})"),
            ));
        }
    }
    for k in 0..m {
        require(
            &format!("rotation_weights[{k}]"),
            graph.rotation_weights[k],
            Requirement::Positive,
        )?;
        require(
            &format!("translation_weights[{k}]"),
            graph.translation_weights[k],
            Requirement::Positive,
        )?;
        let t = graph.translations[k];
        if let Some(c) = (0..3).find(|&c| !t[c].is_finite()) {
            return Err(KliError::invalid(
                format!("translations[{k}]"),
                format!(
                    "must be 3 finite numbers: its {} component is {}",
                    ["x", "y", "z"][c],
                    t[c]
                ),
            ));
        }
        if d == 2 && t.z != 0.0 {
            return Err(KliError::invalid(
                format!("translations[{k}]"),
                format!("must lie in the plane in a 2D graph: z = 0 (got {})", t.z),
            ));
        }
    }
    let mut relative = Vec::with_capacity(m);
    for (k, &q) in graph.relative.iter().enumerate() {
        let q = unit(&format!("relative[{k}]"), q)?;
        if d == 2 && (q.x.abs() > 1e-12 || q.y.abs() > 1e-12) {
            return Err(KliError::invalid(
                format!("relative[{k}]"),
                format!(
                    "must be a rotation about z in a 2D graph (its x and y components are {} and {})",
                    q.x, q.y
                ),
            ));
        }
        relative.push(q);
    }
    if n == 1 {
        // No edge can join a single pose to another; it is the anchor.
        if m > 0 {
            Graph::new(Some(1), &graph.edges[..1], &relative[..1], None)?;
        }
        return Ok(SynchronizedPoses {
            rotations: vec![DQuat::IDENTITY],
            translations: vec![DVec3::ZERO],
            cost: 0.0,
            iterations: 0,
            certificate: PoseCertificate {
                lambda_min: 0.0,
                tolerance: 0.0,
                certified: true,
                rank: d,
                lower_bound: 0.0,
            },
        });
    }
    if m == 0 {
        let cut: Vec<String> = (1..n.min(9)).map(|i| i.to_string()).collect();
        let more = if n > 9 { format!(" and {} more", n - 9) } else { String::new() };
        return Err(KliError::invalid(
            "edges",
            format!(
                "do not connect the graph: {} {}{more} {} cut off from node 0",
                if n == 2 { "node" } else { "nodes" },
                cut.join(", "),
                if n == 2 { "is" } else { "are" }
            ),
        ));
    }
    // Ids, self-loops and connectivity, checked as `synchronize` checks them.
    Graph::new(Some(n), &graph.edges, &relative, Some(&graph.rotation_weights))?;
    // The minimiser does not change when every weight is scaled: the solver sees the largest as 1.
    let unit_weight = graph
        .rotation_weights
        .iter()
        .chain(&graph.translation_weights)
        .copied()
        .fold(0.0, f64::max);
    let edges: Vec<Edge> = (0..m)
        .map(|k| {
            let r = DMat3::from_quat(relative[k]);
            let t = graph.translations[k];
            Edge {
                i: graph.edges[k][0],
                j: graph.edges[k][1],
                kappa: graph.rotation_weights[k] / unit_weight,
                tau: graph.translation_weights[k] / unit_weight,
                rotation: std::array::from_fn(|a| {
                    std::array::from_fn(|b| if a < d && b < d { r.col(b)[a] } else { 0.0 })
                }),
                t: [t.x, t.y, t.z],
            }
        })
        .collect();
    let scale_error = || {
        KliError::invalid(
            "graph",
            "has weights and translations too far apart in scale to be solved in f64 (a \
             factorisation met a non-positive or non-finite pivot)",
        )
    };
    observe(PoseStage::Chordal);
    let problem = Reduced::new(d, n, edges).ok_or_else(scale_error)?;
    let start = chordal::chordal(&problem).ok_or_else(scale_error)?;
    let solved = solve(&problem, options.max_rank, &start, observe).ok_or_else(scale_error)?;
    observe(PoseStage::Translations);
    // Translations with t_0 = 0, then the gauge that takes the anchor to (I, 0).
    let x = stiefel::from_rotations(d, &solved.rotations);
    let z = problem.translations(&x);
    let t = |k: usize| DVec3::new(z[k], z[n + k], if d == 3 { z[2 * n + k] } else { 0.0 });
    let positions: Vec<DVec3> = (0..n).map(t).collect();
    let (rotations, mut translations) = anchor_poses(&solved.rotations, &positions, anchor);
    if d == 2 {
        translations.iter_mut().for_each(|t| t.z = 0.0);
    }
    let cost = pose_cost(graph, &relative, &rotations, &translations);
    if !cost.is_finite() || translations.iter().any(|t| !t.is_finite()) {
        return Err(scale_error());
    }
    let certificate = PoseCertificate {
        lambda_min: solved.lambda_min * unit_weight,
        tolerance: TOLERANCE * problem.scale * unit_weight,
        certified: solved.certified,
        rank: solved.rank,
        lower_bound: solved.lower_bound.max(0.0) * unit_weight,
    };
    Ok(SynchronizedPoses {
        rotations,
        translations,
        cost,
        iterations: solved.iterations,
        certificate,
    })
}

/// Poses in the gauge that puts pose `anchor` at the identity and the origin: each rotation
/// `q̄_a q_i` (normalised, `w ≥ 0`) and each position `q̄_a (t_i − t_a)`, the anchor's exactly
/// `(1, 0)`. The solver's answer is in this gauge; a page puts an initial estimate in it too, to
/// draw the two alike. An `anchor` beyond the poses leaves them as they are.
pub fn anchor_poses(
    rotations: &[DQuat],
    positions: &[DVec3],
    anchor: usize,
) -> (Vec<DQuat>, Vec<DVec3>) {
    let (Some(&r), Some(&origin)) = (rotations.get(anchor), positions.get(anchor)) else {
        return (rotations.to_vec(), positions.to_vec());
    };
    let gauge = r.conjugate();
    let rotations = super::anchored(rotations, anchor);
    let mut positions: Vec<DVec3> = positions.iter().map(|&p| gauge * (p - origin)).collect();
    positions[anchor] = DVec3::ZERO;
    (rotations, positions)
}

/// `f = Σ κ ‖R_j − R_i R̃_ij‖²_F + τ ‖t_j − t_i − R_i t̃_ij‖²` of the poses, directly (in 2D the
/// 3×3 matrices of rotations about z add nothing in their z row and column).
fn pose_cost(graph: &PoseGraph, relative: &[DQuat], rotations: &[DQuat], t: &[DVec3]) -> f64 {
    let mut f = 0.0;
    for (k, &[i, j]) in graph.edges.iter().enumerate() {
        let (ri, rj) = (DMat3::from_quat(rotations[i]), DMat3::from_quat(rotations[j]));
        let e = rj - ri * DMat3::from_quat(relative[k]);
        let frobenius: f64 = (0..3).map(|c| e.col(c).length_squared()).sum();
        let residual = t[j] - t[i] - ri * graph.translations[k];
        f += graph.rotation_weights[k] * frobenius
            + graph.translation_weights[k] * residual.length_squared();
    }
    f
}

/// The staircase's answer: rotations (in no particular gauge), the certificate at them, and the
/// steps.
struct Solved {
    rotations: Vec<DQuat>,
    lambda_min: f64,
    certified: bool,
    rank: usize,
    iterations: usize,
    /// [`PoseCertificate::lower_bound`] on the scaled weights (−∞ where no level was certified).
    lower_bound: f64,
}

/// Steps 3–5 of the module's documentation from the rotations `start`, on weights scaled to a
/// largest of 1. `None` when a factorisation that a well-scaled problem always has fails.
fn solve(
    problem: &Reduced,
    max_rank: usize,
    start: &[DQuat],
    observe: &mut dyn FnMut(PoseStage),
) -> Option<Solved> {
    let d = problem.d;
    let preconditioner = trust::Preconditioner::new(problem)?;
    let tolerance = TOLERANCE * problem.scale;
    let gradient = GRADIENT * problem.scale * ((d * problem.n) as f64).sqrt();
    let mut x: Stack = stiefel::from_rotations(d, start);
    let mut rank = d;
    let mut iterations = 0;
    // The relaxation's value at a certified point, less the tolerance's share (the field's doc).
    let bound = |x: &Stack| problem.cost(x).0 - tolerance * (d * problem.n) as f64;
    let mut lower_bound = f64::NEG_INFINITY;
    let verdict = loop {
        observe(PoseStage::Optimising { rank, iterations });
        x = optimise(problem, &preconditioner, x, gradient, &mut iterations, observe);
        observe(PoseStage::Certifying { rank });
        let verdict = staircase::certify(problem, &x, tolerance);
        if verdict.certified {
            lower_bound = bound(&x);
        }
        if verdict.certified || rank >= max_rank {
            break verdict;
        }
        let Some(escaped) = verdict.vector.as_ref().and_then(|v| staircase::escape(problem, &x, v))
        else {
            break verdict;
        };
        x = escaped;
        rank += 1;
    };
    let (x, verdict) = if x.r > d {
        // Round, polish at rank d, and certify the rotations themselves.
        observe(PoseStage::Rounding);
        let rounded = stiefel::from_rotations(d, &stiefel::round(&x));
        let polished =
            optimise(problem, &preconditioner, rounded, gradient, &mut iterations, observe);
        let final_verdict = staircase::certify(problem, &polished, tolerance);
        if final_verdict.certified {
            lower_bound = lower_bound.max(bound(&polished));
        }
        (polished, final_verdict)
    } else {
        (x, verdict)
    };
    Some(Solved {
        rotations: stiefel::to_rotations(&x),
        lambda_min: verdict.lambda_min,
        certified: verdict.certified,
        rank,
        iterations,
        lower_bound,
    })
}

/// Where a 3D graph's Newton steps pay: its graph's factorisation fills in at most this much
/// ([`Reduced::fill`]). A graph of long chains with few loop closures fills in little, so
/// Newton's factorisation of six unknowns a pose is cheap, and conditions the trust region's
/// conjugate gradients badly (parking-garage, fill 1.54: 26–65 of them a step); a meshed one
/// (sphere2500, fill 5.85) the other way round.
const NEWTON_FILL_3D: f64 = 3.0;

/// Whether Newton's method goes first at `rank` (`newton`): in 2D at ranks 2 and 3 (on
/// city10000 in wasm 421 against 647 ms, on w10000 0.77 against 1.53 s); in 3D at rank 3 where
/// the graph fills in little ([`NEWTON_FILL_3D`]): parking-garage's rank 3 natively 170 → 102 ms,
/// its whole solve in wasm 261–269 → 206–225 ms (medians of 5, alternately), where sphere2500's
/// whole solve took 587 against 326 ms in wasm, and smallGrid3D (fill 3.36) 46 against 10 ms.
fn newton_first(problem: &Reduced, rank: usize) -> bool {
    newton::applies(problem.d, rank) && (problem.d == 2 || problem.fill <= NEWTON_FILL_3D)
}

/// One level's local optimisation from `x`, counting its steps into `iterations`: Newton's method
/// first where it pays ([`newton_first`]), then the trust region from where it stopped unless it
/// converged.
fn optimise(
    problem: &Reduced,
    preconditioner: &trust::Preconditioner,
    x: Stack,
    gradient: f64,
    iterations: &mut usize,
    observe: &mut dyn FnMut(PoseStage),
) -> Stack {
    let rank = x.r;
    let mut x = x;
    if newton_first(problem, rank) {
        let before = *iterations;
        let refined = newton::refine(problem, &x, gradient, &mut |k| {
            observe(PoseStage::Step { rank, iterations: before + k })
        });
        *iterations += refined.iterations;
        if refined.converged {
            return refined.x;
        }
        x = refined.x;
    }
    let before = *iterations;
    let optimised =
        trust::optimise(problem, preconditioner, x, gradient, trust::MAX_ITERATIONS, &mut |k| {
            observe(PoseStage::Step { rank, iterations: before + k })
        });
    *iterations += optimised.iterations;
    optimised.x
}
