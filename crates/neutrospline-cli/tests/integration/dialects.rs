//! Tables as spreadsheets save them (`--delimiter`, detection of `;` and tab, `--decimal-comma`,
//! `.tsv`, `--columns`, `--ignore-columns`, `--ignore-unknown-columns`, `.xlsx`, `.ods`,
//! `.xls` and `--sheet`), read to the same model and data as the plain CSV: fixtures written by
//! Python's csv module (scripts/reference/make_table_dialect_fixtures.py), openpyxl and
//! LibreOffice (scripts/reference/make_spreadsheet_fixtures.py).

use std::path::{Path, PathBuf};

use crate::util::{ok, run};

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/tables")
        .join(name)
}

/// The model `fit` writes for the fixture `file` with 5 control points, the file's name (and
/// a sheet's) replaced by `DATA` in its description.
fn fit(file: &str, extra: &[&str]) -> String {
    let dir = tempfile::tempdir().unwrap();
    let path = fixture(file).display().to_string();
    let mut args = vec!["fit", path.as_str(), "--control-points", "5"];
    args.extend(extra);
    let (code, stdout, stderr) = run(dir.path(), &args);
    assert_eq!(code, 0, "{stderr}");
    let shown = stdout.find(&format!("{path}[")).and_then(|at| {
        stdout[at..]
            .find("]")
            .map(|end| stdout[at..at + end + 1].to_owned())
    });
    match shown {
        Some(sheet) => stdout.replace(&sheet, "DATA"),
        None => stdout.replace(&path, "DATA"),
    }
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

/// Spreadsheets: the first sheet, or the one `--sheet` names, read to the same model and data
/// as the plain CSV, in every command that reads a table; fixtures written by openpyxl and
/// converted by LibreOffice (scripts/reference/make_spreadsheet_fixtures.py).
#[test]
fn spreadsheets_read_as_the_plain_csv() {
    let plain = eval("example1-plain.csv", &[]);
    for book in ["workbook.xlsx", "workbook.ods", "workbook.xls"] {
        assert_eq!(eval(book, &[]), plain, "{book}");
        assert_eq!(eval(book, &["--sheet", "points"]), plain, "{book}");
    }
    let dir = tempfile::tempdir().unwrap();
    let plain = fit("survey-plain.csv", &[]);
    assert!(plain.contains("control_points"), "{plain}");
    // The survey starts at B3, has truth and falsity as mu and nu, and one x typed as text.
    for book in ["workbook.xlsx", "workbook.ods", "workbook.xls"] {
        let mapped = ["--sheet", "Survey", "--columns", "truth=mu,falsity=nu"];
        assert_eq!(fit(book, &mapped), plain, "{book}");
    }
    // query reads its points from a sheet too (the control points of Example 1 as points,
    // with their degrees left out).
    let model = crate::util::example("example1.toml").display().to_string();
    let book = fixture("workbook.xlsx").display().to_string();
    let csv = fixture("example1-plain.csv").display().to_string();
    let query = |points: &str| {
        let ignore = "truth,indeterminacy,falsity";
        let args = ["query", &model, points, "--ignore-columns", ignore];
        let (code, stdout, stderr) = run(dir.path(), &args);
        assert_eq!(code, 0, "{stderr}");
        stdout
    };
    assert_eq!(query(&book), query(&csv));
    assert!(query(&csv).lines().count() > 4);
}

/// A sheet that is not there, a sheet of a CSV file, a delimiter of a spreadsheet, a workbook
/// that cannot be read and an error cell: one message each, naming the file (and the sheet
/// and row), nothing on standard output.
#[test]
fn spreadsheet_refusals_are_located() {
    let dir = tempfile::tempdir().unwrap();
    let book = fixture("workbook.xlsx").display().to_string();
    let csv = fixture("example1-plain.csv").display().to_string();
    let cases: [(&[&str], i32, String); 4] = [
        (
            &["eval", &book, "--sheet", "Table 9"],
            2,
            format!(
                "error: {book}: sheet = Table 9: the workbook has no such sheet (its sheets: \
                 Points, Survey)\n"
            ),
        ),
        (
            &["eval", &csv, "--sheet", "Points"],
            2,
            format!(
                "error: {csv}: sheet = Points applies to a spreadsheet (.xlsx, .xlsm, .xls, \
                 .ods); this file has no sheets (leave out --sheet)\n"
            ),
        ),
        (
            &["fit", &book, "--delimiter", ";"],
            2,
            format!(
                "error: {book}: delimiter = semicolon does not apply to a spreadsheet: its \
                 cells are read as cells (leave out --delimiter)\n"
            ),
        ),
        (
            &["eval", &fixture("error-cell.xlsx").display().to_string()],
            1,
            format!(
                "error: {}[Points]:4: column `truth`: value `#DIV/0!` is not a number\n",
                fixture("error-cell.xlsx").display()
            ),
        ),
    ];
    for (args, code, want) in cases {
        let (got, stdout, stderr) = run(dir.path(), args);
        assert_eq!((got, stdout.as_str(), stderr), (code, "", want), "{args:?}");
    }
    // Not a workbook: the reader's own error, once, with the file's name.
    std::fs::write(dir.path().join("s.xlsx"), b"PK\x03\x04 not read").unwrap();
    for args in [&["eval", "s.xlsx"][..], &["fit", "s.xlsx"]] {
        let (code, stdout, stderr) = run(dir.path(), args);
        assert_eq!((code, stdout.as_str()), (1, ""), "{args:?}");
        assert!(
            stderr.starts_with("error: s.xlsx: cannot read: "),
            "{stderr}"
        );
        assert_eq!(stderr.lines().count(), 1, "{stderr}");
    }
    // A spreadsheet is never written.
    let drawing = crate::util::example("drawing.svg").display().to_string();
    let (code, _, stderr) = run(dir.path(), &["import", &drawing, "-o", "out.xlsx"]);
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains("out.xlsx: a spreadsheet (.xlsx) is read only as a table"),
        "{stderr}"
    );
}
