//! Geometry on the page: its vectors (SVG's y grows down), directions by angle, and the
//! meeting of lines; a page vector as a 3-vector of the library and back.

use glam::{DVec2, DVec3};

pub(super) type V = DVec2;

pub(super) const fn v(x: f64, y: f64) -> V {
    DVec2::new(x, y)
}

/// The unit vector at `deg` degrees counter-clockwise from +x as seen on the page (SVG's
/// y grows down).
pub(super) fn dir(deg: f64) -> V {
    let a = deg.to_radians();
    v(a.cos(), -a.sin())
}

/// `d` turned by `deg` degrees counter-clockwise as seen on the page.
pub(super) fn turn(d: V, deg: f64) -> V {
    let (s, c) = deg.to_radians().sin_cos();
    v(c * d.x + s * d.y, -s * d.x + c * d.y)
}

/// The unit vector half-way between the directions `a` and `b` (the shorter way round).
pub(super) fn bisector(a: V, b: V) -> V {
    (a.normalize() + b.normalize()).normalize()
}

/// Where the lines `p + s d` and `q + t e` meet.
pub(super) fn meet(p: V, d: V, q: V, e: V) -> V {
    let den = d.x * e.y - d.y * e.x;
    let s = ((q.x - p.x) * e.y - (q.y - p.y) * e.x) / den;
    p + d * s
}

/// A page vector as a 3-vector of the library (z = 0), and back.
pub(super) fn to3(p: V) -> DVec3 {
    DVec3::new(p.x, p.y, 0.0)
}

pub(super) fn to2(p: DVec3) -> V {
    v(p.x, p.y)
}
