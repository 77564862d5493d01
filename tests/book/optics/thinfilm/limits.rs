//! Limits that must reduce to a single interface.

use super::*;

/// Angles 0..90° and index pairs including total internal reflection (n1 > n3).
fn interface_cases() -> impl Iterator<Item = (f64, f64, f64)> {
    let pairs = [
        (1.0, 1.33),
        (1.0, 1.5),
        (1.33, 1.5),
        (1.5, 1.0),
        (1.52, 1.33),
        (2.4, 1.0),
    ];
    pairs
        .into_iter()
        .flat_map(|(n1, n3)| (0..=90).map(move |a| (n1, n3, FRAC_PI_2 * f64::from(a) / 90.0)))
}

#[track_caller]
fn assert_bare(film: Film, n1: f64, n3: f64, theta1: f64, tol: f64) {
    let r = film.response(550.0, theta1);
    let [bs, bp] = bare(n1, n3, theta1);
    assert!(
        (r.reflectance_s - bs).abs() <= tol && (r.reflectance_p - bp).abs() <= tol,
        "{film:?} at {theta1}: ({}, {}) vs bare ({bs}, {bp})",
        r.reflectance_s,
        r.reflectance_p
    );
}

/// d = 0: the film vanishes, leaving the bare n1 | n3 interface, for any film index.
#[test]
fn zero_thickness_is_the_bare_interface() {
    for (n1, n3, t) in interface_cases() {
        for n2 in [1.2, 1.38, 2.0, 3.0] {
            assert_bare(Film::new(n1, n2, n3, 0.0), n1, n3, t, 1e-14);
        }
    }
}

/// n2 = n1: the film is part of the ambient and only its far interface (n1 | n3) remains,
/// at any thickness; n2 = n3: it is part of the substrate and only the near one remains.
#[test]
fn film_matching_either_neighbour_leaves_one_interface() {
    for (n1, n3, t) in interface_cases() {
        for d in [10.0, 123.4, 5000.0] {
            assert_bare(Film::new(n1, n1, n3, d), n1, n3, t, 1e-14);
            assert_bare(Film::new(n1, n3, n3, d), n1, n3, t, 1e-14);
        }
    }
}

/// A half-wave film (2δ = 2π, so e^{2iδ} = 1) is absent at its own wavelength and angle:
/// r = (r12 + r23)/(1 + r12 r23) = r13, for any film index.
#[test]
fn half_wave_film_is_absent() {
    for (n1, n3, t) in interface_cases() {
        for n2 in [n1 + 0.3, n1 + 0.9, n1 + 1.5] {
            // Films denser than the ambient, so cos θ2 is real.
            let c2 = cos_theta(n1, t.cos(), n2).re;
            let d = 550.0 / (2.0 * n2 * c2);
            assert_bare(Film::new(n1, n2, n3, d), n1, n3, t, 1e-12);
        }
    }
}
