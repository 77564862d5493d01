//! Figures and tables of the chapters *Checking a sampler*, *Uniform sphere and
//! hemisphere*, *The unit disc* and *Cosine-weighted hemisphere*.

use raylemma::sampling::sphere::sphere_uniform;
use std::f64::consts::{FRAC_PI_4, PI, TAU};
use std::fmt::Write as _;
use std::hint::black_box;

use glam::{DVec2, DVec3};
use rayon::prelude::*;

use super::{Output, Record, Settings, timing};
use crate::plot::{self, BoxError, Legend, Panel, Series};
use raylemma::check::Options;
use raylemma::check::warp::{self, Domain, RngWarp, SquareWarp, Warp, WarpOptions, planted};
use raylemma::rng::{self, Rng};
use raylemma::sampling::cosine::*;
use raylemma::sampling::disc::*;
use raylemma::sampling::sphere::*;
use raylemma::stats;

/// The outputs of these chapters.
pub fn outputs() -> Vec<Output> {
    vec![
        Output {
            file: "sampling_scatter.svg",
            what: "sample scatter plots",
            make: scatter_svg,
        },
        Output {
            file: "sampling_histograms.svg",
            what: "histograms against pdfs",
            make: histograms_svg,
        },
        Output {
            file: "sampling_warped_grids.svg",
            what: "disc maps' distortion",
            make: warped_grids_svg,
        },
        Output {
            file: "sampling_distortion.md",
            what: "disc maps' anisotropy",
            make: distortion_md,
        },
        Output {
            file: "sampling_methods.md",
            what: "speed and accuracy of every sampler",
            make: methods_md,
        },
        Output {
            file: "disc_quarter_speed.md",
            what: "the quarter-range series against the standard library's sin_cos",
            make: quarter_speed_md,
        },
        Output {
            file: "sampling_power.md",
            what: "power against planted bugs",
            make: power_md,
        },
        Output {
            file: "sampling_calibration.svg",
            what: "p-values of correct samplers",
            make: calibration_svg,
        },
        Output {
            file: "sampling_calibration.md",
            what: "false-failure rates",
            make: calibration_md,
        },
    ]
}

type Boxed = Box<dyn Warp + Send>;

fn square_warp(
    name: &str,
    domain: Domain,
    sample: fn(DVec2) -> DVec3,
    pdf: fn(DVec3) -> f64,
) -> Boxed {
    Box::new(SquareWarp::new(name, domain, sample, pdf))
}

fn hemisphere_pdf_z(w: DVec3) -> f64 {
    hemisphere_pdf(w, DVec3::Z)
}

/// Every correct sampler of the sampling chapters.
fn correct_samplers() -> Vec<Boxed> {
    vec![
        square_warp(
            "sphere, inverse CDF",
            Domain::Sphere,
            sphere_inverse_cdf,
            sphere_pdf,
        ),
        Box::new(RngWarp {
            name: "sphere, Gaussian".into(),
            domain: Domain::Sphere,
            sample: sphere_gaussian,
            pdf: sphere_pdf,
        }),
        Box::new(RngWarp {
            name: "sphere, rejection".into(),
            domain: Domain::Sphere,
            sample: |r: &mut Rng| sphere_rejection(r).0,
            pdf: sphere_pdf,
        }),
        Box::new(RngWarp {
            name: "hemisphere, flipped inverse CDF".into(),
            domain: Domain::Sphere,
            sample: |r: &mut Rng| {
                hemisphere_flip(sphere_inverse_cdf(warp::square_point(r)), DVec3::Z)
            },
            pdf: hemisphere_pdf_z,
        }),
        square_warp("disc, polar", Domain::Disc, disc_polar, disc_pdf),
        square_warp("disc, concentric", Domain::Disc, disc_concentric, disc_pdf),
        square_warp(
            "cosine, seed angles",
            Domain::Sphere,
            cosine_seed_angles,
            cosine_pdf,
        ),
        square_warp(
            "cosine, seed Cartesian",
            Domain::Sphere,
            cosine_seed_cartesian,
            cosine_pdf,
        ),
        square_warp(
            "cosine, Malley (concentric)",
            Domain::Sphere,
            cosine_malley,
            cosine_pdf,
        ),
    ]
}

/// The chi-squared p-value of `w` with `samples` samples on a 21-row grid. An error
/// (which none of the figure's samplers should produce) is a NaN p-value, which every
/// table shows and no rate counts as a rejection.
fn chi2_p(w: &dyn Warp, samples: usize, seed: u64) -> f64 {
    let options = WarpOptions {
        resolution: 21,
        points: 0,
        ..WarpOptions::from(Options::default().cases(samples).seed(seed))
    };
    warp::chi_squared(w, &options).map_or(f64::NAN, |(c, _, _)| c.p_value)
}

/// A sampler of the methods table as a value name: `cosine, Malley (concentric)` ->
/// `cosine_malley`.
fn sampler_key(name: &str) -> String {
    match name {
        "sphere, inverse CDF" => "sphere_inverse_cdf".into(),
        "sphere, Gaussian" => "sphere_gaussian".into(),
        "sphere, rejection" => "sphere_rejection".into(),
        "hemisphere, flipped inverse CDF" => "hemisphere_flipped_inverse_cdf".into(),
        "disc, polar" => "disc_polar".into(),
        "disc, concentric" => "disc_concentric".into(),
        "cosine, seed angles" => "cosine_seed_angles".into(),
        "cosine, seed Cartesian" => "cosine_seed_cartesian".into(),
        "cosine, Malley (concentric)" => "cosine_malley".into(),
        other => value_name(other),
    }
}

/// A label as a value name, for a row added without a key of its own: lowercase words of
/// `a-z` and `0-9` joined by `_`.
fn value_name(label: &str) -> String {
    label
        .to_lowercase()
        .split(|c: char| !c.is_ascii_alphanumeric())
        .filter(|w| !w.is_empty())
        .collect::<Vec<_>>()
        .join("_")
}

fn methods_md(settings: &Settings, r: &mut Record) -> Result<Vec<u8>, BoxError> {
    let samples = if settings.quick { 100_000 } else { 1_000_000 };
    let mut md = String::new();
    writeln!(
        md,
        "| sampler | ns per sample | chi-squared p ({samples} samples) | worst Jacobian error | worst \\| \\|w\\| − 1 \\| | f32: worst \\| \\|w\\| − 1 \\| (ε₃₂) | f32: worst relative error of z (ε₃₂) |"
    )?;
    writeln!(md, "|---|---:|---:|---:|---:|---:|---:|")?;
    // The f32 relative errors of z and of |w|, by sampler, for the claims.
    let mut z_errors: Vec<(String, f64)> = Vec::new();
    let mut norm_errors: Vec<(String, f64)> = Vec::new();
    for w in correct_samplers() {
        let mut rng = rng::seeded(9);
        let n = 4096;
        let reps = if settings.quick { 5 } else { 101 };
        let ns = timing::median_ns_per_item(n, reps, || {
            let mut acc = 0.0;
            for _ in 0..n {
                acc += black_box(w.sample(&mut rng)).x;
            }
            acc.to_bits()
        });
        let p = chi2_p(w.as_ref(), samples, warp::SEED);
        // The checker's default: 10 000 Jacobian points.
        let jac = warp::jacobian(w.as_ref(), &Options::default())
            .and_then(|f| f.worst)
            .map_or("n/a (not a warp of the square)".to_string(), |(e, _)| {
                format!("{e:.1e}")
            });
        let mut rng = rng::seeded(10);
        let norm = (0..100_000)
            .map(|_| {
                let p = w.sample(&mut rng);
                if w.domain() == Domain::Sphere {
                    (p.length() - 1.0).abs()
                } else {
                    0.0
                }
            })
            .fold(0.0, f64::max);
        let norm = if w.domain() == Domain::Sphere {
            format!("{norm:.1e}")
        } else {
            "—".into()
        };
        let key = sampler_key(&w.name());
        let (norm32, z32) = single_precision(&w.name());
        if let Some(z) = z32 {
            z_errors.push((key.clone(), z));
        }
        if let Some(e) = norm32 {
            norm_errors.push((key.clone(), e));
        }
        let cell = |x: Option<f64>| x.map_or("—".to_string(), |x| format!("{x:.2}"));
        writeln!(
            md,
            "| {} | {} | {p:.3} | {jac} | {norm} | {} | {} |",
            w.name(),
            r.number(&format!("{key}.ns"), ns, ".1"),
            cell(norm32),
            z32.map_or("—".to_string(), |z| r.number(
                &format!("{key}.f32_z_error"),
                z,
                ".2"
            )),
        )?;
    }
    let z_of = |key: &str| {
        z_errors
            .iter()
            .find(|(k, _)| k == key)
            .map_or(f64::NAN, |&(_, z)| z)
    };
    let (malley, seed) = (z_of("cosine_malley"), z_of("cosine_seed_angles"));
    let cartesian = z_of("cosine_seed_cartesian");
    // The chapter *Cosine-weighted hemisphere*: all three unit to within one eps32; the
    // angle form's z more than a hundred times worse; the other two within one eps32.
    let cosines = [
        "cosine_seed_angles",
        "cosine_seed_cartesian",
        "cosine_malley",
    ];
    let norms: Vec<(&str, f64)> = cosines
        .iter()
        .map(|&k| {
            let e = norm_errors
                .iter()
                .find(|(n, _)| n == k)
                .map_or(f64::NAN, |&(_, e)| e);
            (k, e)
        })
        .collect();
    r.claim(
        "cosine_f32_unit",
        norms.iter().all(|&(_, e)| e < 1.0),
        format!(
            "f32: worst | |w| - 1 | of the three cosine samplers, in eps32, each < 1: {}",
            norms
                .iter()
                .map(|(k, e)| format!("{k} {e:.2}"))
                .collect::<Vec<_>>()
                .join(", ")
        ),
    );
    r.number("cosine_angles_z_error", seed, "int");
    r.claim(
        "cosine_angles_z_error_above_100",
        seed > 100.0,
        format!(
            "the seed's angle form, worst relative error of z in f32: {seed:.1} eps32 > 100 eps32"
        ),
    );
    r.claim(
        "cosine_cartesian_malley_z",
        cartesian <= 1.0 && malley <= 1.0,
        format!(
            "worst relative error of z in f32, in eps32: seed Cartesian {cartesian:.2} <= 1, Malley {malley:.2} <= 1"
        ),
    );
    r.claim(
        "seed_cartesian_z_within_one_eps32",
        cartesian <= 1.0,
        format!("the seed's Cartesian form, worst relative error of z in f32: {cartesian:.2} ε₃₂ <= 1 ε₃₂"),
    );
    r.claim(
        "malley_z_within_one_eps32",
        malley <= 1.0,
        format!("Malley's worst relative error of z in f32: {malley:.2} ε₃₂ <= 1 ε₃₂"),
    );
    r.claim(
        "seed_angles_z_beyond_one_eps32",
        seed > 1.0,
        format!("the seed's angle form, worst relative error of z in f32: {seed:.2} ε₃₂ > 1 ε₃₂"),
    );
    writeln!(
        md,
        "\n*{}; one sample = two uniform numbers from PCG-64 plus the warp, through a `dyn Warp` call; Jacobian by central differences at 10 000 points; norms over 100 000 samples. f32 columns: the same formulas in single precision (`single` modules) at 200 000 random f32 points of the square plus its corners and edges at 0, 1/2 and the largest f32 below 1; z is compared with the f64 formula at the same point (for the Gaussian and rejection methods, the f32 normalisation of 200 000 vectors of lengths 1e-30 to 1e30).*",
        timing::machine()
    )?;
    Ok(md.into_bytes())
}

/// The f32 columns of the methods table for the sampler called `name`: worst norm error
/// and worst relative error of `z`, in units of `f32::EPSILON` (`None` where not defined).
fn single_precision(name: &str) -> (Option<f64>, Option<f64>) {
    use glam::{DVec2, Vec2, Vec3};
    use raylemma::check::single::{norm_error, square_points, z_error};
    use raylemma::sampling::{cosine, sphere};
    use raylemma::single::sampling as single;
    type F32 = fn(Vec2) -> Vec3;
    type F64 = fn(DVec2) -> DVec3;
    let points = square_points(&Options::default());
    let both = |f: F32, exact: F64| {
        (
            Some(norm_error(f, &points)),
            Some(z_error(f, exact, &points)),
        )
    };
    match name {
        "sphere, inverse CDF" | "hemisphere, flipped inverse CDF" => both(
            single::sphere::sphere_inverse_cdf,
            sphere::sphere_inverse_cdf,
        ),
        "sphere, Gaussian" | "sphere, rejection" => {
            let mut r = rng::seeded(0x5F33);
            let worst = raylemma::check::max_abs((0..200_000).map(|_| {
                let v = sphere_uniform(&mut r).as_vec3()
                    * 10f32.powf(rng::uniform(&mut r, -30.0, 30.0) as f32);
                single::sphere::normalize_robust(v).map_or(f64::NAN, |w| {
                    (w.as_dvec3().length() - 1.0) / f64::from(f32::EPSILON)
                })
            }));
            (Some(worst), None)
        }
        "cosine, seed angles" => both(
            single::cosine::cosine_seed_angles,
            cosine::cosine_seed_angles,
        ),
        "cosine, seed Cartesian" => both(
            single::cosine::cosine_seed_cartesian,
            cosine::cosine_seed_cartesian,
        ),
        "cosine, Malley (concentric)" => both(single::cosine::cosine_malley, cosine::cosine_malley),
        _ => (None, None),
    }
}

fn seeds(settings: &Settings) -> u64 {
    if settings.quick { 40 } else { 400 }
}

/// A planted bug of the power table as a value name.
fn bug_key(name: &str) -> String {
    match name {
        "disc, r = u" => "disc_r_equals_u".into(),
        "sphere, theta uniform (missing sin theta)" => "sphere_theta_uniform".into(),
        "cosine^1.1 lobe claimed as cosine" => "cosine_1_1_lobe".into(),
        "cosine^1.05 lobe claimed as cosine (exercise 2 of Cosine-weighted hemisphere)" => {
            "cosine_1_05_lobe".into()
        }
        "uniform hemisphere claimed as cosine" => "uniform_hemisphere_as_cosine".into(),
        other => value_name(other),
    }
}

/// The `cos^1.05` lobe of exercise 2 of *Cosine-weighted hemisphere*, claimed as a cosine
/// lobe: `P(Z <= z) = z^2.05`, so `z = (1 - u1)^(1/2.05)` (the exercise's test draws the
/// same twin).
fn cosine_power_lobe_1_05(u: DVec2) -> DVec3 {
    let z = (1.0 - u.x).powf(1.0 / 2.05);
    let r = ((1.0 - z) * (1.0 + z)).max(0.0).sqrt();
    let phi = TAU * u.y;
    DVec3::new(r * phi.cos(), r * phi.sin(), z)
}

fn power_md(settings: &Settings, r: &mut Record) -> Result<Vec<u8>, BoxError> {
    let runs = if settings.quick { 10 } else { 50 };
    let sizes = [10_000, 100_000, 400_000, 1_000_000];
    let alpha = stats::test_alpha();
    let mut md = String::new();
    writeln!(
        md,
        "| planted bug | rejected at n = 10 000 | n = 100 000 | n = 400 000 | n = 1 000 000 |"
    )?;
    writeln!(md, "|---|---:|---:|---:|---:|")?;
    let mut bugs: Vec<Boxed> = planted::all()
        .into_iter()
        .map(|w| Box::new(w) as Boxed)
        .collect();
    bugs.push(square_warp(
        "cosine^1.05 lobe claimed as cosine (exercise 2 of Cosine-weighted hemisphere)",
        Domain::Sphere,
        cosine_power_lobe_1_05,
        cosine_pdf,
    ));
    for bug in bugs {
        let key = bug_key(&bug.name());
        let mut shares = Vec::new();
        let mut rates = Vec::new();
        for &n in &sizes {
            let ps: Vec<f64> = (0..runs)
                .into_par_iter()
                .map(|s| chi2_p(bug.as_ref(), n, 1000 + s))
                .collect();
            let errors = ps.iter().filter(|p| p.is_nan()).count();
            let rejected = ps.iter().filter(|&&p| p < alpha).count();
            let note = if errors > 0 {
                format!(" ({errors} errors)")
            } else {
                String::new()
            };
            let share = 100.0 * rejected as f64 / runs as f64;
            shares.push(share);
            rates.push(r.text(
                &format!("{key}.rejected_n{n}"),
                format!("{share:.0} %{note}"),
            ));
        }
        if key == "cosine_1_1_lobe" {
            r.claim(
                "cosine_1_1_lobe_needs_about_n100000",
                shares[0] < 50.0 && shares[1] >= 90.0,
                format!(
                    "the cos^1.1 lobe rejected for {:.0} % of the seeds at n = 10 000 < 50 % and {:.0} % at n = 100 000 >= 90 %",
                    shares[0], shares[1]
                ),
            );
        }
        writeln!(md, "| {} | {} |", bug.name(), rates.join(" | "))?;
    }
    writeln!(
        md,
        "\n*Share of {runs} seeds for which chi-squared rejects the bug at the suite's per-test level α = {alpha:.2e}.*"
    )?;
    Ok(md.into_bytes())
}

/// p-values of every correct sampler over many seeds (100 000 samples each).
fn calibration_p_values(settings: &Settings) -> Vec<(String, Vec<f64>)> {
    correct_samplers()
        .into_iter()
        .map(|w| {
            let ps = (0..seeds(settings))
                .into_par_iter()
                .map(|s| chi2_p(w.as_ref(), 100_000, 5000 + s))
                .collect();
            (w.name(), ps)
        })
        .collect()
}

fn calibration_svg(settings: &Settings, _: &mut Record) -> Result<Vec<u8>, BoxError> {
    let all: Vec<f64> = calibration_p_values(settings)
        .into_iter()
        .flat_map(|(_, ps)| ps)
        .collect();
    let bins = 20;
    let mut counts = vec![0usize; bins];
    for p in &all {
        counts[((p * bins as f64) as usize).min(bins - 1)] += 1;
    }
    let density: Vec<f64> = counts
        .iter()
        .map(|&c| c as f64 / all.len() as f64 * bins as f64)
        .collect();
    let edges: Vec<f64> = (0..=bins).map(|k| k as f64 / bins as f64).collect();
    let panels = [Panel::new(
        format!(
            "chi-squared p-values of the correct samplers ({} runs)",
            all.len()
        ),
        "p-value",
        "density",
        vec![
            Series::bars("observed", &edges, &density),
            Series::line("uniform (ideal)", vec![(0.0, 1.0), (1.0, 1.0)]),
        ],
    )
    .x_range((0.0, 1.0))];
    plot::chart(&panels, 1)
}

fn calibration_md(settings: &Settings, _: &mut Record) -> Result<Vec<u8>, BoxError> {
    let alpha = stats::test_alpha();
    let mut md = String::new();
    writeln!(
        md,
        "| sampler | runs | p < 0.05 (95 % interval) | p < 0.01 (95 % interval) | p < α = {alpha:.1e} (95 % interval) | KS p-value of the p-values |"
    )?;
    writeln!(md, "|---|---:|---:|---:|---:|---:|")?;
    for (name, ps) in calibration_p_values(settings) {
        // A NaN p-value (an error) counts as a failure here. Each rate with its Wilson
        // interval: over a few hundred runs the rate at α can only read 0 or the share of
        // one run, and the interval says how little that tells.
        let rate = |a: f64, decimals: usize| {
            let k = ps.iter().filter(|&&p| p.is_nan() || p < a).count();
            let n = ps.len();
            let (lo, hi) = stats::binomial::wilson(k as u32, n as u32);
            format!(
                "{:.decimals$} % ({:.decimals$}–{:.decimals$} %)",
                100.0 * k as f64 / n as f64,
                100.0 * lo,
                100.0 * hi
            )
        };
        let ks = stats::ks::one_sample(&ps, |x| x.clamp(0.0, 1.0)).map_or(f64::NAN, |k| k.p_value);
        writeln!(
            md,
            "| {name} | {} | {} | {} | {} | {ks:.3} |",
            ps.len(),
            rate(0.05, 1),
            rate(0.01, 1),
            rate(alpha, 2)
        )?;
    }
    writeln!(
        md,
        "\n*100 000 samples per run, one seed per run; the intervals are Wilson's at 95 % (`raylemma::stats::binomial::wilson`). A well-calibrated test rejects about 5 % and 1 % of correct samplers at those levels, and its p-values are uniform.*"
    )?;
    Ok(md.into_bytes())
}

fn distortion_md(_: &Settings, r: &mut Record) -> Result<Vec<u8>, BoxError> {
    let grid: Vec<DVec2> = (0..200)
        .flat_map(|i| {
            (0..200).map(move |j| DVec2::new((i as f64 + 0.5) / 200.0, (j as f64 + 0.5) / 200.0))
        })
        .collect();
    let mut md = String::new();
    writeln!(md, "| map | mean anisotropy | worst anisotropy |")?;
    writeln!(md, "|---|---:|---:|")?;
    // (mean, worst) anisotropy of each map.
    let mut maps = Vec::new();
    for (name, f) in [
        ("polar", disc_polar as fn(DVec2) -> DVec3),
        ("concentric", disc_concentric),
    ] {
        let a: Vec<f64> = grid.iter().map(|&u| anisotropy(f, u)).collect();
        let mean = a.iter().sum::<f64>() / a.len() as f64;
        let worst = a.iter().copied().fold(0.0, f64::max);
        maps.push((mean, worst));
        writeln!(
            md,
            "| {name} | {} | {} |",
            r.number(&format!("{name}.mean_anisotropy"), mean, ".2"),
            r.number(&format!("{name}.worst_anisotropy"), worst, ".1"),
        )?;
    }
    let (polar, concentric) = (maps[0], maps[1]);
    // The concentric map's closed form: in the wedge |a_x| > |a_y|, with t = a_y / a_x, its
    // Jacobian in the disc's polar frame is twice [[1, 0], [-pi/4 t, pi/4]]; the ratio of
    // its singular values is 4/pi at t = 0 and grows with |t| to its supremum at t = 1.
    let ratio = |t: f64| {
        let (a, b, c, d) = (1.0, 0.0, -FRAC_PI_4 * t, FRAC_PI_4);
        // Singular values of [[a, b], [c, d]]: from the trace and determinant of M^T M.
        let (tr, det) = (a * a + b * b + c * c + d * d, (a * d - b * c).powi(2));
        let root = (tr * tr - 4.0 * det).max(0.0).sqrt();
        ((tr + root) / (tr - root)).sqrt()
    };
    let (centre_line, supremum) = (ratio(0.0), ratio(1.0));
    r.number("concentric.centre_line_anisotropy", centre_line, ".2");
    r.number("concentric.supremum", supremum, ".2");
    r.claim(
        "concentric_below_sup",
        centre_line <= concentric.1 && concentric.1 <= supremum * (1.0 + 1e-12),
        format!(
            "concentric worst anisotropy {:.4} between 4/pi = {centre_line:.4} and the supremum {supremum:.4}",
            concentric.1
        ),
    );
    // The polar map's closed form: r = sqrt(u1), phi = 2 pi u2 stretch a cell by 1/(2 r)
    // radially and 2 pi r around, so the anisotropy is max(4 pi u1, 1 / (4 pi u1)); the
    // worst is at the grid's smallest u1 = 1/400.
    let closed = |u1: f64| (4.0 * PI * u1).max(1.0 / (4.0 * PI * u1));
    let closed_worst = closed(0.5 / 200.0);
    let closed_mean = (0..200)
        .map(|i| closed((f64::from(i) + 0.5) / 200.0))
        .sum::<f64>()
        / 200.0;
    let near = |x: f64, y: f64| (x - y).abs() <= 1e-3 * y;
    r.claim(
        "polar_closed_form",
        near(polar.1, closed_worst) && near(polar.0, closed_mean),
        format!(
            "polar worst anisotropy {:.4} against the closed form max(4 pi u1, 1/(4 pi u1)) at u1 = 1/400, {closed_worst:.4}; mean {:.4} against the closed form's mean over the grid, {closed_mean:.4}; each within 0.1 %",
            polar.1, polar.0
        ),
    );
    r.claim(
        "concentric_less_anisotropic",
        concentric.0 < polar.0 && concentric.1 < polar.1,
        format!(
            "concentric mean anisotropy {:.2} < polar {:.2}, and worst {:.1} < polar {:.1}",
            concentric.0, polar.0, concentric.1, polar.1
        ),
    );
    writeln!(
        md,
        "\n*Ratio of the larger to the smaller singular value of the map's Jacobian (1 = cells keep their shape), at the centres of a 200 × 200 grid of the unit square.*"
    )?;
    Ok(md.into_bytes())
}

fn warped_grids_svg(_: &Settings, _: &mut Record) -> Result<Vec<u8>, BoxError> {
    use plotters::prelude::*;
    plot::svg(plot::WIDTH, 420, |root, _| {
        type Map = fn(DVec2) -> DVec3;
        let maps: [(&str, Map); 2] = [
            ("polar map", disc_polar),
            ("concentric map", disc_concentric),
        ];
        for ((name, f), area) in maps.iter().zip(root.split_evenly((1, 2)).iter()) {
            let rest = plot::draw_title(area, name)?;
            let mut chart = ChartBuilder::on(&rest)
                .margin(15)
                .build_cartesian_2d(-1.05..1.05, -1.05..1.05)?;
            let lines = 12;
            for k in 0..=lines {
                let c = k as f64 / lines as f64;
                let along = |g: &dyn Fn(f64) -> DVec2| -> Vec<(f64, f64)> {
                    (0..=200)
                        .map(|s| f(g(f64::from(s) / 200.0)))
                        .map(|p| (p.x, p.y))
                        .collect()
                };
                let u1 = along(&|s| DVec2::new(c, s));
                let u2 = along(&|s| DVec2::new(s, c));
                chart.draw_series(LineSeries::new(u1, plot::PALETTE[0].stroke_width(1)))?;
                chart.draw_series(LineSeries::new(u2, plot::PALETTE[1].stroke_width(1)))?;
            }
        }
        Ok(())
    })
}

/// Azimuth in `[0, 2 pi)` and `cos(theta)`: the sphere's equal-area coordinates, in which a
/// uniform sampler looks uniform.
fn phi_z(w: DVec3) -> (f64, f64) {
    let phi = w.y.atan2(w.x);
    (if phi < 0.0 { phi + TAU } else { phi }, w.z)
}

fn scatter_svg(_: &Settings, _: &mut Record) -> Result<Vec<u8>, BoxError> {
    let mut rng = rng::seeded(0x5CA7);
    let n = 2500;
    let sphere_icdf: Vec<_> = (0..n)
        .map(|_| phi_z(sphere_inverse_cdf(warp::square_point(&mut rng))))
        .collect();
    let sphere_gauss: Vec<_> = (0..n).map(|_| phi_z(sphere_gaussian(&mut rng))).collect();
    // One jittered sample per cell of a 24 x 24 grid: stratified samples.
    let k = 24;
    let strata: Vec<DVec2> = (0..k * k)
        .map(|c| {
            let (i, j) = ((c / k) as f64, (c % k) as f64);
            DVec2::new(
                (i + rng::uniform(&mut rng, 0.0, 1.0)) / k as f64,
                (j + rng::uniform(&mut rng, 0.0, 1.0)) / k as f64,
            )
        })
        .collect();
    let xy = |p: DVec3| (p.x, p.y);
    let malley: Vec<_> = (0..n)
        .map(|_| xy(cosine_malley(warp::square_point(&mut rng))))
        .collect();
    let sphere_panel = |title: &str, points| {
        Panel::new(title, "φ", "cos θ", vec![Series::dots("", points)])
            .x_range((0.0, TAU))
            .y_range((-1.0, 1.0))
    };
    let disc_panel = |title: &str, points| {
        Panel::new(title, "x", "y", vec![Series::dots("", points)])
            .x_range((-1.05, 1.05))
            .y_range((-1.05, 1.05))
    };
    let panels = [
        sphere_panel("sphere, inverse CDF (equal-area coordinates)", sphere_icdf),
        sphere_panel("sphere, Gaussian (equal-area coordinates)", sphere_gauss),
        disc_panel("cosine, Malley: (x, y) of the directions", malley),
        disc_panel(
            "polar map of 24 × 24 stratified samples",
            strata.iter().map(|&u| xy(disc_polar(u))).collect(),
        ),
        disc_panel(
            "concentric map of the same samples",
            strata.iter().map(|&u| xy(disc_concentric(u))).collect(),
        ),
    ];
    plot::chart(&panels, 2)
}

fn histograms_svg(settings: &Settings, _: &mut Record) -> Result<Vec<u8>, BoxError> {
    let n = if settings.quick { 100_000 } else { 1_000_000 };
    let bins = 40;
    let histogram = |sample: &dyn Fn(&mut Rng) -> f64| {
        let mut rng = rng::seeded(0x4157);
        let mut counts = vec![0usize; bins];
        for _ in 0..n {
            let z = sample(&mut rng);
            counts[((z * bins as f64) as usize).min(bins - 1)] += 1;
        }
        counts
            .iter()
            .map(|&c| c as f64 / n as f64 * bins as f64)
            .collect::<Vec<_>>()
    };
    let edges: Vec<f64> = (0..=bins).map(|k| k as f64 / bins as f64).collect();
    let cosine = histogram(&|r| cosine_malley(warp::square_point(r)).z);
    let uniform =
        histogram(&|r| hemisphere_flip(sphere_inverse_cdf(warp::square_point(r)), DVec3::Z).z);
    let panel = |what: &str, method: &str, density: &[f64], pdf: Series| {
        Panel::new(
            format!("cos θ of {n} {what} samples"),
            "cos θ",
            "density",
            vec![
                Series::bars(format!("histogram ({method})"), &edges, density),
                pdf,
            ],
        )
        .x_range((0.0, 1.0))
        .legend(Legend::UpperLeft)
    };
    let panels = [
        panel(
            "cosine-weighted",
            "Malley",
            &cosine,
            Series::line("pdf 2 cos θ", vec![(0.0, 0.0), (1.0, 2.0)]),
        ),
        panel(
            "uniform hemisphere",
            "flipped inverse CDF",
            &uniform,
            Series::line("pdf 1", vec![(0.0, 1.0), (1.0, 1.0)]),
        )
        .y_range((0.0, 1.5)),
    ];
    plot::chart(&panels, 2)
}

/// The concentric map with the standard library's `sin_cos` of the wedge angle in place
/// of [`sin_cos_quarter`]: the form the series replaces.
fn disc_concentric_std(u: DVec2) -> DVec3 {
    let a = 2.0 * u - DVec2::ONE;
    if a == DVec2::ZERO {
        return DVec3::ZERO;
    }
    if a.y.abs() < a.x.abs() {
        let (sin, cos) = (FRAC_PI_4 * (a.y / a.x)).sin_cos();
        DVec3::new(a.x * cos, a.x * sin, 0.0)
    } else {
        let (sin, cos) = (FRAC_PI_4 * (a.x / a.y)).sin_cos();
        DVec3::new(a.y * sin, a.y * cos, 0.0)
    }
}

/// Does [`sin_cos_quarter`] pay? Median ns per call of the series and of the standard
/// library's `sin_cos` on angles in `[-pi/4, pi/4]`, in both precisions, and of the
/// concentric map with each, on the same random points of the square.
fn quarter_speed_md(settings: &Settings, r: &mut Record) -> Result<Vec<u8>, BoxError> {
    use raylemma::single::sampling::disc as disc32;
    let reps = if settings.quick { 5 } else { 201 };
    let mut rng = rng::seeded(0x5eed_d15c);
    let angles: Vec<f64> = (0..4096)
        .map(|_| rng::uniform(&mut rng, -FRAC_PI_4, FRAC_PI_4))
        .collect();
    let angles32: Vec<f32> = angles.iter().map(|&x| x as f32).collect();
    let points: Vec<DVec2> = (0..4096)
        .map(|_| {
            DVec2::new(
                rng::uniform(&mut rng, 0.0, 1.0),
                rng::uniform(&mut rng, 0.0, 1.0),
            )
        })
        .collect();
    let time32 = |f: &dyn Fn(f32) -> f32| {
        let mut out = vec![0.0f32; angles32.len()];
        timing::median_ns_per_item(angles32.len(), reps, || {
            for (o, &x) in out.iter_mut().zip(&angles32) {
                *o = f(black_box(x));
            }
            black_box(&out);
            u64::from(out[0].to_bits())
        })
    };
    let map = |f: &dyn Fn(DVec2) -> DVec3| {
        let mut out = vec![0.0; points.len()];
        timing::median_ns_per_item(points.len(), reps, || {
            for (o, &p) in out.iter_mut().zip(&points) {
                let q = f(black_box(p));
                *o = q.x + q.y;
            }
            black_box(&out);
            out[0].to_bits()
        })
    };
    let rows = [
        (
            "sin_cos",
            "f64",
            timing::median_ns_per_input(&angles, reps, |x| {
                let (s, c) = sin_cos_quarter(x);
                s + c
            }),
            timing::median_ns_per_input(&angles, reps, |x| {
                let (s, c) = x.sin_cos();
                s + c
            }),
        ),
        (
            "sin_cos",
            "f32",
            time32(&|x| {
                let (s, c) = disc32::sin_cos_quarter(x);
                s + c
            }),
            time32(&|x| {
                let (s, c) = x.sin_cos();
                s + c
            }),
        ),
        (
            "concentric_map",
            "f64",
            map(&|p| disc_concentric(p)),
            map(&|p| disc_concentric_std(p)),
        ),
    ];
    let mut md = String::new();
    writeln!(
        md,
        "| what | precision | the quarter-range series, ns | the standard library's `sin_cos`, ns | speed-up |"
    )?;
    writeln!(md, "|---|---|---:|---:|---:|")?;
    let mut all_faster = true;
    for (what, precision, ours, std) in rows {
        let key = format!("{what}.{precision}");
        all_faster &= ours < std;
        writeln!(
            md,
            "| {} | {precision} | {} | {} | {} |",
            what.replace('_', " "),
            r.number(&format!("{key}.series_ns"), ours, ".2"),
            r.number(&format!("{key}.std_ns"), std, ".2"),
            r.number(&format!("{key}.speedup"), std / ours, ".2"),
        )?;
    }
    r.claim(
        "series_faster_everywhere",
        all_faster,
        "the series and the map with it take less time than with sin_cos, in every row",
    );
    writeln!(
        md,
        "\n*{}; 4096 angles uniform in [−π/4, π/4] (and 4096 points of the square for the map) per batch, median of {reps} batches{}. Generated by `tools/figures/src/sampling.rs`.*",
        timing::machine(),
        timing::quick_note(settings.quick)
    )?;
    Ok(md.into_bytes())
}
