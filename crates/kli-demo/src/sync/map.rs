//! The map of a pose graph (SLAM): a file's graph, or the page's built-in one ([`World`]),
//! solved whole by [`kli::sync::synchronize_poses`] (SE-Sync: rotations and translations,
//! certified), and drawn as the trajectory seen from above (2D) or turnable (3D): its initial
//! estimate beside the optimum, each edge coloured by its misfit.
//!
//! An edge's misfit is its share of the cost `f = Σ κ ‖R_j − R_i R̃_ij‖²_F + τ ‖t_j − t_i −
//! R_i t̃_ij‖²` (SE-Sync's, the solver's), per degree of freedom, square-rooted:
//! `√(f_ij / (3 or 6))`, in standard deviations of the noise the file's information matrices
//! describe (κ and τ are their inverse variances; about 1 where an edge fits as well as its
//! noise allows).
//!
//! The solve runs in the page's worker (`SyncMap.solve`, telling its stages as it goes); the
//! page then reads the file again with the answer (`SyncMap.solved`). The answer's numbers:
//! `[cost, iterations, λ_min, tolerance, certified (1 or 0), rank, lower bound]`, then `4n`
//! rotations
//! (`w, x, y, z`) and `3n` positions.

use std::f64::consts::FRAC_PI_2;
use std::fmt::Write;

use glam::{DMat3, DQuat, DVec3};
use kli::sync::{
    OtherLines, PoseGraph, PoseOptions, PoseStage, read_g2o, synchronize_poses_observed,
};
use kli::{KliError, from_wxyz, to_wxyz};
use kli_wasm::error::JsResult;
use kli_wasm::options::Fields;
use kli_wasm::typed::numbers;
use kli_wasm::value::describe;
use wasm_bindgen::prelude::*;
use web_sys::CanvasRenderingContext2d;

use super::initial::{Poses, initial};
use super::map_view::{Look, MapPanel, draw_map};
use super::world::{MAX_CLOSURES, MAX_NOISE, World, WorldOptions, route};
use crate::camera::Camera;
use crate::figure::{Frame, Record};
use crate::format::exponential;
use crate::palette::{BACKGROUND, MUTED};
use crate::pen::{Pen, svg_document};

/// The numbers before the poses in the answer.
pub const HEAD: usize = 7;

/// Where a 3D map is first seen from: azimuth and elevation, degrees (the page's "oblique").
const CAMERA: (f64, f64) = (-60.0, 35.0);

/// What the solver found, as the answer's numbers carry it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Answer {
    pub cost: f64,
    pub iterations: usize,
    pub lambda_min: f64,
    pub tolerance: f64,
    pub certified: bool,
    pub rank: usize,
    /// A proven lower bound on the global minimum ([`kli::sync::PoseCertificate::lower_bound`]).
    pub lower_bound: f64,
}

/// A pose graph, its initial estimate and its certified optimum, and how the map is turned.
#[wasm_bindgen]
pub struct SyncMap {
    graph: PoseGraph,
    initial: Poses,
    /// Whether the initial estimate is the file's own (else the odometry chained).
    from_file: bool,
    optimum: Poses,
    answer: Answer,
    initial_misfits: Vec<f64>,
    optimum_misfits: Vec<f64>,
    initial_cost: f64,
    /// Each pose's true position, where it is known (the built-in graph's route).
    truth: Option<Vec<DVec3>>,
    /// The 3D camera, radians.
    azimuth: f64,
    elevation: f64,
}

#[wasm_bindgen(typescript_custom_section)]
const TYPES: &'static str = r#"
/** The page's built-in pose graph: every key optional. */
export interface WorldOptions {
  /** The heading noise of every measurement, degrees (σ), 0 to 10; the translation's is 0.05 m a
   *  degree. Default 2. */
  noise?: number;
  /** How many loop closures, 0 to 40. Default 8. */
  closures?: number;
  /** The noise's seed. Default 1. */
  seed?: number;
}
/** What a pose graph's map sums up to. */
export interface SyncMapSummary {
  dimension: number;
  poses: number;
  edges: number;
  /** Edges between poses that are not consecutive. */
  closures: number;
  /** Whether the initial estimate is the file's own VERTEX lines (else the odometry chained). */
  fromFile: boolean;
  initialCost: number;
  cost: number;
  certified: boolean;
  lambdaMin: number;
  tolerance: number;
  rank: number;
  /** A proven lower bound on the global minimum of the cost: the optimum found is within
   *  cost − lowerBound of it (where the relaxation is not tight, SE-Sync's suboptimality bound). */
  lowerBound: number;
  iterations: number;
  /** The median edge misfit in the optimum, standard deviations. */
  medianMisfit: number;
  /** Lines of other kinds (landmarks, priors, parameters), skipped. */
  skipped: number;
  /** The root mean square distance of the poses from their truth, metres, in the initial
   *  estimate and in the optimum: NaN unless the truth is known (`withTruth`). */
  truthErrorInitial: number;
  truthErrorOptimum: number;
}
"#;

#[wasm_bindgen]
extern "C" {
    #[wasm_bindgen(typescript_type = "WorldOptions")]
    pub type WorldOptionsObject;
}

#[wasm_bindgen]
impl SyncMap {
    /// The built-in pose graph's g2o text: a robot's loop through a town of 3 × 2 blocks (192
    /// poses, its odometry chained as the vertices); an Error naming the option out of range.
    pub fn example(options: Option<WorldOptionsObject>) -> JsResult<String> {
        Ok(World::new(&world_options(options.map(JsValue::from))?).text)
    }

    /// Reads and solves `text` (an Error naming the bad line), telling `progress` each stage in
    /// words as it begins: the answer's numbers for `SyncMap.solved` (the long part: the page
    /// runs it in its worker).
    pub fn solve(
        #[wasm_bindgen(unchecked_param_type = "string")] text: &JsValue,
        progress: Option<js_sys::Function>,
    ) -> JsResult<Vec<f64>> {
        let say = |words: &str| {
            if let Some(f) = &progress {
                let _ = f.call1(&JsValue::NULL, &JsValue::from_str(words));
            }
        };
        say("reading");
        let text = string(text)?;
        Ok(solve_text(&text, &mut |stage| say(&stage_words(stage)))?)
    }

    /// The map of `text` with the answer `SyncMap.solve(text)` gave; an Error naming `answer`
    /// when it is not that call's numbers for a graph of this size.
    pub fn solved(
        #[wasm_bindgen(unchecked_param_type = "string")] text: &JsValue,
        #[wasm_bindgen(unchecked_param_type = "Float64Array")] answer: &JsValue,
    ) -> JsResult<SyncMap> {
        let graph = read(&string(text)?)?;
        let data = numbers("answer", answer, HEAD + 7 * graph.count)?;
        Ok(SyncMap::of(graph, &data)?)
    }

    /// `{ dimension, poses, edges, closures, fromFile, initialCost, cost, certified, lambdaMin,
    /// tolerance, rank, iterations, medianMisfit, skipped }`.
    #[wasm_bindgen(getter, unchecked_return_type = "SyncMapSummary")]
    pub fn summary(&self) -> JsValue {
        let a = self.answer;
        let closures = self.graph.edges.iter().filter(|[i, j]| i.abs_diff(*j) != 1).count();
        let skipped: usize = self.graph.skipped.iter().map(|(_, n)| n).sum();
        Record::new()
            .set("dimension", self.graph.dimension as f64)
            .set("poses", self.graph.count as f64)
            .set("edges", self.graph.edges.len() as f64)
            .set("closures", closures as f64)
            .set("fromFile", self.from_file)
            .set("initialCost", self.initial_cost)
            .set("cost", a.cost)
            .set("certified", a.certified)
            .set("lambdaMin", a.lambda_min)
            .set("tolerance", a.tolerance)
            .set("rank", a.rank as f64)
            .set("lowerBound", a.lower_bound)
            .set("iterations", a.iterations as f64)
            .set("medianMisfit", super::model::median(self.optimum_misfits.clone()))
            .set("skipped", skipped as f64)
            .set("truthErrorInitial", self.truth_error(&self.initial))
            .set("truthErrorOptimum", self.truth_error(&self.optimum))
            .end()
    }

    /// Takes the built-in graph's true poses (its route, the same for every noise and seed) as
    /// this map's truth: drawn dashed under both panels, and each estimate's distance from it in
    /// the summary. An Error naming `truth` when the graph is not the built-in one's size.
    #[wasm_bindgen(js_name = withTruth)]
    pub fn with_truth(&mut self) -> JsResult<()> {
        let truth: Vec<DVec3> = route().iter().map(|&(x, y, _)| DVec3::new(x, y, 0.0)).collect();
        if self.graph.dimension != 2 || truth.len() != self.graph.count {
            let problem = format!(
                "is the built-in graph's ({} planar poses); this graph has {} poses in {}D",
                truth.len(),
                self.graph.count,
                self.graph.dimension
            );
            return Err(KliError::invalid("truth", problem).into());
        }
        self.truth = Some(truth);
        Ok(())
    }

    /// The optimum's poses for `writeG2o`: `{ rotations, translations }` (`w, x, y, z` and
    /// `x, y, z` a pose, flat).
    #[wasm_bindgen(getter)]
    pub fn poses(&self) -> JsValue {
        let rotations: Vec<f64> = self.optimum.rotations.iter().flat_map(|&q| to_wxyz(q)).collect();
        let translations: Vec<f64> =
            self.optimum.positions.iter().flat_map(|p| p.to_array()).collect();
        Record::new()
            .set("rotations", js_sys::Float64Array::from(&rotations[..]))
            .set("translations", js_sys::Float64Array::from(&translations[..]))
            .end()
    }

    /// The optimum as CSV: `id, x, y, z, qx, qy, qz, qw` a pose, after `#` lines with the cost
    /// and the certificate.
    pub fn csv(&self) -> String {
        csv(&self.graph, &self.optimum, &self.answer)
    }

    /// Turns a 3D map's camera by `azimuth` and `elevation` radians (a 2D map is seen from above
    /// and does not turn).
    pub fn turn(&mut self, azimuth: f64, elevation: f64) {
        self.look(self.azimuth + azimuth, self.elevation + elevation);
    }

    /// Looks at a 3D map from `azimuth` (about z, from x) and `elevation` (above the xy plane),
    /// radians; the elevation is held within ±90° (the camera's own limit is ±89.9°), and a
    /// value that is not finite leaves the camera as it is. From above with x to the right and y
    /// up is `look(−π/2, π/2)`.
    pub fn look(&mut self, azimuth: f64, elevation: f64) {
        if azimuth.is_finite() && elevation.is_finite() {
            self.azimuth = azimuth;
            self.elevation = elevation.clamp(-FRAC_PI_2, FRAC_PI_2);
        }
    }

    /// The map on a canvas.
    pub fn draw(
        &self,
        ctx: &CanvasRenderingContext2d,
        #[wasm_bindgen(unchecked_param_type = "Frame")] frame: &JsValue,
    ) {
        let frame = Frame::read(frame);
        let pen = Pen::begin(ctx, frame.width, frame.height, frame.pixel_ratio, BACKGROUND);
        pen.scale_text(frame.text_scale);
        self.paint(&pen, (frame.width, frame.height));
    }

    /// The map's place on a canvas while its graph is being solved: `words`, centred, so that
    /// the figure is never empty.
    #[wasm_bindgen(js_name = drawWaiting)]
    pub fn draw_waiting(
        ctx: &CanvasRenderingContext2d,
        #[wasm_bindgen(unchecked_param_type = "Frame")] frame: &JsValue,
        words: &str,
    ) {
        let frame = Frame::read(frame);
        let pen = Pen::begin(ctx, frame.width, frame.height, frame.pixel_ratio, BACKGROUND);
        pen.scale_text(frame.text_scale);
        pen.text(words, (0.5 * frame.width, 0.5 * frame.height), MUTED, 13.0, "center");
    }

    /// The same as an SVG document: what the page prints (and saves) before the answer comes.
    #[wasm_bindgen(js_name = waitingSvg)]
    pub fn waiting_svg(
        #[wasm_bindgen(unchecked_param_type = "Frame")] frame: &JsValue,
        words: &str,
    ) -> String {
        let frame = Frame::read(frame);
        svg_document(frame.width, frame.height, words, &|pen| {
            pen.scale_text(frame.text_scale);
            pen.text(words, (0.5 * frame.width, 0.5 * frame.height), MUTED, 13.0, "center");
        })
    }

    /// The same as an SVG document.
    #[wasm_bindgen(js_name = toSvg)]
    pub fn to_svg(
        &self,
        #[wasm_bindgen(unchecked_param_type = "Frame")] frame: &JsValue,
    ) -> String {
        let frame = Frame::read(frame);
        let title = "Your pose graph's map: the initial estimate and the optimum";
        svg_document(frame.width, frame.height, title, &|pen| {
            pen.scale_text(frame.text_scale);
            self.paint(pen, (frame.width, frame.height))
        })
    }
}

impl SyncMap {
    /// The map of `graph` with the answer's numbers `data` (of the length `solved` checked).
    pub fn of(graph: PoseGraph, data: &[f64]) -> Result<SyncMap, KliError> {
        let n = graph.count;
        if data.len() != HEAD + 7 * n {
            let problem = format!("must hold {} numbers (got {})", HEAD + 7 * n, data.len());
            return Err(KliError::invalid("answer", problem));
        }
        if let Some(k) = data.iter().position(|x| !x.is_finite()) {
            return Err(KliError::invalid(
                "answer",
                format!("must be finite (got {} at {k})", data[k]),
            ));
        }
        let answer = Answer {
            cost: data[0],
            iterations: data[1] as usize,
            lambda_min: data[2],
            tolerance: data[3],
            certified: data[4] == 1.0,
            rank: data[5] as usize,
            lower_bound: data[6],
        };
        let rotations = data[HEAD..HEAD + 4 * n]
            .chunks_exact(4)
            .map(|c| from_wxyz([c[0], c[1], c[2], c[3]]))
            .collect();
        let positions =
            data[HEAD + 4 * n..].chunks_exact(3).map(|c| DVec3::new(c[0], c[1], c[2])).collect();
        let optimum = Poses { rotations, positions };
        let (initial, from_file) = initial(&graph);
        let initial_costs = edge_costs(&graph, &initial);
        let initial_cost = initial_costs.iter().sum();
        let initial_misfits = misfits(&graph, &initial_costs);
        let optimum_misfits = misfits(&graph, &edge_costs(&graph, &optimum));
        Ok(SyncMap {
            graph,
            initial,
            from_file,
            optimum,
            answer,
            initial_misfits,
            optimum_misfits,
            initial_cost,
            truth: None,
            azimuth: CAMERA.0.to_radians(),
            elevation: CAMERA.1.to_radians(),
        })
    }

    /// The root mean square distance of `poses`' positions from the truth (NaN without one).
    /// Both are in the gauge of pose 0, which the built-in route starts at: the origin, heading
    /// along x.
    pub fn truth_error(&self, poses: &Poses) -> f64 {
        let Some(truth) = &self.truth else { return f64::NAN };
        let sum: f64 =
            truth.iter().zip(&poses.positions).map(|(t, p)| (*t - *p).length_squared()).sum();
        (sum / truth.len().max(1) as f64).sqrt()
    }

    pub fn set_truth(&mut self, truth: Vec<DVec3>) {
        self.truth = Some(truth);
    }

    pub fn initial_poses(&self) -> &Poses {
        &self.initial
    }

    pub fn optimum_misfits(&self) -> &[f64] {
        &self.optimum_misfits
    }

    pub fn paint(&self, pen: &Pen, size: (f64, f64)) {
        let a = self.answer;
        let initial = MapPanel {
            heading: if self.from_file {
                "initial: the file's own estimate".into()
            } else {
                "initial: the odometry chained".into()
            },
            line: format!("f = {}", exponential(self.initial_cost, 4)),
            positions: &self.initial.positions,
            misfits: &self.initial_misfits,
        };
        let optimum = MapPanel {
            heading: if a.certified {
                "the certified optimum".into()
            } else {
                "the optimum found, not certified".into()
            },
            line: format!(
                "f = {}   λmin = {}   rank {}",
                exponential(a.cost, 4),
                exponential(a.lambda_min, 1),
                a.rank
            ),
            positions: &self.optimum.positions,
            misfits: &self.optimum_misfits,
        };
        let look = if self.graph.dimension == 2 {
            Look::Above
        } else {
            Look::Orbit(Camera::orbit(self.azimuth, self.elevation))
        };
        let truth = self.truth.as_deref();
        draw_map(pen, &self.graph.edges, &[initial, optimum], truth, &look, size);
    }
}

/// `text` as a string, or an Error naming it (read as JavaScript's value, so that no other value
/// reaches the glue's string copy).
fn string(text: &JsValue) -> Result<String, KliError> {
    text.as_string().ok_or_else(|| {
        KliError::invalid("text", format!("must be a string (got {})", describe(text)))
    })
}

/// The pose graph `text` holds (landmarks and other lines skipped), or an Error naming the bad
/// line.
pub fn read(text: &str) -> Result<PoseGraph, KliError> {
    read_g2o(text, OtherLines::Skip)
}

/// Reads and solves `text` (pose 0 anchored), telling `observe` each stage: the answer's numbers.
pub fn solve_text(text: &str, observe: &mut dyn FnMut(PoseStage)) -> Result<Vec<f64>, KliError> {
    let graph = read(text)?;
    let solved = synchronize_poses_observed(&graph, &PoseOptions::default(), observe)?;
    let c = solved.certificate;
    let mut out = Vec::with_capacity(HEAD + 7 * graph.count);
    out.extend([
        solved.cost,
        solved.iterations as f64,
        c.lambda_min,
        c.tolerance,
        f64::from(u8::from(c.certified)),
        c.rank as f64,
        c.lower_bound,
    ]);
    solved.rotations.iter().for_each(|&q| out.extend(to_wxyz(q)));
    solved.translations.iter().for_each(|t| out.extend(t.to_array()));
    Ok(out)
}

/// A stage in the page's words.
pub fn stage_words(stage: PoseStage) -> String {
    match stage {
        PoseStage::Chordal => "the chordal start (translations eliminated)".into(),
        PoseStage::Optimising { rank, iterations: 0 } => format!("trust region at rank {rank}"),
        PoseStage::Optimising { rank, iterations } => {
            format!("trust region at rank {rank} ({iterations} steps so far)")
        }
        PoseStage::Step { rank, iterations } => {
            format!("trust region at rank {rank}, step {iterations}")
        }
        PoseStage::Certifying { rank } => format!("the certificate at rank {rank}"),
        PoseStage::Rounding => "rounding to rotations".into(),
        PoseStage::Translations => "the translations".into(),
    }
}

/// Each edge's term of the cost, `κ ‖R_j − R_i R̃_ij‖²_F + τ ‖t_j − t_i − R_i t̃_ij‖²`, at `poses`.
pub fn edge_costs(graph: &PoseGraph, poses: &Poses) -> Vec<f64> {
    let matrices: Vec<DMat3> = poses.rotations.iter().map(|&q| DMat3::from_quat(q)).collect();
    graph
        .edges
        .iter()
        .enumerate()
        .map(|(k, &[i, j])| {
            let (ri, rj) = (matrices[i], matrices[j]);
            let e = rj - ri * DMat3::from_quat(graph.relative[k].normalize());
            let frobenius: f64 = (0..3).map(|c| e.col(c).length_squared()).sum();
            let t = poses.positions[j] - poses.positions[i] - ri * graph.translations[k];
            graph.rotation_weights[k] * frobenius
                + graph.translation_weights[k] * t.length_squared()
        })
        .collect()
}

/// Each edge's misfit: `√(f_ij / dof)`, 3 degrees of freedom a planar pose, 6 in space.
pub fn misfits(graph: &PoseGraph, costs: &[f64]) -> Vec<f64> {
    let dof = if graph.dimension == 2 { 3.0 } else { 6.0 };
    costs.iter().map(|&c| (c / dof).sqrt()).collect()
}

/// The CSV of [`SyncMap::csv`].
pub fn csv(graph: &PoseGraph, poses: &Poses, answer: &Answer) -> String {
    let mut text = format!(
        "# kli: a pose graph's optimum (SE-Sync), {} poses, {} edges, pose 0 at the origin\n\
         # cost {}, certified {}, lambdaMin {}, rank {}\n",
        graph.count,
        graph.edges.len(),
        answer.cost,
        answer.certified,
        answer.lambda_min,
        answer.rank
    );
    // Rust's f64 text (the shortest that reads back as the same number), not JavaScript's:
    // the file's ids are whole numbers up to 2⁶⁴ written as such.
    text.push_str("id,x,y,z,qx,qy,qz,qw\n");
    for k in 0..graph.count {
        let (q, p): (DQuat, DVec3) = (poses.rotations[k], poses.positions[k]);
        let id = graph.ids.get(k).copied().unwrap_or(k as u64);
        let _ = writeln!(text, "{id},{},{},{},{},{},{},{}", p.x, p.y, p.z, q.x, q.y, q.z, q.w);
    }
    text
}

/// The built-in graph's options, each checked (an Error naming it).
fn world_options(value: Option<JsValue>) -> Result<WorldOptions, KliError> {
    let mut options = WorldOptions::default();
    let example = "{ noise: 2, closures: 8, seed: 1 }";
    let Some(fields) = Fields::new(value, &["noise", "closures", "seed"], example)? else {
        return Ok(options);
    };
    if let Some(noise) = fields.number("noise")? {
        if !(0.0..=MAX_NOISE).contains(&noise) {
            let problem = format!("must be from 0 to {MAX_NOISE} degrees (got {noise})");
            return Err(KliError::invalid("noise", problem));
        }
        options.noise = noise;
    }
    if let Some(closures) = fields.whole("closures", 0.0, MAX_CLOSURES as f64)? {
        options.closures = closures as usize;
    }
    if let Some(seed) = fields.seed("seed")? {
        options.seed = seed;
    }
    Ok(options)
}
