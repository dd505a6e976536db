//! The rotating object: a small low-poly aircraft, chosen because no rotation leaves it looking
//! the same. Body axes: the nose points along `+x` (so the Hopf curve on S² is where the nose
//! points), the fin along `+z`, the red (port) wing along `+y`, the green (starboard) wing `-y`.

use glam::DVec3;

/// An sRGB colour.
pub type Rgb = [u8; 3];

pub const FUSELAGE: Rgb = [206, 212, 218];
pub const NOSE: Rgb = [73, 80, 87];
pub const PORT_WING: Rgb = [224, 49, 49];
pub const STARBOARD_WING: Rgb = [47, 158, 68];
pub const TAIL: Rgb = [252, 196, 25];

/// A flat polygon of the mesh.
#[derive(Debug, Clone, PartialEq)]
pub struct Face {
    pub vertices: Vec<DVec3>,
    pub color: Rgb,
}

fn face(color: Rgb, vertices: &[[f64; 3]]) -> Face {
    Face { vertices: vertices.iter().map(|&v| DVec3::from_array(v)).collect(), color }
}

/// The mesh, about 1.2 units from nose to tail, centred near the origin.
pub fn aircraft() -> Vec<Face> {
    // Fuselage: a diamond cross-section, wide at the wing root, narrow at the tail.
    let ring = |x: f64, r: f64| [[x, r, 0.0], [x, 0.0, r], [x, -r, 0.0], [x, 0.0, -r]];
    let (front, back) = (ring(0.55, 0.14), ring(-0.95, 0.06));
    let nose = [1.15, 0.0, 0.0];
    let mut faces = Vec::new();
    for i in 0..4 {
        let j = (i + 1) % 4;
        faces.push(face(FUSELAGE, &[front[i], front[j], back[j], back[i]]));
        faces.push(face(NOSE, &[front[i], nose, front[j]]));
    }
    faces.push(face(FUSELAGE, &back));
    // Wings: swept trapezoids, thin slabs so both sides read as solid.
    for (side, color) in [(1.0, PORT_WING), (-1.0, STARBOARD_WING)] {
        let outline =
            [[0.35, 0.12 * side], [-0.05, 1.05 * side], [-0.3, 1.05 * side], [-0.25, 0.12 * side]];
        let top: Vec<[f64; 3]> = outline.iter().map(|&[x, y]| [x, y, 0.025]).collect();
        let bottom: Vec<[f64; 3]> = outline.iter().map(|&[x, y]| [x, y, -0.025]).collect();
        faces.push(face(color, &top));
        faces.push(face(color, &bottom));
        for i in 0..4 {
            let j = (i + 1) % 4;
            faces.push(face(color, &[top[i], top[j], bottom[j], bottom[i]]));
        }
    }
    // Tail: a horizontal stabiliser and a fin on top (+z).
    faces.push(face(
        TAIL,
        &[[-0.7, 0.05, 0.0], [-0.92, 0.42, 0.0], [-1.02, 0.42, 0.0], [-0.95, 0.05, 0.0]],
    ));
    faces.push(face(
        TAIL,
        &[[-0.7, -0.05, 0.0], [-0.92, -0.42, 0.0], [-1.02, -0.42, 0.0], [-0.95, -0.05, 0.0]],
    ));
    faces.push(face(
        TAIL,
        &[[-0.65, 0.0, 0.05], [-0.95, 0.0, 0.05], [-1.05, 0.0, 0.5], [-0.93, 0.0, 0.5]],
    ));
    faces
}

/// The unit normal of a face (from its first three vertices).
pub fn normal(vertices: &[DVec3]) -> DVec3 {
    (vertices[1] - vertices[0]).cross(vertices[2] - vertices[0]).normalize_or_zero()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_face_is_planar_with_a_normal() {
        for f in aircraft() {
            let n = normal(&f.vertices);
            assert!((n.length() - 1.0).abs() < 1e-12, "{f:?}");
            for v in &f.vertices {
                assert!((v - f.vertices[0]).dot(n).abs() < 1e-12, "{f:?}");
            }
        }
    }

    #[test]
    fn nose_is_plus_x_fin_plus_z_port_plus_y() {
        let faces = aircraft();
        let extreme = |axis: DVec3, color: Rgb| {
            faces
                .iter()
                .filter(|f| f.color == color)
                .flat_map(|f| f.vertices.iter())
                .map(|v| v.dot(axis))
                .fold(f64::MIN, f64::max)
        };
        assert!(extreme(DVec3::X, NOSE) > extreme(DVec3::X, FUSELAGE));
        assert!(extreme(DVec3::Z, TAIL) > 0.4 && extreme(-DVec3::Z, TAIL) <= 0.0);
        assert!(extreme(DVec3::Y, PORT_WING) > 1.0 && extreme(-DVec3::Y, PORT_WING) < 0.0);
        assert!(extreme(-DVec3::Y, STARBOARD_WING) > 1.0);
    }
}
