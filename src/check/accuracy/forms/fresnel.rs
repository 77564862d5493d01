//! The forms answering `data/corpus/fresnel.txt`: [`crate::optics::fresnel`].

use crate::check::accuracy::{Answer, Expect, Form, Precision};
use crate::optics::fresnel::{
    FresnelFit, amplitudes, fresnel_dielectric, fresnel_transmittance, schlick,
};

fn amplitudes_form(a: &[f64]) -> Answer {
    amplitudes(a[0], a[1], a[2]).map(|a| vec![a.r_s, a.r_p, a.t_s, a.t_p])
}

fn reflectance(a: &[f64]) -> Answer {
    Some(vec![fresnel_dielectric(a[0], a[1], a[2])])
}

fn transmittance(a: &[f64]) -> Answer {
    let t = fresnel_transmittance(a[0], a[1], a[2]);
    Some(vec![t.s, t.p])
}

/// The textbook reflectance: `cos_t = sqrt(1 - eta^2 (1 - cos_i^2))` (one subtraction
/// from 1 instead of the chapter's sum of two non-negative terms), the rest as the
/// chapter's.
fn textbook_reflectance(a: &[f64]) -> Answer {
    let (c, n1, n2) = (a[0].abs().min(1.0), a[1], a[2]);
    if n1 == n2 {
        return Some(vec![0.0]);
    }
    let ratio = n1 / n2;
    let cos2_t = 1.0 - ratio * ratio * (1.0 - c * c);
    if cos2_t < 0.0 {
        return Some(vec![1.0]);
    }
    let root = cos2_t.sqrt();
    let s_wave = (n1 * c - n2 * root) / (n1 * c + n2 * root);
    let p_wave = (n2 * c - n1 * root) / (n2 * c + n1 * root);
    Some(vec![0.5 * (s_wave * s_wave + p_wave * p_wave)])
}

fn schlick_form(a: &[f64]) -> Answer {
    Some(vec![schlick(a[0], a[1], a[2])])
}

fn fit(a: &[f64]) -> Answer {
    Some(vec![FresnelFit::new(a[0], a[1]).eval(a[2])])
}

/// Every form of every verb of the corpus.
pub fn forms() -> Vec<Form> {
    let f = Form::stable;
    vec![
        f("fresnel_amplitudes", amplitudes_form),
        f("fresnel", reflectance),
        Form::new(
            "fresnel",
            "textbook",
            Precision::Double,
            Expect::Within,
            textbook_reflectance,
        ),
        f("fresnel_transmittance", transmittance),
        f("schlick", schlick_form),
        f("fresnel_fit", fit),
    ]
}
