//! The eigenvalues and eigenvectors of a symmetric 4×4 matrix, by cyclic Jacobi rotations: each
//! rotation zeroes one off-diagonal pair exactly, the sweeps converge quadratically, and the
//! result is accurate to rounding relative to the matrix's norm (also for close or repeated
//! eigenvalues, where the quartic's roots are not).

/// A symmetric 4×4 matrix, row by row.
pub type Symmetric4 = [[f64; 4]; 4];

/// The eigen-decomposition of `a`: eigenvalues in decreasing order, and the unit eigenvector of
/// each (`vectors[k]` belongs to `values[k]`).
pub fn eigen(mut a: Symmetric4) -> ([f64; 4], [[f64; 4]; 4]) {
    let mut v = [[0.0; 4]; 4];
    for (i, row) in v.iter_mut().enumerate() {
        row[i] = 1.0;
    }
    let scale: f64 = a.iter().flatten().map(|x| x * x).sum::<f64>().sqrt();
    for _sweep in 0..32 {
        let off: f64 = (0..4)
            .flat_map(|p| (p + 1..4).map(move |q| (p, q)))
            .map(|(p, q)| a[p][q] * a[p][q])
            .sum();
        if off.sqrt() <= 1e-300_f64.max(scale * 1e-17) {
            break;
        }
        for p in 0..4 {
            for q in p + 1..4 {
                if a[p][q] == 0.0 {
                    continue;
                }
                // The rotation in the (p, q) plane that zeroes a[p][q] (Golub and Van Loan,
                // Algorithm 8.4.1): t = tan θ, the smaller root.
                let theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
                let t = theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt());
                let c = 1.0 / (t * t + 1.0).sqrt();
                let s = t * c;
                // A ← Jᵀ A J: the columns p and q, then the rows; V ← V J.
                for row in a.iter_mut().chain(v.iter_mut()) {
                    let (xp, xq) = (row[p], row[q]);
                    row[p] = c * xp - s * xq;
                    row[q] = s * xp + c * xq;
                }
                let (row_p, row_q) = (a[p], a[q]);
                for k in 0..4 {
                    a[p][k] = c * row_p[k] - s * row_q[k];
                    a[q][k] = s * row_p[k] + c * row_q[k];
                }
            }
        }
    }
    let mut order = [0, 1, 2, 3];
    order.sort_by(|&i, &j| a[j][j].total_cmp(&a[i][i]));
    let values = order.map(|k| a[k][k]);
    let vectors = order.map(|k| [v[0][k], v[1][k], v[2][k], v[3][k]]);
    (values, vectors)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn times(a: &Symmetric4, x: &[f64; 4]) -> [f64; 4] {
        [0, 1, 2, 3].map(|i| (0..4).map(|j| a[i][j] * x[j]).sum())
    }

    #[test]
    fn a_diagonal_matrix_is_its_own_decomposition() {
        let a = [
            [1.0, 0.0, 0.0, 0.0],
            [0.0, 4.0, 0.0, 0.0],
            [0.0, 0.0, 0.0, 0.0],
            [0.0, 0.0, 0.0, 2.0],
        ];
        let (values, vectors) = eigen(a);
        assert_eq!(values, [4.0, 2.0, 1.0, 0.0]);
        assert_eq!(vectors[0], [0.0, 1.0, 0.0, 0.0]);
    }

    #[test]
    fn eigenpairs_of_a_dense_matrix_satisfy_a_v_equals_lambda_v() {
        // A symmetric matrix with the known eigenvalues 10, 3, 3, −1 (one repeated): Q diag Qᵀ
        // for the orthogonal Q of the Hadamard matrix / 2.
        let h = [
            [1.0, 1.0, 1.0, 1.0],
            [1.0, -1.0, 1.0, -1.0],
            [1.0, 1.0, -1.0, -1.0],
            [1.0, -1.0, -1.0, 1.0],
        ];
        let d = [10.0, 3.0, 3.0, -1.0];
        let a: Symmetric4 = [0, 1, 2, 3]
            .map(|i| [0, 1, 2, 3].map(|j| (0..4).map(|k| h[i][k] * d[k] * h[j][k] / 4.0).sum()));
        let (values, vectors) = eigen(a);
        for (value, expected) in values.iter().zip([10.0, 3.0, 3.0, -1.0]) {
            assert!((value - expected).abs() < 1e-14, "{values:?}");
        }
        for (value, vector) in values.iter().zip(&vectors) {
            let av = times(&a, vector);
            let norm: f64 = vector.iter().map(|x| x * x).sum::<f64>().sqrt();
            assert!((norm - 1.0).abs() < 1e-15);
            for i in 0..4 {
                assert!((av[i] - value * vector[i]).abs() < 1e-14, "{av:?} {value} {vector:?}");
            }
        }
    }
}
