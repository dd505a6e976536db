//! The averaging page's data: the measurements and the four means, as CSV or JSON, with their
//! provenance.

use kli::average::angle;
use kli::quaternion::to_wxyz;

use super::model::{Model, STYLES};
use crate::format::{Json, joined};
use crate::provenance::{Provenance, Value};

/// CSV: a row a measurement, its index, its quaternion `w, x, y, z`, whether it is wild (1) or
/// a noisy measurement (0), its final weight in the median and its angle to the truth, after the
/// run's parameters, the truth and the means as `#` lines. JSON: the parameters, `truth`,
/// `means` (`{ method, rotation, errorDegrees, dispersionDegrees, iterations }`) and
/// `measurements` (`{ quaternion, wild, medianWeight, angleToTruthDegrees }`).
pub fn export(model: &Model, csv: bool) -> String {
    let provenance = provenance(model);
    let weights = model.means[3].weights.clone().unwrap_or_default();
    let rows: Vec<[f64; 8]> = model
        .data
        .iter()
        .enumerate()
        .map(|(j, &q)| {
            let [w, x, y, z] = to_wxyz(q);
            let wild = if model.wild[j] { 1.0 } else { 0.0 };
            let weight = weights.get(j).copied().unwrap_or(0.0);
            [j as f64, w, x, y, z, wild, weight, angle(q, model.truth).to_degrees()]
        })
        .collect();
    let errors = model.errors();
    if csv {
        let mut text = provenance.csv_comments();
        text.push_str(&format!("# truth = [{}]\n", joined(&to_wxyz(model.truth), ", ")));
        for ((mean, style), e) in model.means.iter().zip(&STYLES).zip(&errors) {
            let q = joined(&to_wxyz(mean.rotation), ", ");
            let e = e.to_degrees();
            text.push_str(&format!("# {} mean = [{q}], {e} degrees from the truth\n", style.name));
        }
        let columns = "measurement,w,x,y,z,wild,medianWeight,angleToTruthDegrees\n";
        text.push_str(columns);
        for row in &rows {
            text.push_str(&joined(row, ","));
            text.push('\n');
        }
        return text;
    }
    let means = model.means.iter().zip(&STYLES).zip(&errors).map(|((mean, style), e)| {
        Json::object()
            .string("method", style.method.name())
            .list("rotation", &to_wxyz(mean.rotation))
            .number("errorDegrees", e.to_degrees())
            .number("dispersionDegrees", mean.dispersion.to_degrees())
            .number("iterations", mean.iterations as f64)
    });
    let measurements = rows.iter().map(|r| {
        Json::object()
            .list("quaternion", &r[1..5])
            .flag("wild", r[5] == 1.0)
            .number("medianWeight", r[6])
            .number("angleToTruthDegrees", r[7])
    });
    provenance
        .json(Json::object())
        .list("truth", &to_wxyz(model.truth))
        .objects("means", means)
        .objects("measurements", measurements)
        .document()
}

/// The measurements' recipe (count, noise, outliers, seed, moved), and the columns' units.
fn provenance(model: &Model) -> Provenance {
    let o = &model.options;
    let moved = o.moved.iter().map(|&(j, q)| [vec![j as f64], to_wxyz(q).to_vec()].concat());
    Provenance {
        what: "noisy measurements of one rotation and four means of them (chordal, quaternion, geodesic, median)",
        parameters: vec![
            ("count", Value::Number(o.count as f64)),
            ("noiseDegrees", Value::Number(o.noise)),
            ("outliers", Value::Number(o.outliers)),
            ("seed", Value::Number(o.seed as f64)),
            ("moved", Value::Lists(moved.collect())),
        ],
        units: &[
            ("quaternions", "[w, x, y, z], scalar first, unit; the measurements' signs are random"),
            ("noiseDegrees", "standard deviation of the noise about each axis, degrees"),
            ("outliers", "share of measurements replaced by uniformly random rotations"),
            ("moved", "[index, w, x, y, z]: measurements moved by hand (wild)"),
            ("medianWeight", "the measurement's final Weiszfeld weight in the median (sum 1)"),
            ("angleToTruthDegrees", "rotation angle between the measurement and the truth"),
        ],
    }
}
