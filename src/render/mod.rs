//! The demo page's renderer, on a `<canvas>` 2D context through `web-sys`.
//!
//! Plain-Rust geometry ([`camera`], [`aircraft`], [`scene`], [`ticks`]) is kept apart from the files that
//! draw (`pen`, `object_view`, `sphere_view`, `plots`), which exist only on wasm32.

pub mod aircraft;
pub mod camera;
pub mod scene;
pub mod ticks;

#[cfg(target_arch = "wasm32")]
pub mod object_view;
#[cfg(target_arch = "wasm32")]
pub mod pen;
#[cfg(target_arch = "wasm32")]
pub mod plots;
#[cfg(target_arch = "wasm32")]
pub mod sphere_view;
