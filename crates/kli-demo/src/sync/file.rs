//! A user's own pose graph (g2o or TORO/GTSAM, 2D or 3D, read by [`kli::sync::read_g2o`], each
//! edge weighted by its information matrix's κ): synchronised both ways, summed up and drawn as the two solutions'
//! residuals side by side, robust's flagged edges stacked.

use kli::KliError;
use kli::sync::{Graph, Method, OtherLines, SyncOptions, Synchronized, read_g2o, synchronize};
use kli_wasm::error::JsResult;
use kli_wasm::typed::numbers;
use kli_wasm::value::describe;
use wasm_bindgen::prelude::*;
use web_sys::CanvasRenderingContext2d;

use super::solutions::{Solutions, whole};
use super::view::{Side, draw_sides};
use crate::figure::{Frame, Record};
use crate::format::exponential;
use crate::palette::BACKGROUND;
use crate::pen::{Pen, svg_document};

/// A pose graph read from a file's text, and its chordal and robust solutions.
#[wasm_bindgen]
pub struct SyncFile {
    count: usize,
    /// The lines of other kinds (landmarks, priors) the file held, skipped.
    skipped: usize,
    chordal: Synchronized,
    robust: Synchronized,
    /// Whether each edge is one the robust solution flags.
    flagged: Vec<bool>,
}

#[wasm_bindgen(typescript_custom_section)]
const TYPES: &'static str = r#"
/** What a user's pose graph sums up to: its size, the chordal optimum with its certificate, and
 *  the robust solution's flags; residual angles in degrees. */
export interface SyncFileSummary {
  count: number;
  edges: number;
  chordalCost: number;
  certified: boolean;
  lambdaMin: number;
  chordalMedianResidualDegrees: number;
  robustMedianResidualDegrees: number;
  flagged: number;
  iterations: number;
  /** Lines of other kinds (landmarks, priors, parameters), skipped. */
  skipped: number;
}
"#;

#[wasm_bindgen]
impl SyncFile {
    /// Reads `text` (an Error naming the bad line), then synchronises it (node 0 anchored).
    #[wasm_bindgen(constructor)]
    pub fn new(
        #[wasm_bindgen(unchecked_param_type = "string")] text: &JsValue,
    ) -> JsResult<SyncFile> {
        let (graph, skipped) = read(text)?;
        Ok(SyncFile::of(graph.count(), skipped, solve_both(&graph)?))
    }

    /// Reads and synchronises `text` both ways: for `SyncFile.solved`, the count of lines
    /// skipped, then the solutions as numbers (`Solutions::pack`: the counts of nodes and edges
    /// first). The page runs it in its worker, as it does `SyncDemo.solve`: this is the long part
    /// of `new`, the reading included (on the page, reading a 10⁴-pose file again took a task
    /// of 200 ms).
    pub fn solve(
        #[wasm_bindgen(unchecked_param_type = "string")] text: &JsValue,
    ) -> JsResult<Vec<f64>> {
        let (graph, skipped) = read(text)?;
        let mut out = vec![skipped as f64];
        out.extend(solve_both(&graph)?.pack());
        Ok(out)
    }

    /// The pose graph `SyncFile.solve` solved, from its numbers; an Error naming `solutions`
    /// when they are not such numbers.
    pub fn solved(
        #[wasm_bindgen(unchecked_param_type = "Float64Array")] solutions: &JsValue,
    ) -> JsResult<SyncFile> {
        Ok(SyncFile::from_numbers(&numbers("solutions", solutions, usize::MAX)?)?)
    }

    /// `{ count, edges, chordalCost, certified, lambdaMin, chordalMedianResidualDegrees,
    /// robustMedianResidualDegrees, flagged, iterations, skipped }`.
    #[wasm_bindgen(getter, unchecked_return_type = "SyncFileSummary")]
    pub fn summary(&self) -> JsValue {
        let c = self.chordal.certificate;
        Record::new()
            .set("count", self.count as f64)
            .set("edges", self.chordal.residuals.len() as f64)
            .set("chordalCost", self.chordal.cost)
            .set("certified", c.is_some_and(|c| c.certified))
            .set("lambdaMin", c.map_or(f64::NAN, |c| c.lambda_min))
            .set("chordalMedianResidualDegrees", median_degrees(&self.chordal.residuals))
            .set("robustMedianResidualDegrees", median_degrees(&self.robust.residuals))
            .set("flagged", self.flagged.iter().filter(|&&f| f).count() as f64)
            .set("iterations", self.chordal.iterations as f64)
            .set("skipped", self.skipped as f64)
            .end()
    }

    /// Each edge's chordal residual, radians.
    #[wasm_bindgen(getter)]
    pub fn residuals(&self) -> Vec<f64> {
        self.chordal.residuals.clone()
    }

    /// The two solutions' residuals side by side on a canvas.
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

    /// The same as an SVG document.
    #[wasm_bindgen(js_name = toSvg)]
    pub fn to_svg(
        &self,
        #[wasm_bindgen(unchecked_param_type = "Frame")] frame: &JsValue,
    ) -> String {
        let frame = Frame::read(frame);
        let title = "Your pose graph: the chordal and robust solutions' residuals";
        svg_document(frame.width, frame.height, title, &|pen| {
            pen.scale_text(frame.text_scale);
            self.paint(pen, (frame.width, frame.height))
        })
    }
}

/// The pose graph `text` holds, weighted by each edge's κ, and how many lines of other kinds it
/// skipped (an Error naming the bad line, or `text` when it is not a string: read as
/// JavaScript's value, so that no other value reaches the glue's string copy).
fn read(text: &JsValue) -> Result<(Graph, usize), KliError> {
    let Some(text) = text.as_string() else {
        return Err(KliError::invalid(
            "text",
            format!("must be a string (got {})", describe(text)),
        ));
    };
    graph_of(&text)
}

/// [`read`] of a string.
fn graph_of(text: &str) -> Result<(Graph, usize), KliError> {
    let pose = read_g2o(text, OtherLines::Skip)?;
    let skipped = pose.skipped.iter().map(|(_, n)| n).sum();
    let graph =
        Graph::new(Some(pose.count), &pose.edges, &pose.relative, Some(&pose.rotation_weights))?;
    Ok((graph, skipped))
}

/// `graph` synchronised by the chordal and the robust method, node 0 anchored.
fn solve_both(graph: &Graph) -> Result<Solutions, KliError> {
    let solve = |method| synchronize(graph, &SyncOptions { method, ..SyncOptions::default() });
    Ok(Solutions { chordal: solve(Method::Chordal)?, robust: solve(Method::Robust)? })
}

fn median_degrees(residuals: &[f64]) -> f64 {
    super::model::median(residuals.to_vec()).to_degrees()
}

impl SyncFile {
    /// The file `SyncFile.solve`'s numbers give (`[skipped, n, m, …]`), or an Error naming
    /// `solutions`.
    pub fn from_numbers(data: &[f64]) -> Result<SyncFile, KliError> {
        let counts = match data {
            [skipped, n, m, ..] => whole(*skipped).zip(whole(*n)).zip(whole(*m)),
            _ => None,
        };
        let Some(((skipped, n), m)) = counts else {
            let problem = "must begin with three counts (lines skipped, nodes, edges)";
            return Err(KliError::invalid("solutions", problem.to_string()));
        };
        Ok(SyncFile::of(n, skipped, Solutions::unpack(&data[1..], n, m)?))
    }

    fn of(count: usize, skipped: usize, Solutions { chordal, robust }: Solutions) -> SyncFile {
        let flagged = robust.outliers.clone().unwrap_or_default();
        SyncFile { count, skipped, chordal, robust, flagged }
    }

    fn paint(&self, pen: &Pen, size: (f64, f64)) {
        let certificate = match self.chordal.certificate {
            Some(c) if c.certified => {
                format!("certified: λmin(S) = {}", exponential(c.lambda_min, 1))
            }
            Some(c) => format!("not certified: λmin(S) = {}", exponential(c.lambda_min, 1)),
            None => String::new(),
        };
        let flagged = self.flagged.iter().filter(|&&f| f).count();
        let sides = [
            Side {
                heading: "chordal (least squares)".into(),
                lines: vec![format!("f = {}", exponential(self.chordal.cost, 5)), certificate],
                residuals: &self.chordal.residuals,
                marked: &self.flagged,
                marked_label: "flagged by robust",
            },
            Side {
                heading: "robust (reweighted)".into(),
                lines: vec![
                    format!("flagged {flagged} of {} edges", self.flagged.len()),
                    String::new(),
                ],
                residuals: &self.robust.residuals,
                marked: &self.flagged,
                marked_label: "flagged by robust",
            },
        ];
        draw_sides(pen, &sides, size);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_solutions_the_worker_sends_are_the_file_the_page_unpacks() {
        // The 3D fixture with two lines of other kinds, skipped: the page gets the count of
        // them, the nodes and both solutions without reading the text again.
        let text = include_str!("../../../../tests/fixtures/posegraphs/smallGrid3D.g2o").to_owned()
            + "VERTEX_XY 900 1 2\nPARAMS_SE2OFFSET 0 0 0 0\n";
        let (graph, skipped) = graph_of(&text).unwrap();
        assert_eq!((graph.count(), skipped), (125, 2));
        let solutions = solve_both(&graph).unwrap();
        let mut data = vec![skipped as f64];
        data.extend(solutions.pack());
        let file = SyncFile::from_numbers(&data).unwrap();
        assert_eq!((file.count, file.skipped), (125, 2));
        assert_eq!(file.chordal.cost, solutions.chordal.cost);
        assert_eq!(file.robust.residuals, solutions.robust.residuals);
        assert_eq!(file.flagged, solutions.robust.outliers.clone().unwrap_or_default());
        // Numbers that are not such: too few, a count not whole, one number more or less.
        for bad in [
            &data[..2],
            &[0.5, data[1], data[2]][..],
            &[-1.0, data[1], data[2]][..],
            &data[..data.len() - 1],
            &[&data[..], &[0.0]].concat(),
        ] {
            let error = SyncFile::from_numbers(bad).err().expect("refused");
            assert_eq!(error.argument(), "solutions", "{error}");
        }
        let mut other = data.clone();
        other[0] = 7.0;
        assert_eq!(SyncFile::from_numbers(&other).unwrap().skipped, 7);
    }
}
