//! Twins and alternatives of `sphere_rejection`.

use glam::DVec3;

use crate::rng::{self, Rng};

/// A uniform point of the cube `[lo, hi)^3`.
fn draw(rng: &mut Rng, lo: f64, hi: f64) -> DVec3 {
    let x = rng::uniform(rng, lo, hi);
    let y = rng::uniform(rng, lo, hi);
    DVec3::new(x, y, rng::uniform(rng, lo, hi))
}

/// Rejection from the cube `[lo, hi)^3` against the unit ball, normalised or not.
fn rejecting(rng: &mut Rng, lo: f64, hi: f64, normalise: bool) -> (DVec3, u32) {
    let mut tries = 0;
    loop {
        tries += 1;
        let v = draw(rng, lo, hi);
        if v != DVec3::ZERO && v.length_squared() <= 1.0 {
            return (if normalise { v.normalize() } else { v }, tries);
        }
    }
}

pub fn not_normalised(rng: &mut Rng) -> (DVec3, u32) {
    rejecting(rng, -1.0, 1.0, false)
}

pub fn no_rejection(rng: &mut Rng) -> (DVec3, u32) {
    (draw(rng, -1.0, 1.0).normalize(), 1)
}

pub fn without_factor_two(rng: &mut Rng) -> (DVec3, u32) {
    rejecting(rng, -1.0, 0.0, true)
}

pub fn unit_cube(rng: &mut Rng) -> (DVec3, u32) {
    rejecting(rng, 0.0, 1.0, true)
}

pub fn rejections_only(rng: &mut Rng) -> (DVec3, u32) {
    let (w, tries) = rejecting(rng, -1.0, 1.0, true);
    (w, tries - 1)
}

pub fn for_loop(rng: &mut Rng) -> (DVec3, u32) {
    for tries in 1u32.. {
        let v = 2.0 * draw(rng, 0.0, 1.0) - DVec3::ONE;
        let length = v.length();
        if length <= 1.0 && length > 0.0 {
            return (v / length, tries);
        }
    }
    unreachable!("more than u32::MAX draws")
}

pub fn by_length(rng: &mut Rng) -> (DVec3, u32) {
    let mut tries = 1;
    let mut v = draw(rng, -1.0, 1.0);
    while v.length() > 1.0 || v == DVec3::ZERO {
        v = draw(rng, -1.0, 1.0);
        tries += 1;
    }
    (v.normalize(), tries)
}
