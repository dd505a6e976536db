//! Symmetric matrices with the graph's 3×3 block pattern (the connection Laplacian, the
//! certificate's `S`, the Newton system), and their sparse Cholesky factors by faer.
//!
//! The pattern (and faer's symbolic analysis: the fill-reducing ordering and the elimination
//! tree) is computed once a graph; each numeric factorisation reuses it. Where the factor fills
//! in (random graphs, expanders: a 1,000-node graph of degree 12 fills to a dense triangle of
//! 3.1 million entries, 60 ms a factorisation here), [`Pattern::solve`] uses conjugate gradients
//! with a block-Jacobi preconditioner instead: those graphs are well conditioned, and a
//! solve takes a few dozen sparse products.

use faer::sparse::Pair;
use glam::{DMat3, DVec3};

use super::graph::Graph;
use super::sparse::{Factor, Layout, Lower};

/// A symmetric 3n×3n matrix: `diag[i]` is the block `(i, i)`, `off[k]` the block `(i, j)` of
/// edge `k = (i, j)` (its transpose is the block `(j, i)`; parallel edges add up).
#[derive(Debug, Clone)]
pub(crate) struct Blocks {
    pub diag: Vec<DMat3>,
    pub off: Vec<DMat3>,
}

impl Blocks {
    pub fn zeros(graph: &Graph) -> Blocks {
        Blocks {
            diag: vec![DMat3::ZERO; graph.count()],
            off: vec![DMat3::ZERO; graph.edges().len()],
        }
    }

    /// `y = A x` for vectors of length 3n.
    pub fn apply(&self, graph: &Graph, x: &[f64], y: &mut [f64]) {
        for (i, block) in self.diag.iter().enumerate() {
            put(y, i, *block * get(x, i));
        }
        for (&[i, j], block) in graph.edges().iter().zip(&self.off) {
            add(y, i, *block * get(x, j));
            // Bᵀ x_i: the columns' dot products, without forming Bᵀ.
            let xi = get(x, i);
            add(y, j, DVec3::new(block.x_axis.dot(xi), block.y_axis.dot(xi), block.z_axis.dot(xi)));
        }
    }

    /// `min_i (a_ii − Σ_{j≠i} |a_ij|)` over the rows: no eigenvalue is below it (Gershgorin).
    pub fn gershgorin_lower(&self, graph: &Graph) -> f64 {
        let mut radius = vec![0.0; 3 * graph.count()];
        for (i, block) in self.diag.iter().enumerate() {
            for r in 0..3 {
                for c in 0..3 {
                    if r != c {
                        radius[3 * i + r] += block.col(c)[r].abs();
                    }
                }
            }
        }
        for (&[i, j], block) in graph.edges().iter().zip(&self.off) {
            for r in 0..3 {
                for c in 0..3 {
                    let a = block.col(c)[r].abs();
                    radius[3 * i + r] += a;
                    radius[3 * j + c] += a;
                }
            }
        }
        (0..radius.len())
            .map(|row| self.diag[row / 3].col(row % 3)[row % 3] - radius[row])
            .fold(f64::INFINITY, f64::min)
    }
}

/// The 3-vector of node `i` in a vector of length 3n.
pub(crate) fn get(x: &[f64], i: usize) -> DVec3 {
    DVec3::new(x[3 * i], x[3 * i + 1], x[3 * i + 2])
}

fn put(y: &mut [f64], i: usize, v: DVec3) {
    y[3 * i..3 * i + 3].copy_from_slice(&v.to_array());
}

pub(crate) fn add(y: &mut [f64], i: usize, v: DVec3) {
    y[3 * i] += v.x;
    y[3 * i + 1] += v.y;
    y[3 * i + 2] += v.z;
}

/// The lower triangle of a block matrix with one node's rows and columns left out (or none):
/// which scalar entry each value goes to, and its symbolic Cholesky factorisation.
pub(crate) struct Pattern {
    /// Each node's block row, `None` for the node left out.
    index: Vec<Option<usize>>,
    /// The entries as [`walk`] lists them.
    lower: Lower,
    /// Whether the Cholesky factor holds more than [`FILL`] times the matrix's entries.
    fills: bool,
}

/// The fill beyond which [`Pattern::solve`] prefers conjugate gradients: sphere2500's factor
/// holds 8.5 times its matrix's entries, a random graph of degree 12 on 1,000 nodes 52 times.
const FILL: usize = 20;

impl Pattern {
    /// The pattern of `graph`'s block matrices without node `left_out`'s block row and column.
    pub fn new(graph: &Graph, left_out: Option<usize>) -> Pattern {
        let mut index = vec![None; graph.count()];
        let mut size = 0;
        for (i, slot) in index.iter_mut().enumerate() {
            if Some(i) != left_out {
                *slot = Some(size);
                size += 1;
            }
        }
        let mut pairs = Vec::new();
        visit(graph, &index, |row, col| pairs.push(Pair { row, col }));
        let lower = Lower::new(3 * size, &pairs, Layout::Auto);
        let fills = lower.factor_len() > FILL.saturating_mul(pairs.len());
        Pattern { index, lower, fills }
    }

    /// Node `i`'s block row, `None` for the node left out.
    pub fn row(&self, i: usize) -> Option<usize> {
        self.index[i]
    }

    /// The Cholesky factor of `a + shift I` restricted to the pattern's nodes, or `None` when it
    /// is not positive definite (a pivot ≤ 0 or not finite).
    pub fn factor(&self, graph: &Graph, a: &Blocks, shift: f64) -> Option<Factor> {
        let mut values = Vec::new();
        let shifted: Vec<DMat3> =
            a.diag.iter().map(|d| *d + DMat3::from_diagonal(DVec3::splat(shift))).collect();
        // The same walk as `visit`, reading the values instead of the positions.
        walk(graph, &self.index, |entry| {
            values.push(match entry {
                Entry::Diagonal { node, row, col } => shifted[node].col(col)[row],
                Entry::Edge { edge, row, col, transposed: false } => a.off[edge].col(col)[row],
                Entry::Edge { edge, row, col, transposed: true } => a.off[edge].col(row)[col],
            })
        });
        self.lower.factor(&values)
    }
}

impl Pattern {
    /// Whether the Cholesky factor fills in (more than [`FILL`] times the matrix's entries).
    pub fn fills(&self) -> bool {
        self.fills
    }

    /// Solves `(a + shift I) x = b` on the pattern's nodes (`b` and `x` of length 3n, the node
    /// left out held at 0): by conjugate gradients to `‖r‖ ≤ tolerance ‖b‖` where the factor
    /// fills in, else (or when they have not converged in 500 steps) by Cholesky. `None` when
    /// `a + shift I` is not positive definite (a non-positive curvature met, or a pivot).
    pub fn solve(
        &self,
        graph: &Graph,
        a: &Blocks,
        shift: f64,
        b: &[f64],
        tolerance: f64,
    ) -> Option<Vec<f64>> {
        if self.fills {
            match self.conjugate_gradients(graph, a, shift, b, tolerance) {
                Solved::Yes(x) => return Some(x),
                Solved::Indefinite => return None,
                Solved::Slow => {}
            }
        }
        let factor = self.factor(graph, a, shift)?;
        let mut reduced = vec![0.0; 3 * self.index.iter().flatten().count()];
        for (i, slot) in self.index.iter().enumerate() {
            if let Some(r) = slot {
                reduced[3 * r..3 * r + 3].copy_from_slice(&b[3 * i..3 * i + 3]);
            }
        }
        factor.solve(&mut reduced, 1);
        let mut x = vec![0.0; b.len()];
        for (i, slot) in self.index.iter().enumerate() {
            if let Some(r) = slot {
                x[3 * i..3 * i + 3].copy_from_slice(&reduced[3 * r..3 * r + 3]);
            }
        }
        Some(x)
    }

    /// Preconditioned conjugate gradients (Saad, "Iterative Methods for Sparse Linear Systems",
    /// Algorithm 9.1) with the inverses of the 3×3 diagonal blocks, to `‖r‖ ≤ tolerance ‖b‖`.
    pub(super) fn conjugate_gradients(
        &self,
        graph: &Graph,
        a: &Blocks,
        shift: f64,
        b: &[f64],
        tolerance: f64,
    ) -> Solved {
        let kept = |i: usize| self.index[i].is_some();
        let shifted = DMat3::from_diagonal(DVec3::splat(shift));
        let mut inverse = Vec::with_capacity(a.diag.len());
        for (i, d) in a.diag.iter().enumerate() {
            let block = *d + shifted;
            // A positive definite matrix has positive definite diagonal blocks.
            let minors = [
                block.col(0)[0],
                block.col(0)[0] * block.col(1)[1] - block.col(1)[0] * block.col(0)[1],
                block.determinant(),
            ];
            if kept(i) && !minors.iter().all(|&m| m > 0.0) {
                return Solved::Indefinite;
            }
            inverse.push(if kept(i) { block.inverse() } else { DMat3::ZERO });
        }
        let n = b.len();
        let apply = |x: &[f64], y: &mut [f64]| {
            a.apply(graph, x, y);
            for i in 0..n / 3 {
                for k in 0..3 {
                    y[3 * i + k] = if kept(i) { y[3 * i + k] + shift * x[3 * i + k] } else { 0.0 };
                }
            }
        };
        let precondition = |r: &[f64], z: &mut [f64]| {
            for (i, m) in inverse.iter().enumerate() {
                put(z, i, *m * get(r, i));
            }
        };
        let dot = |u: &[f64], v: &[f64]| u.iter().zip(v).map(|(p, q)| p * q).sum::<f64>();
        let mut x = vec![0.0; n];
        let mut r: Vec<f64> = (0..n).map(|k| if kept(k / 3) { b[k] } else { 0.0 }).collect();
        let target = tolerance * dot(&r, &r).sqrt();
        let mut z = vec![0.0; n];
        precondition(&r, &mut z);
        let mut p = z.clone();
        let mut rz = dot(&r, &z);
        let mut ap = vec![0.0; n];
        for _ in 0..500 {
            if dot(&r, &r).sqrt() <= target {
                return Solved::Yes(x);
            }
            apply(&p, &mut ap);
            let curvature = dot(&p, &ap);
            if curvature.is_nan() || curvature <= 0.0 {
                return Solved::Indefinite;
            }
            let alpha = rz / curvature;
            x.iter_mut().zip(&p).for_each(|(xi, pi)| *xi += alpha * pi);
            r.iter_mut().zip(&ap).for_each(|(ri, api)| *ri -= alpha * api);
            precondition(&r, &mut z);
            let next = dot(&r, &z);
            let beta = next / rz;
            rz = next;
            p.iter_mut().zip(&z).for_each(|(pi, zi)| *pi = zi + beta * *pi);
        }
        if dot(&r, &r).sqrt() <= target { Solved::Yes(x) } else { Solved::Slow }
    }
}

/// How conjugate gradients ended.
#[derive(Debug)]
pub(super) enum Solved {
    Yes(Vec<f64>),
    /// A direction of non-positive curvature: the matrix is not positive definite.
    Indefinite,
    /// Not converged in the steps allowed.
    Slow,
}

/// One stored value of the lower triangle, in the order the pattern lists them.
enum Entry {
    /// Entry `(row, col)` of node `node`'s diagonal block.
    Diagonal { node: usize, row: usize, col: usize },
    /// Entry `(row, col)` of edge `edge`'s block `(i, j)`, or of its transpose.
    Edge { edge: usize, row: usize, col: usize, transposed: bool },
}

/// Every stored entry of the lower triangle, once, in a fixed order: each node's diagonal block
/// (its lower triangle), then each edge whose nodes are both kept (the block below the diagonal).
fn walk(graph: &Graph, index: &[Option<usize>], mut each: impl FnMut(Entry)) {
    for (node, slot) in index.iter().enumerate() {
        if slot.is_some() {
            for col in 0..3 {
                for row in col..3 {
                    each(Entry::Diagonal { node, row, col });
                }
            }
        }
    }
    for (edge, &[i, j]) in graph.edges().iter().enumerate() {
        if let (Some(bi), Some(bj)) = (index[i], index[j]) {
            for col in 0..3 {
                for row in 0..3 {
                    each(Entry::Edge { edge, row, col, transposed: bi < bj });
                }
            }
        }
    }
}

/// The scalar position of each entry `walk` lists.
fn visit(graph: &Graph, index: &[Option<usize>], mut each: impl FnMut(usize, usize)) {
    walk(graph, index, |entry| match entry {
        Entry::Diagonal { node, row, col } => {
            let b = index[node].unwrap_or(0);
            each(3 * b + row, 3 * b + col)
        }
        Entry::Edge { edge, row, col, transposed } => {
            let [i, j] = graph.edges()[edge];
            let (bi, bj) = (index[i].unwrap_or(0), index[j].unwrap_or(0));
            // Block (i, j) sits below the diagonal when i's block row is below j's; otherwise
            // its transpose, block (j, i), does.
            let (br, bc) = if transposed { (bj, bi) } else { (bi, bj) };
            each(3 * br + row, 3 * bc + col)
        }
    });
}
