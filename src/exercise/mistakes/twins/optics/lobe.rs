//! Twins and alternatives of `narrow_lobe_brdf`.

use glam::DVec3;

pub fn keeps_cosine(albedo: f64, pdf: f64, w_i: DVec3, _divide_by_cos: bool) -> f64 {
    if w_i.z <= 0.0 { 0.0 } else { albedo * pdf }
}

pub fn cos_squared(albedo: f64, pdf: f64, w_i: DVec3, divide_by_cos: bool) -> f64 {
    match (w_i.z <= 0.0, divide_by_cos) {
        (true, _) => 0.0,
        (false, true) => albedo * pdf / (w_i.z * w_i.z),
        (false, false) => albedo * pdf,
    }
}

pub fn without_rho(_rho: f64, pdf: f64, w_i: DVec3, divide_by_cos: bool) -> f64 {
    match (w_i.z <= 0.0, divide_by_cos) {
        (true, _) => 0.0,
        (false, true) => pdf / w_i.z,
        (false, false) => pdf,
    }
}

pub fn over_pi(albedo: f64, pdf: f64, w_i: DVec3, divide_by_cos: bool) -> f64 {
    match (w_i.z <= 0.0, divide_by_cos) {
        (true, _) => 0.0,
        (false, true) => albedo * pdf / (std::f64::consts::PI * w_i.z),
        (false, false) => albedo * pdf / std::f64::consts::PI,
    }
}

pub fn no_below_case(albedo: f64, pdf: f64, w_i: DVec3, divide_by_cos: bool) -> f64 {
    if divide_by_cos {
        albedo * pdf / w_i.z.abs()
    } else {
        albedo * pdf
    }
}

pub fn one_match(albedo: f64, pdf: f64, w_i: DVec3, divide_by_cos: bool) -> f64 {
    match (w_i.z > 0.0, divide_by_cos) {
        (false, _) => 0.0,
        (true, true) => albedo / w_i.z * pdf,
        (true, false) => albedo * pdf,
    }
}

pub fn reciprocal(albedo: f64, pdf: f64, w_i: DVec3, divide_by_cos: bool) -> f64 {
    let cos = w_i.z;
    if cos > 0.0 {
        let weight = if divide_by_cos { 1.0 / cos } else { 1.0 };
        albedo * pdf * weight
    } else {
        0.0
    }
}
