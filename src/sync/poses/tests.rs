//! Tests of the eliminated pose-graph problem against an independent dense least-squares solve.

use std::f64::consts::PI;

use faer::prelude::Solve;
use faer::{Mat, Side};
use glam::{DMat3, DQuat, DVec3};

use super::reduced::{Edge, Reduced};
use super::stiefel::from_rotations;
use crate::swarm::Random;
use crate::sync::PoseGraph;

/// A pose graph of `n` poses in dimension `d` with the given measurements.
fn pose_graph(
    d: usize,
    n: usize,
    edges: Vec<[usize; 2]>,
    relative: Vec<DQuat>,
    translations: Vec<DVec3>,
    kappa: Vec<f64>,
    tau: Vec<f64>,
) -> PoseGraph {
    PoseGraph {
        dimension: d,
        count: n,
        ids: (0..n as u64).collect(),
        edges,
        relative,
        translations,
        rotation_weights: kappa,
        translation_weights: tau,
        initial: None,
        positions: None,
        skipped: Vec::new(),
    }
}

/// The problem of `graph` as the solver sees it (weights as given).
fn reduced(graph: &PoseGraph) -> Reduced {
    let d = graph.dimension;
    let edges = (0..graph.edges.len())
        .map(|k| {
            let r = DMat3::from_quat(graph.relative[k]);
            let t = graph.translations[k];
            Edge {
                i: graph.edges[k][0],
                j: graph.edges[k][1],
                kappa: graph.rotation_weights[k],
                tau: graph.translation_weights[k],
                rotation: std::array::from_fn(|a| {
                    std::array::from_fn(|b| if a < d && b < d { r.col(b)[a] } else { 0.0 })
                }),
                t: [t.x, t.y, t.z],
            }
        })
        .collect();
    Reduced::new(d, graph.count, edges).unwrap()
}

/// A graph of random measurements (not consistent with any poses).
fn random_graph(d: usize, n: usize, m: usize, seed: u64) -> PoseGraph {
    let mut random = Random::new(seed);
    let mut edges: Vec<[usize; 2]> = (0..n - 1).map(|i| [i, i + 1]).collect();
    while edges.len() < m {
        let (i, j) =
            ((random.uniform() * n as f64) as usize, (random.uniform() * n as f64) as usize);
        if i != j {
            edges.push([i, j]);
        }
    }
    let relative = edges
        .iter()
        .map(|_| {
            if d == 2 {
                DQuat::from_rotation_z(2.0 * PI * random.uniform())
            } else {
                random.unit_quaternion()
            }
        })
        .collect();
    let translations = edges
        .iter()
        .map(|_| {
            let v = random.gaussian3() * 3.0;
            if d == 2 { DVec3::new(v.x, v.y, 0.0) } else { v }
        })
        .collect();
    let kappa = edges.iter().map(|_| 0.2 + random.uniform()).collect();
    let tau = edges.iter().map(|_| 0.2 + 3.0 * random.uniform()).collect();
    pose_graph(d, n, edges, relative, translations, kappa, tau)
}

/// MATH.md: "the direct least-squares minimum over `T` and `tr(R Q Rᵀ)` agree to 1e-14, and so do
/// the translations". The direct minimum here: the rotation terms summed as written, and the
/// translations solved densely (faer's Cholesky of the normal equations, `t_0 = 0`), their
/// residuals summed as written.
#[test]
fn eliminating_the_translations_is_the_direct_least_squares_minimum() {
    for (d, seed) in [(3, 11), (2, 12), (3, 13)] {
        let (n, m) = (7, 10);
        let graph = random_graph(d, n, m, seed);
        let mut random = Random::new(seed + 100);
        let rotations: Vec<DQuat> = (0..n)
            .map(|_| {
                if d == 2 {
                    DQuat::from_rotation_z(2.0 * PI * random.uniform())
                } else {
                    random.unit_quaternion()
                }
            })
            .collect();
        let r: Vec<DMat3> = rotations.iter().map(|&q| DMat3::from_quat(q)).collect();
        // Rows: d per edge, sqrt(τ) (t_j − t_i − R_i t̃); unknowns t_1 … t_{n−1}.
        let unknowns = d * (n - 1);
        let mut a = Mat::<f64>::zeros(d * m, unknowns);
        let mut b = Mat::<f64>::zeros(d * m, 1);
        for (k, &[i, j]) in graph.edges.iter().enumerate() {
            let w = graph.translation_weights[k].sqrt();
            let rt = r[i] * graph.translations[k];
            for c in 0..d {
                if j > 0 {
                    a[(d * k + c, d * (j - 1) + c)] += w;
                }
                if i > 0 {
                    a[(d * k + c, d * (i - 1) + c)] -= w;
                }
                b[(d * k + c, 0)] = w * rt[c];
            }
        }
        let normal = a.transpose() * &a;
        let t = normal.llt(Side::Lower).unwrap().solve(a.transpose() * &b);
        let residual = &a * &t - &b;
        let mut direct: f64 = (0..d * m).map(|k| residual[(k, 0)].powi(2)).sum();
        for (k, &[i, j]) in graph.edges.iter().enumerate() {
            let e = r[j] - r[i] * DMat3::from_quat(graph.relative[k]);
            direct +=
                graph.rotation_weights[k] * (0..3).map(|c| e.col(c).length_squared()).sum::<f64>();
        }
        let problem = reduced(&graph);
        let x = from_rotations(d, &rotations);
        let (eliminated, _) = problem.cost(&x);
        assert!((eliminated - direct).abs() <= 1e-13 * direct, "{d}D: {eliminated} vs {direct}");
        let z = problem.translations(&x);
        for k in 1..n {
            for c in 0..d {
                let gap = (z[c * n + k] - t[(d * (k - 1) + c, 0)]).abs();
                assert!(gap <= 1e-12, "{d}D: t_{k}[{c}] off by {gap}");
            }
        }
    }
}
