//! Twins and alternatives of `amplitudes`.

use crate::optics::fresnel::Amplitudes;

// The right amplitudes computed here, not the crate's (a stub in the hand-out).
use via_sines as amplitudes;

/// Born & Wolf's amplitudes from the two cosines.
fn from_cosines(c: f64, cos_t: f64, n1: f64, n2: f64) -> Amplitudes {
    let (a, b, d, e) = (n1 * c, n2 * cos_t, n2 * c, n1 * cos_t);
    Amplitudes {
        r_s: (a - b) / (a + b),
        r_p: (d - e) / (d + e),
        t_s: 2.0 * a / (a + b),
        t_p: 2.0 * a / (d + e),
        cos_t,
    }
}

pub fn naive(cos_i: f64, n1: f64, n2: f64) -> Option<Amplitudes> {
    let c = cos_i.abs().min(1.0);
    let ratio = n1 / n2;
    let cos_t = (1.0 - ratio * ratio * (1.0 - c * c)).sqrt();
    Some(from_cosines(c, cos_t, n1, n2))
}

pub fn p_like_s(cos_i: f64, n1: f64, n2: f64) -> Option<Amplitudes> {
    let a = amplitudes(cos_i, n1, n2)?;
    Some(Amplitudes { r_p: a.r_s, ..a })
}

/// The library's amplitudes with `cos_t` from `cos_of_t`, `None` where it is.
fn with_cos_t(
    cos_i: f64,
    n1: f64,
    n2: f64,
    cos_of_t: fn(f64, f64) -> Option<f64>,
) -> Option<Amplitudes> {
    let c = cos_i.abs().min(1.0);
    if n1 == n2 {
        return amplitudes(cos_i, n1, n2);
    }
    Some(from_cosines(c, cos_of_t(c, n1 / n2)?, n1, n2))
}

pub fn eta_upside_down(cos_i: f64, n1: f64, n2: f64) -> Option<Amplitudes> {
    with_cos_t(cos_i, n1, n2, |c, ratio| {
        let cos2_t = 1.0 - (1.0 - c * c) / (ratio * ratio);
        (cos2_t >= 0.0).then(|| cos2_t.sqrt())
    })
}

pub fn no_sqrt(cos_i: f64, n1: f64, n2: f64) -> Option<Amplitudes> {
    with_cos_t(cos_i, n1, n2, |c, ratio| {
        let cos2_t = 1.0 - ratio * ratio * (1.0 - c * c);
        (cos2_t >= 0.0).then_some(cos2_t)
    })
}

pub fn s_without_n2(cos_i: f64, n1: f64, n2: f64) -> Option<Amplitudes> {
    let a = amplitudes(cos_i, n1, n2)?;
    let (x, y) = (n1 * cos_i.abs().min(1.0), a.cos_t);
    Some(Amplitudes {
        r_s: (x - y) / (x + y),
        ..a
    })
}

pub fn signed_cosine(cos_i: f64, n1: f64, n2: f64) -> Option<Amplitudes> {
    let c = cos_i.min(1.0);
    if n1 == n2 {
        return amplitudes(cos_i, n1, n2);
    }
    let ratio = n1 / n2;
    let cos2_t = (1.0 - ratio * ratio) + (ratio * c) * (ratio * c);
    if cos2_t < 0.0 {
        return None;
    }
    Some(from_cosines(c, cos2_t.sqrt(), n1, n2))
}

pub fn via_sines(cos_i: f64, n1: f64, n2: f64) -> Option<Amplitudes> {
    let c = cos_i.abs().min(1.0);
    if n1 == n2 {
        return Some(Amplitudes {
            r_s: 0.0,
            r_p: 0.0,
            t_s: 1.0,
            t_p: 1.0,
            cos_t: c,
        });
    }
    let sin_t = n1 / n2 * ((1.0 - c) * (1.0 + c)).sqrt();
    if sin_t > 1.0 {
        return None;
    }
    let cos_t = ((1.0 - sin_t) * (1.0 + sin_t)).sqrt();
    let r_s = (n1 * c - n2 * cos_t) / (n1 * c + n2 * cos_t);
    let r_p = (n2 * c - n1 * cos_t) / (n2 * c + n1 * cos_t);
    Some(Amplitudes {
        r_s,
        r_p,
        t_s: 1.0 + r_s,
        t_p: n1 / n2 * (1.0 + r_p),
        cos_t,
    })
}

pub fn t_first(cos_i: f64, n1: f64, n2: f64) -> Option<Amplitudes> {
    let c = cos_i.abs().min(1.0);
    if n1 == n2 {
        return Some(Amplitudes {
            r_s: 0.0,
            r_p: 0.0,
            t_s: 1.0,
            t_p: 1.0,
            cos_t: c,
        });
    }
    let cos_t = crate::optics::fresnel::cos_transmitted(c, n1, n2)?;
    let (s_den, p_den) = (n1 * c + n2 * cos_t, n2 * c + n1 * cos_t);
    let t_s = 2.0 * n1 * c / s_den;
    let t_p = 2.0 * n1 * c / p_den;
    Some(Amplitudes {
        r_s: t_s - 1.0,
        r_p: 2.0 * n2 * c / p_den - 1.0,
        t_s,
        t_p,
        cos_t,
    })
}
