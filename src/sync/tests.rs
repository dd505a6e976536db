//! Tests against MATH.md's reference values and independent computations (dense matrices,
//! finite differences, the flow).

use std::f64::consts::{FRAC_1_SQRT_2, PI};

use faer::{Mat, Side};
use glam::{DMat3, DQuat, DVec3};

use super::*;
use crate::error::KliError;
use crate::quaternion::{exp, from_wxyz};
use crate::swarm::Random;

fn about_x(degrees: f64) -> DQuat {
    DQuat::from_rotation_x(degrees.to_radians())
}

/// The angle between two rotations, blind to sign.
fn angle(a: DQuat, b: DQuat) -> f64 {
    let e = a.conjugate() * b;
    2.0 * DVec3::new(e.x, e.y, e.z).length().atan2(e.w.abs())
}

fn triangle() -> Graph {
    let rel = [DQuat::IDENTITY, DQuat::IDENTITY, about_x(60.0)];
    Graph::new(None, &[[0, 1], [1, 2], [0, 2]], &rel, None).unwrap()
}

#[test]
fn triangle_spreads_the_loop_error_evenly() {
    let result = synchronize(&triangle(), &SyncOptions::default()).unwrap();
    let expected = [
        [1.0, 0.0, 0.0, 0.0],
        [0.984807753012208, 0.173648177666930, 0.0, 0.0],
        [0.939692620785908, 0.342020143325669, 0.0, 0.0],
    ];
    for (q, e) in result.rotations.iter().zip(expected) {
        let got = crate::quaternion::to_wxyz(*q);
        for k in 0..4 {
            assert!((got[k] - e[k]).abs() < 1e-12, "{got:?} vs {e:?}");
        }
    }
    assert!((result.cost - 0.723688550569099).abs() < 1e-12, "{}", result.cost);
    for r in &result.residuals {
        assert!((r.to_degrees() - 20.0).abs() < 1e-9, "{r}");
    }
    let certificate = result.certificate.unwrap();
    assert!(certificate.certified);
    assert!(certificate.gap > 0.0);
    // τ = 1e-9 × the largest weighted degree: 2 in a triangle of unit weights; 1 + 2 + 4 = 7 at
    // the centre of a weighted star (in the caller's units, whatever the solver's scaling).
    assert_eq!(certificate.tolerance, 2e-9);
    let star =
        Graph::new(None, &[[0, 1], [0, 2], [3, 0]], &[about_x(10.0); 3], Some(&[1.0, 2.0, 4.0]))
            .unwrap();
    let tolerance =
        synchronize(&star, &SyncOptions::default()).unwrap().certificate.unwrap().tolerance;
    assert!((tolerance - 7e-9).abs() < 1e-24, "{tolerance}");
}

#[test]
fn square_of_quarter_turns_is_consistent_on_so3() {
    // The quaternion product round the loop is −1: a sign-dependent method sees a 360° error.
    let quarter = from_wxyz([FRAC_1_SQRT_2, 0.0, 0.0, FRAC_1_SQRT_2]);
    let graph = Graph::new(None, &[[0, 1], [1, 2], [2, 3], [3, 0]], &[quarter; 4], None).unwrap();
    for method in [Method::Chordal, Method::Spectral, Method::Robust] {
        let result = synchronize(&graph, &SyncOptions { method, ..Default::default() }).unwrap();
        assert!(result.cost < 1e-16, "{method:?} {}", result.cost);
        let expected = [
            [1.0, 0.0, 0.0, 0.0],
            [FRAC_1_SQRT_2, 0.0, 0.0, FRAC_1_SQRT_2],
            [0.0, 0.0, 0.0, 1.0],
            [FRAC_1_SQRT_2, 0.0, 0.0, -FRAC_1_SQRT_2],
        ];
        for (q, e) in result.rotations.iter().zip(expected) {
            assert!(angle(*q, from_wxyz(e)) < 1e-9, "{method:?} {q:?} vs {e:?}");
            assert!(q.w >= 0.0);
        }
    }
}

/// A random connected graph in the style of Chatterjee and Govindu: edges with probability `p`
/// (and a ring, so it is connected), each measured with a Gaussian angle of `noise` radians about
/// a random axis, a share `wrong` of them replaced by uniform random rotations, random signs.
pub(super) struct Synthetic {
    pub graph: Graph,
    pub truth: Vec<DQuat>,
    pub wrong: Vec<bool>,
}

pub(super) fn synthetic(n: usize, p: f64, noise: f64, wrong: f64, seed: u64) -> Synthetic {
    let mut random = Random::new(seed);
    let truth: Vec<DQuat> = (0..n).map(|_| random.unit_quaternion()).collect();
    let mut edges = Vec::new();
    for i in 0..n {
        for j in i + 1..n {
            if j == i + 1 || (i == 0 && j == n - 1) || random.uniform() < p {
                edges.push([i, j]);
            }
        }
    }
    let mut relative = Vec::new();
    let mut is_wrong = Vec::new();
    for &[i, j] in &edges {
        let bad = random.uniform() < wrong;
        let q = if bad {
            random.unit_quaternion()
        } else {
            let axis = random.gaussian3().normalize();
            let angle = noise * random.gaussian();
            truth[i].conjugate() * truth[j] * exp(axis * (angle / 2.0))
        };
        let sign = if random.uniform() < 0.5 { -1.0 } else { 1.0 };
        relative.push(q * sign);
        is_wrong.push(bad);
    }
    Synthetic {
        graph: Graph::new(Some(n), &edges, &relative, None).unwrap(),
        truth,
        wrong: is_wrong,
    }
}

/// `f` at `q_i exp(δ_i/2)`.
fn pulled_back(graph: &Graph, q: &[DQuat], delta: &[f64]) -> f64 {
    let moved: Vec<DQuat> = q
        .iter()
        .enumerate()
        .map(|(i, &q)| q * exp(DVec3::new(delta[3 * i], delta[3 * i + 1], delta[3 * i + 2]) * 0.5))
        .collect();
    cost::cost(graph, &moved)
}

#[test]
fn the_second_order_model_matches_finite_differences() {
    let s = synthetic(12, 0.4, 0.3, 0.2, 7);
    let mut random = Random::new(3);
    let q: Vec<DQuat> = (0..12).map(|_| random.unit_quaternion()).collect();
    let (g, h) = cost::model(&s.graph, &q, false);
    let dim = 36;
    let h_step = 1e-4;
    for trial in 0..5 {
        let v: Vec<f64> = (0..dim).map(|_| random.gaussian()).collect();
        let plus: Vec<f64> = v.iter().map(|x| x * h_step).collect();
        let minus: Vec<f64> = v.iter().map(|x| -x * h_step).collect();
        let zero = vec![0.0; dim];
        let (fp, f0, fm) = (
            pulled_back(&s.graph, &q, &plus),
            pulled_back(&s.graph, &q, &zero),
            pulled_back(&s.graph, &q, &minus),
        );
        let slope = (fp - fm) / (2.0 * h_step);
        let curvature = (fp - 2.0 * f0 + fm) / (h_step * h_step);
        let gv: f64 = g.iter().zip(&v).map(|(a, b)| a * b).sum();
        let mut hv = vec![0.0; dim];
        h.apply(&s.graph, &v, &mut hv);
        let vhv: f64 = v.iter().zip(&hv).map(|(a, b)| a * b).sum();
        assert!((slope - gv).abs() < 1e-6 * (1.0 + gv.abs()), "trial {trial}: {slope} vs {gv}");
        assert!(
            (curvature - vhv).abs() < 1e-4 * (1.0 + vhv.abs()),
            "trial {trial}: {curvature} vs {vhv}"
        );
    }
}

/// The connection Laplacian written densely from MATH.md: `d_i I₃` on the diagonal, `−w_ij R_ij`
/// at `(i, j)` and its transpose at `(j, i)`.
fn dense_laplacian(graph: &Graph) -> Mat<f64> {
    let n = graph.count();
    let mut l = Mat::<f64>::zeros(3 * n, 3 * n);
    for ((&[i, j], &rel), &w) in graph.edges().iter().zip(graph.relative()).zip(graph.weights()) {
        let rij = DMat3::from_quat(rel);
        for a in 0..3 {
            l[(3 * i + a, 3 * i + a)] += w;
            l[(3 * j + a, 3 * j + a)] += w;
            for b in 0..3 {
                l[(3 * i + a, 3 * j + b)] -= w * rij.col(b)[a];
                l[(3 * j + b, 3 * i + a)] -= w * rij.col(b)[a];
            }
        }
    }
    l
}

#[allow(clippy::needless_range_loop)]
/// `S = L − Λ` written densely from MATH.md's formulas.
fn dense_certificate(graph: &Graph, q: &[DQuat]) -> Mat<f64> {
    let n = graph.count();
    let l = dense_laplacian(graph);
    let r: Vec<DMat3> = q.iter().map(|&q| DMat3::from_quat(q)).collect();
    let mut y = Mat::<f64>::zeros(3 * n, 3);
    for i in 0..n {
        for a in 0..3 {
            for b in 0..3 {
                y[(3 * i + a, b)] = r[i].col(a)[b]; // (R_iᵀ)_ab = (R_i)_ba
            }
        }
    }
    let ly = &l * &y;
    let mut s = l.clone();
    for i in 0..n {
        // Λ_i = sym((LY)_i R_i)
        let mut m = [[0.0; 3]; 3];
        for a in 0..3 {
            for b in 0..3 {
                m[a][b] = (0..3).map(|k| ly[(3 * i + a, k)] * r[i].col(b)[k]).sum();
            }
        }
        for a in 0..3 {
            for b in 0..3 {
                s[(3 * i + a, 3 * i + b)] -= 0.5 * (m[a][b] + m[b][a]);
            }
        }
    }
    s
}

/// The eigenvalues of the dense `S`, by faer's dense self-adjoint solver.
fn dense_certificate_eigenvalues(graph: &Graph, q: &[DQuat]) -> Vec<f64> {
    dense_certificate(graph, q).self_adjoint_eigenvalues(Side::Lower).unwrap()
}

/// Gershgorin's bound of the block `S`, the shift the certificate's Lanczos starts from where it
/// is not certified, is the dense matrix's `min_i (s_ii − Σ_{j≠i} |s_ij|)`, and below every
/// eigenvalue: at the optimum (certified) and where wrong edges leave the relaxation loose.
#[test]
fn gershgorins_bound_is_the_dense_matrixs() {
    for wrong in [0.0, 0.3] {
        let s = synthetic(16, 0.35, 0.1, wrong, 0);
        let q = synchronize(&s.graph, &SyncOptions::default()).unwrap().rotations;
        let dense = dense_certificate(&s.graph, &q);
        let rows = dense.nrows();
        let bound = (0..rows)
            .map(|i| {
                dense[(i, i)]
                    - (0..rows).filter(|&j| j != i).map(|j| dense[(i, j)].abs()).sum::<f64>()
            })
            .fold(f64::INFINITY, f64::min);
        let got = certificate::certificate_matrix(&s.graph, &q).gershgorin_lower(&s.graph);
        assert!((got - bound).abs() < 1e-12 * bound.abs(), "{wrong}: {got} vs {bound}");
        let lowest = dense_certificate_eigenvalues(&s.graph, &q)[0];
        assert!(got < lowest, "{wrong}: {got} vs {lowest}");
    }
}

#[test]
fn the_certificate_agrees_with_a_dense_eigensolver() {
    for (seed, noise) in [(1, 0.05), (2, 0.2), (3, 0.4)] {
        let s = synthetic(20, 0.3, noise, 0.0, seed);
        let result = synchronize(&s.graph, &SyncOptions::default()).unwrap();
        let certificate = result.certificate.unwrap();
        let dense = dense_certificate_eigenvalues(&s.graph, &result.rotations);
        assert!(dense[0].abs() < 1e-9 && dense[2].abs() < 1e-9, "{:?}", &dense[..4]);
        assert!(dense[3] > 0.0);
        assert!(certificate.certified);
        // Converged Ritz values are far more accurate than the residual's 1e-8: to 1e-11 here,
        // finer than the shift's own size (τ = 1e-9 d_max), so a shift of the wrong sign shows.
        assert!(
            (certificate.gap - dense[3]).abs() < 1e-11 * dense[3],
            "{} vs {}",
            certificate.gap,
            dense[3]
        );
        assert!(certificate.lambda_min.abs() < 1e-9);
    }
}

/// The solvers see the largest weight as 1; the certificate is given back in the caller's units
/// (`S` is linear in the weights): against the dense eigensolver of the caller's `S`, with
/// uneven weights whose largest is 250, then 1e-3. Noise only, certified: `λ₄` and `τ`; with
/// wrong edges, where the chordal relaxation is not tight (not certified): `λ_min` too.
#[test]
fn the_certificate_is_in_the_callers_units() {
    for largest in [250.0, 1e-3] {
        for (wrong, certified) in [(0.0, true), (0.3, false)] {
            let s = synthetic(16, 0.35, 0.1, wrong, 0);
            let uneven: Vec<f64> =
                (0..s.graph.edges().len()).map(|k| [0.3, 0.7, 1.0][k % 3] * largest).collect();
            let graph =
                Graph::new(Some(16), s.graph.edges(), s.graph.relative(), Some(&uneven)).unwrap();
            let result = synchronize(&graph, &SyncOptions::default()).unwrap();
            let certificate = result.certificate.unwrap();
            assert_eq!(certificate.certified, certified, "{largest}, {wrong}");
            let dense = dense_certificate_eigenvalues(&graph, &result.rotations);
            let (got, want) = if certified {
                (certificate.gap, dense[3])
            } else {
                (certificate.lambda_min, dense[0])
            };
            assert!((got - want).abs() < 1e-7 * want.abs(), "{largest}, {wrong}: {got} vs {want}");
            let mut degrees = [0.0; 16];
            for (&[i, j], &w) in graph.edges().iter().zip(graph.weights()) {
                degrees[i] += w;
                degrees[j] += w;
            }
            let tolerance = 1e-9 * degrees.iter().copied().fold(0.0, f64::max);
            assert!((certificate.tolerance - tolerance).abs() < 1e-12 * tolerance, "{largest}");
        }
    }
}

/// The twisted state of a ring with every measurement the identity: node k turned by
/// 2πk/n about z. Each edge is off by the same angle, so every node is pulled equally both ways:
/// a stationary point with `f > 0`, while the consensus has `f = 0`.
#[test]
fn the_certificate_fails_at_a_twisted_ring() {
    let n = 10;
    let edges: Vec<[usize; 2]> = (0..n).map(|i| [i, (i + 1) % n]).collect();
    let graph = Graph::new(None, &edges, &vec![DQuat::IDENTITY; n], None).unwrap();
    let twisted: Vec<DQuat> =
        (0..n).map(|k| DQuat::from_rotation_z(2.0 * PI * k as f64 / n as f64)).collect();
    let (gradient, _) = cost::model(&graph, &twisted, false);
    assert!(gradient.iter().all(|g| g.abs() < 1e-12));
    // Newton from the twisted state stays there: it is a critical point.
    let reduced = blocks::Pattern::new(&graph, Some(0));
    let refined = newton::refine(&graph, &reduced, twisted.clone(), 50, newton::Accuracy::Full);
    assert!(cost::cost(&graph, &refined.q) > 1.0);
    let full = blocks::Pattern::new(&graph, None);
    let certificate = certificate::certify(&graph, &full, &refined.q);
    let dense = dense_certificate_eigenvalues(&graph, &refined.q);
    assert!(!certificate.certified);
    assert!(dense[0] < -0.1, "{:?}", &dense[..4]);
    // Lanczos on (S − σI)⁻¹ from Gershgorin's σ finds it to rounding.
    assert!(
        (certificate.lambda_min - dense[0]).abs() < 1e-12 * dense[0].abs(),
        "{} vs {}",
        certificate.lambda_min,
        dense[0]
    );
    // From the spectral start, the same graph is solved and certified.
    let solved = synchronize(&graph, &SyncOptions::default()).unwrap();
    assert!(solved.cost < 1e-20 && solved.certificate.unwrap().certified);
}

#[test]
fn the_flow_settles_on_the_certified_minimum() {
    let s = synthetic(50, 0.3, 5f64.to_radians(), 0.0, 11);
    let solved = synchronize(&s.graph, &SyncOptions::default()).unwrap();
    let certificate = solved.certificate.unwrap();
    assert!(certificate.certified && certificate.gap > 0.0);
    let mut flow = SyncFlow::random(s.graph.clone(), 5);
    let mut last = flow.cost();
    for _ in 0..100 {
        flow.step(0.02, 50).unwrap();
        assert!(flow.cost() <= last + 1e-12, "the flow raised f");
        last = flow.cost();
    }
    assert!(
        (flow.cost() - solved.cost).abs() < 1e-9 * solved.cost,
        "{} vs {}",
        flow.cost(),
        solved.cost
    );
    let by_flow = errors_to_truth(flow.rotations(), &solved.rotations);
    assert_eq!(by_flow.len(), 50);
    assert!(
        by_flow.iter().all(|&e| e < 1e-4),
        "{:?}",
        by_flow.iter().fold(0.0_f64, |a, &b| a.max(b))
    );
    let errors = errors_to_truth(&solved.rotations, &s.truth);
    let mean = errors.iter().sum::<f64>() / errors.len() as f64;
    assert!(mean.to_degrees() < 3.0, "{}", mean.to_degrees());
}

fn same(a: &Synchronized, b: &Synchronized) {
    assert!((a.cost - b.cost).abs() < 1e-10 * (1.0 + a.cost), "{} vs {}", a.cost, b.cost);
    for (p, q) in a.rotations.iter().zip(&b.rotations) {
        assert!(angle(*p, *q) < 1e-8, "{p:?} vs {q:?}");
    }
}

#[test]
fn edge_order_direction_and_signs_do_not_matter() {
    let s = synthetic(30, 0.25, 0.1, 0.0, 21);
    let base = synchronize(&s.graph, &SyncOptions::default()).unwrap();
    let edges = s.graph.edges();
    let relative = s.graph.relative();
    let m = edges.len();
    // Reversed order, every other edge reversed as (j, i) with q̄_ij, every third sign flipped.
    let order: Vec<usize> = (0..m).rev().collect();
    let e2: Vec<[usize; 2]> = order
        .iter()
        .map(|&k| if k % 2 == 0 { [edges[k][1], edges[k][0]] } else { edges[k] })
        .collect();
    let r2: Vec<DQuat> = order
        .iter()
        .map(|&k| {
            let q = if k % 2 == 0 { relative[k].conjugate() } else { relative[k] };
            if k % 3 == 0 { -q } else { q }
        })
        .collect();
    let other = Graph::new(Some(30), &e2, &r2, None).unwrap();
    let result = synchronize(&other, &SyncOptions::default()).unwrap();
    same(&base, &result);
    let mut reordered: Vec<f64> = order.iter().map(|&k| base.residuals[k]).collect();
    for (a, b) in reordered.iter_mut().zip(&result.residuals) {
        assert!((*a - b).abs() < 1e-8);
    }
}

#[test]
fn a_parallel_edge_counts_as_its_weight() {
    let s = synthetic(15, 0.3, 0.2, 0.0, 4);
    let edges = s.graph.edges();
    let mut e2 = edges.to_vec();
    e2.push(edges[0]);
    let mut r2 = s.graph.relative().to_vec();
    r2.push(-r2[0]);
    let doubled = Graph::new(None, &e2, &r2, None).unwrap();
    let mut w = vec![1.0; edges.len()];
    w[0] = 2.0;
    let weighted = Graph::new(None, edges, s.graph.relative(), Some(&w)).unwrap();
    let a = synchronize(&doubled, &SyncOptions::default()).unwrap();
    let b = synchronize(&weighted, &SyncOptions::default()).unwrap();
    same(&a, &b);
}

#[test]
fn the_anchor_is_the_identity() {
    let s = synthetic(20, 0.3, 0.1, 0.0, 9);
    let a = synchronize(&s.graph, &SyncOptions::default()).unwrap();
    let b = synchronize(&s.graph, &SyncOptions { anchor: 7, ..Default::default() }).unwrap();
    assert_eq!(b.rotations[7], DQuat::IDENTITY);
    assert!((a.cost - b.cost).abs() < 1e-10 * a.cost);
    // The same solution in another gauge.
    let errors = errors_to_truth(&a.rotations, &b.rotations);
    assert!(errors.iter().all(|&e| e < 1e-8));
}

#[test]
fn robust_ignores_wrong_edges() {
    let s = synthetic(100, 0.1, 5f64.to_radians(), 0.3, 17);
    let robust =
        synchronize(&s.graph, &SyncOptions { method: Method::Robust, ..Default::default() })
            .unwrap();
    let chordal = synchronize(&s.graph, &SyncOptions::default()).unwrap();
    let median = |mut e: Vec<f64>| {
        e.sort_by(f64::total_cmp);
        e[e.len() / 2].to_degrees()
    };
    let robust_error = median(errors_to_truth(&robust.rotations, &s.truth));
    let chordal_error = median(errors_to_truth(&chordal.rotations, &s.truth));
    assert!(
        robust_error < 3.0 && robust_error < 0.5 * chordal_error,
        "{robust_error} vs {chordal_error}"
    );
    // Flags: the edges truly far off are flagged, and few flagged edges are truly good.
    let outliers = robust.outliers.unwrap();
    let truly_off: Vec<f64> = s
        .graph
        .edges()
        .iter()
        .zip(s.graph.relative())
        .map(|(&[i, j], &r)| angle(s.truth[i].conjugate() * s.truth[j], r))
        .collect();
    let far = truly_off.iter().filter(|&&t| t > 15f64.to_radians()).count();
    let far_flagged =
        truly_off.iter().zip(&outliers).filter(|&(&t, &o)| o && t > 15f64.to_radians()).count();
    let good_flagged =
        truly_off.iter().zip(&outliers).filter(|&(&t, &o)| o && t < 10f64.to_radians()).count();
    let flagged = outliers.iter().filter(|&&o| o).count();
    assert!(far_flagged as f64 >= 0.95 * far as f64, "{far_flagged} of {far}");
    assert!(good_flagged as f64 <= 0.01 * flagged as f64, "{good_flagged} of {flagged}");
    let weights = robust.weights.unwrap();
    assert!(weights.iter().all(|&w| w > 0.0 && w <= 1.0));
    let _ = s.wrong;
}

fn refused(result: Result<Graph, KliError>) -> String {
    let error = result.unwrap_err();
    error.message(&|s| s.to_string(), &|x| x.to_string())
}

#[test]
fn bad_graphs_are_refused_naming_the_argument() {
    let one = [DQuat::IDENTITY];
    let two = [DQuat::IDENTITY; 2];
    assert!(refused(Graph::new(None, &[], &[], None)).starts_with("edges is empty"));
    let m = refused(Graph::new(Some(2), &[[0, 2]], &one, None));
    assert!(m.starts_with("edges[0] names node 2, but count is 2"), "{m}");
    let m = refused(Graph::new(None, &[[0, 1], [1, 1]], &two, None));
    assert!(m.starts_with("edges[1] joins node 1 to itself"), "{m}");
    let m = refused(Graph::new(None, &[[0, 1], [1, 2]], &one, None));
    assert!(m.starts_with("relative must hold 4 numbers per edge"), "{m}");
    let m = refused(Graph::new(None, &[[0, 1]], &two, None));
    assert!(m.starts_with("relative must hold"), "{m}");
    let nan = DQuat::from_xyzw(f64::NAN, 0.0, 0.0, 1.0);
    let m = refused(Graph::new(None, &[[0, 1], [1, 2]], &[DQuat::IDENTITY, nan], None));
    assert!(m.starts_with("relative[1] must be a quaternion"), "{m}");
    let zero = DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0);
    let m = refused(Graph::new(None, &[[0, 1]], &[zero], None));
    assert!(m.starts_with("relative[0] must be a quaternion") && m.contains("zero length"), "{m}");
    for w in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let m = refused(Graph::new(None, &[[0, 1], [1, 2]], &two, Some(&[1.0, w])));
        assert!(m.starts_with("weights[1] must be a finite number > 0"), "{w}: {m}");
    }
    let m = refused(Graph::new(None, &[[0, 1], [1, 2]], &two, Some(&[1.0])));
    assert!(m.starts_with("weights must hold one number per edge: 2 (got 1)"), "{m}");
    // Two components: {0, 1} and {2, 3}; and a lone node 4 of a declared count.
    let m = refused(Graph::new(None, &[[0, 1], [2, 3], [3, 2]], &[DQuat::IDENTITY; 3], None));
    assert!(
        m.starts_with("edges do not connect the graph: nodes 2, 3 are cut off from node 0"),
        "{m}"
    );
    let m = refused(Graph::new(Some(4), &[[0, 1], [1, 2], [2, 0]], &[DQuat::IDENTITY; 3], None));
    assert!(m.contains("node 3 is cut off from node 0"), "{m}");
    // A count no edge list could connect is refused before anything of its size is allocated.
    let m = refused(Graph::new(Some(usize::MAX), &[[0, 1]], &one, None));
    let rest = usize::MAX - 2 - 8;
    assert!(
        m.starts_with(&format!(
            "edges do not connect the graph: nodes 2, 3, 4, 5, 6, 7, 8, 9 and {rest} more"
        )),
        "{m}"
    );
    let m = refused(Graph::new(None, &[[0, 1], [1, 4_000_000_000]], &two, None));
    assert!(m.contains("nodes 2, 3, 4, 5, 6, 7, 8, 9 and 3999999990 more are cut off"), "{m}");
    // Node 0 in no edge: everyone else is cut off from it.
    let m = refused(Graph::new(None, &[[1, 2]], &one, None));
    assert!(m.contains("nodes 1, 2 are cut off from node 0"), "{m}");
    // Exactly eight cut off: all named, no "and 0 more".
    let pairs: Vec<[usize; 2]> = [[0, 1], [1, 2], [2, 0], [3, 4], [5, 6], [7, 8], [9, 10]].to_vec();
    let m = refused(Graph::new(None, &pairs, &[DQuat::IDENTITY; 7], None));
    assert!(m.ends_with("nodes 3, 4, 5, 6, 7, 8, 9, 10 are cut off from node 0"), "{m}");
    // Eleven triangles, ten of them cut off from node 0's: 30 nodes named 8 and "22 more".
    let many: Vec<[usize; 2]> = (0..11)
        .flat_map(|t| [[3 * t, 3 * t + 1], [3 * t + 1, 3 * t + 2], [3 * t + 2, 3 * t]])
        .collect();
    let m = refused(Graph::new(None, &many, &vec![DQuat::IDENTITY; many.len()], None));
    assert!(m.contains("nodes 3, 4, 5, 6, 7, 8, 9, 10 and 22 more are cut off"), "{m}");
}

#[test]
fn bad_options_are_refused() {
    let graph = triangle();
    let message = |options: SyncOptions| {
        synchronize(&graph, &options).unwrap_err().message(&|s| s.to_string(), &|x| x.to_string())
    };
    let m = message(SyncOptions { anchor: 3, ..Default::default() });
    assert!(m.starts_with("anchor must be a node, from 0 to 2 (got 3)"), "{m}");
    for scale in [0.0, -1.0, f64::NAN] {
        let m = message(SyncOptions {
            scale: Some(scale),
            method: Method::Robust,
            ..Default::default()
        });
        assert!(m.starts_with("scale must be a finite number > 0"), "{m}");
    }
    assert!("lsq".parse::<Method>().is_err());
    assert_eq!("robust".parse::<Method>().unwrap(), Method::Robust);
}

#[test]
fn the_flow_refuses_bad_steps_and_starts() {
    let mut flow = SyncFlow::random(triangle(), 1);
    assert!(flow.step(0.0, 1).is_err());
    assert!(flow.step(f64::NAN, 1).is_err());
    assert!(flow.step(0.1, MAX_STEPS + 1).is_err());
    assert_eq!(flow.time(), 0.0);
    assert!(SyncFlow::new(triangle(), &[DQuat::IDENTITY; 2]).is_err());
    let zero = DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0);
    let bad = SyncFlow::new(triangle(), &[DQuat::IDENTITY, zero, DQuat::IDENTITY]).unwrap_err();
    assert_eq!(bad.argument(), "start[1]");
    // Started from the caller's own argument, a refusal names it.
    let bad = SyncFlow::starting(triangle(), &[DQuat::IDENTITY, zero, DQuat::IDENTITY], "initial")
        .unwrap_err();
    assert_eq!(bad.argument(), "initial[1]");
    let short = SyncFlow::starting(triangle(), &[DQuat::IDENTITY; 2], "initial").unwrap_err();
    assert_eq!(short.argument(), "initial");
    // A step far too long still leaves every node on S³.
    flow.step(1e6, 3).unwrap();
    assert!(flow.rotations().iter().all(|q| (q.length() - 1.0).abs() < 1e-12));
}

#[test]
fn the_gauss_newton_matrix_is_positive_semidefinite_and_exact_where_the_edges_agree() {
    let s = synthetic(15, 0.4, 0.5, 0.3, 12);
    let mut random = Random::new(8);
    let q: Vec<DQuat> = (0..15).map(|_| random.unit_quaternion()).collect();
    let (_, gn) = cost::model(&s.graph, &q, true);
    let (_, exact) = cost::model(&s.graph, &q, false);
    let mut negative_exact = false;
    for _ in 0..20 {
        let v: Vec<f64> = (0..45).map(|_| random.gaussian()).collect();
        let quadratic = |h: &blocks::Blocks| {
            let mut hv = vec![0.0; 45];
            h.apply(&s.graph, &v, &mut hv);
            v.iter().zip(&hv).map(|(a, b)| a * b).sum::<f64>()
        };
        assert!(quadratic(&gn) >= -1e-12);
        negative_exact |= quadratic(&exact) < 0.0;
    }
    // Far from agreement the exact Hessian has directions of negative curvature; Gauss–Newton not.
    assert!(negative_exact);
    // Where every edge agrees (f = 0) the two are the same matrix.
    let truth = &s.truth;
    let consistent: Vec<DQuat> =
        s.graph.edges().iter().map(|&[i, j]| truth[i].conjugate() * truth[j]).collect();
    let graph = Graph::new(Some(15), s.graph.edges(), &consistent, None).unwrap();
    let (_, gn) = cost::model(&graph, truth, true);
    let (_, exact) = cost::model(&graph, truth, false);
    for (a, b) in gn.diag.iter().zip(&exact.diag) {
        assert!((*a - *b).to_cols_array().iter().all(|d| d.abs() < 1e-12));
    }
}

#[test]
fn conjugate_gradients_solve_as_cholesky_does_where_the_factor_fills_in() {
    // A random graph of degree ~15 on 600 nodes: an expander, whose factor fills in.
    let s = synthetic(600, 0.025, 0.1, 0.0, 31);
    let pattern = blocks::Pattern::new(&s.graph, Some(0));
    assert!(pattern.fills());
    let (_, h) = cost::model(&s.graph, &s.truth, true);
    let mut random = Random::new(2);
    let mut b: Vec<f64> = (0..1800).map(|_| random.gaussian()).collect();
    b[..3].fill(0.0);
    let by_cg = pattern.solve(&s.graph, &h, 1e-3, &b, 1e-12).unwrap();
    let factor = pattern.factor(&s.graph, &h, 1e-3).unwrap();
    let mut by_cholesky = b[3..].to_vec();
    factor.solve(&mut by_cholesky, 1);
    let gap = by_cg[3..].iter().zip(&by_cholesky).map(|(a, c)| (a - c).abs()).fold(0.0, f64::max);
    assert!(gap < 1e-9, "{gap}");
    assert!(by_cg[..3].iter().all(|&x| x == 0.0));
    // And the sphere-like graph of the fixture does not fill in: Cholesky there.
    let ring = Graph::new(
        None,
        &(0..50).map(|i| [i, (i + 1) % 50]).collect::<Vec<_>>(),
        &[DQuat::IDENTITY; 50],
        None,
    )
    .unwrap();
    assert!(!blocks::Pattern::new(&ring, Some(0)).fills());
}

/// Conjugate gradients on their own (`solve` falls back to Cholesky when they are slow, so its
/// test cannot tell a wrong step from a slow one): on the expander's shifted Hessian they
/// converge, well within their 500 steps, to Cholesky's solution, the node left out at 0 whatever
/// `b` holds there; a matrix that is not positive definite is refused as such, by a diagonal
/// block (a shift below minus the largest degree) or, where every diagonal block is positive
/// definite, by a direction of negative curvature: the certificate `S` of the twisted ring
/// (`λ_min < −0.1`, a dense eigensolver says), which Cholesky refuses too.
#[test]
fn conjugate_gradients_converge_on_their_own_and_refuse_an_indefinite_matrix() {
    let s = synthetic(600, 0.025, 0.1, 0.0, 31);
    let pattern = blocks::Pattern::new(&s.graph, Some(0));
    let (_, h) = cost::model(&s.graph, &s.truth, true);
    let mut random = Random::new(2);
    let b: Vec<f64> = (0..1800).map(|_| random.gaussian()).collect();
    let factor = pattern.factor(&s.graph, &h, 1e-3).unwrap();
    let mut by_cholesky = b[3..].to_vec();
    factor.solve(&mut by_cholesky, 1);
    for tolerance in [1e-6, 1e-12] {
        let blocks::Solved::Yes(x) = pattern.conjugate_gradients(&s.graph, &h, 1e-3, &b, tolerance)
        else {
            panic!("not converged to {tolerance}");
        };
        assert_eq!(&x[..3], &[0.0; 3]);
        // The error is within the condition number times the residual asked for; far within it.
        let scale = by_cholesky.iter().map(|v| v.abs()).fold(0.0, f64::max);
        let gap = x[3..].iter().zip(&by_cholesky).map(|(a, c)| (a - c).abs()).fold(0.0, f64::max);
        assert!(gap < 1e3 * tolerance * scale, "{tolerance}: {gap}");
        // And the residual itself, from the blocks: ‖(H + 1e-3 I) x − b‖ ≤ tolerance ‖b‖ on the
        // nodes kept.
        let mut hx = vec![0.0; 1800];
        h.apply(&s.graph, &x, &mut hx);
        let residual = (3..1800).map(|k| (hx[k] + 1e-3 * x[k] - b[k]).powi(2)).sum::<f64>().sqrt();
        let size = b[3..].iter().map(|v| v * v).sum::<f64>().sqrt();
        assert!(residual <= 1.000001 * tolerance * size, "{tolerance}: {residual} vs {size}");
    }
    let largest = s.graph.degrees().into_iter().fold(0.0, f64::max);
    // The tolerance is relative to ‖b‖: a right side 1e4 times smaller converges as well, not at
    // once.
    let small: Vec<f64> = b.iter().map(|v| v * 1e-4).collect();
    let blocks::Solved::Yes(x) = pattern.conjugate_gradients(&s.graph, &h, 1e-3, &small, 1e-9)
    else {
        panic!("not converged on a small right side");
    };
    let gap =
        x[3..].iter().zip(&by_cholesky).map(|(a, c)| (a - 1e-4 * c).abs()).fold(0.0, f64::max);
    assert!(gap < 1e-10, "{gap}");
    // A long ring (a path once its anchor is left out: condition number ~ (2n/π)², some 4e6)
    // needs thousands of steps to 1e-12: slow after its 500.
    let long = 3000;
    let edges: Vec<[usize; 2]> = (0..long).map(|i| [i, (i + 1) % long]).collect();
    let path = Graph::new(None, &edges, &vec![DQuat::IDENTITY; long], None).unwrap();
    let (_, h_path) = cost::model(&path, &vec![DQuat::IDENTITY; long], true);
    let ones = vec![1.0; 3 * long];
    assert!(matches!(
        blocks::Pattern::new(&path, Some(0)).conjugate_gradients(&path, &h_path, 0.0, &ones, 1e-12),
        blocks::Solved::Slow
    ));
    // A large shift is as positive definite (and its diagonal blocks with it).
    assert!(matches!(
        pattern.conjugate_gradients(&s.graph, &h, 10.0 * largest, &b, 1e-9),
        blocks::Solved::Yes(_)
    ));
    assert!(matches!(
        pattern.conjugate_gradients(&s.graph, &h, -2.0 * largest, &b, 1e-9),
        blocks::Solved::Indefinite
    ));
    // The twisted ring's S: positive definite blocks, an indefinite matrix.
    let n = 10;
    let edges: Vec<[usize; 2]> = (0..n).map(|i| [i, (i + 1) % n]).collect();
    let ring = Graph::new(None, &edges, &vec![DQuat::IDENTITY; n], None).unwrap();
    let twisted: Vec<DQuat> =
        (0..n).map(|k| DQuat::from_rotation_z(2.0 * PI * k as f64 / n as f64)).collect();
    assert!(dense_certificate_eigenvalues(&ring, &twisted)[0] < -0.1);
    let s_twisted = certificate::certificate_matrix(&ring, &twisted);
    for d in &s_twisted.diag {
        let minors =
            [d.col(0)[0], d.col(0)[0] * d.col(1)[1] - d.col(1)[0] * d.col(0)[1], d.determinant()];
        assert!(minors.iter().all(|&m| m > 0.0), "{d:?}");
    }
    let full = blocks::Pattern::new(&ring, None);
    let ones = vec![1.0; 3 * n];
    assert!(matches!(
        full.conjugate_gradients(&ring, &s_twisted, 0.0, &ones, 1e-12),
        blocks::Solved::Indefinite
    ));
    assert!(full.factor(&ring, &s_twisted, 0.0).is_none());
}

#[test]
fn the_flow_takes_exactly_a_million_steps_a_call() {
    let mut flow = SyncFlow::random(triangle(), 3);
    flow.step(1e-9, MAX_STEPS).unwrap();
    assert!((flow.time() - 1e-3).abs() < 1e-12, "{}", flow.time());
    assert_eq!(flow.step(1e-9, MAX_STEPS + 1).unwrap_err().argument(), "steps");
}

/// Hamilton's product on `[w, x, y, z]` arrays, written out.
fn product(a: [f64; 4], b: [f64; 4]) -> [f64; 4] {
    [
        a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
        a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
        a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
        a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0],
    ]
}

#[test]
fn one_flow_step_is_maths_euler_step_on_weighted_edges() {
    // MATH.md's model, q_i' = 2 Σ_j w_ij c_ij (x_ij − c_ij q_i), written on arrays, one Euler step
    // of 0.1 and the projection back to S³; uneven weights, so a weight's place in the pull shows.
    let s = synthetic(8, 0.5, 0.4, 0.0, 40);
    let weights: Vec<f64> =
        (0..s.graph.edges().len()).map(|k| 0.5 + 0.25 * (k % 5) as f64).collect();
    let graph = Graph::new(Some(8), s.graph.edges(), s.graph.relative(), Some(&weights)).unwrap();
    let mut random = Random::new(6);
    let start: Vec<DQuat> = (0..8).map(|_| random.unit_quaternion()).collect();
    let mut flow = SyncFlow::new(graph.clone(), &start).unwrap();
    flow.step(0.1, 1).unwrap();
    let q: Vec<[f64; 4]> = start.iter().map(|&q| crate::quaternion::to_wxyz(q)).collect();
    let mut pull = vec![[0.0; 4]; 8];
    for ((&[i, j], &r), &w) in graph.edges().iter().zip(graph.relative()).zip(graph.weights()) {
        let r = crate::quaternion::to_wxyz(r);
        let conj = [r[0], -r[1], -r[2], -r[3]];
        let dot = |a: [f64; 4], b: [f64; 4]| a.iter().zip(&b).map(|(x, y)| x * y).sum::<f64>();
        let x_ij = product(q[j], conj);
        let x_ji = product(q[i], r);
        let c = dot(q[i], x_ij);
        for k in 0..4 {
            pull[i][k] += 2.0 * w * c * (x_ij[k] - c * q[i][k]);
            pull[j][k] += 2.0 * w * c * (x_ji[k] - c * q[j][k]);
        }
    }
    for i in 0..8 {
        let next: Vec<f64> = (0..4).map(|k| q[i][k] + 0.1 * pull[i][k]).collect();
        let length = next.iter().map(|x| x * x).sum::<f64>().sqrt();
        let got = crate::quaternion::to_wxyz(flow.rotations()[i]);
        for k in 0..4 {
            assert!((got[k] - next[k] / length).abs() < 1e-14, "node {i}: {got:?}");
        }
    }
    // Each edge's residual: the angle from q_i q_ij to q_j.
    let rotations = flow.rotations();
    let residuals = flow.residuals();
    assert_eq!(residuals.len(), graph.edges().len());
    for ((&[i, j], &r), theta) in graph.edges().iter().zip(graph.relative()).zip(residuals) {
        assert!((theta - angle(rotations[i] * r, rotations[j])).abs() < 1e-12);
    }
}

#[test]
fn each_edges_term_is_8_sin_squared_of_half_its_residual_up_to_a_half_turn() {
    // MATH.md: ‖R_i R_ij − R_j‖²_F = 8 sin²(θ_ij/2), weighted. Two nodes at the identity and
    // measurements of θ = 60°, 120° and exactly 180° (w = 0: the term's largest, 8) on a path
    // of weights 1, 2 and 3.
    let half_turn = DQuat::from_xyzw(1.0, 0.0, 0.0, 0.0);
    let relative = [about_x(60.0), about_x(120.0), half_turn];
    let graph =
        Graph::new(None, &[[0, 1], [1, 2], [2, 3]], &relative, Some(&[1.0, 2.0, 3.0])).unwrap();
    let flow = SyncFlow::new(graph, &[DQuat::IDENTITY; 4]).unwrap();
    let expected = 8.0 * (0.25 + 2.0 * 0.75 + 3.0 * 1.0);
    assert!((flow.cost() - expected).abs() < 1e-12, "{} against {expected}", flow.cost());
    let residuals = flow.residuals();
    for (r, degrees) in residuals.iter().zip([60.0, 120.0, 180.0]) {
        assert!((r.to_degrees() - degrees).abs() < 1e-12, "{residuals:?}");
    }
}

/// Newton's method as the solver calls it, on its own: its step bound is exact (0 steps leave the
/// start as it is, 1 takes one); at an exact optimum (consistent measurements, the truth) it takes
/// none; from the spectral start it converges in a handful of steps (quadratic convergence: the
/// module says so); and from random starts, where the Hessian is indefinite and the damping
/// works, it reaches the same certified optimum as from the spectral start.
#[test]
fn newton_stops_where_it_should_and_converges_from_anywhere() {
    let s = synthetic(30, 0.3, 0.1, 0.0, 5);
    let reduced = blocks::Pattern::new(&s.graph, Some(0));
    let full = blocks::Pattern::new(&s.graph, None);
    let mut random = Random::new(9);
    let start: Vec<DQuat> = (0..30).map(|_| random.unit_quaternion()).collect();
    let none = newton::refine(&s.graph, &reduced, start.clone(), 0, newton::Accuracy::Full);
    assert_eq!((none.iterations, &none.q), (0, &start));
    let one = newton::refine(&s.graph, &reduced, start.clone(), 1, newton::Accuracy::Full);
    assert_eq!(one.iterations, 1);
    assert!(cost::cost(&s.graph, &one.q) < cost::cost(&s.graph, &start));
    // Consistent measurements at the truth: the gradient is 0 to rounding; no step.
    let consistent = synthetic(30, 0.3, 0.0, 0.0, 6);
    let at_truth = newton::refine(
        &consistent.graph,
        &blocks::Pattern::new(&consistent.graph, Some(0)),
        consistent.truth.clone(),
        newton::MAX_ITERATIONS,
        newton::Accuracy::Full,
    );
    assert_eq!(at_truth.iterations, 0);
    // From the spectral start: a handful of steps to the certified optimum.
    let (spectral_start, _) = spectral::spectral(&s.graph, &full);
    let best = newton::refine(
        &s.graph,
        &reduced,
        spectral_start,
        newton::MAX_ITERATIONS,
        newton::Accuracy::Full,
    );
    assert!(best.iterations <= 8, "{}", best.iterations);
    let optimum = cost::cost(&s.graph, &best.q);
    assert!(certificate::certify(&s.graph, &full, &best.q).certified);
    for seed in 0..4 {
        let mut random = Random::new(100 + seed);
        let start: Vec<DQuat> = (0..30).map(|_| random.unit_quaternion()).collect();
        let refined = newton::refine(
            &s.graph,
            &reduced,
            start,
            newton::MAX_ITERATIONS,
            newton::Accuracy::Full,
        );
        assert!(refined.iterations < newton::MAX_ITERATIONS, "{seed}");
        let f = cost::cost(&s.graph, &refined.q);
        assert!((f - optimum).abs() < 1e-9 * optimum, "{seed}: {f} vs {optimum}");
    }
}

/// The nearest rotation in the Frobenius norm, against the textbook one from a dense SVD
/// (`U diag(1, 1, det(U Vᵀ)) Vᵀ`, faer's): on random matrices, on a rotation itself, and on
/// matrices whose SVD has a negative determinant (the reflection the SVD route must undo).
/// `U diag(1, 1, det(U Vᵀ)) Vᵀ` from faer's SVD of `a`.
fn nearest_by_svd(a: DMat3) -> DMat3 {
    let m = Mat::<f64>::from_fn(3, 3, |r, c| a.col(c)[r]);
    let svd = m.svd().unwrap();
    let (u, v) = (svd.U(), svd.V());
    let uvt = u * v.transpose();
    let det = DMat3::from_cols_array(&std::array::from_fn(|i| uvt[(i % 3, i / 3)])).determinant();
    let mut d = Mat::<f64>::identity(3, 3);
    d[(2, 2)] = det.signum();
    let best = u * d * v.transpose();
    DMat3::from_cols_array(&std::array::from_fn(|i| best[(i % 3, i / 3)]))
}

#[test]
fn the_nearest_rotation_is_the_svds() {
    let mut random = Random::new(21);
    for k in 0..40 {
        let a = DMat3::from_cols_array(&std::array::from_fn(|_| random.gaussian()));
        let best = nearest_by_svd(a);
        let got = DMat3::from_quat(spectral::nearest_rotation(a));
        assert!(got.abs_diff_eq(best, 1e-9), "{k}: {got:?} vs {best:?}");
        assert!(spectral::nearest_rotation(a).w >= 0.0);
    }
    let q = DQuat::from_axis_angle(DVec3::new(1.0, -2.0, 0.5).normalize(), 2.5);
    let back = spectral::nearest_rotation(DMat3::from_quat(q) * 3.0);
    assert!(back.dot(q).abs() > 1.0 - 1e-14, "{back:?} vs {q:?}");
}

/// The spectral estimate (`Method::Spectral`'s answer) against the relaxation solved densely from
/// MATH.md: `L` written out, its three eigenvectors of the smallest eigenvalues by faer's dense solver, each
/// block `V_iᵀ` rounded by SVD after one column is flipped where most blocks are reflections;
/// compared free of the gauge (`q_0⁻¹ q_i`). On graphs whose factor does not fill (shift-and-
/// invert Lanczos) and on an expander (Lanczos on `2 d_max I − L`), with noise, wrong edges and
/// uneven weights.
#[test]
fn the_spectral_estimate_is_the_dense_relaxations() {
    for (seed, (n, p, noise, wrong)) in
        [(40, 0.1, 0.1, 0.0), (40, 0.1, 0.3, 0.3)].into_iter().enumerate()
    {
        let s = synthetic(n, p, noise, wrong, 40 + seed as u64);
        let weights: Vec<f64> =
            (0..s.graph.edges().len()).map(|k| 0.5 + 0.25 * (k % 5) as f64).collect();
        let graph =
            Graph::new(Some(n), s.graph.edges(), s.graph.relative(), Some(&weights)).unwrap();
        let eigen = dense_laplacian(&graph).self_adjoint_eigen(Side::Lower).unwrap();
        let (values, vectors) = (eigen.S().column_vector(), eigen.U());
        assert!(values[3] - values[2] > 1e-3 * values[3], "{seed}: no gap to the fourth");
        let block = |i: usize| {
            DMat3::from_cols_array(&std::array::from_fn(|k| vectors[(3 * i + k / 3, k % 3)]))
        };
        let reflections = (0..n).filter(|&i| block(i).determinant() < 0.0).count();
        let flip = if 2 * reflections > n { -1.0 } else { 1.0 };
        let want: Vec<DMat3> = (0..n)
            .map(|i| nearest_by_svd(DMat3::from_diagonal(DVec3::new(flip, 1.0, 1.0)) * block(i)))
            .collect();
        let synchronized =
            synchronize(&graph, &SyncOptions { method: Method::Spectral, ..Default::default() })
                .unwrap();
        let got: Vec<DMat3> = synchronized.rotations.iter().map(|&q| DMat3::from_quat(q)).collect();
        for i in 0..n {
            let (a, b) = (want[0].transpose() * want[i], got[0].transpose() * got[i]);
            assert!(a.abs_diff_eq(b, 1e-7), "{seed}, node {i}: {a:?} vs {b:?}");
        }
    }
    // An expander (too large for a dense solver here): with consistent measurements `L`'s three
    // smallest eigenvalues are 0 and their vectors the truth's, so the estimate is the truth up
    // to the gauge, in the module doc's "a few dozen" Lanczos steps a vector.
    for (seed, weighted) in [(51, false), (52, true)] {
        let s = synthetic(600, 0.025, 0.0, 0.0, seed);
        let weights: Vec<f64> = (0..s.graph.edges().len())
            .map(|k| if weighted { 0.5 + 0.25 * (k % 5) as f64 } else { 1.0 })
            .collect();
        let graph =
            Graph::new(Some(600), s.graph.edges(), s.graph.relative(), Some(&weights)).unwrap();
        assert!(blocks::Pattern::new(&graph, None).fills());
        let synchronized =
            synchronize(&graph, &SyncOptions { method: Method::Spectral, ..Default::default() })
                .unwrap();
        let got = &synchronized.rotations;
        for i in 0..600 {
            let (a, b) = (s.truth[0].conjugate() * s.truth[i], got[0].conjugate() * got[i]);
            assert!(a.dot(b).abs() > 1.0 - 1e-12, "{seed}, node {i}: {a:?} vs {b:?}");
        }
        // Three Lanczos runs of at least a step each, reported whole.
        let steps = synchronized.iterations;
        assert!((3..=3 * 60).contains(&steps), "{steps}");
    }
}

/// The connection Laplacian from MATH.md's definition, with uneven weights: `d_i I₃` on the
/// diagonal (the weighted degree) and `−w_ij R_ij` off it.
#[test]
fn the_connection_laplacian_is_maths() {
    let s = synthetic(10, 0.4, 0.2, 0.0, 4);
    let weights: Vec<f64> =
        (0..s.graph.edges().len()).map(|k| 0.5 + 0.25 * (k % 5) as f64).collect();
    let graph = Graph::new(Some(10), s.graph.edges(), s.graph.relative(), Some(&weights)).unwrap();
    let l = spectral::laplacian(&graph);
    let mut degree = [0.0; 10];
    for (&[i, j], &w) in graph.edges().iter().zip(&weights) {
        degree[i] += w;
        degree[j] += w;
    }
    for (i, block) in l.diag.iter().enumerate() {
        assert!((*block - DMat3::IDENTITY * degree[i]).abs_diff_eq(DMat3::ZERO, 1e-12), "{i}");
    }
    for (k, block) in l.off.iter().enumerate() {
        let want = DMat3::from_quat(graph.relative()[k]) * -weights[k];
        assert!(block.abs_diff_eq(want, 1e-12), "{k}");
    }
}

/// The robust method with the caller's Geman–McClure scale `σ`: an edge is flagged exactly when
/// its final residual exceeds `3σ`; each weight is MATH.md's `w (σ²/(σ² + θ²))²` at the settled
/// residuals (the last round's, which the final step moved by little); the rounds take at least
/// one step and at most their bounds' (15 L1 and 30 Geman–McClure rounds of one step each) after
/// the least-squares fit that found too many edges far off to judge by (a fifth of them wrong).
#[test]
fn robust_with_the_callers_scale_flags_beyond_three_sigma() {
    let s = synthetic(80, 0.12, 3f64.to_radians(), 0.2, 23);
    let sigma = 4f64.to_radians();
    let options = SyncOptions { method: Method::Robust, scale: Some(sigma), ..Default::default() };
    let robust = synchronize(&s.graph, &options).unwrap();
    assert_eq!(robust.scale, Some(sigma));
    let outliers = robust.outliers.unwrap();
    for (k, (&t, &o)) in robust.residuals.iter().zip(&outliers).enumerate() {
        assert_eq!(o, t > 3.0 * sigma, "{k}: {}°", t.to_degrees());
    }
    assert!(outliers.iter().any(|&o| o) && !outliers.iter().all(|&o| o));
    let weights = robust.weights.unwrap();
    for (k, (&w, &t)) in weights.iter().zip(&robust.residuals).enumerate() {
        let r = sigma * sigma / (sigma * sigma + t * t);
        assert!((w - r * r).abs() < 1e-3 * r * r + 1e-9, "{k}: {w} vs {}", r * r);
    }
    let fit = synchronize(&s.graph, &SyncOptions::default()).unwrap().iterations;
    assert!(robust.iterations > fit && robust.iterations <= fit + 45, "{}", robust.iterations);
}

/// A graph without wrong edges: the robust answer is the least-squares optimum, certified by the
/// chordal method, no edge flagged, no reweighted round taken. Dense (the bench's style) and
/// sparse (a SLAM path of 300 poses with 5 short loop closures: most edges are on no loop, so
/// any fit leaves their residuals 0, and the median residual says nothing of the noise).
#[test]
fn robust_trusts_a_graph_without_wrong_edges() {
    let dense = synthetic(120, 0.1, 3f64.to_radians(), 0.0, 41).graph;
    let mut random = Random::new(5);
    let truth: Vec<DQuat> = (0..300).map(|_| random.unit_quaternion()).collect();
    let mut edges: Vec<[usize; 2]> = (0..299).map(|i| [i, i + 1]).collect();
    edges.extend((0..5).map(|k| [60 * k, 60 * k + 10]));
    let relative: Vec<DQuat> = edges
        .iter()
        .map(|&[i, j]| {
            let noise = exp(random.gaussian3() * (0.5 * 1f64.to_radians()));
            truth[i].conjugate() * truth[j] * noise
        })
        .collect();
    let sparse = Graph::new(None, &edges, &relative, None).unwrap();
    for graph in [dense, sparse] {
        let chordal = synchronize(&graph, &SyncOptions::default()).unwrap();
        assert!(chordal.certificate.unwrap().certified);
        let options = SyncOptions { method: Method::Robust, ..Default::default() };
        let robust = synchronize(&graph, &options).unwrap();
        assert!(robust.outliers.unwrap().iter().all(|&o| !o));
        assert!(robust.weights.unwrap().iter().all(|&w| w == 1.0));
        assert!((robust.cost - chordal.cost).abs() <= 1e-9 * chordal.cost);
        let apart = errors_to_truth(&robust.rotations, &chordal.rotations);
        assert!(apart.iter().all(|&e| e < 1e-7), "{:?}", apart.iter().copied().fold(0.0, f64::max));
        // The least-squares fit, and one more look that changes nothing: no rounds.
        assert_eq!(robust.iterations, chordal.iterations);
    }
}

/// A few wrong edges among many right ones: each is flagged, and the answer is the least-squares
/// optimum of the graph without them, computed here apart (the chordal method on that graph).
#[test]
fn robust_sets_aside_a_few_wrong_edges_and_solves_the_rest() {
    let s = synthetic(150, 0.08, 2f64.to_radians(), 0.0, 77);
    let mut random = Random::new(9);
    let mut relative = s.graph.relative().to_vec();
    let wrong: Vec<usize> = (0..relative.len()).filter(|k| k % 40 == 7).collect();
    for &k in &wrong {
        relative[k] = random.unit_quaternion();
    }
    let graph = Graph::new(Some(150), s.graph.edges(), &relative, None).unwrap();
    let options = SyncOptions { method: Method::Robust, ..Default::default() };
    let robust = synchronize(&graph, &options).unwrap();
    let outliers = robust.outliers.unwrap();
    let flagged: Vec<usize> = (0..outliers.len()).filter(|&k| outliers[k]).collect();
    // A uniform random rotation can land near the truth: those within 20° need not be flagged.
    let truly_off: Vec<usize> = wrong
        .iter()
        .copied()
        .filter(|&k| {
            let [i, j] = graph.edges()[k];
            angle(s.truth[i].conjugate() * s.truth[j], relative[k]) > 20f64.to_radians()
        })
        .collect();
    assert!(truly_off.iter().all(|k| flagged.contains(k)), "{truly_off:?} vs {flagged:?}");
    assert!(flagged.iter().all(|k| wrong.contains(k)), "{flagged:?} vs {wrong:?}");
    let kept: Vec<usize> = (0..outliers.len()).filter(|&k| !outliers[k]).collect();
    let rest = Graph::new(
        Some(150),
        &kept.iter().map(|&k| graph.edges()[k]).collect::<Vec<_>>(),
        &kept.iter().map(|&k| relative[k]).collect::<Vec<_>>(),
        None,
    )
    .unwrap();
    let without = synchronize(&rest, &SyncOptions::default()).unwrap();
    let apart = errors_to_truth(&robust.rotations, &without.rotations);
    assert!(apart.iter().all(|&e| e < 1e-6), "{}", apart.iter().copied().fold(0.0, f64::max));
    let weights = robust.weights.unwrap();
    assert!(weights.iter().zip(&outliers).all(|(&w, &o)| w == if o { 0.0 } else { 1.0 }));
}
