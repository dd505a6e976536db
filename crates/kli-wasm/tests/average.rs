//! `averageRotations` and `blendRotations` (the `kli/average` entry) under Node: MATH.md's
//! reference values through the boundary in every input form, the blend against the per-bone
//! mean and its poses permuted, and bad input naming itself. The means are tested in depth
//! natively (`src/average/tests.rs`); these check what JavaScript sees.
#![cfg(all(target_arch = "wasm32", feature = "average"))]

use js_sys::{Array, Float32Array, Float64Array, Object, Reflect};
use kli_wasm::average::{average_rotations, blend_rotations};
use wasm_bindgen::{JsCast, JsValue};
use wasm_bindgen_test::wasm_bindgen_test;

fn object(entries: &[(&str, JsValue)]) -> JsValue {
    let object = Object::new();
    for (key, value) in entries {
        Reflect::set(&object, &(*key).into(), value).unwrap();
    }
    object.into()
}

fn numbers(values: &[f64]) -> JsValue {
    Float64Array::from(values).into()
}

/// `p = k` and `r = ½(1 + i + j + k)`, scalar first.
const P: [f64; 4] = [0.0, 0.0, 0.0, 1.0];
const R: [f64; 4] = [0.5; 4];

/// The `rotation` of `averageRotations(quaternions, options)`.
fn mean(quaternions: &JsValue, options: &[(&str, JsValue)]) -> Vec<f64> {
    let options = (!options.is_empty()).then(|| object(options).unchecked_into());
    let result = average_rotations(quaternions.unchecked_ref(), options).unwrap();
    Reflect::get(&result, &"rotation".into()).unwrap().unchecked_into::<Float64Array>().to_vec()
}

/// Equal as rotations (either sign), to `tolerance` a component.
fn same(got: &[f64], want: [f64; 4], tolerance: f64) {
    let minus = want.map(|c| -c);
    let off = |w: &[f64; 4]| got.iter().zip(w).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
    assert!(off(&want).min(off(&minus)) < tolerance, "{got:?} against {want:?}");
}

/// The `argument` and `kind` of a thrown Error.
fn refused(result: Result<impl Sized, impl Into<JsValue>>) -> (String, String) {
    let Err(error) = result else { panic!("expected an Error") };
    let error: JsValue = error.into();
    let get = |key: &str| Reflect::get(&error, &key.into()).unwrap().as_string().unwrap();
    (get("argument"), get("kind"))
}

#[wasm_bindgen_test]
fn the_weighted_means_of_the_papers_two_rotations_in_every_input_form() {
    let weights = || numbers(&[3.0, 1.0]);
    let chordal = [0.095819985282240, 0.095819985282240, 0.095819985282240, 0.986131629784551];
    // Nested arrays, a flat Float64Array, a Float32Array (rounded: to 1e-7), `{ x, y, z, w }`.
    let nested: Array = [P, R].iter().map(|q| numbers(q)).collect();
    same(&mean(&nested.into(), &[("weights", weights())]), chordal, 1e-14);
    let flat = numbers(&[P, R].concat());
    same(&mean(&flat, &[("weights", weights())]), chordal, 1e-14);
    let single: Vec<f32> = [P, R].concat().iter().map(|&c| c as f32).collect();
    same(&mean(&Float32Array::from(&single[..]).into(), &[("weights", weights())]), chordal, 1e-7);
    let xyzw = |q: [f64; 4]| {
        object(&[("x", q[1].into()), ("y", q[2].into()), ("z", q[3].into()), ("w", q[0].into())])
    };
    let objects: Array = [xyzw(P), xyzw(R)].into_iter().collect();
    same(&mean(&objects.into(), &[("weights", weights())]), chordal, 1e-14);
    // Scalar last, in and out.
    let last = numbers(&[0.0, 0.0, 1.0, 0.0, 0.5, 0.5, 0.5, 0.5]);
    let got = mean(&last, &[("weights", weights()), ("order", "xyzw".into())]);
    same(&[got[3], got[0], got[1], got[2]], chordal, 1e-14);
    // The other methods: the quaternion mean (3p + r)/√13, Karcher's a quarter of the arc.
    let quaternion = [0.138675049056307, 0.138675049056307, 0.138675049056307, 0.970725343394151];
    same(
        &mean(&flat, &[("weights", weights()), ("method", "quaternion".into())]),
        quaternion,
        1e-14,
    );
    let karcher = [0.149429245361342, 0.149429245361342, 0.149429245361342, 0.965925826289068];
    same(&mean(&flat, &[("weights", weights()), ("method", "geodesic".into())]), karcher, 1e-14);
}

#[wasm_bindgen_test]
fn the_median_reports_each_rotations_weight() {
    // Four identities and a half turn about z: the median stays at the identity, and the half
    // turn's weight is next to nothing.
    let data =
        numbers(&[[1.0, 0.0, 0.0, 0.0]; 4].concat().into_iter().chain(P).collect::<Vec<_>>());
    let options: JsValue = object(&[("method", "median".into())]);
    let result = average_rotations(data.unchecked_ref(), Some(options.unchecked_into())).unwrap();
    let get = |key: &str| Reflect::get(&result, &key.into()).unwrap();
    assert_eq!(get("rotation").unchecked_into::<Float64Array>().to_vec(), [1.0, 0.0, 0.0, 0.0]);
    let weights = get("weights").unchecked_into::<Float64Array>().to_vec();
    assert!(weights[4] < 1e-11, "{weights:?}");
    assert!(
        get("dispersion").as_f64().unwrap() > 1.0 && get("iterations").as_f64().unwrap() >= 1.0
    );
    // The chordal mean has no weights.
    let chordal = average_rotations(data.unchecked_ref(), None).unwrap();
    assert!(Reflect::get(&chordal, &"weights".into()).unwrap().is_undefined());
}

#[wasm_bindgen_test]
fn a_blend_is_each_bones_mean_whatever_the_order_of_the_poses() {
    // Three poses of two bones.
    let poses = [
        [P, [1.0, 0.0, 0.0, 0.0]],
        [R, [0.8, 0.6, 0.0, 0.0]],
        [[0.6, 0.0, 0.8, 0.0], [0.0, 0.0, 0.6, 0.8]],
    ];
    let weights = [0.5, 0.3, 0.2];
    let flat = |order: &[usize]| {
        numbers(&order.iter().flat_map(|&p| poses[p].concat()).collect::<Vec<_>>())
    };
    let blend = |order: &[usize]| {
        let out = Float64Array::new_with_length(8);
        let w: Vec<f64> = order.iter().map(|&p| weights[p]).collect();
        blend_rotations(&flat(order), &numbers(&w), &out.clone().into(), None).unwrap().to_vec()
    };
    let blended = blend(&[0, 1, 2]);
    for bone in 0..2 {
        let data: Vec<f64> = poses.iter().flat_map(|pose| pose[bone]).collect();
        let alone = mean(&numbers(&data), &[("weights", numbers(&weights))]);
        same(&blended[4 * bone..4 * bone + 4], [alone[0], alone[1], alone[2], alone[3]], 1e-15);
    }
    for order in [[2, 1, 0], [1, 2, 0], [0, 2, 1]] {
        let other = blend(&order);
        for (a, b) in blended.iter().zip(&other) {
            assert!((a - b).abs() < 1e-15, "{blended:?} against {other:?}");
        }
    }
    // A pose of weight 0 is left out: the blend of the other two.
    let out = Float64Array::new_with_length(8);
    let without = blend_rotations(&flat(&[0, 1, 2]), &numbers(&[0.5, 0.3, 0.0]), &out.into(), None)
        .unwrap()
        .to_vec();
    let two: Vec<f64> = poses[..2].iter().flat_map(|pose| pose[0]).collect();
    let alone = mean(&numbers(&two), &[("weights", numbers(&[0.5, 0.3]))]);
    same(&without[..4], [alone[0], alone[1], alone[2], alone[3]], 1e-15);
}

#[wasm_bindgen_test]
fn bad_input_names_itself() {
    let two = || numbers(&[P, R].concat());
    let average = |q: JsValue, options: &[(&str, JsValue)]| {
        let options = (!options.is_empty()).then(|| object(options).unchecked_into());
        refused(average_rotations(q.unchecked_ref(), options))
    };
    assert_eq!(average(numbers(&[]), &[]).0, "quaternions");
    assert_eq!(average(numbers(&[1.0, 0.0, 0.0]), &[]).0, "quaternions");
    assert_eq!(
        average(numbers(&[1.0, 0.0, 0.0, 0.0, f64::NAN, 0.0, 0.0, 0.0]), &[]),
        ("quaternions[1]".into(), "not-finite".into())
    );
    assert_eq!(average("abc".into(), &[]).0, "quaternions");
    assert_eq!(
        average(two(), &[("weights", numbers(&[1.0, -2.0]))]),
        ("weights[1]".into(), "out-of-range".into())
    );
    assert_eq!(average(two(), &[("weights", numbers(&[1.0]))]).0, "weights");
    assert_eq!(
        average(two(), &[("method", "mode".into())]),
        ("method".into(), "unknown-name".into())
    );
    assert_eq!(average(two(), &[("colour", 1.into())]).0, "options");
    // 1 and i, weighted equally: no unique chordal mean.
    let tie = numbers(&[1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0]);
    assert_eq!(average(tie.clone(), &[]), ("quaternions".into(), "not-unique".into()));
    // The blend: each argument by name, and the bone whose mean is not unique.
    let out = || JsValue::from(Float64Array::new_with_length(4));
    let blend = |poses: JsValue, weights: &[f64], out: JsValue| {
        refused(blend_rotations(&poses, &numbers(weights), &out, None))
    };
    assert_eq!(blend(tie.clone(), &[1.0, 1.0], out()), ("bones[0]".into(), "not-unique".into()));
    assert_eq!(blend(tie.clone(), &[1.0], out()).0, "poses");
    assert_eq!(blend(tie.clone(), &[0.0, 0.0], out()).0, "weights");
    assert_eq!(blend(tie.clone(), &[1.0, f64::NAN], out()).0, "weights[1]");
    assert_eq!(
        blend(tie.clone(), &[1.0, 1.0], numbers(&[]).unchecked_into::<Float64Array>().into()).0,
        "out"
    );
    assert_eq!(blend(tie.clone(), &[1.0, 1.0], JsValue::from(Array::new())).0, "out");
    let zero = numbers(&[1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
    assert_eq!(blend(zero, &[1.0, 1.0], out()), ("poses[1] (bone 0)".into(), "zero-length".into()));
    // Still working after every refusal.
    same(
        &mean(&two(), &[]),
        [0.288675134594813, 0.288675134594813, 0.288675134594813, 0.866025403784439],
        1e-14,
    );
}
