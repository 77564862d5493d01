//! Benchmark of the emission chapter (issue 5): filled by that section.

fn main() {}
