//! # kli-demo: the demo page's renderer
//!
//! Draws what the page shows on `<canvas>` 2D contexts through `web-sys`, and exports the
//! [`Demo`] class the page drives. The page loads one module: this crate's, which holds the npm
//! package's JavaScript API ([`kli_wasm`]) too, so the page and the package speak one language.
//!
//! Plain-Rust geometry and data ([`camera`], [`aircraft`], [`scene`], [`ticks`], [`palette`]) are
//! apart from the files that draw ([`pen`], [`object_view`], [`sphere_view`], [`plots`]) and the
//! classes themselves ([`demo`] for the KLI page, [`swarm_demo`] for the swarm page, with
//! [`swarm_view`] and [`swarm_plots`], [`spline_demo`] for the keyframes page).

pub mod aircraft;
pub mod camera;
pub mod demo;
pub mod format;
pub mod object_view;
pub mod palette;
pub mod pen;
pub mod plots;
pub mod scene;
pub mod sphere_view;
pub mod spline_demo;
pub mod swarm_demo;
pub mod swarm_plots;
pub mod swarm_view;
pub mod ticks;

pub use demo::Demo;
pub use spline_demo::SplineDemo;
pub use swarm_demo::SwarmDemo;
