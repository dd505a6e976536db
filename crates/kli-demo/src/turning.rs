//! The turning rate of a curve of rotations, as the keyframes page and the tour's section 9
//! measure it: the world-frame angular velocity `ω` (`q′ = ½ ω q`, so `ω = 2 q′ q̄`:
//! [`Curve::angular_velocity`]) at sample times, its rate of change `|ω̇|` by central differences
//! of those samples, and its jump across a key, `ω(t⁺) − ω(t⁻)` (MATH.md, "Smoothness").

use glam::DVec3;
use kli::spline::Curve;

/// How far either side of a key [`jump`] reads `ω`: far past the step of
/// [`Curve::angular_velocity`]'s own difference (1e-6 of the span), so neither reading straddles
/// the key, and far inside a chain's sample interval (1/32 of a key interval), so a smooth curve's
/// reading differs by only `2·JUMP_STEP·|ω̇|`.
pub const JUMP_STEP: f64 = 1e-4;

/// `ω` at each of `times`.
pub fn angular_velocities(curve: &dyn Curve, times: &[f64]) -> Vec<DVec3> {
    times.iter().map(|&t| curve.angular_velocity(t)).collect()
}

/// `|ω̇|` at each sample of `omega` (samples `dt` apart): the central difference
/// `|ω_{k+1} − ω_{k−1}| / 2dt`, one-sided at the ends. Across a jump of `ω` it reads the jump over
/// `2dt`: a spike that grows without bound as the samples get closer.
pub fn accelerations(omega: &[DVec3], dt: f64) -> Vec<f64> {
    (0..omega.len())
        .map(|k| {
            let (a, b) = (k.saturating_sub(1), (k + 1).min(omega.len() - 1));
            if b == a { 0.0 } else { ((omega[b] - omega[a]) / ((b - a) as f64 * dt)).length() }
        })
        .collect()
}

/// The jump of `ω` across time `t`: `ω(t + h) − ω(t − h)`, `h` = [`JUMP_STEP`]. For piecewise
/// SLERP at an inner key it is the difference of the two pieces' constant rates; for a curve with
/// continuous `ω` it tends to 0 with `h`.
pub fn jump(curve: &dyn Curve, t: f64) -> DVec3 {
    curve.angular_velocity(t + JUMP_STEP) - curve.angular_velocity(t - JUMP_STEP)
}
