//! Reading a pose graph: the poses' rotations and translations, each edge's measurement and its
//! weights from the information matrix, in 2D and 3D, from g2o and TORO (GTSAM) files.
//!
//! - 3D, g2o: `EDGE_SE3:QUAT i j x y z qx qy qz qw [21 information entries]` and
//!   `VERTEX_SE3:QUAT id x y z qx qy qz qw`.
//! - 3D, TORO: `EDGE3 i j x y z roll pitch yaw [21]` and `VERTEX3 id x y z roll pitch yaw`, the
//!   rotation `Rz(yaw) Ry(pitch) Rx(roll)` (GTSAM's `Rot3::Ypr`).
//! - 2D, g2o: `EDGE_SE2 i j dx dy dθ [I11 I12 I13 I22 I23 I33]` and `VERTEX_SE2 id x y θ`; TORO:
//!   `EDGE2` with the same fields and `VERTEX2 id x y θ`. TORO's own files write `EDGE2`'s
//!   information as `I11 I12 I22 I33 I13 I23` (`inf_ff inf_fs inf_ss inf_rr inf_fr inf_sr`,
//!   GTSAM's `NoiseFormatTORO`), others in g2o's order: g2o's order is read where it gives a
//!   positive definite matrix, else TORO's. A planar pose is the rotation about z by θ and the
//!   translation `(x, y, 0)`.
//!
//! An edge measures `T̃_ij ≈ T_i⁻¹ T_j`: `R̃_ij ≈ R_iᵀ R_j` (`q_ij ≈ q̄_i q_j`, the
//! synchronisation's relative rotation) and `t̃_ij ≈ R_iᵀ (t_j − t_i)`. Its weights are
//! SE-Sync's (Rosen et al. 2019; MATH.md, "Pose graphs"), with `Σ` the inverse of an information
//! block: in 3D `τ = 3 / tr(Σ_t)` and `κ = 3 / (2 tr(Σ_R))` (the 6×6 information's upper
//! triangle row by row, translation block first); in 2D `τ = 2 / tr(Σ_t)` and `κ = I_θθ`. `Σ_R` is
//! in g2o's units, the error quaternion's vector part (half the angle): an `EDGE3` line's rotation
//! block, on the angles themselves, is multiplied by 4 first, so that a graph weighs the same in
//! either format (GTSAM's `sphere2500.txt` and SE-Sync's `sphere2500.g2o`, one graph, have the
//! same optimum). An edge written without its information has the identity's in its own units:
//! `τ = 1`, and `κ = ½` (`EDGE_SE3:QUAT`), `2` (`EDGE3`) or `1` (2D).
//!
//! `FIX id` lines, blank lines and `#` comments are read and ignored; lines of any other kind
//! (landmarks, priors, parameters) are skipped and counted, or refused with [`OtherLines::Refuse`].
//! Node ids need not be consecutive: the poses are numbered from 0 in the order of their ids,
//! and [`PoseGraph::ids`] keeps each one's id in the file.

use glam::{DMat2, DMat3, DQuat, DVec2, DVec3};

use crate::error::{ErrorKind, KliError};
use crate::quaternion::unit;

/// A pose graph read from a file.
#[derive(Debug, Clone, PartialEq)]
pub struct PoseGraph {
    /// 2 for planar poses (`EDGE_SE2`, `EDGE2`), 3 for poses in space.
    pub dimension: usize,
    /// The number of poses: every id that a pose edge or pose vertex names.
    pub count: usize,
    /// Each pose's id in the file, ascending; pose `k` is `ids[k]`.
    pub ids: Vec<u64>,
    /// The edges `[i, j]` between poses (numbered from 0, as [`ids`](Self::ids) orders them), in
    /// the file's order.
    pub edges: Vec<[usize; 2]>,
    /// Each edge's `q_ij` (unit, its sign as written).
    pub relative: Vec<DQuat>,
    /// Each edge's measured translation `t̃_ij`, in pose `i`'s frame (z = 0 in 2D).
    pub translations: Vec<DVec3>,
    /// Each edge's rotation weight `κ_ij`, from its information matrix.
    pub rotation_weights: Vec<f64>,
    /// Each edge's translation weight `τ_ij`, from its information matrix.
    pub translation_weights: Vec<f64>,
    /// Each edge's information matrix as the file gave it, in g2o's order and units: its upper
    /// triangle row by row, 6 numbers an edge in 2D (`x, y, θ`), 21 in 3D (the translation, then
    /// the error quaternion's vector part). An `EDGE2` line's TORO order is rearranged, an
    /// `EDGE3` line's rotation rows are multiplied by 4 and its coupling block by 2 (angles to
    /// half-angles; see [`read_g2o`]'s module), and a line without one has the identity's in its
    /// own units. Empty for a graph not read from a file: a writer then writes the diagonal
    /// information of `κ` and `τ`.
    pub information: Vec<f64>,
    /// Every pose's rotation from its vertex line, when every pose has one.
    pub initial: Option<Vec<DQuat>>,
    /// Every pose's position from its vertex line, when every pose has one (z = 0 in 2D).
    pub positions: Option<Vec<DVec3>>,
    /// The lines of other kinds, skipped: each kind (its first word) and how many, in the order
    /// they first appear.
    pub skipped: Vec<(String, usize)>,
}

/// What [`read_g2o`] does with a line of a kind it does not read (a landmark, a prior, a
/// parameter block).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum OtherLines {
    /// Skip it, and count it in [`PoseGraph::skipped`].
    #[default]
    Skip,
    /// Refuse the file, naming the line.
    Refuse,
}

/// The line kinds read, their fields and how they are read.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Kind {
    EdgeSe3Quat,
    Edge3,
    EdgeSe2,
    Edge2,
    VertexSe3Quat,
    Vertex3,
    VertexSe2,
    Vertex2,
}

impl Kind {
    const NAMES: &'static str = "EDGE_SE3:QUAT, EDGE3, EDGE_SE2, EDGE2, VERTEX_SE3:QUAT, VERTEX3, \
                                 VERTEX_SE2 or VERTEX2";

    fn of(tag: &str) -> Option<Kind> {
        Some(match tag {
            "EDGE_SE3:QUAT" => Kind::EdgeSe3Quat,
            "EDGE3" => Kind::Edge3,
            "EDGE_SE2" => Kind::EdgeSe2,
            "EDGE2" => Kind::Edge2,
            "VERTEX_SE3:QUAT" => Kind::VertexSe3Quat,
            "VERTEX3" => Kind::Vertex3,
            "VERTEX_SE2" => Kind::VertexSe2,
            "VERTEX2" => Kind::Vertex2,
            _ => return None,
        })
    }

    fn dimension(self) -> usize {
        match self {
            Kind::EdgeSe2 | Kind::Edge2 | Kind::VertexSe2 | Kind::Vertex2 => 2,
            _ => 3,
        }
    }

    fn is_edge(self) -> bool {
        matches!(self, Kind::EdgeSe3Quat | Kind::Edge3 | Kind::EdgeSe2 | Kind::Edge2)
    }

    /// The numbers of the pose after the ids: x y z qx qy qz qw, x y z roll pitch yaw, x y θ.
    fn pose_numbers(self) -> usize {
        match self {
            Kind::EdgeSe3Quat | Kind::VertexSe3Quat => 7,
            Kind::Edge3 | Kind::Vertex3 => 6,
            _ => 3,
        }
    }

    /// What a 3D line's rotation information is multiplied by to be in g2o's units, for which
    /// SE-Sync's `κ` is defined. g2o's `EDGE_SE3:QUAT` measures the rotation error by the error
    /// quaternion's vector part, `sin(θ/2) n ≈ θ/2 · n`; TORO's `EDGE3` by the angles themselves,
    /// `θ n`. The same noise is `4 I` in g2o's units where it is `I` in TORO's (the Jacobian is
    /// `½ I`, and information goes as its inverse squared): SE-Sync's `sphere2500.g2o` writes
    /// `400, 400, 100` where GTSAM's `sphere2500.txt`, the same graph, writes `100, 100, 25`.
    fn rotation_information_scale(self) -> f64 {
        match self {
            Kind::Edge3 => 4.0,
            _ => 1.0,
        }
    }

    /// The entries of the information matrix's upper triangle after an edge's pose.
    fn information_entries(self) -> usize {
        match self.dimension() {
            2 => 6,
            _ => 21,
        }
    }
}

/// An error about line `line` of the text.
fn bad(line: usize, problem: impl Into<String>) -> KliError {
    KliError::new("text", ErrorKind::InvalidLine { line, problem: problem.into() })
}

/// One line's fields after its tag, with the line's number for errors.
struct Fields<'a> {
    fields: Vec<&'a str>,
    line: usize,
}

impl Fields<'_> {
    fn id(&self, index: usize) -> Result<u64, KliError> {
        let text = self.fields[index];
        text.parse::<u64>().map_err(|_| {
            let problem = if text.bytes().all(|b| b.is_ascii_digit()) {
                format!("node id {text} is too large (ids run to {})", u64::MAX)
            } else {
                format!("node id \"{text}\" is not a non-negative integer")
            };
            bad(self.line, problem)
        })
    }

    fn number(&self, index: usize) -> Result<f64, KliError> {
        let text = self.fields[index];
        match text.parse::<f64>() {
            Ok(x) if x.is_finite() => Ok(x),
            _ => Err(bad(self.line, format!("\"{text}\" is not a finite number"))),
        }
    }

    fn numbers<const N: usize>(&self, at: usize) -> Result<[f64; N], KliError> {
        let mut out = [0.0; N];
        for (k, x) in out.iter_mut().enumerate() {
            *x = self.number(at + k)?;
        }
        Ok(out)
    }

    /// The pose at `fields[at..]` as `kind` writes it: its rotation and its translation.
    fn pose(&self, kind: Kind, at: usize) -> Result<(DQuat, DVec3), KliError> {
        match kind.pose_numbers() {
            7 => {
                let [x, y, z, qx, qy, qz, qw] = self.numbers(at)?;
                let q = unit("q", DQuat::from_xyzw(qx, qy, qz, qw))
                    .map_err(|_| bad(self.line, "the quaternion has zero length"))?;
                Ok((q, DVec3::new(x, y, z)))
            }
            6 => {
                let [x, y, z, roll, pitch, yaw] = self.numbers(at)?;
                let q = DQuat::from_rotation_z(yaw)
                    * DQuat::from_rotation_y(pitch)
                    * DQuat::from_rotation_x(roll);
                Ok((q, DVec3::new(x, y, z)))
            }
            _ => {
                let [x, y, theta] = self.numbers(at)?;
                Ok((DQuat::from_rotation_z(theta), DVec3::new(x, y, 0.0)))
            }
        }
    }

    /// The information entries at `fields[at..]` in g2o's order and units (see
    /// [`PoseGraph::information`]), the identity's in the line's own units when it has none, and
    /// `(κ, τ)` from them.
    fn weights(&self, kind: Kind, at: usize) -> Result<(Vec<f64>, f64, f64), KliError> {
        let entries = kind.information_entries();
        let have = self.fields.len().saturating_sub(at);
        let mut upper = if have == 0 {
            // The identity's upper triangle: 1 where a row starts.
            let n = if kind.dimension() == 2 { 3 } else { 6 };
            (0..n).flat_map(|r| (r..n).map(move |c| f64::from(u8::from(r == c)))).collect()
        } else {
            self.information_numbers(entries, have, at)?
        };
        if kind.dimension() == 3 {
            // Rows 3–5 are the rotation's: the rotation block scales by s, the coupling by √s.
            let s = kind.rotation_information_scale();
            let cells = (0..6).flat_map(|r| (r..6).map(move |c| (r, c)));
            for ((r, c), x) in cells.zip(upper.iter_mut()) {
                *x *= [1.0, s.sqrt(), s][usize::from(r >= 3) + usize::from(c >= 3)];
            }
        }
        let (kappa, tau) = self.weights_of(kind, &mut upper)?;
        Ok((upper, kappa, tau))
    }

    /// `entries` numbers at `fields[at..]`, of which the line has `have`.
    fn information_numbers(
        &self,
        entries: usize,
        have: usize,
        at: usize,
    ) -> Result<Vec<f64>, KliError> {
        if have < entries {
            return Err(bad(
                self.line,
                format!(
                    "has {have} of the {entries} entries of its information matrix's upper triangle"
                ),
            ));
        }
        (at..at + entries).map(|k| self.number(k)).collect()
    }

    /// `(κ, τ)` from an information matrix's upper triangle in g2o's units (an `EDGE2` line's
    /// rearranged into g2o's order here where it is written in TORO's).
    fn weights_of(&self, kind: Kind, upper: &mut [f64]) -> Result<(f64, f64), KliError> {
        let positive = |what: &str| {
            bad(
                self.line,
                format!("the information matrix's {what} block is not positive definite"),
            )
        };
        if kind.dimension() == 2 {
            let i = <[f64; 6]>::try_from(&*upper).unwrap_or_default();
            // (I11, I12, I22, I33) from I11 I12 I13 I22 I23 I33 (g2o) or I11 I12 I22 I33 I13 I23
            // (TORO). EDGE2 lines are written both ways (GTSAM's w20000.txt in g2o's order, its
            // .graph files in TORO's): a diagonal information is positive definite in only one
            // reading, so g2o's is taken where it is, else TORO's.
            let g2o = [i[0], i[1], i[3], i[5]];
            let toro = [i[0], i[1], i[2], i[3]];
            let planar = |[i11, i12, i22, i33]: [f64; 4]| {
                let translation = DMat2::from_cols(DVec2::new(i11, i12), DVec2::new(i12, i22));
                let tau = trace_of_inverse2(translation).map(|t| 2.0 / t);
                (tau, (i33 > 0.0).then_some(i33))
            };
            let (tau, kappa) = match planar(g2o) {
                (Some(tau), Some(kappa)) => (Some(tau), Some(kappa)),
                g2o_reading if kind == Kind::Edge2 => match planar(toro) {
                    (Some(tau), Some(kappa)) => {
                        // I11 I12 I13 I22 I23 I33 from I11 I12 I22 I33 I13 I23.
                        upper.copy_from_slice(&[i[0], i[1], i[4], i[2], i[5], i[3]]);
                        (Some(tau), Some(kappa))
                    }
                    _ => g2o_reading,
                },
                g2o_reading => g2o_reading,
            };
            let tau = tau.ok_or_else(|| positive("translation"))?;
            let kappa = kappa.ok_or_else(|| positive("rotation"))?;
            return Ok((kappa, tau));
        }
        // The full symmetric matrix from the upper triangle, row by row.
        let mut m = [[0.0; 6]; 6];
        let cells = (0..6).flat_map(|r| (r..6).map(move |c| (r, c)));
        for ((r, c), &x) in cells.zip(upper.iter()) {
            (m[r][c], m[c][r]) = (x, x);
        }
        // The diagonal 3×3 block from row and column `o` (symmetric: its rows are its columns).
        let block = |o: usize| {
            DMat3::from_cols_array_2d(&[0, 1, 2].map(|r| [0, 1, 2].map(|c| m[o + r][o + c])))
        };
        let tau = 3.0 / trace_of_inverse3(block(0)).ok_or_else(|| positive("translation"))?;
        let kappa =
            3.0 / (2.0 * trace_of_inverse3(block(3)).ok_or_else(|| positive("rotation"))?);
        Ok((kappa, tau))
    }
}

/// `tr(M⁻¹)` of a symmetric 2×2 matrix, or `None` when it is not positive definite (or its
/// inverse overflows).
fn trace_of_inverse2(m: DMat2) -> Option<f64> {
    let det = m.determinant();
    let t = m.x_axis.x + m.y_axis.y;
    (m.x_axis.x > 0.0 && det > 0.0).then(|| t / det).filter(|t| t.is_finite() && *t > 0.0)
}

/// `tr(M⁻¹)` of a symmetric 3×3 matrix, or `None` when it is not positive definite (Sylvester's
/// criterion: its leading minors are positive) or its inverse overflows.
fn trace_of_inverse3(m: DMat3) -> Option<f64> {
    let minor2 = m.x_axis.x * m.y_axis.y - m.x_axis.y * m.y_axis.x;
    let det = m.determinant();
    if !(m.x_axis.x > 0.0 && minor2 > 0.0 && det > 0.0) {
        return None;
    }
    let t = m.inverse();
    Some(t.x_axis.x + t.y_axis.y + t.z_axis.z).filter(|t| t.is_finite() && *t > 0.0)
}

/// The pose graph of a g2o or TORO file (see the module's documentation for the lines read).
///
/// Refused, naming the line (from 1, the Error's `line`): a pose line with too few numbers, a bad
/// id or number, a zero quaternion, part of an information matrix or one that is not positive
/// definite, 2D and 3D poses in one file, and with [`OtherLines::Refuse`] a line of another kind.
/// Also refused: a file without pose edges.
pub fn read_g2o(text: &str, others: OtherLines) -> Result<PoseGraph, KliError> {
    let mut dimension: Option<(usize, usize)> = None;
    let mut file_edges = Vec::new();
    let mut relative = Vec::new();
    let mut translations = Vec::new();
    let mut rotation_weights = Vec::new();
    let mut translation_weights = Vec::new();
    let mut information = Vec::new();
    let mut vertices: Vec<(u64, DQuat, DVec3)> = Vec::new();
    let mut skipped: Vec<(String, usize)> = Vec::new();
    for (index, raw) in text.lines().enumerate() {
        let line = index + 1;
        let mut words = raw.split_whitespace();
        let Some(tag) = words.next() else { continue };
        if tag.starts_with('#') || tag == "FIX" {
            continue;
        }
        let Some(kind) = Kind::of(tag) else {
            if others == OtherLines::Refuse {
                return Err(bad(
                    line,
                    format!(
                        "\"{tag}\" is not a pose line ({}); it was refused as asked",
                        Kind::NAMES
                    ),
                ));
            }
            match skipped.iter_mut().find(|(kind, _)| kind == tag) {
                Some((_, n)) => *n += 1,
                None => skipped.push((tag.to_string(), 1)),
            }
            continue;
        };
        match dimension {
            None => dimension = Some((kind.dimension(), line)),
            Some((d, first)) if d != kind.dimension() => {
                return Err(bad(
                    line,
                    format!(
                        "{tag} is a {}D pose, but line {first} was a {d}D one: a file holds one or \
                         the other",
                        kind.dimension()
                    ),
                ));
            }
            Some(_) => {}
        }
        let fields = Fields { fields: words.collect(), line };
        let ids = if kind.is_edge() { 2 } else { 1 };
        let needs = ids + kind.pose_numbers();
        if fields.fields.len() < needs {
            return Err(bad(
                line,
                format!("{tag} needs {needs} numbers after the tag (got {})", fields.fields.len()),
            ));
        }
        if kind.is_edge() {
            let (i, j) = (fields.id(0)?, fields.id(1)?);
            let (q, t) = fields.pose(kind, 2)?;
            let (upper, kappa, tau) = fields.weights(kind, needs)?;
            information.extend(upper);
            file_edges.push([i, j]);
            relative.push(q);
            translations.push(t);
            rotation_weights.push(kappa);
            translation_weights.push(tau);
        } else {
            let id = fields.id(0)?;
            let (q, t) = fields.pose(kind, 1)?;
            vertices.push((id, q, t));
        }
    }
    let Some((dimension, _)) = dimension.filter(|_| !file_edges.is_empty()) else {
        let mut problem =
            "holds no pose edge (EDGE_SE3:QUAT, EDGE3, EDGE_SE2 or EDGE2 line)".into();
        if !skipped.is_empty() {
            let kinds: Vec<String> = skipped.iter().map(|(k, n)| format!("{k} ({n})")).collect();
            problem = format!("{problem}; the lines skipped were {}", kinds.join(", "));
        }
        return Err(KliError::invalid("text", problem));
    };
    let mut ids: Vec<u64> =
        file_edges.iter().flatten().copied().chain(vertices.iter().map(|v| v.0)).collect();
    ids.sort_unstable();
    ids.dedup();
    let index = |id: u64| ids.binary_search(&id).unwrap_or_default();
    let edges = file_edges.iter().map(|&[i, j]| [index(i), index(j)]).collect();
    let count = ids.len();
    let mut poses: Vec<Option<(DQuat, DVec3)>> = vec![None; count];
    for &(id, q, t) in &vertices {
        poses[index(id)] = Some((q, t));
    }
    let poses: Option<Vec<(DQuat, DVec3)>> = poses.into_iter().collect();
    let (initial, positions) = match poses {
        Some(poses) => {
            let (q, t) = poses.into_iter().unzip();
            (Some(q), Some(t))
        }
        None => (None, None),
    };
    Ok(PoseGraph {
        dimension,
        count,
        ids,
        edges,
        relative,
        translations,
        rotation_weights,
        translation_weights,
        information,
        initial,
        positions,
        skipped,
    })
}
