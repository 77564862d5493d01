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
    normal: DVec3,
    area: f64,
    /// `n . corner`: the plane is `n . p = plane`.
    plane: f64,
    /// The edges across, scaled by the area: `-e2 / A` and `e1 / A`, which read the edge
    /// coordinates of a hit off `(o - corner) x d` ([`Parallelogram::hit_before`]).
    across_a: DVec3,
    across_b: DVec3,
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
        let normal = cross / area;
        Ok(Self {
            corner,
            e1,
            e2,
            normal,
            area,
            plane: normal.dot(corner),
            across_a: -e2 / area,
            across_b: e1 / area,
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

    /// The plane and the vectors [`Parallelogram::hit_before`] tests with: the unit
    /// normal `n`, `n . corner`, and the edges across scaled by the area, `-e2 / A` and
    /// `e1 / A` (for a renderer that keeps them in arrays of its own).
    pub(crate) fn plane_and_across(&self) -> (DVec3, f64, DVec3, DVec3) {
        (self.normal, self.plane, self.across_a, self.across_b)
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
    /// (finite; in units of `|d|`), or `None`. The ray meets the plane `n . p = n . c`
    /// (`c` the corner) at `t = (n . c - n . o) / (n . d)`. The point's coordinates in the
    /// edge basis, `o + t d - c = a e1 + b e2`, are read off without `t`: with
    /// `w = o - c`, the point is `w - (n . w / n . d) d = n x (w x d) / (n . d)`, so that
    /// (Cramer's rule, as in Möller and Trumbore's triangle test)
    /// `a = -(w x d) . e2 / (A n . d)` and `b = (w x d) . e1 / (A n . d)`, `A` the area,
    /// with `-e2 / A` and `e1 / A` precomputed. Inside when both are in `[0, 1]`. A ray
    /// parallel to the plane (`n . d = 0`) gives an infinite or NaN `t`: a miss.
    ///
    /// Reading them off the point `o + t d - c` instead costs a cross product less but
    /// carries the rounding of `t`: an error of about `u t` in the edge coordinates, which
    /// for a hit far along the ray is many times what one rounding of the inputs does
    /// (chapter *Ray-sphere intersection*, *Accuracy against exact arithmetic*).
    pub fn hit(&self, o: DVec3, d: DVec3) -> Option<f64> {
        self.hit_before(o, d, f64::INFINITY)
    }

    /// [`Parallelogram::hit`], for a hit nearer than `t_max` only (the renderer's nearest
    /// hit so far): beyond it, the edge coordinates are not computed at all.
    pub fn hit_before(&self, o: DVec3, d: DVec3, t_max: f64) -> Option<f64> {
        let nd = self.normal.dot(d);
        let t = (self.plane - self.normal.dot(o)) / nd;
        if !(t > 0.0 && t < t_max && t.is_finite()) {
            return None;
        }
        let (a, b) = self.coordinates(o, d, nd);
        ((0.0..=1.0).contains(&a) && (0.0..=1.0).contains(&b)).then_some(t)
    }

    /// The edge coordinates `(a, b)` of the point where the ray's line meets the plane,
    /// as [`Parallelogram::hit_before`] computes them to test it (whether or not they are
    /// inside, and whatever the sign of `t`).
    pub fn edge_coordinates(&self, o: DVec3, d: DVec3) -> (f64, f64) {
        self.coordinates(o, d, self.normal.dot(d))
    }

    fn coordinates(&self, o: DVec3, d: DVec3, nd: f64) -> (f64, f64) {
        let s = (o - self.corner).cross(d);
        (s.dot(self.across_a) / nd, s.dot(self.across_b) / nd)
    }
    // ANCHOR_END: hit
}
