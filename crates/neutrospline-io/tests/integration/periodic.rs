//! Unclamped (`knots = "uniform"`) and periodic (`periodic = true`) models: what the readers
//! build (the distinct control points followed by the first `degree` again, the knots of the
//! breakpoints), what the writers write (the short form), and the located refusals.

use neutrospline::{EvaluateSurface, KnotVector};
use neutrospline_io::{parse, to_string, Format, ReadOptions, Shape};

fn read(text: &str) -> Result<neutrospline_io::Model, String> {
    parse(
        "m.toml",
        Format::Toml,
        text.as_bytes(),
        &ReadOptions::default(),
    )
    .map_err(|e| e.to_string())
}

const SQUARE: &str = "kind = \"bspline\"\ndegree = 2\nperiodic = true\ncontrol_points = [\n\
    { name = \"A\", x = 0, y = 0, T = 0.9, I = 0.1, F = 0.1 },\n\
    { x = 3, y = 0, T = 0.5, I = 0.2, F = 0.3 },\n\
    { x = 3, y = 4, T = 0.3, I = 0.2, F = 0.6 },\n]\n";

#[test]
fn periodic_curve_reads_wrapped_and_writes_short() {
    let model = read(SQUARE).unwrap();
    let curve = model.shape().curve().unwrap();
    assert_eq!(curve.len(), 5);
    assert_eq!(
        curve.knots().unwrap().knots(),
        &[
            1.0 / 3.0 - 1.0,
            2.0 / 3.0 - 1.0,
            0.0,
            1.0 / 3.0,
            2.0 / 3.0,
            1.0,
            1.0 / 3.0 + 1.0,
            2.0 / 3.0 + 1.0
        ]
    );
    assert_eq!(curve.domain(), 0.0..1.0);
    assert_eq!(model.periodic_counts(), [Some(3)]);
    // The copies carry the name of the point they repeat.
    assert_eq!(model.point_names()[3].as_deref(), Some("A"));
    let toml = to_string(&model, Format::Toml).unwrap();
    assert!(
        toml.contains("degree = 2\nknots = [0.0, 0.3333333333333333, 0.6666666666666666, 1.0]\nperiodic = true\n"),
        "{toml}"
    );
    assert_eq!(toml.matches("[[control_points]]").count(), 3);
    for format in [Format::Toml, Format::Json] {
        let text = to_string(&model, format).unwrap();
        let back = parse("m", format, text.as_bytes(), &ReadOptions::default()).unwrap();
        assert_eq!(back, model, "{format}");
    }
    let csv = to_string(&model, Format::Csv).unwrap();
    assert_eq!(csv.lines().count(), 4, "{csv}");
    let back = parse(
        "m.csv",
        Format::Csv,
        csv.as_bytes(),
        &model.csv_read_options(),
    )
    .unwrap();
    assert_eq!(back.shape(), model.shape());
    // The curve closes: its two ends are one point, its degrees too.
    let (a, b) = (
        curve.evaluate_row(0.0).unwrap(),
        curve.evaluate_row(1.0).unwrap(),
    );
    for (x, y) in a.iter().zip(&b) {
        assert!((x - y).abs() < 1e-15, "{a:?} {b:?}");
    }
}

#[test]
fn periodic_knot_rules_and_breakpoints() {
    // Chord length along the closed polygon: edges 3, 4 and the closing 5 of a 3-4-5 triangle.
    let chord = read(&SQUARE.replace(
        "periodic = true",
        "periodic = true\nknots = \"chord-length\"",
    ))
    .unwrap();
    let knots = chord.shape().curve_knots().unwrap();
    assert_eq!(
        knots.periodic_breakpoints(),
        Some(&[0.0, 0.25, 7.0 / 12.0, 1.0][..])
    );
    let given = read(&SQUARE.replace("periodic = true", "periodic = true\nknots = [2, 2.5, 3, 4]"))
        .unwrap();
    assert_eq!(given.shape().curve_domain(), Some(2.0..4.0));
    assert_eq!(
        given.shape().curve_knots().unwrap(),
        &KnotVector::periodic(2, &[2.0, 2.5, 3.0, 4.0]).unwrap()
    );
    // Unclamped uniform knots, domain [0, 1].
    let uniform = read(&SQUARE.replace("periodic = true", "knots = \"uniform\"")).unwrap();
    assert_eq!(
        uniform.shape().curve_knots().unwrap().knots(),
        &[-2.0, -1.0, 0.0, 1.0, 2.0, 3.0]
    );
    assert_eq!(uniform.periodic_counts(), [None]);
}

#[test]
fn periodic_refusals_are_located() {
    let cases = [
        (SQUARE.replace("periodic = true", "periodic = true\nknots = [0, 0.5, 1]"),
         "m.toml:4: knots: a periodic spline of 3 control points takes 4 breakpoints (the control points + 1, from the start of one period to its end), not 3"),
        (SQUARE.replace("periodic = true", "periodic = true\nknots = \"clamped-uniform\""),
         "m.toml:4: knots: clamped-uniform knots cannot close a periodic curve (give uniform, chord-length, centripetal, or the breakpoints: 4 values from the start of one period to its end)"),
        (SQUARE.replace("periodic = true", "periodic = true\nknots = [0, 0.5, 0.25, 1]"),
         "m.toml:4: knots: knot 2 = 0.25 is less than knot 1 = 0.5 (knots must be non-decreasing) (periodic breakpoints)"),
        (SQUARE.replace("periodic = true", "periodic = true\nknots = [1, 1, 1, 1]"),
         "m.toml:4: knots: the domain [knot 2, knot 5] = [1, 1] is empty (the knots there must differ) (periodic breakpoints)"),
        (SQUARE.replace("degree = 2", "degree = 0"),
         "m.toml:3: periodic: a periodic spline needs degree >= 1 (degree 0 has nothing to join)"),
        (SQUARE.replace("periodic = true", "periodic = \"yes\""),
         "m.toml:3: periodic: expected true or false, found the string \"yes\""),
        (SQUARE.replace("kind = \"bspline\"\ndegree = 2\n", "kind = \"bezier\"\n"),
         "m.toml:2: key `periodic` does not apply to kind `bezier` (periodic is for: bspline, nurbs)"),
    ];
    for (text, want) in cases {
        assert_eq!(read(&text).unwrap_err(), want, "{text}");
    }
}

#[test]
fn periodic_surface_wraps_rows_and_columns() {
    let mut text = String::from(
        "kind = \"bspline-surface\"\nrows = 3\ncols = 2\ndegree_u = 2\ndegree_v = 1\nperiodic_u = true\ncontrol_points = [\n",
    );
    for i in 0..3 {
        for j in 0..2 {
            text.push_str(&format!(
                "{{ x = {i}, y = {j}, z = {}, T = 0.5, I = 0.5, F = 0.5 }},\n",
                i * j
            ));
        }
    }
    text.push_str("]\n");
    let model = read(&text).unwrap();
    let Shape::Surface(s) = model.shape() else {
        panic!()
    };
    assert_eq!((s.rows(), s.cols()), (5, 2));
    assert_eq!(
        s.knots_u().periodic_breakpoints(),
        Some(&[0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0][..])
    );
    assert_eq!(model.periodic_counts(), [Some(3), None]);
    let toml = to_string(&model, Format::Toml).unwrap();
    assert!(toml.contains("rows = 3\ncols = 2\n"), "{toml}");
    assert!(
        toml.contains("periodic_u = true\n") && !toml.contains("periodic_v"),
        "{toml}"
    );
    assert_eq!(toml.matches("[[control_points]]").count(), 6);
    let back = read(&toml).unwrap();
    assert_eq!(back, model);
    // The surface closes along u: the row at u = 0 is the row at u = 1.
    for v in [0.0, 0.3, 1.0] {
        let (a, b) = (s.evaluate(0.0, v).unwrap(), s.evaluate(1.0, v).unwrap());
        for (x, y) in a.position.iter().zip(&b.position) {
            assert!((x - y).abs() < 1e-15);
        }
    }
}
