//! `cargo bench -p kli-bench`: kli's SLERP and closed form against glam's and nalgebra's SLERP on
//! the same pairs, Algorithm 1 on the paper's example with each integrator, and a swarm step.

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use kli::batch::{kli_exact_batch, slerp_batch};
use kli::{Integrator, KliOptions, from_wxyz, kli, kli_exact, slerp, to_wxyz};
use kli_bench::random_pairs;
use nalgebra::{Quaternion, UnitQuaternion};
use std::hint::black_box;

const PAIRS: usize = 10_000;

fn interpolation(c: &mut Criterion) {
    let pairs = random_pairs(PAIRS);
    let nalgebra_pairs: Vec<_> = pairs
        .iter()
        .map(|&(p, r, s)| {
            let q =
                |q: kli::DQuat| UnitQuaternion::new_normalize(Quaternion::new(q.w, q.x, q.y, q.z));
            (q(p), q(r), s)
        })
        .collect();
    let starts: Vec<f64> = pairs.iter().flat_map(|&(p, _, _)| to_wxyz(p)).collect();
    let ends: Vec<f64> = pairs.iter().flat_map(|&(_, r, _)| to_wxyz(r)).collect();
    let params: Vec<f64> = pairs.iter().map(|&(_, _, s)| s).collect();
    let mut out = vec![0.0; 4 * PAIRS];

    let mut group = c.benchmark_group("slerp of 10k pairs");
    group.throughput(Throughput::Elements(PAIRS as u64));
    group.bench_function("kli::slerp (one call each, validated)", |b| {
        b.iter(|| pairs.iter().map(|&(p, r, s)| slerp(p, r, s, true).unwrap().w).sum::<f64>())
    });
    group.bench_function("kli::batch::slerp_batch", |b| {
        b.iter(|| slerp_batch(black_box(&starts), &ends, &params, &mut out, true).unwrap())
    });
    group.bench_function("glam DQuat::slerp", |b| {
        b.iter(|| pairs.iter().map(|&(p, r, s)| p.slerp(r, s).w).sum::<f64>())
    });
    group.bench_function("nalgebra UnitQuaternion::slerp", |b| {
        b.iter(|| nalgebra_pairs.iter().map(|(p, r, s)| p.slerp(r, *s).w).sum::<f64>())
    });
    group.finish();

    let mut group = c.benchmark_group("KLI closed form of 10k pairs");
    group.throughput(Throughput::Elements(PAIRS as u64));
    group.bench_function("kli::kli_exact (one call each)", |b| {
        b.iter(|| {
            pairs.iter().map(|&(p, r, t)| kli_exact(p, r, 12.0 * t, true).unwrap().w).sum::<f64>()
        })
    });
    group.bench_function("kli::batch::kli_exact_batch", |b| {
        b.iter(|| kli_exact_batch(black_box(&starts), &ends, &params, &mut out, true).unwrap())
    });
    group.finish();
}

fn algorithm_1(c: &mut Criterion) {
    let (p, r) = (from_wxyz([0.0, 0.0, 0.0, 1.0]), from_wxyz([0.5; 4]));
    let mut group = c.benchmark_group("Algorithm 1, paper's example (1166 steps)");
    for integrator in Integrator::ALL {
        let options = KliOptions { integrator, ..Default::default() };
        group.bench_function(integrator.name(), |b| {
            b.iter(|| kli(black_box(p), r, &options).unwrap().steps())
        });
    }
    group.finish();
}

/// One geodesic RK4 step of the swarm (issue 9's target is ≤ 1 ms for 10⁴ all-to-all in wasm).
fn swarm(c: &mut Criterion) {
    use kli::swarm::{Graph, Swarm, SwarmOptions};
    let mut group = c.benchmark_group("swarm step");
    for (graph, count) in [(Graph::All, 10_000), (Graph::Ring, 10_000), (Graph::All, 2_000)] {
        let options = SwarmOptions { count, graph, frequency_spread: 0.5, ..Default::default() };
        let mut s = Swarm::new(&options).unwrap();
        group.throughput(Throughput::Elements(count as u64));
        group.bench_function(format!("{} oscillators, {}", count, graph.name()), |b| {
            b.iter(|| s.step(black_box(0.01), 1).unwrap())
        });
    }
    group.finish();
}

criterion_group!(benches, interpolation, algorithm_1, swarm);
criterion_main!(benches);
