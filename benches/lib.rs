//! raylemma's criterion benchmarks, one file per topic beside this one (`sphere.rs`,
//! `sampling.rs`, ...), each a bench target of this crate: `cargo bench -p raylemma-bench
//! --bench sphere`. They time the inputs of `raylemma::workload`, the same the speed
//! tables of `cargo run --release` time (chapter *Speed*). This library is empty: the
//! crate exists so that `cargo test` of raylemma never compiles criterion.
