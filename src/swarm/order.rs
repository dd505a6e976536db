//! How synchronised a swarm is (MATH.md, "The swarm"): the order parameter `R = |m|` of the mean
//! `m = (1/N) Σ q_j`, which is blind to nothing (`q` and `-q` cancel), and the sign-blind
//! `λ_max(Q)`, the largest eigenvalue of `Q = (1/N) Σ q_j q_jᵀ`, in `[1/4, 1]`.

use crate::average::{eigen, scatter};
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
    let n = quaternions.len() as f64;
    let q = scatter(quaternions, None).map(|row| row.map(|c| c / n));
    eigen(q).0[0]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::quaternion::from_wxyz;

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
