//! Averaging rotations by the paper's model (MATH.md, "Averaging rotations: many pinned leaders,
//! one follower"): the measurements `r_j` (weights `w_j > 0`, any signs) are pinned leaders, one
//! follower `q` is coupled to all of them, and where it settles is the mean.
//!
//! - [`Method::Chordal`]: the sign-blind flow `q' = M q − (qᵀM q) q`, `M = Σ w_j r_j r_jᵀ`, settles
//!   on the top eigenvector of `M` (Markley's and SciPy's mean), computed by [`eigen`] in one pass
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

pub use chordal::{chordal_flow, scatter};
pub use eigen::{Symmetric4, eigen};
pub use quaternion::quaternion_mean;

use glam::DQuat;

use crate::error::{ErrorKind, KliError, Requirement, require};
use crate::quaternion::unit;

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
    /// The mean rotation, a unit quaternion (its sign is the data's majority hemisphere's).
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

/// The data checked: each quaternion finite and not zero (normalised), each weight finite and
/// positive, as many weights as quaternions (all 1 when absent), the weights scaled so that the
/// largest is 1.
pub(crate) struct Data {
    pub rotations: Vec<DQuat>,
    pub weights: Vec<f64>,
}

impl Data {
    pub fn new(quaternions: &[DQuat], weights: Option<&[f64]>) -> Result<Data, KliError> {
        if quaternions.is_empty() {
            return Err(KliError::invalid("quaternions", "must hold at least one rotation"));
        }
        // Named only when refused: a name a datum costs more than the mean.
        let rotations = quaternions
            .iter()
            .enumerate()
            .map(|(j, &q)| {
                unit("quaternions", q).map_err(|e| e.renamed(format!("quaternions[{j}]")))
            })
            .collect::<Result<Vec<_>, _>>()?;
        let weights = match weights {
            None => vec![1.0; rotations.len()],
            Some(w) if w.len() != rotations.len() => {
                let problem = format!(
                    "must hold one weight for each of the {} rotations (got {})",
                    rotations.len(),
                    w.len()
                );
                return Err(KliError::invalid("weights", problem));
            }
            Some(w) => w
                .iter()
                .enumerate()
                .map(|(j, &x)| {
                    require("weights", x, Requirement::Positive)
                        .map_err(|e| e.renamed(format!("weights[{j}]")))
                })
                .collect::<Result<Vec<_>, _>>()?,
        };
        // The means do not change with the weights' scale: scaled by the largest, 10⁻³⁰⁸ and
        // 10³⁰⁸ are as good as 1, and no sum below overflows or vanishes.
        let largest = weights.iter().fold(0.0_f64, |m, &w| m.max(w));
        let weights = weights.iter().map(|w| w / largest).collect();
        Ok(Data { rotations, weights })
    }

    pub fn total(&self) -> f64 {
        self.weights.iter().sum()
    }

    /// The weighted RMS angle from `q` to the data.
    pub fn dispersion(&self, q: DQuat) -> f64 {
        let squares: f64 =
            self.rotations.iter().zip(&self.weights).map(|(&r, w)| w * angle(q, r).powi(2)).sum();
        (squares / self.total()).sqrt()
    }
}

/// `d(a, b)`: the angle of the rotation between unit quaternions `a` and `b`, in [0, π], blind to
/// their signs; `4 atan2(|a − b|, |a + b|)` of the closer sign, accurate at both ends.
pub fn angle(a: DQuat, b: DQuat) -> f64 {
    let b = if a.dot(b) < 0.0 { -b } else { b };
    4.0 * (a - b).length().atan2((a + b).length())
}

/// The mean of `quaternions` (any signs, normalised) with `weights` (each finite and > 0; all 1
/// when `None`) by `method`. Errors name the argument: an empty list, a quaternion that is not
/// finite or is zero (`quaternions[j]`), a weight that is not finite and positive (`weights[j]`),
/// and a chordal or quaternion mean that is not unique ([`ErrorKind::NotUnique`]).
pub fn average(
    quaternions: &[DQuat],
    weights: Option<&[f64]>,
    method: Method,
) -> Result<Average, KliError> {
    let data = Data::new(quaternions, weights)?;
    let (rotation, iterations, residual, weights) = match method {
        Method::Chordal => {
            let (q, residual) = chordal::chordal(&data)?;
            (q, 0, residual, None)
        }
        Method::Quaternion => {
            let reference = chordal::chordal(&data).map(|(q, _)| q).unwrap_or(data.rotations[0]);
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
    chordal::chordal(data).map(|(q, _)| q).unwrap_or_else(|_| {
        let heaviest = (0..data.weights.len())
            .fold(0, |k, j| if data.weights[j] > data.weights[k] { j } else { k });
        data.rotations[heaviest]
    })
}

#[cfg(test)]
mod tests;
