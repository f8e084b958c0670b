use neutrospline::{AnyCurve, Bezier, ControlPoint, CurveKind, Degrees};
use neutrospline_io::Kind;

use std::path::PathBuf;

use proptest::prelude::*;

use neutrospline::{Evaluate, Family};

use super::{parse_dxf, Limits, Model};
use crate::report::ImportOptions;
use crate::{export, ExportFormat, ExportOptions};
use neutrospline_io::{load, ReadOptions};

fn example(name: &str) -> Model {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples")
        .join(name);
    load(&path, &ReadOptions::default()).unwrap()
}

fn defaults() -> Degrees {
    Degrees::new(0.7, 0.2, 0.1).unwrap()
}

/// A DXF text with `entities` in its ENTITIES section, whose first group is on line 5.
fn dxf(entities: &str) -> String {
    format!("  0\nSECTION\n  2\nENTITIES\n{entities}  0\nENDSEC\n  0\nEOF\n")
}

/// A quadratic spline in the plane through three control points, without extended data.
const QUADRATIC: &str = concat!(
    "  0\nSPLINE\n  8\n0\n 70\n8\n 71\n2\n 72\n6\n 73\n3\n",
    " 40\n0\n 40\n0\n 40\n0\n 40\n1\n 40\n1\n 40\n1\n",
    " 10\n0\n 20\n0\n 30\n0\n 10\n1\n 20\n2\n 30\n0\n 10\n2\n 20\n0\n 30\n0\n",
);

fn message(text: &str) -> String {
    parse_dxf(
        "f.dxf",
        text.as_bytes(),
        &ImportOptions::new(defaults()),
        &Limits::default(),
    )
    .map(|i| i.models)
    .unwrap_err()
    .to_string()
}

#[test]
fn dxf_export_then_import_gives_back_every_example_curve() {
    for file in [
        "example1.toml",
        "helix3d.toml",
        "bspline.toml",
        "nurbs-circle.toml",
    ] {
        let model = example(file);
        let bytes = export(&model, ExportFormat::Dxf, &ExportOptions::new()).unwrap();
        let back = parse_dxf(
            file,
            &bytes,
            &ImportOptions::new(defaults()),
            &Limits::default(),
        )
        .map(|i| i.models)
        .unwrap();
        assert_eq!(back, [model], "{file}");
    }
    // Family, names with escapes and a long description survive too.
    let model = Model::new(AnyCurve::Bezier(neutrospline::example1()))
        .with_name("caf\u{e9} ^ \\U+0041 \u{1F600}")
        .with_description("d".repeat(700))
        .with_point_names([None, Some("a\nb"), Some(""), Some(" C3 ")])
        .unwrap();
    let fuzzy = Model::new(AnyCurve::Bezier(
        Bezier::new(vec![
            ControlPoint::new([0.0, 0.0, 1.0], Degrees::fuzzy(0.1).unwrap()),
            ControlPoint::new(
                [1.0, 1.0, 1.0],
                Degrees::fuzzy(0.30000000000000004).unwrap(),
            ),
        ])
        .unwrap(),
    ))
    .with_membership(Family::Fuzzy)
    .unwrap();
    for model in [model, fuzzy] {
        let bytes = export(&model, ExportFormat::Dxf, &ExportOptions::new()).unwrap();
        let back = parse_dxf(
            "m.dxf",
            &bytes,
            &ImportOptions::new(defaults()),
            &Limits::default(),
        )
        .map(|i| i.models)
        .unwrap();
        assert_eq!(back, [model]);
    }
}

#[test]
fn dxf_spline_without_extended_data_takes_the_default_degrees() {
    let models = parse_dxf(
        "q.dxf",
        dxf(QUADRATIC).as_bytes(),
        &ImportOptions::new(defaults()),
        &Limits::default(),
    )
    .unwrap()
    .models;
    assert_eq!(models.len(), 1);
    let model = &models[0];
    assert_eq!(model.kind(), Kind::Curve(CurveKind::BSpline));
    assert_eq!(
        (model.name(), model.membership()),
        (None, Family::Neutrosophic)
    );
    let Some(neutrospline::DynCurve::Planar(curve)) = model.shape().curve() else {
        panic!("a plane curve")
    };
    // (P0 + 2 P1 + P2) / 4 at t = 0.5, with the default degrees everywhere.
    let p = curve.evaluate(0.5).unwrap();
    assert_eq!(p.position, [1.0, 1.0]);
    assert_eq!(p.degrees, defaults());
    // CRLF line ends, a weight per point and a second spline in 3-D.
    let weighted = QUADRATIC.replace(" 10\n0\n", " 41\n1\n 41\n0.5\n 41\n1\n 10\n0\n");
    let spatial = QUADRATIC.replace(" 30\n0\n 10\n2\n", " 30\n5\n 10\n2\n");
    let text = dxf(&format!("  0\nTEXT\n  8\n0\n{weighted}{spatial}")).replace('\n', "\r\n");
    let models = parse_dxf(
        "w.dxf",
        text.as_bytes(),
        &ImportOptions::new(defaults()),
        &Limits::default(),
    )
    .map(|i| i.models)
    .unwrap();
    assert_eq!(models.len(), 2);
    assert_eq!(models[0].kind(), Kind::Curve(CurveKind::Nurbs));
    assert_eq!(models[0].shape().weights(), Some(&[1.0, 0.5, 1.0][..]));
    assert_eq!(
        (models[1].kind(), models[1].shape().dimension()),
        (Kind::Curve(CurveKind::BSpline), 3)
    );
}

/// Inkscape's R12 export (dxf2gcode's `Inkspace_dxf_export_kreis_splines.dxf`) ends with a
/// blank line after `0 EOF`; DOS programs end a file with 0x1A. Both read as the file
/// without them, curve for curve.
#[test]
fn dxf_blank_lines_and_dos_end_bytes_after_the_end_are_ignored() {
    let plain = parse_dxf(
        "f.dxf",
        dxf(QUADRATIC).as_bytes(),
        &ImportOptions::new(defaults()),
        &Limits::default(),
    )
    .unwrap()
    .models;
    assert_eq!(plain.len(), 1);
    for ending in ["\n", "\n\n  \n", "\u{1a}", "\r\n\u{1a}", "\n\u{1a}\n"] {
        let text = format!("{}{ending}", dxf(QUADRATIC));
        let read = parse_dxf(
            "f.dxf",
            text.as_bytes(),
            &ImportOptions::new(defaults()),
            &Limits::default(),
        )
        .map(|i| i.models);
        assert_eq!(
            read.as_ref().ok(),
            Some(&plain),
            "ending {ending:?}: {read:?}"
        );
    }
    // Without `0 EOF`, a final 0x1A still ends the text.
    let cut = dxf(QUADRATIC).replace("  0\nEOF\n", "\u{1a}");
    let read = parse_dxf(
        "f.dxf",
        cut.as_bytes(),
        &ImportOptions::new(defaults()),
        &Limits::default(),
    )
    .map(|i| i.models);
    assert_eq!(read.as_ref().ok(), Some(&plain), "{read:?}");
}

#[test]
fn dxf_errors_are_located() {
    assert_eq!(
        message(&dxf(&QUADRATIC.replace(" 71\n2\n", ""))),
        "f.dxf:5: the SPLINE has no degree (group code 71)"
    );
    assert_eq!(
        message(&dxf(&QUADRATIC.replace(" 72\n6\n", " 72\n7\n"))),
        "f.dxf:13: the number of knots (group code 72) is 7, but the SPLINE has 6 knots (group code 40)"
    );
    assert_eq!(
        message(&dxf(&QUADRATIC.replace(" 72\n6\n 73\n3\n", " 72\n6\n 73\n2\n"))),
        "f.dxf:15: the number of control points (group code 73) is 2, but the SPLINE has 3 (group code 10)"
    );
    assert_eq!(
        message(&dxf(&QUADRATIC.replace(" 71\n2\n", " 71\n1\n"))),
        "f.dxf:13: knot vector has 6 knots, expected 5 (number of control points + degree + 1)"
    );
    assert_eq!(
        message(&dxf(&QUADRATIC.replacen(" 40\n1\n", " 40\nx\n", 1))),
        "f.dxf:23: knot (group code 40) = `x` is not a finite number"
    );
    assert_eq!(
        message(&dxf("  0\nSPLINE\n 71\n3\n 72\n0\n 73\n0\n 74\n4\n 11\n0\n 21\n0\n")),
        "f.dxf:19: the file has no curve to import (skipped 1 SPLINE (a curve this importer cannot read exactly))"
    );
    assert_eq!(
        message(&dxf(&QUADRATIC.replace(" 70\n8\n", " 70\n12\n"))),
        "f.dxf:9: flags (group code 70) = 12 say the SPLINE is rational (4), but it has no weights (group code 41)"
    );
    assert_eq!(
        message(&dxf("  0\nTEXT\n  8\n0\n  0\nCIRCLE\n 10\n0\n 20\n0\n 40\n0\n")),
        "f.dxf:17: the file has no curve to import (skipped 1 TEXT (not a curve); empty: 1 CIRCLE (draws nothing))"
    );
    assert_eq!(
        message("  0\nSECTION\n  2\nHEADER\n  0\nENDSEC\n"),
        "f.dxf: the file has no ENTITIES section (a DXF file holds its curves there)"
    );
    assert_eq!(
        message(&format!("  0\nSECTION\n  2\nENTITIES\n{QUADRATIC}")),
        "f.dxf: the ENTITIES section has no end (`0 ENDSEC`): the file is cut short"
    );
    assert_eq!(
        message("  0\nSECTION\n  2\n"),
        "f.dxf:3: group code `2` has no value (the file ends)"
    );
    assert_eq!(
        message("  0\nSECTION\nxx\nENTITIES\n"),
        "f.dxf:3: group code `xx` is not an integer from 0 to 1071"
    );
    // The first bytes of ezdxf's and netDxf's binary test files.
    assert_eq!(
        message("AutoCAD Binary DXF\r\n\u{1a}\0\0\0SECTION\0"),
        "f.dxf: the file has no ENTITIES section (a DXF file holds its curves there)"
    );
    assert_eq!(
        message("AutoCAD Binary DXF\r\n\u{1a}\0\0\0SECTION\0\x0a\0"),
        "f.dxf:3: the binary group 2 is cut short (the file ends)"
    );
    // Extended data that contradicts the entity.
    let model = example("example1.toml");
    let text = String::from_utf8(export(&model, ExportFormat::Dxf, &ExportOptions::new()).unwrap())
        .unwrap();
    // The first control point's z, after the SPLINE's normal (210, 220, 230).
    let at = text.find("\n230\n1\n").unwrap();
    let moved = format!(
        "{}{}",
        &text[..at],
        text[at..].replacen(" 30\n0\n", " 30\n1\n", 1)
    );
    let error = parse_dxf(
        "e.dxf",
        moved.as_bytes(),
        &ImportOptions::new(defaults()),
        &Limits::default(),
    )
    .map(|i| i.models)
    .unwrap_err()
    .to_string();
    assert!(
        error.ends_with(
            ": the extended data says the curve is 2-D, but a control point has z other than 0"
        ),
        "{error}"
    );
    let wrong = text.replacen("1040\n0.3\n", "1040\n1.5\n", 1);
    let error = parse_dxf(
        "e.dxf",
        wrong.as_bytes(),
        &ImportOptions::new(defaults()),
        &Limits::default(),
    )
    .map(|i| i.models)
    .unwrap_err()
    .to_string();
    assert!(
        error.contains(": NEUTROSPLINE extended data: truth = 1.5 is outside [0, 1]"),
        "{error}"
    );
}

proptest! {
    /// Any groups in a SPLINE entity (and in its extended data) give models or a message,
    /// never a panic.
    #[test]
    fn dxf_never_panics(
        groups in proptest::collection::vec(
            (
                prop_oneof![Just("10"), Just("20"), Just("30"), Just("40"), Just("41"),
                            Just("70"), Just("71"), Just("72"), Just("73"), Just("74"),
                            Just("11"), Just("1001"), Just("1000"), Just("1040"),
                            Just("1070"), Just("1071"), Just("0"), Just("x")],
                prop_oneof![Just("0".to_owned()), Just("1".to_owned()), Just("3".to_owned()),
                            Just("-1".to_owned()), Just("NEUTROSPLINE".to_owned()),
                            Just("neutrospline 1".to_owned()), Just("kind".to_owned()),
                            Just("degrees".to_owned()), Just("bezier".to_owned()),
                            Just("SPLINE".to_owned()), "[0-9.e-]{1,6}"],
            ),
            0..40,
        ),
    ) {
        let body: String = groups.iter().map(|(c, v)| format!("{c}\n{v}\n")).collect();
        let text = dxf(&format!("  0\nSPLINE\n{body}"));
        let _ = parse_dxf("p.dxf", text.as_bytes(), &ImportOptions::new(defaults()), &Limits::default()).map(|i| i.models);
        let with_quadratic = dxf(&format!("{QUADRATIC}1001\nNEUTROSPLINE\n{body}"));
        let _ = parse_dxf("p.dxf", with_quadratic.as_bytes(), &ImportOptions::new(defaults()), &Limits::default()).map(|i| i.models);
    }
}

/// The import of `text` with the default options.
fn import(text: &str) -> crate::Import {
    parse_dxf(
        "t.dxf",
        text.as_bytes(),
        &ImportOptions::new(defaults()),
        &Limits::default(),
    )
    .unwrap()
}

/// The point at `t` of a model's curve, in space (z = 0 for a plane curve).
fn at(model: &Model, t: f64) -> [f64; 3] {
    match model.shape().curve() {
        Some(neutrospline::DynCurve::Planar(c)) => {
            let p = c.evaluate(t).unwrap().position;
            [p[0], p[1], 0.0]
        }
        Some(neutrospline::DynCurve::Spatial(c)) => c.evaluate(t).unwrap().position,
        None => panic!("a curve"),
    }
}

/// The ends of a model's parameter domain.
fn domain(model: &Model) -> (f64, f64) {
    let d = model.shape().curve_domain().unwrap();
    (d.start, d.end)
}

fn close(a: [f64; 3], b: [f64; 3]) -> bool {
    a.iter()
        .zip(&b)
        .all(|(x, y)| (x - y).abs() <= 1e-12 * (1.0 + y.abs()))
}

#[test]
fn dxf_line_arc_circle_are_exact() {
    let text = dxf(concat!(
        "  0\nLINE\n  8\n0\n 10\n1\n 20\n2\n 30\n0\n 11\n4\n 21\n6\n 31\n0\n",
        "  0\nLINE\n  8\n0\n 10\n0\n 20\n0\n 30\n1\n 11\n1\n 21\n0\n 31\n1\n",
        // An arc from 30° to 150° of radius 2 about (1, 1): its midpoint is (1, 3).
        "  0\nARC\n  8\n0\n 10\n1\n 20\n1\n 30\n0\n 40\n2\n 50\n30\n 51\n150\n",
        "  0\nCIRCLE\n  8\n0\n 10\n0\n 20\n0\n 30\n0\n 40\n3\n",
        // Through 0°: from 315° to 45°, midpoint (r, 0).
        "  0\nARC\n  8\n0\n 10\n0\n 20\n0\n 40\n1\n 50\n315\n 51\n45\n",
    ));
    let import = import(&text);
    let m = &import.models;
    assert_eq!(m.len(), 5);
    assert_eq!(
        import.report.summary(),
        "imported 5 curves (2 LINE, 2 ARC, 1 CIRCLE)"
    );
    assert_eq!(m[0].kind(), Kind::Curve(CurveKind::Bezier));
    assert_eq!(m[0].shape().dimension(), 2);
    assert_eq!(at(&m[0], 0.5), [2.5, 4.0, 0.0]);
    assert_eq!(m[1].shape().dimension(), 3);
    assert_eq!(at(&m[1], 1.0), [1.0, 0.0, 1.0]);
    // 120° is two pieces of 60°: the midpoint is the knot 1 between them.
    assert_eq!(m[2].kind(), Kind::Curve(CurveKind::Nurbs));
    assert_eq!(domain(&m[2]), (0.0, 2.0));
    assert!(
        close(at(&m[2], 1.0), [1.0, 3.0, 0.0]),
        "{:?}",
        at(&m[2], 1.0)
    );
    assert!(close(at(&m[2], 0.0), [1.0 + 3f64.sqrt(), 2.0, 0.0]));
    // A point within a piece is on the circle too (a rational quadratic is exact).
    for t in [0.25, 0.6, 1.7] {
        let p = at(&m[2], t);
        let r = ((p[0] - 1.0).powi(2) + (p[1] - 1.0).powi(2)).sqrt();
        assert!((r - 2.0).abs() < 1e-14, "{t}: {r}");
    }
    // The circle: 4 quarters, control points exact, weights 1, √2/2, 1, ...
    assert_eq!(m[3].shape().control_count(), 9);
    assert_eq!(domain(&m[3]), (0.0, 4.0));
    let h = std::f64::consts::FRAC_1_SQRT_2;
    assert_eq!(
        m[3].shape().weights().unwrap(),
        &[1.0, h, 1.0, h, 1.0, h, 1.0, h, 1.0]
    );
    for (t, p) in [
        (0.0, [3.0, 0.0]),
        (1.0, [0.0, 3.0]),
        (2.0, [-3.0, 0.0]),
        (3.0, [0.0, -3.0]),
    ] {
        assert_eq!(at(&m[3], t), [p[0], p[1], 0.0], "t = {t}");
    }
    let p = at(&m[3], 0.5);
    assert!(close(p, [3.0 * h, 3.0 * h, 0.0]), "{p:?}");
    assert!(close(at(&m[4], 0.5), [1.0, 0.0, 0.0]));
}

#[test]
fn dxf_bulges_are_exact_arcs() {
    // A semicircle of bulge 1 from (0, 0) to (2, 0): counter-clockwise about (1, 0), so
    // through (1, -1); then a line back up, closed (flag 1) with a bulge -1 (clockwise).
    let text = dxf(concat!(
        "  0\nLWPOLYLINE\n  8\n0\n 90\n3\n 70\n1\n 38\n0\n",
        " 10\n0\n 20\n0\n 42\n1\n 10\n2\n 20\n0\n 10\n2\n 20\n2\n 42\n-0.5\n",
        "  0\nLWPOLYLINE\n  8\n0\n 90\n2\n 38\n5\n 10\n0\n 20\n0\n 10\n3\n 20\n4\n",
    ));
    let import = import(&text);
    let m = &import.models;
    assert_eq!(m.len(), 2);
    // Pieces: two quarters of the semicircle, the line, then the closing arc of bulge -0.5
    // (included angle 4 atan 0.5 = 106.26°: two pieces).
    assert_eq!(domain(&m[0]), (0.0, 5.0));
    assert!(
        close(at(&m[0], 1.0), [1.0, -1.0, 0.0]),
        "{:?}",
        at(&m[0], 1.0)
    );
    assert_eq!(at(&m[0], 2.0), [2.0, 0.0, 0.0]);
    assert_eq!(at(&m[0], 3.0), [2.0, 2.0, 0.0]);
    assert_eq!(at(&m[0], 5.0), [0.0, 0.0, 0.0]);
    // The closing arc from (2, 2) to (0, 0), clockwise with bulge -0.5: its sagitta is
    // |c| b / 2 = √8 / 4 on the right of the travel... the centre (p0 + p1)/2 - n (1 - b²)/(4b)
    // with n = (c_y, -c_x) = (-2, 2): (1, 1) - (-2, 2) (0.75 / -2) = (1 - 0.75, 1 + 0.75).
    let centre = [0.25, 1.75];
    let radius = ((2.0f64 - 0.25).powi(2) + (2.0f64 - 1.75).powi(2)).sqrt();
    for t in [3.2, 3.5, 4.0, 4.9] {
        let p = at(&m[0], t);
        let r = ((p[0] - centre[0]).powi(2) + (p[1] - centre[1]).powi(2)).sqrt();
        assert!((r - radius).abs() < 1e-14, "{t}: {r} {radius}");
    }
    // Its middle (the knot 4) is the arc's midpoint: the chord midpoint moved by the
    // sagitta b |c| / 2 along n / |n|, n = (-2, 2): (1, 1) + (-0.5)(-2, 2)/2 = (1.5, 0.5).
    assert!(
        close(at(&m[0], 4.0), [1.5, 0.5, 0.0]),
        "{:?}",
        at(&m[0], 4.0)
    );
    // Elevation 38 = 5: a line at z = 5 in space.
    assert_eq!(m[1].shape().dimension(), 3);
    assert_eq!(at(&m[1], 1.0), [3.0, 4.0, 5.0]);
}

#[test]
fn dxf_ellipse_is_exact_at_its_parameters() {
    // Centre (1, 2), major axis (3, 0), ratio 0.5: (1 + 3 cos u, 2 + 1.5 sin u).
    let full = import(&dxf(
        "  0\nELLIPSE\n  8\n0\n 10\n1\n 20\n2\n 30\n0\n 11\n3\n 21\n0\n 31\n0\n 40\n0.5\n 41\n0\n 42\n6.283185307179586\n",
    ));
    let m = &full.models[0];
    assert_eq!(domain(m), (0.0, 4.0));
    assert_eq!(at(m, 1.0), [1.0, 3.5, 0.0]);
    assert_eq!(at(m, 2.0), [-2.0, 2.0, 0.0]);
    // A rational quadratic piece of 90° is at u = 45° at its middle parameter.
    let h = std::f64::consts::FRAC_1_SQRT_2;
    assert!(close(at(m, 0.5), [1.0 + 3.0 * h, 2.0 + 1.5 * h, 0.0]));
    // From u = π/2 to π/6 the long way round (a turn further), with the normal (0, 0, -1):
    // the minor axis is r (N × M) = 0.5 (0, 0, -1) × (3, 0, 0) = (0, -1.5, 0).
    let part = import(&dxf(
        "  0\nELLIPSE\n  8\n0\n 10\n0\n 20\n0\n 30\n0\n 11\n3\n 21\n0\n 31\n0\n 210\n0\n 220\n0\n 230\n-1\n 40\n0.5\n 41\n1.5707963267948966\n 42\n0.5235987755982988\n",
    ));
    let m = &part.models[0];
    // A sweep of 300°: 4 pieces of 75°.
    assert_eq!(domain(m), (0.0, 4.0));
    assert!(close(at(m, 0.0), [0.0, -1.5, 0.0]));
    let end = at(m, 4.0);
    assert!(close(end, [3.0 * 3f64.sqrt() / 2.0, -0.75, 0.0]), "{end:?}");
    // u = 90° + 150° = 240° at the middle.
    let mid = at(m, 2.0);
    assert!(close(mid, [-1.5, 1.5 * 3f64.sqrt() / 2.0, 0.0]), "{mid:?}");
}

#[test]
fn dxf_extrusion_minus_z_mirrors() {
    // A circle about (1, 2) with extrusion (0, 0, -1): OCS x is world -x, so its centre is
    // at (-1, 2) in the world, and an ARC from 0° to 90° of radius 1 about the OCS origin
    // starts at the world (-1, 0) and ends at (0, 1): clockwise as seen from +z.
    let text = dxf(concat!(
        "  0\nCIRCLE\n  8\n0\n 10\n1\n 20\n2\n 30\n0\n 40\n1\n210\n0\n220\n0\n230\n-1\n",
        "  0\nARC\n  8\n0\n 10\n0\n 20\n0\n 30\n0\n 40\n1\n 50\n0\n 51\n90\n210\n0\n220\n0\n230\n-1\n",
        "  0\nLWPOLYLINE\n  8\n0\n 38\n2\n 10\n1\n 20\n0\n 10\n3\n 20\n0\n210\n0\n220\n0\n230\n-1\n",
    ));
    let m = import(&text).models;
    assert_eq!(at(&m[0], 0.0), [-2.0, 2.0, 0.0]);
    assert_eq!(at(&m[0], 1.0), [-1.0, 3.0, 0.0]);
    assert_eq!(at(&m[1], 0.0), [-1.0, 0.0, 0.0]);
    assert_eq!(at(&m[1], 1.0), [0.0, 1.0, 0.0]);
    // The elevation 2 along (0, 0, -1) is z = -2.
    assert_eq!(at(&m[2], 0.0), [-1.0, 0.0, -2.0]);
    assert_eq!(at(&m[2], 1.0), [-3.0, 0.0, -2.0]);
}

#[test]
fn dxf_inserts_place_their_blocks() {
    // Block B (base point (1, 0)) holds a LINE from (1, 0) to (2, 0); the INSERT at (10, 10),
    // scale 2, rotation 90°, 2 columns 5 apart, 2 rows 3 apart.
    let text = format!(
        "  0\nSECTION\n  2\nBLOCKS\n{}  0\nENDSEC\n{}",
        concat!(
            "  0\nBLOCK\n  8\n0\n  2\nB\n 70\n0\n 10\n1\n 20\n0\n 30\n0\n",
            "  0\nLINE\n  8\n0\n 10\n1\n 20\n0\n 11\n2\n 21\n0\n",
            "  0\nENDBLK\n",
            "  0\nBLOCK\n  8\n0\n  2\nUNUSED\n 10\n0\n 20\n0\n",
            "  0\nCIRCLE\n  8\n0\n 10\n0\n 20\n0\n 40\n1\n  0\nTEXT\n  8\n0\n",
            "  0\nENDBLK\n",
        ),
        dxf("  0\nINSERT\n  8\n0\n  2\nB\n 10\n10\n 20\n10\n 41\n2\n 42\n2\n 50\n90\n 70\n2\n 71\n2\n 44\n5\n 45\n3\n"),
    );
    let import = import(&text);
    let m = &import.models;
    assert_eq!(m.len(), 4);
    // (p - base) = (0, 0)..(1, 0), scaled 2, rotated 90°: (0, 0)..(0, 2), then moved to the
    // insertion point plus the array offset rotated by 90°: column k row j offset
    // R (5k, 3j) = (-3j, 5k).
    let starts: Vec<[f64; 3]> = m.iter().map(|m| at(m, 0.0)).collect();
    let ends: Vec<[f64; 3]> = m.iter().map(|m| at(m, 1.0)).collect();
    assert_eq!(
        starts,
        [
            [10.0, 10.0, 0.0],
            [10.0, 15.0, 0.0],
            [7.0, 10.0, 0.0],
            [7.0, 15.0, 0.0]
        ]
    );
    assert_eq!(ends[0], [10.0, 12.0, 0.0]);
    assert_eq!(
        import.report.summary(),
        "imported 4 curves (4 LINE); not drawn: 1 CIRCLE, 1 TEXT (definitions never used)"
    );
}

#[test]
fn dxf_nested_inserts_and_their_guards() {
    let blocks = |inner: &str| {
        format!(
            "  0\nSECTION\n  2\nBLOCKS\n  0\nBLOCK\n  2\nA\n 10\n0\n 20\n0\n  0\nINSERT\n  8\n0\n  2\n{inner}\n 10\n1\n 20\n0\n  0\nENDBLK\n  0\nBLOCK\n  2\nC\n 10\n0\n 20\n0\n  0\nLINE\n  8\n0\n 10\n0\n 20\n0\n 11\n1\n 21\n0\n  0\nENDBLK\n  0\nENDSEC\n{}",
            dxf("  0\nINSERT\n  8\n0\n  2\nA\n 10\n0\n 20\n5\n")
        )
    };
    let m = import(&blocks("C")).models;
    assert_eq!(at(&m[0], 0.0), [1.0, 5.0, 0.0]);
    let err = parse_dxf(
        "n.dxf",
        blocks("A").as_bytes(),
        &ImportOptions::new(defaults()),
        &Limits::default(),
    )
    .unwrap_err()
    .to_string();
    assert!(
        err.ends_with("the block `A` inserts itself (through A)"),
        "{err}"
    );
    // An array of 2000 x 2000 copies is capped.
    let big = blocks("C").replace(" 20\n5\n", " 20\n5\n 70\n2000\n 71\n2000\n");
    let err = parse_dxf(
        "n.dxf",
        big.as_bytes(),
        &ImportOptions::new(defaults()),
        &Limits::default(),
    )
    .unwrap_err()
    .to_string();
    assert!(err.contains("more than 1000000"), "{err}");
}

#[test]
fn dxf_layers_off_or_frozen_hide_and_filters_exclude() {
    let text = format!(
        "  0\nSECTION\n  2\nTABLES\n  0\nTABLE\n  2\nLAYER\n{}  0\nENDTAB\n  0\nENDSEC\n{}",
        concat!(
            "  0\nLAYER\n  2\nOFF\n 70\n0\n 62\n-7\n",
            "  0\nLAYER\n  2\nFrozen\n 70\n1\n 62\n7\n",
            "  0\nLAYER\n  2\nON\n 70\n0\n 62\n1\n",
        ),
        dxf(concat!(
            "  0\nLINE\n  8\nOFF\n 10\n0\n 20\n0\n 11\n1\n 21\n0\n",
            "  0\nCIRCLE\n  8\nfrozen\n 10\n0\n 20\n0\n 40\n1\n",
            "  0\nLINE\n  8\nON\n 10\n0\n 20\n0\n 11\n1\n 21\n1\n",
            "  0\nCIRCLE\n  8\nON\n 10\n0\n 20\n0\n 40\n1\n",
            "  0\nLINE\n  8\nON\n 67\n1\n 10\n0\n 20\n0\n 11\n1\n 21\n1\n",
            "  0\nMTEXT\n  8\nON\n  1\nhello\n",
            "  0\nHELIX\n  8\nON\n",
        )),
    );
    let import = import(&text);
    assert_eq!(
        import.report.summary(),
        "imported 2 curves (1 LINE, 1 CIRCLE); skipped 1 MTEXT (not a curve); skipped 1 HELIX \
         (a curve this importer cannot read exactly); hidden: 1 LINE, 1 CIRCLE (not displayed); \
         not drawn: 1 LINE (paper space) (definitions never used)"
    );
    let mut options = ImportOptions::new(defaults());
    options.entities = Some(["CIRCLE".to_owned()].into_iter().collect());
    let only = parse_dxf("t.dxf", text.as_bytes(), &options, &Limits::default()).unwrap();
    assert_eq!(only.models.len(), 1);
    assert_eq!(only.report.skipped_count(crate::SkipReason::Excluded), 1);
}

#[test]
fn dxf_polylines_2d_3d_spline_fit_and_meshes() {
    let text = dxf(concat!(
        // A closed 2-D polyline at elevation 1 with a bulge: one curve in space.
        "  0\nPOLYLINE\n  8\n0\n 66\n1\n 10\n0\n 20\n0\n 30\n1\n 70\n1\n",
        "  0\nVERTEX\n  8\n0\n 10\n0\n 20\n0\n 42\n1\n",
        "  0\nVERTEX\n  8\n0\n 10\n2\n 20\n0\n",
        "  0\nSEQEND\n  8\n0\n",
        // A 3-D polyline.
        "  0\nPOLYLINE\n  8\n0\n 66\n1\n 70\n8\n",
        "  0\nVERTEX\n  8\n0\n 10\n0\n 20\n0\n 30\n0\n 70\n32\n",
        "  0\nVERTEX\n  8\n0\n 10\n1\n 20\n2\n 30\n3\n 70\n32\n",
        "  0\nSEQEND\n  8\n0\n",
        // A quadratic spline-fit polyline: frame (0, 0), (2, 2), (4, 0), one fitted vertex.
        "  0\nPOLYLINE\n  8\n0\n 66\n1\n 70\n4\n 75\n5\n",
        "  0\nVERTEX\n  8\n0\n 10\n0\n 20\n0\n 70\n16\n",
        "  0\nVERTEX\n  8\n0\n 10\n2\n 20\n1\n 70\n8\n",
        "  0\nVERTEX\n  8\n0\n 10\n2\n 20\n2\n 70\n16\n",
        "  0\nVERTEX\n  8\n0\n 10\n4\n 20\n0\n 70\n16\n",
        "  0\nSEQEND\n  8\n0\n",
        // A polyface mesh.
        "  0\nPOLYLINE\n  8\n0\n 66\n1\n 70\n64\n",
        "  0\nVERTEX\n  8\n0\n 10\n0\n 20\n0\n 70\n192\n",
        "  0\nSEQEND\n  8\n0\n",
    ));
    let import = import(&text);
    let m = &import.models;
    assert_eq!(m.len(), 3);
    assert_eq!(
        import.report.summary(),
        "imported 3 curves (3 POLYLINE); skipped 1 POLYLINE (a curve this importer cannot read exactly)"
    );
    // The semicircle from (0, 0) to (2, 0) through (1, -1), then back: at z = 1.
    assert!(close(at(&m[0], 1.0), [1.0, -1.0, 1.0]));
    assert_eq!(at(&m[0], 2.0), [2.0, 0.0, 1.0]);
    assert_eq!(at(&m[1], 1.0), [1.0, 2.0, 3.0]);
    // The quadratic Bézier of the frame: (P0 + 2 P1 + P2) / 4 = (2, 1) at its middle.
    assert_eq!(m[2].kind(), Kind::Curve(CurveKind::BSpline));
    assert_eq!(at(&m[2], 0.5), [2.0, 1.0, 0.0]);
}

/// Every real DXF file of `tests/realfiles/dxf` imports, or fails with a clear error (a file
/// cut short, a hand-written fragment with a broken SPLINE); the totals by kind are printed.
#[test]
fn dxf_real_files_import() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../tests/realfiles/dxf");
    let mut paths = Vec::new();
    for dir in std::fs::read_dir(&root).unwrap() {
        for file in std::fs::read_dir(dir.unwrap().path()).unwrap() {
            paths.push(file.unwrap().path());
        }
    }
    paths.sort();
    assert_eq!(paths.len(), 46);
    let expected_errors: &[(&str, &str)] = &[
        ("top.dxf", "group code `70` has no value (the file ends)"),
        ("spline.dxf", "the SPLINE has no degree (group code 71)"),
        // 8 knots (72) for 11 control points of degree 3.
        (
            "bsplineUnclamped.dxf",
            "knot vector has 8 knots, expected 15",
        ),
        // ezdxf's binary R2000 file holds one TEXT.
        (
            "bin_dxf_r2000.dxf",
            "the file has no curve to import (skipped 1 TEXT (not a curve))",
        ),
        (
            "Minimal_DXF_AC1009.dxf",
            "the file has no curve to import (it is empty)",
        ),
    ];
    let mut total = crate::ImportReport::default();
    let mut curves = 0;
    for path in &paths {
        let name = path.file_name().unwrap().to_str().unwrap();
        let read = crate::load_dxf(path, &ImportOptions::new(defaults()), &Limits::default());
        let expected = expected_errors.iter().find(|(n, _)| *n == name);
        match (read, expected) {
            (Ok(import), None) => {
                println!("{name}: {}", import.report.summary());
                curves += import.models.len();
                for (kind, n) in &import.report.imported {
                    total.imported_many(kind, *n);
                }
                for s in &import.report.skipped {
                    total.skip_many(&s.kind, s.reason, s.count);
                }
            }
            (Err(e), Some((_, message))) => {
                let e = e.to_string();
                println!("{name}: {e}");
                assert!(e.contains(message), "{name}: {e}");
            }
            (Ok(import), Some(_)) => panic!("{name} imports: {}", import.report.summary()),
            (Err(e), None) => panic!("{name}: {e}"),
        }
    }
    println!("total: {curves} curves; {}", total.summary());
    assert_eq!(curves, total.curve_count());
}

/// A binary DXF file (R13 and later: 2-byte group codes) with a LINE whose layer is named in
/// windows-1251, and the same as text: both decode the name (the INSERT's error names it).
#[test]
fn dxf_binary_groups_and_code_pages() {
    fn group(out: &mut Vec<u8>, code: u16, value: &[u8]) {
        out.extend(code.to_le_bytes());
        out.extend(value);
    }
    fn text(s: &[u8]) -> Vec<u8> {
        [s, b"\0"].concat()
    }
    let mut b = b"AutoCAD Binary DXF\r\n\x1a\0".to_vec();
    group(&mut b, 0, &text(b"SECTION"));
    group(&mut b, 2, &text(b"ENTITIES"));
    group(&mut b, 0, &text(b"LINE"));
    group(&mut b, 8, &text(b"0"));
    for (code, x) in [
        (10, 1.0f64),
        (20, 0.1),
        (30, 0.0),
        (11, -2.5),
        (21, 3.0),
        (31, 0.0),
    ] {
        group(&mut b, code, &x.to_le_bytes());
    }
    group(&mut b, 0, &text(b"ENDSEC"));
    group(&mut b, 0, &text(b"EOF"));
    let import = parse_dxf(
        "b.dxf",
        &b,
        &ImportOptions::new(defaults()),
        &Limits::default(),
    )
    .unwrap();
    assert_eq!(import.report.summary(), "imported 1 curve (1 LINE)");
    assert_eq!(at(&import.models[0], 0.0), [1.0, 0.1, 0.0]);
    assert_eq!(at(&import.models[0], 1.0), [-2.5, 3.0, 0.0]);
    // "Слой" in windows-1251 as an INSERT's block name that is not defined.
    let name = [0xD1u8, 0xEB, 0xEE, 0xE9];
    let body = [
        &b"  0\nSECTION\n  2\nHEADER\n  9\n$DWGCODEPAGE\n  3\nANSI_1251\n  0\nENDSEC\n"[..],
        b"  0\nSECTION\n  2\nENTITIES\n  0\nINSERT\n  8\n0\n  2\n",
        &name,
        b"\n  0\nENDSEC\n  0\nEOF\n",
    ]
    .concat();
    let err = parse_dxf(
        "c.dxf",
        &body,
        &ImportOptions::new(defaults()),
        &Limits::default(),
    )
    .unwrap_err()
    .to_string();
    assert_eq!(
        err,
        "c.dxf:15: the INSERT draws the block `Слой`, which the BLOCKS section does not define"
    );
    // An unknown code page: windows-1252, with a warning.
    let other = [
        &b"  0\nSECTION\n  2\nHEADER\n  9\n$DWGCODEPAGE\n  3\nANSI_9999\n  0\nENDSEC\n"[..],
        b"  0\nSECTION\n  2\nENTITIES\n  0\nLINE\n  8\n\xe9\n 10\n0\n 20\n0\n 11\n1\n 21\n0\n  0\nENDSEC\n  0\nEOF\n",
    ]
    .concat();
    let import = parse_dxf(
        "u.dxf",
        &other,
        &ImportOptions::new(defaults()),
        &Limits::default(),
    )
    .unwrap();
    assert_eq!(
        import.report.warnings,
        ["the code page `ANSI_9999` ($DWGCODEPAGE) is not one this reader knows: the text is read as windows-1252"]
    );
    assert_eq!(
        super::groups::code_page("dos850").map(|p| p.decode(&[0x9B, 0x41])),
        Some("øA".to_owned())
    );
}

/// netDxf's sample drawing written as text and as binary DXF reads to the same models.
#[test]
fn dxf_binary_and_text_samples_agree() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../tests/realfiles/dxf/netdxf");
    let read = |name: &str| {
        crate::load_dxf(
            root.join(name),
            &ImportOptions::new(defaults()),
            &Limits::default(),
        )
        .unwrap()
    };
    let (text, binary) = (read("sample.dxf"), read("sample_binary.dxf"));
    assert_eq!(text.models.len(), 30);
    // The text file writes some numbers with fewer digits than the binary doubles (an
    // arc's weight differs in the last bit): the same curves to 1e-12.
    assert_eq!(text.models.len(), binary.models.len());
    for (a, b) in text.models.iter().zip(&binary.models) {
        assert_eq!(
            (a.kind(), a.shape().control_count()),
            (b.kind(), b.shape().control_count())
        );
        let (t0, t1) = domain(a);
        assert_eq!((t0, t1), domain(b));
        for k in 0..=8 {
            let t = t0 + (t1 - t0) * f64::from(k) / 8.0;
            let (p, q) = (at(a, t), at(b, t));
            assert!(
                p.iter()
                    .zip(&q)
                    .all(|(x, y)| (x - y).abs() <= 1e-12 * (1.0 + y.abs())),
                "{p:?} {q:?}"
            );
        }
    }
    assert_eq!(text.report, binary.report);
}

proptest! {
    /// Any groups in any curve entity, block or INSERT give models or a message, never a
    /// panic; so do any bytes after the binary sentinel.
    #[test]
    fn dxf_entities_never_panic(
        kind in prop_oneof![Just("LINE"), Just("ARC"), Just("CIRCLE"), Just("ELLIPSE"),
                            Just("LWPOLYLINE"), Just("POLYLINE"), Just("VERTEX"), Just("INSERT"),
                            Just("SEQEND"), Just("TEXT")],
        groups in proptest::collection::vec(
            (
                prop_oneof![Just("10"), Just("20"), Just("30"), Just("11"), Just("21"),
                            Just("31"), Just("40"), Just("41"), Just("42"), Just("43"),
                            Just("44"), Just("45"), Just("50"), Just("51"), Just("70"),
                            Just("71"), Just("75"), Just("38"), Just("2"), Just("8"),
                            Just("67"), Just("210"), Just("220"), Just("230"), Just("0")],
                prop_oneof![Just("0".to_owned()), Just("1".to_owned()), Just("-1".to_owned()),
                            Just("B".to_owned()), Just("VERTEX".to_owned()),
                            Just("1e308".to_owned()), Just("16".to_owned()),
                            Just("3000".to_owned()), "[0-9.e-]{1,6}"],
            ),
            0..30,
        ),
        bytes in proptest::collection::vec(any::<u8>(), 0..200),
    ) {
        let body: String = groups.iter().map(|(c, v)| format!("{c}\n{v}\n")).collect();
        let block = format!(
            "  0\nSECTION\n  2\nBLOCKS\n  0\nBLOCK\n  2\nB\n  0\n{kind}\n{body}  0\nENDBLK\n  0\nENDSEC\n"
        );
        let text = format!("{block}{}", dxf(&format!("  0\n{kind}\n{body}  0\nINSERT\n  2\nB\n")));
        let _ = parse_dxf("p.dxf", text.as_bytes(), &ImportOptions::new(defaults()), &Limits::default());
        let binary = [&b"AutoCAD Binary DXF\r\n\x1a\0"[..], &bytes].concat();
        let _ = parse_dxf("b.dxf", &binary, &ImportOptions::new(defaults()), &Limits::default());
    }
}

/// A closed spline-fit POLYLINE: the periodic uniform quadratic B-spline of its frame, which
/// at each knot is the midpoint of two consecutive frame points.
#[test]
fn dxf_closed_spline_fit_polyline_is_periodic() {
    let text = dxf(concat!(
        "  0\nPOLYLINE\n  8\n0\n 66\n1\n 70\n5\n 75\n5\n",
        "  0\nVERTEX\n  8\n0\n 10\n0\n 20\n0\n 70\n16\n",
        "  0\nVERTEX\n  8\n0\n 10\n2\n 20\n0\n 70\n16\n",
        "  0\nVERTEX\n  8\n0\n 10\n2\n 20\n2\n 70\n16\n",
        "  0\nVERTEX\n  8\n0\n 10\n0\n 20\n2\n 70\n16\n",
        "  0\nSEQEND\n  8\n0\n",
    ));
    let m = &import(&text).models[0];
    assert_eq!(m.shape().control_count(), 6);
    assert_eq!(domain(m), (2.0, 6.0));
    assert_eq!(at(m, 2.0), [1.0, 0.0, 0.0]);
    assert_eq!(at(m, 3.0), [2.0, 1.0, 0.0]);
    assert_eq!(at(m, 5.0), [0.0, 1.0, 0.0]);
    assert_eq!(at(m, 6.0), [1.0, 0.0, 0.0]);
}
