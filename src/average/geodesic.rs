//! The geodesic L2 (Karcher) mean (MATH.md, "Averaging rotations"): the rotation that minimises
//! `Σ w_j d(q, r_j)²`, by the Riemannian iteration `q ← q · exp(Σ w_j v_j / Σ w_j)`,
//! `v_j = log(q̄ r_j)`. From the chordal mean it converges in a few steps when the data lie within
//! a ball of radius π/2, where the mean is unique.

use glam::{DQuat, DVec3};

use super::Data;
use super::tangent::{exp_at, log_at};

/// The most iterations: far more than data within π/2 of each other need.
const MAX_ITERATIONS: usize = 200;

/// The Karcher mean from `start`, the steps applied and the last step's angle: it iterates
/// until a step is below 1e-15 rad, or stops shrinking (rounding; that step is not applied).
pub(super) fn karcher(data: &Data, start: DQuat) -> (DQuat, usize, f64) {
    let total = data.total();
    let (mut q, mut last, mut applied) = (start, f64::INFINITY, 0);
    for _ in 0..MAX_ITERATIONS {
        let mean = data
            .rotations
            .iter()
            .zip(&data.weights)
            .fold(DVec3::ZERO, |sum, (&r, &w)| sum + w * log_at(q, r))
            / total;
        let step = mean.length();
        if step >= last {
            break;
        }
        q = exp_at(q, mean);
        applied += 1;
        last = step;
        if step <= 1e-15 {
            break;
        }
    }
    (q, applied, last)
}
