//! The forms answering `data/corpus/sphere.txt`: [`crate::geometry::sphere`] (both forms,
//! both precisions) and [`crate::geometry::Parallelogram`].

use glam::{DVec3, Vec3};

use super::v3;
use crate::check::accuracy::{Answer, Expect, Form, Precision};
use crate::geometry::{Parallelogram, Ray, Sphere, sphere};
use crate::single::geometry::{Ray as Ray32, Sphere as Sphere32, sphere as sphere32};

type Routine = fn(&Ray, &Sphere, f64) -> Option<f64>;
type Routine32 = fn(&Ray32, &Sphere32, f32) -> Option<f32>;

fn ray_and_sphere(a: &[f64]) -> (Ray, Sphere) {
    (
        Ray::new(v3(&a[0..3]), v3(&a[3..6])),
        Sphere::new(v3(&a[6..9]), a[9]),
    )
}

fn ray_and_sphere32(a: &[f64]) -> (Ray32, Sphere32) {
    let v = |a: &[f64]| Vec3::new(a[0] as f32, a[1] as f32, a[2] as f32);
    (
        Ray32::new(v(&a[0..3]), v(&a[3..6])),
        Sphere32::new(v(&a[6..9]), a[9] as f32),
    )
}

/// Both roots from the routine itself: the near one with `t_min = -inf`, the far one as
/// the first beyond the near one (the same root where the routine finds them equal).
fn roots(routine: Routine, a: &[f64]) -> Answer {
    let (ray, s) = ray_and_sphere(a);
    let near = routine(&ray, &s, f64::NEG_INFINITY)?;
    let far = routine(&ray, &s, near).unwrap_or(near);
    Some(vec![near, far])
}

fn roots32(routine: Routine32, a: &[f64]) -> Answer {
    let (ray, s) = ray_and_sphere32(a);
    let near = routine(&ray, &s, f32::NEG_INFINITY)?;
    let far = routine(&ray, &s, near).unwrap_or(near);
    Some(vec![f64::from(near), f64::from(far)])
}

fn first(routine: Routine, a: &[f64]) -> Answer {
    let (ray, s) = ray_and_sphere(a);
    routine(&ray, &s, a[10]).map(|t| vec![t])
}

fn first32(routine: Routine32, a: &[f64]) -> Answer {
    let (ray, s) = ray_and_sphere32(a);
    routine(&ray, &s, a[10] as f32).map(|t| vec![f64::from(t)])
}

fn roots_stable(a: &[f64]) -> Answer {
    roots(sphere::intersect_stable, a)
}
fn roots_textbook(a: &[f64]) -> Answer {
    roots(sphere::intersect_textbook, a)
}
fn roots_stable32(a: &[f64]) -> Answer {
    roots32(sphere32::intersect_stable, a)
}
fn roots_textbook32(a: &[f64]) -> Answer {
    roots32(sphere32::intersect_textbook, a)
}
fn first_stable(a: &[f64]) -> Answer {
    first(sphere::intersect_stable, a)
}
fn first_textbook(a: &[f64]) -> Answer {
    first(sphere::intersect_textbook, a)
}
fn first_stable32(a: &[f64]) -> Answer {
    first32(sphere32::intersect_stable, a)
}
fn first_textbook32(a: &[f64]) -> Answer {
    first32(sphere32::intersect_textbook, a)
}

/// The parallelogram of a case and its ray (the case's edges are never degenerate).
fn quad(a: &[f64]) -> Option<(Parallelogram, DVec3, DVec3)> {
    let q = Parallelogram::new(v3(&a[6..9]), v3(&a[9..12]), v3(&a[12..15])).ok()?;
    Some((q, v3(&a[0..3]), v3(&a[3..6])))
}

fn quad_hit(a: &[f64]) -> Answer {
    let (q, o, d) = quad(a)?;
    q.hit(o, d).map(|t| vec![t])
}

/// The edge coordinates of the hit, as the parallelogram tests them
/// ([`Parallelogram::edge_coordinates`], the numbers [`Parallelogram::hit`] and the
/// renderer's quads test).
fn quad_coords(a: &[f64]) -> Answer {
    let (q, o, d) = quad(a)?;
    q.hit(o, d)?;
    let (x, y) = q.edge_coordinates(o, d);
    Some(vec![x, y])
}

/// The former form: the point `o + t d - c`, with `t` rounded, read off with the dual
/// basis of the edges, `(e2 x k) / k.k` and `(k x e1) / k.k` with `k = e1 x e2`.
fn coords_via_t(a: &[f64]) -> Answer {
    let (q, o, d) = quad(a)?;
    let t = q.hit(o, d)?;
    let [first, second] = q.edges();
    let k = first.cross(second);
    let kk = k.length_squared();
    let (along_first, along_second) = (second.cross(k) / kk, k.cross(first) / kk);
    let point = o + t * d - q.corner();
    Some(vec![point.dot(along_first), point.dot(along_second)])
}

/// Every form of every verb of the corpus.
pub fn forms() -> Vec<Form> {
    let f = Form::new;
    use Expect::{Exceeds, Within};
    use Precision::{Double as F64, Single as F32};
    vec![
        f("sphere_roots", "stable", F64, Within, roots_stable),
        f("sphere_roots", "textbook", F64, Exceeds, roots_textbook),
        f("sphere_roots", "stable", F32, Exceeds, roots_stable32),
        f("sphere_roots", "textbook", F32, Exceeds, roots_textbook32),
        f("sphere_first", "stable", F64, Within, first_stable),
        f("sphere_first", "textbook", F64, Exceeds, first_textbook),
        f("sphere_first", "stable", F32, Within, first_stable32),
        f("sphere_first", "textbook", F32, Exceeds, first_textbook32),
        f("quad_hit", "stable", F64, Within, quad_hit),
        f("quad_coords", "stable", F64, Within, quad_coords),
        f("quad_coords", "textbook", F64, Exceeds, coords_via_t),
    ]
}
