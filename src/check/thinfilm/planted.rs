//! Planted bugs of the Airy-sum checker. Chapter: *Thin-film interference*.

use num_complex::Complex64;

/// The source notes' denominator, `1 − r12 r23 e^{2iδ}`: the sign of `r21 = −r12` lost.
pub fn denominator_minus(r12: Complex64, r23: Complex64, delta: Complex64) -> Complex64 {
    let round_trip = (Complex64::i() * delta * 2.0).exp();
    (r12 + r23 * round_trip) / (1.0 - r12 * r23 * round_trip)
}

/// The one-way phase `e^{iδ}` where the round trip needs `e^{2iδ}`.
pub fn one_way_phase(r12: Complex64, r23: Complex64, delta: Complex64) -> Complex64 {
    let once = (Complex64::i() * delta).exp();
    (r12 + r23 * once) / (1.0 + r12 * r23 * once)
}
