//! What the page shows for one choice of `p`, `r` and options, computed once when they change:
//! the integrated KLI path, the SLERP path on the same clock, their Hopf curves and the series
//! of the plots. Plain Rust; the canvas views only read it.

use glam::{DQuat, DVec3};

use kli::KliPath;
use kli::closed_form;
use kli::hopf::hopf;
use kli::slerp;

/// The moments of the paper's Table 1 (and Fig. 2), before the final time `T`.
pub const PAPER_MOMENTS: [f64; 7] = [0.0, 0.2, 0.4, 0.55, 0.85, 1.2, 1.8];

/// One KLI run and everything derived from it.
#[derive(Debug, Clone)]
pub struct Scene {
    path: KliPath,
    predicted_time: f64,
    kli_curve: Vec<DVec3>,
    slerp_curve: Vec<DVec3>,
    distances: Vec<f64>,
    norm_drift: Vec<f64>,
    warp: Vec<f64>,
}

impl Scene {
    pub fn new(path: KliPath) -> Self {
        let arc = *path.arc();
        let target = path.target();
        let predicted_time = closed_form::reach_time(&arc, path.options().tolerance);
        let quaternions = path.quaternions();
        let mut scene = Self {
            predicted_time,
            kli_curve: quaternions.iter().map(|&q| hopf(q.normalize())).collect(),
            slerp_curve: Vec::new(),
            distances: quaternions.iter().map(|&q| (target - q).length()).collect(),
            norm_drift: quaternions.iter().map(|&q| (q.length() - 1.0).abs()).collect(),
            warp: path.times().iter().map(|&t| closed_form::time_warp(&arc, t)).collect(),
            path,
        };
        scene.slerp_curve = scene.path.times().iter().map(|&t| hopf(scene.slerp_at(t))).collect();
        scene
    }

    pub fn path(&self) -> &KliPath {
        &self.path
    }

    /// `T`, measured by Algorithm 1.
    pub fn final_time(&self) -> f64 {
        self.path.final_time()
    }

    /// `T*`, predicted by the closed form.
    pub fn predicted_time(&self) -> f64 {
        self.predicted_time
    }

    /// The integrated KLI rotation at `t ∈ [0, T]`, between samples by normalised linear
    /// interpolation (the samples are `δ` apart; Euler's are not unit, hence the normalising).
    pub fn integrated_at(&self, t: f64) -> DQuat {
        let q = self.path.quaternions();
        let step = self.path.options().step;
        let position = (t / step).max(0.0).min((q.len() - 1) as f64);
        let n = (position.floor() as usize).min(q.len() - 1);
        let next = (n + 1).min(q.len() - 1);
        let f = position - n as f64;
        (q[n] * (1.0 - f) + q[next] * f).normalize()
    }

    /// SLERP's parameter on the same clock, `u = t / T` (constant angular speed), in `[0, 1]`: not
    /// KLI's SLERP parameter `s(t)` ([`Scene::warp`]).
    #[allow(clippy::manual_clamp)] // f64::clamp panics on bad bounds; nothing drawn may panic
    pub fn clock_fraction(&self, t: f64) -> f64 {
        if self.final_time() > 0.0 { (t / self.final_time()).max(0.0).min(1.0) } else { 1.0 }
    }

    /// SLERP at [`Scene::clock_fraction`]`(t)`.
    pub fn slerp_at(&self, t: f64) -> DQuat {
        slerp::point_at(self.path.arc(), self.clock_fraction(t))
    }

    /// Hopf images of the integrated samples.
    pub fn kli_curve(&self) -> &[DVec3] {
        &self.kli_curve
    }

    /// Hopf images of SLERP at the sample times (`s = t / T`).
    pub fn slerp_curve(&self) -> &[DVec3] {
        &self.slerp_curve
    }

    /// `||target - q(tₙ)||` at each sample.
    pub fn distances(&self) -> &[f64] {
        &self.distances
    }

    /// `||q(tₙ)| - 1|` at each sample.
    pub fn norm_drift(&self) -> &[f64] {
        &self.norm_drift
    }

    /// The time warp `s(tₙ)` of the closed form at each sample.
    pub fn warp(&self) -> &[f64] {
        &self.warp
    }

    /// Table 1's moments that lie in `[0, T)`, then `T`.
    pub fn moments(&self) -> Vec<f64> {
        let final_time = self.final_time();
        PAPER_MOMENTS.iter().copied().filter(|&t| t < final_time).chain([final_time]).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use kli::{KliOptions, from_wxyz, kli};

    fn paper() -> Scene {
        Scene::new(
            kli(from_wxyz([0.0, 0.0, 0.0, 1.0]), from_wxyz([0.5; 4]), &KliOptions::default())
                .unwrap(),
        )
    }

    #[test]
    fn curves_share_end_points_and_the_path() {
        let scene = paper();
        let (kli_curve, slerp_curve) = (scene.kli_curve(), scene.slerp_curve());
        assert_eq!(kli_curve.len(), 1167);
        assert!((kli_curve[0] - DVec3::new(-1.0, 0.0, 0.0)).length() < 1e-15);
        assert!((slerp_curve[1166] - DVec3::new(0.0, 1.0, 0.0)).length() < 1e-15);
        // Same great circle, other clock: every KLI point lies on the SLERP curve.
        for k in kli_curve.iter().step_by(50) {
            let nearest = slerp_curve.iter().map(|s| (*s - *k).length()).fold(f64::MAX, f64::min);
            assert!(nearest < 2e-3, "{k:?} is {nearest} from the SLERP curve");
        }
    }

    #[test]
    fn clocks_differ_in_the_middle() {
        let scene = paper();
        // At t = 1.2 KLI has covered 1 - φ(1.2)/φ0 of the angle, SLERP only 1.2 / 11.66.
        // Table 1 (MATH.md) at t = 1.2 for KLI.
        assert!(
            (scene.integrated_at(1.2) - from_wxyz([0.3732, 0.3732, 0.3732, 0.7630])).length()
                < 1e-4
        );
        let s = scene.slerp_at(1.2);
        let expected =
            kli::slerp(from_wxyz([0.0, 0.0, 0.0, 1.0]), from_wxyz([0.5; 4]), 1.2 / 11.66, true)
                .unwrap();
        assert!((s - expected).length() < 1e-12);
    }

    #[test]
    fn series_and_moments() {
        let scene = paper();
        assert!((scene.predicted_time() - 11.6568).abs() < 5e-5);
        assert!(scene.distances()[1166] < 1e-5 && scene.distances()[1165] >= 1e-5);
        assert!(scene.norm_drift().iter().all(|&d| d < 1e-9));
        assert_eq!(scene.warp()[0], 0.0);
        assert_eq!(scene.moments(), vec![0.0, 0.2, 0.4, 0.55, 0.85, 1.2, 1.8, scene.final_time()]);
    }
}
