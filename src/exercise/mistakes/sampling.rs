//! The typical mistakes and correct alternatives of the exercises of the book's sampling
//! and geometry chapters and of *Reflection and refraction* (see [`super`]).

use glam::{DVec2, DVec3};

use super::{Alternative, Mistake, Source, Table};
use crate::check::importance::planted as importance_planted;
use crate::check::sphere::planted as sphere_planted;
use crate::check::tabulated::planted as tabulated_planted;
use crate::check::warp::planted as warp_planted;
use crate::exercise::registry::{
    EstimateFn, cosine_malley_checks, cosine_pdf_checks, disc_concentric_checks, disc_polar_checks,
    estimate_checks, hemisphere_flip_checks, intersect_stable_checks,
    piecewise_linear1d_sample_checks, piecewise1d_sample_checks, sphere_rejection_checks,
};
use crate::geometry::{Ray, Sphere};
use crate::sampling::tabulated::{Piecewise1D, PiecewiseLinear1D, Sample};
use crate::sampling::{cosine, disc, importance, sphere};

/// This part's tables, in the book's order.
pub const TABLES: &[Table] = &[
    INTERSECT_STABLE,
    ESTIMATE,
    SPHERE_REJECTION,
    HEMISPHERE_FLIP,
    DISC_POLAR,
    DISC_CONCENTRIC,
    COSINE_MALLEY,
    COSINE_PDF,
    PIECEWISE_SAMPLE,
    PIECEWISE_LINEAR_SAMPLE,
];

/// `intersect_stable`: twins of the `f64` routine (the `f32` one its checks also judge stays
/// the crate's).
const INTERSECT_STABLE: Table = Table {
    exercise: "intersect_stable",
    probe: || ray_probe(crate::geometry::sphere::intersect_stable),
    mistakes: &[
        Mistake {
            words: "t > 0: the source notes' first root \"greater than 0\", t_min ignored (a ray leaving a surface hits it again)",
            source: Source::Errata,
            check: || intersect_stable_checks(intersect::t_greater_than_zero),
            probe: || ray_probe(intersect::t_greater_than_zero),
        },
        Mistake {
            words: "every root counts, behind the origin too: a ray starting inside returns the root behind it",
            source: Source::Branch,
            check: || intersect_stable_checks(intersect::ignoring_t_min),
            probe: || ray_probe(intersect::ignoring_t_min),
        },
        Mistake {
            words: "always the far root (-b + sqrt(b^2 - ac)) / a: the exit, not the entry",
            source: Source::Branch,
            check: || intersect_stable_checks(sphere_planted::always_far_root),
            probe: || ray_probe(sphere_planted::always_far_root),
        },
        Mistake {
            words: "a = D.D taken as 1: right only for a unit direction",
            source: Source::Factor,
            check: || intersect_stable_checks(sphere_planted::assuming_unit_direction),
            probe: || ray_probe(sphere_planted::assuming_unit_direction),
        },
        Mistake {
            words: "near misses counted as hits: a discriminant down to -1 % of a r^2 accepted",
            source: Source::Branch,
            check: || intersect_stable_checks(sphere_planted::loose_discriminant),
            probe: || ray_probe(sphere_planted::loose_discriminant),
        },
        Mistake {
            words: "c = f.f - r: the radius where its square belongs",
            source: Source::Power,
            check: || intersect_stable_checks(intersect::radius_not_squared),
            probe: || ray_probe(intersect::radius_not_squared),
        },
        Mistake {
            words: "f = C - O: centre and origin swapped, so the roots come out negated (the sphere found behind the ray)",
            source: Source::Swapped,
            check: || intersect_stable_checks(intersect::centre_minus_origin),
            probe: || ray_probe(intersect::centre_minus_origin),
        },
    ],
    alternatives: &[
        Alternative {
            words: "q by an explicit if on the sign of b, and the root chosen by explicit comparisons",
            check: || intersect_stable_checks(intersect::explicit_sign),
        },
        Alternative {
            words: "the roots ordered by min and max, the far root q / a computed first",
            check: || intersect_stable_checks(intersect::min_max),
        },
    ],
};

/// `estimate`.
const ESTIMATE: Table = Table {
    exercise: "estimate",
    probe: || estimate_probe(|f, q, n, rng| importance::estimate(f, q, n, rng)),
    mistakes: &[
        Mistake {
            words: "the mean of f(X): the division by the density q(X) left out",
            source: Source::Factor,
            check: || estimate_checks(importance_planted::forgets_the_density),
            probe: || estimate_probe(importance_planted::forgets_the_density),
        },
        Mistake {
            words: "f(X) / q(U): the density taken at the uniform number U, not at the sample X",
            source: Source::Swapped,
            check: || estimate_checks(importance_planted::density_of_u),
            probe: || estimate_probe(importance_planted::density_of_u),
        },
        Mistake {
            words: "f(X) q(X): multiplied by the density where dividing belongs",
            source: Source::Power,
            check: || estimate_checks(estimator::times_density),
            probe: || estimate_probe(estimator::times_density),
        },
        Mistake {
            words: "f(X) / q(X) with no case for q(X) = 0: an infinite (or NaN) term there",
            source: Source::Branch,
            check: || estimate_checks(estimator::unguarded),
            probe: || estimate_probe(estimator::unguarded),
        },
        Mistake {
            words: "a draw where q(X) = 0 skipped instead of adding 0: fewer than n terms, a biased mean",
            source: Source::Branch,
            check: || estimate_checks(importance_planted::skips_zero_density),
            probe: || estimate_probe(importance_planted::skips_zero_density),
        },
        Mistake {
            words: "X = U drawn uniformly, yet weighted by 1 / q(X): the draws not taken from q",
            source: Source::Chapter,
            check: || estimate_checks(estimator::uniform_draws),
            probe: || estimate_probe(estimator::uniform_draws),
        },
        Mistake {
            words: "n + 1 terms (a loop over 0..=n)",
            source: Source::Branch,
            check: || estimate_checks(estimator::one_more_term),
            probe: || estimate_probe(estimator::one_more_term),
        },
    ],
    alternatives: &[
        Alternative {
            words: "Summary::of over an iterator, with an explicit if for q(X) = 0",
            check: || estimate_checks(estimator::by_iterator),
        },
        Alternative {
            words: "f(X) times the reciprocal of q(X), the zero case by match",
            check: || estimate_checks(estimator::by_reciprocal),
        },
    ],
};

/// `sphere_rejection`.
const SPHERE_REJECTION: Table = Table {
    exercise: "sphere_rejection",
    probe: || rejection_probe(sphere::sphere_rejection),
    mistakes: &[
        Mistake {
            words: "the point of the ball returned without normalising it",
            source: Source::Chapter,
            check: || sphere_rejection_checks(rejection::not_normalised),
            probe: || rejection_probe(rejection::not_normalised),
        },
        Mistake {
            words: "no rejection: every point of the cube normalised, so the corners' directions crowd",
            source: Source::Branch,
            check: || sphere_rejection_checks(rejection::no_rejection),
            probe: || rejection_probe(rejection::no_rejection),
        },
        Mistake {
            words: "coordinate = -1 + u: the factor 2 left out, the cube [-1, 0)^3 (one octant)",
            source: Source::Factor,
            check: || sphere_rejection_checks(rejection::without_factor_two),
            probe: || rejection_probe(rejection::without_factor_two),
        },
        Mistake {
            words: "coordinate = u: [0, 1)^3 where [-1, 1)^3 belongs (one octant)",
            source: Source::Constant,
            check: || sphere_rejection_checks(rejection::unit_cube),
            probe: || rejection_probe(rejection::unit_cube),
        },
        Mistake {
            words: "the draws counted without the accepted one (only the rejections)",
            source: Source::Branch,
            check: || sphere_rejection_checks(rejection::rejections_only),
            probe: || rejection_probe(rejection::rejections_only),
        },
    ],
    alternatives: &[
        Alternative {
            words: "a for loop over the draw number, the point as 2 v - 1 and divided by its length",
            check: || sphere_rejection_checks(rejection::for_loop),
        },
        Alternative {
            words: "rejection against |v| <= 1 (the length, not its square), by while",
            check: || sphere_rejection_checks(rejection::by_length),
        },
    ],
};

/// `hemisphere_flip`.
const HEMISPHERE_FLIP: Table = Table {
    exercise: "hemisphere_flip",
    probe: || flip_probe(sphere::hemisphere_flip),
    mistakes: &[
        Mistake {
            words: "w returned as it is: the flip left out (the whole sphere)",
            source: Source::Branch,
            check: || hemisphere_flip_checks(flip::no_flip),
            probe: || flip_probe(flip::no_flip),
        },
        Mistake {
            words: "flipped when w . n > 0: every direction sent to the wrong side",
            source: Source::Branch,
            check: || hemisphere_flip_checks(flip::wrong_side),
            probe: || flip_probe(flip::wrong_side),
        },
        Mistake {
            words: "(w.x, w.y, |w.z|): the side tested on z, right only for n = +z",
            source: Source::Chapter,
            check: || hemisphere_flip_checks(flip::z_only),
            probe: || flip_probe(flip::z_only),
        },
        Mistake {
            words: "n flipped to w's side: w and n swapped",
            source: Source::Swapped,
            check: || hemisphere_flip_checks(flip::swapped),
            probe: || flip_probe(flip::swapped),
        },
        Mistake {
            words: "w - (w . n) n below: the factor 2 of the reflection left out (a projection, not a unit vector)",
            source: Source::Factor,
            check: || hemisphere_flip_checks(flip::projected),
            probe: || flip_probe(flip::projected),
        },
    ],
    alternatives: &[
        Alternative {
            words: "reflected about the tangent plane, w - 2 (w . n) n, instead of negated",
            check: || hemisphere_flip_checks(flip::reflected),
        },
        Alternative {
            words: "w times the sign of w . n",
            check: || hemisphere_flip_checks(flip::by_signum),
        },
    ],
};

const DISC_POLAR: Table = Table {
    exercise: "disc_polar",
    probe: || square_probe(disc::disc_polar),
    mistakes: &[
        Mistake {
            words: "r = u1: the radius without its square root (the radial CDF r^2 forgotten)",
            source: Source::Chapter,
            check: || disc_polar_checks(polar::r_equals_u1),
            probe: || square_probe(polar::r_equals_u1),
        },
        Mistake {
            words: "phi = pi u2: half the turn (pi where 2 pi belongs)",
            source: Source::Constant,
            check: || disc_polar_checks(polar::half_turn),
            probe: || square_probe(polar::half_turn),
        },
        Mistake {
            words: "r = u1^2: the radius squared where its square root belongs",
            source: Source::Power,
            check: || disc_polar_checks(polar::r_squared),
            probe: || square_probe(polar::r_squared),
        },
        Mistake {
            words: "r = sqrt(u2), phi = 2 pi u1: u1 and u2 swapped",
            source: Source::Swapped,
            check: || disc_polar_checks(polar::swapped),
            probe: || square_probe(polar::swapped),
        },
        Mistake {
            words: "(r cos phi, sin phi): the radius left off y",
            source: Source::Factor,
            check: || disc_polar_checks(polar::y_without_r),
            probe: || square_probe(polar::y_without_r),
        },
        Mistake {
            words: "(r sin phi, r cos phi): sine and cosine swapped, a uniform disc but not the polar map (phi runs clockwise from the y axis, so the map's inverse is not the chapter's)",
            source: Source::Swapped,
            check: || disc_polar_checks(polar::sin_cos_swapped),
            probe: || square_probe(polar::sin_cos_swapped),
        },
    ],
    alternatives: &[
        Alternative {
            words: "sin_cos of phi, then the radius times each",
            check: || disc_polar_checks(polar::with_sin_cos),
        },
        Alternative {
            words: "the point (cos phi, sin phi) scaled by sqrt(u1) as a vector",
            check: || disc_polar_checks(polar::scaled_unit_vector),
        },
    ],
};

/// `disc_concentric`.
const DISC_CONCENTRIC: Table = Table {
    exercise: "disc_concentric",
    probe: || square_probe(disc::disc_concentric),
    mistakes: &[
        Mistake {
            words: "phi = (pi/2) a.y / a.x in the first wedge: pi/2 where pi/4 belongs (the disc folded over itself)",
            source: Source::Constant,
            check: || disc_concentric_checks(concentric::wrong_wedge),
            probe: || square_probe(concentric::wrong_wedge),
        },
        Mistake {
            words: "(a.y cos psi, a.y sin psi) in the second wedge: psi where pi/2 - psi belongs",
            source: Source::Chapter,
            check: || disc_concentric_checks(concentric::second_wedge_unturned),
            probe: || square_probe(concentric::second_wedge_unturned),
        },
        Mistake {
            words: "a = u: the square not mapped to [-1, 1]^2 (2u - 1 left out)",
            source: Source::Factor,
            check: || disc_concentric_checks(concentric::unshifted),
            probe: || square_probe(concentric::unshifted),
        },
        Mistake {
            words: "r = sqrt(|a|): the polar map's square root taken over",
            source: Source::Power,
            check: || disc_concentric_checks(concentric::rooted_radius),
            probe: || square_probe(concentric::rooted_radius),
        },
        Mistake {
            words: "|a.y| > |a.x| for the first wedge: each wedge's formula used in the other",
            source: Source::Branch,
            check: || disc_concentric_checks(concentric::wedges_swapped),
            probe: || square_probe(concentric::wedges_swapped),
        },
        Mistake {
            words: "u1 and u2 swapped: a uniform disc, but the map mirrored about the diagonal (its inverse is not the chapter's)",
            source: Source::Swapped,
            check: || disc_concentric_checks(concentric::swapped),
            probe: || square_probe(concentric::swapped),
        },
        Mistake {
            words: "no case for the centre a = 0: psi = 0 / 0, a NaN point at u = (1/2, 1/2)",
            source: Source::Branch,
            check: || disc_concentric_checks(concentric::unguarded),
            probe: || square_probe(concentric::unguarded),
        },
    ],
    alternatives: &[
        Alternative {
            words: "the paper's four regions, each with its own r and phi",
            check: || disc_concentric_checks(concentric::four_regions),
        },
        Alternative {
            words: "the second wedge's angle written pi/2 - psi, with the library's sin_cos",
            check: || disc_concentric_checks(concentric::explicit_angle),
        },
    ],
};

/// `cosine_malley`.
const COSINE_MALLEY: Table = Table {
    exercise: "cosine_malley",
    probe: || square_probe(cosine::cosine_malley),
    mistakes: &[
        Mistake {
            words: "a uniform hemisphere direction: the cosine weighting left out",
            source: Source::Chapter,
            check: || cosine_malley_checks(malley::uniform_hemisphere),
            probe: || square_probe(malley::uniform_hemisphere),
        },
        Mistake {
            words: "z = 1 - r^2: the lift without its square root",
            source: Source::Power,
            check: || cosine_malley_checks(malley::lift_without_root),
            probe: || square_probe(malley::lift_without_root),
        },
        Mistake {
            words: "1 - r = 2 min(u1, u2): the distance to the rim without the sides 1 - u1, 1 - u2",
            source: Source::Branch,
            check: || cosine_malley_checks(malley::two_sides),
            probe: || square_probe(malley::two_sides),
        },
        Mistake {
            words: "1 - r = min(u1, 1 - u1, u2, 1 - u2): the distance to the rim without its 2",
            source: Source::Constant,
            check: || cosine_malley_checks(malley::half_distance),
            probe: || square_probe(malley::half_distance),
        },
        Mistake {
            words: "z = sqrt(1 - r): the factor 1 + r of 1 - r^2 left out",
            source: Source::Factor,
            check: || cosine_malley_checks(malley::without_one_plus_r),
            probe: || square_probe(malley::without_one_plus_r),
        },
    ],
    alternatives: &[
        Alternative {
            words: "Malley's method on the polar map, where 1 - r^2 = 1 - u1 exactly",
            check: || cosine_malley_checks(malley::on_polar),
        },
        Alternative {
            words: "z = sqrt(1 - r) sqrt(1 + r), r the concentric radius max(|2u1 - 1|, |2u2 - 1|)",
            check: || cosine_malley_checks(malley::two_roots),
        },
    ],
};

/// `cosine_pdf`.
const COSINE_PDF: Table = Table {
    exercise: "cosine_pdf",
    probe: || direction_probe(cosine::cosine_pdf),
    mistakes: &[
        Mistake {
            words: "cos theta: the 1 / pi left out",
            source: Source::Factor,
            check: || cosine_pdf_checks(warp_planted::cosine_pdf_without_1_over_pi),
            probe: || direction_probe(warp_planted::cosine_pdf_without_1_over_pi),
        },
        Mistake {
            words: "cos theta / (2 pi): 2 pi where pi belongs",
            source: Source::Constant,
            check: || cosine_pdf_checks(density::two_pi),
            probe: || direction_probe(density::two_pi),
        },
        Mistake {
            words: "cos^2 theta / pi: the cosine squared",
            source: Source::Power,
            check: || cosine_pdf_checks(density::squared),
            probe: || direction_probe(density::squared),
        },
        Mistake {
            words: "|cos theta| / pi: the lower hemisphere given a density too",
            source: Source::Branch,
            check: || cosine_pdf_checks(density::absolute),
            probe: || direction_probe(density::absolute),
        },
        Mistake {
            words: "sin theta cos theta / pi: the density per d theta d phi, not per steradian",
            source: Source::Chapter,
            check: || cosine_pdf_checks(density::per_angles),
            probe: || direction_probe(density::per_angles),
        },
    ],
    alternatives: &[
        Alternative {
            words: "an explicit if on z > 0, divided by pi",
            check: || cosine_pdf_checks(density::explicit_if),
        },
        Alternative {
            words: "(z + |z|) / (2 pi)",
            check: || cosine_pdf_checks(density::half_sum),
        },
    ],
};

/// `Piecewise1D::sample`.
const PIECEWISE_SAMPLE: Table = Table {
    exercise: "Piecewise1D::sample",
    probe: || table_probe(Piecewise1D::sample),
    mistakes: &[
        Mistake {
            words: "the textbook search, the first bin with cdf[i + 1] >= u: at a plateau's level it lands in the bin of zero mass before it",
            source: Source::Errata,
            check: || piecewise1d_sample_checks(tabulated_planted::first_bin_reaching_u),
            probe: || table_probe(tabulated_planted::first_bin_reaching_u),
        },
        Mistake {
            words: "bin floor(u n): every bin given the same mass",
            source: Source::Branch,
            check: || piecewise1d_sample_checks(tabulated_planted::equal_bins),
            probe: || table_probe(tabulated_planted::equal_bins),
        },
        Mistake {
            words: "pdf = the bin's probability v_i w_i / I: the bin width not divided out",
            source: Source::Chapter,
            check: || piecewise1d_sample_checks(constant::probability_as_pdf),
            probe: || table_probe(constant::probability_as_pdf),
        },
        Mistake {
            words: "x = x_i + u (x_i+1 - x_i): the position within the bin from u itself, (u - c_i) / (c_i+1 - c_i) left out",
            source: Source::Factor,
            check: || piecewise1d_sample_checks(constant::position_from_u),
            probe: || table_probe(constant::position_from_u),
        },
        Mistake {
            words: "t = (c_i+1 - u) / (c_i+1 - c_i): c_i and c_i+1 swapped, each bin run backwards",
            source: Source::Swapped,
            check: || piecewise1d_sample_checks(constant::reversed_in_bin),
            probe: || table_probe(constant::reversed_in_bin),
        },
    ],
    alternatives: &[
        Alternative {
            words: "the bin by partition_point on the CDF, the density from the table's pdf",
            check: || piecewise1d_sample_checks(constant::by_partition_point),
        },
        Alternative {
            words: "the bin by a linear scan for the first c_i+1 > u",
            check: || piecewise1d_sample_checks(constant::by_scan),
        },
    ],
};

/// `PiecewiseLinear1D::sample`.
const PIECEWISE_LINEAR_SAMPLE: Table = Table {
    exercise: "PiecewiseLinear1D::sample",
    probe: || linear_table_probe(PiecewiseLinear1D::sample),
    mistakes: &[
        Mistake {
            words: "uniform within the segment: the quadratic's inverse left out (the table sampled as piecewise constant)",
            source: Source::Chapter,
            check: || piecewise_linear1d_sample_checks(linear::uniform_within),
            probe: || linear_table_probe(linear::uniform_within),
        },
        Mistake {
            words: "t = sqrt(s): the inverse of a ramp from 0, right only when a = 0",
            source: Source::Power,
            check: || piecewise_linear1d_sample_checks(linear::ramp_root),
            probe: || linear_table_probe(linear::ramp_root),
        },
        Mistake {
            words: "segment_inverse(b, a, s): the segment's two end densities swapped",
            source: Source::Swapped,
            check: || piecewise_linear1d_sample_checks(linear::ends_swapped),
            probe: || linear_table_probe(linear::ends_swapped),
        },
        Mistake {
            words: "no step away from a zero-valued end: x at a knot of density 0 (pdf 0)",
            source: Source::Branch,
            check: || piecewise_linear1d_sample_checks(linear::no_step),
            probe: || linear_table_probe(linear::no_step),
        },
        Mistake {
            words: "pdf = the segment's mean density (its probability over its width): the slope left out",
            source: Source::Factor,
            check: || piecewise_linear1d_sample_checks(linear::mean_density),
            probe: || linear_table_probe(linear::mean_density),
        },
    ],
    alternatives: &[Alternative {
        words: "the segment by partition_point, the quadratic solved in the form s (a + b) / (a + sqrt(a^2 + s (b^2 - a^2)))",
        check: || piecewise_linear1d_sample_checks(linear::by_partition_point),
    }],
};

/// Probe inputs on the unit square: a 7 x 7 grid inside it and its four corners; the
/// outputs are every coordinate of every point, in order.
fn square_probe(f: fn(DVec2) -> DVec3) -> Vec<f64> {
    let grid = (1..=7).flat_map(|i| (1..=7).map(move |j| DVec2::new(i as f64, j as f64) / 8.0));
    let corners = [DVec2::ZERO, DVec2::X, DVec2::Y, DVec2::ONE];
    grid.chain(corners).flat_map(|u| f(u).to_array()).collect()
}

/// Probe inputs of a ray-sphere intersector: rays from outside, inside and beyond, with
/// unit and non-unit directions, a near miss and `t_min` above the first root; the outputs
/// are the `t` returned, NaN for a miss.
fn ray_probe(f: fn(&Ray, &Sphere, f64) -> Option<f64>) -> Vec<f64> {
    let unit = Sphere::new(DVec3::ZERO, 1.0);
    let big = Sphere::new(DVec3::new(1.0, 2.0, 3.0), 2.0);
    let below = DVec3::new(0.0, 0.0, -3.0);
    let cases = [
        (Ray::new(below, DVec3::Z), unit, 0.0),
        (Ray::new(below, DVec3::Z), unit, 2.5),
        (Ray::new(below, DVec3::Z), unit, 5.0),
        (Ray::new(DVec3::ZERO, DVec3::Z), unit, 0.0),
        (Ray::new(below, 2.0 * DVec3::Z), unit, 0.0),
        (Ray::new(DVec3::new(0.5, 0.0, -3.0), DVec3::Z), unit, 1e-3),
        (Ray::new(DVec3::new(1.001, 0.0, -3.0), DVec3::Z), unit, 1e-3),
        (
            Ray::new(DVec3::new(1.0, 2.0, -5.0), DVec3::new(0.0, 0.0, 0.5)),
            big,
            0.0,
        ),
        (
            Ray::new(DVec3::new(-4.0, 2.5, 3.0), DVec3::new(3.0, 0.0, 0.0)),
            big,
            1e-3,
        ),
    ];
    cases
        .iter()
        .map(|(ray, sphere, t_min)| f(ray, sphere, *t_min).unwrap_or(f64::NAN))
        .collect()
}

/// Probe inputs of an importance-sampling estimator, drawn from a fixed seed: `x^2` under
/// the uniform and matched proposals, `1 + x` under the linear one, and `x^2` under uniform
/// draws whose density is 0 above 1/2; the outputs are each summary's count, mean and
/// variance.
fn estimate_probe(f: EstimateFn) -> Vec<f64> {
    let mut rng = crate::rng::seeded(0x9b0e);
    let plus_one = |x: f64| 1.0 + x;
    let wrong_half = importance::Proposal {
        name: "uniform draws, density 0 above 1/2",
        sample: |u| u,
        pdf: importance::HALF_SUPPORT.pdf,
    };
    type Case<'a> = (&'a dyn Fn(f64) -> f64, importance::Proposal, usize); // f, q, n
    let cases: [Case; 4] = [
        (&importance::square, importance::UNIFORM, 8),
        (&plus_one, importance::LINEAR, 8),
        (&importance::square, importance::MATCHED, 4),
        (&importance::square, wrong_half, 8),
    ];
    cases
        .iter()
        .flat_map(|&(g, q, n)| {
            let s = f(g, &q, n, &mut rng);
            [s.n as f64, s.mean, s.variance()]
        })
        .collect()
}

/// Probe outputs of a rejection sampler: 16 directions from a fixed seed, each with the
/// number of draws it reports.
fn rejection_probe(f: fn(&mut crate::rng::Rng) -> (DVec3, u32)) -> Vec<f64> {
    let mut rng = crate::rng::seeded(0x5eed_ba11);
    (0..16)
        .flat_map(|_| {
            let (w, tries) = f(&mut rng);
            [w.x, w.y, w.z, f64::from(tries)]
        })
        .collect()
}

/// Fixed directions over the whole sphere: the uniform map of a 6 x 6 grid of cell centres.
fn sphere_grid() -> impl Iterator<Item = DVec3> {
    (0..6)
        .flat_map(|i| (0..6).map(move |j| DVec2::new(i as f64, j as f64) / 6.0 + 1.0 / 12.0))
        .map(sphere::sphere_inverse_cdf)
}

/// Probe inputs of a hemisphere flip: the directions of [`sphere_grid`] around `+z`, a
/// tilted normal and `-x`; the outputs are every coordinate of every result.
fn flip_probe(f: fn(DVec3, DVec3) -> DVec3) -> Vec<f64> {
    let normals = [DVec3::Z, DVec3::new(0.3, -0.5, 0.8).normalize(), -DVec3::X];
    normals
        .into_iter()
        .flat_map(|n| sphere_grid().flat_map(move |w| f(w, n).to_array()))
        .collect()
}

/// Probe inputs of a density on the sphere: the directions of [`sphere_grid`], both
/// hemispheres.
fn direction_probe(f: fn(DVec3) -> f64) -> Vec<f64> {
    sphere_grid().map(f).collect()
}

/// The probe values of `u` for a table whose CDF at the edges is `levels`: twenty evenly
/// spaced in `[0, 1)`, every level (where the textbook search lands in bins of zero mass),
/// and `u` just below 1.
fn table_us(levels: &[f64]) -> Vec<f64> {
    let below_one = 1.0 - f64::EPSILON / 2.0;
    (0..20)
        .map(|k| f64::from(k) / 20.0)
        .chain(levels.iter().copied())
        .chain([below_one])
        .map(|u: f64| u.min(below_one))
        .collect()
}

/// A tabulated sample's outputs: `x`, `pdf`, `bin`, and 1 if the density is positive, else
/// 0 (a sampler left at a zero-valued end differs from the right one by a float's step in
/// `x` and a density of about `1e-16`, both within [`super::same_outputs`]'s tolerance: only
/// the density's sign tells them apart).
fn sample_outputs(s: Sample) -> [f64; 4] {
    [s.x, s.pdf, s.bin as f64, f64::from(u8::from(s.pdf > 0.0))]
}

/// Probe inputs of a piecewise-constant sampler: the checker's three tables at
/// [`table_us`]; the outputs are each sample's [`sample_outputs`].
fn table_probe(f: fn(&Piecewise1D, f64) -> Sample) -> Vec<f64> {
    let tables = crate::check::tabulated::tables();
    tables
        .iter()
        .flat_map(|(_, t)| {
            table_us(t.cdf_table())
                .into_iter()
                .flat_map(move |u| sample_outputs(f(t, u)))
        })
        .collect()
}

/// The same for a piecewise-linear sampler, on the checker's three linear tables.
fn linear_table_probe(f: fn(&PiecewiseLinear1D, f64) -> Sample) -> Vec<f64> {
    let tables = crate::check::tabulated::linear_tables();
    tables
        .iter()
        .flat_map(|(_, t)| {
            table_us(t.cdf_table())
                .into_iter()
                .flat_map(move |u| sample_outputs(f(t, u)))
        })
        .collect()
}

/// Twins and alternatives of `intersect_stable` (`f64`).
mod intersect {
    use crate::geometry::sphere::nearest_root_above;
    use crate::geometry::{Ray, Sphere};

    pub fn t_greater_than_zero(ray: &Ray, sphere: &Sphere, _t_min: f64) -> Option<f64> {
        explicit_sign(ray, sphere, 0.0)
    }

    pub fn ignoring_t_min(ray: &Ray, sphere: &Sphere, _t_min: f64) -> Option<f64> {
        explicit_sign(ray, sphere, f64::NEG_INFINITY)
    }

    /// `c = f.f - r`: the correct routine on the sphere of radius `sqrt(r)`, which it squares.
    pub fn radius_not_squared(ray: &Ray, sphere: &Sphere, t_min: f64) -> Option<f64> {
        explicit_sign(
            ray,
            &Sphere::new(sphere.center, sphere.radius.sqrt()),
            t_min,
        )
    }

    /// `f = C - O`: the correct routine from the origin `2C - O`, whose `O - C` is `C - O`.
    pub fn centre_minus_origin(ray: &Ray, sphere: &Sphere, t_min: f64) -> Option<f64> {
        let mirrored = Ray::new(2.0 * sphere.center - ray.origin, ray.dir);
        explicit_sign(&mirrored, sphere, t_min)
    }

    pub fn explicit_sign(ray: &Ray, sphere: &Sphere, t_min: f64) -> Option<f64> {
        let f = ray.origin - sphere.center;
        let a = ray.dir.length_squared();
        let b = -ray.dir.dot(f);
        let r2 = sphere.radius.powi(2);
        let closest = f + (b / a) * ray.dir;
        let delta = r2 - closest.length_squared();
        if delta < 0.0 || delta.is_nan() {
            return None;
        }
        let root = (a * delta).sqrt();
        let q = if b < 0.0 { b - root } else { b + root };
        let c = f.length_squared() - r2;
        let (by_vieta, by_q) = (c / q, q / a);
        let near = if by_vieta < by_q { by_vieta } else { by_q };
        let far = if by_vieta < by_q { by_q } else { by_vieta };
        if near > t_min {
            Some(near)
        } else if far > t_min {
            Some(far)
        } else {
            None
        }
    }

    pub fn min_max(ray: &Ray, sphere: &Sphere, t_min: f64) -> Option<f64> {
        let f = ray.origin - sphere.center;
        let a = ray.dir.dot(ray.dir);
        let half_b = ray.dir.dot(f);
        let r2 = sphere.radius.powi(2);
        let l = f - ray.dir * (half_b / a);
        let delta = r2 - l.length_squared();
        if delta < 0.0 || delta.is_nan() {
            return None;
        }
        let q = -(half_b + (a * delta).sqrt().copysign(half_b));
        let by_q = q / a;
        let by_vieta = (f.dot(f) - r2) / q;
        nearest_root_above(by_q.min(by_vieta), by_q.max(by_vieta), t_min)
    }
}

/// Twins and alternatives of `estimate`.
mod estimator {
    use crate::rng::{self, Rng};
    use crate::sampling::importance::Proposal;
    use crate::stats::ttest::Summary;

    /// `n` terms `term(f, q, X)` of draws `X ~ q`.
    fn terms(
        f: &dyn Fn(f64) -> f64,
        q: &Proposal,
        n: usize,
        r: &mut Rng,
        term: fn(&dyn Fn(f64) -> f64, &Proposal, f64) -> f64,
    ) -> Summary {
        Summary::of((0..n).map(|_| term(f, q, (q.sample)(rng::uniform(r, 0.0, 1.0)))))
    }

    pub fn times_density(f: &dyn Fn(f64) -> f64, q: &Proposal, n: usize, r: &mut Rng) -> Summary {
        terms(f, q, n, r, |f, q, x| f(x) * (q.pdf)(x))
    }

    pub fn unguarded(f: &dyn Fn(f64) -> f64, q: &Proposal, n: usize, r: &mut Rng) -> Summary {
        terms(f, q, n, r, |f, q, x| f(x) / (q.pdf)(x))
    }

    pub fn uniform_draws(f: &dyn Fn(f64) -> f64, q: &Proposal, n: usize, r: &mut Rng) -> Summary {
        Summary::of((0..n).map(|_| {
            let x = rng::uniform(r, 0.0, 1.0);
            let q_x = (q.pdf)(x);
            if q_x > 0.0 { f(x) / q_x } else { 0.0 }
        }))
    }

    pub fn one_more_term(f: &dyn Fn(f64) -> f64, q: &Proposal, n: usize, r: &mut Rng) -> Summary {
        terms(f, q, n + 1, r, |f, q, x| {
            let q_x = (q.pdf)(x);
            if q_x > 0.0 { f(x) / q_x } else { 0.0 }
        })
    }

    pub fn by_iterator(f: &dyn Fn(f64) -> f64, q: &Proposal, n: usize, r: &mut Rng) -> Summary {
        Summary::of((0..n).map(|_| {
            let x = (q.sample)(rng::uniform(r, 0.0, 1.0));
            let q_x = (q.pdf)(x);
            if q_x == 0.0 { 0.0 } else { f(x) / q_x }
        }))
    }

    pub fn by_reciprocal(f: &dyn Fn(f64) -> f64, q: &Proposal, n: usize, r: &mut Rng) -> Summary {
        let mut summary = Summary::default();
        for _ in 0..n {
            let x = (q.sample)(rng::uniform(r, 0.0, 1.0));
            summary.push(match (q.pdf)(x) {
                density if density > 0.0 => f(x) * density.recip(),
                _ => 0.0,
            });
        }
        summary
    }
}

/// Twins and alternatives of `sphere_rejection`.
mod rejection {
    use glam::DVec3;

    use crate::rng::{self, Rng};

    /// A uniform point of the cube `[lo, hi)^3`.
    fn draw(rng: &mut Rng, lo: f64, hi: f64) -> DVec3 {
        let x = rng::uniform(rng, lo, hi);
        let y = rng::uniform(rng, lo, hi);
        DVec3::new(x, y, rng::uniform(rng, lo, hi))
    }

    /// Rejection from the cube `[lo, hi)^3` against the unit ball, normalised or not.
    fn rejecting(rng: &mut Rng, lo: f64, hi: f64, normalise: bool) -> (DVec3, u32) {
        let mut tries = 0;
        loop {
            tries += 1;
            let v = draw(rng, lo, hi);
            if v != DVec3::ZERO && v.length_squared() <= 1.0 {
                return (if normalise { v.normalize() } else { v }, tries);
            }
        }
    }

    pub fn not_normalised(rng: &mut Rng) -> (DVec3, u32) {
        rejecting(rng, -1.0, 1.0, false)
    }

    pub fn no_rejection(rng: &mut Rng) -> (DVec3, u32) {
        (draw(rng, -1.0, 1.0).normalize(), 1)
    }

    pub fn without_factor_two(rng: &mut Rng) -> (DVec3, u32) {
        rejecting(rng, -1.0, 0.0, true)
    }

    pub fn unit_cube(rng: &mut Rng) -> (DVec3, u32) {
        rejecting(rng, 0.0, 1.0, true)
    }

    pub fn rejections_only(rng: &mut Rng) -> (DVec3, u32) {
        let (w, tries) = rejecting(rng, -1.0, 1.0, true);
        (w, tries - 1)
    }

    pub fn for_loop(rng: &mut Rng) -> (DVec3, u32) {
        for tries in 1u32.. {
            let v = 2.0 * draw(rng, 0.0, 1.0) - DVec3::ONE;
            let length = v.length();
            if length <= 1.0 && length > 0.0 {
                return (v / length, tries);
            }
        }
        unreachable!("more than u32::MAX draws")
    }

    pub fn by_length(rng: &mut Rng) -> (DVec3, u32) {
        let mut tries = 1;
        let mut v = draw(rng, -1.0, 1.0);
        while v.length() > 1.0 || v == DVec3::ZERO {
            v = draw(rng, -1.0, 1.0);
            tries += 1;
        }
        (v.normalize(), tries)
    }
}

/// Twins and alternatives of `hemisphere_flip`.
mod flip {
    use glam::DVec3;

    pub fn no_flip(w: DVec3, _n: DVec3) -> DVec3 {
        w
    }

    pub fn wrong_side(w: DVec3, n: DVec3) -> DVec3 {
        if w.dot(n) > 0.0 { -w } else { w }
    }

    pub fn z_only(w: DVec3, _n: DVec3) -> DVec3 {
        DVec3::new(w.x, w.y, w.z.abs())
    }

    pub fn swapped(w: DVec3, n: DVec3) -> DVec3 {
        if n.dot(w) < 0.0 { -n } else { n }
    }

    pub fn projected(w: DVec3, n: DVec3) -> DVec3 {
        let c = w.dot(n);
        if c < 0.0 { w - c * n } else { w }
    }

    pub fn reflected(w: DVec3, n: DVec3) -> DVec3 {
        let c = w.dot(n);
        if c < 0.0 { w - 2.0 * c * n } else { w }
    }

    pub fn by_signum(w: DVec3, n: DVec3) -> DVec3 {
        w * w.dot(n).signum()
    }
}

/// Twins and alternatives of `disc_concentric`.
mod concentric {
    use glam::{DVec2, DVec3};
    use std::f64::consts::{FRAC_PI_2, FRAC_PI_4};

    /// The two-wedge map of the point `a` of `[-1, 1]^2`, with the library's trigonometry
    /// (the twins of this and of `cosine_malley` call no exercise's function: in a hand-out
    /// that is the student's).
    pub fn map(a: DVec2) -> DVec3 {
        if a == DVec2::ZERO {
            return DVec3::ZERO;
        }
        if a.x.abs() > a.y.abs() {
            let phi = FRAC_PI_4 * (a.y / a.x);
            DVec3::new(a.x * phi.cos(), a.x * phi.sin(), 0.0)
        } else {
            let psi = FRAC_PI_4 * (a.x / a.y);
            DVec3::new(a.y * psi.sin(), a.y * psi.cos(), 0.0)
        }
    }

    pub fn second_wedge_unturned(u: DVec2) -> DVec3 {
        let a = 2.0 * u - DVec2::ONE;
        if a.x.abs() > a.y.abs() {
            map(a)
        } else {
            let psi = FRAC_PI_4 * (a.x / a.y);
            DVec3::new(a.y * psi.cos(), a.y * psi.sin(), 0.0)
        }
    }

    pub fn unshifted(u: DVec2) -> DVec3 {
        map(u)
    }

    pub fn rooted_radius(u: DVec2) -> DVec3 {
        let a = 2.0 * u - DVec2::ONE;
        let r = a.x.abs().max(a.y.abs());
        if r == 0.0 {
            return DVec3::ZERO;
        }
        map(a) * (r.sqrt() / r)
    }

    pub fn wedges_swapped(u: DVec2) -> DVec3 {
        let a = 2.0 * u - DVec2::ONE;
        if a == DVec2::ZERO {
            return DVec3::ZERO;
        }
        if a.y.abs() > a.x.abs() {
            let phi = FRAC_PI_4 * (a.y / a.x);
            DVec3::new(a.x * phi.cos(), a.x * phi.sin(), 0.0)
        } else {
            let psi = FRAC_PI_4 * (a.x / a.y);
            DVec3::new(a.y * psi.sin(), a.y * psi.cos(), 0.0)
        }
    }

    pub fn swapped(u: DVec2) -> DVec3 {
        map(2.0 * DVec2::new(u.y, u.x) - DVec2::ONE)
    }

    pub fn wrong_wedge(u: DVec2) -> DVec3 {
        let a = 2.0 * u - DVec2::ONE;
        if a.x.abs() > a.y.abs() {
            let phi = FRAC_PI_2 * (a.y / a.x);
            DVec3::new(a.x * phi.cos(), a.x * phi.sin(), 0.0)
        } else {
            map(a)
        }
    }

    pub fn unguarded(u: DVec2) -> DVec3 {
        let a = 2.0 * u - DVec2::ONE;
        if a.x.abs() > a.y.abs() {
            let phi = FRAC_PI_4 * (a.y / a.x);
            DVec3::new(a.x * phi.cos(), a.x * phi.sin(), 0.0)
        } else {
            let psi = FRAC_PI_4 * (a.x / a.y);
            DVec3::new(a.y * psi.sin(), a.y * psi.cos(), 0.0)
        }
    }

    pub fn four_regions(u: DVec2) -> DVec3 {
        let a = 2.0 * u - DVec2::ONE;
        let (r, phi) = if a.x > -a.y {
            if a.x > a.y {
                (a.x, FRAC_PI_4 * (a.y / a.x))
            } else {
                (a.y, FRAC_PI_4 * (2.0 - a.x / a.y))
            }
        } else if a.x < a.y {
            (-a.x, FRAC_PI_4 * (4.0 + a.y / a.x))
        } else if a.y != 0.0 {
            (-a.y, FRAC_PI_4 * (6.0 - a.x / a.y))
        } else {
            (0.0, 0.0)
        };
        DVec3::new(r * phi.cos(), r * phi.sin(), 0.0)
    }

    pub fn explicit_angle(u: DVec2) -> DVec3 {
        let a = 2.0 * u - DVec2::ONE;
        if a.x == 0.0 && a.y == 0.0 {
            return DVec3::ZERO;
        }
        let (r, phi) = if a.x.abs() > a.y.abs() {
            (a.x, FRAC_PI_4 * a.y / a.x)
        } else {
            (a.y, FRAC_PI_2 - FRAC_PI_4 * a.x / a.y)
        };
        let (sin, cos) = phi.sin_cos();
        DVec3::new(r * cos, r * sin, 0.0)
    }
}

/// Twins and alternatives of `cosine_malley`.
mod malley {
    use glam::{DVec2, DVec3};

    use std::f64::consts::TAU;

    use crate::sampling::disc::disc_polar;

    /// The concentric disc point of `u` lifted to `z`.
    fn lifted(u: DVec2, z: f64) -> DVec3 {
        let d = super::concentric::map(2.0 * u - DVec2::ONE);
        DVec3::new(d.x, d.y, z)
    }

    pub fn uniform_hemisphere(u: DVec2) -> DVec3 {
        let z = 1.0 - u.x;
        let (r, phi) = ((1.0 - z * z).max(0.0).sqrt(), TAU * u.y);
        DVec3::new(r * phi.cos(), r * phi.sin(), z)
    }

    /// `1 - r` for the concentric map's radius `r`, exactly: `2 min(u1, 1 - u1, u2, 1 - u2)`.
    fn to_rim(u: DVec2) -> f64 {
        2.0 * u.x.min(1.0 - u.x).min(u.y).min(1.0 - u.y)
    }

    pub fn lift_without_root(u: DVec2) -> DVec3 {
        let t = to_rim(u);
        lifted(u, t * (2.0 - t))
    }

    pub fn two_sides(u: DVec2) -> DVec3 {
        let t = 2.0 * u.x.min(u.y);
        lifted(u, (t * (2.0 - t)).max(0.0).sqrt())
    }

    pub fn half_distance(u: DVec2) -> DVec3 {
        let t = to_rim(u) / 2.0;
        lifted(u, (t * (2.0 - t)).max(0.0).sqrt())
    }

    pub fn without_one_plus_r(u: DVec2) -> DVec3 {
        lifted(u, to_rim(u).sqrt())
    }

    pub fn on_polar(u: DVec2) -> DVec3 {
        let d = disc_polar(u);
        DVec3::new(d.x, d.y, (1.0 - u.x).sqrt())
    }

    pub fn two_roots(u: DVec2) -> DVec3 {
        let r = (2.0 * u.x - 1.0).abs().max((2.0 * u.y - 1.0).abs());
        lifted(u, (1.0 - r).max(0.0).sqrt() * (1.0 + r).sqrt())
    }
}

/// Twins and alternatives of `cosine_pdf`.
mod density {
    use glam::DVec3;
    use std::f64::consts::{PI, TAU};

    pub fn two_pi(w: DVec3) -> f64 {
        w.z.max(0.0) / TAU
    }

    pub fn squared(w: DVec3) -> f64 {
        w.z.max(0.0).powi(2) / PI
    }

    pub fn absolute(w: DVec3) -> f64 {
        w.z.abs() / PI
    }

    pub fn per_angles(w: DVec3) -> f64 {
        let z = w.z.max(0.0);
        (1.0 - z * z).max(0.0).sqrt() * z / PI
    }

    pub fn explicit_if(w: DVec3) -> f64 {
        if w.z > 0.0 { w.z / PI } else { 0.0 }
    }

    pub fn half_sum(w: DVec3) -> f64 {
        (w.z + w.z.abs()) / TAU
    }
}

/// Twins and alternatives of `Piecewise1D::sample`.
mod constant {
    use crate::sampling::tabulated::{Piecewise1D, Sample};

    /// The bin of `u`: the first with `cdf[i + 1] > u`, never one of zero mass.
    fn bin(t: &Piecewise1D, u: f64) -> usize {
        t.cdf_table()[1..]
            .partition_point(|&c| c <= u)
            .min(t.bins() - 1)
    }

    /// The point of bin `i` at the fraction `s` of its width, kept below its upper edge.
    fn at(t: &Piecewise1D, i: usize, s: f64) -> f64 {
        let e = t.edges();
        (e[i] + s * (e[i + 1] - e[i])).min(e[i + 1].next_down())
    }

    /// The fraction of bin `i`'s share of `[0, 1)` below `u`.
    fn fraction(t: &Piecewise1D, i: usize, u: f64) -> f64 {
        let c = t.cdf_table();
        (u - c[i]) / (c[i + 1] - c[i])
    }

    pub fn probability_as_pdf(t: &Piecewise1D, u: f64) -> Sample {
        let i = bin(t, u);
        let x = at(t, i, fraction(t, i, u));
        Sample {
            x,
            pdf: t.bin_probability(i),
            bin: i,
        }
    }

    pub fn position_from_u(t: &Piecewise1D, u: f64) -> Sample {
        let i = bin(t, u);
        let x = at(t, i, u);
        Sample {
            x,
            pdf: t.pdf(x),
            bin: i,
        }
    }

    pub fn reversed_in_bin(t: &Piecewise1D, u: f64) -> Sample {
        let i = bin(t, u);
        let x = at(t, i, 1.0 - fraction(t, i, u));
        Sample {
            x,
            pdf: t.pdf(x),
            bin: i,
        }
    }

    pub fn by_partition_point(t: &Piecewise1D, u: f64) -> Sample {
        let i = bin(t, u);
        let x = at(t, i, fraction(t, i, u));
        Sample {
            x,
            pdf: t.pdf(x),
            bin: i,
        }
    }

    pub fn by_scan(t: &Piecewise1D, u: f64) -> Sample {
        let c = t.cdf_table();
        let mut i = 0;
        while i + 1 < t.bins() && c[i + 1] <= u {
            i += 1;
        }
        let x = at(t, i, fraction(t, i, u));
        Sample {
            x,
            pdf: t.pdf(x),
            bin: i,
        }
    }
}

/// Twins and alternatives of `PiecewiseLinear1D::sample`.
mod linear {
    use crate::sampling::tabulated::{PiecewiseLinear1D, Sample, segment_inverse};

    /// A piecewise-linear sampler with the position within the segment from `inverse(a, b,
    /// s)` (`a`, `b` the end densities, `s` the fraction of the segment's mass), stepping
    /// off a zero-valued end when `step`.
    fn sample_with(
        t: &PiecewiseLinear1D,
        u: f64,
        inverse: impl Fn(f64, f64, f64) -> f64,
        step: bool,
    ) -> Sample {
        let (c, k) = (t.cdf_table(), t.knots());
        let i = c[1..].partition_point(|&c| c <= u).min(t.segments() - 1);
        // The density at the left knot is the table's; at the right one, from the mass.
        let a = t.pdf(k[i]);
        let b = (2.0 * (c[i + 1] - c[i]) / (k[i + 1] - k[i]) - a).max(0.0);
        let s = (u - c[i]) / (c[i + 1] - c[i]);
        let mut x = (k[i] + inverse(a, b, s) * (k[i + 1] - k[i])).min(k[i + 1].next_down());
        let mut pdf = t.pdf(x);
        let mut steps = 0;
        while step && pdf == 0.0 && steps < 64 {
            x = if a == 0.0 {
                x.next_up().min(k[i + 1].next_down())
            } else {
                x.next_down().max(k[i])
            };
            pdf = t.pdf(x);
            steps += 1;
        }
        Sample { bin: i, x, pdf }
    }

    pub fn uniform_within(t: &PiecewiseLinear1D, u: f64) -> Sample {
        sample_with(t, u, |_, _, s| s, true)
    }

    pub fn ramp_root(t: &PiecewiseLinear1D, u: f64) -> Sample {
        sample_with(t, u, |_, _, s| s.sqrt(), true)
    }

    pub fn ends_swapped(t: &PiecewiseLinear1D, u: f64) -> Sample {
        sample_with(t, u, |a, b, s| segment_inverse(b, a, s), true)
    }

    pub fn no_step(t: &PiecewiseLinear1D, u: f64) -> Sample {
        sample_with(t, u, segment_inverse, false)
    }

    pub fn mean_density(t: &PiecewiseLinear1D, u: f64) -> Sample {
        let sample = sample_with(t, u, segment_inverse, true);
        let (c, k, i) = (t.cdf_table(), t.knots(), sample.bin);
        Sample {
            pdf: (c[i + 1] - c[i]) / (k[i + 1] - k[i]),
            ..sample
        }
    }

    pub fn by_partition_point(t: &PiecewiseLinear1D, u: f64) -> Sample {
        let solve = |a: f64, b: f64, s: f64| {
            let m = a.max(b);
            let (a, b) = (a / m, b / m);
            let denominator = a + (a * a + s * (b * b - a * a)).max(0.0).sqrt();
            if denominator == 0.0 {
                0.0
            } else {
                (s * (a + b) / denominator).min(1.0)
            }
        };
        sample_with(t, u, solve, true)
    }
}

/// Twins and alternatives of `disc_polar`.
mod polar {
    use glam::{DVec2, DVec3};
    use std::f64::consts::{PI, TAU};

    pub fn r_equals_u1(u: DVec2) -> DVec3 {
        let (r, phi) = (u.x, TAU * u.y);
        DVec3::new(r * phi.cos(), r * phi.sin(), 0.0)
    }

    pub fn half_turn(u: DVec2) -> DVec3 {
        let (r, phi) = (u.x.sqrt(), PI * u.y);
        DVec3::new(r * phi.cos(), r * phi.sin(), 0.0)
    }

    pub fn r_squared(u: DVec2) -> DVec3 {
        let (r, phi) = (u.x * u.x, TAU * u.y);
        DVec3::new(r * phi.cos(), r * phi.sin(), 0.0)
    }

    pub fn swapped(u: DVec2) -> DVec3 {
        let (r, phi) = (u.y.sqrt(), TAU * u.x);
        DVec3::new(r * phi.cos(), r * phi.sin(), 0.0)
    }

    pub fn y_without_r(u: DVec2) -> DVec3 {
        let (r, phi) = (u.x.sqrt(), TAU * u.y);
        DVec3::new(r * phi.cos(), phi.sin(), 0.0)
    }

    pub fn sin_cos_swapped(u: DVec2) -> DVec3 {
        let (r, phi) = (u.x.sqrt(), TAU * u.y);
        DVec3::new(r * phi.sin(), r * phi.cos(), 0.0)
    }

    pub fn with_sin_cos(u: DVec2) -> DVec3 {
        let (sin, cos) = (2.0 * PI * u.y).sin_cos();
        let radius = u.x.sqrt();
        DVec3::new(cos * radius, sin * radius, 0.0)
    }

    pub fn scaled_unit_vector(u: DVec2) -> DVec3 {
        let phi = u.y * TAU;
        DVec3::new(phi.cos(), phi.sin(), 0.0) * u.x.sqrt()
    }
}
