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

// ---- The map: the built-in pose graph, the initial estimate, the optimum ---------------------

use super::initial::{Poses, chained, initial};
use super::map::{HEAD, Outline, SyncMap, csv, edge_costs, read, read_poses, solve_graph};

/// Reads and solves `text`: the solver's numbers, as the worker's `SyncMap.solve` has them.
fn solve_text(
    text: &str,
    observe: &mut dyn FnMut(kli::sync::PoseStage),
) -> Result<Vec<f64>, kli::KliError> {
    solve_graph(&read(text)?, observe)
}
use super::map_view::class as misfit_class;
use super::world::{World, WorldOptions, between, revisits, route};

fn world(noise: f64, closures: usize, seed: u64) -> World {
    World::new(&WorldOptions { noise, closures, seed })
}

/// The text with VERTEX lines of `poses` first: a file with an initial estimate of its own.
fn with_vertices(text: &str, poses: &[(f64, f64, f64)]) -> String {
    let vertices: String = poses
        .iter()
        .enumerate()
        .map(|(k, (x, y, t))| format!("VERTEX_SE2 {k} {x} {y} {t}\n"))
        .collect();
    vertices + text
}

fn map_of(text: &str) -> SyncMap {
    let answer = solve_text(text, &mut |_| {}).unwrap();
    SyncMap::of(&read(text).unwrap(), &answer).unwrap()
}

/// `(x, y, θ)` of a planar pose.
fn planar(poses: &Poses, k: usize) -> (f64, f64, f64) {
    let q = poses.rotations[k];
    (poses.positions[k].x, poses.positions[k].y, 2.0 * q.z.atan2(q.w))
}

fn angle_gap(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(std::f64::consts::TAU);
    d.min(std::f64::consts::TAU - d)
}

#[test]
fn the_built_in_world_has_the_poses_and_edges_its_route_gives() {
    // The route: 3 + 2 + 3 + 2 + 1 + 3 + 1 + 2 + 2 + 1 + 2 + 2 = 24 blocks of 8 m, a pose a
    // metre: 192 poses, 191 odometry edges; its last pose a metre short of the first.
    let truth = route();
    assert_eq!(truth.len(), 192);
    assert_eq!((truth[191].0, truth[191].1), (1.0, 0.0));
    assert_eq!(truth[191].2, std::f64::consts::PI);
    // Corners by hand: pose 24 is the first at (3, 0) blocks, heading north (+y).
    assert_eq!(truth[24], (24.0, 0.0, std::f64::consts::FRAC_PI_2));
    for closures in [0, 1, 8, 40] {
        let w = world(2.0, closures, 3);
        assert_eq!(w.edges.len(), 191 + closures);
        let graph = read(&w.text).unwrap();
        assert_eq!((graph.count, graph.edges.len(), graph.dimension), (192, 191 + closures, 2));
        // Every loop closure joins two poses at one place, more than a block apart.
        for &[i, j] in &w.edges[191..] {
            assert!(j > i + 8 && truth[i].0 == truth[j].0 && truth[i].1 == truth[j].1);
        }
    }
    // The streets driven twice or more give at least as many places revisited as the page's
    // slider asks for.
    let pairs = revisits(&truth).len();
    assert!(pairs >= super::world::MAX_CLOSURES, "{pairs}");
}

#[test]
fn the_odometry_chained_without_noise_is_the_truth() {
    let w = world(0.0, 8, 1);
    for (&[i, j], &m) in w.edges.iter().zip(&w.measured) {
        assert_eq!(m, between(w.truth[i], w.truth[j]));
    }
    let graph = read(&w.text).unwrap();
    assert!(graph.initial.is_none());
    let (poses, from_file) = initial(&graph);
    assert!(!from_file);
    for (k, &(x, y, t)) in w.truth.iter().enumerate() {
        let (px, py, pt) = planar(&poses, k);
        assert!((px - x).abs() < 1e-9 && (py - y).abs() < 1e-9, "{k}: {px} {py} against {x} {y}");
        assert!(angle_gap(pt, t) < 1e-12, "{k}");
    }
    // With noise, the chaining (quaternions) is the world's own dead reckoning (angles): the
    // search follows odometry, never a loop closure, on this route. Written as VERTEX lines, it
    // is the file's own estimate.
    let w = world(3.0, 20, 7);
    let chained = chained(&read(&w.text).unwrap());
    let (own, from_file) = initial(&read(&with_vertices(&w.text, &w.dead_reckoning)).unwrap());
    assert!(from_file);
    for (k, &(x, y, t)) in w.dead_reckoning.iter().enumerate() {
        for poses in [&chained, &own] {
            let (px, py, pt) = planar(poses, k);
            assert!((px - x).abs() < 1e-9 && (py - y).abs() < 1e-9 && angle_gap(pt, t) < 1e-12);
        }
    }
}

#[test]
fn the_noise_free_world_solves_to_the_truth_at_cost_zero_certified() {
    let w = world(0.0, 12, 1);
    let map = map_of(&w.text);
    let answer = solve_text(&w.text, &mut |_| {}).unwrap();
    // Weights are 1/σ² with σ's floor of 0.1° and 5 mm: 4e4 for a metre, so "zero" is 1e-12.
    assert!(answer[0] < 1e-12, "cost {}", answer[0]);
    assert_eq!(answer[4], 1.0, "certified");
    let optimum = read_poses(&answer[HEAD..], 192);
    // The truth's pose 0 is the origin heading east: the anchor's gauge is the truth's own.
    for (k, &(x, y, t)) in w.truth.iter().enumerate() {
        let (px, py, pt) = planar(&optimum, k);
        assert!((px - x).abs() < 1e-7 && (py - y).abs() < 1e-7, "{k}: {px} {py} against {x} {y}");
        assert!(angle_gap(pt, t) < 1e-9, "{k}");
    }
    assert!(map.optimum_misfits().iter().all(|&m| m < 1e-5 && misfit_class(m) == 0));
}

#[test]
fn the_misfits_sum_to_the_solvers_cost_and_the_noisy_loop_is_straightened() {
    let w = world(2.0, 8, 1);
    let graph = read(&w.text).unwrap();
    let answer = solve_text(&w.text, &mut |_| {}).unwrap();
    let map = SyncMap::of(&graph, &answer).unwrap();
    let optimum = read_poses(&answer[HEAD..], 192);
    let total: f64 = edge_costs(&graph, &optimum).iter().sum();
    // Certified, the proven lower bound is the cost less the tolerance's share, below it.
    assert!(answer[6] <= answer[0] && answer[6] > 0.99 * answer[0], "{} {}", answer[6], answer[0]);
    assert!((total - answer[0]).abs() <= 1e-9 * answer[0], "{total} against {}", answer[0]);
    assert_eq!(answer[4], 1.0);
    // Dead reckoning drifts; the optimum with its loop closures is nearer the truth at the
    // route's end (the worst place for odometry): by the world's numbers, not the solver's.
    let end = |poses: &Poses| {
        let (x, y, _) = planar(poses, 191);
        (x - w.truth[191].0).hypot(y - w.truth[191].1)
    };
    let drift = end(map.initial_poses());
    assert!(drift > 1.0 && end(&optimum) < 0.5 * drift, "{drift} {}", end(&optimum));
    // Against the route (the truth), by the map's own measure: the optimum nearer than the dead
    // reckoning, by the world's numbers as above.
    let mut map = map;
    map.set_truth(w.truth.iter().map(|&(x, y, _)| glam::DVec3::new(x, y, 0.0)).collect());
    let rms = |poses: &Poses| {
        let sum: f64 = (0..192)
            .map(|k| {
                let (x, y, _) = planar(poses, k);
                (x - w.truth[k].0).powi(2) + (y - w.truth[k].1).powi(2)
            })
            .sum();
        (sum / 192.0).sqrt()
    };
    let (before, after) = (map.truth_error(map.initial_poses()), map.truth_error(&optimum));
    assert!(
        (before - rms(map.initial_poses())).abs() < 1e-12 && (after - rms(&optimum)).abs() < 1e-12
    );
    assert!(after < 0.5 * before, "{after} against {before}");
    // The initial cost (the dead reckoning's) is far above the optimum's.
    let initial: f64 = edge_costs(&graph, map.initial_poses()).iter().sum();
    assert!(initial > 10.0 * answer[0]);
}

#[test]
fn the_csv_reads_back_as_the_optimum() {
    let text = include_str!("../../../../tests/fixtures/posegraphs/tinyGrid3D.g2o");
    let graph = read(text).unwrap();
    let answer = solve_text(text, &mut |_| {}).unwrap();
    let n = graph.count;
    let optimum = read_poses(&answer[HEAD..], n);
    let answer = super::map::Answer::read(&answer);
    let text = csv(&Outline::of(&graph), &optimum, &answer);
    let mut rows = text.lines().filter(|l| !l.starts_with('#'));
    assert_eq!(rows.next(), Some("id,x,y,z,qx,qy,qz,qw"));
    let rows: Vec<Vec<f64>> =
        rows.map(|l| l.split(',').map(|x| x.parse().unwrap()).collect()).collect();
    assert_eq!(rows.len(), n);
    for (k, row) in rows.iter().enumerate() {
        let (q, p) = (optimum.rotations[k], optimum.positions[k]);
        assert_eq!(row[..], [graph.ids[k] as f64, p.x, p.y, p.z, q.x, q.y, q.z, q.w], "{k}");
    }
    // As g2o's VERTEX_SE3:QUAT lines with the file's edges, it reads back as the same poses and
    // edges, at the same cost.
    let vertices: String = rows
        .iter()
        .map(|r| {
            format!(
                "VERTEX_SE3:QUAT {} {} {} {} {} {} {} {}\n",
                r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7]
            )
        })
        .collect();
    let edges: String = include_str!("../../../../tests/fixtures/posegraphs/tinyGrid3D.g2o")
        .lines()
        .filter(|l| l.starts_with("EDGE"))
        .map(|l| format!("{l}\n"))
        .collect();
    let back = read(&(vertices + &edges)).unwrap();
    assert_eq!(back.edges, graph.edges);
    let (poses, from_file) = initial(&back);
    assert!(from_file);
    let cost: f64 = edge_costs(&back, &poses).iter().sum();
    assert!((cost - answer.cost).abs() <= 1e-9 * answer.cost, "{cost} {}", answer.cost);
}

#[test]
fn a_bad_file_is_refused_naming_its_line_and_answers_of_another_size_are_refused() {
    let bad = "VERTEX_SE2 0 0 0 0\nVERTEX_SE2 1 1 0 0\nEDGE_SE2 0 1 1 zero 0\n";
    let error = solve_text(bad, &mut |_| {}).unwrap_err();
    assert!(error.to_string().contains("line 3"), "{error}");
    let w = world(1.0, 4, 2);
    let answer = solve_text(&w.text, &mut |_| {}).unwrap();
    let graph = read(&w.text).unwrap();
    let refused = |data: &[f64]| SyncMap::of(&graph, data).err().unwrap().argument().to_owned();
    assert_eq!(refused(&answer[1..]), "answer");
    let mut nan = answer.clone();
    nan[10] = f64::NAN;
    assert_eq!(refused(&nan), "answer");
}

#[test]
fn the_map_the_worker_sends_is_the_map_the_page_unpacks() {
    // A 3D file with ids of its own, one beyond what an f64 holds whole, and landmarks skipped:
    // every part the page shows or saves comes back as the worker made it.
    let text = include_str!("../../../../tests/fixtures/posegraphs/tinyGrid3D.g2o");
    let big = u64::MAX - 6;
    // Pose 8's id (a vertex's first number, an edge's first two) made `big`.
    let ids = |line: &str| {
        let count = if line.starts_with("EDGE") { 2 } else { 1 };
        let words: Vec<String> = line
            .split_whitespace()
            .enumerate()
            .map(
                |(k, w)| {
                    if (1..=count).contains(&k) && w == "8" { big.to_string() } else { w.into() }
                },
            )
            .collect();
        words.join(" ") + "\n"
    };
    let text =
        text.lines().map(ids).collect::<String>() + "VERTEX_XY 100 1 2\nPARAMS_SE2OFFSET 0 0 0 0\n";
    let graph = read(&text).unwrap();
    assert_eq!((graph.ids[graph.count - 1], graph.skipped.len()), (big, 2), "the file as meant");
    let answer = solve_text(&text, &mut |_| {}).unwrap();
    let map = SyncMap::of(&graph, &answer).unwrap();
    let back = SyncMap::from_numbers(&map.numbers()).unwrap();
    assert_eq!(back.csv(), map.csv());
    assert!(back.csv().contains(&format!("\n{big},")));
    assert_eq!(back.numbers(), map.numbers());
    assert_eq!(back.initial_poses().positions, map.initial_poses().positions);
    assert_eq!(back.optimum_misfits(), map.optimum_misfits());
    let summary = |m: &SyncMap| {
        let data = m.numbers();
        (data[7], data[8], data[9], data[10], data[11], data[12], data[13])
    };
    // Dimension 3, 9 poses, the file's edges, two lines skipped, its own estimate, its cost by
    // the edges' terms, the middle of the optimum's misfits (the 6th of 11).
    let initial: f64 = edge_costs(&graph, map.initial_poses()).iter().sum();
    let mut sorted = map.optimum_misfits().to_vec();
    sorted.sort_by(f64::total_cmp);
    assert_eq!(graph.edges.len(), 11);
    assert_eq!(summary(&back), (3.0, 9.0, 11.0, 2.0, 1.0, initial, sorted[5]));
}

#[test]
fn numbers_that_are_not_a_map_are_refused_by_name() {
    let w = world(1.0, 4, 2);
    let graph = read(&w.text).unwrap();
    let good = SyncMap::of(&graph, &solve_text(&w.text, &mut |_| {}).unwrap()).unwrap().numbers();
    let (n, m) = (192, graph.edges.len());
    let lead = HEAD + 7;
    let edges_at = lead + 16 * n;
    let refused = |change: &dyn Fn(&mut Vec<f64>)| {
        let mut data = good.clone();
        change(&mut data);
        SyncMap::from_numbers(&data).err().map(|e| e.argument().to_owned())
    };
    assert_eq!(refused(&|_| {}), None);
    for change in [
        &(|d: &mut Vec<f64>| d.truncate(5)) as &dyn Fn(&mut Vec<f64>),
        &|d| {
            d.pop();
        },
        &|d| d.push(0.0),
        &|d| d[3] = f64::INFINITY,
        &|d| d[HEAD] = 4.0,
        &|d| d[HEAD] = 1.0,
        &|d| d[HEAD + 1] = 191.5,
        &|d| d[HEAD + 1] = 1e300,
        &|d| d[HEAD + 2] = (m + 1) as f64,
        &|d| d[HEAD + 3] = -1.0,
        // A map of nothing: no pose, no edge, every count agreeing.
        &|d| {
            d.truncate(lead);
            (d[HEAD + 1], d[HEAD + 2]) = (0.0, 0.0);
        },
        &|d| d[lead + 14 * n] = 2f64.powi(32),
        &|d| d[edges_at] = n as f64,
        &|d| d[edges_at + 1] = -1.0,
        &|d| d[edges_at + 2 * m - 1] = 0.5,
    ] {
        assert_eq!(refused(change).as_deref(), Some("answer"));
    }
}

#[test]
fn any_numbers_give_a_finite_map_or_an_error_naming_the_answer() {
    // Seeded mutations of a real map's numbers (a value anywhere replaced by an extreme, a
    // fraction, a negative, or the numbers cut short): each is refused by name, or gives a map
    // of finite numbers whose CSV holds no NaN, with no panic on the way.
    let w = world(1.0, 4, 2);
    let graph = read(&w.text).unwrap();
    let good = SyncMap::of(&graph, &solve_text(&w.text, &mut |_| {}).unwrap()).unwrap().numbers();
    let mut state = 0x9e37_79b9_7f4a_7c15_u64;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state
    };
    let values = [0.0, -0.0, -1.0, 0.5, 1e300, -1e300, 191.0, 192.0, 1e-320, 4e9, f64::NAN];
    let (mut drawn, mut refused) = (0, 0);
    for _ in 0..400 {
        let mut data = good.clone();
        for _ in 0..=next() % 3 {
            let k = (next() % data.len() as u64) as usize;
            data[k] = values[(next() % values.len() as u64) as usize];
        }
        if next() % 8 == 0 {
            data.truncate((next() % data.len() as u64) as usize);
        }
        match SyncMap::from_numbers(&data) {
            Ok(map) => {
                drawn += 1;
                // Every number finite, as the drawing needs (its text is JavaScript's, so the
                // drawing itself is the browser suite's).
                assert!(map.initial_poses().positions.iter().all(|p| p.is_finite()));
                assert!(!map.csv().contains("NaN"));
                assert_eq!(map.numbers(), data, "what it took is what it gives");
            }
            Err(error) => {
                refused += 1;
                assert_eq!(error.argument(), "answer", "{error}");
            }
        }
    }
    assert!(drawn > 50 && refused > 50, "{drawn} drawn, {refused} refused");
}
