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

/// Eq. 4 as printed, integrated from `p` by classical RK4 with step `step`, sampled at each of
/// `times` (increasing, ≥ 0; the last step to a time is shortened to land on it). Shows what the
/// typo does: `|q|` leaves 1 and `q` settles at `r / (1 + c)`, `c = (√5 - 1)/2`, where the
/// printed field vanishes (`q(1 + q·r) = r` gives `c² + c = 1` for `c = q·r`), so `|q| → c`.
pub fn integrate_as_printed(p: DQuat, r: DQuat, step: f64, times: &[f64]) -> Vec<DQuat> {
    let rk4 = |q: DQuat, h: f64| {
        let k1 = velocity_as_printed(q, r);
        let k2 = velocity_as_printed(q + k1 * (h / 2.0), r);
        let k3 = velocity_as_printed(q + k2 * (h / 2.0), r);
        let k4 = velocity_as_printed(q + k3 * h, r);
        q + (k1 + k2 * 2.0 + k3 * 2.0 + k4) * (h / 6.0)
    };
    let (mut q, mut t) = (p, 0.0);
    let mut samples = Vec::with_capacity(times.len());
    for &until in times {
        while t < until {
            let h = step.min(until - t);
            q = rk4(q, h);
            t = if until - t <= step { until } else { t + step };
        }
        samples.push(q);
    }
    samples
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

    #[test]
    fn printed_form_by_rk4_settles_at_r_over_one_plus_the_golden_ratio_conjugate() {
        let (p, r) = (from_wxyz([0.0, 0.0, 0.0, 1.0]), from_wxyz([0.5; 4]));
        let samples = integrate_as_printed(p, r, 0.01, &[0.0, 0.005, 1.0, 40.0]);
        assert_eq!(samples[0], p);
        // One short step of 0.005 agrees with the field to first order.
        let expected = p + velocity_as_printed(p, r) * 0.005;
        assert!((samples[1] - expected).length() < 1e-4);
        assert!(samples[2].length() < 0.95, "|q(1)| = {}: it has left S³", samples[2].length());
        let c = (5.0_f64.sqrt() - 1.0) / 2.0;
        assert!((samples[3] - r / (1.0 + c)).length() < 1e-12, "{:?}", samples[3]);
        assert!(((r - samples[3]).length() - (1.0 - c)).abs() < 1e-12, "never within ε of r");
    }
}
