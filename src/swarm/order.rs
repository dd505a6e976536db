//! How synchronised a swarm is (MATH.md, "The swarm"): the order parameter `R = |m|` of the mean
//! `m = (1/N) Σ q_j`, which is blind to nothing (`q` and `-q` cancel), and the sign-blind
//! `λ_max(Q)`, the largest eigenvalue of `Q = (1/N) Σ q_j q_jᵀ`, in `[1/4, 1]`.

use glam::DQuat;

/// The mean `m = (1/N) Σ q_j` in R⁴ (zero for no quaternions).
pub fn mean(quaternions: &[DQuat]) -> DQuat {
    let sum = quaternions.iter().fold(DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0), |s, &q| s + q);
    if quaternions.is_empty() { sum } else { sum / quaternions.len() as f64 }
}

/// `R = |m| ∈ [0, 1]`: 1 when all agree (as quaternions), 0 when they balance.
pub fn order_parameter(quaternions: &[DQuat]) -> f64 {
    mean(quaternions).length()
}

/// `λ_max(Q)`, `Q = (1/N) Σ q qᵀ`: 1 when all are the same rotation (`q` or `-q`), 1/4 when
/// spread evenly over S³.
pub fn rotation_order(quaternions: &[DQuat]) -> f64 {
    if quaternions.is_empty() {
        return 0.0;
    }
    let mut q = [[0.0; 4]; 4];
    for p in quaternions {
        let v = [p.x, p.y, p.z, p.w];
        for (row, &a) in q.iter_mut().zip(&v) {
            for (cell, &b) in row.iter_mut().zip(&v) {
                *cell += a * b;
            }
        }
    }
    let n = quaternions.len() as f64;
    let q = q.map(|row| row.map(|c| c / n));
    largest_eigenvalue(q)
}

/// The largest eigenvalue of a symmetric 4×4 matrix, by cyclic Jacobi rotations (Golub and Van
/// Loan, Algorithm 8.5.3): each rotation zeroes one off-diagonal pair, and a few sweeps leave
/// the eigenvalues on the diagonal to rounding.
fn largest_eigenvalue(mut a: [[f64; 4]; 4]) -> f64 {
    for _ in 0..32 {
        let off: f64 = (0..4)
            .flat_map(|i| (0..4).filter(move |&j| j != i).map(move |j| (i, j)))
            .map(|(i, j)| a[i][j] * a[i][j])
            .sum();
        let scale: f64 = (0..4).map(|i| a[i][i] * a[i][i]).sum::<f64>() + off;
        if off <= 1e-32 * scale || off == 0.0 {
            break;
        }
        for p in 0..3 {
            for r in p + 1..4 {
                if a[p][r] == 0.0 {
                    continue;
                }
                // The rotation (c, s) that zeroes a[p][r].
                let theta = (a[r][r] - a[p][p]) / (2.0 * a[p][r]);
                let t = theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt());
                let t = if theta == 0.0 { 1.0 } else { t };
                let c = 1.0 / (t * t + 1.0).sqrt();
                let s = t * c;
                // A ← Jᵀ A J: columns p and r, then rows p and r.
                for row in a.iter_mut() {
                    let (akp, akr) = (row[p], row[r]);
                    row[p] = c * akp - s * akr;
                    row[r] = s * akp + c * akr;
                }
                let (row_p, row_r) = (a[p], a[r]);
                for k in 0..4 {
                    a[p][k] = c * row_p[k] - s * row_r[k];
                    a[r][k] = s * row_p[k] + c * row_r[k];
                }
            }
        }
    }
    (0..4).map(|i| a[i][i]).fold(f64::MIN, f64::max)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::quaternion::from_wxyz;

    #[test]
    fn jacobi_finds_known_eigenvalues() {
        // diag(1, 2, 3, 4) turned by a rotation in the (0, 1) and (2, 3) planes keeps its spectrum.
        let (c, s) = (0.6, 0.8);
        let a = [
            [c * c * 1.0 + s * s * 2.0, c * s * (2.0 - 1.0), 0.0, 0.0],
            [c * s * (2.0 - 1.0), s * s * 1.0 + c * c * 2.0, 0.0, 0.0],
            [0.0, 0.0, 3.5, 0.5],
            [0.0, 0.0, 0.5, 3.5],
        ];
        assert!((largest_eigenvalue(a) - 4.0).abs() < 1e-14);
        // The all-ones matrix has eigenvalues 4, 0, 0, 0.
        assert!((largest_eigenvalue([[1.0; 4]; 4]) - 4.0).abs() < 1e-14);
    }

    #[test]
    fn sign_blind_and_sign_aware_orders() {
        let q = from_wxyz([0.5; 4]);
        // q and -q: R = 0 though they are one rotation, λ_max = 1.
        assert_eq!(order_parameter(&[q, -q]), 0.0);
        assert!((rotation_order(&[q, -q]) - 1.0).abs() < 1e-15);
        // The four units 1, i, j, k: Q = I/4, so λ_max = 1/4; their mean has length 1/2.
        let units = [
            [1.0, 0.0, 0.0, 0.0],
            [0.0, 1.0, 0.0, 0.0],
            [0.0, 0.0, 1.0, 0.0],
            [0.0, 0.0, 0.0, 1.0],
        ]
        .map(from_wxyz);
        assert!((rotation_order(&units) - 0.25).abs() < 1e-15);
        assert!((order_parameter(&units) - 0.5).abs() < 1e-15);
    }
}
