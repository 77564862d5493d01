//! The typical mistakes and correct alternatives of the exercises of the book's spectral
//! chapters (see [`super`]).

use super::{Alternative, Mistake, Table};
use crate::check::display::planted as display_planted;
use crate::check::wavelength::planted as wavelength_planted;
use crate::exercise::mistakes::Source;
use crate::exercise::mistakes::probes::{decodings, encodings, heroes};
use crate::exercise::registry::{hero_uniform_checks, srgb_decode_checks, srgb_encode_checks};

/// This part's tables, in the book's order.
pub const TABLES: &[Table] = &[
    Table {
        exercise: "hero_uniform",
        mistakes: &[
            Mistake {
                words: "lanes rotated without the mod 1: the lanes past 830 nm leave the range (the estimate too dark)",
                source: Source::Chapter,
                check: || hero_uniform_checks(wavelength_planted::without_wrap),
                probe: || heroes(wavelength_planted::without_wrap),
            },
            Mistake {
                words: "each lane weighted by 1 / (N x 470), as if the lanes shared one density: the lanes summed, not averaged (N times too bright)",
                source: Source::Chapter,
                check: || hero_uniform_checks(wavelength_planted::pdf_shared),
                probe: || heroes(wavelength_planted::pdf_shared),
            },
            Mistake {
                words: "the source notes' band: a random wavelength in 380-780 nm and its neighbours 5 nm apart, not lanes spread over the range",
                source: Source::Errata,
                check: || hero_uniform_checks(hero::seed_band),
                probe: || heroes(hero::seed_band),
            },
            Mistake {
                words: "the lanes rotated over 380-780 nm with density 1/400: the constants of another visible range",
                source: Source::Constant,
                check: || hero_uniform_checks(hero::other_range),
                probe: || heroes(hero::other_range),
            },
            Mistake {
                words: "each lane weighted by 470, the range, where its reciprocal 1/470 belongs",
                source: Source::Power,
                check: || hero_uniform_checks(hero::pdf_is_range),
                probe: || heroes(hero::pdf_is_range),
            },
            Mistake {
                words: "hero_pdf left at 0: the hero's own density missing (the hero weighted by nothing once the other lanes terminate)",
                source: Source::Factor,
                check: || hero_uniform_checks(hero::hero_pdf_missing),
                probe: || heroes(hero::hero_pdf_missing),
            },
            Mistake {
                words: "the wrap applied to the wavelength itself (mod 470 nm) instead of to its offset from 360 nm: lanes below 360 nm",
                source: Source::Branch,
                check: || hero_uniform_checks(hero::wrapped_wavelength),
                probe: || heroes(hero::wrapped_wavelength),
            },
        ],
        alternatives: &[
            Alternative {
                words: "the offset u + j/N wrapped by an explicit if (>= 1 subtracts 1)",
                check: || hero_uniform_checks(hero::explicit_if),
            },
            Alternative {
                words: "the lanes stepped in nanometres from the hero, 470/N apart, those past 830 nm moved down by 470",
                check: || hero_uniform_checks(hero::in_nanometres),
            },
        ],
    },
    Table {
        exercise: "srgb_encode",
        mistakes: &[
            Mistake {
                words: "x^(1/2.2): the source notes' pure power law, not the sRGB curve",
                source: Source::Errata,
                check: || srgb_encode_checks(srgb::gamma_2_2),
                probe: || encodings(srgb::gamma_2_2),
            },
            Mistake {
                words: "x^2.2: the gamma applied the wrong way (linear 0.5 becomes code 55, not 188)",
                source: Source::Chapter,
                check: || srgb_encode_checks(srgb::gamma_wrong_way),
                probe: || encodings(srgb::gamma_wrong_way),
            },
            Mistake {
                words: "1.055 x^2.4 - 0.055: the power 2.4 where 1/2.4 belongs (the decoding's exponent)",
                source: Source::Power,
                check: || srgb_encode_checks(srgb::power_2_4),
                probe: || encodings(srgb::power_2_4),
            },
            Mistake {
                words: "the breakpoint 0.04045 (the decoding's, an encoded value) on the linear side: the straight segment thirteen times too long",
                source: Source::Constant,
                check: || srgb_encode_checks(display_planted::encode_with_the_encoded_breakpoint),
                probe: || encodings(display_planted::encode_with_the_encoded_breakpoint),
            },
            Mistake {
                words: "1.055 x^(1/2.4) without the offset - 0.055: above 1 at x = 1",
                source: Source::Factor,
                check: || srgb_encode_checks(display_planted::encode_without_offset),
                probe: || encodings(display_planted::encode_without_offset),
            },
            Mistake {
                words: "x / 12.92 near black: the decoding's straight segment",
                source: Source::Swapped,
                check: || srgb_encode_checks(srgb::encode_divides),
                probe: || encodings(srgb::encode_divides),
            },
            Mistake {
                words: "x >= 0.0031308 on the power segment: the breakpoint itself encoded by the power (the standard puts it on the straight segment)",
                source: Source::Branch,
                check: || srgb_encode_checks(srgb::encode_breakpoint_above),
                probe: || encodings(srgb::encode_breakpoint_above),
            },
            Mistake {
                words: "12.92 x for everything below the breakpoint: negative inputs not clamped to 0 (and NaN kept)",
                source: Source::Branch,
                check: || srgb_encode_checks(srgb::encode_unclamped),
                probe: || encodings(srgb::encode_unclamped),
            },
        ],
        alternatives: &[
            Alternative {
                words: "an early return of 0 for NaN and x <= 0, then the segments with the power written as a fused multiply-add",
                check: || srgb_encode_checks(srgb::encode_early_return),
            },
            Alternative {
                words: "the power x^(1/2.4) as exp(ln(x) / 2.4), the segments in a match",
                check: || srgb_encode_checks(srgb::encode_by_logarithm),
            },
        ],
    },
    Table {
        exercise: "srgb_decode",
        mistakes: &[
            Mistake {
                words: "V^2.2: the source notes' pure power law, not the sRGB curve",
                source: Source::Errata,
                check: || srgb_decode_checks(srgb::decode_gamma_2_2),
                probe: || decodings(srgb::decode_gamma_2_2),
            },
            Mistake {
                words: "V^(1/2.2): the gamma applied the wrong way (the encoding's direction)",
                source: Source::Chapter,
                check: || srgb_decode_checks(srgb::decode_wrong_way),
                probe: || decodings(srgb::decode_wrong_way),
            },
            Mistake {
                words: "((V + 0.055) / 1.055)^(1/2.4): the power 1/2.4 where 2.4 belongs (the encoding's exponent)",
                source: Source::Power,
                check: || srgb_decode_checks(srgb::decode_root),
                probe: || decodings(srgb::decode_root),
            },
            Mistake {
                words: "the breakpoint 0.0031308 (the encoding's, a linear value) on the encoded side: the power used down to near black",
                source: Source::Constant,
                check: || srgb_decode_checks(srgb::decode_linear_breakpoint),
                probe: || decodings(srgb::decode_linear_breakpoint),
            },
            Mistake {
                words: "(V / 1.055)^2.4: the offset + 0.055 left out",
                source: Source::Factor,
                check: || srgb_decode_checks(srgb::decode_without_offset),
                probe: || decodings(srgb::decode_without_offset),
            },
            Mistake {
                words: "12.92 V near black: the encoding's straight segment",
                source: Source::Swapped,
                check: || srgb_decode_checks(srgb::decode_multiplies),
                probe: || decodings(srgb::decode_multiplies),
            },
            Mistake {
                words: "V >= 0.04045 on the power segment: the breakpoint itself decoded by the power (the standard puts it on the straight segment)",
                source: Source::Branch,
                check: || srgb_decode_checks(srgb::decode_breakpoint_above),
                probe: || decodings(srgb::decode_breakpoint_above),
            },
            Mistake {
                words: "V / 12.92 for everything below the breakpoint: negative inputs not clamped to 0 (and NaN kept)",
                source: Source::Branch,
                check: || srgb_decode_checks(srgb::decode_unclamped),
                probe: || decodings(srgb::decode_unclamped),
            },
        ],
        alternatives: &[
            Alternative {
                words: "an early return of 0 for NaN and V <= 0, the straight segment as V times 1/12.92",
                check: || srgb_decode_checks(srgb::decode_early_return),
            },
            Alternative {
                words: "the power as exp(2.4 ln((V + 0.055) / 1.055)), the segments in a match",
                check: || srgb_decode_checks(srgb::decode_by_logarithm),
            },
        ],
    },
];

/// Twins and alternatives of `hero_uniform`.
mod hero {
    use crate::spectral::wavelength::{self, N, RANGE, SEED_BAND, Wavelengths};
    use crate::spectral::{LAMBDA_MAX, LAMBDA_MIN};

    fn lanes(u: f64, lo: f64, range: f64) -> [f64; N] {
        std::array::from_fn(|j| lo + ((u + j as f64 / N as f64) % 1.0) * range)
    }

    pub fn seed_band(u: f64) -> Wavelengths {
        wavelength::seed_band(u, &SEED_BAND)
    }

    pub fn other_range(u: f64) -> Wavelengths {
        Wavelengths {
            lambda: lanes(u, 380.0, 400.0),
            pdf: [1.0 / 400.0; N],
            hero_pdf: 1.0 / 400.0,
        }
    }

    pub fn pdf_is_range(u: f64) -> Wavelengths {
        Wavelengths {
            lambda: lanes(u, LAMBDA_MIN, RANGE),
            pdf: [RANGE; N],
            hero_pdf: RANGE,
        }
    }

    pub fn hero_pdf_missing(u: f64) -> Wavelengths {
        Wavelengths {
            lambda: lanes(u, LAMBDA_MIN, RANGE),
            pdf: [RANGE.recip(); N],
            hero_pdf: 0.0,
        }
    }

    pub fn wrapped_wavelength(u: f64) -> Wavelengths {
        Wavelengths {
            lambda: std::array::from_fn(|j| {
                (LAMBDA_MIN + (u + j as f64 / N as f64) * RANGE) % RANGE
            }),
            pdf: [RANGE.recip(); N],
            hero_pdf: RANGE.recip(),
        }
    }

    pub fn explicit_if(u: f64) -> Wavelengths {
        let mut lambda = [0.0; N];
        for (j, l) in lambda.iter_mut().enumerate() {
            let mut x = u + j as f64 / N as f64;
            if x >= 1.0 {
                x -= 1.0;
            }
            *l = LAMBDA_MIN + x * RANGE;
        }
        Wavelengths {
            lambda,
            pdf: [RANGE.recip(); N],
            hero_pdf: RANGE.recip(),
        }
    }

    pub fn in_nanometres(u: f64) -> Wavelengths {
        let hero = LAMBDA_MIN + u * (LAMBDA_MAX - LAMBDA_MIN);
        let step = (LAMBDA_MAX - LAMBDA_MIN) / N as f64;
        let lambda = std::array::from_fn(|j| {
            let l = hero + j as f64 * step;
            if l > LAMBDA_MAX { l - RANGE } else { l }
        });
        let pdf = (LAMBDA_MAX - LAMBDA_MIN).recip();
        Wavelengths {
            lambda,
            pdf: [pdf; N],
            hero_pdf: pdf,
        }
    }
}

/// Twins and alternatives of `srgb_encode` and `srgb_decode`.
mod srgb {
    const LINEAR_BREAK: f64 = 0.003_130_8;
    const ENCODED_BREAK: f64 = 0.040_45;

    pub fn gamma_2_2(x: f64) -> f64 {
        if x > 0.0 { x.powf(1.0 / 2.2) } else { 0.0 }
    }

    pub fn gamma_wrong_way(x: f64) -> f64 {
        if x > 0.0 { x.powf(2.2) } else { 0.0 }
    }

    pub fn power_2_4(x: f64) -> f64 {
        if x > LINEAR_BREAK {
            1.055 * x.powf(2.4) - 0.055
        } else if x > 0.0 {
            12.92 * x
        } else {
            0.0
        }
    }

    pub fn encode_divides(x: f64) -> f64 {
        if x > LINEAR_BREAK {
            1.055 * x.powf(2.4_f64.recip()) - 0.055
        } else if x > 0.0 {
            x / 12.92
        } else {
            0.0
        }
    }

    pub fn encode_breakpoint_above(x: f64) -> f64 {
        if x >= LINEAR_BREAK {
            1.055 * x.powf(2.4_f64.recip()) - 0.055
        } else if x > 0.0 {
            12.92 * x
        } else {
            0.0
        }
    }

    pub fn encode_unclamped(x: f64) -> f64 {
        if x > LINEAR_BREAK {
            1.055 * x.powf(2.4_f64.recip()) - 0.055
        } else {
            12.92 * x
        }
    }

    pub fn encode_early_return(x: f64) -> f64 {
        if x.is_nan() || x <= 0.0 {
            return 0.0;
        }
        if x <= LINEAR_BREAK {
            x * 12.92
        } else {
            x.powf(2.4_f64.recip()).mul_add(1.055, -0.055)
        }
    }

    pub fn encode_by_logarithm(x: f64) -> f64 {
        match x {
            x if x > LINEAR_BREAK => 1.055 * (x.ln() / 2.4).exp() - 0.055,
            x if x > 0.0 => 12.92 * x,
            _ => 0.0,
        }
    }

    pub fn decode_gamma_2_2(v: f64) -> f64 {
        if v > 0.0 { v.powf(2.2) } else { 0.0 }
    }

    pub fn decode_wrong_way(v: f64) -> f64 {
        if v > 0.0 { v.powf(1.0 / 2.2) } else { 0.0 }
    }

    pub fn decode_root(v: f64) -> f64 {
        if v > ENCODED_BREAK {
            ((v + 0.055) / 1.055).powf(1.0 / 2.4)
        } else if v > 0.0 {
            v / 12.92
        } else {
            0.0
        }
    }

    pub fn decode_linear_breakpoint(v: f64) -> f64 {
        if v > LINEAR_BREAK {
            ((0.055 + v) / 1.055).powf(2.4)
        } else if v > 0.0 {
            v / 12.92
        } else {
            0.0
        }
    }

    pub fn decode_without_offset(v: f64) -> f64 {
        if v > ENCODED_BREAK {
            (v / 1.055).powf(2.4)
        } else if v > 0.0 {
            v / 12.92
        } else {
            0.0
        }
    }

    pub fn decode_multiplies(v: f64) -> f64 {
        if v > ENCODED_BREAK {
            ((0.055 + v) / 1.055).powf(2.4)
        } else if v > 0.0 {
            12.92 * v
        } else {
            0.0
        }
    }

    pub fn decode_breakpoint_above(v: f64) -> f64 {
        if v >= ENCODED_BREAK {
            ((0.055 + v) / 1.055).powf(2.4)
        } else if v > 0.0 {
            v / 12.92
        } else {
            0.0
        }
    }

    pub fn decode_unclamped(v: f64) -> f64 {
        if v > ENCODED_BREAK {
            ((0.055 + v) / 1.055).powf(2.4)
        } else {
            v / 12.92
        }
    }

    pub fn decode_early_return(v: f64) -> f64 {
        if v.is_nan() || v <= 0.0 {
            return 0.0;
        }
        if v <= ENCODED_BREAK {
            v * (1.0 / 12.92)
        } else {
            ((0.055 + v) / 1.055).powf(2.4)
        }
    }

    pub fn decode_by_logarithm(v: f64) -> f64 {
        match v {
            v if v > ENCODED_BREAK => (2.4 * ((v + 0.055) / 1.055).ln()).exp(),
            v if v > 0.0 => v / 12.92,
            _ => 0.0,
        }
    }
}
