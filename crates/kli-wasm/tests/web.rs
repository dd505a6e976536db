//! The JavaScript API under Node (wasm-bindgen-test): the paper's numbers through the boundary,
//! and every bad input turning into a JavaScript `Error` after which the module still works.
//! Expected values come from MATH.md or are computed here by an independent formula.
#![cfg(all(target_arch = "wasm32", feature = "api"))]

use js_sys::{Array, Float64Array, Object, Reflect};
use kli_wasm::{self as api, KliOptionsObject, QuaternionLike, Vector3Like};
use wasm_bindgen::{JsCast, JsValue};
use wasm_bindgen_test::wasm_bindgen_test;

const P: [f64; 4] = [0.0, 0.0, 0.0, 1.0];
const R: [f64; 4] = [0.5, 0.5, 0.5, 0.5];

/// A JavaScript number.
fn num(x: f64) -> JsValue {
    x.into()
}

fn quat(values: &[f64]) -> QuaternionLike {
    let array: Array = values.iter().map(|&v| JsValue::from_f64(v)).collect();
    array.unchecked_into()
}

fn typed(values: &[f64]) -> QuaternionLike {
    Float64Array::from(values).unchecked_into()
}

fn options(entries: &[(&str, JsValue)]) -> Option<KliOptionsObject> {
    let object = Object::new();
    for (key, value) in entries {
        Reflect::set(&object, &(*key).into(), value).unwrap();
    }
    Some(object.unchecked_into())
}

fn message(value: JsValue) -> String {
    assert!(value.is_instance_of::<js_sys::Error>(), "not an Error: {value:?}");
    value.unchecked_into::<js_sys::Error>().message().into()
}

fn close(a: &[f64], b: &[f64], tolerance: f64) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| (x - y).abs() <= tolerance)
}

/// The paper's example still gives T = 11.66: the module survived whatever came before.
fn assert_still_works() {
    let path = api::kli(&quat(&P), &quat(&R), None).unwrap();
    assert_eq!(path.steps(), 1166);
}

#[wasm_bindgen_test]
fn paper_example_reaches_at_11_66() {
    let path = api::kli(&quat(&P), &quat(&R), None).unwrap();
    assert!((path.final_time() - 11.66).abs() < 1e-9, "T = {}", path.final_time());
    assert_eq!(path.steps(), 1166);
    let times = path.times().to_vec();
    assert_eq!(times.len(), 1167);
    assert_eq!(times[0], 0.0);
    assert!((times[1166] - 11.66).abs() < 1e-9);
    assert_eq!(path.quaternions().length(), 4 * 1167);
    assert_eq!(path.hopf_curve().length(), 3 * 1167);
    assert!(close(&path.target().to_vec(), &R, 0.0));
    assert_eq!(path.integrator(), "rk4");
}

#[wasm_bindgen_test]
fn table_1_to_four_decimals_with_the_corrected_row() {
    // MATH.md, "The paper's example": t and the first and last components (the middle three
    // equal the second).
    let table = [
        (0.0, 0.0, 1.0),
        (0.2, 0.0943, 0.9866),
        (0.4, 0.1754, 0.9527),
        (0.55, 0.2270, 0.9195),
        (0.85, 0.3083, 0.8455),
        (1.2, 0.3732, 0.7630),
        (1.8, 0.4364, 0.6548),
    ];
    let path = api::kli(&quat(&P), &quat(&R), None).unwrap();
    let q = path.quaternions().to_vec();
    let times = path.times().to_vec();
    for (t, a, d) in table {
        let n = (t / 0.01_f64).round() as usize;
        assert!((times[n] - t).abs() < 1e-12);
        let sample = &q[4 * n..4 * n + 4];
        assert!(close(sample, &[a, a, a, d], 5e-5), "t = {t}: {sample:?}");
    }
    // The last row: within ε of r.
    let last = &q[4 * 1166..];
    assert!(close(last, &R, 1e-5), "{last:?}");
}

#[wasm_bindgen_test]
fn integrated_path_matches_the_closed_form() {
    // At δ = 0.01 both fourth-order schemes agree with the exact solution to 1e-8 (measured 1.3e-10
    // and 7e-11); |q| stays 1 to 1e-9 for RK4 (measured 1.2e-10) and to rounding for geodesic.
    for (integrator, agreement, norm_drift) in [("rk4", 1e-8, 1e-9), ("geodesic", 1e-8, 1e-14)] {
        let path =
            api::kli(&quat(&P), &quat(&R), options(&[("integrator", integrator.into())])).unwrap();
        let q = path.quaternions().to_vec();
        for (n, &t) in path.times().to_vec().iter().enumerate() {
            let exact = path.exact_at(&num(t)).unwrap().to_vec();
            assert!(close(&q[4 * n..4 * n + 4], &exact, agreement), "{integrator} t = {t}");
            let norm = q[4 * n..4 * n + 4].iter().map(|c| c * c).sum::<f64>().sqrt();
            assert!((norm - 1.0).abs() < norm_drift, "{integrator} t = {t}: |q| = {norm}");
        }
    }
    // Euler drifts off the sphere: the reason it is there.
    let euler = api::kli(&quat(&P), &quat(&R), options(&[("integrator", "euler".into())])).unwrap();
    let q = euler.quaternions().to_vec();
    let drift = q
        .chunks(4)
        .map(|c| (c.iter().map(|x| x * x).sum::<f64>().sqrt() - 1.0).abs())
        .fold(0.0, f64::max);
    assert!(drift > 1e-4, "Euler drift {drift}");
}

#[wasm_bindgen_test]
fn closed_form_values() {
    // tan(φ(t)/2) = tan(π/6) e^-t on the paper's pair, computed here with plain trigonometry.
    let phi0 = std::f64::consts::FRAC_PI_3;
    for t in [0.0_f64, 0.2, 1.8, 7.0] {
        let phi = 2.0 * ((phi0 / 2.0).tan() * (-t).exp()).atan();
        let expected: Vec<f64> =
            (0..4).map(|i| ((phi).sin() * P[i] + (phi0 - phi).sin() * R[i]) / phi0.sin()).collect();
        let got = api::kli_exact(&quat(&P), &quat(&R), &num(t), None).unwrap().to_vec();
        assert!(close(&got, &expected, 1e-15), "t = {t}");
        let s = api::kli_to_slerp_parameter(&quat(&P), &quat(&R), &num(t), None).unwrap();
        assert!((s - (1.0 - phi / phi0)).abs() < 1e-15);
        let via_slerp = api::slerp(&quat(&P), &quat(&R), &num(s), None).unwrap().to_vec();
        assert!(close(&via_slerp, &got, 1e-15));
    }
    let t_star = api::kli_reach_time(&quat(&P), &quat(&R), &num(1e-5), None).unwrap();
    assert!((t_star - 11.6568).abs() < 5e-5, "T* = {t_star}");
}

#[wasm_bindgen_test]
fn slerp_matches_the_textbook_formula() {
    // sin((1-s)θ)/sin θ · p + sin(sθ)/sin θ · r on a well-separated pair (θ = acos(p·r)).
    let p = [0.3_f64, -0.1, 0.7, 0.2];
    let r = [0.5_f64, 0.4, -0.2, 0.6];
    let norm = |v: [f64; 4]| {
        let l = v.iter().map(|c| c * c).sum::<f64>().sqrt();
        v.map(|c| c / l)
    };
    let (pu, ru) = (norm(p), norm(r));
    let theta = pu.iter().zip(&ru).map(|(a, b)| a * b).sum::<f64>().acos();
    for s in [0.0, 0.125, 0.5, 0.875, 1.0] {
        let expected: Vec<f64> = (0..4)
            .map(|i| (((1.0 - s) * theta).sin() * pu[i] + (s * theta).sin() * ru[i]) / theta.sin())
            .collect();
        let got = api::slerp(&typed(&p), &quat(&r), &num(s), None).unwrap().to_vec();
        assert!(close(&got, &expected, 1e-12), "s = {s}: {got:?} vs {expected:?}");
    }
}

#[wasm_bindgen_test]
fn hopf_end_points_and_axis_angle() {
    assert!(close(&api::hopf(&quat(&P), None).unwrap().to_vec(), &[-1.0, 0.0, 0.0], 0.0));
    assert!(close(&api::hopf(&quat(&R), None).unwrap().to_vec(), &[0.0, 1.0, 0.0], 0.0));
    let path = api::kli(&quat(&P), &quat(&R), None).unwrap();
    let curve = path.hopf_curve().to_vec();
    assert!(close(&curve[..3], &[-1.0, 0.0, 0.0], 0.0));
    assert!(close(&curve[curve.len() - 3..], &[0.0, 1.0, 0.0], 2e-5));
    // p = k: a half turn about z; r: 120° about (1,1,1)/√3.
    assert!(close(
        &api::axis_angle(&quat(&P), None).unwrap().to_vec(),
        &[0.0, 0.0, 1.0, std::f64::consts::PI],
        0.0
    ));
    let c = 1.0 / 3.0_f64.sqrt();
    let expected = [c, c, c, 2.0 * std::f64::consts::PI / 3.0];
    assert!(close(&api::axis_angle(&quat(&R), None).unwrap().to_vec(), &expected, 1e-15));
    let axis: Vector3Like = Float64Array::from(&[1.0, 1.0, 1.0][..]).unchecked_into();
    let q =
        api::from_axis_angle(&axis, &num(2.0 * std::f64::consts::PI / 3.0), None).unwrap().to_vec();
    assert!(close(&q, &R, 1e-15));
}

#[wasm_bindgen_test]
fn shortest_path_both_ways() {
    // p·r = -0.6: the short way goes to -r through angle acos(0.6), the long way to r through
    // acos(-0.6). T* = ln(tan(φ0/2)/tan(asin(ε/2))) for each, computed here.
    let p = [1.0, 0.0, 0.0, 0.0];
    let r = [-0.6, 0.8, 0.0, 0.0];
    let t_star = |phi0: f64| ((phi0 / 2.0).tan() / (5e-6_f64).asin().tan()).ln();
    let short = api::kli(&quat(&p), &quat(&r), None).unwrap();
    assert!(close(&short.target().to_vec(), &[0.6, -0.8, 0.0, 0.0], 1e-15));
    assert!(
        short.final_time() >= t_star(0.6_f64.acos())
            && short.final_time() < t_star(0.6_f64.acos()) + 0.01
    );
    let long = api::kli(&quat(&p), &quat(&r), options(&[("shortestPath", false.into())])).unwrap();
    assert!(close(&long.target().to_vec(), &r, 1e-15));
    let t_long = t_star((-0.6_f64).acos());
    assert!(
        long.final_time() >= t_long && long.final_time() < t_long + 0.01,
        "{}",
        long.final_time()
    );
    // SLERP half way: the bisector of p and -r, or of p and r.
    let half = api::slerp(&quat(&p), &quat(&r), &num(0.5), None).unwrap().to_vec();
    assert!(close(&half, &[1.6 / 1.6_f64.hypot(0.8), -0.8 / 1.6_f64.hypot(0.8), 0.0, 0.0], 1e-15));
    let half_long =
        api::slerp(&quat(&p), &quat(&r), &num(0.5), options(&[("shortestPath", false.into())]))
            .unwrap()
            .to_vec();
    assert!(close(
        &half_long,
        &[0.4 / 0.4_f64.hypot(0.8), 0.8 / 0.4_f64.hypot(0.8), 0.0, 0.0],
        1e-15
    ));
}

fn expect_error(result: Result<impl Sized, impl Into<JsValue>>, starts_with: &str) {
    match result {
        Ok(_) => panic!("expected an Error starting with {starts_with:?}"),
        Err(e) => {
            let text = message(e.into());
            assert!(text.starts_with(starts_with), "{text:?} does not start with {starts_with:?}");
        }
    }
    assert_still_works();
}

#[wasm_bindgen_test]
fn bad_quaternions_throw_errors_naming_the_argument() {
    let p = quat(&P);
    // Too few numbers or too many: kind "wrong-length", as the batch calls say it.
    expect_error(api::kli(&quat(&[1.0, 2.0, 3.0]), &p, None), "p must hold 4 numbers (got 3)");
    let (argument, kind, _) = properties(api::kli(&quat(&[1.0, 2.0, 3.0]), &p, None));
    assert_eq!((argument.as_str(), kind.as_str()), ("p", "wrong-length"));
    expect_error(
        api::kli(&p, &typed(&[1.0, 2.0, 3.0, 4.0, 5.0]), None),
        "r must hold 4 numbers (got 5)",
    );
    expect_error(
        api::kli(&quat(&[1.0, f64::NAN, 0.0, 0.0]), &p, None),
        "p must be a quaternion of 4 finite numbers",
    );
    expect_error(
        api::kli(&p, &quat(&[f64::INFINITY, 0.0, 0.0, 0.0]), None),
        "r must be a quaternion of 4 finite numbers",
    );
    expect_error(
        api::kli(&p, &typed(&[0.0, 0.0, f64::NEG_INFINITY, 0.0]), None),
        "r must be a quaternion",
    );
    expect_error(
        api::kli(&quat(&[0.0; 4]), &p, None),
        "p must be a quaternion of 4 finite numbers [w, x, y, z], not all zero: it has zero length",
    );
    let strings: QuaternionLike = JsValue::from("abcd").unchecked_into();
    expect_error(api::kli(&strings, &p, None), "p must be an array of 4 numbers");
    let mixed: Array = [JsValue::from("1"), 0.into(), 0.into(), 0.into()].into_iter().collect();
    expect_error(
        api::slerp(&p, mixed.unchecked_ref(), &num(0.5), None),
        "r must hold 4 numbers [w, x, y, z]: element 0 is \"1\"",
    );
    let null: QuaternionLike = JsValue::NULL.unchecked_into();
    expect_error(api::hopf(&null, None), "q must be an array of 4 numbers");
    expect_error(api::axis_angle(&quat(&[0.0; 4]), None), "q must be a quaternion");
    let axis: Vector3Like = Float64Array::from(&[0.0, 0.0, 0.0][..]).unchecked_into();
    expect_error(api::from_axis_angle(&axis, &num(1.0), None), "axis must be 3 finite numbers");
    let axis: Vector3Like = Float64Array::from(&[1.0, 0.0, 0.0][..]).unchecked_into();
    expect_error(
        api::from_axis_angle(&axis, &num(f64::NAN), None),
        "angle must be a finite number",
    );
}

#[wasm_bindgen_test]
fn bad_options_throw_errors_naming_the_option() {
    let (p, r) = (quat(&P), quat(&R));
    for name in ["tolerance", "step", "maxTime"] {
        for bad in [0.0, -1.0, f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            expect_error(
                api::kli(&p, &r, options(&[(name, bad.into())])),
                &format!("{name} must be a finite number > 0"),
            );
        }
        expect_error(
            api::kli(&p, &r, options(&[(name, "1e-5".into())])),
            &format!("{name} must be a number (got \"1e-5\""),
        );
    }
    expect_error(
        api::kli(&p, &r, options(&[("integrator", "rk5".into())])),
        "integrator must be \"rk4\", \"euler\" or \"geodesic\" (got \"rk5\")",
    );
    expect_error(api::kli(&p, &r, options(&[("integrator", 4.into())])), "integrator must be");
    expect_error(
        api::kli(&p, &r, options(&[("shortestPath", "yes".into())])),
        "shortestPath must be true or false",
    );
    expect_error(
        api::kli(&p, &r, options(&[("tolerence", 1e-3.into())])),
        "options has an unknown key \"tolerence\"",
    );
    let number: KliOptionsObject = JsValue::from(5).unchecked_into();
    expect_error(api::kli(&p, &r, Some(number)), "options must be an object");
}

#[wasm_bindgen_test]
fn bad_times_and_impossible_requests_throw() {
    let (p, r) = (quat(&P), quat(&R));
    for t in [-1.0, -1e-300, f64::NAN, f64::INFINITY] {
        expect_error(api::kli_exact(&p, &r, &num(t), None), "t must be a finite number ≥ 0");
        expect_error(
            api::kli_to_slerp_parameter(&p, &r, &num(t), None),
            "t must be a finite number ≥ 0",
        );
        let path = api::kli(&p, &r, None).unwrap();
        expect_error(path.exact_at(&num(t)), "t must be a finite number ≥ 0");
    }
    expect_error(
        api::kli_reach_time(&p, &r, &num(0.0), None),
        "tolerance must be a finite number > 0",
    );
    expect_error(api::slerp(&p, &r, &num(f64::NAN), None), "s must be a finite number");
    // ε below what f64 resolves: reported, not looped forever.
    expect_error(
        api::kli(&p, &r, options(&[("tolerance", 1e-20.into())])),
        "tolerance 1e-20 not reached within maxTime 100",
    );
    expect_error(
        api::kli(&p, &r, options(&[("maxTime", 5.into())])),
        "tolerance 0.00001 not reached within maxTime 5",
    );
    expect_error(
        api::kli(&p, &r, options(&[("step", 1e-7.into())])),
        "step is too small for maxTime",
    );
    // p = -r the long way round: an equilibrium.
    let minus_p = quat(&[0.0, 0.0, 0.0, -3.0]);
    let long = || options(&[("shortestPath", false.into())]);
    expect_error(api::kli(&p, &minus_p, long()), "p and r are antipodal");
    expect_error(api::kli_exact(&p, &minus_p, &num(1.0), long()), "p and r are antipodal");
    expect_error(api::slerp(&p, &minus_p, &num(0.5), long()), "p and r are antipodal");
    // The short way, -r is p itself: nothing to do.
    let path = api::kli(&p, &minus_p, None).unwrap();
    assert_eq!((path.steps(), path.final_time()), (0, 0.0));
}

// ---- Batch API -------------------------------------------------------------------------------

fn f64s(values: &[f64]) -> JsValue {
    Float64Array::from(values).into()
}

/// n pairs (more than one 4096-pair chunk) including near-identical and near-antipodal ones.
fn batch_pairs(n: usize) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let mut seed = 0x9E37_79B9_7F4A_7C15_u64;
    let mut uniform = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed as f64 / u64::MAX as f64) * 2.0 - 1.0
    };
    let (mut starts, mut ends, mut params) = (Vec::new(), Vec::new(), Vec::new());
    for i in 0..n {
        let p: Vec<f64> = (0..4).map(|_| uniform()).collect();
        let r: Vec<f64> = match i % 3 {
            0 => (0..4).map(|_| uniform()).collect(),
            1 => p.iter().enumerate().map(|(k, c)| c + if k == 1 { 1e-12 } else { 0.0 }).collect(),
            _ => p.iter().enumerate().map(|(k, c)| -c + if k == 2 { 1e-12 } else { 0.0 }).collect(),
        };
        starts.extend(p);
        ends.extend(r);
        params.push(uniform().abs() * 3.0);
    }
    (starts, ends, params)
}

#[wasm_bindgen_test]
fn batches_agree_with_the_single_calls() {
    let n = 5000;
    let (starts, ends, params) = batch_pairs(n);
    let (starts_js, ends_js, params_js) = (f64s(&starts), f64s(&ends), f64s(&params));
    for name in ["slerp", "kliExact"] {
        let out = f64s(&vec![0.0; 4 * n]);
        let returned = if name == "slerp" {
            api::slerp_batch(&starts_js, &ends_js, &params_js, &out, None)
        } else {
            api::kli_exact_batch(&starts_js, &ends_js, &params_js, &out, None)
        }
        .unwrap();
        assert!(JsValue::from(returned.clone()) == out, "{name} returns out itself");
        let got = returned.to_vec();
        for i in (0..n).step_by(7) {
            let (p, r) = (quat(&starts[4 * i..4 * i + 4]), quat(&ends[4 * i..4 * i + 4]));
            let single = if name == "slerp" {
                api::slerp(&p, &r, &num(params[i]), None)
            } else {
                api::kli_exact(&p, &r, &num(params[i]), None)
            };
            assert!(
                close(&got[4 * i..4 * i + 4], &single.unwrap().to_vec(), 1e-12),
                "{name} pair {i}"
            );
        }
    }
}

#[wasm_bindgen_test]
fn kli_exact_batch_matches_the_plain_formula_to_1e_12() {
    // The plain formulas of MATH.md with inverse trigonometry, on pairs with p·r ≥ 0 well apart
    // from ±r (where acos itself is accurate): q = [sin φ p + sin(φ0 − φ) r] / sin φ0.
    let p = [0.3_f64, -0.1, 0.7, 0.2];
    let r = [0.5_f64, 0.4, 0.2, 0.6];
    let unit = |v: [f64; 4]| v.map(|c| c / v.iter().map(|x| x * x).sum::<f64>().sqrt());
    let (pu, ru) = (unit(p), unit(r));
    let phi0 = pu.iter().zip(&ru).map(|(a, b)| a * b).sum::<f64>().acos();
    let times: Vec<f64> = (0..200).map(|k| k as f64 * 0.05).collect();
    let n = times.len();
    let out = api::kli_exact_batch(
        &f64s(&p.repeat(n)),
        &f64s(&r.repeat(n)),
        &f64s(&times),
        &f64s(&vec![0.0; 4 * n]),
        None,
    )
    .unwrap()
    .to_vec();
    let sampled = api::kli_sample(&quat(&p), &quat(&r), &f64s(&times), None).unwrap().to_vec();
    for (k, &t) in times.iter().enumerate() {
        let phi = 2.0 * ((phi0 / 2.0).tan() * (-t).exp()).atan();
        let expected: Vec<f64> =
            (0..4).map(|c| (phi.sin() * pu[c] + (phi0 - phi).sin() * ru[c]) / phi0.sin()).collect();
        assert!(close(&out[4 * k..4 * k + 4], &expected, 1e-12), "kliExactBatch t = {t}");
        assert!(close(&sampled[4 * k..4 * k + 4], &expected, 1e-12), "kliSample t = {t}");
    }
}

#[wasm_bindgen_test]
fn kli_sample_near_plus_and_minus_r() {
    // Near ±r the batch path agrees with the single closed-form call to 1e-12.
    for r in [[1.0, 1e-12, 0.0, 0.0], [-1.0, 0.0, 1e-12, 0.0]] {
        let p = [1.0, 0.0, 0.0, 0.0];
        for shortest in [true, false] {
            let o = || options(&[("shortestPath", shortest.into())]);
            let times: Vec<f64> = (0..300).map(|k| k as f64 * 0.1).collect();
            let sampled =
                api::kli_sample(&quat(&p), &quat(&r), &f64s(&times), o()).unwrap().to_vec();
            for (k, &t) in times.iter().enumerate() {
                let single = api::kli_exact(&quat(&p), &quat(&r), &num(t), o()).unwrap().to_vec();
                assert!(
                    close(&sampled[4 * k..4 * k + 4], &single, 1e-12),
                    "r = {r:?} shortest {shortest} t = {t}"
                );
            }
        }
    }
}

#[wasm_bindgen_test]
fn batch_errors_name_the_argument_and_element() {
    let n = 5000;
    let (mut starts, ends, mut params) = batch_pairs(n);
    let out = || f64s(&vec![0.0; 4 * n]);
    let kli_batch = |s: &[f64], p: &[f64], o: JsValue| {
        api::kli_exact_batch(&f64s(s), &f64s(&ends), &f64s(p), &o, None)
    };
    expect_error(
        kli_batch(&starts, &params[..10], out()),
        "starts must hold 4 numbers per t value: 40 for 10 t values (got 20000)",
    );
    expect_error(
        kli_batch(&starts, &params, f64s(&[0.0; 8])),
        "out must hold 4 numbers per t value",
    );
    // A plain array is read (issue 16: three.js's and glTF's arrays are taken as they are), so
    // one of 4 numbers is checked against the others' length; a string is refused by type.
    let plain: Array = [1.0, 0.0, 0.0, 0.0].iter().map(|&v| JsValue::from(v)).collect();
    expect_error(
        api::slerp_batch(&plain, &f64s(&ends), &f64s(&params), &out(), None),
        "starts must hold 4 numbers per s value: 20000 for 5000 s values (got 4)",
    );
    expect_error(
        api::slerp_batch(&"abcd".into(), &f64s(&ends), &f64s(&params), &out(), None),
        "starts must be a typed array or an array of numbers (got \"abcd\", a string)",
    );
    params[4321] = -1.0;
    expect_error(
        kli_batch(&starts, &params, out()),
        "t[4321] must be a finite number ≥ 0 (got -1)",
    );
    params[4321] = 1.0;
    starts[4 * 4500 + 2] = f64::NAN;
    expect_error(
        kli_batch(&starts, &params, out()),
        "starts[4500] must be a quaternion of 4 finite numbers",
    );
    expect_error(
        api::slerp_batch(
            &f64s(&[1.0, 0.0, 0.0, 0.0]),
            &f64s(&[-1.0, 0.0, 0.0, 0.0]),
            &f64s(&[0.5]),
            &f64s(&[0.0; 4]),
            options(&[("shortestPath", false.into())]),
        ),
        "starts[0] and ends[0] are antipodal",
    );
    expect_error(
        api::kli_sample(&quat(&P), &quat(&R), &f64s(&[0.0, f64::NAN]), None),
        "times[1] must be a finite number ≥ 0",
    );
    let text: JsValue = "0,1,2".into();
    expect_error(
        api::kli_sample(&quat(&P), &quat(&R), &text, None),
        "times must be a typed array or an array of numbers (got \"0,1,2\", a string)",
    );
    // nlerp, the baseline, is unit and between the ends.
    let half = api::nlerp_batch(
        &f64s(&[1.0, 0.0, 0.0, 0.0]),
        &f64s(&[0.0, 1.0, 0.0, 0.0]),
        &f64s(&[0.5]),
        &f64s(&[0.0; 4]),
        None,
    )
    .unwrap()
    .to_vec();
    assert!(close(&half, &[0.5_f64.sqrt(), 0.5_f64.sqrt(), 0.0, 0.0], 1e-15));
    // Scalar last, the same numbers in the other layout; a bad component named as laid out.
    let last = || options(&[("order", "xyzw".into())]);
    let (a, b) = (f64s(&[0.0, 0.0, 0.0, 1.0]), f64s(&[1.0, 0.0, 0.0, 0.0]));
    let half = api::nlerp_batch(&a, &b, &f64s(&[0.5]), &f64s(&[0.0; 4]), last()).unwrap();
    assert!(close(&half.to_vec(), &[0.5_f64.sqrt(), 0.0, 0.0, 0.5_f64.sqrt()], 1e-15));
    let bad = f64s(&[0.0, 0.0, 0.0, f64::NAN]);
    let result = api::nlerp_batch(&bad, &b, &f64s(&[0.5]), &f64s(&[0.0; 4]), last());
    expect_error(
        result,
        "starts[0] must be a quaternion of 4 finite numbers [x, y, z, w], not all zero: its w component is NaN",
    );
}

// ---- Errors carry their argument; the fuzzing finds of issue 7 ------------------------------

/// The `argument`, `kind` and `component` properties of a thrown Error.
fn properties(result: Result<impl Sized, impl Into<JsValue>>) -> (String, String, Option<f64>) {
    let Err(error) = result else { panic!("expected an Error") };
    let error: JsValue = error.into();
    let get = |key: &str| Reflect::get(&error, &key.into()).unwrap();
    (
        get("argument").as_string().unwrap(),
        get("kind").as_string().unwrap(),
        get("component").as_f64(),
    )
}

#[wasm_bindgen_test]
fn errors_carry_the_argument_and_kind_as_properties() {
    let (p, r) = (quat(&P), quat(&R));
    let p_nan = quat(&[0.0, f64::NAN, 0.0, 1.0]);
    assert_eq!(
        properties(api::kli(&p_nan, &r, None)),
        ("p".into(), "not-finite".into(), Some(1.0))
    );
    assert_eq!(
        properties(api::kli(&p, &r, options(&[("maxTime", (-1.0).into())]))),
        ("maxTime".into(), "out-of-range".into(), None)
    );
    let minus_p = quat(&[0.0, 0.0, 0.0, -1.0]);
    let long = options(&[("shortestPath", false.into())]);
    assert_eq!(
        properties(api::kli(&p, &minus_p, long)),
        ("shortestPath".into(), "antipodal".into(), None)
    );
    // δ = 5 on the paper's pair: the step's fault, not the shortest-path choice's.
    assert_eq!(
        properties(api::kli(&p, &r, options(&[("step", 5.into())]))),
        ("step".into(), "unstable".into(), None)
    );
    assert_eq!(
        properties(api::kli(&p, &r, options(&[("integrator", "rk5".into())]))),
        ("integrator".into(), "unknown-name".into(), None)
    );
    let mut ends = R.repeat(9);
    ends[4 * 7] = f64::INFINITY;
    let batch = api::slerp_batch(
        &f64s(&P.repeat(9)),
        &f64s(&ends),
        &f64s(&[0.5; 9]),
        &f64s(&[0.0; 36]),
        None,
    );
    assert_eq!(properties(batch), ("ends[7]".into(), "not-finite".into(), Some(0.0)));
    let long = options(&[("shortestPath", false.into())]);
    expect_error(api::kli(&p, &minus_p, long), "p and r are antipodal and shortestPath is false");
}

#[wasm_bindgen_test]
fn huge_slerp_parameters_throw_instead_of_nan() {
    let (p, r) = (quat(&P), quat(&R));
    let one = |x: f64| f64s(&[x]);
    for s in [1e6 + 1.0, 1e20, 1e300, f64::MAX, -1e300] {
        expect_error(
            api::slerp(&p, &r, &num(s), None),
            "s must be a finite number from -1000000 to 1000000",
        );
        let batch = api::slerp_batch(&f64s(&P), &f64s(&R), &one(s), &f64s(&[0.0; 4]), None);
        expect_error(batch, "s[0] must be a finite number from -1000000 to 1000000");
        let nlerp = api::nlerp_batch(&f64s(&P), &f64s(&R), &one(s), &f64s(&[0.0; 4]), None);
        expect_error(nlerp, "s[0] must be a finite number from -1000000 to 1000000");
    }
    // Within the bound, single and batch agree exactly (both take the single call's path).
    for s in [1e6, -7.5e5, 1234.5, -3.0] {
        let single = api::slerp(&p, &r, &num(s), None).unwrap().to_vec();
        let batch =
            api::slerp_batch(&f64s(&P), &f64s(&R), &one(s), &f64s(&[0.0; 4]), None).unwrap();
        assert_eq!(batch.to_vec(), single, "s = {s}");
        assert!((single.iter().map(|c| c * c).sum::<f64>() - 1.0).abs() < 1e-15);
    }
}

#[wasm_bindgen_test]
fn unit_inputs_come_back_exactly_at_the_ends() {
    // Normalised quaternions whose |q|² is 1 exactly in f64 (x² + y² + z² + w², glam's order),
    // found by search: most normalised quaternions are, none of these is a "round" one.
    let mut found = (1..200).map(|k| {
        let k = k as f64;
        let q = [0.3 + 0.01 * k, -0.1 * k, 0.7, 0.2 + 0.003 * k];
        let n = q.iter().map(|c| c * c).sum::<f64>().sqrt();
        q.map(|c| c / n)
    });
    let mut next_unit =
        || found.find(|q| q[1] * q[1] + q[2] * q[2] + q[3] * q[3] + q[0] * q[0] == 1.0).unwrap();
    let (p, r) = (next_unit(), next_unit());
    assert_eq!(api::slerp(&quat(&p), &quat(&r), &num(0.0), None).unwrap().to_vec(), p);
    assert_eq!(api::slerp(&quat(&p), &quat(&r), &num(1.0), None).unwrap().to_vec(), r);
    assert_eq!(api::kli_exact(&quat(&p), &quat(&r), &num(0.0), None).unwrap().to_vec(), p);
    let batch = |s: f64| {
        api::slerp_batch(&f64s(&p), &f64s(&r), &f64s(&[s]), &f64s(&[0.0; 4]), None)
            .unwrap()
            .to_vec()
    };
    assert_eq!(batch(0.0), p);
    assert_eq!(batch(1.0), r);
}

#[wasm_bindgen_test]
fn kli_meets_the_tolerance_or_throws() {
    // 1e-312 apart: a plain |r − p| underflows to 0 and would pass any tolerance at t = 0.
    let (p, r) = ([1.0, 0.0, 0.0, 0.0], [1.0, 1e-312, 0.0, 0.0]);
    for tolerance in [5e-324, 1e-315, 1e-312] {
        match api::kli(&quat(&p), &quat(&r), options(&[("tolerance", tolerance.into())])) {
            Ok(path) => {
                let q = path.quaternions().to_vec();
                let last = &q[q.len() - 4..];
                let gap = ((r[1] - last[1]) * 1e300).hypot((r[0] - last[0]) * 1e300);
                assert!(gap < tolerance * 1e300, "ε = {tolerance:e}: {gap:e} × 1e-300");
            }
            Err(e) => assert_eq!(properties(Err::<(), _>(e)).1, "not-reached", "ε = {tolerance:e}"),
        }
    }
}

#[wasm_bindgen_test]
fn built_with_the_lanes_the_run_asked_for() {
    // The batch kernels above ran on wasm SIMD (`make test-wasm-node`). A build without simd128
    // (`KLI_LANES=portable`, the plain [f64; 2] lanes) would say so; `make lint-wasm-portable`
    // builds it, and the native tests check those lanes bit for bit (src/lanes.rs).
    let portable = option_env!("KLI_LANES") == Some("portable");
    assert_eq!(cfg!(target_feature = "simd128"), !portable);
}

// ---- x, y, z, w: the order three.js, gl-matrix and glTF use (issue 10) -----------------------

/// `[w, x, y, z]` → `[x, y, z, w]`, by hand.
fn xyzw(q: &[f64]) -> Vec<f64> {
    q.chunks_exact(4).flat_map(|q| [q[1], q[2], q[3], q[0]]).collect()
}

fn scalar_last() -> Option<KliOptionsObject> {
    options(&[("order", "xyzw".into())])
}

/// A `THREE.Quaternion`-like object: the numbers behind getters, as three.js keeps them.
fn three_quaternion(q: &[f64]) -> QuaternionLike {
    let object = Object::new();
    for (key, value) in ["_x", "_y", "_z", "_w"].iter().zip([q[1], q[2], q[3], q[0]]) {
        Reflect::set(&object, &(*key).into(), &value.into()).unwrap();
    }
    let getters = js_sys::Function::new_no_args(
        "for (const k of 'xyzw') Object.defineProperty(this, k, { get() { return this['_' + k]; } }); return this;",
    );
    getters.call0(&object).unwrap().unchecked_into()
}

#[wasm_bindgen_test]
fn every_call_takes_and_gives_scalar_last_quaternions_with_order_xyzw() {
    let (p, r) = (xyzw(&P), xyzw(&R));
    let path = api::kli(&quat(&p), &quat(&r), scalar_last()).unwrap();
    let plain = api::kli(&quat(&P), &quat(&R), None).unwrap();
    assert_eq!(path.steps(), 1166);
    assert_eq!(path.quaternions().to_vec(), xyzw(&plain.quaternions().to_vec()));
    assert_eq!(path.target().to_vec(), r);
    assert_eq!(
        path.exact_at(&num(1.8)).unwrap().to_vec(),
        xyzw(&plain.exact_at(&num(1.8)).unwrap().to_vec())
    );
    // Table 1's corrected row 0.4364 + 0.4364i + 0.4364j + 0.6548k, laid out scalar last.
    let row = api::kli_exact(&quat(&p), &quat(&r), &num(1.8), scalar_last()).unwrap().to_vec();
    assert!(close(&row, &[0.4364, 0.4364, 0.6548, 0.4364], 5e-5), "{row:?}");
    let s = api::kli_to_slerp_parameter(&quat(&p), &quat(&r), &num(1.8), scalar_last()).unwrap();
    assert_eq!(s, api::kli_to_slerp_parameter(&quat(&P), &quat(&R), &num(1.8), None).unwrap());
    let reach = api::kli_reach_time(&quat(&p), &quat(&r), &num(1e-5), scalar_last()).unwrap();
    assert!((reach - 11.6568).abs() < 1e-4, "{reach}");
    let half = api::slerp(&quat(&p), &quat(&r), &num(0.5), scalar_last()).unwrap().to_vec();
    assert_eq!(half, xyzw(&api::slerp(&quat(&P), &quat(&R), &num(0.5), None).unwrap().to_vec()));
    // The Hopf map and the polar form read the scalar where the order puts it: h(p) = (-1, 0, 0).
    assert!(close(&api::hopf(&quat(&p), scalar_last()).unwrap().to_vec(), &[-1.0, 0.0, 0.0], 0.0));
    let polar = api::axis_angle(&quat(&r), scalar_last()).unwrap().to_vec();
    assert!(close(&polar, &api::axis_angle(&quat(&R), None).unwrap().to_vec(), 0.0));
    let axis: Vector3Like = f64s(&[0.0, 0.0, 1.0]).unchecked_into();
    let turn =
        api::from_axis_angle(&axis, &num(std::f64::consts::PI), scalar_last()).unwrap().to_vec();
    assert!(close(&turn, &[0.0, 0.0, 1.0, 0.0], 1e-16), "{turn:?}");
    let times = f64s(&[0.0, 0.5, 11.0]);
    let sampled = api::kli_sample(&quat(&p), &quat(&r), &times, scalar_last()).unwrap().to_vec();
    let plain = api::kli_sample(&quat(&P), &quat(&R), &times, None).unwrap().to_vec();
    assert_eq!(sampled, xyzw(&plain));
}

#[wasm_bindgen_test]
fn batches_read_scalar_last_arrays_in_place() {
    // Fast kernels (s in [0, 1]) and the pair-by-pair path (extrapolation) alike.
    for scale in [1.0, 3.0] {
        let (starts, ends, params) = batch_pairs(257);
        let params: Vec<f64> = params.iter().map(|s| s * scale).collect();
        let out = f64s(&vec![0.0; starts.len()]);
        let wxyz = api::slerp_batch(&f64s(&starts), &f64s(&ends), &f64s(&params), &out, None)
            .unwrap()
            .to_vec();
        let (s, e) = (f64s(&xyzw(&starts)), f64s(&xyzw(&ends)));
        let got = api::slerp_batch(&s, &e, &f64s(&params), &out, scalar_last()).unwrap().to_vec();
        // The same formulas; only the dot products are summed in another order (a few ulps,
        // scaled by s up to 9 when extrapolating).
        assert!(close(&got, &xyzw(&wxyz), 4e-15), "slerp, parameters × {scale}");
        let t: Vec<f64> = params.iter().map(|s| s.abs() * 4.0).collect();
        let wxyz = api::kli_exact_batch(&f64s(&starts), &f64s(&ends), &f64s(&t), &out, None)
            .unwrap()
            .to_vec();
        let got = api::kli_exact_batch(&s, &e, &f64s(&t), &out, scalar_last()).unwrap().to_vec();
        assert!(close(&got, &xyzw(&wxyz), 4e-15), "kliExact, times × {scale}");
    }
    // An element's error names the component as the caller laid it out.
    let mut starts = xyzw(&[1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0]);
    starts[4 + 3] = f64::NAN;
    let result = api::slerp_batch(
        &f64s(&starts),
        &f64s(&starts.iter().map(|_| 0.5).collect::<Vec<_>>()),
        &f64s(&[0.5, 0.5]),
        &f64s(&[0.0; 8]),
        scalar_last(),
    );
    let (argument, kind, component) = properties(result);
    assert_eq!(
        (argument.as_str(), kind.as_str(), component),
        ("starts[1]", "not-finite", Some(3.0))
    );
}

#[wasm_bindgen_test]
fn single_calls_take_three_js_style_objects() {
    let (p, r) = (three_quaternion(&P), three_quaternion(&R));
    let path = api::kli(&p, &r, None).unwrap();
    assert_eq!(path.steps(), 1166);
    // Objects are unambiguous: the same answer whatever the order of the arrays.
    let a = api::slerp(&p, &r, &num(0.3), None).unwrap().to_vec();
    let b = api::slerp(&quat(&P), &quat(&R), &num(0.3), None).unwrap().to_vec();
    assert_eq!(a, b);
    let c = api::slerp(&p, &r, &num(0.3), scalar_last()).unwrap().to_vec();
    assert_eq!(c, xyzw(&b));
    assert!(close(&api::hopf(&r, None).unwrap().to_vec(), &[0.0, 1.0, 0.0], 0.0));
    // A plain { x, y, z, w } (glTF-style), and one with a component missing.
    let plain = Object::new();
    for (key, value) in ["x", "y", "z", "w"].iter().zip([0.0, 0.0, 1.0, 0.0]) {
        Reflect::set(&plain, &(*key).into(), &value.into()).unwrap();
    }
    let flipped = api::hopf(plain.unchecked_ref(), None).unwrap().to_vec();
    assert!(close(&flipped, &[-1.0, 0.0, 0.0], 0.0), "{flipped:?}");
    Reflect::delete_property(&plain, &"y".into()).unwrap();
    expect_error(
        api::hopf(plain.unchecked_ref(), None),
        "q must have numbers x, y, z, w: y is undefined",
    );
    assert_still_works();
}

#[wasm_bindgen_test]
fn scalar_last_errors_name_the_components_as_laid_out() {
    let mut p = xyzw(&P);
    p[0] = f64::NAN;
    let result = api::kli(&quat(&p), &quat(&xyzw(&R)), scalar_last());
    let (argument, kind, component) = properties(result);
    assert_eq!((argument.as_str(), kind.as_str(), component), ("p", "not-finite", Some(0.0)));
    p[0] = f64::NAN;
    expect_error(
        api::slerp(&quat(&p), &quat(&R), &num(0.5), scalar_last()),
        "p must be a quaternion of 4 finite numbers [x, y, z, w], not all zero: its x component is NaN",
    );
    expect_error(
        api::slerp(&quat(&[0.0; 3]), &quat(&R), &num(0.5), scalar_last()),
        "p must hold 4 numbers (got 3)",
    );
    expect_error(
        api::kli(&quat(&P), &quat(&R), options(&[("order", "zyxw".into())])),
        "order must be \"wxyz\" or \"xyzw\" (got \"zyxw\")",
    );
    assert_still_works();
}
