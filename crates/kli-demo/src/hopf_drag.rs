//! Dragging a rotation by its point on the Hopf sphere (the keyframes' keys, the averaging
//! page's measurements): where each point is on screen, to find the one under the pointer, and
//! the rotation turned so that its point follows the pointer. The turn is the shortest rotation
//! taking the old point to the new: `h(R q) = R h(q)`, since `h(q)` is the image of the body
//! x-axis under `q` (MATH.md, "The Hopf map").

use glam::DQuat;
use js_sys::Float64Array;
use kli::hopf;

use crate::figure::Frame;

/// Each of `rotations`' Hopf points on the sphere view drawn at `frame`: `[x, y, inFront]` a
/// point, in CSS pixels, `inFront` 1 when it faces the viewer (only those can be grabbed) else 0.
pub(crate) fn points_on_screen(frame: &Frame, rotations: &[DQuat]) -> Float64Array {
    let (viewport, camera) = (frame.sphere_viewport(), frame.camera);
    let flat: Vec<f64> = rotations
        .iter()
        .flat_map(|&q| {
            let p = camera.project(hopf(q));
            let (x, y) = viewport.pixel(p);
            [x, y, if p.depth >= 0.0 { 1.0 } else { 0.0 }]
        })
        .collect();
    Float64Array::from(&flat[..])
}

/// `q` turned so that its Hopf point lands under CSS pixel `(x, y)` of the sphere view drawn at
/// `frame`; `None` when the pixel is off the sphere.
pub(crate) fn turned_to(frame: &Frame, q: DQuat, x: f64, y: f64) -> Option<DQuat> {
    let (sx, sy) = frame.sphere_viewport().unpixel((x, y));
    let target = frame.camera.unproject_on_sphere(sx, sy)?;
    Some((DQuat::from_rotation_arc(hopf(q), target) * q).normalize())
}
