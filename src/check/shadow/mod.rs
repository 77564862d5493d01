//! The checker of the change of variables from area to solid angle: any routine with the
//! signature of [`crate::transport::shadow::area_to_solid_angle`]
//! (`f(pdf_area, dist, cos_light)`) can be checked against the claims of the chapter
//! *Shadow-ray pdfs* (`chapters/transport/shadow.md`).
//!
//! * `solid_angle`: with points drawn uniformly on a quad light, `E[1 / p_ω] = Ω`, the
//!   quad's solid angle (midpoint rule over the quad, against the closed form), for a
//!   light facing the point and for one facing away;
//! * `area_scale`: `f` is proportional to `pdf_area`;
//! * `distance_scale`: `f` grows with the square of the distance;
//! * `cos_scale`: `f` is inversely proportional to `|cos_light|`: halving the cosine
//!   doubles it (a routine without the cosine is caught here by name, not only through
//!   `solid_angle`);
//! * `positive`: `f` is finite and positive for `cos_light ≠ 0` of either sign;
//! * `edge_on`: a patch seen edge-on (`cos_light = 0`) gives 0, not infinity.
//!
//! Its planted bugs are the warp checker's ([`crate::check::warp::planted::missing_r2`],
//! `missing_cos`, `signed_cos`, `unnormalised`), which the sampler chapters share.

use glam::DVec3;

use super::{Finding, Options, Verdict};
use crate::rng;
use crate::transport::shadow::QuadLight;

/// Default number of random cases of the scaling claims.
pub const CASES: usize = 10_000;
/// Default seed.
pub const SEED: u64 = 0x5ad0;
/// Cells per side of the midpoint rule over the quad.
pub(crate) const GRID: usize = 128;
/// Bound of the solid angle's relative error (the midpoint rule's is below `1e-4`).
pub(crate) const SOLID_ANGLE_BOUND: f64 = 1e-3;
/// Bound of the scaling claims' relative errors, in units of `f64::EPSILON`.
pub(crate) const SCALE_BOUND: f64 = 8.0;

/// Runs the chapter's claims on `f`; `options` sets the number of random cases (default
/// [`CASES`]) and their seed (default [`SEED`]).
pub fn area_to_solid_angle(f: &dyn Fn(f64, f64, f64) -> f64, options: &Options) -> Verdict {
    let cases = options.cases_or(CASES);
    let mut rng = rng::seeded(options.seed_or(SEED));
    let eps = f64::EPSILON;
    let mut solid = Finding::new(
        "solid_angle",
        "E[1 / p_w] over the light's area = its solid angle",
    )
    .in_unit("relative error");
    let lights = [
        (DVec3::new(-0.5, -0.5, 2.0), DVec3::X, DVec3::Y),
        (DVec3::new(-0.5, -0.5, 2.0), DVec3::Y, DVec3::X),
        (
            DVec3::new(1.0, -0.3, 0.5),
            DVec3::new(0.0, 0.8, 0.0),
            DVec3::new(-0.3, 0.0, 1.2),
        ),
    ];
    for (corner, e1, e2) in lights {
        let Ok(light) = QuadLight::new(corner, e1, e2) else {
            continue;
        };
        let (n, area) = (light.normal(), light.area());
        let p = DVec3::ZERO;
        let mut sum = 0.0;
        for i in 0..GRID {
            for j in 0..GRID {
                let (s, t) = (
                    (i as f64 + 0.5) / GRID as f64,
                    (j as f64 + 0.5) / GRID as f64,
                );
                let point = corner + s * e1 + t * e2;
                let to = point - p;
                let dist = to.length();
                let pdf = f(1.0 / area, dist, n.dot(to / dist));
                sum += if pdf > 0.0 { 1.0 / pdf } else { f64::NAN };
            }
        }
        let estimate = sum / (GRID * GRID) as f64;
        let exact = light.solid_angle(p);
        solid.measure((estimate / exact - 1.0).abs(), SOLID_ANGLE_BOUND, || {
            format!(
                "quad at {corner:?} + s {e1:?} + t {e2:?} (normal {n:?}) seen from the origin: E[1/p_w] = {estimate}, solid angle {exact}"
            )
        });
    }
    let mut area_scale = Finding::new("area_scale", "f(2 p_A, d, c) = 2 f(p_A, d, c)")
        .in_unit("relative error in machine epsilons");
    let mut distance_scale = Finding::new("distance_scale", "f(p_A, 2 d, c) = 4 f(p_A, d, c)")
        .in_unit("relative error in machine epsilons");
    let mut cos_scale = Finding::new("cos_scale", "f(p_A, d, c / 2) = 2 f(p_A, d, c)")
        .in_unit("relative error in machine epsilons");
    let mut positive = Finding::new(
        "positive",
        "f is finite and > 0 for cos_light != 0, either sign",
    );
    for _ in 0..cases {
        let a = rng::log_uniform(&mut rng, 1e-3, 1e3);
        let d = rng::log_uniform(&mut rng, 1e-2, 1e2);
        let c = rng::uniform(&mut rng, 0.01, 1.0)
            * if rng::uniform(&mut rng, 0.0, 1.0) < 0.5 {
                -1.0
            } else {
                1.0
            };
        let base = f(a, d, c);
        positive.record(base.is_finite() && base > 0.0, || {
            format!("f({a}, {d}, {c}) = {base}")
        });
        let twice = f(2.0 * a, d, c);
        area_scale.measure(
            (twice / (2.0 * base) - 1.0).abs() / eps,
            SCALE_BOUND,
            || {
                format!(
                    "f({a}, {d}, {c}) = {base}, f({}, {d}, {c}) = {twice}",
                    2.0 * a
                )
            },
        );
        let steeper = f(a, d, 0.5 * c);
        cos_scale.measure(
            (steeper / (2.0 * base) - 1.0).abs() / eps,
            SCALE_BOUND,
            || {
                format!(
                    "f({a}, {d}, {c}) = {base}, f({a}, {d}, {}) = {steeper}: halving cos_light must double it",
                    0.5 * c
                )
            },
        );
        let far = f(a, 2.0 * d, c);
        distance_scale.measure((far / (4.0 * base) - 1.0).abs() / eps, SCALE_BOUND, || {
            format!(
                "f({a}, {d}, {c}) = {base}, f({a}, {}, {c}) = {far}",
                2.0 * d
            )
        });
    }
    let mut edge_on = Finding::new("edge_on", "cos_light = 0 gives 0 (the sample is skipped)");
    for c in [0.0, -0.0] {
        let got = f(0.5, 2.0, c);
        edge_on.record(got == 0.0, || format!("f(0.5, 2, {c}) = {got}"));
    }
    let mut verdict = Verdict::new("area to solid angle");
    verdict.findings.extend([
        solid,
        area_scale,
        distance_scale,
        cos_scale,
        positive,
        edge_on,
    ]);
    verdict
}
