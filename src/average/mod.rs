//! Averaging rotations by the paper's model (MATH.md, "Averaging rotations: many pinned leaders,
//! one follower"): the measurements `r_j` (weights `w_j > 0`, any signs) are pinned leaders, one
//! follower `q` is coupled to all of them, and where it settles is the mean.
//!
//! - [`Method::Chordal`]: the sign-blind flow `q' = M q − (qᵀM q) q`, `M = Σ w_j r_j r_jᵀ`, settles
//!   on the top eigenvector of `M` (Markley's and SciPy's mean), computed by [`eigen()`] in one pass
//!   over the data; [`chordal_flow`] integrates the flow itself.
//! - [`Method::Quaternion`]: the Lohe flow `q' = m − (q·m) q`, `m = Σ w_j s_j r_j`, settles on
//!   `m/|m|`, with the signs `s_j` aligned to one hemisphere (without them, the teaching point,
//!   [`quaternion_mean`] with `aligned: false`).
//! - [`Method::Geodesic`]: the Karcher mean, minimising `Σ w_j d(q, r_j)²`.
//! - [`Method::Median`]: the geodesic L1 median, minimising `Σ w_j d(q, r_j)` (robust).
//!
//! `d(a, b) = 2 acos|a·b|` is the angle of the rotation between `a` and `b`, blind to signs.

mod chordal;
mod eigen;
mod geodesic;
mod median;
mod quaternion;
mod tangent;

pub use chordal::{Scatter, chordal_flow, scatter};
pub use eigen::{Symmetric4, eigen};
pub use quaternion::quaternion_mean;

use std::borrow::Borrow;

use glam::DQuat;

use crate::error::{ErrorKind, KliError, Requirement, require};
use crate::quaternion::{plain_inverse_square, unit};

/// Which mean [`average`] computes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Method {
    /// The chordal L2 mean: the top eigenvector of `Σ w_j r_j r_jᵀ`.
    #[default]
    Chordal,
    /// The normalised weighted sum of the data aligned to one hemisphere.
    Quaternion,
    /// The geodesic L2 (Karcher) mean.
    Geodesic,
    /// The geodesic L1 median.
    Median,
}

impl Method {
    pub const NAMES: &'static [&'static str] = &["chordal", "quaternion", "geodesic", "median"];

    pub fn name(self) -> &'static str {
        Self::NAMES[self as usize]
    }
}

impl std::str::FromStr for Method {
    type Err = KliError;

    fn from_str(name: &str) -> Result<Method, KliError> {
        let methods = [Method::Chordal, Method::Quaternion, Method::Geodesic, Method::Median];
        methods.into_iter().find(|m| m.name() == name).ok_or_else(|| {
            KliError::new(
                "method",
                ErrorKind::UnknownName { got: name.into(), allowed: Self::NAMES },
            )
        })
    }
}

/// A mean and how it was reached.
#[derive(Debug, Clone, PartialEq)]
pub struct Average {
    /// The mean rotation, a unit quaternion. Its sign: the chordal mean's first non-zero
    /// component (`w, x, y, z`) is positive, and the other means are on its side (where it is
    /// not unique, the heaviest datum's), whatever the data's own signs.
    pub rotation: DQuat,
    /// Iterations taken (0 for a closed form).
    pub iterations: usize,
    /// How far from settled the answer is: the eigen-residual `|M q − λ q| / λ` (chordal), the
    /// last step's angle in radians (geodesic, median), 0 for the quaternion mean.
    pub residual: f64,
    /// The weighted RMS angle from the mean to the data, radians.
    pub dispersion: f64,
    /// For the median: each datum's final weight in the Weiszfeld step (`w_j / d_j`, summing to
    /// 1): a far outlier's is small.
    pub weights: Option<Vec<f64>>,
}

/// The weights checked (one a rotation, each finite and > 0) and scaled by the largest: the
/// means do not change with the weights' scale, so 10⁻³⁰⁸ and 10³⁰⁸ are as good as 1, and no sum
/// below overflows or vanishes. `None` is all 1, without a list of ones.
pub(crate) struct Weights(Option<Vec<f64>>);

impl Weights {
    pub(super) fn new(weights: Option<&[f64]>, count: usize) -> Result<Weights, KliError> {
        if count == 0 {
            return Err(KliError::invalid("quaternions", "must hold at least one rotation"));
        }
        let Some(weights) = weights else { return Ok(Weights(None)) };
        if weights.len() != count {
            let problem = format!(
                "must hold one weight for each of the {count} rotations (got {})",
                weights.len()
            );
            return Err(KliError::invalid("weights", problem));
        }
        let mut largest = 0.0_f64;
        for (j, &w) in weights.iter().enumerate() {
            let w = require("weights", w, Requirement::Positive)
                .map_err(|e| e.renamed(format!("weights[{j}]")))?;
            largest = largest.max(w);
        }
        Ok(Weights(Some(weights.iter().map(|w| w / largest).collect())))
    }

    #[inline(always)]
    fn get(&self, j: usize) -> f64 {
        self.0.as_ref().map_or(1.0, |w| w[j])
    }
}

/// Each of `quaternions` checked (finite, not zero), given to `visit` as `(q, k, w)`: `q √k` is
/// the datum normalised (`k = 1/|q|²`, or `q` already normalised and `k = 1` for the few that
/// must be scaled first) and `w` its weight. One pass over the data, one division a datum.
fn walk<Q: Borrow<DQuat>>(
    quaternions: impl Iterator<Item = Q>,
    weights: &Weights,
    mut visit: impl FnMut(DQuat, f64, f64),
) -> Result<(), KliError> {
    for (j, q) in quaternions.enumerate() {
        let q = *q.borrow();
        match plain_inverse_square(q) {
            Some(k) => visit(q, k, weights.get(j)),
            None => {
                // Named only when refused: a name a datum costs more than the mean.
                let r =
                    unit("quaternions", q).map_err(|e| e.renamed(format!("quaternions[{j}]")))?;
                visit(r, 1.0, weights.get(j));
            }
        }
    }
    Ok(())
}

/// The weighted RMS angle from a mean to the data, summed a datum at a time.
struct Spread {
    mean: DQuat,
    squares: f64,
    total: f64,
}

impl Spread {
    fn new(mean: DQuat) -> Spread {
        Spread { mean, squares: 0.0, total: 0.0 }
    }

    #[inline(always)]
    fn add(&mut self, r: DQuat, w: f64) {
        self.squares += w * angle(self.mean, r).powi(2);
        self.total += w;
    }

    fn rms(&self) -> f64 {
        (self.squares / self.total).sqrt()
    }
}

/// The data checked and normalised, with their weights and their scatter matrix `Σ w_j r_j r_jᵀ`
/// (every method starts from the chordal mean), for the methods that visit the data again and
/// again.
pub(crate) struct Data {
    pub rotations: Vec<DQuat>,
    pub weights: Vec<f64>,
    pub scatter: Symmetric4,
}

impl Data {
    pub(super) fn new<Q: Borrow<DQuat>>(
        quaternions: impl ExactSizeIterator<Item = Q>,
        weights: Weights,
    ) -> Result<Data, KliError> {
        let mut rotations = Vec::with_capacity(quaternions.len());
        let mut scatter = Scatter::default();
        walk(quaternions, &weights, |q, k, w| {
            scatter.add(w * k, q);
            rotations.push(q * k.sqrt());
        })?;
        let weights = weights.0.unwrap_or_else(|| vec![1.0; rotations.len()]);
        Ok(Data { rotations, weights, scatter: scatter.matrix() })
    }

    pub fn total(&self) -> f64 {
        self.weights.iter().sum()
    }

    /// The weighted RMS angle from `q` to the data.
    pub fn dispersion(&self, q: DQuat) -> f64 {
        let mut spread = Spread::new(q);
        for (&r, &w) in self.rotations.iter().zip(&self.weights) {
            spread.add(r, w);
        }
        spread.rms()
    }
}

/// `d(a, b)`: the angle of the rotation between unit quaternions `a` and `b`, in [0, π], blind to
/// their signs. From the chord `c = |a − b|` of the closer sign (`c = 2 sin(d/4)`, computed
/// without cancellation, where `acos(|a·b|)` would lose half the digits of a small angle): halved
/// once more, `sin(d/8) = √(c²/8 / (1 + √(1 − c²/4)))` ≤ sin(π/8), and `d = 8 asin(sin(d/8))` by
/// fdlibm's rational `asin` for arguments below ½: square roots, a division and no call, as the
/// chordal mean takes a million of them.
#[inline(always)]
pub fn angle(a: DQuat, b: DQuat) -> f64 {
    let b = if a.dot(b) < 0.0 { -b } else { b };
    let chord2 = (a - b).length_squared();
    let s2 = chord2 / 8.0 / (1.0 + (1.0 - chord2 / 4.0).sqrt());
    8.0 * asin_small(s2.sqrt(), s2)
}

/// `asin(x)` for `0 ≤ x < ½` given `x` and `x²`: `x + x R(x²)` with fdlibm's (e_asin.c)
/// rational `R`, within an ulp.
#[inline(always)]
fn asin_small(x: f64, t: f64) -> f64 {
    const P: [f64; 6] = [
        0.16666666666666666,
        -0.3255658186224009,
        0.20121253213486293,
        -0.04005553450067941,
        0.0007915349942898145,
        3.479331075960212e-05,
    ];
    const Q: [f64; 4] =
        [-2.403_394_911_734_414, 2.020_945_760_233_505_7, -0.6882839716054533, 0.07703815055590194];
    let p = t * (P[0] + t * (P[1] + t * (P[2] + t * (P[3] + t * (P[4] + t * P[5])))));
    let q = 1.0 + t * (Q[0] + t * (Q[1] + t * (Q[2] + t * Q[3])));
    x + x * (p / q)
}

/// The mean of `quaternions` (any signs, normalised; a slice, or any iterator that knows its
/// length and can be walked twice) with `weights` (each finite and > 0; all 1 when `None`) by
/// `method`. Errors name the argument: an empty list, a quaternion that is not finite or is zero
/// (`quaternions[j]`), a weight that is not finite and positive (`weights[j]`), and a chordal or
/// quaternion mean that is not unique ([`ErrorKind::NotUnique`]).
pub fn average<I>(
    quaternions: I,
    weights: Option<&[f64]>,
    method: Method,
) -> Result<Average, KliError>
where
    I: IntoIterator,
    I::Item: Borrow<DQuat>,
    I::IntoIter: ExactSizeIterator + Clone,
{
    let quaternions = quaternions.into_iter();
    let weights = Weights::new(weights, quaternions.len())?;
    if method == Method::Chordal {
        // No copy of the data: a pass to check it and sum M (`w q qᵀ/|q|²`, so a datum is not
        // normalised), and a pass for the dispersion.
        let mut scatter = Scatter::default();
        walk(quaternions.clone(), &weights, |q, k, w| scatter.add(w * k, q))?;
        let (rotation, residual) = chordal::top(&scatter.matrix())?;
        let mut spread = Spread::new(rotation);
        walk(quaternions, &weights, |q, k, w| spread.add(q * k.sqrt(), w))?;
        let dispersion = spread.rms();
        return Ok(Average { rotation, iterations: 0, residual, dispersion, weights: None });
    }
    let data = Data::new(quaternions, weights)?;
    let (rotation, iterations, residual, weights) = match method {
        // (The chordal mean returned above.)
        Method::Chordal | Method::Quaternion => {
            let reference = chordal::top(&data.scatter).map_or(data.rotations[0], |(q, _)| q);
            (quaternion::sum(&data, Some(reference))?, 0, 0.0, None)
        }
        Method::Geodesic => {
            let (q, iterations, residual) = geodesic::karcher(&data, start(&data));
            (q, iterations, residual, None)
        }
        Method::Median => {
            let median = median::median(&data, start(&data));
            (median.rotation, median.iterations, median.residual, Some(median.weights))
        }
    };
    let dispersion = data.dispersion(rotation);
    Ok(Average { rotation, iterations, residual, dispersion, weights })
}

/// Where the iterative means start: the chordal mean, or where it is not unique the heaviest
/// datum.
fn start(data: &Data) -> DQuat {
    chordal::top(&data.scatter).map(|(q, _)| q).unwrap_or_else(|_| {
        let heaviest = (0..data.weights.len())
            .fold(0, |k, j| if data.weights[j] > data.weights[k] { j } else { k });
        data.rotations[heaviest]
    })
}

#[cfg(test)]
mod tests;
