//! Tangent frames: an orthonormal basis `(t, b, n)` from a unit normal `n`. Chapter:
//! *Tangent frames* (`chapters/sampling/frame.md`).
//!
//! A sampler draws directions about the `z` axis; a [`Frame`] turns them into directions
//! about a surface normal. Two constructions, both without square roots or normalisation:
//!
//! * [`frisvad`]: Frisvad, "Building an Orthonormal Basis from a 3D Unit Vector Without
//!   Normalization", *Journal of Graphics Tools* 16(3), 2012. The rotation taking `z` to
//!   `n`; it divides by `1 + n_z` and loses orthogonality as `n` approaches `(0, 0, -1)`.
//! * [`duff`]: Duff, Burgess, Christensen, Hery, Kensler, Liani and Villemin, "Building
//!   an Orthonormal Basis, Revisited", *Journal of Computer Graphics Techniques* 6(1),
//!   2017. The same rotation for `n_z >= 0` and its mirror image for `n_z < 0`, chosen by
//!   the sign of `n_z` without a branch; it divides by `1 + |n_z| >= 1`.
//!
//! Both are written once for both precisions (see [`crate::precision`]): `Float` and `V3`
//! are `f64` and `DVec3` in `raylemma::sampling::frame` (the renderer's frames) and `f32`
//! and `Vec3` in its twin `raylemma::single::sampling::frame`.

use glam::DVec3;

use super::precision::{Float, V3, widen};

// ANCHOR: frisvad
/// Frisvad (2012): the columns of the rotation about `z × n` that takes `z` to `n`,
///
/// `t = (1 - x²/(1+z), -xy/(1+z), -x)`, `b = (-xy/(1+z), 1 - y²/(1+z), -y)`,
///
/// with Frisvad's special case for `z < -0.9999999`, where `1 + z` is too close to 0.
pub fn frisvad(n: V3) -> (V3, V3) {
    let V3 { x, y, z } = n;
    if z < -0.9999999 {
        return (V3::new(0.0, -1.0, 0.0), V3::new(-1.0, 0.0, 0.0));
    }
    let a = 1.0 / (1.0 + z);
    let c = -x * y * a;
    (
        V3::new(1.0 - x * x * a, c, -x),
        V3::new(c, 1.0 - y * y * a, -y),
    )
}
// ANCHOR_END: frisvad

// ANCHOR: duff
/// Duff et al. (2017), the branchless form: with `s = copysign(1, z)` and `a = -1 / (s + z)`,
///
/// `t = (1 + s x² a, s x y a, -s x)`, `b = (x y a, s + y² a, -y)`.
///
/// For `z >= 0` this is Frisvad's frame; for `z < 0` it is the frame of the mirror image
/// `(x, y, -z)` reflected back. `s + z` has the sign of `s`, so `|s + z| >= 1`: nothing
/// is divided by a small number. `copysign` treats `z = -0.0` as negative, which is
/// harmless (`|s + z| = 1` either way).
pub fn duff(n: V3) -> (V3, V3) {
    let V3 { x, y, z } = n;
    let s = Float::copysign(1.0, z);
    let a = -1.0 / (s + z);
    let c = x * y * a;
    (
        V3::new(1.0 + s * x * x * a, s * c, -s * x),
        V3::new(c, s + y * y * a, -y),
    )
}
// ANCHOR_END: duff

/// A construction of `(t, b)` from `n`, such as [`duff`] or [`frisvad`].
pub type Construction = fn(V3) -> (V3, V3);

/// An orthonormal frame: tangent `t`, bitangent `b` and normal `n`, right-handed
/// (`t × b = n`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    /// Tangent: the local `x` axis.
    pub t: V3,
    /// Bitangent: the local `y` axis.
    pub b: V3,
    /// Normal: the local `z` axis.
    pub n: V3,
}

// ANCHOR: frame
impl Frame {
    /// The frame of the unit normal `n`, by [`duff`].
    pub fn from_normal(n: V3) -> Self {
        let (t, b) = duff(n);
        Self { t, b, n }
    }

    /// The frame of the unit normal `n` by a given construction (to compare methods).
    pub fn with(n: V3, construct: Construction) -> Self {
        let (t, b) = construct(n);
        Self { t, b, n }
    }

    /// World coordinates to frame coordinates: `(v·t, v·b, v·n)`.
    pub fn to_local(&self, v: V3) -> V3 {
        V3::new(v.dot(self.t), v.dot(self.b), v.dot(self.n))
    }

    /// Frame coordinates to world coordinates: `v_x t + v_y b + v_z n`.
    pub fn to_world(&self, v: V3) -> V3 {
        v.x * self.t + v.y * self.b + v.z * self.n
    }

    /// [`orthonormality_error`] of this frame, from its vectors widened (exactly) to `f64`.
    pub fn error(&self) -> f64 {
        orthonormality_error(widen(self.t), widen(self.b), widen(self.n))
    }
}
// ANCHOR_END: frame

// ANCHOR: error
/// How far a frame is from orthonormal and right-handed, computed in `f64` from the
/// (exactly widened) vectors: the largest of `||t| - 1|`, `||b| - 1|`, `|t·b|`, `|t·n|`,
/// `|b·n|` and `|t × b - n|` (each component). For an `f32` frame the `f64` evaluation adds
/// no error worth counting; for an `f64` frame it adds a few units of `f64::EPSILON`.
/// NaN if any component is NaN, so that a broken frame can never pass a bound.
pub fn orthonormality_error(t: DVec3, b: DVec3, n: DVec3) -> f64 {
    let handedness = (t.cross(b) - n).to_array();
    crate::numeric::max_abs(
        [
            t.length() - 1.0,
            b.length() - 1.0,
            t.dot(b),
            t.dot(n),
            b.dot(n),
        ]
        .into_iter()
        .chain(handedness),
    )
}
// ANCHOR_END: error

/// The common alternative, for the speed table: a helper vector orthogonal to `n`, the
/// cross product of `n` with `e_z` when `|n_x| > |n_z|` and with `e_x` otherwise (its length²
/// is then at least ½, so it is never close to zero), normalised, and a second cross product.
/// Hughes and Möller (1999) zero the smallest component instead, which picks the axis least
/// aligned with `n`; either choice is robust.
pub fn cross_product_frame(n: V3) -> (V3, V3) {
    let helper = if n.x.abs() > n.z.abs() {
        V3::new(-n.y, n.x, 0.0)
    } else {
        V3::new(0.0, -n.z, n.y)
    };
    let t = helper.normalize();
    (t, n.cross(t))
}
