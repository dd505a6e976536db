//! Robust synchronisation by iteratively reweighted least squares on the chordal cost
//! (Chatterjee and Govindu 2013/2018; Hartley, Aftab and Trumpf 2011; MATH.md, "Robust
//! synchronisation").
//!
//! Each round sets `w_ij ← w⁰_ij ρ'(θ_ij)/θ_ij` from the current residual angles and takes one
//! Gauss–Newton step on the reweighted cost. First L1 rounds (`ρ = θ`: weight `1/θ`, the geodesic
//! median's Weiszfeld weight), a robust start that wrong edges cannot drag far; then Geman–McClure
//! rounds (`ρ = σ²θ²/(σ² + θ²)`: weight `(σ²/(σ² + θ²))²`), which all but ignore edges many `σ`
//! off. An edge is an outlier when its final residual exceeds `3σ` for a caller's `σ`, or 6 times
//! the median residual after the L1 rounds by default.

use std::f64::consts::FRAC_PI_2;

use glam::DQuat;

use super::blocks::Pattern;
use super::cost::residuals;
use super::graph::Graph;
use super::newton::{Accuracy, MAX_ITERATIONS, refine};

/// The robust method's result before it is packaged.
pub(crate) struct Robust {
    pub q: Vec<DQuat>,
    /// `w_ij / w⁰_ij`, the last round's factor on each edge's weight.
    pub factors: Vec<f64>,
    pub outliers: Vec<bool>,
    pub iterations: usize,
    /// The Geman–McClure scale `σ`, radians.
    pub scale: f64,
}

/// L1 rounds at most; they stop early when no weight moves by [`L1_SETTLED`] (relative).
const L1_ROUNDS: usize = 15;
const L1_SETTLED: f64 = 1e-3;
/// Geman–McClure rounds at most; they stop early when no weight moves by [`GM_SETTLED`].
const GM_ROUNDS: usize = 30;
const GM_SETTLED: f64 = 1e-6;
/// An edge is far off from the least-squares fit beyond this many typical residuals. Real SLAM
/// graphs have long tails: on SE-Sync's cubicle (16,869 edges, a few of them 10° to 33° off where
/// the median is 0.17°) 6 would set aside 2.1% of the edges, 8 1.0%, 10 0.45%.
const FAR: f64 = 10.0;
/// An edge is an outlier of the reweighted rounds beyond this many median residuals of the L1
/// fit: 1× (the Geman–McClure σ) flags inliers of a long tail (29% of the flagged were
/// within 10° of the truth at 2° noise and 10% wrong), 6× none of them (≤ 0.4% on the bench's
/// graphs).
const FAR_REWEIGHTED: f64 = 6.0;
/// The share of the edges that may be far off from the least-squares fit for it to judge them.
const FEW: f64 = 0.05;
/// Least-squares refits on the edges kept, at most (each a Newton solve).
const REFITS: usize = 5;
/// Newton steps a refit, at most: from the rounds' answer it needs a handful.
const REFIT_STEPS: usize = 20;
/// The factor on a set-aside edge's weight in a refit: negligible, yet it keeps the graph
/// connected (an edge that alone joins two parts is then fitted exactly, and taken back).
const SET_ASIDE: f64 = 1e-9;
/// Gauss–Newton steps a round: the weights move between rounds, so each round's problem is only
/// approached, not solved (1, 2 and 4 steps gave the same errors on the bench's graphs; 1 is the
/// fastest).
const STEPS_A_ROUND: usize = 1;
/// The residual below which the L1 weight stops growing (radians, 0.06°): `1/θ` is unbounded.
const L1_FLOOR: f64 = 1e-3;

fn median(values: &[f64]) -> f64 {
    let mut sorted = values.to_vec();
    sorted.sort_by(f64::total_cmp);
    let n = sorted.len();
    if n % 2 == 1 { sorted[n / 2] } else { 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]) }
}

/// The largest relative change from `old` to `new`.
fn moved(old: &[f64], new: &[f64]) -> f64 {
    old.iter().zip(new).map(|(&a, &b)| ((a - b) / a.max(b)).abs()).fold(0.0, f64::max)
}

/// Each edge's residual angle in the units of a typical edge: `θ_ij √(w_ij / w̃)`, `w̃` the median
/// weight. An edge measured 4 times as precisely (4 times the weight) is as far off at half the
/// angle; in a graph of equal weights these are the angles.
fn normalised(graph: &Graph, q: &[DQuat], typical_weight: f64) -> Vec<f64> {
    residuals(graph, q)
        .iter()
        .zip(graph.weights())
        .map(|(t, w)| t * (w / typical_weight).sqrt())
        .collect()
}

/// The typical residual after the L1 rounds: the median of the residuals left when the `n − 1`
/// smallest are set aside. An L1 fit makes about a spanning tree's worth of residuals vanish
/// (`n − 1` edges pin the `n − 1` free rotations), whatever the noise: in a sparse graph (a SLAM
/// path with a few loop closures, `m ≈ n`) most residuals are 0 and their median says nothing of
/// the noise, which the loop closures alone carry.
fn typical(residuals: &[f64], count: usize) -> f64 {
    let mut sorted = residuals.to_vec();
    sorted.sort_by(f64::total_cmp);
    let carried = &sorted[count.saturating_sub(1).min(sorted.len() - 1)..];
    median(carried)
}

/// Robust synchronisation from the spectral `start`. `scale` is the caller's `σ` in radians,
/// or `None`: then edges are judged in units of the typical residual ([`typical`]), weighed by
/// the edges' weights ([`normalised`]).
///
/// First the least-squares optimum of every edge, and the edges it leaves far off: more than
/// [`FAR`] times the typical residual (or `3σ`). On a graph without wrong edges there are none,
/// and the answer is that optimum (the chordal method's, certified). A few (at most [`FEW`] of
/// the edges) are set aside and the rest solved again, until the set settles: a wrong edge among
/// many right ones stands out of their fit, and the answer is the least-squares optimum of the
/// rest. More, or a fit so dragged that a quarter turn is within its limit, and least squares
/// cannot judge: the reweighted rounds (L1, then Geman–McClure) find the wrong edges
/// ([`reweighted`]).
pub(crate) fn robust(
    graph: &Graph,
    pattern: &Pattern,
    start: Vec<DQuat>,
    scale: Option<f64>,
) -> Robust {
    let typical_weight = median(graph.weights());
    let limit = |typical: f64| scale.map_or(FAR * typical, |s| 3.0 * s);
    let fitted = refine(graph, pattern, start.clone(), MAX_ITERATIONS, Accuracy::Full);
    let mut steps = fitted.iterations;
    let mut q = fitted.q;
    let mut outliers = vec![false; graph.weights().len()];
    let mut sigma = 0.0;
    for _ in 0..=REFITS {
        let residuals = normalised(graph, &q, typical_weight);
        let kept: Vec<f64> =
            residuals.iter().zip(&outliers).filter(|(_, out)| !**out).map(|(t, _)| *t).collect();
        sigma = typical(&kept, graph.count()).max(1e-9);
        let next: Vec<bool> = residuals.iter().map(|&t| t > limit(sigma)).collect();
        let flagged = next.iter().filter(|&&out| out).count();
        // A fit dragged by many wrong edges has a typical residual so large that none is far
        // off beyond it (30% of the edges wrong: 20° and more); or it sees too many.
        let blind = limit(sigma) > FRAC_PI_2;
        if blind || flagged as f64 > FEW * next.len() as f64 {
            let mut r = reweighted(graph, pattern, start, scale, typical_weight);
            r.iterations += steps;
            return r;
        }
        if next == outliers {
            let factors = outliers.iter().map(|&out| if out { 0.0 } else { 1.0 }).collect();
            return Robust {
                q,
                factors,
                outliers,
                iterations: steps,
                scale: scale.unwrap_or(sigma),
            };
        }
        outliers = next;
        let weights: Vec<f64> = graph
            .weights()
            .iter()
            .zip(&outliers)
            .map(|(&w, &out)| if out { w * SET_ASIDE } else { w })
            .collect();
        let refit = refine(&graph.reweighted(weights), pattern, q, REFIT_STEPS, Accuracy::Full);
        q = refit.q;
        steps += refit.iterations;
    }
    // Still a few edges coming and going at the limit after REFITS refits: the last set.
    let residuals = normalised(graph, &q, typical_weight);
    outliers = residuals.iter().map(|&t| t > limit(sigma)).collect();
    let factors = outliers.iter().map(|&out| if out { 0.0 } else { 1.0 }).collect();
    Robust { q, factors, outliers, iterations: steps, scale: scale.unwrap_or(sigma) }
}

/// Iteratively reweighted least squares from `start`: L1 rounds, a start that wrong edges cannot
/// drag far, then Geman–McClure rounds with `σ` = `scale` or the median residual after the L1
/// rounds (with at most half the edges wrong, an inlier's). An outlier is
/// `3σ` off for a caller's `σ`, [`FAR_REWEIGHTED`] times the typical residual by default. Measured on the
/// bench's 1,000-node graphs (σ = 2° and 5°, 10–30% wrong), the median error grows with the
/// factor on σ: 1× gave 1.02°, 1.05°, 1.28° at 5°; 2× 1.09°, 1.17°, 1.37°; 4× 1.24°, 1.33°, 1.49°.
fn reweighted(
    graph: &Graph,
    pattern: &Pattern,
    start: Vec<DQuat>,
    scale: Option<f64>,
    typical_weight: f64,
) -> Robust {
    let mut state = Rounds {
        q: start,
        factors: vec![1.0; graph.weights().len()],
        iterations: 0,
        typical_weight,
    };
    state.run(graph, pattern, L1_ROUNDS, L1_SETTLED, |t| 1.0 / t.max(L1_FLOOR));
    let found = median(&normalised(graph, &state.q, typical_weight)).max(1e-6);
    let sigma = scale.unwrap_or(found);
    let threshold = scale.map_or(FAR_REWEIGHTED * found, |s| 3.0 * s);
    state.run(graph, pattern, GM_ROUNDS, GM_SETTLED, |t| {
        let r = sigma * sigma / (sigma * sigma + t * t);
        r * r
    });
    let Rounds { q, factors, iterations, .. } = state;
    let outliers = normalised(graph, &q, typical_weight).iter().map(|&t| t > threshold).collect();
    Robust { q, factors, outliers, iterations, scale: sigma }
}

/// Where the rounds are: the rotations, each edge's robust factor, the steps taken.
struct Rounds {
    q: Vec<DQuat>,
    factors: Vec<f64>,
    iterations: usize,
    /// The median weight, the unit of [`normalised`] residuals.
    typical_weight: f64,
}

impl Rounds {
    /// Up to `rounds` rounds with the factor `weight(θ)` on each edge's weight, until no factor
    /// moves by `settled` (relative) from one round to the next.
    fn run(
        &mut self,
        graph: &Graph,
        pattern: &Pattern,
        rounds: usize,
        settled: f64,
        weight: impl Fn(f64) -> f64,
    ) {
        for _ in 0..rounds {
            let next: Vec<f64> = normalised(graph, &self.q, self.typical_weight)
                .iter()
                .map(|&t| weight(t))
                .collect();
            let change = moved(&self.factors, &next);
            self.factors = next;
            let weights = graph.weights().iter().zip(&self.factors).map(|(w, f)| w * f).collect();
            let q = std::mem::take(&mut self.q);
            let refined =
                refine(&graph.reweighted(weights), pattern, q, STEPS_A_ROUND, Accuracy::Round);
            self.q = refined.q;
            self.iterations += refined.iterations;
            if change < settled {
                break;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{median, moved, typical};

    #[test]
    fn median_and_largest_relative_change() {
        assert_eq!(median(&[3.0, 1.0, 2.0]), 2.0);
        assert_eq!(median(&[4.0, 1.0, 3.0, 2.0]), 2.5);
        assert_eq!(median(&[7.0]), 7.0);
        assert_eq!(median(&[2.0, 10.0]), 6.0);
        // |1 − 1|/1, |2 − 3|/3, |4 − 2|/4: the largest is 1/2, relative to the larger of each pair.
        assert_eq!(moved(&[1.0, 2.0, 4.0], &[1.0, 3.0, 2.0]), 0.5);
        assert_eq!(moved(&[5.0, 5.0], &[5.0, 5.0]), 0.0);
        assert!((moved(&[0.2], &[0.1]) - 0.5).abs() < 1e-15);
    }

    #[test]
    fn the_typical_residual_sets_a_spanning_trees_worth_aside() {
        // 4 nodes: the 3 smallest of 7 residuals set aside, the median of 1, 2, 3, 4.
        assert_eq!(typical(&[3.0, 0.0, 4.0, 0.0, 1.0, 0.0, 2.0], 4), 2.5);
        // A tree (as many edges as n − 1) keeps its largest.
        assert_eq!(typical(&[0.5, 0.25], 3), 0.5);
        assert_eq!(typical(&[0.5], 1), 0.5);
    }
}
