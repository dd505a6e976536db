//! # kli-demo: the demo page's renderer
//!
//! Draws what the pages show on `<canvas>` 2D contexts through `web-sys`, and exports the classes
//! the pages drive. Each page loads one module, a build of this crate with its feature
//! (`kli-page`, `swarm-page`, `spline-page`), which holds the npm package's API for that page too
//! ([`kli_wasm`]), so the pages and the package speak one language.
//!
//! Plain-Rust geometry and data ([`camera`], [`aircraft`], [`scene`], [`ticks`], [`palette`]) are
//! apart from the files that draw ([`pen`], [`object_view`], [`sphere_view`], [`plots`]) and the
//! classes themselves ([`demo`] for the KLI page, [`swarm_demo`] for the swarm page, with
//! [`swarm_view`] and [`swarm_plots`], [`spline_demo`] for the keyframes page).

// A page's build leaves the other pages' helpers unused.
#![cfg_attr(
    not(all(feature = "kli-page", feature = "swarm-page", feature = "spline-page")),
    allow(dead_code, unused_imports)
)]

pub mod aircraft;
pub mod camera;
#[cfg(feature = "kli-page")]
pub mod demo;
pub mod format;
pub mod object_view;
pub mod palette;
#[cfg(feature = "kli-page")]
pub mod paper;
pub mod pen;
pub mod plots;
pub mod scene;
pub mod sphere_view;
#[cfg(feature = "spline-page")]
pub mod spline_demo;
#[cfg(feature = "swarm-page")]
pub mod swarm_demo;
pub mod swarm_plots;
pub mod swarm_view;
pub mod ticks;

#[cfg(feature = "kli-page")]
pub use demo::Demo;
#[cfg(feature = "spline-page")]
pub use spline_demo::SplineDemo;
#[cfg(feature = "swarm-page")]
pub use swarm_demo::SwarmDemo;

use wasm_bindgen::prelude::*;

/// The sphere views' default (azimuth, elevation) in radians: both ends of the paper's curve in
/// front.
#[wasm_bindgen(js_name = defaultSphereView)]
pub fn default_sphere_view() -> Vec<f64> {
    let d = sphere_view::sphere_camera().toward_viewer();
    vec![d.y.atan2(d.x), d.z.asin()]
}
