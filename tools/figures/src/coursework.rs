//! Generated text of the chapter *Coursework*: a stub as the hand-out has it, a report card
//! and the verdicts the chapter reads, each produced by running the library's own code (the
//! stub writer, the card, the checkers on planted mistakes), never typed by hand.

use anyhow::{Context, anyhow, bail};
use glam::{DVec2, DVec3};

use super::{Output, Record, Settings};
use raylemma::check::warp::{self, Domain, SquareWarp};
use raylemma::check::{self, Finding, Options, Verdict};
use raylemma::exercise::card::{self, Status};
use raylemma::exercise::mistakes::{self, twins};
use raylemma::exercise::{self, edition, marker, registry, stub};
use raylemma::optics::fresnel::schlick_seed;
use raylemma::sampling::cosine::{cosine_malley, cosine_pdf};
use raylemma::sampling::disc::{disc_pdf, disc_polar, disc_polar_invert};
use raylemma::spectral::display::gamma_encode;
use raylemma::transport::roulette::roulette_seed;

/// The outputs of this chapter.
pub fn outputs() -> Vec<Output> {
    vec![
        Output {
            file: "coursework_stub.txt",
            what: "the stub of disc_polar in the hand-out",
            make: stub_txt,
        },
        Output {
            file: "coursework_card.txt",
            what: "a report card with mistakes",
            make: card_txt,
        },
        Output {
            file: "coursework_verdict_disc.txt",
            what: "verdict: disc with r = u1",
            make: disc_verdict_txt,
        },
        Output {
            file: "coursework_disc_rows.txt",
            what: "rows of the disc's cells",
            make: disc_rows_txt,
        },
        Output {
            file: "coursework_seeds.md",
            what: "p-values of a correct disc and a cos^1.1 lobe over seeds",
            make: seeds_md,
        },
        Output {
            file: "coursework_verdict_cosine.txt",
            what: "verdict: cosine pdf without 1/pi",
            make: cosine_verdict_txt,
        },
        Output {
            file: "coursework_verdict_schlick.txt",
            what: "verdict: the seed's Schlick",
            make: schlick_verdict_txt,
        },
        Output {
            file: "coursework_verdict_sphere.txt",
            what: "verdict: the far root",
            make: sphere_verdict_txt,
        },
        Output {
            file: "coursework_verdict_refract.txt",
            what: "verdict: refraction without the square root",
            make: refract_verdict_txt,
        },
        Output {
            file: "coursework_mistakes.md",
            what: "the typical mistakes the card rejects and names, and the alternatives it passes",
            make: mistakes_md,
        },
    ]
}

/// The sampler tests' options.
fn warp_options() -> Options {
    Options::default().cases(warp::TEST_SAMPLES)
}

fn disc_verdict() -> Verdict {
    let w = SquareWarp::new(
        "disc r = u1",
        Domain::Disc,
        warp::planted::disc_r_equals_u,
        disc_pdf,
    )
    .inverse(disc_polar_invert);
    warp::check(&w, &warp_options())
}

fn cosine_verdict() -> Verdict {
    let w = SquareWarp::new(
        "cosine Malley, pdf without 1/pi",
        Domain::Sphere,
        cosine_malley,
        warp::planted::cosine_pdf_without_1_over_pi,
    );
    warp::check(&w, &warp_options())
}

/// The chapter's *Statistical verdicts*: what a correct sampler's chi-squared p-value looks
/// like over seeds 1 to 12 at the tests' settings, against a small real bug (the `cos^1.1`
/// lobe claimed as a cosine lobe), whose Jacobian check fails too.
fn seeds_md(_: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    use std::fmt::Write as _;
    let correct = SquareWarp::new("disc, polar", Domain::Disc, disc_polar, disc_pdf);
    let lobe = SquareWarp::new(
        "cosine^1.1 lobe claimed as cosine",
        Domain::Sphere,
        warp::planted::cosine_power_lobe,
        cosine_pdf,
    );
    let p = |w: &dyn warp::Warp, o: &Options| -> anyhow::Result<f64> {
        Ok(warp::chi_squared(w, o)?.0.p_value)
    };
    let show = |p: f64| {
        if p >= 1e-3 {
            format!("{p:.3}")
        } else {
            format!("{p:.1e}")
        }
    };
    let alpha = raylemma::stats::test_alpha();
    let mut md = String::from(
        "| seed | correct polar disc: p | cos^1.1 lobe as cosine: p | the lobe's Jacobian check |\n|---:|---:|---:|---|\n",
    );
    let (mut disc_p, mut lobe_p, mut as_said) = (Vec::new(), Vec::new(), Vec::new());
    for seed in 1..=12u64 {
        let o = warp_options().seed(seed);
        let jacobian = warp::check(&lobe, &o).finding("jacobian").passed();
        let (pd, pl) = (p(&correct, &o)?, p(&lobe, &o)?);
        disc_p.push(pd);
        lobe_p.push(pl);
        if !(pd >= alpha && pl < alpha && !jacobian) {
            as_said.push(format!(
                "seed {seed}: disc p {pd:.3e}, lobe p {pl:.3e}, lobe's Jacobian {}",
                if jacobian { "passes" } else { "fails" }
            ));
        }
        writeln!(
            md,
            "| {seed} | {} | {} | {} |",
            show(pd),
            show(pl),
            if jacobian { "passes" } else { "fails" }
        )?;
    }
    let range = |ps: &[f64]| {
        ps.iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &p| {
                (lo.min(p), hi.max(p))
            })
    };
    // As the table shows them: three decimals, or (below 1e-3) two significant digits.
    let plain = |p: f64| if p >= 1e-3 { ".3" } else { "s2" };
    let (lo, hi) = range(&disc_p);
    r.number("correct_disc.p_min", lo, plain(lo));
    r.number("correct_disc.p_max", hi, plain(hi));
    let (lo, hi) = range(&lobe_p);
    r.number("lobe.p_min", lo, "x1");
    r.number("lobe.p_max", hi, "x1");
    r.claim(
        "every_seed_disc_passes_lobe_fails_both",
        as_said.is_empty(),
        if as_said.is_empty() {
            format!(
                "at each of seeds 1 to 12: the disc's p >= {alpha:.3e} (lowest {:.3e}), the \
                 lobe's p < {alpha:.3e} (highest {:.3e}) and the lobe's Jacobian check fails",
                range(&disc_p).0,
                range(&lobe_p).1
            )
        } else {
            format!("level {alpha:.3e}; not as said: {}", as_said.join("; "))
        },
    );
    writeln!(
        md,
        "\n*`check::warp` at the tests' settings ({} samples), seeds 1 to 12; the level is {:.3e}.*",
        warp::TEST_SAMPLES,
        alpha
    )?;
    Ok(md.into_bytes())
}

/// `text` with this machine's target folder written as `target` (the failure images'
/// folder is printed in the chi-squared line).
fn portable(settings: &Settings, text: String) -> String {
    let target = std::env::var_os("CARGO_TARGET_DIR")
        .map_or_else(|| settings.root.join("target"), std::path::PathBuf::from);
    text.replace(&format!("{}/", target.display()), "target/")
}

fn verdict_txt(settings: &Settings, verdict: Verdict) -> anyhow::Result<Vec<u8>> {
    Ok(portable(settings, verdict.to_string()).into_bytes())
}

/// The number that follows the last of `anchors` (each searched after the one before) in
/// `text`, a counterexample of a [`Finding`]: the values a chapter quotes from a verdict are
/// the ones its counterexamples print.
///
/// # Errors
/// If an anchor or the number is missing.
pub(crate) fn number_after(text: &str, anchors: &[&str]) -> anyhow::Result<f64> {
    let mut rest = text;
    for a in anchors {
        let at = rest
            .find(a)
            .with_context(|| format!("{a:?} (of {anchors:?}) not found in {text:?}"))?;
        rest = &rest[at + a.len()..];
    }
    let rest = rest.trim_start();
    let b = rest.as_bytes();
    let digits = |mut i: usize| {
        while b.get(i).is_some_and(u8::is_ascii_digit) {
            i += 1;
        }
        i
    };
    let mut end = digits(usize::from(matches!(b.first(), Some(b'+' | b'-'))));
    if b.get(end) == Some(&b'.') {
        end = digits(end + 1);
    }
    if matches!(b.get(end), Some(b'e' | b'E')) {
        let sign = end + 1 + usize::from(matches!(b.get(end + 1), Some(b'+' | b'-')));
        let exponent = digits(sign);
        if exponent > sign {
            end = exponent;
        }
    }
    rest[..end]
        .parse()
        .map_err(|_| anyhow!("no number after {anchors:?} in {text:?}"))
}

/// The first counterexample of `finding`.
pub(crate) fn first_failure(finding: &Finding) -> anyhow::Result<&str> {
    finding
        .example
        .as_deref()
        .with_context(|| format!("`{}` has no counterexample", finding.name))
}

/// The worst counterexample of `finding` (a quantitative claim's largest error).
pub(crate) fn worst_failure(finding: &Finding) -> anyhow::Result<&str> {
    finding
        .worst_example
        .as_deref()
        .with_context(|| format!("`{}` has no worst counterexample", finding.name))
}

/// The disc with `r = u1`: the derivation read off the Jacobian and round-trip lines, and
/// where the chi-squared line puts the worst cell.
fn disc_verdict_txt(settings: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let verdict = disc_verdict();
    let jacobian = verdict.finding("jacobian");
    let at = first_failure(jacobian)?;
    let u1 = number_after(at, &["u = ("])?;
    let det = number_after(at, &["|dT/du| = "])?;
    let product = number_after(at, &["product "])?;
    r.number("jacobian.first.u1", u1, ".3");
    r.number("jacobian.first.det", det, ".3");
    r.number("jacobian.first.product", product, ".3");
    let round_trip = verdict.finding("round_trip");
    let at = first_failure(round_trip)?;
    let u = number_after(at, &["u = ("])?;
    let back = number_after(at, &["came back as ("])?;
    r.number("round_trip.first.u1", u, ".3");
    r.number("round_trip.first.back_u1", back, ".3");
    r.claim(
        "first_failures_follow_the_derivation",
        !jacobian.passed()
            && (det - std::f64::consts::TAU * u1).abs() < 1e-5
            && (product - 2.0 * u1).abs() < 1e-6
            && !round_trip.passed()
            && (u * u - back).abs() < 1e-9,
        format!(
            "jacobian fails ({} of {}); at u1 = {u1}: |dT/du| = {det} = 2 pi u1 = {} within 1e-5, \
             product {product} = 2 u1 = {} within 1e-6; round_trip fails ({} of {}); \
             u1 = {u} came back as {back} = u1^2 = {} within 1e-9",
            jacobian.failures,
            jacobian.cases,
            std::f64::consts::TAU * u1,
            2.0 * u1,
            round_trip.failures,
            round_trip.cases,
            u * u
        ),
    );
    let at = first_failure(verdict.finding("chi_squared"))?;
    r.number("chi_squared.p", number_after(at, &["p = "])?, "int");
    r.number(
        "chi_squared.worst_cell.r_max",
        number_after(at, &["(r in [0.000, "])?,
        ".3",
    );
    r.number(
        "chi_squared.worst_cell.ratio",
        number_after(at, &["predicts", "("])?,
        ".1",
    );
    verdict_txt(settings, verdict)
}

/// The cosine pdf without `1/pi`: the pdf's integral and pdf x area element, both pi.
fn cosine_verdict_txt(settings: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    use std::f64::consts::PI;
    let verdict = cosine_verdict();
    let integral = number_after(
        first_failure(verdict.finding("chi_squared"))?,
        &["integrates to "],
    )?;
    let jacobian = verdict.finding("jacobian");
    let first = number_after(first_failure(jacobian)?, &["product "])?;
    let worst = number_after(worst_failure(jacobian)?, &["product "])?;
    let worst_error = jacobian.worst.map_or(f64::NAN, |w| w.0);
    r.number("chi_squared.pdf_integral", integral, ".6");
    r.number("jacobian.first.product", first, ".6");
    r.claim(
        "pi_at_every_point",
        (integral - PI).abs() < 1e-6
            && (first - PI).abs() < 1e-6
            && (worst - PI).abs() < 1e-6
            && jacobian.cases > 0
            && jacobian.failures == jacobian.cases
            && (worst_error - (PI - 1.0)).abs() < 1e-6,
        format!(
            "the pdf integrates to {integral}, pdf x |dT/du| is {first} at the first point and \
             {worst} at the worst (each pi within 1e-6); every point fails ({} of {}), none by \
             more than pi - 1 (worst |product - 1| = {worst_error}, pi - 1 within 1e-6)",
            jacobian.failures, jacobian.cases
        ),
    );
    verdict_txt(settings, verdict)
}

/// The seed's Schlick: of the claims an approximation keeps, it breaks `tir` and
/// `reciprocity`, as their counterexamples show.
fn schlick_verdict_txt(settings: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let verdict = check::fresnel::reflectance(&schlick_seed, &Options::default());
    // The five claims the chapter names, and the two of them it says the seed breaks.
    let named = ["range", "normal", "grazing", "tir", "reciprocity"];
    let broken = ["tir", "reciprocity"];
    let mut keeps = registry::SCHLICK_KEEPS.to_vec();
    keeps.sort_unstable();
    let mut sorted = named.to_vec();
    sorted.sort_unstable();
    let as_said = named
        .iter()
        .all(|&n| verdict.finding(n).passed() != broken.contains(&n));
    let read: Vec<String> = named
        .iter()
        .map(|&n| {
            let f = verdict.finding(n);
            format!("{n} fails {} of {}", f.failures, f.cases)
        })
        .collect();
    r.claim(
        "breaks_tir_and_reciprocity_of_the_five",
        keeps == sorted && as_said,
        format!(
            "registry::SCHLICK_KEEPS = {:?} (the five named: {named:?}); {}; \
             exactly {broken:?} must fail",
            registry::SCHLICK_KEEPS,
            read.join(", ")
        ),
    );
    let at = first_failure(verdict.finding("tir"))?;
    r.number(
        "tir.first.theta_i_deg",
        number_after(at, &["theta_i = "])?,
        ".1",
    );
    r.number(
        "tir.first.critical_deg",
        number_after(at, &["critical angle "])?,
        ".3",
    );
    r.number("tir.first.r", number_after(at, &["1.33, 1) = "])?, ".3");
    let at = worst_failure(verdict.finding("reciprocity"))?;
    r.number(
        "reciprocity.worst.theta_i_deg",
        number_after(at, &["theta_i = "])?,
        ".1",
    );
    r.number(
        "reciprocity.worst.r_from_air",
        number_after(at, &["1.33) = "])?,
        ".2",
    );
    r.number(
        "reciprocity.worst.theta_t_deg",
        number_after(at, &["theta_t = "])?,
        ".1",
    );
    r.number(
        "reciprocity.worst.r_from_water",
        number_after(at, &["1.33, 1) = "])?,
        ".3",
    );
    verdict_txt(settings, verdict)
}

/// The far root: about a quarter of `nearest_root`'s cases fail.
fn sphere_verdict_txt(settings: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let f = check::sphere::planted::always_far_root;
    let verdict = check::sphere::intersection(&f, &Options::default());
    let nearest = verdict.finding("nearest_root");
    let (failures, cases) = (nearest.failures, nearest.cases);
    r.number("nearest_root.failures", failures as f64, "int");
    r.number("nearest_root.cases", cases as f64, "int");
    let share = failures as f64 / cases as f64;
    r.claim(
        "nearest_root_about_a_quarter_fail",
        0.2 < share && share < 0.3,
        format!("nearest_root fails {failures} of {cases} = {share:.4}, in (0.2, 0.3)"),
    );
    // The cases cycle through four kinds; the first kind (origin outside, sphere ahead),
    // where the far root is wrong, is every fourth case from the first.
    let first_kind = cases.div_ceil(4);
    let others = failures.saturating_sub(first_kind);
    r.number("nearest_root.first_kind_cases", first_kind as f64, "int");
    r.number(
        "nearest_root.failures_beyond_first_kind",
        others as f64,
        "int",
    );
    // The failures beyond the first kind are the textbook formula's rounding: the same far
    // root computed without cancellation fails the first kind only.
    let stable = check::sphere::intersection(&stable_far_root, &Options::default());
    let stable_failures = stable.finding("nearest_root").failures;
    r.claim(
        "nearest_root_first_kind_and_a_few_more_fail",
        failures >= first_kind && others * 1000 <= cases && stable_failures == first_kind,
        format!(
            "nearest_root fails {failures} of {cases}: at least the {first_kind} of the first \
             kind, and {others} more <= 0.1 % of the cases; the far root computed without \
             cancellation fails {stable_failures} = {first_kind}, the first kind only"
        ),
    );
    verdict_txt(settings, verdict)
}

/// The far root, as `always_far_root`, but computed by the stable form itself
/// (`intersect_stable`, chapter *Ray-sphere intersection*): its nearest root above `-∞` is
/// the near root, its nearest above that the far one (the same root for a tangent ray).
/// Wrong only where the near root is the answer.
fn stable_far_root(
    ray: &raylemma::geometry::Ray,
    sphere: &raylemma::geometry::Sphere,
    t_min: f64,
) -> Option<f64> {
    use raylemma::geometry::sphere::intersect_stable;
    let near = intersect_stable(ray, sphere, f64::NEG_INFINITY)?;
    let far = intersect_stable(ray, sphere, near).unwrap_or(near);
    (far > t_min).then_some(far)
}

/// Refraction without the square root: how far `|w_t|` is off, and `tir_iff` passing.
fn refract_verdict_txt(settings: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let f = check::reflect::planted::refract_without_sqrt;
    let verdict = check::reflect::refraction(&f, &Options::default());
    let worst = verdict
        .finding("unit_length")
        .worst
        .context("unit_length measured no error")?
        .0;
    r.number("unit_length.worst_eps", worst, "x1");
    r.number("unit_length.worst_abs", worst * f64::EPSILON, ".2");
    let tir = verdict.finding("tir_iff");
    r.claim(
        "tir_iff_passes",
        tir.passed(),
        format!("tir_iff fails {} of {} cases", tir.failures, tir.cases),
    );
    verdict_txt(settings, verdict)
}

/// The marked region of `disc_polar` in the hand-out: `src/sampling/disc.rs` through the
/// stub writer.
fn stub_txt(settings: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    let root = &settings.root;
    let summary = std::fs::read_to_string(root.join("chapters/SUMMARY.md"))?;
    let file = "src/sampling/disc.rs";
    let text = std::fs::read_to_string(root.join(file))?;
    let markers = marker::parse(file, &text, &marker::chapters(&summary))?;
    let (stubbed, _) = stub::stub_file(&text, &markers);
    let mut out = String::new();
    let mut inside = false;
    for line in stubbed.lines() {
        inside |= line.starts_with(&format!("{}sampling/disc disc_polar:", marker::OPEN));
        if inside {
            out.push_str(line);
            out.push('\n');
            if line.trim() == marker::CLOSE {
                break;
            }
        }
    }
    Ok(out.into_bytes())
}

/// The report card of a student who wrote four exercises right, made a seed's mistake in
/// five, and has not started the others: each mistake judged by its exercise's checkers,
/// each exercise not started by a stub's panic, as the hand-out would have them.
fn card_txt(settings: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    let markers = edition::markers_under(&settings.root)?;
    let o = Options::default();
    let card = card::run_with(&markers, |m| {
        let name = m.name.as_str();
        // Each mistake named as the card names it: by the fingerprint of the twin's probe.
        let named = |words: &str| {
            let twin = twins::tables()
                .filter(|t| t.exercise == name)
                .flat_map(|t| t.mistakes)
                .find(|m| m.words.contains(words))
                .expect("the mistake has a twin");
            mistakes::matching(name, mistakes::fingerprint(&(twin.probe)()))
        };
        let judge = |f: &dyn Fn() -> Vec<Verdict>| {
            let words = match name {
                "disc_polar" => Some("r = u1: "),
                "refract" => Some("cos_t^2 used where cos_t belongs"),
                "schlick" => Some("the source notes' Schlick"),
                "roulette" => Some("survives when u <= p"),
                "srgb_encode" => Some("x^(1/2.2)"),
                _ => None,
            };
            card::naming(card::judge(name, f), words.and_then(named))
        };
        match name {
            "intersect_stable" | "cosine_pdf" | "lambert_brdf" | "reflect" => {
                let e = registry::find(name).expect("registered");
                judge(&e.check)
            }
            "disc_polar" => judge(&|| vec![disc_verdict()]),
            "cosine_malley" => judge(&|| {
                // disc_concentric, which it calls, is still a stub.
                let stubbed = |_: DVec2| -> DVec3 { exercise::todo("disc_concentric") };
                let w = SquareWarp::new("cosine Malley", Domain::Sphere, stubbed, cosine_pdf);
                vec![warp::check(&w, &warp_options())]
            }),
            "refract" => judge(&|| {
                let f = check::reflect::planted::refract_without_sqrt;
                vec![check::reflect::refraction(&f, &o)]
            }),
            "schlick" => judge(&|| vec![registry::schlick_verdict(&schlick_seed)]),
            "roulette" => judge(&|| vec![check::roulette::roulette(&roulette_seed, &o)]),
            "srgb_encode" => {
                judge(&|| vec![check::display::srgb_encode(&|x| gamma_encode(x, 2.2), &o)])
            }
            _ => judge(&|| -> Vec<Verdict> { exercise::todo(name) }),
        }
    })
    .with_sections(&settings.root, &markers);
    debug_assert!(card.rows.iter().any(|r| r.status == Status::NotStarted));
    Ok(portable(settings, card.to_string() + "\n").into_bytes())
}

/// What the chapter's `where_is_my_disc_wrong` prints for the disc with `r = u1`.
///
/// The ratios it prints are recorded from the same counts, drawn again here (with the same
/// samples: the seed is fixed), and must be the ones printed.
fn disc_rows_txt(_: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let text = exercise::disc_rows::where_is_my_disc_wrong_text(warp::planted::disc_r_equals_u);
    let options = warp::WarpOptions::from(warp_options());
    let disc = SquareWarp::new(
        "disc r = u1",
        Domain::Disc,
        warp::planted::disc_r_equals_u,
        disc_pdf,
    );
    let (_, observed, expected) = warp::chi_squared(&disc, &options)?;
    let cols = options.resolution;
    let rows = expected.len() / cols;
    let mut ratio = |row: usize| -> anyhow::Result<f64> {
        let o: u64 = observed[row * cols..(row + 1) * cols].iter().sum();
        let e: f64 = expected[row * cols..(row + 1) * cols].iter().sum();
        let x = o as f64 / e;
        let shown = r.number(&format!("row{row}.ratio"), x, ".2");
        let printed = text.lines().any(|l| {
            l.starts_with(&format!("row {row}: ")) && l.ends_with(&format!("ratio {shown}"))
        });
        if !printed {
            bail!("row {row}: ratio {shown} is not what the example printed:\n{text}");
        }
        Ok(x)
    };
    let (centre, rim) = (ratio(0)?, ratio(20)?);
    // The derivation: the central row (r^2 < 1/21) gets P(u1 < sqrt(1/21)) of the samples
    // instead of 1/21, the outer one P(u1 > sqrt(20/21)).
    let n = rows as f64;
    let share = (1.0 / n).sqrt();
    let (centre_exact, rim_exact) = (n * share, n * (1.0 - ((n - 1.0) / n).sqrt()));
    r.claim(
        "ratios_match_the_derivation",
        rows == 21
            && (share - 0.218).abs() < 5e-4
            && (centre_exact - 4.58).abs() < 5e-3
            && (rim_exact - 0.5).abs() < 0.01
            && (centre - centre_exact).abs() < 0.05
            && (rim - rim_exact).abs() < 0.02,
        format!(
            "{rows} rows (21); derivation: share sqrt(1/21) = {share:.5} (0.218 to 5e-4), centre \
             ratio 21 sqrt(1/21) = {centre_exact:.4} (4.58 to 5e-3), rim ratio 21 (1 - \
             sqrt(20/21)) = {rim_exact:.4} (1/2 to 0.01); drawn: centre {centre:.4} (within \
             0.05), rim {rim:.4} (within 0.02)"
        ),
    );
    Ok(text.into_bytes())
}

/// Whether every verdict passes (and there is one): the card's rule.
fn all_pass(verdicts: &[Verdict]) -> bool {
    !verdicts.is_empty() && verdicts.iter().all(Verdict::passed)
}

/// The chapter's *What the card catches*: for each exercise with a table of typical
/// mistakes ([`raylemma::exercise::mistakes::twins::tables`]), how many mistakes the card's checks
/// reject, how many its probe names (each mistake's outputs matched to itself, the right
/// answer's to none), and how many correct alternatives pass; then every mistake. Every
/// check is run here, on whatever tables exist.
fn mistakes_md(_: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    use raylemma::exercise::mistakes;
    use std::fmt::Write as _;
    let mut summary = String::from(
        "| exercise | mistakes | rejected | named | alternatives | passed |\n|---|---:|---:|---:|---:|---:|\n",
    );
    let mut list = String::from(
        "| exercise | source | the mistake | rejected | named |\n|---|---|---|---|---|\n",
    );
    let yes = |b: bool| if b { "yes" } else { "**no**" };
    let (mut total, mut rejected_all, mut named_all) = (0, 0, 0);
    let (mut alternatives_all, mut passed_all, mut exercises) = (0, 0, 0);
    let mut right_named = Vec::new();
    for t in mistakes::twins::tables() {
        exercises += 1;
        let (mut rejected, mut named) = (0, 0);
        for m in t.mistakes {
            let caught = !all_pass(&(m.check)());
            let found = mistakes::matching(t.exercise, mistakes::fingerprint(&(m.probe)()))
                .is_some_and(|n| n.words == m.words);
            rejected += usize::from(caught);
            named += usize::from(found);
            writeln!(
                list,
                "| `{}` | {} | {} | {} | {} |",
                t.exercise,
                m.source.word(),
                m.words.replace('|', "\\|"),
                yes(caught),
                yes(found)
            )?;
        }
        if mistakes::recognise(t.exercise).is_some() {
            right_named.push(t.exercise);
        }
        let passed = t
            .alternatives
            .iter()
            .filter(|a| all_pass(&(a.check)()))
            .count();
        writeln!(
            summary,
            "| `{}` | {} | {rejected} | {named} | {} | {passed} |",
            t.exercise,
            t.mistakes.len(),
            t.alternatives.len()
        )?;
        total += t.mistakes.len();
        rejected_all += rejected;
        named_all += named;
        alternatives_all += t.alternatives.len();
        passed_all += passed;
    }
    let rate = if alternatives_all == 0 {
        0.0
    } else {
        (alternatives_all - passed_all) as f64 / alternatives_all as f64
    };
    writeln!(
        summary,
        "| **all {exercises}** | {total} | {rejected_all} | {named_all} | {alternatives_all} | {passed_all} |"
    )?;
    r.number("exercises", exercises as f64, "int");
    r.number("mistakes", total as f64, "int");
    r.number("alternatives", alternatives_all as f64, "int");
    r.number("false_fail_rate", rate, ".2");
    r.claim(
        "every_mistake_rejected",
        rejected_all == total,
        format!("{rejected_all} of {total} mistakes rejected by the exercises' checks"),
    );
    r.claim(
        "every_mistake_named",
        named_all == total && right_named.is_empty(),
        format!(
            "{named_all} of {total} mistakes named by their probes; right answers named: {right_named:?}"
        ),
    );
    r.claim(
        "every_alternative_passes",
        passed_all == alternatives_all,
        format!("{passed_all} of {alternatives_all} correct alternatives passed"),
    );
    Ok(format!("{summary}\nEvery mistake:\n\n{list}").into_bytes())
}
