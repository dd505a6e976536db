//! The keyframes page's model: three curves through the same keys (the Kuramoto–Lohe chain,
//! Squad, piecewise SLERP), each sampled for the figures, and what the page measures of each.

use glam::{DQuat, DVec3};
use kli::KliError;
use kli::hopf::hopf;
use kli::quaternion::from_wxyz;
use kli::spline::{ChainOptions, Curve, Keys, KliSpline, PiecewiseSlerp, Squad};

use crate::palette::{INK, KLI, SLERP};
use crate::turning;

/// Samples a unit of time for the series and the figures (as in MATH.md's measurements).
const PER_UNIT: f64 = 256.0;

/// The most samples a curve's plots and Hopf curve hold, whatever the time range: a range of
/// 100,000 at [`PER_UNIT`] would take 2.6e7 samples a curve (26 s, then out of memory).
const MAX_PLOT_SAMPLES: f64 = 4096.0;

/// The most keys the page takes: the three curves, their figures and the key editor stay
/// within a frame's budget (1,000 keys took 9 s).
pub const MAX_KEYS: usize = 256;

/// One of the three curves, as every part of the page names and draws it.
pub struct Style {
    /// Its word in exports ("chain", "squad", "slerp").
    pub id: &'static str,
    /// Its name in legends, titles and the table.
    pub name: &'static str,
    pub colour: &'static str,
    /// Its dash on the sphere (the plots draw all three solid).
    pub dash: &'static [f64],
}

/// The three curves, in the page's order.
pub const STYLES: [Style; 3] = [
    Style { id: "chain", name: "Kuramoto–Lohe chain", colour: KLI, dash: &[] },
    Style { id: "squad", name: "Squad", colour: SLERP, dash: &[6.0, 4.0] },
    Style { id: "slerp", name: "piecewise SLERP", colour: INK, dash: &[2.0, 3.0] },
];

/// One curve sampled at the model's times: Hopf points, |ω| and |ω̇|.
pub struct Series {
    pub hopf: Vec<DVec3>,
    pub speed: Vec<f64>,
    pub acceleration: Vec<f64>,
}

/// What the page measures of a curve (MATH.md, "Smoothness").
#[derive(Clone, Copy)]
pub struct Measures {
    /// The largest distance from a key at its time (of the closer sign).
    pub key_error: f64,
    /// The largest jump of ω across a key ([`turning::jump`]).
    pub largest_jump: f64,
    /// ∫|ω̇|² dt.
    pub bending: f64,
    /// The total rotation angle ∫|ω| dt.
    pub total_angle: f64,
}

/// The three curves through one set of keys, sampled.
pub struct Model {
    pub keys: Keys,
    pub smoothness: f64,
    pub chain: KliSpline,
    pub squad: Squad,
    pub slerp: PiecewiseSlerp,
    /// The sample times, evenly spaced over the keys' span.
    pub times: Vec<f64>,
    /// Each curve's samples and measures, in the order of [`STYLES`].
    pub series: [Series; 3],
    pub measures: [Measures; 3],
}

impl Model {
    /// The three curves through `flat` keys (4m numbers, scalar first) at `times` (m numbers, or
    /// empty for 0, 1, …), the chain with `smoothness`; errors as kliSpline's.
    pub fn new(flat: &[f64], times: &[f64], smoothness: f64) -> Result<Model, KliError> {
        if flat.len() % 4 != 0 {
            let problem = format!("must hold 4 numbers per key (got {})", flat.len());
            return Err(KliError::invalid("keys", problem));
        }
        if flat.len() > 4 * MAX_KEYS {
            let problem = format!("may hold at most {MAX_KEYS} keys here (got {})", flat.len() / 4);
            return Err(KliError::invalid("keys", problem));
        }
        let q: Vec<DQuat> =
            flat.chunks_exact(4).map(|c| from_wxyz([c[0], c[1], c[2], c[3]])).collect();
        let keys = Keys::new(&q, (!times.is_empty()).then_some(times))?;
        let chain =
            KliSpline::new(keys.clone(), &ChainOptions { smoothness, ..Default::default() })?;
        let (squad, slerp) = (Squad::new(keys.clone()), PiecewiseSlerp::new(keys.clone()));
        let (start, end) = (keys.times()[0], keys.times()[keys.len() - 1]);
        let n = ((end - start) * PER_UNIT).ceil().clamp(16.0, MAX_PLOT_SAMPLES) as usize;
        let times: Vec<f64> =
            (0..=n).map(|k| start + (end - start) * k as f64 / n as f64).collect();
        let dt = times[1] - times[0];
        let curves: [&dyn Curve; 3] = [&chain, &squad, &slerp];
        let series = curves.map(|c| series(c, &times));
        let measures = [0, 1, 2].map(|i| measures(curves[i], &keys, &series[i], dt));
        Ok(Model { keys, smoothness, chain, squad, slerp, times, series, measures })
    }

    /// The three curves, in the order of [`STYLES`].
    pub fn curves(&self) -> [&dyn Curve; 3] {
        [&self.chain, &self.squad, &self.slerp]
    }

    pub fn start_time(&self) -> f64 {
        self.chain.start_time()
    }

    pub fn end_time(&self) -> f64 {
        self.chain.end_time()
    }

    /// The first pair of consecutive keys that differ (by more than 0.5°) but have the same
    /// Hopf point: the turn between them is about the body's x-axis, invisible on the sphere.
    pub fn hidden_turn(&self) -> Option<usize> {
        let k = self.keys.quaternions();
        (0..k.len().saturating_sub(1)).find(|&i| {
            let turn = 2.0 * k[i].dot(k[i + 1]).abs().min(1.0).acos();
            turn > 0.5f64.to_radians() && (hopf(k[i]) - hopf(k[i + 1])).length() < 1e-6
        })
    }
}

fn series(curve: &dyn Curve, times: &[f64]) -> Series {
    let omega = turning::angular_velocities(curve, times);
    Series {
        hopf: times.iter().map(|&t| hopf(curve.at(t))).collect(),
        speed: omega.iter().map(|w| w.length()).collect(),
        acceleration: turning::accelerations(&omega, times[1] - times[0]),
    }
}

fn measures(curve: &dyn Curve, keys: &Keys, s: &Series, dt: f64) -> Measures {
    let key_error = keys
        .quaternions()
        .iter()
        .zip(keys.times())
        .map(|(&k, &t)| (curve.at(t) - k).length().min((curve.at(t) + k).length()))
        .fold(0.0, f64::max);
    let largest_jump = keys.times()[1..keys.len() - 1]
        .iter()
        .map(|&t| turning::jump(curve, t).length())
        .fold(0.0, f64::max);
    let bending = trapezoid(s.acceleration.iter().map(|a| a * a), dt);
    let total_angle = trapezoid(s.speed.iter().copied(), dt);
    Measures { key_error, largest_jump, bending, total_angle }
}

/// ∫ f dt by the trapezoid rule over evenly spaced samples `dt` apart.
fn trapezoid(values: impl ExactSizeIterator<Item = f64>, dt: f64) -> f64 {
    let last = values.len().saturating_sub(1);
    values.enumerate().map(|(k, f)| if k == 0 || k == last { 0.5 * f } else { f }).sum::<f64>() * dt
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The largest second difference of a plotted series (a step or a saw shows in it, a
    /// smooth curve's is of order dt²), over the series' largest value.
    fn roughness(values: &[f64]) -> f64 {
        let largest = values.iter().fold(0.0_f64, |m, v| m.max(*v));
        values.windows(3).map(|w| (w[2] - 2.0 * w[1] + w[0]).abs()).fold(0.0, f64::max) / largest
    }

    #[test]
    fn the_chains_angular_acceleration_plot_has_no_saw() {
        // Four tumbling keys at uneven times. Measured: the chain (C²) 0.015; the chain evaluated
        // as before, Squad through its samples (C¹, a step of ω̇ at each sample), 0.051; Squad
        // through the keys 0.13 (steps at the keys).
        let s = std::f64::consts::FRAC_1_SQRT_2;
        let keys = [1.0, 0.0, 0.0, 0.0, s, s, 0.0, 0.0, 0.5, 0.5, 0.5, 0.5, 0.0, 0.0, s, s];
        let model = Model::new(&keys, &[0.0, 1.0, 1.6, 3.0], 1.0).unwrap();
        let chain = roughness(&model.series[0].acceleration);
        assert!(chain < 0.025, "chain {chain}");
        let squad = roughness(&model.series[1].acceleration);
        assert!(squad > 0.1, "Squad {squad}");
    }

    #[test]
    fn measures_of_a_constant_turn() {
        // Three keys a quarter turn apart about z, a unit of time apart: every curve turns about
        // z through π in all, meets every key and has no jump at the middle key; Squad and
        // piecewise SLERP are the uniform turn (no bending), the chain follows the KLI flow's
        // clock between its samples (MATH.md, "The chain"), so it bends.
        let h = std::f64::consts::FRAC_1_SQRT_2;
        // Rotations by 0, π/2 and π about z: (cos θ/2, 0, 0, sin θ/2).
        let keys = [1.0, 0.0, 0.0, 0.0, h, 0.0, 0.0, h, 0.0, 0.0, 0.0, 1.0];
        let model = Model::new(&keys, &[], 1.0).unwrap();
        for (m, style) in model.measures.iter().zip(&STYLES) {
            assert!(m.key_error < 1e-9, "{}: {}", style.id, m.key_error);
            assert!(
                (m.total_angle - std::f64::consts::PI).abs() < 1e-6,
                "{}: {}",
                style.id,
                m.total_angle
            );
            assert!(m.largest_jump < 1e-6, "{}: {}", style.id, m.largest_jump);
            if style.id != "chain" {
                assert!(m.bending < 1e-6, "{}: {}", style.id, m.bending);
            }
        }
    }
}
