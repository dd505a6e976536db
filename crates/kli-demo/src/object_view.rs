//! The rotating object (the paper's Fig. 2): the aircraft turned by `q`, flat-shaded and drawn
//! far-to-near (painter's algorithm), with its body axes.

use glam::{DQuat, DVec3};

use crate::aircraft::{Face, normal};
use crate::camera::{Camera, Viewport};
use crate::palette::{AXIS_X, AXIS_Y, AXIS_Z};
use crate::pen::{Pen, shade};

/// The default view of the object: from the front-left, a little above.
pub fn object_camera() -> Camera {
    Camera::orbit(35f64.to_radians(), 22f64.to_radians())
}

/// A face ready to paint: its mean depth, its outline on screen and its shaded colour.
struct Painted {
    depth: f64,
    outline: Vec<(f64, f64)>,
    color: String,
}

/// Draws `mesh` rotated by `q` (unit) into `viewport`, and its body axes when `axes` is true.
pub fn draw_object(
    pen: &Pen,
    viewport: &Viewport,
    camera: &Camera,
    mesh: &[Face],
    q: DQuat,
    axes: bool,
) {
    let light = (camera.toward_viewer() + DVec3::new(0.0, 0.0, 0.9)).normalize();
    let mut faces: Vec<Painted> = mesh
        .iter()
        .map(|face| {
            let turned: Vec<DVec3> = face.vertices.iter().map(|&v| q * v).collect();
            let mut n = normal(&turned);
            if n.dot(camera.toward_viewer()) < 0.0 {
                n = -n; // double-sided: light the side we see
            }
            let brightness = 0.45 + 0.55 * n.dot(light).max(0.0);
            let depth =
                turned.iter().map(|&v| camera.project(v).depth).sum::<f64>() / turned.len() as f64;
            let outline = turned.iter().map(|&v| viewport.pixel(camera.project(v))).collect();
            Painted { depth, outline, color: shade(face.color, brightness) }
        })
        .collect();
    // Far to near. An insertion sort: a few dozen faces, and it keeps the general-purpose sort
    // (4 KB) out of the module.
    for i in 1..faces.len() {
        let mut j = i;
        while j > 0 && faces[j - 1].depth > faces[j].depth {
            faces.swap(j - 1, j);
            j -= 1;
        }
    }
    for Painted { outline, color, .. } in &faces {
        pen.fill_polygon(outline, color, Some(color));
    }
    if axes {
        let origin = viewport.pixel(camera.project(DVec3::ZERO));
        for (axis, color, label) in
            [(DVec3::X, AXIS_X, "x"), (DVec3::Y, AXIS_Y, "y"), (DVec3::Z, AXIS_Z, "z")]
        {
            let tip = q * (axis * 1.35);
            let end = viewport.pixel(camera.project(tip));
            pen.line(origin, end, color, 2.0, &[]);
            let label_at = viewport.pixel(camera.project(q * (axis * 1.5)));
            pen.text(label, label_at, color, 13.0, "center");
        }
    }
}
