//! Tables as spreadsheets save them (`--delimiter`, detection of `;` and tab, `--decimal-comma`,
//! `.tsv`, `--columns`, `--ignore-columns`, `--ignore-unknown-columns`), read to the same
//! model and data as the plain CSV: fixtures written by Python's csv module
//! (scripts/reference/make_table_dialect_fixtures.py).

use std::path::{Path, PathBuf};

use crate::util::{ok, run};

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/tables")
        .join(name)
}

fn eval(file: &str, extra: &[&str]) -> String {
    let dir = tempfile::tempdir().unwrap();
    let path = fixture(file).display().to_string();
    let mut args = vec!["eval", path.as_str(), "--samples", "11", "--derivative"];
    args.extend(extra);
    ok(dir.path(), &args)
}

#[test]
fn spreadsheet_dialects_read_as_the_plain_csv() {
    let plain = eval("example1-plain.csv", &[]);
    // The semicolons are found in the header; the decimal commas are asked for.
    assert_eq!(eval("example1-excel-fr.csv", &["--decimal-comma"]), plain);
    // A .tsv file is tab-separated; mu and nu are read as truth and falsity, note is left out.
    let mapped = [
        "--columns",
        "truth=mu,falsity=nu",
        "--ignore-columns",
        "note",
    ];
    assert_eq!(eval("example1.tsv", &mapped), plain);
    let unknown = [
        "--columns",
        "truth=mu,falsity=nu",
        "--ignore-unknown-columns",
        "--delimiter",
        "tab",
    ];
    assert_eq!(eval("example1.tsv", &unknown), plain);
}

/// `fit` of the survey's first 12 points: the same model from each dialect (the description
/// names the file).
#[test]
fn fit_reads_the_same_data_from_every_dialect() {
    let dir = tempfile::tempdir().unwrap();
    let fit = |file: &str, extra: &[&str]| {
        let path = fixture(file).display().to_string();
        let mut args = vec!["fit", path.as_str(), "--control-points", "5"];
        args.extend(extra);
        let (code, stdout, stderr) = run(dir.path(), &args);
        assert_eq!(code, 0, "{stderr}");
        stdout.replace(&path, "DATA")
    };
    let plain = fit("survey-plain.csv", &[]);
    assert!(plain.contains("control_points"), "{plain}");
    assert_eq!(fit("survey-excel-fr.csv", &["--decimal-comma"]), plain);
    assert_eq!(
        fit(
            "survey.tsv",
            &[
                "--columns",
                "truth=mu,falsity=nu",
                "--ignore-columns",
                "note"
            ]
        ),
        plain
    );
}

#[test]
fn refusals_name_the_option() {
    let dir = tempfile::tempdir().unwrap();
    let excel = fixture("example1-excel-fr.csv").display().to_string();
    let (code, _, stderr) = run(dir.path(), &["eval", &excel]);
    assert_eq!(code, 1);
    assert_eq!(
        stderr,
        format!(
            "error: {excel}:2: column `truth`: value `0,3` is not a number (a decimal comma? \
             give --decimal-comma)\n"
        )
    );
    let tsv = fixture("example1.tsv").display().to_string();
    let (code, _, stderr) = run(dir.path(), &["eval", &tsv, "--ignore-columns", "note"]);
    assert_eq!(code, 1);
    assert!(
        stderr.starts_with(&format!("error: {tsv}:1: unknown column `mu`")),
        "{stderr}"
    );
    let (code, _, stderr) = run(
        dir.path(),
        &[
            "eval",
            &tsv,
            "--columns",
            "truth=mu,falsity=nu",
            "--ignore-columns",
            "remark",
        ],
    );
    assert_eq!(code, 1);
    assert_eq!(
        stderr,
        format!("error: {tsv}:1: --ignore-columns remark: the header has no column `remark`\n")
    );
    let (code, _, stderr) = run(
        dir.path(),
        &["eval", &excel, "--decimal-comma", "--delimiter", ","],
    );
    assert_eq!(code, 2);
    assert_eq!(
        stderr,
        "error: delimiter and decimal-comma exclude each other (with a decimal comma the cells \
         must be separated by another character, such as ; or a tab)\n"
    );
}

#[test]
fn a_missing_indeterminacy_column_hints_at_membership() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("d.csv"),
        "x,y,truth,falsity\n0,0,0.5,0.2\n1,1,0.6,0.3\n",
    )
    .unwrap();
    let hint = "d.csv:1: missing column `indeterminacy` (neutrosophic rule requires it; truth \
                and falsity alone are an intuitionistic table (--membership intuitionistic, \
                indeterminacy 1 - T - F), truth alone a fuzzy one (--membership fuzzy))\n";
    for command in ["eval", "fit"] {
        let (code, _, stderr) = run(dir.path(), &[command, "d.csv"]);
        assert_eq!((code, stderr), (1, format!("error: {hint}")), "{command}");
    }
}

/// A spreadsheet is refused with one message, the same in every command that reads a table.
#[test]
fn a_spreadsheet_gets_one_message_everywhere() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("s.xlsx"), b"PK\x03\x04 not read").unwrap();
    std::fs::copy(
        crate::util::example("example1.toml"),
        dir.path().join("m.toml"),
    )
    .unwrap();
    let want = "error: s.xlsx: a spreadsheet (.xlsx) is not read: save its sheet as CSV (File > \
                Save As > CSV); a CSV saved with semicolons and decimal commas is read with \
                --decimal-comma\n";
    for args in [
        &["eval", "s.xlsx"][..],
        &["check", "s.xlsx"],
        &["fit", "s.xlsx"],
        &["query", "m.toml", "s.xlsx"],
        &["plot", "m.toml", "--data", "s.xlsx", "-o", "f.svg"],
    ] {
        let (code, stdout, stderr) = run(dir.path(), args);
        assert_eq!(
            (code, stdout.as_str(), stderr.as_str()),
            (2, "", want),
            "{args:?}"
        );
    }
}
