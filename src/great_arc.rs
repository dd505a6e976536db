//! The great circle of S³ from `p` to the target, in a frame that stays accurate when `p ≈ target`
//! and when `p ≈ -target` (MATH.md, "Closed form" and "Edge cases").
//!
//! Every point of the arc is `cos φ · target + sin φ · tangent`, where `φ` is its angle to the
//! target and `tangent` is the unit vector at the target pointing towards `p`. KLI and SLERP differ
//! only in how `φ` depends on time.

use glam::DQuat;

use crate::error::{ErrorKind, KliError};
use crate::quaternion::unit;

/// Below this length, `p - target` or `p + target` is rounding noise of the normalised inputs
/// (each component is within 2 ulp), not a direction.
pub(crate) const ROUNDING_NOISE: f64 = 4.0 * f64::EPSILON;

/// The arc from `start` (angle `angle` from the target) to `target` (angle 0).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GreatArc {
    start: DQuat,
    target: DQuat,
    tangent: DQuat,
    angle: f64,
    half_angle_tan: f64,
}

/// The end the flow and SLERP go to: `-r` when `shortest_path` and `p·r < 0` (the same rotation by
/// the shorter arc), else `r`.
#[inline]
pub fn choose_target(p: DQuat, r: DQuat, shortest_path: bool) -> DQuat {
    if shortest_path && p.dot(r) < 0.0 { -r } else { r }
}

impl GreatArc {
    /// The arc from unit `p` to unit `r` (or `-r`, see [`choose_target`]).
    ///
    /// Errors with [`ErrorKind::Antipodal`] about `shortest_path` when the target is `-p`: every great circle through `p`
    /// reaches it, and the flow `q' = r - (q·r) q` does not move at all.
    pub fn new(p: DQuat, r: DQuat, shortest_path: bool) -> Result<Self, KliError> {
        let target = choose_target(p, r, shortest_path);
        // Differences of nearly equal (or opposite) unit vectors are exact, so these two
        // lengths carry the angle to full precision at both ends: tan(φ0/2) = |p - t| / |p + t|.
        let difference = p - target;
        let sum = p + target;
        let (d, s) = (difference.length(), sum.length());
        if s <= ROUNDING_NOISE {
            let kind = ErrorKind::Antipodal { start: "p".into(), end: "r".into() };
            return Err(KliError::new("shortest_path", kind));
        }
        if d <= ROUNDING_NOISE {
            return Ok(Self { target, ..Self::at_point(p) });
        }
        // p - (p·t) t, written so the cancelling part is an exact difference or sum.
        let raw = if p.dot(target) >= 0.0 {
            difference + target * (0.5 * d * d)
        } else {
            sum - target * (0.5 * s * s)
        };
        let orthogonal = raw - target * (raw.dot(target) / target.length_squared());
        Ok(Self {
            start: p,
            target,
            tangent: orthogonal * (1.0 / orthogonal.length()),
            angle: 2.0 * d.atan2(s),
            half_angle_tan: d / s,
        })
    }

    /// The arc from `p` to `r` as given by a caller: both normalised first, an Error naming `p`
    /// or `r` when one is not a quaternion (see [`unit()`]), then [`GreatArc::new`]. KLI, its
    /// closed form and SLERP all start here.
    pub fn between(p: DQuat, r: DQuat, shortest_path: bool) -> Result<Self, KliError> {
        Self::new(unit("p", p)?, unit("r", r)?, shortest_path)
    }

    /// The arc of no length at `p` (every point of it is `p`).
    pub fn at_point(p: DQuat) -> Self {
        let zero = DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0);
        Self { start: p, target: p, tangent: zero, angle: 0.0, half_angle_tan: 0.0 }
    }

    /// The start `p`.
    #[inline]
    pub fn start(&self) -> DQuat {
        self.start
    }

    /// The end actually used: `r` or `-r`.
    #[inline]
    pub fn target(&self) -> DQuat {
        self.target
    }

    /// `φ0 ∈ [0, π)`, the angle in R⁴ between `p` and the target.
    #[inline]
    pub fn angle(&self) -> f64 {
        self.angle
    }

    /// `tan(φ0 / 2)`.
    #[inline]
    pub fn half_angle_tan(&self) -> f64 {
        self.half_angle_tan
    }

    /// The unit tangent at the target pointing towards `p` (zero when `p` is the target).
    #[inline]
    pub fn tangent(&self) -> DQuat {
        self.tangent
    }

    /// The point of the great circle at angle `φ` from the target, given as `(sin φ, cos φ)`.
    #[inline]
    pub fn point(&self, sin: f64, cos: f64) -> DQuat {
        self.target * cos + self.tangent * sin
    }

    /// The point at angle `φ` from the target (towards `p`).
    #[inline]
    pub fn point_at_angle(&self, phi: f64) -> DQuat {
        let (sin, cos) = crate::trig::sin_cos(phi);
        self.point(sin, cos)
    }

    /// `||target - p||` in R⁴, `= 2 sin(φ0/2)`.
    #[inline]
    pub fn start_distance(&self) -> f64 {
        crate::quaternion::norm(self.target - self.start)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::quaternion::{from_wxyz, unit};

    fn arc(p: [f64; 4], r: [f64; 4], shortest: bool) -> GreatArc {
        GreatArc::new(unit("p", from_wxyz(p)).unwrap(), unit("r", from_wxyz(r)).unwrap(), shortest)
            .unwrap()
    }

    #[test]
    fn paper_example_angle_is_pi_over_3() {
        let a = arc([0.0, 0.0, 0.0, 1.0], [0.5; 4], true);
        assert!((a.angle() - std::f64::consts::FRAC_PI_3).abs() < 1e-15);
        assert!((a.half_angle_tan() - (std::f64::consts::FRAC_PI_6).tan()).abs() < 1e-15);
        // The frame is orthonormal and reproduces p at φ0.
        assert!(a.tangent().dot(a.target()).abs() < 1e-16);
        assert!((a.tangent().length() - 1.0).abs() < 1e-15);
        let p = a.point_at_angle(a.angle());
        assert!((p - from_wxyz([0.0, 0.0, 0.0, 1.0])).length() < 1e-15);
    }

    #[test]
    fn target_follows_shortest_path() {
        let p = [1.0, 0.0, 0.0, 0.0];
        let r = [-0.6, 0.8, 0.0, 0.0];
        assert!((arc(p, r, true).target() - from_wxyz([0.6, -0.8, 0.0, 0.0])).length() < 1e-15);
        assert!((arc(p, r, false).target() - from_wxyz(r)).length() < 1e-15);
        assert!((arc(p, r, true).angle() - 0.6_f64.acos()).abs() < 1e-15);
        assert!((arc(p, r, false).angle() - (-0.6_f64).acos()).abs() < 1e-15);
    }

    #[test]
    fn antipodal_long_way_is_an_equilibrium() {
        let p = unit("p", from_wxyz([0.1, 0.2, 0.3, 0.4])).unwrap();
        let r = unit("r", from_wxyz([-0.3, -0.6, -0.9, -1.2])).unwrap();
        let e = GreatArc::new(p, r, false).unwrap_err();
        assert_eq!((e.argument(), e.kind().code()), ("shortest_path", "antipodal"));
        // The short way, -r = p: nothing to do.
        let a = GreatArc::new(p, r, true).unwrap();
        assert_eq!(a.angle(), 0.0);
    }

    #[test]
    fn near_antipodal_frame_is_orthonormal() {
        let e = 1e-12;
        let a = arc([1.0, 0.0, 0.0, 0.0], [-1.0, e, 0.0, 0.0], false);
        assert!((a.angle() - (std::f64::consts::PI - e)).abs() < 1e-15);
        assert!(a.tangent().dot(a.target()).abs() < 1e-15);
        // The direction towards p from the target is along -x's complement: the j-free plane.
        let mid = a.point_at_angle(std::f64::consts::FRAC_PI_2);
        assert!((mid.length() - 1.0).abs() < 1e-15);
        assert!((mid.x.abs() - 1.0).abs() < 1e-12, "{mid:?}");
    }

    #[test]
    fn near_identical_frame_is_accurate() {
        let e = 1e-12;
        let a = arc([1.0, 0.0, 0.0, 0.0], [1.0, 0.0, e, 0.0], true);
        assert!((a.angle() - e).abs() < 1e-24);
        // Tangent at r towards p: -j, tilted by e towards 1.
        assert!((a.tangent() - from_wxyz([e, 0.0, -1.0, 0.0])).length() < 1e-15);
    }

    /// `‖target − p‖ = 2 sin(φ0/2)`, from the chord of each angle; and at `p·r = 0` exactly the
    /// target stays `r` (the rule flips only for `p·r < 0`).
    #[test]
    fn start_distance_is_the_chord_and_a_right_angle_keeps_r() {
        for phi in [1e-9_f64, 0.3, 1.0, 2.0, 3.1] {
            let (p, r) = ([1.0, 0.0, 0.0, 0.0], [phi.cos(), 0.0, phi.sin(), 0.0]);
            let a = arc(p, r, false);
            assert!((a.start_distance() - 2.0 * (phi / 2.0).sin()).abs() < 1e-15, "φ0 = {phi}");
        }
        let (p, r) = (from_wxyz([1.0, 0.0, 0.0, 0.0]), from_wxyz([0.0, 1.0, 0.0, 0.0]));
        assert_eq!(choose_target(p, r, true), r);
        assert_eq!(choose_target(p, -r, true), -r);
        assert_eq!(
            choose_target(p, from_wxyz([-0.1, 1.0, 0.0, 0.0]), true),
            from_wxyz([0.1, -1.0, 0.0, 0.0])
        );
    }
}
