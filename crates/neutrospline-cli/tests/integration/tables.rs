//! `eval --format latex | markdown` and `--digits`, and the rounding of derived degrees in
//! `check`: exact expected text from the closed form, and a LaTeX compile of the table.

use std::path::Path;
use std::process::Command;

use crate::util::{ok, run};

/// A quadratic intuitionistic Bézier curve: the indeterminacy is derived, 1 - T - F, which in
/// 64-bit floats is 0.09999999999999998 at the first control point and 5.55e-17 at the last.
const INTUITIONISTIC: &str = "x,y,truth,falsity\n0,0,0.3,0.6\n1,2,0.6,0.3\n2,0,0.7,0.3\n";

fn intuitionistic_file(dir: &Path) -> String {
    let path = dir.join("ifs.csv");
    std::fs::write(&path, INTUITIONISTIC).unwrap();
    path.display().to_string()
}

fn eval(dir: &Path, format: &[&str]) -> String {
    let file = intuitionistic_file(dir);
    let mut args = vec![
        "eval",
        file.as_str(),
        "--membership",
        "intuitionistic",
        "--at",
        "0,0.5,1",
    ];
    args.extend(format);
    ok(dir, &args)
}

/// The closed form at t = 0, 1/2, 1 (Bernstein weights 1/4, 1/2, 1/4 in the middle):
/// x = 1, y = 1, T = 0.075 + 0.3 + 0.175 = 0.55, F = 0.15 + 0.15 + 0.075 = 0.375, I = 0.075.
#[test]
fn markdown_prints_what_the_inputs_justify() {
    let dir = tempfile::tempdir().unwrap();
    assert_eq!(
        eval(dir.path(), &["--format", "markdown"]),
        "| t | x | y | truth | indeterminacy | falsity |\n\
         | ---: | ---: | ---: | ---: | ---: | ---: |\n\
         | 0 | 0 | 0 | 0.3 | 0.1 | 0.6 |\n\
         | 0.5 | 1 | 1 | 0.55 | 0.075 | 0.375 |\n\
         | 1 | 2 | 0 | 0.7 | 0 | 0.3 |\n"
    );
    // CSV keeps every digit of the same numbers.
    let csv = eval(dir.path(), &[]);
    let first: Vec<f64> = csv
        .lines()
        .nth(1)
        .unwrap()
        .split(',')
        .map(|c| c.parse().unwrap())
        .collect();
    assert_eq!(first[4], 1.0 - 0.3 - 0.6);
    assert_ne!(first[4], 0.1);
}

#[test]
fn latex_is_a_booktabs_tabular_with_typeset_headings() {
    let dir = tempfile::tempdir().unwrap();
    assert_eq!(
        eval(dir.path(), &["--format", "latex", "--digits", "2"]),
        "\\begin{tabular}{rrrrrr}\n\\toprule\n$t$ & $x$ & $y$ & $T$ & $I$ & $F$ \\\\\n\
         \\midrule\n0.0 & 0.0 & 0.0 & 0.30 & 0.10 & 0.60 \\\\\n\
         0.50 & 1.0 & 1.0 & 0.55 & 0.075 & 0.38 \\\\\n\
         1.0 & 2.0 & 0.0 & 0.70 & 0.0 & 0.30 \\\\\n\\bottomrule\n\\end{tabular}\n"
    );
}

#[test]
fn digits_are_refused_with_every_digit_formats() {
    let dir = tempfile::tempdir().unwrap();
    let file = intuitionistic_file(dir.path());
    let (code, stdout, stderr) = run(
        dir.path(),
        &[
            "eval",
            &file,
            "--membership",
            "intuitionistic",
            "--digits",
            "3",
        ],
    );
    assert_eq!((code, stdout.as_str()), (2, ""));
    assert_eq!(
        stderr,
        "error: format and digits exclude each other (csv and json keep every digit of every \
         number; digits rounds the numbers of --format latex or markdown)\n"
    );
    let (code, _, stderr) = run(
        dir.path(),
        &["eval", &file, "--format", "latex", "--digits", "18"],
    );
    assert_eq!(code, 2);
    assert_eq!(
        stderr,
        "error: digits = 18: significant digits must be 1 to 17 (17 tell every 64-bit float \
         apart)\n"
    );
}

#[test]
fn check_rounds_derived_degrees() {
    let dir = tempfile::tempdir().unwrap();
    let file = intuitionistic_file(dir.path());
    let out = ok(
        dir.path(),
        &["check", &file, "--membership", "intuitionistic"],
    );
    // The control indeterminacies are 0.09999999999999998, 0.10000000000000003 and 5.55e-17.
    assert!(out.contains("\ntruth: 0.3..0.7\n"), "{out}");
    assert!(out.contains("\nindeterminacy: 0..0.1\n"), "{out}");
    assert!(out.contains("\nfalsity: 0.3..0.6\n"), "{out}");
}

/// Whether `program` is installed (it starts; `-v` prints its version).
fn available(program: &str) -> bool {
    Command::new(program).arg("-v").output().is_ok()
}

/// The LaTeX table compiles (pdflatex with booktabs) into a PDF that holds the numbers. Runs
/// when `pdflatex` and `pdftotext` are installed (Debian: texlive-latex-base,
/// texlive-latex-recommended, poppler-utils); with NEUTROSPLINE_REQUIRE_LATEX=1 their absence
/// fails the test.
#[test]
fn latex_table_compiles() {
    let required = std::env::var("NEUTROSPLINE_REQUIRE_LATEX").is_ok_and(|v| v == "1");
    if !(available("pdflatex") && available("pdftotext")) {
        assert!(
            !required,
            "NEUTROSPLINE_REQUIRE_LATEX=1 but pdflatex or pdftotext is missing"
        );
        eprintln!("latex_table_compiles: skipped (no pdflatex or pdftotext)");
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let file = intuitionistic_file(dir.path());
    ok(
        dir.path(),
        &[
            "eval",
            &file,
            "--membership",
            "intuitionistic",
            "--at",
            "0,0.5,1",
            "--scores",
            "--derivative",
            "--format",
            "latex",
            "-o",
            "table.tex",
        ],
    );
    let text = crate::util::compile_latex(
        dir.path(),
        "\\documentclass{article}\n\\usepackage{booktabs}\n\\begin{document}\n\
         \\input{table.tex}\n\\end{document}\n",
        &["-layout"],
    );
    // The middle row: t, x, y, T, I, F, then the intuitionistic score T - F = 0.55 - 0.375 and
    // its accuracy T + F = 0.925 (SPEC section 7: not the neutrosophic (2 + T - I - F) / 3).
    let row: Vec<&str> = text
        .lines()
        .find(|l| l.trim_start().starts_with("0.5 "))
        .unwrap_or_else(|| panic!("no row at t = 0.5 in:\n{text}"))
        .split_whitespace()
        .collect();
    assert_eq!(
        row[..8],
        ["0.5", "1", "1", "0.55", "0.075", "0.375", "0.175", "0.925"],
        "{text}"
    );
}
