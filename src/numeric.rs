//! Small numerical helpers that derivations, checkers and tests share.
//!
//! * [`max_abs`]: the largest magnitude of a list of errors, keeping a NaN, so that an
//!   error bound `max_abs(errors) <= tol` can never pass on a NaN.

/// The largest `|x|` of `xs` (0 when there are none), or NaN if any `x` is NaN.
///
/// For error checks of the form `assert!(max_abs(errors) <= tol)`: `f64::max` and glam's
/// `max_element` silently drop a NaN (glam's in all but the last component), so an error
/// computed with them can pass on a NaN; this one makes the comparison fail.
pub fn max_abs(xs: impl IntoIterator<Item = f64>) -> f64 {
    xs.into_iter().fold(0.0, |m: f64, x| {
        if m.is_nan() || x.is_nan() {
            f64::NAN
        } else {
            m.max(x.abs())
        }
    })
}
