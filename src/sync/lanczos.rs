//! The largest eigenvalues of a symmetric operator, by Lanczos with full reorthogonalisation
//! (Golub and Van Loan, §10.1; Parlett, "The Symmetric Eigenvalue Problem", ch. 13).
//!
//! The operator here is always an inverse, `(A − σ I)⁻¹` through a sparse Cholesky factor, so the
//! wanted eigenvalues of `A` (those nearest the shift `σ`) are the operator's largest and
//! best separated: a few dozen steps converge them. The basis is kept and every new vector is
//! orthogonalised against all of it (and against a given deflation space) twice: no spurious
//! copies, and a Ritz vector as accurate as its residual says.

use faer::{Mat, Side};

use crate::swarm::Random;

/// Eigenpairs `(θ, v)` of the operator, largest `θ` first.
pub(crate) struct Ritz {
    pub values: Vec<f64>,
    pub vectors: Vec<Vec<f64>>,
    /// Lanczos steps taken.
    pub steps: usize,
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// `v` minus its projections on `basis` and then on `deflate`, twice ("twice is enough",
/// Parlett). The deflation space comes last in each pass: the operator amplifies what is left of
/// it (by `1/τ` for a shifted inverse), and the basis vectors carry rounding in it.
fn orthogonalise(v: &mut [f64], basis: &[Vec<f64>], deflate: &[Vec<f64>]) {
    for _pass in 0..2 {
        for u in basis.iter().chain(deflate) {
            let c = dot(v, u);
            v.iter_mut().zip(u).for_each(|(x, y)| *x -= c * y);
        }
    }
}

/// The `wanted` largest eigenpairs of the symmetric operator `apply` (`y = A x`) on the
/// orthogonal complement of `deflate` (orthonormal vectors), each to a residual
/// `‖A v − θ v‖ ≤ tolerance · |θ|`, in at most `max_steps` steps.
pub(crate) fn largest(
    dimension: usize,
    mut apply: impl FnMut(&[f64], &mut [f64]),
    deflate: &[Vec<f64>],
    wanted: usize,
    max_steps: usize,
    tolerance: f64,
) -> Ritz {
    let room = dimension.saturating_sub(deflate.len());
    let max_steps = max_steps.min(room).max(1);
    let wanted = wanted.min(room);
    let mut random = Random::new(0x5eed_1a2c);
    let mut v: Vec<f64> = (0..dimension).map(|_| random.gaussian()).collect();
    orthogonalise(&mut v, &[], deflate);
    let mut basis: Vec<Vec<f64>> = Vec::new();
    let (mut alpha, mut beta): (Vec<f64>, Vec<f64>) = (Vec::new(), Vec::new());
    let mut w = vec![0.0; dimension];
    let mut result = Ritz { values: Vec::new(), vectors: Vec::new(), steps: 0 };
    for step in 0..max_steps {
        let norm = dot(&v, &v).sqrt();
        if norm.is_nan() || norm <= 0.0 {
            break;
        }
        v.iter_mut().for_each(|x| *x /= norm);
        if step > 0 {
            beta.push(norm);
        }
        basis.push(std::mem::take(&mut v));
        apply(&basis[step], &mut w);
        alpha.push(dot(&w, &basis[step]));
        let mut next = w.clone();
        orthogonalise(&mut next, &basis, deflate);
        let residual = dot(&next, &next).sqrt();
        let last = step + 1 == max_steps
            || residual.is_nan()
            || residual <= 1e-14 * alpha[step].abs().max(1e-300);
        if last || (step + 1 >= wanted && (step + 1) % 4 == 0) {
            let (values, vectors, converged) = ritz(&alpha, &beta, residual, wanted, tolerance);
            if converged || last {
                result.values = values;
                result.vectors = vectors
                    .iter()
                    .map(|s| {
                        let mut x = vec![0.0; dimension];
                        for (c, b) in s.iter().zip(&basis) {
                            x.iter_mut().zip(b).for_each(|(xi, bi)| *xi += c * bi);
                        }
                        x
                    })
                    .collect();
                result.steps = step + 1;
                return result;
            }
        }
        v = next;
    }
    result
}

/// The `wanted` largest eigenpairs of the tridiagonal `T` (diagonal `alpha`, off-diagonal `beta`)
/// and whether each has converged: the residual of a Ritz pair is `residual · |s_last|`.
fn ritz(
    alpha: &[f64],
    beta: &[f64],
    residual: f64,
    wanted: usize,
    tolerance: f64,
) -> (Vec<f64>, Vec<Vec<f64>>, bool) {
    let k = alpha.len();
    let t = Mat::<f64>::from_fn(k, k, |r, c| match r.abs_diff(c) {
        0 => alpha[r],
        1 => beta[r.min(c)],
        _ => 0.0,
    });
    let Ok(eigen) = t.self_adjoint_eigen(Side::Lower) else {
        return (Vec::new(), Vec::new(), false);
    };
    let (s, u) = (eigen.S().column_vector(), eigen.U());
    let mut values = Vec::new();
    let mut vectors = Vec::new();
    let mut converged = true;
    for index in (0..k).rev().take(wanted) {
        let theta = s[index];
        converged &= residual * u[(k - 1, index)].abs() <= tolerance * theta.abs();
        values.push(theta);
        vectors.push((0..k).map(|r| u[(r, index)]).collect());
    }
    (values, vectors, converged)
}
