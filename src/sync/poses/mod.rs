//! Pose-graph synchronisation, certifiably: SE-Sync (Rosen, Carlone, Bandeira and Leonard,
//! "SE-Sync: a certifiably correct algorithm for synchronization over the special Euclidean
//! group", IJRR 2019; MATH.md, "Pose graphs").
//!
//! This first part: the problem with its translations eliminated in closed form (`reduced`), its
//! sparse factorisations (`sparse`), and the points of `St(d, r)ⁿ` it is evaluated at
//! (`stiefel`). The solver that uses them comes next.
// Used by the solver, which is not here yet.
#![allow(dead_code)]
// The d × d blocks are indexed as the formulas write them (rows a, columns b).
#![allow(clippy::needless_range_loop)]

mod reduced;
mod sparse;
mod stiefel;
#[cfg(test)]
mod tests;
