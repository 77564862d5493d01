//! Each exercise's probe: its function run on fixed inputs, the outputs flattened (see
//! [`super`]). The probe of the crate's own function is in [`PROBES`]; the twins run the
//! same probe functions on themselves.

use glam::{DVec2, DVec3};

use crate::sampling::disc;

/// A probe: a function run on fixed inputs, its outputs flattened.
pub type Probe = fn() -> Vec<f64>;

/// The probe of the crate's own function (the student's, in a hand-out), by exercise.
pub const PROBES: &[(&str, Probe)] = &[("disc_polar", || square(disc::disc_polar))];

/// The probe of exercise `name`'s function in this crate.
pub fn of(name: &str) -> Option<Probe> {
    PROBES.iter().find(|(n, _)| *n == name).map(|(_, p)| *p)
}

/// A map of the unit square on a 7 x 7 grid inside it and its four corners: every
/// coordinate of every point, in order.
pub fn square(f: fn(DVec2) -> DVec3) -> Vec<f64> {
    let grid =
        (1..=7).flat_map(|i| (1..=7).map(move |j| DVec2::new(f64::from(i), f64::from(j)) / 8.0));
    let corners = [DVec2::ZERO, DVec2::X, DVec2::Y, DVec2::ONE];
    grid.chain(corners).flat_map(|u| f(u).to_array()).collect()
}
