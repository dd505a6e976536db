//! The swarm on S² through the Hopf map: every oscillator a dot at `h(q_i)` (where it sends the
//! body x-axis), those behind the sphere faint; and a few oscillators as whole objects.

use glam::{DQuat, DVec3};

use crate::aircraft::Face;
use crate::camera::{Camera, Viewport};
use crate::legend::{Entry, Mark, draw_legend};
use crate::object_view::{draw_object, object_camera};
use crate::palette::{INK, KLI, MUTED, SLERP};
use crate::pen::Pen;
use crate::sphere_view::{View, draw_globe, draw_grid_back, draw_grid_front, grid};

/// The colours of the oscillators drawn as objects (and ringed on the sphere), in order.
pub const HIGHLIGHTS: [&str; 3] = [KLI, SLERP, INK];

/// Draws the sphere with a dot at each of `points` (Hopf images); the first few, drawn as
/// objects beside it, are ringed in [`HIGHLIGHTS`]' colours.
pub fn draw_swarm_sphere(pen: &Pen, viewport: &Viewport, camera: &Camera, points: &[DVec3]) {
    let view = View { pen, viewport, camera };
    let grid = grid();
    // Smaller dots for larger swarms, so 2,000 of them still show the shape.
    let r = if points.len() > 500 {
        1.6
    } else if points.len() > 100 {
        2.2
    } else {
        3.2
    };
    let (front, back): (Vec<DVec3>, Vec<DVec3>) = points.iter().partition(|&&p| view.in_front(p));
    draw_grid_back(&view, &grid);
    pen.dots(&back.iter().map(|&p| view.at(p)).collect::<Vec<_>>(), r, MUTED);
    pen.alpha(1.0);
    draw_globe(&view);
    draw_grid_front(&view, &grid);
    pen.dots(&front.iter().map(|&p| view.at(p)).collect::<Vec<_>>(), r, "#1864ab");
    for (&p, colour) in points.iter().zip(HIGHLIGHTS) {
        pen.alpha(if view.in_front(p) { 1.0 } else { 0.4 });
        pen.disc(view.at(p), r + 3.5, None, Some((colour, 2.0)));
    }
    pen.alpha(1.0);
    let entries = [
        Entry { mark: Mark::Disc(Some("#1864ab"), "#1864ab"), label: "an oscillator: h(q_i)" },
        Entry { mark: Mark::Disc(Some(MUTED), MUTED), label: "behind the sphere" },
        Entry { mark: Mark::Disc(Some("#ffffff"), KLI), label: "ringed: drawn as objects" },
    ];
    let note = Some("h(q) is where q sends the body's x-axis");
    draw_legend(pen, viewport, &entries, note);
}

/// The first oscillators as whole objects in a row, each labelled.
pub fn draw_swarm_objects(
    pen: &Pen,
    width: f64,
    height: f64,
    mesh: &[Face],
    objects: &[(DQuat, String)],
) {
    let camera = object_camera();
    let cell = width / objects.len().max(1) as f64;
    for (i, ((q, label), colour)) in objects.iter().zip(HIGHLIGHTS).enumerate() {
        let left = i as f64 * cell;
        let viewport = Viewport::fitting(left, 14.0, cell, height - 14.0, 1.6);
        draw_object(pen, &viewport, &camera, mesh, *q, false);
        pen.text(label, (left + 0.5 * cell, 10.0), colour, 12.0, "center");
    }
}
