//! The mean over pixels and channels of the variance of a pixel's mean, read from raylemma's
//! EXR renders (the `var.R`, `var.G`, `var.B` channels), one line per file:
//! `cargo run --release --example mean_variance -- a.exr b.exr`.

use std::path::Path;

use raylemma::image::Image;

fn main() {
    for arg in std::env::args().skip(1) {
        match Image::read_exr(Path::new(&arg)) {
            Ok(image) => {
                let sum: f64 = image.var.iter().map(|v| v.element_sum()).sum();
                println!("{arg} {:.6e}", sum / (3 * image.var.len()) as f64);
            }
            Err(e) => eprintln!("{arg}: {e}"),
        }
    }
}
