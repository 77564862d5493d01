//! Small numerical helpers that derivations, checkers and tests share.
//!
//! * [`max_abs`]: the largest magnitude of a list of errors, keeping a NaN, so that an
//!   error bound `max_abs(errors) <= tol` can never pass on a NaN.
//! * [`tuple_text`]: a point or a vector as a reader writes it, `(0.1, 0.2, 0.97)`, for
//!   messages (glam's `Debug` writes `DVec3(0.1, 0.2, 0.97)`).

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

/// The numbers `xs` as a tuple, `(0.1, 0.2, 0.97)`: each the shortest decimal that reads back
/// as the same `f64` (`1.0`, `1e-300`, `NaN`), so that a counterexample in a message can be
/// pasted into any language. For points and vectors in messages, in place of glam's `Debug`.
pub fn tuple_text(xs: impl IntoIterator<Item = f64>) -> String {
    let xs: Vec<String> = xs.into_iter().map(|x| format!("{x:?}")).collect();
    format!("({})", xs.join(", "))
}
