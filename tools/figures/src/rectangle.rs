//! Tables of the chapter *Sampling a rectangle by solid angle*: what sampling by solid angle
//! buys against sampling by area, for one estimate of the irradiance under a small and a
//! large light, and for the renderer's `cornell`.

use std::fmt::Write as _;
use std::time::Instant;

use super::shadow::{SIDES, measured, square_light, variance_and_time};
use super::{Output, Record, Settings, timing};
use raylemma::image::Image;
use raylemma::render::scene::LightSampling;
use raylemma::render::{self, Progress};
use raylemma::transport::rectangle::RectangleLight;
use raylemma::transport::shadow::IrradianceStrategy;

/// The outputs of this chapter.
pub fn outputs() -> Vec<Output> {
    vec![
        Output {
            file: "rectangle_strategies.md",
            what: "a rectangle light sampled by area or by solid angle: variance and time",
            make: strategies_md,
        },
        Output {
            file: "rectangle_cornell.md",
            what: "cornell rendered with its light sampled by area and by solid angle",
            make: cornell_md,
        },
    ]
}

fn strategies_md(settings: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let mut md = String::from(
        "| light | sampled by | variance per sample / E² | ns per sample | efficiency against area |\n|---|---|---:|---:|---:|\n",
    );
    // Per light: (variance ratio, efficiency ratio) of solid angle against area.
    let mut ratios = Vec::new();
    // Area sampling's row is the shadow chapter's "light" row (the same measurement).
    for (&(label, side), rows) in SIDES.iter().zip(measured(settings)?) {
        let area = square_light(side)?;
        let solid = RectangleLight::try_from(area)?;
        let &(_, exact, va, ta) = rows
            .iter()
            .find(|row| row.0 == "light")
            .ok_or_else(|| anyhow::anyhow!("the shadow table has no \"light\" row"))?;
        let (vs, ts) = variance_and_time(&solid, IrradianceStrategy::Light, settings);
        let (va, vs) = (va / (exact * exact), vs / (exact * exact));
        let key = if side < 1.0 { "small" } else { "large" };
        let eff = (va * ta) / (vs * ts);
        r.number(&format!("{key}.variance_ratio"), vs / va, "s3");
        r.number(&format!("{key}.time_ratio"), ts / ta, "s2");
        r.number(&format!("{key}.efficiency_ratio"), eff, "s2");
        ratios.push((vs / va, eff));
        writeln!(md, "| {label} | area | {va:.3e} | {ta:.0} | 1 |")?;
        writeln!(
            md,
            "| {label} | solid angle | {vs:.3e} | {ts:.0} | {eff:.2} |"
        )?;
    }
    let [(var_small, eff_small), (var_large, eff_large)] = [ratios[0], ratios[1]];
    r.claim(
        "lower_variance_both_lights",
        var_small < 0.5 && var_large < 0.5,
        format!(
            "variance of solid angle over area: small light {var_small:.4} < 0.5, large light {var_large:.4} < 0.5"
        ),
    );
    r.claim(
        "pays_alone_for_both_lights",
        eff_small > 1.0 && eff_large > eff_small,
        format!(
            "efficiency of solid angle against area: small light {eff_small:.3} > 1, large light {eff_large:.3} larger still"
        ),
    );
    writeln!(
        md,
        "\n*Light sampling alone (one sample, no BSDF sample), the lights of `shadow_strategies`: shading point at the origin, normal +z, a square light centred 0.3 off the normal at height 1. Efficiency is 1 / (variance × time), solid angle's over area's. Timed on {}.{}*",
        timing::machine(),
        timing::quick_note(settings.quick)
    )?;
    Ok(md.into_bytes())
}

/// The mean over pixels and channels of the variance of a pixel's mean.
fn mean_variance(image: &Image) -> f64 {
    let sum: f64 = image.var.iter().map(|v| v.element_sum()).sum();
    sum / (3 * image.var.len()) as f64
}

fn cornell_md(settings: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let (side, spp, reps) = if settings.quick {
        (32, 4, 1)
    } else {
        (256, 32, 3)
    };
    let mut scene = crate::render::cornell_timed(settings, side)?;
    let modes = [LightSampling::Area, LightSampling::SolidAngle];
    // Per mode: the render seconds of each round and the mean variance (the same every
    // round: same seed, same image).
    let mut seconds = [vec![], vec![]];
    let mut variance = [0.0; 2];
    for _ in 0..reps {
        for (k, &mode) in modes.iter().enumerate() {
            scene.settings.light_sampling = mode;
            let start = Instant::now();
            let image = render::render(&scene, spp, Progress::Silent);
            seconds[k].push(start.elapsed().as_secs_f64());
            variance[k] = mean_variance(&image);
        }
    }
    let median = |v: &mut Vec<f64>| {
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    };
    let t = [median(&mut seconds[0]), median(&mut seconds[1])];
    let eff = [1.0 / (variance[0] * t[0]), 1.0 / (variance[1] * t[1])];
    let mut md = String::from(
        "| light sampled by | render seconds (median) | mean variance of a pixel's mean | efficiency, 1 / (variance × s) |\n|---|---:|---:|---:|\n",
    );
    for (k, name) in ["area", "solid angle"].iter().enumerate() {
        writeln!(
            md,
            "| {name} | {:.2} | {:.4e} | {:.1} |",
            t[k], variance[k], eff[k]
        )?;
    }
    let (var_ratio, eff_ratio) = (variance[1] / variance[0], eff[1] / eff[0]);
    r.number("variance_ratio", var_ratio, "s3");
    r.number("time_ratio", t[1] / t[0], "s2");
    r.number("efficiency_ratio", eff_ratio, "s2");
    r.claim(
        "does_not_pay",
        eff_ratio < 1.0 && (var_ratio - 1.0).abs() < 0.02,
        format!(
            "solid angle against area on cornell: efficiency ratio {eff_ratio:.3} < 1, variance ratio {var_ratio:.4} within 2 % of 1"
        ),
    );
    writeln!(
        md,
        "\n*`cornell` at {side}×{side}, {spp} samples per pixel, roulette from depth 5, the same seed for both; {reps} rounds, each rendering with area and then with solid-angle sampling; the medians. {}, {} worker threads.{}*",
        timing::machine_name(),
        rayon::current_num_threads(),
        timing::quick_note(settings.quick)
    )?;
    Ok(md.into_bytes())
}
