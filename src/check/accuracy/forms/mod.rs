//! The crate's routines as answers to the corpora's questions: one file per corpus
//! (`data/corpus/NAME.txt` ↔ `forms/NAME.rs`), each listing every form of every verb
//! (textbook, stable, `f32` twin) with what the chapter says of it.

use glam::{DVec2, DVec3, Vec2, Vec3};

use super::{Answer, Form};

mod colour;
mod cosine;
mod disc;
mod dispersion;
mod display;
mod frame;
mod fresnel;
mod reflect;
mod shadow;
mod sphere;
mod tabulated;
mod thinfilm;
mod uniform;
mod wavelength;

/// The corpora with forms, in book order (`tools/exact/exact.py` lists the same).
pub const CORPORA: [&str; 14] = [
    "sphere",
    "uniform",
    "disc",
    "cosine",
    "tabulated",
    "frame",
    "reflect",
    "fresnel",
    "dispersion",
    "thinfilm",
    "shadow",
    "colour",
    "wavelength",
    "display",
];

/// The forms that answer the corpus `name` (e.g. `"fresnel"`), or `None` for a corpus no
/// routine of the crate answers.
pub fn of(name: &str) -> Option<Vec<Form>> {
    Some(match name {
        "sphere" => sphere::forms(),
        "uniform" => uniform::forms(),
        "disc" => disc::forms(),
        "cosine" => cosine::forms(),
        "tabulated" => tabulated::forms(),
        "frame" => frame::forms(),
        "reflect" => reflect::forms(),
        "fresnel" => fresnel::forms(),
        "dispersion" => dispersion::forms(),
        "thinfilm" => thinfilm::forms(),
        "shadow" => shadow::forms(),
        "colour" => colour::forms(),
        "wavelength" => wavelength::forms(),
        "display" => display::forms(),
        _ => return None,
    })
}

// The arguments and answers of the verbs, as the routines take and give them: shared by
// every corpus's forms.

/// The first two arguments as a point of the square.
fn u2(a: &[f64]) -> DVec2 {
    DVec2::new(a[0], a[1])
}

/// The same, rounded to singles (the arguments of an `f32` form are singles already).
fn u2_single(a: &[f64]) -> Vec2 {
    Vec2::new(a[0] as f32, a[1] as f32)
}

/// Three arguments from `a[0]` as a vector.
fn v3(a: &[f64]) -> DVec3 {
    DVec3::new(a[0], a[1], a[2])
}

/// The same, as singles.
fn v3_single(a: &[f64]) -> Vec3 {
    Vec3::new(a[0] as f32, a[1] as f32, a[2] as f32)
}

/// A direction's components as the answer.
fn out3(w: DVec3) -> Answer {
    Some(vec![w.x, w.y, w.z])
}

/// A single-precision direction's components as the answer.
fn out3_single(w: Vec3) -> Answer {
    Some(vec![f64::from(w.x), f64::from(w.y), f64::from(w.z)])
}
