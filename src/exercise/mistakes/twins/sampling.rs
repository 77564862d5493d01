//! The typical mistakes and correct alternatives of the exercises of the book's sampling
//! and geometry chapters and of *Reflection and refraction* (see [`super`] and [`crate::exercise::mistakes`]).

use super::{Alternative, Mistake, Table};
use crate::exercise::mistakes::Source;
use crate::exercise::mistakes::probes::square;
use crate::exercise::registry::disc_polar_checks;

/// This part's tables, in the book's order.
pub const TABLES: &[Table] = &[Table {
    exercise: "disc_polar",
    mistakes: &[
        Mistake {
            words: "r = u1: the radius without its square root (the radial CDF r^2 forgotten)",
            source: Source::Chapter,
            check: || disc_polar_checks(polar::r_equals_u1),
            probe: || square(polar::r_equals_u1),
        },
        Mistake {
            words: "phi = pi u2: half the turn (pi where 2 pi belongs)",
            source: Source::Constant,
            check: || disc_polar_checks(polar::half_turn),
            probe: || square(polar::half_turn),
        },
        Mistake {
            words: "r = u1^2: the radius squared where its square root belongs",
            source: Source::Power,
            check: || disc_polar_checks(polar::r_squared),
            probe: || square(polar::r_squared),
        },
        Mistake {
            words: "r = sqrt(u2), phi = 2 pi u1: u1 and u2 swapped",
            source: Source::Swapped,
            check: || disc_polar_checks(polar::swapped),
            probe: || square(polar::swapped),
        },
        Mistake {
            words: "(r cos phi, sin phi): the radius left off y",
            source: Source::Factor,
            check: || disc_polar_checks(polar::y_without_r),
            probe: || square(polar::y_without_r),
        },
        Mistake {
            words: "(r sin phi, r cos phi): sine and cosine swapped, a uniform disc but not the polar map (phi runs clockwise from the y axis, so the map's inverse is not the chapter's)",
            source: Source::Swapped,
            check: || disc_polar_checks(polar::sin_cos_swapped),
            probe: || square(polar::sin_cos_swapped),
        },
    ],
    alternatives: &[
        Alternative {
            words: "sin_cos of phi, then the radius times each",
            check: || disc_polar_checks(polar::with_sin_cos),
        },
        Alternative {
            words: "the point (cos phi, sin phi) scaled by sqrt(u1) as a vector",
            check: || disc_polar_checks(polar::scaled_unit_vector),
        },
    ],
}];

/// Twins and alternatives of `disc_polar`.
mod polar {
    use glam::{DVec2, DVec3};
    use std::f64::consts::{PI, TAU};

    pub fn r_equals_u1(u: DVec2) -> DVec3 {
        let (r, phi) = (u.x, TAU * u.y);
        DVec3::new(r * phi.cos(), r * phi.sin(), 0.0)
    }

    pub fn half_turn(u: DVec2) -> DVec3 {
        let (r, phi) = (u.x.sqrt(), PI * u.y);
        DVec3::new(r * phi.cos(), r * phi.sin(), 0.0)
    }

    pub fn r_squared(u: DVec2) -> DVec3 {
        let (r, phi) = (u.x * u.x, TAU * u.y);
        DVec3::new(r * phi.cos(), r * phi.sin(), 0.0)
    }

    pub fn swapped(u: DVec2) -> DVec3 {
        let (r, phi) = (u.y.sqrt(), TAU * u.x);
        DVec3::new(r * phi.cos(), r * phi.sin(), 0.0)
    }

    pub fn y_without_r(u: DVec2) -> DVec3 {
        let (r, phi) = (u.x.sqrt(), TAU * u.y);
        DVec3::new(r * phi.cos(), phi.sin(), 0.0)
    }

    pub fn sin_cos_swapped(u: DVec2) -> DVec3 {
        let (r, phi) = (u.x.sqrt(), TAU * u.y);
        DVec3::new(r * phi.sin(), r * phi.cos(), 0.0)
    }

    pub fn with_sin_cos(u: DVec2) -> DVec3 {
        let (sin, cos) = (2.0 * PI * u.y).sin_cos();
        let r = u.x.sqrt();
        DVec3::new(cos * r, sin * r, 0.0)
    }

    pub fn scaled_unit_vector(u: DVec2) -> DVec3 {
        let phi = u.y * TAU;
        DVec3::new(phi.cos(), phi.sin(), 0.0) * u.x.sqrt()
    }
}
