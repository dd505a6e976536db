//! The swarm against MATH.md, "The swarm": synchronisation and balancing, the potential, the
//! reduction to KLI, unit norms, seeds, and bad options.

use super::*;
use crate::closed_form::kli_exact;
use crate::quaternion::from_wxyz;

fn swarm(count: usize, coupling: f64, graph: Graph, seed: u64) -> Swarm {
    Swarm::new(&SwarmOptions { count, coupling, graph, seed, ..Default::default() }).unwrap()
}

#[test]
fn identical_oscillators_synchronise_when_coupled_positively() {
    let mut s = swarm(50, 1.0, Graph::All, 3);
    let start = s.order_parameter();
    assert!(start < 0.4, "a uniform start is far from synchronised: R = {start}");
    s.step(0.05, 800).unwrap();
    assert!(s.order_parameter() > 1.0 - 1e-9, "R = {}", s.order_parameter());
    assert!(s.rotation_order() > 1.0 - 1e-9);
}

#[test]
fn identical_oscillators_balance_when_coupled_negatively() {
    let mut s = swarm(50, -1.0, Graph::All, 4);
    s.step(0.05, 800).unwrap();
    assert!(s.order_parameter() < 1e-6, "R = {}", s.order_parameter());
}

#[test]
fn the_potential_never_decreases_for_identical_oscillators() {
    for (coupling, seed) in [(1.0, 5), (-1.0, 6), (2.5, 7)] {
        let mut s = swarm(40, coupling, Graph::All, seed);
        let mut previous = s.potential();
        for _ in 0..400 {
            s.step(0.02, 1).unwrap();
            let now = s.potential();
            assert!(now >= previous - 1e-12, "K = {coupling}: {previous} → {now}");
            previous = now;
        }
    }
}

#[test]
fn a_pinned_leader_and_one_follower_are_kli_at_time_k_t_over_2() {
    // The paper's pair: the follower starts at p, the leader sits at r.
    let (p, r) = (from_wxyz([0.0, 0.0, 0.0, 1.0]), from_wxyz([0.5; 4]));
    let coupling = 2.0;
    let options =
        SwarmOptions { count: 2, coupling, graph: Graph::Leader, leaders: 1, ..Default::default() };
    let mut s = Swarm::new(&options).unwrap();
    s.set_quaternions(&[r, p]).unwrap();
    for _ in 0..12 {
        s.step(0.005, 50).unwrap();
        let expected = kli_exact(p, r, coupling * s.time() / 2.0, false).unwrap();
        let error = (s.quaternions()[1] - expected).length();
        assert!(error < 1e-10, "t = {}: {error:e}", s.time());
        assert_eq!(s.quaternions()[0], r, "the leader is pinned");
    }
}

#[test]
fn every_oscillator_stays_on_the_sphere_for_ten_thousand_steps() {
    for graph in [Graph::All, Graph::Ring] {
        let options = SwarmOptions {
            count: 64,
            coupling: 0.5,
            graph,
            frequency_spread: 1.0,
            seed: 8,
            ..Default::default()
        };
        let mut s = Swarm::new(&options).unwrap();
        s.step(0.01, 10_000).unwrap();
        let drift = s.quaternions().iter().map(|q| (q.length() - 1.0).abs()).fold(0.0, f64::max);
        assert!(drift < 1e-12, "{graph:?}: {drift:e}");
        assert!((s.time() - 100.0).abs() < 1e-9);
    }
}

#[test]
fn a_ring_of_identical_oscillators_synchronises_from_a_near_start() {
    let options = SwarmOptions {
        count: 8,
        coupling: 1.0,
        graph: Graph::Ring,
        start_spread: Some(0.5),
        seed: 9,
        ..Default::default()
    };
    let mut s = Swarm::new(&options).unwrap();
    s.step(0.05, 4000).unwrap();
    assert!(s.order_parameter() > 1.0 - 1e-6, "R = {}", s.order_parameter());
}

#[test]
fn spread_frequencies_need_strong_coupling_to_synchronise() {
    // The transition the page sweeps: with frequencies of spread 1, weak coupling leaves the
    // swarm incoherent and strong coupling locks it (time-averaged R over the last stretch).
    let averaged_r = |coupling: f64| {
        let options = SwarmOptions {
            count: 100,
            coupling,
            frequency_spread: 1.0,
            seed: 10,
            ..Default::default()
        };
        let mut s = Swarm::new(&options).unwrap();
        s.step(0.02, 1500).unwrap();
        (0..100)
            .map(|_| {
                s.step(0.02, 5).unwrap();
                s.order_parameter()
            })
            .sum::<f64>()
            / 100.0
    };
    let (weak, strong) = (averaged_r(0.2), averaged_r(8.0));
    assert!(weak < 0.3, "K = 0.2: R = {weak}");
    assert!(strong > 0.9, "K = 8: R = {strong}");
}

#[test]
fn the_same_seed_gives_the_same_swarm() {
    let options = SwarmOptions {
        count: 30,
        frequency_spread: 0.3,
        start_spread: Some(0.4),
        seed: 12,
        ..Default::default()
    };
    let (mut a, mut b) = (Swarm::new(&options).unwrap(), Swarm::new(&options).unwrap());
    a.step(0.1, 10).unwrap();
    b.step(0.1, 10).unwrap();
    assert_eq!(a.quaternions(), b.quaternions());
    let other = Swarm::new(&SwarmOptions { seed: 13, ..options }).unwrap();
    assert_ne!(Swarm::new(&options).unwrap().quaternions(), other.quaternions());
}

#[test]
fn a_near_start_has_the_spread_asked_for() {
    // q = exp(v) with v normal, σ in each of 3 directions: the angle |v| from the identity is
    // σ times a χ variable with 3 degrees of freedom, of mean 2√(2/π).
    let sigma = 0.4;
    let options =
        SwarmOptions { count: 4000, start_spread: Some(sigma), seed: 14, ..Default::default() };
    let s = Swarm::new(&options).unwrap();
    let angles: Vec<f64> = s.quaternions().iter().map(|q| q.xyz().length().atan2(q.w)).collect();
    let mean = angles.iter().sum::<f64>() / angles.len() as f64;
    let expected = sigma * 2.0 * (2.0 / std::f64::consts::PI).sqrt();
    // Standard error: σ √(3 − 8/π) / √4000 ≈ 0.0043.
    assert!((mean - expected).abs() < 0.02, "mean angle {mean} against {expected}");
}

#[test]
fn bad_options_name_the_option() {
    let bad = |options: SwarmOptions| Swarm::new(&options).unwrap_err().argument().to_owned();
    let base = SwarmOptions::default();
    assert_eq!(bad(SwarmOptions { count: 0, ..base }), "count");
    assert_eq!(bad(SwarmOptions { count: MAX_COUNT + 1, ..base }), "count");
    assert_eq!(bad(SwarmOptions { coupling: f64::NAN, ..base }), "coupling");
    assert_eq!(bad(SwarmOptions { frequency_spread: -1.0, ..base }), "frequency_spread");
    assert_eq!(bad(SwarmOptions { start_spread: Some(f64::INFINITY), ..base }), "start_spread");
    assert_eq!(bad(SwarmOptions { graph: Graph::Leader, leaders: 0, ..base }), "leaders");
    assert_eq!(bad(SwarmOptions { graph: Graph::Leader, count: 3, leaders: 4, ..base }), "leaders");
    assert_eq!("star".parse::<Graph>().unwrap_err().argument(), "graph");
    // The JavaScript API's names, each read back as its graph.
    for (graph, name) in [(Graph::All, "all"), (Graph::Ring, "ring"), (Graph::Leader, "leader")] {
        assert_eq!((graph.name(), name.parse::<Graph>().unwrap()), (name, graph));
    }
    let mut s = Swarm::new(&base).unwrap();
    assert_eq!(s.step(0.0, 1).unwrap_err().argument(), "dt");
    assert_eq!(s.set_quaternions(&[DQuat::IDENTITY]).unwrap_err().argument(), "quaternions");
    let mut two = swarm(2, 1.0, Graph::All, 1);
    let zero = DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0);
    assert_eq!(
        two.set_quaternions(&[DQuat::IDENTITY, zero]).unwrap_err().argument(),
        "quaternions[1]"
    );
}

#[test]
fn a_call_takes_up_to_a_million_steps_and_refuses_more() {
    let mut one = swarm(1, 1.0, Graph::All, 1);
    one.step(1e-6, MAX_STEPS).unwrap();
    assert!((one.time() - 1.0).abs() < 1e-9, "{}", one.time());
    let e = one.step(1e-6, MAX_STEPS + 1).unwrap_err();
    assert_eq!(e.argument(), "steps");
    assert!((one.time() - 1.0).abs() < 1e-9, "a refused call runs no step");
}

/// The swarm's measures on two oscillators worked by hand, `1` and `(1 + i)/√2` with `K = 3`:
/// `m = (1 + (1 + i)/√2)/2`, so `R = |m|`, the potential `(K N/2)|m|²`, `λ_max(Q) = (1 +
/// |q·p|)/2` (the two eigenvalues of `½(qqᵀ + ppᵀ)` are `(1 ± q·p)/2`), and each Hopf point the
/// body x-axis rotated, `q x q̄`.
#[test]
fn the_measures_of_two_oscillators() {
    let mut s = swarm(2, 3.0, Graph::All, 1);
    let (one, p) = (DQuat::IDENTITY, from_wxyz([0.5f64.sqrt(), 0.5f64.sqrt(), 0.0, 0.0]));
    s.set_quaternions(&[one, p]).unwrap();
    let m = (one + p) * 0.5;
    assert!((s.order_parameter() - m.length()).abs() < 1e-15);
    assert!((s.potential() - 3.0 * m.length_squared()).abs() < 1e-14, "{}", s.potential());
    let c = 0.5f64.sqrt();
    assert!((s.rotation_order() - (1.0 + c) / 2.0).abs() < 1e-14, "{}", s.rotation_order());
    let points = s.hopf_points();
    assert_eq!(points.len(), 2);
    for (point, q) in points.iter().zip([one, p]) {
        let x = q * DQuat::from_xyzw(1.0, 0.0, 0.0, 0.0) * q.conjugate();
        assert!((*point - DVec3::new(x.x, x.y, x.z)).length() < 1e-15, "{point:?}");
    }
}

/// The ring's field written out from MATH.md, `f_i = w_i q_i + (K/N) Σ_{j = i ± 1} (q_j −
/// (q_i·q_j) q_i)`, for five oscillators and for two (one edge, counted once).
#[test]
fn the_rings_field_is_the_neighbours_pull() {
    let mut random = crate::swarm::Random::new(43);
    for n in [5, 2] {
        let state: Vec<DQuat> = (0..n).map(|_| random.unit_quaternion()).collect();
        let frequencies: Vec<DQuat> = (0..n)
            .map(|_| DQuat::from_xyzw(random.uniform(), random.uniform(), -0.3, 0.0))
            .collect();
        let mut out = vec![DQuat::IDENTITY; n];
        field(&state, &frequencies, 1.7, Graph::Ring, 0, &mut out);
        for i in 0..n {
            let neighbours = if n == 2 { vec![1 - i] } else { vec![(i + n - 1) % n, (i + 1) % n] };
            let pull = neighbours.iter().fold(DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0), |sum, &j| {
                sum + (state[j] - state[i] * state[i].dot(state[j]))
            });
            let want = frequencies[i] * state[i] + pull * (1.7 / n as f64);
            assert!((out[i] - want).length() < 1e-15, "N = {n}, i = {i}");
        }
    }
}
