//! An orthographic camera orbiting the origin with `z` up: what the object and the sphere views
//! share. Plain Rust, so the projection is tested natively.

use glam::DVec3;

/// Looks at the origin from the direction `(cos e cos a, cos e sin a, sin e)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Camera {
    right: DVec3,
    up: DVec3,
    toward_viewer: DVec3,
}

/// Where a point lands: screen `x` to the right, `y` up, and `depth` towards the viewer
/// (larger is nearer; `depth > 0` is the front half of the unit sphere).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Projected {
    pub x: f64,
    pub y: f64,
    pub depth: f64,
}

impl Camera {
    /// The camera at `azimuth` (about `z`, from `x`) and `elevation` (above the `xy` plane), in
    /// radians. Elevation is clamped to ±89.9° so `z` stays a usable up direction.
    pub fn orbit(azimuth: f64, elevation: f64) -> Self {
        let limit = 89.9_f64.to_radians();
        let elevation = if elevation.is_finite() { elevation.max(-limit).min(limit) } else { 0.0 };
        let azimuth = if azimuth.is_finite() { azimuth } else { 0.0 };
        let toward_viewer = DVec3::new(
            elevation.cos() * azimuth.cos(),
            elevation.cos() * azimuth.sin(),
            elevation.sin(),
        );
        let right = DVec3::Z.cross(toward_viewer).normalize();
        Self { right, up: toward_viewer.cross(right), toward_viewer }
    }

    /// The orthographic projection of `v`.
    #[inline]
    pub fn project(&self, v: DVec3) -> Projected {
        Projected { x: v.dot(self.right), y: v.dot(self.up), depth: v.dot(self.toward_viewer) }
    }

    /// The unit vector from the origin towards the viewer.
    pub fn toward_viewer(&self) -> DVec3 {
        self.toward_viewer
    }

    /// The point of the unit sphere's front half that projects to screen `(x, y)`, if any.
    pub fn unproject_on_sphere(&self, x: f64, y: f64) -> Option<DVec3> {
        let depth_squared = 1.0 - x * x - y * y;
        (depth_squared >= 0.0)
            .then(|| self.right * x + self.up * y + self.toward_viewer * depth_squared.sqrt())
    }
}

/// A rectangle of the canvas (CSS pixels) with a centre and a scale for unit lengths.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Viewport {
    pub left: f64,
    pub top: f64,
    pub width: f64,
    pub height: f64,
    /// Pixels per unit length.
    pub scale: f64,
}

impl Viewport {
    /// A viewport whose unit disc of radius `extent` fills the smaller side (with a margin).
    pub fn fitting(left: f64, top: f64, width: f64, height: f64, extent: f64) -> Self {
        Self { left, top, width, height, scale: 0.5 * width.min(height) / extent }
    }

    /// The screen `(x, y)` of the projection at a pixel (the inverse of [`Viewport::pixel`]).
    pub fn unpixel(&self, (px, py): (f64, f64)) -> (f64, f64) {
        (
            (px - self.left - 0.5 * self.width) / self.scale,
            (self.top + 0.5 * self.height - py) / self.scale,
        )
    }

    /// Screen pixel of a projected point.
    #[inline]
    pub fn pixel(&self, p: Projected) -> (f64, f64) {
        (
            self.left + 0.5 * self.width + self.scale * p.x,
            self.top + 0.5 * self.height - self.scale * p.y,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn looking_down_x_puts_y_right_and_z_up() {
        let camera = Camera::orbit(0.0, 0.0);
        let p = camera.project(DVec3::new(0.0, 1.0, 0.0));
        assert!((p.x - 1.0).abs() < 1e-15 && p.y.abs() < 1e-15);
        let p = camera.project(DVec3::Z);
        assert!((p.y - 1.0).abs() < 1e-15);
        assert!((camera.project(DVec3::X).depth - 1.0).abs() < 1e-15);
    }

    #[test]
    fn basis_is_orthonormal_and_right_handed() {
        let c = Camera::orbit(2.3, -0.7);
        assert!((c.right.cross(c.up) - c.toward_viewer).length() < 1e-15);
        assert!(c.right.dot(c.up).abs() < 1e-15);
        // Straight down is clamped, not degenerate.
        let top = Camera::orbit(0.0, std::f64::consts::FRAC_PI_2);
        assert!(top.right.is_finite() && top.up.is_finite());
    }

    #[test]
    fn viewport_maps_up_to_smaller_y() {
        let v = Viewport::fitting(0.0, 0.0, 200.0, 100.0, 1.0);
        assert_eq!(v.pixel(Projected { x: 0.0, y: 0.0, depth: 0.0 }), (100.0, 50.0));
        assert_eq!(v.pixel(Projected { x: 1.0, y: 1.0, depth: 0.0 }), (150.0, 0.0));
    }

    #[test]
    fn unprojecting_a_projected_front_point_gives_it_back() {
        let camera = Camera::orbit(0.7, 0.3);
        let viewport = Viewport::fitting(10.0, 20.0, 300.0, 200.0, 1.2);
        let p = DVec3::new(0.2, 0.5, 0.7).normalize();
        assert!(camera.project(p).depth > 0.0);
        let (x, y) = viewport.unpixel(viewport.pixel(camera.project(p)));
        let back = camera.unproject_on_sphere(x, y).unwrap();
        assert!((back - p).length() < 1e-12, "{back:?}");
        assert!(camera.unproject_on_sphere(1.5, 0.0).is_none());
    }
}
