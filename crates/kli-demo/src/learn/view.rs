//! The tour's pictures, one function a view, all through the one [`Pen`]: the object
//! ([`draw_object`]), the sphere S² ([`crate::sphere_view`]'s globe and grid), plots
//! ([`Panel`]: the turning rate of section 9 too), and a plane of R⁴ cut through S³ (a great circle, drawn as a circle).

use glam::{DQuat, DVec3};
use kli::{Integrator, hopf};

use super::model::{
    END, Model, SAMPLE, in_plane, lock_angle, nlerp, order, paper_p, paper_r, plane, slerp,
};
use super::words::{Words, fill};
use crate::aircraft::Face;
use crate::camera::Viewport;
use crate::figure::Frame;
use crate::format::{exponential, fixed};
use crate::legend::{
    Entry, Mark, TextBox, clear_place, draw_legend_row, draw_plot_key, legend_row_width, text_box,
};
use crate::object_view::{draw_object, object_camera};
use crate::palette::{AXIS_X, AXIS_Y, AXIS_Z, GRID, INK, KLI, MUTED, SLERP};
use crate::pen::Pen;
use crate::plots::{Panel, inset, trim};
use crate::sphere_view::{Side, View, draw_globe, draw_grid_back, draw_grid_front, grid};
use crate::ticks::{decades, nice_step};

/// A rectangle `(left, top, width, height)`, CSS pixels.
type Rect = (f64, f64, f64, f64);

/// A line of text at the top left of `rect`.
fn caption(pen: &Pen, rect: Rect, text: &str) {
    pen.text(text, (rect.0 + 8.0, rect.1 + 14.0 * pen.text_scale()), INK, 12.5, "left");
}

/// A line of text at the bottom left of the view (clear of a sphere's z label).
fn footnote(pen: &Pen, frame: &Frame, text: &str) {
    pen.text(text, (8.0, frame.height - 10.0), INK, 12.5, "left");
}

/// An arrow from `from` to `to`, with a head.
fn arrow(pen: &Pen, from: (f64, f64), to: (f64, f64), color: &str, width: f64) {
    pen.line(from, to, color, width, &[]);
    let (dx, dy) = (to.0 - from.0, to.1 - from.1);
    let length = (dx * dx + dy * dy).sqrt();
    if length < 1.0 {
        return;
    }
    let (ux, uy) = (dx / length, dy / length);
    let size = (3.5 * width).max(8.0).min(length);
    let back = (to.0 - ux * size, to.1 - uy * size);
    let side = (-uy * size * 0.45, ux * size * 0.45);
    let head = [to, (back.0 + side.0, back.1 + side.1), (back.0 - side.0, back.1 - side.1)];
    pen.fill_polygon(&head, color, Some(color));
}

/// The object turned by `q` in `rect`, seen from the object views' camera.
fn object(pen: &Pen, rect: Rect, mesh: &[Face], q: DQuat, axes: bool) -> Viewport {
    let viewport = Viewport::fitting(rect.0, rect.1, rect.2, rect.3, 1.75);
    draw_object(pen, &viewport, &object_camera(), mesh, q, axes);
    viewport
}

/// `rect` less a line of text above and below: where a figure with a caption and a footnote
/// draws its object.
fn between_lines(pen: &Pen, (left, top, width, height): Rect) -> Rect {
    let line = 22.0 * pen.text_scale();
    (left, top + line, width, (height - 2.0 * line).max(10.0))
}

/// Section 1: the object turned by yaw, pitch and bank, with the three gimbal axes; the yaw and
/// bank axes meet at pitch ±90°.
pub fn draw_euler(pen: &Pen, model: &Model, mesh: &[Face], frame: &Frame) {
    let o = &model.options;
    let rect = (0.0, 0.0, frame.width, frame.height);
    let q = super::model::euler(o.yaw, o.pitch, o.bank);
    let viewport = object(pen, between_lines(pen, rect), mesh, q, false);
    let camera = object_camera();
    let at = |v: DVec3| viewport.pixel(camera.project(v));
    let axes = super::model::gimbal_axes(o.yaw, o.pitch);
    let words = &o.words;
    for (axis, color, label) in [
        (axes[0], AXIS_Z, words.yaw.as_str()),
        (axes[1], AXIS_Y, words.pitch.as_str()),
        (axes[2], AXIS_X, words.bank.as_str()),
    ] {
        pen.line(at(-axis * 1.45), at(axis * 1.45), color, 2.0, &[6.0, 4.0]);
        pen.text(label, at(axis * 1.6), color, 12.0, "center");
    }
    let apart = lock_angle(o.pitch);
    let text = if apart < 0.05 {
        words.locked.clone()
    } else {
        fill(&words.apart, &[("angle", fixed(apart, 1).as_str())])
    };
    caption(pen, rect, &text);
}

/// Section 2: the object turned by the axis and angle, the axis drawn through it.
pub fn draw_turn(pen: &Pen, model: &Model, mesh: &[Face], frame: &Frame) {
    let rect = (0.0, 0.0, frame.width, frame.height);
    let q = model.turn();
    let viewport = object(pen, between_lines(pen, rect), mesh, q, true);
    let camera = object_camera();
    let axis = model.options.axis.vector();
    let at = |v: DVec3| viewport.pixel(camera.project(v));
    pen.line(at(-axis * 1.6), at(axis * 1.6), INK, 1.5, &[3.0, 3.0]);
    let o = &model.options;
    pen.text(&o.words.axis, at(-axis * 1.72), INK, 12.0, "center");
    let name = if o.axis == super::model::Axis::Diagonal {
        o.words.diagonal.as_str()
    } else {
        o.axis.name()
    };
    caption(pen, rect, &fill(&o.words.about, &[("angle", trim(o.angle).as_str()), ("axis", name)]));
    let line = format!("q = {}", quaternion_text(q));
    pen.text(&line, (8.0, frame.height - 10.0), MUTED, 12.0, "left");
}

/// `w + x i + y j + z k` to three decimals.
pub fn quaternion_text(q: DQuat) -> String {
    let part = |x: f64, unit: &str| {
        let sign = if x < 0.0 { "−" } else { "+" };
        format!(" {sign} {}{unit}", fixed(x.abs(), 3))
    };
    let w = if q.w < 0.0 { format!("−{}", fixed(-q.w, 3)) } else { fixed(q.w, 3) };
    format!("{w}{}{}{}", part(q.x, "i"), part(q.y, "j"), part(q.z, "k"))
}

/// A circle of radius `radius` around `centre`, and where the plane's point `(a, b)` lands.
struct Plane {
    centre: (f64, f64),
    radius: f64,
}

impl Plane {
    /// The largest circle in `rect` with room for its labels, below a caption's line.
    fn in_rect((left, top, width, height): Rect, text: f64) -> Plane {
        let (margin, caption) = (34.0 * text, 22.0 * text);
        let radius = ((width.min(height - caption) - 2.0 * margin) / 2.0).max(8.0);
        Plane { centre: (left + width / 2.0, top + caption + (height - caption) / 2.0), radius }
    }

    fn at(&self, angle: f64, length: f64) -> (f64, f64) {
        let (s, c) = angle.sin_cos();
        (self.centre.0 + self.radius * length * c, self.centre.1 - self.radius * length * s)
    }

    fn circle(&self, pen: &Pen) {
        let points: Vec<(f64, f64)> =
            (0..=120).map(|k| self.at(k as f64 / 120.0 * std::f64::consts::TAU, 1.0)).collect();
        pen.polyline(&points, GRID, 2.0, &[]);
        pen.line(self.at(std::f64::consts::PI, 1.1), self.at(0.0, 1.1), GRID, 1.0, &[]);
        let half = std::f64::consts::FRAC_PI_2;
        pen.line(self.at(-half, 1.1), self.at(half, 1.1), GRID, 1.0, &[]);
    }

    fn arc(&self, pen: &Pen, from: f64, to: f64, color: &str, width: f64, dash: &[f64]) {
        let n = ((to - from).abs() / 0.03).ceil().max(2.0) as usize;
        let points: Vec<(f64, f64)> =
            (0..=n).map(|k| self.at(from + (to - from) * k as f64 / n as f64, 1.0)).collect();
        pen.polyline(&points, color, width, dash);
    }

    fn label(&self, pen: &Pen, text: &str, angle: f64, length: f64, color: &str) {
        pen.text(text, self.at(angle, length), color, 12.5, "center");
    }

    /// The label of the circle's point at `angle` (its mark reaching `mark` from it), outside the
    /// circle and clear of the labels `taken` (which it joins).
    fn clear_label(
        &self,
        pen: &Pen,
        text: &str,
        (angle, mark): (f64, f64),
        color: &str,
        taken: &mut Vec<TextBox>,
    ) {
        let at =
            clear_place(pen, text, (self.at(angle, 1.0), self.centre), mark, 24.0, 12.5, taken);
        pen.text(text, at, color, 12.5, "center");
    }
}

/// Section 3: the great circle of S³ through `1` and the axis `u`, with `q = cos(θ/2) + u
/// sin(θ/2)` and `−q` on it, and the object turned by each: the same picture.
pub fn draw_cover(pen: &Pen, model: &Model, mesh: &[Face], frame: &Frame) {
    let (w, h) = (frame.width, frame.height);
    let wide = w >= 1.3 * h;
    let (circle, objects) = if wide {
        ((0.0, 0.0, w * 0.55, h), (w * 0.55, 0.0, w * 0.45, h))
    } else {
        ((0.0, 0.0, w, h * 0.62), (0.0, h * 0.62, w, h * 0.38))
    };
    let plane = Plane::in_rect(circle, pen.text_scale());
    plane.circle(pen);
    let half = 0.5 * model.options.angle.to_radians();
    let pi = std::f64::consts::PI;
    plane.arc(pen, 0.0, half, KLI, 3.5, &[]);
    plane.label(pen, "1", 0.0, 1.22, INK);
    plane.label(pen, "−1", pi, 1.22, INK);
    let mut taken: Vec<TextBox> = [("1", 0.0), ("−1", pi)]
        .iter()
        .map(|&(text, angle)| text_box(pen, text, plane.at(angle, 1.22), 12.5))
        .collect();
    let unit = match model.options.axis {
        super::model::Axis::X => "i",
        super::model::Axis::Y => "j",
        super::model::Axis::Z => "k",
        super::model::Axis::Diagonal => "u",
    };
    plane.label(pen, unit, pi / 2.0, 1.22, INK);
    taken.push(text_box(pen, unit, plane.at(pi / 2.0, 1.22), 12.5));
    let minus = pen.disc(plane.at(half + pi, 1.0), 6.5, Some("#ffffff"), Some((KLI, 2.5)));
    let plus = pen.disc(plane.at(half, 1.0), 7.0, Some(KLI), Some((INK, 1.5)));
    plane.clear_label(pen, "q", (half, plus), KLI, &mut taken);
    plane.clear_label(pen, "−q", (half + pi, minus), KLI, &mut taken);
    let q = model.turn();
    let (a, b) = if wide {
        ((objects.0, 0.0, objects.2, h / 2.0), (objects.0, h / 2.0, objects.2, h / 2.0))
    } else {
        ((0.0, objects.1, w / 2.0, objects.3), (w / 2.0, objects.1, w / 2.0, objects.3))
    };
    object(pen, a, mesh, q, true);
    object(pen, b, mesh, -q, true);
    let o = &model.options;
    pen.text(&o.words.turned_by, (a.0 + a.2 / 2.0, a.1 + a.3 - 6.0), MUTED, 12.0, "center");
    pen.text(&o.words.turned_by_minus, (b.0 + b.2 / 2.0, b.1 + b.3 - 6.0), MUTED, 12.0, "center");
    let (angle, half) = (trim(o.angle), trim(o.angle / 2.0));
    caption(
        pen,
        circle,
        &fill(&o.words.circle, &[("angle", angle.as_str()), ("half", half.as_str())]),
    );
}

/// Section 4: the paper's `p` and `r` on their great circle, SLERP's point (even steps) and
/// NLERP's (the chord's point pushed back), their steps of 0.1 marked.
pub fn draw_slerp(pen: &Pen, model: &Model, frame: &Frame) {
    let rect = (0.0, 0.0, frame.width, frame.height);
    let (p, r) = (paper_p(), paper_r());
    let Some(basis) = plane(p, r) else { return };
    let text = pen.text_scale();
    let mut plane = Plane::in_rect(rect, text);
    // The arc spans 60°: show the quarter it lies in, larger.
    plane.radius = (frame.height - 70.0 * text).min(frame.width * 0.8).max(20.0);
    plane.centre = (frame.width * 0.5 - plane.radius * 0.45, frame.height - 26.0 * text);
    let end = in_plane(r, basis);
    plane.arc(pen, -0.1, end + 0.35, GRID, 2.0, &[]);
    pen.line(plane.at(0.0, 1.0), plane.at(end, 1.0), GRID, 1.0, &[4.0, 3.0]);
    plane.arc(pen, 0.0, end, SLERP, 3.0, &[]);
    pen.line(plane.centre, plane.at(0.0, 1.08), GRID, 1.0, &[]);
    pen.line(plane.centre, plane.at(end, 1.08), GRID, 1.0, &[]);
    for k in 0..=10 {
        let s = k as f64 / 10.0;
        let (a, b) = (in_plane(slerp(p, r, s), basis), in_plane(nlerp(p, r, s), basis));
        pen.line(plane.at(a, 1.0), plane.at(a, 1.06), SLERP, 1.5, &[]);
        pen.line(plane.at(b, 0.94), plane.at(b, 1.0), KLI, 1.5, &[]);
    }
    let s = model.options.s;
    let (a, b) = (in_plane(slerp(p, r, s), basis), in_plane(nlerp(p, r, s), basis));
    pen.disc(plane.at(b, 1.0), 6.0, Some("#ffffff"), Some((KLI, 2.5)));
    pen.disc(plane.at(a, 1.0), 6.5, Some(SLERP), Some((INK, 1.5)));
    plane.label(pen, "p", 0.0, 1.13, INK);
    plane.label(pen, "r", end, 1.13, INK);
    let (s, a, b) = (fixed(s, 2), fixed(a.to_degrees(), 1), fixed(b.to_degrees(), 1));
    let values = [("s", s.as_str()), ("slerp", a.as_str()), ("nlerp", b.as_str())];
    caption(pen, rect, &fill(&model.options.words.slerp, &values));
    let entries = [
        Entry { mark: Mark::Disc(Some(SLERP), INK), label: "SLERP" },
        Entry { mark: Mark::Disc(Some("#ffffff"), KLI), label: "NLERP" },
    ];
    let y = frame.height - 10.0;
    let x = frame.width - 8.0;
    draw_legend_row(pen, (x, y), &entries);
}

/// The sphere S² with its grid, seen from the frame's camera, in `viewport`; returns how to
/// place a point, and the axis labels' boxes (for the labels placed after them to keep clear of).
fn globe<'a>(
    pen: &'a Pen<'a>,
    viewport: &'a Viewport,
    frame: &'a Frame,
) -> (View<'a>, Vec<TextBox>) {
    let view = View { pen, viewport, camera: &frame.camera };
    let lines = grid();
    draw_grid_back(&view, &lines);
    pen.alpha(1.0);
    draw_globe(&view);
    let labels = draw_grid_front(&view, &lines);
    (view, labels)
}

/// Section 5: where the nose points, `h(q)` (paper eq. 5), and where a wing points, `q j q̄`,
/// on the circle of directions square to the nose: the roll moves the wing and not the dot.
pub fn draw_hopf(pen: &Pen, model: &Model, frame: &Frame) {
    let viewport = frame.sphere_viewport();
    let (view, mut labels) = globe(pen, &viewport, frame);
    let q = model.rolled();
    let nose = hopf(q);
    let wing = q * DVec3::Y;
    let across = nose.cross(wing);
    let ring: Vec<DVec3> = (0..=96)
        .map(|k| {
            let (s, c) = (k as f64 / 96.0 * std::f64::consts::TAU).sin_cos();
            wing * c + across * s
        })
        .collect();
    view.polyline_on(&ring, Side::Back, (AXIS_Y, 1.0, &[4.0, 3.0]));
    view.polyline_on(&ring, Side::Front, (AXIS_Y, 1.5, &[4.0, 3.0]));
    let words = &model.options.words;
    for (point, fill, ring, label) in
        [(wing, "#ffffff", AXIS_Y, words.wing.as_str()), (nose, KLI, INK, words.nose.as_str())]
    {
        pen.alpha(if view.in_front(point) { 1.0 } else { 0.45 });
        let at = view.at(point);
        let mark = pen.disc(at, 7.0, Some(fill), Some((ring, 2.0)));
        let place =
            clear_place(pen, label, (at, view.at(DVec3::ZERO)), mark, 18.0, 12.0, &mut labels);
        pen.text(label, place, INK, 12.0, "center");
    }
    pen.alpha(1.0);
    footnote(pen, frame, &format!("h(q) = ({})", vector_text(nose)));
}

/// `x, y, z` to three decimals.
pub fn vector_text(v: DVec3) -> String {
    let c = |x: f64| if x.abs() < 5e-4 { fixed(0.0, 3) } else { fixed(x, 3).replace('-', "−") };
    format!("{}, {}, {}", c(v.x), c(v.y), c(v.z))
}

/// Section 5, beside the sphere: the object turned and rolled.
pub fn draw_rolled(pen: &Pen, model: &Model, mesh: &[Face], frame: &Frame) {
    let rect = (0.0, 0.0, frame.width, frame.height);
    object(pen, between_lines(pen, rect), mesh, model.rolled(), true);
    let angle = trim(model.options.roll);
    caption(pen, rect, &fill(&model.options.words.rolled, &[("angle", angle.as_str())]));
}

/// Section 6: the phases on the circle at `t`, coloured by natural frequency, the order parameter
/// as an arrow; beside them, `R(t)` from 0 to the clock's end.
pub fn draw_phases(pen: &Pen, model: &Model, frame: &Frame) {
    let (w, h) = (frame.width, frame.height);
    let text = pen.text_scale();
    let wide = w >= 1.4 * h;
    let (left, right) = if wide {
        ((0.0, 0.0, w * 0.42, h), (w * 0.42, 0.0, w * 0.58, h))
    } else {
        ((0.0, 0.0, w, h * 0.58), (0.0, h * 0.58, w, h * 0.42))
    };
    let plane = Plane::in_rect(left, text);
    plane.circle(pen);
    let phases = &model.phases;
    let theta = phases.at(frame.t);
    for (&angle, &omega) in theta.iter().zip(&phases.omega) {
        let color = if omega < 0.0 { SLERP } else { KLI };
        pen.disc(plane.at(angle, 1.0), 5.5, Some(color), Some(("#ffffff", 1.0)));
    }
    let (r, psi) = order(theta);
    arrow(pen, plane.centre, plane.at(psi, r), INK, 2.5);
    caption(pen, left, &format!("t = {}   R = {}", fixed(frame.t, 2), fixed(r, 3)));
    let (l, t, pw, ph) = inset(right, text, 34.0);
    let panel = Panel::new((l, t, pw, ph), (0.0, model.end), (0.0, 1.0));
    let ticks: Vec<(f64, String)> = [0.0, 0.5, 1.0].iter().map(|&y| (y, trim(y))).collect();
    panel.frame_with(pen, &model.options.words.order, &ticks, "t");
    let times: Vec<f64> = (0..phases.samples.len()).map(|k| k as f64 * SAMPLE).collect();
    panel.series(pen, &times, phases.samples.iter().map(|s| order(s).0), INK, 2.0, &[]);
    let (x, y) = panel.at(frame.t, r);
    pen.line((x, panel.top), (x, panel.top + panel.height), MUTED, 1.0, &[3.0, 3.0]);
    pen.disc((x, y), 4.5, Some(INK), None);
}

/// Section 6, on S³: the followers' Hopf images with their trails to `t`, the pinned leader
/// `h(r)` as a star.
pub fn draw_lohe(pen: &Pen, model: &Model, frame: &Frame) {
    let viewport = frame.sphere_viewport();
    let (view, mut labels) = globe(pen, &viewport, frame);
    let swarm = &model.swarm;
    let last = ((frame.t.max(0.0) / SAMPLE).round() as usize).min(swarm.samples.len() - 1);
    let followers = swarm.samples[0].len();
    for i in 0..followers {
        let trail: Vec<DVec3> =
            swarm.samples[..=last].iter().step_by(3).map(|s| hopf(s[i])).collect();
        view.polyline_on(&trail, Side::Back, (SLERP, 1.0, &[]));
        view.polyline_on(&trail, Side::Front, (SLERP, 1.5, &[]));
    }
    for q in swarm.at(frame.t) {
        let point = hopf(*q);
        pen.alpha(if view.in_front(point) { 1.0 } else { 0.45 });
        pen.disc(view.at(point), 5.5, Some(SLERP), Some(("#ffffff", 1.0)));
    }
    let leader = hopf(swarm.leader);
    pen.alpha(if view.in_front(leader) { 1.0 } else { 0.45 });
    let mark = pen.disc(view.at(leader), 8.0, Some(KLI), Some((INK, 2.0)));
    let centre = view.at(DVec3::ZERO);
    let pinned = &model.options.words.pinned;
    let place = clear_place(pen, pinned, (view.at(leader), centre), mark, 20.0, 12.0, &mut labels);
    pen.text(pinned, place, INK, 12.0, "center");
    pen.alpha(1.0);
    let (t, widest) = (fixed(frame.t, 2), fixed(swarm.spread(frame.t), 1));
    footnote(
        pen,
        frame,
        &fill(&model.options.words.widest, &[("t", t.as_str()), ("angle", widest.as_str())]),
    );
}

/// Section 7: the great circle through `p` and `r`, `q(t)` on it, `r` split at `q` into its part
/// along `q`, `(q·r) q`, and the tangent part `r − (q·r) q`, which is `q′` (paper eq. 3).
pub fn draw_kli(pen: &Pen, model: &Model, frame: &Frame) {
    let rect = (0.0, 0.0, frame.width, frame.height);
    let (p, r) = (paper_p(), paper_r());
    let Some(basis) = plane(p, r) else { return };
    let mut plane = Plane::in_rect(rect, pen.text_scale());
    plane.centre.0 -= plane.radius * 0.2;
    plane.circle(pen);
    let end = in_plane(r, basis);
    plane.arc(pen, 0.0, end, SLERP, 1.5, &[5.0, 4.0]);
    let q = model.kli_at(frame.t);
    let a = in_plane(q, basis);
    plane.arc(pen, 0.0, a, KLI, 3.5, &[]);
    let dot = q.dot(r);
    // r from the centre, and its part along q.
    pen.line(plane.centre, plane.at(end, 1.0), MUTED, 1.0, &[]);
    pen.line(plane.centre, plane.at(a, dot), MUTED, 1.5, &[4.0, 3.0]);
    pen.line(plane.at(a, dot), plane.at(end, 1.0), GRID, 1.0, &[2.0, 2.0]);
    // The tangent part, drawn at q: (r − (q·r) q) has plane coordinates from `end` and `a`.
    let tangent = r - q * dot;
    let (tx, ty) = (tangent.dot(basis.0), tangent.dot(basis.1));
    let from = plane.at(a, 1.0);
    let to = (from.0 + plane.radius * tx, from.1 - plane.radius * ty);
    arrow(pen, from, to, KLI, 2.5);
    pen.disc(plane.at(0.0, 1.0), 6.0, Some("#ffffff"), Some((INK, 2.0)));
    pen.disc(plane.at(end, 1.0), 6.0, Some(INK), Some(("#ffffff", 1.5)));
    pen.disc(from, 7.0, Some(KLI), Some((INK, 1.5)));
    plane.label(pen, "p", 0.0, 1.16, INK);
    plane.label(pen, "r", end, 1.16, INK);
    plane.label(pen, "(q·r) q", a, dot * 0.5 - 0.12, MUTED);
    let phi = model.phi(frame.t);
    // Named while the arrow is long enough to see (φ > 10°: |q′| = sin φ); near r it shrinks
    // to nothing and its name would sit on r's.
    if phi > 10f64.to_radians() {
        pen.text("q′", (to.0 + 10.0, to.1 - 6.0), KLI, 13.0, "left");
    }
    caption(
        pen,
        rect,
        &format!(
            "t = {}   φ = {}°   |q′| = sin φ = {}",
            fixed(frame.t, 2),
            fixed(phi.to_degrees(), 2),
            fixed(phi.sin(), 4)
        ),
    );
}

/// Section 7, the clock: KLI's `s(t) = 1 − φ(t)/φ₀` against SLERP's steady `t/T`, `t` marked.
pub fn draw_clock(pen: &Pen, model: &Model, frame: &Frame) {
    let text = pen.text_scale();
    let (l, t, w, h) = inset((0.0, 0.0, frame.width, frame.height), text, 40.0);
    let panel = Panel::new((l, t, w, h), (0.0, model.end), (0.0, 1.0));
    let ticks: Vec<(f64, String)> = [0.0, 0.5, 1.0].iter().map(|&y| (y, trim(y))).collect();
    panel.frame_with(pen, &model.options.words.along, &ticks, "t");
    let times: Vec<f64> = (0..=240).map(|k| k as f64 / 240.0 * model.end).collect();
    let big_t = model.path.final_time();
    panel.series(pen, &times, times.iter().map(|&x| (x / big_t).min(1.0)), SLERP, 1.5, &[5.0, 4.0]);
    panel.series(pen, &times, times.iter().map(|&x| model.warp(x)), KLI, 3.0, &[]);
    let now = frame.t.clamp(0.0, model.end);
    let (x, y) = panel.at(now, model.warp(now));
    pen.line((x, panel.top), (x, panel.top + panel.height), MUTED, 1.0, &[3.0, 3.0]);
    pen.disc((x, y), 5.0, Some(KLI), Some((INK, 1.5)));
    let entries = [
        Entry { mark: Mark::Line(KLI, 3.0, &[]), label: "KLI" },
        Entry { mark: Mark::Line(SLERP, 1.5, &[5.0, 4.0]), label: "SLERP, t/T" },
    ];
    draw_legend_row(pen, (l + w, t + h - 10.0 * text), &entries);
}

/// Section 7, Algorithm 1: `‖r − qₙ‖` at each step `tₙ = nδ` on a log scale, the tolerance ε,
/// the stop `T` and the prediction `T*`, step `⌊t/δ⌋` marked.
pub fn draw_steps(pen: &Pen, model: &Model, frame: &Frame) {
    let text = pen.text_scale();
    let (l, t, w, h) = inset((0.0, 0.0, frame.width, frame.height), text, 46.0);
    let r = model.path.target();
    let digits = model.options.digits;
    let y_min = -(digits + 1.0).ceil();
    let panel = Panel::new((l, t, w, h), (0.0, model.end), (y_min, 0.5));
    let every = if digits > 6.0 { 2 } else { 1 };
    let ticks: Vec<(f64, String)> =
        decades(y_min as i32, 0, every).into_iter().map(|e| (e as f64, format!("1e{e}"))).collect();
    panel.frame_with(pen, &model.options.words.steps, &ticks, "t");
    let distance = |q: DQuat| (r - q).length().max(1e-300).log10();
    let times = model.path.times();
    let values: Vec<f64> = model.path.quaternions().iter().map(|&q| distance(q)).collect();
    if times.len() <= 160 {
        let points: Vec<(f64, f64)> =
            times.iter().zip(&values).map(|(&x, &y)| panel.at(x, y)).collect();
        pen.dots(&points, 2.5, KLI);
    } else {
        panel.series(pen, times, values.iter().copied(), KLI, 2.0, &[]);
    }
    let eps = -digits;
    pen.line(panel.at(0.0, eps), panel.at(model.end, eps), INK, 1.0, &[5.0, 3.0]);
    pen.text(
        "ε",
        (panel.at(model.end, eps).0 + 6.0, panel.at(model.end, eps).1),
        INK,
        12.0,
        "left",
    );
    let (big_t, star) = (model.path.final_time(), model.predicted());
    if big_t <= model.end {
        let (x, _) = panel.at(big_t, 0.0);
        pen.line((x, panel.top), (x, panel.top + panel.height), INK, 1.5, &[]);
        pen.text(
            &format!("T = {}", fixed(big_t, 2)),
            (x - 4.0, panel.top + 10.0 * text),
            INK,
            11.5,
            "right",
        );
    }
    if star <= model.end {
        let (x, _) = panel.at(star, 0.0);
        pen.line(
            (x, panel.top + 16.0 * text),
            (x, panel.top + panel.height),
            MUTED,
            1.0,
            &[2.0, 3.0],
        );
    }
    let n = model.step_at(frame.t);
    if let (Some(&x), Some(&y)) = (times.get(n), values.get(n)) {
        pen.disc(panel.at(x, y), 6.0, Some(KLI), Some((INK, 2.0)));
    }
}

/// Section 8: `| |q| − 1 |` for Euler, RK4 and the geodesic step at the reader's step size on the
/// paper's example, on a log scale (what lies below 1e-17 drawn at 1e-17), the chosen one thick.
pub fn draw_drift(pen: &Pen, model: &Model, frame: &Frame) {
    let text = pen.text_scale();
    let (l, t, w, h) = inset((0.0, 0.0, frame.width, frame.height), text, 46.0);
    let panel = Panel::new((l, t, w, h), (0.0, END), (-17.0, 0.0));
    let ticks: Vec<(f64, String)> =
        decades(-16, 0, 4).into_iter().map(|e| (e as f64, format!("1e{e}"))).collect();
    let words = &model.options.words;
    panel.frame_with(pen, &words.drift, &ticks, "t");
    let mut entries = Vec::new();
    for drift in &model.drifts {
        let chosen = drift.integrator == model.options.integrator;
        let (color, label) = integrator_style(drift.integrator, words);
        let width = if chosen { 3.5 } else { 1.25 };
        let ys = drift.drift.iter().map(|&d| if d > 0.0 { d.log10().max(-17.0) } else { -17.0 });
        panel.series(pen, &drift.times, ys, color, width, &[]);
        entries.push(Entry { mark: Mark::Line(color, width, &[]), label });
    }
    draw_legend_row(pen, (l + w, t + 8.0 * text), &entries);
    let chosen = model.drifts.iter().find(|d| d.integrator == model.options.integrator);
    if let Some(d) = chosen {
        let largest = d.largest();
        let text = if largest == 0.0 { String::from("0") } else { exponential(largest, 1) };
        let name = integrator_style(d.integrator, words).1;
        let line = fill(&words.largest, &[("integrator", name), ("drift", text.as_str())]);
        // Between the curves: Euler and RK4 have fallen below 1e-11 by then, the geodesic step
        // stays at rounding, below.
        pen.text(&line, (l + 0.3 * w, t + 0.8 * h), INK, 12.0, "left");
    }
}

/// Each integrator's colour and name.
pub fn integrator_style(integrator: Integrator, words: &Words) -> (&'static str, &str) {
    match integrator {
        Integrator::Euler => (KLI, "Euler"),
        Integrator::Rk4 => (SLERP, "RK4"),
        Integrator::Geodesic => (AXIS_Y, &words.geodesic),
    }
}

/// Y ticks at a nice step from `low` to `high`, as [`trim`] writes them.
fn even_ticks(low: f64, high: f64) -> Vec<(f64, String)> {
    let step = nice_step(high - low);
    if step <= 0.0 {
        return vec![(low, trim(low))];
    }
    let first = (low / step).ceil() as i64;
    let last = (high / step).floor() as i64;
    (first..=last).map(|k| k as f64 * step).map(|y| (y, trim(y))).collect()
}

/// Section 9, the turning rate through the four keyframes: `|ω(t)|` of the chain at the reader's
/// smoothness (thick) over piecewise SLERP's (dotted), a line at each key with the chain's jump of
/// `ω` there where it has one; beside it (below, when narrow) the chain's `ω` in its x, y and z
/// parts, where a jump shows even at a key where only the axis changes (k2: both pieces turn
/// 123° in a unit of time, so `|ω|` is the same either side).
pub fn draw_rates(pen: &Pen, model: &Model, frame: &Frame) {
    let (rates, words) = (&model.rates, &model.options.words);
    let text = pen.text_scale();
    let (w, h) = (frame.width, frame.height);
    let cells = if w >= 1.6 * h {
        [(0.0, 0.0, w / 2.0, h), (w / 2.0, 0.0, w / 2.0, h)]
    } else {
        [(0.0, 0.0, w, h / 2.0), (0.0, h / 2.0, w, h / 2.0)]
    };
    let times = &rates.times;
    let span = (times[0], times[times.len() - 1]);
    let key_times = rates.keys.times();
    let lines = |panel: &Panel| {
        for &k in key_times {
            let (x, _) = panel.at(k, 0.0);
            pen.line((x, panel.top), (x, panel.top + panel.height), MUTED, 1.0, &[2.0, 3.0]);
        }
    };
    // |ω(t)|, both curves on one scale.
    let speed = |omega: &[DVec3]| omega.iter().map(|v| v.length()).collect::<Vec<f64>>();
    let (chain, slerp) = (speed(&rates.chain.omega), speed(&rates.slerp.omega));
    let top = chain.iter().chain(&slerp).fold(0.0_f64, |m, &v| m.max(v)).max(1e-9) * 1.25;
    let panel = Panel::new(inset(cells[0], text, 40.0), span, (0.0, top));
    panel.frame_with(pen, &words.rate, &even_ticks(0.0, top), "t");
    lines(&panel);
    panel.series(pen, times, slerp.iter().copied(), INK, 1.5, &[2.0, 3.0]);
    panel.series(pen, times, chain.iter().copied(), KLI, 3.0, &[]);
    let size = 11.0;
    for (i, &k) in key_times.iter().enumerate() {
        let (x, y) = panel.at(k, top);
        let align = if i + 1 == key_times.len() { "right" } else { "left" };
        let dx = if align == "right" { -4.0 } else { 4.0 };
        pen.text(&format!("k{i}"), (x + dx, y + 10.0 * text), MUTED, size, align);
    }
    // A jump is written where the text quotes one (page.js: above 0.01 rad per unit time).
    for (&k, &jump) in key_times[1..].iter().zip(&rates.chain.jumps) {
        if jump >= 0.01 {
            let label = fill(&words.jump, &[("jump", fixed(jump, 2).as_str())]);
            let (x, y) = panel.at(k, top);
            pen.text(&label, (x + 4.0, y + 24.0 * text), KLI, size, "left");
        }
    }
    let smoothness = trim(rates.smoothness);
    let chain_label = fill(&words.chain, &[("smoothness", smoothness.as_str())]);
    let entries = [
        Entry { mark: Mark::Line(KLI, 3.0, &[]), label: &chain_label },
        Entry { mark: Mark::Line(INK, 1.5, &[2.0, 3.0]), label: &words.pieces },
    ];
    // Along the foot of the panel, below the curves, clear of the last key's line at the panel's
    // right edge; one above the other where the row is wider than the panel (a phone, or large
    // text).
    let (right, foot, line) =
        (panel.left + panel.width - 6.0, panel.top + panel.height - 10.0 * text, 15.0 * text);
    if legend_row_width(pen, &entries) <= panel.width - 8.0 {
        draw_legend_row(pen, (right, foot), &entries);
    } else {
        for (i, entry) in entries.iter().enumerate() {
            let y = foot - (entries.len() - 1 - i) as f64 * line;
            draw_legend_row(pen, (right, y), std::slice::from_ref(entry));
        }
    }
    // The chain's ω in its parts.
    let parts = |c: usize| rates.chain.omega.iter().map(move |v| v.to_array()[c]);
    let (low, high) =
        (0..3).flat_map(parts).fold((0.0_f64, 0.0_f64), |(lo, hi), v| (lo.min(v), hi.max(v)));
    let pad = 0.1 * (high - low).max(1e-9);
    let panel = Panel::new(inset(cells[1], text, 40.0), span, (low - pad, high + pad));
    panel.frame_with(pen, &words.parts, &even_ticks(low - pad, high + pad), "t");
    lines(&panel);
    let colours = [AXIS_X, AXIS_Y, AXIS_Z];
    for (c, colour) in colours.iter().enumerate() {
        panel.series(pen, times, parts(c), colour, 2.0, &[]);
    }
    let names = ["ωx", "ωy", "ωz"];
    let entries: Vec<Entry> = colours
        .iter()
        .zip(names)
        .map(|(&colour, label)| Entry { mark: Mark::Line(colour, 2.0, &[]), label })
        .collect();
    draw_plot_key(pen, &panel, &words.parts, &entries);
}
