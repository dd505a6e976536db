//! What the tour's figures compute, a section at a time: Euler angles and their lock, a turn by
//! axis and angle, SLERP beside NLERP, the Hopf map under a roll, the Kuramoto model on the
//! circle, the Lohe model on S³ with a pinned leader, KLI and Algorithm 1, and the integrators'
//! drift, and the turning rate through keyframes ([`Rates`]). Every formula is the paper's or docs/MATH.md's, named where it is used.

pub use super::rates::Rates;
use super::words::Words;
use glam::{DQuat, DVec3};
use kli::closed_form::{angle_at, reach_time, time_warp};
use kli::great_arc::GreatArc;
use kli::{Integrator, KliError, KliOptions, KliPath, from_wxyz, hopf, kli};

/// The tour's clock runs from 0 to at least this (past the paper's T = 11.66); further when the
/// reader's ε stops Algorithm 1 later ([`Model::end`]). The drift figure's runs end here.
pub const END: f64 = 12.0;
/// The Kuramoto and Lohe flows are sampled every `SAMPLE` units of time.
pub const SAMPLE: f64 = 0.02;
/// How many phases the Kuramoto figure has.
pub const PHASES: usize = 20;
/// The half-width of the phases' natural frequencies, uniform on `[−γ, γ]`.
pub const GAMMA: f64 = 0.5;
/// How many followers the Lohe figure has (the leader is one more oscillator).
pub const FOLLOWERS: usize = 8;

/// The paper's example (Section 3; MATH.md, "The paper's example"): `p = k`, `r = ½(1 + i + j + k)`.
pub fn paper_p() -> DQuat {
    from_wxyz([0.0, 0.0, 0.0, 1.0])
}

/// See [`paper_p`].
pub fn paper_r() -> DQuat {
    from_wxyz([0.5, 0.5, 0.5, 0.5])
}

/// The axis of the turn in the second section.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum Axis {
    X,
    Y,
    Z,
    /// `(1, 1, 1)/√3`.
    Diagonal,
}

impl Axis {
    pub const NAMES: [&'static str; 4] = ["x", "y", "z", "diagonal"];

    pub fn parse(name: &str) -> Option<Axis> {
        match name {
            "x" => Some(Axis::X),
            "y" => Some(Axis::Y),
            "z" => Some(Axis::Z),
            "diagonal" => Some(Axis::Diagonal),
            _ => None,
        }
    }

    pub fn name(self) -> &'static str {
        Axis::NAMES[self as usize]
    }

    pub fn vector(self) -> DVec3 {
        match self {
            Axis::X => DVec3::X,
            Axis::Y => DVec3::Y,
            Axis::Z => DVec3::Z,
            Axis::Diagonal => DVec3::ONE / 3f64.sqrt(),
        }
    }
}

/// The reader's settings, every section's (angles in degrees).
#[derive(Clone, Debug)]
pub struct Options {
    pub yaw: f64,
    pub pitch: f64,
    pub bank: f64,
    pub axis: Axis,
    pub angle: f64,
    pub s: f64,
    pub roll: f64,
    pub coupling: f64,
    pub lohe: f64,
    /// `ε = 10^−digits`.
    pub digits: f64,
    pub delta: f64,
    pub integrator: Integrator,
    pub step: f64,
    /// The keyframe chain's smoothness in section 9, 0 (piecewise SLERP) to 1.
    pub smoothness: f64,
    /// The words the views draw (English unless the page gives its language's).
    pub words: Words,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            yaw: 30.0,
            pitch: 40.0,
            bank: 0.0,
            axis: Axis::Z,
            angle: 90.0,
            s: 0.5,
            roll: 0.0,
            coupling: 1.5,
            lohe: 3.0,
            digits: 5.0,
            delta: 0.01,
            integrator: Integrator::Euler,
            step: 0.5,
            smoothness: 1.0,
            words: Words::default(),
        }
    }
}

/// A unit quaternion turning by `degrees` about the unit `axis`: `cos(θ/2) + sin(θ/2) u` (the
/// paper's polar form; MATH.md, "Polar form").
pub fn turn(axis: DVec3, degrees: f64) -> DQuat {
    let (s, c) = (0.5 * degrees.to_radians()).sin_cos();
    DQuat::from_xyzw(s * axis.x, s * axis.y, s * axis.z, c)
}

/// The Euler angles' rotation `R = R_z(yaw) R_y(pitch) R_x(bank)` (aerospace order), as a
/// quaternion.
pub fn euler(yaw: f64, pitch: f64, bank: f64) -> DQuat {
    turn(DVec3::Z, yaw) * turn(DVec3::Y, pitch) * turn(DVec3::X, bank)
}

/// The three gimbal axes in the world, `[yaw, pitch, bank]`: `z`, `R_z y` and `R_z R_y x`.
pub fn gimbal_axes(yaw: f64, pitch: f64) -> [DVec3; 3] {
    let z = turn(DVec3::Z, yaw);
    [DVec3::Z, z * DVec3::Y, z * (turn(DVec3::Y, pitch) * DVec3::X)]
}

/// The angle in degrees between the yaw axis and the bank axis (as lines): `90° − |pitch|`, since
/// `z · R_z R_y x = −sin(pitch)`. At 0 the two rings turn about one line: gimbal lock.
pub fn lock_angle(pitch: f64) -> f64 {
    let [yaw, _, bank] = gimbal_axes(0.0, pitch);
    yaw.dot(bank).abs().min(1.0).acos().to_degrees()
}

/// An orthonormal basis `(e₁, e₂)` of the plane of R⁴ through `p` and `r` (`e₁ = p`), so that a
/// point of their great circle is `cos α e₁ + sin α e₂`. `None` when `r = ±p`.
pub fn plane(p: DQuat, r: DQuat) -> Option<(DQuat, DQuat)> {
    let e2 = r - p * p.dot(r);
    let length = e2.length();
    (length > 1e-12).then(|| (p, e2 * (1.0 / length)))
}

/// The angle of `q` in the plane `(e₁, e₂)`, radians.
pub fn in_plane(q: DQuat, (e1, e2): (DQuat, DQuat)) -> f64 {
    q.dot(e2).atan2(q.dot(e1))
}

/// SLERP from `p` to `r` at `s`: `[sin((1−s)φ₀) p + sin(sφ₀) r] / sin φ₀` (Shoemake 1985; the
/// paper's comparison).
pub fn slerp(p: DQuat, r: DQuat, s: f64) -> DQuat {
    kli::slerp(p, r, s, true).unwrap_or(p)
}

/// NLERP: the chord's point `(1−s) p + s r`, pushed back onto S³.
pub fn nlerp(p: DQuat, r: DQuat, s: f64) -> DQuat {
    (p * (1.0 - s) + r * s).normalize()
}

/// The Kuramoto model on the circle (Kuramoto 1975), `θᵢ′ = ωᵢ + (K/N) Σⱼ sin(θⱼ − θᵢ)`
/// `= ωᵢ + K R sin(ψ − θᵢ)`, with `N` = [`PHASES`] natural frequencies evenly spread on
/// `[−γ, γ]` and starting phases spread by the golden angle; RK4 with step `SAMPLE/2`, sampled
/// every [`SAMPLE`] from 0 to `end`.
pub struct Phases {
    pub omega: Vec<f64>,
    /// `samples[k][i]`, phase `i` at time `k·SAMPLE`.
    pub samples: Vec<Vec<f64>>,
}

impl Phases {
    pub fn new(coupling: f64, end: f64) -> Phases {
        let n = PHASES;
        let omega: Vec<f64> =
            (0..n).map(|i| GAMMA * (2.0 * (i as f64 + 0.5) / n as f64 - 1.0)).collect();
        let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
        let mut theta: Vec<f64> =
            (0..n).map(|i| (i as f64 * golden) % std::f64::consts::TAU).collect();
        let rate = |theta: &[f64]| -> Vec<f64> {
            let (r, psi) = order(theta);
            theta.iter().zip(&omega).map(|(&t, &w)| w + coupling * r * (psi - t).sin()).collect()
        };
        let h = SAMPLE / 2.0;
        let count = (end / SAMPLE).round() as usize;
        let mut samples = Vec::with_capacity(count + 1);
        samples.push(theta.clone());
        for _ in 0..count {
            for _ in 0..2 {
                let k1 = rate(&theta);
                let add = |k: &[f64], f: f64| -> Vec<f64> {
                    theta.iter().zip(k).map(|(t, k)| t + f * k).collect()
                };
                let k2 = rate(&add(&k1, h / 2.0));
                let k3 = rate(&add(&k2, h / 2.0));
                let k4 = rate(&add(&k3, h));
                for i in 0..n {
                    theta[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
                }
            }
            samples.push(theta.clone());
        }
        Phases { omega, samples }
    }

    /// The phases at time `t` (the nearest sample).
    pub fn at(&self, t: f64) -> &[f64] {
        &self.samples[sample_index(t, self.samples.len())]
    }
}

/// The order parameter `R e^{iψ} = (1/N) Σ e^{iθⱼ}`: `(R, ψ)`.
pub fn order(theta: &[f64]) -> (f64, f64) {
    let n = theta.len().max(1) as f64;
    let (s, c) = theta.iter().fold((0.0, 0.0), |(s, c), t| (s + t.sin(), c + t.cos()));
    ((s * s + c * c).sqrt() / n, s.atan2(c))
}

/// The index of the sample nearest `t` among `len` samples `SAMPLE` apart.
fn sample_index(t: f64, len: usize) -> usize {
    let k = (t / SAMPLE).round();
    if k.is_nan() || k < 0.0 { 0 } else { (k as usize).min(len.saturating_sub(1)) }
}

/// The non-abelian Kuramoto (Lohe) model on S³ with one pinned leader (MATH.md, "The swarm"):
/// N = [`FOLLOWERS`] + 1 oscillators, all to all,
/// `qᵢ′ = (K/N) Σⱼ (qⱼ − (qᵢ·qⱼ) qᵢ)` for each follower, the leader `r` fixed. With one follower
/// this is KLI at time `Kt/2`. RK4 with step `SAMPLE/2`, each step put back on S³; sampled every
/// [`SAMPLE`] from 0 to `end`.
pub struct Swarm {
    pub leader: DQuat,
    /// `samples[k][i]`, follower `i` at time `k·SAMPLE`.
    pub samples: Vec<Vec<DQuat>>,
}

impl Swarm {
    pub fn new(coupling: f64, leader: DQuat, end: f64) -> Swarm {
        let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
        let mut q: Vec<DQuat> = (0..FOLLOWERS)
            .map(|i| {
                // Axes on a golden spiral, angles from 100° to 170°: spread over S³, none at −r.
                let z = 1.0 - 2.0 * (i as f64 + 0.5) / FOLLOWERS as f64;
                let ring = (1.0 - z * z).sqrt();
                let (s, c) = (i as f64 * golden).sin_cos();
                let axis = DVec3::new(ring * c, ring * s, z);
                turn(axis, 100.0 + 10.0 * i as f64)
            })
            .collect();
        let n = (FOLLOWERS + 1) as f64;
        let rate = |q: &[DQuat]| -> Vec<DQuat> {
            let sum = q.iter().fold(leader, |m, &x| m + x);
            q.iter().map(|&x| (sum - x * x.dot(sum)) * (coupling / n)).collect()
        };
        let h = SAMPLE / 2.0;
        let count = (end / SAMPLE).round() as usize;
        let mut samples = Vec::with_capacity(count + 1);
        samples.push(q.clone());
        for _ in 0..count {
            for _ in 0..2 {
                let k1 = rate(&q);
                let add = |k: &[DQuat], f: f64| -> Vec<DQuat> {
                    q.iter().zip(k).map(|(&x, &k)| x + k * f).collect()
                };
                let k2 = rate(&add(&k1, h / 2.0));
                let k3 = rate(&add(&k2, h / 2.0));
                let k4 = rate(&add(&k3, h));
                for i in 0..q.len() {
                    let step = (k1[i] + (k2[i] + k3[i]) * 2.0 + k4[i]) * (h / 6.0);
                    q[i] = (q[i] + step).normalize();
                }
            }
            samples.push(q.clone());
        }
        Swarm { leader, samples }
    }

    pub fn at(&self, t: f64) -> &[DQuat] {
        &self.samples[sample_index(t, self.samples.len())]
    }

    /// The order parameter `R = |(1/N) Σ qⱼ|` over all N, the leader too.
    pub fn order(&self, t: f64) -> f64 {
        let q = self.at(t);
        (q.iter().fold(self.leader, |m, &x| m + x) * (1.0 / (q.len() + 1) as f64)).length()
    }

    /// The largest rotation angle from a follower to the leader, degrees: `2 acos |q·r|`.
    pub fn spread(&self, t: f64) -> f64 {
        self.at(t)
            .iter()
            .map(|q| 2.0 * q.dot(self.leader).abs().min(1.0).acos())
            .fold(0.0, f64::max)
            .to_degrees()
    }
}

/// One integrator's run from `p` towards `r` at step `h` to [`END`]: the times and `| |q| − 1 |`.
pub struct Drift {
    pub integrator: Integrator,
    pub times: Vec<f64>,
    pub drift: Vec<f64>,
}

impl Drift {
    pub fn new(integrator: Integrator, p: DQuat, r: DQuat, h: f64) -> Drift {
        let steps = (END / h).ceil() as usize;
        let (mut times, mut drift) = (vec![0.0], vec![(p.length() - 1.0).abs()]);
        let mut q = p;
        for n in 1..=steps {
            q = integrator.step(q, r, h);
            times.push(n as f64 * h);
            drift.push((q.length() - 1.0).abs());
        }
        Drift { integrator, times, drift }
    }

    pub fn largest(&self) -> f64 {
        self.drift.iter().copied().fold(0.0, f64::max)
    }
}

/// Everything the tour's figures show, for one setting of the reader's controls.
pub struct Model {
    pub options: Options,
    pub phases: Phases,
    pub swarm: Swarm,
    /// The paper's example run by Algorithm 1 with the reader's ε and δ (RK4).
    pub path: KliPath,
    /// The great circle from the paper's `p` to `r`.
    pub arc: GreatArc,
    pub drifts: Vec<Drift>,
    /// Section 9's turning rates through the keyframes.
    pub rates: Rates,
    /// The end of the tour's clock: [`END`], or later if Algorithm 1 stops (or `T*` falls)
    /// later, so that the stop and `T*` are on show: the first whole time past both by 0.25.
    pub end: f64,
}

impl Model {
    pub fn new(options: Options) -> Result<Model, KliError> {
        let (p, r) = (paper_p(), paper_r());
        let settings = KliOptions {
            tolerance: options.epsilon(),
            step: options.delta,
            ..KliOptions::default()
        };
        let path = kli(p, r, &settings).map_err(|e| match e.argument() {
            "step" => e.renamed("delta"),
            "tolerance" => e.renamed("digits"),
            _ => e,
        })?;
        let arc = GreatArc::new(p, r, true)?;
        let drifts = Integrator::ALL.iter().map(|&i| Drift::new(i, p, r, options.step)).collect();
        let rates = Rates::new(options.smoothness)?;
        let predicted = reach_time(&arc, options.epsilon());
        let end = END.max((path.final_time().max(predicted) + 0.25).ceil());
        Ok(Model {
            phases: Phases::new(options.coupling, end),
            swarm: Swarm::new(options.lohe, r, end),
            end,
            path,
            arc,
            drifts,
            rates,
            options,
        })
    }

    /// The second section's turn.
    pub fn turn(&self) -> DQuat {
        turn(self.options.axis.vector(), self.options.angle)
    }

    /// The Hopf section's rotation: the turn, then a roll of `roll` about the object's own nose
    /// (its x axis): `q · (cos(ρ/2) + sin(ρ/2) i)`. `h(q)` does not change with `ρ`.
    pub fn rolled(&self) -> DQuat {
        self.turn() * turn(DVec3::X, self.options.roll)
    }

    /// The Hopf map (paper eq. 5) of [`Model::rolled`], where its nose points.
    pub fn nose(&self) -> DVec3 {
        hopf(self.rolled())
    }

    /// The exact KLI point at `t` (MATH.md, "Closed form": `tan(φ(t)/2) = tan(φ₀/2) e^−t`).
    pub fn kli_at(&self, t: f64) -> DQuat {
        kli::closed_form::point_at(&self.arc, t.max(0.0))
    }

    /// `φ(t)`, the angle in R⁴ between `q(t)` and `r`.
    pub fn phi(&self, t: f64) -> f64 {
        angle_at(&self.arc, t.max(0.0))
    }

    /// `s(t) = 1 − φ(t)/φ₀`, KLI's time warp: where on SLERP's path it is at time `t`.
    pub fn warp(&self, t: f64) -> f64 {
        time_warp(&self.arc, t.max(0.0))
    }

    /// `T*` for the reader's ε.
    pub fn predicted(&self) -> f64 {
        reach_time(&self.arc, self.options.epsilon())
    }

    /// Algorithm 1's step on show at time `t`: `n = ⌊t/δ⌋`, at most its last.
    pub fn step_at(&self, t: f64) -> usize {
        let n = (t.max(0.0) / self.options.delta * (1.0 + 1e-12)).floor();
        if n.is_nan() { 0 } else { (n as usize).min(self.path.steps()) }
    }
}

impl Options {
    pub fn epsilon(&self) -> f64 {
        10f64.powf(-self.digits)
    }
}
