//! (c) The pdf returned with a sample is the pdf of its direction.

use super::*;

/// The worst relative difference between the pdf returned with a sample and the pdf of its
/// direction evaluated by casting the ray: all samples weighted by `cos_light^2`; samples
/// with `|cos_light| > 0.1`; all samples weighted by `|cos_light|`. Near a silhouette
/// `|cos_light|` is small and the ray meets the light at a grazing angle. For a
/// parallelogram the cast's `n . w` and distance carry an absolute rounding: a relative
/// error like `eps / |cos_light|`. For a sphere the hit point's error along the ray tilts
/// the normal there, and the cosine's relative error grows faster, like `1 / cos_light^2`
/// (with a factor that grows with the distance); only at the exact tangent is the
/// distance itself as poor as `sqrt(eps)`. Hence the weight `cos_light^2`.
fn worst_pdf_mismatch(
    light: &dyn Light,
    rng: &mut Rng,
    points: impl Fn(&mut Rng) -> DVec3,
) -> [f64; 3] {
    let (mut weighted, mut steep, mut linear): (f64, f64, f64) = (0.0, 0.0, 0.0);
    for _ in 0..20_000 {
        let p = points(rng);
        let Some(s) = light.sample(p, square_point(rng)) else {
            continue;
        };
        let eval = light.pdf(p, s.dir);
        assert!(
            eval.is_finite() && eval > 0.0 && s.pdf.is_finite() && s.pdf > 0.0,
            "{s:?}: {eval}"
        );
        let rel = (eval - s.pdf).abs() / s.pdf;
        weighted = max_abs([weighted, rel * s.cos_light * s.cos_light]);
        linear = max_abs([linear, rel * s.cos_light]);
        if s.cos_light.abs() > 0.1 {
            steep = max_abs([steep, rel]);
        }
    }
    [weighted, steep, linear]
}

#[test]
fn sampled_pdf_equals_evaluated_pdf() {
    let mut rng = rng::seeded(30);
    // Shading points in front of the quad, from 1e-4 to 10 away from its plane.
    let front = |r: &mut Rng| {
        let v = sphere_uniform(r);
        DVec3::new(v.x * 3.0, v.y * 3.0, 1.2 - rng::log_uniform(r, 1e-4, 10.0))
    };
    // Shading points from 1e-6 to 1e3 radii outside the unit sphere.
    let outside = |r: &mut Rng| sphere_uniform(r) * (1.0 + rng::log_uniform(r, 1e-6, 1e3));
    let sph = SphereLight::new(DVec3::ZERO, 1.0).unwrap();
    let results = [
        ("quad", worst_pdf_mismatch(&quad(), &mut rng, front)),
        (
            "parallelogram",
            worst_pdf_mismatch(&tilted_quad(), &mut rng, front),
        ),
        (
            "sphere, cap area",
            worst_pdf_mismatch(&sph, &mut rng, outside),
        ),
        (
            "sphere, cone",
            worst_pdf_mismatch(&SphereCone(sph), &mut rng, outside),
        ),
    ];
    for (name, [weighted, steep, linear]) in results {
        println!(
            "{name}: worst rel. error x cos^2 {weighted:.2e}, x |cos| {linear:.2e}, where |cos| > 0.1 {steep:.2e}"
        );
        assert!(
            weighted < 1e-11 && steep < 1e-9,
            "{name}: {weighted:e}, {steep:e}"
        );
        // The parallelogram's is within about 450 eps / |cos| (measured: 20 eps): far from
        // sqrt(eps) = 1.5e-8 at every angle.
        if name == "quad" || name == "parallelogram" {
            assert!(linear < 1e-13, "{name}: {linear:e} x |cos|");
        }
    }
}

/// The parallelogram's edge coordinates on the corpus input where reading them off the
/// point `o + t d - c` was 10 times the accuracy bound (25 ulps where one rounding of the
/// inputs moves them by 2.4): a hit 1e3 along the ray, whose rounded `t` the old form
/// carried into `a`. The exact answer is the corpus's (`tools/exact/sphere.py`, mpmath).
#[test]
fn edge_coordinates_keep_their_digits_far_along_the_ray() {
    use raylemma::check::accuracy::{self, BOUND, Precision, corpus};
    use raylemma::geometry::Parallelogram;
    let root = crate::support::root();
    let c = corpus::load(&root.join("data/corpus/sphere.txt")).expect("the corpus reads");
    let verb = c.verb("quad_coords").expect("declared");
    let case = c
        .cases_of("quad_coords")
        .find(|k| k.why.starts_with("an oblique parallelogram, 1e3 away"))
        .expect("the case");
    let v = |i: usize| DVec3::new(case.args[i], case.args[i + 1], case.args[i + 2]);
    let q = Parallelogram::new(v(6), v(9), v(12)).expect("a parallelogram");
    assert!(q.hit(v(0), v(3)).is_some(), "{}", case.question);
    let (a, b) = q.edge_coordinates(v(0), v(3));
    let m = accuracy::measure_one(case, 0, verb, &Some(vec![a, b]), Precision::Double);
    assert!(
        m.ratio <= BOUND,
        "{}: ({a}, {b}) is {} ulps off, condition {}",
        case.question,
        m.ulps,
        m.condition
    );
}

/// The MIS weights on the corpus inputs where `pa / (pa + pb)` of the densities or of
/// their squares failed: equal densities whose squares overflow (the power heuristic was
/// NaN), whose squares underflow (it was 0), and two largest doubles (the balance
/// heuristic's sum overflowed, giving 0). The exact answers are the corpus's
/// (`tools/exact/shadow.py`, mpmath).
#[test]
fn mis_weights_survive_huge_and_tiny_densities() {
    use raylemma::check::accuracy::{self, BOUND, Precision, corpus};
    let root = crate::support::root();
    let c = corpus::load(&root.join("data/corpus/shadow.txt")).expect("the corpus reads");
    for (verb, heuristic, why) in [
        (
            "mis_power",
            Heuristic::Power,
            "equal pdfs whose squares overflow (1e154)",
        ),
        (
            "mis_power",
            Heuristic::Power,
            "equal pdfs whose squares underflow",
        ),
        (
            "mis_balance",
            Heuristic::Balance,
            "both the largest double: the sum overflows",
        ),
    ] {
        let v = c.verb(verb).expect("declared");
        let case = c
            .cases_of(verb)
            .find(|k| k.why == why)
            .unwrap_or_else(|| panic!("no case {verb}: {why}"));
        let w = heuristic.weight(case.args[0], case.args[1]);
        let m = accuracy::measure_one(case, 0, v, &Some(vec![w]), Precision::Double);
        assert!(m.ratio <= BOUND, "{}: {w}, {} ulps", case.question, m.ulps);
    }
}
