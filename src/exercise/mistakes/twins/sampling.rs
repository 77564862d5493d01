//! The typical mistakes and correct alternatives of the exercises of the book's sampling
//! and geometry chapters and of *Reflection and refraction* (see [`super`] and [`crate::exercise::mistakes`]); the twins themselves are in one file per exercise below.

use super::{Alternative, Mistake, Table};
use crate::check::importance::planted as importance_planted;
use crate::check::sphere::planted as sphere_planted;
use crate::check::tabulated::planted as tabulated_planted;
use crate::check::warp::planted as warp_planted;
use crate::exercise::mistakes::Source;
use crate::exercise::mistakes::probes::{
    directions, estimates, flips, linear_table, rays, rejections, square, table,
};
use crate::exercise::registry::{
    cosine_malley_checks, cosine_pdf_checks, disc_concentric_checks, disc_polar_checks,
    estimate_checks, hemisphere_flip_checks, intersect_stable_checks,
    piecewise_linear1d_sample_checks, piecewise1d_sample_checks, sphere_rejection_checks,
};

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
    mistakes: &[
        Mistake {
            words: "t > 0: the source notes' first root \"greater than 0\", t_min ignored (a ray leaving a surface hits it again)",
            source: Source::Errata,
            check: || intersect_stable_checks(intersect::t_greater_than_zero),
            probe: || rays(intersect::t_greater_than_zero),
        },
        Mistake {
            words: "every root counts, behind the origin too: a ray starting inside returns the root behind it",
            source: Source::Branch,
            check: || intersect_stable_checks(intersect::ignoring_t_min),
            probe: || rays(intersect::ignoring_t_min),
        },
        Mistake {
            words: "always the far root (-b + sqrt(b^2 - ac)) / a: the exit, not the entry",
            source: Source::Branch,
            check: || intersect_stable_checks(sphere_planted::always_far_root),
            probe: || rays(sphere_planted::always_far_root),
        },
        Mistake {
            words: "a = D.D taken as 1: right only for a unit direction",
            source: Source::Factor,
            check: || intersect_stable_checks(sphere_planted::assuming_unit_direction),
            probe: || rays(sphere_planted::assuming_unit_direction),
        },
        Mistake {
            words: "near misses counted as hits: a discriminant down to -1 % of a r^2 accepted",
            source: Source::Branch,
            check: || intersect_stable_checks(sphere_planted::loose_discriminant),
            probe: || rays(sphere_planted::loose_discriminant),
        },
        Mistake {
            words: "c = f.f - r: the radius where its square belongs",
            source: Source::Power,
            check: || intersect_stable_checks(intersect::radius_not_squared),
            probe: || rays(intersect::radius_not_squared),
        },
        Mistake {
            words: "f = C - O: centre and origin swapped, so the roots come out negated (the sphere found behind the ray)",
            source: Source::Swapped,
            check: || intersect_stable_checks(intersect::centre_minus_origin),
            probe: || rays(intersect::centre_minus_origin),
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
    mistakes: &[
        Mistake {
            words: "the mean of f(X): the division by the density q(X) left out",
            source: Source::Factor,
            check: || estimate_checks(importance_planted::forgets_the_density),
            probe: || estimates(importance_planted::forgets_the_density),
        },
        Mistake {
            words: "f(X) / q(U): the density taken at the uniform number U, not at the sample X",
            source: Source::Swapped,
            check: || estimate_checks(importance_planted::density_of_u),
            probe: || estimates(importance_planted::density_of_u),
        },
        Mistake {
            words: "f(X) q(X): multiplied by the density where dividing belongs",
            source: Source::Power,
            check: || estimate_checks(estimator::times_density),
            probe: || estimates(estimator::times_density),
        },
        Mistake {
            words: "f(X) / q(X) with no case for q(X) = 0: an infinite (or NaN) term there",
            source: Source::Branch,
            check: || estimate_checks(estimator::unguarded),
            probe: || estimates(estimator::unguarded),
        },
        Mistake {
            words: "a draw where q(X) = 0 skipped instead of adding 0: fewer than n terms, a biased mean",
            source: Source::Branch,
            check: || estimate_checks(importance_planted::skips_zero_density),
            probe: || estimates(importance_planted::skips_zero_density),
        },
        Mistake {
            words: "X = U drawn uniformly, yet weighted by 1 / q(X): the draws not taken from q",
            source: Source::Chapter,
            check: || estimate_checks(estimator::uniform_draws),
            probe: || estimates(estimator::uniform_draws),
        },
        Mistake {
            words: "n + 1 terms (a loop over 0..=n)",
            source: Source::Branch,
            check: || estimate_checks(estimator::one_more_term),
            probe: || estimates(estimator::one_more_term),
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
    mistakes: &[
        Mistake {
            words: "the point of the ball returned without normalising it",
            source: Source::Chapter,
            check: || sphere_rejection_checks(rejection::not_normalised),
            probe: || rejections(rejection::not_normalised),
        },
        Mistake {
            words: "no rejection: every point of the cube normalised, so the corners' directions crowd",
            source: Source::Branch,
            check: || sphere_rejection_checks(rejection::no_rejection),
            probe: || rejections(rejection::no_rejection),
        },
        Mistake {
            words: "coordinate = -1 + u: the factor 2 left out, the cube [-1, 0)^3 (one octant)",
            source: Source::Factor,
            check: || sphere_rejection_checks(rejection::without_factor_two),
            probe: || rejections(rejection::without_factor_two),
        },
        Mistake {
            words: "coordinate = u: [0, 1)^3 where [-1, 1)^3 belongs (one octant)",
            source: Source::Constant,
            check: || sphere_rejection_checks(rejection::unit_cube),
            probe: || rejections(rejection::unit_cube),
        },
        Mistake {
            words: "the draws counted without the accepted one (only the rejections)",
            source: Source::Branch,
            check: || sphere_rejection_checks(rejection::rejections_only),
            probe: || rejections(rejection::rejections_only),
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
    mistakes: &[
        Mistake {
            words: "w returned as it is: the flip left out (the whole sphere)",
            source: Source::Branch,
            check: || hemisphere_flip_checks(flip::no_flip),
            probe: || flips(flip::no_flip),
        },
        Mistake {
            words: "flipped when w . n > 0: every direction sent to the wrong side",
            source: Source::Branch,
            check: || hemisphere_flip_checks(flip::wrong_side),
            probe: || flips(flip::wrong_side),
        },
        Mistake {
            words: "(w.x, w.y, |w.z|): the side tested on z, right only for n = +z",
            source: Source::Chapter,
            check: || hemisphere_flip_checks(flip::z_only),
            probe: || flips(flip::z_only),
        },
        Mistake {
            words: "n flipped to w's side: w and n swapped",
            source: Source::Swapped,
            check: || hemisphere_flip_checks(flip::swapped),
            probe: || flips(flip::swapped),
        },
        Mistake {
            words: "w - (w . n) n below: the factor 2 of the reflection left out (a projection, not a unit vector)",
            source: Source::Factor,
            check: || hemisphere_flip_checks(flip::projected),
            probe: || flips(flip::projected),
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
    mistakes: &[
        Mistake {
            words: "r = u1: the radius without its square root (the radial CDF r^2 forgotten)",
            source: Source::Chapter,
            check: || disc_polar_checks(polar::r_equals_u1),
            probe: || square(polar::r_equals_u1),
        },
        Mistake {
            words: "phi = pi u2: half the turn (pi where 2 pi belongs)",
            source: Source::Constant,
            check: || disc_polar_checks(polar::half_turn),
            probe: || square(polar::half_turn),
        },
        Mistake {
            words: "r = u1^2: the radius squared where its square root belongs",
            source: Source::Power,
            check: || disc_polar_checks(polar::r_squared),
            probe: || square(polar::r_squared),
        },
        Mistake {
            words: "r = sqrt(u2), phi = 2 pi u1: u1 and u2 swapped",
            source: Source::Swapped,
            check: || disc_polar_checks(polar::swapped),
            probe: || square(polar::swapped),
        },
        Mistake {
            words: "(r cos phi, sin phi): the radius left off y",
            source: Source::Factor,
            check: || disc_polar_checks(polar::y_without_r),
            probe: || square(polar::y_without_r),
        },
        Mistake {
            words: "(r sin phi, r cos phi): sine and cosine swapped, a uniform disc but not the polar map (phi runs clockwise from the y axis, so the map's inverse is not the chapter's)",
            source: Source::Swapped,
            check: || disc_polar_checks(polar::sin_cos_swapped),
            probe: || square(polar::sin_cos_swapped),
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
    mistakes: &[
        Mistake {
            words: "phi = (pi/2) a.y / a.x in the first wedge: pi/2 where pi/4 belongs (the disc folded over itself)",
            source: Source::Constant,
            check: || disc_concentric_checks(concentric::wrong_wedge),
            probe: || square(concentric::wrong_wedge),
        },
        Mistake {
            words: "(a.y cos psi, a.y sin psi) in the second wedge: psi where pi/2 - psi belongs",
            source: Source::Chapter,
            check: || disc_concentric_checks(concentric::second_wedge_unturned),
            probe: || square(concentric::second_wedge_unturned),
        },
        Mistake {
            words: "a = u: the square not mapped to [-1, 1]^2 (2u - 1 left out)",
            source: Source::Factor,
            check: || disc_concentric_checks(concentric::unshifted),
            probe: || square(concentric::unshifted),
        },
        Mistake {
            words: "r = sqrt(|a|): the polar map's square root taken over",
            source: Source::Power,
            check: || disc_concentric_checks(concentric::rooted_radius),
            probe: || square(concentric::rooted_radius),
        },
        Mistake {
            words: "|a.y| > |a.x| for the first wedge: each wedge's formula used in the other",
            source: Source::Branch,
            check: || disc_concentric_checks(concentric::wedges_swapped),
            probe: || square(concentric::wedges_swapped),
        },
        Mistake {
            words: "u1 and u2 swapped: a uniform disc, but the map mirrored about the diagonal (its inverse is not the chapter's)",
            source: Source::Swapped,
            check: || disc_concentric_checks(concentric::swapped),
            probe: || square(concentric::swapped),
        },
        Mistake {
            words: "no case for the centre a = 0: psi = 0 / 0, a NaN point at u = (1/2, 1/2)",
            source: Source::Branch,
            check: || disc_concentric_checks(concentric::unguarded),
            probe: || square(concentric::unguarded),
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
    mistakes: &[
        Mistake {
            words: "a uniform hemisphere direction: the cosine weighting left out",
            source: Source::Chapter,
            check: || cosine_malley_checks(malley::uniform_hemisphere),
            probe: || square(malley::uniform_hemisphere),
        },
        Mistake {
            words: "z = 1 - r^2: the lift without its square root",
            source: Source::Power,
            check: || cosine_malley_checks(malley::lift_without_root),
            probe: || square(malley::lift_without_root),
        },
        Mistake {
            words: "1 - r = 2 min(u1, u2): the distance to the rim without the sides 1 - u1, 1 - u2",
            source: Source::Branch,
            check: || cosine_malley_checks(malley::two_sides),
            probe: || square(malley::two_sides),
        },
        Mistake {
            words: "1 - r = min(u1, 1 - u1, u2, 1 - u2): the distance to the rim without its 2",
            source: Source::Constant,
            check: || cosine_malley_checks(malley::half_distance),
            probe: || square(malley::half_distance),
        },
        Mistake {
            words: "z = sqrt(1 - r): the factor 1 + r of 1 - r^2 left out",
            source: Source::Factor,
            check: || cosine_malley_checks(malley::without_one_plus_r),
            probe: || square(malley::without_one_plus_r),
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
    mistakes: &[
        Mistake {
            words: "cos theta: the 1 / pi left out",
            source: Source::Factor,
            check: || cosine_pdf_checks(warp_planted::cosine_pdf_without_1_over_pi),
            probe: || directions(warp_planted::cosine_pdf_without_1_over_pi),
        },
        Mistake {
            words: "cos theta / (2 pi): 2 pi where pi belongs",
            source: Source::Constant,
            check: || cosine_pdf_checks(density::two_pi),
            probe: || directions(density::two_pi),
        },
        Mistake {
            words: "cos^2 theta / pi: the cosine squared",
            source: Source::Power,
            check: || cosine_pdf_checks(density::squared),
            probe: || directions(density::squared),
        },
        Mistake {
            words: "|cos theta| / pi: the lower hemisphere given a density too",
            source: Source::Branch,
            check: || cosine_pdf_checks(density::absolute),
            probe: || directions(density::absolute),
        },
        Mistake {
            words: "sin theta cos theta / pi: the density per d theta d phi, not per steradian",
            source: Source::Chapter,
            check: || cosine_pdf_checks(density::per_angles),
            probe: || directions(density::per_angles),
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
    mistakes: &[
        Mistake {
            words: "the textbook search, the first bin with cdf[i + 1] >= u: at a plateau's level it lands in the bin of zero mass before it",
            source: Source::Errata,
            check: || piecewise1d_sample_checks(tabulated_planted::first_bin_reaching_u),
            probe: || table(tabulated_planted::first_bin_reaching_u),
        },
        Mistake {
            words: "bin floor(u n): every bin given the same mass",
            source: Source::Branch,
            check: || piecewise1d_sample_checks(tabulated_planted::equal_bins),
            probe: || table(tabulated_planted::equal_bins),
        },
        Mistake {
            words: "pdf = the bin's probability v_i w_i / I: the bin width not divided out",
            source: Source::Chapter,
            check: || piecewise1d_sample_checks(constant::probability_as_pdf),
            probe: || table(constant::probability_as_pdf),
        },
        Mistake {
            words: "x = x_i + u (x_i+1 - x_i): the position within the bin from u itself, (u - c_i) / (c_i+1 - c_i) left out",
            source: Source::Factor,
            check: || piecewise1d_sample_checks(constant::position_from_u),
            probe: || table(constant::position_from_u),
        },
        Mistake {
            words: "t = (c_i+1 - u) / (c_i+1 - c_i): c_i and c_i+1 swapped, each bin run backwards",
            source: Source::Swapped,
            check: || piecewise1d_sample_checks(constant::reversed_in_bin),
            probe: || table(constant::reversed_in_bin),
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
    mistakes: &[
        Mistake {
            words: "uniform within the segment: the quadratic's inverse left out (the table sampled as piecewise constant)",
            source: Source::Chapter,
            check: || piecewise_linear1d_sample_checks(linear::uniform_within),
            probe: || linear_table(linear::uniform_within),
        },
        Mistake {
            words: "t = sqrt(s): the inverse of a ramp from 0, right only when a = 0",
            source: Source::Power,
            check: || piecewise_linear1d_sample_checks(linear::ramp_root),
            probe: || linear_table(linear::ramp_root),
        },
        Mistake {
            words: "segment_inverse(b, a, s): the segment's two end densities swapped",
            source: Source::Swapped,
            check: || piecewise_linear1d_sample_checks(linear::ends_swapped),
            probe: || linear_table(linear::ends_swapped),
        },
        Mistake {
            words: "no step away from a zero-valued end: x at a knot of density 0 (pdf 0)",
            source: Source::Branch,
            check: || piecewise_linear1d_sample_checks(linear::no_step),
            probe: || linear_table(linear::no_step),
        },
        Mistake {
            words: "pdf = the segment's mean density (its probability over its width): the slope left out",
            source: Source::Factor,
            check: || piecewise_linear1d_sample_checks(linear::mean_density),
            probe: || linear_table(linear::mean_density),
        },
    ],
    alternatives: &[Alternative {
        words: "the segment by partition_point, the quadratic solved in the form s (a + b) / (a + sqrt(a^2 + s (b^2 - a^2)))",
        check: || piecewise_linear1d_sample_checks(linear::by_partition_point),
    }],
};

mod concentric;
mod constant;
mod density;
mod estimator;
mod flip;
mod intersect;
mod linear;
mod malley;
mod polar;
mod rejection;
