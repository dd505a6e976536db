//! Many rotations: curves through keyframes `k_0 … k_{m-1}` at times `t_0 < … < t_{m-1}`
//! (MATH.md, "Many rotations: the Kuramoto–Lohe chain"), the paper's open question.
//!
//! - [`KliSpline`]: the Kuramoto–Lohe chain. Dense samples, the keys pinned as leaders, the free
//!   ones at the equilibrium of the flow `x_j' = -P_{x_j} ∂E/∂x_j` of the energy
//!   `E = (α/2) Σ |x_{j+1} - x_j|²/h_j + (β/2) Σ w_j |D²x_j|²` (neighbours attract, second
//!   neighbours repel), found by Riemannian Newton; `smoothness = β` runs from piecewise SLERP
//!   (`0`) to the smoothest curve through the keys (`1`).
//! - [`Squad`]: Shoemake's spherical quadrangle, with helper points for uneven times, the usual
//!   smooth baseline; [`PiecewiseSlerp`], the other baseline; [`SequentialKli`], the paper's
//!   Algorithm 1 run key to key, its literal reading.
//!
//! Every curve is a [`Curve`]: `at(t)` clamps `t` to the key times, and the angular velocity is
//! the world-frame `ω` with `q' = ½ ω q`.

mod chain;
mod keys;
mod rotvec_cubic;
mod sequential;
mod slerp_spline;
mod squad;

pub use chain::{ChainOptions, KliSpline, MAX_SAMPLES, MAX_SAMPLES_PER_SEGMENT};
pub use keys::{Keys, MAX_TIME, MIN_SPAN};
pub use rotvec_cubic::RotvecCubic;
pub use sequential::SequentialKli;
pub use slerp_spline::PiecewiseSlerp;
pub use squad::Squad;

use glam::{DQuat, DVec3};

/// A rotation as a function of time on `[start_time, end_time]`.
pub trait Curve {
    /// `q(t)`, unit, with `t` clamped to the curve's time span.
    fn at(&self, t: f64) -> DQuat;

    /// The first key time.
    fn start_time(&self) -> f64;

    /// The last key time.
    fn end_time(&self) -> f64;

    /// `q` at each of `times` into `out` (`4·times.len()` numbers, scalar first).
    fn sample_into(&self, times: &[f64], out: &mut [f64]) {
        for (t, slot) in times.iter().zip(out.chunks_exact_mut(4)) {
            slot.copy_from_slice(&crate::quaternion::to_wxyz(self.at(*t)));
        }
    }

    /// The world-frame angular velocity `ω = 2 q' q̄` (so `q' = ½ ω q`), by a central difference
    /// of `q` (one-sided at the ends) over a step of 1e-6 of the curve's span.
    fn angular_velocity(&self, t: f64) -> DVec3 {
        let (start, end) = (self.start_time(), self.end_time());
        let h = 1e-6 * (end - start).max(f64::MIN_POSITIVE);
        let t = t.max(start).min(end);
        let (a, b) = ((t - h).max(start), (t + h).min(end));
        if b <= a {
            return DVec3::ZERO;
        }
        let (qa, qb, q) = (self.at(a), self.at(b), self.at(t));
        // The same sign on both sides and at t (they are 2e-6 of the span apart): a curve may
        // answer with either sign of each rotation.
        let same = |x: DQuat| if qa.dot(x) < 0.0 { -x } else { x };
        let derivative = (same(qb) - qa) / (b - a);
        let w = derivative * same(q).conjugate() * 2.0;
        DVec3::new(w.x, w.y, w.z)
    }
}

/// `Slerp(p, r; s)` for unit quaternions, without choosing a sign (the curves' points are made
/// consistent first); exact at `s = 0` and `1`, accurate when `p ≈ r`.
pub(crate) fn slerp(p: DQuat, r: DQuat, s: f64) -> DQuat {
    match crate::great_arc::GreatArc::new(p, r, false) {
        Ok(arc) => crate::slerp::point_at(&arc, s),
        Err(_) => p, // r = -p: no path; the curves never ask for one (signs are consistent)
    }
}

/// The index `i` of the interval `[times[i], times[i+1]]` holding `t` (clamped), and `u ∈ [0, 1]`
/// within it.
pub(crate) fn locate(times: &[f64], t: f64) -> (usize, f64) {
    let last = times.len() - 1;
    let t = t.max(times[0]).min(times[last]);
    let i = times.partition_point(|&x| x <= t).saturating_sub(1).min(last - 1);
    let u = (t - times[i]) / (times[i + 1] - times[i]);
    (i, u.clamp(0.0, 1.0))
}

#[cfg(test)]
mod tests;
