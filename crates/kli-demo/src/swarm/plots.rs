//! The swarm's history as plots (the order parameter `R`, the sign-blind `λ_max` and the
//! potential over time) and the sweep of the final `R` against the coupling `K`.

use crate::format::fixed;
use crate::palette::{INK, KLI, MUTED, SLERP};
use crate::pen::Pen;
use crate::plots::{Panel, inset, plot_area, trim};

/// How many samples the history keeps (the oldest are dropped, so memory stays flat).
pub const HISTORY: usize = 1500;

/// `(t, R, λ_max, potential)` samples, the newest last.
#[derive(Debug, Clone, Default)]
pub struct History {
    pub times: Vec<f64>,
    pub order: Vec<f64>,
    pub rotation: Vec<f64>,
    pub potential: Vec<f64>,
}

impl History {
    /// Appends a sample, dropping the oldest beyond [`HISTORY`].
    pub fn push(&mut self, t: f64, order: f64, rotation: f64, potential: f64) {
        if self.times.len() == HISTORY {
            for series in
                [&mut self.times, &mut self.order, &mut self.rotation, &mut self.potential]
            {
                series.remove(0);
            }
        }
        self.times.push(t);
        self.order.push(order);
        self.rotation.push(rotation);
        self.potential.push(potential);
    }

    pub fn clear(&mut self) {
        *self = Self::default();
    }
}

fn ticks(values: &[f64]) -> Vec<(f64, String)> {
    values.iter().map(|&v| (v, trim(v))).collect()
}

/// `R(t)`, `λ_max(t)` and the potential over the history, side by side (stacked when narrow).
pub fn draw_history(pen: &Pen, width: f64, height: f64, history: &History) {
    let (first, last) = match (history.times.first(), history.times.last()) {
        (Some(&a), Some(&b)) if b > a => (a, b),
        (Some(&a), _) => (a, a + 1.0),
        _ => (0.0, 1.0),
    };
    let x = (first, last);
    let order = Panel::new(plot_area(0, width, height, pen.text_scale()), x, (0.0, 1.0));
    order.frame_with(pen, "order parameter R = |m|", &ticks(&[0.0, 0.25, 0.5, 0.75, 1.0]), "t");
    order.series(pen, &history.times, history.order.iter().copied(), KLI, 2.0, &[]);
    let rotation = Panel::new(plot_area(1, width, height, pen.text_scale()), x, (0.25, 1.0));
    rotation.frame_with(pen, "rotation order λmax(Q)", &ticks(&[0.25, 0.5, 0.75, 1.0]), "t");
    rotation.series(pen, &history.times, history.rotation.iter().copied(), SLERP, 2.0, &[]);
    let (low, high) =
        history.potential.iter().fold((0.0_f64, 0.0_f64), |(l, h), &v| (l.min(v), h.max(v)));
    let span = if high > low { high - low } else { 1.0 };
    let potential = Panel::new(plot_area(2, width, height, pen.text_scale()), x, (low, low + span));
    let labels =
        [low, low + 0.5 * span, low + span].map(|v| (v, fixed(v, if span < 10.0 { 2 } else { 0 })));
    potential.frame_with(pen, "potential (K N/2)|m|²", &labels, "t");
    potential.series(pen, &history.times, history.potential.iter().copied(), INK, 2.0, &[]);
}

/// The sweep: the final `R` (time-averaged) against the coupling `K`, with the current `K`.
pub fn draw_sweep(
    pen: &Pen,
    width: f64,
    height: f64,
    couplings: &[f64],
    orders: &[f64],
    current: f64,
) {
    let (low, high) = couplings.iter().fold((current, current), |(l, h), &k| (l.min(k), h.max(k)));
    let (low, high) = if high > low { (low, high) } else { (low - 1.0, high + 1.0) };
    let p = Panel::new(
        inset((0.0, 0.0, width, height), pen.text_scale(), 46.0),
        (low, high),
        (0.0, 1.0),
    );
    p.frame_with(pen, "final R against the coupling K", &ticks(&[0.0, 0.5, 1.0]), "K");
    let n = couplings.len().min(orders.len());
    p.series(pen, &couplings[..n], orders[..n].iter().copied(), KLI, 2.0, &[]);
    let points: Vec<(f64, f64)> = (0..n).map(|i| p.at(couplings[i], orders[i])).collect();
    pen.dots(&points, 3.0, KLI);
    let (x, _) = p.at(current, 0.0);
    pen.line((x, p.top), (x, p.top + p.height), MUTED, 1.0, &[3.0, 3.0]);
}
