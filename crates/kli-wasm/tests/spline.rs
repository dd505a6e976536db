//! The `kli/spline` entry under Node: the three curves through the boundary, call for call,
//! and bad input naming the argument and the element. The curves' mathematics is tested
//! natively (`src/spline/tests.rs`).
#![cfg(all(target_arch = "wasm32", feature = "spline"))]

use js_sys::{Array, Float64Array, Object, Reflect};
use kli_wasm::spline::{
    KeysLike, KliSplineOptionsObject, RotationSpline, kli_spline, slerp_spline, squad_spline,
};
use wasm_bindgen::{JsCast, JsValue};
use wasm_bindgen_test::wasm_bindgen_test;

/// Four keys, the second with the opposite sign (the same rotation).
const KEYS: [f64; 16] = [
    1.0, 0.0, 0.0, 0.0, //
    -0.8, -0.6, 0.0, 0.0, //
    0.6, 0.0, 0.8, 0.0, //
    0.0, 0.0, 0.6, 0.8,
];

/// A JavaScript number.
fn n(x: f64) -> JsValue {
    x.into()
}

fn flat() -> KeysLike {
    Float64Array::from(&KEYS[..]).unchecked_into()
}

fn options(entries: &[(&str, JsValue)]) -> Option<KliSplineOptionsObject> {
    let object = Object::new();
    for (key, value) in entries {
        Reflect::set(&object, &(*key).into(), value).unwrap();
    }
    Some(object.unchecked_into())
}

fn argument(result: Result<RotationSpline, impl Into<JsValue>>) -> String {
    let Err(error) = result else { panic!("expected an Error") };
    let error: JsValue = error.into();
    Reflect::get(&error, &"argument".into()).unwrap().as_string().unwrap()
}

#[wasm_bindgen_test]
fn the_three_curves_hit_the_keys_as_made_consistent() {
    let times = || Float64Array::from(&[0.0, 0.5, 2.0, 3.0][..]);
    let kli = kli_spline(&flat(), options(&[("times", times().into())])).unwrap();
    let squad = squad_spline(
        &flat(),
        options(&[("times", times().into())]).map(JsValue::from).map(JsCast::unchecked_into),
    )
    .unwrap();
    let slerp = slerp_spline(&flat(), None).unwrap();
    // The second key flipped to (0.8, 0.6, 0, 0): k1·k0 ≥ 0.
    let used = kli.keys().to_vec();
    assert_eq!(&used[4..8], &[0.8, 0.6, 0.0, 0.0]);
    for (i, &t) in [0.0, 0.5, 2.0, 3.0].iter().enumerate() {
        for curve in [&kli, &squad] {
            let q = curve.at(&n(t), &JsValue::UNDEFINED).unwrap().to_vec();
            let gap: f64 = (0..4).map(|c| (q[c] - used[4 * i + c]).abs()).fold(0.0, f64::max);
            assert!(gap < 1e-12, "key {i}: {q:?}");
        }
    }
    // slerpSpline uses the default times 0, 1, 2, 3; t outside is clamped.
    assert_eq!(slerp.at(&n(-5.0), &JsValue::UNDEFINED).unwrap().to_vec(), used[..4].to_vec());
    assert_eq!((slerp.start_time(), slerp.end_time()), (0.0, 3.0));
    assert!(kli.residual().unwrap() <= 1e-10 && kli.iterations().is_some());
    assert!(squad.residual().is_none() && squad.iterations().is_none());
}

#[wasm_bindgen_test]
fn sample_matches_at_and_fills_out() {
    let kli = kli_spline(&flat(), options(&[("smoothness", 0.5.into())])).unwrap();
    let times: Vec<f64> = (0..31).map(|k| k as f64 * 0.1).collect();
    let out = Float64Array::new_with_length(4 * 31);
    let returned = kli.sample(&Float64Array::from(&times[..]).into(), &out.clone().into()).unwrap();
    assert!(JsValue::from(returned) == JsValue::from(out.clone()));
    for (k, &t) in times.iter().enumerate() {
        assert_eq!(
            out.subarray(4 * k as u32, 4 * k as u32 + 4).to_vec(),
            kli.at(&n(t), &JsValue::UNDEFINED).unwrap().to_vec()
        );
    }
    // ω: q' = ½ ω q; piecewise SLERP turns at constant speed on a segment: |ω| = the rotation
    // angle between the keys (2·acos(k0·k1) = 2·acos(0.8)) over the segment's time (1).
    let slerp = slerp_spline(&flat(), None).unwrap();
    let omega = slerp.angular_velocity(&n(0.5), &JsValue::UNDEFINED).unwrap().to_vec();
    let speed = omega.iter().map(|c| c * c).sum::<f64>().sqrt();
    assert!((speed - 2.0 * 0.8_f64.acos()).abs() < 1e-6, "{speed}");
}

#[wasm_bindgen_test]
fn bad_input_names_the_argument_and_element() {
    assert_eq!(
        argument(kli_spline(&Float64Array::from(&KEYS[..4]).unchecked_into(), None)),
        "keys"
    );
    assert_eq!(
        argument(kli_spline(&Float64Array::from(&KEYS[..6]).unchecked_into(), None)),
        "keys"
    );
    let nested: Array = [
        JsValue::from(Array::of4(&1.into(), &0.into(), &0.into(), &0.into())),
        JsValue::from("abcd"),
    ]
    .into_iter()
    .collect();
    assert_eq!(argument(kli_spline(nested.unchecked_ref(), None)), "keys[1]");
    let mut zero = KEYS;
    zero[8..12].copy_from_slice(&[0.0; 4]);
    assert_eq!(
        argument(kli_spline(&Float64Array::from(&zero[..]).unchecked_into(), None)),
        "keys[2]"
    );
    let uneven = Float64Array::from(&[0.0, 1.0, 1.0, 2.0][..]);
    assert_eq!(argument(kli_spline(&flat(), options(&[("times", uneven.into())]))), "times[2]");
    assert_eq!(argument(kli_spline(&flat(), options(&[("smoothness", 2.into())]))), "smoothness");
    assert_eq!(
        argument(kli_spline(&flat(), options(&[("samplesPerSegment", 1.5.into())]))),
        "samplesPerSegment"
    );
    assert_eq!(argument(kli_spline(&flat(), options(&[("tension", 1.into())]))), "options");
    let spline = slerp_spline(&flat(), None).unwrap();
    let Err(error) = spline.at(&n(f64::NAN), &JsValue::UNDEFINED) else { panic!() };
    assert_eq!(Reflect::get(&error.into(), &"argument".into()).unwrap(), "t");
}

/// `[w, x, y, z]` → `[x, y, z, w]`, by hand.
fn xyzw(q: &[f64]) -> Vec<f64> {
    q.chunks_exact(4).flat_map(|q| [q[1], q[2], q[3], q[0]]).collect()
}

#[wasm_bindgen_test]
fn scalar_last_keys_give_scalar_last_curves_and_objects_are_read_as_named() {
    let scalar_last = || options(&[("order", "xyzw".into())]);
    let keys: KeysLike = Float64Array::from(&xyzw(&KEYS)[..]).unchecked_into();
    // Keys as THREE.Quaternion-like objects { x, y, z, w }: no order needed.
    let objects: Array = KEYS
        .chunks_exact(4)
        .map(|q| {
            let o = Object::new();
            for (k, v) in ["x", "y", "z", "w"].iter().zip([q[1], q[2], q[3], q[0]]) {
                Reflect::set(&o, &(*k).into(), &v.into()).unwrap();
            }
            JsValue::from(o)
        })
        .collect();
    let times = Float64Array::from(&[0.0, 0.4, 1.7, 2.5, 3.0][..]);
    let plain = kli_spline(&flat(), None).unwrap();
    let last = kli_spline(&keys, scalar_last()).unwrap();
    let from_objects = kli_spline(objects.unchecked_ref(), None).unwrap();
    let expected = plain.sample(&times, &JsValue::UNDEFINED).unwrap().to_vec();
    assert_eq!(last.sample(&times, &JsValue::UNDEFINED).unwrap().to_vec(), xyzw(&expected));
    assert_eq!(
        last.at(&n(1.7), &JsValue::UNDEFINED).unwrap().to_vec(),
        xyzw(&plain.at(&n(1.7), &JsValue::UNDEFINED).unwrap().to_vec())
    );
    assert_eq!(last.keys().to_vec(), xyzw(&plain.keys().to_vec()));
    assert_eq!(from_objects.sample(&times, &JsValue::UNDEFINED).unwrap().to_vec(), expected);
    let squad = squad_spline(&keys, Some(scalar_last().unwrap().unchecked_into())).unwrap();
    let plain_squad = squad_spline(&flat(), None).unwrap();
    assert_eq!(
        squad.at(&n(0.5), &JsValue::UNDEFINED).unwrap().to_vec(),
        xyzw(&plain_squad.at(&n(0.5), &JsValue::UNDEFINED).unwrap().to_vec())
    );
    // A bad component is named as laid out.
    let mut bad = xyzw(&KEYS);
    bad[4 + 3] = f64::NAN;
    let bad: Array = bad.chunks_exact(4).map(|q| JsValue::from(Float64Array::from(q))).collect();
    let Err(error) = kli_spline(bad.unchecked_ref(), scalar_last()) else { panic!() };
    let message: String = JsValue::from(error).unchecked_into::<js_sys::Error>().message().into();
    assert!(message.starts_with("keys[1] must be a quaternion of 4 finite numbers [x, y, z, w]"));
    assert!(message.ends_with("its w component is NaN"), "{message}");
}
