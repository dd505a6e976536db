//! The plots beside the views: the distance `||target - q(t)||` on a log scale with the tolerance,
//! `T` and `T*`; the time warp `s(t)` against SLERP's `t / T`; the drift of `|q|` from 1.

use crate::format::{exponential, fixed};
use crate::palette::{GRID, INK, KLI, MUTED, SLERP};
use crate::pen::Pen;
use crate::scene::Scene;
use crate::ticks::{decades, nice_step};

/// A plot frame: data ranges mapped onto a rectangle of the canvas.
pub(crate) struct Panel {
    pub left: f64,
    pub top: f64,
    pub width: f64,
    pub height: f64,
    pub x_min: f64,
    pub x_max: f64,
    pub y_min: f64,
    pub y_max: f64,
}

impl Panel {
    /// The rectangle `(left, top, width, height)` showing `x` = `(min, max)` across and `y` up.
    // Only the swarm's and the synchronisation's plots build a panel this way; a page module
    // built without both would otherwise warn.
    #[cfg_attr(not(any(feature = "swarm-page", feature = "sync-page")), allow(dead_code))]
    pub fn new(
        (left, top, width, height): (f64, f64, f64, f64),
        x: (f64, f64),
        y: (f64, f64),
    ) -> Self {
        Panel { left, top, width, height, x_min: x.0, x_max: x.1, y_min: y.0, y_max: y.1 }
    }

    pub fn at(&self, x: f64, y: f64) -> (f64, f64) {
        let span = self.x_max - self.x_min;
        let fx = if span > 0.0 { (x - self.x_min) / span } else { 0.0 };
        // max/min rather than clamp: clamp panics on bad bounds, and nothing here may panic.
        let fy = (y.max(self.y_min).min(self.y_max) - self.y_min) / (self.y_max - self.y_min);
        (self.left + fx * self.width, self.top + (1.0 - fy) * self.height)
    }

    /// The title, the y ticks given, x ticks at a nice step, the axes, and `x_label` at the end
    /// of the x axis.
    pub fn frame_with(&self, pen: &Pen, title: &str, y_ticks: &[(f64, String)], x_label: &str) {
        self.frame_y(pen, title, y_ticks);
        // Offsets from the axes grow with the text, as the margins do (see `inset`).
        let s = pen.text_scale();
        let step = nice_step(self.x_max - self.x_min);
        let mut x = if step > 0.0 { (self.x_min / step).ceil() * step } else { self.x_max + 1.0 };
        while x <= self.x_max + 1e-9 * (self.x_max - self.x_min).abs() && step > 0.0 {
            let (px, py) = self.at(x, self.y_min);
            pen.line((px, py), (px, py + 4.0), MUTED, 1.0, &[]);
            pen.text(&trim(x), (px, py + 12.0 * s), MUTED, 10.5, "center");
            x += step;
        }
        let end = (self.left + self.width + 8.0 * s, self.top + self.height);
        pen.text(x_label, end, MUTED, 11.0, "center");
    }

    /// The title, the y ticks given and the axes, no x ticks (for bars over categories, each
    /// labelled by its caller).
    pub fn frame_y(&self, pen: &Pen, title: &str, y_ticks: &[(f64, String)]) {
        pen.text(title, (self.left, self.top - 14.0 * pen.text_scale()), INK, 12.5, "left");
        for (y, label) in y_ticks {
            let (_, py) = self.at(0.0, *y);
            pen.line((self.left, py), (self.left + self.width, py), GRID, 1.0, &[]);
            pen.text(label, (self.left - 5.0, py), MUTED, 10.5, "right");
        }
        pen.line(
            (self.left, self.top + self.height),
            (self.left + self.width, self.top + self.height),
            MUTED,
            1.0,
            &[],
        );
        pen.line((self.left, self.top), (self.left, self.top + self.height), MUTED, 1.0, &[]);
    }

    fn frame(&self, pen: &Pen, title: &str, y_ticks: &[(f64, String)]) {
        self.frame_with(pen, title, y_ticks, "t");
    }

    pub fn series(
        &self,
        pen: &Pen,
        xs: &[f64],
        ys: impl Iterator<Item = f64>,
        color: &str,
        width: f64,
        dash: &[f64],
    ) {
        let points: Vec<(f64, f64)> = xs.iter().zip(ys).map(|(&x, y)| self.at(x, y)).collect();
        pen.polyline(&points, color, width, dash);
    }
}

/// A tick label: at most two decimals, trailing zeros dropped.
pub(crate) fn trim(x: f64) -> String {
    let text = fixed(x, 2);
    text.trim_end_matches('0').trim_end_matches('.').to_string()
}

fn decade_ticks(low: i32, high: i32, every: i32) -> Vec<(f64, String)> {
    decades(low, high, every).into_iter().map(|e| (e as f64, format!("1e{e}"))).collect()
}

fn log10_floor(values: &[f64], floor: f64) -> impl Iterator<Item = f64> + '_ {
    values.iter().map(move |&v| if v > 0.0 { v.log10().max(floor) } else { floor })
}

/// A rectangle `(left, top, width, height)` in CSS pixels.
pub type Rect = (f64, f64, f64, f64);

/// The plotting rectangle inside a plot's cell: `left_margin` for the tick labels, 30 above for
/// the title, 24 right, 28 below for the axis labels, all grown with the text `scale` (so
/// projector-sized labels stay inside the figure).
pub fn inset((left, top, width, height): Rect, scale: f64, left_margin: f64) -> Rect {
    let right = (left_margin + 24.0) * scale;
    (
        left + left_margin * scale,
        top + 30.0 * scale,
        (width - right).max(10.0),
        (height - 58.0 * scale).max(10.0),
    )
}

/// The plotting rectangle of plot `index` of three (0 distance, 1 time warp, 2 drift; the
/// swarm's three too) in a canvas of `(width, height)`: side by side when wide, stacked when
/// narrow, at text `scale`.
pub fn plot_area(index: usize, width: f64, height: f64, scale: f64) -> Rect {
    let wide = width >= 2.0 * height;
    let (cell_w, cell_h) = if wide { (width / 3.0, height) } else { (width, height / 3.0) };
    let (col, row) = if wide { (index as f64, 0.0) } else { (0.0, index as f64) };
    inset((col * cell_w, row * cell_h, cell_w, cell_h), scale, 46.0)
}

/// The time axis of every plot ends a little past both `T` and `T*` (and spans at least 1, so
/// a run that ends at once still gets a readable axis).
pub fn time_axis_end(scene: &Scene) -> f64 {
    scene.final_time().max(scene.predicted_time()).max(1.0) * 1.04
}

/// Draws the three plots into `(width, height)`; [`draw_plot_cursors`] marks a time on them.
pub fn draw_plots(pen: &Pen, width: f64, height: f64, scene: &Scene) {
    let x_max = time_axis_end(scene);
    let cell = |i: usize, y_min: f64, y_max: f64| {
        let (left, top, width, height) = plot_area(i, width, height, pen.text_scale());
        Panel { left, top, width, height, x_min: 0.0, x_max, y_min, y_max }
    };
    draw_distance(pen, scene, |low| cell(0, low, 0.5));
    draw_warp(pen, scene, &cell(1, 0.0, 1.0));
    draw_drift(pen, scene, |high| cell(2, -17.0, high));
}

/// The distance to the target on a log scale, with ε, the measured `T` and the predicted `T*`;
/// `panel` makes the frame once the lowest decade `low` is known.
fn draw_distance(pen: &Pen, scene: &Scene, panel: impl Fn(f64) -> Panel) {
    let (times, final_time) = (scene.path().times(), scene.final_time());
    let tolerance = scene.path().options().tolerance;
    let smallest = scene.distances().iter().copied().filter(|&d| d > 0.0).fold(tolerance, f64::min);
    let low = (smallest.log10().floor() as i32 - 1).max(-17);
    let panel = panel(low as f64);
    let every = ((1 - low) / 6).max(1);
    panel.frame(pen, "distance ||r − q(t)|| (log)", &decade_ticks(low, 0, every));
    panel.series(pen, times, log10_floor(scene.distances(), low as f64), KLI, 2.0, &[]);
    let (x0, ty) = panel.at(0.0, tolerance.log10());
    let right = panel.left + panel.width;
    pen.line((x0, ty), (right, ty), MUTED, 1.0, &[4.0, 3.0]);
    pen.text(
        &format!("ε = {}", exponential(tolerance, 0)),
        (right, ty - 8.0),
        MUTED,
        10.5,
        "right",
    );
    let (tx, _) = panel.at(final_time, 0.0);
    pen.line((tx, panel.top), (tx, panel.top + panel.height), KLI, 1.0, &[]);
    let (sx, _) = panel.at(scene.predicted_time(), 0.0);
    pen.line((sx, panel.top), (sx, panel.top + panel.height), INK, 1.0, &[3.0, 3.0]);
    let times_label =
        format!("T = {}  T* = {}", fixed(final_time, 2), fixed(scene.predicted_time(), 4));
    pen.text(&times_label, (right, panel.top + 8.0), INK, 10.5, "right");
}

/// The time warp: KLI's SLERP parameter `s(t)` against SLERP's linear clock `u = t / T` (two
/// different numbers: at t = 1.8 of the paper's example, s = 0.818 and u = 0.154).
fn draw_warp(pen: &Pen, scene: &Scene, panel: &Panel) {
    let times = scene.path().times();
    let ticks: Vec<(f64, String)> =
        [0.0, 0.25, 0.5, 0.75, 1.0].iter().map(|&y| (y, trim(y))).collect();
    panel.frame(pen, "SLERP parameter: KLI's s(t), SLERP's u = t/T", &ticks);
    let slerp = times.iter().map(|&x| scene.clock_fraction(x));
    panel.series(pen, times, slerp, SLERP, 1.5, &[5.0, 4.0]);
    panel.series(pen, times, scene.warp().iter().copied(), KLI, 2.0, &[]);
    pen.text("KLI, s(t)", panel.at(panel.x_max * 0.08, 0.93), KLI, 11.0, "left");
    pen.text("SLERP, u = t/T", panel.at(panel.x_max * 0.55, 0.3), SLERP, 11.0, "left");
}

/// How far the chosen integrator lets `|q|` drift from 1, on a log scale; `panel` makes the
/// frame once the highest decade `high` is known.
fn draw_drift(pen: &Pen, scene: &Scene, panel: impl Fn(f64) -> Panel) {
    let largest = scene.norm_drift().iter().copied().fold(0.0_f64, f64::max);
    let high = if largest > 0.0 { (largest.log10().ceil() as i32).clamp(-15, 0) } else { -15 };
    let panel = panel(high as f64);
    let integrator = scene.path().options().integrator;
    let title = format!("| |q| − 1 |, {} (log)", integrator.name());
    panel.frame(pen, &title, &decade_ticks(-17, high, (high + 17) / 5));
    let drift = log10_floor(scene.norm_drift(), -17.0);
    panel.series(pen, scene.path().times(), drift, KLI, 2.0, &[]);
    let label = format!("max {}", exponential(largest, 1));
    pen.text(&label, (panel.left + panel.width, panel.top + 8.0), INK, 10.5, "right");
}

/// The current time `t` as a dotted vertical line on each plot, over [`draw_plots`]' drawing.
pub fn draw_plot_cursors(pen: &Pen, width: f64, height: f64, scene: &Scene, t: f64) {
    let x_max = time_axis_end(scene);
    for i in 0..3 {
        let (left, top, w, h) = plot_area(i, width, height, pen.text_scale());
        let x = left + t.max(0.0).min(x_max) / x_max * w;
        pen.line((x, top), (x, top + h), INK, 1.0, &[2.0, 3.0]);
    }
}
