//! The Hopf map S³ → S² (paper eq. 5):
//!
//! ```text
//! h(a, b, c, d) = (a² + b² - c² - d², 2(ad + bc), 2(bd - ac))
//! ```
//!
//! for `q = a + b i + c j + d k`. It is the image of the body x-axis `(1, 0, 0)` under the rotation
//! `q` (MATH.md, "The Hopf map"), so `h(q) = h(-q)`.

use glam::{DQuat, DVec3};

/// `h(q)` for a unit quaternion `q`. Total: unchecked, so any `q` gives `|q|²` times a point of
/// S² (NaN for NaN); normalise a caller's quaternion first ([`unit()`](crate::quaternion::unit)).
#[inline]
pub fn hopf(q: DQuat) -> DVec3 {
    let (a, b, c, d) = (q.w, q.x, q.y, q.z);
    DVec3::new(a * a + b * b - c * c - d * d, 2.0 * (a * d + b * c), 2.0 * (b * d - a * c))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::quaternion::from_wxyz;

    #[test]
    fn paper_end_points() {
        assert_eq!(hopf(from_wxyz([0.0, 0.0, 0.0, 1.0])), DVec3::new(-1.0, 0.0, 0.0));
        assert_eq!(hopf(from_wxyz([0.5; 4])), DVec3::new(0.0, 1.0, 0.0));
    }

    #[test]
    fn is_the_rotated_x_axis_and_ignores_sign() {
        let q = from_wxyz([0.3, -0.1, 0.7, 0.2]).normalize();
        assert!((hopf(q) - q * DVec3::X).length() < 1e-15);
        assert_eq!(hopf(q), hopf(-q));
        assert!((hopf(q).length() - 1.0).abs() < 1e-15);
    }

    #[test]
    fn fibre_rotations_about_x_do_not_move_the_point() {
        let q = from_wxyz([0.3, -0.1, 0.7, 0.2]).normalize();
        let spun = q * DQuat::from_rotation_x(1.234);
        assert!((hopf(q) - hopf(spun)).length() < 1e-15);
    }
}
