//! The map of a pose graph: two panels at one scale, the initial estimate and the optimum, each
//! pose's position joined in order (the trajectory) and every other edge (a loop closure) drawn
//! thin, each edge in the colour of its misfit in that panel's poses; seen from above in 2D, by
//! an orbiting camera in 3D. Where the truth is known (the built-in graph), it is drawn dashed
//! under both panels. A key at the bottom says the colours.

use glam::DVec3;

use crate::camera::Camera;
use crate::palette::{INK, MISFIT, MUTED};
use crate::pen::Pen;

/// The misfit classes' upper ends (standard deviations) and labels; the colours are
/// [`MISFIT`]'s.
pub const CLASSES: [(f64, &str); 5] =
    [(0.5, "< 0.5σ"), (1.0, "0.5–1σ"), (2.0, "1–2σ"), (4.0, "2–4σ"), (f64::INFINITY, "≥ 4σ")];

/// The class of a misfit (a NaN, which no pose gives, is the worst).
pub fn class(misfit: f64) -> usize {
    CLASSES.iter().position(|&(end, _)| misfit < end).unwrap_or(CLASSES.len() - 1)
}

/// One panel: its heading, a line under it, each pose's position, each edge's misfit.
pub struct MapPanel<'a> {
    pub heading: String,
    pub line: String,
    pub positions: &'a [DVec3],
    pub misfits: &'a [f64],
}

/// Where the map is seen from: above (2D), or a camera (3D).
pub enum Look {
    Above,
    Orbit(Camera),
}

impl Look {
    fn flat(&self, p: DVec3) -> (f64, f64) {
        match self {
            Look::Above => (p.x, p.y),
            Look::Orbit(camera) => {
                let q = camera.project(p);
                (q.x, q.y)
            }
        }
    }
}

/// The font sizes: headings, lines and the key.
const HEADING: f64 = 13.0;
const LINE: f64 = 11.0;

/// The truth's dash, `[on, off]` pixels.
const TRUTH_DASH: &[f64] = &[3.0, 3.0];

/// The most segments one part of a map draws ([`Parts`]).
pub const PART_SEGMENTS: usize = 8_000;

/// The most segments of a map drawn in one part whatever its parts' budget: some 20 ms of the
/// main thread here, and a map turned by dragging is redrawn at each move, where parts would show
/// it half drawn (sphere2500's two panels: 9,898 segments).
pub const WHOLE_SEGMENTS: usize = 24_000;

/// The map in parts, for a page that draws a large one a task at a time: a part holds whole
/// strokes of at most [`PART_SEGMENTS`] segments (a stroke of more stands alone), with the text
/// and discs drawn between them, so that drawing every part in order makes the same calls as
/// drawing the whole. w10000's two panels (128,622 segments) drawn whole took the page's main
/// thread one task of 110 ms (57 ms of calls, then 53 ms of Chromium rasterising them at the
/// task's end); in parts of at most 20,000 segments its longest was still 50–54 ms in two loads
/// of three (a part's time varies with what the engine does beside it), hence 8,000. A map of
/// at most [`WHOLE_SEGMENTS`] is one part.
pub struct Parts {
    /// The part to draw (`None`: all of them).
    want: Option<usize>,
    /// The most segments a part holds.
    budget: usize,
    /// The part the next stroke falls in, and the segments already in it.
    part: usize,
    load: usize,
}

impl Parts {
    pub fn new(want: Option<usize>) -> Self {
        Parts { want, budget: PART_SEGMENTS, part: 0, load: 0 }
    }

    /// Whether the next drawing, `segments` long (0 for text or a disc), is in the wanted part.
    fn take(&mut self, segments: usize) -> bool {
        if self.load > 0 && self.load + segments > self.budget {
            (self.part, self.load) = (self.part + 1, 0);
        }
        self.load += segments;
        self.want.is_none_or(|want| want == self.part)
    }

    /// Whether the part wanted is one after the first (drawn over the ones before it).
    pub fn wants_later(&self) -> bool {
        self.want.is_some_and(|want| want > 0)
    }

    /// How many parts the drawing took.
    pub fn count(&self) -> usize {
        self.part + 1
    }
}

/// Draws the panels side by side (stacked when the figure is taller than wide), over `truth`
/// (each pose's true position, in the panels' gauge) where it is known: of each drawing, what
/// falls in `parts`' wanted part.
pub fn draw_map(
    pen: &Pen,
    edges: &[[usize; 2]],
    panels: &[MapPanel],
    truth: Option<&[DVec3]>,
    look: &Look,
    (width, height): (f64, f64),
    parts: &mut Parts,
) {
    if panels.len() * (edges.len() + truth.map_or(0, <[DVec3]>::len)) <= WHOLE_SEGMENTS {
        parts.budget = usize::MAX;
    }
    let s = pen.text_scale();
    let key = key_entries(truth.is_some());
    let key_height = draw_key(pen, &key, (8.0, 0.0), width - 16.0, false);
    let body = (height - key_height - 8.0 * s).max(10.0);
    let wide = width >= height;
    let k = panels.len().max(1) as f64;
    let head = 40.0 * s;
    let cells: Vec<(f64, f64, f64, f64)> = (0..panels.len())
        .map(|n| {
            let n = n as f64;
            if wide {
                (n * width / k, 0.0, width / k, body)
            } else {
                (0.0, n * body / k, width, body / k)
            }
        })
        .collect();
    // One scale for both: the box of every panel's points, fitted in the smallest map area.
    let flat: Vec<Vec<(f64, f64)>> =
        panels.iter().map(|p| p.positions.iter().map(|&v| look.flat(v)).collect()).collect();
    let truth: Vec<(f64, f64)> = truth.unwrap_or_default().iter().map(|&v| look.flat(v)).collect();
    let points = flat.iter().flatten().chain(&truth).filter(|p| p.0.is_finite() && p.1.is_finite());
    let (mut low, mut high) =
        ((f64::INFINITY, f64::INFINITY), (f64::NEG_INFINITY, f64::NEG_INFINITY));
    for &(x, y) in points {
        low = (low.0.min(x), low.1.min(y));
        high = (high.0.max(x), high.1.max(y));
    }
    if low.0 > high.0 {
        (low, high) = ((-1.0, -1.0), (1.0, 1.0));
    }
    let margin = 10.0;
    let span = ((high.0 - low.0).max(1e-9), (high.1 - low.1).max(1e-9));
    let scale = cells
        .iter()
        .map(|&(_, _, w, h)| {
            ((w - 2.0 * margin).max(1.0) / span.0).min((h - head - 2.0 * margin).max(1.0) / span.1)
        })
        .fold(f64::INFINITY, f64::min);
    let centre = (0.5 * (low.0 + high.0), 0.5 * (low.1 + high.1));
    for ((panel, points), &(left, top, w, h)) in panels.iter().zip(&flat).zip(&cells) {
        if parts.take(0) {
            pen.text(&panel.heading, (left + 10.0, top + 12.0 * s), INK, HEADING, "left");
            pen.text(&panel.line, (left + 10.0, top + 28.0 * s), MUTED, LINE, "left");
        }
        let (cx, cy) = (left + 0.5 * w, top + head + 0.5 * (h - head));
        let at = |(x, y): (f64, f64)| (cx + scale * (x - centre.0), cy - scale * (y - centre.1));
        if parts.take(truth.len()) {
            let line: Vec<(f64, f64)> = truth.iter().map(|&p| at(p)).collect();
            pen.polyline(&line, MUTED, 1.0, TRUTH_DASH);
        }
        draw_edges(pen, edges, panel.misfits, &|i| at(points[i]), parts);
        if let Some(&first) = points.first() {
            if parts.take(0) {
                pen.disc(at(first), 4.0, Some("#ffffff"), Some((INK, 2.0)));
            }
        }
    }
    if parts.take(0) {
        draw_key(pen, &key, (8.0, body + 4.0 * s), width - 16.0, true);
    }
}

/// Every edge as a segment: loop closures thin and under, then the trajectory, each class over
/// the ones below it (a large misfit stays visible among many small ones), wider as it rises
/// (but a large graph's loop closures, below).
fn draw_edges(
    pen: &Pen,
    edges: &[[usize; 2]],
    misfits: &[f64],
    at: &dyn Fn(usize) -> (f64, f64),
    parts: &mut Parts,
) {
    let mut groups: Vec<Vec<[(f64, f64); 2]>> = vec![Vec::new(); 2 * CLASSES.len()];
    for (&[i, j], &misfit) in edges.iter().zip(misfits) {
        let closure = usize::from(i.abs_diff(j) != 1);
        let (a, b) = (at(i), at(j));
        if [a.0, a.1, b.0, b.1].iter().all(|v| v.is_finite()) {
            groups[2 * class(misfit) + 1 - closure].push([a, b]);
        }
    }
    // A large graph's loop closures are hairlines whatever their class: Chromium rasterises a
    // long stroke wider than a device pixel some fifty times slower (64,000 random segments: 0.9
    // s at 1 device pixel, 57 s at 2.8), and a map far from its optimum has many long ones. Its
    // trajectory is a pixel wide, its class told by colour alone: at 10⁴ poses the segments are
    // shorter than the wider line's width, and rasterising them at 1.4–3 px took the page's
    // main thread 77 ms of one task (w10000's map), at 1 px 34–52 ms. The paths are cut in
    // pieces of 2,000 segments, which Skia fills faster than one.
    let large = edges.len() > 5000;
    for (g, segments) in groups.iter().enumerate() {
        let (c, trajectory) = (g / 2, g % 2 == 1);
        let width = match (trajectory, large) {
            (true, true) => 1.0,
            (true, false) => 1.4 + 0.4 * c as f64,
            (false, true) => 0.5,
            (false, false) => 0.8 + 0.3 * c as f64,
        };
        for piece in segments.chunks(2000) {
            if parts.take(piece.len()) {
                pen.segments(piece, MISFIT[c], width, &[]);
            }
        }
    }
}

/// A key's entry: a swatch (a line of a colour, width and dash, or the first pose's ring) and a
/// label.
struct KeyEntry {
    colour: &'static str,
    width: f64,
    dash: &'static [f64],
    ring: bool,
    label: &'static str,
}

/// The key: the misfit classes, the loop closures, pose 0, and the truth where it is drawn.
fn key_entries(truth: bool) -> Vec<KeyEntry> {
    let entry = |colour, width, label| KeyEntry { colour, width, dash: &[], ring: false, label };
    let mut entries = vec![entry(INK, 0.0, "edge misfit:")];
    for (c, &(_, label)) in CLASSES.iter().enumerate() {
        entries.push(entry(MISFIT[c], 1.4 + 0.4 * c as f64, label));
    }
    entries.push(entry(MUTED, 0.8, "thin: loop closure"));
    entries.push(KeyEntry { ring: true, ..entry(INK, 2.0, "pose 0 (held fixed)") });
    if truth {
        entries.push(KeyEntry { dash: TRUTH_DASH, ..entry(MUTED, 1.0, "the true path") });
    }
    entries
}

/// Lays the key out in rows from `(left, top)` within `width`, wrapping; draws it when `draw`.
/// Returns its height.
fn draw_key(
    pen: &Pen,
    entries: &[KeyEntry],
    (left, top): (f64, f64),
    width: f64,
    draw: bool,
) -> f64 {
    let s = pen.text_scale();
    let (line, swatch) = (16.0 * s, 18.0 * s.sqrt());
    let (mut x, mut y) = (left, top + 0.5 * line);
    for entry in entries {
        let text = pen.text_width(entry.label, LINE);
        let swatch = if entry.width > 0.0 { swatch + 4.0 } else { 0.0 };
        let wide = swatch + text + 12.0;
        if x > left && x + wide > left + width {
            (x, y) = (left, y + line);
        }
        if draw {
            if entry.ring {
                pen.disc(
                    (x + 0.5 * swatch, y),
                    4.0,
                    Some("#ffffff"),
                    Some((entry.colour, entry.width)),
                );
            } else if entry.width > 0.0 {
                pen.line((x, y), (x + swatch - 4.0, y), entry.colour, entry.width, entry.dash);
            }
            pen.text(entry.label, (x + swatch, y), INK, LINE, "left");
        }
        x += wide;
    }
    y + 0.5 * line - top
}
