//! Quaternion conventions: the paper writes `q = a + b i + c j + d k`, i.e. scalar first
//! `[w, x, y, z]`; glam stores `(x, y, z, w)`. This is the one place that converts between them,
//! and the one place that turns user input into a unit quaternion.

use glam::{DQuat, DVec3};

use crate::error::{ErrorKind, KliError, Shape};

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

/// `|q|²` in this range is computed without underflow or overflow: `|q|` is `√(|q|²)`.
const PLAIN: std::ops::Range<f64> = 1e-290..1e290;

/// Validates and normalises an input quaternion: 4 finite numbers, not all zero.
///
/// A quaternion whose `|q|²` already rounds to 1 is returned as it is, bit for bit (so unit
/// inputs come back unchanged from, say, SLERP at `s = 0`). Others are divided by `|q|`, which
/// for lengths as small as `1e-300` or as large as `1e300` is computed after scaling by the
/// largest component, without underflow or overflow.
pub fn unit(name: &str, q: DQuat) -> Result<DQuat, KliError> {
    match plain_inverse_square(q) {
        // Divided by |q|, not multiplied by 1/|q|: a unit input comes back bit for bit.
        Some(_) => Ok(q / q.length()),
        None => unit_rare(name, q),
    }
}

/// `1/|q|²` for nearly every input, `None` for the rest (which [`unit()`] refuses or scales
/// first): `q` finite (a NaN or ∞ component makes `|q|²` NaN or ∞) and `|q|²` far from under-
/// and overflow. A loop over a million quaternions inlines this test, and `q √(1/|q|²)` is `q`
/// normalised with one division.
#[inline(always)]
pub fn plain_inverse_square(q: DQuat) -> Option<f64> {
    let length_squared = q.length_squared();
    PLAIN.contains(&length_squared).then(|| 1.0 / length_squared)
}

/// [`unit()`] for the rest: refused (not finite, zero) or scaled first (tiny or huge).
#[inline(never)]
fn unit_rare(name: &str, q: DQuat) -> Result<DQuat, KliError> {
    let wxyz = to_wxyz(q);
    if let Some(index) = wxyz.iter().position(|c| !c.is_finite()) {
        let kind = ErrorKind::NotFinite { shape: Shape::Quaternion, index, value: wxyz[index] };
        return Err(KliError::new(name, kind));
    }
    let largest = wxyz.iter().fold(0.0_f64, |m, c| m.max(c.abs()));
    if largest == 0.0 {
        return Err(KliError::new(name, ErrorKind::ZeroLength { shape: Shape::Quaternion }));
    }
    let scaled = from_wxyz(wxyz.map(|c| c / largest));
    Ok(scaled / scaled.length())
}

/// `|q|` in R⁴ without underflow or overflow: a distance of `1e-312` is `1e-312`, not `0`.
pub fn norm(q: DQuat) -> f64 {
    let length_squared = q.length_squared();
    if PLAIN.contains(&length_squared) {
        return length_squared.sqrt();
    }
    let largest = to_wxyz(q).iter().fold(0.0_f64, |m, c| m.max(c.abs()));
    if largest == 0.0 || !largest.is_finite() {
        return largest;
    }
    largest * (q / largest).length()
}

/// `exp(v) = cos|v| + sin|v| v/|v|` of a pure quaternion `v` (given as its vector part): the
/// point of S³ at angle `|v|` from 1 in the direction `v`.
pub fn exp(v: DVec3) -> DQuat {
    let angle = v.length();
    if angle == 0.0 {
        return DQuat::IDENTITY;
    }
    let (sin, cos) = crate::trig::sin_cos(angle);
    let axis = v * (sin / angle);
    DQuat::from_xyzw(axis.x, axis.y, axis.z, cos)
}

/// `log(q)` of a unit quaternion, the inverse of [`exp`] on `w > -1`: `atan2(|v|, w) v/|v|` for
/// `q = w + v`, and 0 where `v = 0` (repeated keys, `q = 1`), not 0/0. `atan2` keeps its relative
/// accuracy as `|v| → 0`, so near 1 this is `v/w` to rounding with no series of its own.
pub fn log(q: DQuat) -> DVec3 {
    let v = DVec3::new(q.x, q.y, q.z);
    let s = v.length();
    if s == 0.0 {
        return DVec3::ZERO;
    }
    v * (s.atan2(q.w) / s)
}

/// The largest distance between two lists of rotations as quaternions, blind to each sign (the
/// dense references' tests, which faer and so the feature `sync` bring).
#[cfg(test)]
#[cfg(feature = "sync")]
pub(crate) fn farthest_apart(a: &[DQuat], b: &[DQuat]) -> f64 {
    a.iter().zip(b).map(|(&x, &y)| (x - y).length().min((x + y).length())).fold(0.0, f64::max)
}

/// Normalised quaternions whose `|q|²` is 1 exactly in f64 (glam's order of summation), from a
/// fixed seed: most normalised quaternions are.
#[cfg(test)]
pub(crate) fn exact_units(seed: u64, count: usize) -> Vec<[f64; 4]> {
    let mut state = seed;
    let mut next = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    };
    let mut out = Vec::new();
    while out.len() < count {
        let q = [next(), next(), next(), next()];
        let n = q.iter().map(|c| c * c).sum::<f64>().sqrt();
        let q = q.map(|c| c / n);
        if from_wxyz(q).length_squared() == 1.0 {
            out.push(q);
        }
    }
    out
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
        let zero = unit("p", from_wxyz([0.0; 4])).unwrap_err();
        assert_eq!(zero.argument(), "p");
        assert_eq!(zero.kind(), &ErrorKind::ZeroLength { shape: Shape::Quaternion });
        let nan = unit("r", from_wxyz([1.0, f64::NAN, 0.0, 0.0])).unwrap_err();
        assert_eq!((nan.argument(), nan.kind().component()), ("r", Some(1)));
        assert!(nan.to_string().ends_with("its x component is NaN"), "{nan}");
        let inf = unit("r", from_wxyz([1.0, 0.0, 0.0, f64::INFINITY])).unwrap_err();
        assert!(inf.to_string().ends_with("its z component is inf"), "{inf}");
    }

    #[test]
    fn unit_inputs_are_returned_bit_for_bit() {
        // Each has |q|² = 1 in f64 though |q| is not exactly 1 in exact arithmetic.
        for q in exact_units(0x2545_f491_4f6c_dd1d, 2000) {
            let q = from_wxyz(q);
            assert_eq!(unit("q", q).unwrap(), q);
        }
    }

    #[test]
    fn exp_and_log_invert_each_other() {
        let q = exp(DVec3::new(0.0, 0.0, std::f64::consts::FRAC_PI_2));
        assert!((q - from_wxyz([0.0, 0.0, 0.0, 1.0])).length() < 1e-15);
        assert_eq!(exp(DVec3::ZERO), DQuat::IDENTITY);
        for v in
            [DVec3::new(0.3, -1.2, 0.5), DVec3::new(1e-10, 0.0, -2e-10), DVec3::new(0.0, 3.0, 0.0)]
        {
            assert!((log(exp(v)) - v).length() < 1e-15 * (1.0 + v.length()), "{v:?}");
        }
        // glam's own: the rotation by 1.2 rad about z is exp of (0, 0, 0.6).
        let rotation = DQuat::from_rotation_z(1.2);
        assert!((log(rotation) - DVec3::new(0.0, 0.0, 0.6)).length() < 1e-15);
        assert_eq!(log(DQuat::IDENTITY), DVec3::ZERO);
        // Tiny rotations keep their relative accuracy (a few ulp, not 1e-15 absolute)…
        for size in [1e-8, 1e-10, 1e-30, 1e-150] {
            let v = DVec3::new(0.6, 0.0, -0.8) * size;
            let error = (log(exp(v)) - v).length() / size;
            assert!(error <= 4.0 * f64::EPSILON, "{size}: {error:e}");
        }
        // …and so do rotations 1e-9 short of a full turn, where `w ≈ -1` and `|v| ≈ 1e-9`.
        let v = DVec3::new(0.6, 0.0, -0.8) * (std::f64::consts::PI - 1e-9);
        assert!((log(exp(v)) - v).length() < 1e-15, "{:?}", log(exp(v)));
    }

    #[test]
    fn norm_does_not_underflow_or_overflow() {
        assert_eq!(norm(from_wxyz([0.0, 1e-312, 0.0, 0.0])), 1e-312);
        assert_eq!(norm(from_wxyz([3e-200, 4e-200, 0.0, 0.0])), 5e-200);
        let big = 2.0_f64.powi(700);
        assert_eq!(norm(from_wxyz([3.0 * big, 0.0, 4.0 * big, 0.0])), 5.0 * big);
        assert_eq!(norm(from_wxyz([0.0; 4])), 0.0);
        assert_eq!(norm(from_wxyz([0.5; 4])), 1.0);
    }
}
