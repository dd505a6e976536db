//! The demo page's boundary: one [`Demo`] per choice of `p`, `r` and options, holding the
//! computed [`Scene`] and drawing its views onto canvas contexts the page passes in.

use wasm_bindgen::prelude::*;
use web_sys::CanvasRenderingContext2d;

use super::{KliOptionsObject, QuaternionLike, error, options, quaternion, to_array};
use crate::render::aircraft::{Face, aircraft};
use crate::render::camera::{Camera, Viewport};
use crate::render::object_view::{draw_object, object_camera};
use crate::render::pen::{INK, KLI, MUTED, Pen, SLERP, fixed, number};
use crate::render::plots::{draw_plot_cursors, draw_plots};
use crate::render::scene::Scene;
use crate::render::sphere_view::{draw_sphere, draw_sphere_cursor, sphere_camera};

const BACKGROUND: &str = "#ffffff";

/// The KLI run behind the demo page, and its canvas views.
#[wasm_bindgen]
pub struct Demo {
    scene: Scene,
    mesh: Vec<Face>,
}

#[wasm_bindgen]
impl Demo {
    /// Runs KLI from p to r with the same arguments, checks and errors as `kli`.
    #[wasm_bindgen(constructor)]
    pub fn new(
        p: &QuaternionLike,
        r: &QuaternionLike,
        options: Option<KliOptionsObject>,
    ) -> Result<Demo, JsError> {
        let options = self::options(options).map_err(error)?;
        let (p, r) = (quaternion("p", p).map_err(error)?, quaternion("r", r).map_err(error)?);
        let path = crate::kli(p, r, &options).map_err(error)?;
        Ok(Demo { scene: Scene::new(path), mesh: aircraft() })
    }

    /// T, measured by Algorithm 1.
    #[wasm_bindgen(getter, js_name = finalTime)]
    pub fn final_time(&self) -> f64 {
        self.scene.final_time()
    }

    /// T*, the closed form's reach time for the same tolerance.
    #[wasm_bindgen(getter, js_name = predictedTime)]
    pub fn predicted_time(&self) -> f64 {
        self.scene.predicted_time()
    }

    /// The number of steps n.
    #[wasm_bindgen(getter)]
    pub fn steps(&self) -> usize {
        self.scene.path().steps()
    }

    /// The end actually used: r, or −r when shortestPath and p·r < 0.
    #[wasm_bindgen(getter)]
    pub fn target(&self) -> Vec<f64> {
        to_array(self.scene.path().target())
    }

    /// Table 1's moments that lie before T, then T.
    #[wasm_bindgen(getter)]
    pub fn moments(&self) -> Vec<f64> {
        self.scene.moments()
    }

    /// The integrated q at t (between samples by normalised linear interpolation).
    #[wasm_bindgen(js_name = kliAt)]
    pub fn kli_at(&self, t: f64) -> Vec<f64> {
        to_array(self.scene.kli_at(finite(t)))
    }

    /// The exact q(t) of the closed form.
    #[wasm_bindgen(js_name = exactAt)]
    pub fn exact_at(&self, t: f64) -> Result<Vec<f64>, JsError> {
        self.scene.path().at(t).map(to_array).map_err(error)
    }

    /// SLERP on the same clock, s = t / T.
    #[wasm_bindgen(js_name = slerpAt)]
    pub fn slerp_at(&self, t: f64) -> Vec<f64> {
        to_array(self.scene.slerp_at(finite(t)))
    }

    /// The rotating object at t: KLI, and SLERP at s = t/T beside it (Fig. 2, live).
    #[wasm_bindgen(js_name = drawObject)]
    pub fn draw_object(
        &self,
        ctx: &CanvasRenderingContext2d,
        width: f64,
        height: f64,
        pixel_ratio: f64,
        t: f64,
    ) {
        let t = finite(t);
        let pen = Pen::begin(ctx, width, height, pixel_ratio, BACKGROUND);
        let camera = object_camera();
        let side_by_side = width >= height;
        let (w, h) = if side_by_side { (width / 2.0, height) } else { (width, height / 2.0) };
        let panels = [
            (self.scene.kli_at(t), KLI, format!("KLI  t = {}", fixed(t, 2))),
            (
                self.scene.slerp_at(t),
                SLERP,
                format!("SLERP  s = t/T = {}", fixed(self.scene.slerp_parameter(t), 3)),
            ),
        ];
        for (i, (q, color, label)) in panels.iter().enumerate() {
            let (left, top) = if side_by_side { (i as f64 * w, 0.0) } else { (0.0, i as f64 * h) };
            let viewport = Viewport::fitting(left, top + 10.0, w, h - 10.0, 1.6);
            draw_object(&pen, &viewport, &camera, &self.mesh, *q, true);
            pen.text(label, (left + 10.0, top + 14.0), color, 13.0, "left");
        }
    }

    /// The object at each of Table 1's moments, in a row (Fig. 2).
    #[wasm_bindgen(js_name = drawFilmstrip)]
    pub fn draw_filmstrip(
        &self,
        ctx: &CanvasRenderingContext2d,
        width: f64,
        height: f64,
        pixel_ratio: f64,
    ) {
        let pen = Pen::begin(ctx, width, height, pixel_ratio, BACKGROUND);
        let camera = object_camera();
        let moments = self.scene.moments();
        let cell = width / moments.len() as f64;
        for (i, &t) in moments.iter().enumerate() {
            let left = i as f64 * cell;
            let viewport = Viewport::fitting(left, 0.0, cell, height - 16.0, 1.6);
            draw_object(&pen, &viewport, &camera, &self.mesh, self.scene.kli_at(t), false);
            let label = if i + 1 == moments.len() {
                format!("T = {}", fixed(t, 2))
            } else {
                format!("t = {}", number(t))
            };
            pen.text(
                &label,
                (left + 0.5 * cell, height - 9.0),
                if i + 1 == moments.len() { INK } else { MUTED },
                12.0,
                "center",
            );
        }
    }

    /// The Hopf curves on S², seen from (azimuth, elevation) in radians (Fig. 1), without the
    /// current time: draw this when the scene or the view changes, then `drawSphereTime` over
    /// (a copy of) it each frame.
    #[wasm_bindgen(js_name = drawSphere)]
    pub fn draw_sphere(
        &self,
        ctx: &CanvasRenderingContext2d,
        width: f64,
        height: f64,
        pixel_ratio: f64,
        azimuth: f64,
        elevation: f64,
    ) {
        let pen = Pen::begin(ctx, width, height, pixel_ratio, BACKGROUND);
        draw_sphere(
            &pen,
            &sphere_viewport(width, height),
            &Camera::orbit(azimuth, elevation),
            &self.scene,
        );
    }

    /// The KLI and SLERP points at t over a drawing of `drawSphere` with the same view.
    #[wasm_bindgen(js_name = drawSphereTime)]
    #[allow(clippy::too_many_arguments)]
    pub fn draw_sphere_time(
        &self,
        ctx: &CanvasRenderingContext2d,
        width: f64,
        height: f64,
        pixel_ratio: f64,
        t: f64,
        azimuth: f64,
        elevation: f64,
    ) {
        let pen = Pen::over(ctx, pixel_ratio);
        draw_sphere_cursor(
            &pen,
            &sphere_viewport(width, height),
            &Camera::orbit(azimuth, elevation),
            &self.scene,
            finite(t),
        );
    }

    /// The distance, time-warp and |q|-drift plots, without the current time (see `drawPlotsTime`).
    #[wasm_bindgen(js_name = drawPlots)]
    pub fn draw_plots(
        &self,
        ctx: &CanvasRenderingContext2d,
        width: f64,
        height: f64,
        pixel_ratio: f64,
    ) {
        let pen = Pen::begin(ctx, width, height, pixel_ratio, BACKGROUND);
        draw_plots(&pen, width, height, &self.scene);
    }

    /// The current time t as a line on each plot, over a drawing of `drawPlots`.
    #[wasm_bindgen(js_name = drawPlotsTime)]
    pub fn draw_plots_time(
        &self,
        ctx: &CanvasRenderingContext2d,
        width: f64,
        height: f64,
        pixel_ratio: f64,
        t: f64,
    ) {
        draw_plot_cursors(&Pen::over(ctx, pixel_ratio), width, height, &self.scene, finite(t));
    }

    /// The sphere view's default (azimuth, elevation) in radians.
    #[wasm_bindgen(js_name = defaultSphereView)]
    pub fn default_sphere_view() -> Vec<f64> {
        let d = sphere_camera().toward_viewer();
        vec![d.y.atan2(d.x), d.z.asin()]
    }
}

fn sphere_viewport(width: f64, height: f64) -> Viewport {
    Viewport::fitting(0.0, 0.0, width, height, 1.22)
}

/// Drawing never fails: a non-finite time is drawn as t = 0.
fn finite(t: f64) -> f64 {
    if t.is_finite() { t.max(0.0) } else { 0.0 }
}
