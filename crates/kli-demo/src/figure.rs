//! The one run contract: every page class (one a page: the pages are listed once, in
//! `www/pages.js`) is a [`Figure`]. It says what it shows (its [`View`]s, each with a
//! name, a title and a [`Motion`]), owns its time (its span, the time on show, `seek` and
//! `advance` with its own bound on work), sums itself up in named fields, and paints any view
//! with any [`Pen`] at a [`Frame`]. [`figure_class!`] gives each class the
//! same JavaScript members from it: `views`, `span`, `time`, `seek(t)`, `advance(seconds)`,
//! `summary`, `draw(view, ctx, frame, layer?)`, `toSvg(view, frame)` and `export(kind, format)`.
//! The pages, `<kli-figure>` and the video recorder all drive a run through these alone
//! (`www/player.js`).

use js_sys::Reflect;
use kli::{ErrorKind, KliError};
use kli_wasm::error::JsResult;
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
    // The swarm is drawn as it is now: its page alone draws no time from a frame.
    #[cfg_attr(
        not(any(
            feature = "kli-page",
            feature = "keyframes-page",
            feature = "average-page",
            feature = "learn-page"
        )),
        allow(dead_code)
    )]
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
        let [azimuth, elevation] = crate::sphere_view::default_angles();
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

/// How a view follows the time: the page draws a `Moving` view whole every frame, a `Layered`
/// one as its still part (kept) with the moving part over it, and a `Still` one only when the
/// run, its size or the camera changes.
#[derive(Clone, Copy, PartialEq, Eq)]
#[cfg_attr(not(feature = "kli-page"), allow(dead_code))] // the swarm's views all move
pub(crate) enum Motion {
    Moving,
    Layered,
    Still,
}

impl Motion {
    fn name(self) -> &'static str {
        match self {
            Motion::Moving => "moving",
            Motion::Layered => "layered",
            Motion::Still => "still",
        }
    }
}

/// One of a page class's views: its name (the `view` of `draw`), its title (the SVG's
/// `<title>`) and how it follows the time.
pub(crate) struct View {
    pub name: &'static str,
    pub title: &'static str,
    pub motion: Motion,
}

/// A run's time, for the run contract: its span, the time on show, `seek` and `advance`. A run
/// with a span keeps a [`Clock`](crate::clock::Clock) and has this through it.
pub(crate) trait Timed {
    /// The span of the run's time, `(start, end)`; `end` is infinite for a run with no end (the
    /// swarm, which runs on as long as it is asked to).
    fn span(&self) -> (f64, f64);

    /// The time on show.
    fn time(&self) -> f64;

    /// Moves towards the time `t`; true once there. A run that must compute its way there (the
    /// swarm) takes a bounded piece of work a call, so a page calls again in its next task.
    fn seek(&mut self, t: f64) -> bool;

    /// Moves on by `seconds` of the page's clock (at speed 1), within the run's own bound on
    /// work a frame; true once at the end of the span.
    fn advance(&mut self, seconds: f64) -> bool;
}

/// A page class: the run contract (module docs), its views drawn with any [`Pen`], and its data
/// as CSV and JSON.
pub(crate) trait Figure: Timed {
    /// The views, in the page's order.
    const VIEWS: &'static [View];
    /// Their names (`&names::<N>(Self::VIEWS)`), for the message about a view it does not have.
    const NAMES: &'static [&'static str];
    /// What `export` writes (the first word of `export(kind, format)`).
    const EXPORT: &'static str;

    /// The run's figures as named fields, for readouts and tables.
    fn summary(&self) -> JsValue;

    /// Paints `layer` of `view` (one of `VIEWS`, matched by its name) at `frame`.
    fn paint(&self, view: &View, layer: Layer, pen: &Pen, frame: &Frame);

    /// The data behind the figures as CSV (`csv == true`) or JSON.
    fn export(&self, csv: bool) -> String;

    /// The index of the view named `name`, or an Error naming the argument `view`.
    fn view(name: &str) -> Result<usize, KliError> {
        Self::NAMES.iter().position(|n| *n == name).ok_or_else(|| {
            KliError::new("view", ErrorKind::UnknownName { got: name.into(), allowed: Self::NAMES })
        })
    }
}

/// A JavaScript object made field by field: the summaries and the views' list.
pub(crate) struct Record(js_sys::Object);

impl Record {
    pub fn new() -> Record {
        Record(js_sys::Object::new())
    }

    /// Adds `key: value` (setting a property on a fresh plain object cannot fail).
    pub fn set(self, key: &str, value: impl Into<JsValue>) -> Record {
        let _ = Reflect::set(&self.0, &key.into(), &value.into());
        self
    }

    pub fn end(self) -> JsValue {
        self.0.into()
    }
}

/// `views`, for [`figure_class!`]: `[{ name, title, kind }]`.
pub(crate) fn views<F: Figure>() -> JsValue {
    F::VIEWS
        .iter()
        .map(|v| {
            Record::new()
                .set("name", v.name)
                .set("title", v.title)
                .set("kind", v.motion.name())
                .end()
        })
        .collect::<js_sys::Array>()
        .into()
}

/// `span`, for [`figure_class!`]: `[start, end]`.
pub(crate) fn span<F: Figure>(figure: &F) -> Vec<f64> {
    let (start, end) = figure.span();
    vec![start, end]
}

/// The names of `views`, for a class's [`Figure::NAMES`]: `N` is their count (a wrong one fails
/// to compile).
pub(crate) const fn names<const N: usize>(views: &[View]) -> [&'static str; N] {
    let mut names = [""; N];
    let mut i = 0;
    while i < N {
        names[i] = views[i].name;
        i += 1;
    }
    names
}

/// `draw(view, ctx, frame, layer?)`, for [`figure_class!`].
pub(crate) fn draw<F: Figure>(
    figure: &F,
    view: &str,
    ctx: &CanvasRenderingContext2d,
    frame: &JsValue,
    layer: Option<String>,
) -> JsResult<()> {
    let (view, layer) = (F::view(view)?, Layer::read(layer)?);
    let frame = Frame::read(frame);
    let pen = if layer == Layer::Moving {
        Pen::over(ctx, frame.pixel_ratio)
    } else {
        Pen::begin(ctx, frame.width, frame.height, frame.pixel_ratio, BACKGROUND)
    };
    pen.scale_text(frame.text_scale);
    figure.paint(&F::VIEWS[view], layer, &pen, &frame);
    Ok(())
}

/// `toSvg(view, frame)`, for [`figure_class!`].
pub(crate) fn to_svg<F: Figure>(figure: &F, view: &str, frame: &JsValue) -> JsResult<String> {
    let view = F::view(view)?;
    let frame = Frame::read(frame);
    let paint = |pen: &Pen| {
        pen.scale_text(frame.text_scale);
        figure.paint(&F::VIEWS[view], Layer::Whole, pen, &frame)
    };
    Ok(svg_document(frame.width, frame.height, F::VIEWS[view].title, &paint))
}

/// `export(kind, format)`, for [`figure_class!`].
pub(crate) fn export<F: Figure>(figure: &F, kind: &str, format: &str) -> JsResult<String> {
    if kind != F::EXPORT {
        let allowed = std::slice::from_ref(&F::EXPORT);
        return Err(
            KliError::new("kind", ErrorKind::UnknownName { got: kind.into(), allowed }).into()
        );
    }
    match format {
        "csv" => Ok(figure.export(true)),
        "json" => Ok(figure.export(false)),
        other => {
            let allowed = &["csv", "json"];
            Err(KliError::new("format", ErrorKind::UnknownName { got: other.into(), allowed })
                .into())
        }
    }
}

/// A time to draw at: a non-finite one is drawn as t = 0.
pub(crate) fn finite(t: f64) -> f64 {
    if t.is_finite() { t } else { 0.0 }
}

/// The JavaScript members every page class has, written once: the run contract (module docs).
/// `$summary` is the TypeScript type of the class's `summary`.
macro_rules! figure_class {
    ($class:ident, $summary:literal) => {
        #[wasm_bindgen::prelude::wasm_bindgen]
        impl $class {
            /// The views, in the page's order: each one's `name` (for `draw`, `toSvg`), `title`
            /// and `kind` ("moving": drawn whole each frame; "layered": a still part with a
            /// moving part over it; "still": drawn only when the run, size or camera changes).
            #[wasm_bindgen(getter, unchecked_return_type = "ViewInfo[]")]
            pub fn views(&self) -> wasm_bindgen::JsValue {
                $crate::figure::views::<Self>()
            }

            /// The span of the run's time, `[start, end]`; `end` is `Infinity` for a run that
            /// has none (the swarm).
            #[wasm_bindgen(getter)]
            pub fn span(&self) -> Vec<f64> {
                $crate::figure::span(self)
            }

            /// The time on show.
            #[wasm_bindgen(getter)]
            pub fn time(&self) -> f64 {
                $crate::figure::Timed::time(self)
            }

            /// Moves towards the time `t` (within the span); true once there. A run that
            /// computes its way there (the swarm) takes a bounded piece of work a call: call
            /// again, in a later task, until it returns true.
            pub fn seek(&mut self, t: f64) -> bool {
                $crate::figure::Timed::seek(self, t)
            }

            /// Moves on by `seconds` of a page's clock at speed 1, within the run's bound on
            /// work a frame; true once at the end of the span.
            pub fn advance(&mut self, seconds: f64) -> bool {
                $crate::figure::Timed::advance(self, seconds)
            }

            /// The run's figures as named fields.
            #[wasm_bindgen(getter, unchecked_return_type = $summary)]
            pub fn summary(&self) -> wasm_bindgen::JsValue {
                $crate::figure::Figure::summary(self)
            }

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
pub(crate) use figure_class;

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
/** One of a run's views: its name (for `draw`, `toSvg`), its title, and how it follows the time. */
export interface ViewInfo {
  name: string;
  title: string;
  kind: "moving" | "layered" | "still";
}
"#;
