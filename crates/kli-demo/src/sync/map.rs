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
//! The solve runs in the page's worker (`SyncMap.solve`, telling its stages as it goes), which
//! also reads the file, chains the initial estimate and measures every edge's misfit, and sends
//! the whole map as numbers ([`SyncMap::numbers`]); the page only unpacks them
//! (`SyncMap.solved`). Reading a 10⁴-pose file again on the page took one task of 220 ms (half
//! of it copying the text into the module).
//!
//! The solver's numbers ([`solve_graph`]): `[cost, iterations, λ_min, tolerance, certified (1 or
//! 0), rank, lower bound]`, then `4n` rotations (`w, x, y, z`) and `3n` positions.

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
use super::map_view::{Look, MapPanel, Parts, draw_map};
use super::model::median;
use super::solutions;
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

impl Answer {
    /// The answer the first [`HEAD`] of `data` give (at least that many).
    pub fn read(data: &[f64]) -> Answer {
        Answer {
            cost: data[0],
            iterations: data[1] as usize,
            lambda_min: data[2],
            tolerance: data[3],
            certified: data[4] == 1.0,
            rank: data[5] as usize,
            lower_bound: data[6],
        }
    }

    /// Its [`HEAD`] numbers.
    pub fn numbers(&self) -> [f64; HEAD] {
        let flag = |b: bool| f64::from(u8::from(b));
        let (i, r) = (self.iterations as f64, self.rank as f64);
        [self.cost, i, self.lambda_min, self.tolerance, flag(self.certified), r, self.lower_bound]
    }
}

/// `4n` rotations (`w, x, y, z`) then `3n` positions from `data`, from its start.
pub fn read_poses(data: &[f64], n: usize) -> Poses {
    Poses {
        rotations: data[..4 * n]
            .chunks_exact(4)
            .map(|c| from_wxyz([c[0], c[1], c[2], c[3]]))
            .collect(),
        positions: data[4 * n..7 * n]
            .chunks_exact(3)
            .map(|c| DVec3::new(c[0], c[1], c[2]))
            .collect(),
    }
}

/// The numbers [`read_poses`] reads, after `out`'s.
fn write_poses(out: &mut Vec<f64>, rotations: &[DQuat], positions: &[DVec3]) {
    rotations.iter().for_each(|&q| out.extend(to_wxyz(q)));
    positions.iter().for_each(|p| out.extend(p.to_array()));
}

/// What the map keeps of its pose graph: enough to draw it, sum it up and save its poses.
#[derive(Debug, Clone, PartialEq)]
pub struct Outline {
    pub dimension: usize,
    pub count: usize,
    pub edges: Vec<[usize; 2]>,
    /// Each pose's id in the file.
    pub ids: Vec<u64>,
    /// How many lines of other kinds the file had (landmarks, priors), skipped.
    pub skipped: usize,
}

impl Outline {
    pub fn of(graph: &PoseGraph) -> Outline {
        Outline {
            dimension: graph.dimension,
            count: graph.count,
            edges: graph.edges.clone(),
            ids: graph.ids.clone(),
            skipped: graph.skipped.iter().map(|(_, n)| n).sum(),
        }
    }
}

/// A pose graph, its initial estimate and its certified optimum, and how the map is turned.
#[wasm_bindgen]
pub struct SyncMap {
    graph: Outline,
    initial: Poses,
    /// Whether the initial estimate is the file's own (else the odometry chained).
    from_file: bool,
    optimum: Poses,
    answer: Answer,
    initial_misfits: Vec<f64>,
    optimum_misfits: Vec<f64>,
    initial_cost: f64,
    /// The optimum's median edge misfit (a sort of every edge's: the worker's, not the page's).
    median_misfit: f64,
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
    /// words as it begins: the whole map as numbers for `SyncMap.solved` (the page runs this in
    /// its worker: all that is long, the reading included).
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
        let graph = read(&string(text)?)?;
        let answer = solve_graph(&graph, &mut |stage| say(&stage_words(stage)))?;
        Ok(SyncMap::of(&graph, &answer)?.numbers())
    }

    /// The map `SyncMap.solve` sent (its `answer`); an Error naming `answer` when it is not such
    /// numbers.
    pub fn solved(
        #[wasm_bindgen(unchecked_param_type = "Float64Array")] answer: &JsValue,
    ) -> JsResult<SyncMap> {
        Ok(SyncMap::from_numbers(&numbers("answer", answer, usize::MAX)?)?)
    }

    /// `{ dimension, poses, edges, closures, fromFile, initialCost, cost, certified, lambdaMin,
    /// tolerance, rank, iterations, medianMisfit, skipped }`.
    #[wasm_bindgen(getter, unchecked_return_type = "SyncMapSummary")]
    pub fn summary(&self) -> JsValue {
        let a = self.answer;
        let closures = self.graph.edges.iter().filter(|[i, j]| i.abs_diff(*j) != 1).count();
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
            .set("medianMisfit", self.median_misfit)
            .set("skipped", self.graph.skipped as f64)
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
        self.draw_parts(ctx, frame, Parts::new(None));
    }

    /// Part `part` of the map on a canvas, for a page that draws a large map a task at a time
    /// (`map_view::Parts`): part 0 clears the canvas, the others draw over it, and drawing parts
    /// 0, 1, … in order at one frame gives what `draw` gives. Returns how many parts there are
    /// (1 for a map of at most `map_view::PART_SEGMENTS` segments; a part past the last draws
    /// nothing).
    #[wasm_bindgen(js_name = drawPart)]
    pub fn draw_part(
        &self,
        ctx: &CanvasRenderingContext2d,
        #[wasm_bindgen(unchecked_param_type = "Frame")] frame: &JsValue,
        part: usize,
    ) -> usize {
        self.draw_parts(ctx, frame, Parts::new(Some(part)))
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
            self.paint(pen, (frame.width, frame.height), &mut Parts::new(None))
        })
    }
}

impl SyncMap {
    /// The map of `graph` with the solver's numbers `data` (`solve_graph`'s).
    pub fn of(graph: &PoseGraph, data: &[f64]) -> Result<SyncMap, KliError> {
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
        let answer = Answer::read(data);
        let optimum = read_poses(&data[HEAD..], n);
        let (initial, from_file) = initial(graph);
        let initial_costs = edge_costs(graph, &initial);
        let initial_cost = initial_costs.iter().sum();
        let initial_misfits = misfits(graph, &initial_costs);
        let optimum_misfits = misfits(graph, &edge_costs(graph, &optimum));
        let median_misfit = median(optimum_misfits.clone());
        Ok(SyncMap {
            graph: Outline::of(graph),
            initial,
            from_file,
            optimum,
            answer,
            initial_misfits,
            optimum_misfits,
            initial_cost,
            median_misfit,
            truth: None,
            azimuth: CAMERA.0.to_radians(),
            elevation: CAMERA.1.to_radians(),
        })
    }

    /// The map as numbers, what the worker sends the page ([`SyncMap::from_numbers`] reads
    /// them back): the solver's seven (`Answer`); `[dimension, n, m, skipped, from file (1 or
    /// 0), initial cost, the optimum's median misfit]`; the optimum and the initial estimate, each `4n` rotations (`w, x, y,
    /// z`) then `3n` positions; each pose's id as two 32-bit halves (an id may be any `u64`, more
    /// than an `f64` holds whole); the `m` edges' `i, j`; the `m` initial misfits, then the `m`
    /// optimum's. The camera and the truth are the page's, not the solve's.
    pub fn numbers(&self) -> Vec<f64> {
        let (a, g) = (self.answer, &self.graph);
        let mut out = a.numbers().to_vec();
        out.extend([
            g.dimension as f64,
            g.count as f64,
            g.edges.len() as f64,
            g.skipped as f64,
            f64::from(u8::from(self.from_file)),
            self.initial_cost,
            self.median_misfit,
        ]);
        for poses in [&self.optimum, &self.initial] {
            write_poses(&mut out, &poses.rotations, &poses.positions);
        }
        out.extend(g.ids.iter().flat_map(|&id| [(id >> 32) as f64, (id & 0xffff_ffff) as f64]));
        out.extend(g.edges.iter().flat_map(|&[i, j]| [i as f64, j as f64]));
        out.extend(&self.initial_misfits);
        out.extend(&self.optimum_misfits);
        out
    }

    /// The map [`SyncMap::numbers`] wrote; an Error naming `answer` when `data` is not such
    /// numbers (a length that disagrees with the counts it gives, a number that is not finite,
    /// a count, index or id half that is not a whole number in its range).
    pub fn from_numbers(data: &[f64]) -> Result<SyncMap, KliError> {
        const LEAD: usize = HEAD + 7;
        let refuse = |problem: String| KliError::invalid("answer", problem);
        if data.len() < LEAD {
            return Err(refuse(format!("must hold at least {LEAD} numbers (got {})", data.len())));
        }
        if let Some(k) = data.iter().position(|x| !x.is_finite()) {
            return Err(refuse(format!("must be finite (got {} at {k})", data[k])));
        }
        let whole = |k: usize, below: f64| -> Result<usize, KliError> {
            let x = data[k];
            let problem =
                || refuse(format!("must hold a whole number below {below} at {k} (got {x})"));
            solutions::whole(x).filter(|&v| (v as f64) < below).ok_or_else(problem)
        };
        let dimension = whole(HEAD, 4.0)?;
        if dimension < 2 {
            return Err(refuse(format!("must give the dimension 2 or 3 (got {dimension})")));
        }
        let (n, m) = (whole(HEAD + 1, data.len() as f64)?, whole(HEAD + 2, data.len() as f64)?);
        if n == 0 {
            return Err(refuse("must give at least one pose (got 0)".into()));
        }
        let want = LEAD + 14 * n + 2 * n + 4 * m;
        if data.len() != want {
            let problem = format!("must hold {want} numbers for {n} poses and {m} edges");
            return Err(refuse(format!("{problem} (got {})", data.len())));
        }
        let poses = |at: usize| read_poses(&data[at..], n);
        let (ids_at, edges_at) = (LEAD + 14 * n, LEAD + 16 * n);
        let half = 2f64.powi(32);
        let ids = (0..n)
            .map(|k| {
                let (hi, lo) = (whole(ids_at + 2 * k, half)?, whole(ids_at + 2 * k + 1, half)?);
                Ok(((hi as u64) << 32) | lo as u64)
            })
            .collect::<Result<_, KliError>>()?;
        let edges = (0..m)
            .map(|k| {
                Ok([whole(edges_at + 2 * k, n as f64)?, whole(edges_at + 2 * k + 1, n as f64)?])
            })
            .collect::<Result<_, KliError>>()?;
        let misfits_at = edges_at + 2 * m;
        Ok(SyncMap {
            graph: Outline { dimension, count: n, edges, ids, skipped: whole(HEAD + 3, f64::MAX)? },
            initial: poses(LEAD + 7 * n),
            from_file: data[HEAD + 4] == 1.0,
            optimum: poses(LEAD),
            answer: Answer::read(data),
            initial_misfits: data[misfits_at..misfits_at + m].to_vec(),
            optimum_misfits: data[misfits_at + m..].to_vec(),
            initial_cost: data[HEAD + 5],
            median_misfit: data[HEAD + 6],
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

    /// What falls in `parts`' wanted part (all of it, or its first part, on a cleared canvas;
    /// a later part over what the canvas holds); returns the count of parts.
    fn draw_parts(
        &self,
        ctx: &CanvasRenderingContext2d,
        frame: &JsValue,
        mut parts: Parts,
    ) -> usize {
        let frame = Frame::read(frame);
        let pen = if parts.wants_later() {
            Pen::over(ctx, frame.pixel_ratio)
        } else {
            Pen::begin(ctx, frame.width, frame.height, frame.pixel_ratio, BACKGROUND)
        };
        pen.scale_text(frame.text_scale);
        self.paint(&pen, (frame.width, frame.height), &mut parts);
        parts.count()
    }

    /// The map, or of it what falls in `parts`' wanted part.
    pub fn paint(&self, pen: &Pen, size: (f64, f64), parts: &mut Parts) {
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
        draw_map(pen, &self.graph.edges, &[initial, optimum], truth, &look, size, parts);
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

/// Solves `graph` (pose 0 anchored), telling `observe` each stage: the solver's numbers.
pub fn solve_graph(
    graph: &PoseGraph,
    observe: &mut dyn FnMut(PoseStage),
) -> Result<Vec<f64>, KliError> {
    let solved = synchronize_poses_observed(graph, &PoseOptions::default(), observe)?;
    let c = solved.certificate;
    let answer = Answer {
        cost: solved.cost,
        iterations: solved.iterations,
        lambda_min: c.lambda_min,
        tolerance: c.tolerance,
        certified: c.certified,
        rank: c.rank,
        lower_bound: c.lower_bound,
    };
    let mut out = Vec::with_capacity(HEAD + 7 * graph.count);
    out.extend(answer.numbers());
    write_poses(&mut out, &solved.rotations, &solved.translations);
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
pub fn csv(graph: &Outline, poses: &Poses, answer: &Answer) -> String {
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
        let id = graph.ids[k];
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
