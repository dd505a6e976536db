//! The chordal cost of MATH.md and its second-order model on (S³)ⁿ.
//!
//! With `c_ij = ⟨q_i q_ij, q_j⟩`, `‖R_i R_ij − R_j‖²_F = 8 (1 − c_ij²) = 8 sin²(θ_ij/2)`,
//! `θ_ij` the residual angle of the edge. Blind to the sign of every quaternion.

use glam::{DMat3, DQuat, DVec3};

use super::blocks::{Blocks, add};
use super::graph::Graph;

/// `e = (q_i q_ij)⁻¹ q_j`: the rotation by which the measurement misses, per edge.
fn miss(q: &[DQuat], [i, j]: [usize; 2], relative: DQuat) -> DQuat {
    (q[i] * relative).conjugate() * q[j]
}

/// The edge's residual angle `θ_ij = 2 atan2(|e_xyz|, |e_w|)` in radians, in `[0, π]`
/// (accurate for small angles, where `2 acos|c|` is not).
pub(crate) fn residual(q: &[DQuat], edge: [usize; 2], relative: DQuat) -> f64 {
    let e = miss(q, edge, relative);
    2.0 * DVec3::new(e.x, e.y, e.z).length().atan2(e.w.abs())
}

/// The edge's term `‖R_i R_ij − R_j‖²_F = 8 |e_xyz|²` (`e` is a unit quaternion, a product of
/// the unit rotations every caller keeps, so `|e_xyz| = sin(θ/2)`).
fn term(q: &[DQuat], edge: [usize; 2], relative: DQuat) -> f64 {
    let e = miss(q, edge, relative);
    8.0 * (e.x * e.x + e.y * e.y + e.z * e.z)
}

/// `f = Σ w_ij ‖R_i R_ij − R_j‖²_F`.
pub(crate) fn cost(graph: &Graph, q: &[DQuat]) -> f64 {
    graph
        .edges()
        .iter()
        .zip(graph.relative())
        .zip(graph.weights())
        .map(|((&edge, &relative), &w)| w * term(q, edge, relative))
        .sum()
}

/// Each edge's residual angle, radians.
pub(crate) fn residuals(graph: &Graph, q: &[DQuat]) -> Vec<f64> {
    graph
        .edges()
        .iter()
        .zip(graph.relative())
        .map(|(&edge, &relative)| residual(q, edge, relative))
        .collect()
}

/// `v(X) = (X₂₃ − X₃₂, X₃₁ − X₁₃, X₁₂ − X₂₁)`, so that `tr(u^ X) = u · v(X)` for the cross-product
/// matrix `u^`.
fn axial(x: DMat3) -> DVec3 {
    let at = |r: usize, c: usize| x.col(c)[r];
    DVec3::new(at(1, 2) - at(2, 1), at(2, 0) - at(0, 2), at(0, 1) - at(1, 0))
}

fn hat(u: DVec3) -> DMat3 {
    DMat3::from_cols(
        DVec3::new(0.0, u.z, -u.y),
        DVec3::new(-u.z, 0.0, u.x),
        DVec3::new(u.y, -u.x, 0.0),
    )
}

/// The gradient `g` (length 3n) and Hessian of `f` pulled back through `R_i → R_i exp(δ_i^)`
/// (`q_i → q_i exp(δ_i/2)`), at `δ = 0`.
///
/// Each edge's term is `6 w − 2 w tr(exp(−a^) M exp(b^) N)` with `M = R_iᵀ R_j`, `N = R_ijᵀ`,
/// `a = δ_i`, `b = δ_j`. To second order, with `P = M N`, `Q = N M` and `exp(x^) ≈ I + x^ + ½ x^²`:
/// `tr(…) ≈ tr P − a·v(P) + b·v(Q) + ½ aᵀ(sym P − tr P I) a + ½ bᵀ(sym Q − tr Q I) b + aᵀ C b`,
/// `C_kl = −tr(e_k^ M e_l^ N)`, using `tr(u^ X) = u·v(X)` and `u^u^ = u uᵀ − |u|² I`.
/// At a critical point this is the Riemannian Hessian; elsewhere it is the Hessian of the
/// pullback, which Newton's method with the exponential retraction uses.
///
/// With `gauss_newton`, the Gauss–Newton matrix instead: the linearised residual
/// `R_i (a^ − M b^ N) R_ij` has `‖·‖²_F = 2|a|² + 2|b|² − 2 aᵀ C b`, so the diagonal blocks become
/// `4 w I` and the off-diagonal ones stay: positive semidefinite everywhere (the robust rounds,
/// whose outliers give the exact Hessian negative curvature).
pub(crate) fn model(graph: &Graph, q: &[DQuat], gauss_newton: bool) -> (Vec<f64>, Blocks) {
    let rotation: Vec<DMat3> = q.iter().map(|&q| DMat3::from_quat(q)).collect();
    let mut gradient = vec![0.0; 3 * graph.count()];
    let mut hessian = Blocks::zeros(graph);
    let edges = graph.edges().iter().zip(graph.relative()).zip(graph.weights());
    for (k, ((&[i, j], &relative), &w)) in edges.enumerate() {
        let m = rotation[i].transpose() * rotation[j];
        let n = DMat3::from_quat(relative).transpose();
        let (p, q) = (m * n, n * m);
        add(&mut gradient, i, axial(p) * (2.0 * w));
        add(&mut gradient, j, axial(q) * (-2.0 * w));
        let curvature = |x: DMat3| {
            if gauss_newton {
                return DMat3::IDENTITY * (4.0 * w);
            }
            let sym = (x + x.transpose()) * 0.5;
            (sym - DMat3::from_diagonal(DVec3::splat(x.col(0)[0] + x.col(1)[1] + x.col(2)[2])))
                * (-2.0 * w)
        };
        hessian.diag[i] += curvature(p);
        hessian.diag[j] += curvature(q);
        let cross = DMat3::from_cols_array_2d(&[0, 1, 2].map(|l| {
            let column = -axial(m * hat(DVec3::AXES[l]) * n);
            column.to_array()
        }));
        hessian.off[k] += cross * (-2.0 * w);
    }
    (gradient, hessian)
}
