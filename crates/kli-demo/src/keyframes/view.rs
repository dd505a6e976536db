//! The keyframes page's pictures of its curves: the object under each curve, and the three Hopf
//! curves through the keys on the sphere.

use glam::DVec3;
use kli::hopf::hopf;

use super::model::{Model, STYLES};
use crate::aircraft::Face;
use crate::camera::Viewport;
use crate::figure::{Frame, Layer};
use crate::legend::{Entry, Mark, draw_legend, grouped_labels, wrapped};
use crate::object_view::{draw_object, object_camera};
use crate::palette::{INK, MUTED};
use crate::pen::Pen;
use crate::sphere_view::{Side, View, draw_globe, draw_grid_back, draw_grid_front, grid};

/// The object under each curve at `t`, side by side (or stacked on a tall figure).
pub fn draw_objects(pen: &Pen, model: &Model, mesh: &[Face], (width, height): (f64, f64), t: f64) {
    let camera = object_camera();
    let wide = width >= height;
    let (w, h) = if wide { (width / 3.0, height) } else { (width, height / 3.0) };
    for (i, (curve, style)) in model.curves().iter().zip(&STYLES).enumerate() {
        let (left, top) = if wide { (i as f64 * w, 0.0) } else { (0.0, i as f64 * h) };
        let viewport = Viewport::fitting(left, top + 14.0, w, h - 14.0, 1.6);
        draw_object(pen, &viewport, &camera, mesh, curve.at(t), false);
        pen.text(style.name, (left + 0.5 * w, top + 10.0), style.colour, 12.0, "center");
    }
}

/// The curves and the keys (the still part), and each curve's point at the frame's time (the
/// moving part).
pub fn draw_sphere(pen: &Pen, model: &Model, frame: &Frame, layer: Layer) {
    let viewport = frame.sphere_viewport();
    let view = View { pen, viewport: &viewport, camera: &frame.camera };
    if layer.still() {
        draw_curves(&view, model);
    }
    if layer != Layer::Still {
        for (curve, style) in model.curves().iter().zip(&STYLES) {
            let point = view.at(hopf(curve.at(frame.t)));
            pen.disc(point, 5.0, Some(style.colour), Some(("#ffffff", 1.5)));
        }
    }
}

fn draw_curves(view: &View, model: &Model) {
    let pen = view.pen;
    let grid = grid();
    draw_grid_back(view, &grid);
    for (s, style) in model.series.iter().zip(&STYLES) {
        view.polyline_on(&s.hopf, Side::Back, (style.colour, 2.0, style.dash));
    }
    pen.alpha(1.0);
    draw_globe(view);
    let axis_labels = draw_grid_front(view, &grid);
    for (s, style) in model.series.iter().zip(&STYLES) {
        view.polyline_on(&s.hopf, Side::Front, (style.colour, 2.5, style.dash));
    }
    let points: Vec<DVec3> = model.keys.quaternions().iter().map(|&k| hopf(k)).collect();
    for &p in &points {
        pen.alpha(if view.in_front(p) { 1.0 } else { 0.4 });
        pen.disc(view.at(p), 5.5, Some("#ffffff"), Some((INK, 2.0)));
    }
    pen.alpha(1.0);
    // Keys whose points coincide (a turn about the body's x-axis) share one label.
    let pixels: Vec<(f64, f64)> = points.iter().map(|&p| view.at(p)).collect();
    let names: Vec<String> = (0..points.len()).map(|i| format!("k{i}")).collect();
    for (label, (x, y)) in grouped_labels(&pixels, &names, 14.0) {
        pen.text(&label, (x + 9.0, y - 9.0), INK, 11.0, "left");
    }
    let mut entries: Vec<Entry> = STYLES
        .iter()
        .map(|s| Entry { mark: Mark::Line(s.colour, 2.5, s.dash), label: s.name })
        .collect();
    entries.push(Entry { mark: Mark::Disc(Some("#ffffff"), INK), label: "k0, k1, …: the keys" });
    draw_legend(pen, view.viewport, &entries, None);
    // In the top left corner, outside the sphere, in lines that stop short of the axis labels
    // along the top (the z label, with the default camera).
    if let Some(i) = model.hidden_turn() {
        let note = format!("k{i} → k{}: turns about the body's x-axis: not seen here", i + 1);
        let v = view.viewport;
        let (left, line) = (v.left + 8.0, 14.0 * pen.text_scale());
        let top_labels = axis_labels.iter().filter(|b| b[1] < v.top + 4.0 * line && b[2] > left);
        let width =
            top_labels.fold(v.left + v.width - 8.0, |right, b| right.min(b[0] - 6.0)) - left;
        for (k, text) in wrapped(pen, &note, 11.0, width.max(60.0)).iter().enumerate() {
            pen.text(text, (left, v.top + 12.0 + k as f64 * line), MUTED, 11.0, "left");
        }
    }
}
