//! Legends and labels that keep a figure readable on its own (issue 15): a key of what each
//! curve and mark is, drawn in the figure itself (so in its SVG, PNG and video too), labels that
//! stay clear of each other, and a note where the figure cannot show something.

use crate::camera::Viewport;
use crate::palette::{INK, MUTED};
use crate::pen::Pen;

/// What a legend entry shows beside its label.
#[derive(Clone, Copy)]
pub enum Mark<'a> {
    /// A line of `colour`, `width` and `dash` (`[on, off]`, empty for solid).
    Line(&'a str, f64, &'a [f64]),
    /// A disc: its fill and its ring's colour.
    Disc(Option<&'a str>, &'a str),
}

/// A legend's entry.
pub struct Entry<'a> {
    pub mark: Mark<'a>,
    pub label: &'a str,
}

/// The font size of legends and notes (before the pen's text scale).
const SIZE: f64 = 11.0;

/// A key's white backing over what is drawn beneath, `[left, top, right, bottom]`, nearly opaque
/// (what it covers shows faintly), with `outline` if any.
fn backing(pen: &Pen, [left, top, right, bottom]: [f64; 4], outline: Option<&str>) {
    pen.alpha(0.88);
    let corners = [(left, top), (right, top), (right, bottom), (left, bottom)];
    pen.fill_polygon(&corners, "#ffffff", outline);
    pen.alpha(1.0);
}

/// Draws `entries` in a box at the bottom left of `area`, one a line, then `note` (muted,
/// below them) if any. A legend that would cover more than 60% of the area's width or 40% of
/// its height (a thumbnail, a large text scale on a small figure) is left out: it would hide
/// the figure it explains. Returns whether it was drawn.
pub fn draw_legend(pen: &Pen, area: &Viewport, entries: &[Entry], note: Option<&str>) -> bool {
    let scale = pen.text_scale();
    let line = 15.0 * scale;
    let swatch = 22.0 * scale.sqrt();
    let rows = entries.len() + usize::from(note.is_some());
    let height = rows as f64 * line + 6.0;
    let widths = entries.iter().map(|e| swatch + 6.0 + pen.text_width(e.label, SIZE));
    let note_width = note.map_or(0.0, |n| pen.text_width(n, SIZE));
    let width = widths.fold(note_width, f64::max) + 10.0;
    if width > 0.6 * area.width || height > 0.4 * area.height {
        return false;
    }
    let (left, bottom) = (area.left + 4.0, area.top + area.height - 4.0);
    let top = bottom - height;
    backing(pen, [left, top, left + width, bottom], Some("#ced4da"));
    for (i, entry) in entries.iter().enumerate() {
        let y = top + 3.0 + (i as f64 + 0.5) * line;
        let (x0, x1) = (left + 5.0, left + 5.0 + swatch);
        match entry.mark {
            Mark::Line(colour, width, dash) => pen.line((x0, y), (x1, y), colour, width, dash),
            Mark::Disc(fill, ring) => {
                pen.disc((0.5 * (x0 + x1), y), 4.5, fill, Some((ring, 1.5)));
            }
        }
        pen.text(entry.label, (x1 + 6.0, y), INK, SIZE, "left");
    }
    if let Some(note) = note {
        let y = top + 3.0 + (entries.len() as f64 + 0.5) * line;
        pen.text(note, (left + 5.0, y), MUTED, SIZE, "left");
    }
    true
}

/// The width of [`draw_legend_row`]'s row.
pub fn legend_row_width(pen: &Pen, entries: &[Entry]) -> f64 {
    let swatch = 16.0 * pen.text_scale().sqrt();
    entries.iter().map(|e| pen.text_width(e.label, SIZE) + swatch + 14.0).sum::<f64>() - 10.0
}

/// Draws `entries` in one row ending at `(right, y)` (a plot's title line, or inside a plot):
/// each a short line of its mark and its label, on a white band that keeps the curves and lines
/// drawn before it out of its words (inside a plot on a phone, the keys' dotted lines ran through
/// them; beside a title the band is white on white).
pub fn draw_legend_row(pen: &Pen, (right, y): (f64, f64), entries: &[Entry]) {
    let swatch = 16.0 * pen.text_scale().sqrt();
    let (left, half) = (right - legend_row_width(pen, entries) - 4.0, 8.0 * pen.text_scale());
    backing(pen, [left, y - half, right + 3.0, y + half], None);
    let mut x = right;
    for entry in entries.iter().rev() {
        let width = pen.text_width(entry.label, SIZE);
        pen.text(entry.label, (x, y), INK, SIZE, "right");
        x -= width + 4.0;
        match entry.mark {
            Mark::Line(colour, width, dash) => {
                pen.line((x - swatch, y), (x, y), colour, width, dash)
            }
            Mark::Disc(fill, ring) => {
                pen.disc((x - 0.5 * swatch, y), 4.0, fill, Some((ring, 1.5)));
            }
        }
        x -= swatch + 10.0;
    }
}

/// A plot's legend: beside its title when there is room; else one row inside the panel's top
/// (keep the curves below 1/1.08 of its height); else, on a narrow panel, an entry a row there.
#[cfg_attr(not(any(feature = "keyframes-page", feature = "average-page")), allow(dead_code))]
pub(crate) fn draw_plot_key(
    pen: &Pen,
    panel: &crate::plots::Panel,
    title: &str,
    entries: &[Entry],
) {
    let (right, line) = (panel.left + panel.width - 4.0, 14.0 * pen.text_scale());
    let row = legend_row_width(pen, entries);
    if row <= panel.width - pen.text_width(title, 12.5) - 12.0 {
        draw_legend_row(pen, (right, panel.top - line), entries);
    } else if row <= panel.width - 8.0 {
        draw_legend_row(pen, (right, panel.top + 8.0 * pen.text_scale()), entries);
    } else {
        for (i, entry) in entries.iter().enumerate() {
            let y = panel.top + 8.0 * pen.text_scale() + i as f64 * line;
            draw_legend_row(pen, (right, y), std::slice::from_ref(entry));
        }
    }
}

/// Labels for points that may fall on top of each other (keys whose Hopf points coincide):
/// points within `radius` pixels of an earlier one share its label ("k0, k1"). Returns each
/// label and where its first point is.
pub fn grouped_labels(
    points: &[(f64, f64)],
    names: &[String],
    radius: f64,
) -> Vec<(String, (f64, f64))> {
    let mut groups: Vec<(String, (f64, f64))> = Vec::new();
    for (point, name) in points.iter().zip(names) {
        let near =
            groups.iter_mut().find(|(_, at)| (at.0 - point.0).hypot(at.1 - point.1) < radius);
        match near {
            Some((label, _)) => {
                label.push_str(", ");
                label.push_str(name);
            }
            None => groups.push((name.clone(), *point)),
        }
    }
    groups
}

/// Where a label of a point on the sphere's outline goes: `distance` pixels from the point,
/// away from the sphere's centre (off the curves through the point, which cross the disc).
pub fn outward((x, y): (f64, f64), (cx, cy): (f64, f64), distance: f64) -> (f64, f64) {
    let (dx, dy) = (x - cx, y - cy);
    let length = dx.hypot(dy);
    if length < 1e-9 {
        return (x, y - distance);
    }
    (x + distance * dx / length, y + distance * dy / length)
}

/// `text` broken at spaces into lines no wider than `width` at `size` (a word wider than that
/// stands on a line of its own).
pub fn wrapped(pen: &Pen, text: &str, size: f64, width: f64) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    for word in text.split(' ') {
        match lines.last_mut() {
            Some(line) if pen.text_width(&format!("{line} {word}"), size) <= width => {
                line.push(' ');
                line.push_str(word);
            }
            _ => lines.push(word.to_owned()),
        }
    }
    lines
}

/// A text's box, `[left, top, right, bottom]` in CSS pixels.
pub type TextBox = [f64; 4];

/// The box of `text` centred at `(x, y)` at `size` (the pen's text scale applied).
pub fn text_box(pen: &Pen, text: &str, (x, y): (f64, f64), size: f64) -> TextBox {
    let (half_width, half_height) =
        (0.5 * pen.text_width(text, size), 0.5 * size * pen.text_scale());
    [x - half_width, y - half_height, x + half_width, y + half_height]
}

/// Whether two boxes share any area.
pub fn overlap(a: &TextBox, b: &TextBox) -> bool {
    a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3]
}

/// Where to centre the label `text` of `point`, `distance` from it: away from `centre` (off the
/// curves, which run inside the sphere's disc) when that is clear of every box in `taken` and of
/// the point's own mark (`mark` each way, how far its disc reaches: [`Pen::disc`]'s answer; a
/// label wider than twice `distance`, set beside its point, covered it, as "h(q): the nose" did
/// on a phone), else the first clear place turning from there by ±45°, ±90°, ±135°, 180°; away
/// from `centre` when none is. The label's box is added to `taken`.
pub fn clear_place(
    pen: &Pen,
    text: &str,
    (point, centre): ((f64, f64), (f64, f64)),
    mark: f64,
    distance: f64,
    size: f64,
    taken: &mut Vec<TextBox>,
) -> (f64, f64) {
    let away = outward(point, centre, distance);
    let (dx, dy) = (away.0 - point.0, away.1 - point.1);
    let turned = |degrees: f64| {
        let (sin, cos) = degrees.to_radians().sin_cos();
        (point.0 + dx * cos - dy * sin, point.1 + dx * sin + dy * cos)
    };
    let mark = [point.0 - mark, point.1 - mark, point.0 + mark, point.1 + mark];
    let place = [0.0, 45.0, -45.0, 90.0, -90.0, 135.0, -135.0, 180.0]
        .into_iter()
        .map(turned)
        .find(|&at| {
            let candidate = text_box(pen, text, at, size);
            !overlap(&mark, &candidate) && !taken.iter().any(|b| overlap(b, &candidate))
        })
        .unwrap_or(away);
    taken.push(text_box(pen, text, place, size));
    place
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn points_that_coincide_share_one_label() {
        let points = [(10.0, 10.0), (11.0, 10.5), (80.0, 40.0), (10.0, 30.0)];
        let names: Vec<String> = (0..4).map(|i| format!("k{i}")).collect();
        let groups = grouped_labels(&points, &names, 12.0);
        let labels: Vec<&str> = groups.iter().map(|(l, _)| l.as_str()).collect();
        assert_eq!(labels, ["k0, k1", "k2", "k3"]);
        assert_eq!(groups[0].1, (10.0, 10.0));
    }

    #[test]
    fn outward_moves_away_from_the_centre() {
        assert_eq!(outward((110.0, 100.0), (100.0, 100.0), 5.0), (115.0, 100.0));
        assert_eq!(outward((100.0, 90.0), (100.0, 100.0), 5.0), (100.0, 85.0));
        assert_eq!(outward((100.0, 100.0), (100.0, 100.0), 5.0), (100.0, 95.0));
    }
}
