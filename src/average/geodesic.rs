//! The geodesic L2 (Karcher) mean (MATH.md, "Averaging rotations"): the rotation that minimises
//! `Σ w_j d(q, r_j)²`, by the Riemannian iteration `q ← q · exp(Σ w_j v_j / Σ w_j)`,
//! `v_j = log(q̄ r_j)`. From the chordal mean it converges in a few steps when the data lie within
//! a ball of radius π/2, where the mean is unique.

use glam::{DQuat, DVec3};

use super::Data;
use super::tangent::{exp_at, log_at};

/// The most iterations: far more than data within π/2 of each other need.
const MAX_ITERATIONS: usize = 200;

/// The Karcher mean from `start`, the iterations taken and the last step's angle: it iterates
/// until a step is below 1e-15 rad, or stops shrinking (rounding).
pub(super) fn karcher(data: &Data, start: DQuat) -> (DQuat, usize, f64) {
    let total = data.total();
    let (mut q, mut last) = (start, f64::INFINITY);
    for iteration in 1..=MAX_ITERATIONS {
        let mean = data
            .rotations
            .iter()
            .zip(&data.weights)
            .fold(DVec3::ZERO, |sum, (&r, &w)| sum + w * log_at(q, r))
            / total;
        let step = mean.length();
        if step >= last {
            return (q, iteration - 1, last);
        }
        q = exp_at(q, mean);
        if step <= 1e-15 {
            return (q, iteration, step);
        }
        last = step;
    }
    (q, MAX_ITERATIONS, last)
}
