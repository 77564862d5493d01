//! Benchmark of the colour chapter (issue 5): filled by that section.

fn main() {}
