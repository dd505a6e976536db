//! A sweep: each method's error against the share of wrong data (the averaging page's means, the
//! synchronisation page's solvers), one curve a method, the page's share marked.

use crate::legend::{Entry, Mark, draw_plot_key};
use crate::palette::MUTED;
use crate::pen::Pen;
use crate::plots::{Panel, inset, trim};
use crate::ticks::nice_step;

/// One curve of a sweep: the method's name and colour.
pub struct Curve {
    pub name: &'static str,
    pub colour: &'static str,
}

/// Draws `curves.len()` errors a share (radians, in `curves`' order; a non-finite one is left
/// out) against the shares from 0 to `last`, under `title`, with a dashed line at `current`.
pub fn draw_error_sweep(
    pen: &Pen,
    (width, height): (f64, f64),
    title: &str,
    curves: &[Curve],
    last: f64,
    (shares, errors): (&[f64], &[f64]),
    current: f64,
) {
    let k = curves.len().max(1);
    let n = shares.len().min(errors.len() / k);
    let finite = |v: f64| v.is_finite().then_some(v);
    let largest = (0..k * n).filter_map(|i| finite(errors[i].to_degrees())).fold(1.0, f64::max);
    // Room above the curves for the legend's row inside the panel.
    let step = nice_step(1.1 * largest);
    let top = step * (1.1 * largest / step).ceil();
    let (left, top_edge, w, h) = inset((0.0, 0.0, width, height), pen.text_scale(), 46.0);
    let p = Panel {
        left,
        top: top_edge,
        width: w,
        height: h,
        x_min: 0.0,
        x_max: last,
        y_min: 0.0,
        y_max: top,
    };
    let ticks: Vec<(f64, String)> =
        [0.0, 0.5 * top, top].iter().map(|&v| (v, format!("{}°", trim(v)))).collect();
    p.frame_with(pen, title, &ticks, "share");
    for (m, curve) in curves.iter().enumerate() {
        let (xs, ys): (Vec<f64>, Vec<f64>) = (0..n)
            .filter_map(|i| finite(errors[k * i + m]).map(|e| (shares[i], e.to_degrees())))
            .unzip();
        p.series(pen, &xs, ys.iter().copied(), curve.colour, 2.0, &[]);
        let points: Vec<(f64, f64)> = xs.iter().zip(&ys).map(|(&x, &y)| p.at(x, y)).collect();
        pen.dots(&points, 2.5, curve.colour);
    }
    let (x, _) = p.at(current.max(0.0).min(last), 0.0);
    pen.line((x, p.top), (x, p.top + p.height), MUTED, 1.0, &[3.0, 3.0]);
    let entries: Vec<Entry> = curves
        .iter()
        .map(|c| Entry { mark: Mark::Line(c.colour, 2.0, &[]), label: c.name })
        .collect();
    draw_plot_key(pen, &p, title, &entries);
}
