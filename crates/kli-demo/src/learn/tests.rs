//! The tour's model against docs/MATH.md's values and against computations written apart from
//! it: the paper's example (Table 1, T = 11.66, T* = 11.6568), the Hopf images of p and r, the
//! gimbal lock at pitch 90°, q and −q one rotation, the uncoupled phases turning at their own
//! rates, the swarm reaching its leader, and the integrators' drift ordered as the text says.

use glam::{DQuat, DVec3};
use kli::{Integrator, from_wxyz, hopf};

use super::model::*;

fn close(a: f64, b: f64, tolerance: f64) -> bool {
    (a - b).abs() <= tolerance
}

#[test]
fn the_paper_example_gives_table_1_and_t_11_66() {
    let model = Model::new(Options::default()).unwrap();
    // MATH.md, "The paper's example": T* = 11.6568, the loop stops at T = 11.66 (δ = 0.01).
    assert!(close(model.predicted(), 11.6568, 5e-5), "{}", model.predicted());
    assert!(close(model.path.final_time(), 11.66, 1e-9), "{}", model.path.final_time());
    // Table 1's rows (w, x, y, z), as MATH.md prints them to 4 decimals.
    for (t, row) in [
        (0.2, [0.0943, 0.0943, 0.0943, 0.9866]),
        (0.55, [0.2270, 0.2270, 0.2270, 0.9195]),
        (1.8, [0.4364, 0.4364, 0.4364, 0.6548]),
    ] {
        let q = kli::to_wxyz(model.kli_at(t));
        for (c, want) in q.iter().zip(row) {
            assert!(close(*c, want, 5e-5), "t = {t}: {q:?}");
        }
    }
    // φ0 = π/3, so s(t) = 1 − φ(t)/φ0 and tan(φ/2) = tan(π/6) e^−t (MATH.md, "Closed form").
    let t: f64 = 1.0;
    let phi = 2.0 * ((std::f64::consts::PI / 6.0).tan() * (-t).exp()).atan();
    assert!(close(model.phi(t), phi, 1e-12));
    assert!(close(model.warp(t), 1.0 - phi / (std::f64::consts::PI / 3.0), 1e-12));
}

#[test]
fn the_hopf_map_sends_p_and_r_where_math_md_says_and_ignores_a_roll() {
    assert!((hopf(paper_p()) - DVec3::new(-1.0, 0.0, 0.0)).length() < 1e-15);
    assert!((hopf(paper_r()) - DVec3::new(0.0, 1.0, 0.0)).length() < 1e-15);
    let mut options = Options { axis: Axis::Diagonal, angle: 130.0, ..Options::default() };
    let still = Model::new(options.clone()).unwrap().nose();
    // h(q) is where the body x axis points: q x q̄.
    let q = turn(DVec3::ONE / 3f64.sqrt(), 130.0);
    assert!((still - q * DVec3::X).length() < 1e-12);
    for roll in [-180.0, -45.0, 90.0, 180.0] {
        options.roll = roll;
        let model = Model::new(options.clone()).unwrap();
        assert!((model.nose() - still).length() < 1e-12, "roll {roll}");
        // ... while the wing turns by the roll about the nose.
        let wing = model.rolled() * DVec3::Y;
        let cos = wing.dot(q * DVec3::Y);
        assert!(close(cos, f64::to_radians(roll).cos(), 1e-12), "roll {roll}: {cos}");
    }
}

#[test]
fn euler_angles_lock_at_pitch_90_degrees() {
    assert!(close(lock_angle(40.0), 50.0, 1e-9));
    assert!(close(lock_angle(-30.0), 60.0, 1e-9));
    assert!(close(lock_angle(90.0), 0.0, 1e-6));
    // At pitch 90°, yaw by a and bank by b give the same rotation as yaw a − b... one freedom lost:
    // R_z(a) R_y(90°) R_x(b) depends on a − b alone.
    let one = euler(50.0, 90.0, 20.0);
    let other = euler(70.0, 90.0, 40.0);
    assert!(one.dot(other).abs() > 1.0 - 1e-12);
}

#[test]
fn a_turn_is_cos_half_plus_axis_sin_half_and_q_and_minus_q_agree() {
    let q = turn(DVec3::Z, 90.0);
    let h = std::f64::consts::FRAC_1_SQRT_2;
    assert_eq!(
        kli::to_wxyz(q).map(|c| (c * 1e12).round() / 1e12),
        [h, 0.0, 0.0, h].map(|c| (c * 1e12).round() / 1e12)
    );
    // 90° about z takes x to y.
    assert!((q * DVec3::X - DVec3::Y).length() < 1e-15);
    // 360° is −1: the object back where it started, q on the far side of S³.
    let full = turn(DVec3::X, 360.0);
    assert!((full - from_wxyz([-1.0, 0.0, 0.0, 0.0])).length() < 1e-15);
    let v = DVec3::new(0.3, -0.2, 0.9);
    let any = turn(DVec3::ONE / 3f64.sqrt(), 77.0);
    assert!((any * v - (-any) * v).length() < 1e-15);
    // q v q̄ written out as quaternion products.
    let pure = DQuat::from_xyzw(v.x, v.y, v.z, 0.0);
    let turned = any * pure * any.conjugate();
    assert!((DVec3::new(turned.x, turned.y, turned.z) - any * v).length() < 1e-14);
}

#[test]
fn slerp_moves_evenly_and_nlerp_does_not() {
    let (p, r) = (paper_p(), paper_r());
    let basis = plane(p, r).unwrap();
    for s in [0.1, 0.25, 0.5, 0.9] {
        // φ0 = 60° (MATH.md): SLERP's point is s·60° along.
        assert!(close(in_plane(slerp(p, r, s), basis).to_degrees(), 60.0 * s, 1e-9));
        // NLERP's: atan2(s sin 60°, 1 − s + s cos 60°).
        let third = std::f64::consts::PI / 3.0;
        let want = (s * third.sin()).atan2(1.0 - s + s * third.cos());
        assert!(close(in_plane(nlerp(p, r, s), basis), want, 1e-12));
    }
}

#[test]
fn uncoupled_phases_turn_at_their_own_rates_and_coupled_ones_fall_into_step() {
    let free = Phases::new(0.0, END);
    let t = 7.0;
    let k = (t / SAMPLE).round() as usize;
    for i in 0..PHASES {
        let want = free.samples[0][i] + free.omega[i] * t;
        assert!(close(free.samples[k][i], want, 1e-9), "phase {i}");
    }
    assert!(free.omega.iter().all(|w| w.abs() <= GAMMA));
    // The critical coupling of a uniform spread on [−γ, γ] is 4γ/π ≈ 0.64: at K = 3 they lock.
    let locked = Phases::new(3.0, END);
    assert!(order(locked.at(END)).0 > 0.95, "{}", order(locked.at(END)).0);
    assert!(order(free.at(END)).0 < 0.5);
}

#[test]
fn the_swarm_stays_on_s3_and_reaches_its_pinned_leader() {
    let r = paper_r();
    let swarm = Swarm::new(4.0, r, END);
    assert!(swarm.spread(0.0) > 90.0);
    assert!(swarm.spread(END) < 2.0, "{}", swarm.spread(END));
    for q in swarm.at(END) {
        assert!(close(q.length(), 1.0, 1e-12));
    }
    // Uncoupled, nothing moves.
    let still = Swarm::new(0.0, r, END);
    for (a, b) in still.at(0.0).iter().zip(still.at(END)) {
        assert!((*a - *b).length() < 1e-13);
    }
}

#[test]
fn euler_drifts_off_s3_rk4_less_and_the_geodesic_step_not_at_all() {
    let (p, r) = (paper_p(), paper_r());
    let drift = |i| Drift::new(i, p, r, 0.5).largest();
    let (euler, rk4, geodesic) =
        (drift(Integrator::Euler), drift(Integrator::Rk4), drift(Integrator::Geodesic));
    // Euler's first step: |p + h(r − (p·r)p)|² = 1 + h² sin²φ0, φ0 = 60°.
    let first = (1.0 + 0.25 * 0.75f64).sqrt() - 1.0;
    assert!(euler >= first - 1e-15, "{euler} {first}");
    assert!(rk4 < euler / 20.0 && rk4 > 1e-9, "{rk4}");
    assert!(geodesic < 1e-15, "{geodesic}");
}

#[test]
fn the_options_are_checked_with_the_key_named() {
    let model = Model::new(Options { digits: 8.0, delta: 0.1, ..Options::default() }).unwrap();
    // T is the first multiple of δ past T*.
    let (big_t, star) = (model.path.final_time(), model.predicted());
    assert!(big_t >= star && big_t < star + 0.1 + 1e-9, "{big_t} {star}");
    assert_eq!(model.step_at(0.35), 3);
    assert_eq!(model.step_at(1e9), model.path.steps());
}

#[test]
fn the_clock_reaches_past_the_stop_for_every_epsilon() {
    // The paper's ε = 1e-5: the clock ends at 12, past T = 11.66.
    assert_eq!(Model::new(Options::default()).unwrap().end, END);
    // One more digit: T = 13.96, so the clock (and the plots' axes) go on to 15.
    for digits in 1..=10 {
        let model = Model::new(Options { digits: digits as f64, ..Options::default() }).unwrap();
        let (big_t, star) = (model.path.final_time(), model.predicted());
        assert!(
            model.end >= big_t.max(star) + 0.25,
            "digits {digits}: {} {big_t} {star}",
            model.end
        );
        assert!(model.end >= END && model.end == model.end.round());
        assert!((model.phases.samples.len() - 1) as f64 * SAMPLE >= model.end - 1e-9);
    }
    let six = Model::new(Options { digits: 6.0, ..Options::default() }).unwrap();
    assert!(close(six.path.final_time(), 13.96, 1e-9));
    assert_eq!(six.end, 15.0);
}

/// The world-frame angular velocity of the SLERP piece from `a` to `b` over `duration`, from the
/// keys alone: `b = exp(v) a` with `v = (θ/2) u`, so `q(t) = exp(v t/duration) a` and
/// `ω = 2 q′ q̄ = θ u / duration` (θ the piece's turning angle, u its axis, by glam's own
/// axis–angle).
fn piece_rate(a: DQuat, b: DQuat, duration: f64) -> DVec3 {
    let d = b * a.conjugate();
    let d = if d.w < 0.0 { -d } else { d };
    let (axis, angle) = d.to_axis_angle();
    axis * angle / duration
}

#[test]
fn at_smoothness_0_the_turning_rate_jumps_at_each_inner_key_by_the_pieces_difference() {
    let model = Model::new(Options { smoothness: 0.0, ..Options::default() }).unwrap();
    let keys: Vec<DQuat> = super::rates::KEYS.iter().map(|&k| from_wxyz(k)).collect();
    let rates = &model.rates;
    // Unit durations (the keys at 0, 1, 2, 3): the first piece turns 2 acos 0.8 = 73.7° about x.
    let pieces: Vec<DVec3> = keys.windows(2).map(|k| piece_rate(k[0], k[1], 1.0)).collect();
    assert!((pieces[0] - DVec3::X * 2.0 * 0.8f64.acos()).length() < 1e-12);
    for (i, jump) in rates.chain.jumps.iter().enumerate() {
        let want = (pieces[i + 1] - pieces[i]).length();
        assert!(close(*jump, want, 1e-6), "k{}: {jump} against {want}", i + 1);
    }
    // At k2 both pieces turn 2 acos 0.48 = 122.6° in a unit of time: |ω| is the same either side,
    // and yet ω jumps (its axis turns), by 2.53.
    assert!(close(pieces[1].length(), pieces[2].length(), 1e-12));
    assert!(rates.chain.jumps[1] > 2.5, "{}", rates.chain.jumps[1]);
    // Between the keys each piece turns at its constant rate.
    for (k, &t) in rates.times.iter().enumerate() {
        let piece = (t.floor() as usize).min(2);
        if (t - t.round()).abs() > 0.01 {
            assert!((rates.chain.omega[k] - pieces[piece]).length() < 1e-6, "t = {t}");
        }
    }
    // The plot steps at each inner key: the key's time twice, with the piece before and then the
    // piece after.
    for (i, &key) in [1.0, 2.0].iter().enumerate() {
        let at = rates.times.iter().position(|&t| t == key).unwrap();
        assert_eq!(rates.times[at + 1], key);
        assert!((rates.chain.omega[at] - pieces[i]).length() < 1e-6, "before k{}", i + 1);
        assert!((rates.chain.omega[at + 1] - pieces[i + 1]).length() < 1e-6, "after k{}", i + 1);
    }
    assert!(!rates.continuous());
    // Piecewise SLERP is the same curve.
    assert_eq!(rates.slerp.jumps.len(), 2);
    for (a, b) in rates.chain.jumps.iter().zip(&rates.slerp.jumps) {
        assert!(close(*a, *b, 1e-9));
    }
}

#[test]
fn at_smoothness_above_0_the_turning_rate_does_not_jump() {
    for smoothness in [0.05, 0.5, 1.0] {
        let model = Model::new(Options { smoothness, ..Options::default() }).unwrap();
        let rates = &model.rates;
        assert!(rates.continuous());
        // A continuous ω read ±1e-4 either side of a key differs by 2e-4 |ω̇| (|ω̇| < 10 here).
        for (i, jump) in rates.chain.jumps.iter().enumerate() {
            assert!(*jump < 2e-3, "smoothness {smoothness}, k{}: {jump}", i + 1);
        }
        // ... and ω̇ is bounded: no sample's difference is a jump over two sample intervals.
        assert!(rates.chain.acceleration < 12.0, "{}", rates.chain.acceleration);
        // Piecewise SLERP still jumps, whatever the chain's smoothness.
        assert!(rates.slerp.largest_jump().0 > 2.9, "{:?}", rates.slerp.largest_jump());
    }
}
