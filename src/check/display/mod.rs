//! The checker of the sRGB transfer curve: any routine with the signature of
//! [`crate::spectral::display::srgb_encode`] or [`crate::spectral::display::srgb_decode`]
//! can be checked against the claims of the chapter *From spectrum to display*
//! (`chapters/spectral/display.md`).
//!
//! * `reference`: the curve of IEC 61966-2-1 at [`ENCODED`] (or [`DECODED`]) points, each
//!   value to 1e-12, on both segments and at the breakpoint (linear up to and including
//!   it, as the standard states);
//! * `continuous`: the two segments meet at the breakpoint (within 1e-7: the standard's
//!   rounded constants leave a step of 3e-8);
//! * `monotone`: non-decreasing on a fine grid of `[0, 1]`;
//! * `clamps`: negative and NaN inputs give 0.
//!
//! Planted bugs that it must reject are in [`planted`], beside the source's pure power law
//! ([`crate::spectral::display::gamma_encode`] with `γ = 2.2`).

pub mod planted;

use super::{Finding, Options, Verdict};

/// Linear values and their sRGB encodings (IEC 61966-2-1), each the nearest `f64`.
pub const ENCODED: [(f64, f64); 12] = [
    (0.0005, 0.0064600000000000005),
    (0.002, 0.025840000000000002),
    (0.0031308, 0.040449936),
    (0.005, 0.06100854008843736),
    (0.01, 0.09985282273412832),
    (0.05, 0.24780052799263164),
    (0.1, 0.3491902126282938),
    (0.18, 0.46135612950044164),
    (0.2, 0.48452920448170694),
    (0.5, 0.7353569830524495),
    (0.75, 0.8808250210902997),
    (1.0, 0.9999999999999999),
];

/// Encoded values and their linear decodings (IEC 61966-2-1), each the nearest `f64`.
pub const DECODED: [(f64, f64); 11] = [
    (0.005, 0.0003869969040247678),
    (0.02, 0.0015479876160990713),
    (0.04045, 0.0031308049535603713),
    (0.05, 0.003935939504088967),
    (0.1, 0.010022825574869039),
    (0.25, 0.05087608817155679),
    (0.4, 0.13286832155381798),
    (0.5, 0.21404114048223255),
    (0.735, 0.4994581635400763),
    (0.9, 0.7874122893956174),
    (1.0, 1.0),
];

/// Default number of grid points of the monotonicity claim.
pub const CASES: usize = 100_000;
/// Bound of the reference values' absolute error.
pub(crate) const REFERENCE_BOUND: f64 = 1e-12;
/// Bound of the step between the segments at the breakpoint.
pub(crate) const STEP_BOUND: f64 = 1e-7;

/// The claims on an encoding `f` (linear to encoded).
pub fn srgb_encode(f: &dyn Fn(f64) -> f64, options: &Options) -> Verdict {
    curve("sRGB encoding", f, &ENCODED, 0.003_130_8, options)
}

/// The claims on a decoding `f` (encoded to linear).
pub fn srgb_decode(f: &dyn Fn(f64) -> f64, options: &Options) -> Verdict {
    curve("sRGB decoding", f, &DECODED, 0.040_45, options)
}

/// `x` to 12 significant digits, without trailing zeros: `0.02584`, not the nearest
/// `f64`'s `0.025840000000000002` (the error the line shows is in the third digit or later,
/// never past the twelfth).
pub fn digits(x: f64) -> String {
    match format!("{x:.11e}").parse::<f64>() {
        Ok(r) if x.is_finite() => format!("{r}"),
        _ => format!("{x}"),
    }
}

fn curve(
    subject: &str,
    f: &dyn Fn(f64) -> f64,
    table: &[(f64, f64)],
    breakpoint: f64,
    options: &Options,
) -> Verdict {
    let mut reference = Finding::new(
        "reference",
        "the IEC 61966-2-1 curve at the reference points",
    )
    .in_unit("absolute error");
    for &(x, want) in table {
        let got = f(x);
        reference.measure((got - want).abs(), REFERENCE_BOUND, || {
            format!(
                "f({}) = {}, the standard gives {}",
                digits(x),
                digits(got),
                digits(want)
            )
        });
    }
    let mut continuous = Finding::new("continuous", "the two segments meet at the breakpoint")
        .in_unit("absolute jump");
    let (below, above) = (f(breakpoint * (1.0 - 1e-12)), f(breakpoint * (1.0 + 1e-12)));
    continuous.measure((above - below).abs(), STEP_BOUND, || {
        format!("f just below {breakpoint} = {below}, just above = {above}")
    });
    let mut monotone = Finding::new("monotone", "f is non-decreasing on [0, 1]");
    let n = options.cases_or(CASES).max(2);
    let mut previous = f(0.0);
    for k in 1..=n {
        let x = k as f64 / n as f64;
        let y = f(x);
        let (p, xp) = (previous, (k - 1) as f64 / n as f64);
        monotone.record(y >= p, || format!("f({xp}) = {p} > f({x}) = {y}"));
        previous = y;
    }
    let mut clamps = Finding::new("clamps", "negative and NaN inputs give 0");
    for x in [-1.0, -1e-300, f64::NAN, -0.0] {
        let y = f(x);
        clamps.record(y == 0.0, || format!("f({x}) = {y}"));
    }
    let mut verdict = Verdict::new(subject);
    verdict
        .findings
        .extend([reference, continuous, monotone, clamps]);
    verdict
}
