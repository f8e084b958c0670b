//! End-to-end tests of the B-spline, NURBS and surface kinds: the same model read from TOML,
//! JSON and CSV, known values per kind, domain sampling, and every new error with its exact
//! message and exit code.

use std::io::Read;
use std::path::Path;
use std::process::{Command, Stdio};

use crate::util::{dir_with, examples_dir, ok, Output, BIN};

/// Runs the binary in `dir` with no standard input.
fn run_in(dir: &Path, args: &[&str]) -> Output {
    crate::util::run_in(dir, args, None)
}

/// Runs `args` in a directory holding one file; expects `code`, exactly `message` (one line)
/// on stderr and nothing on stdout.
fn assert_error(name: &str, contents: &str, args: &[&str], code: i32, message: &str) {
    let dir = dir_with(&[(name, contents)]);
    let out = run_in(dir.path(), args);
    assert_eq!(
        (out.code, out.stderr.as_str(), out.stdout.as_str()),
        (code, format!("{message}\n").as_str(), ""),
        "args {args:?}, file {name}:\n{contents}"
    );
}

/// Header and rows of a CSV table (empty cells as `None`).
fn parse_table(text: &str) -> (Vec<String>, Vec<Vec<Option<f64>>>) {
    let mut lines = text.lines();
    let header = lines
        .next()
        .expect("header")
        .split(',')
        .map(str::to_owned)
        .collect();
    let rows = lines
        .map(|l| {
            l.split(',')
                .map(|c| (!c.is_empty()).then(|| c.parse::<f64>().expect(c)))
                .collect()
        })
        .collect();
    (header, rows)
}

fn values(text: &str) -> Vec<Vec<f64>> {
    parse_table(text)
        .1
        .into_iter()
        .map(|r| r.into_iter().map(|v| v.expect("no empty cell")).collect())
        .collect()
}

// ---------------------------------------------------------------------------------------------
// The same model in three formats.

/// A structure setting of a model.
#[derive(Clone, Copy)]
enum V {
    Int(usize),
    Knots(&'static [f64]),
    Rule(&'static str),
}

impl V {
    fn toml(self) -> String {
        match self {
            V::Int(n) => n.to_string(),
            V::Knots(k) => format!(
                "[{}]",
                k.iter().map(f64::to_string).collect::<Vec<_>>().join(", ")
            ),
            V::Rule(r) => format!("\"{r}\""),
        }
    }

    fn option(self) -> String {
        match self {
            V::Int(n) => n.to_string(),
            V::Knots(k) => k.iter().map(f64::to_string).collect::<Vec<_>>().join(","),
            V::Rule(r) => r.to_owned(),
        }
    }
}

type Point = Vec<(&'static str, f64)>;

struct Case {
    kind: &'static str,
    settings: Vec<(&'static str, V)>,
    points: Vec<Point>,
}

impl Case {
    fn toml(&self) -> String {
        let mut s = format!("kind = \"{}\"\n", self.kind);
        for (key, v) in &self.settings {
            s += &format!("{key} = {}\n", v.toml());
        }
        for p in &self.points {
            s += "\n[[control_points]]\n";
            for (k, v) in p {
                s += &format!("{k} = {v}\n");
            }
        }
        s
    }

    fn json(&self) -> String {
        let mut fields = vec![format!("\"kind\": \"{}\"", self.kind)];
        for (key, v) in &self.settings {
            fields.push(format!("\"{key}\": {}", v.toml()));
        }
        let points: Vec<String> = self
            .points
            .iter()
            .map(|p| {
                let kv: Vec<String> = p.iter().map(|(k, v)| format!("\"{k}\": {v}")).collect();
                format!("{{{}}}", kv.join(", "))
            })
            .collect();
        fields.push(format!(
            "\"control_points\": [\n  {}\n]",
            points.join(",\n  ")
        ));
        format!("{{\n{}\n}}\n", fields.join(",\n"))
    }

    fn csv(&self) -> String {
        let header: Vec<&str> = self.points[0].iter().map(|(k, _)| *k).collect();
        let mut s = format!("# {} as CSV\n{}\n", self.kind, header.join(","));
        for p in &self.points {
            let cells: Vec<String> = p.iter().map(|(_, v)| v.to_string()).collect();
            s += &cells.join(",");
            s += "\n";
        }
        s
    }

    fn options(&self) -> Vec<String> {
        let mut args = vec!["--kind".to_owned(), self.kind.to_owned()];
        for (key, v) in &self.settings {
            args.push(format!("--{}", key.replace('_', "-")));
            args.push(v.option());
        }
        args
    }
}

/// Control point with position, degrees and (if `w` is Some) a weight.
fn pt(xyz: &[f64], t: f64, i: f64, f: f64, w: Option<f64>) -> Point {
    let mut p: Point = ["x", "y", "z"]
        .into_iter()
        .zip(xyz.iter().copied())
        .collect();
    p.extend([("truth", t), ("indeterminacy", i), ("falsity", f)]);
    if let Some(w) = w {
        p.push(("weight", w));
    }
    p
}

fn curve_points(dim: usize, count: usize, weights: bool) -> Vec<Point> {
    (0..count)
        .map(|k| {
            let s = k as f64;
            let xyz = [s, (s * 1.3).sin() * 2.0, s * 0.25];
            let w = weights.then_some(0.5 + 0.25 * (k % 3) as f64);
            pt(&xyz[..dim], 0.1 + 0.1 * s, 0.5 - 0.05 * s, 0.05 * s, w)
        })
        .collect()
}

fn grid_points(rows: usize, cols: usize, weights: bool) -> Vec<Point> {
    let mut points = Vec::new();
    for i in 0..rows {
        for j in 0..cols {
            let (u, v) = (i as f64, j as f64);
            let w = weights.then_some(1.0 + 0.5 * ((i + j) % 2) as f64);
            points.push(pt(
                &[u, v, (u * 0.7 - v * 0.4).cos()],
                0.1 * (1.0 + u),
                0.1 * (1.0 + v),
                0.05 * (u + v),
                w,
            ));
        }
    }
    points
}

fn cases() -> Vec<Case> {
    vec![
        Case {
            kind: "bezier",
            settings: vec![("degree", V::Int(4))],
            points: curve_points(2, 5, false),
        },
        Case {
            kind: "bspline",
            settings: vec![
                ("degree", V::Int(3)),
                (
                    "knots",
                    V::Knots(&[0.0, 0.0, 0.0, 0.0, 0.3, 0.5, 1.0, 1.0, 1.0, 1.0]),
                ),
            ],
            points: curve_points(2, 6, false),
        },
        Case {
            kind: "bspline",
            settings: vec![("degree", V::Int(2)), ("knots", V::Rule("centripetal"))],
            points: curve_points(3, 6, false),
        },
        Case {
            kind: "nurbs",
            settings: vec![("degree", V::Int(2)), ("knots", V::Rule("chord-length"))],
            points: curve_points(2, 5, true),
        },
        Case {
            kind: "nurbs",
            settings: vec![
                ("degree", V::Int(2)),
                // Unclamped: the domain is [knot 2, knot 5] = [2, 5].
                ("knots", V::Knots(&[0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0])),
            ],
            points: curve_points(3, 5, true),
        },
        Case {
            kind: "bezier-surface",
            settings: vec![("rows", V::Int(3)), ("cols", V::Int(4))],
            points: grid_points(3, 4, false),
        },
        Case {
            kind: "bspline-surface",
            settings: vec![
                ("rows", V::Int(4)),
                ("cols", V::Int(3)),
                ("degree_u", V::Int(2)),
                ("degree_v", V::Int(1)),
                ("knots_u", V::Knots(&[0.0, 0.0, 0.0, 0.4, 1.0, 1.0, 1.0])),
            ],
            points: grid_points(4, 3, false),
        },
        Case {
            kind: "nurbs-surface",
            settings: vec![
                ("rows", V::Int(3)),
                ("cols", V::Int(3)),
                ("degree_u", V::Int(2)),
                ("degree_v", V::Int(2)),
                ("knots_u", V::Rule("clamped-uniform")),
                ("knots_v", V::Knots(&[0.0, 0.0, 0.0, 2.0, 2.0, 2.0])),
            ],
            points: grid_points(3, 3, true),
        },
    ]
}

#[test]
fn every_kind_reads_alike_from_toml_json_and_csv() {
    for case in cases() {
        let dir = dir_with(&[
            ("m.toml", &case.toml()),
            ("m.json", &case.json()),
            ("m.csv", &case.csv()),
        ]);
        let surface = case.kind.ends_with("surface");
        let mut eval = vec!["--samples", "5", "--derivative", "--format", "json"];
        if surface {
            eval.push("--normal");
        }
        let options = case.options();
        let options: Vec<&str> = options.iter().map(String::as_str).collect();
        let mut outputs = Vec::new();
        for (file, extra) in [("m.toml", &[][..]), ("m.json", &[]), ("m.csv", &options)] {
            let args: Vec<&str> = ["eval", file]
                .iter()
                .chain(&eval)
                .chain(extra)
                .copied()
                .collect();
            let table = ok(dir.path(), &args);
            let check: Vec<&str> = ["check", file].iter().chain(extra).copied().collect();
            let summary = ok(dir.path(), &check);
            let summary = summary.split_once('\n').expect("two lines").1.to_owned();
            assert!(
                summary.starts_with(&format!("kind: {}\n", case.kind)),
                "{summary}"
            );
            outputs.push((table, summary));
        }
        assert_eq!(outputs[0], outputs[1], "{}: TOML vs JSON", case.kind);
        assert_eq!(outputs[0], outputs[2], "{}: TOML vs CSV", case.kind);
        let rows: serde_json::Value = serde_json::from_str(&outputs[0].0).expect("JSON table");
        let expected_rows = if surface { 25 } else { 5 };
        assert_eq!(rows.as_array().expect("array").len(), expected_rows);

        // The model options, given with a model file that declares the same, are accepted.
        let args: Vec<&str> = ["check", "m.toml"]
            .iter()
            .chain(&options)
            .copied()
            .collect();
        ok(dir.path(), &args);
    }
}

// ---------------------------------------------------------------------------------------------
// Known values.

#[test]
fn nurbs_circle_points_lie_on_the_unit_circle() {
    let out = ok(
        &examples_dir(),
        &["eval", "nurbs-circle.toml", "--samples", "1001"],
    );
    let rows = values(&out);
    assert_eq!(rows.len(), 1001);
    for row in &rows {
        let r = row[1].hypot(row[2]);
        assert!((r - 1.0).abs() <= 1e-12, "t = {}: radius {r}", row[0]);
        for d in &row[3..6] {
            assert!((0.0..=1.0).contains(d), "{row:?}");
        }
    }
    // Starts and ends at E = (1, 0) with its degrees; at t = 0.5 the curve is at W.
    assert_eq!(out.lines().nth(1), Some("0,1,0,0.9,0.1,0"));
    assert_eq!(out.lines().last(), Some("1,1,0,0.9,0.1,0"));
    let w = ok(
        &examples_dir(),
        &["eval", "nurbs-circle.toml", "--at", "0.5"],
    );
    assert_eq!(w.lines().nth(1), Some("0.5,-1,0,0.1,0.5,0.8"));
}

#[test]
fn clamped_single_segment_bspline_equals_bezier_exactly() {
    let dir = examples_dir();
    let bezier = ok(
        &dir,
        &["eval", "example1.csv", "--samples", "1001", "--derivative"],
    );
    let bspline = ok(
        &dir,
        &[
            "eval",
            "example1.csv",
            "--samples",
            "1001",
            "--derivative",
            "--kind",
            "bspline",
            "--degree",
            "3",
        ],
    );
    assert_eq!(bezier, bspline);
    let explicit = ok(
        &dir,
        &[
            "eval",
            "example1.csv",
            "--samples",
            "1001",
            "--derivative",
            "--kind",
            "bspline",
            "--degree",
            "3",
            "--knots",
            "0,0,0,0,1,1,1,1",
        ],
    );
    assert_eq!(bezier, explicit);
}

#[test]
fn bspline_toml_and_csv_examples_agree() {
    let dir = examples_dir();
    let toml = ok(&dir, &["eval", "bspline.toml", "--derivative"]);
    let csv = ok(
        &dir,
        &[
            "eval",
            "bspline.csv",
            "--derivative",
            "--kind",
            "bspline",
            "--degree",
            "3",
            "--knots",
            "0,0,0,0,0.2,0.5,0.7,1,1,1,1",
        ],
    );
    assert_eq!(toml, csv);
    // Clamped: the curve starts at B0 and ends at B6, degrees included.
    assert_eq!(toml.lines().nth(1).unwrap().split(',').count(), 11);
    assert!(toml.lines().nth(1).unwrap().starts_with("0,0,0,0.9,0.1,0,"));
    assert!(toml
        .lines()
        .last()
        .unwrap()
        .starts_with("1,9,3,0.9,0.1,0.1,"));
}

#[test]
fn surface_corners_are_the_corner_control_points() {
    let out = ok(
        &examples_dir(),
        &["eval", "surface.toml", "--at", "0:0,0:1,1:0,1:1"],
    );
    assert_eq!(
        out,
        "u,v,x,y,z,truth,indeterminacy,falsity\n\
         0,0,0,0,0,0.9,0.1,0\n\
         0,1,0,3,0,0.9,0.4,0.15\n\
         1,0,3,0,0,0.3,0.1,0.15\n\
         1,1,3,3,0,0.3,0.4,0.3\n"
    );
}

#[test]
fn nurbs_surface_lies_on_the_cylinder() {
    let out = ok(
        &examples_dir(),
        &["eval", "nurbs-surface.json", "--samples", "21", "--normal"],
    );
    let rows = values(&out);
    assert_eq!(rows.len(), 441);
    for row in &rows {
        let (u, v, x, y, z) = (row[0], row[1], row[2], row[3], row[4]);
        assert!((x.hypot(y) - 1.0).abs() <= 1e-12, "{u}, {v}: {x}, {y}");
        assert!((z - 2.0 * v).abs() <= 1e-12, "{u}, {v}: z = {z}");
        // The normal is radial: (x, y, 0).
        assert!((row[8] - x).abs() <= 1e-12 && (row[9] - y).abs() <= 1e-12);
        assert!(row[10].abs() <= 1e-12);
    }
}

#[test]
fn surface_grid_is_row_major_with_exact_ends() {
    // knots_v [0, 0, 0, 2, 2, 2]: the v domain is [0, 2].
    let case = &cases()[7];
    let dir = dir_with(&[("m.toml", &case.toml())]);
    let out = ok(dir.path(), &["eval", "m.toml", "--samples", "3"]);
    let uv: Vec<(f64, f64)> = values(&out).iter().map(|r| (r[0], r[1])).collect();
    assert_eq!(
        uv,
        [
            (0.0, 0.0),
            (0.0, 1.0),
            (0.0, 2.0),
            (0.5, 0.0),
            (0.5, 1.0),
            (0.5, 2.0),
            (1.0, 0.0),
            (1.0, 1.0),
            (1.0, 2.0)
        ]
    );
    let out = ok(dir.path(), &["eval", "m.toml", "--samples", "1"]);
    assert_eq!(out.lines().nth(1).unwrap().split(',').next(), Some("0"));
    assert_eq!(out.lines().count(), 2);
}

#[test]
fn unclamped_domain_is_sampled_with_exact_ends() {
    let toml = "kind = \"bspline\"\ndegree = 2\n\
        knots = [0, 0.1, 0.2, 0.3, 0.7, 0.8, 0.9, 1]\n\
        control_points = [\n\
        { x = 0, y = 0, T = 0.1, I = 0.2, F = 0.3 },\n\
        { x = 1, y = 2, T = 0.2, I = 0.2, F = 0.3 },\n\
        { x = 2, y = 0, T = 0.3, I = 0.2, F = 0.3 },\n\
        { x = 3, y = 2, T = 0.4, I = 0.2, F = 0.3 },\n\
        { x = 4, y = 0, T = 0.5, I = 0.2, F = 0.3 },\n]\n";
    let dir = dir_with(&[("u.toml", toml)]);
    for n in [2u32, 3, 7, 100, 1001] {
        let out = ok(dir.path(), &["eval", "u.toml", "--samples", &n.to_string()]);
        let ts: Vec<f64> = values(&out).iter().map(|r| r[0]).collect();
        assert_eq!(ts.len(), n as usize);
        assert_eq!(ts[0], 0.2, "first of {n}");
        assert_eq!(*ts.last().unwrap(), 0.8, "last of {n}");
        for (k, &t) in ts.iter().enumerate().take(n as usize - 1).skip(1) {
            let want = 0.2 + (0.8 - 0.2) * (k as f64 / f64::from(n - 1));
            assert_eq!(t, want);
        }
        assert!(ts.windows(2).all(|w| w[0] < w[1]));
    }
    let at = ok(dir.path(), &["eval", "u.toml", "--at", "0.2,0.8"]);
    let all = ok(dir.path(), &["eval", "u.toml", "--samples", "2"]);
    assert_eq!(at, all);
    let summary = ok(dir.path(), &["check", "u.toml"]);
    assert!(
        summary.contains(
            "knots: 0, 0.1, 0.2, 0.3, 0.7, 0.8, 0.9, 1 (8 knots, given, unclamped)\ndomain: [0.2, 0.8]\n"
        ),
        "{summary}"
    );
}

#[test]
fn degenerate_surface_normal_is_empty_or_null() {
    // The u = 0 edge collapses to a point: no normal there.
    let toml = "kind = \"bezier-surface\"\nrows = 2\ncols = 2\ncontrol_points = [\n\
        { x = 0, y = 0, z = 0, T = 1, I = 0, F = 0 },\n\
        { x = 0, y = 0, z = 0, T = 1, I = 0, F = 0 },\n\
        { x = 1, y = 0, z = 0, T = 0, I = 0, F = 1 },\n\
        { x = 1, y = 1, z = 0, T = 0, I = 0, F = 1 },\n]\n";
    let dir = dir_with(&[("d.toml", toml)]);
    let out = ok(
        dir.path(),
        &["eval", "d.toml", "--at", "0:0.5,1:0.5", "--normal"],
    );
    assert_eq!(
        out,
        "u,v,x,y,z,truth,indeterminacy,falsity,nx,ny,nz\n\
         0,0.5,0,0,0,1,0,0,,,\n\
         1,0.5,1,0.5,0,0,0,1,0,0,1\n"
    );
    let out = ok(
        dir.path(),
        &[
            "eval", "d.toml", "--at", "0:0.5", "--normal", "--format", "json",
        ],
    );
    let v: serde_json::Value = serde_json::from_str(&out).expect("JSON");
    assert!(v[0]["nx"].is_null() && v[0]["nz"].is_null(), "{out}");
}

#[test]
fn surface_derivative_columns() {
    let out = ok(
        &examples_dir(),
        &[
            "eval",
            "nurbs-surface.json",
            "--at",
            "0:0.5",
            "--derivative",
        ],
    );
    let (header, rows) = parse_table(&out);
    assert_eq!(
        header.join(","),
        "u,v,x,y,z,truth,indeterminacy,falsity,\
         dx_du,dy_du,dz_du,dtruth_du,dindeterminacy_du,dfalsity_du,\
         dx_dv,dy_dv,dz_dv,dtruth_dv,dindeterminacy_dv,dfalsity_dv"
    );
    let row: Vec<f64> = rows[0].iter().map(|v| v.unwrap()).collect();
    // Along v the surface is the straight segment z = 2 v: dz/dv = 2, dx/dv = dy/dv = 0.
    assert!((row[16] - 2.0).abs() < 1e-12 && row[14].abs() < 1e-12 && row[15].abs() < 1e-12);
    // At u = 0 the arc leaves (1, 0) in the +y direction: dx/du = 0, dy/du > 0.
    assert!(row[8].abs() < 1e-12 && row[9] > 0.0 && row[10].abs() < 1e-12);
}

#[test]
fn check_summaries() {
    let dir = examples_dir();
    assert_eq!(
        ok(&dir, &["check", "nurbs-circle.toml"]),
        "nurbs-circle.toml: valid\nkind: nurbs\nname: unit circle\ndegree: 2\ndimension: 2\n\
         control points: 9\nmembership: neutrosophic\n\
         knots: 0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1 (12 knots, given, clamped)\n\
         domain: [0, 1]\nweights: 0.7071067811865476..1\ntruth: 0.1..0.9\n\
         indeterminacy: 0.1..0.5\nfalsity: 0..0.8\n\
         length: 6.28318530718\naverage truth: 0.55\naverage indeterminacy: 0.3\n\
         average falsity: 0.3\naverage score: 0.65\n"
    );
    assert_eq!(
        ok(&dir, &["check", "nurbs-surface.json"]),
        "nurbs-surface.json: valid\nkind: nurbs-surface\nname: quarter cylinder\n\
         degree_u: 2\ndegree_v: 1\ndimension: 3\ncontrol points: 9 (3 rows x 3 columns)\n\
         membership: neutrosophic\nknots_u: 0, 0, 0, 1, 1, 1 (6 knots, given, clamped)\n\
         knots_v: 0, 0, 0.5, 1, 1 (5 knots, clamped-uniform)\ndomain_u: [0, 1]\n\
         domain_v: [0, 1]\nweights: 0.7071067811865476..1\ntruth: 0.3..0.9\n\
         indeterminacy: 0.1..0.5\nfalsity: 0.05..0.65\n"
    );
    assert_eq!(
        ok(&dir, &["check", "surface.toml"]),
        "surface.toml: valid\nkind: bezier-surface\nname: bicubic hill\ndegree_u: 3\n\
         degree_v: 3\ndimension: 3\ncontrol points: 16 (4 rows x 4 columns)\n\
         membership: neutrosophic\ndomain_u: [0, 1]\ndomain_v: [0, 1]\ntruth: 0.3..0.9\n\
         indeterminacy: 0.1..0.4\nfalsity: 0..0.3\n"
    );
    let summary = ok(
        &dir,
        &["check", "bspline.csv", "--kind", "bspline", "--degree", "3"],
    );
    assert!(
        summary.contains(
            "knots: 0, 0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1, 1 (11 knots, clamped-uniform)\n"
        ),
        "{summary}"
    );
    // Long knot vectors show their ends.
    let points: String = (0..30).map(|k| format!("{k},0,0.5,0.5,0.5\n")).collect();
    let csv = format!("x,y,T,I,F\n{points}");
    let dir = dir_with(&[("long.csv", &csv)]);
    let summary = ok(
        dir.path(),
        &["check", "long.csv", "--kind", "bspline", "--degree", "1"],
    );
    assert!(
        summary.contains(
            "knots: 0, 0, 0.034482758620689655, 0.06896551724137931, 0.10344827586206896, \
             0.13793103448275862, ..., 0.8620689655172413, 0.896551724137931, \
             0.9310344827586207, 0.9655172413793104, 1, 1 (32 knots, clamped-uniform)\n"
        ),
        "{summary}"
    );
}

// ---------------------------------------------------------------------------------------------
// Errors.

/// A B-spline model whose `knots` are on line 3.
const BSPLINE: &str = "kind = \"bspline\"\n\
degree = 1\n\
knots = [0, 0, 0.5, 0.7, 1, 1]\n\
control_points = [\n\
  { x = 0, y = 0, T = 0.5, I = 0.5, F = 0.5 },\n\
  { x = 1, y = 0, T = 0.5, I = 0.5, F = 0.5 },\n\
  { x = 2, y = 1, T = 0.5, I = 0.5, F = 0.5 },\n\
  { x = 3, y = 0, T = 0.5, I = 0.5, F = 0.5 },\n\
]\n";

/// A NURBS model: weights on lines 5-8.
const NURBS: &str = "kind = \"nurbs\"\n\
degree = 2\n\
knots = \"chord-length\"\n\
control_points = [\n\
  { x = 0, y = 0, T = 0.5, I = 0.5, F = 0.5, weight = 1 },\n\
  { x = 1, y = 0, T = 0.5, I = 0.5, F = 0.5, weight = 2 },\n\
  { x = 2, y = 1, T = 0.5, I = 0.5, F = 0.5, weight = 1 },\n\
  { x = 3, y = 0, T = 0.5, I = 0.5, F = 0.5, weight = 1 },\n\
]\n";

/// A B-spline surface: 2 x 3, rows on line 2.
const SURFACE: &str = "kind = \"bspline-surface\"\n\
rows = 2\n\
cols = 3\n\
degree_u = 1\n\
degree_v = 2\n\
knots_u = [0, 0, 1, 1]\n\
control_points = [\n\
  { x = 0, y = 0, z = 0, T = 0.5, I = 0.5, F = 0.5 },\n\
  { x = 0, y = 1, z = 0, T = 0.5, I = 0.5, F = 0.5 },\n\
  { x = 0, y = 2, z = 0, T = 0.5, I = 0.5, F = 0.5 },\n\
  { x = 1, y = 0, z = 0, T = 0.5, I = 0.5, F = 0.5 },\n\
  { x = 1, y = 1, z = 1, T = 0.5, I = 0.5, F = 0.5 },\n\
  { x = 1, y = 2, z = 0, T = 0.5, I = 0.5, F = 0.5 },\n\
]\n";

const CSV4: &str =
    "x,y,T,I,F\n0,0,0.5,0.5,0.5\n1,0,0.5,0.5,0.5\n2,1,0.5,0.5,0.5\n3,0,0.5,0.5,0.5\n";

#[test]
fn model_files_are_valid_before_the_error_cases() {
    for (name, text) in [("b.toml", BSPLINE), ("n.toml", NURBS), ("s.toml", SURFACE)] {
        let dir = dir_with(&[(name, text)]);
        ok(dir.path(), &["check", name]);
    }
}

#[test]
fn knot_errors_name_field_and_line() {
    let cases: &[(&str, &str, &str)] = &[
        ("[0, 0, 0.5, 0.7, 1, 1]", "[0, 0, 0.7, 0.5, 1, 1]",
         "error: f.toml:3: knots: knot 3 = 0.5 is less than knot 2 = 0.7 (knots must be non-decreasing)"),
        ("[0, 0, 0.5, 0.7, 1, 1]", "[0, 0, 0.5, 1, 1]",
         "error: f.toml:3: knots: knot vector has 5 knots, expected 6 (number of control points + degree + 1)"),
        ("[0, 0, 0.5, 0.7, 1, 1]", "[0, 0, 0, 0.7, 1, 1]",
         "error: f.toml:3: knots: knot 0 appears 3 times, more than degree + 1 = 2"),
        ("[0, 0, 0.5, 0.7, 1, 1]", "[0, 0, nan, 0.7, 1, 1]",
         "error: f.toml:3: knots[2]: value NaN is not a finite number (NaN and infinities are not allowed)"),
        ("[0, 0, 0.5, 0.7, 1, 1]", "[0, 0, \"a\", 0.7, 1, 1]",
         "error: f.toml:3: knots[2]: expected a number, found the string \"a\""),
        ("[0, 0, 0.5, 0.7, 1, 1]", "\"open-uniform\"",
         "error: f.toml:3: knots: unknown knot rule `open-uniform` (expected one of: clamped-uniform, chord-length, centripetal, uniform, or an array of knot values)"),
        ("[0, 0, 0.5, 0.7, 1, 1]", "7",
         "error: f.toml:3: knots: expected an array of knot values or one of: clamped-uniform, chord-length, centripetal, uniform, found a number"),
        // A multi-line array: the line of the offending knot.
        ("[0, 0, 0.5, 0.7, 1, 1]", "[\n  0, 0,\n  0.5,\n  0.4,\n  1, 1,\n]",
         "error: f.toml:6: knots: knot 3 = 0.4 is less than knot 2 = 0.5 (knots must be non-decreasing)"),
        ("degree = 1", "degree = 4",
         "error: f.toml:2: degree: 4 control points are too few for degree 4 (need at least degree + 1 = 5)"),
        ("degree = 1", "degree = -1",
         "error: f.toml:2: degree: expected a non-negative integer, found -1"),
        ("degree = 1", "degree = 1.5",
         "error: f.toml:2: degree: expected a non-negative integer, found 1.5"),
        ("degree = 1", "degree = 10000000000",
         "error: f.toml:2: degree: 10000000000 is too large (at most 1000000000)"),
        ("degree = 1\n", "",
         "error: f.toml: missing key `degree` (kind `bspline` needs the polynomial degree; or give --degree)"),
    ];
    for (from, to, message) in cases {
        let text = BSPLINE.replacen(from, to, 1);
        assert_ne!(text, BSPLINE);
        assert_error("f.toml", &text, &["eval", "f.toml"], 1, message);
    }
    assert_error(
        "f.json",
        r#"{"kind": "bspline", "degree": 1, "knots": [0, 0, 1, 1],
            "control_points": [{"x": 0, "y": 0, "T": 1, "I": 0, "F": 0},
                               {"x": 1, "y": 0, "T": 1, "I": 0, "F": 0},
                               {"x": 2, "y": 0, "T": 1, "I": 0, "F": 0}]}"#,
        &["check", "f.json"],
        1,
        "error: f.json: knots: knot vector has 4 knots, expected 5 (number of control points + degree + 1)",
    );
}

#[test]
fn knot_errors_from_the_command_line() {
    let cases: &[(&[&str], &str)] = &[
        (&["--knots", "0,0,0.7,0.5,1,1"], "error: c.csv: --knots: knot 3 = 0.5 is less than knot 2 = 0.7 (knots must be non-decreasing)"),
        (&["--knots", "0,0,1,1"], "error: c.csv: --knots: knot vector has 4 knots, expected 6 (number of control points + degree + 1)"),
        (&["--knots", "0,0,0,1,1,1"], "error: c.csv: --knots: knot 0 appears 3 times, more than degree + 1 = 2"),
        (&["--degree", "5"], "error: c.csv: --degree: 4 control points are too few for degree 5 (need at least degree + 1 = 6)"),
    ];
    for (extra, message) in cases {
        let mut args = vec!["eval", "c.csv", "--kind", "bspline"];
        if !extra.contains(&"--degree") {
            args.extend(["--degree", "1"]);
        }
        args.extend(*extra);
        assert_error("c.csv", CSV4, &args, 1, message);
    }
    // Syntax errors are clap's usage errors (exit 2).
    let dir = dir_with(&[("c.csv", CSV4)]);
    let out = run_in(
        dir.path(),
        &[
            "eval",
            "c.csv",
            "--kind",
            "bspline",
            "--degree",
            "1",
            "--knots",
            "open-uniform",
        ],
    );
    assert_eq!(out.code, 2);
    assert_eq!(
        out.stderr.lines().next(),
        Some("error: invalid value 'open-uniform' for '--knots <RULE|K0,K1,...>': unknown knot rule `open-uniform` (expected one of: clamped-uniform, chord-length, centripetal, uniform, or knot values K0,K1,...)")
    );
}

#[test]
fn weight_errors_name_the_control_point_and_rule() {
    let cases: &[(&str, &str, &str)] = &[
        ("weight = 2", "weight = 0",
         "error: n.toml:6: control_points[1].weight: weight = 0 is not a positive finite number (NURBS weights must be > 0)"),
        ("weight = 2", "weight = -0.5",
         "error: n.toml:6: control_points[1].weight: weight = -0.5 is not a positive finite number (NURBS weights must be > 0)"),
        ("weight = 2", "weight = nan",
         "error: n.toml:6: control_points[1].weight: weight = NaN is not a positive finite number (NURBS weights must be > 0)"),
        ("weight = 2", "weight = \"2\"",
         "error: n.toml:6: control_points[1].weight: expected a number, found the string \"2\""),
        (", weight = 2", "",
         "error: n.toml:6: control_points[1]: missing key `weight` (kind `nurbs` needs a positive weight for every control point)"),
        ("kind = \"nurbs\"", "kind = \"bspline\"",
         "error: n.toml:5: control_points[0]: key `weight` does not apply to kind `bspline` (weights only apply to NURBS: nurbs, nurbs-surface)"),
    ];
    for (from, to, message) in cases {
        let text = NURBS.replacen(from, to, 1);
        assert_ne!(text, NURBS);
        assert_error("n.toml", &text, &["eval", "n.toml"], 1, message);
    }
    assert_error(
        "n.json",
        r#"{"kind": "nurbs", "degree": 1, "control_points": [
            {"x": 0, "y": 0, "T": 1, "I": 0, "F": 0, "weight": 1},
            {"x": 1, "y": 0, "T": 1, "I": 0, "F": 0, "weight": -1}]}"#,
        &["eval", "n.json"],
        1,
        "error: n.json: control_points[1].weight: weight = -1 is not a positive finite number (NURBS weights must be > 0)",
    );
    let csv = "x,y,T,I,F,weight\n0,0,1,0,0,1\n# comment\n1,0,1,0,0,0\n2,0,1,0,0,1\n";
    let nurbs = ["eval", "w.csv", "--kind", "nurbs", "--degree", "2"];
    assert_error(
        "w.csv",
        csv,
        &nurbs,
        1,
        "error: w.csv:4: column `weight`: weight = 0 is not a positive finite number (NURBS weights must be > 0)",
    );
    assert_error(
        "w.csv",
        &csv.replace(",0\n2", ",-inf\n2"),
        &nurbs,
        1,
        "error: w.csv:4: column `weight`: weight = -inf is not a positive finite number (NURBS weights must be > 0)",
    );
    assert_error(
        "w.csv",
        &csv.replace(",0\n2", ",heavy\n2"),
        &nurbs,
        1,
        "error: w.csv:4: column `weight`: value `heavy` is not a number",
    );
    assert_error(
        "w.csv",
        CSV4,
        &nurbs,
        1,
        "error: w.csv:1: missing column `weight` (kind `nurbs` needs a positive weight for every control point)",
    );
    assert_error(
        "w.csv",
        csv,
        &["eval", "w.csv", "--kind", "bspline", "--degree", "2"],
        1,
        "error: w.csv:1: column `weight` does not apply to kind `bspline` (weights only apply to NURBS: --kind nurbs or --kind nurbs-surface); a table of measured points (with a parameter or weight per point) is fitted by `neutrospline fit FILE`, not evaluated",
    );
    assert_error(
        "w.csv",
        csv,
        &["eval", "w.csv"],
        1,
        "error: w.csv:1: column `weight` does not apply to kind `bezier` (weights only apply to NURBS: --kind nurbs or --kind nurbs-surface); a table of measured points (with a parameter or weight per point) is fitted by `neutrospline fit FILE`, not evaluated",
    );
}

#[test]
fn surface_errors() {
    let cases: &[(&str, &str, &str)] = &[
        ("cols = 3", "cols = 4",
         "error: s.toml:2: rows: 6 control points do not fill a grid of 2 rows x 4 columns (8 points)"),
        ("{ x = 0, y = 1, z = 0,", "{ x = 0, y = 1,",
         "error: s.toml:9: control_points[1]: missing key `z` (surfaces are 3-D: every control point needs x, y and z)"),
        ("knots_u = [0, 0, 1, 1]", "knots_u = [0, 0, 1]",
         "error: s.toml:6: knots_u: knot vector has 3 knots, expected 4 (rows + degree_u + 1 = 2 + 1 + 1)"),
        ("knots_u = [0, 0, 1, 1]", "knots_u = [0, 1, 0, 1]",
         "error: s.toml:6: knots_u: knot 2 = 0 is less than knot 1 = 1 (knots must be non-decreasing)"),
        ("knots_u = [0, 0, 1, 1]", "knots_u = \"chord-length\"",
         "error: s.toml:6: knots_u: chord-length knots are only available for curves (for surfaces use clamped-uniform or an array of knot values)"),
        ("degree_v = 2", "degree_v = 3",
         "error: s.toml:5: degree_v: cols = 3 control points along v are too few for degree 3 (need at least degree_v + 1 = 4)"),
        ("degree_v = 2\n", "",
         "error: s.toml: missing key `degree_v` (kind `bspline-surface` needs the polynomial degree along v; or give --degree-v)"),
        ("rows = 2\n", "",
         "error: s.toml: missing key `rows` (kind `bspline-surface` needs the number of control points along u; or give --rows)"),
        ("rows = 2", "rows = 0",
         "error: s.toml:2: rows: expected a positive integer, found 0"),
        ("rows = 2", "rows = 2\ndegree = 2",
         "error: s.toml:3: key `degree` does not apply to kind `bspline-surface` (degree is for: bezier, bspline, nurbs)"),
        ("z = 1, T = 0.5, I = 0.5, F = 0.5", "z = 1, T = 0.5, I = 0.5, F = 0.5, weight = 1",
         "error: s.toml:12: control_points[4]: key `weight` does not apply to kind `bspline-surface` (weights only apply to NURBS: nurbs, nurbs-surface)"),
    ];
    for (from, to, message) in cases {
        let text = SURFACE.replacen(from, to, 1);
        assert_ne!(text, SURFACE, "{from}");
        assert_error("s.toml", &text, &["check", "s.toml"], 1, message);
    }
    let bezier = SURFACE
        .replace("bspline-surface", "bezier-surface")
        .replace("knots_u = [0, 0, 1, 1]\n", "");
    let dir = dir_with(&[("s.toml", &bezier)]);
    ok(dir.path(), &["check", "s.toml"]);
    assert_error(
        "s.toml",
        &bezier.replace("degree_v = 2", "degree_v = 1"),
        &["check", "s.toml"],
        1,
        "error: s.toml:5: degree_v: degree_v 1 does not match cols = 3 (a bezier surface has degree_v = cols - 1 = 2)",
    );
    assert_error(
        "s.toml",
        &bezier.replace("knots_u = [0, 0, 1, 1]\n", "").replace("cols = 3", "cols = 3\nknots_v = [0, 1]"),
        &["check", "s.toml"],
        1,
        "error: s.toml:4: key `knots_v` does not apply to kind `bezier-surface` (knots_v is for: bspline-surface, nurbs-surface)",
    );

    // CSV surfaces.
    let csv = "x,y,z,T,I,F\n0,0,0,1,0,0\n0,1,0,1,0,0\n1,0,0,0,0,1\n1,1,1,0,0,1\n";
    let dir = dir_with(&[("s.csv", csv)]);
    let out = ok(
        dir.path(),
        &[
            "eval",
            "s.csv",
            "--kind",
            "bezier-surface",
            "--rows",
            "2",
            "--cols",
            "2",
            "--at",
            "0.5:0.5",
        ],
    );
    assert_eq!(
        out,
        "u,v,x,y,z,truth,indeterminacy,falsity\n0.5,0.5,0.5,0.5,0.25,0.5,0,0.5\n"
    );
    assert_error(
        "s.csv",
        csv,
        &["eval", "s.csv", "--kind", "bezier-surface", "--rows", "3", "--cols", "2"],
        1,
        "error: s.csv: --rows: 4 control points do not fill a grid of 3 rows x 2 columns (6 points)",
    );
    assert_error(
        "s.csv",
        &csv.replace("x,y,z,", "x,y,").replace(",0,0,1,0,0", ",0,1,0,0").replace(",1,0,1,0,0", ",1,1,0,0").replace(",0,0,0,0,1", ",0,0,0,1").replace(",1,1,0,0,1", ",1,0,0,1"),
        &["eval", "s.csv", "--kind", "bezier-surface", "--rows", "2", "--cols", "2"],
        1,
        "error: s.csv:1: missing column `z` (surfaces are 3-D: every control point needs x, y and z)",
    );
    assert_error(
        "s.csv",
        csv,
        &["eval", "s.csv", "--kind", "bezier-surface", "--rows", "2", "--cols", "2", "--degree-u", "2"],
        1,
        "error: s.csv: --degree-u: degree_u 2 does not match rows = 2 (a bezier surface has degree_u = rows - 1 = 1)",
    );
    assert_error(
        "s.csv",
        csv,
        &["eval", "s.csv", "--kind", "bspline-surface", "--rows", "2", "--cols", "2", "--degree-u", "1"],
        2,
        "error: kind `bspline-surface` needs --degree-v for a CSV file (the polynomial degree along v; a CSV file only lists control points)",
    );
    assert_error(
        "s.csv",
        csv,
        &["eval", "s.csv", "--kind", "bezier-surface", "--cols", "2"],
        2,
        "error: kind `bezier-surface` needs --rows for a CSV file (the number of control points along u; a CSV file only lists control points)",
    );
    let out = run_in(
        dir.path(),
        &[
            "eval",
            "s.csv",
            "--kind",
            "bezier-surface",
            "--rows",
            "0",
            "--cols",
            "2",
        ],
    );
    assert_eq!(out.code, 2, "{}", out.stderr);
}

#[test]
fn at_outside_the_domain_exits_2_naming_the_domain() {
    let dir = examples_dir();
    let cases: &[(&[&str], &str)] = &[
        (&["eval", "example1.toml", "--at", "0.5,1.5"], "error: --at: t = 1.5 is outside the curve's domain [0, 1]"),
        (&["eval", "example1.toml", "--at", "-0.5"], "error: --at: t = -0.5 is outside the curve's domain [0, 1]"),
        (&["eval", "bspline.toml", "--at", "1.25"], "error: --at: t = 1.25 is outside the curve's domain [knot 3, knot 7] = [0, 1]"),
        (&["eval", "surface.toml", "--at", "0.5:1.5"], "error: --at: v = 1.5 (in `0.5:1.5`) is outside the surface's v domain [0, 1]"),
        (&["eval", "nurbs-surface.json", "--at", "0:0,-1:0"], "error: --at: u = -1 (in `-1:0`) is outside the surface's u domain [knot_u 2, knot_u 3] = [0, 1]"),
        (&["eval", "surface.toml", "--at", "0.5"], "error: --at: `0.5` is not a pair U:V (a surface is evaluated at --at U:V,U:V,...)"),
        (&["eval", "bspline.toml", "--at", "0.5:0.5"], "error: --at: `0.5:0.5` is a pair U:V but the file holds a curve (give --at T1,T2,...)"),
        (&["eval", "bspline.toml", "--normal"], "error: --normal applies only to surfaces (bspline.toml holds a bspline curve)"),
    ];
    for (args, message) in cases {
        let out = run_in(&dir, args);
        assert_eq!(
            (out.code, out.stderr.as_str(), out.stdout.as_str()),
            (2, format!("{message}\n").as_str(), ""),
            "{args:?}"
        );
    }
    let toml =
        "kind = \"bspline\"\ndegree = 2\nknots = [0, 1, 2, 3, 4, 5, 6, 7]\ncontrol_points = [\n\
        { x = 0, y = 0, T = 0, I = 0, F = 0 }, { x = 1, y = 0, T = 0, I = 0, F = 0 },\n\
        { x = 2, y = 0, T = 0, I = 0, F = 0 }, { x = 3, y = 0, T = 0, I = 0, F = 0 },\n\
        { x = 4, y = 0, T = 0, I = 0, F = 0 },\n]\n";
    assert_error(
        "u.toml",
        toml,
        &["eval", "u.toml", "--at", "1"],
        2,
        "error: --at: t = 1 is outside the curve's domain [knot 2, knot 5] = [2, 5]",
    );
}

#[test]
fn malformed_at_is_a_usage_error() {
    let dir = examples_dir();
    let cases: &[(&str, &str)] = &[
        ("0.5:", "`0.5:` is not a pair U:V of finite numbers (such as 0.5:0.25)"),
        ("0.5:x", "`0.5:x` is not a pair U:V of finite numbers (such as 0.5:0.25)"),
        ("1:2:3", "`1:2:3` is not a pair U:V of finite numbers (such as 0.5:0.25)"),
        ("NaN:0", "`NaN:0` is not a pair U:V of finite numbers (such as 0.5:0.25)"),
        ("0:0,0.5", "`0:0` and `0.5` mix single parameters and pairs (give T1,T2,... for a curve or U:V,U:V,... for a surface)"),
        ("0,inf", "parameter `inf` is not a finite number"),
        ("0,,1", "parameter `` is not a number"),
    ];
    for (at, message) in cases {
        let out = run_in(&dir, &["eval", "surface.toml", "--at", at]);
        assert_eq!(out.code, 2, "{at}: {}", out.stderr);
        assert_eq!(
            out.stderr.lines().next().unwrap_or_default(),
            format!("error: invalid value '{at}' for '--at <T1,T2,...|U:V,...>': {message}"),
        );
        assert!(out.stdout.is_empty());
    }
}

#[test]
fn options_must_agree_with_the_file() {
    let cases: &[(&[&str], i32, &str)] = &[
        (&["--kind", "nurbs"], 1, "error: f.toml:1: kind: the file declares kind `bspline` but --kind is `nurbs` (omit --kind or make them agree)"),
        (&["--degree", "2"], 1, "error: f.toml:2: degree: the file declares degree `1` but --degree is `2` (omit --degree or make them agree)"),
        (&["--knots", "clamped-uniform"], 1, "error: f.toml:3: knots: the file declares knots `[0, 0, 0.5, 0.7, 1, 1]` but --knots is `clamped-uniform` (omit --knots or make them agree)"),
        (&["--rows", "2"], 1, "error: f.toml:1: kind: --rows does not apply to kind `bspline` (--rows is for: bezier-surface, bspline-surface, nurbs-surface)"),
        (&["--kind", "bspline", "--rows", "2"], 2, "error: --rows does not apply to kind `bspline` (--rows is for: bezier-surface, bspline-surface, nurbs-surface)"),
    ];
    for (extra, code, message) in cases {
        let mut args = vec!["eval", "f.toml"];
        args.extend(*extra);
        assert_error("f.toml", BSPLINE, &args, *code, message);
    }
    // Agreeing options and options filling in what the file leaves out are fine.
    let dir = dir_with(&[
        ("f.toml", BSPLINE),
        (
            "g.toml",
            &BSPLINE.replace("kind = \"bspline\"\ndegree = 1\n", ""),
        ),
    ]);
    let a = ok(
        dir.path(),
        &[
            "eval",
            "f.toml",
            "--kind",
            "bspline",
            "--degree",
            "1",
            "--knots",
            "0,0,0.5,0.7,1,1",
        ],
    );
    let b = ok(
        dir.path(),
        &["eval", "g.toml", "--kind", "bspline", "--degree", "1"],
    );
    assert_eq!(a, b);
    assert_error(
        "g.toml",
        &BSPLINE.replace("kind = \"bspline\"\ndegree = 1\n", ""),
        &["eval", "g.toml", "--degree", "1"],
        1,
        "error: g.toml: missing key `kind` (known kinds: bezier, bspline, nurbs, bezier-surface, bspline-surface, nurbs-surface)",
    );

    // Bezier curves: --degree must be n; --knots does not apply.
    let dir_examples = examples_dir();
    ok(&dir_examples, &["check", "example1.csv", "--degree", "3"]);
    let cases: &[(&[&str], i32, &str)] = &[
        (&["--degree", "2"], 1, "error: example1.csv: --degree: degree 2 does not match the 4 control points (a bezier curve of n + 1 control points has degree n = 3)"),
        (&["--knots", "chord-length"], 2, "error: --knots does not apply to kind `bezier` (--knots is for: bspline, nurbs); choose the kind with --kind"),
        (&["--kind", "bspline"], 2, "error: kind `bspline` needs --degree for a CSV file (the polynomial degree; a CSV file only lists control points)"),
        (&["--kind", "nurbs", "--degree", "2"], 1, "error: example1.csv:4: missing column `weight` (kind `nurbs` needs a positive weight for every control point)"),
    ];
    for (extra, code, message) in cases {
        let mut args = vec!["check", "example1.csv"];
        args.extend(*extra);
        let out = run_in(&dir_examples, &args);
        assert_eq!(
            (out.code, out.stderr.as_str(), out.stdout.as_str()),
            (*code, format!("{message}\n").as_str(), ""),
            "{args:?}"
        );
    }
    assert_error(
        "e.toml",
        "kind = \"bezier\"\ndegree = 3\ncontrol_points = [{ x = 0, y = 0, truth = 1, I = 0, F = 0 }, { x = 1, y = 0, truth = 1, I = 0, F = 0 }]\n",
        &["check", "e.toml"],
        1,
        "error: e.toml:2: degree: degree 3 does not match the 2 control points (a bezier curve of n + 1 control points has degree n = 1)",
    );
}

#[test]
fn surface_rows_stream_and_output_file_stays_atomic() {
    // 10^10 rows: only streaming can produce the first lines.
    let mut child = Command::new(BIN)
        .args(["eval", "surface.toml", "--samples", "100000", "--normal"])
        .current_dir(examples_dir())
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("binary runs");
    let mut stdout = child.stdout.take().expect("stdout piped");
    let mut first = [0u8; 4096];
    stdout.read_exact(&mut first).expect("some output");
    drop(stdout);
    let out = child.wait_with_output().expect("binary finishes");
    assert_eq!(out.status.code(), Some(0));
    assert!(out.stderr.is_empty());
    assert!(first.starts_with(b"u,v,x,y,z,truth,indeterminacy,falsity,nx,ny,nz\n0,0,0,0,0,"));

    let surface = std::fs::read_to_string(examples_dir().join("surface.toml")).unwrap();
    let dir = dir_with(&[("s.toml", surface.as_str()), ("out.csv", "old\n")]);
    let out = run_in(
        dir.path(),
        &["eval", "s.toml", "--at", "0:0,2:0", "-o", "out.csv"],
    );
    assert_eq!(out.code, 2);
    assert_eq!(
        std::fs::read_to_string(dir.path().join("out.csv")).unwrap(),
        "old\n"
    );
    let out = run_in(
        dir.path(),
        &["eval", "s.toml", "--samples", "4", "-o", "out.csv"],
    );
    assert_eq!(out.code, 0, "{}", out.stderr);
    let written = std::fs::read_to_string(dir.path().join("out.csv")).unwrap();
    assert_eq!(written.lines().count(), 17);
}

#[test]
fn huge_degree_is_a_usage_error_not_a_panic() {
    // Regression: --degree 18446744073709551615 overflowed `degree + 1` in the core.
    let out = run_in(
        &examples_dir(),
        &[
            "check",
            "bspline.csv",
            "--kind",
            "bspline",
            "--degree",
            "18446744073709551615",
        ],
    );
    assert_eq!(out.code, 2);
    assert_eq!(
        out.stderr.lines().next(),
        Some("error: invalid value '18446744073709551615' for '--degree <P>': 18446744073709551615 is not in 0..=1000000000")
    );
    let out = run_in(
        &examples_dir(),
        &[
            "check",
            "bspline.csv",
            "--kind",
            "bspline",
            "--degree",
            "1000000000",
        ],
    );
    assert_eq!(
        (out.code, out.stderr.as_str()),
        (1, "error: bspline.csv: --degree: 7 control points are too few for degree 1000000000 (need at least degree + 1 = 1000000001)\n")
    );
}
