//! `synchronizePoses` and `writeG2o` (the `kli/sync` entry) under Node: CSAIL to MATH.md's
//! optimum and a 3D grid to bench/posegraph_reference.py's, certified; every input form; bad
//! input naming itself; and a graph written by `writeG2o` read back by `readG2o` as it was, the
//! written poses its vertices. The solver is tested in depth natively (`src/sync/poses/tests.rs`).
#![cfg(all(target_arch = "wasm32", feature = "sync"))]

use js_sys::{Float64Array, Uint32Array};
use kli_wasm::poses::{synchronize_poses_js, write_g2o};
use kli_wasm::sync::read_g2o_text;
use wasm_bindgen::{JsCast, JsValue};
use wasm_bindgen_test::wasm_bindgen_test;

use crate::common::{field, floats, nested, object, refused};

const CSAIL: &str = include_str!("../../../tests/fixtures/posegraphs/CSAIL.g2o");
const SMALL_GRID: &str = include_str!("../../../tests/fixtures/posegraphs/smallGrid3D.g2o");

/// Options as key–value pairs.
type Options = Vec<(&'static str, JsValue)>;

fn cost(result: &JsValue) -> f64 {
    field(result, "cost").as_f64().unwrap()
}

fn certified(result: &JsValue) -> bool {
    field(&field(result, "certificate"), "certified").as_bool().unwrap()
}

fn read(text: &str) -> JsValue {
    read_g2o_text(&text.into(), None).unwrap()
}

fn solve(input: &JsValue, options: &[(&str, JsValue)]) -> Result<JsValue, JsValue> {
    let options = (!options.is_empty()).then(|| object(options).unchecked_into());
    synchronize_poses_js(input, options).map_err(Into::into)
}

/// CSAIL (2D, 1,045 poses): MATH.md's 31.70372 to 1e-6, certified, z = 0 and rotations about z.
#[wasm_bindgen_test]
fn csail_reaches_maths_optimum_certified() {
    let graph = read(CSAIL);
    let result = solve(&graph, &[]).unwrap();
    assert!((cost(&result) - 31.70372).abs() <= 1e-6 * 31.70372, "{}", cost(&result));
    assert!(certified(&result));
    let certificate = field(&result, "certificate");
    assert_eq!(field(&certificate, "rank").as_f64(), Some(2.0));
    // The dual bound: below MATH.md's optimum, by at most the tolerance's share (d n of it).
    let number = |key: &str| field(&certificate, key).as_f64().unwrap();
    let gap = 31.70372 - number("lowerBound");
    assert!(gap >= -1e-6 * 31.70372 && gap <= 2.0 * 1045.0 * number("tolerance") + 1e-5, "{gap}");
    let (rotations, translations) = (floats(&result, "rotations"), floats(&result, "translations"));
    assert_eq!((rotations.len(), translations.len()), (4 * 1045, 3 * 1045));
    assert!(translations.chunks(3).all(|t| t[2] == 0.0));
    assert!(rotations.chunks(4).all(|q| q[1] == 0.0 && q[2] == 0.0 && q[0] >= 0.0));
    assert_eq!(&rotations[..4], &[1.0, 0.0, 0.0, 0.0]);
    assert_eq!(&translations[..3], &[0.0, 0.0, 0.0]);
}

/// smallGrid3D (125 poses) against bench/posegraph_reference.py's 1025.39805563 (the value in
/// src/sync/poses/tests.rs), in both orders, and another anchor: the same cost.
#[wasm_bindgen_test]
fn a_3d_grid_reaches_the_reference_in_both_orders() {
    let reference = 1025.39805563;
    let graph = read(SMALL_GRID);
    let result = solve(&graph, &[]).unwrap();
    assert!((cost(&result) - reference).abs() <= 1e-9 * reference, "{}", cost(&result));
    assert!(certified(&result));
    let xyzw = object(&[("order", "xyzw".into())]).unchecked_into();
    let graph_xyzw = read_g2o_text(&SMALL_GRID.into(), Some(xyzw)).unwrap();
    let other = solve(
        &graph_xyzw,
        &[("order", "xyzw".into()), ("anchor", 7.into()), ("maxRank", 5.into())],
    )
    .unwrap();
    assert!((cost(&other) - reference).abs() <= 1e-9 * reference, "{}", cost(&other));
    let rotations = floats(&other, "rotations");
    assert_eq!(&rotations[28..32], &[0.0, 0.0, 0.0, 1.0]);
    assert_eq!(&floats(&other, "translations")[21..24], &[0.0, 0.0, 0.0]);
}

/// A plain object with nested edges, quaternions and translations, default weights and count.
#[wasm_bindgen_test]
fn a_plain_square_is_exact() {
    let h = std::f64::consts::FRAC_1_SQRT_2;
    let quarter: &[f64] = &[h, 0.0, 0.0, h];
    let input = object(&[
        ("dimension", 2.into()),
        ("edges", nested(&[&[0.0, 1.0], &[1.0, 2.0], &[2.0, 3.0], &[3.0, 0.0]])),
        ("relative", nested(&[quarter, quarter, quarter, quarter])),
        ("translations", nested(&[&[1.0, 0.0, 0.0] as &[f64]; 4])),
    ]);
    let result = solve(&input, &[]).unwrap();
    assert!(cost(&result) < 1e-20 && certified(&result), "{}", cost(&result));
    let t = floats(&result, "translations");
    let expected = [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 1.0, 0.0];
    assert!(t.iter().zip(expected).all(|(a, b)| (a - b).abs() < 1e-12), "{t:?}");
}

#[wasm_bindgen_test]
fn bad_input_names_itself() {
    let h = std::f64::consts::FRAC_1_SQRT_2;
    let base = || {
        vec![
            ("dimension", JsValue::from(3)),
            ("edges", Uint32Array::from(&[0u32, 1, 1, 2][..]).into()),
            ("relative", nested(&[&[1.0, 0.0, 0.0, 0.0], &[h, 0.0, 0.0, h]])),
            ("translations", Float64Array::from(&[1.0, 0.0, 0.0, 0.0, 1.0, 0.0][..]).into()),
        ]
    };
    let with = |key: &'static str, value: JsValue| {
        let mut entries = base();
        entries.retain(|(k, _)| *k != key);
        entries.push((key, value));
        object(&entries)
    };
    let without = |key: &str| {
        let mut entries = base();
        entries.retain(|(k, _)| *k != key);
        object(&entries)
    };
    assert!(solve(&object(&base()), &[]).is_ok());
    let cases: Vec<(JsValue, Options, &str, &str)> = vec![
        (JsValue::from("graph"), vec![], "input", "invalid"),
        (JsValue::NULL, vec![], "input", "invalid"),
        (with("extra", 1.into()), vec![], "input", "invalid"),
        (without("dimension"), vec![], "dimension", "invalid"),
        (with("dimension", 4.into()), vec![], "dimension", "invalid"),
        (without("translations"), vec![], "translations", "invalid"),
        (with("translations", "x".into()), vec![], "translations", "invalid"),
        (
            with(
                "translations",
                Float64Array::from(&[1.0, 0.0, 0.0, 0.0, f64::NAN, 0.0][..]).into(),
            ),
            vec![],
            "translations[1]",
            "invalid",
        ),
        (with("translations", nested(&[&[1.0, 0.0, 0.0]])), vec![], "translations", "invalid"),
        (
            with("relative", nested(&[&[1.0, 0.0, 0.0, 0.0], &[f64::NAN, 0.0, 0.0, 1.0]])),
            vec![],
            "relative[1]",
            "not-finite",
        ),
        (
            with("relative", nested(&[&[1.0, 0.0, 0.0, 0.0], &[0.0, 0.0, 0.0, 0.0]])),
            vec![],
            "relative[1]",
            "zero-length",
        ),
        (
            with("weights", Float64Array::from(&[1.0, -2.0][..]).into()),
            vec![],
            "weights[1]",
            "out-of-range",
        ),
        (
            with("translationWeights", Float64Array::from(&[f64::NAN, 1.0][..]).into()),
            vec![],
            "translationWeights[0]",
            "out-of-range",
        ),
        (with("weights", Float64Array::from(&[1.0][..]).into()), vec![], "weights", "invalid"),
        (with("edges", nested(&[&[0.0, 1.0], &[1.0, 1.5]])), vec![], "edges[1]", "invalid"),
        (with("edges", nested(&[&[0.0, 1.0], &[1.0, 1.0]])), vec![], "edges[1]", "invalid"),
        (with("count", 2.into()), vec![], "edges[1]", "invalid"),
        (with("count", 4_294_967_295u32.into()), vec![], "edges", "invalid"),
        (object(&base()), vec![("anchor", 3.into())], "anchor", "invalid"),
        (object(&base()), vec![("anchor", (-1).into())], "anchor", "invalid"),
        (object(&base()), vec![("anchor", "0".into())], "anchor", "invalid"),
        (object(&base()), vec![("maxRank", 2.into())], "maxRank", "invalid"),
        (object(&base()), vec![("maxRank", 65.into())], "maxRank", "invalid"),
        (object(&base()), vec![("order", "zyx".into())], "order", "unknown-name"),
        (object(&base()), vec![("method", "robust".into())], "options", "invalid"),
    ];
    for (k, (input, options, argument, kind)) in cases.into_iter().enumerate() {
        let (got, got_kind, message) = refused(solve(&input, &options));
        assert_eq!((got.as_str(), got_kind.as_str()), (argument, kind), "case {k}: {message}");
        assert!(message.starts_with(argument), "case {k}: {message}");
    }
    // A 2D graph: rotations about z and translations in the plane only.
    let planar = |relative: JsValue, translations: JsValue| {
        object(&[
            ("dimension", 2.into()),
            ("edges", nested(&[&[0.0, 1.0]])),
            ("relative", relative),
            ("translations", translations),
        ])
    };
    let (argument, _, message) =
        refused(solve(&planar(nested(&[&[h, h, 0.0, 0.0]]), nested(&[&[1.0, 0.0, 0.0]])), &[]));
    assert_eq!(argument, "relative[0]", "{message}");
    let (argument, _, message) =
        refused(solve(&planar(nested(&[&[1.0, 0.0, 0.0, 0.0]]), nested(&[&[1.0, 0.0, 0.5]])), &[]));
    assert_eq!(argument, "translations[0]", "{message}");
    // A disconnected graph: the poses cut off are named.
    let disconnected = object(&[
        ("dimension", 3.into()),
        ("edges", nested(&[&[0.0, 1.0], &[2.0, 3.0]])),
        ("relative", nested(&[&[1.0, 0.0, 0.0, 0.0], &[1.0, 0.0, 0.0, 0.0]])),
        ("translations", nested(&[&[1.0, 0.0, 0.0], &[1.0, 0.0, 0.0]])),
    ]);
    let (argument, _, message) = refused(solve(&disconnected, &[]));
    assert_eq!(argument, "edges");
    assert!(message.contains("2, 3 are cut off from node 0"), "{message}");
    // The module keeps working after every refusal.
    assert!(solve(&object(&base()), &[]).is_ok());
}

/// `writeG2o`'s text read back: the same edges, κ, τ and measurements, the written poses as its
/// vertices, and the same optimum; in 2D (CSAIL) and 3D (smallGrid3D), in both orders.
#[wasm_bindgen_test]
fn written_graphs_read_back_as_they_were() {
    for (text, xyzw) in [(CSAIL, false), (SMALL_GRID, true)] {
        let options = || xyzw.then(|| object(&[("order", "xyzw".into())]));
        let graph = read_g2o_text(&text.into(), options().map(JsCast::unchecked_into)).unwrap();
        let solve_options: Vec<(&str, JsValue)> =
            if xyzw { vec![("order", "xyzw".into())] } else { vec![] };
        let result = solve(&graph, &solve_options).unwrap();
        let written = write_g2o(&graph, &result, options().map(JsCast::unchecked_into)).unwrap();
        let again = read_g2o_text(&written.into(), options().map(JsCast::unchecked_into)).unwrap();
        for key in ["dimension", "count"] {
            assert_eq!(field(&again, key), field(&graph, key), "{key}");
        }
        assert_eq!(floats(&again, "ids"), floats(&graph, "ids"));
        let edges = |g: &JsValue| field(g, "edges").unchecked_into::<Uint32Array>().to_vec();
        assert_eq!(edges(&again), edges(&graph));
        let close = |key: &str, a: Vec<f64>, b: Vec<f64>, tolerance: f64| {
            assert_eq!(a.len(), b.len(), "{key}");
            for (k, (x, y)) in a.iter().zip(&b).enumerate() {
                assert!((x - y).abs() <= tolerance * (1.0 + y.abs()), "{key}[{k}]: {x} vs {y}");
            }
        };
        for (key, tolerance) in [
            ("weights", 1e-14),
            ("translationWeights", 1e-14),
            ("translations", 0.0),
            ("relative", 1e-14),
            ("information", 0.0),
        ] {
            close(key, floats(&again, key), floats(&graph, key), tolerance);
        }
        // The written poses are the file's vertices now.
        close("initial", floats(&again, "initial"), floats(&result, "rotations"), 1e-14);
        let positions = floats(&again, "positions");
        assert_eq!(positions, floats(&result, "translations"));
        let resolved = solve(&again, &solve_options).unwrap();
        assert!((cost(&resolved) - cost(&result)).abs() <= 1e-9 * cost(&result));
    }
}

/// The file's information written back as it was read, off-diagonal entries too, so that
/// another tool weighs the written file's errors as it weighed the original's; a TORO file's
/// (EDGE3: on the angles; EDGE2: in TORO's order) written in g2o's units and order, which read
/// back give the TORO file's κ and τ; an `information` of the wrong length named.
#[wasm_bindgen_test]
fn written_edges_keep_the_files_information() {
    let full = "2 1 0 0.5 0 0 2 0 0 0 0 1 0 0 0 10 1 0 20 0 40";
    let text = format!(
        "EDGE_SE3:QUAT 0 1 1 0 0 0 0 0 1 {full}\nEDGE3 1 2 0 1 0 0 0 0.1 {full}\n\
         EDGE3 2 0 -1 -1 0 0 0 -0.1\n"
    );
    let graph = read(&text);
    let result = solve(&graph, &[]).unwrap();
    let written = write_g2o(&graph, &result, None).unwrap();
    let edges: Vec<&str> = written.lines().filter(|l| l.starts_with("EDGE")).collect();
    assert_eq!(edges.len(), 3, "{written}");
    // The g2o line's 21 numbers as they were.
    assert!(edges[0].ends_with(full), "{}", edges[0]);
    // The TORO line's in g2o's units: the coupling (0, 3) doubled, the rotation block ×4.
    assert!(edges[1].ends_with("2 1 0 1 0 0 2 0 0 0 0 1 0 0 0 40 4 0 80 0 160"), "{}", edges[1]);
    assert!(edges[2].ends_with("1 0 0 0 0 0 1 0 0 0 0 1 0 0 0 4 0 0 4 0 4"), "{}", edges[2]);
    let again = read(&written);
    for key in ["weights", "translationWeights", "information"] {
        assert_eq!(floats(&again, key), floats(&graph, key), "{key}");
    }
    // 2D: an EDGE2 line in TORO's order (I11 I12 I22 I33 I13 I23) written in g2o's.
    let graph = read("EDGE2 0 1 1 0 0 4 1 2 9 0 0\nEDGE2 1 0 -1 0 0 4 1 2 9 0 0\n");
    let written = write_g2o(&graph, &solve(&graph, &[]).unwrap(), None).unwrap();
    assert!(written.contains("EDGE_SE2 0 1 1 0 0 4 1 0 2 0 9\n"), "{written}");
    let again = read(&written);
    for key in ["weights", "translationWeights"] {
        assert_eq!(floats(&again, key), floats(&graph, key), "{key}");
    }
    // A graph's own information of the wrong length, or not finite, names it.
    let base = |information: &[f64]| {
        object(&[
            ("dimension", 2.into()),
            ("edges", nested(&[&[0.0, 1.0]])),
            ("relative", nested(&[&[1.0, 0.0, 0.0, 0.0]])),
            ("translations", nested(&[&[1.0, 0.0, 0.0]])),
            ("information", Float64Array::from(information).into()),
        ])
    };
    let (argument, _, message) = refused(solve(&base(&[1.0; 5]), &[]));
    assert_eq!(argument, "information");
    assert!(message.contains("6 numbers an edge") && message.contains("got 5"), "{message}");
    let (argument, ..) = refused(solve(&base(&[1.0, 0.0, 0.0, 1.0, 0.0, f64::NAN]), &[]));
    assert_eq!(argument, "information[5]");
    assert!(solve(&base(&[1.0, 0.0, 0.0, 1.0, 0.0, 1.0]), &[]).is_ok());
}

/// `writeG2o`'s lines, ids kept, and its refusals.
#[wasm_bindgen_test]
fn written_lines_keep_ids_and_bad_poses_are_named() {
    let text = "VERTEX_SE2 10 0 0 0\nVERTEX_SE2 20 1 0 0\nVERTEX_XY 15 3 3\n\
                EDGE_SE2 10 20 1 0 0.5 4 0 0 4 0 9\n";
    let graph = read(text);
    let poses = object(&[
        ("rotations", nested(&[&[1.0, 0.0, 0.0, 0.0], &[0.25f64.cos(), 0.0, 0.0, 0.25f64.sin()]])),
        ("translations", nested(&[&[0.0, 0.0, 0.0], &[1.0, 0.0, 0.0]])),
    ]);
    let written = write_g2o(&graph, &poses, None).unwrap();
    let expected =
        ["VERTEX_SE2 10 0 0 0", "VERTEX_SE2 20 1 0 0.5", "EDGE_SE2 10 20 1 0 0.5 4 0 0 4 0 9"];
    assert_eq!(written.lines().count(), 3, "{written}");
    for (line, want) in written.lines().zip(expected) {
        let (got, want): (Vec<&str>, Vec<&str>) =
            (line.split(' ').collect(), want.split(' ').collect());
        assert_eq!(got.len(), want.len(), "{line}");
        assert_eq!(got[..2], want[..2], "{line}");
        for (a, b) in got.iter().zip(&want).skip(2) {
            let (a, b) = (a.parse::<f64>().unwrap(), b.parse::<f64>().unwrap());
            assert!((a - b).abs() < 1e-15, "{line}");
        }
    }
    // Without ids, poses are numbered from 0; weights exact in exponent form far from 1.
    let plain = object(&[
        ("dimension", 3.into()),
        ("edges", nested(&[&[0.0, 1.0]])),
        ("relative", nested(&[&[1.0, 0.0, 0.0, 0.0]])),
        ("translations", nested(&[&[1e-7, 0.0, 0.0]])),
        ("weights", Float64Array::from(&[2.5e20][..]).into()),
    ]);
    let poses3 = object(&[
        ("rotations", nested(&[&[1.0, 0.0, 0.0, 0.0], &[1.0, 0.0, 0.0, 0.0]])),
        ("translations", nested(&[&[0.0, 0.0, 0.0], &[1e-7, 0.0, 0.0]])),
    ]);
    let written = write_g2o(&plain, &poses3, None).unwrap();
    assert_eq!(
        written,
        "VERTEX_SE3:QUAT 0 0 0 0 0 0 0 1\nVERTEX_SE3:QUAT 1 1e-7 0 0 0 0 0 1\n\
         EDGE_SE3:QUAT 0 1 1e-7 0 0 0 0 0 1 1 0 0 0 0 0 1 0 0 0 0 1 0 0 0 5e20 0 0 5e20 0 5e20\n"
    );
    let again = read(&written);
    assert!((floats(&again, "weights")[0] / 2.5e20 - 1.0).abs() < 1e-15);
    // Refusals name the argument.
    let run = |graph: &JsValue, poses: &JsValue, options: &[(&str, JsValue)]| {
        let options = (!options.is_empty()).then(|| object(options).unchecked_into());
        refused(write_g2o(graph, poses, options))
    };
    let one_pose = object(&[
        ("rotations", nested(&[&[1.0, 0.0, 0.0, 0.0]])),
        ("translations", nested(&[&[0.0, 0.0, 0.0]])),
    ]);
    let tilted = object(&[
        ("rotations", nested(&[&[1.0, 0.0, 0.0, 0.0], &[0.6, 0.8, 0.0, 0.0]])),
        ("translations", nested(&[&[0.0, 0.0, 0.0], &[1.0, 0.0, 0.0]])),
    ]);
    let lifted = object(&[
        ("rotations", nested(&[&[1.0, 0.0, 0.0, 0.0], &[1.0, 0.0, 0.0, 0.0]])),
        ("translations", nested(&[&[0.0, 0.0, 0.0], &[1.0, 0.0, f64::NAN]])),
    ]);
    let descending = object(&[
        ("dimension", 3.into()),
        ("edges", nested(&[&[0.0, 1.0]])),
        ("relative", nested(&[&[1.0, 0.0, 0.0, 0.0]])),
        ("translations", nested(&[&[1.0, 0.0, 0.0]])),
        ("ids", Float64Array::from(&[5.0, 3.0][..]).into()),
    ]);
    // A count of 2³² − 1: 4n is beyond wasm32's usize.
    let huge_count = object(&[
        ("dimension", 3.into()),
        ("edges", nested(&[&[0.0, 1.0]])),
        ("relative", nested(&[&[1.0, 0.0, 0.0, 0.0]])),
        ("translations", nested(&[&[1.0, 0.0, 0.0]])),
        ("count", 4_294_967_295u32.into()),
    ]);
    let cases: Vec<(JsValue, JsValue, Options, &str)> = vec![
        (JsValue::from(3), poses.clone(), vec![], "graph"),
        (graph.clone(), JsValue::UNDEFINED, vec![], "poses"),
        (graph.clone(), object(&[("quaternions", nested(&[]))]), vec![], "poses"),
        (graph.clone(), object(&[("rotations", nested(&[]))]), vec![], "rotations"),
        (graph.clone(), one_pose, vec![], "rotations"),
        (graph.clone(), tilted, vec![], "rotations[1]"),
        (graph.clone(), lifted.clone(), vec![], "translations[1]"),
        (plain.clone(), lifted, vec![], "translations[1]"),
        (descending, poses3.clone(), vec![], "ids[1]"),
        (huge_count, poses3.clone(), vec![], "rotations"),
        (plain, poses3, vec![("order", 1.into())], "order"),
        (graph, poses, vec![("strict", true.into())], "options"),
    ];
    for (k, (graph, poses, options, argument)) in cases.into_iter().enumerate() {
        let (got, _, message) = run(&graph, &poses, &options);
        assert_eq!(got, argument, "case {k}: {message}");
    }
}
