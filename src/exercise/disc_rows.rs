//! The chapter *Coursework*'s look inside a failed chi-squared test: the sample counts of
//! three rows of the disc's cells. The chapter shows this function; the book's tests
//! (`tests/book/coursework/mine.rs`) run it, and the figure job
//! (`tools/figures/src/coursework.rs`) writes what it prints.

use glam::{DVec2, DVec3};

use crate::check::Options;
use crate::check::warp::{self, Domain, SquareWarp};
use crate::sampling::disc::disc_pdf;

// ANCHOR: rows
/// The observed and expected counts of rows 0, 10 and 20 of the disc's cells (rows in
/// `r^2`, row 0 at the centre) for the disc sampler `my_disc`, one line per row.
pub fn where_is_my_disc_wrong_text(my_disc: fn(DVec2) -> DVec3) -> String {
    let options = warp::WarpOptions::from(Options::default().cases(warp::TEST_SAMPLES));
    let mine = SquareWarp::new("mine", Domain::Disc, my_disc, disc_pdf);
    let (_chi2, observed, expected) = warp::chi_squared(&mine, &options).unwrap();
    let cols = options.resolution; // columns in phi
    let mut text = String::new();
    for row in [0, 10, 20] {
        let o: u64 = observed[row * cols..(row + 1) * cols].iter().sum();
        let e: f64 = expected[row * cols..(row + 1) * cols].iter().sum();
        let ratio = o as f64 / e;
        text.push_str(&format!(
            "row {row}: observed {o}, expected {e:.0}, ratio {ratio:.2}\n"
        ));
    }
    text
}
// ANCHOR_END: rows
