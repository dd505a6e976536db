//! Riemannian Newton on (S³)ⁿ for the chordal cost, with Levenberg–Marquardt damping
//! (Absil, Mahony and Sepulchre, "Optimization Algorithms on Matrix Manifolds", §6; Nielsen's
//! damping update, 1999).
//!
//! Each step solves `(H + μ I) δ = −g` for the tangent step `δ` with the anchor's `δ` fixed at 0
//! (the gauge), by a sparse Cholesky factorisation on the graph's pattern, and moves
//! `q_i → q_i exp(δ_i/2)`. `μ = 0` (Newton's step, quadratic convergence) whenever `H` is positive
//! definite and the step lowers `f`; otherwise `μ` grows until both hold.

use glam::DQuat;

use super::blocks::{Pattern, get};
use super::cost::{cost, model};
use super::graph::Graph;
use crate::quaternion::exp;

/// Where Newton's method stopped.
pub(crate) struct Refined {
    pub q: Vec<DQuat>,
    pub iterations: usize,
}

/// At most this many Newton steps (it needs a handful from the spectral start).
pub(crate) const MAX_ITERATIONS: usize = 200;

fn moved(q: &[DQuat], step: &[f64]) -> Vec<DQuat> {
    q.iter().enumerate().map(|(i, &qi)| (qi * exp(get(step, i) * 0.5)).normalize()).collect()
}

/// The answer's steps (the exact Hessian, solved to rounding where the solve is iterative:
/// quadratic convergence), or a robust round's (the Gauss–Newton matrix, positive semidefinite
/// with outliers about, solved to 1e-6: the weights move next round).
#[derive(Debug, Clone, Copy)]
pub(crate) enum Accuracy {
    Full,
    Round,
}

/// Newton's method from `q` on the weighted cost of `graph`, with the node `pattern` leaves out
/// held fixed, until the gradient vanishes to rounding or `max_iterations` steps.
pub(crate) fn refine(
    graph: &Graph,
    pattern: &Pattern,
    q: Vec<DQuat>,
    max_iterations: usize,
    accuracy: Accuracy,
) -> Refined {
    let tolerance = match accuracy {
        Accuracy::Full => 1e-12,
        Accuracy::Round => 1e-6,
    };
    let scale = graph.degrees().into_iter().fold(0.0, f64::max);
    let mut q = q;
    let mut f = cost(graph, &q);
    let mut mu = 0.0;
    let mut nu = 2.0;
    let mut iterations = 0;
    let mut last_size = f64::INFINITY;
    while iterations < max_iterations {
        let (mut g, hessian) = model(graph, &q, matches!(accuracy, Accuracy::Round));
        // The node left out (the anchor) does not move.
        for i in (0..graph.count()).filter(|&i| pattern.row(i).is_none()) {
            g[3 * i..3 * i + 3].fill(0.0);
        }
        let size = g.iter().map(|x| x * x).sum::<f64>().sqrt();
        // Stationary to rounding: the gradient of a sum of `m` terms is computed to about
        // `1e-15 · Σ w` at best.
        if size.is_nan() || size <= 1e-13 * scale.max(f64::MIN_POSITIVE) {
            break;
        }
        // Rounding has the last word: the gradient stopped shrinking near the optimum.
        if size > 0.5 * last_size && size < 1e-8 * scale {
            break;
        }
        last_size = size;
        iterations += 1;
        let mut accepted = false;
        // At most ~60 doublings of μ: from 1e-12 scale to 1e6 scale.
        for _ in 0..64 {
            let minus: Vec<f64> = g.iter().map(|x| -x).collect();
            let Some(step) = pattern.solve(graph, &hessian, mu, &minus, tolerance) else {
                mu = (mu * nu).max(1e-12 * scale);
                nu *= 2.0;
                continue;
            };
            let trial = moved(&q, &step);
            let f_trial = cost(graph, &trial);
            // The model's predicted decrease −(gᵀδ + ½ δᵀ H δ) = ½ (μ|δ|² − gᵀδ) for the damped
            // step, always > 0.
            let predicted = 0.5
                * (mu * step.iter().map(|x| x * x).sum::<f64>()
                    - g.iter().zip(&step).map(|(a, b)| a * b).sum::<f64>());
            let rho = (f - f_trial) / predicted;
            // A pure Newton step may raise f by rounding alone (4 ulps a term) near the optimum,
            // where the gradient still shrinks quadratically: it is accepted.
            let noise = 4.0 * f64::EPSILON * f.abs() * (graph.edges().len() as f64).sqrt();
            if rho.is_finite() && (f_trial < f || (mu == 0.0 && f_trial <= f + noise)) {
                q = trial;
                f = f_trial;
                mu = if mu > 0.0 {
                    mu * (1.0_f64 / 3.0).max(1.0 - (2.0 * rho - 1.0).powi(3))
                } else {
                    0.0
                };
                if mu < 1e-12 * scale {
                    mu = 0.0;
                }
                nu = 2.0;
                accepted = true;
                break;
            }
            mu = (mu * nu).max(1e-12 * scale);
            nu *= 2.0;
        }
        if !accepted {
            break;
        }
    }
    Refined { q, iterations }
}
