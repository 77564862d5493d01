//! Properties over random rays and spheres (quickcheck, fixed seed).

use super::*;

fn component(g: &mut Gen) -> f64 {
    let x = i32::arbitrary(g) % 100_000;
    f64::from(x) / 1000.0
}

impl Arbitrary for Case {
    fn arbitrary(g: &mut Gen) -> Self {
        let v = |g: &mut Gen| DVec3::new(component(g), component(g), component(g));
        let r = f64::from(u16::arbitrary(g) % 50_000 + 1) / 1000.0;
        Case {
            o: v(g),
            d: v(g),
            c: v(g),
            r,
        }
    }
    fn shrink(&self) -> Box<dyn Iterator<Item = Self>> {
        // Shrink towards a simpler picture: sphere at the origin, then a unit radius.
        let mut simpler = Vec::new();
        if self.c != DVec3::ZERO {
            simpler.push(Case {
                o: self.o - self.c,
                c: DVec3::ZERO,
                ..self.clone()
            });
        }
        if self.r != 1.0 {
            simpler.push(Case {
                r: 1.0,
                ..self.clone()
            });
        }
        Box::new(simpler.into_iter())
    }
}

fn quickcheck(seed: u64) -> QuickCheck {
    QuickCheck::new()
        .rng(Gen::from_size_and_seed(100, seed))
        .tests(5_000)
        .max_tests(50_000)
}

/// A t returned by `intersect` (the stable form, in either precision) is finite, above
/// t_min, and its point lies on the sphere.
fn prop_hit_point_on_sphere<R: Real>(
    intersect: fn(&R::Ray, &R::Sphere, R) -> Option<R>,
    case: Case,
) -> TestResult {
    if case.d.length() < 1e-3 {
        return TestResult::discard();
    }
    let ray = R::ray(case.o, case.d);
    let sphere = R::sphere(case.c, case.r);
    let Some(t) = intersect(&ray, &sphere, R::ZERO) else {
        return TestResult::passed();
    };
    let (center, radius) = (R::wide3(R::center(&sphere)), R::radius(&sphere).wide());
    let p = R::wide3(R::at(&ray, t));
    let off = ((p - center).length() - radius).abs();
    // Error budget: the inputs' own rounding plus that of the point O + tD.
    let eps = R::EPSILON.wide();
    let scale = R::wide3(R::origin(&ray)).length() + center.length() + radius;
    let bound = T_ERROR_BOUND * eps * (scale + t.wide() * R::wide3(R::dir(&ray)).length());
    TestResult::from_bool(t.wide().is_finite() && t > R::ZERO && off <= bound)
}

#[test]
fn quickcheck_hit_point_on_sphere_f32() {
    let prop: fn(Case) -> TestResult =
        |case| prop_hit_point_on_sphere(single::intersect_stable, case);
    quickcheck(1).quickcheck(prop);
}

#[test]
fn quickcheck_hit_point_on_sphere_f64() {
    let prop: fn(Case) -> TestResult = |case| prop_hit_point_on_sphere(intersect_stable, case);
    quickcheck(2).quickcheck(prop);
}

/// f32 and f64 agree on hit or miss, except within the silhouette band of f32.
fn prop_precisions_agree(case: Case) -> TestResult {
    if case.d.length() < 1e-3 {
        return TestResult::discard();
    }
    let (r32, s32) = case.f32();
    // Compare on the f32 inputs, widened exactly.
    let wide = Case {
        o: r32.origin.as_dvec3(),
        d: r32.dir.as_dvec3(),
        c: s32.center.as_dvec3(),
        r: f64::from(s32.radius),
    };
    if (wide.line_distance() - wide.r).abs() <= SILHOUETTE_BAND * wide.unit(f64::from(f32::EPSILON))
    {
        return TestResult::discard();
    }
    let (r64, s64) = wide.f64();
    let a = single::intersect_stable(&r32, &s32, f32::NEG_INFINITY).is_some();
    let b = intersect_stable(&r64, &s64, f64::NEG_INFINITY).is_some();
    TestResult::from_bool(a == b)
}

#[test]
fn quickcheck_precisions_agree() {
    quickcheck(3).quickcheck(prop_precisions_agree as fn(Case) -> TestResult);
}

/// Translating ray and sphere together moves nothing: the same t within the bound.
fn prop_translation_invariant(case: Case, shift: (i16, i16, i16)) -> TestResult {
    if case.d.length() < 1e-3 || (case.line_distance() - case.r).abs() < 1e-3 * case.r {
        return TestResult::discard();
    }
    let v = DVec3::new(f64::from(shift.0), f64::from(shift.1), f64::from(shift.2)) / 100.0;
    let (ray, sphere) = case.f64();
    let moved = Case {
        o: case.o + v,
        c: case.c + v,
        ..case.clone()
    };
    let (ray2, sphere2) = moved.f64();
    let (t1, t2) = (
        intersect_stable(&ray, &sphere, 0.0),
        intersect_stable(&ray2, &sphere2, 0.0),
    );
    let unit = moved.unit(f64::EPSILON).max(case.unit(f64::EPSILON));
    // Near the tangent the root is ill-conditioned; elsewhere the two agree closely.
    let bound = 64.0 * unit
        / (case.d.length()
            * (1.0 - (case.line_distance() / case.r).min(1.0))
                .sqrt()
                .max(1e-6));
    TestResult::from_bool(match (t1, t2) {
        (None, None) => true,
        (Some(a), Some(b)) => (a - b).abs() <= bound,
        _ => false,
    })
}

#[test]
fn quickcheck_translation_invariant() {
    quickcheck(4).quickcheck(prop_translation_invariant as fn(Case, (i16, i16, i16)) -> TestResult);
}
