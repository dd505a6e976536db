//! The npm package's API in wasm under Node (`make test-wasm-node`): an entry a module, each
//! present where its entry's feature is on.

mod average;
#[cfg(all(target_arch = "wasm32", feature = "sync"))]
mod common;
mod poses;
mod spline;
mod swarm;
mod sync;
mod web;
