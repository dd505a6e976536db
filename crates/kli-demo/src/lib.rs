//! # kli-demo: the demo page's renderer
//!
//! Draws what the pages show on `<canvas>` 2D contexts through `web-sys`, and exports the classes
//! the pages drive. Each page loads one module, a build of this crate with its feature
//! (`<page>-page`, one a page), which holds the npm package's API for that page too
//! ([`kli_wasm`]), so the pages and the package speak one language.
//!
//! Plain-Rust geometry and data ([`camera`], [`aircraft`], [`scene`], [`ticks`], [`palette`]) are
//! apart from the files that draw ([`pen`], [`object_view`], [`sphere_view`], [`plots`]) and the
//! classes themselves, a folder a page named as the page (`kli`, `keyframes`, `swarm`,
//! `average`, `sync`, `learn`: the pages' registry, `www/pages.js`, lists them); every export
//! says where it came from ([`provenance`]).

pub mod aircraft;
#[cfg(feature = "average-page")]
pub mod average;
pub mod camera;
#[cfg(any(
    feature = "kli-page",
    feature = "keyframes-page",
    feature = "average-page",
    feature = "learn-page"
))]
mod clock;
mod figure;
pub mod format;
#[cfg(any(feature = "keyframes-page", feature = "average-page"))]
mod hopf_drag;
#[cfg(feature = "keyframes-page")]
pub mod keyframes;
#[cfg(feature = "kli-page")]
pub mod kli;
#[cfg(feature = "learn-page")]
pub mod learn;
pub mod legend;
pub mod object_view;
pub mod palette;
pub mod pen;
pub mod plots;
pub mod provenance;
pub mod scene;
pub mod sphere_view;
#[cfg(any(feature = "swarm-page", feature = "sync-page"))]
mod stepped;
#[cfg(feature = "swarm-page")]
pub mod swarm;
#[cfg(any(feature = "average-page", feature = "sync-page"))]
mod sweep;
#[cfg(feature = "sync-page")]
pub mod sync;
pub mod ticks;
#[cfg(any(feature = "keyframes-page", feature = "learn-page"))]
mod turning;

#[cfg(feature = "kli-page")]
pub use self::kli::KliDemo;
#[cfg(feature = "average-page")]
pub use average::AverageDemo;
#[cfg(feature = "keyframes-page")]
pub use keyframes::KeyframesDemo;
#[cfg(feature = "learn-page")]
pub use learn::LearnDemo;
#[cfg(feature = "swarm-page")]
pub use swarm::SwarmDemo;
#[cfg(feature = "sync-page")]
pub use sync::{SyncDemo, SyncFile, SyncMap};

use wasm_bindgen::prelude::*;

/// The sphere views' default camera, [azimuth, elevation] in radians: both ends of the paper's
/// curve in front.
#[wasm_bindgen(js_name = defaultCamera)]
pub fn default_camera() -> Vec<f64> {
    sphere_view::default_angles().to_vec()
}
