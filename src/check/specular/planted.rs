//! Planted bugs of the specular lobe checker. Chapter: *The missing cosine in specular
//! reflection* (`chapters/optics/specular.md`).

use glam::DVec3;

/// The lobe with the surface test `w_i.z < 0` where `<= 0` belongs: on the surface it
/// divides by a cosine of 0 and returns infinity (a sample `f cos / pdf` is then NaN).
pub fn horizon_included(albedo: f64, pdf: f64, w_i: DVec3, divide_by_cos: bool) -> f64 {
    if w_i.z < 0.0 {
        return 0.0;
    }
    if divide_by_cos {
        albedo * pdf / w_i.z
    } else {
        albedo * pdf
    }
}
