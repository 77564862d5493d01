//! The typical mistakes and correct alternatives of the exercises of the book's optics
//! chapters, *Reflection and refraction* to *Thin-film interference* (see [`super`]).
//!
//! Twins already planted beside a chapter's checker (`src/check/*/planted.rs`) are reused
//! where their signature is the exercise's; the others are in one private module per
//! exercise. Every twin is self-contained: none calls an exercise's function (a stub in a
//! hand-out). `amplitudes` is judged through the reflectance built from it, as the card
//! judges the crate's through `fresnel_dielectric`
//! ([`crate::exercise::registry::amplitudes_checks`]); its probe
//! ([`crate::exercise::mistakes::probes::amplitude_probe`]) reads the amplitudes
//! themselves.

use super::{Alternative, Mistake, Table};
use crate::check::dispersion::planted as dispersion_planted;
use crate::check::fresnel::planted as fresnel_planted;
use crate::check::reflect::planted as reflect_planted;
use crate::check::specular::planted as specular_planted;
use crate::check::thinfilm::planted as thinfilm_planted;
use crate::exercise::mistakes::Source;
use crate::exercise::mistakes::probes::{
    airy_probe, amplitude_probe, lobe_probe, reflect_probe, refract_probe, scalar_probe,
    sellmeier_probe, transmittance_probe,
};
use crate::exercise::registry::{
    airy_r_checks, amplitudes_checks, fresnel_transmittance_checks, narrow_lobe_brdf_checks,
    reflect_checks, refract_checks, schlick_verdict, sellmeier_index_checks,
};
use crate::optics::fresnel::{self, Amplitudes};

/// This part's tables, in the book's order.
pub const TABLES: &[Table] = &[
    Table {
        exercise: "reflect",
        mistakes: &[
            Mistake {
                words: "w_o = 2n + w_i: the source notes' mirror, right only at normal incidence (the factor cos theta_i dropped, |w_o| = sqrt(5 - 4 cos theta_i))",
                source: Source::Errata,
                check: || reflect_checks(reflect_planted::seed_reflect),
                probe: || reflect_probe(reflect_planted::seed_reflect),
            },
            Mistake {
                words: "w_o = 2 (w_i . n) n - w_i: the formula of the other convention (w_i towards the light) used with w_i travelling towards the surface, so the mirror direction comes out reversed, into the surface",
                source: Source::Chapter,
                check: || reflect_checks(mirror::other_convention),
                probe: || reflect_probe(mirror::other_convention),
            },
            Mistake {
                words: "w_o = w_i - (w_i . n) n: 1 where 2 belongs, the incident direction projected onto the surface instead of mirrored",
                source: Source::Constant,
                check: || reflect_checks(mirror::projected),
                probe: || reflect_probe(mirror::projected),
            },
            Mistake {
                words: "w_o = w_i - 2n: the dot product w_i . n left out of the normal component",
                source: Source::Factor,
                check: || reflect_checks(mirror::without_dot),
                probe: || reflect_probe(mirror::without_dot),
            },
            Mistake {
                words: "w_o = w_i - 2 |w_i . n| n: the cosine folded with abs() but the normal not flipped, right only when n faces away from the light",
                source: Source::Branch,
                check: || reflect_checks(mirror::abs_cosine),
                probe: || reflect_probe(mirror::abs_cosine),
            },
        ],
        alternatives: &[
            Alternative {
                words: "the normal flipped to face the light first, then w_i + 2 cos_i m",
                check: || reflect_checks(mirror::flipped_first),
            },
            Alternative {
                words: "w_i split into its normal part and the rest: the rest kept, the normal part negated",
                check: || reflect_checks(mirror::split),
            },
        ],
    },
    Table {
        exercise: "refract",
        mistakes: &[
            Mistake {
                words: "the normal taken as given (the source notes' outward normal assumption): a ray leaving the glass, n facing away from the light, refracts the wrong way",
                source: Source::Errata,
                check: || refract_checks(reflect_planted::refract_unflipped_normal),
                probe: || refract_probe(reflect_planted::refract_unflipped_normal),
            },
            Mistake {
                words: "no total-internal-reflection test: past the critical angle the square root of a negative number, a NaN direction returned as transmitted",
                source: Source::Chapter,
                check: || refract_checks(reflect_planted::refract_nan_tir),
                probe: || refract_probe(reflect_planted::refract_nan_tir),
            },
            Mistake {
                words: "cos_t^2 used where cos_t belongs: the square root forgotten",
                source: Source::Power,
                check: || refract_checks(reflect_planted::refract_without_sqrt),
                probe: || refract_probe(reflect_planted::refract_without_sqrt),
            },
            Mistake {
                words: "eta = n2 / n1: the ratio of indices upside down (refraction bends the wrong way, total reflection entering the denser medium)",
                source: Source::Swapped,
                check: || refract_checks(snell::swapped_ratio),
                probe: || refract_probe(snell::swapped_ratio),
            },
            Mistake {
                words: "w_t = w_i + (eta cos_i - cos_t) m: the factor eta left off w_i",
                source: Source::Factor,
                check: || refract_checks(snell::eta_off_w_i),
                probe: || refract_probe(snell::eta_off_w_i),
            },
            Mistake {
                words: "cos_i = |w_i . n| but the normal not flipped with it: right only when n faces the light",
                source: Source::Branch,
                check: || refract_checks(snell::abs_cosine),
                probe: || refract_probe(snell::abs_cosine),
            },
        ],
        alternatives: &[
            Alternative {
                words: "the tangential part w_i + cos_i m scaled by eta, then the normal part -cos_t m added, cos_t^2 = (1 - eta^2) + (eta cos_i)^2",
                check: || refract_checks(snell::tangent_and_normal),
            },
            Alternative {
                words: "an explicit if for matched indices, a match on the side of the light, then the textbook cos_t^2 = 1 - eta^2 (1 - cos_i^2) and an if for total reflection",
                check: || refract_checks(snell::matched_side),
            },
        ],
    },
    Table {
        exercise: "amplitudes",
        mistakes: &[
            Mistake {
                words: "the source notes' equations as written: cos_t = sqrt(1 - eta^2 sin^2) with no total-internal-reflection case (NaN past the critical angle) and no matched-indices case (0/0 at grazing incidence)",
                source: Source::Errata,
                check: || amplitudes_checks(|c, n1, n2| reflectance(amp::naive(c, n1, n2))),
                probe: || amplitude_probe(amp::naive),
            },
            Mistake {
                words: "r_p with n1 and n2 paired as in r_s, so r_p = r_s: no Brewster angle, the s reflectance for all light",
                source: Source::Swapped,
                check: || amplitudes_checks(|c, n1, n2| reflectance(amp::p_like_s(c, n1, n2))),
                probe: || amplitude_probe(amp::p_like_s),
            },
            Mistake {
                words: "cos_t from eta = n2 / n1: Snell's ratio upside down (total reflection entering the denser medium, none leaving it)",
                source: Source::Swapped,
                check: || {
                    amplitudes_checks(|c, n1, n2| reflectance(amp::eta_upside_down(c, n1, n2)))
                },
                probe: || amplitude_probe(amp::eta_upside_down),
            },
            Mistake {
                words: "cos_t = 1 - eta^2 sin^2 theta_i: the square root forgotten",
                source: Source::Power,
                check: || amplitudes_checks(|c, n1, n2| reflectance(amp::no_sqrt(c, n1, n2))),
                probe: || amplitude_probe(amp::no_sqrt),
            },
            Mistake {
                words: "r_s = (n1 cos_i - cos_t) / (n1 cos_i + cos_t): the index n2 left off the s terms",
                source: Source::Factor,
                check: || amplitudes_checks(|c, n1, n2| reflectance(amp::s_without_n2(c, n1, n2))),
                probe: || amplitude_probe(amp::s_without_n2),
            },
            Mistake {
                words: "cos_i used as given: a negative cosine (the light on the normal's other side) not folded with abs(), so |r| > 1",
                source: Source::Branch,
                check: || amplitudes_checks(|c, n1, n2| reflectance(amp::signed_cosine(c, n1, n2))),
                probe: || amplitude_probe(amp::signed_cosine),
            },
        ],
        alternatives: &[
            Alternative {
                words: "cos_t from sin_t = (n1/n2) sin_i, None when sin_t > 1, and t_s, t_p by Stokes from r_s, r_p",
                check: || amplitudes_checks(|c, n1, n2| reflectance(amp::via_sines(c, n1, n2))),
            },
            Alternative {
                words: "matched indices first, then the transmission amplitudes, and r_s = t_s - 1, r_p = 2 n2 cos_i / (n2 cos_i + n1 cos_t) - 1",
                check: || amplitudes_checks(|c, n1, n2| reflectance(amp::t_first(c, n1, n2))),
            },
        ],
    },
    Table {
        exercise: "fresnel_transmittance",
        mistakes: &[
            Mistake {
                words: "T = t^2: the beam factor (n2 cos_t) / (n1 cos_i) forgotten (1 - R = 0.96 but t_s^2 = 0.64 at normal incidence on glass)",
                source: Source::Chapter,
                check: || fresnel_transmittance_checks(trans::without_beam_factor),
                probe: || transmittance_probe(trans::without_beam_factor),
            },
            Mistake {
                words: "T = (n1 cos_i) / (n2 cos_t) t^2: the beam factor upside down",
                source: Source::Swapped,
                check: || fresnel_transmittance_checks(trans::beam_factor_upside_down),
                probe: || transmittance_probe(trans::beam_factor_upside_down),
            },
            Mistake {
                words: "T_s = 4ab / (a + b): the denominator's square forgotten",
                source: Source::Power,
                check: || fresnel_transmittance_checks(trans::unsquared_denominator),
                probe: || transmittance_probe(trans::unsquared_denominator),
            },
            Mistake {
                words: "T_s = 2ab / (a + b)^2: 2 where 4 belongs",
                source: Source::Constant,
                check: || fresnel_transmittance_checks(trans::two_ab),
                probe: || transmittance_probe(trans::two_ab),
            },
            Mistake {
                words: "T = 1 past the critical angle: the total-internal-reflection case returns the matched-indices answer (nothing is transmitted there)",
                source: Source::Branch,
                check: || fresnel_transmittance_checks(trans::tir_transmits),
                probe: || transmittance_probe(trans::tir_transmits),
            },
            Mistake {
                words: "no matched-indices case: at grazing incidence with n1 = n2 both cosines are 0 and T = 0 where it is 1",
                source: Source::Branch,
                check: || fresnel_transmittance_checks(trans::no_matched_case),
                probe: || transmittance_probe(trans::no_matched_case),
            },
        ],
        alternatives: &[
            Alternative {
                words: "T = 1 - r^2 for each polarisation, from the amplitudes (energy conservation)",
                check: || fresnel_transmittance_checks(trans::one_minus_r2),
            },
            Alternative {
                words: "the beam factor written out, (n2 cos_t / n1) (t / cos_i) t, with explicit ifs for matched indices and grazing incidence",
                check: || fresnel_transmittance_checks(trans::beam_factor_written_out),
            },
        ],
    },
    Table {
        exercise: "schlick",
        mistakes: &[
            Mistake {
                words: "R0 + (1 - R0)(1 - cos)^4: the fourth power where Schlick has the fifth (every claim of a reflectance kept, only the formula tells)",
                source: Source::Power,
                check: || vec![schlick_verdict(&fresnel_planted::schlick_fourth_power)],
                probe: || scalar_probe(fresnel_planted::schlick_fourth_power),
            },
            Mistake {
                words: "the source notes' Schlick, always with cos theta_i: inside the denser medium the wrong cosine, and no total internal reflection",
                source: Source::Errata,
                check: || vec![schlick_verdict(&fresnel::schlick_seed)],
                probe: || scalar_probe(fresnel::schlick_seed),
            },
            Mistake {
                words: "R0 = ((n1 - 1)/(n1 + 1))^2: the second medium taken to be air",
                source: Source::Constant,
                check: || vec![schlick_verdict(&approx::r0_against_air)],
                probe: || scalar_probe(approx::r0_against_air),
            },
            Mistake {
                words: "R0 + (1 - cos)^5: the factor (1 - R0) left out (R > 1 at grazing incidence)",
                source: Source::Factor,
                check: || vec![schlick_verdict(&approx::without_one_minus_r0)],
                probe: || scalar_probe(approx::without_one_minus_r0),
            },
            Mistake {
                words: "the cosine on the denser side: cos_t entering the denser medium and cos_i leaving it (the test n1 <= n2 the wrong way round)",
                source: Source::Branch,
                check: || vec![schlick_verdict(&approx::denser_side)],
                probe: || scalar_probe(approx::denser_side),
            },
            Mistake {
                words: "cos_t computed with n1 and n2 swapped: inside the denser medium never a total internal reflection, and the wrong cosine",
                source: Source::Swapped,
                check: || vec![schlick_verdict(&approx::swapped_cos_t)],
                probe: || scalar_probe(approx::swapped_cos_t),
            },
            Mistake {
                words: "R = 0 past the critical angle: the total-internal-reflection branch returns nothing reflected",
                source: Source::Branch,
                check: || vec![schlick_verdict(&approx::tir_zero)],
                probe: || scalar_probe(approx::tir_zero),
            },
        ],
        alternatives: &[
            Alternative {
                words: "powi(5), with cos_t from sin_t = (n1/n2) sin_i and an explicit if for total reflection",
                check: || vec![schlick_verdict(&approx::via_sines)],
            },
            Alternative {
                words: "a match on the pair (entering, cos_transmitted) and Horner's form R0 + (1 - R0) x x x x x",
                check: || vec![schlick_verdict(&approx::matched)],
            },
        ],
    },
    Table {
        exercise: "narrow_lobe_brdf",
        mistakes: &[
            Mistake {
                words: "rho lobe(w_i): the lobe without its 1 / |cos theta_i| (the mirror that keeps the cosine, the chapter's planted bug)",
                source: Source::Chapter,
                check: || narrow_lobe_brdf_checks(lobe::keeps_cosine),
                probe: || lobe_probe(lobe::keeps_cosine),
            },
            Mistake {
                words: "rho lobe(w_i) / cos^2 theta_i: the cosine divided out twice",
                source: Source::Power,
                check: || narrow_lobe_brdf_checks(lobe::cos_squared),
                probe: || lobe_probe(lobe::cos_squared),
            },
            Mistake {
                words: "lobe(w_i) / cos theta_i: the albedo rho left out",
                source: Source::Factor,
                check: || narrow_lobe_brdf_checks(lobe::without_rho),
                probe: || lobe_probe(lobe::without_rho),
            },
            Mistake {
                words: "rho lobe(w_i) / (pi cos theta_i): Lambert's 1 / pi carried over to the mirror",
                source: Source::Constant,
                check: || narrow_lobe_brdf_checks(lobe::over_pi),
                probe: || lobe_probe(lobe::over_pi),
            },
            Mistake {
                words: "rho lobe(w_i) / |cos theta_i| below the surface too: the case w_i.z <= 0 left out",
                source: Source::Branch,
                check: || narrow_lobe_brdf_checks(lobe::no_below_case),
                probe: || lobe_probe(lobe::no_below_case),
            },
            Mistake {
                words: "the surface test w_i.z < 0 where <= 0 belongs: on the surface it divides by a cosine of 0 and returns infinity (a NaN sample in the renderer)",
                source: Source::Branch,
                check: || narrow_lobe_brdf_checks(specular_planted::horizon_included),
                probe: || lobe_probe(specular_planted::horizon_included),
            },
        ],
        alternatives: &[
            Alternative {
                words: "(rho / cos theta_i) lobe(w_i) in another order, the flag and the side tested in one match",
                check: || narrow_lobe_brdf_checks(lobe::one_match),
            },
            Alternative {
                words: "the weight 1 / cos theta_i (or 1) chosen by an if above the surface, then rho lobe(w_i) times it",
                check: || narrow_lobe_brdf_checks(lobe::reciprocal),
            },
        ],
    },
    Table {
        exercise: "Sellmeier::index",
        mistakes: &[
            Mistake {
                words: "lambda squared in nm while C is in um^2: every term about B, n flat at about sqrt(1 + sum B)",
                source: Source::Chapter,
                check: || sellmeier_index_checks(dispersion_planted::nanometres),
                probe: || sellmeier_probe(dispersion_planted::nanometres),
            },
            Mistake {
                words: "returns n^2: the square root forgotten",
                source: Source::Power,
                check: || sellmeier_index_checks(dispersion_planted::n_squared),
                probe: || sellmeier_probe(dispersion_planted::n_squared),
            },
            Mistake {
                words: "B lambda / (lambda - C): lambda where lambda^2 belongs",
                source: Source::Power,
                check: || sellmeier_index_checks(sellmeier::lambda_not_squared),
                probe: || sellmeier_probe(sellmeier::lambda_not_squared),
            },
            Mistake {
                words: "lambda^2 = nm^2 / 1000: the conversion to um applied once, not squared",
                source: Source::Constant,
                check: || sellmeier_index_checks(sellmeier::converted_once),
                probe: || sellmeier_probe(sellmeier::converted_once),
            },
            Mistake {
                words: "C lambda^2 / (lambda^2 - B): B and C swapped in each term",
                source: Source::Swapped,
                check: || sellmeier_index_checks(sellmeier::b_c_swapped),
                probe: || sellmeier_probe(sellmeier::b_c_swapped),
            },
            Mistake {
                words: "n^2 = sum B lambda^2 / (lambda^2 - C): the 1 (the vacuum's n^2) left out",
                source: Source::Factor,
                check: || sellmeier_index_checks(sellmeier::without_one),
                probe: || sellmeier_probe(sellmeier::without_one),
            },
        ],
        alternatives: &[
            Alternative {
                words: "B lambda^2 / (lambda^2 - C) summed in a loop, lambda in um first",
                check: || sellmeier_index_checks(sellmeier::as_written),
            },
            Alternative {
                words: "the sum folded from 1, with lambda^2 in nm^2 and C converted to nm^2 instead",
                check: || sellmeier_index_checks(sellmeier::in_nanometres),
            },
        ],
    },
    Table {
        exercise: "airy_r",
        mistakes: &[
            Mistake {
                words: "the source notes' denominator 1 - r12 r23 e^(2 i delta): the sign of r21 = -r12 lost",
                source: Source::Errata,
                check: || airy_r_checks(thinfilm_planted::denominator_minus),
                probe: || airy_probe(thinfilm_planted::denominator_minus),
            },
            Mistake {
                words: "e^(i delta) where the round trip needs e^(2 i delta): one crossing's phase",
                source: Source::Chapter,
                check: || airy_r_checks(thinfilm_planted::one_way_phase),
                probe: || airy_probe(thinfilm_planted::one_way_phase),
            },
            Mistake {
                words: "(r23 + r12 z) / (1 + r12 r23 z): r12 and r23 swapped in the numerator",
                source: Source::Swapped,
                check: || airy_r_checks(airy::swapped),
                probe: || airy_probe(airy::swapped),
            },
            Mistake {
                words: "r12 + r23 z / (1 + r12 r23 z): the factor t12 t21 = 1 - r12^2 of the multiply reflected waves left out",
                source: Source::Factor,
                check: || airy_r_checks(airy::without_stokes_factor),
                probe: || airy_probe(airy::without_stokes_factor),
            },
            Mistake {
                words: "r12 + r23 z: two waves, the multiple reflections' denominator left out",
                source: Source::Factor,
                check: || airy_r_checks(airy::two_waves),
                probe: || airy_probe(airy::two_waves),
            },
            Mistake {
                words: "z = e^(-2 i delta): the phase's other sign, which for an evanescent film (complex delta) grows instead of decaying",
                source: Source::Branch,
                check: || airy_r_checks(airy::conjugate_phase),
                probe: || airy_probe(airy::conjugate_phase),
            },
        ],
        alternatives: &[
            Alternative {
                words: "the round trip as (e^(i delta))^2 and the quotient as a product with the reciprocal",
                check: || airy_r_checks(airy::squared_phase),
            },
            Alternative {
                words: "r12 plus the rest of the series, (1 - r12^2) r23 z / (1 + r12 r23 z)",
                check: || airy_r_checks(airy::first_wave_plus_rest),
            },
        ],
    },
];

/// The unpolarised reflectance of amplitudes, as `fresnel_dielectric` builds it from
/// `amplitudes` (`1` under total internal reflection).
fn reflectance(a: Option<Amplitudes>) -> f64 {
    match a {
        Some(a) => 0.5 * (a.r_s * a.r_s + a.r_p * a.r_p),
        None => 1.0,
    }
}

mod airy;
mod amp;
mod approx;
mod lobe;
mod mirror;
mod sellmeier;
mod snell;
mod trans;
