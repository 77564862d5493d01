//! The speed and accuracy of every sampler (`sampling_methods.md`), of the chapters *Uniform
//! sphere and hemisphere* and *Cosine-weighted hemisphere*: time, chi-squared p-value and
//! the f32 columns.

use std::fmt::Write as _;
use std::hint::black_box;

use glam::DVec3;

use super::{chi2_p, correct_samplers, value_name};
use crate::{Record, Settings, timing};
use raylemma::check::Options;
use raylemma::check::warp::{self, Domain};
use raylemma::rng;
use raylemma::sampling::sphere::*;

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

pub(super) fn methods_md(settings: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
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
        "\n*{}; one sample = the uniform numbers it draws from PCG-64 (two for a warp of the square; the Gaussian method four, for two Box-Muller pairs; rejection three a try, 18/pi = 5.7 on average) plus the warp, through a `dyn Warp` call; Jacobian by central differences at 10 000 points; norms over 100 000 samples. f32 columns: the same formulas in single precision (`single` modules) at 200 000 random f32 points of the square plus its corners and edges at 0, 1/2 and the largest f32 below 1; z is compared with the f64 formula at the same point (for the Gaussian and rejection methods, the f32 normalisation of 200 000 vectors of lengths 1e-30 to 1e30).*",
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
