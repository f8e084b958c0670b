//! Replays the fuzz seed corpus (`fuzz/corpus/<target>/`) through the same functions the
//! cargo-fuzz targets call, on stable, in a few seconds: every file must go through without a
//! panic. Crashers found by fuzzing are added to the corpus and so stay fixed.

use std::path::Path;

fn replay(target: &str, body: fn(&[u8])) {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../fuzz/corpus")
        .join(target);
    let mut count = 0;
    for entry in std::fs::read_dir(&dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display())) {
        let path = entry.unwrap().path();
        let data = std::fs::read(&path).unwrap();
        let outcome = std::panic::catch_unwind(|| body(&data));
        assert!(
            outcome.is_ok(),
            "{}: the fuzz target panicked",
            path.display()
        );
        count += 1;
    }
    assert!(count > 0, "{}: empty corpus", dir.display());
}

#[test]
fn fuzz_corpus_csv_model() {
    replay("csv_model", neutrospline_cli::fuzzing::csv_model);
}

#[test]
fn fuzz_corpus_toml_model() {
    replay("toml_model", neutrospline_cli::fuzzing::toml_model);
}

#[test]
fn fuzz_corpus_json_model() {
    replay("json_model", neutrospline_cli::fuzzing::json_model);
}

#[test]
fn fuzz_corpus_evaluate() {
    replay("evaluate", neutrospline_cli::fuzzing::evaluate);
}

#[test]
fn fuzz_corpus_dxf_model() {
    replay("dxf_model", neutrospline_cli::fuzzing::dxf_model);
}

#[test]
fn fuzz_corpus_svg_model() {
    replay("svg_model", neutrospline_cli::fuzzing::svg_model);
}
