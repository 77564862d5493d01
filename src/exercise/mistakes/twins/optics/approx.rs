//! Twins and alternatives of `schlick`.

use crate::optics::fresnel::{cos_transmitted, r0};

/// Schlick's curve at `cos` with `r0`.
fn curve(r0: f64, cos: f64) -> f64 {
    r0 + (1.0 - r0) * (1.0 - cos).powi(5)
}

/// The cosine on the less dense side, `None` under total internal reflection.
fn less_dense(ci: f64, n1: f64, n2: f64) -> Option<f64> {
    if n1 <= n2 {
        Some(ci)
    } else {
        cos_transmitted(ci, n1, n2)
    }
}

pub fn r0_against_air(cos_i: f64, n1: f64, n2: f64) -> f64 {
    let ci = cos_i.abs().min(1.0);
    match less_dense(ci, n1, n2) {
        Some(cos) => curve(r0(n1, 1.0), cos),
        None => 1.0,
    }
}

pub fn without_one_minus_r0(cos_i: f64, n1: f64, n2: f64) -> f64 {
    let ci = cos_i.abs().min(1.0);
    match less_dense(ci, n1, n2) {
        Some(cos) => r0(n1, n2) + (1.0 - cos).powi(5),
        None => 1.0,
    }
}

pub fn denser_side(cos_i: f64, n1: f64, n2: f64) -> f64 {
    let ci = cos_i.abs().min(1.0);
    let cos = if n1 >= n2 {
        ci
    } else {
        match cos_transmitted(ci, n1, n2) {
            Some(cos_t) => cos_t,
            None => return 1.0,
        }
    };
    curve(r0(n1, n2), cos)
}

pub fn swapped_cos_t(cos_i: f64, n1: f64, n2: f64) -> f64 {
    let ci = cos_i.abs().min(1.0);
    if n1 <= n2 {
        return curve(r0(n1, n2), ci);
    }
    match cos_transmitted(ci, n2, n1) {
        Some(cos) => curve(r0(n1, n2), cos),
        None => 1.0,
    }
}

pub fn tir_zero(cos_i: f64, n1: f64, n2: f64) -> f64 {
    let ci = cos_i.abs().min(1.0);
    match less_dense(ci, n1, n2) {
        Some(cos) => curve(r0(n1, n2), cos),
        None => 0.0,
    }
}

pub fn via_sines(cos_i: f64, n1: f64, n2: f64) -> f64 {
    let ci = cos_i.abs().min(1.0);
    let r0 = ((n1 - n2) / (n1 + n2)).powi(2);
    let cos = if n1 > n2 {
        let sin_t = n1 / n2 * ((1.0 - ci) * (1.0 + ci)).sqrt();
        if sin_t > 1.0 {
            return 1.0;
        }
        ((1.0 - sin_t) * (1.0 + sin_t)).sqrt()
    } else {
        ci
    };
    r0 + (1.0 - r0) * (1.0 - cos).powi(5)
}

pub fn matched(cos_i: f64, n1: f64, n2: f64) -> f64 {
    let ci = cos_i.abs().min(1.0);
    let cos = match (n1 <= n2, cos_transmitted(ci, n1, n2)) {
        (true, _) => ci,
        (false, Some(cos_t)) => cos_t,
        (false, None) => return 1.0,
    };
    let r0 = r0(n1, n2);
    let x = 1.0 - cos;
    r0 + (1.0 - r0) * x * x * x * x * x
}
