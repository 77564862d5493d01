//! Planted bugs of the roulette checker. Chapter: *Russian roulette*.

/// Survivors keep `f` instead of `f / p`: the estimate shrinks to `p f`.
pub fn without_division(f: f64, p: f64, u: f64) -> f64 {
    if u < p { f } else { 0.0 }
}

/// Survival decided by `u > p`: right on average only for `p = 1/2`.
pub fn survives_above(f: f64, p: f64, u: f64) -> f64 {
    if u > p { f / p } else { 0.0 }
}
