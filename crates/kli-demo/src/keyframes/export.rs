//! The keyframes page's data: the three curves sampled, as CSV or JSON, with their provenance.

use kli::quaternion::to_wxyz;
use kli::spline::ChainOptions;

use super::model::{Model, STYLES};
use crate::format::{Json, joined, number};
use crate::provenance::{Provenance, Value};

/// CSV: a row a curve and sample time, `t`, the curve's id ("chain", "squad", "slerp"), its
/// quaternion `w, x, y, z`, |ω| and its Hopf point, after the run's parameters as `#` lines.
/// JSON: the parameters, `keys` ([w, x, y, z] each), `keyTimes`, and each curve's `samples`,
/// `{ t, quaternion, angularSpeed, hopf }`.
pub fn export(model: &Model, csv: bool) -> String {
    let provenance = provenance(model);
    let curves = STYLES.iter().zip(model.curves()).zip(&model.series);
    if csv {
        let mut text = provenance.csv_comments();
        text.push_str("t,curve,w,x,y,z,angularSpeed,hopfX,hopfY,hopfZ\n");
        for ((style, curve), s) in curves {
            for (k, &t) in model.times.iter().enumerate() {
                let [w, x, y, z] = to_wxyz(curve.at(t));
                let h = s.hopf[k];
                let fields = joined(&[w, x, y, z, s.speed[k], h.x, h.y, h.z], ",");
                text.push_str(&format!("{},{},{fields}\n", number(t), style.id));
            }
        }
        return text;
    }
    let keys: Vec<f64> = model.keys.quaternions().iter().flat_map(|&q| to_wxyz(q)).collect();
    let mut json = Json::object();
    for ((style, curve), s) in curves {
        let samples = model.times.iter().enumerate().map(|(k, &t)| {
            Json::object()
                .number("t", t)
                .list("quaternion", &to_wxyz(curve.at(t)))
                .number("angularSpeed", s.speed[k])
                .list("hopf", &s.hopf[k].to_array())
        });
        json = json.objects(style.id, samples);
    }
    provenance
        .json(Json::object())
        .lists("keys", keys.chunks(4))
        .list("keyTimes", model.keys.times())
        .raw("curves", &json.end())
        .document()
}

/// The keys, their times and the chain's options, and the columns' units.
fn provenance(model: &Model) -> Provenance {
    let keys = model.keys.quaternions().iter().map(|&q| to_wxyz(q).to_vec()).collect();
    Provenance {
        what: "three curves through the same keyframes: the Kuramoto–Lohe chain (chain), Shoemake's Squad (squad), piecewise SLERP (slerp)",
        parameters: vec![
            ("keys", Value::Lists(keys)),
            ("keyTimes", Value::List(model.keys.times().to_vec())),
            ("smoothness", Value::Number(model.smoothness)),
            (
                "samplesPerSegment",
                Value::Number(ChainOptions::default().samples_per_segment as f64),
            ),
        ],
        units: &[
            (
                "quaternions",
                "[w, x, y, z], scalar first, unit; the keys as used (signs made consistent)",
            ),
            ("t", "the keys' time unit (the page's seconds)"),
            ("angularSpeed", "|omega| in radians per unit of t (world frame, q' = omega q / 2)"),
            ("hopf", "the point of the unit sphere S^2 the body's x-axis points to (paper eq. 5)"),
        ],
    }
}
