//! Benchmark of the wavelength chapter (issue 5): filled by that section.

fn main() {}
