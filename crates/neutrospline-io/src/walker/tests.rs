//! Unit tests of the TOML and JSON readers: messages, lines and fields.

use super::*;

fn with_membership(membership: Option<Family>) -> ReadOptions {
    ReadOptions {
        membership,
        ..ReadOptions::default()
    }
}

const EXAMPLE1_TOML: &str = r#"kind = "bezier"
name = "Example 1"
description = "Paper's Example 1"

[[control_points]]
name = "C0"
x = 1
y = 3
truth = 0.3
indeterminacy = 0.6
falsity = 0.1

[[control_points]]
name = "C1"
x = 3
y = 6
T = 0.8
I = 0.1
F = 0.1

[[control_points]]
name = "C2"
x = 6.0
y = 2.0
truth = 0.7
indeterminacy = 0.1
falsity = 0.2

[[control_points]]
name = "C3"
x = 9
y = 5
truth = 0.2
indeterminacy = 0.4
falsity = 0.4
"#;

fn toml_err(text: &str) -> String {
    parse_toml("m.toml", text.as_bytes(), &ReadOptions::default())
        .unwrap_err()
        .to_string()
}

fn json_err(text: &str) -> String {
    parse_json("m.json", text.as_bytes(), &ReadOptions::default())
        .unwrap_err()
        .to_string()
}

#[test]
fn model_parse_toml_example1() {
    let m = parse_toml("m.toml", EXAMPLE1_TOML.as_bytes(), &ReadOptions::default()).unwrap();
    assert_eq!(m.kind, Kind::DEFAULT);
    assert_eq!(m.name.as_deref(), Some("Example 1"));
    assert_eq!(m.membership, Family::Neutrosophic);
    assert_eq!(m.dimension, 2);
    assert_eq!(m.points.len(), 4);
    assert_eq!(m.points[1].degrees.to_array(), [0.8, 0.1, 0.1]);
    assert_eq!(m.points[2].position, vec![6.0, 2.0]);
    assert_eq!(m.points[3].name.as_deref(), Some("C3"));
}

#[test]
fn model_parse_json_inline() {
    let text = r#"{"kind": "bezier", "membership": "intuitionistic",
        "control_points": [{"x": 0, "y": 0, "z": 1, "truth": 0.5, "falsity": 0.25},
                           {"x": 1, "y": 0, "z": 2, "T": 0.25, "F": 0.5, "I": 0.25}]}"#;
    let m = parse_json("m.json", text.as_bytes(), &ReadOptions::default()).unwrap();
    assert_eq!(m.dimension, 3);
    assert_eq!(m.membership, Family::Intuitionistic);
    assert_eq!(m.points[0].degrees.to_array(), [0.5, 0.25, 0.25]);
    assert_eq!(m.points[1].position, vec![1.0, 0.0, 2.0]);
}

#[test]
fn model_parse_toml_errors_name_path_and_line() {
    let bad = EXAMPLE1_TOML.replace("truth = 0.7", "truth = 1.7");
    assert_eq!(
        toml_err(&bad),
        "m.toml:25: control_points[2]: truth = 1.7 is outside [0, 1] (every degree must be in [0, 1])"
    );
    let bad = EXAMPLE1_TOML.replace("y = 2.0", "y = \"two\"");
    assert_eq!(
        toml_err(&bad),
        "m.toml:24: control_points[2].y: expected a number, found the string \"two\""
    );
    let bad = EXAMPLE1_TOML.replace("I = 0.1", "I = 0.1\nw = 2");
    assert_eq!(
        toml_err(&bad),
        "m.toml:19: control_points[1]: unknown key `w` (known keys: x, y, z, truth (T), indeterminacy (I), falsity (F), weight, name)"
    );
    let bad = EXAMPLE1_TOML.replace("I = 0.1", "I = 0.1\nweight = 2");
    assert_eq!(
        toml_err(&bad),
        "m.toml:19: control_points[1]: key `weight` does not apply to kind `bezier` (weights only apply to NURBS: nurbs, nurbs-surface)"
    );
    let bad = EXAMPLE1_TOML.replace("T = 0.8", "T = 0.8\ntruth = 0.8");
    assert_eq!(
        toml_err(&bad),
        "m.toml:18: control_points[1]: key `truth` repeats key `T` (each field may appear once; T, I and F are aliases of truth, indeterminacy and falsity)"
    );
    let bad = EXAMPLE1_TOML.replace("falsity = 0.4\n", "");
    assert_eq!(
        toml_err(&bad),
        "m.toml:29: control_points[3]: missing key `falsity` (neutrosophic rule requires it)"
    );
    let bad = EXAMPLE1_TOML.replace("x = 9\n", "x = 9\nz = 1\n");
    assert_eq!(
        toml_err(&bad),
        "m.toml:29: control_points[3]: has `z` but control_points[0] has none (all control points must have the same dimension)"
    );
    let bad = EXAMPLE1_TOML.replace("x = 3\n", "x = nan\n");
    assert_eq!(
        toml_err(&bad),
        "m.toml:15: control_points[1].x: value NaN is not a finite number (NaN and infinities are not allowed)"
    );
    let bad = EXAMPLE1_TOML.replace("kind = \"bezier\"", "kind = \"spline\"");
    assert_eq!(
        toml_err(&bad),
        "m.toml:1: kind: unknown kind `spline` (known kinds: bezier, bspline, nurbs, bezier-surface, bspline-surface, nurbs-surface)"
    );
    let bad = EXAMPLE1_TOML.replace("kind = \"bezier\"\n", "");
    assert_eq!(
        toml_err(&bad),
        "m.toml: missing key `kind` (known kinds: bezier, bspline, nurbs, bezier-surface, bspline-surface, nurbs-surface)"
    );
    let bad = EXAMPLE1_TOML.replace("name = \"Example 1\"", "title = \"Example 1\"");
    assert_eq!(
        toml_err(&bad),
        "m.toml:2: unknown key `title` (known keys: kind, name, description, membership, q, n, degree, knots, rows, cols, degree_u, degree_v, knots_u, knots_v, periodic, periodic_u, periodic_v, control_points)"
    );
}

#[test]
fn model_parse_toml_syntax_error_has_line() {
    let e = toml_err("kind = \"bezier\"\nx = = 1\n");
    assert!(e.starts_with("m.toml:2: invalid TOML: "), "{e}");
    assert!(!e.contains('\n'), "{e}");
}

#[test]
fn model_parse_membership_conflict_and_default() {
    let text = "kind = \"bezier\"\nmembership = \"fuzzy\"\ncontrol_points = [{x = 0, y = 0, truth = 0.5}]\n";
    let m = parse_toml("m.toml", text.as_bytes(), &ReadOptions::default()).unwrap();
    assert_eq!(m.points[0].degrees.to_array(), [0.5, 0.0, 0.0]);
    let e = parse_toml(
        "m.toml",
        text.as_bytes(),
        &with_membership(Some(Family::Neutrosophic)),
    )
    .unwrap_err()
    .to_string();
    assert_eq!(
        e,
        "m.toml:2: membership: the file declares membership `fuzzy` but --membership is `neutrosophic` (omit --membership or make them agree)"
    );
    let text = "kind = \"bezier\"\ncontrol_points = [{x = 0, y = 0, truth = 0.5}]\n";
    let m = parse_toml(
        "m.toml",
        text.as_bytes(),
        &with_membership(Some(Family::Fuzzy)),
    )
    .unwrap();
    assert_eq!(m.membership, Family::Fuzzy);
}

#[test]
fn model_parse_json_errors() {
    assert_eq!(
        json_err(r#"{"kind": "bezier", "kind": "bezier", "control_points": []}"#),
        "m.json: duplicated key `kind` (each key may appear once)"
    );
    assert_eq!(
        json_err(r#"{"kind": "bezier", "control_points": []}"#),
        "m.json: control_points: no control points (a curve needs at least one)"
    );
    assert_eq!(
        json_err(
            r#"{"kind": "bezier", "control_points": [{"x": 1, "y": 2, "truth": 0.5, "indeterminacy": 0.5, "falsity": 0.5}, 3]}"#
        ),
        "m.json: control_points[1]: expected an object, found a number"
    );
    assert_eq!(
        json_err(r#"{"kind": "bezier", "control_points": [{"x": 1, "y": null, "truth": 0.5}]}"#),
        "m.json: control_points[0].y: expected a number, found null"
    );
    assert_eq!(
        json_err(r#"{"kind": "bezier", "control_points": [{"x": 1, "truth": 0.5}]}"#),
        "m.json: control_points[0]: missing key `y` (every control point needs x and y)"
    );
    assert_eq!(
        json_err("[1, 2]"),
        "m.json: expected an object at the top level, found an array"
    );
    assert_eq!(
        json_err("{\n  \"kind\": \"bezier\",\n  \"control_points\": [\n}"),
        "m.json:4: invalid JSON: expected value (column 1)"
    );
    assert_eq!(
        json_err(
            r#"{"kind": "bezier", "control_points": [{"x": 1, "y": 1e999, "truth": 0.5}]}"#
        ),
        "m.json:1: invalid JSON: number out of range (column 57; the number does not fit a 64-bit float)"
    );
}

#[test]
fn model_parse_json_numbers_round_trip_exactly() {
    // Regression: serde_json's default float parser was 2 ULP off for this value, so a
    // JSON model evaluated differently from the same TOML model.
    let y = -1.7669093114403063_f64;
    let text = format!(
        r#"{{"kind": "bezier", "control_points": [{{"x": 0, "y": {y}, "T": 1, "I": 0, "F": 0}}]}}"#
    );
    let m = parse_json("m.json", text.as_bytes(), &ReadOptions::default()).unwrap();
    assert_eq!(m.points[0].position[1].to_bits(), y.to_bits());
}

#[test]
fn model_parse_structure_keys_and_knot_lines() {
    let text = "kind = \"nurbs\"\ndegree = 1\nknots = [\n  0, 0,\n  1, 1,\n]\n\
                control_points = [{ x = 0, y = 0, T = 1, I = 0, F = 0, weight = 2 },\n\
                { x = 1, y = 0, T = 1, I = 0, F = 0, weight = 0.5 }]\n";
    let m = parse_toml("m.toml", text.as_bytes(), &ReadOptions::default()).unwrap();
    let Structure::Curve { degree, knots, .. } = &m.structure else {
        panic!("a curve")
    };
    assert_eq!(degree.as_ref().map(|d| d.value), Some(1));
    let knots = knots.as_ref().unwrap();
    assert_eq!(knots.spec, KnotSpec::Explicit(vec![0.0, 0.0, 1.0, 1.0]));
    assert_eq!(knots.origin.line, Some(3));
    assert_eq!(knots.lines, [Some(4), Some(4), Some(5), Some(5)]);
    assert_eq!(m.points[1].weight, Some(0.5));
    assert_eq!(m.points[1].weight_origin.line, Some(8));
}

#[test]
fn model_parse_invalid_utf8() {
    let e = parse_json("m.json", b"{\"kind\":\n\"\xff\"}", &ReadOptions::default()).unwrap_err();
    assert_eq!(
        e.to_string(),
        "m.json:2: invalid UTF-8 (the file must be UTF-8 encoded)"
    );
}

#[test]
fn model_parse_spreads_symmetric_and_asymmetric() {
    let text = "kind = \"bezier\"\n\n[[control_points]]\nx = 0\ny = 0\ntruth = 1\nI = 0\nF = 0\n\
                spread_x = 0.5\nspread_y_left = 1\nspread_y_right = 2\n\n[[control_points]]\nx = 1\n\
                y = 1\ntruth = 1\nI = 0\nF = 0\n";
    let m = parse_toml("m.toml", text.as_bytes(), &ReadOptions::default()).unwrap();
    assert_eq!(m.points[0].spread.left, [0.5, 1.0, 0.0]);
    assert_eq!(m.points[0].spread.right, [0.5, 2.0, 0.0]);
    assert_eq!(m.points[1].spread, neutrospline::Spread::ZERO);
    let json = r#"{"kind": "bezier", "control_points": [
        {"x": 0, "y": 0, "z": 1, "T": 1, "I": 0, "F": 0, "spread_z": 3, "spread_x_right": 0.25}]}"#;
    let m = parse_json("m.json", json.as_bytes(), &ReadOptions::default()).unwrap();
    assert_eq!(m.points[0].spread.left, [0.0, 0.0, 3.0]);
    assert_eq!(m.points[0].spread.right, [0.25, 0.0, 3.0]);
}

#[test]
fn model_parse_spread_errors_are_located() {
    let point = |extra: &str| {
        format!("kind = \"bezier\"\n\n[[control_points]]\nx = 0\ny = 0\ntruth = 1\nI = 0\nF = 0\n{extra}")
    };
    let cases: &[(&str, &str)] = &[
        (
            "spread_x = 1\nspread_x_left = 2\n",
            "m.toml:9: control_points[0]: key `spread_x` and `spread_x_left` are both given (give the symmetric spread `spread_x` or the asymmetric `spread_x_left` and `spread_x_right` for one axis, not both)",
        ),
        (
            "spread_y = -1\n",
            "m.toml:9: control_points[0].spread_y: spread -1 is negative (a spread is a distance >= 0)",
        ),
        (
            "spread_y_right = nan\n",
            "m.toml:9: control_points[0].spread_y_right: value NaN is not a finite number (NaN and infinities are not allowed)",
        ),
        (
            "spread_z = 1\n",
            "m.toml:9: control_points[0]: key `spread_z` does not apply to a curve without z (the spread of z needs a z coordinate)",
        ),
        (
            "spread_w = 1\n",
            "m.toml:9: control_points[0]: unknown key `spread_w` (known keys: x, y, z, truth (T), indeterminacy (I), falsity (F), weight, name) (spreads: spread_x, spread_y, spread_z, or spread_x_left and spread_x_right and so on)",
        ),
        (
            "spread_x = \"wide\"\n",
            "m.toml:9: control_points[0].spread_x: expected a number, found the string \"wide\"",
        ),
    ];
    for (extra, want) in cases {
        assert_eq!(toml_err(&point(extra)), *want, "{extra}");
    }
    let surface = "kind = \"bezier-surface\"\nrows = 1\ncols = 1\n\n[[control_points]]\nx = 0\n\
                   y = 0\nz = 0\ntruth = 1\nI = 0\nF = 0\nspread_x = 1\n";
    assert_eq!(
        toml_err(surface),
        "m.toml:12: control_points[0]: key `spread_x` does not apply to surfaces (spreads apply to curves only)"
    );
    assert_eq!(
        json_err(
            r#"{"kind": "bezier", "control_points": [{"x": 0, "y": 0, "T": 1, "I": 0, "F": 0, "spread_x": -0.5}]}"#
        ),
        "m.json: control_points[0].spread_x: spread -0.5 is negative (a spread is a distance >= 0)"
    );
}
