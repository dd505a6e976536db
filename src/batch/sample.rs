//! One KLI path at many times: the closed form, with an even-step recurrence for evenly spaced
//! times (the page's animation and plots sample that way).

use glam::DQuat;

use crate::closed_form::point_from_half_angle_tan;
use crate::error::{ErrorKind, KliError, Requirement, require};
use crate::great_arc::GreatArc;

/// The step of times sampled evenly, when every `times[k]` is `times[0] + k·step` to rounding.
fn even_steps(times: &[f64]) -> Option<f64> {
    let (&first, &last) = (times.first()?, times.last()?);
    if times.len() < 3 {
        return None;
    }
    let step = (last - first) / (times.len() - 1) as f64;
    let even = times.iter().enumerate().all(|(k, &t)| {
        (t - (first + k as f64 * step)).abs() <= 8.0 * f64::EPSILON * (1.0 + t.abs())
    });
    even.then_some(step)
}

/// How many samples the even-step recurrence runs before it re-anchors on an exact `exp`, so
/// rounding in `u` stays within a few ulp.
const REANCHOR: usize = 32;

/// One KLI path from `p` towards `r`, at each of `times` (each finite and `≥ 0`), into `out`
/// (`4·times.len()` numbers). Evenly spaced times advance `e^(-t)` by a fixed factor.
pub fn kli_sample_into(
    p: DQuat,
    r: DQuat,
    times: &[f64],
    out: &mut [f64],
    shortest_path: bool,
) -> Result<(), KliError> {
    if out.len() != 4 * times.len() {
        let kind = ErrorKind::WrongLength {
            expected: 4 * times.len(),
            got: out.len(),
            per: "time".into(),
        };
        return Err(KliError::new("out", kind));
    }
    for (k, &t) in times.iter().enumerate() {
        require("t", t, Requirement::NonNegative).map_err(|e| e.renamed(format!("times[{k}]")))?;
    }
    let arc = GreatArc::between(p, r, shortest_path)?;
    let u0 = arc.half_angle_tan();
    match even_steps(times) {
        Some(step) => {
            let factor = (-step).exp();
            let mut u = 0.0;
            for (k, &t) in times.iter().enumerate() {
                u = if k % REANCHOR == 0 { u0 * (-t).exp() } else { u * factor };
                write(out, k, point(&arc, t, u));
            }
        }
        None => {
            for (k, &t) in times.iter().enumerate() {
                write(out, k, point(&arc, t, u0 * (-t).exp()));
            }
        }
    }
    Ok(())
}

/// The point at time `t`, with `u = tan(φ(t)/2)`; the start exactly at `t = 0`, as
/// [`crate::closed_form::point_at`] gives it.
#[inline]
fn point(arc: &GreatArc, t: f64, u: f64) -> DQuat {
    if t == 0.0 { arc.start() } else { point_from_half_angle_tan(arc, u) }
}

#[inline]
fn write(out: &mut [f64], k: usize, q: DQuat) {
    out[4 * k..4 * k + 4].copy_from_slice(&[q.w, q.x, q.y, q.z]);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::quaternion::{from_wxyz, to_wxyz};

    #[test]
    fn even_sampling_stays_within_1e12_of_the_plain_formula() {
        let (p, r) = (from_wxyz([0.0, 0.0, 0.0, 1.0]), from_wxyz([0.5; 4]));
        let times: Vec<f64> = (0..5000).map(|k| k as f64 * 0.004).collect();
        assert!(even_steps(&times).is_some());
        let mut out = vec![0.0; 4 * times.len()];
        kli_sample_into(p, r, &times, &mut out, true).unwrap();
        for (k, &t) in times.iter().enumerate() {
            // Plain formula: φ = 2 atan(tan(φ0/2) e^-t) and the SLERP form of MATH.md.
            let phi0 = std::f64::consts::FRAC_PI_3;
            let phi = 2.0 * ((phi0 / 2.0).tan() * (-t).exp()).atan();
            let expected = to_wxyz((p * phi.sin() + r * (phi0 - phi).sin()) * (1.0 / phi0.sin()));
            for c in 0..4 {
                assert!((out[4 * k + c] - expected[c]).abs() < 1e-12, "t = {t}");
            }
        }
        // Uneven times take the plain path; three even ones from anywhere, the recurrence.
        assert!(even_steps(&[0.0, 0.1, 0.3]).is_none());
        assert_eq!(even_steps(&[2.0, 2.5, 3.0]), Some(0.5));
        assert_eq!(even_steps(&[2.0, 2.5]), None);
        // Times written as `first + k·step` carry a rounding of an ulp or so of t (from 10.3 in
        // steps of 0.1: up to 0.13 of the tolerance 8 ε (1 + t)): still even.
        let written: Vec<f64> = (0..100).map(|k| 10.3 + k as f64 * 0.1).collect();
        assert!(even_steps(&written).is_some());
    }

    /// Uneven times, each by the closed form: against the plain formula.
    #[test]
    fn uneven_samples_are_the_plain_formula() {
        let (p, r) = (from_wxyz([0.0, 0.0, 0.0, 1.0]), from_wxyz([0.5; 4]));
        let times = [0.0, 0.1, 0.3, 1.7, 5.0, 0.2];
        assert!(even_steps(&times).is_none());
        let mut out = vec![0.0; 4 * times.len()];
        kli_sample_into(p, r, &times, &mut out, true).unwrap();
        let phi0 = std::f64::consts::FRAC_PI_3;
        for (k, &t) in times.iter().enumerate() {
            let phi = 2.0 * ((phi0 / 2.0).tan() * (-t).exp()).atan();
            let expected = to_wxyz((p * phi.sin() + r * (phi0 - phi).sin()) * (1.0 / phi0.sin()));
            for c in 0..4 {
                assert!((out[4 * k + c] - expected[c]).abs() < 1e-15, "t = {t}");
            }
        }
    }

    /// A million evenly spaced samples: the recurrence alone would carry a million roundings of
    /// `e^(-step)` (about 1e-10 by the end); re-anchored, each sample stays within a few ulp of
    /// the plain formula.
    #[test]
    fn a_million_even_samples_stay_within_ulps_of_the_plain_formula() {
        let (p, r) = (from_wxyz([0.0, 0.0, 0.0, 1.0]), from_wxyz([0.5; 4]));
        let n = 1_000_000;
        let times: Vec<f64> = (0..n).map(|k| k as f64 * 1e-6).collect();
        let mut out = vec![0.0; 4 * n];
        kli_sample_into(p, r, &times, &mut out, true).unwrap();
        let phi0 = std::f64::consts::FRAC_PI_3;
        let mut worst: f64 = 0.0;
        for (k, &t) in times.iter().enumerate() {
            let phi = 2.0 * ((phi0 / 2.0).tan() * (-t).exp()).atan();
            let expected = to_wxyz((p * phi.sin() + r * (phi0 - phi).sin()) * (1.0 / phi0.sin()));
            for c in 0..4 {
                worst = worst.max((out[4 * k + c] - expected[c]).abs());
            }
        }
        assert!(worst < 2e-15, "{worst:e}");
    }
}
