//! The page's problem: its graphs have the sizes their definitions give, its measurements follow
//! the recipe (the noise's median angle is the normal distribution's), its solutions are the
//! core's, and its flow settles on the chordal optimum.

use glam::DQuat;
use kli::average::angle;
use kli::sync::{Method, errors_to_truth};

use super::model::{Model, Options, Problem, Shape, layout, median};
use super::solutions::Solutions;
use kli::swarm::Random;

/// The model's solutions (solved by `Model::new`).
fn solved(model: &Model) -> &Solutions {
    model.solutions.as_ref().expect("Model::new solves")
}

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
    assert_eq!(solved(&noisy).chordal.rotations, chordal.rotations);
    assert!(solved(&noisy).chordal.certificate.unwrap().certified);
    // A fifth of the edges wrong: the robust solution is nearer the truth.
    let model = Model::new(options(120, Shape::Random, 3.0, 0.2, 7)).unwrap();
    let errors = |q: &[DQuat]| median(errors_to_truth(q, &model.problem.truth)).to_degrees();
    let (c, r) =
        (errors(&solved(&model).chordal.rotations), errors(&solved(&model).robust.rotations));
    assert!(r < c, "robust {r}° against chordal {c}°");
    // Without noise or wrong edges both are the truth.
    let clean = Model::new(options(50, Shape::Grid, 0.0, 0.0, 2)).unwrap();
    for q in [&solved(&clean).chordal.rotations, &solved(&clean).robust.rotations] {
        assert!(clean.problem.median_error(q) < 1e-7);
    }
    assert!(solved(&clean).chordal.cost < 1e-20);
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
    assert!(model.arrived(), "f = {} against {}", model.flow.cost(), solved(&model).chordal.cost);
    assert!(model.flow.cost() < start);
    // Where the flow arrived, it agrees with the chordal solution up to the gauge.
    let q = model.flow.rotations();
    // Within 1e-6 of f*, a node may still be ~√(1e-6 f*/λ) away: a tenth of a degree here.
    let apart = median(errors_to_truth(q, &solved(&model).chordal.rotations));
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
    assert!(solved(&model).chordal.cost < 1e-20);
    model.step(20_000).unwrap();
    assert!(model.problem.median_error(model.flow.rotations()) < 1e-6);
    assert!(model.arrived());
}

#[test]
fn a_run_made_unsolved_takes_the_solutions_a_worker_computed() {
    let recipe = options(60, Shape::Random, 4.0, 0.2, 9);
    let whole = Model::new(recipe.clone()).unwrap();
    let mut model = Model::unsolved(recipe.clone()).unwrap();
    // Unsolved, the flow runs and has arrived nowhere.
    assert!(model.solutions.is_none());
    assert!(!model.arrived());
    model.step(10).unwrap();
    // The numbers a worker sends (the problem rebuilt from the same recipe, as
    // `SyncDemo.solve` does) give back exactly the solutions `Model::new` found: both
    // methods' every field, the certificate and the robust flags included.
    let packed = Solutions::of(&Problem::new(&recipe).unwrap()).unwrap().pack();
    let (n, m) = (recipe.count, whole.problem.graph.edges().len());
    assert_eq!(packed.len(), 2 + 2 * (4 * n + 3 * m + 11));
    let taken = Solutions::unpack(&packed, n, m).unwrap();
    assert_eq!(taken.chordal, solved(&whole).chordal);
    assert_eq!(taken.robust, solved(&whole).robust);
    assert!(taken.chordal.certificate.is_some() && taken.robust.outliers.is_some());
    assert!(taken.robust.outliers.as_ref().unwrap().iter().any(|&o| o), "some edges flagged");
    model.solutions = Some(taken);
    assert!(!model.arrived(), "ten steps from a random start are not the optimum");
}

#[test]
fn numbers_that_are_not_this_problems_solutions_are_refused_by_name() {
    let recipe = options(20, Shape::Ring, 5.0, 0.0, 1);
    let problem = Problem::new(&recipe).unwrap();
    let good = Solutions::of(&problem).unwrap().pack();
    let (n, m) = (20, 20);
    let refused = |data: &[f64], says: &str| {
        let error = Solutions::unpack(data, n, m).unwrap_err();
        assert_eq!(error.argument(), "solutions");
        assert!(error.to_string().contains(says), "{error}");
    };
    refused(&good[..good.len() - 1], "got");
    refused(&[], "got");
    // Another problem of the same length's worth of numbers: its header says so.
    let mut other = good.clone();
    other[0] = 21.0;
    refused(&other, "another problem");
    // A rotation off the unit sphere, a NaN among them, a flag of 0.5, a count of 1.5.
    let mut long = good.clone();
    long[2] = 2.0;
    refused(&long, "unit length");
    let mut nan = good.clone();
    nan[5] = f64::NAN;
    refused(&nan, "unit length");
    let iterations = 2 + 4 * n + 1 + m;
    let mut count = good.clone();
    count[iterations] = 1.5;
    refused(&count, "whole");
    let mut flag = good.clone();
    flag[iterations + 1] = 0.5;
    refused(&flag, "flag");
    assert!(Solutions::unpack(&good, n, m).is_ok());
}
