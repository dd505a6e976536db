//! The averaging page's model: its means are the core's, its flow ends on the chordal mean, its
//! measurements follow the recipe, and the sweep reproduces MATH.md's robustness ordering.

use kli::average::{Method, angle, average};

use super::model::{Model, Options, STYLES, measurements, sweep_point};

fn options(count: usize, noise: f64, outliers: f64, seed: u64) -> Options {
    Options { count, noise, outliers, seed, moved: vec![] }
}

#[test]
fn the_means_are_the_cores_and_the_follower_arrives_at_the_chordal_mean() {
    let model = Model::new(options(60, 5.0, 0.2, 4)).unwrap();
    for (mean, style) in model.means.iter().zip(&STYLES) {
        let core = average(&model.data, None, style.method).unwrap();
        assert_eq!(mean.rotation, core.rotation, "{}", style.name);
    }
    let end = model.end_time();
    assert!(end > 1.0 && end < 60.0, "flow time {end}");
    assert_eq!(model.follower(0.0), glam::DQuat::IDENTITY);
    assert!(angle(model.follower(end), model.means[0].rotation) < 1e-4);
    // Before the end it has not arrived: the span is the flow's, not padding.
    assert!(angle(model.follower(0.5 * end), model.means[0].rotation) > 1e-4);
}

#[test]
fn measurements_follow_the_recipe_and_the_seed() {
    let o = options(2000, 5.0, 0.3, 9);
    let (truth, data, wild) = measurements(&o);
    assert_eq!(measurements(&o).1, data);
    let share = wild.iter().filter(|&&w| w).count() as f64 / 2000.0;
    assert!((share - 0.3).abs() < 0.04, "wild share {share}");
    // Noise of 5° about each axis: the angle to the truth is 5°·χ₃, RMS 5°·√3.
    let squares: Vec<f64> = data
        .iter()
        .zip(&wild)
        .filter(|(_, w)| !**w)
        .map(|(&q, _)| angle(q, truth).to_degrees().powi(2))
        .collect();
    let rms = (squares.iter().sum::<f64>() / squares.len() as f64).sqrt();
    assert!((rms - 5.0 * 3f64.sqrt()).abs() < 0.4, "rms {rms}");
    // Random signs: about half the measurements on each hemisphere of the truth.
    let negative = data.iter().filter(|q| q.dot(truth) < 0.0).count() as f64 / 2000.0;
    assert!((negative - 0.5).abs() < 0.05, "{negative}");
}

#[test]
fn the_median_marks_the_wild_measurements() {
    let model = Model::new(options(100, 5.0, 0.2, 2)).unwrap();
    let marked = model.marked();
    let wild = model.wild.iter().filter(|&&w| w).count();
    let caught = marked.iter().zip(&model.wild).filter(|(m, w)| **m && **w).count();
    let wrong = marked.iter().zip(&model.wild).filter(|(m, w)| **m && !**w).count();
    assert!(caught as f64 >= 0.9 * wild as f64, "{caught} of {wild}");
    assert!(wrong <= 2, "{wrong} inliers marked");
}

#[test]
fn a_moved_measurement_is_wild_and_a_bad_one_is_refused() {
    let mut o = options(10, 5.0, 0.0, 1);
    o.moved = vec![(3, glam::DQuat::from_xyzw(1.0, 0.0, 0.0, 0.0))];
    let model = Model::new(o.clone()).unwrap();
    assert!(model.wild[3] && model.wild.iter().filter(|&&w| w).count() == 1);
    assert_eq!(model.data[3], glam::DQuat::from_xyzw(1.0, 0.0, 0.0, 0.0));
    o.moved = vec![(10, glam::DQuat::IDENTITY)];
    assert_eq!(Model::new(o.clone()).err().unwrap().argument(), "moved");
    o.moved = vec![(0, glam::DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0))];
    assert_eq!(Model::new(o).err().unwrap().argument(), "moved");
}

#[test]
fn the_sweep_orders_the_means_as_mathmds_robustness_table() {
    // MATH.md: 100 measurements, 5° noise, 30% outliers: median 1.2°, chordal 3.3°, Karcher 8.7°.
    let errors = sweep_point(&options(100, 5.0, 0.0, 1), 0.3, 20).unwrap().map(f64::to_degrees);
    let [chordal, _, geodesic, median] = errors;
    assert!(median < chordal && chordal < geodesic, "{errors:?}");
    assert!((0.6..2.0).contains(&median), "median {median}");
    assert!((2.0..5.0).contains(&chordal), "chordal {chordal}");
    assert!((5.0..13.0).contains(&geodesic), "Karcher {geodesic}");
    // Without outliers all four agree to a fraction of the noise.
    let clean = sweep_point(&options(100, 5.0, 0.0, 1), 0.0, 20).unwrap().map(f64::to_degrees);
    assert!(clean.iter().all(|&e| e < 1.5), "{clean:?}");
    let _ = Method::Chordal;
}
