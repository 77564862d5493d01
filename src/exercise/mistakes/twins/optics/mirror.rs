//! Twins and alternatives of `reflect`.

use glam::DVec3;

pub fn other_convention(w_i: DVec3, n: DVec3) -> DVec3 {
    2.0 * w_i.dot(n) * n - w_i
}

pub fn projected(w_i: DVec3, n: DVec3) -> DVec3 {
    w_i - w_i.dot(n) * n
}

pub fn without_dot(w_i: DVec3, n: DVec3) -> DVec3 {
    w_i - 2.0 * n
}

pub fn abs_cosine(w_i: DVec3, n: DVec3) -> DVec3 {
    w_i - 2.0 * w_i.dot(n).abs() * n
}

pub fn flipped_first(w_i: DVec3, n: DVec3) -> DVec3 {
    let m = if w_i.dot(n) > 0.0 { -n } else { n };
    let cos_i = -w_i.dot(m);
    w_i + 2.0 * cos_i * m
}

pub fn split(w_i: DVec3, n: DVec3) -> DVec3 {
    let normal = w_i.dot(n) * n;
    let tangential = w_i - normal;
    tangential - normal
}
