//! Twins and alternatives of `hemisphere_flip`.

use glam::DVec3;

pub fn no_flip(w: DVec3, _n: DVec3) -> DVec3 {
    w
}

pub fn wrong_side(w: DVec3, n: DVec3) -> DVec3 {
    if w.dot(n) > 0.0 { -w } else { w }
}

pub fn z_only(w: DVec3, _n: DVec3) -> DVec3 {
    DVec3::new(w.x, w.y, w.z.abs())
}

pub fn swapped(w: DVec3, n: DVec3) -> DVec3 {
    if n.dot(w) < 0.0 { -n } else { n }
}

pub fn projected(w: DVec3, n: DVec3) -> DVec3 {
    let c = w.dot(n);
    if c < 0.0 { w - c * n } else { w }
}

pub fn reflected(w: DVec3, n: DVec3) -> DVec3 {
    let c = w.dot(n);
    if c < 0.0 { w - 2.0 * c * n } else { w }
}

pub fn by_signum(w: DVec3, n: DVec3) -> DVec3 {
    w * w.dot(n).signum()
}
