//! A thin layer over the canvas 2D context: the few drawing calls the views need, in CSS pixels.
//! Drawing errors (only possible for non-finite coordinates) are ignored rather than unwrapped:
//! nothing here may panic.

use js_sys::Array;
use wasm_bindgen::JsValue;
use web_sys::CanvasRenderingContext2d;

use crate::aircraft::Rgb;

/// Draws on one canvas context.
pub struct Pen<'a> {
    ctx: &'a CanvasRenderingContext2d,
}

/// `rgb(…)` of a colour scaled by `light` (1 = as is).
pub fn shade(color: Rgb, light: f64) -> String {
    #[allow(clippy::manual_clamp)] // f64::clamp can panic; nothing drawn may
    let [r, g, b] = color.map(|c| (c as f64 * light).round().max(0.0).min(255.0) as u8);
    format!("rgb({r},{g},{b})")
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
        let ratio = if pixel_ratio.is_finite() && pixel_ratio > 0.0 { pixel_ratio } else { 1.0 };
        let _ = ctx.set_transform(ratio, 0.0, 0.0, ratio, 0.0, 0.0);
        ctx.set_global_alpha(1.0);
        let _ = ctx.set_line_dash(&Array::new());
        ctx.set_fill_style_str(background);
        ctx.fill_rect(0.0, 0.0, width, height);
        ctx.set_line_join("round");
        ctx.set_line_cap("round");
        Self { ctx }
    }

    /// Draws over what the canvas holds (no clearing), in CSS pixels at `pixel_ratio`.
    pub fn over(ctx: &'a CanvasRenderingContext2d, pixel_ratio: f64) -> Self {
        let ratio = if pixel_ratio.is_finite() && pixel_ratio > 0.0 { pixel_ratio } else { 1.0 };
        let _ = ctx.set_transform(ratio, 0.0, 0.0, ratio, 0.0, 0.0);
        ctx.set_global_alpha(1.0);
        Self { ctx }
    }

    pub fn context(&self) -> &CanvasRenderingContext2d {
        self.ctx
    }

    pub fn alpha(&self, alpha: f64) {
        self.ctx.set_global_alpha(alpha);
    }

    fn trace(&self, points: &[(f64, f64)]) {
        self.ctx.begin_path();
        for (i, &(x, y)) in points.iter().enumerate() {
            if i == 0 { self.ctx.move_to(x, y) } else { self.ctx.line_to(x, y) }
        }
    }

    pub fn fill_polygon(&self, points: &[(f64, f64)], fill: &str, outline: Option<&str>) {
        self.trace(points);
        self.ctx.close_path();
        self.ctx.set_fill_style_str(fill);
        self.ctx.fill();
        if let Some(color) = outline {
            self.ctx.set_stroke_style_str(color);
            self.ctx.set_line_width(0.6);
            self.ctx.stroke();
        }
    }

    /// A polyline; `dash` is `[on, off]` in pixels, empty for solid.
    pub fn polyline(&self, points: &[(f64, f64)], color: &str, width: f64, dash: &[f64]) {
        if points.len() < 2 {
            return;
        }
        let pattern: Array = dash.iter().map(|&d| JsValue::from_f64(d)).collect();
        let _ = self.ctx.set_line_dash(&pattern);
        self.trace(points);
        self.ctx.set_stroke_style_str(color);
        self.ctx.set_line_width(width);
        self.ctx.stroke();
        let _ = self.ctx.set_line_dash(&Array::new());
    }

    pub fn line(&self, from: (f64, f64), to: (f64, f64), color: &str, width: f64, dash: &[f64]) {
        self.polyline(&[from, to], color, width, dash);
    }

    /// A disc of radius `r`, optionally ringed.
    pub fn disc(&self, (x, y): (f64, f64), r: f64, fill: Option<&str>, ring: Option<(&str, f64)>) {
        self.ctx.begin_path();
        let _ = self.ctx.arc(x, y, r, 0.0, std::f64::consts::TAU);
        if let Some(fill) = fill {
            self.ctx.set_fill_style_str(fill);
            self.ctx.fill();
        }
        if let Some((color, width)) = ring {
            self.ctx.set_stroke_style_str(color);
            self.ctx.set_line_width(width);
            self.ctx.stroke();
        }
    }

    /// Discs of radius `r` at every point, filled in one path (one call for many points).
    pub fn dots(&self, points: &[(f64, f64)], r: f64, fill: &str) {
        if points.is_empty() {
            return;
        }
        self.ctx.begin_path();
        for &(x, y) in points {
            self.ctx.move_to(x + r, y);
            let _ = self.ctx.arc(x, y, r, 0.0, std::f64::consts::TAU);
        }
        self.ctx.set_fill_style_str(fill);
        self.ctx.fill();
    }

    /// A disc shaded as a sphere lit from the upper left.
    pub fn shaded_disc(&self, (x, y): (f64, f64), r: f64, light: &str, dark: &str) {
        if let Ok(gradient) =
            self.ctx.create_radial_gradient(x - 0.35 * r, y - 0.4 * r, 0.05 * r, x, y, r)
        {
            let _ = gradient.add_color_stop(0.0, light);
            let _ = gradient.add_color_stop(1.0, dark);
            self.ctx.set_fill_style_canvas_gradient(&gradient);
            self.ctx.begin_path();
            let _ = self.ctx.arc(x, y, r, 0.0, std::f64::consts::TAU);
            self.ctx.fill();
        }
    }

    /// Text at `(x, y)`; `align` is "left", "center" or "right", the baseline is the middle.
    pub fn text(&self, text: &str, (x, y): (f64, f64), color: &str, size: f64, align: &str) {
        self.font(size);
        self.ctx.set_text_align(align);
        self.ctx.set_text_baseline("middle");
        self.ctx.set_fill_style_str(color);
        let _ = self.ctx.fill_text(text, x, y);
    }

    /// The width of `text` in CSS pixels at `size`.
    pub fn text_width(&self, text: &str, size: f64) -> f64 {
        self.font(size);
        self.ctx.measure_text(text).map(|m| m.width()).unwrap_or(0.0)
    }

    fn font(&self, size: f64) {
        let tenths = (size * 10.0).round() as u32;
        self.ctx.set_font(&format!(
            "{}.{}px system-ui, -apple-system, 'Segoe UI', sans-serif",
            tenths / 10,
            tenths % 10
        ));
    }
}
