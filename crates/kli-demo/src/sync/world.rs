//! The synchronisation page's built-in pose graph: a robot drives a loop through a small world
//! (a town of 3 × 2 square blocks, streets 8 m apart), one pose a metre, measuring each step by
//! noisy odometry and, where it passes a place it has been before, a few loop closures. It is
//! written as a g2o file of `EDGE_SE2` lines with their information, so the page reads it like
//! any file a user opens; with no `VERTEX` lines, its initial estimate is the odometry chained,
//! the robot's own dead reckoning.
//!
//! The route, in blocks from the town's corner: round the outside, then up the first side
//! street, along the middle street, and through the two cross streets,
//! `(0,0) (3,0) (3,2) (0,2) (0,0) (0,1) (3,1) (3,0) (1,0) (1,2) (2,2) (2,0)` and back to
//! `(0,0)`: 24 blocks, so 24 · 8 = 192 poses, 191 odometry edges. A loop closure joins two poses
//! at the same place more than a block apart along the route.

use std::fmt::Write;

use kli::swarm::Random;

/// The side of a block, metres; the robot's step is 1 m.
pub const BLOCK: usize = 8;

/// The route's corners, in blocks.
const ROUTE: [(i32, i32); 13] = [
    (0, 0),
    (3, 0),
    (3, 2),
    (0, 2),
    (0, 0),
    (0, 1),
    (3, 1),
    (3, 0),
    (1, 0),
    (1, 2),
    (2, 2),
    (2, 0),
    (0, 0),
];

/// The most loop closures the page's slider asks for.
pub const MAX_CLOSURES: usize = 40;

/// The most noise, degrees of heading a step.
pub const MAX_NOISE: f64 = 10.0;

/// The translation noise per degree of heading noise, metres (2° and 0.1 m a step by default).
const METRES_PER_DEGREE: f64 = 0.05;

/// The smallest standard deviation the information is written with (so that a noise-free
/// world still has finite weights): 0.1° and 5 mm.
const FLOOR_DEGREES: f64 = 0.1;

/// How the world is measured.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WorldOptions {
    /// The odometry's and the loop closures' heading noise, degrees a measurement (σ); the
    /// translation's is 0.05 m a degree.
    pub noise: f64,
    /// How many loop closures, spread along the route (at most the places revisited).
    pub closures: usize,
    /// The noise's seed.
    pub seed: u64,
}

impl Default for WorldOptions {
    fn default() -> Self {
        WorldOptions { noise: 2.0, closures: 8, seed: 1 }
    }
}

/// A planar pose: position and heading (radians).
pub type Pose2 = (f64, f64, f64);

/// The world: its true poses, its edges and their measurements, and the g2o text (the page reads
/// the text alone; the tests read the rest).
#[cfg_attr(not(test), allow(dead_code))]
pub struct World {
    pub truth: Vec<Pose2>,
    /// The edges, odometry `(k, k + 1)` first, then the loop closures.
    pub edges: Vec<[usize; 2]>,
    /// Each edge's measured `(dx, dy, dθ)` in its first pose's frame.
    pub measured: Vec<Pose2>,
    /// The odometry chained from the first pose: the robot's own (drifting) estimate, computed
    /// here by angles (the map chains quaternions).
    pub dead_reckoning: Vec<Pose2>,
    pub text: String,
}

/// The true poses along the route, a metre apart: each heads along the street it is on (at a
/// corner, the street it turns into).
pub fn route() -> Vec<Pose2> {
    let mut poses = Vec::new();
    for leg in ROUTE.windows(2) {
        let (a, b) = (leg[0], leg[1]);
        let (dx, dy) = ((b.0 - a.0).signum(), (b.1 - a.1).signum());
        let length = ((b.0 - a.0).abs() + (b.1 - a.1).abs()) as usize * BLOCK;
        let heading = f64::from(dy).atan2(f64::from(dx));
        for s in 0..length {
            let x = (a.0 as usize * BLOCK) as f64 + f64::from(dx) * s as f64;
            let y = (a.1 as usize * BLOCK) as f64 + f64::from(dy) * s as f64;
            poses.push((x, y, heading));
        }
    }
    poses
}

/// Every pair `(i, j)` of poses at the same place more than a block apart along the route,
/// ordered by `j`, then `i`.
pub fn revisits(poses: &[Pose2]) -> Vec<[usize; 2]> {
    let mut pairs = Vec::new();
    for j in 0..poses.len() {
        for i in 0..j.saturating_sub(BLOCK) {
            if (poses[i].0 - poses[j].0).abs() < 1e-9 && (poses[i].1 - poses[j].1).abs() < 1e-9 {
                pairs.push([i, j]);
            }
        }
    }
    pairs
}

/// `b` in `a`'s frame: `a⁻¹ b`.
pub fn between(a: Pose2, b: Pose2) -> Pose2 {
    let (c, s) = (a.2.cos(), a.2.sin());
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    (c * dx + s * dy, -s * dx + c * dy, wrap(b.2 - a.2))
}

/// `a ∘ d`: the pose `d` (in `a`'s frame) in the world.
pub fn compose(a: Pose2, d: Pose2) -> Pose2 {
    let (c, s) = (a.2.cos(), a.2.sin());
    (a.0 + c * d.0 - s * d.1, a.1 + s * d.0 + c * d.1, wrap(a.2 + d.2))
}

/// An angle in (−π, π].
fn wrap(angle: f64) -> f64 {
    let a = angle.rem_euclid(std::f64::consts::TAU);
    if a > std::f64::consts::PI { a - std::f64::consts::TAU } else { a }
}

impl World {
    /// The world `options` describe (their ranges are the page's to check).
    pub fn new(options: &WorldOptions) -> World {
        let truth = route();
        let n = truth.len();
        let candidates = revisits(&truth);
        let k = options.closures.min(candidates.len());
        // Spread evenly through the candidates, as a robot that closes a loop now and then.
        let closures = (0..k).map(|c| candidates[((2 * c + 1) * candidates.len()) / (2 * k)]);
        let edges: Vec<[usize; 2]> = (0..n - 1).map(|i| [i, i + 1]).chain(closures).collect();
        let mut random = Random::new(options.seed);
        let sigma = options.noise.to_radians();
        let metres = options.noise * METRES_PER_DEGREE;
        let measured: Vec<Pose2> = edges
            .iter()
            .map(|&[i, j]| {
                let (x, y, t) = between(truth[i], truth[j]);
                let noise = [random.gaussian(), random.gaussian(), random.gaussian()];
                (x + metres * noise[0], y + metres * noise[1], wrap(t + sigma * noise[2]))
            })
            .collect();
        let mut dead_reckoning = vec![truth[0]];
        for k in 0..n - 1 {
            dead_reckoning.push(compose(dead_reckoning[k], measured[k]));
        }
        let floor = options.noise.max(FLOOR_DEGREES);
        let information =
            [1.0 / (floor * METRES_PER_DEGREE).powi(2), 1.0 / floor.to_radians().powi(2)];
        let text = text(options, n, &edges, &measured, information);
        World { truth, edges, measured, dead_reckoning, text }
    }
}

/// The g2o file: a comment, then the edges with the information
/// `diag(1/σ_t², 1/σ_t², 1/σ_θ²)` (g2o's `I11 I12 I13 I22 I23 I33`). Numbers are written as
/// Rust writes an f64, the shortest text that reads back as the same number.
fn text(
    options: &WorldOptions,
    poses: usize,
    edges: &[[usize; 2]],
    measured: &[Pose2],
    [translation, rotation]: [f64; 2],
) -> String {
    let mut out = String::with_capacity(100 * edges.len());
    let _ = writeln!(
        out,
        "# kli's built-in pose graph: a robot's loop through a town of 3 x 2 blocks, {} poses, \
         {} loop closures, noise {} degrees, seed {}",
        poses,
        edges.len() - (poses - 1),
        options.noise,
        options.seed
    );
    for (&[i, j], &(x, y, t)) in edges.iter().zip(measured) {
        let _ = writeln!(
            out,
            "EDGE_SE2 {i} {j} {x} {y} {t} {translation} 0 0 {translation} 0 {rotation}"
        );
    }
    out
}
