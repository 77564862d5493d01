//! The forms answering `data/corpus/frame.txt`: [`crate::sampling::frame`] and its `f32`
//! twin.

use glam::{DVec3, Vec3};

use super::{v3, v3_single};
use crate::check::accuracy::{Answer, Expect, Form, Precision};
use crate::sampling::frame;
use crate::single::sampling::frame as frame32;

fn double(construct: fn(DVec3) -> (DVec3, DVec3), a: &[f64]) -> Answer {
    let (t, b) = construct(v3(a));
    Some(vec![t.x, t.y, t.z, b.x, b.y, b.z])
}

fn single(construct: fn(Vec3) -> (Vec3, Vec3), a: &[f64]) -> Answer {
    let (t, b) = construct(v3_single(a));
    Some([t.x, t.y, t.z, b.x, b.y, b.z].map(f64::from).to_vec())
}

fn duff(a: &[f64]) -> Answer {
    double(frame::duff, a)
}
fn duff32(a: &[f64]) -> Answer {
    single(frame32::duff, a)
}
fn frisvad(a: &[f64]) -> Answer {
    double(frame::frisvad, a)
}
fn frisvad32(a: &[f64]) -> Answer {
    single(frame32::frisvad, a)
}
fn cross(a: &[f64]) -> Answer {
    double(frame::cross_product_frame, a)
}
fn cross32(a: &[f64]) -> Answer {
    single(frame32::cross_product_frame, a)
}

/// Every form of every verb of the corpus.
pub fn forms() -> Vec<Form> {
    let f = Form::new;
    use Expect::Within;
    use Precision::{Double as F64, Single as F32};
    vec![
        f("frame_duff", "stable", F64, Within, duff),
        f("frame_duff", "stable", F32, Within, duff32),
        f("frame_frisvad", "textbook", F64, Within, frisvad),
        f("frame_frisvad", "textbook", F32, Within, frisvad32),
        f("frame_cross", "stable", F64, Within, cross),
        f("frame_cross", "stable", F32, Within, cross32),
    ]
}
