//! The exact solution of the model (MATH.md, "Closed form"): along the great circle from `p` to
//! the target, the angle `φ(t)` to the target obeys `φ' = -sin φ`, so
//!
//! ```text
//! tan(φ(t)/2) = tan(φ0/2) · e^(-t)
//! q(t) = cos φ(t) · target + sin φ(t) · tangent  =  Slerp(p, target; s(t)),  s(t) = 1 - φ(t)/φ0
//! ```
//!
//! With `u = tan(φ/2)`, `sin φ = 2u/(1+u²)` and `cos φ = (1-u²)/(1+u²)`: no inverse trigonometry
//! per sample.

use glam::DQuat;

use crate::error::{KliError, Requirement, require};
use crate::great_arc::GreatArc;

/// `q(t)` on `arc` for `t ≥ 0`; `q(0)` is the start, exactly. Total: `t` is not checked (NaN
/// gives NaN); [`kli_exact`] is the checked call.
#[inline]
pub fn point_at(arc: &GreatArc, t: f64) -> DQuat {
    if t == 0.0 {
        return arc.start();
    }
    point_from_half_angle_tan(arc, arc.half_angle_tan() * (-t).exp())
}

/// The point whose angle `φ` to the target has `tan(φ/2) = u`.
#[inline]
pub fn point_from_half_angle_tan(arc: &GreatArc, u: f64) -> DQuat {
    let u2 = u * u;
    let inv = 1.0 / (1.0 + u2);
    arc.point(2.0 * u * inv, (1.0 - u2) * inv)
}

/// `φ(t) = 2 atan(tan(φ0/2) e^(-t))`, the angle between `q(t)` and the target.
#[inline]
pub fn angle_at(arc: &GreatArc, t: f64) -> f64 {
    2.0 * (arc.half_angle_tan() * (-t).exp()).atan()
}

/// The time warp `s(t) = 1 - φ(t)/φ0 ∈ [0, 1)`: `q(t) = Slerp(p, target; s(t))`.
///
/// When `p` is the target, `φ0 = 0` and this is the limit `1 - e^(-t)`.
pub fn time_warp(arc: &GreatArc, t: f64) -> f64 {
    let u0 = arc.half_angle_tan();
    if u0 == 0.0 {
        return -(-t).exp_m1();
    }
    1.0 - (u0 * (-t).exp()).atan() / u0.atan()
}

/// `T* = ln( tan(φ0/2) / tan(arcsin(ε/2)) )`, the first time `||target - q(t)|| < ε`
/// (`||target - q|| = 2 sin(φ/2)`); `0` when `p` is already closer than `ε`.
pub fn reach_time(arc: &GreatArc, tolerance: f64) -> f64 {
    if arc.start_distance() < tolerance {
        return 0.0;
    }
    let x = 0.5 * tolerance;
    // ln(tan(arcsin x)) as logarithms, so a subnormal ε (whose half rounds to 0) gives a finite
    // time, not ln(·/0) = ∞.
    let ln_tan_half = tolerance.ln() - std::f64::consts::LN_2 - 0.5 * ((1.0 - x) * (1.0 + x)).ln();
    (arc.half_angle_tan().ln() - ln_tan_half).max(0.0)
}

/// The exact KLI solution `q(t)` from `p` towards `r` (or `-r` when `shortest_path` and
/// `p·r < 0`); inputs are normalised.
pub fn kli_exact(p: DQuat, r: DQuat, t: f64, shortest_path: bool) -> Result<DQuat, KliError> {
    let t = require("t", t, Requirement::NonNegative)?;
    Ok(point_at(&GreatArc::between(p, r, shortest_path)?, t))
}

/// The SLERP parameter `s(t)` at KLI time `t`: `kli_exact(p, r, t) = slerp(p, r, s(t))`.
pub fn kli_to_slerp_parameter(
    p: DQuat,
    r: DQuat,
    t: f64,
    shortest_path: bool,
) -> Result<f64, KliError> {
    let t = require("t", t, Requirement::NonNegative)?;
    Ok(time_warp(&GreatArc::between(p, r, shortest_path)?, t))
}

/// The predicted reach time `T*` for `tolerance` (see [`reach_time`]).
pub fn kli_reach_time(
    p: DQuat,
    r: DQuat,
    tolerance: f64,
    shortest_path: bool,
) -> Result<f64, KliError> {
    let tolerance = require("tolerance", tolerance, Requirement::Positive)?;
    Ok(reach_time(&GreatArc::between(p, r, shortest_path)?, tolerance))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::quaternion::from_wxyz;
    use std::f64::consts::FRAC_PI_3;

    fn paper() -> (DQuat, DQuat) {
        (from_wxyz([0.0, 0.0, 0.0, 1.0]), from_wxyz([0.5; 4]))
    }

    #[test]
    fn paper_reach_time_is_11_6568() {
        let (p, r) = paper();
        let t = kli_reach_time(p, r, 1e-5, true).unwrap();
        // MATH.md: T* = 11.6568; recomputed here from the formula with plain trigonometry.
        let expected = ((FRAC_PI_3 / 2.0).tan() / (5e-6_f64).asin().tan()).ln();
        assert!((t - expected).abs() < 1e-12);
        assert!((t - 11.6568).abs() < 5e-5);
    }

    #[test]
    fn exact_solution_satisfies_the_ode() {
        // Central difference of q(t) against r - (q·r) q.
        let (p, r) = paper();
        let h = 1e-5;
        for t in [0.1, 0.5, 1.0, 3.0, 8.0] {
            let q = kli_exact(p, r, t, true).unwrap();
            let dq = (kli_exact(p, r, t + h, true).unwrap()
                - kli_exact(p, r, t - h, true).unwrap())
                * (0.5 / h);
            assert!((dq - crate::model::velocity(q, r)).length() < 1e-9, "t = {t}");
        }
    }

    #[test]
    fn warp_maps_onto_slerp_angle() {
        let (p, r) = paper();
        let a = GreatArc::between(p, r, true).unwrap();
        assert_eq!(time_warp(&a, 0.0), 0.0);
        for t in [0.2, 1.0, 5.0] {
            let s = time_warp(&a, t);
            assert!(((1.0 - s) * FRAC_PI_3 - angle_at(&a, t)).abs() < 1e-15);
        }
        assert!((time_warp(&a, 50.0) - 1.0).abs() < 1e-15);
    }

    #[test]
    fn identical_ends() {
        let (p, _) = paper();
        assert_eq!(kli_exact(p, p, 3.0, true).unwrap(), p);
        assert_eq!(kli_reach_time(p, p, 1e-5, true).unwrap(), 0.0);
        assert!(
            (kli_to_slerp_parameter(p, p, 1.0, true).unwrap() - (1.0 - (-1.0_f64).exp())).abs()
                < 1e-15
        );
    }

    #[test]
    fn rejects_bad_time_and_tolerance() {
        let (p, r) = paper();
        for t in [-1e-9, f64::NAN, f64::INFINITY] {
            assert!(kli_exact(p, r, t, true).unwrap_err().to_string().starts_with("t must be"));
        }
        for eps in [0.0, -1.0, f64::NAN] {
            assert!(
                kli_reach_time(p, r, eps, true)
                    .unwrap_err()
                    .to_string()
                    .starts_with("tolerance must be")
            );
        }
    }
}
