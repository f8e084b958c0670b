//! Spreadsheets as tables (docs/formats.md, "Spreadsheets"): the fixtures of the command line's
//! tests (written by openpyxl and LibreOffice) read to the same data as the plain CSV, and
//! damaged workbooks are refused with an error, never a panic or a partial table.

use std::path::{Path, PathBuf};

use neutrospline::options::{OptionSet, OptionValue};
use neutrospline::Family;
use neutrospline_io::{load_data_with, ReadError, TableInput};

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../neutrospline-cli/tests/data/tables")
        .join(name)
}

fn survey_input() -> TableInput {
    let mut input = TableInput::default();
    input
        .set("sheet", OptionValue::Word("Survey".into()))
        .unwrap();
    input
        .set("columns", OptionValue::Word("truth=mu,falsity=nu".into()))
        .unwrap();
    input
}

#[test]
fn every_workbook_reads_the_survey_exactly() {
    let plain = load_data_with(
        fixture("survey-plain.csv"),
        Family::Neutrosophic,
        &TableInput::default(),
    )
    .unwrap();
    assert_eq!(plain.len(), 12);
    for book in ["workbook.xlsx", "workbook.ods", "workbook.xls"] {
        let table = load_data_with(fixture(book), Family::Neutrosophic, &survey_input()).unwrap();
        assert_eq!(table.positions(), plain.positions(), "{book}");
        assert_eq!(table.degrees(), plain.degrees(), "{book}");
    }
}

/// A deterministic byte generator (64-bit LCG), so that a failure names its case.
struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        self.0 >> 33
    }
}

/// Damaged workbooks: bytes flipped, the file cut short. Each is either read (a flip in
/// padding) or refused with an error that names the file; none panics.
#[test]
fn damaged_workbooks_are_refused_not_panicked_on() {
    let dir = tempfile::tempdir().unwrap();
    let mut random = Lcg(0x5eed);
    let mut refused = 0;
    for book in ["workbook.xlsx", "workbook.ods", "workbook.xls"] {
        let bytes = std::fs::read(fixture(book)).unwrap();
        for case in 0..150 {
            let mut damaged = bytes.clone();
            if case % 3 == 0 {
                damaged.truncate(random.next() as usize % bytes.len());
            } else {
                for _ in 0..1 + case % 4 {
                    let at = random.next() as usize % damaged.len();
                    damaged[at] ^= 1 << (random.next() % 8);
                }
            }
            let path = dir.path().join(format!("case{case}-{book}"));
            std::fs::write(&path, &damaged).unwrap();
            let result = std::panic::catch_unwind(|| {
                load_data_with(&path, Family::Neutrosophic, &survey_input())
            });
            let result = result.unwrap_or_else(|_| panic!("{book} case {case} panicked"));
            match result {
                Ok(table) => assert!(!table.is_empty(), "{book} case {case}"),
                Err(error) => {
                    refused += 1;
                    let shown = path.display().to_string();
                    assert!(
                        error.to_string().starts_with(&shown),
                        "{book} case {case}: {error}"
                    );
                    assert!(!matches!(error, ReadError::Format(_)), "{error}");
                }
            }
        }
    }
    assert!(refused > 200, "{refused}");
}
