//! The polar form of a unit quaternion (MATH.md, "Polar form"; the paper's Fig. 2):
//!
//! ```text
//! q = cos(θ/2) + U sin(θ/2),   θ = 2 atan2(|v|, w),   U = v / |v|    for q = w + v
//! ```
//!
//! `θ ∈ [0, 2π]`: `q` and `-q` give `θ` and `2π - θ` about opposite axes, the same rotation.
//! For `|v| = 0` the axis is arbitrary; `(1, 0, 0)` is returned.

use glam::{DQuat, DVec3};

use crate::error::{ErrorKind, KliError, Requirement, Shape, require};
use crate::quaternion::{from_wxyz, unit};

/// `(U, θ)` of the polar form; `q` is normalised first.
pub fn axis_angle(q: DQuat) -> Result<(DVec3, f64), KliError> {
    let q = unit("q", q)?;
    let v = DVec3::new(q.x, q.y, q.z);
    let length = v.length();
    let angle = 2.0 * length.atan2(q.w);
    if length == 0.0 {
        return Ok((DVec3::X, angle));
    }
    Ok((v / length, angle))
}

/// The unit quaternion `cos(θ/2) + U sin(θ/2)` of a rotation by `angle` about `axis` (normalised).
pub fn from_axis_angle(axis: DVec3, angle: f64) -> Result<DQuat, KliError> {
    if let Some(index) = axis.to_array().iter().position(|c| !c.is_finite()) {
        let kind = ErrorKind::NotFinite { shape: Shape::Vector3, index, value: axis[index] };
        return Err(KliError::new("axis", kind));
    }
    if axis == DVec3::ZERO {
        return Err(KliError::new("axis", ErrorKind::ZeroLength { shape: Shape::Vector3 }));
    }
    let angle = require("angle", angle, Requirement::Finite)?;
    // Scaled first so tiny and huge axes normalise without underflow or overflow.
    let scaled = axis / axis.abs().max_element();
    let u = scaled / scaled.length();
    let (sin, cos) = crate::trig::sin_cos(0.5 * angle);
    Ok(from_wxyz([cos, u.x * sin, u.y * sin, u.z * sin]))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::{FRAC_PI_2, PI};

    #[test]
    fn paper_end_points() {
        // p = k: a half turn about z.
        let (axis, angle) = axis_angle(from_wxyz([0.0, 0.0, 0.0, 1.0])).unwrap();
        assert_eq!((axis, angle), (DVec3::Z, PI));
        // r = (1 + i + j + k)/2: 120° about (1, 1, 1)/√3.
        let (axis, angle) = axis_angle(from_wxyz([0.5; 4])).unwrap();
        assert!((axis - DVec3::ONE / 3.0_f64.sqrt()).length() < 1e-15);
        assert!((angle - 2.0 * PI / 3.0).abs() < 1e-15);
    }

    #[test]
    fn identity_and_its_negative() {
        assert_eq!(axis_angle(from_wxyz([2.0, 0.0, 0.0, 0.0])).unwrap(), (DVec3::X, 0.0));
        assert_eq!(axis_angle(from_wxyz([-1.0, 0.0, 0.0, 0.0])).unwrap(), (DVec3::X, 2.0 * PI));
    }

    #[test]
    fn round_trips_through_glam() {
        let q = from_axis_angle(DVec3::new(1.0, -2.0, 2.0), 1.1).unwrap();
        let reference = DQuat::from_axis_angle(DVec3::new(1.0, -2.0, 2.0) / 3.0, 1.1);
        assert!((q - reference).length() < 1e-15);
        let (axis, angle) = axis_angle(q).unwrap();
        assert!((axis - DVec3::new(1.0, -2.0, 2.0) / 3.0).length() < 1e-15);
        assert!((angle - 1.1).abs() < 1e-15);
        // Within the core's sin/cos accuracy (crate::trig, 4e-16) of glam's std-based value.
        assert!(
            (from_axis_angle(DVec3::Y, FRAC_PI_2).unwrap() - DQuat::from_rotation_y(FRAC_PI_2))
                .length()
                < 4e-16
        );
    }

    #[test]
    fn rejects_bad_axis_and_angle() {
        let zero = from_axis_angle(DVec3::ZERO, 1.0).unwrap_err().to_string();
        assert!(zero.starts_with("axis must be 3 finite numbers"), "{zero}");
        let nan = from_axis_angle(DVec3::X, f64::NAN).unwrap_err().to_string();
        assert!(nan.starts_with("angle must be a finite number"), "{nan}");
        assert!(axis_angle(from_wxyz([0.0; 4])).unwrap_err().to_string().starts_with("q must be"));
    }

    /// An axis's length does not matter, down to subnormal and up to the largest `f64`: its
    /// square would underflow or overflow.
    #[test]
    fn tiny_and_huge_axes_give_the_same_rotation() {
        let reference = DQuat::from_axis_angle(DVec3::new(1.0, -2.0, 2.0) / 3.0, 1.1);
        for scale in [5e-324, 1e-300, 1e-160, 1e160, 1e300, 5e307] {
            let q = from_axis_angle(DVec3::new(1.0, -2.0, 2.0) * scale, 1.1).unwrap();
            assert!((q - reference).length() < 4e-16, "{scale}: {q:?}");
        }
    }
}
