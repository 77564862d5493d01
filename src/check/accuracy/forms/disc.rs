//! The forms answering `data/corpus/disc.txt`: [`crate::sampling::disc`] and its `f32`
//! twin [`crate::single::sampling::disc`].

use glam::{DVec2, DVec3, Vec2, Vec3};

use super::{u2, u2_single};
use crate::check::accuracy::{Answer, Expect, Form, Precision};
use crate::sampling::disc as double;
use crate::single::sampling::disc as single;

fn p3(a: &[f64]) -> DVec3 {
    DVec3::new(a[0], a[1], 0.0)
}

fn p3_single(a: &[f64]) -> Vec3 {
    Vec3::new(a[0] as f32, a[1] as f32, 0.0)
}

fn xy(p: DVec3) -> Answer {
    Some(vec![p.x, p.y])
}

fn xy_single(p: Vec3) -> Answer {
    Some(vec![f64::from(p.x), f64::from(p.y)])
}

fn pair(u: DVec2) -> Answer {
    Some(vec![u.x, u.y])
}

fn pair_single(u: Vec2) -> Answer {
    Some(vec![f64::from(u.x), f64::from(u.y)])
}

/// The concentric map as the paper and pbrt write it: the wedge angle `phi` itself
/// (`pi/2 - psi` in the second wedge), then the library's `cos` and `sin` of it.
fn concentric_library(a: &[f64]) -> Answer {
    let (sx, sy) = (2.0 * a[0] - 1.0, 2.0 * a[1] - 1.0);
    if sx == 0.0 && sy == 0.0 {
        return Some(vec![0.0, 0.0]);
    }
    let quarter = std::f64::consts::FRAC_PI_4;
    let (radius, angle) = if sy.abs() < sx.abs() {
        (sx, quarter * (sy / sx))
    } else {
        (sy, std::f64::consts::FRAC_PI_2 - quarter * (sx / sy))
    };
    Some(vec![radius * angle.cos(), radius * angle.sin()])
}

/// Every form of every verb of the corpus.
pub fn forms() -> Vec<Form> {
    let f = Form::stable;
    let single = Form::single;
    vec![
        f("disc_concentric", |a| xy(double::disc_concentric(u2(a)))),
        Form::new(
            "disc_concentric",
            "textbook",
            Precision::Double,
            Expect::Within,
            concentric_library,
        ),
        single("disc_concentric", |a| {
            xy_single(single::disc_concentric(u2_single(a)))
        }),
        f("disc_polar", |a| xy(double::disc_polar(u2(a)))),
        single("disc_polar", |a| {
            xy_single(single::disc_polar(u2_single(a)))
        }),
        f("disc_concentric_invert", |a| {
            pair(double::disc_concentric_invert(p3(a)))
        }),
        single("disc_concentric_invert", |a| {
            pair_single(single::disc_concentric_invert(p3_single(a)))
        }),
        f("disc_polar_invert", |a| {
            pair(double::disc_polar_invert(p3(a)))
        }),
        single("disc_polar_invert", |a| {
            pair_single(single::disc_polar_invert(p3_single(a)))
        }),
        f("disc_pdf", |a| Some(vec![double::disc_pdf(p3(a))])),
        single("disc_pdf", |a| {
            Some(vec![f64::from(single::disc_pdf(p3_single(a)))])
        }),
    ]
}
