//! What the synchronisation page computes: `n` true rotations on a graph (a ring, a grid, a
//! random geometric graph or the complete graph), a measurement `q_ij = q̄_i q_j · noise` on each
//! edge (a share of them replaced by uniformly random rotations), the chordal optimum with its
//! certificate and the robust solution of [`kli::sync::synchronize`], and the Lohe flow of
//! [`SyncFlow`] from a random start with its history (MATH.md, "Synchronising rotations on a
//! graph").

use glam::{DQuat, DVec3};
use kli::KliError;
use kli::quaternion::exp;
use kli::swarm::Random;
use kli::sync::{Graph, Method, SyncFlow, SyncOptions, Synchronized, errors_to_truth, synchronize};

use super::solutions::Solutions;

/// The graphs the page draws, by the word its URL uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shape {
    /// A random geometric graph: each node joined to its nearest neighbours in the square.
    Random,
    Ring,
    Grid,
    Complete,
}

impl Shape {
    pub const NAMES: &'static [&'static str] = &["random", "ring", "grid", "complete"];

    pub fn name(self) -> &'static str {
        Self::NAMES[self as usize]
    }

    pub fn from_name(name: &str) -> Option<Shape> {
        [Shape::Random, Shape::Ring, Shape::Grid, Shape::Complete]
            .into_iter()
            .find(|s| s.name() == name)
    }
}

/// How many nearest neighbours each node of the random graph is joined to (then the graph is
/// symmetrised and joined up): about 10 a node, as the bench's graphs have. With 4, a tenth
/// of the edges wrong already put the robust solution 25° off on some seeds.
const NEAREST: usize = 8;

/// How the problem is made.
#[derive(Debug, Clone, PartialEq)]
pub struct Options {
    pub count: usize,
    pub shape: Shape,
    /// The standard deviation of each measurement's angle of noise, degrees.
    pub noise: f64,
    /// The share of edges whose measurement is replaced by a uniformly random rotation, 0 to 1.
    pub wrong: f64,
    pub seed: u64,
    /// Every `q_ij = 1`: consensus (the truth is any common rotation; no noise, no wrong edges).
    pub consensus: bool,
}

/// The problem: where each node is drawn, the truth, the graph and which edges are wrong.
#[derive(Debug, Clone)]
pub struct Problem {
    /// Each node's place in the unit square, for the graph view.
    pub places: Vec<(f64, f64)>,
    pub truth: Vec<DQuat>,
    pub graph: Graph,
    pub wrong: Vec<bool>,
}

/// Each node's place and the edges of `shape` on `count` nodes (always connected).
pub fn layout(
    shape: Shape,
    count: usize,
    random: &mut Random,
) -> (Vec<(f64, f64)>, Vec<[usize; 2]>) {
    let on_circle = |count: usize| -> Vec<(f64, f64)> {
        (0..count)
            .map(|i| {
                let a = std::f64::consts::TAU * i as f64 / count as f64;
                (0.5 + 0.5 * a.cos(), 0.5 + 0.5 * a.sin())
            })
            .collect()
    };
    match shape {
        Shape::Ring => {
            let edges = (0..count).map(|i| [i, (i + 1) % count]).collect();
            (on_circle(count), edges)
        }
        Shape::Complete => {
            let edges = (0..count).flat_map(|i| (i + 1..count).map(move |j| [i, j])).collect();
            (on_circle(count), edges)
        }
        Shape::Grid => {
            let columns = (count as f64).sqrt().ceil() as usize;
            let rows = count.div_ceil(columns);
            let place = |i: usize| {
                let (r, c) = (i / columns, i % columns);
                let step =
                    |k: usize, of: usize| if of > 1 { k as f64 / (of - 1) as f64 } else { 0.5 };
                (step(c, columns), step(r, rows))
            };
            let mut edges = Vec::new();
            for i in 0..count {
                if (i + 1) % columns != 0 && i + 1 < count {
                    edges.push([i, i + 1]);
                }
                if i + columns < count {
                    edges.push([i, i + columns]);
                }
            }
            ((0..count).map(place).collect(), edges)
        }
        Shape::Random => {
            let places: Vec<(f64, f64)> =
                (0..count).map(|_| (random.uniform(), random.uniform())).collect();
            let distance = |a: usize, b: usize| {
                let (p, q) = (places[a], places[b]);
                (p.0 - q.0).hypot(p.1 - q.1)
            };
            let mut edges: Vec<[usize; 2]> = Vec::new();
            for i in 0..count {
                let mut others: Vec<usize> = (0..count).filter(|&j| j != i).collect();
                others.sort_by(|&a, &b| distance(i, a).total_cmp(&distance(i, b)));
                for &j in others.iter().take(NEAREST) {
                    let edge = [i.min(j), i.max(j)];
                    if !edges.contains(&edge) {
                        edges.push(edge);
                    }
                }
            }
            // Nearest neighbours can leave islands: join each to its nearest node outside it.
            let mut parts = Parts::new(count);
            for &[i, j] in &edges {
                parts.join(i, j);
            }
            loop {
                let roots: Vec<usize> = (0..count).map(|i| parts.root(i)).collect();
                let Some(&root) = roots.iter().find(|&&r| r != roots[0]) else { break };
                let inside: Vec<usize> = (0..count).filter(|&i| roots[i] == root).collect();
                let outside: Vec<usize> = (0..count).filter(|&i| roots[i] != root).collect();
                let (a, b) = inside
                    .iter()
                    .flat_map(|&a| outside.iter().map(move |&b| (a, b)))
                    .min_by(|x, y| distance(x.0, x.1).total_cmp(&distance(y.0, y.1)))
                    .expect("both sides are non-empty");
                edges.push([a.min(b), a.max(b)]);
                parts.join(a, b);
            }
            (places, edges)
        }
    }
}

/// Union–find over node ids, to join the random graph's islands.
struct Parts(Vec<usize>);

impl Parts {
    fn new(count: usize) -> Parts {
        Parts((0..count).collect())
    }

    fn root(&mut self, mut i: usize) -> usize {
        while self.0[i] != i {
            self.0[i] = self.0[self.0[i]];
            i = self.0[i];
        }
        i
    }

    fn join(&mut self, a: usize, b: usize) {
        let (a, b) = (self.root(a), self.root(b));
        self.0[a] = b;
    }
}

impl Problem {
    /// The problem `options` describe, reproducibly from the seed.
    pub fn new(options: &Options) -> Result<Problem, KliError> {
        let mut random = Random::new(options.seed);
        let (places, edges) = layout(options.shape, options.count, &mut random);
        let truth: Vec<DQuat> = if options.consensus {
            vec![DQuat::IDENTITY; options.count]
        } else {
            (0..options.count).map(|_| random.unit_quaternion()).collect()
        };
        // Exactly round(share × m) wrong edges, chosen by a seeded shuffle.
        let m = edges.len();
        let mut order: Vec<usize> = (0..m).collect();
        for k in (1..m).rev() {
            order.swap(k, (random.uniform() * (k + 1) as f64) as usize);
        }
        let mut wrong = vec![false; m];
        if !options.consensus {
            let count = (options.wrong * m as f64).round() as usize;
            order.iter().take(count).for_each(|&k| wrong[k] = true);
        }
        let sigma = options.noise.to_radians();
        let relative: Vec<DQuat> = edges
            .iter()
            .zip(&wrong)
            .map(|(&[i, j], &wrong)| {
                if options.consensus {
                    DQuat::IDENTITY
                } else if wrong {
                    random.unit_quaternion()
                } else {
                    // A random axis and a normal angle of deviation σ (Chatterjee and Govindu).
                    let axis = random.gaussian3().normalize_or(DVec3::X);
                    let noise = exp(axis * (0.5 * sigma * random.gaussian()));
                    truth[i].conjugate() * truth[j] * noise
                }
            })
            .collect();
        let graph = Graph::new(Some(options.count), &edges, &relative, None)?;
        Ok(Problem { places, truth, graph, wrong })
    }

    /// The problem solved by `method`.
    pub fn solve(&self, method: Method) -> Result<Synchronized, KliError> {
        synchronize(&self.graph, &SyncOptions { method, ..SyncOptions::default() })
    }

    /// The median of each node's angle to the truth after the best gauge, radians.
    pub fn median_error(&self, q: &[DQuat]) -> f64 {
        median(errors_to_truth(q, &self.truth))
    }

    /// The gauge `g` that best takes the truth onto `q` (see [`errors_to_truth`]): the figures
    /// draw `ḡ q_i`, which is the truth when `q` is right.
    pub fn gauge(&self, q: &[DQuat]) -> DQuat {
        let mut m = [[0.0; 4]; 4];
        for (&q, &t) in q.iter().zip(&self.truth) {
            let v = kli::to_wxyz(q * t.conjugate());
            for r in 0..4 {
                for c in 0..4 {
                    m[r][c] += v[r] * v[c];
                }
            }
        }
        kli::from_wxyz(kli::average::eigen(m).1[0]).normalize()
    }
}

/// The median of `values` (NaN for none).
pub fn median(mut values: Vec<f64>) -> f64 {
    if values.is_empty() {
        return f64::NAN;
    }
    values.sort_by(f64::total_cmp);
    let n = values.len();
    if n % 2 == 1 { values[n / 2] } else { 0.5 * (values[n / 2 - 1] + values[n / 2]) }
}

/// How many samples the history keeps (the oldest are dropped, so memory stays flat).
pub const HISTORY: usize = 1500;

/// The flow's `(t, f, median error)` samples, the newest last.
#[derive(Debug, Clone, Default)]
pub struct History {
    pub times: Vec<f64>,
    pub costs: Vec<f64>,
    pub errors: Vec<f64>,
}

impl History {
    pub fn push(&mut self, t: f64, cost: f64, error: f64) {
        if self.times.len() == HISTORY {
            self.times.remove(0);
            self.costs.remove(0);
            self.errors.remove(0);
        }
        self.times.push(t);
        self.costs.push(cost);
        self.errors.push(error);
    }
}

/// The whole run: the problem, both solutions, and the flow with its history.
pub struct Model {
    pub options: Options,
    pub problem: Problem,
    /// Both solutions, once solved (the page solves in a worker and hands them over).
    pub solutions: Option<Solutions>,
    pub flow: SyncFlow,
    /// The flow's step: `0.1 / d_max`, stable for every graph (the pull on a node is at most
    /// `2 d_i`).
    pub dt: f64,
    pub history: History,
}

impl Model {
    /// The problem, solved both ways, and the flow at its start.
    pub fn new(options: Options) -> Result<Model, KliError> {
        let mut model = Model::unsolved(options)?;
        model.solutions = Some(Solutions::of(&model.problem)?);
        Ok(model)
    }

    /// The problem and the flow at its start, not yet solved.
    pub fn unsolved(options: Options) -> Result<Model, KliError> {
        let problem = Problem::new(&options)?;
        let mut degree = vec![0.0; options.count];
        for &[i, j] in problem.graph.edges() {
            degree[i] += 1.0;
            degree[j] += 1.0;
        }
        let dt = 0.1 / degree.iter().copied().fold(1.0, f64::max);
        // Not the problem's seed: the start is not the truth's draw.
        let flow = SyncFlow::random(problem.graph.clone(), options.seed ^ 0x5eed_f10e);
        let mut model =
            Model { options, problem, solutions: None, flow, dt, history: History::default() };
        model.record();
        Ok(model)
    }

    /// Samples the flow into the history.
    pub fn record(&mut self) {
        let q = self.flow.rotations();
        let error = self.problem.median_error(q);
        self.history.push(self.flow.time(), self.flow.cost(), error);
    }

    /// `steps` steps of the flow, then one sample.
    pub fn step(&mut self, steps: usize) -> Result<(), KliError> {
        self.flow.step(self.dt, steps)?;
        self.record();
        Ok(())
    }

    /// Whether the flow's cost is within `1e-6` (relative, or absolutely for an optimum of 0) of
    /// the chordal optimum: it has arrived (false while the problem is not solved).
    pub fn arrived(&self) -> bool {
        let Some(best) = self.solutions.as_ref().map(|s| s.chordal.cost) else { return false };
        self.flow.cost() - best <= 1e-6 * best.max(1.0)
    }
}
