//! The synchronisation page's data: every edge (its nodes, its measurement, whether it is wrong,
//! its residual in the flow now and in both solutions, the robust weight and flag) and every node
//! (its truth, the flow now, both solutions), as CSV or JSON, with their provenance.

use kli::quaternion::to_wxyz;

use super::model::Model;
use super::solutions::Solutions;
use crate::format::{Json, joined, number};
use crate::provenance::{Provenance, Value};

/// CSV: a row an edge, `i, j`, its measurement `w, x, y, z`, `wrong` (1 or 0), its residual
/// angle (degrees) in the flow now, in the chordal and in the robust solution, the robust weight
/// and flag, after the parameters and both solutions' figures as `#` lines. JSON: the
/// parameters, `t`, `chordal` and `robust` (cost, median error, certificate or flags), `nodes`
/// (`{ truth, flow, chordal, robust }`) and `edges`.
pub fn export(model: &Model, csv: bool) -> String {
    let provenance = provenance(model);
    let p = &model.problem;
    // A run made unsolved may be saved before its solutions are in: they are computed here.
    let computed;
    let Solutions { chordal, robust } = match &model.solutions {
        Some(solutions) => solutions,
        None => match Solutions::of(p) {
            Ok(solutions) => {
                computed = solutions;
                &computed
            }
            Err(error) => {
                // In JavaScript's names and numbers, as a thrown Error says it.
                let message = error.message(&kli_wasm::error::js_name, &number);
                return format!("# the problem could not be solved: {message}\n");
            }
        },
    };
    let flow = model.flow.residuals();
    let weights = robust.weights.clone().unwrap_or_default();
    let flags = robust.outliers.clone().unwrap_or_default();
    let rows: Vec<[f64; 13]> = p
        .graph
        .edges()
        .iter()
        .enumerate()
        .map(|(k, &[i, j])| {
            let [w, x, y, z] = to_wxyz(p.graph.relative()[k]);
            [
                i as f64,
                j as f64,
                w,
                x,
                y,
                z,
                f64::from(u8::from(p.wrong[k])),
                flow[k].to_degrees(),
                chordal.residuals[k].to_degrees(),
                robust.residuals[k].to_degrees(),
                weights.get(k).copied().unwrap_or(f64::NAN),
                f64::from(u8::from(flags.get(k).copied().unwrap_or(false))),
                p.graph.weights()[k],
            ]
        })
        .collect();
    let certificate = chordal.certificate;
    let chordal_error = p.median_error(&chordal.rotations).to_degrees();
    let robust_error = p.median_error(&robust.rotations).to_degrees();
    if csv {
        let mut text = provenance.csv_comments();
        let (certified, lambda) =
            certificate.map_or((false, f64::NAN), |c| (c.certified, c.lambda_min));
        text.push_str(&format!(
            "# chordal: cost {}, median error {} degrees, certified {certified}, lambdaMin {}\n",
            number(chordal.cost),
            number(chordal_error),
            number(lambda)
        ));
        text.push_str(&format!(
            "# robust: cost {}, median error {} degrees, flagged {}\n",
            number(robust.cost),
            number(robust_error),
            flags.iter().filter(|&&f| f).count()
        ));
        text.push_str(&format!(
            "# flow: t {}, cost {}\n",
            number(model.flow.time()),
            number(model.flow.cost())
        ));
        text.push_str("i,j,w,x,y,z,wrong,flowResidualDegrees,chordalResidualDegrees,robustResidualDegrees,robustWeight,outlier,weight\n");
        for row in &rows {
            text.push_str(&joined(row, ","));
            text.push('\n');
        }
        return text;
    }
    let q = model.flow.rotations();
    let g = p.gauge(q).conjugate();
    let nodes = (0..p.truth.len()).map(|i| {
        Json::object()
            .list("truth", &to_wxyz(p.truth[i]))
            .list("flow", &to_wxyz(g * q[i]))
            .list("chordal", &to_wxyz(chordal.rotations[i]))
            .list("robust", &to_wxyz(robust.rotations[i]))
    });
    let edges = rows.iter().map(|r| {
        Json::object()
            .list("nodes", &r[0..2])
            .list("relative", &r[2..6])
            .flag("wrong", r[6] == 1.0)
            .number("flowResidualDegrees", r[7])
            .number("chordalResidualDegrees", r[8])
            .number("robustResidualDegrees", r[9])
            .number("robustWeight", r[10])
            .flag("outlier", r[11] == 1.0)
    });
    let mut chordal_json = Json::object()
        .number("cost", chordal.cost)
        .number("medianErrorDegrees", chordal_error)
        .number("iterations", chordal.iterations as f64);
    if let Some(c) = certificate {
        chordal_json = chordal_json
            .flag("certified", c.certified)
            .number("lambdaMin", c.lambda_min)
            .number("gap", c.gap);
    }
    let robust_json = Json::object()
        .number("cost", robust.cost)
        .number("medianErrorDegrees", robust_error)
        .number("scaleDegrees", robust.scale.unwrap_or(f64::NAN).to_degrees())
        .number("flagged", flags.iter().filter(|&&f| f).count() as f64);
    provenance
        .json(Json::object())
        .number("t", model.flow.time())
        .number("flowCost", model.flow.cost())
        .raw("chordal", &chordal_json.end())
        .raw("robust", &robust_json.end())
        .objects("nodes", nodes)
        .objects("edges", edges)
        .document()
}

/// The problem's recipe and the columns' units.
fn provenance(model: &Model) -> Provenance {
    let o = &model.options;
    Provenance {
        what: "rotations synchronised on a graph: measured relative rotations, the chordal and robust solutions, and the Lohe flow from a random start",
        parameters: vec![
            ("count", Value::Number(o.count as f64)),
            ("graph", Value::Text(o.shape.name().into())),
            ("noiseDegrees", Value::Number(o.noise)),
            ("wrong", Value::Number(o.wrong)),
            ("seed", Value::Number(o.seed as f64)),
            ("consensus", Value::Flag(o.consensus)),
            ("dt", Value::Number(model.dt)),
            ("integrator", Value::Text("Euler, projected to S^3".into())),
        ],
        units: &[
            ("quaternions", "[w, x, y, z], scalar first, unit; relative[i, j] = conj(q_i) q_j"),
            ("noiseDegrees", "standard deviation of each measurement's angle of noise, degrees"),
            ("wrong", "share of edges measured as uniformly random rotations"),
            ("residual", "angle between q_i relative[i, j] and q_j, degrees"),
            ("flow", "the flow's rotations now, moved by the gauge that best fits the truth"),
            ("chordal, robust", "the solutions, node 0 at the identity"),
        ],
    }
}
