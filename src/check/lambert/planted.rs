//! Planted bugs of the Lambertian checker. Chapter: *Lambertian reflectance*.

use glam::DVec3;

/// `f = ρ`: the albedo is `π ρ`.
pub fn without_one_over_pi(rho: f64, wi: DVec3, wo: DVec3) -> f64 {
    if wi.z.min(wo.z) > 0.0 { rho } else { 0.0 }
}

/// Tests only the incoming side: reflects light to directions below the surface.
pub fn one_sided(rho: f64, wi: DVec3, _wo: DVec3) -> f64 {
    if wi.z > 0.0 {
        rho / std::f64::consts::PI
    } else {
        0.0
    }
}
