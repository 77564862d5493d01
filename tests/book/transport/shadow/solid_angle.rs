//! (a) The subtended solid angle, as the mean of 1 / p_w.

use super::*;

#[test]
fn van_oosterom_strackee_matches_the_on_axis_rectangle_formula() {
    // A w x h rectangle at distance d on its axis: Omega = 4 asin(w h / sqrt((w^2 + 4d^2)(h^2 + 4d^2))).
    for (w, h, d) in [
        (1.0, 1.0, 1.0),
        (0.3, 2.0, 0.5),
        (1e-3, 2e-3, 10.0),
        (50.0, 40.0, 0.01),
    ] {
        let light = QuadLight::new(
            DVec3::new(-w / 2.0, -h / 2.0, d),
            DVec3::new(0.0, h, 0.0),
            DVec3::new(w, 0.0, 0.0),
        )
        .unwrap();
        let exact = 4.0 * (w * h / ((w * w + 4.0 * d * d) * (h * h + 4.0 * d * d)).sqrt()).asin();
        let ours = light.solid_angle(DVec3::ZERO);
        assert!(
            (ours - exact).abs() <= 1e-12 * exact,
            "{w} x {h} at {d}: {ours} vs {exact}"
        );
    }
}

#[test]
fn quad_solid_angle_is_the_mean_of_one_over_pdf() {
    for (name, light, seed) in [
        ("rectangle", quad(), 1),
        ("parallelogram", tilted_quad(), 2),
    ] {
        let p = DVec3::ZERO;
        let exact = light.solid_angle(p);
        let s = mean_of(seed, N, |u, _| {
            light.sample(p, u).map_or(0.0, |s| 1.0 / s.pdf)
        });
        assert!(
            accepts(&s, exact),
            "{name}: mean {} vs {exact}, p = {:e}",
            s.mean,
            p_value(&s, exact)
        );
        for (bug, convert) in PLANTED {
            let s = mean_of(seed, N, |u, _| {
                let s = light.sample(p, u).unwrap();
                1.0 / convert(1.0 / light.area(), s.dist, s.cos_light)
            });
            assert!(
                !accepts(&s, exact),
                "{name}, planted bug {bug} passed: mean {} vs {exact}",
                s.mean
            );
        }
    }
}

#[test]
fn sphere_solid_angle_is_the_mean_of_one_over_pdf() {
    let light = sphere();
    let p = DVec3::new(0.1, 0.2, -0.4);
    let exact = light.solid_angle(p);
    let d = (light.center() - p).length();
    let closed = TAU * (1.0 - (1.0 - (light.radius() / d).powi(2)).sqrt());
    assert!((exact - closed).abs() < 1e-14, "{exact} vs {closed}");
    let s = mean_of(3, N, |u, _| light.sample(p, u).map_or(0.0, |s| 1.0 / s.pdf));
    assert!(accepts(&s, exact), "mean {} vs {exact}", s.mean);
    // The planted bugs, plus normalising by the whole sphere's area instead of the visible cap.
    let whole_sphere: Convert = |_pa, r, c| r * r / c.abs() / (4.0 * PI * 0.81);
    for (bug, convert) in PLANTED
        .into_iter()
        .chain([("whole-sphere area", whole_sphere)])
    {
        let s = mean_of(3, N, |u, _| {
            let s = light.sample(p, u).unwrap();
            1.0 / convert(1.0 / light.visible_area(p), s.dist, s.cos_light)
        });
        assert!(
            !accepts(&s, exact),
            "planted bug {bug} passed: mean {} vs {exact}",
            s.mean
        );
    }
}
