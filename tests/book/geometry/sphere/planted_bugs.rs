//! Planted bugs (`raylemma::check::sphere::planted`): each must be rejected by the
//! checker, naming the right claim.

use super::*;

fn verdict_f64(f: fn(&Ray, &Sphere, f64) -> Option<f64>) -> raylemma::check::Verdict {
    check::intersection(&f, &Options::default().cases(4_000))
}

#[test]
fn checker_rejects_the_textbook_form() {
    // Even at ordinary scales (centres within 10 radii of the origin) the discriminant's
    // cancellation exceeds the error bound for some rays (d / r of about 10 in the verdict's
    // examples).
    let verdict = check::intersection(&single::intersect_textbook, &Options::default());
    assert!(!verdict.passed(), "{verdict}");
    // And in f64: rarer, but the same cancellation.
    let verdict = check::intersection(&intersect_textbook, &Options::default());
    assert!(!verdict.passed(), "{verdict}");
}

#[test]
fn checker_rejects_the_seeds_t_greater_than_zero_rule() {
    // The source notes: "the smallest value that is still greater than 0", ignoring t_min.
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

/// The half-fix of exercise 2: only `b^2 - ac` in f64, from `b` and `c` rounded to f32.
/// The cancellation has already happened in `c`, so the far bundle still defeats it.
#[test]
fn only_the_discriminant_in_f64_still_fails_far_spheres() {
    let verdict = check::far(&planted::discriminant_only_in_f64, &Options::default());
    for distance in ["far_1e3", "far_3e3", "far_1e4"] {
        assert!(verdict.failed(distance), "passed {distance}:\n{verdict}");
    }
}

/// Exercise 3's change: the direction normalised first (a = 1). The discriminant
/// `b^2 - c` still subtracts two numbers of about d^2, so the far bundle still defeats it,
/// and at ordinary scales it fails the same claims as the textbook form.
#[test]
fn normalising_first_keeps_the_cancellation() {
    let verdict = check::far(&planted::textbook_normalised, &Options::default());
    for distance in ["far_1e3", "far_3e3", "far_1e4"] {
        assert!(verdict.failed(distance), "passed {distance}:\n{verdict}");
    }
    let failed = |v: &raylemma::check::Verdict| {
        v.findings
            .iter()
            .filter(|f| !f.passed())
            .map(|f| f.name.clone())
            .collect::<Vec<_>>()
    };
    let normalised = check::intersection(&planted::textbook_normalised, &Options::default());
    let textbook = check::intersection(&single::intersect_textbook, &Options::default());
    assert_eq!(
        failed(&normalised),
        failed(&textbook),
        "{normalised}\n{textbook}"
    );
}

#[test]
fn far_checker_rejects_a_sphere_that_is_never_hit() {
    let verdict = check::far(&planted::never_hits, &Options::default());
    assert!(!verdict.passed(), "{verdict}");
}
