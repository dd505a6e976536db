//! The Hopf curve on S² (the paper's Fig. 1): a shaded unit sphere with a light grid, the KLI and
//! SLERP curves, Table 1's moments as thick points, the start, the end and the current time.
//! What lies behind the sphere is drawn first and faintly, what lies in front last.

use glam::DVec3;

use crate::camera::{Camera, Viewport};
use crate::format::fixed;
use crate::legend::{Entry, Mark, TextBox, clear_place, draw_legend, text_box};
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
pub(crate) enum Side {
    Back,
    Front,
}

/// `(colour, width, dash)` of a line.
type Stroke<'a> = (&'a str, f64, &'a [f64]);

/// The sphere as seen: where a point of S² lands on the canvas, and which side it is on.
pub(crate) struct View<'a> {
    pub pen: &'a Pen<'a>,
    pub viewport: &'a Viewport,
    pub camera: &'a Camera,
}

impl View<'_> {
    pub fn at(&self, p: DVec3) -> (f64, f64) {
        self.viewport.pixel(self.camera.project(p))
    }

    pub fn in_front(&self, p: DVec3) -> bool {
        self.camera.project(p).depth >= 0.0
    }

    /// Draws the runs of `points` that lie on `side`.
    pub fn polyline_on(&self, points: &[DVec3], side: Side, (color, width, dash): Stroke) {
        let mut run: Vec<(f64, f64)> = Vec::new();
        for &p in points {
            let projected = self.camera.project(p);
            if (projected.depth >= 0.0) == (side == Side::Front) {
                run.push(self.viewport.pixel(projected));
            } else if !run.is_empty() {
                // End the run exactly on the rim so front and back halves meet.
                run.push(self.viewport.pixel(projected));
                self.pen.polyline(&run, color, width, dash);
                run.clear();
            }
        }
        self.pen.polyline(&run, color, width, dash);
    }
}

const SLERP_STROKE: Stroke = (SLERP, 1.5, &[5.0, 4.0]);

fn circle(f: impl Fn(f64) -> DVec3) -> Vec<DVec3> {
    (0..=96).map(|i| f(i as f64 / 96.0 * std::f64::consts::TAU)).collect()
}

/// The grid: latitudes every 30° and meridians every 30°.
pub(crate) fn grid() -> Vec<Vec<DVec3>> {
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
/// [`draw_sphere_cursor`] adds on top. Back to front: what lies behind, faintly; the globe; the
/// grid, axes and curves in front; Table 1's moments; the ends.
pub fn draw_sphere(pen: &Pen, viewport: &Viewport, camera: &Camera, scene: &Scene) {
    let view = View { pen, viewport, camera };
    let grid = grid();
    draw_back(&view, &grid, scene);
    draw_globe(&view);
    let mut labels = draw_front(&view, &grid, scene);
    draw_moments(&view, scene);
    draw_ends(&view, scene, &mut labels);
    draw_key(&view, !scene.moments().is_empty());
}

/// The legend, bottom left: which curve is which (they lie on one arc), the ends, the moments.
fn draw_key(view: &View, moments: bool) {
    let mut entries = vec![
        Entry { mark: Mark::Line(KLI, 3.5, &[]), label: "KLI" },
        Entry { mark: Mark::Line(SLERP, 1.5, &[5.0, 4.0]), label: "SLERP" },
        Entry { mark: Mark::Disc(Some("#ffffff"), INK), label: "h(p), the start" },
        Entry { mark: Mark::Disc(Some(INK), INK), label: "h(r), the end" },
    ];
    if moments {
        entries.push(Entry {
            mark: Mark::Disc(Some(KLI), KLI),
            label: "Table 1's times (the paper's)",
        });
    }
    let note = Some("KLI and SLERP: one arc, two speeds");
    draw_legend(view.pen, view.viewport, &entries, note);
}

/// The half of the grid behind the sphere, faint (alpha left at 0.35 for what follows).
pub(crate) fn draw_grid_back(view: &View, grid: &[Vec<DVec3>]) {
    view.pen.alpha(0.35);
    for line in grid {
        view.polyline_on(line, Side::Back, (GRID, 1.0, &[]));
    }
}

/// The half of the grid in front and the axes x, y, z, labelled; returns the labels' boxes, for
/// the labels placed after them to keep clear of.
pub(crate) fn draw_grid_front(view: &View, grid: &[Vec<DVec3>]) -> Vec<TextBox> {
    for line in grid {
        view.polyline_on(line, Side::Front, ("#c3ccd5", 1.0, &[]));
    }
    let mut boxes = Vec::with_capacity(3);
    for (axis, color, label) in
        [(DVec3::X, AXIS_X, "x"), (DVec3::Y, AXIS_Y, "y"), (DVec3::Z, AXIS_Z, "z")]
    {
        view.pen.alpha(if view.in_front(axis) { 1.0 } else { 0.35 });
        view.pen.line(view.at(axis * 0.94), view.at(axis * 1.1), color, 2.0, &[]);
        let at = view.at(axis * 1.2);
        view.pen.text(label, at, color, 13.0, "center");
        boxes.push(text_box(view.pen, label, at, 13.0));
    }
    view.pen.alpha(1.0);
    boxes
}

fn draw_back(view: &View, grid: &[Vec<DVec3>], scene: &Scene) {
    draw_grid_back(view, grid);
    view.polyline_on(scene.slerp_curve(), Side::Back, SLERP_STROKE);
    view.polyline_on(scene.kli_curve(), Side::Back, (KLI, 3.0, &[]));
    view.pen.alpha(1.0);
}

/// The sphere itself, translucent enough to show what lies behind.
pub(crate) fn draw_globe(view: &View) {
    let centre = view.at(DVec3::ZERO);
    view.pen.alpha(0.82);
    view.pen.shaded_disc(centre, view.viewport.scale, "#ffffff", "#bac8d3");
    view.pen.alpha(1.0);
    view.pen.disc(centre, view.viewport.scale, None, Some(("#adb5bd", 1.0)));
}

/// The front half; returns the axis labels' boxes.
fn draw_front(view: &View, grid: &[Vec<DVec3>], scene: &Scene) -> Vec<TextBox> {
    let labels = draw_grid_front(view, grid);
    view.polyline_on(scene.kli_curve(), Side::Front, (KLI, 3.5, &[]));
    view.polyline_on(scene.slerp_curve(), Side::Front, SLERP_STROKE);
    labels
}

/// Table 1's moments on both curves, fainter behind the sphere.
fn draw_moments(view: &View, scene: &Scene) {
    for m in scene.moments() {
        let (k, s) = (hopf(scene.integrated_at(m)), hopf(scene.slerp_at(m)));
        view.pen.alpha(if view.in_front(s) { 1.0 } else { 0.4 });
        view.pen.disc(view.at(s), 3.5, Some("#ffffff"), Some((SLERP, 1.5)));
        view.pen.alpha(if view.in_front(k) { 1.0 } else { 0.4 });
        view.pen.disc(view.at(k), 5.5, Some(KLI), Some(("#ffffff", 1.0)));
    }
    view.pen.alpha(1.0);
}

/// The ends, labelled away from the sphere's centre (off the curves and the markers that move
/// along them) where that is clear of the labels already drawn (`labels`).
fn draw_ends(view: &View, scene: &Scene, labels: &mut Vec<TextBox>) {
    let (start, end) =
        (view.at(hopf(scene.path().arc().start())), view.at(hopf(scene.path().target())));
    let centre = view.at(DVec3::ZERO);
    let start_mark = view.pen.disc(start, 6.0, Some("#ffffff"), Some((INK, 2.0)));
    let end_mark = view.pen.disc(end, 6.0, Some(INK), Some(("#ffffff", 1.5)));
    for (text, point, mark) in [("h(p)", start, start_mark), ("h(r)", end, end_mark)] {
        let at = clear_place(view.pen, text, (point, centre), mark, 18.0, 12.0, labels);
        view.pen.text(text, at, INK, 12.0, "center");
    }
}

/// The KLI and SLERP points at time `t`, over [`draw_sphere`]'s drawing.
pub fn draw_sphere_cursor(pen: &Pen, viewport: &Viewport, camera: &Camera, scene: &Scene, t: f64) {
    let view = View { pen, viewport, camera };
    pen.disc(view.at(hopf(scene.slerp_at(t))), 7.0, None, Some((SLERP, 2.5)));
    pen.disc(view.at(hopf(scene.integrated_at(t))), 7.5, Some(KLI), Some((INK, 2.0)));
    pen.text(
        &format!("t = {}", fixed(t, 2)),
        (viewport.left + 8.0, viewport.top + 12.0),
        MUTED,
        12.0,
        "left",
    );
}

/// The sphere views' default camera, `[azimuth, elevation]` in radians (see
/// [`crate::default_camera`]).
pub fn default_angles() -> [f64; 2] {
    let d = sphere_camera().toward_viewer();
    [d.y.atan2(d.x), d.z.asin()]
}
