//! Reading the rotations of a pose graph: g2o's `VERTEX_SE3:QUAT` and `EDGE_SE3:QUAT` lines and
//! TORO's (GTSAM's) `VERTEX3` and `EDGE3` lines, as GTSAM's `parse3DFactors` and `readG2o` read
//! them. Translations and information matrices are skipped.
//!
//! - `EDGE_SE3:QUAT i j x y z qx qy qz qw [21 information entries]`: `R_ij = R_iᵀ R_j`, the
//!   rotation part of the relative pose `T_i⁻¹ T_j`.
//! - `VERTEX_SE3:QUAT id x y z qx qy qz qw`: node `id`'s pose, the initial estimate.
//! - `EDGE3 i j x y z roll pitch yaw [21]` and `VERTEX3 id x y z roll pitch yaw`:
//!   `R = Rz(yaw) Ry(pitch) Rx(roll)`.
//! - `FIX id` lines, blank lines and `#` comments are skipped.

use glam::DQuat;

use crate::error::KliError;
use crate::quaternion::unit;

/// The rotations of a pose graph file.
#[derive(Debug, Clone, PartialEq)]
pub struct PoseGraph {
    /// One more than the largest node id.
    pub count: usize,
    /// The edges `[i, j]`, in the file's order.
    pub edges: Vec<[usize; 2]>,
    /// Each edge's `q_ij` (unit, its sign as written).
    pub relative: Vec<DQuat>,
    /// Every node's rotation from its vertex line, when every node has one.
    pub initial: Option<Vec<DQuat>>,
}

fn bad(line: usize, problem: impl std::fmt::Display) -> KliError {
    KliError::invalid("text", format!("line {line}: {problem}"))
}

/// The `index`-th field after the tag as a node id (a non-negative integer).
fn id(fields: &[&str], index: usize, line: usize) -> Result<usize, KliError> {
    let text = fields[index];
    text.parse::<usize>()
        .map_err(|_| bad(line, format!("node id \"{text}\" is not a non-negative integer")))
}

fn number(fields: &[&str], index: usize, line: usize) -> Result<f64, KliError> {
    let text = fields[index];
    match text.parse::<f64>() {
        Ok(x) if x.is_finite() => Ok(x),
        _ => Err(bad(line, format!("\"{text}\" is not a finite number"))),
    }
}

/// `qx qy qz qw` from `fields[at..at + 4]`, normalised.
fn quaternion(fields: &[&str], at: usize, line: usize) -> Result<DQuat, KliError> {
    let [x, y, z, w] = [0, 1, 2, 3].map(|k| number(fields, at + k, line));
    let q = DQuat::from_xyzw(x?, y?, z?, w?);
    unit("q", q).map_err(|_| bad(line, "the quaternion has zero length"))
}

/// `Rz(yaw) Ry(pitch) Rx(roll)` from `fields[at..at + 3]` = roll, pitch, yaw.
fn euler(fields: &[&str], at: usize, line: usize) -> Result<DQuat, KliError> {
    let [roll, pitch, yaw] = [0, 1, 2].map(|k| number(fields, at + k, line));
    Ok(DQuat::from_rotation_z(yaw?)
        * DQuat::from_rotation_y(pitch?)
        * DQuat::from_rotation_x(roll?))
}

/// The rotations of a g2o or TORO file. A line that is not one of the kinds above, has too few
/// numbers, a bad id or number, or a zero quaternion is refused with its number (from 1); so is
/// a file without edges.
pub fn read_g2o(text: &str) -> Result<PoseGraph, KliError> {
    let mut edges = Vec::new();
    let mut relative = Vec::new();
    let mut vertices: Vec<(usize, DQuat)> = Vec::new();
    for (index, raw) in text.lines().enumerate() {
        let line = index + 1;
        let fields: Vec<&str> = raw.split_whitespace().collect();
        let Some(&tag) = fields.first() else { continue };
        if tag.starts_with('#') || tag == "FIX" {
            continue;
        }
        let needs = match tag {
            "EDGE_SE3:QUAT" => 9,
            "EDGE3" => 8,
            "VERTEX_SE3:QUAT" => 8,
            "VERTEX3" => 7,
            _ => {
                return Err(bad(
                    line,
                    format!(
                        "\"{tag}\" is not a 3D pose line (EDGE_SE3:QUAT, VERTEX_SE3:QUAT, EDGE3 or \
                         VERTEX3)"
                    ),
                ));
            }
        };
        if fields.len() - 1 < needs {
            return Err(bad(
                line,
                format!("{tag} needs {needs} numbers after the tag (got {})", fields.len() - 1),
            ));
        }
        match tag {
            "EDGE_SE3:QUAT" | "EDGE3" => {
                let (i, j) = (id(&fields, 1, line)?, id(&fields, 2, line)?);
                let q = if tag == "EDGE3" {
                    euler(&fields, 6, line)?
                } else {
                    quaternion(&fields, 6, line)?
                };
                edges.push([i, j]);
                relative.push(q);
            }
            _ => {
                let node = id(&fields, 1, line)?;
                let q = if tag == "VERTEX3" {
                    euler(&fields, 5, line)?
                } else {
                    quaternion(&fields, 5, line)?
                };
                vertices.push((node, q));
            }
        }
    }
    if edges.is_empty() {
        return Err(KliError::invalid("text", "holds no EDGE_SE3:QUAT or EDGE3 line"));
    }
    let largest =
        edges.iter().flatten().chain(vertices.iter().map(|(i, _)| i)).copied().max().unwrap_or(0);
    let count = largest
        .checked_add(1)
        .ok_or_else(|| KliError::invalid("text", format!("node id {largest} is too large")))?;
    let initial = if vertices.len() >= count {
        let mut initial: Vec<Option<DQuat>> = vec![None; count];
        for (i, q) in vertices {
            initial[i] = Some(q);
        }
        initial.into_iter().collect::<Option<Vec<_>>>()
    } else {
        None
    };
    Ok(PoseGraph { count, edges, relative, initial })
}
