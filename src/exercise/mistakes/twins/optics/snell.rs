//! Twins and alternatives of `refract`.

use glam::DVec3;

use crate::optics::reflect::Refraction;

pub fn eta_off_w_i(w_i: DVec3, n: DVec3, n1: f64, n2: f64) -> Refraction {
    let m = if w_i.dot(n) > 0.0 { -n } else { n };
    let cos_i = -w_i.dot(m);
    let ratio = n1 / n2;
    let cos2_t = 1.0 - ratio * ratio * (1.0 - cos_i * cos_i);
    if cos2_t < 0.0 {
        return Refraction::TotalInternalReflection;
    }
    Refraction::Transmitted(w_i + (ratio * cos_i - cos2_t.sqrt()) * m)
}

pub fn swapped_ratio(w_i: DVec3, n: DVec3, n1: f64, n2: f64) -> Refraction {
    let m = if w_i.dot(n) > 0.0 { -n } else { n };
    let cos_i = -w_i.dot(m);
    let ratio = n2 / n1;
    let cos2_t = 1.0 - ratio * ratio * (1.0 - cos_i * cos_i);
    if cos2_t < 0.0 {
        return Refraction::TotalInternalReflection;
    }
    Refraction::Transmitted(ratio * w_i + (ratio * cos_i - cos2_t.sqrt()) * m)
}

pub fn abs_cosine(w_i: DVec3, n: DVec3, n1: f64, n2: f64) -> Refraction {
    let cos_i = w_i.dot(n).abs();
    let ratio = n1 / n2;
    let cos2_t = 1.0 - ratio * ratio * (1.0 - cos_i * cos_i);
    if cos2_t < 0.0 {
        return Refraction::TotalInternalReflection;
    }
    Refraction::Transmitted(ratio * w_i + (ratio * cos_i - cos2_t.sqrt()) * n)
}

pub fn tangent_and_normal(w_i: DVec3, n: DVec3, n1: f64, n2: f64) -> Refraction {
    let m = if w_i.dot(n) <= 0.0 { n } else { -n };
    let cos_i = -w_i.dot(m);
    let tangential = w_i + cos_i * m;
    let ratio = n1 / n2;
    let cos2_t = (1.0 - ratio * ratio) + (ratio * cos_i) * (ratio * cos_i);
    if cos2_t < 0.0 {
        return Refraction::TotalInternalReflection;
    }
    Refraction::Transmitted(ratio * tangential - cos2_t.sqrt() * m)
}

pub fn matched_side(w_i: DVec3, n: DVec3, n1: f64, n2: f64) -> Refraction {
    if n1 == n2 {
        return Refraction::Transmitted(w_i);
    }
    let (m, cos_i) = match w_i.dot(n) {
        d if d > 0.0 => (-n, d),
        d => (n, -d),
    };
    let ratio = n1 / n2;
    let cos2_t = 1.0 - ratio * ratio * (1.0 - cos_i * cos_i);
    if cos2_t >= 0.0 {
        Refraction::Transmitted(ratio * w_i + (ratio * cos_i - cos2_t.sqrt()) * m)
    } else {
        Refraction::TotalInternalReflection
    }
}
