//! The averaging page's pictures: the measurements, the truth, the four means and the follower's
//! path on the Hopf sphere; the follower as an object beside the truth; each mean's error as a
//! bar; and the sweep of the errors against the outlier share.

use glam::DVec3;
use kli::average::Method;
use kli::hopf::hopf;

use super::model::{Model, STYLES};
use crate::aircraft::Face;
use crate::camera::Viewport;
use crate::figure::{Frame, Layer};
use crate::format::fixed;
use crate::legend::{Entry, Mark, draw_legend};
use crate::object_view::{draw_object, object_camera};
use crate::palette::{GRID, INK, MUTED};
use crate::pen::Pen;
use crate::sphere_view::{Side, View, draw_globe, draw_grid_back, draw_grid_front, grid};
use crate::sweep::{Curve, draw_error_sweep};

/// The measurements' dots: inliers, wild ones, and the ring of those the median marks.
const DATUM: &str = "#1864ab";
const WILD: &str = "#e8590c";

/// The still part: the sphere, the measurements (wild ones in their own colour, those the median
/// marks ringed), the truth, the means and the follower's whole path; the moving part: the
/// follower at the frame's time.
pub fn draw_sphere(pen: &Pen, model: &Model, frame: &Frame, layer: Layer) {
    let viewport = frame.sphere_viewport();
    let view = View { pen, viewport: &viewport, camera: &frame.camera };
    if layer.still() {
        draw_still(&view, model);
    }
    if layer != Layer::Still {
        let p = hopf(model.follower(frame.t));
        pen.alpha(if view.in_front(p) { 1.0 } else { 0.45 });
        pen.disc(view.at(p), 6.5, Some(INK), Some(("#ffffff", 2.0)));
        pen.alpha(1.0);
    }
}

fn draw_still(view: &View, model: &Model) {
    let pen = view.pen;
    let grid = grid();
    let points: Vec<DVec3> = model.data.iter().map(|&q| hopf(q)).collect();
    let r = if points.len() > 200 { 2.4 } else { 3.4 };
    draw_grid_back(view, &grid);
    view.polyline_on(&model.flow_hopf, Side::Back, (INK, 1.5, &[4.0, 3.0]));
    for (&p, &wild) in points.iter().zip(&model.wild) {
        if !view.in_front(p) {
            pen.disc(view.at(p), r, Some(if wild { WILD } else { MUTED }), None);
        }
    }
    pen.alpha(1.0);
    draw_globe(view);
    draw_grid_front(view, &grid);
    view.polyline_on(&model.flow_hopf, Side::Front, (INK, 2.0, &[4.0, 3.0]));
    let marked = model.marked();
    for ((&p, &wild), &mark) in points.iter().zip(&model.wild).zip(&marked) {
        let front = view.in_front(p);
        pen.alpha(if front { 1.0 } else { 0.4 });
        if front {
            pen.disc(view.at(p), r, Some(if wild { WILD } else { DATUM }), None);
        }
        if mark {
            pen.disc(view.at(p), r + 3.0, None, Some((WILD, 1.5)));
        }
    }
    let truth = hopf(model.truth);
    pen.alpha(if view.in_front(truth) { 1.0 } else { 0.4 });
    star(pen, view.at(truth), 9.0, INK);
    for (mean, style) in model.means.iter().zip(&STYLES) {
        let p = hopf(mean.rotation);
        pen.alpha(if view.in_front(p) { 1.0 } else { 0.4 });
        pen.disc(view.at(p), 5.0, Some("#ffffff"), Some((style.colour, 2.5)));
    }
    pen.alpha(1.0);
    // Each mean by its own ring: the figure stands alone (a <kli-figure>, a slide, its SVG), away
    // from the page's bars that share the colours.
    let names: Vec<String> = STYLES
        .iter()
        .map(|style| match style.method {
            Method::Median => "the median".to_string(),
            _ => format!("the {} mean", style.name),
        })
        .collect();
    let mut entries = vec![
        Entry { mark: Mark::Disc(Some(DATUM), DATUM), label: "a measurement h(r_j)" },
        Entry {
            mark: Mark::Disc(Some(WILD), WILD),
            label: "a wild one (ringed: marked by the median)",
        },
        Entry {
            mark: Mark::Disc(Some(INK), INK), label: "★ the truth; ● the follower, from 1"
        },
    ];
    entries.extend(STYLES.iter().zip(&names).map(|(style, name)| Entry {
        mark: Mark::Disc(Some("#ffffff"), style.colour),
        label: name,
    }));
    draw_legend(pen, view.viewport, &entries, None);
}

/// A five-pointed star centred at `(x, y)`.
fn star(pen: &Pen, (x, y): (f64, f64), r: f64, colour: &str) {
    let points: Vec<(f64, f64)> = (0..10)
        .map(|k| {
            let a = std::f64::consts::PI * (k as f64 / 5.0 - 0.5);
            let radius = if k % 2 == 0 { r } else { 0.45 * r };
            (x + radius * a.cos(), y + radius * a.sin())
        })
        .collect();
    pen.fill_polygon(&points, colour, Some("#ffffff"));
}

/// The follower at `t` beside the truth, as objects.
pub fn draw_objects(pen: &Pen, model: &Model, mesh: &[Face], (width, height): (f64, f64), t: f64) {
    let camera = object_camera();
    let wide = width >= height;
    let (w, h) = if wide { (width / 2.0, height) } else { (width, height / 2.0) };
    let error = kli::average::angle(model.follower(t), model.truth).to_degrees();
    let objects = [
        (model.follower(t), format!("the follower: {}° from the truth", fixed(error, 1)), INK),
        (model.truth, "the truth".to_owned(), MUTED),
    ];
    for (i, (q, label, colour)) in objects.iter().enumerate() {
        let (left, top) = if wide { (i as f64 * w, 0.0) } else { (0.0, i as f64 * h) };
        let viewport = Viewport::fitting(left, top + 14.0, w, h - 14.0, 1.6);
        draw_object(pen, &viewport, &camera, mesh, *q, false);
        pen.text(label, (left + 0.5 * w, top + 10.0), colour, 12.0, "center");
    }
}

/// Each mean's angle to the truth as a bar, degrees, its value at its end.
pub fn draw_means(pen: &Pen, model: &Model, (width, height): (f64, f64)) {
    let s = pen.text_scale();
    let errors: Vec<f64> = model.errors().iter().map(|e| e.to_degrees()).collect();
    let largest = errors.iter().fold(1.0_f64, |m, &e| m.max(e));
    let names = STYLES.iter().map(|st| pen.text_width(st.name, 11.0));
    let label = names.fold(0.0_f64, f64::max) + 12.0;
    let left = label.min(0.45 * width);
    let top = 26.0 * s;
    let value = pen.text_width("88.88°", 11.0) + 10.0;
    let span = (width - left - value).max(10.0);
    let row = ((height - top - 8.0) / STYLES.len() as f64).max(1.0);
    pen.text("Each mean's angle to the truth", (4.0, 12.0 * s), INK, 12.5, "left");
    pen.line((left, top), (left, top + row * STYLES.len() as f64), GRID, 1.0, &[]);
    for (i, (style, &e)) in STYLES.iter().zip(&errors).enumerate() {
        let y = top + (i as f64 + 0.5) * row;
        let bar = (0.7 * row).min(22.0);
        let length = span * e / largest;
        let corners = [
            (left, y - 0.5 * bar),
            (left + length, y - 0.5 * bar),
            (left + length, y + 0.5 * bar),
            (left, y + 0.5 * bar),
        ];
        pen.fill_polygon(&corners, style.colour, None);
        pen.text(style.name, (left - 6.0, y), INK, 11.0, "right");
        pen.text(&format!("{}°", fixed(e, 2)), (left + length + 5.0, y), INK, 11.0, "left");
    }
}

/// The sweep: each mean's error against the outlier share, 0 to 0.5.
pub fn draw_sweep(pen: &Pen, size: (f64, f64), shares: &[f64], errors: &[f64], current: f64) {
    let curves = STYLES.map(|s| Curve { name: s.name, colour: s.colour });
    let title = "each mean's error against the outlier share";
    draw_error_sweep(pen, size, title, &curves, 0.5, (shares, errors), current);
}
