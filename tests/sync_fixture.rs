//! `kli::sync` against GTSAM: tests/fixtures/sync.json holds the chordal optimum of each graph as
//! GTSAM's Levenberg–Marquardt finds it on its own Frobenius factors, and the certificate's
//! eigenvalues by NumPy's dense `eigvalsh` (bench/sync_fixture.py). Every rotation agrees to 1e-9.
#![cfg(not(target_arch = "wasm32"))]

use kli::sync::{Graph, SyncOptions, synchronize};
use kli::{DQuat, from_wxyz};
use serde_json::Value;

fn quaternions(value: &Value) -> Vec<DQuat> {
    value
        .as_array()
        .unwrap()
        .iter()
        .map(|q| {
            let q: Vec<f64> = q.as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect();
            from_wxyz([q[0], q[1], q[2], q[3]])
        })
        .collect()
}

#[test]
fn chordal_optima_match_gtsam_to_1e_9() {
    let fixture: Value =
        serde_json::from_str(include_str!("fixtures/sync.json")).expect("the fixture is JSON");
    let cases = fixture["cases"].as_array().unwrap();
    assert!(cases.len() >= 3);
    for case in cases {
        let name = case["name"].as_str().unwrap();
        let edges: Vec<[usize; 2]> = case["edges"]
            .as_array()
            .unwrap()
            .iter()
            .map(|e| [e[0].as_u64().unwrap() as usize, e[1].as_u64().unwrap() as usize])
            .collect();
        let weights: Vec<f64> =
            case["weights"].as_array().unwrap().iter().map(|w| w.as_f64().unwrap()).collect();
        let count = case["count"].as_u64().unwrap() as usize;
        let graph =
            Graph::new(Some(count), &edges, &quaternions(&case["relative"]), Some(&weights))
                .unwrap();
        let result = synchronize(&graph, &SyncOptions::default()).unwrap();
        let expected = quaternions(&case["rotations"]);
        for (i, (q, e)) in result.rotations.iter().zip(&expected).enumerate() {
            let gap = (*q - *e).length();
            assert!(gap < 1e-9, "{name}: node {i}: {q:?} vs GTSAM's {e:?}");
        }
        let cost = case["cost"].as_f64().unwrap();
        assert!((result.cost - cost).abs() < 1e-9 * cost, "{name}: {} vs {cost}", result.cost);
        let eigenvalues: Vec<f64> =
            case["eigenvalues"].as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect();
        let certificate = result.certificate.unwrap();
        assert!(certificate.certified, "{name}");
        assert!(
            (certificate.gap - eigenvalues[3]).abs() < 1e-7 * eigenvalues[3],
            "{name}: λ₄ {} vs NumPy's {}",
            certificate.gap,
            eigenvalues[3]
        );
    }
}
