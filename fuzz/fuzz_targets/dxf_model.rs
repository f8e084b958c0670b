//! Fuzz target `dxf_model`: the body is `neutrospline_cli::fuzzing::dxf_model`, which the corpus replay
//! test `crates/neutrospline-cli/tests/integration/fuzz_corpus.rs` also runs on stable.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    neutrospline_cli::fuzzing::dxf_model(data);
});
