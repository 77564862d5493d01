//! (b) Irradiance against the closed forms.

use super::*;

#[test]
fn lambert_formula_limits() {
    let n = DVec3::Z;
    // A tiny square far away: E = L Omega cos(theta).
    let tiny = QuadLight::new(
        DVec3::new(3.0, 0.0, 4.0),
        DVec3::new(0.0, 1e-4, 0.0),
        DVec3::new(1e-4, 0.0, 0.0),
    )
    .unwrap();
    let small = tiny.irradiance(DVec3::ZERO, n, 1.0);
    let expected = tiny.solid_angle(DVec3::ZERO) * 0.8;
    assert!(
        (small - expected).abs() < 1e-4 * expected,
        "{small} vs {expected}"
    );
    // A huge square just above the point: E -> pi L.
    let huge = QuadLight::new(
        DVec3::new(-1e4, -1e4, 1e-3),
        DVec3::new(0.0, 2e4, 0.0),
        DVec3::new(2e4, 0.0, 0.0),
    )
    .unwrap();
    let e = huge.irradiance(DVec3::ZERO, n, 1.0);
    assert!((e - PI).abs() < 1e-6, "{e} vs pi");
    // Facing away: nothing.
    assert_eq!(huge.irradiance(DVec3::new(0.0, 0.0, 1.0), -n, 1.0), 0.0);
}

#[test]
fn quad_irradiance_matches_lambert_for_every_strategy() {
    let n = DVec3::new(0.3, 0.1, 1.0).normalize();
    let (p, radiance) = (DVec3::ZERO, 2.5);
    for (name, light) in [("rectangle", quad()), ("parallelogram", tilted_quad())] {
        let exact = light.irradiance(p, n, radiance);
        for (k, strategy) in STRATEGIES.into_iter().enumerate() {
            let s = mean_of(10 + k as u64, N, |a, b| {
                estimate_irradiance(&light, p, n, radiance, strategy, a, b)
            });
            assert!(
                accepts(&s, exact),
                "{name} {strategy:?}: mean {} vs {exact}, p = {:e}",
                s.mean,
                p_value(&s, exact)
            );
        }
        // Planted: the light-sampling estimate with each wrong pdf.
        for (bug, convert) in PLANTED {
            let s = mean_of(10, N, |a, _| {
                let s = light.sample(p, a).unwrap();
                let pdf = convert(1.0 / light.area(), s.dist, s.cos_light);
                radiance * n.dot(s.dir).max(0.0) / pdf
            });
            assert!(
                !accepts(&s, exact),
                "{name}: planted bug {bug} passed: mean {} vs {exact}",
                s.mean
            );
        }
    }
}

#[test]
fn sphere_irradiance_matches_the_closed_form_for_every_strategy() {
    let light = sphere();
    let n = DVec3::new(0.2, -0.1, 1.0).normalize();
    let (p, radiance) = (DVec3::new(0.1, 0.2, -0.4), 1.7);
    let exact = sphere_irradiance(p, n, &light, radiance);
    for (lname, l) in [("area", &light as &dyn Light), ("cone", &SphereCone(light))] {
        for (k, strategy) in STRATEGIES.into_iter().enumerate() {
            let s = mean_of(20 + k as u64, N, |a, b| {
                estimate_irradiance(l, p, n, radiance, strategy, a, b)
            });
            assert!(
                accepts(&s, exact),
                "{lname} {strategy:?}: mean {} vs {exact}, p = {:e}",
                s.mean,
                p_value(&s, exact)
            );
        }
    }
    // Planted: the cap sampled but the density normalised by the whole sphere's area.
    let s = mean_of(20, N, |a, _| {
        let s = light.sample(p, a).unwrap();
        let pdf = area_to_solid_angle(1.0 / (4.0 * PI * 0.81), s.dist, s.cos_light);
        radiance * n.dot(s.dir).max(0.0) / pdf
    });
    assert!(
        !accepts(&s, exact),
        "whole-sphere normalisation passed: {} vs {exact}",
        s.mean
    );
}
