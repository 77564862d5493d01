//! Twins and alternatives of `cosine_pdf`.

use glam::DVec3;
use std::f64::consts::{PI, TAU};

pub fn two_pi(w: DVec3) -> f64 {
    w.z.max(0.0) / TAU
}

pub fn squared(w: DVec3) -> f64 {
    w.z.max(0.0).powi(2) / PI
}

pub fn absolute(w: DVec3) -> f64 {
    w.z.abs() / PI
}

pub fn per_angles(w: DVec3) -> f64 {
    let z = w.z.max(0.0);
    (1.0 - z * z).max(0.0).sqrt() * z / PI
}

pub fn explicit_if(w: DVec3) -> f64 {
    if w.z > 0.0 { w.z / PI } else { 0.0 }
}

pub fn half_sum(w: DVec3) -> f64 {
    (w.z + w.z.abs()) / TAU
}
