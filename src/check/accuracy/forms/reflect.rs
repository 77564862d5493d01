//! The forms answering `data/corpus/reflect.txt`: [`crate::optics::reflect`].

use super::v3;
use crate::check::accuracy::{Answer, Expect, Form, Precision};
use crate::optics::reflect::{reflect, refract};

fn reflect_form(a: &[f64]) -> Answer {
    Some(reflect(v3(&a[0..3]), v3(&a[3..6])).to_array().to_vec())
}

fn refract_form(a: &[f64]) -> Answer {
    refract(v3(&a[0..3]), v3(&a[3..6]), a[6], a[7])
        .transmitted()
        .map(|w| w.to_array().to_vec())
}

/// The textbook refraction: `cos_t^2 = 1 - eta^2 (1 - cos_i^2)`, one subtraction from 1
/// instead of the chapter's `(1 - eta^2) + (eta cos_i)^2`, the rest as the chapter's.
fn textbook_refract(a: &[f64]) -> Answer {
    let (dir, mut facing) = (v3(&a[0..3]), v3(&a[3..6]));
    let mut cosine = -dir.dot(facing);
    if cosine < 0.0 {
        facing = -facing;
        cosine = -cosine;
    }
    let ratio = a[6] / a[7];
    let under_root = 1.0 - ratio * ratio * (1.0 - cosine * cosine);
    if under_root < 0.0 {
        return None;
    }
    let along = ratio * cosine - under_root.sqrt();
    Some((ratio * dir + along * facing).to_array().to_vec())
}

/// Every form of every verb of the corpus.
pub fn forms() -> Vec<Form> {
    let f = |verb, form, expect, eval| Form::new(verb, form, Precision::Double, expect, eval);
    vec![
        f("reflect", "stable", Expect::Within, reflect_form),
        f("refract", "stable", Expect::Within, refract_form),
        f("refract", "textbook", Expect::Within, textbook_refract),
    ]
}
