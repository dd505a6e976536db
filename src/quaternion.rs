//! Quaternion conventions: the paper writes `q = a + b i + c j + d k`, i.e. scalar first
//! `[w, x, y, z]`; glam stores `(x, y, z, w)`. This is the one place that converts between them,
//! and the one place that turns user input into a unit quaternion.

use glam::DQuat;

use crate::error::{KliError, non_finite};

/// `[w, x, y, z]` (scalar first, the paper's `a + b i + c j + d k`) to a glam quaternion.
#[inline]
pub fn from_wxyz([w, x, y, z]: [f64; 4]) -> DQuat {
    DQuat::from_xyzw(x, y, z, w)
}

/// A glam quaternion to `[w, x, y, z]` (scalar first).
#[inline]
pub fn to_wxyz(q: DQuat) -> [f64; 4] {
    [q.w, q.x, q.y, q.z]
}

/// Validates and normalises an input quaternion: 4 finite numbers, not all zero.
///
/// The components are first scaled by the largest magnitude, so inputs as small as `1e-300` or as
/// large as `1e300` normalise without underflow or overflow.
pub fn unit(name: &'static str, q: DQuat) -> Result<DQuat, KliError> {
    let wxyz = to_wxyz(q);
    if let Some(i) = wxyz.iter().position(|c| !c.is_finite()) {
        return Err(KliError::InvalidQuaternion {
            name: name.into(),
            problem: format!("component {i} is {}", non_finite(wxyz[i])),
        });
    }
    let largest = wxyz.iter().fold(0.0_f64, |m, c| m.max(c.abs()));
    if largest == 0.0 {
        return Err(KliError::InvalidQuaternion {
            name: name.into(),
            problem: "it has zero length".into(),
        });
    }
    let scaled = q * (1.0 / largest);
    // 1/largest overflows for subnormal `largest`; divide instead in that case.
    let scaled = if scaled.is_finite() { scaled } else { from_wxyz(wxyz.map(|c| c / largest)) };
    Ok(scaled * (1.0 / scaled.length()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trips_scalar_first() {
        let q = from_wxyz([1.0, 2.0, 3.0, 4.0]);
        assert_eq!((q.w, q.x, q.y, q.z), (1.0, 2.0, 3.0, 4.0));
        assert_eq!(to_wxyz(q), [1.0, 2.0, 3.0, 4.0]);
    }

    #[test]
    fn normalises_any_scale() {
        for scale in [1e-310, 1e-300, 1e-20, 1.0, 3.0, 1e20, 1e300] {
            let q = unit("p", from_wxyz([scale, -2.0 * scale, 2.0 * scale, 4.0 * scale])).unwrap();
            let expected = [0.2, -0.4, 0.4, 0.8];
            for (got, want) in to_wxyz(q).iter().zip(expected) {
                assert!((got - want).abs() < 1e-15, "scale {scale}: {got} vs {want}");
            }
            assert!((q.length() - 1.0).abs() < 1e-15);
        }
    }

    #[test]
    fn rejects_zero_and_non_finite() {
        let zero = unit("p", from_wxyz([0.0; 4])).unwrap_err().to_string();
        assert!(zero.starts_with("p ") && zero.contains("zero length"), "{zero}");
        let nan = unit("r", from_wxyz([1.0, f64::NAN, 0.0, 0.0])).unwrap_err().to_string();
        assert!(nan.starts_with("r ") && nan.contains("component 1 is NaN"), "{nan}");
        let inf = unit("r", from_wxyz([1.0, 0.0, 0.0, f64::INFINITY])).unwrap_err().to_string();
        assert!(inf.contains("component 3 is Infinity"), "{inf}");
    }
}
