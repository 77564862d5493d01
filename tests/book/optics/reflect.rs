//! Tests of the chapter *Reflection and refraction* (`chapters/optics/reflect.md`).
//!
//! Deterministic checks (fixed seeds, constructed answers). The chapter's checker runs on
//! the project's `reflect` and `refract`, which must pass, and on planted bugs, each of which
//! must fail the claim it breaks.

use glam::DVec3;
use quickcheck::{Arbitrary, Gen, QuickCheck, TestResult};
use raylemma::check::Options;
use raylemma::check::reflect::{self as check, planted};
use raylemma::optics::reflect::{Refraction, critical_angle, reflect, refract};

const EPS: f64 = f64::EPSILON;

/// A unit direction at angle `theta` (radians) from `-n`, tilted towards `t`.
fn incident(theta: f64, n: DVec3, t: DVec3) -> DVec3 {
    -theta.cos() * n + theta.sin() * t
}

fn frame() -> (DVec3, DVec3) {
    let n = DVec3::new(0.3, -0.5, 0.8).normalize();
    (n, n.any_orthonormal_vector())
}

fn transmitted(r: Refraction) -> DVec3 {
    match r {
        Refraction::Transmitted(w) => w,
        Refraction::TotalInternalReflection => panic!("unexpected total internal reflection"),
    }
}

// ---------------------------------------------------------------------------------------
// The project's code passes every claim.

#[test]
fn reflect_passes_every_check() {
    let verdict = check::reflection(&reflect, &Options::default());
    verdict.assert_pass();
}

#[test]
fn refract_passes_every_check() {
    let verdict = check::refraction(&refract, &Options::default());
    verdict.assert_pass();
}

// ---------------------------------------------------------------------------------------
// The seed's claims.

// ANCHOR: seed_reflection
/// Source notes: "w_o = 2n + w_i". Right at normal incidence only; elsewhere the result is not
/// even a unit vector (|2n + w_i|^2 = 5 - 4 cos_i) and leaves at the wrong angle.
#[test]
fn seed_reflection_fails_unit_length_and_equal_angles() {
    let verdict = check::reflection(&planted::seed_reflect, &Options::default());
    assert!(verdict.failed("unit_length"), "{verdict}");
    assert!(verdict.failed("equal_angles"), "{verdict}");
    // It stays in the plane of incidence and retraces itself: those claims cannot see it.
    assert!(
        !verdict.failed("coplanar") && !verdict.failed("reversible"),
        "{verdict}"
    );
    let (n, t) = frame();
    let w_i = incident(60f64.to_radians(), n, t);
    let seed = planted::seed_reflect(w_i, n);
    assert!((seed.length() - 3f64.sqrt()).abs() < 1e-15); // 5 - 4 cos 60° = 3
    assert!((reflect(w_i, n) - incident(60f64.to_radians(), -n, t)).length() < 1e-15);
}
// ANCHOR_END: seed_reflection

/// Seed: "n = (w_o - w_i) / 2". For the true mirror direction this is cos(theta_i) n: it
/// has the normal's direction but not its length, except at normal incidence.
#[test]
fn seed_normal_formula_is_off_by_cos_theta() {
    let (n, t) = frame();
    for degrees in [0.0, 30.0, 60.0, 85.0] {
        let theta = f64::to_radians(degrees);
        let w_i = incident(theta, n, t);
        let half = (reflect(w_i, n) - w_i) / 2.0;
        assert!((half - theta.cos() * n).length() < 4.0 * EPS, "{degrees}");
        assert!(half.normalize().dot(n) > 1.0 - 4.0 * EPS);
    }
}

/// Seed: the perpendicular (surface) component of w_t is (n1/n2) times that of w_i, and
/// the normal component is -sqrt(1 - |w_t,perp|^2) n, for a normal facing the light.
#[test]
fn seed_refraction_components_are_right() {
    let (n, t) = frame();
    for (n1, n2) in [(1.0, 1.5), (1.5, 1.0), (1.0, 2.4)] {
        for degrees in [0.0, 20.0, 40.0, 60.0, 89.0] {
            let w_i = incident(f64::to_radians(degrees), n, t);
            let Refraction::Transmitted(w_t) = refract(w_i, n, n1, n2) else {
                assert!(n1 / n2 * f64::to_radians(degrees).sin() > 1.0);
                continue;
            };
            let perp_i = w_i - w_i.dot(n) * n;
            let perp_t = n1 / n2 * perp_i;
            let seed = perp_t - (1.0 - perp_t.length_squared()).sqrt() * n;
            assert!(
                (seed - w_t).length() < 8.0 * EPS,
                "{n1} -> {n2} at {degrees} deg: w_t = {w_t:?}, the seed's perpendicular/parallel split gives {seed:?}"
            );
        }
    }
}

// ---------------------------------------------------------------------------------------
// Planted bugs the refraction checker must reject.

#[test]
fn checker_rejects_a_missing_square_root() {
    let verdict = check::refraction(&planted::refract_without_sqrt, &Options::default());
    assert!(
        verdict.failed("unit_length") && verdict.failed("snell"),
        "{verdict}"
    );
}

#[test]
fn checker_rejects_swapped_indices() {
    let verdict = check::refraction(&planted::refract_swapped_indices, &Options::default());
    assert!(
        verdict.failed("snell") && verdict.failed("tir_iff"),
        "{verdict}"
    );
}

#[test]
fn checker_rejects_nan_for_total_internal_reflection() {
    let verdict = check::refraction(&planted::refract_nan_tir, &Options::default());
    assert!(
        verdict.failed("finite") && verdict.failed("tir_iff"),
        "{verdict}"
    );
}

#[test]
fn checker_rejects_an_unflipped_normal() {
    let verdict = check::refraction(&planted::refract_unflipped_normal, &Options::default());
    assert!(
        verdict.failed("normal_side") && verdict.failed("far_side"),
        "{verdict}"
    );
}

#[test]
fn reflection_checker_rejects_nan_and_identity() {
    // The identity map is reversible and coplanar: only the angle claim sees it.
    let options = Options::default().cases(1_000);
    let verdict = check::reflection(&planted::reflect_nan, &options);
    assert!(
        verdict.failed("finite") && verdict.failed("unit_length"),
        "{verdict}"
    );
    let verdict = check::reflection(&planted::reflect_identity, &options);
    assert!(
        verdict.failed("equal_angles") && !verdict.failed("reversible"),
        "{verdict}"
    );
}

// ---------------------------------------------------------------------------------------
// Constructed cases.

/// Reflection: the angle of reflection equals the angle of incidence, for constructed
/// angles, with the normal on either side.
#[test]
fn angle_of_reflection_equals_angle_of_incidence() {
    let (n, t) = frame();
    for degrees in [0.0, 10.0, 45.0, 80.0, 90.0] {
        let theta = f64::to_radians(degrees);
        let w_i = incident(theta, n, t);
        let expected = incident(theta, -n, t); // mirror image: normal component flipped
        for normal in [n, -n] {
            let w_o = reflect(w_i, normal);
            assert!((w_o - expected).length() < 4.0 * EPS, "{degrees}: {w_o:?}");
        }
    }
}

/// Snell's law on constructed angles, both ways through glass: n1 sin t1 = n2 sin t2.
#[test]
fn snell_law_on_constructed_angles() {
    let (n, t) = frame();
    for (n1, n2) in [(1.0, 1.5), (1.5, 1.0), (1.33, 2.4)] {
        for degrees in [0.0, 15.0, 30.0, 41.0, 60.0, 89.0] {
            let theta = f64::to_radians(degrees);
            let w_i = incident(theta, n, t);
            let sin_t = n1 * theta.sin() / n2;
            let result = refract(w_i, n, n1, n2);
            if sin_t > 1.0 {
                assert_eq!(result, Refraction::TotalInternalReflection);
                continue;
            }
            // The expected direction, built from the angle asin(sin_t) on the far side.
            let expected = -(1.0 - sin_t * sin_t).sqrt() * n + sin_t * t;
            let w_t = transmitted(result);
            assert!(
                (w_t - expected).length() < 8.0 * EPS,
                "{n1} -> {n2} at {degrees} deg: w_t = {w_t:?}, Snell's angle asin({sin_t}) gives {expected:?}"
            );
        }
    }
}

/// The critical angle of glass (1.5) to air: asin(1/1.5) = 41.81°. Just below it the ray
/// is transmitted, nearly grazing; just above it is totally reflected.
#[test]
fn critical_angle_of_glass_is_41_81_degrees() {
    let theta_c = critical_angle(1.5, 1.0).unwrap();
    assert!((theta_c.to_degrees() - 41.81).abs() < 0.005);
    assert_eq!(critical_angle(1.0, 1.5), None);
    let (n, t) = frame();
    let below = refract(incident(theta_c - 1e-9, n, t), n, 1.5, 1.0);
    let w_t = transmitted(below);
    assert!(w_t.dot(n) > -1e-3 && w_t.dot(n) < 0.0, "{w_t:?}"); // nearly grazing
    let above = refract(incident(theta_c + 1e-9, n, t), n, 1.5, 1.0);
    assert_eq!(above, Refraction::TotalInternalReflection);
    // At the critical angle itself either answer is right, but never a NaN.
    if let Refraction::Transmitted(w) = refract(incident(theta_c, n, t), n, 1.5, 1.0) {
        assert!(w.is_finite() && (w.length() - 1.0).abs() < 1e-15);
    }
}

/// Grazing incidence: into the denser medium the ray bends to the critical angle; out of
/// it, it is totally reflected; with matched indices it goes straight on.
#[test]
fn grazing_incidence() {
    let (n, t) = frame();
    let w_i = t; // exactly along the surface
    let w_t = transmitted(refract(w_i, n, 1.0, 1.5));
    let sin_t = w_t.cross(n).length();
    assert!((sin_t - 1.0 / 1.5).abs() < 4.0 * EPS);
    assert!(w_t.dot(n) < 0.0);
    assert_eq!(
        refract(w_i, n, 1.5, 1.0),
        Refraction::TotalInternalReflection
    );
    assert!((transmitted(refract(w_i, n, 1.2, 1.2)) - w_i).length() < 4.0 * EPS);
    assert!((reflect(w_i, n) - w_i).length() < 4.0 * EPS);
}

/// Normal incidence goes straight through, whatever the indices.
#[test]
fn normal_incidence_goes_straight_through() {
    let (n, _) = frame();
    for (n1, n2) in [(1.0, 1.5), (1.5, 1.0), (2.4, 1.0)] {
        for normal in [n, -n] {
            let w_t = transmitted(refract(-n, normal, n1, n2));
            assert!((w_t + n).length() < 8.0 * EPS);
        }
    }
}

/// The normal on either side gives the same answer, bit for bit up to rounding.
#[test]
fn either_side_normal_gives_the_same_answer() {
    let (n, t) = frame();
    for degrees in [5.0, 35.0, 50.0, 80.0] {
        let w_i = incident(f64::to_radians(degrees), n, t);
        for (n1, n2) in [(1.0, 1.5), (1.5, 1.0)] {
            assert_eq!(refract(w_i, n, n1, n2), refract(w_i, -n, n1, n2));
        }
        assert_eq!(reflect(w_i, n), reflect(w_i, -n));
    }
}

/// Reversibility: refracting back along -w_t recovers -w_i.
#[test]
fn refraction_is_reversible() {
    let (n, t) = frame();
    for (n1, n2) in [(1.0, 1.5), (1.5, 1.0), (1.0, 2.4)] {
        for degrees in [0.0, 20.0, 40.0, 70.0] {
            let w_i = incident(f64::to_radians(degrees), n, t);
            let Refraction::Transmitted(w_t) = refract(w_i, n, n1, n2) else {
                continue;
            };
            let back = transmitted(refract(-w_t, n, n2, n1));
            assert!(
                (back + w_i).length() < 16.0 * EPS,
                "{n1} -> {n2} at {degrees} deg: refracting -w_t back gave {back:?}, expected -w_i = {:?}",
                -w_i
            );
        }
    }
}

/// Refraction never returns NaN, even for every angle around the critical one, and each
/// answer is on the correct side of the critical angle to within 1e-14 rad (ten steps of
/// the walk; the rounding of the incident direction and of cos_i is about 1e-16 rad).
#[test]
fn no_nan_across_the_critical_angle() {
    let (n, t) = frame();
    let theta_c = critical_angle(1.5, 1.0).unwrap();
    for k in -1000..=1000 {
        let theta = theta_c + f64::from(k) * 1e-15;
        match refract(incident(theta, n, t), n, 1.5, 1.0) {
            Refraction::Transmitted(w) => {
                assert!(
                    w.is_finite() && theta <= theta_c + 1e-14,
                    "{k}: transmitted"
                )
            }
            Refraction::TotalInternalReflection => {
                assert!(theta >= theta_c - 1e-14, "{k}: totally reflected")
            }
        }
    }
}

// ---------------------------------------------------------------------------------------
// Properties over random inputs (quickcheck, fixed seeds).

/// A random unit direction and normal, from three integers each.
#[derive(Clone, Debug)]
struct Dirs {
    w_i: DVec3,
    n: DVec3,
    pair: usize,
}

fn unit(g: &mut Gen) -> DVec3 {
    loop {
        let mut c = || f64::from(i32::arbitrary(g) % 10_000) / 10_000.0;
        let v = DVec3::new(c(), c(), c());
        if v.length() > 1e-3 {
            return v.normalize();
        }
    }
}

impl Arbitrary for Dirs {
    fn arbitrary(g: &mut Gen) -> Self {
        let n = unit(g);
        let mut w_i = unit(g);
        if bool::arbitrary(g) && w_i.dot(n) > 0.0 {
            w_i = -w_i; // so three quarters of the cases have the normal facing the light
        }
        Dirs {
            w_i,
            n,
            pair: usize::arbitrary(g) % check::INDEX_PAIRS.len(),
        }
    }
}

fn quickcheck(seed: u64) -> QuickCheck {
    QuickCheck::new()
        .rng(Gen::from_size_and_seed(100, seed))
        .tests(5_000)
        .max_tests(50_000)
}

fn prop_reflection(d: Dirs) -> bool {
    let w_o = reflect(d.w_i, d.n);
    let coplanar = d.w_i.cross(d.n).dot(w_o).abs() <= 8.0 * EPS;
    let angles = (w_o.dot(d.n) + d.w_i.dot(d.n)).abs() <= 8.0 * EPS;
    let length = (w_o.length() - 1.0).abs() <= 8.0 * EPS;
    coplanar && angles && length
}

#[test]
fn quickcheck_reflection() {
    quickcheck(11).quickcheck(prop_reflection as fn(Dirs) -> bool);
}

fn prop_refraction(d: Dirs) -> TestResult {
    let (n1, n2) = check::INDEX_PAIRS[d.pair];
    let cos_i = d.w_i.dot(d.n).abs();
    let sin_i = d.w_i.cross(d.n).length();
    if (n1 / n2 * sin_i - 1.0).abs() < 1e-9 || cos_i < 1e-6 {
        return TestResult::discard();
    }
    match refract(d.w_i, d.n, n1, n2) {
        Refraction::TotalInternalReflection => TestResult::from_bool(n1 / n2 * sin_i > 1.0),
        Refraction::Transmitted(w_t) => {
            let sin_t = w_t.cross(d.n).length();
            let snell = (n1 * sin_i - n2 * sin_t).abs() <= 8.0 * EPS * n1.max(n2);
            let length = (w_t.length() - 1.0).abs() <= 8.0 * EPS;
            let through = w_t.dot(d.n) * d.w_i.dot(d.n) > 0.0;
            let back = refract(-w_t, d.n, n2, n1)
                .transmitted()
                .is_some_and(|b| (b + d.w_i).length() * cos_i <= 16.0 * EPS);
            TestResult::from_bool(snell && length && through && back)
        }
    }
}

#[test]
fn quickcheck_refraction() {
    quickcheck(12).quickcheck(prop_refraction as fn(Dirs) -> TestResult);
}

// ---------------------------------------------------------------------------------------
// Exercises. Each scaffold is the student's to fill in; each ignored test checks it, and
// fails until it is done: `cargo test --test book optics::reflect::exercise_ -- --ignored`.

/// Exercise 1 of *Reflection and refraction*: mirror reflection of `w`, which points
/// *away* from the surface, towards where the light came from; the result points away too.
#[allow(unused_variables)]
fn your_reflect_away(w: DVec3, n: DVec3) -> DVec3 {
    unimplemented!(
        "exercise 1 of Reflection and refraction: reflect w (pointing away from the surface) about n"
    )
}

/// Exercise 1 of *Reflection and refraction*: refraction of `w`, which points *away* from
/// the surface on the side of index `n1`, into the medium of index `n2`.
#[allow(unused_variables)]
fn your_refract_away(w: DVec3, n: DVec3, n1: f64, n2: f64) -> Refraction {
    unimplemented!(
        "exercise 1 of Reflection and refraction: refract w (pointing away from the surface) from n1 into n2"
    )
}

#[test]
#[ignore = "exercise 1 of Reflection and refraction: fill in your_reflect_away and your_refract_away, then run it"]
fn exercise_1_the_other_convention() {
    let reflection = |w_i: DVec3, n: DVec3| your_reflect_away(-w_i, n);
    check::reflection(&reflection, &Options::default()).assert_pass();
    let refraction = |w_i: DVec3, n: DVec3, n1: f64, n2: f64| your_refract_away(-w_i, n, n1, n2);
    check::refraction(&refraction, &Options::default()).assert_pass();
}

/// Exercise 2 of *Reflection and refraction*: the direction in which a ray `w_i` (the
/// direction of travel) leaves a slab of index `n_slab` in air, with parallel faces of
/// normal `n`: refracted in at the first face and out at the second. `None` if the second
/// face reflects it totally.
#[allow(unused_variables)]
fn your_through_slab(w_i: DVec3, n: DVec3, n_slab: f64) -> Option<DVec3> {
    unimplemented!(
        "exercise 2 of Reflection and refraction: refract w_i into the slab and out again"
    )
}

#[test]
#[ignore = "exercise 2 of Reflection and refraction: fill in your_through_slab, then run it"]
fn exercise_2_through_a_slab() {
    let mut rng = raylemma::rng::seeded(7);
    for k in 0..1000 {
        let c = check::random_case(&mut rng, k); // grazing cases are skipped below
        let cos_i = -c.w_i.dot(c.m);
        for n_slab in [1.33, 1.5, 2.4] {
            let out = your_through_slab(c.w_i, c.n, n_slab);
            if cos_i < 1e-6 {
                continue; // rounding at grazing incidence may decide either way
            }
            let w = out.unwrap_or_else(|| {
                panic!("{n_slab}: total internal reflection at the second face for {c:?}, but sin inside <= 1/n")
            });
            assert!(
                (w - c.w_i).length() <= 16.0 * EPS / cos_i,
                "{n_slab}: {w:?} leaves, {:?} came in",
                c.w_i
            );
        }
    }
}

/// Exercise 3 of *Reflection and refraction*: the unit normal `h` that mirrors the
/// incident direction `w_i` (the direction of travel) into `w_o`, `reflect(w_i, h) = w_o`,
/// or `None` if there is none (`w_o = w_i`: the ray goes on, grazing).
#[allow(unused_variables)]
fn your_half_vector(w_i: DVec3, w_o: DVec3) -> Option<DVec3> {
    unimplemented!("exercise 3 of Reflection and refraction: the normal that reflects w_i into w_o")
}

#[test]
#[ignore = "exercise 3 of Reflection and refraction: fill in your_half_vector, then run it"]
fn exercise_3_half_vector() {
    let mut rng = raylemma::rng::seeded(8);
    for _ in 0..10_000 {
        let w_i = raylemma::sampling::sphere::sphere_uniform(&mut rng);
        let w_o = raylemma::sampling::sphere::sphere_uniform(&mut rng);
        let gap = (w_o - w_i).length();
        if gap <= 1e-3 {
            continue;
        }
        let h = your_half_vector(w_i, w_o).expect("w_o != w_i has a half vector");
        assert!(
            (h.length() - 1.0).abs() <= 4.0 * EPS,
            "|h| = {}",
            h.length()
        );
        let back = reflect(w_i, h);
        assert!(
            (back - w_o).length() <= 16.0 * EPS / gap,
            "reflect(w_i, h) = {back:?}, w_o = {w_o:?}"
        );
    }
    let w = DVec3::new(0.6, 0.0, 0.8);
    assert_eq!(
        your_half_vector(w, w),
        None,
        "w_o = w_i: no normal reflects w_i into itself"
    );
}

/// Exercise 4 of *Reflection and refraction*: `refract` in `f32`, `None` under total
/// internal reflection.
#[allow(unused_variables)]
fn your_refract_f32(w_i: glam::Vec3, n: glam::Vec3, n1: f32, n2: f32) -> Option<glam::Vec3> {
    unimplemented!("exercise 4 of Reflection and refraction: write refract in f32")
}

#[test]
#[ignore = "exercise 4 of Reflection and refraction: fill in your_refract_f32, then run it"]
fn exercise_4_refract_in_f32() {
    let eps32 = f64::from(f32::EPSILON);
    let mut rng = raylemma::rng::seeded(9);
    let (mut worst_unit, mut worst_snell) = (0.0f64, 0.0f64);
    for k in 0..20_000 {
        let c = check::random_case(&mut rng, k);
        let (n1, n2) = check::INDEX_PAIRS[(k / 16) % check::INDEX_PAIRS.len()];
        let (w_i, n, m) = (c.w_i.as_vec3(), c.n.as_vec3(), c.m.as_vec3().as_dvec3());
        let w_i64 = w_i.as_dvec3(); // the f32 input, exactly, measured in f64
        let sin_i = w_i64.cross(m).length() / w_i64.length();
        let past = n1 / n2 * sin_i - 1.0;
        let out = your_refract_f32(w_i, n, n1 as f32, n2 as f32);
        if past.abs() > 1e-5 {
            assert_eq!(out.is_none(), past > 0.0, "{c:?}, {n1} -> {n2}: {out:?}");
        }
        let Some(w_t) = out else { continue };
        let w_t = w_t.as_dvec3();
        worst_unit = worst_unit.max((w_t.length() - 1.0).abs() / eps32);
        let sin_t = w_t.cross(m).length() / w_t.length();
        worst_snell = worst_snell.max((n1 * sin_i - n2 * sin_t).abs() / n1.max(n2) / eps32);
    }
    assert!(
        worst_unit <= 8.0,
        "worst | |w_t| - 1 | = {worst_unit:.2} f32 eps"
    );
    assert!(
        worst_snell <= 8.0,
        "worst Snell error = {worst_snell:.2} f32 eps"
    );
}

/// What the rearranged `cos^2 theta_t = (1 - eta^2) + (eta cos_i)^2` does *not* buy over
/// the textbook `1 - eta^2 (1 - cos_i^2)`: a sign. Entering a denser medium (the rounded
/// `eta = n1 / n2` at most 1) the textbook form cannot round below 0 either, because
/// rounding is monotone: for `cos_i <= 1` the rounded `eta^2 (1 - cos_i^2)` is at most 1,
/// and for a dot product that rounded above 1 it is at most 0. Checked on nearly matched
/// indices (`n2 / n1 - 1` from 1e-16 on), cosines near 0 and 1, and `1 + 2^-52`.
#[test]
fn neither_form_of_cos_t_squared_rounds_below_zero_entering_a_denser_medium() {
    let mut rng = raylemma::rng::seeded(7);
    let mut u = || raylemma::rng::uniform(&mut rng, 0.0, 1.0);
    for k in 0..1_000_000 {
        let n1 = 1.0 + 1.5 * u();
        let gap = [1e-16, 1e-15, 1e-12, 1e-7, 0.1, 0.5][k % 6] * u();
        let eta = n1 / (n1 * (1.0 + gap));
        assert!(eta <= 1.0);
        let c = match k % 4 {
            0 => u(),
            1 => 1.0 - 1e-15 * u(),
            2 => 1e-8 * u(),
            _ => 1.0 + f64::EPSILON,
        };
        let textbook = 1.0 - eta * eta * (1.0 - c * c);
        let rearranged = (1.0 - eta * eta) + (eta * c) * (eta * c);
        assert!(
            textbook >= 0.0 && rearranged >= 0.0,
            "eta {eta:e}, cos {c:e}"
        );
    }
}
