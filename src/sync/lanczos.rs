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

#[cfg(test)]
mod tests {
    use faer::{Mat, Side};

    use super::largest;
    use crate::swarm::Random;

    /// A symmetric 60×60 matrix `B Bᵀ / 60 + diag(k / 60)`, and its eigenpairs by faer's dense
    /// solver, largest first.
    fn matrix() -> (Mat<f64>, Vec<f64>, Vec<Vec<f64>>) {
        let n = 60;
        let mut random = Random::new(7);
        let b = Mat::<f64>::from_fn(n, n, |_, _| random.gaussian());
        let a = Mat::<f64>::from_fn(n, n, |r, c| {
            (0..n).map(|k| b[(r, k)] * b[(c, k)]).sum::<f64>() / n as f64
                + if r == c { r as f64 / n as f64 } else { 0.0 }
        });
        let eigen = a.self_adjoint_eigen(Side::Lower).unwrap();
        let (s, u) = (eigen.S().column_vector(), eigen.U());
        let values = (0..n).rev().map(|k| s[k]).collect();
        let vectors = (0..n).rev().map(|k| (0..n).map(|r| u[(r, k)]).collect()).collect();
        (a, values, vectors)
    }

    fn times(a: &Mat<f64>, x: &[f64], y: &mut [f64]) {
        for (r, out) in y.iter_mut().enumerate() {
            *out = (0..x.len()).map(|c| a[(r, c)] * x[c]).sum();
        }
    }

    /// The three largest eigenpairs, each to its residual `‖A v − θ v‖ ≤ 1e-10 |θ|`, against the
    /// dense solver; a step is one product with `A`, and the count says so.
    #[test]
    fn the_largest_eigenpairs_agree_with_a_dense_solver() {
        let (a, values, vectors) = matrix();
        let mut products = 0;
        let ritz = largest(
            60,
            |x, y| {
                products += 1;
                times(&a, x, y)
            },
            &[],
            3,
            60,
            1e-10,
        );
        assert_eq!(ritz.steps, products);
        assert!(ritz.steps < 60, "{}", ritz.steps);
        assert_eq!(ritz.values.len(), 3);
        let mut av = vec![0.0; 60];
        for k in 0..3 {
            assert!((ritz.values[k] - values[k]).abs() < 1e-9 * values[k], "{k}");
            let v = &ritz.vectors[k];
            times(&a, v, &mut av);
            let residual =
                av.iter().zip(v).map(|(p, q)| (p - ritz.values[k] * q).powi(2)).sum::<f64>();
            assert!(residual.sqrt() <= 1e-9 * values[k], "{k}: {}", residual.sqrt());
            // The eigenvector itself (up to its sign), of unit length.
            let along: f64 = v.iter().zip(&vectors[k]).map(|(p, q)| p * q).sum();
            assert!((along.abs() - 1.0).abs() < 1e-8, "{k}: {along}");
        }
    }

    /// Its tolerance is relative: the operator scaled by 1e4 or 1e-4 takes the same steps to the
    /// scaled values (the Krylov spaces are the same).
    #[test]
    fn the_tolerance_is_relative_to_the_values() {
        let (a, _, _) = matrix();
        let run = |scale: f64| {
            largest(
                60,
                |x, y| {
                    times(&a, x, y);
                    y.iter_mut().for_each(|v| *v *= scale);
                },
                &[],
                3,
                60,
                1e-10,
            )
        };
        let plain = run(1.0);
        for scale in [1e4, 1e-4] {
            let scaled = run(scale);
            assert_eq!(scaled.steps, plain.steps, "{scale}");
            for (p, q) in plain.values.iter().zip(&scaled.values) {
                assert!((q / scale - p).abs() < 1e-10 * p, "{scale}: {p} vs {q}");
            }
        }
    }

    /// Stopped by its step bound, it returns its best estimates all the same, after exactly that
    /// many products; on the complement of the top eigenvector, the largest is the second.
    #[test]
    fn the_step_bound_and_the_deflation() {
        let (a, values, vectors) = matrix();
        let mut products = 0;
        let short = largest(
            60,
            |x, y| {
                products += 1;
                times(&a, x, y)
            },
            &[],
            2,
            5,
            1e-14,
        );
        assert_eq!((short.steps, products), (5, 5));
        assert_eq!(short.values.len(), 2);
        // Ritz values from below: a five-step estimate is no larger than the eigenvalue.
        assert!(short.values[0] <= values[0] * (1.0 + 1e-12) && short.values[0] > 0.5 * values[0]);
        let deflated = largest(60, |x, y| times(&a, x, y), &vectors[..1], 1, 60, 1e-10);
        assert!((deflated.values[0] - values[1]).abs() < 1e-9 * values[1]);
    }

    /// `s (I + 2 u uᵀ)` has two distinct eigenvalues: its Krylov space from any start has two
    /// dimensions, so Lanczos ends after two steps with both, exactly, at any scale `s` (what is
    /// left after them is rounding, relative to the operator's size).
    #[test]
    fn an_exhausted_krylov_space_ends_the_run() {
        let n = 40;
        let u: Vec<f64> = (0..n).map(|k| ((k + 1) as f64).sqrt()).collect();
        let length = u.iter().map(|x| x * x).sum::<f64>().sqrt();
        let u: Vec<f64> = u.iter().map(|x| x / length).collect();
        for scale in [1.0, 1e6, 1e-6] {
            let apply = |x: &[f64], y: &mut [f64]| {
                let c: f64 = x.iter().zip(&u).map(|(p, q)| p * q).sum();
                y.iter_mut()
                    .zip(x)
                    .zip(&u)
                    .for_each(|((out, xi), ui)| *out = scale * (xi + 2.0 * c * ui));
            };
            let ritz = largest(n, apply, &[], 2, 40, 1e-12);
            assert_eq!(ritz.steps, 2, "{scale}");
            let [first, second] = [ritz.values[0] / scale, ritz.values[1] / scale];
            assert!(
                (first - 3.0).abs() < 1e-12 && (second - 1.0).abs() < 1e-12,
                "{scale}: {first}, {second}"
            );
        }
    }

    /// With no room left beside the deflation space there is nothing to find: no product, no
    /// value.
    #[test]
    fn no_room_no_product() {
        let axes: Vec<Vec<f64>> =
            (0..3).map(|k| (0..3).map(|r| if r == k { 1.0 } else { 0.0 }).collect()).collect();
        let mut products = 0;
        let ritz = largest(
            3,
            |x, y| {
                products += 1;
                y.copy_from_slice(x)
            },
            &axes,
            1,
            10,
            1e-10,
        );
        assert_eq!((ritz.steps, products, ritz.values.len()), (0, 0, 0));
    }
}
