//! The Hopf curve on S² (the paper's Fig. 1): a shaded unit sphere with a light grid, the KLI and
//! SLERP curves, Table 1's moments as thick points, the start, the end and the current time.
//! What lies behind the sphere is drawn first and faintly, what lies in front last.

use glam::DVec3;

use crate::camera::{Camera, Viewport};
use crate::format::fixed;
use crate::palette::{AXIS_X, AXIS_Y, AXIS_Z, GRID, INK, KLI, MUTED, SLERP};
use crate::pen::Pen;
use crate::scene::Scene;
use kli::hopf::hopf;

/// The default view of the sphere: both ends of the paper's curve in front.
pub fn sphere_camera() -> Camera {
    Camera::orbit(135f64.to_radians(), 25f64.to_radians())
}

/// Which half of the sphere a pass draws.
#[derive(Clone, Copy, PartialEq)]
enum Side {
    Back,
    Front,
}

/// Draws the runs of `points` that lie on `side`.
/// `(colour, width, dash)` of a line.
type Stroke<'a> = (&'a str, f64, &'a [f64]);

fn polyline_on(
    pen: &Pen,
    viewport: &Viewport,
    camera: &Camera,
    points: &[DVec3],
    side: Side,
    (color, width, dash): Stroke,
) {
    let mut run: Vec<(f64, f64)> = Vec::new();
    for &p in points {
        let projected = camera.project(p);
        if (projected.depth >= 0.0) == (side == Side::Front) {
            run.push(viewport.pixel(projected));
        } else if !run.is_empty() {
            // End the run exactly on the rim so front and back halves meet.
            run.push(viewport.pixel(projected));
            pen.polyline(&run, color, width, dash);
            run.clear();
        }
    }
    pen.polyline(&run, color, width, dash);
}

fn circle(f: impl Fn(f64) -> DVec3) -> Vec<DVec3> {
    (0..=96).map(|i| f(i as f64 / 96.0 * std::f64::consts::TAU)).collect()
}

/// The grid: latitudes every 30° and meridians every 30°.
fn grid() -> Vec<Vec<DVec3>> {
    let mut lines = Vec::new();
    for lat in [-60.0_f64, -30.0, 0.0, 30.0, 60.0] {
        let (s, c) = lat.to_radians().sin_cos();
        lines.push(circle(|a| DVec3::new(c * a.cos(), c * a.sin(), s)));
    }
    for lon in (0..6).map(|i| (i as f64 * 30.0).to_radians()) {
        lines.push(circle(|a| DVec3::new(a.cos() * lon.cos(), a.cos() * lon.sin(), a.sin())));
    }
    lines
}

/// Draws the sphere view of `scene` into `viewport`: everything but the current time, which
/// [`draw_sphere_cursor`] adds on top.
pub fn draw_sphere(pen: &Pen, viewport: &Viewport, camera: &Camera, scene: &Scene) {
    let grid = grid();
    let moments = scene.moments();
    let kli_moments: Vec<DVec3> = moments.iter().map(|&m| hopf(scene.integrated_at(m))).collect();
    let slerp_moments: Vec<DVec3> = moments.iter().map(|&m| hopf(scene.slerp_at(m))).collect();
    let start = hopf(scene.path().arc().start());
    let end = hopf(scene.path().target());
    let at = |p: DVec3| viewport.pixel(camera.project(p));
    let in_front = |p: DVec3| camera.project(p).depth >= 0.0;

    // Behind the sphere, faint.
    pen.alpha(0.35);
    for line in &grid {
        polyline_on(pen, viewport, camera, line, Side::Back, (GRID, 1.0, &[]));
    }
    polyline_on(pen, viewport, camera, scene.slerp_curve(), Side::Back, (SLERP, 1.5, &[5.0, 4.0]));
    polyline_on(pen, viewport, camera, scene.kli_curve(), Side::Back, (KLI, 3.0, &[]));
    pen.alpha(1.0);

    // The sphere itself, translucent enough to show what lies behind.
    let centre = at(DVec3::ZERO);
    pen.alpha(0.82);
    pen.shaded_disc(centre, viewport.scale, "#ffffff", "#bac8d3");
    pen.alpha(1.0);
    pen.disc(centre, viewport.scale, None, Some(("#adb5bd", 1.0)));

    // In front.
    for line in &grid {
        polyline_on(pen, viewport, camera, line, Side::Front, ("#c3ccd5", 1.0, &[]));
    }
    for (axis, color, label) in
        [(DVec3::X, AXIS_X, "x"), (DVec3::Y, AXIS_Y, "y"), (DVec3::Z, AXIS_Z, "z")]
    {
        let alpha = if in_front(axis) { 1.0 } else { 0.35 };
        pen.alpha(alpha);
        pen.line(at(axis * 0.94), at(axis * 1.1), color, 2.0, &[]);
        pen.text(label, at(axis * 1.2), color, 13.0, "center");
    }
    pen.alpha(1.0);
    polyline_on(pen, viewport, camera, scene.kli_curve(), Side::Front, (KLI, 3.5, &[]));
    polyline_on(pen, viewport, camera, scene.slerp_curve(), Side::Front, (SLERP, 1.5, &[5.0, 4.0]));

    for (&k, &s) in kli_moments.iter().zip(&slerp_moments) {
        pen.alpha(if in_front(s) { 1.0 } else { 0.4 });
        pen.disc(at(s), 3.5, Some("#ffffff"), Some((SLERP, 1.5)));
        pen.alpha(if in_front(k) { 1.0 } else { 0.4 });
        pen.disc(at(k), 5.5, Some(KLI), Some(("#ffffff", 1.0)));
    }
    pen.alpha(1.0);
    pen.disc(at(start), 6.0, Some("#ffffff"), Some((INK, 2.0)));
    pen.text("h(p)", offset(at(start), 0.0, -14.0), INK, 12.0, "center");
    pen.disc(at(end), 6.0, Some(INK), Some(("#ffffff", 1.5)));
    pen.text("h(r)", offset(at(end), 0.0, -14.0), INK, 12.0, "center");
}

/// The KLI and SLERP points at time `t`, over [`draw_sphere`]'s drawing.
pub fn draw_sphere_cursor(pen: &Pen, viewport: &Viewport, camera: &Camera, scene: &Scene, t: f64) {
    let at = |p: DVec3| viewport.pixel(camera.project(p));
    pen.disc(at(hopf(scene.slerp_at(t))), 7.0, None, Some((SLERP, 2.5)));
    pen.disc(at(hopf(scene.integrated_at(t))), 7.5, Some(KLI), Some((INK, 2.0)));
    pen.text(
        &format!("t = {}", fixed(t, 2)),
        (viewport.left + 8.0, viewport.top + 12.0),
        MUTED,
        12.0,
        "left",
    );
}

fn offset((x, y): (f64, f64), dx: f64, dy: f64) -> (f64, f64) {
    (x + dx, y + dy)
}
