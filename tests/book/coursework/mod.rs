//! Tests of chapter *Coursework*: the verdict a checker returns, as a student reads it
//! (a claim with no cases fails, a NaN error fails and stays visible, the worst failure is
//! reported beside the first), the one `Options` every checker takes, and `max_abs`, which
//! keeps a NaN. The student edition (markers, stubs, the scrubber, `raylemma exercises`)
//! is tested in [`edition`], the new checkers on the seeds' mistakes in [`checkers`].

mod checkers;
mod edition;
/// The chapter's test file of one's own, shown by anchor.
mod mine;
#[cfg(feature = "twins")]
mod mistakes;

use raylemma::check::reflect::{self, REFLECTION_SEED, REFRACTION_SEED};
use raylemma::check::{Finding, Options, Verdict, max_abs};

#[test]
fn options_left_unset_take_each_checker_default() {
    let default = Options::default();
    assert_eq!(default, Options::new());
    assert_eq!(default.cases_or(20_000), 20_000);
    assert_eq!(default.seed_or(0xC41), 0xC41);
    assert_eq!(default.level(), raylemma::stats::test_alpha());
    let set = Options::default().cases(1_000).seed(7).alpha(0.01);
    assert_eq!(
        (set.cases_or(20_000), set.seed_or(0xC41), set.level()),
        (1_000, 7, 0.01)
    );
    // The same options, two checkers, each with its own default seed: the reflection and
    // refraction checkers draw different cases from `Options::default()`.
    assert_ne!(REFLECTION_SEED, REFRACTION_SEED);
    let verdict = reflect::reflection(&raylemma::optics::reflect::reflect, &Options::default());
    assert_eq!(verdict.finding("finite").cases, reflect::CASES);
}

#[test]
fn max_abs_keeps_a_nan_wherever_it_is() {
    assert_eq!(max_abs([]), 0.0);
    assert_eq!(max_abs([1.0, -3.0, 2.0]), 3.0);
    for i in 0..3 {
        let mut xs = [1.0, 2.0, 3.0];
        xs[i] = f64::NAN;
        assert!(max_abs(xs).is_nan(), "NaN at {i} dropped");
        // What it replaces: glam drops a NaN in all but the last component.
        let dropped = glam::DVec3::from_array(xs).max_element();
        assert_eq!(dropped.is_nan(), i == 2);
    }
}

#[test]
fn nan_errors_fail_and_stay_visible() {
    let mut f = Finding::new("x", "claim");
    f.measure(1.0, 2.0, String::new);
    assert!(f.passed());
    f.measure(f64::NAN, 2.0, || "nan".into());
    f.measure(0.5, 2.0, String::new);
    assert!(!f.passed());
    assert!(f.worst.is_some_and(|(w, _)| w.is_nan()));
    assert_eq!(f.example.as_deref(), Some("nan"));
}

#[test]
fn the_worst_failure_is_kept_beside_the_first() {
    let mut f = Finding::new("x", "claim");
    for (e, what) in [
        (3.0, "first"),
        (9.0, "worst"),
        (5.0, "middle"),
        (0.5, "fine"),
    ] {
        f.measure(e, 2.0, || what.into());
    }
    assert_eq!((f.cases, f.failures), (4, 3));
    assert_eq!(f.example.as_deref(), Some("first"));
    assert_eq!(f.worst_example.as_deref(), Some("worst"));
    let mut v = Verdict::new("demo");
    v.findings.push(f);
    assert!(v.to_string().contains("worst failure: worst"), "{v}");
    // One failure: no separate worst case.
    let mut g = Finding::new("y", "claim");
    g.measure(3.0, 2.0, || "only".into());
    assert!(g.worst_example.is_none());
}

#[test]
fn a_check_with_no_cases_fails() {
    assert!(!Finding::new("x", "claim").passed());
    assert!(!Verdict::new("nothing").passed());
}

#[test]
fn report_names_failures() {
    let mut v = Verdict::new("demo");
    let mut f = Finding::new("bad", "never exceeds 1");
    f.measure(3.0, 1.0, || "case 7".into());
    v.findings.push(f);
    let text = v.to_string();
    assert!(
        text.starts_with("FAIL: demo") && text.contains("[FAIL] bad") && text.contains("case 7"),
        "{text}"
    );
    assert!(v.failed("bad"));
}
