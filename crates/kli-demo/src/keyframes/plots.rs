//! The keyframes page's plots: |ω(t)| and |ω̇(t)| of the three curves, side by side (or stacked
//! on a narrow figure), and the time on show as a dotted line across both.

use super::model::{Model, STYLES, Series};
use crate::figure::Layer;
use crate::legend::{Entry, Mark, draw_plot_key};
use crate::palette::MUTED;
use crate::pen::Pen;
use crate::plots::{Panel, inset, trim};

/// What a panel plots of a curve's series.
type Values = fn(&Series) -> &[f64];

/// The two panels and their curves (the still part), and the time `t` on each (the moving part).
pub fn draw_plots(pen: &Pen, model: &Model, (width, height): (f64, f64), t: f64, layer: Layer) {
    let wide = width >= 1.5 * height;
    let (cell_w, cell_h) = if wide { (width / 2.0, height) } else { (width, height / 2.0) };
    let (start, end) = (model.start_time(), model.end_time());
    let panels: [(&str, Values); 2] =
        [("|ω(t)|, rad per unit time", |s| &s.speed), ("|ω̇(t)|", |s| &s.acceleration)];
    for (index, (title, values)) in panels.into_iter().enumerate() {
        // The scale of the continuous curves (the chain's and Squad's): piecewise SLERP's
        // |ω̇| is a spike at every key, left off the top.
        let largest =
            model.series[..2].iter().flat_map(|s| values(s).iter()).fold(0.0_f64, |m, v| m.max(*v));
        let top_value = largest.max(1e-9) * 1.08;
        let (col, row) = if wide { (index as f64, 0.0) } else { (0.0, index as f64) };
        let area = (col * cell_w, row * cell_h, cell_w, cell_h);
        let (left, top, width, height) = inset(area, pen.text_scale(), 52.0);
        let panel = Panel {
            left,
            top,
            width,
            height,
            x_min: start,
            x_max: end,
            y_min: 0.0,
            y_max: top_value,
        };
        let ticks: Vec<(f64, String)> =
            [0.0, 0.5, 1.0].iter().map(|&f| (f * top_value, trim(f * top_value))).collect();
        if layer.still() {
            panel.frame_with(pen, title, &ticks, "t");
            for (s, style) in model.series.iter().zip(&STYLES).rev() {
                panel.series(pen, &model.times, values(s).iter().copied(), style.colour, 1.8, &[]);
            }
            if index == 0 {
                draw_key(pen, &panel, title);
            }
        }
        if layer != Layer::Still {
            let (x, _) = panel.at(t.max(start).min(end), 0.0);
            pen.line((x, panel.top), (x, panel.top + panel.height), MUTED, 1.0, &[2.0, 3.0]);
        }
    }
}

/// The curves' legend (see [`draw_plot_key`]).
fn draw_key(pen: &Pen, panel: &Panel, title: &str) {
    let entries: Vec<Entry> = STYLES
        .iter()
        .map(|s| Entry { mark: Mark::Line(s.colour, 2.0, &[]), label: s.name })
        .collect();
    draw_plot_key(pen, panel, title, &entries);
}
