//! End-to-end tests of `neutrospline query MODEL POINTS.csv [-o OUT]`: exact headers for
//! curves (2-D, 3-D) and surfaces, closed-form answers (the unit circle of
//! `examples/nurbs-circle.toml`, the quarter cylinder of `examples/nurbs-surface.json`), JSON
//! output, the atomic `-o`, and located errors with their exit codes.

use crate::util::{dir_with_examples, ok, rows, run};

/// A temporary directory with the given files and copies of the examples used here.
fn dir_with(files: &[(&str, &str)]) -> tempfile::TempDir {
    dir_with_examples(
        &[
            "example1.toml",
            "nurbs-circle.toml",
            "helix3d.toml",
            "nurbs-surface.json",
        ],
        files,
    )
}

#[test]
fn query_curve_header_and_closed_forms() {
    let dir = dir_with(&[(
        "q.csv",
        "# the centre, a point on the seam's line, one inside, one far\nx,y\n0,0\n3,0\n0.3,0.4\n-300,400\n",
    )]);
    let out = ok(dir.path(), &["query", "nurbs-circle.toml", "q.csv"]);
    assert_eq!(
        out.lines().next().unwrap(),
        "index,t,distance,x,y,truth,indeterminacy,falsity,score"
    );
    let r = rows(&out);
    assert_eq!(r.len(), 4);
    // The centre: every point is nearest, the start (t = 0, the point E) is reported, with
    // its degrees (0.9, 0.1, 0) and score (2 + 0.9 - 0.1 - 0) / 3.
    assert_eq!(&r[0][..8], &[0.0, 0.0, 1.0, 1.0, 0.0, 0.9, 0.1, 0.0]);
    assert!((r[0][8] - 2.8 / 3.0).abs() < 1e-15);
    // On the seam: t = 0 and t = 1 tie, 0 is reported.
    assert_eq!(&r[1][..5], &[1.0, 0.0, 2.0, 1.0, 0.0]);
    // Radially: distance | |P| - 1 |, the point P / |P|.
    for (row, (x, y)) in [(2, (0.3, 0.4)), (3, (-300.0, 400.0))] {
        let radius: f64 = f64::hypot(x, y);
        assert_eq!(r[row][0], row as f64);
        assert!((r[row][2] - (radius - 1.0).abs()).abs() < 1e-12 * radius);
        assert!((r[row][3] - x / radius).abs() < 1e-12 && (r[row][4] - y / radius).abs() < 1e-12);
    }
    // JSON: the same columns as keys.
    let json = ok(
        dir.path(),
        &["query", "nurbs-circle.toml", "q.csv", "--format", "json"],
    );
    let value: serde_json::Value = serde_json::from_str(&json).unwrap();
    assert_eq!(value[1]["t"], 0.0);
    assert_eq!(value[1]["distance"], 2.0);
    assert_eq!(value.as_array().unwrap().len(), 4);
}

#[test]
fn query_spatial_curve_and_surface_headers() {
    let dir = dir_with(&[("p.csv", "name,x,y,z\nA,0,0,0.75\nB,2,0.5,0.25\n")]);
    let helix = ok(dir.path(), &["query", "helix3d.toml", "p.csv"]);
    assert_eq!(
        helix.lines().next().unwrap(),
        "index,t,distance,x,y,z,truth,indeterminacy,falsity,score"
    );
    let surface = ok(dir.path(), &["query", "nurbs-surface.json", "p.csv"]);
    assert_eq!(
        surface.lines().next().unwrap(),
        "index,u,v,distance,x,y,z,truth,indeterminacy,falsity,score"
    );
    let r = rows(&surface);
    // On the axis of the quarter cylinder every point of the arc at z = 0.75 is at distance
    // 1: the smallest u is reported, on the arc's start (1, 0, 0.75).
    assert_eq!(r[0][1], 0.0);
    assert!((r[0][2] - 0.375).abs() < 1e-12);
    assert!((r[0][3] - 1.0).abs() < 1e-15);
    // Outside: | sqrt(x^2 + y^2) - 1 |.
    assert!((r[1][3] - (f64::hypot(2.0, 0.5) - 1.0)).abs() < 1e-12);
}

#[test]
fn query_output_file_is_replaced_atomically() {
    let dir = dir_with(&[
        ("q.csv", "x,y\n1,2\n"),
        ("bad.csv", "x,y\n1,2\n3\n"),
        ("out.csv", "old\n"),
    ]);
    let (code, stdout, stderr) = run(
        dir.path(),
        &["query", "example1.toml", "q.csv", "-o", "out.csv"],
    );
    assert_eq!((code, stdout.as_str(), stderr.as_str()), (0, "", ""));
    let written = std::fs::read_to_string(dir.path().join("out.csv")).unwrap();
    assert_eq!(written, "index,t,distance,x,y,truth,indeterminacy,falsity,score\n0,0,1,1,3,0.3,0.6,0.1,0.5333333333333332\n");
    let (code, _, stderr) = run(
        dir.path(),
        &["query", "example1.toml", "bad.csv", "-o", "out.csv"],
    );
    assert_eq!(code, 1);
    assert_eq!(
        stderr,
        "error: bad.csv:3: the row has 1 cells but the header has 2 (every row needs one cell per column)\n"
    );
    assert_eq!(
        std::fs::read_to_string(dir.path().join("out.csv")).unwrap(),
        written
    );
}

#[test]
fn query_errors_name_the_file_line_field_and_rule() {
    let huge = "x,y,truth,indeterminacy,falsity\n-1e308,0,1,0,0\n-1e308,1,1,0,0\n";
    let dir = dir_with(&[
        ("nan.csv", "x,y\n0,0\n1,NaN\n"),
        ("three.csv", "x,y,z\n0,0,0\n"),
        ("two.csv", "X,Y\n0,0\n"),
        ("extra.csv", "x,y,truth\n0,0,1\n"),
        ("empty.csv", "x,y\n"),
        ("huge.csv", huge),
        ("far.csv", "x,y\n1e308,0\n"),
    ]);
    let cases: &[(&[&str], i32, &str)] = &[
        (&["query", "example1.toml", "nan.csv"], 1,
         "error: nan.csv:3: column `y`: value `NaN` is not a finite number (NaN and infinities are not allowed)"),
        (&["query", "example1.toml", "three.csv"], 1,
         "error: three.csv: 3-D points, but example1.toml holds a 2-D bezier curve (query points need the columns x, y)"),
        (&["query", "helix3d.toml", "two.csv"], 1,
         "error: two.csv: 2-D points, but helix3d.toml holds a 3-D bezier curve (query points need the columns x, y, z)"),
        (&["query", "nurbs-surface.json", "two.csv"], 1,
         "error: two.csv: 2-D points, but nurbs-surface.json holds a nurbs-surface (3-D) (query points need the columns x, y, z)"),
        (&["query", "example1.toml", "extra.csv"], 1,
         "error: extra.csv:1: unknown column `truth` (known columns of query points: x, y, z, name)"),
        (&["query", "example1.toml", "empty.csv"], 1,
         "error: empty.csv: no query points (the header row is not followed by any data row)"),
        (&["query", "example1.toml", "missing.csv"], 1,
         "error: missing.csv: cannot read: No such file or directory (os error 2)"),
        (&["query", "huge.csv", "far.csv", "--kind", "bezier"], 1,
         "error: far.csv:2: cannot find the nearest point: the distance from the query point overflows a 64-bit float (coordinates too large)"),
    ];
    for (args, code, message) in cases {
        let (got_code, stdout, stderr) = run(dir.path(), args);
        assert_eq!(
            (got_code, stdout.as_str(), stderr.as_str()),
            (*code, "", format!("{message}\n").as_str()),
            "{args:?}"
        );
    }
    let (code, _, stderr) = run(dir.path(), &["query", "example1.toml"]);
    assert_eq!(code, 2, "{stderr}");
}
