//! End-to-end tests of the `neutrospline` binary: good and bad files written into a temporary
//! directory, exact messages on stderr, exit codes 0 / 1 / 2, and no panic for any input.

use std::io::Read;
use std::path::Path;
use std::process::{Command, Stdio};

use crate::util::{dir_with, examples_dir, run_in, BIN};

/// Runs `args` in a directory holding one file and expects exit 1 with exactly `message`.
fn assert_invalid(name: &str, contents: &[u8], args: &[&str], message: &str) {
    let dir = dir_with(&[(name, contents)]);
    let out = run_in(dir.path(), args, None);
    assert_eq!(
        (out.code, out.stderr.as_str(), out.stdout.as_str()),
        (1, format!("{message}\n").as_str(), ""),
        "args {args:?}, file {name}: {:?}",
        String::from_utf8_lossy(contents)
    );
}

fn parse_csv(text: &str) -> (Vec<String>, Vec<Vec<f64>>) {
    let mut lines = text.lines();
    let header = lines
        .next()
        .expect("header")
        .split(',')
        .map(str::to_owned)
        .collect();
    let rows = lines
        .map(|l| l.split(',').map(|c| c.parse::<f64>().expect(c)).collect())
        .collect();
    (header, rows)
}

fn assert_close(actual: &[f64], expected: &[f64]) {
    assert_eq!(actual.len(), expected.len(), "{actual:?} vs {expected:?}");
    for (a, e) in actual.iter().zip(expected) {
        assert!((a - e).abs() <= 1e-12, "{actual:?} vs {expected:?}");
    }
}

const EXAMPLE1_CSV: &str = "name,x,y,truth,indeterminacy,falsity\n\
C0,1,3,0.3,0.6,0.1\nC1,3,6,0.8,0.1,0.1\nC2,6,2,0.7,0.1,0.2\nC3,9,5,0.2,0.4,0.4\n";

const HEADER_2D: &str = "t,x,y,truth,indeterminacy,falsity";

#[test]
fn eval_example1_csv_toml_json_agree() {
    let dir = examples_dir();
    for format in ["csv", "json"] {
        let outputs: Vec<String> = ["example1.csv", "example1.toml", "example1.json"]
            .iter()
            .map(|f| {
                let out = run_in(&dir, &["eval", f, "--derivative", "--format", format], None);
                assert_eq!(out.code, 0, "{f}: {}", out.stderr);
                out.stdout
            })
            .collect();
        assert_eq!(outputs[0], outputs[1]);
        assert_eq!(outputs[0], outputs[2]);
    }
}

#[test]
fn eval_example1_at_half() {
    let out = run_in(
        &examples_dir(),
        &["eval", "example1.toml", "--at", "0.5"],
        None,
    );
    assert_eq!(out.code, 0, "{}", out.stderr);
    let (header, rows) = parse_csv(&out.stdout);
    assert_eq!(header.join(","), HEADER_2D);
    assert_eq!(rows.len(), 1);
    assert_close(&rows[0], &[0.5, 4.625, 4.0, 0.625, 0.2, 0.175]);
}

#[test]
fn eval_scores_are_the_blend_of_the_control_scores() {
    let out = run_in(
        &examples_dir(),
        &["eval", "example1.toml", "--at", "0,0.5,1", "--scores"],
        None,
    );
    assert_eq!(out.code, 0, "{}", out.stderr);
    let (header, rows) = parse_csv(&out.stdout);
    assert_eq!(
        header.join(","),
        format!("{HEADER_2D},score,accuracy,certainty")
    );
    // Control scores (2 + T - I - F) / 3 of Table 1: 1.6/3, 2.6/3, 2.4/3, 1.4/3; at t = 1/2
    // the Bernstein weights are 1/8, 3/8, 3/8, 1/8: score (1.6 + 7.8 + 7.2 + 1.4) / 24 = 0.75,
    // accuracy (0.2 + 2.1 + 1.5 - 0.2) / 8 = 0.45, certainty = truth = 0.625.
    assert_close(&rows[0][6..], &[1.6 / 3.0, 0.2, 0.3]);
    assert_close(&rows[1][6..], &[0.75, 0.45, 0.625]);
    assert_close(&rows[2][6..], &[1.4 / 3.0, -0.2, 0.2]);
}

#[test]
fn eval_derivative_columns_and_values() {
    let out = run_in(
        &examples_dir(),
        &["eval", "example1.csv", "--at", "0,0.5,1", "--derivative"],
        None,
    );
    assert_eq!(out.code, 0, "{}", out.stderr);
    let (header, rows) = parse_csv(&out.stdout);
    assert_eq!(
        header.join(","),
        "t,x,y,truth,indeterminacy,falsity,dx,dy,dtruth,dindeterminacy,dfalsity"
    );
    // Hodograph of the position: 3 [(2, 3), (3, -4), (3, 3)]; of the degrees (T, I, F):
    // 3 [(0.5, -0.5, 0), (-0.1, 0, 0.1), (-0.5, 0.3, 0.2)]. At t = 0.5 the weights are
    // (1/4, 1/2, 1/4): dx = 3 * 2.75, dy = 3 * -0.5, dT = 3 * -0.05, dI = 3 * -0.05, dF = 3 * 0.1.
    assert_close(
        &rows[0],
        &[0.0, 1.0, 3.0, 0.3, 0.6, 0.1, 6.0, 9.0, 1.5, -1.5, 0.0],
    );
    assert_close(
        &rows[1],
        &[
            0.5, 4.625, 4.0, 0.625, 0.2, 0.175, 8.25, -1.5, -0.15, -0.15, 0.3,
        ],
    );
    assert_close(
        &rows[2],
        &[1.0, 9.0, 5.0, 0.2, 0.4, 0.4, 9.0, 9.0, -1.5, 0.9, 0.6],
    );
}

#[test]
fn eval_samples_are_evenly_spaced_and_end_at_one() {
    let dir = examples_dir();
    let out = run_in(&dir, &["eval", "example1.csv"], None);
    assert_eq!(out.code, 0, "{}", out.stderr);
    let (_, rows) = parse_csv(&out.stdout);
    assert_eq!(rows.len(), 101);
    assert_eq!(out.stdout.lines().nth(1).unwrap(), "0,1,3,0.3,0.6,0.1");
    assert_eq!(out.stdout.lines().last().unwrap(), "1,9,5,0.2,0.4,0.4");
    for (k, row) in rows.iter().enumerate() {
        assert_eq!(row[0], k as f64 / 100.0);
    }

    let out = run_in(&dir, &["eval", "example1.csv", "--samples", "3"], None);
    let (_, rows) = parse_csv(&out.stdout);
    let ts: Vec<f64> = rows.iter().map(|r| r[0]).collect();
    assert_eq!(ts, [0.0, 0.5, 1.0]);

    let out = run_in(&dir, &["eval", "example1.csv", "--samples", "1"], None);
    assert_eq!(out.stdout, format!("{HEADER_2D}\n0,1,3,0.3,0.6,0.1\n"));
}

#[test]
fn eval_json_is_an_array_of_objects() {
    let out = run_in(
        &examples_dir(),
        &["eval", "example1.json", "--at", "0,0.5", "--format", "json"],
        None,
    );
    assert_eq!(out.code, 0, "{}", out.stderr);
    assert!(
        out.stdout.starts_with(
            "[\n  {\"t\": 0, \"x\": 1, \"y\": 3, \"truth\": 0.3, \"indeterminacy\": 0.6, \"falsity\": 0.1},\n  {\"t\": 0.5, "
        ),
        "{}",
        out.stdout
    );
    assert!(out.stdout.ends_with("}\n]\n"), "{}", out.stdout);
    let value: serde_json::Value = serde_json::from_str(&out.stdout).expect("valid JSON");
    let rows = value.as_array().expect("an array");
    assert_eq!(rows.len(), 2);
    let at_half: Vec<f64> = ["t", "x", "y", "truth", "indeterminacy", "falsity"]
        .iter()
        .map(|c| rows[1][c].as_f64().expect(c))
        .collect();
    assert_close(&at_half, &[0.5, 4.625, 4.0, 0.625, 0.2, 0.175]);
}

#[test]
fn eval_3d_input_adds_z() {
    let out = run_in(
        &examples_dir(),
        &["eval", "helix3d.toml", "--at", "0,1", "--derivative"],
        None,
    );
    assert_eq!(out.code, 0, "{}", out.stderr);
    let (header, rows) = parse_csv(&out.stdout);
    assert_eq!(
        header.join(","),
        "t,x,y,z,truth,indeterminacy,falsity,dx,dy,dz,dtruth,dindeterminacy,dfalsity"
    );
    assert_close(&rows[0][..7], &[0.0, 1.0, 0.0, 0.0, 0.9, 0.1, 0.0]);
    assert_close(&rows[1][..7], &[1.0, 0.0, 1.0, 0.75, 0.1, 0.2, 0.8]);

    let csv = "x,y,z,T,I,F\n0,0,0,1,0,0\n1,2,3,0,1,0\n";
    let out = run_in(
        Path::new("."),
        &["eval", "-", "--at", "0.5"],
        Some(csv.as_bytes()),
    );
    assert_eq!(
        out.stdout,
        "t,x,y,z,truth,indeterminacy,falsity\n0.5,0.5,1,1.5,0.5,0.5,0\n"
    );
}

#[test]
fn eval_reads_csv_from_stdin() {
    let out = run_in(
        Path::new("."),
        &["eval", "-", "--at", "0.5"],
        Some(EXAMPLE1_CSV.as_bytes()),
    );
    assert_eq!(out.code, 0, "{}", out.stderr);
    let (_, rows) = parse_csv(&out.stdout);
    assert_close(&rows[0], &[0.5, 4.625, 4.0, 0.625, 0.2, 0.175]);

    let out = run_in(Path::new("."), &["eval", "-"], Some(b"x,y,truth\n1,2,3\n"));
    assert_eq!(
        (out.code, out.stderr.as_str()),
        (
            1,
            "error: <stdin>:1: missing column `indeterminacy` (neutrosophic rule requires it; truth and falsity alone are an intuitionistic table (--membership intuitionistic, indeterminacy 1 - T - F), truth alone a fuzzy one (--membership fuzzy))\n"
        )
    );
}

#[test]
fn eval_membership_rules_on_csv() {
    let dir = dir_with(&[
        (
            "ifs.csv",
            b"x,y,truth,falsity\n0,0,0.5,0.25\n1,1,0.2,0.7\n".as_slice(),
        ),
        ("fuzzy.csv", b"x,y,truth\n0,0,0.5\n1,1,1\n"),
    ]);
    let out = run_in(
        dir.path(),
        &[
            "eval",
            "ifs.csv",
            "--at",
            "0",
            "--membership",
            "intuitionistic",
        ],
        None,
    );
    assert_eq!(out.stdout, format!("{HEADER_2D}\n0,0,0,0.5,0.25,0.25\n"));
    let out = run_in(
        dir.path(),
        &["eval", "fuzzy.csv", "--at", "1", "--membership", "fuzzy"],
        None,
    );
    assert_eq!(out.stdout, format!("{HEADER_2D}\n1,1,1,1,0,0\n"));
    let out = run_in(dir.path(), &["eval", "ifs.csv"], None);
    assert_eq!(
        (out.code, out.stderr.as_str()),
        (
            1,
            "error: ifs.csv:1: missing column `indeterminacy` (neutrosophic rule requires it; truth and falsity alone are an intuitionistic table (--membership intuitionistic, indeterminacy 1 - T - F), truth alone a fuzzy one (--membership fuzzy))\n"
        )
    );
}

#[test]
fn eval_output_file_is_written_atomically() {
    let dir = dir_with(&[
        ("good.csv", EXAMPLE1_CSV.as_bytes()),
        ("bad.csv", b"x,y,truth,indeterminacy,falsity\n1,2,3,0,0\n"),
        ("out.csv", b"old contents\n"),
    ]);
    let out = run_in(dir.path(), &["eval", "bad.csv", "-o", "out.csv"], None);
    assert_eq!(out.code, 1);
    assert_eq!(
        std::fs::read_to_string(dir.path().join("out.csv")).unwrap(),
        "old contents\n"
    );

    let out = run_in(
        dir.path(),
        &["eval", "good.csv", "--at", "0.5", "-o", "out.csv"],
        None,
    );
    assert_eq!((out.code, out.stdout.as_str()), (0, ""), "{}", out.stderr);
    let written = std::fs::read_to_string(dir.path().join("out.csv")).unwrap();
    let (header, rows) = parse_csv(&written);
    assert_eq!(header.join(","), HEADER_2D);
    assert_close(&rows[0], &[0.5, 4.625, 4.0, 0.625, 0.2, 0.175]);

    let out = run_in(
        dir.path(),
        &["eval", "good.csv", "--output", "missing/out.csv"],
        None,
    );
    assert_eq!(out.code, 1);
    assert!(
        out.stderr
            .starts_with("error: missing/out.csv: cannot write: "),
        "{}",
        out.stderr
    );
    let mut names: Vec<String> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(
        names,
        ["bad.csv", "good.csv", "out.csv"],
        "no temporary file left"
    );
}

#[test]
fn eval_usage_errors_exit_2() {
    let dir = examples_dir();
    for args in [
        &["eval", "example1.csv", "--samples", "0"][..],
        &["eval", "example1.csv", "--samples", "-3"],
        &["eval", "example1.csv", "--samples", "many"],
        &["eval", "example1.csv", "--at", "1.5"],
        &["eval", "example1.csv", "--at", "-0.5"],
        &["eval", "example1.csv", "--at", "0,NaN"],
        &["eval", "example1.csv", "--at", "inf"],
        &["eval", "example1.csv", "--at", "0,,1"],
        &["eval", "example1.csv", "--at", "0.5", "--samples", "3"],
        &["eval", "example1.csv", "--format", "xml"],
        &["eval", "example1.csv", "--membership", "crisp"],
        &["eval"],
        &["frobnicate"],
        &[],
    ] {
        let out = run_in(&dir, args, None);
        assert_eq!(out.code, 2, "{args:?}: {}", out.stderr);
        // Without a subcommand clap prints the usage (not an `error:` line), still exit 2.
        assert!(
            out.stderr.starts_with("error: ") || args.is_empty(),
            "{args:?}: {}",
            out.stderr
        );
        assert!(out.stdout.is_empty(), "{args:?}");
    }
    let out = run_in(&dir, &["eval", "example1.csv", "--at", "1.5"], None);
    assert_eq!(
        out.stderr,
        "error: --at: t = 1.5 is outside the curve's domain [0, 1]\n"
    );
}

#[test]
fn eval_geometry_columns() {
    let dir = examples_dir();
    let out = run_in(
        &dir,
        &["eval", "nurbs-circle.toml", "--geometry", "--samples", "5"],
        None,
    );
    assert_eq!(out.code, 0, "{}", out.stderr);
    let mut lines = out.stdout.lines();
    assert_eq!(
        lines.next(),
        Some("t,x,y,truth,indeterminacy,falsity,arc_length,curvature")
    );
    // The unit circle: arc length 2 pi t, curvature 1.
    for (k, line) in lines.enumerate() {
        let cells: Vec<f64> = line.split(',').map(|c| c.parse().unwrap()).collect();
        let t = k as f64 / 4.0;
        assert_eq!(cells[0], t);
        let want = 2.0 * std::f64::consts::PI * t;
        assert!((cells[6] - want).abs() <= 1e-12 * want.max(1.0), "{line}");
        assert!((cells[7] - 1.0).abs() <= 1e-12, "{line}");
    }
    // --at in any order, a looser accuracy, JSON.
    let out = run_in(
        &dir,
        &[
            "eval",
            "example1.toml",
            "--geometry",
            "--accuracy",
            "1e-6",
            "--at",
            "1,0.5",
            "--format",
            "json",
        ],
        None,
    );
    assert_eq!(out.code, 0, "{}", out.stderr);
    let rows: serde_json::Value = serde_json::from_str(&out.stdout).unwrap();
    let length = |i: usize| rows[i]["arc_length"].as_f64().unwrap();
    // mpmath: 8.786730707839524 and 4.066732096133451.
    assert!(
        (length(0) - 8.786730707839524).abs() < 1e-5,
        "{}",
        out.stdout
    );
    assert!(
        (length(1) - 4.066732096133451).abs() < 1e-5,
        "{}",
        out.stdout
    );
    // A cusp has no curvature: an empty cell.
    let cusp = "x,y,truth,indeterminacy,falsity\n0,0,0.5,0.2,0.1\n1,1,0.5,0.2,0.1\n\
                0,1,0.5,0.2,0.1\n1,0,0.5,0.2,0.1\n";
    let out = run_in(
        Path::new("."),
        &["eval", "-", "--geometry", "--at", "0.5"],
        Some(cusp.as_bytes()),
    );
    assert_eq!(out.code, 0, "{}", out.stderr);
    let row = out.stdout.lines().nth(1).unwrap();
    assert!(
        row.starts_with("0.5,0.5,0.75,") && row.ends_with(','),
        "{row}"
    );
}

#[test]
fn eval_geometry_usage_errors_exit_2() {
    let dir = examples_dir();
    for (args, message) in [
        (
            &["eval", "surface.toml", "--geometry"][..],
            "error: --geometry applies only to curves (surface.toml holds a bezier-surface; \
             arc length and curvature are measured along a curve)\n",
        ),
        (
            &["eval", "example1.toml", "--geometry", "--accuracy", "0"],
            "error: invalid value '0' for '--accuracy <E>': `0` is not a positive finite \
             number (a relative accuracy such as 1e-12)\n\nFor more information, try '--help'.\n",
        ),
        (
            &["eval", "example1.toml", "--geometry", "--accuracy", "-1e-9"],
            "error: invalid value '-1e-9' for '--accuracy <E>': `-1e-9` is not a positive \
             finite number (a relative accuracy such as 1e-12)\n\nFor more information, try '--help'.\n",
        ),
    ] {
        let out = run_in(&dir, args, None);
        assert_eq!((out.code, out.stderr.as_str()), (2, message), "{args:?}");
        assert!(out.stdout.is_empty());
    }
    let out = run_in(&dir, &["eval", "example1.toml", "--accuracy", "1e-6"], None);
    assert_eq!(out.code, 2, "{}", out.stderr);
    assert!(out.stderr.contains("--geometry"), "{}", out.stderr);
}

#[test]
fn eval_unsupported_extension_exits_2() {
    let dir = dir_with(&[("curve.txt", EXAMPLE1_CSV.as_bytes())]);
    let out = run_in(dir.path(), &["eval", "curve.txt"], None);
    assert_eq!(
        (out.code, out.stderr.as_str()),
        (
            2,
            "error: curve.txt: unsupported file extension `.txt` (accepted: .csv, .tsv, .toml, .json; `-` reads CSV from standard input)\n"
        )
    );
}

#[test]
fn eval_missing_file_exits_1() {
    let dir = dir_with::<&str>(&[]);
    let out = run_in(dir.path(), &["eval", "nope.csv"], None);
    assert_eq!(out.code, 1);
    assert!(
        out.stderr.starts_with("error: nope.csv: cannot read: "),
        "{}",
        out.stderr
    );
}

#[test]
fn csv_errors_have_exact_messages() {
    let h = "x,y,truth,indeterminacy,falsity\n";
    let cases: &[(&[u8], &str)] = &[
        (b"", "error: bad.csv: empty file (expected a header row such as `x,y,truth,indeterminacy,falsity`)"),
        (b"# comment only\r\n", "error: bad.csv: empty file (expected a header row such as `x,y,truth,indeterminacy,falsity`)"),
        (h.as_bytes(), "error: bad.csv: no control points (the header row is not followed by any data row)"),
        (b"x,truth,indeterminacy,falsity\n1,0,0,0\n", "error: bad.csv:1: missing column `y` (every file needs x and y)"),
        (b"x,y,indeterminacy,falsity\n1,2,0,0\n", "error: bad.csv:1: missing column `truth` (every membership rule requires it)"),
        (b"x,y,truth,indeterminacy\n1,2,0,0\n", "error: bad.csv:1: missing column `falsity` (neutrosophic rule requires it)"),
        (b"x,y,truth,indeterminacy,falsity,T\n", "error: bad.csv:1: column 6 `T` repeats column 3 `truth` (each field may appear once; T, I and F are aliases of truth, indeterminacy and falsity)"),
        (b"X,y,x,truth,indeterminacy,falsity\n", "error: bad.csv:1: column 3 `x` repeats column 1 `X` (each field may appear once; T, I and F are aliases of truth, indeterminacy and falsity)"),
        (b"x,y,w,truth,indeterminacy,falsity\n", "error: bad.csv:1: unknown column `w` (known columns: x, y, z, truth (T), indeterminacy (I), falsity (F), weight, name)"),
        (b"# c\nx,y,truth,indeterminacy,falsity\n# c\n1,2,high,0,0\n", "error: bad.csv:4: column `truth`: value `high` is not a number"),
        (b"x,y,truth,indeterminacy,falsity\n1,2,0,0,0\n1,,0,0,0\n", "error: bad.csv:3: column `y`: value `` is not a number"),
        (b"x,y,truth,indeterminacy,falsity\r\n1,NaN,0,0,0\r\n", "error: bad.csv:2: column `y`: value `NaN` is not a finite number (NaN and infinities are not allowed)"),
        (b"x,y,truth,indeterminacy,falsity\n1,2,0,inf,0\n", "error: bad.csv:2: column `indeterminacy`: value `inf` is not a finite number (NaN and infinities are not allowed)"),
        (b"x,y,truth,indeterminacy,falsity\n1,2,0,0,0\n\n1,2,0,0\n", "error: bad.csv:4: the row has 4 cells but the header has 5 (every row needs one cell per column)"),
        (b"x,y,truth,indeterminacy,falsity\n1,2,0,0,0,0\n", "error: bad.csv:2: the row has 6 cells but the header has 5 (every row needs one cell per column)"),
        (b"x,y,truth,indeterminacy,falsity\n# \xe9t\xe9\n1,2,0,0,0\n", "error: bad.csv:2: invalid UTF-8 (the file must be UTF-8 encoded)"),
        (b"x,y,truth,indeterminacy,falsity\n1,2,1.2,0,0\n", "error: bad.csv:2: truth = 1.2 is outside [0, 1] (every degree must be in [0, 1])"),
        (b"\xEF\xBB\xBFx,y,T,I,F\r\n1,2,0.5,-0.25,0\r\n", "error: bad.csv:2: indeterminacy = -0.25 is outside [0, 1] (every degree must be in [0, 1])"),
        (b"name,x,y,T,I,F\n\"two\nlines\",1,2,0,0,0\nC1,1,2,0,0,2\n", "error: bad.csv:4: falsity = 2 is outside [0, 1] (every degree must be in [0, 1])"),
    ];
    for (contents, message) in cases {
        assert_invalid("bad.csv", contents, &["eval", "bad.csv"], message);
        assert_invalid("bad.csv", contents, &["check", "bad.csv"], message);
    }
}

#[test]
fn csv_membership_errors_have_exact_messages() {
    let cases: &[(&str, &str, &str)] = &[
        ("intuitionistic", "x,y,truth,falsity\n0,0,0.7,0.6\n", "error: bad.csv:2: truth + falsity = 0.7 + 0.6 = 1.2999999999999998 exceeds 1 (intuitionistic rule: truth + falsity <= 1)"),
        ("intuitionistic", "x,y,T,I,F\n0,0,0.5,0.3,0.25\n", "error: bad.csv:2: indeterminacy = 0.3 differs from the hesitation 1 - truth - falsity = 0.25 (intuitionistic rule: indeterminacy is derived; omit it or give 1 - truth - falsity)"),
        ("intuitionistic", "x,y,truth\n0,0,0.5\n", "error: bad.csv:1: missing column `falsity` (intuitionistic rule requires it)"),
        ("fuzzy", "x,y,truth,falsity\n0,0,0.5,0.1\n", "error: bad.csv:2: falsity = 0.1 is not allowed (fuzzy rule: only truth is given; falsity must be absent or 0)"),
    ];
    for (rule, contents, message) in cases {
        assert_invalid(
            "bad.csv",
            contents.as_bytes(),
            &["eval", "bad.csv", "--membership", rule],
            message,
        );
    }
}

const MODEL_TOML: &str = r#"kind = "bezier"
name = "test"

[[control_points]]
x = 0
y = 0
truth = 0.5
indeterminacy = 0.5
falsity = 0.5

[[control_points]]
x = 1
y = 1
truth = 0.25
indeterminacy = 0.75
falsity = 0.125
"#;

#[test]
fn toml_errors_name_field_path_and_line() {
    // Lines 11-16 hold the second control point: its table starts at line 11.
    let cases: &[(&str, &str, &str)] = &[
        ("truth = 0.25", "truth = 1.5", "error: bad.toml:14: control_points[1]: truth = 1.5 is outside [0, 1] (every degree must be in [0, 1])"),
        ("y = 1\n", "y = \"one\"\n", "error: bad.toml:13: control_points[1].y: expected a number, found the string \"one\""),
        ("y = 1\n", "y = 1\nw = 2\n", "error: bad.toml:14: control_points[1]: unknown key `w` (known keys: x, y, z, truth (T), indeterminacy (I), falsity (F), weight, name)"),
        ("y = 1\n", "y = 1\nT = 0.5\n", "error: bad.toml:15: control_points[1]: key `truth` repeats key `T` (each field may appear once; T, I and F are aliases of truth, indeterminacy and falsity)"),
        ("y = 1\n", "y = 1\nz = 2\n", "error: bad.toml:11: control_points[1]: has `z` but control_points[0] has none (all control points must have the same dimension)"),
        ("y = 1\n", "y = inf\n", "error: bad.toml:13: control_points[1].y: value inf is not a finite number (NaN and infinities are not allowed)"),
        ("falsity = 0.125\n", "", "error: bad.toml:11: control_points[1]: missing key `falsity` (neutrosophic rule requires it)"),
        ("y = 1\n", "", "error: bad.toml:11: control_points[1]: missing key `y` (every control point needs x and y)"),
        ("kind = \"bezier\"", "kind = \"spline\"", "error: bad.toml:1: kind: unknown kind `spline` (known kinds: bezier, bspline, nurbs, bezier-surface, bspline-surface, nurbs-surface)"),
        ("kind = \"bezier\"\n", "", "error: bad.toml: missing key `kind` (known kinds: bezier, bspline, nurbs, bezier-surface, bspline-surface, nurbs-surface)"),
        ("name = \"test\"", "name = \"test\"\ncolour = \"red\"", "error: bad.toml:3: unknown key `colour` (known keys: kind, name, description, membership, q, n, degree, knots, rows, cols, degree_u, degree_v, knots_u, knots_v, periodic, periodic_u, periodic_v, control_points)"),
        ("name = \"test\"", "name = 7", "error: bad.toml:2: name: expected a string, found a number"),
        ("name = \"test\"", "membership = \"crisp\"", "error: bad.toml:2: membership: unknown membership family `crisp` (no such family; expected one of: neutrosophic, intuitionistic, fuzzy, pythagorean, fermatean, q-rung:Q, picture, spherical, t-spherical:N, interval-neutrosophic, interval-intuitionistic, interval-type2, bipolar-neutrosophic (Q and N integers >= 1))"),
        ("name = \"test\"", "name = \"test\"\nname = \"again\"", "error: bad.toml:3: invalid TOML: duplicate key `name` in document root"),
    ];
    for (from, to, message) in cases {
        let contents = MODEL_TOML.replacen(from, to, 1);
        assert_ne!(contents, MODEL_TOML, "replacement {from:?} applied");
        assert_invalid(
            "bad.toml",
            contents.as_bytes(),
            &["eval", "bad.toml"],
            message,
        );
    }
    assert_invalid(
        "bad.toml",
        b"kind = \"bezier\"\ncontrol_points = []\n",
        &["check", "bad.toml"],
        "error: bad.toml:2: control_points: no control points (a curve needs at least one)",
    );
    assert_invalid(
        "bad.toml",
        b"kind = \"bezier\"\n",
        &["check", "bad.toml"],
        "error: bad.toml: missing key `control_points` (the list of control points)",
    );
    assert_invalid(
        "bad.toml",
        b"kind = \"bezier\"\ncontrol_points = [1]\n",
        &["check", "bad.toml"],
        "error: bad.toml:2: control_points[0]: expected a table, found a number",
    );
    assert_invalid(
        "bad.toml",
        b"kind = \"bezier\"\n\xff\n",
        &["check", "bad.toml"],
        "error: bad.toml:2: invalid UTF-8 (the file must be UTF-8 encoded)",
    );
}

#[test]
fn toml_syntax_error_is_one_line_with_line_number() {
    let dir = dir_with(&[("bad.toml", b"kind = \"bezier\"\n\n[[control_points]\n")]);
    let out = run_in(dir.path(), &["check", "bad.toml"], None);
    assert_eq!(out.code, 1);
    assert!(
        out.stderr.starts_with("error: bad.toml:3: invalid TOML: "),
        "{}",
        out.stderr
    );
    assert_eq!(out.stderr.lines().count(), 1, "{}", out.stderr);
}

#[test]
fn toml_membership_declared_and_overridden() {
    let fuzzy = "kind = \"bezier\"\nmembership = \"fuzzy\"\ncontrol_points = [{ x = 0, y = 0, truth = 0.25 }]\n";
    let dir = dir_with(&[("f.toml", fuzzy.as_bytes())]);
    let out = run_in(dir.path(), &["eval", "f.toml", "--at", "0"], None);
    assert_eq!(out.stdout, format!("{HEADER_2D}\n0,0,0,0.25,0,0\n"));
    let out = run_in(
        dir.path(),
        &["eval", "f.toml", "--membership", "fuzzy", "--samples", "1"],
        None,
    );
    assert_eq!(out.code, 0, "{}", out.stderr);
    assert_invalid(
        "f.toml",
        fuzzy.as_bytes(),
        &["eval", "f.toml", "--membership", "intuitionistic"],
        "error: f.toml:2: membership: the file declares membership `fuzzy` but --membership is `intuitionistic` (omit --membership or make them agree)",
    );
    let none = fuzzy.replace("membership = \"fuzzy\"\n", "");
    assert_invalid(
        "n.toml",
        none.as_bytes(),
        &["eval", "n.toml"],
        "error: n.toml:2: control_points[0]: missing key `indeterminacy` (neutrosophic rule requires it)",
    );
}

#[test]
fn json_errors_name_field_path() {
    let cases: &[(&str, &str)] = &[
        (r#"{"kind": "bezier", "control_points": [{"x": 0, "y": 0, "T": 0.5, "I": 0.5, "F": 0.5}, {"x": 0, "y": 0, "T": 0.5, "I": 1.5, "F": 0.5}]}"#,
         "error: bad.json: control_points[1]: indeterminacy = 1.5 is outside [0, 1] (every degree must be in [0, 1])"),
        (r#"{"kind": "bezier", "control_points": [{"x": 0, "y": "0", "T": 0.5, "I": 0.5, "F": 0.5}]}"#,
         "error: bad.json: control_points[0].y: expected a number, found the string \"0\""),
        (r#"{"kind": "bezier", "control_points": [{"x": 0, "y": 0, "truth": 0.5, "T": 0.5, "I": 0.5, "F": 0.5}]}"#,
         "error: bad.json: control_points[0]: key `T` repeats key `truth` (each field may appear once; T, I and F are aliases of truth, indeterminacy and falsity)"),
        (r#"{"kind": "bezier", "kind": "bezier", "control_points": []}"#,
         "error: bad.json: duplicated key `kind` (each key may appear once)"),
        (r#"{"kind": "bezier", "control_points": {}}"#,
         "error: bad.json: control_points: expected an array, found an object"),
        (r#"{"kind": "bezier", "extra": 1, "control_points": []}"#,
         "error: bad.json: unknown key `extra` (known keys: kind, name, description, membership, q, n, degree, knots, rows, cols, degree_u, degree_v, knots_u, knots_v, periodic, periodic_u, periodic_v, control_points)"),
        (r#"{"kind": "bezier", "control_points": [{"x": 0, "y": 0, "z": 0, "T": 0.5, "I": 0.5, "F": 0.5}, {"x": 0, "y": 0, "T": 0.5, "I": 0.5, "F": 0.5}]}"#,
         "error: bad.json: control_points[1]: has no `z` but control_points[0] has one (all control points must have the same dimension)"),
        ("{\n  \"kind\": \"bezier\",\n  \"control_points\": [\n}\n", "error: bad.json:4: invalid JSON: expected value (column 1)"),
        ("", "error: bad.json:1: invalid JSON: EOF while parsing a value (column 0)"),
        ("[]", "error: bad.json: expected an object at the top level, found an array"),
    ];
    for (contents, message) in cases {
        assert_invalid(
            "bad.json",
            contents.as_bytes(),
            &["eval", "bad.json"],
            message,
        );
    }
}

#[test]
fn check_prints_summary() {
    let out = run_in(&examples_dir(), &["check", "example1.toml"], None);
    assert_eq!(out.code, 0, "{}", out.stderr);
    assert_eq!(
        out.stdout,
        "example1.toml: valid\nkind: bezier\nname: Example 1\ndegree: 3\ndimension: 2\n\
         control points: 4\nmembership: neutrosophic\ndomain: [0, 1]\ntruth: 0.2..0.8\n\
         indeterminacy: 0.1..0.6\nfalsity: 0.1..0.4\n\
         length: 8.78673070784\naverage truth: 0.486657146182\n\
         average indeterminacy: 0.304139343158\naverage falsity: 0.209203510661\n\
         average score: 0.657771430788\n"
    );
    // The length and averages above, and the circle's below, are mpmath's rounded to 12
    // digits (scripts/reference/make_arc_length_reference.py prints them).
    let out = run_in(&examples_dir(), &["check", "nurbs-circle.toml"], None);
    assert_eq!(out.code, 0, "{}", out.stderr);
    assert!(
        out.stdout.ends_with(
            "length: 6.28318530718\naverage truth: 0.55\naverage indeterminacy: 0.3\n\
             average falsity: 0.3\naverage score: 0.65\n"
        ),
        "{}",
        out.stdout
    );
    // Above degree 30 check does not measure, and says so.
    let points: String = (0..32)
        .map(|k| format!("{k},{},0.5,0.1,0.1\n", k % 3))
        .collect();
    let csv = format!("x,y,truth,indeterminacy,falsity\n{points}");
    let out = run_in(Path::new("."), &["check", "-"], Some(csv.as_bytes()));
    assert_eq!(out.code, 0, "{}", out.stderr);
    assert!(
        out.stdout.ends_with(
            "length: not measured (check measures curves of at most 1000 control points and \
             degree 30; `eval --geometry` gives the arc length)\n"
        ),
        "{}",
        out.stdout
    );
    // Surfaces have no length line.
    let out = run_in(&examples_dir(), &["check", "surface.toml"], None);
    assert_eq!(out.code, 0, "{}", out.stderr);
    assert!(!out.stdout.contains("length"), "{}", out.stdout);
    let out = run_in(&examples_dir(), &["check", "helix3d.toml"], None);
    assert_eq!(out.code, 0, "{}", out.stderr);
    assert!(out.stdout.contains("dimension: 3\n"), "{}", out.stdout);
    assert!(out.stdout.contains("falsity: 0..0.8\n"), "{}", out.stdout);

    let out = run_in(
        Path::new("."),
        &["check", "-"],
        Some(EXAMPLE1_CSV.as_bytes()),
    );
    assert_eq!(out.code, 0, "{}", out.stderr);
    assert!(out
        .stdout
        .starts_with("<stdin>: valid\nkind: bezier\ndegree: 3\n"));
}

#[test]
fn example_prints_control_points_curve_and_erratum() {
    let out = run_in(Path::new("."), &["example"], None);
    assert_eq!(out.code, 0, "{}", out.stderr);
    let lines: Vec<&str> = out.stdout.lines().collect();
    assert!(
        lines.contains(&"point  x  y  truth  indeterminacy  falsity"),
        "{}",
        out.stdout
    );
    assert!(
        lines.contains(&"C3     9  5    0.2            0.4      0.4"),
        "{}",
        out.stdout
    );
    let row = lines
        .iter()
        .find(|l| l.trim_start().starts_with("0.5 "))
        .expect("t = 0.5 row");
    let cells: Vec<&str> = row.split_whitespace().collect();
    assert_eq!(cells, ["0.5", "4.625", "4", "0.625", "0.2", "0.175"]);
    let ts: Vec<&str> = lines
        .iter()
        .skip_while(|l| !l.starts_with("Curve at"))
        .skip(2)
        .take_while(|l| !l.is_empty())
        .map(|l| l.split_whitespace().next().unwrap())
        .collect();
    assert_eq!(
        ts,
        ["0", "0.1", "0.2", "0.3", "0.4", "0.5", "0.6", "0.7", "0.8", "0.9", "1"]
    );
    assert!(out
        .stdout
        .contains("Table 3 gives C3 an indeterminacy of 0.1"));
}

#[test]
fn help_and_version_exit_0() {
    for args in [
        &["--help"][..],
        &["--version"],
        &["eval", "--help"],
        &["help", "check"],
    ] {
        let out = run_in(Path::new("."), args, None);
        assert_eq!(out.code, 0, "{args:?}: {}", out.stderr);
        assert!(!out.stdout.is_empty());
    }
}

#[test]
fn closed_stdout_ends_quietly() {
    let dir = examples_dir();
    let mut child = Command::new(BIN)
        .args(["eval", "example1.csv", "--samples", "2000000"])
        .current_dir(&dir)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("binary runs");
    let mut stdout = child.stdout.take().expect("stdout piped");
    let mut first = [0u8; 64];
    stdout.read_exact(&mut first).expect("some output");
    drop(stdout);
    let out = child.wait_with_output().expect("binary finishes");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert!(stderr.is_empty(), "{stderr}");
}

/// A long `eval` shows a progress bar on a terminal's standard error (a pseudo-terminal from
/// util-linux `script`), counting to the row total, and clears it; the table is complete.
#[test]
fn progress_bar_on_a_terminal_only() {
    let dir = tempfile::tempdir().expect("temp dir");
    let model = examples_dir().join("example1.csv");
    let table = dir.path().join("table.csv");
    let rows = 1_000_000;
    let command = format!(
        "'{BIN}' eval '{}' --samples {rows} -o '{}'",
        model.display(),
        table.display()
    );
    let out = Command::new("script")
        .args(["--quiet", "--return", "--command", &command, "/dev/null"])
        .stdin(Stdio::null())
        .output()
        .expect("util-linux `script` runs");
    let terminal = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{terminal}");
    assert!(
        terminal.contains("/1,000,000 rows, ") && terminal.contains(" M rows/s, "),
        "no progress bar in {terminal:?}"
    );
    // Cleared at the end: the last thing drawn erases the line.
    assert!(
        terminal
            .trim_end_matches(['\r', '\n'])
            .ends_with("\u{1b}[2K"),
        "bar not cleared: {:?}",
        &terminal[terminal.len().saturating_sub(200)..]
    );
    let written = std::fs::read_to_string(&table).expect("table written");
    assert_eq!(written.lines().count(), rows + 1);
    assert_eq!(written.lines().last(), Some("1,9,5,0.2,0.4,0.4"));

    // Standard error not a terminal: nothing on it.
    let out = run_in(
        &examples_dir(),
        &[
            "eval",
            "example1.csv",
            "--samples",
            "1000000",
            "-o",
            table.to_str().expect("UTF-8 path"),
        ],
        None,
    );
    assert_eq!((out.code, out.stderr.as_str()), (0, ""));
}

/// `eval` streams: its peak resident memory (VmHWM, polled from /proc while it runs) stays
/// far below the size of the table it writes (2,000,000 rows, about 190 MB of CSV).
#[test]
fn eval_memory_stays_flat() {
    let mut child = Command::new(BIN)
        .args([
            "eval",
            "example1.csv",
            "--samples",
            "2000000",
            "-o",
            "/dev/null",
        ])
        .current_dir(examples_dir())
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .expect("binary runs");
    let status = format!("/proc/{}/status", child.id());
    let mut peak_kib = 0u64;
    let mut readings = 0;
    while child.try_wait().expect("child state").is_none() {
        let hwm = std::fs::read_to_string(&status).ok().and_then(|s| {
            s.lines()
                .find_map(|l| l.strip_prefix("VmHWM:"))
                .and_then(|v| v.trim().trim_end_matches("kB").trim().parse::<u64>().ok())
        });
        if let Some(kib) = hwm {
            peak_kib = peak_kib.max(kib);
            readings += 1;
        }
        std::thread::sleep(std::time::Duration::from_millis(5));
    }
    let out = child.wait_with_output().expect("binary finishes");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(readings > 10, "only {readings} readings");
    assert!(peak_kib < 32 * 1024, "peak resident memory {peak_kib} KiB");
}
