//! Twins and alternatives of `airy_r`.

use num_complex::Complex64;

fn round_trip(delta: Complex64) -> Complex64 {
    (2.0 * Complex64::i() * delta).exp()
}

pub fn swapped(r12: Complex64, r23: Complex64, delta: Complex64) -> Complex64 {
    let z = round_trip(delta);
    (r23 + r12 * z) / (1.0 + r12 * r23 * z)
}

pub fn without_stokes_factor(r12: Complex64, r23: Complex64, delta: Complex64) -> Complex64 {
    let z = round_trip(delta);
    r12 + r23 * z / (1.0 + r12 * r23 * z)
}

pub fn two_waves(r12: Complex64, r23: Complex64, delta: Complex64) -> Complex64 {
    r12 + r23 * round_trip(delta)
}

pub fn conjugate_phase(r12: Complex64, r23: Complex64, delta: Complex64) -> Complex64 {
    let back = (-2.0 * Complex64::i() * delta).exp();
    (r12 + r23 * back) / (1.0 + r12 * r23 * back)
}

pub fn squared_phase(r12: Complex64, r23: Complex64, delta: Complex64) -> Complex64 {
    let once = (Complex64::i() * delta).exp();
    let z = once * once;
    (r12 + r23 * z) * (1.0 + r12 * r23 * z).inv()
}

pub fn first_wave_plus_rest(r12: Complex64, r23: Complex64, delta: Complex64) -> Complex64 {
    let z = round_trip(delta);
    r12 + (1.0 - r12 * r12) * r23 * z / (1.0 + r12 * r23 * z)
}
