//! The integration tests of neutrospline-io, one binary: one module per topic.
//! Proptest keeps the failures of `tests/integration/X.rs` in `tests/proptest-regressions/X.txt`
//! (`FileFailurePersistence::SourceParallel`, the default: the sibling of the directory holding
//! `main.rs`).

mod directories;
mod periodic;
mod roundtrip;
mod schema;
mod spreadsheets;
mod wide;
mod write;
