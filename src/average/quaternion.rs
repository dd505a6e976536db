//! The quaternion mean (MATH.md, "Averaging rotations"): where the Lohe follower
//! `q' = m − (q·m) q`, `m = Σ w_j s_j r_j`, settles, `m/|m|`. It depends on the signs `s_j`: the
//! data aligned to one hemisphere give a fair estimate; left as they come (the teaching point), a
//! rotation's sign changes the answer.

use glam::DQuat;

use super::{Average, Data, Method, Weights, average};
use crate::error::KliError;

/// `m/|m|`, the data's signs aligned to `reference`'s hemisphere (`s_j = sign(r_j·reference)`),
/// or left as they are when `reference` is `None`; an Error when they sum to zero.
pub(super) fn sum(data: &Data, reference: Option<DQuat>) -> Result<DQuat, KliError> {
    let m = data.rotations.iter().zip(&data.weights).fold(
        DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0),
        |m, (&r, &w)| {
            let sign = match reference {
                Some(reference) if reference.dot(r) < 0.0 => -1.0,
                _ => 1.0,
            };
            m + r * (w * sign)
        },
    );
    let length = m.length();
    if length <= 1e-12 * data.total() {
        let problem = "sum to zero (their quaternion mean is not defined): align their signs, or take the chordal mean";
        return Err(KliError::invalid("quaternions", problem));
    }
    Ok(m / length)
}

/// The quaternion mean of `quaternions` with `weights`: aligned to the hemisphere of the chordal
/// mean (of the first datum where that is not unique), as [`average`] with
/// [`Method::Quaternion`]; or with `aligned: false`, the signs as they come. Errors as
/// [`average`]'s.
pub fn quaternion_mean(
    quaternions: &[DQuat],
    weights: Option<&[f64]>,
    aligned: bool,
) -> Result<Average, KliError> {
    if aligned {
        return average(quaternions, weights, Method::Quaternion);
    }
    let data = Data::new(quaternions.iter(), Weights::new(weights, quaternions.len())?)?;
    let rotation = sum(&data, None)?;
    let dispersion = data.dispersion(rotation);
    Ok(Average { rotation, iterations: 0, residual: 0.0, dispersion, weights: None })
}
