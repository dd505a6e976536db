//! What the averaging page computes: n noisy measurements of a true rotation (a share replaced by
//! wild ones, random signs, seeded; any of them moved by hand), the four means of
//! [`kli::average`], and the follower's path under the sign-blind flow `q' = M q − (qᵀM q) q`
//! from `1` to the chordal mean (MATH.md, "Averaging rotations").

use glam::{DQuat, DVec3};
use kli::KliError;
use kli::average::{Average, Method, angle, average, chordal_flow, scatter};
use kli::hopf::hopf;
use kli::swarm::Random;

/// The four means in the order the page shows them, with their names and colours.
pub struct Style {
    pub method: Method,
    pub name: &'static str,
    pub colour: &'static str,
}

pub const STYLES: [Style; 4] = [
    Style { method: Method::Chordal, name: "chordal", colour: crate::palette::KLI },
    Style { method: Method::Quaternion, name: "quaternion", colour: crate::palette::AXIS_Y },
    Style { method: Method::Geodesic, name: "geodesic (Karcher)", colour: crate::palette::SLERP },
    Style { method: Method::Median, name: "median", colour: crate::palette::AXIS_Z },
];

/// The follower's step (model time) and the longest flow drawn.
pub const FLOW_DT: f64 = 0.05;
const FLOW_LIMIT: f64 = 60.0;

/// Within this angle (radians) of the chordal mean, the follower has arrived: the flow's end.
const ARRIVED: f64 = 1e-4;

/// How the measurements are made.
#[derive(Debug, Clone, PartialEq)]
pub struct Options {
    pub count: usize,
    /// The standard deviation of the noise about each axis, degrees.
    pub noise: f64,
    /// The share of measurements replaced by uniformly random rotations, 0 to 1.
    pub outliers: f64,
    pub seed: u64,
    /// Measurements moved by hand: `(index, rotation)`, each then an outlier.
    pub moved: Vec<(usize, DQuat)>,
}

/// The measurements, their means and the follower's path.
pub struct Model {
    pub options: Options,
    pub truth: DQuat,
    pub data: Vec<DQuat>,
    /// Whether each measurement is wild (drawn at random, or moved by hand).
    pub wild: Vec<bool>,
    /// The four means, in [`STYLES`]' order.
    pub means: Vec<Average>,
    /// The follower at `0, FLOW_DT, 2 FLOW_DT, …` to its arrival.
    pub flow: Vec<DQuat>,
    pub flow_hopf: Vec<DVec3>,
}

impl Model {
    pub fn new(options: Options) -> Result<Model, KliError> {
        let (truth, mut data, mut wild) = measurements(&options);
        for &(index, rotation) in &options.moved {
            if index >= data.len() {
                let problem = format!("must be below the count ({})", data.len());
                return Err(KliError::invalid("moved", problem));
            }
            data[index] = kli::quaternion::unit("moved", rotation)?;
            wild[index] = true;
        }
        let means =
            STYLES.iter().map(|s| average(&data, None, s.method)).collect::<Result<Vec<_>, _>>()?;
        let flow = follow(&data, means[0].rotation);
        let flow_hopf = flow.iter().map(|&q| hopf(q)).collect();
        Ok(Model { options, truth, data, wild, means, flow, flow_hopf })
    }

    /// The flow's span, `[0, T]`: `T` when the follower is within 1e-4 rad of the chordal mean.
    pub fn end_time(&self) -> f64 {
        (self.flow.len().max(2) - 1) as f64 * FLOW_DT
    }

    /// The follower at `t` (between samples along the great arc).
    pub fn follower(&self, t: f64) -> DQuat {
        let s = (t / FLOW_DT).clamp(0.0, (self.flow.len() - 1) as f64);
        let i = (s.floor() as usize).min(self.flow.len().saturating_sub(2));
        match (self.flow.get(i), self.flow.get(i + 1)) {
            (Some(&a), Some(&b)) => a.slerp(b, s - i as f64),
            (Some(&a), None) => a,
            _ => DQuat::IDENTITY,
        }
    }

    /// Each mean's angle to the truth, radians.
    pub fn errors(&self) -> Vec<f64> {
        self.means.iter().map(|m| angle(m.rotation, self.truth)).collect()
    }

    /// Which measurements the median marks as outliers: a final Weiszfeld weight below a
    /// quarter of the typical (median) weight, as a far datum pulls with its weight alone.
    pub fn marked(&self) -> Vec<bool> {
        let Some(weights) = &self.means[3].weights else { return vec![false; self.data.len()] };
        let mut sorted = weights.clone();
        sorted.sort_by(f64::total_cmp);
        let typical = sorted[sorted.len() / 2];
        weights.iter().map(|&w| w < 0.25 * typical).collect()
    }
}

/// `count` measurements of a seeded true rotation (its Hopf point towards the viewer): `truth · exp(v/2)` with `v` normal of
/// `noise` degrees about each axis (a rotation vector), a share `outliers` uniform on S³
/// instead, each with a random sign. The same draws as MATH.md's robustness table's recipe.
pub fn measurements(options: &Options) -> (DQuat, Vec<DQuat>, Vec<bool>) {
    let mut random = Random::new(options.seed);
    // Turned so that its Hopf point faces the sphere view's default camera (h(R q) = R h(q)):
    // the measurements gather where the reader sees them.
    let drawn = random.unit_quaternion();
    let facing = crate::sphere_view::sphere_camera().toward_viewer();
    let truth = (DQuat::from_rotation_arc(hopf(drawn), facing) * drawn).normalize();
    let sigma = options.noise.to_radians();
    let (mut data, mut wild) = (Vec::with_capacity(options.count), vec![false; options.count]);
    for w in wild.iter_mut() {
        *w = random.uniform() < options.outliers;
        let q = if *w { random.unit_quaternion() } else { random.near(truth, 0.5 * sigma) };
        data.push(if random.uniform() < 0.5 { -q } else { q });
    }
    (truth, data, wild)
}

/// The follower from `1` under `q' = M q − (qᵀM q) q` (`M` the scatter matrix over the count,
/// so a step of [`FLOW_DT`] is small), sampled every step until within [`ARRIVED`] of `mean`.
fn follow(data: &[DQuat], mean: DQuat) -> Vec<DQuat> {
    let n = data.len() as f64;
    let m = scatter(data, None).map(|row| row.map(|c| c / n));
    let steps = (FLOW_LIMIT / FLOW_DT) as usize;
    let mut flow: Vec<DQuat> = Vec::new();
    for q in chordal_flow(m, DQuat::IDENTITY, FLOW_DT).take(steps + 1) {
        flow.push(q);
        if angle(q, mean) < ARRIVED {
            break;
        }
    }
    flow
}

/// Each mean's angle to the truth (radians) at the outlier share `outliers`: the median over
/// `sets` seeded sets (the seeds following `options.seed`) of the page's count and noise. One
/// point of the sweep.
pub fn sweep_point(options: &Options, outliers: f64, sets: usize) -> Result<[f64; 4], KliError> {
    let mut errors: [Vec<f64>; 4] = Default::default();
    for set in 0..sets as u64 {
        let seed = options.seed.wrapping_add(set);
        let o = Options { outliers, seed, moved: vec![], ..options.clone() };
        let (truth, data, _) = measurements(&o);
        for (e, style) in errors.iter_mut().zip(&STYLES) {
            // A set whose mean is not unique (rare at random) is left out of that mean's median.
            if let Ok(mean) = average(&data, None, style.method) {
                e.push(angle(mean.rotation, truth));
            }
        }
    }
    Ok(errors.map(|mut e| {
        e.sort_by(f64::total_cmp);
        if e.is_empty() { f64::NAN } else { e[e.len() / 2] }
    }))
}
