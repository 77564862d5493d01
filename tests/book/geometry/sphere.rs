//! Tests of the chapter *Ray-sphere intersection* (`chapters/geometry/sphere.md`).
//!
//! These checks are deterministic (fixed seeds, constructed answers), not statistical:
//! no significance level is involved. Each checker is also run on planted bugs, which it
//! must reject, so that a check that cannot fail would be noticed here.

use glam::{DVec3, Vec3};
use quickcheck::{Arbitrary, Gen, QuickCheck, TestResult};
use raylemma::check::sphere::{self as check, SILHOUETTE_BAND, T_ERROR_BOUND, planted};
use raylemma::check::{Options, Real};
use raylemma::geometry::sphere::{intersect_stable, intersect_textbook, nearest_root_above};
use raylemma::geometry::{Ray, Sphere};
use raylemma::single::geometry::sphere as single;
use raylemma::single::geometry::{Ray as Ray32, Sphere as Sphere32};

/// Random cases of this file's own loops (as many as the checker's default).
const CASES: usize = 20_000;

// ---------------------------------------------------------------------------------------
// The project's code passes every check.

#[test]
fn stable_form_passes_every_check_f32() {
    check::intersection(&single::intersect_stable, &Options::default()).assert_pass();
}

#[test]
fn stable_form_passes_every_check_f64() {
    check::intersection(&intersect_stable, &Options::default()).assert_pass();
}

// ANCHOR: far_test
/// The hard case: a unit sphere 1e2 to 1e4 radii away, f32, parallel rays.
/// The stable form answers every ray correctly with a bounded error...
#[test]
fn stable_form_survives_far_spheres() {
    let verdict = check::far(&single::intersect_stable, &Options::default());
    verdict.assert_pass();
}

/// ...while the textbook form fails past some distance: this is why the rewrite exists.
#[test]
fn textbook_form_fails_far_spheres() {
    let verdict = check::far(&single::intersect_textbook, &Options::default());
    for distance in ["far_1e3", "far_3e3", "far_1e4"] {
        assert!(
            verdict.failed(distance),
            "textbook form passed {distance}:\n{verdict}"
        );
    }
    // Not only inaccurate: wrong about hit or miss for many rays at 1e4 radii.
    let row = check::far_row(&single::intersect_textbook, 1e4, &Options::default());
    assert!(
        row.wrong * 10 >= row.rays,
        "only {} of {} rays wrong",
        row.wrong,
        row.rays
    );
}
// ANCHOR_END: far_test

/// The stable form's worst t error stays within the bound at every distance, and the
/// textbook's grows past it: the error of the textbook form grows like distance^2.
#[test]
fn textbook_error_grows_quadratically_stable_linearly() {
    let options = Options::default().cases(41 * 41); // a 41 x 41 bundle
    let stable = |d| check::far_row(&single::intersect_stable, d, &options);
    let textbook = |d| check::far_row(&single::intersect_textbook, d, &options);
    let (s1, s2) = (stable(1e2), stable(1e3));
    let (t1, t2) = (textbook(1e2), textbook(1e3));
    // Ten times farther: the stable error grows by about 10 (allow 3..30), the textbook's
    // by about 100 (allow >= 30).
    let stable_growth = s2.worst_t_error / s1.worst_t_error;
    let textbook_growth = t2.worst_t_error / t1.worst_t_error;
    assert!(
        (3.0..=30.0).contains(&stable_growth),
        "stable growth {stable_growth}"
    );
    assert!(textbook_growth >= 30.0, "textbook growth {textbook_growth}");
}

// ---------------------------------------------------------------------------------------
// Planted bugs (`raylemma::check::sphere::planted`): each must be rejected by the
// checker, naming the right claim.

fn verdict_f64(f: fn(&Ray, &Sphere, f64) -> Option<f64>) -> raylemma::check::Verdict {
    check::intersection(&f, &Options::default().cases(4_000))
}

#[test]
fn checker_rejects_the_textbook_form() {
    // Even at ordinary scales (scenes within 10 radii of the origin) the cancellation in
    // -b + sqrt(b^2 - ac) exceeds the error bound for some rays.
    let verdict = check::intersection(&single::intersect_textbook, &Options::default());
    assert!(!verdict.passed(), "{verdict}");
}

#[test]
fn checker_rejects_the_seeds_t_greater_than_zero_rule() {
    // The seed: "the smallest value that is still greater than 0", ignoring t_min.
    let verdict = verdict_f64(planted::t_greater_than_zero);
    assert!(verdict.failed("surface_origin"), "{verdict}");
    assert!(verdict.failed("nearest_root"), "{verdict}");
}

#[test]
fn checker_rejects_always_the_far_root() {
    let verdict = verdict_f64(planted::always_far_root);
    assert!(
        verdict.failed("hits") && verdict.failed("nearest_root"),
        "{verdict}"
    );
}

#[test]
fn checker_rejects_ignoring_t_min() {
    assert!(verdict_f64(planted::ignoring_t_min).failed("nearest_root"));
}

#[test]
fn checker_rejects_assuming_a_unit_direction() {
    // a = D.D replaced by 1: right only for normalised directions.
    let verdict = verdict_f64(planted::assuming_unit_direction);
    assert!(
        verdict.failed("direction_scale") && verdict.failed("hits"),
        "{verdict}"
    );
}

#[test]
fn checker_rejects_a_loose_discriminant_test() {
    // Counting near misses as hits (discriminant >= -1% of a r^2), clamped to a real root.
    assert!(verdict_f64(planted::loose_discriminant).failed("misses"));
}

#[test]
fn checker_rejects_nan() {
    let verdict = check::intersection(&planted::always_nan, &Options::default().cases(1_000));
    assert!(
        verdict.failed("hits") && verdict.failed("misses"),
        "{verdict}"
    );
}

#[test]
fn far_checker_rejects_a_sphere_that_is_never_hit() {
    let verdict = check::far(&planted::never_hits, &Options::default());
    assert!(!verdict.passed(), "{verdict}");
}

// ---------------------------------------------------------------------------------------
// The seed's claims, one by one.

/// Seed: "the value of t corresponding to the first intersection is the smallest value
/// that is still greater than 0". In floating point, a ray leaving a surface point finds
/// its own sphere again at a tiny t about 4 times in 10: a caller needs t_min > 0.
#[test]
fn seed_rule_t_greater_than_zero_self_intersects() {
    for rate in [
        check::self_hit_rate(&single::intersect_stable, &Options::default()),
        check::self_hit_rate(&single::intersect_textbook, &Options::default()),
        check::self_hit_rate(&intersect_stable, &Options::default()),
    ] {
        assert!(rate >= 0.2, "self-intersection rate {rate}");
    }
}

/// Seed: "the ray intersects our sphere when the discriminant is >= 0". With
/// t_min = -infinity the routine reports every meeting of the *line* with the sphere, so
/// a hit must happen exactly when the centre is within r of the line.
#[test]
fn hit_iff_discriminant_nonnegative() {
    let mut rng = raylemma::rng::seeded(7);
    let mut decided = 0;
    for _ in 0..CASES {
        let case = random_case(&mut rng);
        let (ray, sphere) = case.f64();
        let h = case.line_distance();
        let unit = case.unit(f64::EPSILON);
        if (h - case.r).abs() <= SILHOUETTE_BAND * unit {
            continue;
        }
        decided += 1;
        let hit = intersect_stable(&ray, &sphere, f64::NEG_INFINITY).is_some();
        assert_eq!(hit, h < case.r, "{case:?}");
    }
    assert!(decided > CASES / 2);
}

#[test]
fn nearest_root_ordering() {
    assert_eq!(nearest_root_above(1.0, 2.0, 0.0), Some(1.0));
    assert_eq!(nearest_root_above(-1.0, 2.0, 0.0), Some(2.0));
    assert_eq!(nearest_root_above(-2.0, -1.0, 0.0), None);
    assert_eq!(nearest_root_above(1.0, 2.0, 1.5), Some(2.0));
    assert_eq!(nearest_root_above(f64::NAN, 2.0, 0.0), Some(2.0));
    assert_eq!(nearest_root_above(f64::NAN, f64::NAN, 0.0), None);
    // Strictly greater: a root exactly at t_min is behind the caller.
    assert_eq!(nearest_root_above(1.0, 2.0, 1.0), Some(2.0));
    assert_eq!(nearest_root_above(1.0, 2.0, 2.0), None);
}

/// The textbook form is right where it is well-conditioned: in f64, at a scale of a few
/// radii, with unnormalised directions, it agrees with the stable form to 1e-12. (Its
/// failures elsewhere are numerical, not algebraic; this test catches algebraic slips.)
#[test]
fn textbook_form_is_right_where_well_conditioned() {
    let mut rng = raylemma::rng::seeded(11);
    let mut hits = 0;
    for _ in 0..10_000 {
        let origin = raylemma::sampling::sphere::sphere_uniform(&mut rng) * 5.0;
        let target = raylemma::sampling::sphere::sphere_uniform(&mut rng)
            * 1.5
            * raylemma::rng::uniform(&mut rng, 0.0, 1.0);
        let scale = raylemma::rng::log_uniform(&mut rng, 0.1, 10.0);
        let ray = Ray::new(origin, (target - origin) * scale);
        let sphere = Sphere::new(DVec3::new(0.1, -0.2, 0.3), 1.0);
        for t_min in [0.0, 0.3 / scale, f64::NEG_INFINITY] {
            let (a, b) = (
                intersect_textbook(&ray, &sphere, t_min),
                intersect_stable(&ray, &sphere, t_min),
            );
            match (a, b) {
                (Some(a), Some(b)) => {
                    hits += 1;
                    assert!((a - b).abs() <= 1e-12 * b.abs().max(1.0), "{a} vs {b}");
                }
                (None, None) => {}
                _ => panic!("textbook {a:?} vs stable {b:?} for {ray:?}"),
            }
        }
    }
    assert!(hits > 10_000);
}

#[test]
fn exact_tangent_and_degenerate_rays_give_no_nan() {
    let unit = Sphere::new(DVec3::ZERO, 1.0);
    // Tangent at (0, 1, 0): exactly representable, discriminant exactly 0.
    let tangent = Ray::new(DVec3::new(-5.0, 1.0, 0.0), DVec3::X);
    for f in [intersect_stable, intersect_textbook] {
        let t = f(&tangent, &unit, 0.0).expect("exact tangent counts as a hit");
        assert!((t - 5.0).abs() <= 1e-12, "t = {t}");
    }
    // Origin exactly on the sphere, tangent direction: both roots are 0.
    let grazing = Ray::new(DVec3::new(0.0, 1.0, 0.0), DVec3::X);
    assert_eq!(intersect_stable(&grazing, &unit, 0.0), None);
    assert_eq!(intersect_stable(&grazing, &unit, -1.0), Some(0.0));
    // Origin at the centre: exit at t = r / |D|.
    let centre = Ray::new(DVec3::ZERO, DVec3::new(0.0, 0.0, 4.0));
    assert_eq!(intersect_stable(&centre, &unit, 0.0), Some(0.25));
    // A zero direction is not a ray: no NaN escapes, the answer is "no hit".
    let zero = Ray::new(DVec3::new(0.0, 0.0, -3.0), DVec3::ZERO);
    assert_eq!(intersect_stable(&zero, &unit, 0.0), None);
    assert_eq!(intersect_textbook(&zero, &unit, 0.0), None);
    // NaN input: no hit rather than a NaN distance.
    let nan = Ray::new(DVec3::new(f64::NAN, 0.0, -3.0), DVec3::Z);
    assert_eq!(intersect_stable(&nan, &unit, 0.0), None);
}

#[test]
fn f32_and_f64_agree_on_a_simple_case() {
    let ray32 = Ray32::new(Vec3::new(0.0, 0.0, -10.0), Vec3::Z);
    let s32 = Sphere32::new(Vec3::ZERO, 2.0);
    assert_eq!(single::intersect_stable(&ray32, &s32, 0.0), Some(8.0));
    assert_eq!(single::intersect_textbook(&ray32, &s32, 0.0), Some(8.0));
}

// ---------------------------------------------------------------------------------------
// Properties over random rays and spheres (quickcheck, fixed seed).

/// A ray and a sphere with components in [-100, 100], radius in (0, 50], any direction.
#[derive(Clone, Debug)]
struct Case {
    o: DVec3,
    d: DVec3,
    c: DVec3,
    r: f64,
}

impl Case {
    fn f64(&self) -> (Ray, Sphere) {
        (Ray::new(self.o, self.d), Sphere::new(self.c, self.r))
    }
    fn f32(&self) -> (Ray32, Sphere32) {
        (
            Ray32::new(self.o.as_vec3(), self.d.as_vec3()),
            Sphere32::new(self.c.as_vec3(), self.r as f32),
        )
    }
    /// Distance of the centre from the ray's line, in f64.
    fn line_distance(&self) -> f64 {
        let f = self.o - self.c;
        (f - self.d * (f.dot(self.d) / self.d.dot(self.d))).length()
    }
    fn unit(&self, eps: f64) -> f64 {
        eps * (self.o.length() + self.c.length() + self.r)
    }
}

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

fn random_case(rng: &mut raylemma::rng::Rng) -> Case {
    use raylemma::rng::uniform;
    let mut v = || {
        DVec3::new(
            uniform(rng, -100.0, 100.0),
            uniform(rng, -100.0, 100.0),
            uniform(rng, -100.0, 100.0),
        )
    };
    let (o, d, c) = (v(), v(), v());
    Case {
        o,
        d,
        c,
        r: uniform(rng, 0.0, 50.0) + 1e-3,
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

// ---------------------------------------------------------------------------------------
// The coursework interface, as a student uses it.

// ANCHOR: coursework
/// A student's own routine: any function with this signature can be checked. This one is
/// `f32`: `Ray32` and `Sphere32` are `raylemma::single::geometry::{Ray, Sphere}`, and
/// `single` is `raylemma::single::geometry::sphere`.
fn my_intersect(ray: &Ray32, sphere: &Sphere32, t_min: f32) -> Option<f32> {
    single::intersect_stable(ray, sphere, t_min) // replace with your own code
}

#[test]
fn my_intersect_passes_the_chapter_checks() {
    use raylemma::check::{self, Options};
    let verdict = check::sphere::intersection(&my_intersect, &Options::default());
    println!("{verdict}"); // shown with `cargo test -- --nocapture`
    verdict.assert_pass(); // on failure, panics with the whole report
    check::sphere::far(&my_intersect, &Options::default()).assert_pass();
}
// ANCHOR_END: coursework
