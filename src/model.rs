//! The Kuramoto–Lohe model of the paper, `q' = -1/2 (q r̄ q - r)` (eq. 3), written for unit `q` as
//!
//! ```text
//! q' = r - (q·r) q        (MATH.md, "The model")
//! ```
//!
//! the projection of `r` onto the tangent space of S³ at `q`: the gradient flow of `q·r`.
//! The paper's component form (eq. 4) prints an extra `- q_i`; that is a typo (MATH.md).

use glam::DQuat;

use crate::error::{KliError, Requirement, require, rust_number};
use crate::quaternion::unit;

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

/// The most RK4 steps [`integrate_as_printed`] takes in one call (as Algorithm 1's
/// [`MAX_SAMPLES`](crate::algorithm::MAX_SAMPLES)): a bound on its work.
pub const MAX_PRINTED_STEPS: usize = 1_000_000;

/// Eq. 4 as printed, integrated from `p` by classical RK4 with step `step`, sampled at each of
/// `times` (non-decreasing, finite, ≥ 0; the last step to a time is shortened to land on it).
/// Shows what the typo does: `|q|` leaves 1 and `q` settles at `r / (1 + c)`, `c = (√5 - 1)/2`,
/// where the printed field vanishes (`q(1 + q·r) = r` gives `c² + c = 1` for `c = q·r`), so
/// `|q| → c`.
///
/// `p` and `r` are normalised. Errors name the argument: `p` or `r` not a quaternion, `step` not
/// finite and > 0, `times[i]` negative, not finite or below `times[i-1]`, and `step` when the
/// last time takes more than [`MAX_PRINTED_STEPS`] steps (so no call runs unbounded) or is so
/// large that a step overflows.
pub fn integrate_as_printed(
    p: DQuat,
    r: DQuat,
    step: f64,
    times: &[f64],
) -> Result<Vec<DQuat>, KliError> {
    let (p, r) = (unit("p", p)?, unit("r", r)?);
    let step = require("step", step, Requirement::Positive)?;
    let mut previous = 0.0;
    for (i, &t) in times.iter().enumerate() {
        let name = || format!("times[{i}]");
        require("times", t, Requirement::NonNegative).map_err(|e| e.renamed(name()))?;
        if t < previous {
            let problem = format!("must be at least times[{}] (non-decreasing times)", i - 1);
            return Err(KliError::invalid(name(), problem));
        }
        previous = t;
    }
    // Also the guarantee of progress: with at most MAX_PRINTED_STEPS steps to the last time,
    // `step` is at least 1e-6 of every time reached, so `t + step > t` in the loop below.
    let steps = (previous / step).ceil();
    if steps > MAX_PRINTED_STEPS as f64 {
        let problem = format!(
            "is too small for times: {} steps to {}, more than the {MAX_PRINTED_STEPS} a call \
             may take",
            rust_number(steps),
            rust_number(previous)
        );
        return Err(KliError::invalid("step", problem));
    }
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
            if !q.is_finite() {
                let problem = format!(
                    "is too large: RK4 on eq. 4 as printed overflowed at t = {}",
                    rust_number(t)
                );
                return Err(KliError::invalid("step", problem));
            }
        }
        samples.push(q);
    }
    Ok(samples)
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
        let samples = integrate_as_printed(p, r, 0.01, &[0.0, 0.005, 1.0, 40.0]).unwrap();
        assert_eq!(samples[0], p);
        // One short step of 0.005 agrees with the field to first order.
        let expected = p + velocity_as_printed(p, r) * 0.005;
        assert!((samples[1] - expected).length() < 1e-4);
        assert!(samples[2].length() < 0.95, "|q(1)| = {}: it has left S³", samples[2].length());
        let c = (5.0_f64.sqrt() - 1.0) / 2.0;
        assert!((samples[3] - r / (1.0 + c)).length() < 1e-12, "{:?}", samples[3]);
        assert!(((r - samples[3]).length() - (1.0 - c)).abs() < 1e-12, "never within ε of r");
    }

    #[test]
    fn printed_form_refuses_what_would_not_end_and_names_the_argument() {
        let (p, r) = (from_wxyz([0.0, 0.0, 0.0, 1.0]), from_wxyz([0.5; 4]));
        let refused = |step: f64, times: &[f64]| {
            let e = integrate_as_printed(p, r, step, times).unwrap_err();
            (e.argument().to_owned(), e.to_string())
        };
        // The five hangs a probe found: steps 0, −0.01 and 1e-300, times ∞ and 1e300.
        for step in [0.0, -0.01, f64::NAN, f64::INFINITY] {
            assert_eq!(refused(step, &[1.0]).0, "step", "step {step}");
        }
        let (argument, message) = refused(1e-300, &[1.0]);
        assert_eq!(argument, "step");
        assert!(message.contains("steps to 1, more than the 1000000"), "{message}");
        assert_eq!(refused(0.01, &[f64::INFINITY]).0, "times[0]");
        let (argument, message) = refused(0.01, &[0.0, 1e300]);
        assert_eq!(argument, "step", "{message}");
        assert_eq!(refused(0.01, &[0.0, -1.0]).0, "times[1]");
        assert_eq!(refused(0.01, &[2.0, 1.0]).0, "times[1]");
        let (argument, message) = refused(1e308, &[1e308]);
        assert_eq!(argument, "step");
        assert!(message.contains("overflowed at t = 1e308"), "{message}");
        let nan = DQuat::from_xyzw(f64::NAN, 0.0, 0.0, 1.0);
        assert!(integrate_as_printed(nan, r, 0.01, &[1.0]).is_err());
        assert!(
            integrate_as_printed(p, DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0), 0.01, &[1.0]).is_err()
        );
        // At the bound exactly the call is allowed: 10⁶ steps of 1e-6 to t = 1.
        assert!(integrate_as_printed(p, r, 1e-6, &[1.0]).is_ok());
        assert_eq!(refused(1e-6, &[1.000001]).0, "step");
        // Equal times are allowed, and no times give no samples.
        assert_eq!(integrate_as_printed(p, r, 0.01, &[0.5, 0.5]).unwrap().len(), 2);
        assert!(integrate_as_printed(p, r, 0.01, &[]).unwrap().is_empty());
    }

    /// RK4 is of fourth order: halving the step shrinks the change at t = 1 sixteenfold (the
    /// differences of the answers at δ, δ/2 and δ/4, Richardson's test), where a wrong stage
    /// leaves a lower order.
    #[test]
    fn printed_form_by_rk4_is_of_fourth_order() {
        let (p, r) = (from_wxyz([0.0, 0.0, 0.0, 1.0]), from_wxyz([0.5; 4]));
        let at = |step: f64| integrate_as_printed(p, r, step, &[1.0]).unwrap()[0];
        let (a, b, c) = (at(0.2), at(0.1), at(0.05));
        let ratio = (a - b).length() / (b - c).length();
        assert!((13.0..19.0).contains(&ratio), "{ratio}");
    }

    /// A time between steps is reached by a shortened last step, and the next time goes on from
    /// it: the answers agree with a finer step's to RK4's error, not to a step's worth.
    #[test]
    fn printed_form_lands_on_each_time() {
        let (p, r) = (from_wxyz([0.0, 0.0, 0.0, 1.0]), from_wxyz([0.5; 4]));
        let coarse = integrate_as_printed(p, r, 0.1, &[0.25, 0.5]).unwrap();
        let fine = integrate_as_printed(p, r, 0.025, &[0.25, 0.5]).unwrap();
        let alone = integrate_as_printed(p, r, 0.1, &[0.5]).unwrap();
        assert!((coarse[0] - fine[0]).length() < 1e-5, "{:?}", coarse[0] - fine[0]);
        assert!((coarse[1] - fine[1]).length() < 1e-5, "{:?}", coarse[1] - fine[1]);
        assert!((coarse[1] - alone[0]).length() < 1e-5, "{:?}", coarse[1] - alone[0]);
    }
}
