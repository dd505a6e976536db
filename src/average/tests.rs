//! The means against MATH.md's reference values ("Averaging rotations", computed independently
//! in f64), the flow against the eigensolver, and the refusals.

use glam::DQuat;

use super::*;
use crate::quaternion::{from_wxyz, to_wxyz};
use crate::swarm::Random;

/// `p = k` and `r = ½(1 + i + j + k)`, the paper's example.
fn p() -> DQuat {
    from_wxyz([0.0, 0.0, 0.0, 1.0])
}
fn r() -> DQuat {
    from_wxyz([0.5; 4])
}

/// Equal as rotations (either sign), to `tolerance` a component.
fn same(got: DQuat, wxyz: [f64; 4], tolerance: f64) {
    let want = from_wxyz(wxyz);
    let error = (got - want).length().min((got + want).length());
    assert!(error < tolerance, "{:?} against {wxyz:?} (off by {error:e})", to_wxyz(got));
}

fn mean(quaternions: &[DQuat], weights: Option<&[f64]>, method: Method) -> DQuat {
    average(quaternions, weights, method).unwrap().rotation
}

#[test]
fn two_rotations_weighted_equally_meet_halfway() {
    let want = [0.288675134594813, 0.288675134594813, 0.288675134594813, 0.866025403784439];
    for method in [Method::Chordal, Method::Geodesic, Method::Quaternion] {
        same(mean(&[p(), r()], None, method), want, 1e-14);
    }
    // Two data: any point of the arc between them is a median; it stays on that arc.
    let median = mean(&[p(), r()], None, Method::Median);
    assert!((angle(median, p()) + angle(median, r()) - angle(p(), r())).abs() < 1e-12);
}

#[test]
fn two_rotations_weighted_three_to_one() {
    let weights = [3.0, 1.0];
    // The chordal mean, as SciPy's Rotation.mean gives it: slerp(p, r, 0.1592217112572425).
    let chordal = [0.095819985282240, 0.095819985282240, 0.095819985282240, 0.986131629784551];
    same(mean(&[p(), r()], Some(&weights), Method::Chordal), chordal, 1e-14);
    // The closed form for two data: the top eigenvector of a ppᵀ + b rrᵀ is
    // slerp(p, r, θ/φ₀), θ = ½ atan2(b sin 2φ₀, a + b cos 2φ₀).
    let phi = p().dot(r()).acos();
    let theta = 0.5 * (2.0 * phi).sin().atan2(3.0 + (2.0 * phi).cos());
    same(
        mean(&[p(), r()], Some(&weights), Method::Chordal),
        to_wxyz(p().slerp(r(), theta / phi)),
        1e-14,
    );
    // The quaternion mean (3p + r)/√13, and Karcher's: a quarter of the arc, exactly.
    let quaternion = [0.138675049056307, 0.138675049056307, 0.138675049056307, 0.970725343394151];
    same(mean(&[p(), r()], Some(&weights), Method::Quaternion), quaternion, 1e-14);
    let karcher = [0.149429245361342, 0.149429245361342, 0.149429245361342, 0.965925826289068];
    same(mean(&[p(), r()], Some(&weights), Method::Geodesic), karcher, 1e-14);
    // A datum's sign changes none of these (the quaternion mean aligns the signs first)...
    for method in [Method::Chordal, Method::Geodesic, Method::Quaternion] {
        let flipped = mean(&[p(), -r()], Some(&weights), method);
        same(flipped, to_wxyz(mean(&[p(), r()], Some(&weights), method)), 1e-14);
    }
    // ...but left unaligned, the quaternion mean is (3p − r)/|3p − r|: another rotation.
    let unaligned = quaternion_mean(&[p(), -r()], Some(&weights), false).unwrap().rotation;
    same(unaligned, to_wxyz((p() * 3.0 - r()).normalize()), 1e-15);
    assert!(angle(unaligned, from_wxyz(quaternion)) > 0.5);
}

#[test]
fn a_tie_is_refused_never_picked() {
    // 1 and i: M has the eigenvalues 1, 1, 0, 0.
    let error = average([DQuat::IDENTITY, from_wxyz([0.0, 1.0, 0.0, 0.0])], None, Method::Chordal)
        .unwrap_err();
    assert_eq!(error.kind().code(), "not-unique");
    assert_eq!(error.argument(), "quaternions");
    assert!(error.to_string().starts_with("quaternions have no unique mean"), "{error}");
}

/// Four identities and the half turn about z, `k`.
fn four_identities_and_a_half_turn_about_z() -> Vec<DQuat> {
    [DQuat::IDENTITY; 4].into_iter().chain([from_wxyz([0.0, 0.0, 0.0, 1.0])]).collect()
}

#[test]
fn four_identities_and_a_half_turn() {
    let data = four_identities_and_a_half_turn_about_z();
    // M = diag(4, 0, 0, 1): the identity exactly.
    assert_eq!(mean(&data, None, Method::Chordal), DQuat::IDENTITY);
    // Karcher's is pulled 36° (180°/5) towards the half turn about z.
    let eighteen = 18f64.to_radians();
    same(mean(&data, None, Method::Geodesic), [eighteen.cos(), 0.0, 0.0, eighteen.sin()], 1e-13);
    // The median stays at the identity exactly (Vardi–Zhang: 1 ≤ 4).
    let median = average(&data, None, Method::Median).unwrap();
    assert_eq!(median.rotation, DQuat::IDENTITY);
    let weights = median.weights.unwrap();
    assert!(weights[4] < 1e-11 && (weights.iter().sum::<f64>() - 1.0).abs() < 1e-15, "{weights:?}");
}

/// Noisy measurements of `truth` (Gaussian, `spread` radians), a share of them replaced by
/// uniform random rotations, each with a random sign.
fn measurements(
    random: &mut Random,
    truth: DQuat,
    n: usize,
    spread: f64,
    outliers: f64,
) -> Vec<DQuat> {
    (0..n)
        .map(|_| {
            let q = if random.uniform() < outliers {
                random.unit_quaternion()
            } else {
                random.near(truth, spread)
            };
            if random.uniform() < 0.5 { -q } else { q }
        })
        .collect()
}

#[test]
fn the_flow_settles_on_the_eigensolvers_mean() {
    let mut random = Random::new(11);
    for _ in 0..20 {
        let truth = random.unit_quaternion();
        let data = measurements(&mut random, truth, 30, 0.3, 0.2);
        let weights: Vec<f64> = (0..30).map(|_| 0.5 + random.uniform()).collect();
        let eigen = mean(&data, Some(&weights), Method::Chordal);
        let total: f64 = weights.iter().sum();
        let m = scatter(&data, Some(&weights)).map(|row| row.map(|x| x / total));
        let start = random.unit_quaternion();
        let (mut q, mut steps) = (start, 0);
        for next in chordal_flow(m, start, 1.0).skip(1) {
            steps += 1;
            let settled = (next - q).length() < 1e-16;
            q = next;
            if settled || steps > 100_000 {
                break;
            }
        }
        same(q, to_wxyz(eigen), 1e-12);
    }
}

#[test]
fn the_order_of_the_data_does_not_change_the_means() {
    let mut random = Random::new(5);
    let truth = random.unit_quaternion();
    let data = measurements(&mut random, truth, 50, 0.2, 0.1);
    let weights: Vec<f64> = (0..50).map(|_| 0.1 + random.uniform()).collect();
    let (mut shuffled, mut shuffled_weights) = (data.clone(), weights.clone());
    shuffled.reverse();
    shuffled_weights.reverse();
    for method in [Method::Chordal, Method::Quaternion, Method::Geodesic, Method::Median] {
        let a = mean(&data, Some(&weights), method);
        let b = mean(&shuffled, Some(&shuffled_weights), method);
        assert!(angle(a, b) < 1e-12, "{method:?}: {}", angle(a, b));
    }
}

/// Karcher's count is the steps it applied. A reference iteration, written with glam's
/// axis-angle maps rather than the crate's, counts the steps to bring the step below 1e-9 rad;
/// converging at least linearly by half a step, the crate's iteration (to 1e-15 or rounding)
/// needs those and at most 20 more.
#[test]
fn karchers_count_is_the_steps_it_applied() {
    let mut random = Random::new(5);
    let truth = random.unit_quaternion();
    let rotations = measurements(&mut random, truth, 12, 0.5, 0.0);
    let start = truth * DQuat::from_scaled_axis(glam::DVec3::new(0.4, -0.5, 0.3));
    let step_at = |q: DQuat| {
        rotations.iter().fold(glam::DVec3::ZERO, |sum, &r| {
            let u = q.conjugate() * r;
            sum + if u.w < 0.0 { -u } else { u }.to_scaled_axis()
        }) / rotations.len() as f64
    };
    let (mut q, mut steps) = (start, 0);
    while step_at(q).length() >= 1e-9 {
        q = (q * DQuat::from_scaled_axis(step_at(q))).normalize();
        steps += 1;
    }
    let data = Data::new(rotations.iter().copied(), Weights::new(None, 12).unwrap()).unwrap();
    let (got, applied, last) = geodesic::karcher(&data, start);
    assert!(angle(got, q) < 1e-8, "{}", angle(got, q));
    assert!((steps..=steps + 20).contains(&applied), "{applied} steps against {steps}");
    assert!(last < 1e-9, "{last}");
    // From its own answer the iteration has nothing left to apply but rounding.
    let (again, more, _) = geodesic::karcher(&data, got);
    assert!(angle(again, got) < 1e-14 && more <= 1, "{more}");
}

#[test]
fn the_means_settle_where_their_objectives_are_stationary() {
    // The Karcher mean zeroes the weighted sum of tangents, the median the sum of unit tangents.
    let mut random = Random::new(3);
    let truth = random.unit_quaternion();
    let data = measurements(&mut random, truth, 40, 0.4, 0.0);
    let karcher = average(&data, None, Method::Geodesic).unwrap();
    let sum = data.iter().fold(glam::DVec3::ZERO, |s, &r| s + tangent::log_at(karcher.rotation, r));
    assert!(sum.length() < 1e-13, "{sum:?}");
    assert!(karcher.iterations < 20 && karcher.residual < 1e-14);
    let median = average(&data, None, Method::Median).unwrap();
    let pull = data.iter().fold(glam::DVec3::ZERO, |s, &r| {
        let v = tangent::log_at(median.rotation, r);
        s + v / v.length()
    });
    assert!(pull.length() < 1e-9, "{pull:?}");
}

#[test]
fn outliers_drag_the_means_and_not_the_median() {
    // MATH.md's robustness table: 100 measurements with 5° of noise, 30% replaced by random
    // rotations; the median over 20 sets of the angle to the truth is 3.3° (chordal), 8.7°
    // (Karcher) and 1.2° (median). Here: the same ordering, on 20 sets of our own.
    let mut random = Random::new(2026);
    let mut errors: [Vec<f64>; 3] = Default::default();
    for _ in 0..20 {
        let truth = random.unit_quaternion();
        let data = measurements(&mut random, truth, 100, 5f64.to_radians() / 3f64.sqrt(), 0.3);
        for (k, method) in
            [Method::Chordal, Method::Geodesic, Method::Median].into_iter().enumerate()
        {
            errors[k].push(angle(mean(&data, None, method), truth).to_degrees());
        }
    }
    let median_of = |v: &mut Vec<f64>| {
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    };
    let [chordal, karcher, median] = errors.each_mut().map(median_of);
    assert!(median < 2.0 && median < chordal && chordal < karcher, "{chordal} {karcher} {median}");
}

#[test]
fn bad_input_is_refused_by_name() {
    let refusal = |q: &[DQuat], w: Option<&[f64]>| average(q, w, Method::Chordal).unwrap_err();
    assert_eq!(refusal(&[], None).argument(), "quaternions");
    let nan = from_wxyz([f64::NAN, 0.0, 0.0, 1.0]);
    let error = refusal(&[p(), r(), nan], None);
    assert_eq!((error.argument(), error.kind().code()), ("quaternions[2]", "not-finite"));
    let zero = from_wxyz([0.0; 4]);
    assert_eq!(refusal(&[zero], None).kind().code(), "zero-length");
    for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let error = refusal(&[p(), r()], Some(&[1.0, bad]));
        assert_eq!((error.argument(), error.kind().code()), ("weights[1]", "out-of-range"));
    }
    assert_eq!(refusal(&[p(), r()], Some(&[1.0])).argument(), "weights");
    // The weights' scale does not matter, however large or small.
    let three = [p(), r(), DQuat::IDENTITY];
    for method in [Method::Chordal, Method::Quaternion, Method::Geodesic, Method::Median] {
        let plain = mean(&three, Some(&[3.0, 1.0, 1.0]), method);
        for scale in [1e300, 1e-300] {
            let got = mean(&three, Some(&[3.0 * scale, scale, scale]), method);
            assert!(angle(got, plain) < 1e-14, "{method:?} at {scale:e}");
        }
        let tiny = average(three, Some(&[5e-324; 3]), method).unwrap();
        assert!(
            tiny.dispersion.is_finite() && tiny.weights.iter().flatten().all(|w| w.is_finite())
        );
    }
    assert_eq!("karcher".parse::<Method>().unwrap_err().argument(), "method");
    assert_eq!("median".parse::<Method>().unwrap(), Method::Median);
}

#[test]
fn the_angle_is_exact_from_a_nanoradian_to_a_half_turn() {
    // A rotation about an axis through `t` from `a` is `t` away, whatever the axis and sign:
    // built from (cos t/2, sin t/2 n), independent of the chord formula.
    let a = from_wxyz([0.5, -0.5, 0.5, 0.5]);
    let mut random = Random::new(7);
    for t in [1e-9, 1e-5, 0.1, 1.0, 2.0, 3.0, 3.1, std::f64::consts::PI] {
        let axis = random.gaussian3().normalize();
        let b = a * DQuat::from_axis_angle(axis, t);
        for b in [b, -b] {
            let got = angle(a, b);
            // `acos(|a·b|)` would be 1e-8 off at a nanoradian.
            assert!((got - t).abs() <= 1e-15 * (1.0 + t), "{t}: {got}");
            assert!((angle(b, a) - got).abs() <= 1e-15 * (1.0 + t));
        }
    }
    assert_eq!(angle(a, a), 0.0);
    assert_eq!(angle(a, -a), 0.0);
}

/// Weiszfeld's iteration with the Vardi–Zhang rule for data on one line (angles `θ_j` about one
/// axis), written afresh in scalars from Vardi and Zhang (2000): from `start`, the step is
/// `T = Σ_{j≠k} w_j s_j / Σ_{j≠k} w_j/|θ_j − q|` (`s_j` the sign of `θ_j − q`), shortened by
/// `1 − w_k/|Σ_{j≠k} w_j s_j|` when `q` is on a datum `k`, and zero when that is negative (the
/// datum is the median). Stops once a step is at most 1e-14, after at most 1000 steps. Returns
/// the median, the steps taken and the last step's length.
fn weiszfeld_on_a_line(thetas: &[f64], weights: &[f64], start: f64) -> (f64, usize, f64) {
    let (mut q, mut steps, mut last) = (start, 0, 0.0);
    while steps < 1000 {
        steps += 1;
        let (mut force, mut conductance, mut on) = (0.0, 0.0, 0.0);
        for (&theta, &w) in thetas.iter().zip(weights) {
            let d = (theta - q).abs();
            if d < 1e-12 {
                on += w;
            } else {
                force += w * (theta - q).signum();
                conductance += w / d;
            }
        }
        let toward = if conductance > 0.0 { force / conductance } else { 0.0 };
        let step = if on > 0.0 { toward * (1.0 - on / force.abs()).max(0.0) } else { toward };
        last = step.abs();
        q += step;
        if last <= 1e-14 {
            break;
        }
    }
    (q, steps, last)
}

/// The median of data on one great circle, from a start on a datum, against the scalar
/// iteration: where Vardi–Zhang shortens the first step (the datum is not the median) and where
/// it stops there (the datum is). Both the answer and how it was reached: the steps taken and
/// the last step's length.
#[test]
fn the_median_on_a_line_follows_vardi_and_zhang() {
    let line =
        |thetas: &[f64]| thetas.iter().map(|&t| DQuat::from_rotation_x(t)).collect::<Vec<_>>();
    let weights_of = |w: &[f64]| {
        let largest = w.iter().cloned().fold(0.0, f64::max);
        w.iter().map(|x| x / largest).collect::<Vec<_>>()
    };
    // 1. The weighted median of the angles is 0.3 (the cumulative weight passes half of 3.7
    //    there); from the datum at 0 the rule shortens the first step by 1 − 1/2.3.
    // 2. The datum at 0 carries more than the rest pull (2 ≥ |1 − 0.5|): the median, at once.
    // 3. Four data, none heavy enough to hold the iteration: it leaves the datum it starts on.
    for (thetas, w, start) in [
        (vec![-0.2, 0.0, 0.3, 0.5], vec![0.2, 1.0, 1.0, 1.5], 1),
        (vec![-0.4, 0.0, 0.25], vec![0.5, 2.0, 1.0], 1),
        (vec![-0.3, 0.1, 0.2, 0.6], vec![1.0, 1.0, 1.0, 1.0], 0),
        // 4. The datum at 0 holds the rest by a hair (1 against 0.99): Weiszfeld creeps to it and
        //    runs out of its 1000 steps first.
        (vec![-0.2, 0.0, 0.3], vec![0.01, 1.0, 1.0], 2),
    ] {
        let w = weights_of(&w);
        let data =
            Data::new(line(&thetas).into_iter(), Weights::new(Some(&w), w.len()).unwrap()).unwrap();
        let got = median::median(&data, DQuat::from_rotation_x(thetas[start]));
        let (want, steps, last) = weiszfeld_on_a_line(&thetas, &w, thetas[start]);
        let (axis, angle) = got.rotation.to_axis_angle();
        let got_angle = if axis.x < 0.0 { -angle } else { angle };
        assert!((got_angle - want).abs() < 1e-12, "{thetas:?}: {got_angle} against {want}");
        assert_eq!(got.iterations, steps, "{thetas:?}: steps");
        assert!(
            (got.residual - last).abs() <= 1e-15,
            "{thetas:?}: {} against {last}",
            got.residual
        );
    }
    // The second set's answer is known without iterating: the datum at 0, in one step of 0.
    let w = weights_of(&[0.5, 2.0, 1.0]);
    let data = Data::new(line(&[-0.4, 0.0, 0.25]).into_iter(), Weights::new(Some(&w), 3).unwrap())
        .unwrap();
    let got = median::median(&data, DQuat::IDENTITY);
    assert_eq!((got.rotation, got.iterations, got.residual), (DQuat::IDENTITY, 1, 0.0));
}

/// The weighted RMS angle from each mean to the data, against values worked by hand: four
/// identities and a half turn about z put the chordal mean at the identity (the angles 0, 0, 0,
/// 0 and 180°: `π/√5`) and Karcher's 36° towards the half turn (36° four times and 144°); the
/// paper's pair weighted 3:1, from `2 acos |q·r|` at each mean.
#[test]
fn the_dispersion_is_the_weighted_rms_angle() {
    let data = four_identities_and_a_half_turn_about_z();
    let chordal = average(&data, None, Method::Chordal).unwrap().dispersion;
    assert!((chordal - std::f64::consts::PI / 5f64.sqrt()).abs() < 1e-14, "{chordal}");
    let karcher = average(&data, None, Method::Geodesic).unwrap().dispersion;
    let want = ((4.0 * 36f64.powi(2) + 144f64.powi(2)) / 5.0).sqrt().to_radians();
    assert!((karcher - want).abs() < 1e-12, "{karcher} against {want}");
    let weights = [3.0, 1.0];
    for method in [Method::Chordal, Method::Quaternion, Method::Geodesic, Method::Median] {
        let mean = average([p(), r()], Some(&weights), method).unwrap();
        let d = |x: DQuat| 2.0 * mean.rotation.dot(x).abs().min(1.0).acos();
        let want = ((3.0 * d(p()).powi(2) + d(r()).powi(2)) / 4.0).sqrt();
        assert!((mean.dispersion - want).abs() < 1e-12, "{method:?}: {}", mean.dispersion);
    }
}

/// Data need not be unit: a datum scaled by any factor is the same rotation, so every mean, its
/// dispersion and its residual are the unit data's.
#[test]
fn scaled_data_have_the_unit_datas_means() {
    let mut random = Random::new(29);
    let truth = random.unit_quaternion();
    let data = measurements(&mut random, truth, 12, 0.4, 0.0);
    let scaled: Vec<DQuat> =
        data.iter().enumerate().map(|(j, q)| *q * [0.5, 3.0, 1e-3, 7.5][j % 4]).collect();
    let weights: Vec<f64> = (0..12).map(|j| 1.0 + j as f64 / 4.0).collect();
    for method in [Method::Chordal, Method::Quaternion, Method::Geodesic, Method::Median] {
        let (unit, other) = (
            average(&data, Some(&weights), method).unwrap(),
            average(&scaled, Some(&weights), method).unwrap(),
        );
        same(other.rotation, to_wxyz(unit.rotation), 1e-12);
        assert!((other.dispersion - unit.dispersion).abs() < 1e-12, "{method:?}");
        assert!((other.residual - unit.residual).abs() < 1e-12, "{method:?}");
    }
}

/// The iterative means start at the chordal mean, or, where it is not unique, at the heaviest
/// datum (the first of equals).
#[test]
fn the_iterative_means_start_at_the_chordal_mean_or_the_heaviest_datum() {
    let (one, i, j) =
        (DQuat::IDENTITY, from_wxyz([0.0, 1.0, 0.0, 0.0]), from_wxyz([0.0, 0.0, 1.0, 0.0]));
    let data = |q: &[DQuat], w: &[f64]| {
        Data::new(q.iter(), Weights::new(Some(w), q.len()).unwrap()).unwrap()
    };
    // M = diag(2, 2, 0, 0) and diag(2, 2, 1, 0): ties.
    assert_eq!(start(&data(&[i, one, i], &[1.0, 2.0, 1.0])), one);
    assert_eq!(start(&data(&[one, i, j], &[2.0, 2.0, 1.0])), one);
    assert_eq!(start(&data(&[j, one, i], &[1.0, 2.0, 2.0])), one);
    let unique = data(&[p(), r()], &[3.0, 1.0]);
    assert_eq!(start(&unique), chordal::top(&unique.scatter).unwrap().0);
}

/// The chordal mean's tie test is relative to the top eigenvalue: the top two eigenvalues
/// `w(1 ± g)` are refused below the tie's 1e-12 and accepted above it, whatever the scale `w`
/// (`average` normalises the weights, so `top` is called on the scaled matrices); its
/// eigen-residual is rounding's, relative to the eigenvalue.
#[test]
fn the_chordal_tie_and_residual_are_relative() {
    for scale in [1e-6, 1.0, 1e6] {
        for (gap, unique) in [(2e-13, false), (5e-12, true)] {
            let (a, b) = (scale * (1.0 + gap), scale * (1.0 - gap));
            let m = [[a, 0.0, 0.0, 0.0], [0.0, b, 0.0, 0.0], [0.0; 4], [0.0; 4]];
            assert_eq!(chordal::top(&m).is_ok(), unique, "scale {scale}, gap {gap}");
        }
        let mut random = Random::new(31);
        let truth = random.unit_quaternion();
        let data = measurements(&mut random, truth, 20, 0.5, 0.3);
        let weights: Vec<f64> = (0..20).map(|j| scale * (1.0 + j as f64)).collect();
        let (_, residual) = chordal::top(&scatter(&data, Some(&weights))).unwrap();
        assert!(residual < 1e-14, "scale {scale}: {residual:e}");
    }
}

/// The chordal mean is given with its first non-zero component (`w, x, y, z`) positive, as
/// documented: for a mean with `w = 0` exactly (`M = diag(0, 2, 1, 0)`: `i`), and for data whose
/// eigenvector came out either way.
#[test]
fn the_chordal_mean_has_its_first_nonzero_component_positive() {
    for x in [1.0, -1.0] {
        let data = [from_wxyz([0.0, x, 0.0, 0.0]), from_wxyz([0.0, 0.0, x, 0.0])];
        let mean = average(data, Some(&[2.0, 1.0]), Method::Chordal).unwrap().rotation;
        assert_eq!(to_wxyz(mean), [0.0, 1.0, 0.0, 0.0]);
    }
    let mut random = Random::new(37);
    let (mut negative, mut positive) = (0, 0);
    for _ in 0..40 {
        let truth = random.unit_quaternion();
        let data = measurements(&mut random, truth, 5, 0.3, 0.0);
        let (q, _) = chordal::top(&scatter(&data, None)).unwrap();
        let v = eigen(scatter(&data, None)).1[0];
        if v[0] < 0.0 {
            negative += 1
        } else {
            positive += 1
        }
        assert!(q.w > 0.0, "{q:?}");
        // The other means on its side, whatever the data's signs (here all on the other).
        let flipped: Vec<DQuat> =
            data.iter().map(|r| if r.dot(q) > 0.0 { -*r } else { *r }).collect();
        for method in [Method::Quaternion, Method::Geodesic, Method::Median] {
            let mean = average(&flipped, None, method).unwrap().rotation;
            assert!(mean.dot(q) > 0.0, "{method:?}");
        }
    }
    assert!(
        negative > 0 && positive > 0,
        "the eigensolver's signs: {negative} negative, {positive} positive"
    );
}

/// One step of the chordal flow is RK4 for `q' = M q − (qᵀM q) q`, written out here, then
/// normalised.
#[test]
fn a_step_of_the_chordal_flow_is_rk4() {
    let mut random = Random::new(41);
    let truth = random.unit_quaternion();
    let data = measurements(&mut random, truth, 6, 0.6, 0.0);
    let m = scatter(&data, None).map(|row| row.map(|x| x / 6.0));
    let start = random.unit_quaternion();
    let f = |q: DQuat| {
        let v = to_wxyz(q);
        let mq = from_wxyz([0, 1, 2, 3].map(|i| (0..4).map(|j| m[i][j] * v[j]).sum::<f64>()));
        mq - q * q.dot(mq)
    };
    let dt = 0.7;
    let k1 = f(start);
    let k2 = f(start + k1 * (dt / 2.0));
    let k3 = f(start + k2 * (dt / 2.0));
    let k4 = f(start + k3 * dt);
    let want = (start + (k1 + k2 * 2.0 + k3 * 2.0 + k4) * (dt / 6.0)).normalize();
    let got = chordal_flow(m, start, dt).nth(1).unwrap();
    same(got, to_wxyz(want), 1e-15);
}

/// Jacobi's eigenvalues against the closed form on a matrix whose off-diagonal entries sum to
/// zero (`[[2, 1, −1, 0], [1, 2, 0, 0], [−1, 0, 2, 0], [0, 0, 0, 1]]`: `2 + √2, 2, 1, 2 − √2`),
/// each `A v = λ v`, and the same relative accuracy for the matrix scaled by 1e-20 to 1e20.
#[test]
fn the_eigenvalues_of_a_matrix_with_cancelling_entries() {
    let a =
        [[2.0, 1.0, -1.0, 0.0], [1.0, 2.0, 0.0, 0.0], [-1.0, 0.0, 2.0, 0.0], [0.0, 0.0, 0.0, 1.0]];
    let want = [2.0 + 2f64.sqrt(), 2.0, 1.0, 2.0 - 2f64.sqrt()];
    for scale in [1e-20, 1e-12, 1.0, 1e12, 1e20] {
        let (values, vectors) = eigen(a.map(|row| row.map(|x| x * scale)));
        for k in 0..4 {
            assert!((values[k] / scale - want[k]).abs() < 1e-14, "scale {scale}: {values:?}");
            let v = vectors[k];
            for i in 0..4 {
                let av: f64 = (0..4).map(|j| a[i][j] * v[j]).sum();
                assert!((av - want[k] * v[i]).abs() < 1e-14, "scale {scale}, λ_{k}");
            }
        }
    }
}

/// The quaternion mean aligns each datum to the chordal mean's side: one at right angles to it
/// keeps its sign (`1` weighted 3 and `i`: the chordal mean is `1` exactly, the quaternion mean
/// `(3 + i)/√10`, not `(3 − i)/√10`). Left unaligned, data that nearly cancel are refused
/// relative to their total weight: 500 copies of `1` and of `−(1 + 1e-13 i)` sum to `5e-11 i`.
#[test]
fn the_quaternion_means_signs_and_cancellation() {
    let (one, i) = (DQuat::IDENTITY, from_wxyz([0.0, 1.0, 0.0, 0.0]));
    let mean = average([one, i], Some(&[3.0, 1.0]), Method::Quaternion).unwrap().rotation;
    let want = [3.0 / 10f64.sqrt(), 1.0 / 10f64.sqrt(), 0.0, 0.0];
    assert!((to_wxyz(mean)[1] - want[1]).abs() < 1e-15 && (mean.w - want[0]).abs() < 1e-15);
    let near = -from_wxyz([1.0, 1e-13, 0.0, 0.0]).normalize();
    let data: Vec<DQuat> = (0..1000).map(|j| if j % 2 == 0 { one } else { near }).collect();
    let error = quaternion_mean(&data, None, false).unwrap_err();
    assert!(error.to_string().contains("sum to zero"), "{error}");
}
