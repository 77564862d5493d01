//! Tests of the chapter *Ray-sphere intersection* (`chapters/geometry/sphere.md`).
//!
//! These checks are deterministic (fixed seeds, constructed answers), not statistical:
//! no significance level is involved. Each checker is also run on planted bugs, which it
//! must reject, so that a check that cannot fail would be noticed here.

use glam::{DVec3, Vec3};
use quickcheck::{Arbitrary, Gen, QuickCheck, TestResult};
use raylemma::check::Options;
use raylemma::check::sphere::{self as check, SILHOUETTE_BAND, T_ERROR_BOUND, planted};
use raylemma::geometry::sphere::{intersect_stable, intersect_textbook, nearest_root_above};
use raylemma::geometry::{Ray, Sphere};
use raylemma::real::Real;
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

/// How the worst t error grows with distance, on a 41 x 41 bundle. Ten times farther, the
/// stable error grows by about 10 (like eps d; allow 3..30). The textbook error grows like
/// eps d^2 / r below the cliff, d ~ eps^(-1/2) r ~ 2 900 r in f32: by about 100 from 1e2
/// to 1e3 (allow >= 60, an exponent of 1.8). Beyond the cliff the discriminant is noise
/// and the error is its square root, sqrt(eps) d: from 3e3 to 1e4 it grows like d again,
/// by about 3.3 (allow 1.5..6, well below the 11 of d^2).
#[test]
fn textbook_error_grows_quadratically_stable_linearly() {
    let options = Options::default().cases(41 * 41); // a 41 x 41 bundle
    let stable = |d| check::far_row(&single::intersect_stable, d, &options);
    let textbook = |d| check::far_row(&single::intersect_textbook, d, &options);
    let (s1, s2) = (stable(1e2), stable(1e3));
    let (t1, t2) = (textbook(1e2), textbook(1e3));
    let (t3, t4) = (textbook(3e3), textbook(1e4));
    let stable_growth = s2.worst_t_error / s1.worst_t_error;
    let textbook_growth = t2.worst_t_error / t1.worst_t_error;
    let beyond_the_cliff = t4.worst_t_error / t3.worst_t_error;
    assert!(
        (3.0..=30.0).contains(&stable_growth),
        "stable growth {stable_growth}"
    );
    assert!(textbook_growth >= 60.0, "textbook growth {textbook_growth}");
    assert!(
        (1.5..=6.0).contains(&beyond_the_cliff),
        "textbook growth from 3e3 to 1e4: {beyond_the_cliff}"
    );
}

/// In f64 the textbook form answers every hit/miss of the far bundle right (its cliff is
/// much farther away), but its t error still grows like d^2: by about 100 per decade, and
/// past the checker's bound. `far_row`'s reference is good to a few eps_64 d, far below
/// these errors (the textbook's is about eps_64 d^2 / r, 100 times more at d = 1e2).
#[test]
fn textbook_form_in_f64_keeps_hit_or_miss_but_its_error_grows_quadratically() {
    let options = Options::default().cases(41 * 41);
    let rows: Vec<_> = [1e2, 1e3, 1e4]
        .map(|d| check::far_row(&intersect_textbook, d, &options))
        .into();
    for row in &rows {
        assert_eq!(row.wrong, 0, "{row:?}");
    }
    for pair in rows.windows(2) {
        let growth = pair[1].worst_t_error / pair[0].worst_t_error;
        assert!(growth >= 60.0, "growth {growth}: {pair:?}");
    }
    let verdict = check::far(&intersect_textbook, &Options::default());
    assert!(verdict.failed("far_1e4"), "{verdict}");
}

/// Vieta's `t0 = c / q` removes the subtraction `-b - sqrt(b^2 - ac)` of the near root, but
/// `c = f.f - r^2` cancels near the surface too, so in general the near root is no more
/// accurate than `c`. Where `c` is exact the gain shows: integer origins just outside a
/// sphere of radius 2048 (f.f and r^2 below 2^24, so c = 1 ... 64 is exact in f32), rays
/// entering it at least 60 degrees from grazing (nearer the silhouette the stable form's
/// own r^2 - l.l loses a factor 1 / cos^2 of its relative precision, as the problem does).
/// The textbook near root is then off by more than a per cent (1e5 eps); the stable one
/// is within a few eps. In absolute terms, though, both are within the checker's bound:
/// the textbook form's failures at ordinary scales are the discriminant's, not these.
#[test]
fn vieta_keeps_the_near_root_where_c_is_exact() {
    let radius = 2048.0_f32;
    let sphere = Sphere32::new(Vec3::ZERO, radius);
    let sphere64 = Sphere::new(DVec3::ZERO, f64::from(radius));
    let mut rng = raylemma::rng::seeded(0x71e7a);
    let (mut worst_stable, mut worst_textbook, mut rays) = (0.0_f64, 0.0_f64, 0);
    for y in 0..40 {
        for z in 0..40 {
            let rest = 2048 * 2048 - y * y - z * z;
            let x = (f64::from(rest).sqrt().ceil()) as i32;
            let c = x * x - rest;
            if !(1..=64).contains(&c) {
                continue;
            }
            let origin = Vec3::new(x as f32, y as f32, z as f32);
            for _ in 0..20 {
                let dir = raylemma::sampling::sphere::sphere_uniform(&mut rng).as_vec3();
                let cos = -dir.dot(origin) / origin.length();
                if cos < 0.5 {
                    continue; // entering, well away from the silhouette
                }
                let ray = Ray32::new(origin, dir);
                let t_ref = intersect_stable(
                    &Ray::new(origin.as_dvec3(), dir.as_dvec3()),
                    &sphere64,
                    f64::NEG_INFINITY,
                )
                .expect("an entering ray hits");
                let bound = T_ERROR_BOUND
                    * f64::from(f32::EPSILON)
                    * (origin.as_dvec3().length() + f64::from(radius));
                for (form, worst) in [
                    (
                        single::intersect_stable as fn(&Ray32, &Sphere32, f32) -> Option<f32>,
                        &mut worst_stable,
                    ),
                    (single::intersect_textbook, &mut worst_textbook),
                ] {
                    let t = f64::from(form(&ray, &sphere, f32::NEG_INFINITY).expect("a hit"));
                    let along = (t - t_ref).abs() * dir.as_dvec3().length();
                    assert!(
                        along <= bound,
                        "t = {t}, want {t_ref}: {along:e} beyond {bound:e}"
                    );
                    *worst = worst.max((t / t_ref - 1.0).abs() / f64::from(f32::EPSILON));
                }
                rays += 1;
            }
        }
    }
    assert!(rays >= 100, "only {rays} rays");
    assert!(
        worst_stable <= 4.0,
        "stable near root: {worst_stable} eps relative"
    );
    assert!(
        worst_textbook >= 1e5,
        "textbook near root: only {worst_textbook} eps relative"
    );
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

mod planted_bugs;
mod properties;

// ---------------------------------------------------------------------------------------
// The source notes' claims, one by one.

/// The source notes: "the value of t corresponding to the first intersection is the
/// smallest value that is still greater than 0". In floating point, a ray leaving a surface
/// point finds its own sphere again at a tiny t about 4 times in 10, with both forms in both
/// precisions: a caller needs t_min > 0.
#[test]
fn seed_rule_t_greater_than_zero_self_intersects() {
    for (form, rate) in [
        (
            "stable f32",
            check::self_hit_rate(&single::intersect_stable, &Options::default()),
        ),
        (
            "textbook f32",
            check::self_hit_rate(&single::intersect_textbook, &Options::default()),
        ),
        (
            "stable f64",
            check::self_hit_rate(&intersect_stable, &Options::default()),
        ),
        (
            "textbook f64",
            check::self_hit_rate(&intersect_textbook, &Options::default()),
        ),
    ] {
        assert!(rate >= 0.35, "{form}: self-intersection rate {rate}");
    }
}

/// The source notes: "the ray intersects our sphere when the discriminant is >= 0". With
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

// ---------------------------------------------------------------------------------------
// Exercises: each test is ignored until the exercise is done; run one with
// `cargo test --test book geometry::sphere::exercise_1 -- --ignored`.

/// Exercise 1 of *Ray-sphere intersection*: the geometric method, from the closest point
/// of the line, `t_c = -f.D / a`, `h^2 = |f + t_c D|^2`, and the half-chord
/// `sqrt((r^2 - h^2) / a)`.
fn your_geometric_intersect(ray: &Ray32, sphere: &Sphere32, t_min: f32) -> Option<f32> {
    let _ = (ray, sphere, t_min);
    unimplemented!("exercise 1 of Ray-sphere intersection: write the geometric method")
}

#[test]
#[ignore = "exercise 1 of Ray-sphere intersection: fill in your_geometric_intersect, then run it"]
fn exercise_1_geometric_method() {
    let verdict = check::intersection(&your_geometric_intersect, &Options::default());
    println!("{verdict}");
    verdict.assert_pass();
    check::far(&your_geometric_intersect, &Options::default()).assert_pass();
}

/// Exercise 2 of *Ray-sphere intersection*: the textbook form with `b = D.f`,
/// `c = f.f - r^2` and `b^2 - a c` computed in `f64` from the widened `f32` components
/// (`f = O - C` itself stays `f32`), the roots rounded back to `f32`.
fn your_mixed_precision(ray: &Ray32, sphere: &Sphere32, t_min: f32) -> Option<f32> {
    let _ = (ray, sphere, t_min);
    unimplemented!("exercise 2 of Ray-sphere intersection: write the mixed-precision form")
}

#[test]
#[ignore = "exercise 2 of Ray-sphere intersection: fill in your_mixed_precision, then run it"]
fn exercise_2_mixed_precision_passes_far() {
    let far = check::far(&your_mixed_precision, &Options::default());
    println!("{far}");
    far.assert_pass();
    check::intersection(&your_mixed_precision, &Options::default()).assert_pass();
}

/// Exercise 3 of *Ray-sphere intersection*: the textbook form with `D` normalised first
/// (so `a = 1`), `t` divided by `|D|` at the end.
fn your_textbook_normalised(ray: &Ray32, sphere: &Sphere32, t_min: f32) -> Option<f32> {
    let _ = (ray, sphere, t_min);
    unimplemented!("exercise 3 of Ray-sphere intersection: normalise D inside the textbook form")
}

#[test]
#[ignore = "exercise 3 of Ray-sphere intersection: fill in your_textbook_normalised, then run it"]
fn exercise_3_normalise_first() {
    let failed = |v: &raylemma::check::Verdict| {
        v.findings
            .iter()
            .filter(|f| !f.passed())
            .map(|f| f.name.clone())
            .collect::<Vec<_>>()
    };
    let yours = check::intersection(&your_textbook_normalised, &Options::default());
    let textbook = check::intersection(&single::intersect_textbook, &Options::default());
    println!("{yours}");
    // Where the textbook form is well-conditioned, yours agrees with it: every claim that
    // does not measure rounding (misses, tangents, surface_origin) passes...
    for claim in ["misses", "tangents", "surface_origin"] {
        assert!(!yours.failed(claim), "{claim}:\n{yours}");
    }
    // ... the claims that fail are the textbook form's ...
    assert_eq!(failed(&yours), failed(&textbook), "{yours}\n{textbook}");
    // ... and the far bundle still defeats it: the cancellation is in b^2 - c.
    let far = check::far(&your_textbook_normalised, &Options::default());
    for distance in ["far_1e3", "far_3e3", "far_1e4"] {
        assert!(far.failed(distance), "passed {distance}:\n{far}");
    }
}

/// Exercise 4 of *Ray-sphere intersection*: your geometric method of exercise 1 called with
/// `t_min = 0` whatever the caller passes: the source notes' rule.
fn your_source_rule(ray: &Ray32, sphere: &Sphere32, t_min: f32) -> Option<f32> {
    let _ = t_min;
    your_geometric_intersect(ray, sphere, 0.0)
}

#[test]
#[ignore = "exercise 4 of Ray-sphere intersection: do exercise 1 first, then run it"]
fn exercise_4_the_source_rule() {
    let verdict = check::intersection(&your_source_rule, &Options::default());
    println!("{verdict}"); // read the counterexamples of the claims that fail
    // The rule breaks exactly the two claims that pass a t_min > 0.
    for claim in ["surface_origin", "nearest_root"] {
        assert!(verdict.failed(claim), "{claim} passed:\n{verdict}");
    }
    for claim in ["hits", "misses", "tangents", "direction_scale"] {
        assert!(!verdict.failed(claim), "{claim} failed:\n{verdict}");
    }
}

/// Exercise 5 of *Ray-sphere intersection*: your prediction of the distance, in radii, at
/// which the textbook form in `f64` starts answering hit or miss wrongly.
const YOUR_F64_CLIFF: Option<f64> = None;

#[test]
#[ignore = "exercise 5 of Ray-sphere intersection: set YOUR_F64_CLIFF, then run it"]
fn exercise_5_the_f64_cliff() {
    // The cliff as measured: the first distance, in steps of a quarter decade, at which the
    // far bundle gets at least 10 % of its hit/miss answers wrong. `far_row`'s f64 reference
    // decides hit or miss from the distance of the centre to the line, good to a few
    // eps_64 d, far inside the silhouette band: it can judge f64 routines at these
    // distances. The same rule finds the f32 cliff between 1e3 and 3e3 radii.
    let options = Options::default().cases(41 * 41);
    let cliff = |wrong_share: &dyn Fn(f64) -> f64, from: i32| {
        (from..from + 16)
            .map(|k| 10f64.powf(f64::from(k) / 4.0))
            .find(|&d| wrong_share(d) >= 0.1)
            .expect("a cliff within four decades")
    };
    let share = |row: check::FarRow| row.wrong as f64 / row.rays as f64;
    let f32_cliff = cliff(
        &|d| share(check::far_row(&single::intersect_textbook, d, &options)),
        8,
    );
    assert!(
        (1e3..=3.2e3).contains(&f32_cliff),
        "f32 cliff at {f32_cliff}"
    );
    let f64_cliff = cliff(
        &|d| share(check::far_row(&intersect_textbook, d, &options)),
        24,
    );
    let answer = YOUR_F64_CLIFF.expect("set YOUR_F64_CLIFF");
    assert!(
        (f64_cliff / 3.0..=f64_cliff * 3.0).contains(&answer),
        "your cliff {answer:e} radii; measured {f64_cliff:e} (f32: {f32_cliff:e})"
    );
}
