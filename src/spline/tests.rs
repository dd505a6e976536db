//! The curves through keyframes against MATH.md, "Many rotations", and against each other. The
//! angular quantities are measured here from samples of `at`, independently of the code under
//! test.

use glam::{DQuat, DVec3};

use super::*;
use crate::quaternion::{exp, from_wxyz};
use crate::swarm::Random;

/// `m` random keys, each within `max_angle` (radians of rotation) of the previous, at times
/// `times` (`None`: 0, 1, …).
fn random_keys(seed: u64, m: usize, max_angle: f64) -> Vec<DQuat> {
    let mut random = Random::new(seed);
    let mut keys = vec![random.unit_quaternion()];
    while keys.len() < m {
        let axis = random.gaussian3().normalize();
        let angle = max_angle * random.uniform();
        // A rotation by `angle` is a step of angle/2 on S³.
        let last = *keys.last().unwrap();
        keys.push(last * exp(axis * (0.5 * angle)));
    }
    keys
}

/// `∫|ω̇|² dt` over the curve, from `q` sampled `per_unit` times a unit of time: `ω` by central
/// differences of the samples, `ω̇` by differences of `ω`.
fn angular_acceleration_energy(curve: &dyn Curve, per_unit: usize) -> f64 {
    let (start, end) = (curve.start_time(), curve.end_time());
    let n = ((end - start) * per_unit as f64).round() as usize;
    let dt = (end - start) / n as f64;
    let mut q: Vec<DQuat> = (0..=n).map(|k| curve.at(start + k as f64 * dt)).collect();
    for k in 1..q.len() {
        if q[k].dot(q[k - 1]) < 0.0 {
            q[k] = -q[k];
        }
    }
    let omega: Vec<DVec3> = (1..n)
        .map(|k| {
            let w = (q[k + 1] - q[k - 1]) * (1.0 / dt) * q[k].conjugate();
            DVec3::new(w.x, w.y, w.z)
        })
        .collect();
    (1..omega.len()).map(|k| ((omega[k] - omega[k - 1]) / dt).length_squared() * dt).sum()
}

fn keys(quaternions: &[DQuat], times: Option<&[f64]>) -> Keys {
    Keys::new(quaternions, times).unwrap()
}

fn chain(keys: Keys, smoothness: f64) -> KliSpline {
    KliSpline::new(keys, &ChainOptions { smoothness, ..Default::default() }).unwrap()
}

#[test]
fn smoothness_0_is_piecewise_slerp_at_every_sample() {
    let q = random_keys(1, 6, 2.0);
    let times = [0.0, 0.7, 1.9, 2.4, 4.0, 5.1];
    let spline = chain(keys(&q, Some(&times)), 0.0);
    let slerp = PiecewiseSlerp::new(keys(&q, Some(&times)));
    let samples = spline.samples();
    for (&x, &t) in samples.quaternions().iter().zip(samples.times()) {
        assert!((x - slerp.at(t)).length() < 1e-12, "t = {t}");
    }
    // …and between the samples too, kinks at the keys included.
    for k in 0..=510 {
        let t = k as f64 * 0.01;
        assert!((spline.at(t) - slerp.at(t)).length() < 1e-12, "t = {t}");
    }
    // Piecewise SLERP is the equilibrium: Newton only polishes its rounding.
    assert!(
        spline.iterations() <= 2 && spline.residual() <= 1e-10,
        "{} {:e}",
        spline.iterations(),
        spline.residual()
    );
}

#[test]
fn the_keys_are_hit() {
    for smoothness in [0.0, 0.3, 1.0] {
        let q = random_keys(2, 7, 2.0);
        let spline = chain(keys(&q, None), smoothness);
        for (i, &k) in spline.keys().quaternions().iter().enumerate() {
            assert!((spline.at(i as f64) - k).length() < 1e-12, "key {i}, smoothness {smoothness}");
        }
    }
}

#[test]
fn two_keys_stay_on_their_great_circle_at_any_smoothness() {
    let (p, r) = (from_wxyz([0.0, 0.0, 0.0, 1.0]), from_wxyz([0.5; 4]));
    for smoothness in [0.0, 0.5, 1.0] {
        let spline = chain(keys(&[p, r], Some(&[0.0, 2.0])), smoothness);
        // The circle's plane is spanned by p and the unit tangent from p towards r.
        let tangent = (r - p * p.dot(r)).normalize();
        for k in 0..=40 {
            let q = spline.at(k as f64 * 0.05);
            let off_plane = q - p * q.dot(p) - tangent * q.dot(tangent);
            assert!(off_plane.length() < 1e-12, "smoothness {smoothness}: {off_plane:?}");
        }
    }
}

#[test]
fn the_solve_reaches_its_residual_in_a_few_newton_steps() {
    for seed in 0..10 {
        let q = random_keys(10 + seed, 10, 2.0);
        let spline = chain(keys(&q, None), 1.0);
        assert!(spline.residual() <= 1e-10, "seed {seed}: residual {:e}", spline.residual());
        assert!(spline.iterations() <= 12, "seed {seed}: {} iterations", spline.iterations());
    }
}

#[test]
fn the_smooth_end_bends_less_than_squad() {
    // MATH.md: about 0.78 of Squad's ∫|ω̇|² on the same keys (6 random keys, consecutive ones up
    // to 120° apart, even times), with ω continuous so the measure does not depend on density.
    let mut ratios = Vec::new();
    for seed in 0..20 {
        let q = random_keys(100 + seed, 6, 120f64.to_radians());
        let smooth = angular_acceleration_energy(&chain(keys(&q, None), 1.0), 256);
        let squad = angular_acceleration_energy(&Squad::new(keys(&q, None)), 256);
        ratios.push(smooth / squad);
    }
    let mean = ratios.iter().sum::<f64>() / ratios.len() as f64;
    assert!(ratios.iter().all(|&r| r < 1.0), "{ratios:?}");
    assert!(mean <= 0.85, "mean ratio {mean}: {ratios:?}");
}

#[test]
fn squad_with_uneven_times_has_continuous_angular_velocity() {
    let q = random_keys(5, 5, 1.5);
    let times = [0.0, 0.4, 2.0, 2.3, 4.0];
    let squad = Squad::new(keys(&q, Some(&times)));
    for &t in &times[1..4] {
        let (before, after) = (squad.angular_velocity(t - 1e-4), squad.angular_velocity(t + 1e-4));
        assert!(
            (before - after).length() < 1e-2 * (1.0 + before.length()),
            "t = {t}: {before:?} vs {after:?}"
        );
    }
    // Piecewise SLERP jumps there: the measure above would see it.
    let slerp = PiecewiseSlerp::new(keys(&q, Some(&times)));
    let t = times[2];
    assert!((slerp.angular_velocity(t - 1e-4) - slerp.angular_velocity(t + 1e-4)).length() > 0.05);
}

#[test]
fn hard_keys_work_repeated_opposite_and_half_turns() {
    let a = from_wxyz([1.0, 0.0, 0.0, 0.0]);
    let b = from_wxyz([0.0, 1.0, 0.0, 0.0]); // a half turn from a: a·b = 0
    let c = from_wxyz([0.6, 0.0, 0.8, 0.0]);
    let q = [a, a, b, -c, c * 3.0, a];
    for smoothness in [0.0, 1.0] {
        let spline = chain(keys(&q, None), smoothness);
        let squad = Squad::new(keys(&q, None));
        for curve in [&spline as &dyn Curve, &squad] {
            for k in 0..=250 {
                let t = k as f64 * 0.02;
                let x = curve.at(t);
                assert!(x.is_finite() && (x.length() - 1.0).abs() < 1e-12, "t = {t}: {x:?}");
            }
            // The keys, signs made consistent, are hit.
            for (i, &k) in spline.keys().quaternions().iter().enumerate() {
                assert!((curve.at(i as f64) - k).length() < 1e-12, "key {i}");
            }
        }
    }
}

#[test]
fn bad_keys_and_options_name_themselves() {
    let q = random_keys(7, 3, 1.0);
    let argument = |e: crate::KliError| e.argument().to_owned();
    assert_eq!(argument(Keys::new(&q[..1], None).unwrap_err()), "keys");
    let mut bad = q.clone();
    bad[2] = DQuat::from_xyzw(f64::NAN, 0.0, 0.0, 1.0);
    assert_eq!(argument(Keys::new(&bad, None).unwrap_err()), "keys[2]");
    bad[2] = DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0);
    assert_eq!(argument(Keys::new(&bad, None).unwrap_err()), "keys[2]");
    assert_eq!(argument(Keys::new(&q, Some(&[0.0, 1.0])).unwrap_err()), "times");
    assert_eq!(argument(Keys::new(&q, Some(&[0.0, 1.0, 1.0])).unwrap_err()), "times[2]");
    assert_eq!(argument(Keys::new(&q, Some(&[0.0, f64::NAN, 2.0])).unwrap_err()), "times[1]");
    let options =
        |smoothness, samples_per_segment| ChainOptions { smoothness, samples_per_segment };
    for (o, name) in [
        (options(1.5, 32), "smoothness"),
        (options(-0.1, 32), "smoothness"),
        (options(0.5, 1), "samples_per_segment"),
    ] {
        assert_eq!(argument(KliSpline::new(keys(&q, None), &o).unwrap_err()), name);
    }
}

#[test]
fn sequential_kli_reaches_each_key_within_the_tolerance_and_is_kli_on_each_segment() {
    let q = random_keys(21, 4, 2.0);
    let times = [0.0, 1.0, 3.0, 3.5];
    let options = crate::KliOptions::default();
    let curve = SequentialKli::new(keys(&q, Some(&times)), &options).unwrap();
    let used = curve.keys().quaternions();
    for (i, path) in curve.paths().iter().enumerate() {
        // The segment ends within ε of the next key (Algorithm 1), at T_i = its steps · δ.
        let end = curve.at(times[i + 1] - 1e-12);
        assert!((end - used[i + 1]).length() < 1e-5 + 1e-9, "segment {i}");
        // Half way through the segment, KLI time T_i/2: the closed form from key i to key i+1, up
        // to RK4's error and the normalised lerp between samples δ apart ((δ|q'|)²/8 ≤ 1.3e-5
        // at the fastest, far less here).
        let middle = curve.at(0.5 * (times[i] + times[i + 1]));
        let exact = crate::kli_exact(used[i], used[i + 1], 0.5 * path.final_time(), false).unwrap();
        assert!((middle - exact).length() < 1e-6, "segment {i}: {:e}", (middle - exact).length());
    }
    // KLI crawls into each key and leaves the next at full speed: ω jumps there.
    let (before, after) = (curve.angular_velocity(0.999), curve.angular_velocity(1.001));
    assert!(after.length() > 10.0 * before.length(), "{before:?} {after:?}");
}

/// The largest step of `ω̇` between evaluations `h` apart, relative to the largest `|ω̇|`: `ω`
/// by central differences of `at` (step 1e-5), `ω̇` by differences of `ω`.
fn angular_acceleration_steps(curve: &dyn Curve, h: f64) -> f64 {
    let (start, end) = (curve.start_time(), curve.end_time());
    let omega = |t: f64| {
        let d = 1e-5;
        let (a, b, q) = (curve.at(t - d), curve.at(t + d), curve.at(t));
        let b = if a.dot(b) < 0.0 { -b } else { b };
        let w = (b - a) * (1.0 / (2.0 * d)) * q.conjugate() * 2.0;
        DVec3::new(w.x, w.y, w.z)
    };
    let n = ((end - start - 4e-5) / h) as usize;
    let w: Vec<DVec3> = (0..=n).map(|k| omega(start + 2e-5 + k as f64 * h)).collect();
    let dw: Vec<DVec3> = w.windows(2).map(|p| (p[1] - p[0]) / h).collect();
    let largest = dw.iter().map(|v| v.length()).fold(0.0, f64::max);
    let step = dw.windows(2).map(|p| (p[1] - p[0]).length()).fold(0.0, f64::max);
    step / largest
}

#[test]
fn the_chain_is_c2_its_angular_acceleration_does_not_step() {
    // Issue 16: at h = 1e-4 the largest step of ω̇ is at most 1e-2 of its largest value (Squad
    // through the samples, the evaluation before: 0.16; Squad through the keys steps at them).
    let q = random_keys(31, 6, 120f64.to_radians());
    for times in [[0.0, 1.0, 2.0, 3.0, 4.0, 5.0], [0.0, 0.4, 1.9, 2.2, 4.0, 4.5]] {
        let spline = chain(keys(&q, Some(&times)), 1.0);
        assert!(spline.is_c2());
        let steps = angular_acceleration_steps(&spline, 1e-4);
        assert!(steps <= 1e-2, "{times:?}: {steps}");
        let squad = angular_acceleration_steps(&Squad::new(keys(&q, Some(&times))), 1e-4);
        assert!(squad > 0.1, "{times:?}: Squad {squad}");
    }
}

#[test]
fn the_chains_angular_velocity_is_exact() {
    let q = random_keys(32, 5, 2.0);
    let times = [0.0, 0.5, 2.0, 2.1, 3.0];
    let spline = chain(keys(&q, Some(&times)), 0.7);
    for k in 1..300 {
        let t = k as f64 * 0.01;
        let d = 1e-6;
        let (a, b) = (spline.at(t - d), spline.at(t + d));
        let w = (b - a) * (1.0 / (2.0 * d)) * spline.at(t).conjugate() * 2.0;
        let by_difference = DVec3::new(w.x, w.y, w.z);
        let exact = spline.angular_velocity(t);
        assert!((exact - by_difference).length() < 1e-7 * (1.0 + exact.length()), "t = {t}");
    }
}

#[test]
fn far_apart_keys_at_uneven_times_give_a_unit_curve_through_the_keys() {
    // Keys up to a half turn apart, 2 samples a segment, spans from 1e-6 to 10: the coarsest
    // chains the options allow. Where the C² cubic has no solution the chain is C¹ (Squad
    // through its samples), never an error or a NaN.
    let mut random = Random::new(33);
    let mut c1 = 0;
    for case in 0..200 {
        let q = random_keys(1000 + case, 5, std::f64::consts::PI);
        let mut times = vec![0.0];
        for _ in 0..4 {
            let span = 10f64.powf(-6.0 + 7.0 * random.uniform());
            times.push(times.last().unwrap() + span);
        }
        let options = ChainOptions { smoothness: random.uniform(), samples_per_segment: 2 };
        let spline = KliSpline::new(keys(&q, Some(&times)), &options).unwrap();
        c1 += usize::from(!spline.is_c2() && options.smoothness > 0.0);
        for (i, &k) in spline.keys().quaternions().iter().enumerate() {
            // The rotation (a chain this coarse can have samples more than a half turn apart,
            // and the samples' signs are made consistent along it).
            assert!((spline.at(times[i]).dot(k).abs() - 1.0).abs() < 1e-12, "case {case}, key {i}");
        }
        for k in 0..=100 {
            let t = times[4] * k as f64 / 100.0;
            let x = spline.at(t);
            assert!(x.is_finite() && (x.length() - 1.0).abs() < 1e-12, "case {case}");
            assert!(spline.angular_velocity(t).is_finite(), "case {case}, t = {t}");
        }
    }
    // Measured: 11 of the 200 (all with spans 10⁵ times apart beside each other).
    assert!((1..=20).contains(&c1), "{c1} of 200 are C¹");
}

/// MATH.md's chain energy for samples `x` at `times`, written from its formula:
/// `(α/2) Σ |x_{j+1} − x_j|²/h_j` and `(β/2) Σ w_j |D²x_j|²` with
/// `D²x_j = [(x_{j+1} − x_j)/h_j − (x_j − x_{j−1})/h_{j−1}] / w_j`, `w_j = (h_{j−1} + h_j)/2`, as
/// the two terms apart.
pub(super) fn chain_energy(x: &[DQuat], times: &[f64], alpha: f64, beta: f64) -> (f64, f64) {
    let n = x.len();
    let h = |j: usize| times[j + 1] - times[j];
    let neighbours: f64 =
        (0..n - 1).map(|j| (x[j + 1] - x[j]).length_squared() / h(j)).sum::<f64>() * alpha / 2.0;
    let bending: f64 = (1..n - 1)
        .map(|j| {
            let w = (h(j - 1) + h(j)) / 2.0;
            let second = ((x[j + 1] - x[j]) / h(j) - (x[j] - x[j - 1]) / h(j - 1)) / w;
            w * second.length_squared()
        })
        .sum::<f64>()
        * beta
        / 2.0;
    (neighbours, bending)
}

/// The chain's samples are an equilibrium of MATH.md's energy on uneven spacing: moving any free
/// sample along S³ changes `E` only to second order. By central differences of the energy
/// written above (not the code's matrix), each derivative is below 1e-7 of the largest that the
/// two terms contribute apart (they balance; an equilibrium of another energy leaves percents).
#[test]
fn the_chain_is_stationary_for_the_energy_on_uneven_times() {
    let quaternions = random_keys(7, 4, 2.0);
    let times = [0.0, 1.0, 3.5, 4.0];
    let smoothness = 0.7;
    let per = 8;
    let options = ChainOptions { smoothness, samples_per_segment: per };
    let curve = KliSpline::new(keys(&quaternions, Some(&times)), &options).unwrap();
    let (x, t) = (curve.samples().quaternions().to_vec(), curve.samples().times().to_vec());
    assert_eq!(x.len(), 3 * per + 1);
    let (alpha, beta) = (1.0 - smoothness, smoothness);
    let s = 1e-5;
    let (mut worst, mut scale): (f64, f64) = (0.0, 0.0);
    for j in (0..x.len()).filter(|j| j % per != 0) {
        for e in [
            DQuat::from_xyzw(1.0, 0.0, 0.0, 0.0),
            DQuat::from_xyzw(0.0, 1.0, 0.0, 0.0),
            DQuat::from_xyzw(0.0, 0.0, 1.0, 0.0),
        ] {
            let moved = |s: f64| {
                let mut y = x.clone();
                y[j] = (x[j] + x[j] * e * s).normalize();
                chain_energy(&y, &t, alpha, beta)
            };
            let ((a_plus, b_plus), (a_minus, b_minus)) = (moved(s), moved(-s));
            let (da, db) = ((a_plus - a_minus) / (2.0 * s), (b_plus - b_minus) / (2.0 * s));
            worst = worst.max((da + db).abs());
            scale = scale.max(da.abs() + db.abs());
        }
    }
    assert!(scale > 0.1, "the terms' derivatives: {scale}");
    assert!(worst < 1e-7 * scale, "not stationary: a derivative {worst:e} against {scale:e}");
}

/// What the chain reports of itself: its span (the first and last key times), the relative
/// residual its Newton solve reached (`max_j |g_j| / max_j |(Lx)_j|`, measured here afresh from
/// MATH.md's energy: `(Lx)_j = ∂E/∂x_j` in ℝ⁴ by central differences, exact to rounding for a
/// quadratic, and `g_j` its part tangent to S³ at `x_j`), and its iterations (from piecewise SLERP,
/// a residual of order 0.1, quadratic convergence needs more than one step to reach 1e-12).
/// Equal keys make a constant chain, for which `Lx = 0`: no step, a residual of exactly 0.
#[test]
fn the_chain_reports_its_span_residual_and_iterations() {
    let quaternions = random_keys(3, 4, 1.5);
    let times = [2.0, 3.5, 4.0, 7.0];
    let smoothness = 0.6;
    let options = ChainOptions { smoothness, samples_per_segment: 6 };
    let curve = KliSpline::new(keys(&quaternions, Some(&times)), &options).unwrap();
    assert_eq!((curve.start_time(), curve.end_time()), (2.0, 7.0));
    let (x, t) = (curve.samples().quaternions().to_vec(), curve.samples().times().to_vec());
    let energy = |y: &[DQuat]| {
        let (a, b) = chain_energy(y, &t, 1.0 - smoothness, smoothness);
        a + b
    };
    let (mut largest_g, mut largest_lx): (f64, f64) = (0.0, 0.0);
    let s = 1e-3;
    for j in 0..x.len() {
        let mut lx = [0.0; 4];
        for (c, slot) in lx.iter_mut().enumerate() {
            let moved = |s: f64| {
                let mut y = x.clone();
                let mut v = y[j].to_array();
                v[c] += s;
                y[j] = DQuat::from_array(v);
                energy(&y)
            };
            *slot = (moved(s) - moved(-s)) / (2.0 * s);
        }
        let lx = DQuat::from_array(lx);
        largest_lx = largest_lx.max(lx.length());
        if j % 6 != 0 {
            let g = x[j].conjugate() * lx;
            largest_g = largest_g.max(DVec3::new(g.x, g.y, g.z).length());
        }
    }
    assert!(largest_g < 1e-9 * largest_lx, "{largest_g:e} against {largest_lx:e}");
    assert!(
        curve.residual() > 0.0 && curve.residual() <= chain::TOLERANCE,
        "{:e}",
        curve.residual()
    );
    assert!((2..=12).contains(&curve.iterations()), "{}", curve.iterations());

    let a = from_wxyz([0.6, 0.0, 0.8, 0.0]);
    for (times, per) in [([0.0, 1.0, 2.0], 32), ([0.0, 0.3, 1.7], 7), ([1e3, 1e3 + 0.1, 1e4], 255)]
    {
        for smoothness in [0.5, 1.0] {
            let options = ChainOptions { smoothness, samples_per_segment: per };
            let constant = KliSpline::new(keys(&[a, a, a], Some(&times)), &options).unwrap();
            assert_eq!((constant.iterations(), constant.residual()), (0, 0.0), "{times:?}");
            let x = constant.samples().quaternions();
            assert!(x.iter().all(|&x| (x - a).length() < 1e-15), "{times:?}");
        }
    }
}

/// A rotation at the constant world-frame rate `ω` from `q0` at `start`, `q(t) = exp(ω(t −
/// start)/2) q0`, whose `at` answers with the sign flipped on alternate stretches of 1.3e-6 of
/// its span (both signs are the same rotation), to test `Curve`'s provided methods on their own.
struct Flipping {
    q0: DQuat,
    omega: DVec3,
    start: f64,
    end: f64,
}

impl Flipping {
    fn flipped(&self, t: f64) -> bool {
        ((t - self.start) / (1.3e-6 * (self.end - self.start))).floor() as i64 % 2 != 0
    }
}

impl Curve for Flipping {
    fn at(&self, t: f64) -> DQuat {
        let t = t.clamp(self.start, self.end);
        let q = exp(self.omega * (0.5 * (t - self.start))) * self.q0;
        if self.flipped(t) { -q } else { q }
    }
    fn start_time(&self) -> f64 {
        self.start
    }
    fn end_time(&self) -> f64 {
        self.end
    }
}

/// `Curve`'s provided `angular_velocity` is `ω` wherever its two samples differ in sign, on a
/// long span far from 0 (its step, 1e-6 of the span, is then 1e-2: central differences right
/// to 1e-9 of `ω`, one-sided ones at the ends to 1e-4), and `sample_into` is `at` at each time.
#[test]
fn curves_provided_methods_on_a_constant_rate() {
    let slow = DVec3::new(0.3, -0.2, 0.6) * 1e-3;
    for (omega, start, end) in [(slow, 5e3, 1.5e4), (slow * 500.0, 1e6, 1e6 + 10.0)] {
        let curve = Flipping { q0: from_wxyz([0.6, 0.0, 0.8, 0.0]), omega, start, end };
        let h = 1e-6 * (end - start);
        let mut straddled = 0;
        for k in 1..40 {
            let t = start + (k as f64 + 0.013) * (end - start) / 40.0;
            let w = curve.angular_velocity(t);
            assert!((w - omega).length() < 1e-9 * omega.length(), "t = {t}: {w:?}");
            straddled += usize::from(curve.flipped(t - h) != curve.flipped(t + h));
        }
        assert!(straddled > 5, "{straddled}");
        for t in [start, end, start - 1.0, end + 1.0] {
            let w = curve.angular_velocity(t);
            assert!((w - omega).length() < 1e-4 * omega.length(), "t = {t}: {w:?}");
        }
    }
    let curve =
        Flipping { q0: from_wxyz([0.6, 0.0, 0.8, 0.0]), omega: slow, start: 5e3, end: 1.5e4 };
    let times = [5e3, 7e3 + 0.01, 1.2e4, 1.5e4];
    let mut out = [f64::NAN; 16];
    curve.sample_into(&times, &mut out);
    for (t, slot) in times.iter().zip(out.chunks_exact(4)) {
        assert_eq!(slot, crate::quaternion::to_wxyz(curve.at(*t)));
    }
}

/// Keys as MATH.md's curves take them: each sign chosen the shorter way from the previous key
/// (`k_{i+1}·k_i ≥ 0`; a key exactly a half turn on, `k·k_prev = 0`, is kept as given), times
/// strictly increasing (the first out of order named), and no span shorter than 1e-9 of the
/// whole range nor than 1e-9 (exactly that short is allowed; a range far from 0 is its length).
#[test]
fn keys_take_the_shorter_way_and_refuse_short_spans() {
    let a = from_wxyz([0.6, 0.0, 0.8, 0.0]);
    let b = from_wxyz([0.8, 0.6, 0.0, 0.0]); // a·b = 0.48
    let c = from_wxyz([0.0, 0.0, 0.0, 1.0]); // b·c = 0: a half turn from b
    let keys = Keys::new(&[a, -b, c, -c], None).unwrap();
    assert_eq!(keys.quaternions(), &[a, b, c, c]);
    assert!(!keys.is_empty());
    assert_eq!((keys.len(), keys.times()), (4, &[0.0, 1.0, 2.0, 3.0][..]));
    let refused = |times: &[f64]| Keys::new(&[a, b, c], Some(times)).unwrap_err().to_string();
    let m = refused(&[0.0, 2.0, 1.0]);
    assert!(m.contains("times[2]") && m.contains("strictly increasing"), "{m}");
    let m = refused(&[5.0, 5.0 + 1e-12, 6.0]);
    assert!(m.contains("times[1]") && m.contains("must be at least"), "{m}");
    let m = refused(&[0.0, 1e3 - 1e-7, 1e3]);
    assert!(m.contains("times[2]") && m.contains("must be at least"), "{m}");
    for times in [[0.0, 1e-9, 1.0], [1e3, 1e3 + 1e-6, 1e3 + 1.0], [-7.0, -6.0, -6.0 + 1e-9]] {
        assert!(Keys::new(&[a, b, c], Some(&times)).is_ok(), "{times:?}");
    }
}

/// Every curve's span is its first and last key times, away from 0; and Algorithm 1's
/// sequential curve keeps one path a segment.
#[test]
fn every_curve_spans_its_key_times() {
    let q = random_keys(5, 3, 1.0);
    let k = keys(&q, Some(&[2.0, 3.5, 7.0]));
    let sequential =
        SequentialKli::new(k.clone(), &crate::algorithm::KliOptions::default()).unwrap();
    assert_eq!(sequential.paths().len(), 2);
    // At its end, and beyond, the last path's last sample (within ε of the last key).
    let last = *sequential.paths()[1].quaternions().last().unwrap();
    for t in [7.0, 8.0] {
        assert!((sequential.at(t) - last.normalize()).length() < 1e-15);
    }
    let curves: [&dyn Curve; 4] = [
        &sequential,
        &PiecewiseSlerp::new(k.clone()),
        &Squad::new(k.clone()),
        &chain(k.clone(), 0.5),
    ];
    for curve in curves {
        assert_eq!((curve.start_time(), curve.end_time()), (2.0, 7.0));
    }
}
/// Nearly equal keys (1e-17 to 1e-6 rad apart, a hold up to float noise) at 2, 32 and 256
/// samples a segment: `|Lx|` is of second order in the spread, so the residual is rounding's
/// long before the tolerance; the solve stops once the gradient is within rounding of `L`'s size
/// (it ran its 100 steps, 3 s at 256 samples a segment, reporting residuals near 1), and every
/// sample stays near the keys (a bending chain may pass a little beyond them; at 256 samples a
/// segment the bending term's condition, ~256⁴, leaves 1e-10 of rounding).
#[test]
fn nearly_equal_keys_stop_at_roundings_level() {
    let a = from_wxyz([0.6, 0.0, 0.8, 0.0]);
    for d in [1e-17, 1e-15, 1e-13, 1e-11, 1e-9, 1e-6] {
        let b = (a * exp(DVec3::new(d, -d, 0.5 * d))).normalize();
        let c = (b * exp(DVec3::new(0.0, d, d))).normalize();
        for per in [2, 32, 256] {
            let options = ChainOptions { smoothness: 1.0, samples_per_segment: per };
            let chain = KliSpline::new(keys(&[a, b, c], None), &options).unwrap();
            assert!(chain.iterations() <= 20, "{d:e}, {per}: {}", chain.iterations());
            assert!(chain.residual() < 1e-3, "{d:e}, {per}: {:e}", chain.residual());
            for &x in chain.samples().quaternions() {
                assert!((x - a).length() < 10.0 * d + 1e-9, "{d:e}, {per}: {x:?}");
            }
        }
    }
}

/// Keys a few milliradians to a tenth of a radian apart, on even and uneven times: `E` is then
/// small beside `L`'s entries (`∝ 1/h³`). Summed through those entries, `E` rounded to more than
/// a Newton step changes it, Armijo halved every step to nothing, and the solve ran its 100 steps
/// to residuals up to 9e-4 (8 samples a segment, smoothness 0.1, keys 0.03 rad apart); summed
/// from differences of neighbours it converges in a few steps.
#[test]
fn close_keys_converge_in_a_few_steps() {
    let turns =
        [DVec3::new(0.3, 0.8, -0.2), DVec3::new(-0.7, 0.1, 0.5), DVec3::new(0.1, -0.4, 0.9)];
    for spread in [1e-3, 3e-3, 1e-2, 3e-2, 0.1] {
        let second = exp(turns[0] * spread);
        let quaternions =
            [DQuat::IDENTITY, second, second * exp(turns[1] * spread), exp(turns[2] * spread)];
        for times in [None, Some(&[0.0, 1.0, 8.0, 9.0][..])] {
            for per in [2, 4, 8, 16, 32] {
                for smoothness in [0.1, 0.5, 1.0] {
                    let options = ChainOptions { smoothness, samples_per_segment: per };
                    let chain = KliSpline::new(keys(&quaternions, times), &options).unwrap();
                    let case =
                        format!("spread {spread}, {times:?}, {per}, smoothness {smoothness}");
                    assert!(chain.iterations() <= 8, "{case}: {} steps", chain.iterations());
                    assert!(chain.residual() < 1e-8, "{case}: {:e}", chain.residual());
                }
            }
        }
    }
}
