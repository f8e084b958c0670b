//! End-to-end tests of `neutrospline intersect A B [-o OUT]`: the exact header, closed forms
//! (a cubic's loop at s = (3 - sqrt 3) / 6, tangent circles at (0, 1), a line through the unit
//! circle), curves meeting at their ends, self-intersections when B is A, overlaps refused
//! with their parameters, and the errors for other shapes.

use crate::util::{dir_with_examples, ok, run};

/// A temporary directory with the given files and copies of the examples used here.
fn dir_with(files: &[(&str, &str)]) -> tempfile::TempDir {
    dir_with_examples(
        &["nurbs-circle.toml", "helix3d.toml", "surface.toml"],
        files,
    )
}

const HEADER: &str =
    "index,t_a,t_b,x,y,truth_a,indeterminacy_a,falsity_a,truth_b,indeterminacy_b,falsity_b,contact";

/// The numeric columns of each row (all but the last, `contact`).
fn rows(table: &str) -> Vec<Vec<f64>> {
    table
        .lines()
        .skip(1)
        .map(|l| {
            let cells: Vec<&str> = l.split(',').collect();
            cells[..cells.len() - 1]
                .iter()
                .map(|c| c.parse().unwrap())
                .collect()
        })
        .collect()
}

/// The `contact` column of each row.
fn contacts(table: &str) -> Vec<String> {
    table
        .lines()
        .skip(1)
        .map(|l| l.rsplit(',').next().unwrap().to_owned())
        .collect()
}

const LOOP: &str = "x,y,truth,indeterminacy,falsity\n0,0,0.9,0.1,0\n4,2,0.5,0.2,0.1\n-1,2,0.3,0.3,0.2\n3,0,0.1,0.4,0.3\n";
const LINE: &str = "x,y,truth,indeterminacy,falsity\n-2,0.3,1,0,0\n2,0.7,0,0,1\n";
/// The unit circle of nurbs-circle.toml moved up by 2: tangent to it at (0, 1).
const UPPER: &str = "x,y,weight,truth,indeterminacy,falsity\n1,2,1,0.5,0.5,0.5\n1,3,0.7071067811865476,0.5,0.5,0.5\n0,3,1,0.5,0.5,0.5\n-1,3,0.7071067811865476,0.5,0.5,0.5\n-1,2,1,0.5,0.5,0.5\n-1,1,0.7071067811865476,0.5,0.5,0.5\n0,1,1,0.5,0.5,0.5\n1,1,0.7071067811865476,0.5,0.5,0.5\n1,2,1,0.5,0.5,0.5\n";

#[test]
fn intersect_closed_forms() {
    let dir = dir_with(&[("loop.csv", LOOP), ("line.csv", LINE)]);
    // B is A: the self-intersection of the loop, once, t_a < t_b.
    let out = ok(dir.path(), &["intersect", "loop.csv", "loop.csv"]);
    assert_eq!(out.lines().next().unwrap(), HEADER);
    let r = rows(&out);
    assert_eq!(r.len(), 1);
    assert_eq!(contacts(&out), ["crossing"]);
    let s = (3.0 - 3f64.sqrt()) / 6.0;
    assert!((r[0][1] - s).abs() < 1e-14 && (r[0][2] - (1.0 - s)).abs() < 1e-14);
    assert!((r[0][3] - 1.5).abs() < 1e-14 && (r[0][4] - 1.0).abs() < 1e-14);
    // The line y = 0.3 + 0.1 (x + 2) through the unit circle: two points on the circle, in
    // the order of the line's parameter (x = 4 t - 2).
    let out = ok(dir.path(), &["intersect", "line.csv", "nurbs-circle.toml"]);
    let r = rows(&out);
    assert_eq!(r.len(), 2);
    assert_eq!(contacts(&out), ["crossing", "crossing"]);
    for row in &r {
        let (x, y) = (row[3], row[4]);
        assert!((x.hypot(y) - 1.0).abs() < 1e-14, "{row:?}");
        assert!((y - (0.3 + 0.1 * (x + 2.0))).abs() < 1e-14);
        assert!((x - (4.0 * row[1] - 2.0)).abs() < 1e-14);
        // The degrees of the line at t_a: truth 1 - t, falsity t.
        assert!((row[5] - (1.0 - row[1])).abs() < 1e-15 && (row[7] - row[1]).abs() < 1e-15);
    }
    assert!(r[0][1] < r[1][1]);
    // Swapping A and B swaps the parameters (and orders by the circle's).
    let swapped = rows(&ok(
        dir.path(),
        &["intersect", "nurbs-circle.toml", "line.csv"],
    ));
    assert_eq!(swapped.len(), 2);
    assert!((swapped[0][1] - r[1][2]).abs() < 1e-12 && (swapped[0][2] - r[1][1]).abs() < 1e-12);
}

#[test]
fn intersect_tangent_and_end_points_once() {
    let first = "x,y,truth,indeterminacy,falsity\n0,0,1,0,0\n1,2,1,0,0\n2,-1,1,0,0\n3,1,1,0,0\n";
    let second =
        "x,y,truth,indeterminacy,falsity\n3,1,0,0,1\n2,3,0,0,1\n1,-2,0,0,1\n0.5,1.5,0,0,1\n";
    let dir = dir_with(&[
        ("upper.csv", UPPER),
        ("first.csv", first),
        ("second.csv", second),
    ]);
    let out = ok(
        dir.path(),
        &[
            "intersect",
            "nurbs-circle.toml",
            "upper.csv",
            "--kind",
            "nurbs",
            "--degree",
            "2",
            "--knots",
            "0,0,0,0.25,0.25,0.5,0.5,0.75,0.75,1,1,1",
        ],
    );
    // Tangent at (0, 1): the circle's N (t = 1/4) and the upper circle's S (t = 3/4), once.
    assert_eq!(
        out,
        format!("{HEADER}\n0,0.25,0.75,0,1,0.6,0.3,0.2,0.5,0.5,0.5,tangent\n")
    );
    // Cubics meeting at their ends (A's end is B's start), crossing twice more; the reference
    // values are from scripts/reference/make_intersection_reference.py (mpmath).
    let out = ok(dir.path(), &["intersect", "first.csv", "second.csv"]);
    assert_eq!(contacts(&out), ["crossing", "crossing", "end"]);
    let r = rows(&out);
    let want = [
        (0.22036411574419631, 0.9019118154414405),
        (0.47910729834322924, 0.5483771332872838),
        (1.0, 0.0),
    ];
    assert_eq!(r.len(), 3);
    for (row, (ta, tb)) in r.iter().zip(want) {
        assert!(
            (row[1] - ta).abs() < 1e-10 && (row[2] - tb).abs() < 1e-10,
            "{row:?}"
        );
    }
    assert_eq!((r[2][1], r[2][2], r[2][3], r[2][4]), (1.0, 0.0, 3.0, 1.0));
}

#[test]
fn intersect_writes_atomically_and_refuses_overlaps_and_other_shapes() {
    let a = "x,y,truth,indeterminacy,falsity\n0,0,1,0,0\n2,2,1,0,0\n";
    let b = "x,y,truth,indeterminacy,falsity\n1,1,1,0,0\n3,3,1,0,0\n";
    let dir = dir_with(&[
        ("a.csv", a),
        ("b.csv", b),
        ("loop.csv", LOOP),
        ("out.csv", "old\n"),
    ]);
    let (code, stdout, stderr) = run(
        dir.path(),
        &["intersect", "a.csv", "b.csv", "-o", "out.csv"],
    );
    assert_eq!(
        (code, stdout.as_str(), stderr.as_str()),
        (
            1,
            "",
            "error: a.csv and b.csv: the curves overlap: t_a in [0.5, 1] lies on the other curve (t_b in [0, 0.5]), so they meet in infinitely many points\n"
        )
    );
    assert_eq!(
        std::fs::read_to_string(dir.path().join("out.csv")).unwrap(),
        "old\n"
    );
    let (code, _, stderr) = run(
        dir.path(),
        &["intersect", "loop.csv", "loop.csv", "-o", "out.csv"],
    );
    assert_eq!((code, stderr.as_str()), (0, ""));
    let written = std::fs::read_to_string(dir.path().join("out.csv")).unwrap();
    assert!(
        written.starts_with(&format!("{HEADER}\n0,0.211324865405187")),
        "{written}"
    );
    for (args, message) in [
        (["intersect", "helix3d.toml", "loop.csv"], "error: helix3d.toml: holds a 3-D bezier curve (intersect takes plane curves: positions x, y only)"),
        (["intersect", "loop.csv", "surface.toml"], "error: surface.toml: holds a bezier-surface (intersect takes plane curves: positions x, y only)"),
    ] {
        let (code, stdout, stderr) = run(dir.path(), &args);
        assert_eq!((code, stdout.as_str(), stderr.as_str()), (1, "", format!("{message}\n").as_str()));
    }
    let (code, _, _) = run(dir.path(), &["intersect", "loop.csv"]);
    assert_eq!(code, 2);
}
