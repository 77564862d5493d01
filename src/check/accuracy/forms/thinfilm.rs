//! The forms answering `data/corpus/thinfilm.txt`: [`crate::optics::thinfilm`], one film's
//! reflectances and transmittances for s and p light.

use num_complex::Complex64;

use crate::check::accuracy::{Answer, Expect, Form, Precision};
use crate::optics::thinfilm::{Film, airy_r, airy_t, cos_theta, interface, phase};

/// [`Film::response_cos`], the rearranged Airy sum the renderer uses.
fn stable(a: &[f64]) -> Answer {
    let r = Film::new(a[0], a[1], a[2], a[3]).response_cos(a[4], a[5]);
    Some(vec![
        r.reflectance_s,
        r.reflectance_p,
        r.transmittance_s,
        r.transmittance_p,
    ])
}

/// The plain Airy sums [`airy_r`] and [`airy_t`] of the two interfaces' Fresnel
/// coefficients ([`interface`]), the chapter's first form.
fn plain(a: &[f64]) -> Answer {
    let (n1, n2, n3, d, nm, cos1) = (a[0], a[1], a[2], a[3], a[4], a[5]);
    let ambient = Complex64::new(cos1, 0.0);
    let (inside, below) = (cos_theta(n1, cos1, n2), cos_theta(n1, cos1, n3));
    let top = interface(n1, ambient, n2, inside);
    let bottom = interface(n2, inside, n3, below);
    let delta = phase(n2, d, inside, nm);
    let power = (below * n3).re / (n1 * cos1);
    let (rs, rp) = (
        airy_r(top.r_s, bottom.r_s, delta),
        airy_r(top.r_p, bottom.r_p, delta),
    );
    let ts = airy_t(top.r_s, bottom.r_s, top.t_s, bottom.t_s, delta);
    let tp = airy_t(top.r_p, bottom.r_p, top.t_p, bottom.t_p, delta);
    Some(vec![
        rs.norm_sqr(),
        rp.norm_sqr(),
        power * ts.norm_sqr(),
        power * tp.norm_sqr(),
    ])
}

/// Every form of every verb of the corpus.
pub fn forms() -> Vec<Form> {
    vec![
        Form::new("film", "stable", Precision::Double, Expect::Within, stable),
        Form::new(
            "film",
            "plain Airy sum",
            Precision::Double,
            Expect::Exceeds,
            plain,
        ),
    ]
}
