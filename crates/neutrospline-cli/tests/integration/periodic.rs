//! Periodic (closed) and unclamped curves from end to end (examples/closed-bspline.toml):
//! `check` names the knots' kind, `eval` closes the curve, `transform` keeps it periodic and
//! knot removal undoes insertion, a CSV reads with `--periodic`, `fit --closed` writes the
//! periodic form, the DXF export reads back periodic, and misuse gets its message.

use std::path::Path;

use crate::util::{dir_with, dir_with_examples, run_in, Output};

const EXAMPLE: &str = "closed-bspline.toml";

fn ok(dir: &Path, args: &[&str]) -> Output {
    let out = run_in(dir, args, None);
    assert_eq!(out.code, 0, "{args:?}: {}", out.stderr);
    out
}

/// The model file `name` written in `dir`, which must be in the periodic form.
fn periodic_file(dir: &Path, name: &str) -> String {
    let text = std::fs::read_to_string(dir.join(name)).unwrap();
    assert!(text.contains("periodic = true\n"), "{name}: {text}");
    text
}

fn rows(out: &Output) -> Vec<Vec<f64>> {
    out.stdout
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect()
}

fn assert_close(a: &[Vec<f64>], b: &[Vec<f64>], what: &str) {
    assert_eq!(a.len(), b.len(), "{what}");
    for (r, s) in a.iter().zip(b) {
        for (x, y) in r.iter().zip(s) {
            assert!(
                (x - y).abs() <= 1e-12 * x.abs().max(100.0),
                "{what}: {r:?} vs {s:?}"
            );
        }
    }
}

#[test]
fn the_example_is_periodic_and_closes() {
    let dir = dir_with_examples(&[EXAMPLE], &[("none", "")]);
    let check = ok(dir.path(), &["check", EXAMPLE]).stdout;
    assert!(check.contains("control points: 9\n"), "{check}");
    assert!(
        check.contains("(13 knots, chord-length, periodic)\ndomain: [0, 1]\n"),
        "{check}"
    );
    let ends = rows(&ok(
        dir.path(),
        &["eval", EXAMPLE, "--at", "0,1", "--derivative", "2"],
    ));
    for (x, y) in ends[0][1..].iter().zip(&ends[1][1..]) {
        assert!((x - y).abs() <= 1e-12 * x.abs().max(1.0), "{ends:?}");
    }
}

#[test]
fn transform_keeps_it_periodic_and_removal_undoes_insertion() {
    let dir = dir_with_examples(&[EXAMPLE], &[("none", "")]);
    let original = rows(&ok(dir.path(), &["eval", EXAMPLE, "--samples", "41"]));
    ok(
        dir.path(),
        &[
            "transform",
            EXAMPLE,
            "-o",
            "more.toml",
            "--insert-knot",
            "0.3,0.3,0.95",
        ],
    );
    let more = periodic_file(dir.path(), "more.toml");
    assert_eq!(more.matches("[[control_points]]").count(), 9);
    assert_close(
        &original,
        &rows(&ok(dir.path(), &["eval", "more.toml", "--samples", "41"])),
        "inserted",
    );
    let removed = ok(
        dir.path(),
        &[
            "transform",
            "more.toml",
            "-o",
            "back.toml",
            "--remove-knot",
            "0.3",
            "--times",
            "2",
            "--tolerance",
            "1e-9",
        ],
    );
    assert!(
        removed.stderr.contains("removed knot 0.3 2 of 2 times"),
        "{}",
        removed.stderr
    );
    ok(
        dir.path(),
        &[
            "transform",
            "back.toml",
            "-o",
            "back2.toml",
            "--remove-knot",
            "0.95",
            "--tolerance",
            "1e-9",
        ],
    );
    let back = periodic_file(dir.path(), "back2.toml");
    assert_eq!(back.matches("[[control_points]]").count(), 6);
    assert_close(
        &original,
        &rows(&ok(dir.path(), &["eval", "back2.toml", "--samples", "41"])),
        "removed",
    );
    // Reversal keeps it periodic too; splitting opens it.
    ok(
        dir.path(),
        &["transform", EXAMPLE, "-o", "rev.toml", "--reverse"],
    );
    periodic_file(dir.path(), "rev.toml");
    ok(
        dir.path(),
        &["transform", EXAMPLE, "-o", "half.toml", "--split", "0.5"],
    );
    assert!(!std::fs::read_to_string(dir.path().join("half-1.toml"))
        .unwrap()
        .contains("periodic"));
}

#[test]
fn a_csv_reads_with_periodic_and_refusals_name_the_rule() {
    let csv = "x,y,truth,indeterminacy,falsity\n0,0,0.9,0.1,0.1\n2,0,0.5,0.2,0.3\n2,2,0.3,0.2,0.6\n0,2,0.1,0.4,0.8\n";
    let toml = "kind = \"bspline\"\ndegree = 2\nperiodic = true\ncontrol_points = [\n\
        { x = 0, y = 0, T = 0.9, I = 0.1, F = 0.1 },\n{ x = 2, y = 0, T = 0.5, I = 0.2, F = 0.3 },\n\
        { x = 2, y = 2, T = 0.3, I = 0.2, F = 0.6 },\n{ x = 0, y = 2, T = 0.1, I = 0.4, F = 0.8 },\n]\n";
    let dir = dir_with(&[("c.csv", csv), ("c.toml", toml)]);
    let from_csv = ok(
        dir.path(),
        &[
            "eval",
            "c.csv",
            "--kind",
            "bspline",
            "--degree",
            "2",
            "--periodic",
            "--samples",
            "9",
        ],
    );
    let from_toml = ok(dir.path(), &["eval", "c.toml", "--samples", "9"]);
    assert_eq!(from_csv.stdout, from_toml.stdout);
    let cases: [(&[&str], i32, &str); 3] = [
        (&["eval", "c.csv", "--periodic"], 2, "error: --periodic does not apply to kind `bezier` (--periodic is for: bspline, nurbs); choose the kind with --kind"),
        (&["eval", "c.csv", "--kind", "bspline", "--degree", "2", "--periodic", "--knots", "0,1,2"],
         1, "error: c.csv: --knots: a periodic spline of 4 control points takes 5 breakpoints (the control points + 1, from the start of one period to its end), not 3"),
        (&["eval", "c.csv", "--kind", "bspline", "--degree", "0", "--periodic"],
         1, "error: c.csv: --periodic: a periodic spline needs degree >= 1 (degree 0 has nothing to join)"),
    ];
    for (args, code, want) in cases {
        let out = run_in(dir.path(), args, None);
        assert_eq!((out.code, out.stderr.trim_end()), (code, want), "{args:?}");
    }
}

#[test]
fn fit_closed_and_dxf_write_the_periodic_form() {
    let mut data = String::from("x,y,truth\n");
    for k in 0..30 {
        let a = std::f64::consts::TAU * f64::from(k) / 30.0;
        data.push_str(&format!(
            "{},{},{}\n",
            3.0 * a.cos(),
            2.0 * a.sin(),
            0.5 + 0.4 * a.cos()
        ));
    }
    let dir = dir_with_examples(&[EXAMPLE], &[("ring.csv", data)]);
    ok(
        dir.path(),
        &[
            "fit",
            "ring.csv",
            "--closed",
            "--membership",
            "fuzzy",
            "-o",
            "ring.toml",
        ],
    );
    periodic_file(dir.path(), "ring.toml");
    ok(dir.path(), &["export", EXAMPLE, "-o", "pond.dxf"]);
    ok(dir.path(), &["import", "pond.dxf", "-o", "pond.toml"]);
    periodic_file(dir.path(), "pond.toml");
    assert_close(
        &rows(&ok(dir.path(), &["eval", EXAMPLE, "--samples", "33"])),
        &rows(&ok(dir.path(), &["eval", "pond.toml", "--samples", "33"])),
        "DXF round trip",
    );
}

/// Found in review: a periodic curve with fewer distinct points than its degree keeps its
/// shape under insertion (the copies of the knot share control points), a surface stays
/// periodic when reversed, and unclamped uniform knots are not called periodic.
#[test]
fn few_points_surfaces_and_uniform_knots() {
    let few = "kind = \"bspline\"\ndegree = 4\nperiodic = true\ncontrol_points = [\n\
        { x = 0, y = 0, T = 0.5, I = 0.5, F = 0.5 },\n{ x = 1, y = 0, T = 0.2, I = 0.5, F = 0.5 },\n]\n";
    let mut surface = String::from(
        "kind = \"bspline-surface\"\nrows = 3\ncols = 2\ndegree_u = 2\ndegree_v = 1\nperiodic_u = true\ncontrol_points = [\n",
    );
    for i in 0..3 {
        for j in 0..2 {
            surface.push_str(&format!(
                "{{ x = {i}, y = {j}, z = {}, T = 0.5, I = 0.5, F = 0.5 }},\n",
                (i + j) % 2
            ));
        }
    }
    surface.push_str("]\n");
    let uniform = "kind = \"bspline\"\ndegree = 2\nknots = \"uniform\"\ncontrol_points = [\n\
        { x = 0, y = 0, T = 0.5, I = 0.5, F = 0.5 },\n{ x = 1, y = 1, T = 0.5, I = 0.5, F = 0.5 },\n\
        { x = 2, y = 0, T = 0.5, I = 0.5, F = 0.5 },\n]\n";
    let dir = dir_with(&[
        ("few.toml", few),
        ("s.toml", surface.as_str()),
        ("u.toml", uniform),
    ]);
    let before = rows(&ok(dir.path(), &["eval", "few.toml", "--samples", "21"]));
    ok(
        dir.path(),
        &[
            "transform",
            "few.toml",
            "-o",
            "more.toml",
            "--insert-knot",
            "0.25,0.6",
        ],
    );
    assert_close(
        &before,
        &rows(&ok(dir.path(), &["eval", "more.toml", "--samples", "21"])),
        "few points",
    );
    ok(
        dir.path(),
        &[
            "transform",
            "more.toml",
            "-o",
            "back.toml",
            "--remove-knot",
            "0.25",
            "--tolerance",
            "1e-9",
        ],
    );
    assert_close(
        &before,
        &rows(&ok(dir.path(), &["eval", "back.toml", "--samples", "21"])),
        "removed",
    );
    ok(
        dir.path(),
        &[
            "transform",
            "s.toml",
            "-o",
            "r.toml",
            "--reverse",
            "--direction",
            "u",
        ],
    );
    let reversed = std::fs::read_to_string(dir.path().join("r.toml")).unwrap();
    assert!(
        reversed.contains("rows = 3\n") && reversed.contains("periodic_u = true\n"),
        "{reversed}"
    );
    let check = ok(dir.path(), &["check", "u.toml"]).stdout;
    assert!(
        check.contains("knots: -2, -1, 0, 1, 2, 3 (6 knots, uniform)\n"),
        "{check}"
    );
}
