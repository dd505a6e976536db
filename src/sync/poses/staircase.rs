//! The certificate and the Riemannian staircase (Rosen et al., IJRR 2019, §4.2 and Algorithm 1;
//! Boumal 2015, "A Riemannian low-rank method for optimization over semidefinite matrices with
//! block-diagonal constraints", Theorem 3.9).
//!
//! At a first-order critical point `X` of the rank-`r` problem, `Λ = SymBlockDiag_d(Q YᵀY)` and
//! `S = Q − Λ` (SE-Sync eqs. (41)–(42)); `S X = 0`. If `λ_min(S) ≥ −tol`, `X YᵀY` solves the
//! semidefinite relaxation (SE-Sync Theorem 7 and eq. (55)), and a rank-`d` `X` (a set of
//! rotations) is the global minimum of the pose-graph problem. Decided by a sparse Cholesky
//! factorisation of `S + tol I` (it exists if and only if `λ_min(S) > −tol`), which `M` gives
//! without forming `Q` (its Schur complement); measured by shift-and-invert Lanczos on
//! `(S − σ I)⁻¹` off the columns of `X`, with the same factorisation.
//!
//! Where it fails, the eigenvector `v` of `λ_min(S) < 0` is a direction of negative curvature at
//! rank `r + 1`: `[X 0] + α [0 v]` (a tangent vector), retracted, lowers `F` for small `α`
//! (SE-Sync's `escape_saddle`, a backtracking line search from `α = √n`).

use super::reduced::Reduced;
use super::stiefel::{Block, Stack, multipliers, retract};
use crate::sync::lanczos;

/// What the certificate found at one point.
pub(super) struct Verdict {
    /// The smallest eigenvalue of `S` (its estimate by Lanczos, to a relative residual of 1e-8).
    pub lambda_min: f64,
    /// Whether `S + tol I` is positive definite.
    pub certified: bool,
    /// The eigenvector of `lambda_min` off the columns of `X` (length `dn`, unit).
    pub vector: Option<Vec<f64>>,
}

/// The columns of `X`, orthonormalised (Gram–Schmidt twice), those of rounding's size dropped: at
/// a rank-deficient `X` (the staircase's answer when the relaxation is tight) they span `d`
/// dimensions.
fn column_space(x: &Stack) -> Vec<Vec<f64>> {
    let rows = x.rows();
    let mut basis: Vec<Vec<f64>> = Vec::new();
    for c in 0..x.r {
        let mut v: Vec<f64> = x.data[c * rows..(c + 1) * rows].to_vec();
        let before = v.iter().map(|a| a * a).sum::<f64>().sqrt();
        for _pass in 0..2 {
            for u in &basis {
                let k: f64 = v.iter().zip(u).map(|(a, b)| a * b).sum();
                v.iter_mut().zip(u).for_each(|(a, b)| *a -= k * b);
            }
        }
        let after = v.iter().map(|a| a * a).sum::<f64>().sqrt();
        if after > 1e-8 * before.max(f64::MIN_POSITIVE) && after > 0.0 {
            basis.push(v.iter().map(|a| a / after).collect());
        }
    }
    basis
}

/// The shift `−Λ_i + s I` of every rotation block.
pub(super) fn shifted(lambda: &[Block], d: usize, s: f64) -> Vec<Block> {
    lambda
        .iter()
        .map(|l| {
            std::array::from_fn(|a| {
                std::array::from_fn(|b| -l[a][b] + if a == b && a < d { s } else { 0.0 })
            })
        })
        .collect()
}

/// The certificate of `x`, a first-order critical point, with tolerance `tolerance`.
pub(super) fn certify(problem: &Reduced, x: &Stack, tolerance: f64) -> Verdict {
    let (d, n) = (problem.d, problem.n);
    let (_, qx) = problem.cost(x);
    let lambda = multipliers(x, &qx);
    let basis = column_space(x);
    let times_s = |v: &[f64]| {
        let v = Stack { d, n, r: 1, data: v.to_vec() };
        let mut sv = problem.apply(&v);
        sv.subtract_block_products(&lambda, &v);
        sv.data
    };
    // λ on span(X): 0 at an exactly critical point.
    let on_x = basis
        .iter()
        .map(|u| u.iter().zip(times_s(u)).map(|(a, b)| a * b).sum::<f64>())
        .fold(f64::INFINITY, f64::min);
    let positive = problem.factor_shifted(&shifted(&lambda, d, tolerance));
    let certified = positive.is_some();
    // A shift σ below every eigenvalue of S: −tol when certified, else −tol · 4^k for the first k
    // at which S − σ I factors (σ within a factor 4 of λ_min: Lanczos converges fast).
    let mut found = positive.map(|f| (-tolerance, f));
    let mut sigma = -tolerance;
    for _ in 0..80 {
        if found.is_some() {
            break;
        }
        sigma *= 4.0;
        found = problem.factor_shifted(&shifted(&lambda, d, -sigma)).map(|f| (sigma, f));
    }
    let Some((sigma, factor)) = found else {
        return Verdict { lambda_min: f64::NAN, certified, vector: None };
    };
    let ritz = lanczos::largest(
        d * n,
        |v, out| {
            let z = problem.solve_shifted(&factor, &Stack { d, n, r: 1, data: v.to_vec() });
            out.copy_from_slice(&z.data);
        },
        &basis,
        1,
        300,
        1e-8,
    );
    let (off_x, vector) = match (ritz.values.first(), ritz.vectors.into_iter().next()) {
        (Some(&theta), Some(v)) => (sigma + 1.0 / theta, Some(v)),
        _ => (f64::INFINITY, None),
    };
    Verdict { lambda_min: on_x.min(off_x), certified, vector }
}

/// The saddle escape: `[X 0] + α [0 v]` retracted, from `α = √n` halved until `F` falls below its
/// value at `X` (at most 60 halvings); `None` if it never does.
pub(super) fn escape(problem: &Reduced, x: &Stack, v: &[f64]) -> Option<Stack> {
    let wide = x.widened(1);
    let (f, _) = problem.cost(x);
    let mut direction = Stack::zeros(x.d, x.n, x.r + 1);
    let rows = x.rows();
    direction.data[x.r * rows..].copy_from_slice(v);
    let mut alpha = (x.n as f64).sqrt();
    for _ in 0..60 {
        let trial = retract(&wide, &direction.scaled(alpha));
        let (value, _) = problem.cost(&trial);
        if value < f {
            return Some(trial);
        }
        alpha /= 2.0;
    }
    None
}
