//! Tests of pose-graph synchronisation against independent computations: exact data, a dense
//! least-squares solve of the translations, finite differences, an eigenvalue worked by hand,
//! MATH.md's reference optimum for CSAIL, and `bench/posegraph_reference.py`'s (NumPy/SciPy
//! Levenberg–Marquardt) for the 3D grids.

use std::f64::consts::PI;

use faer::prelude::Solve;
use faer::{Mat, Side};
use glam::{DMat3, DQuat, DVec3};

use super::reduced::{Edge, Reduced};
use super::stiefel::{Stack, from_rotations, project, retract};
use super::*;
use crate::swarm::Random;
use crate::sync::{OtherLines, read_g2o};

/// The angle between two rotations, blind to sign.
fn angle(a: DQuat, b: DQuat) -> f64 {
    let e = a.conjugate() * b;
    2.0 * DVec3::new(e.x, e.y, e.z).length().atan2(e.w.abs())
}

fn message(error: KliError) -> String {
    error.message(&|s| s.to_string(), &|x| x.to_string())
}

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
        information: Vec::new(),
        initial: None,
        positions: None,
        skipped: Vec::new(),
    }
}

/// A rotation uniform on SO(3), or about z with its angle uniform in 2D.
fn rotation(random: &mut Random, d: usize) -> DQuat {
    if d == 2 {
        DQuat::from_rotation_z(2.0 * PI * random.uniform())
    } else {
        random.unit_quaternion()
    }
}

/// Random poses (rotations uniform, about z in 2D; positions normal, spread 5) on a ring with
/// chords of probability `p`, each edge measured exactly, `κ` in [1, 10), `τ` in [0.1, 5).
fn exact(d: usize, n: usize, p: f64, seed: u64) -> (PoseGraph, Vec<DQuat>, Vec<DVec3>) {
    let mut random = Random::new(seed);
    let rotations: Vec<DQuat> = (0..n).map(|_| rotation(&mut random, d)).collect();
    let positions: Vec<DVec3> = (0..n)
        .map(|_| {
            let v = random.gaussian3() * 5.0;
            if d == 2 { DVec3::new(v.x, v.y, 0.0) } else { v }
        })
        .collect();
    let mut edges = Vec::new();
    for i in 0..n {
        for j in i + 1..n {
            if j == i + 1 || (i == 0 && j == n - 1) || random.uniform() < p {
                // Either direction: the measurement is T_i⁻¹ T_j for the edge as written.
                edges.push(if random.uniform() < 0.5 { [i, j] } else { [j, i] });
            }
        }
    }
    let relative = edges.iter().map(|&[i, j]| rotations[i].conjugate() * rotations[j]).collect();
    let translations = edges
        .iter()
        .map(|&[i, j]| rotations[i].conjugate() * (positions[j] - positions[i]))
        .collect();
    let kappa = edges.iter().map(|_| 1.0 + 9.0 * random.uniform()).collect();
    let tau = edges.iter().map(|_| 0.1 + 4.9 * random.uniform()).collect();
    (pose_graph(d, n, edges, relative, translations, kappa, tau), rotations, positions)
}

/// The truth in the anchor's frame: `R_aᵀ R_i`, `R_aᵀ (t_i − t_a)`.
fn anchored(rotations: &[DQuat], positions: &[DVec3], a: usize) -> (Vec<DQuat>, Vec<DVec3>) {
    let g = rotations[a].conjugate();
    (
        rotations.iter().map(|&q| g * q).collect(),
        positions.iter().map(|&t| g * (t - positions[a])).collect(),
    )
}

#[test]
fn exact_measurements_give_the_poses_back_certified() {
    for (d, n, p, seed) in [(2, 30, 0.1, 1), (3, 30, 0.1, 2), (2, 12, 0.5, 3), (3, 60, 0.05, 4)] {
        let (graph, rotations, positions) = exact(d, n, p, seed);
        for anchor in [0, n / 2] {
            let result =
                synchronize_poses(&graph, &PoseOptions { anchor, ..Default::default() }).unwrap();
            let (truth_q, truth_t) = anchored(&rotations, &positions, anchor);
            assert!(result.cost < 1e-16, "{d}D {n}: {}", result.cost);
            for i in 0..n {
                let gap = angle(result.rotations[i], truth_q[i]);
                assert!(gap < 1e-9, "{d}D {n}: rotation {i} off by {gap}");
                let gap = (result.translations[i] - truth_t[i]).length();
                assert!(gap < 1e-9, "{d}D {n}: translation {i} off by {gap}");
                assert!(result.rotations[i].w >= 0.0);
            }
            assert_eq!(result.rotations[anchor], DQuat::IDENTITY);
            assert_eq!(result.translations[anchor], DVec3::ZERO);
            if d == 2 {
                assert!(result.translations.iter().all(|t| t.z == 0.0));
                assert!(result.rotations.iter().all(|q| q.x == 0.0 && q.y == 0.0));
            }
            let c = result.certificate;
            assert!(c.certified && c.rank == d, "{d}D {n}: {c:?}");
            assert!(c.lambda_min.abs() <= c.tolerance, "{d}D {n}: {c:?}");
        }
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
    let relative = edges.iter().map(|_| rotation(&mut random, d)).collect();
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
        let rotations: Vec<DQuat> = (0..n).map(|_| rotation(&mut random, d)).collect();
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

/// A random point of `St(d, r)ⁿ`: each block's rows orthonormalised.
fn random_point(d: usize, n: usize, r: usize, random: &mut Random) -> Stack {
    let mut x = Stack::zeros(d, n, r);
    x.data.iter_mut().for_each(|v| *v = random.gaussian());
    retract(&x, &Stack::zeros(d, n, r))
}

/// `⟨grad F, V⟩` and `⟨V, Hess F[V]⟩` against central differences of `F(R_X(h V))`: the polar
/// retraction is second order, so the second difference is the Hessian's quadratic form.
#[test]
fn the_gradient_and_hessian_match_finite_differences() {
    for (d, r, seed) in [(2, 2, 21), (2, 3, 22), (3, 3, 23), (3, 5, 24)] {
        let graph = random_graph(d, 6, 11, seed);
        let problem = reduced(&graph);
        let mut random = Random::new(seed);
        let x = random_point(d, 6, r, &mut random);
        let mut v = Stack::zeros(d, 6, r);
        v.data.iter_mut().for_each(|a| *a = random.gaussian());
        let v = project(&x, &v);
        let model = trust::Model::at(&problem, x.clone());
        let f = |h: f64| problem.cost(&retract(&x, &v.scaled(h))).0;
        let h = 1e-4;
        let first = (f(h) - f(-h)) / (2.0 * h);
        let second = (f(h) - 2.0 * f(0.0) + f(-h)) / (h * h);
        let g = model.gradient.dot(&v);
        let hv = v.dot(&model.hessian(&problem, &v));
        assert!((first - g).abs() <= 1e-6 * g.abs().max(1.0), "{d}, {r}: {first} vs {g}");
        assert!((second - hv).abs() <= 1e-4 * hv.abs().max(1.0), "{d}, {r}: {second} vs {hv}");
    }
}

/// A ring of eight planar poses measured as identical (`R̃ = I`, `t̃ = 0`) started at the twisted
/// state `R_k = rot(2πk/8)`: a local minimum on SO(2)⁸, so the certificate fails there with
/// `S = L − (2 − 2 cos 45°) I` (`Λ_i = (2 − 2cos φ) I`, and `L`'s smallest eigenvalue is 0 on the
/// constant vectors): `λ_min = −(2 − √2)`. The staircase climbs, escapes, and ends at the global
/// minimum, 0, certified.
#[test]
fn the_staircase_escapes_a_twisted_ring() {
    let n = 8;
    let edges: Vec<[usize; 2]> = (0..n).map(|i| [i, (i + 1) % n]).collect();
    let graph = pose_graph(
        2,
        n,
        edges,
        vec![DQuat::IDENTITY; n],
        vec![DVec3::ZERO; n],
        vec![1.0; n],
        vec![1.0; n],
    );
    let problem = reduced(&graph);
    let twisted: Vec<DQuat> =
        (0..n).map(|k| DQuat::from_rotation_z(2.0 * PI * k as f64 / n as f64)).collect();
    let verdict = staircase::certify(&problem, &from_rotations(2, &twisted), 1e-9);
    assert!(!verdict.certified);
    let expected = -(2.0 - 2.0_f64.sqrt());
    assert!((verdict.lambda_min - expected).abs() < 1e-9, "{}", verdict.lambda_min);
    // At rank 3 the escape leads (by the ring's symmetry) to a second saddle: one row of every
    // block common, the other twisted in the plane orthogonal to it, half the cost and the same
    // λ_min; rank 4 untwists it.
    let solved = solve(&problem, 10, &twisted, &mut |_| {}).unwrap();
    assert!(solved.certified && solved.rank > 2, "{} {}", solved.certified, solved.rank);
    let (cost, _) = problem.cost(&from_rotations(2, &solved.rotations));
    assert!(cost < 1e-20, "{cost}");
    // With no room to climb, the twisted ring is where it stays, uncertified.
    let stuck = solve(&problem, 2, &twisted, &mut |_| {}).unwrap();
    assert!(!stuck.certified && stuck.rank == 2);
    let (cost, _) = problem.cost(&from_rotations(2, &stuck.rotations));
    assert!((cost - 8.0 * 2.0 * (2.0 - 2.0_f64.sqrt())).abs() < 1e-9, "{cost}");
}

/// The certificate's lower bound on the global minimum (the relaxation's dual bound). Certified:
/// below the cost by at most the tolerance's share. Ten planar poses with 1 rad of noise, where
/// the relaxation is not tight (its optimum, at rank 3, lies below every set of rotations): not
/// certified, the bound well below the cost and far above 0, and below every local minimum that
/// the rank-2 trust region finds from 40 random starts (none can undercut the global minimum).
/// The same graph held at rank 2: no level certified, the bound 0.
#[test]
fn the_lower_bound_is_below_every_minimum_found() {
    for graph in [noisy(3, 12, 0.3, 31, 0.1), noisy(2, 10, 0.4, 5, 0.1), fixture("tinyGrid3D")] {
        let r = synchronize_poses(&graph, &PoseOptions::default()).unwrap();
        assert!(r.certificate.certified);
        // At a certified optimum the relaxation's value is the cost (to rounding, 1e-15 of it),
        // so the gap is the tolerance's share itself, `tolerance · dn`.
        let share = r.certificate.tolerance * (graph.dimension * graph.count) as f64;
        let gap = r.cost - r.certificate.lower_bound;
        assert!((gap - share).abs() <= 1e-6 * share + 1e-13 * r.cost, "{gap} vs {share}");
    }
    let loose = noisy(2, 10, 0.4, 1, 1.0);
    let r = synchronize_poses(&loose, &PoseOptions::default()).unwrap();
    let lower = r.certificate.lower_bound;
    assert!(!r.certificate.certified && r.certificate.rank > 2);
    assert!(lower > 0.5 * r.cost && lower < r.cost * (1.0 - 1e-3), "{lower} vs {}", r.cost);
    let problem = reduced(&loose);
    let mut random = Random::new(77);
    let mut best = f64::INFINITY;
    for _ in 0..40 {
        let start: Vec<DQuat> = (0..loose.count).map(|_| rotation(&mut random, 2)).collect();
        let local = solve(&problem, 2, &start, &mut |_| {}).unwrap();
        let (cost, _) = problem.cost(&from_rotations(2, &local.rotations));
        assert!(lower <= cost, "a local minimum {cost} below the bound {lower}");
        best = best.min(cost);
    }
    assert!(r.cost <= best * (1.0 + 1e-9), "{} vs the best local minimum {best}", r.cost);
    // Held at rank 2, where it was not certified: no level certified, the bound 0.
    let held = PoseOptions { max_rank: 2, ..PoseOptions::default() };
    let stuck = synchronize_poses(&loose, &held).unwrap().certificate;
    assert!(!stuck.certified && stuck.lower_bound == 0.0, "{stuck:?}");
}

/// The radius after a trial step. One that raised `F`: the minimum of the parabola through
/// `φ(0) = 0`, `φ'(0) = slope` and `φ(1) = rise`, found here by a search over a grid of `t`, times
/// the step's size (or the radius, if smaller), within `[1/64, 1/4]`, a quarter where the slope is
/// not negative. Otherwise the rule of Absil, Baker and Gallivan: a quarter below `ρ = ¼`, double
/// (at most the largest) above `¾` at the boundary, else the same.
#[test]
fn the_radius_follows_what_a_step_taught() {
    let raised = |size: f64, slope: f64, rise: f64| trust::Trial {
        rho: -1.0,
        boundary: true,
        size,
        slope,
        rise,
    };
    for (slope, rise) in [(-1.0, 1.0), (-2.0, 3.0), (-1.0, 9.0), (-0.5, 0.1)] {
        let c = rise - slope;
        let best = (1..=1_000_000)
            .map(|k| k as f64 * 1e-6)
            .min_by(|a, b| (slope * a + c * a * a).total_cmp(&(slope * b + c * b * b)))
            .unwrap();
        let expected = best.clamp(1.0 / 64.0, 0.25) * 8.0;
        let got = trust::next_radius(8.0, 100.0, &raised(8.0, slope, rise));
        assert!((got - expected).abs() <= 8.0 * 2e-6, "{slope}, {rise}: {got} vs {expected}");
    }
    // Far off (ρ of −2,000 after an escape): the floor, a 64th; of the radius where the step
    // stopped short of it.
    assert_eq!(trust::next_radius(8.0, 100.0, &raised(8.0, -1.0, 2000.0)), 8.0 / 64.0);
    assert_eq!(trust::next_radius(8.0, 100.0, &raised(4.0, -1.0, 2000.0)), 4.0 / 64.0);
    assert_eq!(trust::next_radius(2.0, 100.0, &raised(4.0, -1.0, 2000.0)), 2.0 / 64.0);
    // Barely raised: no more than a quarter.
    assert_eq!(trust::next_radius(8.0, 100.0, &raised(8.0, -1.0, 1e-9)), 2.0);
    for slope in [0.0, 1.0, f64::NAN] {
        assert_eq!(trust::next_radius(8.0, 100.0, &raised(8.0, slope, 1.0)), 2.0, "{slope}");
    }
    let taught = |rho: f64, boundary: bool| {
        let trial = trust::Trial { rho, boundary, size: 8.0, slope: -1.0, rise: -0.5 };
        trust::next_radius(8.0, 12.0, &trial)
    };
    for (rho, boundary, expected) in [
        (0.0, true, 2.0),
        (0.1, true, 2.0),
        (0.1, false, 2.0),
        (f64::NAN, true, 2.0),
        (0.25, true, 8.0),
        (0.5, true, 8.0),
        (0.75, true, 8.0),
        (0.9, false, 8.0),
        (0.9, true, 12.0),
    ] {
        assert_eq!(taught(rho, boundary), expected, "ρ = {rho}, boundary {boundary}");
    }
    let trial = trust::Trial { rho: 0.9, boundary: true, size: 8.0, slope: -1.0, rise: -0.5 };
    assert_eq!(trust::next_radius(2.0, 12.0, &trial), 4.0);
    // F unchanged (ρ = 0) by a step short of the boundary: a quarter of the radius, not of the step.
    let trial = trust::Trial { rho: 0.0, boundary: false, size: 4.0, slope: -1.0, rise: 0.0 };
    assert_eq!(trust::next_radius(8.0, 12.0, &trial), 2.0);
}

/// Above rank `d` the preconditioner is `Proj_X((Q − Λ + λ I)⁻¹ ·)` with the point's own `Λ`
/// (where it is positive definite); at rank `d`, `Proj_X((Q + λ I)⁻¹ ·)` even where `Q − Λ + λ I`
/// is positive definite too. Checked against dense solves of those matrices, `Q` assembled column
/// by column from its products, at certified optima (`Q − Λ ⪰ 0`): at rank 3, ten noisy planar
/// poses whose relaxation is not tight; at rank 2, the same with a tenth of the noise.
#[test]
fn above_the_dimension_the_preconditioner_sees_the_multipliers() {
    let mut random = Random::new(9);
    for (sigma, rank) in [(1.0, 3), (0.1, 2)] {
        let graph = noisy(2, 10, 0.4, 1, sigma);
        let problem = reduced(&graph);
        let pre = trust::Preconditioner::new(&problem).unwrap();
        // Rank 3 from a random point; rank 2 from the chordal start (a random one may end at a
        // local minimum, where `Q − Λ` is not positive semidefinite).
        let start = if rank > 2 {
            random_point(2, graph.count, rank, &mut random)
        } else {
            from_rotations(2, &chordal::chordal(&problem).unwrap())
        };
        let x = trust::optimise(&problem, &pre, start, 1e-12, trust::MAX_ITERATIONS, &mut |_| {}).x;
        assert!(staircase::certify(&problem, &x, 1e-9 * problem.scale).certified);
        let sees_lambda = rank > 2;
        let rows = 2 * graph.count;
        let mut a = Mat::<f64>::zeros(rows, rows);
        for c in 0..rows {
            let mut e = Stack::zeros(2, graph.count, 1);
            e.data[c] = 1.0;
            let column = problem.apply(&e);
            for r in 0..rows {
                a[(r, c)] = column.data[r];
            }
        }
        let (_, qx) = problem.cost(&x);
        let lambda = stiefel::multipliers(&x, &qx);
        for i in 0..graph.count {
            for r in 0..2 {
                for c in 0..2 {
                    if sees_lambda {
                        a[(2 * i + r, 2 * i + c)] -= lambda[i][r][c];
                    }
                }
                a[(2 * i + r, 2 * i + r)] += 1e-6 * problem.scale;
            }
        }
        let mut z = Stack::zeros(2, graph.count, rank);
        z.data.iter_mut().for_each(|v| *v = random.gaussian());
        let z = project(&x, &z);
        let rhs = Mat::<f64>::from_fn(rows, rank, |r, c| z.at(r, c));
        let w = a.llt(Side::Lower).unwrap().solve(&rhs);
        let mut dense = Stack::zeros(2, graph.count, rank);
        for c in 0..rank {
            for r in 0..rows {
                *dense.at_mut(r, c) = w[(r, c)];
            }
        }
        let expected = project(&x, &dense);
        let model = trust::Model::at(&problem, x).preconditioned(&problem);
        let got = pre.apply(&problem, &model, &z);
        let gap =
            got.data.iter().zip(&expected.data).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
        let size = expected.data.iter().map(|v| v.abs()).fold(0.0, f64::max);
        assert!(gap <= 1e-8 * size, "rank {rank}: off by {gap} of {size}");
    }
}

fn fixture(name: &str) -> PoseGraph {
    let text = match name {
        "CSAIL" => include_str!("../../../tests/fixtures/posegraphs/CSAIL.g2o"),
        "smallGrid3D" => include_str!("../../../tests/fixtures/posegraphs/smallGrid3D.g2o"),
        _ => include_str!("../../../tests/fixtures/posegraphs/tinyGrid3D.g2o"),
    };
    read_g2o(text, OtherLines::Refuse).unwrap()
}

/// CSAIL (2D, 1,045 poses): MATH.md's optimum, 31.70372 (NumPy LM; SE-Sync's Table 1: 31.70).
#[test]
fn csail_reaches_maths_certified_optimum() {
    let graph = fixture("CSAIL");
    assert_eq!((graph.dimension, graph.count, graph.edges.len()), (2, 1045, 1172));
    let result = synchronize_poses(&graph, &PoseOptions::default()).unwrap();
    assert!((result.cost - 31.70372).abs() <= 1e-6 * 31.70372, "{}", result.cost);
    assert!(result.certificate.certified, "{:?}", result.certificate);
}

/// The 3D grids against bench/posegraph_reference.py (NumPy/SciPy Levenberg–Marquardt from the
/// chordal rotations and least-squares translations, to a relative decrease of 1e-15):
/// tinyGrid3D 18.5193664213, smallGrid3D 1025.39805563.
#[test]
fn the_3d_grids_reach_the_reference_optima_certified() {
    for (name, poses, edges, reference) in
        [("tinyGrid3D", 9, 11, 18.5193664213), ("smallGrid3D", 125, 297, 1025.39805563)]
    {
        let graph = fixture(name);
        assert_eq!((graph.dimension, graph.count, graph.edges.len()), (3, poses, edges));
        let result = synchronize_poses(&graph, &PoseOptions::default()).unwrap();
        assert!((result.cost - reference).abs() <= 1e-9 * reference, "{name}: {}", result.cost);
        assert!(result.certificate.certified, "{name}: {:?}", result.certificate);
    }
}

/// `exact`'s graph with every measurement perturbed: the relative rotation by a normal rotation
/// vector of `sigma` radians, the translation by normal noise of `sigma`.
fn noisy(d: usize, n: usize, p: f64, seed: u64, sigma: f64) -> PoseGraph {
    let (mut graph, _, _) = exact(d, n, p, seed);
    let mut random = Random::new(seed + 1000);
    for (q, t) in graph.relative.iter_mut().zip(&mut graph.translations) {
        let mut v = random.gaussian3() * sigma;
        let mut u = random.gaussian3() * sigma;
        if d == 2 {
            (v.x, v.y, u.z) = (0.0, 0.0, 0.0);
        }
        *q = (*q * crate::quaternion::exp(v * 0.5)).normalize();
        *t += u;
    }
    graph
}

/// Every weight times 1e6: the same poses, the cost and the certificate's numbers times 1e6.
#[test]
fn the_answer_is_in_the_callers_units() {
    let graph = noisy(3, 12, 0.3, 31, 0.1);
    let mut scaled = graph.clone();
    scaled.rotation_weights.iter_mut().for_each(|w| *w *= 1e6);
    scaled.translation_weights.iter_mut().for_each(|w| *w *= 1e6);
    let (a, b) = (
        synchronize_poses(&graph, &PoseOptions::default()).unwrap(),
        synchronize_poses(&scaled, &PoseOptions::default()).unwrap(),
    );
    assert!((b.cost - 1e6 * a.cost).abs() <= 1e-9 * b.cost, "{} vs {}", a.cost, b.cost);
    assert!(a.certificate.certified && b.certificate.certified);
    assert!(
        (b.certificate.tolerance - 1e6 * a.certificate.tolerance).abs()
            <= 1e-9 * b.certificate.tolerance
    );
    let lambda = (a.certificate.lambda_min, b.certificate.lambda_min);
    assert!((lambda.1 - 1e6 * lambda.0).abs() <= 1e6 * a.certificate.tolerance, "{lambda:?}");
    for i in 0..12 {
        assert!(angle(a.rotations[i], b.rotations[i]) < 1e-8);
        assert!((a.translations[i] - b.translations[i]).length() < 1e-8);
    }
}

#[test]
fn bad_graphs_and_options_are_refused_naming_them() {
    let (graph, _, _) = exact(3, 6, 0.3, 41);
    let refused = |graph: &PoseGraph, options: PoseOptions| {
        message(synchronize_poses(graph, &options).unwrap_err())
    };
    let plain = PoseOptions::default;
    let m = refused(&graph, PoseOptions { anchor: 6, ..plain() });
    assert!(m.starts_with("anchor must be a pose, from 0 to 5 (got 6)"), "{m}");
    let m = refused(&graph, PoseOptions { max_rank: 2, ..plain() });
    assert!(m.starts_with("max_rank must be from the dimension, 3, to 64 (got 2)"), "{m}");
    let m = refused(&graph, PoseOptions { max_rank: 65, ..plain() });
    assert!(m.starts_with("max_rank must be from the dimension, 3, to 64 (got 65)"), "{m}");
    let mut bad = graph.clone();
    bad.dimension = 4;
    assert!(refused(&bad, plain()).starts_with("dimension must be 2 or 3 (got 4)"));
    for w in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let mut bad = graph.clone();
        bad.rotation_weights[2] = w;
        let m = refused(&bad, plain());
        assert!(m.starts_with("rotation_weights[2] must be a finite number > 0"), "{w}: {m}");
        let mut bad = graph.clone();
        bad.translation_weights[1] = w;
        let m = refused(&bad, plain());
        assert!(m.starts_with("translation_weights[1] must be a finite number > 0"), "{w}: {m}");
    }
    let mut bad = graph.clone();
    bad.translations[3].y = f64::NAN;
    let m = refused(&bad, plain());
    assert!(
        m.starts_with("translations[3] must be 3 finite numbers: its y component is NaN"),
        "{m}"
    );
    let mut bad = graph.clone();
    bad.relative[0] = DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0);
    assert!(refused(&bad, plain()).starts_with("relative[0] must be a quaternion"));
    let mut bad = graph.clone();
    bad.translation_weights.pop();
    let m = refused(&bad, plain());
    assert!(m.starts_with("translation_weights must hold one value per edge"), "{m}");
    // Two components: poses {0, 1, 2} and {3, 4}, as `synchronize` names them.
    let split = pose_graph(
        2,
        5,
        vec![[0, 1], [1, 2], [3, 4]],
        vec![DQuat::IDENTITY; 3],
        vec![DVec3::X; 3],
        vec![1.0; 3],
        vec![1.0; 3],
    );
    let m = refused(&split, plain());
    assert!(
        m.starts_with("edges do not connect the graph: nodes 3, 4 are cut off from node 0"),
        "{m}"
    );
    let lonely = pose_graph(2, 3, vec![], vec![], vec![], vec![], vec![]);
    let m = refused(&lonely, plain());
    assert!(
        m.starts_with("edges do not connect the graph: nodes 1, 2 are cut off from node 0"),
        "{m}"
    );
    // Ids beyond the count, and a count no edge list could connect (refused without allocating
    // anything of its size).
    let mut beyond = split.clone();
    beyond.edges[1] = [1, 7];
    let m = refused(&beyond, plain());
    assert!(m.starts_with("edges[1] names node 7, but count is 5"), "{m}");
    let mut huge = split.clone();
    huge.count = usize::MAX;
    let m = refused(&huge, plain());
    assert!(m.starts_with("edges do not connect the graph: nodes 3, 4, 5, 6"), "{m}");
    let mut off = split.clone();
    off.edges[2] = [3, 3];
    assert!(refused(&off, plain()).starts_with("edges[2] joins node 3 to itself"));
    // 2D: rotations about z only, translations in the plane.
    let (planar, _, _) = exact(2, 5, 0.3, 42);
    let mut bad = planar.clone();
    bad.relative[1] = DQuat::from_rotation_x(0.1);
    assert!(refused(&bad, plain()).starts_with("relative[1] must be a rotation about z"));
    let mut bad = planar.clone();
    bad.translations[1].z = 1.0;
    assert!(refused(&bad, plain()).starts_with("translations[1] must lie in the plane"));
    let none = pose_graph(2, 0, vec![], vec![], vec![], vec![], vec![]);
    assert!(refused(&none, plain()).starts_with("count must be at least 1"));
    // One pose: trivially the anchor, certified.
    let one = pose_graph(3, 1, vec![], vec![], vec![], vec![], vec![]);
    let result = synchronize_poses(&one, &plain()).unwrap();
    assert_eq!((result.rotations, result.translations), (vec![DQuat::IDENTITY], vec![DVec3::ZERO]));
    assert!(result.cost == 0.0 && result.certificate.certified);
}

/// The benchmark graphs, timed: `KLI_POSEGRAPHS=<folder of SE-Sync's data/> cargo test --release
/// --lib measure_the_benchmark_graphs -- --ignored --nocapture` prints each file's poses, cost,
/// certificate and time (MATH.md's optima: CSAIL 31.70372, intel 52.34823, manhattan 6,431.391,
/// garage 1.262524, sphere2500 1,687.006).
#[cfg(not(target_arch = "wasm32"))]
#[test]
#[ignore]
fn measure_the_benchmark_graphs() {
    let Ok(folder) = std::env::var("KLI_POSEGRAPHS") else { return };
    let names = std::env::var("KLI_POSEGRAPH_FILES")
        .unwrap_or_else(|_| "CSAIL intel parking-garage sphere2500".into());
    for name in names.split_whitespace() {
        let text = std::fs::read_to_string(format!("{folder}/{name}.g2o")).unwrap();
        let start = std::time::Instant::now();
        let graph = read_g2o(&text, OtherLines::Skip).unwrap();
        let read = start.elapsed();
        let result = synchronize_poses(&graph, &PoseOptions::default()).unwrap();
        let total = start.elapsed();
        println!(
            "{name}: d = {}, {} poses, {} edges: f = {:.10}, {} trust-region steps, {:?}, read \
             {read:.2?}, total {total:.2?}",
            graph.dimension,
            graph.count,
            graph.edges.len(),
            result.cost,
            result.iterations,
            result.certificate,
        );
    }
}

/// Weights and translations at the ends of f64's range: an answer with finite poses, or the
/// refusal that names the graph's scale; never a panic or a hang.
#[test]
fn extreme_scales_end_in_an_answer_or_a_refusal() {
    let base = noisy(3, 8, 0.3, 51, 0.05);
    let m = base.edges.len();
    let mut cases = Vec::new();
    for (k, w) in [(0, 1e-300), (1, 1e300), (2, f64::MIN_POSITIVE), (3, 1e-20)] {
        let mut g = base.clone();
        g.translation_weights[k] = w;
        cases.push(g.clone());
        g.rotation_weights[k] = w;
        cases.push(g);
    }
    for scale in [1e200, 1e-200, 1e150] {
        let mut g = base.clone();
        g.translations.iter_mut().for_each(|t| *t *= scale);
        cases.push(g);
    }
    let mut g = base.clone();
    g.translations[m - 1] = DVec3::splat(1e300);
    cases.push(g);
    for (c, graph) in cases.iter().enumerate() {
        match synchronize_poses(graph, &PoseOptions::default()) {
            Ok(result) => {
                assert!(result.cost.is_finite() && result.cost >= 0.0, "case {c}: {}", result.cost);
                assert!(result.translations.iter().all(|t| t.is_finite()), "case {c}");
                assert!(result.rotations.iter().all(|q| q.is_finite()), "case {c}");
            }
            Err(e) => assert_eq!(e.argument(), "graph", "case {c}: {e}"),
        }
    }
}

/// Observing a solve changes nothing, and the stages come in the order the solver takes them:
/// the chordal start, then each level optimised then certified (ranks rising by one from the
/// dimension, the iterations so far never falling), rounding only after a level above the
/// dimension, the translations last.
#[test]
fn observing_a_solve_reports_its_stages_and_changes_nothing() {
    for (graph, d) in [(noisy(2, 40, 0.2, 5, 0.3), 2), (fixture("tinyGrid3D"), 3)] {
        let options = PoseOptions::default();
        let mut stages = Vec::new();
        let observed =
            synchronize_poses_observed(&graph, &options, &mut |s| stages.push(s)).unwrap();
        assert_eq!(observed, synchronize_poses(&graph, &options).unwrap());
        assert_eq!(stages.first(), Some(&PoseStage::Chordal));
        assert_eq!(stages.last(), Some(&PoseStage::Translations));
        assert_eq!(stages[1], PoseStage::Optimising { rank: d, iterations: 0 });
        let levels: Vec<(usize, usize)> = stages
            .iter()
            .filter_map(|s| match *s {
                PoseStage::Optimising { rank, iterations } => Some((rank, iterations)),
                _ => None,
            })
            .collect();
        let certified: Vec<usize> = stages
            .iter()
            .filter_map(|s| match *s {
                PoseStage::Certifying { rank } => Some(rank),
                _ => None,
            })
            .collect();
        assert!(levels.windows(2).all(|w| w[1].0 == w[0].0 + 1 && w[1].1 >= w[0].1), "{levels:?}");
        let rounded = stages.contains(&PoseStage::Rounding);
        assert_eq!(rounded, levels.len() > 1, "{stages:?}");
        // A certificate a level, and one more of the rounded rotations.
        assert_eq!(certified.len(), levels.len() + usize::from(rounded), "{stages:?}");
        assert_eq!(observed.certificate.rank, levels.last().unwrap().0);
        // Each trust-region step announced once, numbered 1, 2, … through the whole solve, at the
        // rank of the level it belongs to (the last pass's at the dimension).
        let steps: Vec<(usize, usize)> = stages
            .iter()
            .filter_map(|s| match *s {
                PoseStage::Step { rank, iterations } => Some((rank, iterations)),
                _ => None,
            })
            .collect();
        assert_eq!(
            steps.iter().map(|s| s.1).collect::<Vec<_>>(),
            (1..=observed.iterations).collect::<Vec<_>>()
        );
        let mut rank = d;
        for stage in &stages {
            match *stage {
                PoseStage::Optimising { rank: r, .. } => rank = r,
                PoseStage::Rounding => rank = d,
                PoseStage::Step { rank: r, .. } => assert_eq!(r, rank, "{stages:?}"),
                _ => {}
            }
        }
    }
}

/// Newton's gradient and Hessian (translations kept, `Y_i ← exp([Ω_i]) Y_i`, `t_i + δ_i`, node 0
/// fixed) against central differences of the cost, along random directions at random points, in
/// 2D at ranks 2 and 3 and in 3D: `gᵀx` and `xᵀ H x`. The cost itself: at rank `d` against
/// `pose_cost` (the caller's form), and at every rank, with the translations solved, against the
/// eliminated `tr(Xᵀ Q X)`.
#[test]
fn newtons_gradient_and_hessian_match_finite_differences() {
    for (d, r, seed) in [(2, 2, 31), (2, 3, 34), (3, 3, 32), (3, 3, 33)] {
        let n = 6;
        let graph = random_graph(d, n, 11, seed);
        let problem = reduced(&graph);
        let system = newton::System::new(&problem, r);
        let (p, v) = (system.p, system.v);
        let mut random = Random::new(seed);
        // At rank d, rotations (random_point's blocks may be reflections).
        let rotations: Vec<DQuat> = (0..n).map(|_| rotation(&mut random, d)).collect();
        let x =
            if r == d { from_rotations(d, &rotations) } else { random_point(d, n, r, &mut random) };
        let y = newton::blocks(&x);
        let t: Vec<[f64; 3]> = (0..n)
            .map(|_| std::array::from_fn(|a| if a < r { 2.0 * random.gaussian() } else { 0.0 }))
            .collect();
        let optimal = newton::translations(&problem, &y, r);
        let eliminated = problem.cost(&x).0;
        let kept = newton::cost(&problem, r, &y, &optimal);
        assert!(
            (kept - eliminated).abs() <= 1e-12 * eliminated,
            "{d}D, {r}: {kept} vs {eliminated}"
        );
        if r == d {
            let positions: Vec<DVec3> = t.iter().map(|t| DVec3::new(t[0], t[1], t[2])).collect();
            let direct = pose_cost(&graph, &graph.relative, &rotations, &positions);
            let ours = newton::cost(&problem, r, &y, &t);
            assert!((ours - direct).abs() <= 1e-12 * direct, "{d}D: {ours} vs {direct}");
        }
        let direction: Vec<f64> = (0..v * (n - 1)).map(|_| random.gaussian()).collect();
        // exp(h [Ω]) by glam (r = 3) or by its angle (r = 2), Y_i and t_i moved by h.
        let f = |h: f64| {
            let mut moved = y.clone();
            let mut shifted = t.clone();
            for i in 1..n {
                let at = v * (i - 1);
                let w = &direction[at..at + p];
                let e = if r == 2 {
                    DMat3::from_rotation_z(h * w[0])
                } else {
                    DMat3::from_quat(DQuat::from_scaled_axis(h * DVec3::new(w[0], w[1], w[2])))
                };
                for a in 0..r {
                    for b in 0..d {
                        moved[i][a][b] = (0..r).map(|k| e.col(k)[a] * y[i][k][b]).sum();
                    }
                    shifted[i][a] += h * direction[at + p + a];
                }
            }
            newton::cost(&problem, r, &moved, &shifted)
        };
        let (g, values, _) = newton::model(&system, &problem, &y, &t);
        let hx = system.apply(&values, &direction, &problem.edges);
        let gx: f64 = g.iter().zip(&direction).map(|(a, b)| a * b).sum();
        let xhx: f64 = hx.iter().zip(&direction).map(|(a, b)| a * b).sum();
        let h = 1e-4;
        let first = (f(h) - f(-h)) / (2.0 * h);
        let second = (f(h) - 2.0 * f(0.0) + f(-h)) / (h * h);
        assert!((first - gx).abs() <= 1e-6 * gx.abs().max(1.0), "{d}D, {r}: {first} vs {gx}");
        assert!((second - xhx).abs() <= 1e-4 * xhx.abs().max(1.0), "{d}D, {r}: {second} vs {xhx}");
    }
}

/// The model's decrease along a shortened damped step, as the halvings judge it, against the
/// quadratic model written out with the Hessian: for a random `δ` and `μ`, `g` is set so that `δ`
/// solves `(H + μD) δ = −g`, and `m(0) − m(αδ) = −α gᵀδ − ½ α² δᵀHδ`.
#[test]
fn newtons_decrease_along_a_halved_step_is_the_models() {
    for (r, seed) in [(2, 71), (3, 72)] {
        let n = 7;
        let graph = random_graph(2, n, 12, seed);
        let problem = reduced(&graph);
        let system = newton::System::new(&problem, r);
        let mut random = Random::new(seed);
        let x = random_point(2, n, r, &mut random);
        let y = newton::blocks(&x);
        let t = newton::translations(&problem, &y, r);
        let (_, values, diagonal) = newton::model(&system, &problem, &y, &t);
        let delta: Vec<f64> = (0..system.v * (n - 1)).map(|_| random.gaussian()).collect();
        let h_delta = system.apply(&values, &delta, &problem.edges);
        let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(a, b)| a * b).sum::<f64>();
        let d_delta: Vec<f64> = diagonal.iter().zip(&delta).map(|(d, x)| d * x).collect();
        for mu in [0.0, 1e-3, 0.7] {
            let g: Vec<f64> = h_delta.iter().zip(&d_delta).map(|(h, dd)| -(h + mu * dd)).collect();
            let (slope, curvature) = (dot(&g, &delta), dot(&delta, &h_delta));
            for alpha in [1.0, 0.5, 0.125, 1.0 / 32.0] {
                let model = -alpha * slope - 0.5 * alpha * alpha * curvature;
                let ours = newton::decrease(alpha, mu, dot(&delta, &d_delta), slope);
                assert!(
                    (ours - model).abs() <= 1e-10 * model.abs().max(1.0),
                    "rank {r}, μ {mu}, α {alpha}: {ours} against {model}"
                );
            }
        }
    }
}

/// The line search along a rejected step: it takes the first of `α = 1, ½, ¼, …` that lowers `f`
/// (here `f(α) = (α − 0.2)² − 0.04` from `f(0) = 0`, lowered from `α < 0.4`: at `¼`), gives up
/// after [`newton::HALVINGS`] halvings (a step that never lowers `f`), and takes a `ρ` that is not
/// a number for a rise.
#[test]
fn newtons_line_search_halves_a_rejected_step_until_it_lowers_f() {
    let mut tried = Vec::new();
    let (alpha, rho, halvings) = newton::backtrack(|alpha| {
        tried.push(alpha);
        let f = (alpha - 0.2_f64).powi(2) - 0.04;
        (alpha, -f / alpha)
    });
    assert_eq!((alpha, halvings), (0.25, 2));
    assert_eq!(tried, [1.0, 0.5, 0.25]);
    assert!((rho - 0.15).abs() < 1e-12, "ρ {rho}");
    let mut count = 0;
    let (alpha, rho, halvings) = newton::backtrack(|alpha| {
        count += 1;
        (alpha, if count % 2 == 0 { f64::NAN } else { -1.0 })
    });
    assert_eq!(halvings, newton::HALVINGS);
    assert_eq!(count, newton::HALVINGS + 1);
    assert_eq!(alpha, 0.5_f64.powi(newton::HALVINGS as i32));
    assert!(!newton::lowers(rho));
    assert!(!newton::lowers(0.0) && !newton::lowers(f64::INFINITY) && newton::lowers(1e-300));
}

/// The damping after a step (Nielsen 1999, with Marquardt's threshold for Newton's own step):
/// `ρ > 0.75` returns Newton's own step, `μ = 0`; otherwise `μ · (1 − (2ρ − 1)³)`; and only
/// Newton's own step, neither damped nor halved, predicting no more than `f`'s rounding, ends the
/// method.
#[test]
fn newtons_damping_after_a_step_and_its_last_step() {
    let mu = 1e-3;
    assert_eq!(newton::damping_after(mu, 0.76), 0.0);
    assert_eq!(newton::damping_after(mu, 1.4), 0.0);
    for (rho, factor) in [(0.75, 0.875), (0.6, 1.0 - 0.2_f64.powi(3)), (0.5, 1.0), (0.1, 1.512)] {
        let after = newton::damping_after(mu, rho);
        assert!((after - mu * factor).abs() <= 1e-15, "ρ {rho}: {after} against {}", mu * factor);
    }
    assert!((newton::damping_after(mu, 0.7) - mu * (1.0 - 0.4_f64.powi(3))).abs() <= 1e-15);
    assert!(newton::last_step(0.0, 0, 1e-16, 1e-15));
    assert!(newton::last_step(0.0, 0, 1e-15, 1e-15));
    assert!(!newton::last_step(0.0, 0, 2e-15, 1e-15));
    assert!(!newton::last_step(1e-9, 0, 1e-16, 1e-15));
    assert!(!newton::last_step(0.0, 1, 1e-16, 1e-15));
}

/// The damping after a refusal (or a step that raised `f` even halved), worked by hand: Newton's own
/// step refused, a tenth of the last damping that took a step, or the least, 1e-12, if none did;
/// then, until a damped step is taken, a hundredfold each time (ν untouched); after one, Nielsen's
/// `μ ν` with `ν` doubling.
#[test]
fn newtons_damping_probes_a_hundredfold_until_a_step_is_taken() {
    let close = |(mu, nu): (f64, f64), (want_mu, want_nu): (f64, f64)| {
        assert!((mu - want_mu).abs() <= 1e-15 * want_mu, "μ {mu} against {want_mu}");
        assert_eq!(nu, want_nu);
    };
    close(newton::grown(0.0, 2.0, 0.0), (1e-12, 2.0));
    close(newton::grown(1e-12, 2.0, 0.0), (1e-10, 2.0));
    close(newton::grown(1e-10, 2.0, 0.0), (1e-8, 2.0));
    close(newton::grown(0.0, 2.0, 3e-5), (3e-6, 2.0));
    close(newton::grown(3e-6, 2.0, 3e-5), (6e-6, 4.0));
    close(newton::grown(6e-6, 4.0, 3e-5), (2.4e-5, 8.0));
    // The least is a floor for Nielsen's growth too.
    close(newton::grown(1e-20, 2.0, 1e-9), (1e-12, 4.0));
}

/// Newton's method (translations kept) and the trust region (translations eliminated) are two
/// methods on two forms of one cost: from the chordal start of noisy graphs, 2D and 3D, Newton
/// converges in a handful of steps to the trust region's minimum (the cost to 1e-10, where the
/// reduced gradient is at rounding), and from a random start, where the Hessian is indefinite,
/// its damping takes it to a critical point below where it began.
#[test]
fn newton_reaches_the_trust_regions_minimum() {
    for (d, seed, sigma) in [(2, 51, 0.05), (3, 52, 0.05), (2, 53, 0.3), (3, 54, 0.3)] {
        let graph = noisy(d, 25, 0.2, seed, sigma);
        let problem = reduced(&graph);
        let gradient = GRADIENT * problem.scale * ((d * problem.n) as f64).sqrt();
        let start = from_rotations(d, &chordal::chordal(&problem).unwrap());
        let mut steps = Vec::new();
        let refined = newton::refine(&problem, &start, gradient, &mut |k| steps.push(k));
        assert!(refined.converged, "{d}D σ {sigma}: Newton did not converge");
        assert!(refined.iterations <= 8, "{d}D σ {sigma}: {} steps", refined.iterations);
        assert_eq!(steps, (1..=refined.iterations).collect::<Vec<_>>());
        let preconditioner = trust::Preconditioner::new(&problem).unwrap();
        let optimised =
            trust::optimise(&problem, &preconditioner, start.clone(), gradient, 300, &mut |_| {});
        let (newton_cost, trust_cost) = (problem.cost(&refined.x).0, problem.cost(&optimised.x).0);
        assert!(
            (newton_cost - trust_cost).abs() <= 1e-10 * trust_cost,
            "{d}D σ {sigma}: Newton {newton_cost} against the trust region {trust_cost}"
        );
        let reduced_gradient = trust::Model::at(&problem, refined.x.clone()).gradient.norm();
        assert!(reduced_gradient <= 1e3 * gradient, "{d}D σ {sigma}: gradient {reduced_gradient}");
        let mut random = Random::new(seed);
        let far = from_rotations(d, &(0..25).map(|_| rotation(&mut random, d)).collect::<Vec<_>>());
        let from_far = newton::refine(&problem, &far, gradient, &mut |_| {});
        assert!(problem.cost(&from_far.x).0 <= problem.cost(&far).0, "{d}D σ {sigma}: rose");
        // From there the Hessian is indefinite: only the damping gets Newton to a critical point.
        assert!(from_far.converged, "{d}D σ {sigma}: from a random start, not converged");
        let far_gradient = trust::Model::at(&problem, from_far.x.clone()).gradient.norm();
        assert!(far_gradient <= 1e3 * gradient, "{d}D σ {sigma}: gradient {far_gradient}");
    }
}

/// Newton from random points of random graphs (measurements no poses fit), 2D at ranks 2 and 3:
/// the Hessian is indefinite there, and only the damping (`μ` over the Gauss–Newton diagonal)
/// takes the method to a critical point, below where it began.
#[test]
fn newtons_damping_reaches_a_critical_point_from_anywhere() {
    for (n, m, seed) in [(25, 60, 61), (12, 40, 63), (30, 30, 64)] {
        let graph = random_graph(2, n, m, seed);
        let problem = reduced(&graph);
        let gradient = GRADIENT * problem.scale * ((2 * problem.n) as f64).sqrt();
        let mut random = Random::new(seed);
        for r in [2, 3] {
            let far = random_point(2, n, r, &mut random);
            let out = newton::refine(&problem, &far, gradient, &mut |_| {});
            assert!(out.converged, "n {n}, m {m}, rank {r}: not converged");
            assert!(problem.cost(&out.x).0 <= problem.cost(&far).0, "n {n}, rank {r}: rose");
            let size = trust::Model::at(&problem, out.x.clone()).gradient.norm();
            assert!(size <= 1e3 * gradient, "n {n}, m {m}, rank {r}: gradient {size}");
        }
    }
}

/// Newton's method goes first in 3D where the graph fills in little ([`NEWTON_FILL_3D`]): a ring
/// with node 0 left out is a path, which a factorisation fills in not at all (fill exactly 1);
/// smallGrid3D, a 5 × 5 × 5 lattice, fills in well beyond the bound. In 2D it always goes first,
/// and above rank 3 (`St(3, 4)` has directions that leave the cost unchanged) never.
#[test]
fn newton_goes_first_where_the_graph_fills_in_little() {
    let ring = reduced(&exact(3, 60, 0.0, 71).0);
    assert_eq!(ring.fill, 1.0);
    assert!(newton_first(&ring, 3));
    assert!(!newton_first(&ring, 4));
    let grid = fixture("smallGrid3D");
    let lattice = reduced(&grid);
    assert!(lattice.fill > NEWTON_FILL_3D, "smallGrid3D fills {}", lattice.fill);
    assert!(!newton_first(&lattice, 3));
    // The lattice's edges in the plane, each measurement the identity.
    let m = grid.edges.len();
    let planar = pose_graph(
        2,
        grid.count,
        grid.edges.clone(),
        vec![DQuat::IDENTITY; m],
        vec![DVec3::X; m],
        vec![1.0; m],
        vec![1.0; m],
    );
    let planar = reduced(&planar);
    assert_eq!(planar.fill, lattice.fill);
    assert!(newton_first(&planar, 2) && newton_first(&planar, 3));
}
