//! `LoheSwarm` (the `kli/swarm` entry) under Node: the model's behaviour through the boundary,
//! and bad options naming themselves. The dynamics are tested in depth natively
//! (`src/swarm/tests.rs`); these check what JavaScript sees.
#![cfg(all(target_arch = "wasm32", feature = "swarm"))]

use js_sys::{Float64Array, Object, Reflect};
use kli_wasm::swarm::JsLoheSwarm as LoheSwarm;
use wasm_bindgen::{JsCast, JsValue};
use wasm_bindgen_test::wasm_bindgen_test;

fn options(entries: &[(&str, JsValue)]) -> JsValue {
    let object = Object::new();
    for (key, value) in entries {
        Reflect::set(&object, &(*key).into(), value).unwrap();
    }
    object.into()
}

/// A JavaScript number.
fn n(x: f64) -> JsValue {
    x.into()
}

/// The `argument` and the message of a thrown Error.
fn refused(result: Result<impl Sized, impl Into<JsValue>>) -> (String, String) {
    let Err(error) = result else { panic!("expected an Error") };
    let error: JsValue = error.into();
    assert!(error.is_instance_of::<js_sys::Error>());
    let argument = Reflect::get(&error, &"argument".into()).unwrap().as_string().unwrap();
    (argument, error.unchecked_into::<js_sys::Error>().message().into())
}

#[wasm_bindgen_test]
fn identical_oscillators_synchronise_and_balance() {
    for (coupling, synchronised) in [(1.0, true), (-1.0, false)] {
        let o =
            options(&[("count", 100.into()), ("coupling", coupling.into()), ("seed", 5.into())]);
        let mut swarm = LoheSwarm::new(&o).unwrap();
        assert_eq!(swarm.count(), 100);
        let before = swarm.potential();
        swarm.step(&n(0.05), &n(600.0)).unwrap();
        assert!((swarm.time() - 30.0).abs() < 1e-9);
        let r = swarm.order_parameter();
        if synchronised {
            assert!(r > 1.0 - 1e-9 && swarm.rotation_order() > 1.0 - 1e-9, "R = {r}");
        } else {
            assert!(r < 1e-6, "R = {r}");
        }
        // (K N/2)|m|² never decreases: here it rose, to K N/2 or to 0 from below.
        assert!(swarm.potential() >= before);
    }
}

#[wasm_bindgen_test]
fn a_pinned_leader_pulls_one_follower_as_kli_does() {
    // MATH.md: the follower obeys q' = (K/2)(r − (q·r) q), KLI at time Kt/2; the closed form
    // tan(φ/2) = tan(φ0/2) e^(−τ) with φ0 = π/3 for the paper's pair gives the angle to r.
    let o = options(&[("count", 2.into()), ("graph", "leader".into()), ("coupling", 2.into())]);
    let mut swarm = LoheSwarm::new(&o).unwrap();
    let (r, p) = ([0.5, 0.5, 0.5, 0.5], [0.0, 0.0, 0.0, 1.0]);
    let start: Vec<f64> = r.iter().chain(&p).copied().collect();
    // A plain array works as a Float64Array does.
    let plain: js_sys::Array = start.iter().map(|&c| JsValue::from(c)).collect();
    swarm.set_quaternions(&plain.into()).unwrap();
    assert_eq!(swarm.quaternions().to_vec(), start);
    swarm.step(&n(0.005), &n(240.0)).unwrap();
    let q = swarm.quaternions().to_vec();
    assert_eq!(&q[..4], &r, "the leader stays");
    let tau = 2.0 * swarm.time() / 2.0;
    let phi = 2.0 * ((std::f64::consts::FRAC_PI_6).tan() * (-tau).exp()).atan();
    let cos_phi: f64 = q[4..].iter().zip(&r).map(|(a, b)| a * b).sum();
    assert!((cos_phi - phi.cos()).abs() < 1e-10, "{cos_phi} vs {}", phi.cos());
    // Hopf points: 3 per oscillator, on S²; the leader's is h(r) = (0, 1, 0).
    let h = swarm.hopf_points().to_vec();
    assert_eq!(h.len(), 6);
    assert!((h[0]).abs() < 1e-15 && (h[1] - 1.0).abs() < 1e-15 && h[2].abs() < 1e-15);
}

#[wasm_bindgen_test]
fn the_same_seed_gives_the_same_swarm() {
    let o =
        || options(&[("count", 20.into()), ("seed", 77.into()), ("frequencySpread", 0.5.into())]);
    let (mut a, mut b) = (LoheSwarm::new(&o()).unwrap(), LoheSwarm::new(&o()).unwrap());
    a.step(&n(0.1), &JsValue::UNDEFINED).unwrap();
    b.step(&n(0.1), &n(1.0)).unwrap();
    assert_eq!(a.quaternions().to_vec(), b.quaternions().to_vec());
    let c = LoheSwarm::new(&options(&[("count", 20.into()), ("seed", 78.into())])).unwrap();
    assert_ne!(LoheSwarm::new(&o()).unwrap().quaternions().to_vec(), c.quaternions().to_vec());
}

#[wasm_bindgen_test]
fn bad_options_and_arguments_name_themselves() {
    let cases: [(&str, JsValue, &str); 9] = [
        ("count", 0.into(), "count"),
        ("count", 2.5.into(), "count"),
        ("coupling", f64::NAN.into(), "coupling"),
        ("coupling", "strong".into(), "coupling"),
        ("graph", "star".into(), "graph"),
        ("frequencySpread", (-1.0).into(), "frequencySpread"),
        ("startSpread", f64::INFINITY.into(), "startSpread"),
        ("seed", (-3.0).into(), "seed"),
        ("colour", 1.into(), "options"),
    ];
    for (key, value, argument) in cases {
        let (got, message) = refused(LoheSwarm::new(&options(&[(key, value)])));
        assert_eq!(got, argument, "{key}: {message}");
        assert!(message.starts_with(argument), "{message}");
    }
    let leaders =
        options(&[("graph", "leader".into()), ("count", 3.into()), ("leaders", 4.into())]);
    assert_eq!(refused(LoheSwarm::new(&leaders)).0, "leaders");
    let mut swarm = LoheSwarm::new(&options(&[("count", 2.into())])).unwrap();
    assert_eq!(refused(swarm.step(&n(0.0), &JsValue::UNDEFINED)).0, "dt");
    assert_eq!(refused(swarm.step(&n(0.1), &n(-1.0))).0, "steps");
    let short = Float64Array::from(&[1.0, 0.0, 0.0, 0.0][..]);
    assert_eq!(refused(swarm.set_quaternions(&short.into())).0, "quaternions");
    assert_eq!(refused(swarm.set_quaternions(&"1,0,0,0".into())).0, "quaternions");
    let zero = Float64Array::from(&[1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0][..]);
    assert_eq!(refused(swarm.set_quaternions(&zero.into())).0, "quaternions[1]");
    // Still working after every refusal.
    swarm.step(&n(0.1), &n(3.0)).unwrap();
    assert!((swarm.time() - 0.3).abs() < 1e-12);
}

#[wasm_bindgen_test]
fn a_scalar_last_swarm_reads_and_writes_scalar_last() {
    let seed = || ("seed", JsValue::from(7.0));
    let plain = LoheSwarm::new(&options(&[seed(), ("count", 5.into())])).unwrap();
    let last =
        LoheSwarm::new(&options(&[seed(), ("count", 5.into()), ("order", "xyzw".into())])).unwrap();
    let wxyz = plain.quaternions().to_vec();
    let got = last.quaternions().to_vec();
    for (a, b) in got.chunks_exact(4).zip(wxyz.chunks_exact(4)) {
        assert_eq!(a, [b[1], b[2], b[3], b[0]]);
    }
    // Written scalar last: (x, y, z, w) = (0, 0, 0, 1) is the identity, whose Hopf point is +x.
    let mut last = last;
    let identities: Vec<f64> = (0..5).flat_map(|_| [0.0, 0.0, 0.0, 1.0]).collect();
    last.set_quaternions(&Float64Array::from(&identities[..])).unwrap();
    assert_eq!(&last.hopf_points().to_vec()[..3], &[1.0, 0.0, 0.0]);
    assert_eq!(last.quaternions().to_vec(), identities);
    let (argument, _) = refused(LoheSwarm::new(&options(&[("order", "wzyx".into())])));
    assert_eq!(argument, "order");
}
