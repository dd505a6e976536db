//! Riemannian Newton on (S³)ⁿ for the chordal cost, with Levenberg–Marquardt damping
//! (Absil, Mahony and Sepulchre, "Optimization Algorithms on Matrix Manifolds", §6; Nielsen's
//! damping update, 1999).
//!
//! Each step solves `(H + μ I) δ = −g` for the tangent step `δ` with the anchor's `δ` fixed at 0
//! (the gauge), by a sparse Cholesky factorisation on the graph's pattern, and moves
//! `q_i → q_i exp(δ_i/2)`. `μ` starts at 0 (Newton's step, quadratic convergence: from the
//! spectral start `H` is positive definite and each step lowers `f`); where either fails `μ`
//! grows until both hold, and each step taken shrinks it by Nielsen's factor. A step that changes
//! `f` by no more than rounding is taken: there `f` cannot judge it, and the gradient can.

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

/// The damping after a refused factorisation or a rejected step (Nielsen): `μ ← max(νμ, 1e-12
/// d)` (`d` the largest degree, so that the first damping is felt at the graph's scale) and
/// `ν ← 2ν`, so that repeated failures grow `μ` ever faster.
fn grown(mu: f64, nu: f64, scale: f64) -> (f64, f64) {
    ((mu * nu).max(1e-12 * scale), 2.0 * nu)
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
                (mu, nu) = grown(mu, nu, scale);
                continue;
            };
            let trial = moved(&q, &step);
            let f_trial = cost(graph, &trial);
            // The model's predicted decrease −(gᵀδ + ½ δᵀ H δ) = ½ (μ|δ|² − gᵀδ) for the damped
            // step, always > 0.
            let predicted = 0.5
                * (mu * step.iter().map(|x| x * x).sum::<f64>()
                    - g.iter().zip(&step).map(|(a, b)| a * b).sum::<f64>());
            // Near the optimum f changes by rounding alone (4 ulps a term) while the gradient
            // still shrinks: f cannot judge such a step, and it is taken as the model predicts
            // it (ρ = 1). Otherwise a step is taken when it lowers f.
            let noise = 4.0 * f64::EPSILON * f.abs() * (graph.edges().len() as f64).sqrt();
            let change = f - f_trial;
            let rho = if change.abs() <= noise { 1.0 } else { change / predicted };
            if rho.is_finite() && rho > 0.0 {
                q = trial;
                f = f_trial;
                mu *= (1.0_f64 / 3.0).max(1.0 - (2.0 * rho - 1.0).powi(3));
                nu = 2.0;
                accepted = true;
                break;
            }
            (mu, nu) = grown(mu, nu, scale);
        }
        if !accepted {
            break;
        }
    }
    Refined { q, iterations }
}

#[cfg(test)]
mod tests {
    use faer::prelude::Solve;
    use faer::{Mat, Side};
    use glam::{DQuat, DVec3};

    use super::{Accuracy, MAX_ITERATIONS, refine};
    use crate::quaternion::{exp, farthest_apart};
    use crate::swarm::Random;
    use crate::sync::blocks::Pattern;
    use crate::sync::cost::{cost, model};
    use crate::sync::graph::Graph;
    use crate::sync::tests::synthetic;

    /// Which of the method's branches a run went through.
    #[derive(Debug, Default, Clone, Copy)]
    struct Branches {
        /// `H + μI` not positive definite: `μ` grows.
        refused: usize,
        /// A step that raised `f` well beyond rounding (by 1e-6 of it): `μ` grows.
        rejected: usize,
        /// A damped step taken: `μ` shrinks by Nielsen's factor.
        damped: usize,
        /// A step taken although it raised `f`, by no more than rounding.
        noise: usize,
        /// Stopped because the gradient stopped shrinking (by half) below `1e-8` of the scale.
        stalled: usize,
    }

    /// Levenberg–Marquardt on the pulled-back chordal cost written afresh from the module's doc,
    /// densely: the model's `g` and `H` (tested against finite differences), `H` written out
    /// column by column, `(H + μI) δ = −g` by faer's dense Cholesky on every node but `anchor`.
    /// `μ` starts at 0 (Newton's step); a refused factorisation or a step that raises `f` by more
    /// than rounding (`4 ε |f| √m`) makes `μ ← max(νμ, 1e-12 d)`, `ν ← 2ν` (`d` the largest
    /// degree); a step taken makes `μ ← μ max(1/3, 1 − (2ρ − 1)³)`, `ν ← 2` (Nielsen), `ρ` the
    /// actual over the predicted decrease `½(μ|δ|² − gᵀδ)`, or 1 where `f` changed by no more
    /// than rounding. It stops when `|g| ≤ 1e-13 d`, or when `|g| < 1e-8 d` no longer halves, or
    /// after 64 refusals in a row. Each step's `q`.
    fn dense(
        graph: &Graph,
        anchor: usize,
        start: &[DQuat],
        gauss_newton: bool,
    ) -> (Vec<Vec<DQuat>>, Branches) {
        let n = graph.count();
        let free: Vec<usize> = (0..3 * n).filter(|k| k / 3 != anchor).collect();
        let d = graph.degrees().into_iter().fold(0.0, f64::max);
        let m = graph.edges().len() as f64;
        let mut q = start.to_vec();
        let mut f = cost(graph, &q);
        let (mut mu, mut nu, mut last) = (0.0_f64, 2.0_f64, f64::INFINITY);
        let mut branches = Branches::default();
        let mut path = vec![q.clone()];
        'steps: while path.len() <= MAX_ITERATIONS {
            let (mut g, h) = model(graph, &q, gauss_newton);
            g[3 * anchor..3 * anchor + 3].fill(0.0);
            let size = g.iter().map(|x| x * x).sum::<f64>().sqrt();
            if size <= 1e-13 * d {
                break;
            }
            if size < 1e-8 * d && size > last / 2.0 {
                branches.stalled += 1;
                break;
            }
            last = size;
            let mut column = vec![0.0; 3 * n];
            let mut hessian = Mat::<f64>::zeros(free.len(), free.len());
            for (c, &k) in free.iter().enumerate() {
                let mut unit = vec![0.0; 3 * n];
                unit[k] = 1.0;
                h.apply(graph, &unit, &mut column);
                for (r, &l) in free.iter().enumerate() {
                    hessian[(r, c)] = column[l];
                }
            }
            for _ in 0..64 {
                let shifted = Mat::<f64>::from_fn(free.len(), free.len(), |r, c| {
                    hessian[(r, c)] + if r == c { mu } else { 0.0 }
                });
                let Ok(llt) = shifted.llt(Side::Lower) else {
                    branches.refused += 1;
                    (mu, nu) = ((nu * mu).max(1e-12 * d), 2.0 * nu);
                    continue;
                };
                let minus = Mat::<f64>::from_fn(free.len(), 1, |r, _| -g[free[r]]);
                let solved = llt.solve(&minus);
                let mut step = vec![0.0; 3 * n];
                for (r, &k) in free.iter().enumerate() {
                    step[k] = solved[(r, 0)];
                }
                let trial: Vec<DQuat> = (0..n)
                    .map(|i| {
                        let v = DVec3::new(step[3 * i], step[3 * i + 1], step[3 * i + 2]);
                        (q[i] * exp(v / 2.0)).normalize()
                    })
                    .collect();
                let f_trial = cost(graph, &trial);
                let gd: f64 = g.iter().zip(&step).map(|(a, b)| a * b).sum();
                let dd: f64 = step.iter().map(|x| x * x).sum();
                let predicted = 0.5 * (mu * dd - gd);
                let by_rounding = (f_trial - f).abs() <= 4.0 * f64::EPSILON * f.abs() * m.sqrt();
                let rho = if by_rounding { 1.0 } else { (f - f_trial) / predicted };
                if by_rounding || f_trial < f {
                    branches.noise += usize::from(by_rounding && f_trial > f);
                    branches.damped += usize::from(mu > 0.0);
                    mu *= (1.0 - (2.0 * rho - 1.0).powi(3)).max(1.0 / 3.0);
                    nu = 2.0;
                    (q, f) = (trial, f_trial);
                    path.push(q.clone());
                    continue 'steps;
                }
                branches.rejected += usize::from(f_trial > f * (1.0 + 1e-6));
                (mu, nu) = ((nu * mu).max(1e-12 * d), 2.0 * nu);
            }
            break;
        }
        (path, branches)
    }

    /// `refine` stopped after each number of steps is where the dense method is after as many
    /// (to 1e-9, while the gradient is above `1e-8 d`: below, rounding decides which steps are
    /// taken, and the two differ in it), and it stops within a step of the dense method, with the
    /// gradient at rounding's level: from random starts (indefinite Hessians: refusals, rejected
    /// steps, damped ones), near the optimum (pure Newton steps taken that raise `f` by rounding),
    /// and in a robust round's Gauss–Newton steps (linear convergence: the stall). Every branch
    /// of the method is taken, so a wrong rate, clause or bound changes a path below.
    #[test]
    fn each_step_is_the_dense_methods() {
        let mut seen = Branches::default();
        let mut compare = |graph: &Graph, start: &[DQuat], accuracy: Accuracy| {
            let pattern = Pattern::new(graph, Some(0));
            let gauss_newton = matches!(accuracy, Accuracy::Round);
            let (path, branches) = dense(graph, 0, start, gauss_newton);
            let d = graph.degrees().into_iter().fold(0.0, f64::max);
            let gradient = |q: &[DQuat]| {
                let (mut g, _) = model(graph, q, gauss_newton);
                g[..3].fill(0.0);
                g.iter().map(|x| x * x).sum::<f64>().sqrt()
            };
            for (k, expected) in path.iter().enumerate() {
                let after = refine(graph, &pattern, start.to_vec(), k, accuracy);
                assert_eq!(after.iterations, k);
                let gap = farthest_apart(&after.q, expected);
                assert!(gap < 1e-9, "step {k} of {}: {gap:e} ({branches:?})", path.len() - 1);
                if gradient(expected) < 1e-8 * d {
                    break;
                }
            }
            let full = refine(graph, &pattern, start.to_vec(), MAX_ITERATIONS, accuracy);
            let steps = path.len() - 1;
            assert!(full.iterations.abs_diff(steps) <= 1, "{} vs {steps}", full.iterations);
            let limit = if branches.stalled > 0 { 1e-8 } else { 1e-13 };
            assert!(gradient(&full.q) <= limit * d, "{:e}", gradient(&full.q));
            seen.refused += branches.refused;
            seen.rejected += branches.rejected;
            seen.damped += branches.damped;
            seen.noise += branches.noise;
            seen.stalled += branches.stalled;
        };
        let s = synthetic(12, 0.4, 0.1, 0.0, 5);
        let optimum =
            refine(&s.graph, &Pattern::new(&s.graph, Some(0)), s.truth.clone(), 50, Accuracy::Full)
                .q;
        let mut random = Random::new(60);
        for size in [1e-5, 1e-5, 1e-5, 0.1, 0.3, 0.5, 1.0, 1.5, 3.0, 3.0, 3.0] {
            let near: Vec<DQuat> =
                optimum.iter().map(|&q| (q * exp(random.gaussian3() * size)).normalize()).collect();
            compare(&s.graph, &near, Accuracy::Full);
        }
        // Residuals of ~0.8 rad: Gauss–Newton converges linearly, slower than halving.
        // Starts from which a step raises f well beyond rounding (found by a search of 90).
        for (seed, size) in [(5, 0.6), (5, 1.0), (20, 0.6)] {
            let mut random = Random::new(500 + seed);
            let near: Vec<DQuat> =
                optimum.iter().map(|&q| (q * exp(random.gaussian3() * size)).normalize()).collect();
            compare(&s.graph, &near, Accuracy::Full);
        }
        let noisy = synthetic(12, 0.5, 0.8, 0.0, 8);
        for size in [0.01, 0.1] {
            let near: Vec<DQuat> = noisy
                .truth
                .iter()
                .map(|&q| (q * exp(random.gaussian3() * size)).normalize())
                .collect();
            compare(&noisy.graph, &near, Accuracy::Round);
        }
        assert!(seen.refused > 0 && seen.rejected > 0 && seen.damped > 0, "{seen:?}");
        assert!(seen.noise > 0 && seen.stalled > 0, "{seen:?}");
    }
}
