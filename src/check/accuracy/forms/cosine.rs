//! The forms answering `data/corpus/cosine.txt`: [`crate::sampling::cosine`] and its `f32`
//! twin [`crate::single::sampling::cosine`].

use glam::{DVec3, Vec3};

use super::{out3, out3_single, u2, u2_single, v3, v3_single};
use crate::check::accuracy::{Answer, Form};
use crate::sampling::{cosine as double, disc as double_disc};
use crate::single::sampling::{cosine as single, disc as single_disc};

/// The naive lift: `z = sqrt(1 - x^2 - y^2)` from the disc point itself.
fn lift(a: &[f64]) -> DVec3 {
    let point = double_disc::disc_concentric(u2(a));
    let height = (1.0 - point.x * point.x - point.y * point.y)
        .max(0.0)
        .sqrt();
    DVec3::new(point.x, point.y, height)
}

fn lift_single(a: &[f64]) -> Vec3 {
    let point = single_disc::disc_concentric(u2_single(a));
    let height = (1.0 - point.x * point.x - point.y * point.y)
        .max(0.0)
        .sqrt();
    Vec3::new(point.x, point.y, height)
}

fn malley(a: &[f64]) -> DVec3 {
    double::cosine_malley(u2(a))
}

fn malley_single(a: &[f64]) -> Vec3 {
    single::cosine_malley(u2_single(a))
}

fn pdf_of(w: DVec3) -> Answer {
    Some(vec![double::cosine_pdf(w)])
}

fn pdf_of_single(w: Vec3) -> Answer {
    Some(vec![f64::from(single::cosine_pdf(w))])
}

/// Every form of every verb of the corpus.
pub fn forms() -> Vec<Form> {
    let f = Form::stable;
    let single = Form::single;
    let textbook = Form::textbook;
    let named = |name, form: Form| Form { form: name, ..form };
    vec![
        f("cosine_malley", |a| out3(malley(a))),
        textbook(f("cosine_malley", |a| out3(lift(a)))),
        single("cosine_malley", |a| out3_single(malley_single(a))),
        textbook(single("cosine_malley", |a| out3_single(lift_single(a)))),
        f("cosine_malley_pdf", |a| pdf_of(malley(a))),
        textbook(f("cosine_malley_pdf", |a| pdf_of(lift(a)))),
        single("cosine_malley_pdf", |a| pdf_of_single(malley_single(a))),
        textbook(single("cosine_malley_pdf", |a| {
            pdf_of_single(lift_single(a))
        })),
        f("cosine_malley_invert", |a| {
            let u = double_disc::disc_concentric_invert(v3(a));
            Some(vec![u.x, u.y])
        }),
        single("cosine_malley_invert", |a| {
            let u = single_disc::disc_concentric_invert(v3_single(a));
            Some(vec![f64::from(u.x), f64::from(u.y)])
        }),
        named(
            "cartesian",
            f("cosine_seed", |a| {
                out3(double::cosine_seed_cartesian(u2(a)))
            }),
        ),
        named(
            "angles",
            f("cosine_seed", |a| out3(double::cosine_seed_angles(u2(a)))),
        ),
        named(
            "cartesian",
            single("cosine_seed", |a| {
                out3_single(single::cosine_seed_cartesian(u2_single(a)))
            }),
        ),
        named(
            "angles",
            single("cosine_seed", |a| {
                out3_single(single::cosine_seed_angles(u2_single(a)))
            }),
        ),
        named(
            "cartesian",
            f("cosine_seed_pdf", |a| {
                pdf_of(double::cosine_seed_cartesian(u2(a)))
            }),
        ),
        named(
            "angles",
            f("cosine_seed_pdf", |a| {
                pdf_of(double::cosine_seed_angles(u2(a)))
            }),
        ),
        named(
            "cartesian",
            single("cosine_seed_pdf", |a| {
                pdf_of_single(single::cosine_seed_cartesian(u2_single(a)))
            }),
        ),
        named(
            "angles",
            single("cosine_seed_pdf", |a| {
                pdf_of_single(single::cosine_seed_angles(u2_single(a)))
            }),
        ),
        f("cosine_pdf", |a| pdf_of(v3(a))),
        single("cosine_pdf", |a| pdf_of_single(v3_single(a))),
    ]
}
