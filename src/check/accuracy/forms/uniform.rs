//! The forms answering `data/corpus/uniform.txt`: [`crate::sampling::sphere`] and its `f32`
//! twin [`crate::single::sampling::sphere`].

use glam::{DVec2, Vec2};

use super::{out3, out3_single, v3, v3_single};
use crate::check::accuracy::{Answer, Form};
use crate::sampling::sphere as double;
use crate::single::sampling::sphere as single;

fn warp(a: &[f64]) -> Answer {
    out3(double::sphere_inverse_cdf(DVec2::new(a[0], a[1])))
}

fn warp_single(a: &[f64]) -> Answer {
    out3_single(single::sphere_inverse_cdf(Vec2::new(
        a[0] as f32,
        a[1] as f32,
    )))
}

/// The source notes' radius `sqrt(1 - z^2)` of the circle at height `z`.
fn warp_textbook(a: &[f64]) -> Answer {
    let height = 1.0 - 2.0 * a[0];
    let ring = (1.0 - height * height).max(0.0).sqrt();
    let angle = std::f64::consts::TAU * a[1];
    Some(vec![ring * angle.cos(), ring * angle.sin(), height])
}

fn invert(a: &[f64]) -> Answer {
    let u = double::sphere_inverse_cdf_invert(v3(a));
    Some(vec![u.x, u.y])
}

fn invert_single(a: &[f64]) -> Answer {
    let u = single::sphere_inverse_cdf_invert(v3_single(a));
    Some(vec![f64::from(u.x), f64::from(u.y)])
}

fn hemisphere(a: &[f64]) -> Answer {
    let w = double::sphere_inverse_cdf(DVec2::new(a[0], a[1]));
    out3(double::hemisphere_flip(w, v3(&a[2..])))
}

fn hemisphere_single(a: &[f64]) -> Answer {
    let w = single::sphere_inverse_cdf(Vec2::new(a[0] as f32, a[1] as f32));
    out3_single(single::hemisphere_flip(w, v3_single(&a[2..])))
}

fn sphere_pdf(a: &[f64]) -> Answer {
    Some(vec![double::sphere_pdf(v3(a))])
}

fn sphere_pdf_single(a: &[f64]) -> Answer {
    Some(vec![f64::from(single::sphere_pdf(v3_single(a)))])
}

fn hemisphere_pdf(a: &[f64]) -> Answer {
    Some(vec![double::hemisphere_pdf(v3(a), v3(&a[3..]))])
}

fn hemisphere_pdf_single(a: &[f64]) -> Answer {
    Some(vec![f64::from(single::hemisphere_pdf(
        v3_single(a),
        v3_single(&a[3..]),
    ))])
}

/// Every form of every verb of the corpus.
pub fn forms() -> Vec<Form> {
    let f = Form::stable;
    let single = Form::single;
    vec![
        f("sphere_inverse_cdf", warp),
        f("sphere_inverse_cdf", warp_textbook).textbook(),
        single("sphere_inverse_cdf", warp_single),
        f("sphere_invert", invert),
        single("sphere_invert", invert_single),
        f("hemisphere_inverse_cdf", hemisphere),
        single("hemisphere_inverse_cdf", hemisphere_single),
        f("sphere_pdf", sphere_pdf),
        single("sphere_pdf", sphere_pdf_single),
        f("hemisphere_pdf", hemisphere_pdf),
        single("hemisphere_pdf", hemisphere_pdf_single),
    ]
}
