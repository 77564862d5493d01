//! Twins and alternatives of `disc_concentric`.

use glam::{DVec2, DVec3};
use std::f64::consts::{FRAC_PI_2, FRAC_PI_4};

/// The two-wedge map of the point `a` of `[-1, 1]^2`, with the library's trigonometry
/// (the twins of this and of `cosine_malley` call no exercise's function: in a hand-out
/// that is the student's).
pub fn map(a: DVec2) -> DVec3 {
    if a == DVec2::ZERO {
        return DVec3::ZERO;
    }
    if a.x.abs() > a.y.abs() {
        let phi = FRAC_PI_4 * (a.y / a.x);
        DVec3::new(a.x * phi.cos(), a.x * phi.sin(), 0.0)
    } else {
        let psi = FRAC_PI_4 * (a.x / a.y);
        DVec3::new(a.y * psi.sin(), a.y * psi.cos(), 0.0)
    }
}

pub fn second_wedge_unturned(u: DVec2) -> DVec3 {
    let a = 2.0 * u - DVec2::ONE;
    if a.x.abs() > a.y.abs() {
        map(a)
    } else {
        let psi = FRAC_PI_4 * (a.x / a.y);
        DVec3::new(a.y * psi.cos(), a.y * psi.sin(), 0.0)
    }
}

pub fn unshifted(u: DVec2) -> DVec3 {
    map(u)
}

pub fn rooted_radius(u: DVec2) -> DVec3 {
    let a = 2.0 * u - DVec2::ONE;
    let r = a.x.abs().max(a.y.abs());
    if r == 0.0 {
        return DVec3::ZERO;
    }
    map(a) * (r.sqrt() / r)
}

pub fn wedges_swapped(u: DVec2) -> DVec3 {
    let a = 2.0 * u - DVec2::ONE;
    if a == DVec2::ZERO {
        return DVec3::ZERO;
    }
    if a.y.abs() > a.x.abs() {
        let phi = FRAC_PI_4 * (a.y / a.x);
        DVec3::new(a.x * phi.cos(), a.x * phi.sin(), 0.0)
    } else {
        let psi = FRAC_PI_4 * (a.x / a.y);
        DVec3::new(a.y * psi.sin(), a.y * psi.cos(), 0.0)
    }
}

pub fn swapped(u: DVec2) -> DVec3 {
    map(2.0 * DVec2::new(u.y, u.x) - DVec2::ONE)
}

pub fn wrong_wedge(u: DVec2) -> DVec3 {
    let a = 2.0 * u - DVec2::ONE;
    if a.x.abs() > a.y.abs() {
        let phi = FRAC_PI_2 * (a.y / a.x);
        DVec3::new(a.x * phi.cos(), a.x * phi.sin(), 0.0)
    } else {
        map(a)
    }
}

pub fn unguarded(u: DVec2) -> DVec3 {
    let a = 2.0 * u - DVec2::ONE;
    if a.x.abs() > a.y.abs() {
        let phi = FRAC_PI_4 * (a.y / a.x);
        DVec3::new(a.x * phi.cos(), a.x * phi.sin(), 0.0)
    } else {
        let psi = FRAC_PI_4 * (a.x / a.y);
        DVec3::new(a.y * psi.sin(), a.y * psi.cos(), 0.0)
    }
}

pub fn four_regions(u: DVec2) -> DVec3 {
    let a = 2.0 * u - DVec2::ONE;
    let (r, phi) = if a.x > -a.y {
        if a.x > a.y {
            (a.x, FRAC_PI_4 * (a.y / a.x))
        } else {
            (a.y, FRAC_PI_4 * (2.0 - a.x / a.y))
        }
    } else if a.x < a.y {
        (-a.x, FRAC_PI_4 * (4.0 + a.y / a.x))
    } else if a.y != 0.0 {
        (-a.y, FRAC_PI_4 * (6.0 - a.x / a.y))
    } else {
        (0.0, 0.0)
    };
    DVec3::new(r * phi.cos(), r * phi.sin(), 0.0)
}

pub fn explicit_angle(u: DVec2) -> DVec3 {
    let a = 2.0 * u - DVec2::ONE;
    if a.x == 0.0 && a.y == 0.0 {
        return DVec3::ZERO;
    }
    let (r, phi) = if a.x.abs() > a.y.abs() {
        (a.x, FRAC_PI_4 * a.y / a.x)
    } else {
        (a.y, FRAC_PI_2 - FRAC_PI_4 * a.x / a.y)
    };
    let (sin, cos) = phi.sin_cos();
    DVec3::new(r * cos, r * sin, 0.0)
}
