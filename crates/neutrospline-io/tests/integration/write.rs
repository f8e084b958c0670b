//! The writers' exact output for a small model of each kind, in TOML, JSON and CSV, and that
//! it reads back to the same model.

use neutrospline::{
    AnyCurve, BSpline, Bezier, ControlPoint, Degrees, Family, KnotVector, Nurbs, Surface,
};
use neutrospline_io::{
    parse, save, to_csv_string, to_json_string, to_toml_string, Format, Model, ReadOptions,
    WriteError,
};

fn point<const D: usize>(position: [f64; D], degrees: Degrees) -> ControlPoint<D> {
    ControlPoint::new(position, degrees)
}

fn d(t: f64, i: f64, f: f64) -> Degrees {
    Degrees::new(t, i, f).unwrap()
}

fn knots(values: &[f64], degree: usize, count: usize) -> KnotVector {
    KnotVector::new(values.to_vec(), degree, count).unwrap()
}

/// A planar Bézier curve with a name, a description and named points.
fn bezier() -> Model {
    let curve = Bezier::new(vec![
        point([1.0, 3.0], d(0.3, 0.6, 0.1)),
        point([9.0, 5.0], d(0.2, 0.4, 0.4)),
    ])
    .unwrap();
    Model::new(AnyCurve::Bezier(curve))
        .with_name("Line \"one\"")
        .with_description("two points\nsecond line")
        .with_point_names([Some("C0"), Some("C1")])
        .unwrap()
}

/// A spatial B-spline with non-uniform knots, intuitionistic degrees, extreme numbers.
fn bspline() -> Model {
    let i = |t, f| Degrees::intuitionistic(t, f).unwrap();
    let curve = BSpline::new(
        vec![
            point([0.0, -0.0, 1e-300], i(0.5, 0.25)),
            point([0.1 + 0.2, 1.0 / 3.0, 2.0], i(0.1 + 0.2, 0.5)),
            point([1e16, -1.7976931348623157e308, 5e-324], i(1.0, 0.0)),
        ],
        knots(&[0.0, 0.0, 0.25, 1.0, 1.0], 1, 3),
    )
    .unwrap();
    Model::new(AnyCurve::BSpline(curve))
        .with_membership(Family::Intuitionistic)
        .unwrap()
}

/// A planar NURBS with fuzzy degrees and some named points.
fn nurbs() -> Model {
    let curve = Nurbs::new(
        vec![
            point([0.0, 0.0], Degrees::fuzzy(0.25).unwrap()),
            point([1.0, 1.0], Degrees::fuzzy(1.0).unwrap()),
            point([2.0, 0.0], Degrees::fuzzy(0.0).unwrap()),
        ],
        vec![1.0, 0.5, 2.0],
        knots(&[0.0, 0.0, 0.0, 1.0, 1.0, 1.0], 2, 3),
    )
    .unwrap();
    Model::new(AnyCurve::Nurbs(curve))
        .with_membership(Family::Fuzzy)
        .unwrap()
        .with_point_names([Some("a"), None, Some("c")])
        .unwrap()
}

fn grid(rows: usize, cols: usize) -> Vec<ControlPoint<3>> {
    (0..rows * cols)
        .map(|k| {
            let (r, c) = ((k / cols) as f64, (k % cols) as f64);
            point([r, c, r * c], d(0.5, 0.25, 0.125))
        })
        .collect()
}

fn bezier_surface() -> Model {
    Model::new(Surface::bezier(2, 2, grid(2, 2)).unwrap()).with_name("patch")
}

fn bspline_surface() -> Model {
    let surface = Surface::bspline(
        2,
        2,
        grid(2, 2),
        knots(&[0.0, 0.0, 1.0, 1.0], 1, 2),
        knots(&[0.0, 1.0, 2.0, 3.0], 1, 2),
    )
    .unwrap();
    Model::new(surface)
}

fn nurbs_surface() -> Model {
    let surface = Surface::nurbs(
        1,
        2,
        grid(1, 2),
        vec![1.0, 4.0],
        knots(&[0.0, 1.0], 0, 1),
        knots(&[0.0, 0.0, 1.0, 1.0], 1, 2),
    )
    .unwrap();
    Model::new(surface).with_description("one row")
}

/// Reads `text` in `format` (CSV: with the model's own options) and checks it equals `model`
/// (CSV: without name and description).
fn reads_back(model: &Model, format: Format, text: &str) {
    let options = match format {
        Format::Csv => model.csv_read_options(),
        _ => ReadOptions::default(),
    };
    let back = parse("m", format, text.as_bytes(), &options).unwrap();
    let expected = match format {
        Format::Csv => Model::new(model.shape().clone())
            .with_membership(model.membership())
            .unwrap()
            .with_point_names(model.point_names().to_vec())
            .unwrap(),
        _ => model.clone(),
    };
    assert_eq!(back, expected, "{format}:\n{text}");
}

fn check(model: &Model, toml: &str, json: &str, csv: &str) {
    assert_eq!(to_toml_string(model), toml);
    assert_eq!(to_json_string(model), json);
    assert_eq!(to_csv_string(model).unwrap(), csv);
    reads_back(model, Format::Toml, toml);
    reads_back(model, Format::Json, json);
    reads_back(model, Format::Csv, csv);
}

#[test]
fn write_bezier() {
    check(
        &bezier(),
        r#"kind = "bezier"
name = "Line \"one\""
description = "two points\nsecond line"
membership = "neutrosophic"
degree = 1

[[control_points]]
name = "C0"
x = 1.0
y = 3.0
truth = 0.3
indeterminacy = 0.6
falsity = 0.1

[[control_points]]
name = "C1"
x = 9.0
y = 5.0
truth = 0.2
indeterminacy = 0.4
falsity = 0.4
"#,
        r#"{
  "kind": "bezier",
  "name": "Line \"one\"",
  "description": "two points\nsecond line",
  "membership": "neutrosophic",
  "degree": 1,
  "control_points": [
    { "name": "C0", "x": 1.0, "y": 3.0, "truth": 0.3, "indeterminacy": 0.6, "falsity": 0.1 },
    { "name": "C1", "x": 9.0, "y": 5.0, "truth": 0.2, "indeterminacy": 0.4, "falsity": 0.4 }
  ]
}
"#,
        "name,x,y,truth,indeterminacy,falsity\nC0,1.0,3.0,0.3,0.6,0.1\nC1,9.0,5.0,0.2,0.4,0.4\n",
    );
}

#[test]
fn write_bspline_intuitionistic_with_extreme_numbers() {
    check(
        &bspline(),
        r#"kind = "bspline"
membership = "intuitionistic"
degree = 1
knots = [0.0, 0.0, 0.25, 1.0, 1.0]

[[control_points]]
x = 0.0
y = -0.0
z = 1e-300
truth = 0.5
falsity = 0.25

[[control_points]]
x = 0.30000000000000004
y = 0.3333333333333333
z = 2.0
truth = 0.30000000000000004
falsity = 0.5

[[control_points]]
x = 1e16
y = -1.7976931348623157e308
z = 5e-324
truth = 1.0
falsity = 0.0
"#,
        r#"{
  "kind": "bspline",
  "membership": "intuitionistic",
  "degree": 1,
  "knots": [0.0, 0.0, 0.25, 1.0, 1.0],
  "control_points": [
    { "x": 0.0, "y": -0.0, "z": 1e-300, "truth": 0.5, "falsity": 0.25 },
    { "x": 0.30000000000000004, "y": 0.3333333333333333, "z": 2.0, "truth": 0.30000000000000004, "falsity": 0.5 },
    { "x": 1e16, "y": -1.7976931348623157e308, "z": 5e-324, "truth": 1.0, "falsity": 0.0 }
  ]
}
"#,
        "x,y,z,truth,falsity\n0.0,-0.0,1e-300,0.5,0.25\n\
         0.30000000000000004,0.3333333333333333,2.0,0.30000000000000004,0.5\n\
         1e16,-1.7976931348623157e308,5e-324,1.0,0.0\n",
    );
}

#[test]
fn write_nurbs_fuzzy_with_some_names() {
    check(
        &nurbs(),
        r#"kind = "nurbs"
membership = "fuzzy"
degree = 2
knots = [0.0, 0.0, 0.0, 1.0, 1.0, 1.0]

[[control_points]]
name = "a"
x = 0.0
y = 0.0
truth = 0.25
weight = 1.0

[[control_points]]
x = 1.0
y = 1.0
truth = 1.0
weight = 0.5

[[control_points]]
name = "c"
x = 2.0
y = 0.0
truth = 0.0
weight = 2.0
"#,
        r#"{
  "kind": "nurbs",
  "membership": "fuzzy",
  "degree": 2,
  "knots": [0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
  "control_points": [
    { "name": "a", "x": 0.0, "y": 0.0, "truth": 0.25, "weight": 1.0 },
    { "x": 1.0, "y": 1.0, "truth": 1.0, "weight": 0.5 },
    { "name": "c", "x": 2.0, "y": 0.0, "truth": 0.0, "weight": 2.0 }
  ]
}
"#,
        "name,x,y,truth,weight\na,0.0,0.0,0.25,1.0\n,1.0,1.0,1.0,0.5\nc,2.0,0.0,0.0,2.0\n",
    );
}

/// The four control points of [`grid`]`(2, 2)` as TOML tables.
const GRID_TOML: &str = r#"
[[control_points]]
x = 0.0
y = 0.0
z = 0.0
truth = 0.5
indeterminacy = 0.25
falsity = 0.125

[[control_points]]
x = 0.0
y = 1.0
z = 0.0
truth = 0.5
indeterminacy = 0.25
falsity = 0.125

[[control_points]]
x = 1.0
y = 0.0
z = 0.0
truth = 0.5
indeterminacy = 0.25
falsity = 0.125

[[control_points]]
x = 1.0
y = 1.0
z = 1.0
truth = 0.5
indeterminacy = 0.25
falsity = 0.125
"#;

const GRID_JSON: &str = r#"  "control_points": [
    { "x": 0.0, "y": 0.0, "z": 0.0, "truth": 0.5, "indeterminacy": 0.25, "falsity": 0.125 },
    { "x": 0.0, "y": 1.0, "z": 0.0, "truth": 0.5, "indeterminacy": 0.25, "falsity": 0.125 },
    { "x": 1.0, "y": 0.0, "z": 0.0, "truth": 0.5, "indeterminacy": 0.25, "falsity": 0.125 },
    { "x": 1.0, "y": 1.0, "z": 1.0, "truth": 0.5, "indeterminacy": 0.25, "falsity": 0.125 }
  ]
}
"#;

const GRID_CSV: &str = "x,y,z,truth,indeterminacy,falsity\n\
    0.0,0.0,0.0,0.5,0.25,0.125\n0.0,1.0,0.0,0.5,0.25,0.125\n\
    1.0,0.0,0.0,0.5,0.25,0.125\n1.0,1.0,1.0,0.5,0.25,0.125\n";

#[test]
fn write_bezier_surface() {
    check(
        &bezier_surface(),
        &format!(
            "kind = \"bezier-surface\"\nname = \"patch\"\nmembership = \"neutrosophic\"\n\
             rows = 2\ncols = 2\ndegree_u = 1\ndegree_v = 1\n{GRID_TOML}"
        ),
        &format!(
            "{{\n  \"kind\": \"bezier-surface\",\n  \"name\": \"patch\",\n  \"membership\": \
             \"neutrosophic\",\n  \"rows\": 2,\n  \"cols\": 2,\n  \"degree_u\": 1,\n  \
             \"degree_v\": 1,\n{GRID_JSON}"
        ),
        GRID_CSV,
    );
}

#[test]
fn write_bspline_surface() {
    check(
        &bspline_surface(),
        &format!(
            "kind = \"bspline-surface\"\nmembership = \"neutrosophic\"\nrows = 2\ncols = 2\n\
             degree_u = 1\ndegree_v = 1\nknots_u = [0.0, 0.0, 1.0, 1.0]\n\
             knots_v = [0.0, 1.0, 2.0, 3.0]\n{GRID_TOML}"
        ),
        &format!(
            "{{\n  \"kind\": \"bspline-surface\",\n  \"membership\": \"neutrosophic\",\n  \
             \"rows\": 2,\n  \"cols\": 2,\n  \"degree_u\": 1,\n  \"degree_v\": 1,\n  \
             \"knots_u\": [0.0, 0.0, 1.0, 1.0],\n  \"knots_v\": [0.0, 1.0, 2.0, 3.0],\n{GRID_JSON}"
        ),
        GRID_CSV,
    );
}

#[test]
fn write_nurbs_surface() {
    check(
        &nurbs_surface(),
        r#"kind = "nurbs-surface"
description = "one row"
membership = "neutrosophic"
rows = 1
cols = 2
degree_u = 0
degree_v = 1
knots_u = [0.0, 1.0]
knots_v = [0.0, 0.0, 1.0, 1.0]

[[control_points]]
x = 0.0
y = 0.0
z = 0.0
truth = 0.5
indeterminacy = 0.25
falsity = 0.125
weight = 1.0

[[control_points]]
x = 0.0
y = 1.0
z = 0.0
truth = 0.5
indeterminacy = 0.25
falsity = 0.125
weight = 4.0
"#,
        r#"{
  "kind": "nurbs-surface",
  "description": "one row",
  "membership": "neutrosophic",
  "rows": 1,
  "cols": 2,
  "degree_u": 0,
  "degree_v": 1,
  "knots_u": [0.0, 1.0],
  "knots_v": [0.0, 0.0, 1.0, 1.0],
  "control_points": [
    { "x": 0.0, "y": 0.0, "z": 0.0, "truth": 0.5, "indeterminacy": 0.25, "falsity": 0.125, "weight": 1.0 },
    { "x": 0.0, "y": 1.0, "z": 0.0, "truth": 0.5, "indeterminacy": 0.25, "falsity": 0.125, "weight": 4.0 }
  ]
}
"#,
        "x,y,z,truth,indeterminacy,falsity,weight\n\
         0.0,0.0,0.0,0.5,0.25,0.125,1.0\n0.0,1.0,0.0,0.5,0.25,0.125,4.0\n",
    );
}

#[test]
fn csv_options_name_what_csv_cannot_hold() {
    let options = nurbs_surface().csv_read_options();
    assert_eq!(options.rows, Some(1));
    assert_eq!(options.degree_v, Some(1));
    assert_eq!(
        options.knots_u,
        Some(neutrospline_io::KnotSpec::Explicit(vec![0.0, 1.0]))
    );
    assert_eq!(options.membership, Some(Family::Neutrosophic));
    // Without them the CSV table is a Bézier curve, or an error.
    let csv = to_csv_string(&bspline()).unwrap();
    let e = parse(
        "m.csv",
        Format::Csv,
        csv.as_bytes(),
        &ReadOptions::default(),
    )
    .unwrap_err();
    assert_eq!(
        e.to_string(),
        "m.csv:1: missing column `indeterminacy` (neutrosophic rule requires it; truth and falsity alone are an intuitionistic table (--membership intuitionistic, indeterminacy 1 - T - F), truth alone a fuzzy one (--membership fuzzy))"
    );
}

#[test]
fn save_chooses_the_format_by_extension_and_replaces_atomically() {
    let dir = tempfile::tempdir().unwrap();
    let model = bezier();
    for format in Format::ALL {
        let path = dir.path().join(format!("model.{}", format.extension()));
        std::fs::write(&path, "old").unwrap();
        save(&model, &path).unwrap();
        let text = std::fs::read_to_string(&path).unwrap();
        assert_eq!(text, neutrospline_io::to_string(&model, format).unwrap());
        let back = neutrospline_io::load(&path, &model.csv_read_options()).unwrap();
        let expected = match format {
            Format::Csv => bezier_without_name(),
            _ => model.clone(),
        };
        assert_eq!(back, expected);
    }
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 3);

    // Errors leave the old file and no temporary file.
    let path = dir.path().join("model.txt");
    let e = save(&model, &path).unwrap_err();
    assert!(matches!(e, WriteError::Format(_)), "{e}");
    let path = dir.path().join("model.csv");
    let padded = bezier().with_point_names([Some(" C0"), None]).unwrap();
    assert_eq!(
        save(&padded, &path).unwrap_err().to_string(),
        format!(
            "{}: cannot write CSV: control point 0: the name \" C0\" has leading or trailing \
             whitespace, which a CSV cell loses (write TOML or JSON to keep it)",
            path.display()
        )
    );
    assert_eq!(
        std::fs::read_to_string(&path).unwrap(),
        to_csv_string(&model).unwrap()
    );
    let e = save(&model, dir.path().join("missing/model.toml")).unwrap_err();
    assert!(
        e.to_string().contains("missing/model.toml: cannot write: "),
        "{e}"
    );
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 3);
}

fn bezier_without_name() -> Model {
    Model::new(bezier().into_shape())
        .with_point_names([Some("C0"), Some("C1")])
        .unwrap()
}

/// A spatial NURBS with spreads: symmetric, asymmetric and none.
fn fuzzy_nurbs() -> Model {
    use neutrospline::Spread;
    let curve = Nurbs::new(
        vec![
            point([0.0, 0.0, 0.0], d(1.0, 0.0, 0.0)),
            point([1.0, 2.0, 0.0], d(0.5, 0.5, 0.0)),
        ],
        vec![1.0, 2.0],
        knots(&[0.0, 0.0, 1.0, 1.0], 1, 2),
    )
    .unwrap();
    Model::new(AnyCurve::Nurbs(curve))
        .with_spreads(vec![
            Spread::new([0.5, 0.0, 0.0], [0.5, 0.0, 0.0]),
            Spread::new([0.25, 1.0, 0.0], [0.25, 3.0, 0.0]),
        ])
        .unwrap()
}

#[test]
fn write_spreads_symmetric_or_asymmetric() {
    let model = fuzzy_nurbs();
    let toml = to_toml_string(&model);
    assert!(
        toml.ends_with(
            "weight = 2.0\nspread_x = 0.25\nspread_y_left = 1.0\nspread_y_right = 3.0\n"
        ),
        "{toml}"
    );
    assert!(toml.contains("weight = 1.0\nspread_x = 0.5\n\n"), "{toml}");
    let json = to_json_string(&model);
    assert!(
        json.contains(r#""weight": 1.0, "spread_x": 0.5 }"#),
        "{json}"
    );
    let csv = to_csv_string(&model).unwrap();
    assert_eq!(
        csv,
        "x,y,z,truth,indeterminacy,falsity,weight,spread_x,spread_y_left,spread_y_right\n\
         0.0,0.0,0.0,1.0,0.0,0.0,1.0,0.5,0.0,0.0\n\
         1.0,2.0,0.0,0.5,0.5,0.0,2.0,0.25,1.0,3.0\n"
    );
    for (format, text) in [(Format::Toml, &toml), (Format::Json, &json)] {
        let back = parse("m", format, text.as_bytes(), &ReadOptions::default()).unwrap();
        assert_eq!(back, model);
        assert_eq!(back.spreads(), model.spreads());
    }
    let back = parse("m", Format::Csv, csv.as_bytes(), &model.csv_read_options()).unwrap();
    assert_eq!(back, model);
    // Without spreads, nothing changes: no spread key or column.
    let crisp = Model::new(model.shape().clone());
    assert_eq!(crisp.spreads(), None);
    assert!(!to_toml_string(&crisp).contains("spread"));
    assert!(!to_csv_string(&crisp).unwrap().contains("spread"));
}

#[test]
fn model_spreads_are_checked() {
    use neutrospline::Spread;
    let model = fuzzy_nurbs();
    let e = |spreads: Vec<Spread<3>>| model.clone().with_spreads(spreads).unwrap_err().to_string();
    assert_eq!(
        e(vec![Spread::ZERO]),
        "1 spreads for 2 control points (give one spread per control point)"
    );
    assert_eq!(
        e(vec![Spread::ZERO, Spread::symmetric([0.0, -1.0, 0.0])]),
        "control point 1: left spread of y = -1 is not a finite number >= 0"
    );
    assert_eq!(
        bezier()
            .with_spreads(vec![Spread::ZERO, Spread::symmetric([0.0, 0.0, 1.0])])
            .unwrap_err()
            .to_string(),
        "control point 1: a planar curve has no z to spread"
    );
    assert_eq!(
        bezier_surface()
            .with_spreads(vec![Spread::symmetric([1.0, 0.0, 0.0]); 4])
            .unwrap_err()
            .to_string(),
        "control point 0: spreads apply to curves only, not to surfaces"
    );
}
