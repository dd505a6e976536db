//! The input of synchronisation, checked once: `n` nodes, edges `(i, j)` with measured relative
//! rotations `q_ij ≈ q̄_i q_j` (`R_ij = R_iᵀ R_j`, any sign) and weights `w_ij > 0`, on a
//! connected graph (MATH.md, "Synchronising rotations on a graph").

use glam::DQuat;

use crate::error::{ErrorKind, KliError, Requirement, require};
use crate::quaternion::unit;

/// A checked measurement graph: every id below [`count`](Graph::count), no self-loops, unit
/// relatives, positive finite weights, and every node reachable from every other.
#[derive(Debug, Clone, PartialEq)]
pub struct Graph {
    count: usize,
    edges: Vec<[usize; 2]>,
    relative: Vec<DQuat>,
    weights: Vec<f64>,
}

/// How many cut-off nodes an error names before it says "and k more".
const NAMED: usize = 8;

impl Graph {
    /// Checks the measurements: `count` nodes (by default one more than the largest id),
    /// `edges[k] = [i, j]` measured as `relative[k]` (normalised here; its sign is irrelevant),
    /// weighted `weights[k]` (1 by default). Parallel edges add up; the order of the edges and
    /// the direction of each (`[j, i]` with `q̄_ij`) do not change the problem.
    ///
    /// Refused, naming the argument: no edges; an id at or above `count`; a self-loop; fewer or
    /// more relatives (or weights) than edges; a NaN, infinite or zero relative; a weight that is
    /// not finite and `> 0`; a graph that is not connected (the error lists the nodes cut off
    /// from node 0).
    pub fn new(
        count: Option<usize>,
        edges: &[[usize; 2]],
        relative: &[DQuat],
        weights: Option<&[f64]>,
    ) -> Result<Graph, KliError> {
        if edges.is_empty() {
            return Err(KliError::invalid(
                "edges",
                "is empty: synchronisation needs at least one edge",
            ));
        }
        let largest = edges.iter().flatten().copied().max().unwrap_or(0);
        let count = match count {
            Some(count) => {
                if let Some((k, &[i, j])) =
                    edges.iter().enumerate().find(|(_, e)| e[0] >= count || e[1] >= count)
                {
                    let id = if i >= count { i } else { j };
                    return Err(KliError::invalid(
                        format!("edges[{k}]"),
                        format!(
                            "names node {id}, but count is {count} (ids run from 0 to count − 1)"
                        ),
                    ));
                }
                count
            }
            None => largest.saturating_add(1),
        };
        if let Some((k, e)) = edges.iter().enumerate().find(|(_, e)| e[0] == e[1]) {
            return Err(KliError::invalid(
                format!("edges[{k}]"),
                format!("joins node {} to itself: a self-loop measures nothing", e[0]),
            ));
        }
        if relative.len() != edges.len() {
            return Err(KliError::new(
                "relative",
                ErrorKind::WrongLength {
                    expected: 4 * edges.len(),
                    got: relative.len().saturating_mul(4),
                    per: "edge".into(),
                },
            ));
        }
        let relative = relative
            .iter()
            .enumerate()
            .map(|(k, &q)| unit(&format!("relative[{k}]"), q))
            .collect::<Result<Vec<_>, _>>()?;
        let weights = match weights {
            None => vec![1.0; edges.len()],
            Some(weights) => {
                if weights.len() != edges.len() {
                    return Err(KliError::invalid(
                        "weights",
                        format!(
                            "must hold one number per edge: {} (got {})",
                            edges.len(),
                            weights.len()
                        ),
                    ));
                }
                for (k, &w) in weights.iter().enumerate() {
                    require(&format!("weights[{k}]"), w, Requirement::Positive)?;
                }
                weights.to_vec()
            }
        };
        check_connected(count, edges)?;
        Ok(Graph { count, edges: edges.to_vec(), relative, weights })
    }

    /// The number of nodes.
    pub fn count(&self) -> usize {
        self.count
    }

    /// The edges `[i, j]`, in the caller's order.
    pub fn edges(&self) -> &[[usize; 2]] {
        &self.edges
    }

    /// The measured `q_ij` of each edge, normalised.
    pub fn relative(&self) -> &[DQuat] {
        &self.relative
    }

    /// The weight of each edge.
    pub fn weights(&self) -> &[f64] {
        &self.weights
    }

    /// The same graph with other weights (already checked: the robust method's rounds).
    pub(crate) fn reweighted(&self, weights: Vec<f64>) -> Graph {
        Graph { weights, ..self.clone() }
    }

    /// `d_i = Σ_j w_ij`, each node's weighted degree.
    pub(crate) fn degrees(&self) -> Vec<f64> {
        let mut degree = vec![0.0; self.count];
        for (&[i, j], &w) in self.edges.iter().zip(&self.weights) {
            degree[i] += w;
            degree[j] += w;
        }
        degree
    }
}

/// Refuses a graph whose nodes are not all reachable from node 0, naming the first ones cut off
/// and counting the rest. Works on the ids the edges name (at most 2m of them), so a `count` far
/// beyond the edges is refused without allocating anything of its size.
fn check_connected(count: usize, edges: &[[usize; 2]]) -> Result<(), KliError> {
    let mut ids: Vec<usize> = edges.iter().flatten().copied().collect();
    ids.sort_unstable();
    ids.dedup();
    let index = |id: usize| ids.binary_search(&id).ok();
    // Union–find with path halving over the ids: near-linear, no recursion.
    let mut parent: Vec<usize> = (0..ids.len()).collect();
    fn root(parent: &mut [usize], mut a: usize) -> usize {
        while parent[a] != a {
            parent[a] = parent[parent[a]];
            a = parent[a];
        }
        a
    }
    for &[i, j] in edges {
        let (a, b) = (index(i).unwrap_or(0), index(j).unwrap_or(0));
        let (a, b) = (root(&mut parent, a), root(&mut parent, b));
        if a != b {
            parent[a.max(b)] = a.min(b);
        }
    }
    let origin = index(0).map(|k| root(&mut parent, k));
    let mut reached = 0;
    for k in 0..ids.len() {
        if Some(root(&mut parent, k)) == origin {
            reached += 1;
        }
    }
    // Node 0 without an edge reaches only itself.
    let reached = reached.max(1);
    if reached == count {
        return Ok(());
    }
    let mut joined = |id: usize| match (index(id), origin) {
        (Some(k), Some(o)) => root(&mut parent, k) == o,
        _ => id == 0,
    };
    // The cut-off nodes are found within the first `reached + NAMED` ids.
    let named: Vec<String> =
        (0..count).filter(|&id| !joined(id)).take(NAMED).map(|id| id.to_string()).collect();
    let cut = count - reached;
    let more = if cut > NAMED { format!(" and {} more", cut - NAMED) } else { String::new() };
    let (noun, verb) = if cut == 1 { ("node", "is") } else { ("nodes", "are") };
    Err(KliError::invalid(
        "edges",
        format!(
            "do not connect the graph: {noun} {}{more} {verb} cut off from node 0",
            named.join(", ")
        ),
    ))
}
