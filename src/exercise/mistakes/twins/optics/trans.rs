//! Twins and alternatives of `fresnel_transmittance`.

use super::amp::via_sines as amplitudes;
use crate::optics::fresnel::{Polarized, cos_transmitted};

/// Everything transmitted.
const ALL: Polarized = Polarized { s: 1.0, p: 1.0 };
/// Nothing transmitted.
const NOTHING: Polarized = Polarized { s: 0.0, p: 0.0 };

pub fn without_beam_factor(cos_i: f64, n1: f64, n2: f64) -> Polarized {
    match amplitudes(cos_i, n1, n2) {
        Some(a) => Polarized {
            s: a.t_s * a.t_s,
            p: a.t_p * a.t_p,
        },
        None => NOTHING,
    }
}

pub fn beam_factor_upside_down(cos_i: f64, n1: f64, n2: f64) -> Polarized {
    let ci = cos_i.abs().min(1.0);
    match amplitudes(cos_i, n1, n2) {
        Some(a) if ci > 0.0 && a.cos_t > 0.0 => {
            let k = (n1 * ci) / (n2 * a.cos_t);
            Polarized {
                s: (k * a.t_s * a.t_s).min(1.0),
                p: (k * a.t_p * a.t_p).min(1.0),
            }
        }
        Some(_) if n1 == n2 => ALL,
        _ => NOTHING,
    }
}

/// The library's transmittance with `4ab / den` replaced by `t(a, b, den)`.
fn with_formula(cos_i: f64, n1: f64, n2: f64, t: fn(f64, f64, f64) -> f64) -> Polarized {
    if n1 == n2 {
        return ALL;
    }
    let ci = cos_i.abs().min(1.0);
    let Some(cos_t) = cos_transmitted(ci, n1, n2) else {
        return NOTHING;
    };
    let (a, b, d, e) = (n1 * ci, n2 * cos_t, n2 * ci, n1 * cos_t);
    if a + b == 0.0 {
        return NOTHING;
    }
    Polarized {
        s: t(a, b, a + b).min(1.0),
        p: t(a, b, d + e).min(1.0),
    }
}

pub fn unsquared_denominator(cos_i: f64, n1: f64, n2: f64) -> Polarized {
    with_formula(cos_i, n1, n2, |a, b, den| 4.0 * a * b / den)
}

pub fn two_ab(cos_i: f64, n1: f64, n2: f64) -> Polarized {
    with_formula(cos_i, n1, n2, |a, b, den| 2.0 * a * b / (den * den))
}

pub fn tir_transmits(cos_i: f64, n1: f64, n2: f64) -> Polarized {
    if n1 == n2 {
        return ALL;
    }
    let ci = cos_i.abs().min(1.0);
    let Some(cos_t) = cos_transmitted(ci, n1, n2) else {
        return ALL;
    };
    let (a, b, d, e) = (n1 * ci, n2 * cos_t, n2 * ci, n1 * cos_t);
    if a + b == 0.0 {
        return NOTHING;
    }
    Polarized {
        s: (4.0 * a * b / ((a + b) * (a + b))).min(1.0),
        p: (4.0 * a * b / ((d + e) * (d + e))).min(1.0),
    }
}

pub fn no_matched_case(cos_i: f64, n1: f64, n2: f64) -> Polarized {
    let ci = cos_i.abs().min(1.0);
    let Some(cos_t) = cos_transmitted(ci, n1, n2) else {
        return NOTHING;
    };
    let (a, b, d, e) = (n1 * ci, n2 * cos_t, n2 * ci, n1 * cos_t);
    if a + b == 0.0 {
        return NOTHING;
    }
    Polarized {
        s: (4.0 * a * b / ((a + b) * (a + b))).min(1.0),
        p: (4.0 * a * b / ((d + e) * (d + e))).min(1.0),
    }
}

pub fn one_minus_r2(cos_i: f64, n1: f64, n2: f64) -> Polarized {
    match amplitudes(cos_i, n1, n2) {
        Some(a) => Polarized {
            s: 1.0 - a.r_s * a.r_s,
            p: 1.0 - a.r_p * a.r_p,
        },
        None => NOTHING,
    }
}

pub fn beam_factor_written_out(cos_i: f64, n1: f64, n2: f64) -> Polarized {
    let ci = cos_i.abs().min(1.0);
    let Some(a) = amplitudes(cos_i, n1, n2) else {
        return NOTHING;
    };
    if n1 == n2 {
        ALL
    } else if ci == 0.0 {
        NOTHING
    } else {
        // (n2 cos_t / (n1 cos_i)) t^2, divided so that a subnormal cos_i cannot
        // overflow the beam factor.
        let beam = n2 * a.cos_t / n1;
        Polarized {
            s: (beam * (a.t_s / ci) * a.t_s).min(1.0),
            p: (beam * (a.t_p / ci) * a.t_p).min(1.0),
        }
    }
}
