//! Tests of the chapter *Accuracy against exact arithmetic* (`chapters/checking/accuracy.md`):
//! every form of every corpus meets what the book says of it, the claim rejects answers
//! with the mistakes it is meant to catch, and bad corpus files are refused with their line.
//! Deterministic: the corpora are fixed inputs with exact answers (`tools/exact`).

use raylemma::check::accuracy::{self, BOUND, Expect, Precision, corpus, forms, planted};

use crate::support::root;

fn load(name: &str) -> accuracy::Corpus {
    corpus::load(&root().join(format!("data/corpus/{name}.txt"))).expect("the corpus reads")
}

#[test]
fn every_corpus_file_has_forms_and_every_verb_a_form_within_the_bound() {
    let all = corpus::load_all(root()).expect("the corpora read");
    let names: Vec<&str> = all.iter().map(|c| c.name.as_str()).collect();
    let mut listed = forms::CORPORA.to_vec();
    listed.sort_unstable();
    assert_eq!(names, listed, "data/corpus/*.txt and forms::CORPORA differ");
    for c in &all {
        let forms = forms::of(&c.name).expect("forms");
        for v in &c.verbs {
            assert!(
                forms
                    .iter()
                    .any(|f| f.verb == v.name && f.expect == Expect::Within),
                "{}: no form of {} is held to the bound",
                c.file,
                v.name
            );
            assert!(
                c.cases_of(&v.name).count() > 0,
                "{}: no case of {}",
                c.file,
                v.name
            );
        }
        for f in &forms {
            assert!(
                c.verb(f.verb).is_some(),
                "{}: {} is not a verb of it",
                c.file,
                f.verb
            );
        }
    }
}

#[test]
fn every_form_meets_what_the_book_says_of_it() {
    for name in forms::CORPORA {
        let corpus = load(name);
        for form in forms::of(name).expect("forms") {
            let verdict = accuracy::check_forms(&corpus, &[form]);
            match form.expect {
                Expect::Within => verdict.assert_pass(),
                Expect::Exceeds => assert!(
                    !verdict.passed(),
                    "{} no longer exceeds:\n{verdict}",
                    form.label()
                ),
            }
        }
    }
}

/// The claim's planted twins: a double routine with one single-precision step, and one
/// nine ulps off everywhere (more than the bound's 8 where κ ≤ 1), are rejected; an
/// answer one ulp off everywhere passes.
#[test]
fn the_claim_rejects_lost_digits_and_accepts_one_ulp() {
    let corpus = load("fresnel");
    for form in forms::of("fresnel").expect("forms") {
        let f32_step = accuracy::check(&corpus, &[form.verb], Precision::Double, |c| {
            planted::through_f32(&form, &c.args)
        });
        assert!(!f32_step.passed(), "{}:\n{f32_step}", form.label());
        let nine = accuracy::check(&corpus, &[form.verb], Precision::Double, |c| {
            planted::ulps_off(&form, &c.args, 9)
        });
        assert!(!nine.passed(), "{}:\n{nine}", form.label());
        let one = accuracy::check(&corpus, &[form.verb], Precision::Double, |c| {
            planted::ulps_off(&form, &c.args, 1)
        });
        let worst = one.findings[0].worst.map_or(f64::NAN, |w| w.0);
        assert!(
            worst <= BOUND,
            "{}: one ulp off gives {worst}\n{one}",
            form.label()
        );
    }
}

/// What one rounding of an input costs, in ulps of the answer: up to κ u |y|, which is
/// between κ/2 and κ ulps, as y falls at the bottom or the top of its binade (an ulp of a
/// number in [2^e, 2^(e+1)) is 2^(e+1) u). The routine y = c x with a constant c has κ = 1.
/// The real input x = 1 + 2^-53 - 2^-70 rounds to 1, a relative error of almost u, and the
/// routine, exact on the rounded input, answers c.
#[test]
fn an_input_rounded_once_costs_between_half_kappa_and_kappa_ulps() {
    let u = f64::EPSILON / 2.0;
    let lost = u - (2f64).powi(-70); // x - round(x), exactly
    assert_eq!(1.0 + lost, 1.0);
    let cost = |c: f64| c * lost / accuracy::ulp(c, Precision::Double);
    // At the bottom of the binade, κ/2; towards its top, κ.
    assert!((cost(1.0) - 0.5).abs() < 1e-5, "{}", cost(1.0));
    assert!((cost(1.75) - 0.875).abs() < 1e-5, "{}", cost(1.75));
    let top = 2.0 - (2f64).powi(-10);
    assert!(cost(top) > 0.999 && cost(top) < 1.0, "{}", cost(top));
    // So more than "about κ/2", and never more than κ: BOUND max(κ, 1) absorbs it.
}

#[test]
fn ulps_are_counted_in_the_binade_of_the_answer_or_its_scale() {
    assert_eq!(accuracy::ulp(1.0, Precision::Double), f64::EPSILON);
    assert_eq!(accuracy::ulp(1.5, Precision::Double), f64::EPSILON);
    assert_eq!(accuracy::ulp(0.75, Precision::Double), f64::EPSILON / 2.0);
    assert_eq!(
        accuracy::ulp(1.0, Precision::Single),
        f64::from(f32::EPSILON)
    );
    assert_eq!(accuracy::ulp(0.0, Precision::Double), f64::from_bits(1));
    assert_eq!(accuracy::ulp(1e-310, Precision::Double), f64::from_bits(1));
    // Below 2^-970 the unit is itself below 2^-1022 (a power of two still, built from its
    // bits: `powi` would give 0 there). From data/corpus/tabulated.txt's tiny answers.
    for v in [2.75e-300, 1e-305, f64::MIN_POSITIVE] {
        assert_eq!(
            accuracy::ulp(v, Precision::Double),
            v.next_up() - v,
            "{v:e}"
        );
    }
    // Far below 1, where 2^(e - 52) is no longer a power of 2 that `powi` can reach.
    assert_eq!(
        accuracy::ulp(3.0e-300, Precision::Double),
        (2f64).powi(-995) * f64::EPSILON
    );
    assert_eq!(
        accuracy::ulp(f64::MIN_POSITIVE, Precision::Double),
        f64::from_bits(1)
    );
    assert_eq!(
        accuracy::ulp(2.0 * f64::MIN_POSITIVE, Precision::Double),
        f64::from_bits(2)
    );
    assert!(accuracy::ulp(f64::NAN, Precision::Double).is_nan());
}

#[test]
fn a_bad_corpus_is_refused_with_its_line() {
    let verb = "verb f x -> y ; scale 0 ; a test\n";
    for (text, line, says) in [
        (format!("{verb}\nf 1 = 2 @ 1\n"), 3, "saying why"),
        (format!("{verb}\n# why\ng 1 = 2 @ 1\n"), 4, "not a verb"),
        (
            format!("{verb}\n# why\nf 1 2 = 2 @ 1\n"),
            4,
            "takes 1 argument",
        ),
        (format!("{verb}\n# why\nf 1 = 2\n"), 4, "condition numbers"),
        (
            format!("{verb}\n# why\nf nan = 2 @ 1\n"),
            4,
            "not a finite number",
        ),
        (format!("{verb}\n# why\nf 1 = 2 3 @ 1 1\n"), 4, "1 output"),
        (format!("{verb}\n# why\nf 1 = 2 @ -1\n"), 4, "negative"),
        ("verb f x ; scale 0 ; no arrow\n".to_string(), 1, "->"),
        (verb.to_string(), 0, "no case"),
    ] {
        let e = corpus::parse(&text, "test.txt").expect_err(&text);
        assert_eq!(e.line, line, "{text}: {e}");
        assert!(e.problem.contains(says), "{text}: {e}");
    }
}

#[test]
fn an_undecided_kind_of_answer_accepts_both_kinds() {
    let text = "verb f x -> y ; scale 1 ; a test\n\n# at the edge\nf 1 = none @ inf\n\n# inside\nf 2 = none\n";
    let c = corpus::parse(text, "test.txt").expect("parses");
    assert!(c.cases[0].undecided && !c.cases[1].undecided);
    let v = accuracy::check(&c, &["f"], Precision::Double, |_| Some(vec![1.0]));
    assert_eq!(v.findings[0].failures, 1, "{v}");
}
