//! Answers with the kind of mistake the accuracy claim must catch
//! ([`crate::check::accuracy`]); the tests hold that each is rejected.

use super::{Answer, Form};

/// `form`'s answer with every output rounded through `f32`: a double routine with one
/// single-precision step (about 2^29 ulps off, wherever the answer is not a single).
pub fn through_f32(form: &Form, args: &[f64]) -> Answer {
    (form.eval)(args).map(|y| y.iter().map(|&v| f64::from(v as f32)).collect())
}

/// `form`'s answer with every output `k` doubles away from the right one (toward +∞): an
/// error of exactly `k` ulps, as an extra rounding step or a lost guard digit makes.
pub fn ulps_off(form: &Form, args: &[f64], k: u32) -> Answer {
    (form.eval)(args).map(|y| {
        y.iter()
            .map(|&v| (0..k).fold(v, |v, _| v.next_up()))
            .collect()
    })
}
