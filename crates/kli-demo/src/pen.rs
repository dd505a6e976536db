//! The one drawing interface of the views: the few calls they need, in CSS pixels, onto either a
//! canvas 2D context (the live pages, PNG export) or an SVG document (vector export: real paths,
//! circles and text, not a bitmap). Drawing errors (only possible for non-finite coordinates) are
//! ignored rather than unwrapped: nothing here may panic.

use std::cell::{Cell, RefCell};
use std::fmt::Write;

use js_sys::Array;
use kli::{ErrorKind, KliError};
use wasm_bindgen::JsValue;
use web_sys::CanvasRenderingContext2d;

use crate::aircraft::Rgb;
use crate::format::number;
use crate::palette::BACKGROUND;

/// Where a [`Pen`] draws.
enum Surface<'a> {
    Canvas(&'a CanvasRenderingContext2d),
    /// The SVG document so far, and the count of gradients defined in it (for their ids).
    Svg(RefCell<String>, Cell<usize>),
}

/// Draws on one canvas context or into one SVG document.
pub struct Pen<'a> {
    surface: Surface<'a>,
    /// The opacity of what is drawn next (the canvas keeps its own; SVG elements carry it).
    opacity: Cell<f64>,
    /// Every text's size is multiplied by this (a projector's larger labels: issue 15).
    text_scale: Cell<f64>,
}

/// `rgb(…)` of a colour scaled by `light` (1 = as is).
pub fn shade(color: Rgb, light: f64) -> String {
    #[allow(clippy::manual_clamp)] // f64::clamp can panic; nothing drawn may
    let [r, g, b] = color.map(|c| (c as f64 * light).round().max(0.0).min(255.0) as u8);
    format!("rgb({r},{g},{b})")
}

const FONT: &str = "system-ui, -apple-system, 'Segoe UI', sans-serif";

fn ratio_or_one(pixel_ratio: f64) -> f64 {
    if pixel_ratio.is_finite() && pixel_ratio > 0.0 { pixel_ratio } else { 1.0 }
}

/// Text safe inside SVG elements and attribute values.
fn escape(text: &str) -> String {
    text.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

/// A coordinate in SVG: two decimals (a hundredth of a CSS pixel), non-finite as 0, written by
/// JavaScript (Rust's float formatting would add its code to the module).
fn n(x: f64) -> String {
    number(if x.is_finite() { (x * 100.0).round() / 100.0 } else { 0.0 })
}

impl<'a> Pen<'a> {
    /// Resets the transform to `pixel_ratio` (so the views draw in CSS pixels on a high-DPI
    /// backing store) and fills the whole canvas with `background`.
    pub fn begin(
        ctx: &'a CanvasRenderingContext2d,
        width: f64,
        height: f64,
        pixel_ratio: f64,
        background: &str,
    ) -> Self {
        let ratio = ratio_or_one(pixel_ratio);
        let _ = ctx.set_transform(ratio, 0.0, 0.0, ratio, 0.0, 0.0);
        ctx.set_global_alpha(1.0);
        let _ = ctx.set_line_dash(&Array::new());
        ctx.set_fill_style_str(background);
        ctx.fill_rect(0.0, 0.0, width, height);
        ctx.set_line_join("round");
        ctx.set_line_cap("round");
        Self { surface: Surface::Canvas(ctx), opacity: Cell::new(1.0), text_scale: Cell::new(1.0) }
    }

    /// Draws over what the canvas holds (no clearing), in CSS pixels at `pixel_ratio`.
    pub fn over(ctx: &'a CanvasRenderingContext2d, pixel_ratio: f64) -> Self {
        let ratio = ratio_or_one(pixel_ratio);
        let _ = ctx.set_transform(ratio, 0.0, 0.0, ratio, 0.0, 0.0);
        ctx.set_global_alpha(1.0);
        Self { surface: Surface::Canvas(ctx), opacity: Cell::new(1.0), text_scale: Cell::new(1.0) }
    }

    /// A new SVG document `width` × `height` CSS pixels, filled with `background`; `title` is its
    /// accessible name. [`Pen::finish`] returns the text.
    pub fn svg(width: f64, height: f64, background: &str, title: &str) -> Pen<'static> {
        let (w, h) = (n(width.max(1.0)), n(height.max(1.0)));
        let mut doc = format!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" \
             viewBox=\"0 0 {w} {h}\" role=\"img\" font-family=\"{FONT}\" \
             stroke-linecap=\"round\" stroke-linejoin=\"round\">\n<title>{}</title>\n",
            escape(title)
        );
        let _ = writeln!(doc, "<rect width=\"{w}\" height=\"{h}\" fill=\"{background}\"/>");
        Pen {
            surface: Surface::Svg(RefCell::new(doc), Cell::new(0)),
            opacity: Cell::new(1.0),
            text_scale: Cell::new(1.0),
        }
    }

    /// The SVG document, closed (empty for a canvas pen).
    pub fn finish(self) -> String {
        match self.surface {
            Surface::Svg(doc, _) => doc.into_inner() + "</svg>\n",
            Surface::Canvas(_) => String::new(),
        }
    }

    /// Appends an SVG element, with the current opacity.
    fn element(&self, doc: &RefCell<String>, tag: &str, attributes: &str, text: Option<&str>) {
        let mut doc = doc.borrow_mut();
        let opacity = self.opacity.get();
        let _ = write!(doc, "<{tag} {attributes}");
        if opacity < 1.0 {
            let _ = write!(doc, " opacity=\"{}\"", n(opacity));
        }
        match text {
            Some(text) => {
                let _ = writeln!(doc, ">{}</{tag}>", escape(text));
            }
            None => doc.push_str("/>\n"),
        }
    }

    pub fn alpha(&self, alpha: f64) {
        self.opacity.set(alpha);
        if let Surface::Canvas(ctx) = self.surface {
            ctx.set_global_alpha(alpha);
        }
    }

    fn trace(ctx: &CanvasRenderingContext2d, points: &[(f64, f64)]) {
        ctx.begin_path();
        for (i, &(x, y)) in points.iter().enumerate() {
            if i == 0 { ctx.move_to(x, y) } else { ctx.line_to(x, y) }
        }
    }

    fn points(points: &[(f64, f64)]) -> String {
        let mut text = String::with_capacity(points.len() * 14);
        for (i, &(x, y)) in points.iter().enumerate() {
            let _ = write!(text, "{}{},{}", if i == 0 { "" } else { " " }, n(x), n(y));
        }
        text
    }

    pub fn fill_polygon(&self, points: &[(f64, f64)], fill: &str, outline: Option<&str>) {
        match &self.surface {
            Surface::Canvas(ctx) => {
                Self::trace(ctx, points);
                ctx.close_path();
                ctx.set_fill_style_str(fill);
                ctx.fill();
                if let Some(color) = outline {
                    ctx.set_stroke_style_str(color);
                    ctx.set_line_width(0.6);
                    ctx.stroke();
                }
            }
            Surface::Svg(doc, _) => {
                let stroke = outline
                    .map(|c| format!(" stroke=\"{c}\" stroke-width=\"0.6\""))
                    .unwrap_or_default();
                let attributes =
                    format!("points=\"{}\" fill=\"{fill}\"{stroke}", Self::points(points));
                self.element(doc, "polygon", &attributes, None);
            }
        }
    }

    /// A polyline; `dash` is `[on, off]` in pixels, empty for solid.
    pub fn polyline(&self, points: &[(f64, f64)], color: &str, width: f64, dash: &[f64]) {
        if points.len() < 2 {
            return;
        }
        match &self.surface {
            Surface::Canvas(ctx) => {
                let pattern: Array = dash.iter().map(|&d| JsValue::from_f64(d)).collect();
                let _ = ctx.set_line_dash(&pattern);
                Self::trace(ctx, points);
                ctx.set_stroke_style_str(color);
                ctx.set_line_width(width);
                ctx.stroke();
                let _ = ctx.set_line_dash(&Array::new());
            }
            Surface::Svg(doc, _) => {
                let mut attributes = format!(
                    "points=\"{}\" fill=\"none\" stroke=\"{color}\" stroke-width=\"{}\"",
                    Self::points(points),
                    n(width)
                );
                if !dash.is_empty() {
                    let pattern: Vec<String> = dash.iter().map(|&d| n(d)).collect();
                    let _ = write!(attributes, " stroke-dasharray=\"{}\"", pattern.join(" "));
                }
                self.element(doc, "polyline", &attributes, None);
            }
        }
    }

    /// Many separate segments of one stroke, as one path: a thousand edges of a graph cost one
    /// stroke, not a thousand.
    pub fn segments(&self, segments: &[[(f64, f64); 2]], color: &str, width: f64, dash: &[f64]) {
        if segments.is_empty() {
            return;
        }
        match &self.surface {
            Surface::Canvas(ctx) => {
                let pattern: Array = dash.iter().map(|&d| JsValue::from_f64(d)).collect();
                let _ = ctx.set_line_dash(&pattern);
                ctx.begin_path();
                for [(x0, y0), (x1, y1)] in segments {
                    ctx.move_to(*x0, *y0);
                    ctx.line_to(*x1, *y1);
                }
                ctx.set_stroke_style_str(color);
                ctx.set_line_width(width);
                ctx.stroke();
                let _ = ctx.set_line_dash(&Array::new());
            }
            Surface::Svg(doc, _) => {
                let mut path = String::with_capacity(segments.len() * 28);
                for [(x0, y0), (x1, y1)] in segments {
                    let _ = write!(path, "M{},{}L{},{}", n(*x0), n(*y0), n(*x1), n(*y1));
                }
                let mut attributes = format!(
                    "d=\"{path}\" fill=\"none\" stroke=\"{color}\" stroke-width=\"{}\"",
                    n(width)
                );
                if !dash.is_empty() {
                    let pattern: Vec<String> = dash.iter().map(|&d| n(d)).collect();
                    let _ = write!(attributes, " stroke-dasharray=\"{}\"", pattern.join(" "));
                }
                self.element(doc, "path", &attributes, None);
            }
        }
    }

    pub fn line(&self, from: (f64, f64), to: (f64, f64), color: &str, width: f64, dash: &[f64]) {
        self.polyline(&[from, to], color, width, dash);
    }

    /// A disc of radius `r`, optionally ringed; returns how far it reaches from its centre, the
    /// ring stroked on its edge with half its width outside (the mark a label keeps clear of:
    /// [`crate::legend::clear_place`]).
    pub fn disc(
        &self,
        (x, y): (f64, f64),
        r: f64,
        fill: Option<&str>,
        ring: Option<(&str, f64)>,
    ) -> f64 {
        match &self.surface {
            Surface::Canvas(ctx) => {
                ctx.begin_path();
                let _ = ctx.arc(x, y, r, 0.0, std::f64::consts::TAU);
                if let Some(fill) = fill {
                    ctx.set_fill_style_str(fill);
                    ctx.fill();
                }
                if let Some((color, width)) = ring {
                    ctx.set_stroke_style_str(color);
                    ctx.set_line_width(width);
                    ctx.stroke();
                }
            }
            Surface::Svg(doc, _) => {
                let mut attributes = format!(
                    "cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"{}\"",
                    n(x),
                    n(y),
                    n(r),
                    fill.unwrap_or("none")
                );
                if let Some((color, width)) = ring {
                    let _ = write!(attributes, " stroke=\"{color}\" stroke-width=\"{}\"", n(width));
                }
                self.element(doc, "circle", &attributes, None);
            }
        }
        r + ring.map_or(0.0, |(_, width)| 0.5 * width)
    }

    /// Discs of radius `r` at every point, filled in one path (one call for many points).
    pub fn dots(&self, points: &[(f64, f64)], r: f64, fill: &str) {
        if points.is_empty() {
            return;
        }
        match &self.surface {
            Surface::Canvas(ctx) => {
                ctx.begin_path();
                for &(x, y) in points {
                    ctx.move_to(x + r, y);
                    let _ = ctx.arc(x, y, r, 0.0, std::f64::consts::TAU);
                }
                ctx.set_fill_style_str(fill);
                ctx.fill();
            }
            Surface::Svg(doc, _) => {
                // Each disc as two half-circle arcs: one path element for all of them.
                let mut d = String::with_capacity(points.len() * 40);
                let (r_, d2) = (n(r), n(2.0 * r));
                for &(x, y) in points {
                    let _ = write!(
                        d,
                        "M{},{}a{r_},{r_} 0 1 0 {d2},0a{r_},{r_} 0 1 0 -{d2},0",
                        n(x - r),
                        n(y)
                    );
                }
                self.element(doc, "path", &format!("d=\"{d}\" fill=\"{fill}\""), None);
            }
        }
    }

    /// A disc shaded as a sphere lit from the upper left.
    pub fn shaded_disc(&self, (x, y): (f64, f64), r: f64, light: &str, dark: &str) {
        match &self.surface {
            Surface::Canvas(ctx) => {
                if let Ok(gradient) =
                    ctx.create_radial_gradient(x - 0.35 * r, y - 0.4 * r, 0.05 * r, x, y, r)
                {
                    let _ = gradient.add_color_stop(0.0, light);
                    let _ = gradient.add_color_stop(1.0, dark);
                    ctx.set_fill_style_canvas_gradient(&gradient);
                    ctx.begin_path();
                    let _ = ctx.arc(x, y, r, 0.0, std::f64::consts::TAU);
                    ctx.fill();
                }
            }
            Surface::Svg(doc, gradients) => {
                let id = gradients.get();
                gradients.set(id + 1);
                let _ = writeln!(
                    doc.borrow_mut(),
                    "<defs><radialGradient id=\"shade{id}\" gradientUnits=\"userSpaceOnUse\" \
                     cx=\"{}\" cy=\"{}\" r=\"{}\" fx=\"{}\" fy=\"{}\" fr=\"{}\">\
                     <stop offset=\"0\" stop-color=\"{light}\"/><stop offset=\"1\" \
                     stop-color=\"{dark}\"/></radialGradient></defs>",
                    n(x),
                    n(y),
                    n(r),
                    n(x - 0.35 * r),
                    n(y - 0.4 * r),
                    n(0.05 * r)
                );
                let attributes = format!(
                    "cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"url(#shade{id})\"",
                    n(x),
                    n(y),
                    n(r)
                );
                self.element(doc, "circle", &attributes, None);
            }
        }
    }

    /// Scales every text drawn from now on by `scale` (from [`MIN_TEXT_SCALE`] to
    /// [`MAX_TEXT_SCALE`]; anything else, non-finite included, is clamped or taken as 1).
    pub fn scale_text(&self, scale: f64) {
        let scale =
            if scale.is_finite() { scale.clamp(MIN_TEXT_SCALE, MAX_TEXT_SCALE) } else { 1.0 };
        self.text_scale.set(scale);
    }

    /// The factor texts are drawn at (see [`Pen::scale_text`]).
    pub fn text_scale(&self) -> f64 {
        self.text_scale.get()
    }

    /// Text at `(x, y)`; `align` is "left", "center" or "right", the baseline is the middle.
    /// `size` is multiplied by the pen's text scale.
    pub fn text(&self, text: &str, (x, y): (f64, f64), color: &str, size: f64, align: &str) {
        let size = size * self.text_scale.get();
        match &self.surface {
            Surface::Canvas(ctx) => {
                ctx.set_font(&font(size));
                ctx.set_text_align(align);
                ctx.set_text_baseline("middle");
                ctx.set_fill_style_str(color);
                let _ = ctx.fill_text(text, x, y);
            }
            Surface::Svg(doc, _) => {
                let anchor = match align {
                    "center" => "middle",
                    "right" => "end",
                    _ => "start",
                };
                let attributes = format!(
                    "x=\"{}\" y=\"{}\" fill=\"{color}\" font-size=\"{}\" text-anchor=\"{anchor}\" \
                     dominant-baseline=\"central\"",
                    n(x),
                    n(y),
                    n(size)
                );
                self.element(doc, "text", &attributes, Some(text));
            }
        }
    }

    /// The width of `text` in CSS pixels at `size` (in SVG, where the viewer's font decides, an
    /// estimate by `em_width`).
    pub fn text_width(&self, text: &str, size: f64) -> f64 {
        let size = size * self.text_scale.get();
        match &self.surface {
            Surface::Canvas(ctx) => {
                ctx.set_font(&font(size));
                ctx.measure_text(text).map(|m| m.width()).unwrap_or(0.0)
            }
            Surface::Svg(..) => size * text.chars().map(em_width).sum::<f64>(),
        }
    }
}

/// `paint` drawn into a new SVG document of `width` × `height` CSS pixels on the pages' background,
/// titled `title`: the document's text. What every class's `toSvg` returns.
pub fn svg_document(width: f64, height: f64, title: &str, paint: &dyn Fn(&Pen)) -> String {
    let pen = Pen::svg(width, height, BACKGROUND, title);
    paint(&pen);
    pen.finish()
}

/// The range of the text scale (a figure's `textScale`).
pub const MIN_TEXT_SCALE: f64 = 0.5;
pub const MAX_TEXT_SCALE: f64 = 4.0;

/// A figure's side in CSS pixels: 1 to 10⁴ (a non-finite size is 1).
pub fn size(x: f64) -> f64 {
    if x.is_finite() { x.clamp(1.0, 1e4) } else { 1.0 }
}

/// The error for a figure name `toSvg` does not know.
pub fn unknown_view(got: &str, allowed: &'static [&'static str]) -> KliError {
    KliError::new("view", ErrorKind::UnknownName { got: got.into(), allowed })
}

/// A character's advance in em in DejaVu Sans, the font Chromium uses for `system-ui` on Linux
/// (measured there; Segoe UI and San Francisco are a little narrower): where an SVG is laid
/// out without a font to measure, labels then sit within a pixel of where the live canvas puts
/// them. Letters and digits from DejaVu's own advances, other characters by class.
fn em_width(c: char) -> f64 {
    const LOWER: [f64; 26] = [
        0.613, 0.635, 0.550, 0.635, 0.615, 0.352, 0.635, 0.634, 0.278, 0.278, 0.579, 0.278, 0.974,
        0.634, 0.612, 0.635, 0.635, 0.411, 0.521, 0.392, 0.634, 0.592, 0.818, 0.592, 0.592, 0.525,
    ];
    const UPPER: [f64; 26] = [
        0.684, 0.686, 0.698, 0.770, 0.632, 0.575, 0.775, 0.752, 0.295, 0.295, 0.656, 0.557, 0.863,
        0.748, 0.787, 0.603, 0.787, 0.695, 0.635, 0.611, 0.732, 0.684, 0.989, 0.685, 0.611, 0.685,
    ];
    match c {
        'a'..='z' => LOWER[c as usize - 'a' as usize],
        'A'..='Z' => UPPER[c as usize - 'A' as usize],
        '0'..='9' => 0.636,
        '\'' => 0.275,
        ' ' | '.' | ',' => 0.3179,
        ':' | ';' | '|' | '/' => 0.337,
        '-' => 0.361,
        '(' | ')' | '[' | ']' => 0.39,
        '=' | '+' | '<' | '>' | '−' | '#' => 0.838,
        _ => 0.6,
    }
}

fn font(size: f64) -> String {
    let tenths = (size * 10.0).round() as u32;
    format!("{}.{}px {FONT}", tenths / 10, tenths % 10)
}
