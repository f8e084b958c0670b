//! Fuzzy positions on the command line: `eval --alpha A` and `--centroid` columns (exact
//! headers, values against the closed form), `check`'s spread ranges, and the messages for
//! bad spreads and bad alphas.

use crate::util::{examples_dir, run};

/// A temporary directory holding the file `name`.
fn dir_with(name: &str, text: &str) -> tempfile::TempDir {
    crate::util::dir_with(&[(name, text)])
}

/// A straight line from (0, 0) to (3, 0) as a cubic Bézier curve, y spreads 0, 1, 2, 3 to the
/// left and 0, 2, 4, 6 to the right: the cut curves are y = -(1 - alpha) 3t and
/// y = (1 - alpha) 6t, the centroid y = t.
const LINE: &str = "x,y,T,I,F,spread_y_left,spread_y_right\n\
    0,0,1,0,0,0,0\n1,0,1,0,0,1,2\n2,0,1,0,0,2,4\n3,0,1,0,0,3,6\n";

#[test]
fn eval_alpha_and_centroid_columns_of_a_line() {
    let dir = dir_with("line.csv", LINE);
    let (code, out, err) = run(
        dir.path(),
        &[
            "eval",
            "line.csv",
            "--samples",
            "5",
            "--alpha",
            "0.5",
            "--centroid",
        ],
    );
    assert_eq!(code, 0, "{err}");
    let mut lines = out.lines();
    assert_eq!(
        lines.next(),
        Some("t,x,y,truth,indeterminacy,falsity,x_lo,x_hi,y_lo,y_hi,x_centroid,y_centroid")
    );
    for line in lines {
        let v: Vec<f64> = line.split(',').map(|c| c.parse().unwrap()).collect();
        let t = v[0];
        let close = |a: f64, b: f64| (a - b).abs() < 1e-12;
        assert!(close(v[6], 3.0 * t) && close(v[7], 3.0 * t), "{line}");
        assert!(close(v[8], -1.5 * t), "{line}");
        assert!(close(v[9], 3.0 * t), "{line}");
        assert!(close(v[10], 3.0 * t) && close(v[11], t), "{line}");
    }
    // At alpha = 1 the cut is the crisp curve, to the bit.
    let (code, out, _) = run(
        dir.path(),
        &["eval", "line.csv", "--samples", "7", "--alpha", "1"],
    );
    assert_eq!(code, 0);
    for line in out.lines().skip(1) {
        let c: Vec<&str> = line.split(',').collect();
        assert_eq!((c[6], c[7], c[8], c[9]), (c[1], c[1], c[2], c[2]), "{line}");
    }
}

#[test]
fn eval_alpha_columns_of_every_kind_and_3d() {
    let dir = examples_dir();
    for (file, header) in [
        (
            "fuzzy-bspline.toml",
            "t,x,y,truth,indeterminacy,falsity,x_lo,x_hi,y_lo,y_hi",
        ),
        (
            "nurbs-circle.toml",
            "t,x,y,truth,indeterminacy,falsity,x_lo,x_hi,y_lo,y_hi",
        ),
        (
            "helix3d.toml",
            "t,x,y,z,truth,indeterminacy,falsity,x_lo,x_hi,y_lo,y_hi,z_lo,z_hi",
        ),
    ] {
        let (code, out, err) = run(&dir, &["eval", file, "--samples", "3", "--alpha", "0"]);
        assert_eq!(code, 0, "{file}: {err}");
        assert_eq!(out.lines().next(), Some(header), "{file}");
    }
    let (code, out, _) = run(
        &dir,
        &[
            "eval",
            "helix3d.toml",
            "--samples",
            "2",
            "--centroid",
            "--scores",
        ],
    );
    assert_eq!(code, 0);
    assert_eq!(
        out.lines().next(),
        Some(
            "t,x,y,z,truth,indeterminacy,falsity,score,accuracy,certainty,x_centroid,\
             y_centroid,z_centroid"
        )
    );
    // The fuzzy example: at t = 1 the curve ends at B6 = (9, 3), spreads y 0.1 left and 0.6
    // right: at alpha = 0.5 the cut is [2.95, 3.3], the centroid 3 + 0.5 / 3.
    let (_, out, _) = run(
        &dir,
        &[
            "eval",
            "fuzzy-bspline.toml",
            "--at",
            "1",
            "--alpha",
            "0.5",
            "--centroid",
        ],
    );
    assert_eq!(
        out.lines().nth(1),
        Some("1,9,3,0.9,0.1,0.1,9,9,2.95,3.3,9,3.1666666666666665")
    );
}

#[test]
fn eval_fuzzy_usage_errors() {
    let dir = examples_dir();
    for (args, message) in [
        (
            &["eval", "example1.toml", "--alpha", "1.5"][..],
            "error: invalid value '1.5' for '--alpha <A>': `1.5` is not a number in [0, 1] (the \
             membership level of the alpha-cut: 0 is the widest band, 1 the crisp curve)",
        ),
        (
            &["eval", "example1.toml", "--alpha", "-0.1"],
            "error: invalid value '-0.1' for '--alpha <A>': `-0.1` is not a number in [0, 1] \
             (the membership level of the alpha-cut: 0 is the widest band, 1 the crisp curve)",
        ),
        (
            &["eval", "surface.toml", "--centroid"],
            "error: --centroid applies only to curves (surface.toml holds a bezier-surface; \
             spreads are given per control point of a curve)",
        ),
    ] {
        let (code, out, err) = run(&dir, args);
        assert_eq!(code, 2, "{args:?}");
        assert!(out.is_empty());
        assert_eq!(err.lines().next(), Some(message), "{args:?}");
    }
}

#[test]
fn bad_spreads_are_located() {
    let dir = dir_with(
        "bad.csv",
        "x,y,T,I,F,spread_y,spread_y_left\n0,0,1,0,0,1,1\n",
    );
    let (code, _, err) = run(dir.path(), &["eval", "bad.csv"]);
    assert_eq!(code, 1);
    assert_eq!(
        err,
        "error: bad.csv:1: column `spread_y` and `spread_y_left` are both given (give the \
         symmetric spread `spread_y` or the asymmetric `spread_y_left` and `spread_y_right` for \
         one axis, not both)\n"
    );
    let dir = dir_with(
        "bad.toml",
        "kind = \"bezier\"\n[[control_points]]\nx = 0\ny = 0\nT = 1\nI = 0\nF = 0\nspread_x = -1\n",
    );
    let (code, _, err) = run(dir.path(), &["check", "bad.toml"]);
    assert_eq!(code, 1);
    assert_eq!(
        err,
        "error: bad.toml:8: control_points[0].spread_x: spread -1 is negative (a spread is a \
         distance >= 0)\n"
    );
}

#[test]
fn check_reports_spread_ranges_only_when_some_are_not_zero() {
    let dir = examples_dir();
    let (code, out, _) = run(&dir, &["check", "fuzzy-bspline.toml"]);
    assert_eq!(code, 0);
    assert!(
        out.contains(
            "falsity: 0..0.3\nspread_x: left 0..0.3, right 0..0.3\nspread_y: left 0..0.8, \
             right 0..0.9\nlength: "
        ),
        "{out}"
    );
    let (_, out, _) = run(&dir, &["check", "bspline.toml"]);
    assert!(!out.contains("spread"), "{out}");
    let zero = dir_with("z.csv", "x,y,T,I,F,spread_x\n0,0,1,0,0,0\n1,1,1,0,0,0\n");
    let (code, out, _) = run(zero.path(), &["check", "z.csv"]);
    assert_eq!(code, 0);
    assert!(!out.contains("spread"), "{out}");
}

#[test]
fn plot_band_view() {
    let out = tempfile::tempdir().unwrap();
    let svg = out.path().join("band.svg");
    let svg_arg = svg.to_str().unwrap();
    let dir = examples_dir();
    let (code, _, err) = run(
        &dir,
        &[
            "plot",
            "fuzzy-bspline.toml",
            "--view",
            "band",
            "--alpha",
            "0,0.25,1",
            "-o",
            svg_arg,
        ],
    );
    assert_eq!(code, 0, "{err}");
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(text.contains("band alpha-0\"") && text.contains("band alpha-0.25\""));
    assert!(text.contains("curve centroid"));
    let (code, _, err) = run(
        &dir,
        &[
            "plot",
            "fuzzy-bspline.toml",
            "--view",
            "band",
            "--alpha",
            "0,2",
            "-o",
            svg_arg,
        ],
    );
    assert_eq!(code, 2);
    assert_eq!(
        err.lines().next(),
        Some(
            "error: alpha level 2 is outside [0, 1] (the band view draws alpha-cuts at levels in \
             [0, 1])"
        )
    );
    let (code, _, err) = run(
        &dir,
        &["plot", "surface.toml", "--view", "band", "-o", svg_arg],
    );
    assert_eq!(code, 1);
    assert_eq!(
        err,
        "error: the band view draws curves (spreads are given per control point of a curve); \
         surfaces have no band\n"
    );
}
