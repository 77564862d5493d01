//! `compare` on agreeing and disagreeing renders (chapter *Comparing images*): two seeds
//! against a changed scene, images it cannot judge, its critical values, and the emission
//! wavelengths of a lamp against `hero_visible`.

use super::*;

#[test]
fn compare_accepts_two_seeds_and_rejects_a_changed_scene() {
    let s = small(load("cornell-diffuse.toml"), 32, 32);
    let a = render(&s, 32, Progress::Silent);
    let mut s2 = s.clone();
    s2.settings.seed = 99;
    let b = render(&s2, 32, Progress::Silent);
    let c = compare(&a, &b, test_alpha()).unwrap();
    assert!(
        c.agree(),
        "two seeds of one scene differ:\n{}",
        c.report(["a", "b"])
    );
    assert!(
        (0.8..=1.25).contains(&c.mean_z2),
        "mean z^2 = {} (variances wrong?)",
        c.mean_z2
    );
    // Planted bug: the white sphere and walls reflect 5 % more.
    let mut bright = s2.clone();
    for m in &mut bright.materials {
        if let Material::Lambert {
            reflectance: Spectrum::Table(t),
        } = m
        {
            *t = t.scaled(1.05);
        }
    }
    let d = render(&bright, 32, Progress::Silent);
    let c = compare(&a, &d, test_alpha()).unwrap();
    assert!(
        !c.agree(),
        "a 5 % brighter box passed:\n{}",
        c.report(["a", "b"])
    );
    assert!(c.regions[0].z.abs() > c.z_critical);
}

#[test]
fn compare_refuses_images_it_cannot_judge() {
    let s = small(load("cornell-diffuse.toml"), 8, 2);
    let a = render(&s, 2, Progress::Silent);
    let b = render(
        &small(load("cornell-diffuse.toml"), 9, 2),
        2,
        Progress::Silent,
    );
    assert!(
        compare(&a, &b, 0.01)
            .unwrap_err()
            .to_string()
            .contains("different sizes")
    );
    let one = render(&s, 1, Progress::Silent);
    assert!(
        compare(&a, &one, 0.01)
            .unwrap_err()
            .to_string()
            .contains("at least 2 samples")
    );
    assert!(compare(&a, &a, 0.0).is_err());
    assert!(compare(&a, &a, 0.01).unwrap().agree());
}

#[test]
fn two_sided_critical_values_match_the_normal_table() {
    // Published values: P(|Z| > 1.959964) = 0.05, P(|Z| > 3.290527) = 0.001.
    assert!((two_sided_critical(0.05) - 1.959_964).abs() <= 1e-6);
    assert!((two_sided_critical(0.001) - 3.290_527).abs() <= 1e-6);
}

fn lamp_named(name: &str, strategy: Option<raylemma::render::WavelengthSampler>) -> Image {
    let s = small(load(name), 24, 64);
    match strategy {
        None => render(&s, s.settings.spp, Progress::Silent),
        Some(w) => render_with(&s, s.settings.spp, Progress::Silent, w),
    }
}

fn lamp(strategy: Option<raylemma::render::WavelengthSampler>) -> Image {
    lamp_named("lamps/high-pressure-sodium.toml", strategy)
}

fn total_variance(i: &Image) -> f64 {
    i.var.iter().map(|v| v.element_sum()).sum()
}

#[test]
fn emission_wavelengths_agree_with_hero_visible_and_cut_the_noise() {
    let by_emission = lamp(None);
    let by_visible = lamp(Some(&|u| WavelengthStrategy::HeroVisible.sample(u)));
    let c = compare(&by_emission, &by_visible, test_alpha()).unwrap();
    assert!(
        c.agree(),
        "emission vs visible wavelengths:\n{}",
        c.report(["a", "b"])
    );
    let gain = total_variance(&by_visible) / total_variance(&by_emission);
    assert!(
        gain >= 1.3,
        "high-pressure sodium: the emission strategy's variance is only {gain} times lower"
    );
    // On a line spectrum the gain is the point of the emission chapter.
    let lps = "lamps/low-pressure-sodium.toml";
    let gain = total_variance(&lamp_named(
        lps,
        Some(&|u| WavelengthStrategy::HeroVisible.sample(u)),
    )) / total_variance(&lamp_named(lps, None));
    assert!(
        gain >= 10.0,
        "low-pressure sodium: the emission strategy's variance is only {gain} times lower"
    );
}

#[test]
fn emission_wavelengths_weighted_by_another_pdf_are_rejected() {
    // Planted bug: lanes drawn from the lamp's colour proposal, weighted by the visible pdf.
    let s = small(load("lamps/high-pressure-sodium.toml"), 24, 64);
    let wavelengths = s.settings.wavelengths.clone();
    let wrong = lamp(Some(&move |u| {
        let mut w = wavelengths.sample(u);
        w.pdf = w.lambda.map(raylemma::spectral::wavelength::visible_pdf);
        w.hero_pdf = w.pdf[0];
        w
    }));
    let c = compare(&lamp(None), &wrong, test_alpha()).unwrap();
    assert!(
        !c.agree(),
        "a wrong weight passed:\n{}",
        c.report(["a", "b"])
    );
}

#[test]
fn light_sampling_by_solid_angle_agrees_with_area_sampling() {
    // The cornell-diffuse box's light is a rectangle: `light_sampling = "solid-angle"` samples
    // it with chapter *Sampling a rectangle by solid angle*'s sampler, in the next-event
    // estimate and in the MIS weight of a BSDF sample that hits it. Same expected image.
    use raylemma::render::scene::LightSampling;
    let dir = crate::support::root().join("scenes");
    let text = std::fs::read_to_string(dir.join("cornell-diffuse.toml")).unwrap();
    let with = |value: &str| {
        let t = text.replacen(
            "[render]",
            &format!("[render]\nlight_sampling = {value:?}"),
            1,
        );
        raylemma::render::format::parse(&t, "cornell-diffuse.toml", &dir)
    };
    let area = small(with("area").unwrap(), 32, 32);
    assert_eq!(area.settings.light_sampling, LightSampling::Area);
    let mut solid = small(with("solid-angle").unwrap(), 32, 32);
    assert_eq!(solid.settings.light_sampling, LightSampling::SolidAngle);
    assert!(solid.lights.iter().all(|l| l.rectangle.is_some()));
    let e = with("cone").unwrap_err().to_string();
    assert!(
        e.contains("unknown light sampling") && e.contains("solid-angle"),
        "{e}"
    );
    // Independent seeds, so that `compare`'s variances hold for the difference.
    solid.settings.seed = area.settings.seed + 1;
    let a = render(&area, 32, Progress::Silent);
    let b = render(&solid, 32, Progress::Silent);
    let c = compare(&a, &b, test_alpha()).unwrap();
    assert!(
        c.agree(),
        "area vs solid angle:\n{}",
        c.report(["area", "solid angle"])
    );
    // Not vacuous: the same seed gives a different image.
    solid.settings.seed = area.settings.seed;
    assert!(bits(&a) != bits(&render(&solid, 32, Progress::Silent)));
}
