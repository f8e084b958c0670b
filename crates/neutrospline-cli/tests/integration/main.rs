//! The end-to-end tests of the `neutrospline` binary, one test binary: one module per command
//! or topic (each runs `CARGO_BIN_EXE_neutrospline`).

mod arc_length;
mod bench;
mod cli;
mod derivatives;
mod dialects;
mod export;
mod families;
mod faults;
mod fit;
mod fit_surface;
mod fuzz_corpus;
mod fuzzy;
mod hostile;
mod import;
mod intersect;
mod kinds;
mod periodic;
mod plot;
mod query;
mod readers;
mod relation;
mod studio;
mod tables;
mod transform;
mod util;
mod warnings;
mod wide_families;
mod wide_fit;
mod wide_plot;
mod wide_transform;
