//! Spherical linear interpolation (Shoemake 1985), `Slerp(p, r; s) = p (p⁻¹ r)^s`: the point of the
//! great circle from `p` to the target at angle `(1 - s) φ0` from the target.
//!
//! Built on [`GreatArc`], so it is accurate near `p ≈ r` and `p ≈ -r` and follows the same
//! `shortest_path` rule as KLI.

use glam::DQuat;

use crate::error::{KliError, Requirement, require};
use crate::great_arc::GreatArc;

/// The largest `|s|`: SLERP extrapolated a million times the arc's length is still accurate to
/// about `1e-9` (the angle `(1 - s) φ0` carries `|s|` ulps of rounding); far beyond it the angle
/// is rounding noise, and past `1e308` it overflows.
pub const MAX_PARAMETER: f64 = 1e6;

/// `Slerp(p, r; s)`; inputs are normalised. `s` outside `[0, 1]` extrapolates along the circle;
/// `|s| ≤` [`MAX_PARAMETER`]. At `s = 0` and `s = 1` the (normalised) ends come back exactly.
pub fn slerp(p: DQuat, r: DQuat, s: f64, shortest_path: bool) -> Result<DQuat, KliError> {
    let s = require("s", s, Requirement::AtMost(MAX_PARAMETER))?;
    Ok(point_at(&GreatArc::between(p, r, shortest_path)?, s))
}

/// The SLERP point of `arc` at parameter `s`. Total: `s` is not checked (a non-finite `s`
/// gives NaN); [`slerp()`] is the checked call.
#[inline]
pub fn point_at(arc: &GreatArc, s: f64) -> DQuat {
    if s == 0.0 {
        arc.start()
    } else if s == 1.0 {
        arc.target()
    } else {
        arc.point_at_angle((1.0 - s) * arc.angle())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::quaternion::{from_wxyz, unit};

    /// Shoemake's product form, `p (p⁻¹ r)^s`, through glam's axis–angle conversions.
    fn shoemake(p: DQuat, r: DQuat, s: f64) -> DQuat {
        let (axis, angle) = (p.conjugate() * r).to_axis_angle();
        p * DQuat::from_axis_angle(axis, angle * s)
    }

    #[test]
    fn matches_shoemake_product_form() {
        let p = unit("p", from_wxyz([0.3, -0.1, 0.7, 0.2])).unwrap();
        let r = unit("r", from_wxyz([0.5, 0.4, -0.2, 0.6])).unwrap();
        for s in [0.0, 0.1, 0.25, 0.5, 0.9, 1.0] {
            let got = slerp(p, r, s, true).unwrap();
            assert!((got - shoemake(p, r, s)).length() < 1e-12, "s = {s}");
        }
    }

    #[test]
    fn shortest_path_negates_the_far_end() {
        let p = from_wxyz([1.0, 0.0, 0.0, 0.0]);
        let r = from_wxyz([-0.6, 0.8, 0.0, 0.0]);
        // Short way: to -r = (0.6, -0.8): half way is the unit bisector of p and -r.
        let half = slerp(p, r, 0.5, true).unwrap();
        let bisector = (p - r) * (1.0 / (p - r).length());
        assert!((half - bisector).length() < 1e-15);
        // Long way: to r, through the bisector of p and r.
        let half_long = slerp(p, r, 0.5, false).unwrap();
        let bisector_long = (p + r) * (1.0 / (p + r).length());
        assert!((half_long - bisector_long).length() < 1e-15);
    }

    #[test]
    fn ends_are_exact_and_s_is_checked() {
        let p = unit("p", from_wxyz([0.3, -0.1, 0.7, 0.2])).unwrap();
        let r = unit("r", from_wxyz([0.5, 0.4, -0.2, 0.6])).unwrap();
        assert_eq!(slerp(p, r, 0.0, true).unwrap(), p);
        assert_eq!(slerp(p, r, 1.0, true).unwrap(), r);
        assert_eq!(slerp(p, -r, 1.0, true).unwrap(), r);
        assert_eq!(slerp(p, -r, 1.0, false).unwrap(), -r);
        assert!(slerp(p, r, f64::NAN, true).unwrap_err().to_string().starts_with("s must be"));
    }

    #[test]
    fn huge_parameters_are_refused_not_nan() {
        let p = from_wxyz([0.0, 0.0, 0.0, 1.0]);
        let r = from_wxyz([0.5; 4]);
        for s in [1e6 + 1.0, -2e6, 1e20, 1e300, f64::MAX, -f64::MAX] {
            let e = slerp(p, r, s, true).unwrap_err();
            assert_eq!(e.argument(), "s");
            assert!(
                e.to_string().starts_with("s must be a finite number from -1000000 to 1000000")
            );
        }
        // At the bound the answer is still the point at angle (1 - s) π/3 from r: 1e6 π/3
        // reduced by whole turns, computed independently with the period 6 of s.
        let far = slerp(p, r, 1e6, true).unwrap();
        let near = slerp(p, r, 1e6 % 6.0, true).unwrap();
        assert!((far - near).length() < 1e-9, "{far:?} vs {near:?}");
    }
}
