//! The one figure interface: every page class ([`crate::Demo`], [`crate::SwarmDemo`],
//! [`crate::KeyframesDemo`]) is a [`Figure`] with named views, painted with any [`Pen`] at a
//! [`Frame`]. [`figure_class!`](crate::figure_class) gives each class the same three JavaScript
//! methods from it: `draw(view, ctx, frame, layer?)`, `toSvg(view, frame)` and
//! `export(kind, format)`.

use js_sys::Reflect;
use kli::{ErrorKind, KliError};
use kli_wasm::error::{JsResult, throw};
use wasm_bindgen::prelude::*;
use web_sys::CanvasRenderingContext2d;

use crate::camera::{Camera, Viewport};
use crate::palette::BACKGROUND;
use crate::pen::{MAX_TEXT_SCALE, MIN_TEXT_SCALE, Pen, size, svg_document};

/// What a view is drawn at: its size in CSS pixels, device pixels per CSS pixel, the time,
/// where the sphere views are seen from, and the text's scale. Read from the page's `{ width, height, pixelRatio, t,
/// azimuth, elevation }`; what is missing or not a finite number takes its default (1 × 1 px at
/// ratio 1, t = 0, the default camera), so drawing never fails.
pub(crate) struct Frame {
    pub width: f64,
    pub height: f64,
    pub pixel_ratio: f64,
    // The swarm runs on its own clock: its page alone draws no time from a frame.
    #[cfg_attr(not(any(feature = "kli-page", feature = "keyframes-page")), allow(dead_code))]
    pub t: f64,
    pub camera: Camera,
    /// Every text's size is multiplied by this (0.5 to 4).
    pub text_scale: f64,
}

impl Frame {
    pub fn read(frame: &JsValue) -> Frame {
        // Reflect.get catches a throwing getter or Proxy trap: the field is then missing.
        let field = |index: usize| {
            FIELDS
                .with(|names| Reflect::get(frame, &names[index]).ok())
                .and_then(|v| v.as_f64())
                .filter(|v| v.is_finite())
        };
        let [azimuth, elevation] = crate::default_angles();
        Frame {
            width: size(field(0).unwrap_or(1.0)),
            height: size(field(1).unwrap_or(1.0)),
            pixel_ratio: field(2).unwrap_or(1.0).clamp(0.1, 16.0),
            t: finite(field(3).unwrap_or(0.0)),
            camera: Camera::orbit(field(4).unwrap_or(azimuth), field(5).unwrap_or(elevation)),
            text_scale: field(6).unwrap_or(1.0).clamp(MIN_TEXT_SCALE, MAX_TEXT_SCALE),
        }
    }

    /// The viewport of a view that shows the whole sphere.
    pub fn sphere_viewport(&self) -> Viewport {
        Viewport::fitting(0.0, 0.0, self.width, self.height, 1.22)
    }
}

thread_local! {
    /// A frame's field names as JavaScript strings, made once: every view reads a frame every
    /// animation frame.
    static FIELDS: [JsValue; 7] = ["width", "height", "pixelRatio", "t", "azimuth", "elevation", "textScale"]
        .map(JsValue::from_str);
}

/// Which part of a view to draw. A page keeps the still part of a view (it changes only with
/// the run, the size or the camera) in an offscreen layer, and draws the moving part (what
/// follows the time) over a copy of it each frame.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(crate) enum Layer {
    Whole,
    Still,
    Moving,
}

impl Layer {
    fn read(layer: Option<String>) -> Result<Layer, KliError> {
        match layer.as_deref() {
            None | Some("whole") => Ok(Layer::Whole),
            Some("still") => Ok(Layer::Still),
            Some("moving") => Ok(Layer::Moving),
            Some(other) => Err(KliError::new(
                "layer",
                ErrorKind::UnknownName {
                    got: other.into(),
                    allowed: &["whole", "still", "moving"],
                },
            )),
        }
    }

    /// Whether the still part (all of a view that has no moving part) is drawn in this layer.
    pub fn still(self) -> bool {
        self != Layer::Moving
    }
}

/// A page class: views drawn with any [`Pen`], and its data as CSV and JSON.
pub(crate) trait Figure {
    /// The views' names.
    const VIEWS: &'static [&'static str];
    /// Each view's title (the SVG's `<title>`), in the order of `VIEWS`.
    const TITLES: &'static [&'static str];
    /// What `export` writes (the first word of `export(kind, format)`).
    const EXPORT: &'static str;

    /// Paints `layer` of the view `VIEWS[view]` at `frame`.
    fn paint(&self, view: usize, layer: Layer, pen: &Pen, frame: &Frame);

    /// The data behind the figures as CSV (`csv == true`) or JSON.
    fn export(&self, csv: bool) -> String;

    /// The index of the view named `name`, or an Error naming the argument `view`.
    fn view(name: &str) -> Result<usize, KliError> {
        Self::VIEWS.iter().position(|n| *n == name).ok_or_else(|| {
            KliError::new("view", ErrorKind::UnknownName { got: name.into(), allowed: Self::VIEWS })
        })
    }
}

/// `draw(view, ctx, frame, layer?)`, for [`figure_class!`](crate::figure_class).
pub(crate) fn draw<F: Figure>(
    figure: &F,
    view: &str,
    ctx: &CanvasRenderingContext2d,
    frame: &JsValue,
    layer: Option<String>,
) -> JsResult<()> {
    let (view, layer) = (F::view(view).map_err(throw)?, Layer::read(layer).map_err(throw)?);
    let frame = Frame::read(frame);
    let pen = if layer == Layer::Moving {
        Pen::over(ctx, frame.pixel_ratio)
    } else {
        Pen::begin(ctx, frame.width, frame.height, frame.pixel_ratio, BACKGROUND)
    };
    pen.scale_text(frame.text_scale);
    figure.paint(view, layer, &pen, &frame);
    Ok(())
}

/// `toSvg(view, frame)`, for [`figure_class!`](crate::figure_class).
pub(crate) fn to_svg<F: Figure>(figure: &F, view: &str, frame: &JsValue) -> JsResult<String> {
    let view = F::view(view).map_err(throw)?;
    let frame = Frame::read(frame);
    let paint = |pen: &Pen| {
        pen.scale_text(frame.text_scale);
        figure.paint(view, Layer::Whole, pen, &frame)
    };
    Ok(svg_document(frame.width, frame.height, F::TITLES[view], &paint))
}

/// `export(kind, format)`, for [`figure_class!`](crate::figure_class).
pub(crate) fn export<F: Figure>(figure: &F, kind: &str, format: &str) -> JsResult<String> {
    if kind != F::EXPORT {
        let allowed = std::slice::from_ref(&F::EXPORT);
        return Err(throw(KliError::new(
            "kind",
            ErrorKind::UnknownName { got: kind.into(), allowed },
        )));
    }
    match format {
        "csv" => Ok(figure.export(true)),
        "json" => Ok(figure.export(false)),
        other => Err(throw(KliError::new(
            "format",
            ErrorKind::UnknownName { got: other.into(), allowed: &["csv", "json"] },
        ))),
    }
}

/// A time to draw at: a non-finite one is drawn as t = 0.
pub(crate) fn finite(t: f64) -> f64 {
    if t.is_finite() { t } else { 0.0 }
}

/// The JavaScript methods every page class has, written once: `draw`, `toSvg` and `export`.
#[macro_export]
macro_rules! figure_class {
    ($class:ident) => {
        #[wasm_bindgen::prelude::wasm_bindgen]
        impl $class {
            /// Draws `view` onto `ctx` at `frame` (`{ width, height, pixelRatio, t, azimuth,
            /// elevation }`, CSS pixels and radians): the whole view, or with `layer` "still"
            /// the part that does not follow the time, or "moving" the part that does, over it.
            pub fn draw(
                &self,
                view: &str,
                ctx: &web_sys::CanvasRenderingContext2d,
                #[wasm_bindgen(unchecked_param_type = "Frame")] frame: &wasm_bindgen::JsValue,
                #[wasm_bindgen(unchecked_param_type = "Layer | undefined")] layer: Option<String>,
            ) -> kli_wasm::error::JsResult<()> {
                $crate::figure::draw(self, view, ctx, frame, layer)
            }

            /// `view` at `frame` as an SVG document: vector paths and text, as `draw` paints it.
            #[wasm_bindgen(js_name = toSvg)]
            pub fn to_svg(
                &self,
                view: &str,
                #[wasm_bindgen(unchecked_param_type = "Frame")] frame: &wasm_bindgen::JsValue,
            ) -> kli_wasm::error::JsResult<String> {
                $crate::figure::to_svg(self, view, frame)
            }

            /// The data behind the figures, as `format` "csv" or "json".
            pub fn export(&self, kind: &str, format: &str) -> kli_wasm::error::JsResult<String> {
                $crate::figure::export(self, kind, format)
            }
        }
    };
}

#[wasm_bindgen(typescript_custom_section)]
const TYPES: &'static str = r#"
/** What a view is drawn at: CSS pixels, device pixels per CSS pixel, the time, and where the
 *  sphere views are seen from (radians). Missing or non-finite fields take their defaults. */
export interface Frame {
  width: number;
  height: number;
  pixelRatio?: number;
  t?: number;
  azimuth?: number;
  elevation?: number;
  /** Every text's size is multiplied by this, 0.5 to 4 (default 1): larger labels for a projector. */
  textScale?: number;
}
/** The part of a view to draw: all of it, the part that does not follow the time, or the part
 *  that does (over the still part). */
export type Layer = "whole" | "still" | "moving";
"#;
