//! Twins and alternatives of `cosine_malley`.

use glam::{DVec2, DVec3};

use std::f64::consts::TAU;

use crate::sampling::disc::disc_polar;

/// The concentric disc point of `u` lifted to `z`.
fn lifted(u: DVec2, z: f64) -> DVec3 {
    let d = super::concentric::map(2.0 * u - DVec2::ONE);
    DVec3::new(d.x, d.y, z)
}

pub fn uniform_hemisphere(u: DVec2) -> DVec3 {
    let z = 1.0 - u.x;
    let (r, phi) = ((1.0 - z * z).max(0.0).sqrt(), TAU * u.y);
    DVec3::new(r * phi.cos(), r * phi.sin(), z)
}

/// `1 - r` for the concentric map's radius `r`, exactly: `2 min(u1, 1 - u1, u2, 1 - u2)`.
fn to_rim(u: DVec2) -> f64 {
    2.0 * u.x.min(1.0 - u.x).min(u.y).min(1.0 - u.y)
}

pub fn lift_without_root(u: DVec2) -> DVec3 {
    let t = to_rim(u);
    lifted(u, t * (2.0 - t))
}

pub fn two_sides(u: DVec2) -> DVec3 {
    let t = 2.0 * u.x.min(u.y);
    lifted(u, (t * (2.0 - t)).max(0.0).sqrt())
}

pub fn half_distance(u: DVec2) -> DVec3 {
    let t = to_rim(u) / 2.0;
    lifted(u, (t * (2.0 - t)).max(0.0).sqrt())
}

pub fn without_one_plus_r(u: DVec2) -> DVec3 {
    lifted(u, to_rim(u).sqrt())
}

pub fn on_polar(u: DVec2) -> DVec3 {
    let d = disc_polar(u);
    DVec3::new(d.x, d.y, (1.0 - u.x).sqrt())
}

pub fn two_roots(u: DVec2) -> DVec3 {
    let r = (2.0 * u.x - 1.0).abs().max((2.0 * u.y - 1.0).abs());
    lifted(u, (1.0 - r).max(0.0).sqrt() * (1.0 + r).sqrt())
}
