//! The typical mistakes and correct alternatives of the exercises of the book's transport
//! chapters (see [`super`]).

use super::{Alternative, Mistake, Table};
use crate::check::lambert::planted as lambert_planted;
use crate::check::roulette::planted as roulette_planted;
use crate::check::warp::planted as warp_planted;
use crate::exercise::mistakes::Source;
use crate::exercise::mistakes::probes::{areas, brdfs, roulettes};
use crate::exercise::registry::{area_to_solid_angle_checks, lambert_brdf_checks, roulette_checks};
use crate::transport::roulette;

/// This part's tables, in the book's order.
pub const TABLES: &[Table] = &[
    Table {
        exercise: "lambert_brdf",
        mistakes: &[
            Mistake {
                words: "f = rho: the albedo taken for the BRDF's value, without the 1/pi (its albedo is pi rho)",
                source: Source::Errata,
                check: || lambert_brdf_checks(lambert_planted::without_one_over_pi),
                probe: || brdfs(lambert_planted::without_one_over_pi),
            },
            Mistake {
                words: "f = rho / (2 pi): the uniform hemisphere's density 1/(2 pi) where 1/pi belongs (its albedo is rho / 2)",
                source: Source::Constant,
                check: || lambert_brdf_checks(brdf::two_pi),
                probe: || brdfs(brdf::two_pi),
            },
            Mistake {
                words: "f = rho cos(theta_i) / pi: the cosine of the rendering equation folded into the BRDF (not reciprocal, albedo 2 rho / 3)",
                source: Source::Chapter,
                check: || lambert_brdf_checks(brdf::with_cosine),
                probe: || brdfs(brdf::with_cosine),
            },
            Mistake {
                words: "f = 1 / pi: rho left out (every surface white)",
                source: Source::Factor,
                check: || lambert_brdf_checks(brdf::without_rho),
                probe: || brdfs(brdf::without_rho),
            },
            Mistake {
                words: "only w_i tested against the surface: light reflected to directions below it (not reciprocal)",
                source: Source::Branch,
                check: || lambert_brdf_checks(lambert_planted::one_sided),
                probe: || brdfs(lambert_planted::one_sided),
            },
            Mistake {
                words: "rho / pi for every pair of directions: the test for directions below the surface left out",
                source: Source::Branch,
                check: || lambert_brdf_checks(brdf::everywhere),
                probe: || brdfs(brdf::everywhere),
            },
        ],
        alternatives: &[
            Alternative {
                words: "an early return of 0 below the surface (the lower of the two z), then rho / pi",
                check: || lambert_brdf_checks(brdf::early_return),
            },
            Alternative {
                words: "a match on both signs, rho times 1/pi computed from PI",
                check: || lambert_brdf_checks(brdf::matched),
            },
        ],
    },
    Table {
        exercise: "roulette",
        mistakes: &[
            Mistake {
                words: "a survivor keeps f, not f / p: the estimate shrinks to p f (the image darkens)",
                source: Source::Chapter,
                check: || roulette_checks(roulette_planted::without_division),
                probe: || roulettes(roulette_planted::without_division),
            },
            Mistake {
                words: "survives when u <= p (the source notes' rule): p = 0 and u = 0 survive and give 0 / 0",
                source: Source::Errata,
                check: || roulette_checks(roulette::roulette_seed),
                probe: || roulettes(roulette::roulette_seed),
            },
            Mistake {
                words: "survives when u > p: the threshold on the wrong side (right on average only for p = 1/2)",
                source: Source::Branch,
                check: || roulette_checks(roulette_planted::survives_above),
                probe: || roulettes(roulette_planted::survives_above),
            },
            Mistake {
                words: "a survivor carries f / (1 - p): divided by the probability of being killed",
                source: Source::Branch,
                check: || roulette_checks(rr::over_killed),
                probe: || roulettes(rr::over_killed),
            },
            Mistake {
                words: "p read as the probability of termination: survives when u >= p and carries f / (1 - p) (unbiased, but p = 0 always survives and p = 1 never does)",
                source: Source::Branch,
                check: || roulette_checks(rr::termination),
                probe: || roulettes(rr::termination),
            },
            Mistake {
                words: "a survivor carries f p: p to the power 1 where -1 belongs",
                source: Source::Power,
                check: || roulette_checks(rr::times_p),
                probe: || roulettes(rr::times_p),
            },
            Mistake {
                words: "a survivor carries f / u: divided by the random number instead of the probability",
                source: Source::Swapped,
                check: || roulette_checks(rr::over_u),
                probe: || roulettes(rr::over_u),
            },
        ],
        alternatives: &[
            Alternative {
                words: "an early return of 0 when u >= p, then f / p",
                check: || roulette_checks(rr::early_return),
            },
            Alternative {
                words: "a match on p > u, f times the reciprocal of p",
                check: || roulette_checks(rr::matched),
            },
        ],
    },
    Table {
        exercise: "area_to_solid_angle",
        mistakes: &[
            Mistake {
                words: "p_A r^2: the light's cosine left out (the density no longer grows as the light turns edge-on)",
                source: Source::Factor,
                check: || area_to_solid_angle_checks(warp_planted::missing_cos),
                probe: || areas(warp_planted::missing_cos),
            },
            Mistake {
                words: "p_A / |cos|: the distance squared left out",
                source: Source::Factor,
                check: || area_to_solid_angle_checks(warp_planted::missing_r2),
                probe: || areas(warp_planted::missing_r2),
            },
            Mistake {
                words: "p_A r^2 / cos without the absolute value (the source notes' formula): negative for a light facing the point",
                source: Source::Errata,
                check: || area_to_solid_angle_checks(warp_planted::signed_cos),
                probe: || areas(warp_planted::signed_cos),
            },
            Mistake {
                words: "r^2 / |cos|: the area density left out (taken as 1)",
                source: Source::Factor,
                check: || area_to_solid_angle_checks(warp_planted::unnormalised),
                probe: || areas(warp_planted::unnormalised),
            },
            Mistake {
                words: "p_A r / |cos|: the distance where its square belongs",
                source: Source::Power,
                check: || area_to_solid_angle_checks(solid::distance_not_squared),
                probe: || areas(solid::distance_not_squared),
            },
            Mistake {
                words: "p_A r^2 / cos^2: the cosine squared",
                source: Source::Power,
                check: || area_to_solid_angle_checks(solid::cos_squared),
                probe: || areas(solid::cos_squared),
            },
            Mistake {
                words: "p_A |cos| / r^2: the conversion the wrong way round (solid angle to area)",
                source: Source::Swapped,
                check: || area_to_solid_angle_checks(solid::inverted),
                probe: || areas(solid::inverted),
            },
            Mistake {
                words: "no case for a light seen edge-on: cos = 0 gives infinity instead of 0",
                source: Source::Branch,
                check: || area_to_solid_angle_checks(solid::unguarded),
                probe: || areas(solid::unguarded),
            },
            Mistake {
                words: "0 when cos <= 0, as if the light faced away: but a light facing the point has n . w < 0",
                source: Source::Branch,
                check: || area_to_solid_angle_checks(solid::facing_skipped),
                probe: || areas(solid::facing_skipped),
            },
        ],
        alternatives: &[
            Alternative {
                words: "an explicit if for cos = 0, then p_A r^2 / |cos|",
                check: || area_to_solid_angle_checks(solid::explicit_edge_on),
            },
            Alternative {
                words: "p_A divided by |cos| / r^2 (the solid angle per unit area), non-finite results mapped to 0",
                check: || area_to_solid_angle_checks(solid::divided_by_ratio),
            },
        ],
    },
];

/// Twins and alternatives of `lambert_brdf`.
mod brdf {
    use glam::DVec3;
    use std::f64::consts::{FRAC_1_PI, PI, TAU};

    pub fn two_pi(rho: f64, wi: DVec3, wo: DVec3) -> f64 {
        if 0.0 < wi.z && 0.0 < wo.z {
            rho / TAU
        } else {
            0.0
        }
    }

    pub fn with_cosine(rho: f64, wi: DVec3, wo: DVec3) -> f64 {
        if 0.0 < wi.z && 0.0 < wo.z {
            rho * wi.z / PI
        } else {
            0.0
        }
    }

    pub fn without_rho(_rho: f64, wi: DVec3, wo: DVec3) -> f64 {
        if 0.0 < wi.z && 0.0 < wo.z {
            FRAC_1_PI
        } else {
            0.0
        }
    }

    pub fn everywhere(rho: f64, _wi: DVec3, _wo: DVec3) -> f64 {
        FRAC_1_PI * rho
    }

    pub fn early_return(rho: f64, wi: DVec3, wo: DVec3) -> f64 {
        if wi.z.min(wo.z) <= 0.0 {
            return 0.0;
        }
        rho / PI
    }

    pub fn matched(rho: f64, wi: DVec3, wo: DVec3) -> f64 {
        match (wi.z > 0.0, wo.z > 0.0) {
            (true, true) => rho * (1.0 / PI),
            _ => 0.0,
        }
    }
}

/// Twins and alternatives of `roulette`.
mod rr {
    pub fn over_killed(f: f64, p: f64, u: f64) -> f64 {
        if u < p { f / (1.0 - p) } else { 0.0 }
    }

    pub fn termination(f: f64, p: f64, u: f64) -> f64 {
        if u >= p { f / (1.0 - p) } else { 0.0 }
    }

    pub fn times_p(f: f64, p: f64, u: f64) -> f64 {
        if u < p { f * p } else { 0.0 }
    }

    pub fn over_u(f: f64, p: f64, u: f64) -> f64 {
        if u < p { f / u } else { 0.0 }
    }

    pub fn early_return(f: f64, p: f64, u: f64) -> f64 {
        if u >= p {
            return 0.0;
        }
        f / p
    }

    pub fn matched(f: f64, p: f64, u: f64) -> f64 {
        match p > u {
            true => f * p.recip(),
            false => 0.0,
        }
    }
}

/// Twins and alternatives of `area_to_solid_angle`.
mod solid {
    pub fn distance_not_squared(pdf_area: f64, dist: f64, cos_light: f64) -> f64 {
        let pdf = pdf_area * dist / cos_light.abs();
        if !pdf.is_finite() {
            return 0.0;
        }
        pdf
    }

    pub fn cos_squared(pdf_area: f64, dist: f64, cos_light: f64) -> f64 {
        let pdf = pdf_area * dist * dist / (cos_light * cos_light);
        if !pdf.is_finite() {
            return 0.0;
        }
        pdf
    }

    pub fn inverted(pdf_area: f64, dist: f64, cos_light: f64) -> f64 {
        pdf_area * cos_light.abs() / (dist * dist)
    }

    pub fn unguarded(pdf_area: f64, dist: f64, cos_light: f64) -> f64 {
        pdf_area * dist * dist / cos_light.abs()
    }

    pub fn facing_skipped(pdf_area: f64, dist: f64, cos_light: f64) -> f64 {
        if cos_light <= 0.0 {
            0.0
        } else {
            pdf_area * dist * dist / cos_light
        }
    }

    pub fn explicit_edge_on(pdf_area: f64, dist: f64, cos_light: f64) -> f64 {
        let cos = cos_light.abs();
        if cos == 0.0 {
            0.0
        } else {
            pdf_area * dist.powi(2) / cos
        }
    }

    pub fn divided_by_ratio(pdf_area: f64, dist: f64, cos_light: f64) -> f64 {
        let pdf = pdf_area / (cos_light.abs() / (dist * dist));
        if !pdf.is_finite() {
            return 0.0;
        }
        pdf
    }
}
