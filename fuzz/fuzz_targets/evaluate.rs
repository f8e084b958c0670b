//! Fuzz target `evaluate`: the body is `neutrospline_cli::fuzzing::evaluate`, which the corpus replay
//! test `crates/neutrospline-cli/tests/integration/fuzz_corpus.rs` also runs on stable.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    neutrospline_cli::fuzzing::evaluate(data);
});
