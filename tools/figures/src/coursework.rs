//! Generated text of the chapter *Coursework*: a stub as the hand-out has it, a report card
//! and the verdicts the chapter reads, each produced by running the library's own code (the
//! stub writer, the card, the checkers on planted mistakes), never typed by hand.

use glam::{DVec2, DVec3};

use super::{Output, Record, Settings};
use crate::plot::BoxError;
use raylemma::check::warp::{self, Domain, SquareWarp};
use raylemma::check::{self, Options, Verdict};
use raylemma::exercise::card::{self, Status};
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
            make: |s, _| verdict_txt(s, disc_verdict()),
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
            make: |s, _| verdict_txt(s, cosine_verdict()),
        },
        Output {
            file: "coursework_verdict_schlick.txt",
            what: "verdict: the seed's Schlick",
            make: |s, _| {
                verdict_txt(
                    s,
                    check::fresnel::reflectance(&schlick_seed, &Options::default()),
                )
            },
        },
        Output {
            file: "coursework_verdict_sphere.txt",
            what: "verdict: the far root",
            make: |s, _| {
                let f = check::sphere::planted::always_far_root;
                verdict_txt(s, check::sphere::intersection(&f, &Options::default()))
            },
        },
        Output {
            file: "coursework_verdict_refract.txt",
            what: "verdict: refraction without the square root",
            make: |s, _| {
                let f = check::reflect::planted::refract_without_sqrt;
                verdict_txt(s, check::reflect::refraction(&f, &Options::default()))
            },
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
fn seeds_md(_: &Settings, _: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
    use std::fmt::Write as _;
    let correct = SquareWarp::new("disc, polar", Domain::Disc, disc_polar, disc_pdf);
    let lobe = SquareWarp::new(
        "cosine^1.1 lobe claimed as cosine",
        Domain::Sphere,
        warp::planted::cosine_power_lobe,
        cosine_pdf,
    );
    let p = |w: &dyn warp::Warp, o: &Options| -> Result<f64, BoxError> {
        Ok(warp::chi_squared(w, o)
            .map_err(|e| -> BoxError { e.into() })?
            .0
            .p_value)
    };
    let show = |p: f64| {
        if p >= 1e-3 {
            format!("{p:.3}")
        } else {
            format!("{p:.1e}")
        }
    };
    let mut md = String::from(
        "| seed | correct polar disc: p | cos^1.1 lobe as cosine: p | the lobe's Jacobian check |\n|---:|---:|---:|---|\n",
    );
    for seed in 1..=12u64 {
        let o = warp_options().seed(seed);
        let jacobian = warp::check(&lobe, &o).finding("jacobian").passed();
        writeln!(
            md,
            "| {seed} | {} | {} | {} |",
            show(p(&correct, &o)?),
            show(p(&lobe, &o)?),
            if jacobian { "passes" } else { "fails" }
        )?;
    }
    writeln!(
        md,
        "\n*`check::warp` at the tests' settings ({} samples), seeds 1 to 12; the level is {:.3e}.*",
        warp::TEST_SAMPLES,
        raylemma::stats::test_alpha()
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

fn verdict_txt(settings: &Settings, verdict: Verdict) -> Result<Vec<u8>, BoxError> {
    Ok(portable(settings, verdict.to_string()).into_bytes())
}

/// The marked region of `disc_polar` in the hand-out: `src/sampling/disc.rs` through the
/// stub writer.
fn stub_txt(settings: &Settings, _: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
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
fn card_txt(settings: &Settings, _: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
    let markers = edition::markers_under(&settings.root)?;
    let o = Options::default();
    let card = card::run_with(&markers, |m| {
        let name = m.name.as_str();
        let judge = |f: &dyn Fn() -> Vec<Verdict>| card::judge(name, f);
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
            "schlick" => judge(&|| {
                let v = check::fresnel::reflectance(&schlick_seed, &o);
                let why = "the claims an approximation keeps";
                vec![registry::only(v, &registry::SCHLICK_KEEPS, why)]
            }),
            "roulette" => judge(&|| vec![check::roulette::roulette(&roulette_seed, &o)]),
            "srgb_encode" => {
                judge(&|| vec![check::display::srgb_encode(&|x| gamma_encode(x, 2.2), &o)])
            }
            _ => judge(&|| -> Vec<Verdict> { exercise::todo(name) }),
        }
    });
    debug_assert!(card.rows.iter().any(|r| r.status == Status::NotStarted));
    Ok(portable(settings, card.to_string() + "\n").into_bytes())
}

/// What the chapter's `where_is_my_disc_wrong` prints for the disc with `r = u1`.
fn disc_rows_txt(_: &Settings, _: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
    let text = tests_mine::where_is_my_disc_wrong_text(warp::planted::disc_r_equals_u);
    Ok(text.into_bytes())
}

/// The chapter's example, shared with `tests/book/coursework/mine.rs` by `#[path]`: the
/// same code prints the rows there and writes them here.
#[path = "../../../tests/book/coursework/rows.rs"]
mod tests_mine;
