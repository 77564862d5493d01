//! The pinhole camera. Chapter: *The path tracer* (`chapters/renderer/path-tracer.md`).

use glam::{DVec2, DVec3};

use super::scene::CameraSpec;
use crate::geometry::Ray;

// ANCHOR: camera
/// A pinhole camera: rays from `position` through a rectangle at unit distance along the
/// view direction, `2 tan(fov_y / 2)` high and `width / height` times that wide.
///
/// The image's right is `forward x up` (right-handed: a camera looking down `+z` with up
/// `+y` has `-x` on its right), its top is `up` made perpendicular to `forward`; pixel
/// row 0 is the top of the image.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    origin: DVec3,
    forward: DVec3,
    right: DVec3,
    up: DVec3,
    width: u32,
    height: u32,
}

impl Camera {
    /// The camera of a checked scene (its view and up directions are not parallel).
    pub fn new(spec: &CameraSpec) -> Self {
        let forward = (spec.look_at - spec.position).normalize();
        let right = forward.cross(spec.up).normalize();
        let up = right.cross(forward);
        let half_h = (spec.fov_y_deg.to_radians() / 2.0).tan();
        let half_w = half_h * f64::from(spec.width) / f64::from(spec.height);
        Camera {
            origin: spec.position,
            forward,
            right: right * half_w,
            up: up * half_h,
            width: spec.width,
            height: spec.height,
        }
    }

    /// The ray through the point `(x + jitter.x, y + jitter.y)` of the image, in pixels
    /// from its top-left corner (a box filter when `jitter` is uniform in the unit square).
    pub fn ray(&self, x: u32, y: u32, jitter: DVec2) -> Ray {
        let sx = 2.0 * (f64::from(x) + jitter.x) / f64::from(self.width) - 1.0;
        let sy = 1.0 - 2.0 * (f64::from(y) + jitter.y) / f64::from(self.height);
        let d = self.forward + sx * self.right + sy * self.up;
        Ray::new(self.origin, d.normalize())
    }
}
// ANCHOR_END: camera
