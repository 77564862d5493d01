//! Scale invariance and hard cases.

use super::*;

#[test]
fn scaling_the_scene_leaves_the_estimate_unchanged() {
    let n = DVec3::new(0.3, 0.1, 1.0).normalize();
    let p = DVec3::new(0.2, -0.1, 0.1);
    let mut worst: f64 = 0.0;
    for scale in [1e-3, 0.37, 3.0, 1e4] {
        let lights: [(Box<dyn Light>, Box<dyn Light>); 3] = [
            (
                Box::new(tilted_quad()),
                Box::new(tilted_quad().scaled(scale).unwrap()),
            ),
            (
                Box::new(sphere()),
                Box::new(sphere().scaled(scale).unwrap()),
            ),
            (
                Box::new(SphereCone(sphere())),
                Box::new(SphereCone(sphere().scaled(scale).unwrap())),
            ),
        ];
        for (a, b) in &lights {
            let mut rng = rng::seeded(40);
            for _ in 0..2_000 {
                let (u, v) = (square_point(&mut rng), square_point(&mut rng));
                for strategy in STRATEGIES {
                    let ea = estimate_irradiance(a.as_ref(), p, n, 1.0, strategy, u, v);
                    let eb = estimate_irradiance(b.as_ref(), p * scale, n, 1.0, strategy, u, v);
                    worst = max_abs([worst, (ea - eb) / ea.abs().max(1e-300)]);
                }
            }
        }
    }
    println!("worst relative change under scaling: {worst:e}");
    assert!(worst < 1e-12, "{worst:e}");
}

#[test]
fn degenerate_lights_are_errors_not_panics() {
    let (c, x, y) = (DVec3::ZERO, DVec3::X, DVec3::Y);
    assert_eq!(
        QuadLight::new(c, DVec3::ZERO, y),
        Err(LightError::ZeroLengthEdge("e1"))
    );
    assert_eq!(
        QuadLight::new(c, x, DVec3::ZERO),
        Err(LightError::ZeroLengthEdge("e2"))
    );
    assert_eq!(
        QuadLight::new(c, x, 2.0 * x),
        Err(LightError::ParallelEdges)
    );
    assert_eq!(
        QuadLight::new(c, x, -x + DVec3::new(0.0, 1e-15, 0.0)),
        Err(LightError::ParallelEdges)
    );
    assert_eq!(
        QuadLight::new(DVec3::NAN, x, y),
        Err(LightError::NonFinite("corner"))
    );
    assert_eq!(
        QuadLight::new(c, x, DVec3::INFINITY),
        Err(LightError::NonFinite("edge e2"))
    );
    for r in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let e = SphereLight::new(c, r).unwrap_err();
        assert!(matches!(e, LightError::BadRadius(_)), "{e}");
        assert!(e.to_string().contains("radius"), "{e}");
    }
    assert_eq!(
        SphereLight::new(DVec3::NAN, 1.0),
        Err(LightError::NonFinite("centre"))
    );
    assert!(
        QuadLight::new(c, x, x)
            .unwrap_err()
            .to_string()
            .contains("parallel")
    );
}

/// Every strategy's estimate at `p`, from 2 000 random number pairs: all finite and >= 0.
fn estimates(light: &dyn Light, p: DVec3, n: DVec3) -> Vec<f64> {
    let mut rng = rng::seeded(50);
    let mut out = Vec::new();
    for _ in 0..2_000 {
        let (u, v) = (square_point(&mut rng), square_point(&mut rng));
        for strategy in STRATEGIES {
            let e = estimate_irradiance(light, p, n, 1.0, strategy, u, v);
            assert!(e.is_finite() && e >= 0.0, "{strategy:?} at {p:?}: {e}");
            out.push(e);
            let _ = light.pdf(p, light.sample(p, u).map_or(n, |s| s.dir));
        }
    }
    out
}

#[test]
fn a_light_behind_the_point_contributes_nothing() {
    let n = DVec3::Z;
    // The quad above, its normal facing down; the shading point faces down too.
    assert!(
        estimates(&quad(), DVec3::ZERO, -n)
            .iter()
            .all(|&e| e == 0.0)
    );
    // The shading point above the quad: it sees the quad's back.
    assert!(
        estimates(&quad(), DVec3::new(0.1, 0.0, 2.0), n)
            .iter()
            .all(|&e| e == 0.0)
    );
    // A sphere below the horizon.
    let below = SphereLight::new(DVec3::new(0.0, 0.0, -3.0), 1.0).unwrap();
    assert!(estimates(&below, DVec3::ZERO, n).iter().all(|&e| e == 0.0));
    assert!(
        estimates(&SphereCone(below), DVec3::ZERO, n)
            .iter()
            .all(|&e| e == 0.0)
    );
}

#[test]
fn grazing_and_touching_configurations_are_finite() {
    let n = DVec3::Z;
    let q = quad();
    // In the light's plane: seen exactly edge-on, no sample, no NaN.
    let edge_on = DVec3::new(-3.0, 0.0, 1.2);
    assert!(q.sample(edge_on, DVec2::splat(0.5)).is_none());
    assert!(estimates(&q, edge_on, DVec3::X).iter().all(|&e| e == 0.0));
    // Just below the plane, far to the side: grazing angles.
    estimates(&q, DVec3::new(-30.0, 0.1, 1.2 - 1e-9), DVec3::X);
    // Very close to the light's centre: nearly a hemisphere, E -> pi L.
    let close = DVec3::new(0.35, 0.1, 1.2 - 1e-7);
    let e = q.irradiance(close, n, 1.0);
    assert!((e - PI).abs() < 1e-5, "{e}");
    estimates(&q, close, n);
    // A sphere seen from 1e-9 radii above its surface, and from its surface and inside.
    let s = SphereLight::new(DVec3::new(0.0, 0.0, 1.0), 1.0).unwrap();
    estimates(&s, DVec3::new(0.0, 0.0, -1e-9), n);
    estimates(&SphereCone(s), DVec3::new(0.0, 0.0, -1e-9), n);
    for inside in [DVec3::ZERO, DVec3::new(0.0, 0.0, 1.0)] {
        assert!(s.sample(inside, DVec2::splat(0.3)).is_none());
        assert_eq!(s.pdf(inside, n), 0.0);
        assert!(estimates(&s, inside, n).iter().all(|&e| e == 0.0));
    }
    // A pdf of a direction that misses is 0.
    assert_eq!(q.pdf(DVec3::ZERO, -n), 0.0);
    assert_eq!(s.pdf(DVec3::new(0.0, 0.0, -2.0), -n), 0.0);
}

#[test]
fn cone_sampling_beats_cap_area_sampling() {
    // Variance of the one-sample irradiance estimate, normal towards the light.
    for d in [1.05, 2.0, 10.0] {
        let light = SphereLight::new(DVec3::new(0.0, 0.0, d), 1.0).unwrap();
        let n = DVec3::new(0.0, 0.0, 1.0);
        let area = mean_of(60, N, |a, b| {
            estimate_irradiance(&light, DVec3::ZERO, n, 1.0, IrradianceStrategy::Light, a, b)
        });
        let cone = mean_of(60, N, |a, b| {
            estimate_irradiance(
                &SphereCone(light),
                DVec3::ZERO,
                n,
                1.0,
                IrradianceStrategy::Light,
                a,
                b,
            )
        });
        println!(
            "d = {d}: variance area {:.3e}, cone {:.3e}",
            area.variance(),
            cone.variance()
        );
        assert!(
            cone.variance() < 0.5 * area.variance(),
            "d = {d}: {} vs {}",
            cone.variance(),
            area.variance()
        );
    }
}
