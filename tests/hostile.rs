//! Every public function of the crate called with hostile floats (NaN, ±∞, ±0, negatives, 1e308,
//! ±f64::MAX, the smallest subnormal, 1e-300) in each float argument, under a time bound: each
//! call returns (a value or an Error) and none panics or runs on. A function documented as
//! total may give NaN for NaN; one that returns a `Result` gives a finite answer or an Error.
//!
//! The calls run on a worker thread that names the call it is in; the test fails, naming it,
//! when one panics or when the worker has not finished within the bound.
#![cfg(not(target_arch = "wasm32"))]

use std::sync::mpsc;
use std::sync::{Arc, Mutex};
use std::time::Duration;

use kli::average::{Method, average, chordal_flow, eigen, quaternion_mean, scatter};
use kli::batch::{
    BatchKind, check_lengths, kli_exact_batch, kli_sample_into, nlerp_batch, run_batch, slerp_batch,
};
use kli::closed_form::{self, kli_exact, kli_reach_time, kli_to_slerp_parameter};
use kli::error::rust_number;
use kli::great_arc::{GreatArc, choose_target};
use kli::model::{integrate_as_printed, velocity, velocity_as_printed};
use kli::quaternion::{exp, log, norm, plain_inverse_square, unit};
use kli::spline::{
    ChainOptions, Curve, Keys, KliSpline, PiecewiseSlerp, RotvecCubic, SequentialKli, Squad,
};
use kli::swarm::{Graph, Random, Swarm, SwarmOptions, mean, order_parameter, rotation_order};
#[cfg(feature = "sync")]
use kli::sync::{self, OtherLines, SyncFlow, SyncOptions, errors_to_truth, read_g2o, synchronize};
use kli::{
    DQuat, DVec3, Integrator, KliOptions, Requirement, axis_angle, from_axis_angle, from_wxyz,
    hopf, kli, require, slerp, to_wxyz,
};

/// The hostile values, and two ordinary ones so that each argument is also tried alone.
const HOSTILE: [f64; 15] = [
    f64::NAN,
    f64::INFINITY,
    f64::NEG_INFINITY,
    0.0,
    -0.0,
    -1.0,
    -1e-3,
    1e308,
    f64::MAX,
    -f64::MAX,
    5e-324,
    -5e-324,
    1e-300,
    0.5,
    1.0,
];

/// How long all the calls of one test may take together (each ends in well under a second;
/// the slowest, a refused or bounded run of Algorithm 1, in milliseconds).
const BOUND: Duration = Duration::from_secs(120);

/// Runs `calls` on a worker thread, which records the call it is in through the `Probe`.
fn bounded(calls: impl FnOnce(&Probe) + Send + 'static) {
    let current = Arc::new(Mutex::new(String::from("(not started)")));
    let probe = Probe(current.clone());
    let (done, finished) = mpsc::channel();
    let worker = std::thread::spawn(move || {
        calls(&probe);
        done.send(()).ok();
    });
    match finished.recv_timeout(BOUND) {
        Ok(()) => worker.join().unwrap(),
        Err(mpsc::RecvTimeoutError::Disconnected) => {
            let call = current.lock().map(|c| c.clone()).unwrap_or_default();
            panic!("panicked in {call}");
        }
        Err(mpsc::RecvTimeoutError::Timeout) => {
            let call = current.lock().map(|c| c.clone()).unwrap_or_default();
            panic!("no answer within {BOUND:?}: still in {call}");
        }
    }
}

struct Probe(Arc<Mutex<String>>);

impl Probe {
    /// Records `call` as the one running, then runs it.
    fn call<T>(&self, call: impl FnOnce() -> String, f: impl FnOnce() -> T) -> T {
        if let Ok(mut current) = self.0.lock() {
            *current = call();
        }
        f()
    }
}

/// A quaternion with `x` in component `k` (the others those of a unit quaternion), and `x` in
/// every component.
fn quaternions(x: f64) -> [DQuat; 5] {
    let base = [0.5, -0.5, 0.5, 0.5];
    let mut out = [from_wxyz([x; 4]); 5];
    for (k, slot) in out.iter_mut().take(4).enumerate() {
        let mut c = base;
        c[k] = x;
        *slot = from_wxyz(c);
    }
    out
}

fn every_quaternion() -> Vec<DQuat> {
    let mut all = vec![from_wxyz([0.0, 0.0, 0.0, 1.0]), from_wxyz([0.5; 4])];
    for x in HOSTILE {
        all.extend(quaternions(x));
    }
    all
}

/// An Error names its argument and says something; an answer is left to the caller.
fn named<T>(result: Result<T, kli::KliError>) {
    if let Err(e) = result {
        assert!(!e.argument().is_empty() && !e.to_string().is_empty(), "{e:?}");
    }
}

fn finite(q: DQuat) -> bool {
    q.is_finite()
}

/// A `Result` from a call with a quaternion answer: an Error, or a finite unit quaternion.
fn unit_or_error(q: &Result<DQuat, kli::KliError>) -> bool {
    match q {
        Ok(q) => q.is_finite() && (q.length() - 1.0).abs() < 1e-12,
        Err(e) => !e.to_string().is_empty(),
    }
}

#[test]
fn single_rotations_hostile_floats() {
    bounded(|probe| {
        let qs = every_quaternion();
        let p = from_wxyz([0.0, 0.0, 0.0, 1.0]);
        for &q in &qs {
            let name = || format!("{q:?}");
            probe.call(|| format!("to_wxyz({})", name()), || to_wxyz(q));
            probe.call(|| format!("norm({})", name()), || norm(q));
            probe.call(|| format!("plain_inverse_square({})", name()), || plain_inverse_square(q));
            let u = probe.call(|| format!("unit({})", name()), || unit("q", q));
            assert!(unit_or_error(&u), "unit({q:?}) = {u:?}");
            probe.call(|| format!("log({})", name()), || log(q));
            probe.call(|| format!("hopf({})", name()), || hopf(q));
            let aa = probe.call(|| format!("axis_angle({})", name()), || axis_angle(q));
            if let Ok((axis, angle)) = aa {
                assert!(axis.is_finite() && angle.is_finite(), "axis_angle({q:?}) = {aa:?}");
            }
            probe.call(|| format!("velocity({})", name()), || velocity(q, p));
            probe.call(|| format!("velocity_as_printed({})", name()), || velocity_as_printed(q, p));
            probe.call(|| format!("choose_target({})", name()), || choose_target(p, q, true));
            for integrator in Integrator::ALL {
                for h in HOSTILE {
                    probe.call(
                        || format!("{}.step({}, h = {h})", integrator.name(), name()),
                        || integrator.step(q, p, h),
                    );
                }
            }
            for v in [DVec3::new(q.x, q.y, q.z), DVec3::splat(q.w)] {
                probe.call(|| format!("exp({v:?})"), || exp(v));
                for angle in HOSTILE {
                    let r = probe.call(
                        || format!("from_axis_angle({v:?}, {angle})"),
                        || from_axis_angle(v, angle),
                    );
                    assert!(unit_or_error(&r), "from_axis_angle({v:?}, {angle}) = {r:?}");
                }
            }
        }
        for x in HOSTILE {
            for requirement in [
                Requirement::Finite,
                Requirement::Positive,
                Requirement::NonNegative,
                Requirement::AtMost(x),
                Requirement::Between(x, 1.0),
                Requirement::Between(-1.0, x),
            ] {
                named(probe.call(
                    || format!("require({x}, {requirement:?})"),
                    || require("x", x, requirement),
                ));
            }
            probe.call(|| format!("rust_number({x})"), || rust_number(x));
        }
    });
}

#[test]
fn pairs_hostile_floats() {
    bounded(|probe| {
        let qs = every_quaternion();
        let good = from_wxyz([0.5; 4]);
        for &q in &qs {
            for (p, r) in [(q, good), (good, q), (q, q)] {
                let pair = || format!("({p:?}, {r:?})");
                for shortest in [true, false] {
                    let arc = probe.call(
                        || format!("GreatArc::between{}", pair()),
                        || GreatArc::between(p, r, shortest),
                    );
                    named(probe.call(
                        || format!("GreatArc::new{}", pair()),
                        || GreatArc::new(p, r, shortest),
                    ));
                    let at_point = GreatArc::at_point(p);
                    for x in HOSTILE {
                        let s = probe.call(
                            || format!("slerp{} at {x}", pair()),
                            || slerp(p, r, x, shortest),
                        );
                        assert!(unit_or_error(&s), "slerp{} at {x} = {s:?}", pair());
                        let e = probe.call(
                            || format!("kli_exact{} at {x}", pair()),
                            || kli_exact(p, r, x, shortest),
                        );
                        assert!(unit_or_error(&e), "kli_exact{} at {x} = {e:?}", pair());
                        let w = probe.call(
                            || format!("kli_to_slerp_parameter{} at {x}", pair()),
                            || kli_to_slerp_parameter(p, r, x, shortest),
                        );
                        assert!(w.as_ref().map_or(true, |w| w.is_finite()), "{w:?}");
                        let t = probe.call(
                            || format!("kli_reach_time{} for {x}", pair()),
                            || kli_reach_time(p, r, x, shortest),
                        );
                        assert!(t.as_ref().map_or(true, |t| t.is_finite()), "{t:?}");
                        for arc in arc.iter().chain([&at_point]) {
                            probe.call(
                                || format!("arc{} at {x}", pair()),
                                || {
                                    (
                                        closed_form::point_at(arc, x),
                                        closed_form::point_from_half_angle_tan(arc, x),
                                        closed_form::angle_at(arc, x),
                                        closed_form::time_warp(arc, x),
                                        closed_form::reach_time(arc, x),
                                        kli::slerp::point_at(arc, x),
                                        arc.point_at_angle(x),
                                        arc.point(x, x),
                                        arc.start_distance(),
                                    )
                                },
                            );
                        }
                    }
                }
            }
        }
    });
}

#[test]
fn algorithm_one_and_the_printed_model_hostile_floats() {
    bounded(|probe| {
        let (p, r) = (from_wxyz([0.0, 0.0, 0.0, 1.0]), from_wxyz([0.5; 4]));
        for x in HOSTILE {
            for integrator in Integrator::ALL {
                let ordinary = KliOptions { integrator, ..KliOptions::default() };
                for options in [
                    KliOptions { tolerance: x, ..ordinary },
                    KliOptions { step: x, ..ordinary },
                    KliOptions { max_time: x, ..ordinary },
                    KliOptions { tolerance: x, step: x, max_time: x, ..ordinary },
                ] {
                    let path =
                        probe.call(|| format!("kli(paper, {options:?})"), || kli(p, r, &options));
                    if let Ok(path) = path {
                        let last = *path.quaternions().last().unwrap();
                        assert!(finite(last) && path.final_time().is_finite(), "{options:?}");
                        for t in HOSTILE {
                            let q = probe.call(|| format!("exact_at({t})"), || path.exact_at(t));
                            assert!(unit_or_error(&q), "exact_at({t}) = {q:?}");
                        }
                        probe.call(|| "hopf_curve".into(), || path.hopf_curve());
                    }
                }
            }
            for q in quaternions(x) {
                let path =
                    probe.call(|| format!("kli({q:?}, r)"), || kli(q, r, &KliOptions::default()));
                assert!(path.is_ok() || path.is_err());
            }
            for step in HOSTILE {
                for times in [vec![x], vec![0.0, x], vec![x, 1.0], vec![1.0, 2.0]] {
                    let samples = probe.call(
                        || format!("integrate_as_printed(step {step}, {times:?})"),
                        || integrate_as_printed(p, r, step, &times),
                    );
                    if let Ok(samples) = samples {
                        assert!(samples.iter().all(|q| finite(*q)), "step {step}, {times:?}");
                    }
                }
            }
            for q in quaternions(x) {
                let samples = probe.call(
                    || format!("integrate_as_printed({q:?})"),
                    || integrate_as_printed(q, r, 0.01, &[1.0]),
                );
                assert!(samples.is_err() || samples.unwrap().iter().all(|q| finite(*q)));
            }
        }
    });
}

#[test]
fn batches_hostile_floats() {
    bounded(|probe| {
        let good = [0.0, 0.0, 0.0, 1.0, 0.5, 0.5, 0.5, 0.5];
        for x in HOSTILE {
            let mut bad = good;
            bad[1] = x;
            let every = [x; 8];
            for (starts, ends) in [(bad, good), (good, bad), (every, good), (good, good)] {
                for parameters in [[x, 0.5], [0.5, x], [0.5, 0.25]] {
                    let mut out = [0.0; 8];
                    for shortest in [true, false] {
                        for kind in [BatchKind::Slerp, BatchKind::KliExact, BatchKind::Nlerp] {
                            let result = probe.call(
                                || format!("{kind:?} {starts:?} {ends:?} {parameters:?}"),
                                || {
                                    run_batch(
                                        kind,
                                        &starts,
                                        &ends,
                                        &parameters,
                                        &mut out,
                                        0,
                                        shortest,
                                    )
                                },
                            );
                            if result.is_ok() {
                                assert!(out.iter().all(|c| c.is_finite()), "{kind:?}: {out:?}");
                            }
                        }
                        named(probe.call(
                            || format!("slerp_batch {starts:?} {ends:?} {parameters:?}"),
                            || slerp_batch(&starts, &ends, &parameters, &mut out, shortest),
                        ));
                        named(probe.call(
                            || format!("kli_exact_batch {starts:?} {ends:?} {parameters:?}"),
                            || kli_exact_batch(&starts, &ends, &parameters, &mut out, shortest),
                        ));
                        let p = from_wxyz([starts[0], starts[1], starts[2], starts[3]]);
                        let r = from_wxyz([ends[4], ends[5], ends[6], ends[7]]);
                        let sampled = probe.call(
                            || format!("kli_sample_into({p:?}, {r:?}, {parameters:?})"),
                            || kli_sample_into(p, r, &parameters, &mut out, shortest),
                        );
                        if sampled.is_ok() {
                            assert!(out.iter().all(|c| c.is_finite()), "sampled: {out:?}");
                        }
                    }
                    named(probe.call(
                        || format!("nlerp_batch {starts:?} {ends:?} {parameters:?}"),
                        || nlerp_batch(&starts, &ends, &parameters, &mut out),
                    ));
                }
            }
        }
        // Wrong lengths are refused, whatever the sizes.
        for (a, b, c, d) in [(0, 0, 0, 0), (usize::MAX, 4, 1, 4), (4, 4, usize::MAX / 4 + 1, 4)] {
            named(probe.call(
                || format!("check_lengths{:?}", (a, b, c, d)),
                || check_lengths(a, b, c, d, "s"),
            ));
        }
        assert!(check_lengths(4, 4, usize::MAX / 2, 4, "s").is_err());
    });
}

#[test]
fn means_hostile_floats() {
    bounded(|probe| {
        let good = [
            from_wxyz([1.0, 0.0, 0.0, 0.0]),
            from_wxyz([0.9, 0.1, 0.0, 0.0]),
            from_wxyz([0.9, 0.0, 0.1, 0.0]),
        ];
        for x in HOSTILE {
            for q in quaternions(x) {
                let data = [good[0], q, good[2]];
                for weights in [None, Some([1.0, x, 1.0]), Some([x; 3])] {
                    for method in
                        [Method::Chordal, Method::Quaternion, Method::Geodesic, Method::Median]
                    {
                        let mean = probe.call(
                            || format!("average({data:?}, {weights:?}, {method:?})"),
                            || average(data, weights.as_ref().map(|w| &w[..]), method),
                        );
                        if let Ok(mean) = mean {
                            assert!(
                                mean.rotation.is_finite() && mean.dispersion.is_finite(),
                                "{mean:?}"
                            );
                        }
                    }
                    for aligned in [true, false] {
                        named(probe.call(
                            || format!("quaternion_mean({data:?}, {weights:?})"),
                            || quaternion_mean(&data, weights.as_ref().map(|w| &w[..]), aligned),
                        ));
                    }
                    probe.call(
                        || format!("scatter({data:?}, {weights:?})"),
                        || scatter(&data, weights.as_ref().map(|w| &w[..])),
                    );
                }
                probe.call(|| format!("angle({q:?})"), || kli::average::angle(q, good[0]));
            }
            let mut m =
                [[1.0, 0.2, 0.0, 0.0], [0.2, 0.5, 0.0, 0.0], [0.0, 0.0, 0.1, 0.0], [0.0; 4]];
            for cell in [(0, 0), (0, 1), (3, 3)] {
                let mut hostile = m;
                hostile[cell.0][cell.1] = x;
                hostile[cell.1][cell.0] = x;
                probe.call(|| format!("eigen({hostile:?})"), || eigen(hostile));
                for dt in HOSTILE {
                    probe.call(
                        || format!("chordal_flow({hostile:?}, dt {dt}).take(64)"),
                        || chordal_flow(hostile, good[1], dt).take(64).count(),
                    );
                }
            }
            m[1][1] = x;
            probe.call(|| format!("eigen(diag {x})"), || eigen(m));
            probe.call(
                || format!("chordal_flow from {x}"),
                || chordal_flow(m, from_wxyz([x; 4]), 0.1).take(64).count(),
            );
        }
    });
}

#[test]
fn swarm_hostile_floats() {
    bounded(|probe| {
        for x in HOSTILE {
            let ordinary = SwarmOptions { count: 16, ..SwarmOptions::default() };
            for graph in [Graph::All, Graph::Ring, Graph::Leader] {
                let ordinary = SwarmOptions { graph, leaders: 2, ..ordinary };
                for options in [
                    SwarmOptions { coupling: x, ..ordinary },
                    SwarmOptions { frequency_spread: x, ..ordinary },
                    SwarmOptions { start_spread: Some(x), ..ordinary },
                ] {
                    let swarm =
                        probe.call(|| format!("Swarm::new({options:?})"), || Swarm::new(&options));
                    let Ok(mut swarm) = swarm else { continue };
                    for dt in HOSTILE {
                        let stepped = probe.call(
                            || format!("step({dt}, 10) of {options:?}"),
                            || swarm.step(dt, 10),
                        );
                        if stepped.is_ok() {
                            assert!(
                                swarm.quaternions().iter().all(|q| q.is_finite()),
                                "dt {dt}, {options:?}"
                            );
                        }
                    }
                    let mut hostile = swarm.quaternions().to_vec();
                    for q in quaternions(x) {
                        hostile[3] = q;
                        named(probe.call(
                            || format!("set_quaternions({q:?})"),
                            || swarm.set_quaternions(&hostile),
                        ));
                    }
                    probe.call(
                        || "order parameters".into(),
                        || {
                            (
                                swarm.order_parameter(),
                                swarm.rotation_order(),
                                swarm.potential(),
                                swarm.hopf_points(),
                            )
                        },
                    );
                }
            }
            // More steps than a call may take are refused, not run.
            let mut swarm = Swarm::new(&ordinary).unwrap();
            let refused =
                probe.call(|| "step(0.01, usize::MAX)".into(), || swarm.step(0.01, usize::MAX));
            assert_eq!(refused.unwrap_err().argument(), "steps");
            let qs = quaternions(x);
            probe.call(
                || format!("mean({qs:?})"),
                || (mean(&qs), order_parameter(&qs), rotation_order(&qs)),
            );
            let mut random = Random::new(x.to_bits());
            for q in qs {
                probe.call(|| format!("Random::near({q:?}, {x})"), || random.near(q, x));
            }
        }
    });
}

#[test]
fn curves_hostile_floats() {
    bounded(|probe| {
        let keys =
            [from_wxyz([1.0, 0.0, 0.0, 0.0]), from_wxyz([0.5; 4]), from_wxyz([0.0, 1.0, 0.0, 0.0])];
        for x in HOSTILE {
            let mut hostile_keys = keys;
            hostile_keys[1] = from_wxyz([x, 0.5, 0.5, 0.5]);
            for (quaternions, times) in [
                (keys, Some([0.0, x, 2.0])),
                (keys, Some([x, 1.0, 2.0])),
                (keys, Some([0.0, 1.0, x])),
                (hostile_keys, None),
                (keys, None),
            ] {
                let made = probe.call(
                    || format!("Keys::new({quaternions:?}, {times:?})"),
                    || Keys::new(&quaternions, times.as_ref().map(|t| &t[..])),
                );
                let Ok(made) = made else { continue };
                let mut curves: Vec<Box<dyn Curve>> = vec![
                    Box::new(Squad::new(made.clone())),
                    Box::new(PiecewiseSlerp::new(made.clone())),
                ];
                for smoothness in HOSTILE {
                    for samples_per_segment in [0, 1, 2, 32, 257, usize::MAX] {
                        let options = ChainOptions { smoothness, samples_per_segment };
                        let chain = probe.call(
                            || format!("KliSpline::new({quaternions:?}, {times:?}, {options:?})"),
                            || KliSpline::new(made.clone(), &options),
                        );
                        if let Ok(chain) = chain {
                            curves.push(Box::new(chain));
                        }
                    }
                }
                if let Ok(sequential) = SequentialKli::new(made.clone(), &KliOptions::default()) {
                    curves.push(Box::new(sequential));
                }
                for curve in &curves {
                    for t in HOSTILE {
                        let q = probe.call(|| format!("curve.at({t})"), || curve.at(t));
                        assert!(q.is_finite(), "at({t}) = {q:?}");
                        let w = probe.call(
                            || format!("curve.angular_velocity({t})"),
                            || curve.angular_velocity(t),
                        );
                        assert!(w.is_finite(), "angular_velocity({t}) = {w:?}");
                    }
                    let times = HOSTILE;
                    let mut out = [0.0; 4 * HOSTILE.len()];
                    probe.call(
                        || "sample_into(HOSTILE)".into(),
                        || curve.sample_into(&times, &mut out),
                    );
                    assert!(out.iter().all(|c| c.is_finite()), "{out:?}");
                }
            }
            for (samples, times) in [
                (&keys[..], vec![0.0, x, 2.0]),
                (&keys[..], vec![x, 1.0, 2.0]),
                (&hostile_keys[..], vec![0.0, 1.0, 2.0]),
                (&keys[..0], vec![]),
                (&keys[..1], vec![0.0]),
                (&keys[..], vec![0.0, 1.0]),
            ] {
                let cubic = probe.call(
                    || format!("RotvecCubic::new({samples:?}, {times:?})"),
                    || RotvecCubic::new(samples, &times),
                );
                if x == 0.5 && samples.len() == 3 && times.len() == 3 {
                    assert!(cubic.is_ok() || !samples[1].is_finite(), "{samples:?} {times:?}");
                }
            }
        }
    });
}

#[cfg(feature = "sync")]
#[test]
fn synchronisation_hostile_floats() {
    bounded(|probe| {
        let edges = [[0, 1], [1, 2], [0, 2], [2, 3]];
        let ordinary = [
            DQuat::IDENTITY,
            from_wxyz([0.5; 4]),
            from_wxyz([0.0, 1.0, 0.0, 0.0]),
            DQuat::IDENTITY,
        ];
        for x in HOSTILE {
            let mut graphs = Vec::new();
            for q in quaternions(x) {
                let mut relative = ordinary;
                relative[2] = q;
                let graph = probe.call(
                    || format!("sync::Graph::new(relative[2] = {q:?})"),
                    || sync::Graph::new(None, &edges, &relative, None),
                );
                named(graph.clone());
                graphs.extend(graph);
            }
            let weights = [1.0, x, 1.0, x];
            let graph = probe.call(
                || format!("sync::Graph::new(weights {weights:?})"),
                || sync::Graph::new(None, &edges, &ordinary, Some(&weights)),
            );
            named(graph.clone());
            graphs.extend(graph);
            for graph in &graphs {
                for method in [sync::Method::Chordal, sync::Method::Robust, sync::Method::Spectral]
                {
                    for scale in [None, Some(x)] {
                        let options = SyncOptions { method, scale, anchor: 3 };
                        let result = probe.call(
                            || format!("synchronize({graph:?}, {options:?})"),
                            || synchronize(graph, &options),
                        );
                        match result {
                            Ok(r) => {
                                assert!(r.rotations.iter().all(|q| finite(*q)), "{graph:?}");
                                assert!(
                                    r.cost.is_finite() && r.residuals.iter().all(|t| t.is_finite())
                                );
                            }
                            Err(e) => assert_eq!(e.argument(), "scale", "{e}"),
                        }
                    }
                }
                let mut flow = SyncFlow::random(graph.clone(), x.to_bits());
                for dt in HOSTILE {
                    let stepped =
                        probe.call(|| format!("SyncFlow::step({dt}, 10)"), || flow.step(dt, 10));
                    if stepped.is_ok() {
                        assert!(flow.rotations().iter().all(|q| finite(*q)), "dt {dt}");
                    }
                }
                let refused = probe.call(
                    || "SyncFlow::step(0.01, usize::MAX)".into(),
                    || flow.step(0.01, usize::MAX),
                );
                assert_eq!(refused.unwrap_err().argument(), "steps");
                let mut start = vec![DQuat::IDENTITY; graph.count()];
                for q in quaternions(x) {
                    start[1] = q;
                    named(probe.call(
                        || format!("SyncFlow::new(start[1] = {q:?})"),
                        || SyncFlow::new(graph.clone(), &start),
                    ));
                }
            }
            let qs = quaternions(x);
            probe.call(|| format!("errors_to_truth({qs:?})"), || errors_to_truth(&qs, &qs));
            for line in [
                format!("EDGE3 0 1 0 0 0 {x} 0 0"),
                format!("EDGE_SE3:QUAT 0 1 0 0 0 {x} 0 0 1"),
                format!("EDGE_SE3:QUAT 0 1 0 0 0 {x} {x} {x} {x}"),
                format!("VERTEX3 {x} 0 0 0 0 0 0\nEDGE3 0 1 0 0 0 0 0 0"),
                format!("EDGE3 {x} 1 0 0 0 0 0 0"),
                format!("EDGE_SE2 0 1 {x} 0 {x}"),
                format!("EDGE2 0 1 0 0 0 {x} 0 {x} 1 0 0"),
                format!("EDGE_SE2 0 1 0 0 0 1 0 0 1 0 {x}"),
                format!("VERTEX_SE2 {x} 0 0 0\nEDGE_SE2 0 1 0 0 0"),
                format!(
                    "EDGE_SE3:QUAT 0 1 0 0 0 0 0 0 1 {x} 0 0 0 0 0 1 0 0 0 0 1 0 0 0 1 0 0 1 0 {x}"
                ),
            ] {
                for others in [OtherLines::Skip, OtherLines::Refuse] {
                    named(probe.call(
                        || format!("read_g2o({line:?}, {others:?})"),
                        || read_g2o(&line, others),
                    ));
                }
            }
        }
    });
}
