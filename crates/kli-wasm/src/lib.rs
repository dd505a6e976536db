//! # kli-wasm: the npm package `kli`
//!
//! The JavaScript API of the [`kli`](mod@::kli) crate, and nothing else: each file converts and checks
//! JavaScript values, calls the plain-Rust core, and turns every [`kli::KliError`] into a
//! JavaScript `Error` whose message names the argument and whose `argument` and `kind` properties
//! say the same for code ([`error`]). Nothing here may panic: a panic would trap and kill the
//! module for the page.
//!
//! Quaternions cross as 4 numbers, scalar first `[w, x, y, z]` or, with the option
//! `order: "xyzw"`, scalar last (three.js, gl-matrix); single calls also take `{ x, y, z, w }`
//! objects. Results are `Float64Array`s in the call's order.
//! Names are the Rust names in camelCase (`max_time` is `maxTime`), everywhere.
//!
//! Files: [`error`] (errors and number formatting, the one conversion of a `KliError` to a
//! JavaScript `Error`), [`value`] (JavaScript values touched without a throw crossing Rust's
//! stack), [`typed`] (typed arrays and array-likes), [`read`] (numbers, quaternions and vectors
//! in), [`options`] (options objects, and a pair of rotations with its options); with the `api` feature (the `kli` entry) `calls` (the single calls), `path`
//! (the `KliPath` class), `batch` (many pairs a call), `buffer` (`Float64Buffer`); with `swarm`
//! (the `kli/swarm` entry) `swarm` (`LoheSwarm`); with `spline` (`kli/spline`) `spline`; with
//! `average` (`kli/average`) `average` (`averageRotations`, `blendRotations`); with `sync`
//! (`kli/sync`) `sync` (`synchronizeRotations`, `readG2o`, `SyncFlow`) and `poses` (`synchronizePoses`,
//! `writeG2o`). Crates that add to the module (the demo page's
//! `kli-demo`) use [`error`], [`read`] and [`options`] too.

#[cfg(feature = "average")]
pub mod average;
#[cfg(feature = "api")]
pub mod batch;
#[cfg(feature = "api")]
pub mod buffer;
#[cfg(feature = "api")]
pub mod calls;
pub mod error;
pub mod options;
#[cfg(feature = "api")]
pub mod path;
#[cfg(feature = "sync")]
pub mod poses;
pub mod read;
#[cfg(feature = "spline")]
pub mod spline;
#[cfg(feature = "swarm")]
pub mod swarm;
#[cfg(feature = "sync")]
pub mod sync;
pub mod typed;
pub mod value;

#[cfg(feature = "api")]
pub use batch::{kli_exact_batch, kli_sample, nlerp_batch, slerp_batch};
#[cfg(feature = "api")]
pub use buffer::Float64Buffer;
#[cfg(feature = "api")]
pub use calls::{
    axis_angle, from_axis_angle, hopf, kli, kli_exact, kli_reach_time, kli_to_slerp_parameter,
    slerp,
};
pub use error::JsResult;
pub use options::KliOptionsObject;
#[cfg(feature = "api")]
pub use path::JsKliPath;
pub use read::{QuaternionLike, Vector3Like};
#[cfg(feature = "swarm")]
pub use swarm::{JsLoheSwarm, SwarmOptionsObject};

use wasm_bindgen::prelude::*;

#[cfg(all(target_arch = "wasm32", feature = "small-allocator"))]
mod allocator {
    use std::alloc::{GlobalAlloc, Layout};

    use lol_alloc::{AssumeSingleThreaded, FreeListAllocator};

    /// The package's allocator: a free list kept in address order that coalesces neighbours, so
    /// memory stays flat under repeated large allocations (paths, batch scratch). Its calls are
    /// kept out of line: inlined into every allocating function, it would cost more than
    /// std's allocator it replaces.
    pub struct Allocator(AssumeSingleThreaded<FreeListAllocator>);

    // SAFETY: delegates to lol_alloc's allocator, which upholds GlobalAlloc's contract.
    unsafe impl GlobalAlloc for Allocator {
        #[inline(never)]
        unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
            // SAFETY: the caller's obligations are passed on unchanged.
            unsafe { self.0.alloc(layout) }
        }

        #[inline(never)]
        unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
            // SAFETY: as above.
            unsafe { self.0.dealloc(ptr, layout) }
        }
    }

    #[global_allocator]
    // SAFETY: the module is single-threaded: it is built without wasm threads (no `atomics`).
    static ALLOCATOR: Allocator =
        Allocator(unsafe { AssumeSingleThreaded::new(FreeListAllocator::new()) });
}

#[wasm_bindgen(typescript_custom_section)]
const TYPES: &'static str = r#"
/** A quaternion: 4 finite numbers, an Array or a typed array, scalar first `[w, x, y, z]` (the
 *  paper's a + bi + cj + dk) or, with the option `order: "xyzw"`, scalar last; or an object with
 *  number properties `x, y, z, w` (a THREE.Quaternion, a glTF rotation as an object). It is
 *  normalised, and must not be all zero. */
export type QuaternionLike = ArrayLike<number> | { x: number; y: number; z: number; w: number };

/** How quaternions are laid out in arrays, in and out: scalar first (the paper's, the default) or
 *  scalar last (three.js, gl-matrix, Babylon.js, glTF). */
export type QuaternionOrder = "wxyz" | "xyzw";

/** A 3-vector as 3 finite numbers `[x, y, z]`: an Array or a typed array. */
export type Vector3Like = ArrayLike<number>;

/** How Algorithm 1 takes a step: classical Runge–Kutta, explicit Euler (drifts off S³), or the
 *  RK4 step taken along a great circle (stays on S³). */
export type Integrator = "rk4" | "euler" | "geodesic";

/** Options of every call; every key is optional and unknown keys are rejected. */
export interface KliOptions {
  /** ε: Algorithm 1 stops once ||target − q(T)|| < ε. Finite, > 0. Default 1e-5. */
  tolerance?: number;
  /** δ: the time step of Algorithm 1. Finite, > 0. Default 0.01. */
  step?: number;
  /** Algorithm 1 fails with an Error past this time. Finite, > 0. Default 100. */
  maxTime?: number;
  /** Default "rk4". */
  integrator?: Integrator;
  /** When true (default) and p·r < 0, go to −r: the same rotation, the shorter arc. When false,
   *  go to r the long way round; p = −r is then an equilibrium and an Error. */
  shortestPath?: boolean;
  /** How quaternion arrays are laid out, the call's arguments and its results. Default "wxyz". */
  order?: QuaternionOrder;
}

/** What is wrong, in a word: the `kind` of every Error kli throws. */
export type KliErrorKind =
  | "not-finite" | "zero-length" | "out-of-range" | "wrong-length" | "unknown-name" | "antipodal"
  | "not-reached" | "stalled" | "left-sphere" | "unstable" | "too-many-steps" | "not-unique" | "invalid"
  /** A method of an object after its free(). */
  | "freed"
  /** A call into an object from inside one of its own calls (a getter or Proxy called back). */
  | "busy"
  /** A call before the entry's `init()` (or `initSync`) has run; `argument` is the entry to
   *  initialise, e.g. "kli/spline". */
  | "not-initialised";

/** Every Error kli throws: the message starts with the argument's name, and the same facts are
 *  properties, so code can route an error without reading its text. */
export interface KliError extends Error {
  /** The argument at fault, as the call names it: "p", "maxTime", "ends[7]"; "this" for the
   *  object itself (kinds "freed" and "busy"); the entry to initialise for "not-initialised". */
  argument: string;
  kind: KliErrorKind;
  /** For kind "not-finite": the component's position in the caller's array (0 is w in the order
   *  "wxyz", x in "xyzw" and in a 3-vector). */
  component?: number;
  /** For a file read (`readG2o`): the line at fault, from 1. */
  line?: number;
}
"#;
