//! The synchronisation page's pictures: the graph with each edge coloured by its residual and
//! each node's error as a needle; every node on the Hopf sphere beside its truth; the first nodes
//! as objects; the flow's cost and error over time; and the two solutions' residuals side by
//! side.

use glam::{DQuat, DVec3};
use kli::hopf::hopf;

use super::model::{History, Model};
use super::solutions::Solutions;
use crate::aircraft::Face;
use crate::camera::{Camera, Viewport};
use crate::format::{exponential, fixed};
use crate::legend::{Entry, Mark, draw_legend, draw_plot_key};
use crate::object_view::{draw_object, object_camera};
use crate::palette::{INK, KLI, MUTED, SLERP};
use crate::pen::Pen;
use crate::plots::{Panel, inset, trim};
use crate::sphere_view::{View, draw_globe, draw_grid_back, draw_grid_front, grid};
use crate::ticks::nice_step;

/// The residual classes' upper ends, degrees, and their colours (each ≥ 3:1 on white).
pub const CLASSES: [(f64, &str, &str); 5] = [
    (2.0, "#3b5bdb", "< 2°"),
    (5.0, "#0c8599", "2–5°"),
    (15.0, "#5c940d", "5–15°"),
    (45.0, "#e8590c", "15–45°"),
    (f64::INFINITY, "#c92a2a", "≥ 45°"),
];

/// The class of a residual angle in radians.
pub fn class(residual: f64) -> usize {
    let degrees = residual.to_degrees();
    CLASSES.iter().position(|&(end, _, _)| degrees < end).unwrap_or(CLASSES.len() - 1)
}

/// The truth's colour on the sphere and in the objects.
const TRUTH: &str = MUTED;
/// The flow's nodes.
const NODE: &str = "#1864ab";
/// A wrong edge's dash.
const WRONG_DASH: &[f64] = &[4.0, 3.0];

/// Each node's error rotation `t̄_i ḡ q_i`, 1 when it agrees with the truth.
fn errors(model: &Model) -> Vec<DQuat> {
    let q = model.flow.rotations();
    let g = model.problem.gauge(q).conjugate();
    q.iter().zip(&model.problem.truth).map(|(&q, &t)| t.conjugate() * g * q).collect()
}

/// The graph in a square: every edge in the colour of its residual now (a wrong one dashed),
/// every node a dot with a needle, its error rotation applied to the body x-axis (seen from
/// above: a needle pointing right agrees with the truth).
pub fn draw_graph(pen: &Pen, model: &Model, (width, height): (f64, f64)) {
    let s = pen.text_scale();
    let side = (width.min(height) - 28.0 * s).max(10.0);
    let (left, top) = (0.5 * (width - side), 18.0 * s);
    let at = |(x, y): (f64, f64)| (left + x * side, top + y * side);
    let places = &model.problem.places;
    let residuals = model.flow.residuals();
    let mut groups: Vec<Vec<[(f64, f64); 2]>> = vec![Vec::new(); 2 * CLASSES.len()];
    for ((&[i, j], &r), &wrong) in
        model.problem.graph.edges().iter().zip(&residuals).zip(&model.problem.wrong)
    {
        groups[2 * class(r) + usize::from(wrong)].push([at(places[i]), at(places[j])]);
    }
    let line = if model.problem.graph.edges().len() > 3000 { 0.6 } else { 1.4 };
    for (k, segments) in groups.iter().enumerate() {
        let dash = if k % 2 == 1 { WRONG_DASH } else { &[] };
        pen.segments(segments, CLASSES[k / 2].1, line, dash);
    }
    let r = if places.len() > 150 { 1.8 } else { 2.6 };
    let needle = (0.45 * side / (places.len() as f64).sqrt()).clamp(4.0, 14.0);
    let mut needles = Vec::with_capacity(places.len());
    for (&place, e) in places.iter().zip(errors(model)) {
        let (x, y) = at(place);
        let v = e * DVec3::X;
        needles.push([(x, y), (x + needle * v.x, y - needle * v.y)]);
    }
    pen.segments(&needles, INK, 1.4, &[]);
    let dots: Vec<(f64, f64)> = places.iter().map(|&p| at(p)).collect();
    pen.dots(&dots, r, NODE);
    let flow = &model.flow;
    let title = format!("t = {}   f = {}", fixed(flow.time(), 2), exponential(flow.cost(), 3));
    pen.text(&title, (left, 9.0 * s), MUTED, 12.0, "left");
    let mut entries: Vec<Entry> = CLASSES
        .iter()
        .map(|&(_, colour, label)| Entry { mark: Mark::Line(colour, 2.0, &[]), label })
        .collect();
    if model.problem.wrong.iter().any(|&w| w) {
        entries.push(Entry { mark: Mark::Line(INK, 1.4, WRONG_DASH), label: "a wrong edge" });
    }
    // In the strip left of the square when there is one (else the figure's caption is the key).
    let area = Viewport::fitting(0.0, 0.0, left.max(0.4 * width), height, 1.0);
    draw_legend(pen, &area, &entries, Some("needle →: agrees"));
}

/// Every node's aligned rotation `ḡ q_i` on S² through the Hopf map, its truth `h(t_i)` a ring:
/// the dots settle into the rings as the flow agrees with the truth.
pub fn draw_sphere(pen: &Pen, model: &Model, viewport: &Viewport, camera: &Camera) {
    let view = View { pen, viewport, camera };
    let q = model.flow.rotations();
    let g = model.problem.gauge(q).conjugate();
    let points: Vec<DVec3> = q.iter().map(|&q| hopf(g * q)).collect();
    let truths: Vec<DVec3> = model.problem.truth.iter().map(|&t| hopf(t)).collect();
    let r = if points.len() > 150 { 2.0 } else { 3.0 };
    draw_grid_back(&view, &grid());
    let behind = |p: &&DVec3| !view.in_front(**p);
    pen.alpha(0.5);
    for t in truths.iter().filter(behind) {
        pen.disc(view.at(*t), r + 1.5, None, Some((TRUTH, 1.0)));
    }
    pen.dots(&points.iter().filter(behind).map(|&p| view.at(p)).collect::<Vec<_>>(), r, MUTED);
    pen.alpha(1.0);
    draw_globe(&view);
    draw_grid_front(&view, &grid());
    for t in truths.iter().filter(|p| view.in_front(**p)) {
        pen.disc(view.at(*t), r + 1.5, None, Some((TRUTH, 1.2)));
    }
    let front: Vec<(f64, f64)> =
        points.iter().filter(|p| view.in_front(**p)).map(|&p| view.at(p)).collect();
    pen.dots(&front, r, NODE);
    let entries = [
        Entry { mark: Mark::Disc(Some(NODE), NODE), label: "a node now: h(ḡ q_i)" },
        Entry { mark: Mark::Disc(None, TRUTH), label: "its truth h(t_i)" },
    ];
    draw_legend(pen, viewport, &entries, Some("ḡ: the gauge that best fits the truth"));
}

/// The first three nodes as objects, each aligned (`ḡ q_i`) over its truth drawn faint.
pub fn draw_objects(pen: &Pen, model: &Model, mesh: &[Face], (width, height): (f64, f64)) {
    let camera = object_camera();
    let q = model.flow.rotations();
    let g = model.problem.gauge(q).conjugate();
    let shown = q.len().min(3);
    let cell = width / shown.max(1) as f64;
    let angles = kli::sync::errors_to_truth(q, &model.problem.truth);
    for i in 0..shown {
        let left = i as f64 * cell;
        let viewport = Viewport::fitting(left, 14.0, cell, height - 14.0, 1.6);
        pen.alpha(0.3);
        draw_object(pen, &viewport, &camera, mesh, model.problem.truth[i], false);
        pen.alpha(1.0);
        draw_object(pen, &viewport, &camera, mesh, g * q[i], false);
        let off = fixed(angles[i].to_degrees(), 1);
        // A phone's third of the width holds only the short form.
        let label = if cell >= 130.0 {
            format!("node {}: {off}° off", i + 1)
        } else {
            format!("{}: {off}°", i + 1)
        };
        pen.text(&label, (left + 0.5 * cell, 10.0), INK, 12.0, "center");
    }
}

/// The flow's cost `f` (log) with the chordal optimum, and its median error to the truth with
/// both solutions' errors: side by side when wide, stacked when narrow.
pub fn draw_plots(pen: &Pen, model: &Model, (width, height): (f64, f64)) {
    let History { times, costs, errors } = &model.history;
    let wide = width >= 1.6 * height;
    let cell = |k: usize| {
        let s = pen.text_scale();
        if wide {
            inset((k as f64 * 0.5 * width, 0.0, 0.5 * width, height), s, 50.0)
        } else {
            inset((0.0, k as f64 * 0.5 * height, width, 0.5 * height), s, 50.0)
        }
    };
    let x = match (times.first(), times.last()) {
        (Some(&a), Some(&b)) if b > a => (a, b),
        _ => (0.0, 1.0),
    };
    // The cost, log10, from the optimum's decade (or 1e-12 for consensus; the flow's lowest
    // while the problem is being solved) to the largest.
    let solved = model.solutions.as_ref();
    let best = solved
        .map_or_else(|| costs.iter().fold(f64::INFINITY, |l, &c| l.min(c)), |s| s.chordal.cost);
    let floor = if best > 0.0 && best.is_finite() { best.log10().floor() } else { -12.0 };
    let high = costs
        .iter()
        .fold(best.clamp(1e-12, f64::MAX), |h, &c| h.max(c))
        .log10()
        .ceil()
        .max(floor + 1.0);
    let cost = Panel::new(cell(0), x, (floor, high));
    let every = ((high - floor) / 4.0).ceil().max(1.0);
    let ticks: Vec<(f64, String)> = (0..=((high - floor) / every) as usize)
        .map(|k| floor + k as f64 * every)
        .map(|e| (e, format!("1e{}", e as i32)))
        .collect();
    cost.frame_with(pen, "the flow's cost f", &ticks, "t");
    let log = costs.iter().map(|&c| if c > 0.0 { c.log10().max(floor) } else { floor });
    cost.series(pen, times, log, NODE, 2.0, &[]);
    // The flow now, a dot: at the start the line is a single point.
    if let (Some(&t), Some(&c)) = (times.last(), costs.last()) {
        let now = if c > 0.0 { c.log10().max(floor) } else { floor };
        pen.dots(&[cost.at(t, now)], 3.0, NODE);
    }
    let certified = solved.and_then(|s| s.chordal.certificate).is_some_and(|c| c.certified);
    if solved.is_some() && best > 0.0 {
        let (_, y) = cost.at(x.0, best.log10());
        pen.line((cost.left, y), (cost.left + cost.width, y), KLI, 1.5, &[5.0, 3.0]);
    }
    let optimum = match solved {
        Some(_) if certified => "chordal optimum, certified",
        Some(_) => "chordal optimum",
        None => "chordal optimum: solving…",
    };
    let key = [
        Entry { mark: Mark::Line(NODE, 2.0, &[]), label: "flow" },
        Entry { mark: Mark::Line(KLI, 1.5, &[5.0, 3.0]), label: optimum },
    ];
    draw_plot_key(pen, &cost, "the flow's cost f", &key);

    let median = |q: &[DQuat]| model.problem.median_error(q).to_degrees();
    let both =
        solved.map(|s| [(median(&s.chordal.rotations), KLI), (median(&s.robust.rotations), SLERP)]);
    let lines = both.as_ref().map_or(&[][..], |b| &b[..]);
    let largest = errors
        .iter()
        .fold(lines.iter().fold(0.0_f64, |h, &(e, _)| h.max(e)), |h, &e| h.max(e.to_degrees()));
    let step = nice_step(1.1 * largest.max(0.5));
    let top = step * (1.1 * largest.max(0.5) / step).ceil();
    let error = Panel::new(cell(1), x, (0.0, top));
    let ticks: Vec<(f64, String)> =
        [0.0, 0.5 * top, top].iter().map(|&v| (v, format!("{}°", trim(v)))).collect();
    let title = "median error to the truth";
    error.frame_with(pen, title, &ticks, "t");
    error.series(pen, times, errors.iter().map(|e| e.to_degrees()), NODE, 2.0, &[]);
    if let (Some(&t), Some(&e)) = (times.last(), errors.last()) {
        pen.dots(&[error.at(t, e.to_degrees())], 3.0, NODE);
    }
    for &(value, colour) in lines {
        let (_, y) = error.at(x.0, value);
        pen.line((error.left, y), (error.left + error.width, y), colour, 1.5, &[5.0, 3.0]);
    }
    let key = [
        Entry { mark: Mark::Line(NODE, 2.0, &[]), label: "flow" },
        Entry { mark: Mark::Line(KLI, 1.5, &[5.0, 3.0]), label: "chordal" },
        Entry { mark: Mark::Line(SLERP, 1.5, &[5.0, 3.0]), label: "robust" },
    ];
    draw_plot_key(pen, &error, title, &key);
}

/// One side of the comparison: a solution's residuals as a histogram over [`CLASSES`], the
/// edges known to be wrong (or flagged, for a file) stacked on top, under its heading lines.
pub struct Side<'a> {
    pub heading: String,
    pub lines: Vec<String>,
    pub residuals: &'a [f64],
    pub marked: &'a [bool],
    pub marked_label: &'a str,
}

/// Two solutions side by side (stacked when narrow): each a histogram of residuals.
pub fn draw_sides(pen: &Pen, sides: &[Side], (width, height): (f64, f64)) {
    let s = pen.text_scale();
    let wide = width >= 1.6 * height;
    let k = sides.len().max(1) as f64;
    let counts: Vec<[[usize; 2]; 5]> = sides
        .iter()
        .map(|side| {
            let mut c = [[0usize; 2]; 5];
            for (i, &r) in side.residuals.iter().enumerate() {
                c[class(r)][usize::from(side.marked.get(i).copied().unwrap_or(false))] += 1;
            }
            c
        })
        .collect();
    let most = counts.iter().flatten().map(|c| c[0] + c[1]).max().unwrap_or(1).max(1) as f64;
    for (n, (side, counts)) in sides.iter().zip(&counts).enumerate() {
        let (cl, ct, cw, ch) = if wide {
            (n as f64 * width / k, 0.0, width / k, height)
        } else {
            (0.0, n as f64 * height / k, width, height / k)
        };
        pen.text(&side.heading, (cl + 10.0, ct + 12.0 * s), INK, 13.0, "left");
        for (i, line) in side.lines.iter().enumerate() {
            pen.text(line, (cl + 10.0, ct + (28.0 + 14.0 * i as f64) * s), MUTED, 11.0, "left");
        }
        let head = (24.0 + 14.0 * side.lines.len() as f64) * s;
        let (left, top, w, h) = inset((cl, ct + head, cw, ch - head), s, 40.0);
        let step = nice_step(most).max(1.0);
        let y_top = step * (most / step).ceil();
        let p = Panel::new((left, top, w, h), (0.0, 5.0), (0.0, y_top));
        let ticks: Vec<(f64, String)> =
            [0.0, 0.5 * y_top, y_top].iter().map(|&v| (v, trim(v.round()))).collect();
        p.frame_y(pen, "edges by residual", &ticks);
        let bar = p.width / 5.0;
        for (c, &[plain, marked]) in counts.iter().enumerate() {
            let x0 = p.left + c as f64 * bar + 0.12 * bar;
            let x1 = x0 + 0.76 * bar;
            let (_, y0) = p.at(0.0, 0.0);
            let (_, y1) = p.at(0.0, plain as f64);
            let (_, y2) = p.at(0.0, (plain + marked) as f64);
            let colour = CLASSES[c].1;
            if plain > 0 {
                pen.fill_polygon(&[(x0, y1), (x1, y1), (x1, y0), (x0, y0)], colour, None);
            }
            if marked > 0 {
                let outline = [(x0, y2), (x1, y2), (x1, y1), (x0, y1)];
                pen.fill_polygon(&outline, "#ffffff", Some(colour));
                pen.segments(&[[(x0, y2), (x1, y1)], [(x0, y1), (x1, y2)]], colour, 1.0, &[]);
            }
            pen.text(CLASSES[c].2, (x0 + 0.38 * bar, y0 + 12.0 * s), MUTED, 10.5, "center");
        }
        let key = [
            Entry { mark: Mark::Line(INK, 6.0, &[]), label: "edges" },
            Entry { mark: Mark::Disc(Some("#ffffff"), INK), label: side.marked_label },
        ];
        draw_plot_key(pen, &p, "edges by residual", &key);
    }
}

/// The sides of the page's own problem: chordal with its certificate, robust with its flags.
pub fn draw_results(pen: &Pen, model: &Model, size: (f64, f64)) {
    let p = &model.problem;
    let wrong = p.wrong.iter().filter(|&&w| w).count();
    let Some(Solutions { chordal, robust }) = &model.solutions else {
        let (width, height) = size;
        pen.text("Solving…", (0.5 * width, 0.5 * height), MUTED, 14.0, "center");
        return;
    };
    let certificate = match chordal.certificate {
        Some(c) if c.certified => format!("certified: λmin(S) = {}", exponential(c.lambda_min, 1)),
        Some(c) => format!("not certified: λmin(S) = {}", exponential(c.lambda_min, 1)),
        None => String::new(),
    };
    let flags = robust.outliers.as_deref().unwrap_or(&[]);
    let caught = flags.iter().zip(&p.wrong).filter(|&(&f, &w)| f && w).count();
    let good = flags.iter().zip(&p.wrong).filter(|&(&f, &w)| f && !w).count();
    let error = |q: &[DQuat]| fixed(p.median_error(q).to_degrees(), 2);
    let sides = [
        Side {
            heading: "chordal (least squares)".into(),
            lines: vec![
                format!(
                    "median error {}°, f = {}",
                    error(&chordal.rotations),
                    exponential(chordal.cost, 3)
                ),
                certificate,
            ],
            residuals: &chordal.residuals,
            marked: &p.wrong,
            marked_label: "wrong edges",
        },
        Side {
            heading: "robust (reweighted)".into(),
            lines: vec![
                format!("median error {}°", error(&robust.rotations)),
                format!("flagged {caught} of {wrong} wrong edges, {good} good ones"),
            ],
            residuals: &robust.residuals,
            marked: &p.wrong,
            marked_label: "wrong edges",
        },
    ];
    draw_sides(pen, &sides, size);
}
