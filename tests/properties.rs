//! Property tests over random and adversarial pairs (native only): near-identical and
//! near-antipodal pairs 1e-12 apart, and inputs scaled to tiny and huge magnitudes.
#![cfg(not(target_arch = "wasm32"))]

use kli::{
    DQuat, ErrorKind, Integrator, KliOptions, batch, from_wxyz, hopf, kli, kli_exact,
    kli_to_slerp_parameter, slerp,
};
use proptest::prelude::*;

fn unit4() -> impl Strategy<Value = DQuat> {
    prop::array::uniform4(-1.0..1.0_f64)
        .prop_filter("not too short", |v| v.iter().map(|c| c * c).sum::<f64>() > 1e-4)
        .prop_map(|v| from_wxyz(v).normalize())
}

/// How the second end is made from the first.
#[derive(Debug, Clone, Copy)]
enum Pair {
    Random,
    NearIdentical,
    NearAntipodal,
}

fn pair() -> impl Strategy<Value = (DQuat, DQuat, Pair)> {
    (
        unit4(),
        unit4(),
        prop_oneof![Just(Pair::Random), Just(Pair::NearIdentical), Just(Pair::NearAntipodal)],
    )
        .prop_map(|(p, other, kind)| {
            // A unit direction orthogonal to p, so the 1e-12 offset is not lost to normalisation.
            let across = other - p * other.dot(p);
            let across = if across.length() > 1e-3 {
                across.normalize()
            } else {
                DQuat::from_xyzw(-p.y, p.x, -p.w, p.z)
            };
            let r = match kind {
                Pair::Random => other,
                Pair::NearIdentical => (p + across * 1e-12).normalize(),
                Pair::NearAntipodal => (-p + across * 1e-12).normalize(),
            };
            (p, r, kind)
        })
}

/// Tiny, ordinary and huge scales of the same input.
fn scale() -> impl Strategy<Value = f64> {
    prop_oneof![Just(1.0), 1e-300..1e-250_f64, 1e250..1e300_f64, 1e-8..1e8_f64]
}

fn is_unit(q: DQuat) -> bool {
    q.is_finite() && (q.length() - 1.0).abs() < 1e-14
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(384))]

    #[test]
    fn outputs_are_unit_and_finite((p, r, _) in pair(), shortest in any::<bool>(), t in 0.0..60.0_f64, s in 0.0..=1.0_f64) {
        for q in [kli_exact(p, r, t, shortest), slerp(p, r, s, shortest)] {
            let q = q.unwrap();
            prop_assert!(is_unit(q), "{q:?}");
            prop_assert!((hopf(q).length() - 1.0).abs() < 1e-14);
        }
        let warp = kli_to_slerp_parameter(p, r, t, shortest).unwrap();
        prop_assert!((0.0..=1.0).contains(&warp));
    }

    #[test]
    fn scale_does_not_matter((p, r, _) in pair(), a in scale(), b in scale(), t in 0.0..20.0_f64) {
        let plain = kli_exact(p, r, t, true).unwrap();
        let scaled = kli_exact(p * a, r * b, t, true).unwrap();
        prop_assert!((plain - scaled).length() < 1e-14, "{plain:?} vs {scaled:?}");
    }

    #[test]
    fn closed_form_is_slerp_with_another_clock((p, r, _) in pair(), shortest in any::<bool>(), t in 0.0..40.0_f64) {
        let s = kli_to_slerp_parameter(p, r, t, shortest).unwrap();
        let via_slerp = slerp(p, r, s, shortest).unwrap();
        prop_assert!((kli_exact(p, r, t, shortest).unwrap() - via_slerp).length() < 1e-12);
    }

    #[test]
    fn integrated_path_is_the_slerp_path_reparametrised(
        (p, r, kind) in pair(),
        shortest in any::<bool>(),
        integrator in prop_oneof![Just(Integrator::Rk4), Just(Integrator::Geodesic)],
    ) {
        let options = KliOptions { integrator, shortest_path: shortest, ..Default::default() };
        let path = match kli(p, r, &options) {
            // RK4 works in R⁴, where near -r the sphere repels rounding errors (see LeftSphere):
            // a clear error is the right answer there; the geodesic integrator must succeed.
            Err(e) if matches!(e.kind(), ErrorKind::LeftSphere { .. })
                && integrator == Integrator::Rk4
                && !shortest
                && matches!(kind, Pair::NearAntipodal) =>
            {
                return Ok(());
            }
            other => other.unwrap(),
        };
        let target = path.target();
        // On the short way (φ0 ≤ π/2) the step error stays below 1e-9 (measured ≤ 1.5e-10).
        // The long way starts near the unstable equilibrium -r, which amplifies step errors
        // while the flow leaves it: measured up to 5.4e-9 for RK4 on random pairs
        // (`cargo run --release --example accuracy`), bounded here by 1e-8.
        let bound = if shortest || p.dot(r) >= 0.0 { 1e-9 } else { 1e-8 };
        let mut previous = f64::INFINITY;
        for (&t, &q) in path.times().iter().zip(path.quaternions()) {
            prop_assert!(q.is_finite() && (q.length() - 1.0).abs() < bound, "|q| = {}", q.length());
            // The distance to the target never increases.
            let distance = (target - q).length();
            prop_assert!(distance <= previous + 1e-14, "t = {t}: {distance} after {previous}");
            previous = distance;
            // Near-antipodal ends taken the long way are ill-conditioned: a rounding of the inputs
            // (1e-16) turns the great circle by ~1e-4, in the model itself. Only the rest is
            // compared with SLERP.
            if shortest || !matches!(kind, Pair::NearAntipodal) {
                let on_slerp = slerp(p, r, kli_to_slerp_parameter(p, r, t, shortest).unwrap(), shortest).unwrap();
                prop_assert!((q - on_slerp).length() < bound, "t = {t}: {}", (q - on_slerp).length());
            }
        }
        prop_assert!(previous < options.tolerance);
    }

    #[test]
    fn batches_are_the_single_calls_pair_by_pair(
        pairs in prop::collection::vec((pair(), 0.0..=1.0_f64, 0.0..40.0_f64), 1..12),
        shortest in any::<bool>(),
    ) {
        // Any count (whole steps of two and four pairs and every padded rest), any mix of the
        // kernels' common case and the pairs they hand back to the general loop.
        let flat = |q: DQuat| [q.w, q.x, q.y, q.z];
        let starts: Vec<f64> = pairs.iter().flat_map(|((p, _, _), _, _)| flat(*p)).collect();
        let ends: Vec<f64> = pairs.iter().flat_map(|((_, r, _), _, _)| flat(*r)).collect();
        let s: Vec<f64> = pairs.iter().map(|(_, s, _)| *s).collect();
        let t: Vec<f64> = pairs.iter().map(|(_, _, t)| *t).collect();
        let n = pairs.len();
        let (mut sl, mut kl, mut nl) = (vec![0.0; 4 * n], vec![0.0; 4 * n], vec![0.0; 4 * n]);
        batch::slerp_batch(&starts, &ends, &s, &mut sl, shortest).unwrap();
        batch::kli_exact_batch(&starts, &ends, &t, &mut kl, shortest).unwrap();
        batch::nlerp_batch(&starts, &ends, &s, &mut nl).unwrap();
        for (i, ((p, r, _), s, t)) in pairs.iter().enumerate() {
            let near = |batch: &[f64], single: DQuat, what: &str| -> Result<(), TestCaseError> {
                let single = flat(single);
                for c in 0..4 {
                    let error = (batch[4 * i + c] - single[c]).abs();
                    prop_assert!(error < 2e-15, "{what}, pair {i} of {n}: {error:e}");
                }
                Ok(())
            };
            near(&sl, slerp(*p, *r, *s, shortest).unwrap(), "slerp")?;
            near(&kl, kli_exact(*p, *r, *t, shortest).unwrap(), "kli_exact")?;
            let r = if p.dot(*r) < 0.0 { -*r } else { *r };
            near(&nl, (*p + (r - *p) * *s).normalize(), "nlerp")?;
        }
    }

    #[test]
    fn euler_still_converges((p, r, _) in pair()) {
        let path = kli(p, r, &KliOptions { integrator: Integrator::Euler, ..Default::default() }).unwrap();
        let last = *path.quaternions().last().unwrap();
        prop_assert!((path.target() - last).length() < 1e-5);
    }
}
