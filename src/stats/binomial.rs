//! Intervals for a rate measured by counting: how often a test raised a false alarm, or
//! caught a planted bug, in `n` independent trials. Chapter: *Statistical tests*.

// ANCHOR: wilson
/// The Wilson score interval at 95 % (`z = 1.96`) for `k` successes in `n` trials:
///
/// `(p + z²/2n ± z sqrt(p(1-p)/n + z²/4n²)) / (1 + z²/n)`, with `p = k / n`,
///
/// clamped to `[0, 1]`. Unlike the normal interval `p ± z sqrt(p(1-p)/n)` it does not
/// collapse to a point at `k = 0` or `k = n`, which is where false-alarm counts sit.
/// For `n = 0` there is no information: the interval is `[0, 1]`.
pub fn wilson(k: u32, n: u32) -> (f64, f64) {
    if n == 0 {
        return (0.0, 1.0);
    }
    let (k, n, z) = (f64::from(k), f64::from(n), 1.96f64);
    let p = k / n;
    let c = (p + z * z / (2.0 * n)) / (1.0 + z * z / n);
    let h = z * (p * (1.0 - p) / n + z * z / (4.0 * n * n)).sqrt() / (1.0 + z * z / n);
    ((c - h).max(0.0), (c + h).min(1.0))
}
// ANCHOR_END: wilson
