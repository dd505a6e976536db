//! The page's problem: its graphs have the sizes their definitions give, its measurements follow
//! the recipe (the noise's median angle is the normal distribution's), its solutions are the
//! core's, and its flow settles on the chordal optimum.

use glam::DQuat;
use kli::average::angle;
use kli::sync::{Method, errors_to_truth};

use super::model::{Model, Options, Problem, Shape, layout, median};
use kli::swarm::Random;

fn options(count: usize, shape: Shape, noise: f64, wrong: f64, seed: u64) -> Options {
    Options { count, shape, noise, wrong, seed, consensus: false }
}

#[test]
fn each_graph_has_the_edges_its_definition_gives() {
    let mut random = Random::new(1);
    // A ring has n edges, the complete graph n(n − 1)/2, a full 10 × 10 grid 2 · 10 · 9, and a
    // 7-node grid (3 columns: rows 3, 3, 1) 2 + 2 + 0 across and 3 + 3 down … counted by hand:
    // 0-1 1-2 3-4 4-5 across, 0-3 1-4 2-5 3-6 down.
    assert_eq!(layout(Shape::Ring, 12, &mut random).1.len(), 12);
    assert_eq!(layout(Shape::Complete, 12, &mut random).1.len(), 66);
    assert_eq!(layout(Shape::Grid, 100, &mut random).1.len(), 180);
    let (_, grid) = layout(Shape::Grid, 7, &mut random);
    let mut edges = grid.clone();
    edges.sort();
    assert_eq!(edges, vec![[0, 1], [0, 3], [1, 2], [1, 4], [2, 5], [3, 4], [3, 6], [4, 5]]);
    // The random graph: every node has at least its nearest neighbours, and it is connected
    // (Graph::new refuses one that is not) for every seed tried.
    for seed in 0..20 {
        let problem = Problem::new(&options(60, Shape::Random, 5.0, 0.0, seed)).unwrap();
        let mut degree = [0usize; 60];
        for &[i, j] in problem.graph.edges() {
            assert_ne!(i, j);
            degree[i] += 1;
            degree[j] += 1;
        }
        assert!(degree.iter().all(|&d| d >= 8), "seed {seed}: {degree:?}");
    }
}

#[test]
fn measurements_follow_the_recipe() {
    // Noise-free: every measurement is t̄_i t_j, so the truth costs nothing.
    let clean = Problem::new(&options(40, Shape::Random, 0.0, 0.0, 3)).unwrap();
    for (&[i, j], &r) in clean.graph.edges().iter().zip(clean.graph.relative()) {
        assert!(angle(r, clean.truth[i].conjugate() * clean.truth[j]) < 1e-12);
    }
    // σ = 5°: each edge's angle at the truth is |σ g| for a standard normal g, whose median is
    // 0.6745 σ (the normal distribution's quartile); 1,770 edges give it to a few per cent.
    let noisy = Problem::new(&options(60, Shape::Complete, 5.0, 0.0, 4)).unwrap();
    let at_truth: Vec<f64> = noisy
        .graph
        .edges()
        .iter()
        .zip(noisy.graph.relative())
        .map(|(&[i, j], &r)| angle(r, noisy.truth[i].conjugate() * noisy.truth[j]).to_degrees())
        .collect();
    let m = median(at_truth);
    assert!((m / (0.6745 * 5.0) - 1.0).abs() < 0.06, "median noise {m}°");
    // Exactly round(share × m) wrong edges, and those are the ones far off.
    let wrong = Problem::new(&options(100, Shape::Grid, 2.0, 0.25, 5)).unwrap();
    assert_eq!(wrong.wrong.iter().filter(|&&w| w).count(), 45); // 0.25 × 180
    // Consensus: every measurement and every truth the identity.
    let consensus =
        Problem::new(&Options { consensus: true, ..options(30, Shape::Ring, 5.0, 0.3, 1) })
            .unwrap();
    assert!(consensus.graph.relative().iter().all(|&r| r == DQuat::IDENTITY));
    assert!(consensus.wrong.iter().all(|&w| !w));
}

#[test]
fn the_solutions_are_the_cores_and_robust_beats_chordal_on_wrong_edges() {
    // Noise alone: the chordal solution is the core's, and certified.
    let noisy = Model::new(options(120, Shape::Random, 3.0, 0.0, 7)).unwrap();
    let chordal = kli::sync::synchronize(&noisy.problem.graph, &Default::default()).unwrap();
    assert_eq!(noisy.chordal.rotations, chordal.rotations);
    assert!(noisy.chordal.certificate.unwrap().certified);
    // A fifth of the edges wrong: the robust solution is nearer the truth.
    let model = Model::new(options(120, Shape::Random, 3.0, 0.2, 7)).unwrap();
    let errors = |q: &[DQuat]| median(errors_to_truth(q, &model.problem.truth)).to_degrees();
    let (c, r) = (errors(&model.chordal.rotations), errors(&model.robust.rotations));
    assert!(r < c, "robust {r}° against chordal {c}°");
    // Without noise or wrong edges both are the truth.
    let clean = Model::new(options(50, Shape::Grid, 0.0, 0.0, 2)).unwrap();
    for q in [&clean.chordal.rotations, &clean.robust.rotations] {
        assert!(clean.problem.median_error(q) < 1e-7);
    }
    assert!(clean.chordal.cost < 1e-20);
    let spectral = clean.problem.solve(Method::Spectral).unwrap();
    assert!(clean.problem.median_error(&spectral.rotations) < 1e-6);
}

#[test]
fn the_flow_settles_on_the_certified_optimum() {
    let mut model = Model::new(options(40, Shape::Random, 5.0, 0.1, 2)).unwrap();
    let start = model.flow.cost();
    assert!(!model.arrived());
    let mut steps = 0;
    while !model.arrived() && steps < 400_000 {
        model.step(2000).unwrap();
        steps += 2000;
    }
    assert!(model.arrived(), "f = {} against {}", model.flow.cost(), model.chordal.cost);
    assert!(model.flow.cost() < start);
    // Where the flow arrived, it agrees with the chordal solution up to the gauge.
    let q = model.flow.rotations();
    // Within 1e-6 of f*, a node may still be ~√(1e-6 f*/λ) away: a tenth of a degree here.
    let apart = median(errors_to_truth(q, &model.chordal.rotations));
    assert!(apart.to_degrees() < 0.2, "{}° from the chordal solution", apart.to_degrees());
    // The history keeps a sample a call (and the first), its times the flow's.
    let h = &model.history;
    assert_eq!(h.times.len(), 1 + steps / 2000);
    assert!((h.times.last().unwrap() - steps as f64 * model.dt).abs() < 1e-9);
    // The gauge takes the truth onto the flow: the aligned error is the one errors_to_truth
    // gives.
    let g = model.problem.gauge(q).conjugate();
    let first = angle(g * q[0], model.problem.truth[0]);
    assert!((first - errors_to_truth(q, &model.problem.truth)[0]).abs() < 1e-9);
}

#[test]
fn consensus_agrees_from_any_start() {
    let options = Options { consensus: true, ..options(30, Shape::Complete, 0.0, 0.0, 4) };
    let mut model = Model::new(options).unwrap();
    assert!(model.chordal.cost < 1e-20);
    model.step(20_000).unwrap();
    assert!(model.problem.median_error(model.flow.rotations()) < 1e-6);
    assert!(model.arrived());
}
