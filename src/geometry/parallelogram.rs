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
    /// The dual basis of the edges in the plane: `a = q . dual_a`, `b = q . dual_b` for a
    /// point `corner + q` of the plane.
    dual_a: DVec3,
    dual_b: DVec3,
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
        let cc = cross.length_squared();
        Ok(Self {
            corner,
            e1,
            e2,
            normal,
            area,
            plane: normal.dot(corner),
            dual_a: e2.cross(cross) / cc,
            dual_b: cross.cross(e1) / cc,
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

    /// The plane and the dual basis [`Parallelogram::hit_before`] tests with: the unit
    /// normal `n`, `n . corner`, and the dual vectors of the edges (for a renderer that
    /// keeps them in arrays of its own).
    pub fn plane_and_duals(&self) -> (DVec3, f64, DVec3, DVec3) {
        (self.normal, self.plane, self.dual_a, self.dual_b)
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
    /// edge basis, `q = o + t d - c = a e1 + b e2`, are read off with the dual basis: with
    /// `k = e1 x e2`, `a = q . (e2 x k) / (k . k)` and `b = q . (k x e1) / (k . k)` (each
    /// dual vector is perpendicular to the other edge and to the normal, and has a dot
    /// product of 1 with its own edge), both precomputed, so a test costs three dot
    /// products. Inside when both are in `[0, 1]`. A ray parallel to the plane
    /// (`n . d = 0`) gives an infinite or NaN `t`: a miss.
    pub fn hit(&self, o: DVec3, d: DVec3) -> Option<f64> {
        self.hit_before(o, d, f64::INFINITY)
    }

    /// [`Parallelogram::hit`], for a hit nearer than `t_max` only (the renderer's nearest
    /// hit so far): beyond it, the point is not computed at all.
    pub fn hit_before(&self, o: DVec3, d: DVec3, t_max: f64) -> Option<f64> {
        let t = (self.plane - self.normal.dot(o)) / self.normal.dot(d);
        if !(t > 0.0 && t < t_max && t.is_finite()) {
            return None;
        }
        let q = o + t * d - self.corner;
        let (a, b) = (q.dot(self.dual_a), q.dot(self.dual_b));
        ((0.0..=1.0).contains(&a) && (0.0..=1.0).contains(&b)).then_some(t)
    }
    // ANCHOR_END: hit
}
