//! `synchronizeRotations`, `readG2o` and `SyncFlow` (the `kli/sync` entry) under Node: MATH.md's
//! triangle and square through the boundary in every input form, and bad input naming itself.
//! The solvers are tested in depth natively (`src/sync/tests.rs`, `tests/sync_fixture.rs`).
#![cfg(all(target_arch = "wasm32", feature = "sync"))]

use js_sys::{Array, Float64Array, Int32Array, Uint8Array, Uint32Array};
use kli_wasm::sync::{JsSyncFlow, read_g2o_text, synchronize_rotations};
use wasm_bindgen::{JsCast, JsValue};
use wasm_bindgen_test::wasm_bindgen_test;

use crate::common::{field, floats, nested, object, refused};

const S60: f64 = 0.5; // sin 30°
const C60: f64 = 0.866_025_403_784_438_6; // cos 30°

/// MATH.md's triangle: `q_01 = q_12 = 1`, `q_02` = 60° about x.
fn triangle(edges: JsValue, order_xyzw: bool) -> JsValue {
    let (one, sixty): (&[f64], &[f64]) = if order_xyzw {
        (&[0.0, 0.0, 0.0, 1.0], &[S60, 0.0, 0.0, C60])
    } else {
        (&[1.0, 0.0, 0.0, 0.0], &[C60, S60, 0.0, 0.0])
    };
    object(&[("edges", edges), ("relative", nested(&[one, one, sixty]))])
}

fn check_triangle(result: &JsValue, order_xyzw: bool) {
    let rotations = floats(result, "rotations");
    let expected: [[f64; 4]; 3] = [
        [1.0, 0.0, 0.0, 0.0],
        [0.984807753012208, 0.173648177666930, 0.0, 0.0],
        [0.939692620785908, 0.342020143325669, 0.0, 0.0],
    ];
    for (i, e) in expected.iter().enumerate() {
        let e = if order_xyzw { [e[1], e[2], e[3], e[0]] } else { *e };
        for k in 0..4 {
            assert!((rotations[4 * i + k] - e[k]).abs() < 1e-12, "{rotations:?}");
        }
    }
    assert!((field(result, "cost").as_f64().unwrap() - 0.723688550569099).abs() < 1e-12);
    for r in floats(result, "residuals") {
        assert!((r - 20f64.to_radians()).abs() < 1e-10);
    }
    let certificate = field(result, "certificate");
    assert_eq!(field(&certificate, "certified").as_bool(), Some(true));
    assert!(field(&certificate, "gap").as_f64().unwrap() > 0.0);
}

#[wasm_bindgen_test]
fn the_triangle_in_every_edge_form_and_order() {
    let pairs = nested(&[&[0.0, 1.0], &[1.0, 2.0], &[0.0, 2.0]]);
    let flat: JsValue =
        [0.0, 1.0, 1.0, 2.0, 0.0, 2.0].iter().map(|&x| JsValue::from(x)).collect::<Array>().into();
    let u32s: JsValue = Uint32Array::from(&[0u32, 1, 1, 2, 0, 2][..]).into();
    let i32s: JsValue = Int32Array::from(&[0i32, 1, 1, 2, 0, 2][..]).into();
    for edges in [pairs, flat, u32s, i32s] {
        let result = synchronize_rotations(&triangle(edges, false), None).unwrap();
        check_triangle(&result, false);
    }
    let u32s: JsValue = Uint32Array::from(&[0u32, 1, 1, 2, 0, 2][..]).into();
    let options = object(&[("order", "xyzw".into())]).unchecked_into();
    let result = synchronize_rotations(&triangle(u32s, true), Some(options)).unwrap();
    check_triangle(&result, true);
}

#[wasm_bindgen_test]
fn robust_reports_weights_and_outliers() {
    let u32s: JsValue = Uint32Array::from(&[0u32, 1, 1, 2, 0, 2][..]).into();
    let options = object(&[("method", "robust".into())]).unchecked_into();
    let result = synchronize_rotations(&triangle(u32s, false), Some(options)).unwrap();
    assert_eq!(field(&result, "outliers").unchecked_into::<Uint8Array>().length(), 3);
    assert_eq!(floats(&result, "weights").len(), 3);
    assert!(field(&result, "scale").as_f64().unwrap() > 0.0);
    assert!(field(&result, "certificate").is_undefined());
}

#[wasm_bindgen_test]
fn bad_input_names_itself() {
    let run = |input: JsValue, options: &[(&str, JsValue)]| {
        let options = (!options.is_empty()).then(|| object(options).unchecked_into());
        refused(synchronize_rotations(&input, options))
    };
    let ones = || nested(&[&[1.0, 0.0, 0.0, 0.0]]);
    let (argument, _, message) = run(JsValue::from(3), &[]);
    assert_eq!(argument, "input", "{message}");
    let (argument, _, _) = run(object(&[("relative", ones())]), &[]);
    assert_eq!(argument, "edges");
    let (argument, _, _) = run(object(&[("edges", nested(&[&[0.0, 1.0]]))]), &[]);
    assert_eq!(argument, "relative");
    for bad in [-1.0, 0.5, f64::NAN] {
        let (argument, _, message) =
            run(object(&[("edges", nested(&[&[0.0, bad]])), ("relative", ones())]), &[]);
        assert_eq!(argument, "edges[0]", "{message}");
    }
    let (argument, _, message) =
        run(object(&[("edges", nested(&[&[1.0, 1.0]])), ("relative", ones())]), &[]);
    assert_eq!(argument, "edges[0]");
    assert!(message.contains("itself"), "{message}");
    let zero = nested(&[&[0.0, 0.0, 0.0, 0.0]]);
    let (argument, kind, _) =
        run(object(&[("edges", nested(&[&[0.0, 1.0]])), ("relative", zero)]), &[]);
    assert_eq!((argument.as_str(), kind.as_str()), ("relative[0]", "zero-length"));
    let input = || object(&[("edges", nested(&[&[0.0, 1.0]])), ("relative", ones())]);
    let (argument, _, _) = run(
        object(&[
            ("edges", nested(&[&[0.0, 1.0]])),
            ("relative", ones()),
            ("weights", nested(&[&[0.0]])),
        ]),
        &[],
    );
    assert_eq!(argument, "weights");
    let weights: JsValue = Float64Array::from(&[-1.0][..]).into();
    let (argument, _, _) = run(
        object(&[("edges", nested(&[&[0.0, 1.0]])), ("relative", ones()), ("weights", weights)]),
        &[],
    );
    assert_eq!(argument, "weights[0]");
    let (argument, _, message) = run(input(), &[("anchor", 5.into())]);
    assert_eq!(argument, "anchor", "{message}");
    let (argument, kind, _) = run(input(), &[("method", "lsq".into())]);
    assert_eq!((argument.as_str(), kind.as_str()), ("method", "unknown-name"));
    let (argument, _, _) = run(input(), &[("scale", 0.into())]);
    assert_eq!(argument, "scale");
    let (argument, _, message) = run(input(), &[("tolerance", 1.into())]);
    assert_eq!(argument, "options", "{message}");
    let disconnected = object(&[
        ("edges", nested(&[&[0.0, 1.0], &[2.0, 3.0]])),
        ("relative", nested(&[&[1.0, 0.0, 0.0, 0.0], &[1.0, 0.0, 0.0, 0.0]])),
    ]);
    let (argument, _, message) = run(disconnected, &[]);
    assert_eq!(argument, "edges");
    assert!(message.contains("nodes 2, 3 are cut off from node 0"), "{message}");
}

#[wasm_bindgen_test]
fn g2o_text_is_read_and_bad_lines_are_named() {
    let text = "VERTEX_SE3:QUAT 0 0 0 0 0 0 0 1\nVERTEX_SE3:QUAT 1 0 0 0 0 0 1 0\nEDGE_SE3:QUAT 0 1 0 0 0 0 0 1 0\n";
    let graph = read_g2o_text(&text.into(), None).unwrap();
    assert_eq!(field(&graph, "count").as_f64(), Some(2.0));
    assert_eq!(field(&graph, "dimension").as_f64(), Some(3.0));
    assert_eq!(field(&graph, "edges").unchecked_into::<Uint32Array>().to_vec(), vec![0, 1]);
    assert_eq!(floats(&graph, "ids"), vec![0.0, 1.0]);
    assert_eq!(floats(&graph, "relative"), vec![0.0, 0.0, 0.0, 1.0]);
    assert_eq!(floats(&graph, "initial"), vec![1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0]);
    // No information written: the identity's, κ = 3 / (2 tr I₃) = ½ and τ = 3 / tr I₃ = 1.
    assert_eq!(floats(&graph, "weights"), vec![0.5]);
    assert_eq!(floats(&graph, "translationWeights"), vec![1.0]);
    let (argument, _, message) = refused(read_g2o_text(&"EDGE3 0 1 0 0 0 0 0\n".into(), None));
    assert_eq!(argument, "text");
    assert!(message.starts_with("text line 1: EDGE3 needs 8 numbers"), "{message}");
    let (argument, _, _) = refused(read_g2o_text(&JsValue::from(7), None));
    assert_eq!(argument, "text");
}

#[wasm_bindgen_test]
fn planar_graphs_with_landmarks_are_read_and_a_bad_line_carries_its_number() {
    let text = "VERTEX_SE2 0 0 0 0\nVERTEX_XY 1 2 2\nVERTEX_SE2 2 1 0 1.5\n\
                EDGE_SE2 0 2 1 0 1.5 1 0 0 1 0 4\nEDGE_SE2_XY 0 1 2 2 1 0 1\n";
    let graph = read_g2o_text(&text.into(), None).unwrap();
    assert_eq!(field(&graph, "dimension").as_f64(), Some(2.0));
    assert_eq!(floats(&graph, "ids"), vec![0.0, 2.0]);
    assert_eq!(field(&graph, "edges").unchecked_into::<Uint32Array>().to_vec(), vec![0, 1]);
    assert_eq!(floats(&graph, "weights"), vec![4.0]);
    assert_eq!(floats(&graph, "translations"), vec![1.0, 0.0, 0.0]);
    assert_eq!(floats(&graph, "positions"), vec![0.0, 0.0, 0.0, 1.0, 0.0, 0.0]);
    let skipped = field(&graph, "skipped");
    assert_eq!(field(&skipped, "VERTEX_XY").as_f64(), Some(1.0));
    assert_eq!(field(&skipped, "EDGE_SE2_XY").as_f64(), Some(1.0));
    // The result is an input as it is: a single edge of 1.5 rad about z.
    let result = synchronize_rotations(&graph, None).unwrap();
    let q = floats(&result, "rotations");
    let (s, c) = (0.75f64.sin(), 0.75f64.cos());
    let expected = [c, 0.0, 0.0, s];
    assert!((4..8).all(|k| (q[k] - expected[k - 4]).abs() < 1e-12), "{q:?}");
    // Strict: the landmark line refused, its number a property.
    let strict = object(&[("strict", true.into())]).unchecked_into();
    let error: JsValue = read_g2o_text(&text.into(), Some(strict)).err().unwrap().into();
    assert_eq!(field(&error, "line").as_f64(), Some(2.0));
    assert_eq!(field(&error, "kind").as_string().as_deref(), Some("invalid"));
    let error: JsValue = read_g2o_text(&"EDGE_SE2 0 1 0 0 x\n".into(), None).err().unwrap().into();
    assert_eq!(field(&error, "line").as_f64(), Some(1.0));
    // Other errors carry no line.
    let error: JsValue = read_g2o_text(&"".into(), None).err().unwrap().into();
    assert!(field(&error, "line").is_undefined());
}

#[wasm_bindgen_test]
fn the_flow_starts_from_a_pose_graphs_vertices() {
    let text = "VERTEX_SE3:QUAT 0 0 0 0 0 0 0 1\nVERTEX_SE3:QUAT 1 0 0 0 0 0 1 0\n\
                EDGE_SE3:QUAT 0 1 0 0 0 0 0 0.6 0.8\n";
    let graph = read_g2o_text(&text.into(), None).unwrap();
    let flow = JsSyncFlow::new(&graph, None).unwrap();
    assert_eq!(flow.rotations().to_vec(), vec![1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0]);
    // A start given wins over the vertices.
    let start = nested(&[&[0.0, 1.0, 0.0, 0.0], &[1.0, 0.0, 0.0, 0.0]]);
    let flow = JsSyncFlow::new(&graph, Some(object(&[("start", start)]).unchecked_into())).unwrap();
    assert_eq!(flow.rotations().to_vec(), vec![0.0, 1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0]);
    // A bad initial is named as the caller passed it.
    let bad = object(&[
        ("edges", field(&graph, "edges")),
        ("relative", field(&graph, "relative")),
        ("initial", nested(&[&[1.0, 0.0, 0.0, 0.0], &[0.0, 0.0, 0.0, 0.0]])),
    ]);
    let (argument, _, message) = refused(JsSyncFlow::new(&bad, None));
    assert!(argument.starts_with("initial"), "{argument}: {message}");
}

#[wasm_bindgen_test]
fn the_flow_steps_and_lowers_the_cost() {
    let u32s: JsValue = Uint32Array::from(&[0u32, 1, 1, 2, 0, 2][..]).into();
    let options = object(&[("seed", 3.into())]).unchecked_into();
    let mut flow = JsSyncFlow::new(&triangle(u32s, false), Some(options)).unwrap();
    let before = flow.cost();
    flow.step(&0.05.into(), &400.into()).unwrap();
    assert!(flow.cost() < before);
    assert!((flow.cost() - 0.723688550569099).abs() < 1e-9, "{}", flow.cost());
    assert!((flow.time() - 20.0).abs() < 1e-9);
    assert_eq!(flow.rotations().length(), 12);
    assert_eq!(flow.hopf_points().length(), 9);
    assert_eq!(flow.residuals().length(), 3);
    let (argument, _, _) = refused(flow.step(&0.into(), &JsValue::UNDEFINED));
    assert_eq!(argument, "dt");
    let (argument, _, _) = refused(flow.step(&0.1.into(), &2e6.into()));
    assert_eq!(argument, "steps");
    let u32s: JsValue = Uint32Array::from(&[0u32, 1, 1, 2, 0, 2][..]).into();
    let start = object(&[("start", nested(&[&[1.0, 0.0, 0.0, 0.0]]))]).unchecked_into();
    let (argument, _, _) = refused(JsSyncFlow::new(&triangle(u32s, false), Some(start)));
    assert_eq!(argument, "start");
}
