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
//! Both are written once, generic over the scalar ([`num_traits::Float`]), and used with
//! `f32` ([`glam::Vec3`]) and `f64` ([`glam::DVec3`]).

use glam::{DVec3, Vec3};
use num_traits::Float;

// ANCHOR: frisvad
/// Frisvad (2012): the columns of the rotation about `z × n` that takes `z` to `n`,
///
/// `t = (1 - x²/(1+z), -xy/(1+z), -x)`, `b = (-xy/(1+z), 1 - y²/(1+z), -y)`,
///
/// with Frisvad's special case for `z < -0.9999999`, where `1 + z` is too close to 0.
pub fn frisvad<F: Float>([x, y, z]: [F; 3]) -> ([F; 3], [F; 3]) {
    let (zero, one) = (F::zero(), F::one());
    if z < F::from(-0.9999999).unwrap_or(-one) {
        return ([zero, -one, zero], [-one, zero, zero]);
    }
    let a = one / (one + z);
    let c = -x * y * a;
    ([one - x * x * a, c, -x], [c, one - y * y * a, -y])
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
pub fn duff<F: Float>([x, y, z]: [F; 3]) -> ([F; 3], [F; 3]) {
    let one = F::one();
    let s = one.copysign(z);
    let a = -one / (s + z);
    let c = x * y * a;
    ([one + s * x * x * a, s * c, -s * x], [c, s + y * y * a, -y])
}
// ANCHOR_END: duff

/// The 3-vectors a [`Frame`] is built from: [`Vec3`] and [`DVec3`].
pub trait FrameVector: Copy {
    /// The scalar.
    type S: Float;
    /// The components.
    fn to_xyz(self) -> [Self::S; 3];
    /// A vector from components.
    fn from_xyz(v: [Self::S; 3]) -> Self;
}

impl FrameVector for Vec3 {
    type S = f32;
    fn to_xyz(self) -> [f32; 3] {
        self.to_array()
    }
    fn from_xyz(v: [f32; 3]) -> Self {
        Vec3::from_array(v)
    }
}

impl FrameVector for DVec3 {
    type S = f64;
    fn to_xyz(self) -> [f64; 3] {
        self.to_array()
    }
    fn from_xyz(v: [f64; 3]) -> Self {
        DVec3::from_array(v)
    }
}

/// A construction of `(t, b)` from `n`, such as [`duff`] or [`frisvad`].
pub type Construction<F> = fn([F; 3]) -> ([F; 3], [F; 3]);

/// An orthonormal frame: tangent `t`, bitangent `b` and normal `n`, right-handed
/// (`t × b = n`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame<V> {
    /// Tangent: the local `x` axis.
    pub t: V,
    /// Bitangent: the local `y` axis.
    pub b: V,
    /// Normal: the local `z` axis.
    pub n: V,
}

// ANCHOR: frame
impl<V: FrameVector> Frame<V> {
    /// The frame of the unit normal `n`, by [`duff`].
    pub fn from_normal(n: V) -> Self {
        let (t, b) = duff(n.to_xyz());
        Self {
            t: V::from_xyz(t),
            b: V::from_xyz(b),
            n,
        }
    }

    /// The frame of the unit normal `n` by a given construction (to compare methods).
    pub fn with(n: V, construct: Construction<V::S>) -> Self {
        let (t, b) = construct(n.to_xyz());
        Self {
            t: V::from_xyz(t),
            b: V::from_xyz(b),
            n,
        }
    }

    /// World coordinates to frame coordinates: `(v·t, v·b, v·n)`.
    pub fn to_local(&self, v: V) -> V {
        V::from_xyz([dot(v, self.t), dot(v, self.b), dot(v, self.n)])
    }

    /// Frame coordinates to world coordinates: `v_x t + v_y b + v_z n`.
    pub fn to_world(&self, v: V) -> V {
        let [x, y, z] = v.to_xyz();
        let (t, b, n) = (self.t.to_xyz(), self.b.to_xyz(), self.n.to_xyz());
        V::from_xyz(std::array::from_fn(|k| x * t[k] + y * b[k] + z * n[k]))
    }
}
// ANCHOR_END: frame

fn dot<V: FrameVector>(a: V, b: V) -> V::S {
    let (a, b) = (a.to_xyz(), b.to_xyz());
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

// ANCHOR: error
/// How far a frame is from orthonormal and right-handed, computed in `f64` from the
/// (exactly widened) vectors: the largest of `||t| - 1|`, `||b| - 1|`, `|t·b|`, `|t·n|`,
/// `|b·n|` and `|t × b - n|` (each component). For an `f32` frame the `f64` evaluation adds
/// no error worth counting; for an `f64` frame it adds a few units of `f64::EPSILON`.
/// NaN if any component is NaN, so that a broken frame can never pass a bound.
pub fn orthonormality_error(t: DVec3, b: DVec3, n: DVec3) -> f64 {
    let handedness = (t.cross(b) - n).to_array();
    crate::check::max_abs(
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

impl Frame<Vec3> {
    /// [`orthonormality_error`] of this frame, widened to `f64`.
    pub fn error(&self) -> f64 {
        orthonormality_error(self.t.as_dvec3(), self.b.as_dvec3(), self.n.as_dvec3())
    }
}

impl Frame<DVec3> {
    /// [`orthonormality_error`] of this frame.
    pub fn error(&self) -> f64 {
        orthonormality_error(self.t, self.b, self.n)
    }
}

/// The common alternative, for the speed table: pick the coordinate axis least aligned
/// with `n`, then two cross products and one normalisation (Hughes and Möller 1999).
pub fn cross_product_frame(n: DVec3) -> (DVec3, DVec3) {
    let helper = if n.x.abs() > n.z.abs() {
        DVec3::new(-n.y, n.x, 0.0)
    } else {
        DVec3::new(0.0, -n.z, n.y)
    };
    let t = helper.normalize();
    (t, n.cross(t))
}
