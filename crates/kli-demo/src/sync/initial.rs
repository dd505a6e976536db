//! A pose graph's initial estimate, what the map shows beside the optimum: the file's own
//! (its `VERTEX` lines), or, where it has none, the odometry chained: each pose reached from
//! pose 0 through the fewest loop closures (a 0–1 breadth-first search, an odometry edge
//! `(k, k ± 1)` costing 0 and any other 1), composing the measurements along the way,
//! `T_j = T_i T̃_ij` forwards and `T_i = T_j T̃_ij⁻¹` backwards. Either is then put in the
//! optimum's gauge: pose 0 at the identity and the origin (`T_0⁻¹ T_k`).

use std::collections::VecDeque;

use glam::{DQuat, DVec3};
use kli::sync::{PoseGraph, anchor_poses};

/// Poses: each one's rotation and position.
#[derive(Debug, Clone, PartialEq)]
pub struct Poses {
    pub rotations: Vec<DQuat>,
    pub positions: Vec<DVec3>,
}

/// The graph's initial estimate, and whether it is the file's own (else the odometry chained).
/// Poses the edges do not reach from pose 0 stay at the identity and the origin (the solver
/// refuses such a graph before the map is drawn).
pub fn initial(graph: &PoseGraph) -> (Poses, bool) {
    let poses = match (&graph.initial, &graph.positions) {
        (Some(rotations), Some(positions)) => {
            Poses { rotations: rotations.clone(), positions: positions.clone() }
        }
        _ => chained(graph),
    };
    (anchored(poses, 0), graph.initial.is_some() && graph.positions.is_some())
}

/// The odometry chained along the search the module describes.
pub fn chained(graph: &PoseGraph) -> Poses {
    let n = graph.count;
    let mut neighbours: Vec<Vec<usize>> = vec![Vec::new(); n];
    for (k, &[i, j]) in graph.edges.iter().enumerate() {
        neighbours[i].push(k);
        neighbours[j].push(k);
    }
    let mut rotations = vec![DQuat::IDENTITY; n];
    let mut positions = vec![DVec3::ZERO; n];
    let mut closures = vec![usize::MAX; n];
    let mut done = vec![false; n];
    let mut queue = VecDeque::new();
    if n > 0 {
        closures[0] = 0;
        queue.push_back(0);
    }
    while let Some(a) = queue.pop_front() {
        if done[a] {
            continue;
        }
        done[a] = true;
        for &k in &neighbours[a] {
            let [i, j] = graph.edges[k];
            let b = if i == a { j } else { i };
            let step = usize::from(i.abs_diff(j) != 1);
            if done[b] || closures[a] + step >= closures[b] {
                continue;
            }
            closures[b] = closures[a] + step;
            let (q, t) = (graph.relative[k].normalize(), graph.translations[k]);
            if i == a {
                rotations[b] = (rotations[a] * q).normalize();
                positions[b] = positions[a] + rotations[a] * t;
            } else {
                rotations[b] = (rotations[a] * q.conjugate()).normalize();
                positions[b] = positions[a] - rotations[b] * t;
            }
            if step == 0 { queue.push_front(b) } else { queue.push_back(b) }
        }
    }
    Poses { rotations, positions }
}

/// `poses` in the gauge that puts pose `anchor` at the identity and the origin, as the solver
/// returns its own ([`anchor_poses`]).
pub fn anchored(poses: Poses, anchor: usize) -> Poses {
    let (rotations, positions) = anchor_poses(&poses.rotations, &poses.positions, anchor);
    Poses { rotations, positions }
}
