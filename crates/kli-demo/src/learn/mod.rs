//! The `LearnDemo` class: the tour's run (learn.html, "Rotations, from a turn to the Kuramoto
//! flow"). One run holds every section's figure, each a view: the reader's controls are its
//! options, and the tour's clock (0 to 12, past the paper's T = 11.66, or on past Algorithm 1's stop
//! for a smaller ε) moves the flows. What it
//! computes is `model`, its pictures `view`; this file is the class and the run contract.

mod model;
mod rates;
mod view;
mod words;

use std::cell::OnceCell;
use std::str::FromStr;

use glam::DQuat;
use kli::quaternion::to_wxyz;
use kli::{ErrorKind, Integrator, KliError};
use kli_wasm::error::JsResult;
use kli_wasm::options::Fields;
use wasm_bindgen::prelude::*;

use crate::aircraft::{Face, aircraft};
use crate::clock::Clock;
use crate::figure::{Figure, Frame, Layer, Motion, Record, View, names};
use crate::format::{Json, joined};
use crate::pen::Pen;
use crate::provenance::{Provenance, Value};
use model::{Axis, Model, Options, in_plane, nlerp, paper_p, paper_r, plane, slerp};
use words::Words;

/// Every section's figure for one setting of the reader's controls, the tour's clock, and the
/// object's mesh.
#[wasm_bindgen]
pub struct LearnDemo {
    model: Model,
    clock: Clock,
    mesh: Vec<Face>,
    summary: OnceCell<JsValue>,
}

#[wasm_bindgen(typescript_custom_section)]
const TYPES: &'static str = r#"
/** The tour's controls; every key is optional (angles in degrees). */
export interface LearnDemoOptions {
  /** Euler angles, R = R_z(yaw) R_y(pitch) R_x(bank): yaw and bank −180 to 180, pitch −90 to 90. Defaults 30, 40, 0. */
  yaw?: number; pitch?: number; bank?: number;
  /** The turn's axis, "x", "y", "z" or "diagonal" ((1,1,1)/√3), and its angle, 0 to 720. Defaults "z", 90. */
  axis?: string; angle?: number;
  /** SLERP's parameter from the paper's p to r, 0 to 1. Default 0.5. */
  s?: number;
  /** The roll about the object's nose after the turn, −180 to 180. Default 0. */
  roll?: number;
  /** The Kuramoto phases' coupling K, 0 to 4. Default 1.5. */
  coupling?: number;
  /** The Lohe swarm's coupling K, 0 to 4. Default 3. */
  lohe?: number;
  /** Algorithm 1's tolerance ε = 10^−digits, digits a whole number from 1 to 10. Default 5. */
  digits?: number;
  /** Algorithm 1's step δ, 0.001 to 0.5. Default 0.01. */
  delta?: number;
  /** The integrator shown thick in the drift figure, "euler", "rk4" or "geodesic", and its step, 0.01 to 1. Defaults "euler", 0.5. */
  integrator?: string; step?: number;
  /** The keyframe chain's smoothness in section 9, 0 (piecewise SLERP) to 1. Default 1. */
  smoothness?: number;
  /** The words the views draw, in the page's language, by key (www/learn/strings/en.js's `canvas`); English when absent. */
  words?: Record<string, string>;
}
/** What the tour's run sums up to: each section's figures' values at rest. */
export interface LearnSummary {
  /** Degrees between the yaw and bank axes: 90 − |pitch|. */
  lockDegrees: number;
  /** The turn's quaternion [w, x, y, z]. */
  turn: number[];
  /** SLERP's and NLERP's angle along the arc from p, degrees (of 60). */
  slerpDegrees: number; nlerpDegrees: number;
  /** The Hopf image of the rolled turn (paper eq. 5), and where its wing points. */
  nose: number[]; wing: number[];
  /** Algorithm 1's stop T, its steps, the predicted T* and ε. */
  finalTime: number; steps: number; predictedTime: number; epsilon: number;
  /** The largest | |q| − 1 | of each integrator at the reader's step. */
  drift: { euler: number; rk4: number; geodesic: number };
  /** Section 9's turning rate ω through the keyframes (keys: 16 numbers, [w, x, y, z] each, at
   *  times 0, 1, 2, 3): the chain's largest jump |ω(t⁺) − ω(t⁻)| at an inner key and that key's
   *  index, piecewise SLERP's, the chain's largest |ω̇| (rad per unit time²; meaningful only when
   *  continuous), and whether its ω is continuous (smoothness above 0). */
  rates: { keys: number[]; jump: number; jumpKey: number; slerpJump: number; slerpJumpKey: number;
    acceleration: number; continuous: boolean };
}
/** The tour's values at a time t: the phases' order R, the swarm's order and widest angle to the
 *  leader (degrees), KLI's q(t), φ(t) (degrees), s(t), Algorithm 1's step n and ‖r − qₙ‖. */
export interface LearnReadings {
  order: number; swarmOrder: number; spreadDegrees: number;
  q: number[]; phiDegrees: number; s: number; step: number; stepTime: number; distance: number;
}
"#;

#[wasm_bindgen]
extern "C" {
    #[wasm_bindgen(typescript_type = "LearnDemoOptions")]
    pub type LearnDemoOptions;
}

#[wasm_bindgen]
impl LearnDemo {
    /// Every section's figure for `options`; an Error naming the option that is out of range.
    #[wasm_bindgen(constructor)]
    pub fn new(options: Option<LearnDemoOptions>) -> JsResult<LearnDemo> {
        let model = Model::new(read_options(options.map(JsValue::from))?)?;
        Ok(LearnDemo {
            clock: Clock::new(0.0, model.end),
            model,
            mesh: aircraft(),
            summary: OnceCell::new(),
        })
    }

    /// The values the tour's text quotes at time `t` (a non-finite `t` reads as 0).
    #[wasm_bindgen(unchecked_return_type = "LearnReadings")]
    pub fn readings(&self, t: f64) -> JsValue {
        let t = crate::figure::finite(t).clamp(0.0, self.model.end);
        let m = &self.model;
        let (order, _) = model::order(m.phases.at(t));
        let n = m.step_at(t);
        let (times, qs) = (m.path.times(), m.path.quaternions());
        let distance = qs.get(n).map_or(f64::NAN, |&q| (m.path.target() - q).length());
        Record::new()
            .set("order", order)
            .set("swarmOrder", m.swarm.order(t))
            .set("spreadDegrees", m.swarm.spread(t))
            .set("q", list(&to_wxyz(m.kli_at(t))))
            .set("phiDegrees", m.phi(t).to_degrees())
            .set("s", m.warp(t))
            .set("step", n as f64)
            .set("stepTime", times.get(n).copied().unwrap_or(0.0))
            .set("distance", distance)
            .end()
    }
}

fn list(values: &[f64]) -> js_sys::Array {
    values.iter().map(|&c| JsValue::from(c)).collect()
}

/// A number option within `[min, max]`, or an Error naming it.
fn bounded(fields: &Fields, key: &str, min: f64, max: f64) -> Result<Option<f64>, KliError> {
    let Some(value) = fields.number(key)? else { return Ok(None) };
    if (min..=max).contains(&value) {
        return Ok(Some(value));
    }
    let (lo, hi, got) =
        (crate::format::number(min), crate::format::number(max), crate::format::number(value));
    Err(KliError::invalid(key, format!("must be a number from {lo} to {hi} (got {got})")))
}

/// The options, checked: an Error names the option.
fn read_options(value: Option<JsValue>) -> Result<Options, KliError> {
    let example = "{ axis: \"z\", angle: 90 }";
    let keys = [
        "yaw",
        "pitch",
        "bank",
        "axis",
        "angle",
        "s",
        "roll",
        "coupling",
        "lohe",
        "digits",
        "delta",
        "integrator",
        "step",
        "smoothness",
        "words",
    ];
    let mut o = Options::default();
    let Some(fields) = Fields::new(value, &keys, example)? else { return Ok(o) };
    let numbers: [(&str, f64, f64, &mut f64); 11] = [
        ("yaw", -180.0, 180.0, &mut o.yaw),
        ("pitch", -90.0, 90.0, &mut o.pitch),
        ("bank", -180.0, 180.0, &mut o.bank),
        ("angle", 0.0, 720.0, &mut o.angle),
        ("s", 0.0, 1.0, &mut o.s),
        ("roll", -180.0, 180.0, &mut o.roll),
        ("coupling", 0.0, 4.0, &mut o.coupling),
        ("lohe", 0.0, 4.0, &mut o.lohe),
        ("delta", 0.001, 0.5, &mut o.delta),
        ("step", 0.01, 1.0, &mut o.step),
        ("smoothness", 0.0, 1.0, &mut o.smoothness),
    ];
    for (key, min, max, slot) in numbers {
        if let Some(value) = bounded(&fields, key, min, max)? {
            *slot = value;
        }
    }
    if let Some(digits) = fields.whole("digits", 1.0, 10.0)? {
        o.digits = digits;
    }
    if let Some(name) = fields.name("axis")? {
        o.axis = Axis::parse(&name).ok_or_else(|| {
            KliError::new("axis", ErrorKind::UnknownName { got: name, allowed: &Axis::NAMES })
        })?;
    }
    if let Some(name) = fields.name("integrator")? {
        o.integrator = Integrator::from_str(&name).map_err(|e| e.renamed("integrator"))?;
    }
    if let Some(value) = fields.value("words")? {
        o.words = read_words(&value)?;
    }
    Ok(o)
}

/// The views' words from an object of strings by key (each optional: English stands in); an
/// Error naming `words` for a value that is no string.
fn read_words(value: &JsValue) -> Result<Words, KliError> {
    if !value.is_object() {
        return Err(KliError::invalid("words", "must be an object of strings by key"));
    }
    let mut words = Words::default();
    for &key in Words::KEYS {
        let word = js_sys::Reflect::get(value, &JsValue::from_str(key))
            .map_err(|_| KliError::invalid("words", format!("cannot read \"{key}\"")))?;
        if word.is_undefined() {
            continue;
        }
        let text = word
            .as_string()
            .ok_or_else(|| KliError::invalid("words", format!("\"{key}\" must be a string")))?;
        if let Some(slot) = words.slot(key) {
            *slot = text;
        }
    }
    Ok(words)
}

impl LearnDemo {
    fn make_summary(&self) -> JsValue {
        let m = &self.model;
        let o = &m.options;
        let (slerp_angle, nlerp_angle) = arc_angles(o.s);
        let q = m.rolled();
        let drift = |i: Integrator| {
            m.drifts.iter().find(|d| d.integrator == i).map_or(f64::NAN, |d| d.largest())
        };
        let drifts = Record::new()
            .set("euler", drift(Integrator::Euler))
            .set("rk4", drift(Integrator::Rk4))
            .set("geodesic", drift(Integrator::Geodesic))
            .end();
        let wing = q * glam::DVec3::Y;
        let rates = &m.rates;
        let ((jump, key), (slerp_jump, slerp_key)) =
            (rates.chain.largest_jump(), rates.slerp.largest_jump());
        let keys: Vec<f64> = rates.keys.quaternions().iter().flat_map(|&k| to_wxyz(k)).collect();
        let rates = Record::new()
            .set("keys", list(&keys))
            .set("jump", jump)
            .set("jumpKey", key as f64)
            .set("slerpJump", slerp_jump)
            .set("slerpJumpKey", slerp_key as f64)
            .set("acceleration", rates.chain.acceleration)
            .set("continuous", rates.continuous())
            .end();
        Record::new()
            .set("lockDegrees", model::lock_angle(o.pitch))
            .set("turn", list(&to_wxyz(m.turn())))
            .set("slerpDegrees", slerp_angle)
            .set("nlerpDegrees", nlerp_angle)
            .set("nose", list(&m.nose().to_array()))
            .set("wing", list(&wing.to_array()))
            .set("finalTime", m.path.final_time())
            .set("steps", m.path.steps() as f64)
            .set("predictedTime", m.predicted())
            .set("epsilon", o.epsilon())
            .set("drift", drifts)
            .set("rates", rates)
            .end()
    }
}

/// SLERP's and NLERP's angles along the paper's arc from `p` at `s`, degrees.
fn arc_angles(s: f64) -> (f64, f64) {
    let (p, r) = (paper_p(), paper_r());
    plane(p, r).map_or((0.0, 0.0), |basis| {
        let angle = |q: DQuat| in_plane(q, basis).to_degrees();
        (angle(slerp(p, r, s)), angle(nlerp(p, r, s)))
    })
}

crate::clock::clocked!(LearnDemo);

crate::figure::figure_class!(LearnDemo, "LearnSummary");

/// The tour's views, in its order: a figure a section (two where the section shows two things).
impl Figure for LearnDemo {
    const VIEWS: &'static [View] = &[
        View { name: "euler", title: "Euler angles and gimbal lock", motion: Motion::Still },
        View { name: "turn", title: "A turn by axis and angle", motion: Motion::Still },
        View {
            name: "cover",
            title: "q and −q on S³ turn the object alike",
            motion: Motion::Still,
        },
        View { name: "slerp", title: "SLERP and NLERP on the great circle", motion: Motion::Still },
        View { name: "hopf", title: "The Hopf map: where the nose points", motion: Motion::Still },
        View { name: "rolled", title: "The object, rolled about its nose", motion: Motion::Still },
        View {
            name: "phases",
            title: "Kuramoto phases and their order R(t)",
            motion: Motion::Moving,
        },
        View {
            name: "lohe",
            title: "The Lohe model on S³ with a pinned leader",
            motion: Motion::Moving,
        },
        View {
            name: "kli",
            title: "KLI: q′ = r − (q·r) q on the great circle",
            motion: Motion::Moving,
        },
        View {
            name: "clock",
            title: "KLI's time warp s(t) against SLERP's t/T",
            motion: Motion::Moving,
        },
        View { name: "steps", title: "Algorithm 1's steps towards ε", motion: Motion::Moving },
        View { name: "drift", title: "The integrators' drift off S³", motion: Motion::Still },
        View {
            name: "rates",
            title: "The turning rate ω(t) through keyframes",
            motion: Motion::Still,
        },
    ];
    const NAMES: &'static [&'static str] = &names::<13>(Self::VIEWS);
    const EXPORT: &'static str = "tour";

    /// See `LearnSummary` (the TypeScript section above).
    fn summary(&self) -> JsValue {
        self.summary.get_or_init(|| self.make_summary()).clone()
    }

    fn paint(&self, which: &View, layer: Layer, pen: &Pen, frame: &Frame) {
        if !layer.still() {
            return;
        }
        let (m, mesh) = (&self.model, &self.mesh[..]);
        match which.name {
            "euler" => view::draw_euler(pen, m, mesh, frame),
            "turn" => view::draw_turn(pen, m, mesh, frame),
            "cover" => view::draw_cover(pen, m, mesh, frame),
            "slerp" => view::draw_slerp(pen, m, frame),
            "hopf" => view::draw_hopf(pen, m, frame),
            "rolled" => view::draw_rolled(pen, m, mesh, frame),
            "phases" => view::draw_phases(pen, m, frame),
            "lohe" => view::draw_lohe(pen, m, frame),
            "kli" => view::draw_kli(pen, m, frame),
            "clock" => view::draw_clock(pen, m, frame),
            "steps" => view::draw_steps(pen, m, frame),
            "drift" => view::draw_drift(pen, m, frame),
            _ => view::draw_rates(pen, m, frame),
        }
    }

    /// Algorithm 1's path on the paper's example with the reader's ε and δ: CSV a row a step
    /// (`t, w, x, y, z, distance`), JSON the same as lists, with the parameters.
    fn export(&self, csv: bool) -> String {
        let m = &self.model;
        let target = m.path.target();
        let rows: Vec<[f64; 6]> = m
            .path
            .times()
            .iter()
            .zip(m.path.quaternions())
            .map(|(&t, &q)| {
                let [w, x, y, z] = to_wxyz(q);
                [t, w, x, y, z, (target - q).length()]
            })
            .collect();
        let provenance = Provenance {
            what: "Algorithm 1 of Kapić and Crnkić on the paper's example (p = k, r = (1 + i + j + k)/2), RK4",
            parameters: vec![
                ("p", Value::List(to_wxyz(paper_p()).to_vec())),
                ("r", Value::List(to_wxyz(paper_r()).to_vec())),
                ("epsilon", Value::Number(m.options.epsilon())),
                ("delta", Value::Number(m.options.delta)),
                ("finalTime", Value::Number(m.path.final_time())),
                ("predictedTime", Value::Number(m.predicted())),
            ],
            units: &[
                ("t", "time of the model, a multiple of delta"),
                ("w,x,y,z", "q(t), scalar first"),
                ("distance", "‖r − q(t)‖ in R⁴"),
            ],
        };
        if csv {
            let mut text = provenance.csv_comments();
            text.push_str("t,w,x,y,z,distance\n");
            for row in &rows {
                text.push_str(&joined(row, ","));
                text.push('\n');
            }
            return text;
        }
        provenance
            .json(Json::object())
            .list("times", &rows.iter().map(|r| r[0]).collect::<Vec<_>>())
            .lists("quaternions", rows.iter().map(|r| &r[1..5]))
            .list("distances", &rows.iter().map(|r| r[5]).collect::<Vec<_>>())
            .document()
    }
}

#[cfg(test)]
mod tests;
