//! Planted bugs of the sRGB checker. Chapter: *From spectrum to display*.

/// The encoding with the decoding's breakpoint (0.04045, an encoded value) used on the
/// linear side: the linear segment runs thirteen times too far.
pub fn encode_with_the_encoded_breakpoint(x: f64) -> f64 {
    match x {
        x if x > 0.040_45 => 1.055 * x.powf(2.4_f64.recip()) - 0.055,
        x if x > 0.0 => x * 12.92,
        _ => 0.0,
    }
}

/// The power segment without its offset: `1.055 x^(1/2.4)`, above 1 at `x = 1`.
pub fn encode_without_offset(x: f64) -> f64 {
    if x > 0.003_130_8 {
        1.055 * x.powf(1.0 / 2.4)
    } else {
        (12.92 * x).max(0.0)
    }
}
