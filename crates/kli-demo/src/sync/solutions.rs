//! Both solutions of the page's problem (or of a user's pose graph), and their transfer as one
//! array of numbers: the page solves in a worker (the solve is the only long work of a run: 230
//! ms on its first call in Chromium, some 900 ms on Lighthouse's phone, one task; a large pose
//! graph takes seconds), so that building a run never blocks the page, and hands the numbers to
//! its run (`SyncDemo.takeSolutions`) or to the file's reading (`SyncFile.solved`).
//!
//! The array, for `n` nodes and `m` edges: `[n, m]`, then each of the chordal and the robust
//! solution as `4n` rotations (`w, x, y, z`), the cost, `m` residuals, the iterations, the
//! certificate `[present, λ_min, gap, τ, certified]`, the weights `[present, m values]`, the
//! outlier flags `[present, m flags]` and the scale `[present, value]`: `2 + 2(4n + 3m + 11)`.

use glam::DQuat;
use kli::sync::{Certificate, Method, Synchronized};
use kli::{KliError, from_wxyz, to_wxyz};

use super::model::Problem;

/// The chordal optimum (with its certificate) and the robust solution of one problem.
#[derive(Debug, Clone, PartialEq)]
pub struct Solutions {
    pub chordal: Synchronized,
    pub robust: Synchronized,
}

/// How many numbers one solution takes in the array.
const fn one(n: usize, m: usize) -> usize {
    4 * n + 3 * m + 11
}

impl Solutions {
    /// The problem solved both ways.
    pub fn of(problem: &Problem) -> Result<Solutions, KliError> {
        Ok(Solutions {
            chordal: problem.solve(Method::Chordal)?,
            robust: problem.solve(Method::Robust)?,
        })
    }

    /// How many numbers the array has for `n` nodes and `m` edges.
    pub const fn length(n: usize, m: usize) -> usize {
        2 + 2 * one(n, m)
    }

    /// The array the module's doc describes.
    pub fn pack(&self) -> Vec<f64> {
        let (n, m) = (self.chordal.rotations.len(), self.chordal.residuals.len());
        let mut out = Vec::with_capacity(Solutions::length(n, m));
        out.extend([n as f64, m as f64]);
        for s in [&self.chordal, &self.robust] {
            s.rotations.iter().for_each(|&q| out.extend(to_wxyz(q)));
            out.push(s.cost);
            out.extend(&s.residuals);
            out.push(s.iterations as f64);
            match s.certificate {
                Some(c) => out.extend([1.0, c.lambda_min, c.gap, c.tolerance, flag(c.certified)]),
                None => out.extend([0.0; 5]),
            }
            let present = |values: Option<Vec<f64>>| -> Vec<f64> {
                match values {
                    Some(v) => std::iter::once(1.0).chain(v).collect(),
                    None => vec![0.0; m + 1],
                }
            };
            out.extend(present(s.weights.clone()));
            out.extend(present(s.outliers.as_ref().map(|o| o.iter().map(|&b| flag(b)).collect())));
            out.extend([flag(s.scale.is_some()), s.scale.unwrap_or(0.0)]);
        }
        out
    }

    /// The solutions an array holds, for a problem of `n` nodes and `m` edges; an Error naming
    /// `solutions` when the array is not one [`Solutions::pack`] makes for that problem (its
    /// length or size, a rotation not of unit length, a count or flag out of range).
    pub fn unpack(data: &[f64], n: usize, m: usize) -> Result<Solutions, KliError> {
        let wrong = |what: &str| {
            KliError::invalid(
                "solutions",
                format!("must be what solve returns for this problem: {what}"),
            )
        };
        if data.len() != Solutions::length(n, m) {
            return Err(wrong(&format!(
                "{} numbers for {n} nodes and {m} edges, got {}",
                Solutions::length(n, m),
                data.len()
            )));
        }
        if data[0] != n as f64 || data[1] != m as f64 {
            // Counts as whole numbers: no float formatting in the module, and none that needs
            // JavaScript (these checks run natively in the tests too).
            let count = |x: f64| whole(x).map_or_else(|| "?".to_string(), |c| c.to_string());
            let other =
                format!("another problem's ({} nodes, {} edges)", count(data[0]), count(data[1]));
            return Err(wrong(&other));
        }
        let mut at = 2;
        let mut take = |count: usize| {
            at += count;
            &data[at - count..at]
        };
        let mut side = || -> Result<Synchronized, KliError> {
            let rotations: Vec<DQuat> =
                take(4 * n).chunks_exact(4).map(|c| from_wxyz([c[0], c[1], c[2], c[3]])).collect();
            if !rotations.iter().all(|q| (q.length() - 1.0).abs() <= 1e-9) {
                return Err(wrong("a rotation not of unit length"));
            }
            let cost = take(1)[0];
            let residuals = take(m).to_vec();
            let iterations =
                whole(take(1)[0]).ok_or_else(|| wrong("iterations not a whole number"))?;
            let c = take(5);
            let certificate = match present(c[0]).ok_or_else(|| wrong("a flag not 0 or 1"))? {
                true => Some(Certificate {
                    lambda_min: c[1],
                    gap: c[2],
                    tolerance: c[3],
                    certified: present(c[4]).ok_or_else(|| wrong("a flag not 0 or 1"))?,
                }),
                false => None,
            };
            let w = take(m + 1);
            let weights =
                present(w[0]).ok_or_else(|| wrong("a flag not 0 or 1"))?.then(|| w[1..].to_vec());
            let o = take(m + 1);
            let outliers = match present(o[0]).ok_or_else(|| wrong("a flag not 0 or 1"))? {
                true => Some(
                    o[1..]
                        .iter()
                        .map(|&f| present(f))
                        .collect::<Option<Vec<bool>>>()
                        .ok_or_else(|| wrong("a flag not 0 or 1"))?,
                ),
                false => None,
            };
            let s = take(2);
            let scale = present(s[0]).ok_or_else(|| wrong("a flag not 0 or 1"))?.then_some(s[1]);
            Ok(Synchronized {
                rotations,
                cost,
                residuals,
                iterations,
                certificate,
                weights,
                outliers,
                scale,
            })
        };
        let chordal = side()?;
        let robust = side()?;
        Ok(Solutions { chordal, robust })
    }
}

fn flag(b: bool) -> f64 {
    if b { 1.0 } else { 0.0 }
}

/// A flag's value: `Some` for exactly 0 or 1.
fn present(x: f64) -> Option<bool> {
    (x == 0.0 || x == 1.0).then_some(x == 1.0)
}

/// A count: `Some` for a whole number from 0 to 2⁵³.
pub fn whole(x: f64) -> Option<usize> {
    (x.fract() == 0.0 && (0.0..=9_007_199_254_740_992.0).contains(&x)).then_some(x as usize)
}
