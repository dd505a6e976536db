//! The tangent space of the rotations at `q`, blind to signs: [`log_at`] is the rotation vector
//! (axis × angle) of the shorter rotation from `q` to `r`, in `q`'s body frame, and [`exp_at`]
//! goes back (`q · exp(v)`). The iterative means step in it (MATH.md, "Averaging rotations").

use glam::{DQuat, DVec3};

/// `log(q̄ r)` of the shorter of `±r`: a rotation vector of length `d(q, r)` in [0, π].
pub fn log_at(q: DQuat, r: DQuat) -> DVec3 {
    let u = q.conjugate() * r;
    let u = if u.w < 0.0 { -u } else { u };
    let v = DVec3::new(u.x, u.y, u.z);
    let sine = v.length();
    if sine == 0.0 {
        return DVec3::ZERO;
    }
    // The half angle by atan2, accurate at 0 and at π.
    v * (2.0 * sine.atan2(u.w) / sine)
}

/// `q · exp(v)`: `q` turned by `|v|` about `v` in its body frame, normalised.
pub fn exp_at(q: DQuat, v: DVec3) -> DQuat {
    let angle = v.length();
    if angle == 0.0 {
        return q;
    }
    let (sine, cosine) = (0.5 * angle).sin_cos();
    let axis = v * (sine / angle);
    (q * DQuat::from_xyzw(axis.x, axis.y, axis.z, cosine)).normalize()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn log_and_exp_undo_each_other_and_ignore_the_sign() {
        let q = DQuat::from_xyzw(0.1, -0.3, 0.5, 0.8).normalize();
        let r = DQuat::from_xyzw(-0.6, 0.2, 0.1, 0.7).normalize();
        let v = log_at(q, r);
        assert_eq!(v, log_at(q, -r));
        let back = exp_at(q, v);
        assert!((back - r).length().min((back + r).length()) < 1e-15, "{back:?} {r:?}");
        // Its length is the rotation angle between them: 2 acos|q·r|.
        assert!((v.length() - 2.0 * q.dot(r).abs().acos()).abs() < 1e-14);
        // A half turn about z from the identity: length π.
        assert!(
            (log_at(DQuat::IDENTITY, DQuat::from_xyzw(0.0, 0.0, 1.0, 0.0)).length()
                - std::f64::consts::PI)
                .abs()
                < 1e-15
        );
    }
}
