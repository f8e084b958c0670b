//! The subcommands: each parses nothing itself, calls the input layer and the core library,
//! and writes through the output layer.

pub mod bench;
pub mod bench_fit;
pub mod check;
pub mod eval;
pub mod example;
pub mod export;
pub mod fit;
pub mod import;
pub mod intersect;
pub mod options;
pub mod plot;
pub mod query;
pub mod relation;
pub mod studio;
pub mod transform;

use neutrospline::Family;

/// Parses a `--membership` value with the core's [`Family`] names (`pythagorean`,
/// `q-rung:4`, ...); the message lists the accepted forms.
pub fn parse_family(text: &str) -> Result<Family, String> {
    text.parse::<Family>().map_err(|e| e.to_string())
}
