//! End-to-end tests of `neutrospline transform`: every exact operation writes a model that
//! `eval` shows to be the same curve or surface (to 1e-12 of its scale), pieces cover their
//! parts, knot removal undoes insertion and reports itself, the membership rule and spreads
//! survive, and each misuse gets its message.

use std::path::Path;

use crate::util::{example, run_in, Output};

fn run(dir: &Path, args: &[&str]) -> Output {
    run_in(dir, args, None)
}

fn ok(dir: &Path, args: &[&str]) -> Output {
    let out = run(dir, args);
    assert_eq!(out.code, 0, "{args:?}: {}", out.stderr);
    out
}

/// The numeric rows of an `eval` CSV table.
fn table(dir: &Path, args: &[&str]) -> Vec<Vec<f64>> {
    let out = ok(dir, &[&["eval"], args].concat());
    out.stdout
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect()
}

fn assert_tables(a: &[Vec<f64>], b: &[Vec<f64>], skip: usize, what: &str) {
    assert_eq!(a.len(), b.len(), "{what}");
    for (r, s) in a.iter().zip(b) {
        for (x, y) in r[skip..].iter().zip(&s[skip..]) {
            assert!(
                (x - y).abs() <= 1e-12 * x.abs().max(10.0),
                "{what}: {r:?} vs {s:?}"
            );
        }
    }
}

const AT: &str = "0,0.05,0.2,0.33,0.5,0.61,0.77,0.9,1";

#[test]
fn exact_operations_keep_every_kind_of_curve() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for name in [
        "example1.toml",
        "bspline.toml",
        "nurbs-circle.toml",
        "helix3d.toml",
        "fuzzy-bspline.toml",
    ] {
        let model = example(name);
        let model = model.to_str().unwrap();
        let original = table(d, &[model, "--at", AT]);
        for op in [
            vec!["--elevate", "2"],
            vec!["--insert-knot", "0.33,0.33,0.8"],
            vec!["--refine", "2"],
            vec!["--reparametrize", "0:1"],
        ] {
            let mut args = vec!["transform", model, "-o", "out.toml"];
            args.extend(&op);
            ok(d, &args);
            ok(d, &["check", "out.toml"]);
            let after = table(d, &["out.toml", "--at", AT]);
            assert_tables(&original, &after, 1, &format!("{name} {op:?}"));
        }
        // Reversed: the point at t is the original's at 1 - t.
        ok(d, &["transform", model, "-o", "rev.toml", "--reverse"]);
        let mirrored: Vec<String> = AT
            .split(',')
            .rev()
            .map(|t| (1.0 - t.parse::<f64>().unwrap()).to_string())
            .collect();
        let reversed = table(d, &["rev.toml", "--at", &mirrored.join(",")]);
        let mut expected = original.clone();
        expected.reverse();
        assert_tables(&expected, &reversed, 1, &format!("{name} reverse"));
        // Reparametrized onto [2, 6]: the point at 2 + 4 t is the original's at t.
        ok(
            d,
            &[
                "transform",
                model,
                "-o",
                "moved.toml",
                "--reparametrize",
                "2:6",
            ],
        );
        let mapped: Vec<String> = AT
            .split(',')
            .map(|t| (2.0 + 4.0 * t.parse::<f64>().unwrap()).to_string())
            .collect();
        assert_tables(
            &original,
            &table(d, &["moved.toml", "--at", &mapped.join(",")]),
            1,
            &format!("{name} reparametrize"),
        );
        // Split at 0.5: a Bézier curve's pieces are Bézier curves on [0, 1]; a spline's keep
        // the parameters.
        ok(
            d,
            &["transform", model, "-o", "piece.toml", "--split", "0.5"],
        );
        let bezier = ok(d, &["check", model]).stdout.contains("kind: bezier\n");
        let (left_at, right_at) = if bezier {
            ("0,0.4,1", "0,0.4,1")
        } else {
            ("0,0.2,0.5", "0.5,0.7,1")
        };
        let left = table(d, &["piece-1.toml", "--at", left_at]);
        let right = table(d, &["piece-2.toml", "--at", right_at]);
        assert_tables(
            &table(d, &[model, "--at", "0,0.2,0.5"]),
            &left,
            1,
            &format!("{name} split left"),
        );
        assert_tables(
            &table(d, &[model, "--at", "0.5,0.7,1"]),
            &right,
            1,
            &format!("{name} split right"),
        );
        // The Bézier pieces cover the curve span by span.
        ok(d, &["transform", model, "-o", "bz.toml", "--to-bezier"]);
        // (one piece, a Bézier curve, is written to OUT itself)
        ok(d, &["check", if bezier { "bz.toml" } else { "bz-1.toml" }]);
    }
}

#[test]
fn spreads_follow_exact_operations() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let model = example("fuzzy-bspline.toml");
    let model = model.to_str().unwrap();
    let cuts = table(d, &[model, "--at", AT, "--alpha", "0.5"]);
    ok(d, &["transform", model, "-o", "fine.toml", "--refine", "3"]);
    assert_tables(
        &cuts,
        &table(d, &["fine.toml", "--at", AT, "--alpha", "0.5"]),
        1,
        "alpha-cuts",
    );
    let out = run(
        d,
        &[
            "transform",
            model,
            "-o",
            "x.toml",
            "--remove-knot",
            "0.5",
            "--tolerance",
            "1",
        ],
    );
    assert_eq!(out.code, 1);
    assert!(out.stderr.contains("--remove-knot is not exact, so the spreads (fuzzy positions) of this model cannot follow it"), "{}", out.stderr);
}

#[test]
fn reduction_undoes_elevation_and_reports_it() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for name in ["bspline.toml", "nurbs-circle.toml", "example1.toml"] {
        let model = example(name);
        let model = model.to_str().unwrap();
        ok(d, &["transform", model, "-o", "up.toml", "--elevate", "2"]);
        let out = ok(
            d,
            &[
                "transform",
                "up.toml",
                "-o",
                "down.toml",
                "--reduce",
                "2",
                "--tolerance",
                "1e-9",
            ],
        );
        assert!(
            out.stderr.contains("largest deviation found"),
            "{}",
            out.stderr
        );
        assert_tables(
            &table(d, &[model, "--at", AT]),
            &table(d, &["down.toml", "--at", AT]),
            1,
            name,
        );
        let degree = |file: &str| {
            ok(d, &["check", file])
                .stdout
                .lines()
                .find(|l| l.starts_with("degree:"))
                .unwrap()
                .to_owned()
        };
        assert_eq!(degree("down.toml"), degree(model), "{name}");
    }
    let surface = example("surface.toml");
    let surface = surface.to_str().unwrap();
    ok(
        d,
        &[
            "transform",
            surface,
            "-o",
            "up.json",
            "--elevate",
            "1",
            "--direction",
            "v",
        ],
    );
    ok(
        d,
        &[
            "transform",
            "up.json",
            "-o",
            "down.json",
            "--reduce",
            "1",
            "--tolerance",
            "1e-9",
            "--direction",
            "v",
        ],
    );
    let at = "0:0,0.2:0.7,0.5:0.5,0.9:0.1,1:1";
    assert_tables(
        &table(d, &[surface, "--at", at]),
        &table(d, &["down.json", "--at", at]),
        2,
        "surface",
    );
}

#[test]
fn removal_undoes_insertion_and_reports_it() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let model = example("bspline.toml");
    let model = model.to_str().unwrap();
    ok(
        d,
        &[
            "transform",
            model,
            "-o",
            "more.toml",
            "--insert-knot",
            "0.35,0.35",
        ],
    );
    let out = ok(
        d,
        &[
            "transform",
            "more.toml",
            "-o",
            "back.toml",
            "--remove-knot",
            "0.35",
            "--tolerance",
            "1e-9",
        ],
    );
    assert!(
        out.stderr
            .contains("more.toml: --remove-knot: wrote back.toml"),
        "{}",
        out.stderr
    );
    assert!(
        out.stderr.contains("removed knot 0.35 2 of 2 times"),
        "{}",
        out.stderr
    );
    let knots = |file: &str| {
        ok(d, &["check", file])
            .stdout
            .lines()
            .find(|l| l.starts_with("knots:"))
            .unwrap()
            .to_owned()
    };
    assert_eq!(
        knots("back.toml"),
        knots(model).replace("clamped-uniform", "given, clamped")
    );
    assert_tables(
        &table(d, &[model, "--at", AT]),
        &table(d, &["back.toml", "--at", AT]),
        1,
        "removal",
    );
    // The original knot 0.5 does not come off within 1e-9; with 1 it does, and the report
    // gives the deviation.
    let out = ok(
        d,
        &[
            "transform",
            model,
            "-o",
            "same.toml",
            "--remove-knot",
            "0.5",
            "--tolerance",
            "1e-9",
        ],
    );
    assert!(
        out.stderr.contains("knot 0.5 not removed: removing it once would move the curve by more than the tolerance"),
        "{}",
        out.stderr
    );
}

#[test]
fn surfaces_transform_in_a_direction() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let model = example("surface.toml");
    let model = model.to_str().unwrap();
    let at = "0:0,0.2:0.7,0.5:0.5,0.9:0.1,1:1";
    let original = table(d, &[model, "--at", at]);
    for direction in ["u", "v"] {
        for op in [
            vec!["--elevate", "1"],
            vec!["--insert-knot", "0.4,0.4"],
            vec!["--refine", "1"],
        ] {
            let mut args = vec!["transform", model, "-o", "s.json", "--direction", direction];
            args.extend(&op);
            ok(d, &args);
            ok(d, &["check", "s.json"]);
            assert_tables(
                &original,
                &table(d, &["s.json", "--at", at]),
                2,
                &format!("{direction} {op:?}"),
            );
        }
    }
    let out = run(d, &["transform", model, "-o", "s.toml", "--elevate", "1"]);
    assert_eq!(out.code, 1);
    assert!(
        out.stderr
            .ends_with("surface.toml: --elevate on a surface needs --direction u or v\n"),
        "{}",
        out.stderr
    );
    ok(d, &["transform", model, "-o", "patch.toml", "--to-bezier"]);
    ok(d, &["check", "patch.toml"]);
}

#[test]
fn misuse_gets_its_message() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let model = example("bspline.toml");
    let model = model.to_str().unwrap();
    for (args, code, message) in [
        (vec![], 2, "error: give one operation: --elevate, --reduce, --insert-knot, --refine, --remove-knot, --split, --subsegment, --reverse, --to-bezier, --reparametrize\n"),
        (vec!["--reverse", "--split", "0.5"], 2, "error: give one operation per call (given: split, reverse)\n"),
        (vec!["--remove-knot", "0.5"], 2, "error: --remove-knot needs --tolerance E: the largest deviation the removal may cause\n"),
        (vec!["--elevate", "1", "--tolerance", "1"], 2, "error: --tolerance goes with --remove-knot or --reduce\n"),
        (vec!["--reduce", "1"], 2, "error: --reduce needs --tolerance E: the largest deviation the reduction may cause\n"),
        (vec!["--reduce", "1", "--tolerance", "1e-3"], 1, "bspline.toml: no curve of degree 2 lies within 1e-3 of this one: the nearest found deviates by 9.032067383751896e-2\n"),
        (vec!["--subsegment", "0.2"], 2, "error: subsegment = 0.2: expected A:B, two numbers\n"),
        (vec!["--elevate", "1", "--direction", "u"], 1, "bspline.toml: --direction u is for surfaces; this model is a curve\n"),
        (vec!["--remove-knot", "0.25", "--tolerance", "1"], 1, "bspline.toml: 0.25 is not an interior knot (the interior knots are 0.2, 0.5, 0.7)\n"),
        (vec!["--split", "1"], 1, "bspline.toml: the piece [1, 1] of the spline would be a single point (a spline piece needs a non-empty domain)\n"),
        (vec!["--insert-knot", "2"], 1, "bspline.toml: parameter 2 is outside the domain [0, 1]\n"),
        (vec!["--reparametrize", "3:1"], 1, "bspline.toml: [3, 1] is not a parameter interval (the start must be finite and less than the end)\n"),
    ] {
        let mut argv = vec!["transform", model, "-o", "bad.toml"];
        argv.extend(&args);
        let out = run(d, &argv);
        assert_eq!(out.code, code, "{args:?}: {}", out.stderr);
        assert!(out.stderr.ends_with(message), "{args:?}: {}", out.stderr);
        assert!(!d.join("bad.toml").exists());
    }
    let out = run(d, &["transform", model, "-o", "bad.csv", "--reverse"]);
    assert_eq!(out.code, 2);
    assert!(out.stderr.contains("bad.csv: unsupported model extension for a transformed model (accepted: .toml, .json; a CSV file cannot hold the knots)"));
}

#[test]
fn intuitionistic_models_stay_exact() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::write(
        d.join("ifs.csv"),
        "x,y,truth,falsity\n0,0,0.3,0.6\n1,2,0.7,0.2\n3,2,0.1,0.8\n4,0,0.45,0.55\n5,1,0.2,0.3\n",
    )
    .unwrap();
    let base = [
        "--membership",
        "intuitionistic",
        "--kind",
        "bspline",
        "--degree",
        "3",
    ];
    for op in [
        vec!["--elevate", "3"],
        vec!["--refine", "5"],
        vec!["--insert-knot", "0.3,0.3,0.71"],
    ] {
        let mut args = vec!["transform", "ifs.csv", "-o", "out.toml"];
        args.extend(&op);
        args.extend(&base);
        ok(d, &args);
        let check = ok(d, &["check", "out.toml"]);
        assert!(
            check.stdout.contains("membership: intuitionistic"),
            "{}",
            check.stdout
        );
    }
}
