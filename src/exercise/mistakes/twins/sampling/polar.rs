//! Twins and alternatives of `disc_polar`.

use glam::{DVec2, DVec3};
use std::f64::consts::{PI, TAU};

pub fn r_equals_u1(u: DVec2) -> DVec3 {
    let (r, phi) = (u.x, TAU * u.y);
    DVec3::new(r * phi.cos(), r * phi.sin(), 0.0)
}

pub fn half_turn(u: DVec2) -> DVec3 {
    let (r, phi) = (u.x.sqrt(), PI * u.y);
    DVec3::new(r * phi.cos(), r * phi.sin(), 0.0)
}

pub fn r_squared(u: DVec2) -> DVec3 {
    let (r, phi) = (u.x * u.x, TAU * u.y);
    DVec3::new(r * phi.cos(), r * phi.sin(), 0.0)
}

pub fn swapped(u: DVec2) -> DVec3 {
    let (r, phi) = (u.y.sqrt(), TAU * u.x);
    DVec3::new(r * phi.cos(), r * phi.sin(), 0.0)
}

pub fn y_without_r(u: DVec2) -> DVec3 {
    let (r, phi) = (u.x.sqrt(), TAU * u.y);
    DVec3::new(r * phi.cos(), phi.sin(), 0.0)
}

pub fn sin_cos_swapped(u: DVec2) -> DVec3 {
    let (r, phi) = (u.x.sqrt(), TAU * u.y);
    DVec3::new(r * phi.sin(), r * phi.cos(), 0.0)
}

pub fn with_sin_cos(u: DVec2) -> DVec3 {
    let (sin, cos) = (2.0 * PI * u.y).sin_cos();
    let radius = u.x.sqrt();
    DVec3::new(cos * radius, sin * radius, 0.0)
}

pub fn scaled_unit_vector(u: DVec2) -> DVec3 {
    let phi = u.y * TAU;
    DVec3::new(phi.cos(), phi.sin(), 0.0) * u.x.sqrt()
}
