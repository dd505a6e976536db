//! Reading pose graphs: each line kind against its definition, the weights against MATH.md's
//! formulas worked by hand, landmarks skipped, and every refusal with its line.

use std::f64::consts::PI;

use glam::{DMat3, DQuat, DVec3};

use super::*;

/// The angle between two rotations, blind to sign.
fn angle(a: DQuat, b: DQuat) -> f64 {
    let e = a.conjugate() * b;
    2.0 * DVec3::new(e.x, e.y, e.z).length().atan2(e.w.abs())
}

fn read(text: &str) -> PoseGraph {
    read_g2o(text, OtherLines::Skip).unwrap()
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-14 * b.abs().max(1.0)
}

/// The 6×6 identity's upper triangle, row by row.
const IDENTITY6: &str = "1 0 0 0 0 0 1 0 0 0 0 1 0 0 0 1 0 0 1 0 1";

#[test]
fn g2o_and_toro_3d_lines_are_read() {
    // One g2o edge (qx qy qz qw = a quarter turn about z), one TORO edge (roll, pitch, yaw), the
    // vertices of all three nodes, a comment, FIX, information entries and a blank line.
    let text = format!(
        "# a pose graph\n\
         VERTEX_SE3:QUAT 0 0 0 0 0 0 0 1\n\
         VERTEX_SE3:QUAT 1 1 2 3 0 0 0.7071067811865476 0.7071067811865476\n\
         VERTEX3 2 0 0 0 0.1 0.2 0.3\n\
         \n\
         FIX 0\n\
         EDGE_SE3:QUAT 0 1 1 0 0 0 0 0.7071067811865476 0.7071067811865476 {IDENTITY6}\n\
         EDGE3 1 2 4 5 6 0.1 0.2 0.3\n"
    );
    let graph = read(&text);
    assert_eq!((graph.dimension, graph.count), (3, 3));
    assert_eq!(graph.ids, vec![0, 1, 2]);
    assert_eq!(graph.edges, vec![[0, 1], [1, 2]]);
    assert!(graph.skipped.is_empty());
    assert!(angle(graph.relative[0], DQuat::from_rotation_z(PI / 2.0)) < 1e-15);
    // R = Rz(yaw) Ry(pitch) Rx(roll), multiplied out as matrices.
    let (roll, pitch, yaw): (f64, f64, f64) = (0.1, 0.2, 0.3);
    let rx = DMat3::from_cols_array_2d(&[
        [1.0, 0.0, 0.0],
        [0.0, roll.cos(), roll.sin()],
        [0.0, -roll.sin(), roll.cos()],
    ]);
    let ry = DMat3::from_cols_array_2d(&[
        [pitch.cos(), 0.0, -pitch.sin()],
        [0.0, 1.0, 0.0],
        [pitch.sin(), 0.0, pitch.cos()],
    ]);
    let rz = DMat3::from_cols_array_2d(&[
        [yaw.cos(), yaw.sin(), 0.0],
        [-yaw.sin(), yaw.cos(), 0.0],
        [0.0, 0.0, 1.0],
    ]);
    let expected = rz * ry * rx;
    let got = DMat3::from_quat(graph.relative[1]);
    assert!((got - expected).to_cols_array().iter().all(|d| d.abs() < 1e-15));
    assert_eq!(graph.translations, vec![DVec3::new(1.0, 0.0, 0.0), DVec3::new(4.0, 5.0, 6.0)]);
    // The identity's information, written or not: τ = 3 / tr(I₃) = 1, κ = 3 / (2 tr(I₃)) = ½ on
    // the g2o line; on the TORO line the identity is on the angles, 4 I₃ in g2o's half-angle
    // units: κ = 3 / (2 tr(I₃ / 4)) = 2.
    assert_eq!(graph.rotation_weights, vec![0.5, 2.0]);
    assert_eq!(graph.translation_weights, vec![1.0, 1.0]);
    let initial = graph.initial.unwrap();
    assert!(angle(initial[1], DQuat::from_rotation_z(PI / 2.0)) < 1e-15);
    assert!(angle(initial[2], graph.relative[1]) < 1e-15);
    assert_eq!(graph.positions.unwrap()[1], DVec3::new(1.0, 2.0, 3.0));
    // Without a vertex for every node, no initial estimate.
    let graph = read("VERTEX3 0 0 0 0 0 0 0\nEDGE3 0 1 0 0 0 0 0 0\n");
    assert!(graph.initial.is_none() && graph.positions.is_none());
}

#[test]
fn weights_in_3d_are_se_syncs() {
    // Translation block [[2, 1, 0], [1, 2, 0], [0, 0, 1]]: its inverse's trace is
    // (2 + 2)/3 + 1 = 7/3, so τ = 3 / (7/3) = 9/7. Rotation block diag(10, 20, 40): tr Σ_R =
    // 0.175, κ = 3 / 0.35 = 60/7. The coupling entry (0, 3) = 0.5 belongs to neither block.
    let information = "2 1 0 0.5 0 0  2 0 0 0 0  1 0 0 0  10 0 0  20 0  40";
    let graph = read(&format!("EDGE_SE3:QUAT 0 1 0 0 0 0 0 0 1 {information}\n"));
    assert!(close(graph.translation_weights[0], 9.0 / 7.0), "{:?}", graph.translation_weights);
    assert!(close(graph.rotation_weights[0], 60.0 / 7.0), "{:?}", graph.rotation_weights);
    // The same entries on a TORO line: its rotation block is on the angles, diag(40, 80, 160) in
    // g2o's half-angle units, tr Σ_R = 0.04375, κ = 3 / 0.0875 = 240/7; τ as before.
    let graph = read(&format!("EDGE3 0 1 0 0 0 0 0 0 {information}\n"));
    assert!(close(graph.translation_weights[0], 9.0 / 7.0));
    assert!(close(graph.rotation_weights[0], 240.0 / 7.0), "{:?}", graph.rotation_weights);
}

/// Each edge's information as written, in g2o's order and units: a g2o line's numbers as they
/// are; a TORO `EDGE3` line's rotation rows from angles to half-angles (the error quaternion's
/// vector part is half the angle, so the same noise has 4 times the information: the rotation
/// block times 4, the coupling block times 2); an `EDGE2` line's TORO order rearranged; the
/// identity's, in the line's own units, where a line has none.
#[test]
fn information_is_kept_in_g2os_order_and_units() {
    let upper3 = [2.0, 1.0, 0.0, 0.5, 0.0, 0.0, 2.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0];
    let rotation = [10.0, 0.0, 0.0, 20.0, 0.0, 40.0];
    let words = |x: &[f64]| x.iter().map(f64::to_string).collect::<Vec<_>>().join(" ");
    let information: Vec<f64> = upper3.iter().chain(&rotation).copied().collect();
    let text = format!(
        "EDGE_SE3:QUAT 0 1 0 0 0 0 0 0 1 {0}\nEDGE3 1 2 0 0 0 0 0 0 {0}\nEDGE3 2 0 0 0 0 0 0 0\n",
        words(&information)
    );
    let graph = read(&text);
    assert_eq!(graph.information.len(), 3 * 21);
    assert_eq!(graph.information[..21], information[..]);
    // Row 0's entries in columns 3–5 (the coupling, here (0, 3) = 0.5) double; the rotation
    // block's entries quadruple; the translation block stays.
    let toro: Vec<f64> =
        [2.0, 1.0, 0.0, 1.0, 0.0, 0.0, 2.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0]
            .into_iter()
            .chain([40.0, 0.0, 0.0, 80.0, 0.0, 160.0])
            .collect();
    assert_eq!(graph.information[21..42], toro[..]);
    // No information on the TORO line: the identity on the angles, diag(1, 1, 1, 4, 4, 4).
    let diagonal: Vec<f64> = (0..6)
        .flat_map(|r| (r..6).map(move |c| (r, c)))
        .map(|(r, c)| {
            if r != c {
                0.0
            } else if r < 3 {
                1.0
            } else {
                4.0
            }
        })
        .collect();
    assert_eq!(graph.information[42..], diagonal[..]);
    // 2D: EDGE_SE2 as written; EDGE2 in TORO's order (I11 I12 I22 I33 I13 I23 = 4 1 2 9 0 0,
    // whose g2o reading has I33 = 0) rearranged to g2o's (I11 I12 I13 I22 I23 I33); none: the
    // identity.
    let graph = read(
        "EDGE_SE2 0 1 1 0 0 4 1 0.3 2 0.2 9\nEDGE2 1 2 1 0 0 4 1 2 9 0 0\nEDGE_SE2 2 0 1 0 0\n",
    );
    assert_eq!(
        graph.information,
        vec![
            4.0, 1.0, 0.3, 2.0, 0.2, 9.0, 4.0, 1.0, 0.0, 2.0, 0.0, 9.0, 1.0, 0.0, 0.0, 1.0, 0.0,
            1.0
        ]
    );
}

#[test]
fn planar_lines_are_read_with_their_weights() {
    // Information [[4, 1, 0.3], [1, 2, 0.2], [0.3, 0.2, 9]] (x, y, θ): Σ_t = [[4, 1], [1, 2]]⁻¹
    // = [[2, −1], [−1, 4]] / 7, trace 6/7, τ = 2 / (6/7) = 7/3; κ = I_θθ = 9. g2o writes the
    // upper triangle row by row; the EDGE2 line writes it (with I13 = I23 = 0) as TORO does,
    // I11 I12 I22 I33 I13 I23.
    let text = "VERTEX_SE2 0 0 0 0\n\
                VERTEX_SE2 1 1 0 0.5\n\
                VERTEX2 2 1 1 1.0\n\
                EDGE_SE2 0 1 1 0 0.5 4 1 0.3 2 0.2 9\n\
                EDGE2 1 2 0.5 1 0.5 4 1 2 9 0 0\n\
                EDGE_SE2 2 0 -1 -1 -1\n";
    let graph = read(text);
    assert_eq!((graph.dimension, graph.count), (2, 3));
    assert_eq!(graph.edges, vec![[0, 1], [1, 2], [2, 0]]);
    for (q, theta) in graph.relative.iter().zip([0.5, 0.5, -1.0]) {
        assert!(angle(*q, DQuat::from_rotation_z(theta)) < 1e-15);
    }
    assert_eq!(graph.translations[1], DVec3::new(0.5, 1.0, 0.0));
    for k in 0..2 {
        assert!(close(graph.translation_weights[k], 7.0 / 3.0), "{:?}", graph.translation_weights);
        assert_eq!(graph.rotation_weights[k], 9.0);
    }
    // Without information, the identity's: τ = 2 / tr(I₂) = 1, κ = 1.
    assert_eq!((graph.rotation_weights[2], graph.translation_weights[2]), (1.0, 1.0));
    let initial = graph.initial.unwrap();
    assert!(angle(initial[2], DQuat::from_rotation_z(1.0)) < 1e-15);
    assert_eq!(graph.positions.unwrap()[2], DVec3::new(1.0, 1.0, 0.0));
}

#[test]
fn toro_edges_are_read_in_either_order_of_their_information() {
    // diag(3, 3, 5) written in g2o's order (GTSAM's w20000.txt) and in TORO's (its .graph
    // files): each is positive definite in only its own reading. τ = 2 / (2/3) = 3, κ = 5.
    for information in ["3 0 0 3 0 5", "3 0 3 5 0 0"] {
        let graph = read(&format!("EDGE2 0 1 1 0 0 {information}\n"));
        assert!(close(graph.translation_weights[0], 3.0), "{information}");
        assert_eq!(graph.rotation_weights[0], 5.0, "{information}");
    }
    // Positive definite both ways: g2o's reading (I22 = 2, I33 = 7; TORO's would be I33 = 2).
    let graph = read("EDGE2 0 1 1 0 0 4 1 1 2 0 7\n");
    assert_eq!(graph.rotation_weights[0], 7.0);
    // EDGE_SE2 is g2o's alone: TORO's order there is refused.
    assert!(read_g2o("EDGE_SE2 0 1 1 0 0 3 0 3 5 0 0\n", OtherLines::Skip).is_err());
}

#[test]
fn landmarks_and_other_lines_are_skipped_and_counted() {
    // Poses 0, 2 and 5 with landmarks 1 and 3 among their ids, a prior and a parameter line.
    let text = "VERTEX_SE2 0 0 0 0\n\
                VERTEX_XY 1 3 4\n\
                VERTEX_SE2 2 1 0 0\n\
                VERTEX_XY 3 5 5\n\
                VERTEX_SE2 5 2 0 0\n\
                PARAMS_SE2OFFSET 0 0 0 0\n\
                EDGE_SE2 0 2 1 0 0\n\
                EDGE_SE2_XY 0 1 3 4 1 0 1\n\
                EDGE_SE2 2 5 1 0 0\n\
                EDGE_SE2_XY 2 3 4 5 1 0 1\n\
                EDGE_SE2_XY 5 3 3 5 1 0 1\n\
                EDGE_PRIOR_SE2 0 0 0 0 1 0 0 1 0 1\n";
    let graph = read(text);
    assert_eq!(graph.ids, vec![0, 2, 5]);
    assert_eq!(graph.count, 3);
    assert_eq!(graph.edges, vec![[0, 1], [1, 2]]);
    assert!(graph.initial.is_some());
    let skipped: Vec<(&str, usize)> = graph.skipped.iter().map(|(k, n)| (k.as_str(), *n)).collect();
    assert_eq!(
        skipped,
        vec![("VERTEX_XY", 2), ("PARAMS_SE2OFFSET", 1), ("EDGE_SE2_XY", 3), ("EDGE_PRIOR_SE2", 1)]
    );
    // A synchronisable graph: the landmarks' ids left no node cut off.
    let g = Graph::new(Some(graph.count), &graph.edges, &graph.relative, None).unwrap();
    assert_eq!(g.count(), 3);
    // Refused when asked, by the first such line.
    let e = read_g2o(text, OtherLines::Refuse).unwrap_err();
    assert_eq!(e.kind().line(), Some(2));
    assert_eq!(e.kind().code(), "invalid");
}

#[test]
fn the_weights_decide_a_planar_loop() {
    // A triangle of planar edges with a loop error of 0.6 rad and rotation weights 1, 2 and 4.
    // The chordal cost Σ 8κ sin²(θ_k/2) under Σ θ_k = 0.6 is stationary where κ_k sin θ_k is
    // the same on every edge (Lagrange): the stiffer edge takes less of the error.
    let text = "EDGE_SE2 0 1 0 0 0.2 1 0 0 1 0 1\n\
                EDGE_SE2 1 2 0 0 0.2 1 0 0 1 0 2\n\
                EDGE_SE2 2 0 0 0 0.2 1 0 0 1 0 4\n";
    let pose = read(text);
    let graph =
        Graph::new(Some(3), &pose.edges, &pose.relative, Some(&pose.rotation_weights)).unwrap();
    let result = synchronize(&graph, &SyncOptions::default()).unwrap();
    assert!(result.certificate.unwrap().certified);
    for q in &result.rotations {
        assert!(q.x.abs() < 1e-12 && q.y.abs() < 1e-12, "a planar graph stays about z: {q:?}");
    }
    let balance: Vec<f64> =
        result.residuals.iter().zip(&pose.rotation_weights).map(|(t, k)| k * t.sin()).collect();
    assert!((balance[0] - balance[1]).abs() < 1e-9 && (balance[0] - balance[2]).abs() < 1e-9);
    assert!((result.residuals.iter().sum::<f64>() - 0.6).abs() < 1e-9, "{:?}", result.residuals);
    assert!(result.residuals[0] > result.residuals[1] && result.residuals[1] > result.residuals[2]);
}

#[test]
fn bad_lines_are_refused_with_their_number() {
    let refused = |text: &str| {
        let e = read_g2o(text, OtherLines::Skip).unwrap_err();
        (e.kind().line(), e.message(&|s| s.to_string(), &|x| x.to_string()))
    };
    let edge = "EDGE3 0 1 0 0 0 0 0 0\n";
    // Ids need not be small or consecutive: the largest u64 is an id.
    let graph = read("EDGE3 0 18446744073709551615 0 0 0 0 0 0\n");
    assert_eq!(graph.ids, vec![0, u64::MAX]);
    let (line, m) = refused("");
    assert!(line.is_none() && m.starts_with("text holds no pose edge"), "{m}");
    assert!(
        refused("# only a comment\nVERTEX_XY 0 1 1\n").1.starts_with("text holds no pose edge")
    );
    assert!(refused("VERTEX_SE2 0 0 0 0\n").1.starts_with("text holds no pose edge"));
    let cases = [
        (
            format!("{edge}EDGE_SE2 0 1 0 0 0\n"),
            2,
            "EDGE_SE2 is a 2D pose, but line 1 was a 3D one",
        ),
        (
            format!("{edge}{edge}EDGE3 0 1 0 0 0 0 0\n"),
            3,
            "EDGE3 needs 8 numbers after the tag (got 7)",
        ),
        ("EDGE_SE2 0 1 0 0\n".into(), 1, "EDGE_SE2 needs 5 numbers after the tag (got 4)"),
        ("EDGE3 0 -1 0 0 0 0 0 0\n".into(), 1, "node id \"-1\" is not a non-negative integer"),
        ("EDGE3 0 1.5 0 0 0 0 0 0\n".into(), 1, "node id \"1.5\" is not a non-negative integer"),
        ("EDGE_SE3:QUAT 0 1 0 0 0 0 0 0 0\n".into(), 1, "the quaternion has zero length"),
        ("EDGE_SE3:QUAT 0 1 0 0 0 nan 0 0 1\n".into(), 1, "\"nan\" is not a finite number"),
        ("EDGE_SE2 0 1 0 0 0 1 0 0\n".into(), 1, "has 3 of the 6 entries of its information"),
        (
            "EDGE_SE2 0 1 0 0 0 1 0 0 1 0 0\n".into(),
            1,
            "information matrix's rotation block is not",
        ),
        ("EDGE_SE2 0 1 0 0 0 1 2 0 1 0 1\n".into(), 1, "information matrix's translation block is"),
        ("EDGE2 0 1 0 0 0 1 0 1 -1 0 0\n".into(), 1, "block is not positive definite"),
        ("EDGE2 0 1 0 0 0 1 0 0 0 0 1\n".into(), 1, "information matrix's translation block is"),
        (
            "EDGE_SE3:QUAT 0 1 0 0 0 0 0 0 1 1 0 0 0 0 0 1 0 0 0 0 1 0 0 0 0 0 0 1 0 1\n".into(),
            1,
            "information matrix's rotation block is not positive definite",
        ),
        (
            "EDGE3 0 1 0 0 0 0 0 0 1 0 0 0 0 0 -1 0 0 0 0 1 0 0 0 1 0 0 1 0 1\n".into(),
            1,
            "information matrix's translation block is not positive definite",
        ),
        (format!("{edge}EDGE3 0 18446744073709551616 0 0 0 0 0 0\n"), 2, "is too large"),
    ];
    for (text, line, problem) in cases {
        let (got, m) = refused(&text);
        assert_eq!(got, Some(line), "{text:?}: {m}");
        assert!(m.starts_with(&format!("text line {line}: ")), "{m}");
        assert!(m.contains(problem), "{text:?}: {m}");
    }
}
