//! The Kuramoto–Lohe model of the paper, `q' = -1/2 (q r̄ q - r)` (eq. 3), written for unit `q` as
//!
//! ```text
//! q' = r - (q·r) q        (MATH.md, "The model")
//! ```
//!
//! the projection of `r` onto the tangent space of S³ at `q`: the gradient flow of `q·r`.
//! The paper's component form (eq. 4) prints an extra `- q_i`; that is a typo (MATH.md).

use glam::DQuat;

/// The vector field `f(q) = r - (q·r) q`.
#[inline]
pub fn velocity(q: DQuat, r: DQuat) -> DQuat {
    r - q * q.dot(r)
}

/// The paper's eq. 4 exactly as printed, `q_i' = r_i - q_i - q_i cos θ`: kept only to show the
/// typo. It leaves S³ and settles at a point of norm `(√5 - 1)/2 ≈ 0.618`, never at `r`.
#[inline]
pub fn velocity_as_printed(q: DQuat, r: DQuat) -> DQuat {
    r - q - q * q.dot(r)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::quaternion::from_wxyz;

    #[test]
    fn velocity_is_tangent_and_matches_quaternion_form() {
        // Compare with eq. 3 evaluated with quaternion products: -1/2 (q r̄ q - r).
        let q = from_wxyz([0.5, -0.5, 0.5, 0.5]);
        let r = from_wxyz([0.0, 0.6, 0.0, 0.8]);
        let eq3 = (q * r.conjugate() * q - r) * -0.5;
        assert!((velocity(q, r) - eq3).length() < 1e-15);
        assert!(velocity(q, r).dot(q).abs() < 1e-15);
        assert_eq!(velocity(r, r).length(), 0.0);
    }

    #[test]
    fn printed_form_settles_off_the_sphere() {
        // Euler-integrate the printed eq. 4 far past convergence: |q| → 0.618, not 1.
        let r = from_wxyz([0.5; 4]);
        let mut q = from_wxyz([0.0, 0.0, 0.0, 1.0]);
        for _ in 0..20_000 {
            q = q + velocity_as_printed(q, r) * 0.01;
        }
        let golden = (5.0_f64.sqrt() - 1.0) / 2.0;
        assert!((q.length() - golden).abs() < 1e-9, "{}", q.length());
    }
}
