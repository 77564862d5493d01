//! Parallelograms, `corner + a e1 + b e2` with `a, b` in `[0, 1]`: the quads of the
//! renderer's scenes, and the shape of the parallelogram light. Chapter: *Shadow-ray pdfs*
//! (`chapters/transport/shadow.md`), which derives the intersection; *The reference
//! renderer* (`chapters/renderer/renderer.md`) uses it for walls.
//!
//! A plain geometric type in double precision: a [`Parallelogram`] has no side and emits
//! nothing. [`crate::transport::shadow::QuadLight`] is one that emits on the side of its
//! normal.

use std::fmt;

use glam::DVec3;

/// Why three vectors are not a parallelogram.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Degenerate {
    /// The corner or an edge (named) is NaN or infinite.
    NonFinite(&'static str),
    /// An edge (`"e1"` or `"e2"`) has zero length.
    ZeroLengthEdge(&'static str),
    /// The two edges are parallel: there is no area and no normal.
    ParallelEdges,
}

impl fmt::Display for Degenerate {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::NonFinite(what) => write!(f, "the parallelogram's {what} is not finite"),
            Self::ZeroLengthEdge(which) => {
                write!(f, "edge {which} of the parallelogram has zero length")
            }
            Self::ParallelEdges => {
                write!(
                    f,
                    "the edges of the parallelogram are parallel: it has no area"
                )
            }
        }
    }
}

impl std::error::Error for Degenerate {}

/// The points `corner + a e1 + b e2`, `a, b` in `[0, 1]`, with the unit normal
/// `n = (e1 x e2) / |e1 x e2|` (the corners run counter-clockwise about it).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Parallelogram {
    corner: DVec3,
    e1: DVec3,
    e2: DVec3,
    /// `e1 x e2`.
    cross: DVec3,
    normal: DVec3,
    area: f64,
}

impl Parallelogram {
    // ANCHOR: new
    /// The parallelogram with a corner and two edge vectors.
    ///
    /// # Errors
    /// [`Degenerate::NonFinite`] for a NaN or infinite input, [`Degenerate::ZeroLengthEdge`]
    /// for a zero edge, [`Degenerate::ParallelEdges`] when `|e1 x e2|` is below `1e-12`
    /// of `|e1| |e2|` (the edges' angle below about `1e-12` radians).
    pub fn new(corner: DVec3, e1: DVec3, e2: DVec3) -> Result<Self, Degenerate> {
        for (v, what) in [(corner, "corner"), (e1, "edge e1"), (e2, "edge e2")] {
            if !v.is_finite() {
                return Err(Degenerate::NonFinite(what));
            }
        }
        let (l1, l2) = (e1.length(), e2.length());
        if l1 == 0.0 {
            return Err(Degenerate::ZeroLengthEdge("e1"));
        }
        if l2 == 0.0 {
            return Err(Degenerate::ZeroLengthEdge("e2"));
        }
        let cross = e1.cross(e2);
        let area = cross.length();
        if area.is_nan() || area <= 1e-12 * l1 * l2 || area.is_infinite() {
            return Err(Degenerate::ParallelEdges);
        }
        Ok(Self {
            corner,
            e1,
            e2,
            cross,
            normal: cross / area,
            area,
        })
    }
    // ANCHOR_END: new

    /// The corner `c`.
    pub fn corner(&self) -> DVec3 {
        self.corner
    }

    /// The two edges `e1`, `e2`.
    pub fn edges(&self) -> [DVec3; 2] {
        [self.e1, self.e2]
    }

    /// The four corners, counter-clockwise about the normal.
    pub fn vertices(&self) -> [DVec3; 4] {
        let c = self.corner;
        [c, c + self.e1, c + self.e1 + self.e2, c + self.e2]
    }

    /// The point `corner + a e1 + b e2`.
    pub fn point(&self, a: f64, b: f64) -> DVec3 {
        self.corner + a * self.e1 + b * self.e2
    }

    /// The unit normal `(e1 x e2) / |e1 x e2|`.
    pub fn normal(&self) -> DVec3 {
        self.normal
    }

    /// The area `|e1 x e2|`.
    pub fn area(&self) -> f64 {
        self.area
    }

    /// The same parallelogram scaled by `s` about the origin.
    ///
    /// # Errors
    /// As [`Parallelogram::new`] (a zero or non-finite `s`).
    pub fn scaled(&self, s: f64) -> Result<Self, Degenerate> {
        Self::new(self.corner * s, self.e1 * s, self.e2 * s)
    }

    // ANCHOR: hit
    /// Where the ray `o + t d` meets the parallelogram, from either side: the `t > 0`
    /// (finite; in units of `|d|`), or `None`. The ray meets the plane at
    /// `t = n . (corner - o) / (n . d)`; the hit's coordinates in the edge basis are
    /// `a = ((q x e2) . c) / c.c` and `b = ((e1 x q) . c) / c.c` with `q = o + t d - corner`
    /// and `c = e1 x e2`, and it is inside when both are in `[0, 1]`. A ray parallel to the
    /// plane (`n . d = 0`) gives an infinite or NaN `t`: a miss.
    pub fn hit(&self, o: DVec3, d: DVec3) -> Option<f64> {
        let t = self.normal.dot(self.corner - o) / self.normal.dot(d);
        if !(t > 0.0 && t.is_finite()) {
            return None;
        }
        let q = o + t * d - self.corner;
        let cc = self.cross.length_squared();
        let a = q.cross(self.e2).dot(self.cross) / cc;
        let b = self.e1.cross(q).dot(self.cross) / cc;
        ((0.0..=1.0).contains(&a) && (0.0..=1.0).contains(&b)).then_some(t)
    }
    // ANCHOR_END: hit
}
