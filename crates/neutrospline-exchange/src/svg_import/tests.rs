//! The SVG importer: curves, degrees, transforms, arcs and the messages of bad input.

use neutrospline::{CurveKind, Evaluate};
use proptest::prelude::*;

use super::*;
use neutrospline_io::{Kind, Shape};

fn defaults() -> Degrees {
    Degrees::new(0.6, 0.3, 0.1).unwrap()
}

fn curves(svg: &str) -> Vec<AnyCurve<2>> {
    parse_svg(
        "f.svg",
        svg.as_bytes(),
        &ImportOptions::new(defaults()),
        &Limits::default(),
    )
    .map(|i| i.models)
    .unwrap()
    .into_iter()
    .map(|m| match m.into_shape() {
        Shape::Curve(neutrospline::DynCurve::Planar(c)) => c,
        other => panic!("a plane curve, not {:?}", other.kind()),
    })
    .collect()
}

fn one(d: &str) -> AnyCurve<2> {
    let all = curves(&format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\"><path d=\"{d}\"/></svg>"
    ));
    assert_eq!(all.len(), 1, "{d}");
    all.into_iter().next().unwrap()
}

fn positions(c: &AnyCurve<2>) -> Vec<[f64; 2]> {
    c.control_points().iter().map(|p| p.position).collect()
}

fn message(svg: &str) -> String {
    parse_svg(
        "f.svg",
        svg.as_bytes(),
        &ImportOptions::new(defaults()),
        &Limits::default(),
    )
    .map(|i| i.models)
    .unwrap_err()
    .to_string()
}

#[test]
fn svg_lines_make_a_degree_one_spline() {
    let c = one("M0 0 H10 V10 H0 Z");
    assert_eq!(c.kind(), CurveKind::BSpline);
    assert_eq!(
        positions(&c),
        [
            [0.0, 0.0],
            [10.0, 0.0],
            [10.0, 10.0],
            [0.0, 10.0],
            [0.0, 0.0]
        ]
    );
    assert_eq!(
        c.knots().unwrap().knots(),
        [0.0, 0.0, 1.0, 2.0, 3.0, 4.0, 4.0]
    );
    assert!(c.control_points().iter().all(|p| p.degrees == defaults()));
    let p = c.evaluate(2.5).unwrap();
    assert_eq!(p.position, [5.0, 10.0]);
}

#[test]
fn svg_cubic_with_reflection_and_mixed_degrees() {
    let c = one("M0 0 C 0 10 10 10 10 0 S 20 -10 20 0");
    assert_eq!(
        positions(&c),
        [
            [0.0, 0.0],
            [0.0, 10.0],
            [10.0, 10.0],
            [10.0, 0.0],
            [10.0, -10.0],
            [20.0, -10.0],
            [20.0, 0.0]
        ]
    );
    assert_eq!(
        c.knots().unwrap().knots(),
        [0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 2.0, 2.0, 2.0, 2.0]
    );
    // A single cubic is a Bezier curve; a line before it is raised to degree 3 exactly.
    assert_eq!(one("M0 0 C 0 10 10 10 10 0").kind(), CurveKind::Bezier);
    let c = one("M0 0 L 3 0 C 4 0 5 1 5 2");
    assert_eq!(
        positions(&c)[..5],
        [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [3.0, 0.0], [4.0, 0.0]]
    );
    assert_eq!(c.evaluate(1.0).unwrap().position, [3.0, 0.0]);
    // Relative commands, the implicit lineto after m, and T's reflection.
    let c = one("m 1 1 2 0 q 1 1 2 0 t 2 0");
    assert_eq!(
        positions(&c),
        [
            [1.0, 1.0],
            [2.0, 1.0],
            [3.0, 1.0],
            [4.0, 2.0],
            [5.0, 1.0],
            [6.0, 0.0],
            [7.0, 1.0]
        ]
    );
    // Two subpaths are two curves; numbers run together as SVG allows.
    let all = curves("<svg><path d='M0,0L1-1.5.5-2M3 3l1e1 0'/></svg>");
    assert_eq!(positions(&all[0]), [[0.0, 0.0], [1.0, -1.5], [0.5, -2.0]]);
    assert_eq!(positions(&all[1]), [[3.0, 3.0], [13.0, 3.0]]);
}

#[test]
fn svg_arcs_are_exact_rational_quadratics() {
    // A quarter of the unit circle (sweep 1: from +x towards +y): one rational piece.
    let c = one("M 1 0 A 1 1 0 0 1 0 1");
    assert_eq!(c.kind(), CurveKind::Nurbs);
    let p = positions(&c);
    assert_eq!((p[0], p[2]), ([1.0, 0.0], [0.0, 1.0]));
    assert!(
        (p[1][0] - 1.0).abs() < 1e-15 && (p[1][1] - 1.0).abs() < 1e-15,
        "{p:?}"
    );
    let w = c.weights().unwrap();
    assert_eq!((w[0], w[2]), (1.0, 1.0));
    assert!((w[1] - std::f64::consts::FRAC_1_SQRT_2).abs() < 1e-15);
    // A whole circle of two half arcs: four pieces, every point at distance 2 from (5, 5).
    let c = one("M 7 5 A 2 2 0 1 1 3 5 A 2 2 0 1 1 7 5");
    assert_eq!(c.len(), 9);
    for k in 0..=400 {
        let t = 4.0 * f64::from(k) / 400.0;
        let q = c.evaluate(t).unwrap().position;
        let r = ((q[0] - 5.0).powi(2) + (q[1] - 5.0).powi(2)).sqrt();
        assert!((r - 2.0).abs() < 1e-14, "t = {t}: r = {r}");
    }
    // A quarter of an ellipse with radii 3 and 1 turned 30 degrees about the centre
    // (5, 5), after a line: every point satisfies the ellipse's equation.
    let (sin, cos) = 30f64.to_radians().sin_cos();
    let start = [5.0 + 3.0 * cos, 5.0 + 3.0 * sin];
    let end = [5.0 - sin, 5.0 + cos];
    let c = one(&format!(
        "M 5 5 L {} {} A 3 1 30 0 1 {} {}",
        start[0], start[1], end[0], end[1]
    ));
    assert_eq!((c.kind(), c.degree(), c.len()), (CurveKind::Nurbs, 2, 5));
    for k in 0..=200 {
        let t = 1.0 + f64::from(k) / 200.0;
        let q = c.evaluate(t).unwrap().position;
        let (x, y) = (q[0] - 5.0, q[1] - 5.0);
        let (u, v) = (cos * x + sin * y, -sin * x + cos * y);
        let e = (u / 3.0).powi(2) + v * v - 1.0;
        assert!(e.abs() < 1e-14, "t = {t}: {e}");
    }
    // Radii too small are scaled up: a half circle of diameter 4.
    let c = one("M 0 0 A 1 1 0 0 1 4 0");
    for k in 0..=100 {
        let t = c.domain().end * f64::from(k) / 100.0;
        let q = c.evaluate(t).unwrap().position;
        let r = ((q[0] - 2.0).powi(2) + q[1].powi(2)).sqrt();
        assert!((r - 2.0).abs() < 1e-14, "r = {r}");
    }
    // A zero radius is a line.
    assert_eq!(
        positions(&one("M 0 0 A 0 1 0 0 1 4 0")),
        [[0.0, 0.0], [4.0, 0.0]]
    );
}

#[test]
fn svg_transforms_hidden_elements_and_markup() {
    let svg = r#"<?xml version="1.0"?>
<!DOCTYPE svg [ <!ENTITY x "y"> ]>
<svg xmlns="http://www.w3.org/2000/svg">
  <!-- <path d="M 9 9 L 8 8"/> -->
  <defs><path id="hidden" d="M 0 0 L 1 1"/></defs>
  <clipPath id="c"><polygon points="0,0 1,0 1,1"/></clipPath>
  <g transform="translate(10 20) scale(2)">
<path id="a &amp; b" d="M1 1 L2 1"/>
<polyline transform="rotate(90)" points="1 0, 2 0"/>
  </g>
  <text><![CDATA[ <path d="M 5 5 L 6 6"/> ]]></text>
  <polygon points="0 0 4 0 4 3"/>
</svg>"#;
    let models = parse_svg(
        "t.svg",
        svg.as_bytes(),
        &ImportOptions::new(defaults()),
        &Limits::default(),
    )
    .map(|i| i.models)
    .unwrap();
    assert_eq!(models.len(), 3);
    assert_eq!(models[0].name(), Some("a & b"));
    let Some(neutrospline::DynCurve::Planar(a)) = models[0].shape().curve() else {
        panic!()
    };
    assert_eq!(positions(a), [[12.0, 22.0], [14.0, 22.0]]);
    let Some(neutrospline::DynCurve::Planar(b)) = models[1].shape().curve() else {
        panic!()
    };
    let p = positions(b);
    assert!((p[0][0] - 10.0).abs() < 1e-15 && p[0][1] == 22.0, "{p:?}");
    assert!((p[1][0] - 10.0).abs() < 1e-15 && p[1][1] == 24.0, "{p:?}");
    let Some(neutrospline::DynCurve::Planar(c)) = models[2].shape().curve() else {
        panic!()
    };
    assert_eq!(
        positions(c),
        [[0.0, 0.0], [4.0, 0.0], [4.0, 3.0], [0.0, 0.0]]
    );
    assert_eq!(models[2].kind(), Kind::Curve(CurveKind::BSpline));
}

/// The import of `svg` with every kind.
fn import(svg: &str) -> Import {
    parse_svg(
        "f.svg",
        svg.as_bytes(),
        &ImportOptions::new(defaults()),
        &Limits::default(),
    )
    .unwrap()
}

#[test]
fn svg_errors_are_located() {
    let huge = message("<svg><path d='M 1e308 0 l 1e308 0'/></svg>");
    assert_eq!(
        huge,
        "f.svg:1: <path>: control point 1: x = inf is not a finite number (positions must be finite)"
    );
    assert_eq!(
        message("<svg>\n\n<path d='M0 0 L1 1'"),
        "f.svg:1: the XML does not parse: the root node was opened but never closed"
    );
    assert_eq!(
        message("<svg></g></svg>"),
        "f.svg:1: the XML does not parse: expected 'svg' tag, not 'g' at 1:6"
    );
    assert_eq!(
        message("<html><path d='M0 0 L1 1'/></html>"),
        "f.svg:1: the root element is <html>, not <svg>"
    );
    assert_eq!(
        message("<svg><rect width='3' height='0'/><text>a</text></svg>"),
        "f.svg: the file has no curve to import (imported no curve; skipped 1 <text> (not a \
         curve); empty: 1 <rect> (draws nothing))"
    );
    assert_eq!(
        message("<svg><g id='a'><use href='#a'/></g></svg>"),
        "f.svg:1: <use>: it draws itself (the element it refers to contains it, or a <use> chain \
         comes back to it)"
    );
    assert_eq!(
        message("<svg><use id='a' href='#b'/><use id='b' href='#a'/></svg>"),
        "f.svg:1: <use id=\"a\">: it draws itself (the element it refers to contains it, or a \
         <use> chain comes back to it)"
    );
    let unknown = parse_svg(
        "f.svg",
        b"<?xml version='1.0' encoding='latin9'?><svg>\xa4</svg>",
        &ImportOptions::new(defaults()),
        &Limits::default(),
    )
    .unwrap_err()
    .to_string();
    assert_eq!(
        unknown,
        "f.svg: the XML declaration's encoding \"latin9\" is not one this reader knows"
    );
    let not_utf8 = parse_svg(
        "f.svg",
        b"<svg><path d='M0 0 L1 1'/>\xff</svg>",
        &ImportOptions::new(defaults()),
        &Limits::default(),
    )
    .unwrap_err()
    .to_string();
    assert_eq!(
        not_utf8,
        "f.svg: the file is not UTF-8 text (byte 26) and its XML declaration names no encoding"
    );
    // A declared single-byte encoding is decoded.
    let cyrillic =
        b"<?xml version='1.0' encoding='windows-1251'?><svg><path id='\xcf' d='M0 0 L1 1'/></svg>";
    let read = parse_svg(
        "f.svg",
        cyrillic,
        &ImportOptions::new(defaults()),
        &Limits::default(),
    )
    .unwrap();
    assert_eq!(read.models[0].name(), Some("\u{41f}"));
}

#[test]
fn svg_bad_data_is_drawn_up_to_the_error_with_a_warning() {
    let read = import(
        "<svg>\n<path id='p' d='M 0 0 L 10 0 L 10 # L 0 0'/>\n<polyline points='0 0 1 1 2'/></svg>",
    );
    assert_eq!(read.models.len(), 2);
    let Some(neutrospline::DynCurve::Planar(c)) = read.models[0].shape().curve() else {
        panic!()
    };
    assert_eq!(positions(c), [[0.0, 0.0], [10.0, 0.0]]);
    assert_eq!(
        read.report.warnings,
        [
            "line 2: <path id=\"p\">: d: invalid number at position 19; drawn up to it (1 segment \
             kept), as the SVG specification says",
            "line 3: <polyline>: points: an odd number of coordinates (5): the last one is left \
             out; drawn up to it (2 points kept)"
        ]
    );
    // A transform that does not parse is ignored, as renderers do, and said.
    let read = import("<svg><path transform='spin(3)' d='M0 0 L1 1'/></svg>");
    let Some(neutrospline::DynCurve::Planar(c)) = read.models[0].shape().curve() else {
        panic!()
    };
    assert_eq!(positions(c), [[0.0, 0.0], [1.0, 1.0]]);
    assert_eq!(read.report.warnings.len(), 1, "{:?}", read.report.warnings);
    assert!(read.report.warnings[0].starts_with("line 1: <path>: transform = \"spin(3)\": "));
    assert_eq!(read.report.strict_violations().len(), 1);
}

/// The point of `c` at `t`.
fn at(c: &AnyCurve<2>, t: f64) -> [f64; 2] {
    c.evaluate(t).unwrap().position
}

fn close(a: [f64; 2], b: [f64; 2], what: &str) {
    let d = ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2)).sqrt();
    assert!(d < 1e-12, "{what}: {a:?} vs {b:?} ({d:e})");
}

#[test]
fn svg_circles_ellipses_and_rounded_rects_are_exact() {
    let all = curves(
        "<svg xmlns='http://www.w3.org/2000/svg'>\
         <circle cx='5' cy='-2' r='3'/>\
         <ellipse cx='1' cy='2' rx='4' ry='1' transform='rotate(30)'/>\
         <rect x='10' y='20' width='30' height='10' rx='4'/>\
         <rect x='1' y='2' width='3' height='4'/>\
         <line x1='1' y1='2' x2='3' y2='5'/></svg>",
    );
    assert_eq!(all.len(), 5);
    // The circle: a closed NURBS of four quarters, every point at distance 3 from the centre,
    // starting at (cx + r, cy) and turning towards +y.
    let circle = &all[0];
    assert_eq!(circle.kind(), CurveKind::Nurbs);
    assert_eq!(circle.domain(), 0.0..4.0);
    close(at(circle, 0.0), [8.0, -2.0], "start");
    close(at(circle, 1.0), [5.0, 1.0], "a quarter");
    close(at(circle, 4.0), [8.0, -2.0], "closed");
    for k in 0..=64 {
        let p = at(circle, f64::from(k) / 16.0);
        let r = ((p[0] - 5.0).powi(2) + (p[1] + 2.0).powi(2)).sqrt();
        assert!((r - 3.0).abs() < 1e-14, "{p:?}: {r}");
    }
    // The rotated ellipse: (x, y) = R(30) (1 + 4 cos s, 2 + sin s) for some s at every point.
    let (sin, cos) = 30f64.to_radians().sin_cos();
    for k in 0..=64 {
        let [x, y] = at(&all[1], f64::from(k) / 16.0);
        let (u, v) = (cos * x + sin * y, -sin * x + cos * y);
        let e = ((u - 1.0) / 4.0).powi(2) + (v - 2.0).powi(2);
        assert!((e - 1.0).abs() < 1e-14, "{x} {y}: {e}");
    }
    // The rounded rectangle: ry = rx = 4; its first side from (14, 20) to (36, 20); the corner
    // quarter around (36, 24) passes through (36 + 4 cos 45, 24 - 4 sin 45).
    let rect = &all[2];
    close(at(rect, 0.0), [14.0, 20.0], "rect start");
    close(at(rect, 1.0), [36.0, 20.0], "side end");
    let h = std::f64::consts::FRAC_1_SQRT_2 * 4.0;
    close(at(rect, 1.5), [36.0 + h, 24.0 - h], "corner middle");
    close(at(rect, 2.0), [40.0, 24.0], "corner end");
    close(at(rect, rect.domain().end), [14.0, 20.0], "closed");
    // Arc length in closed form: 2 (w + h) - 8 r + 2 pi r.
    let length = neutrospline::CurveGeometry::length(rect).unwrap();
    let exact = 2.0 * 40.0 - 8.0 * 4.0 + 2.0 * std::f64::consts::PI * 4.0;
    assert!((length - exact).abs() < 1e-10, "{length} vs {exact}");
    assert_eq!(
        positions(&all[3]),
        [[1.0, 2.0], [4.0, 2.0], [4.0, 6.0], [1.0, 6.0], [1.0, 2.0]]
    );
    assert_eq!(positions(&all[4]), [[1.0, 2.0], [3.0, 5.0]]);
}

#[test]
fn svg_use_symbols_nested_viewports_css_and_units() {
    let svg = r##"<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink"
     xmlns:s="http://www.w3.org/2000/svg" width="100mm" height="50mm" viewBox="0 0 200 100">
  <style>.big { transform: scale(2) } #moved { transform: translate(5px, 0) }</style>
  <defs>
    <path id="tick" d="M 0 0 L 1 0"/>
    <symbol id="box" viewBox="0 0 10 10"><path d="M 0 0 L 10 10"/></symbol>
  </defs>
  <use xlink:href="#tick" x="3" y="4" transform="translate(10 0)"/>
  <use href="#box" x="100" y="0" width="20" height="40"/>
  <svg x="50" y="60" width="40" height="20" viewBox="0 0 4 4">
    <path d="M 0 0 L 4 4"/>
  </svg>
  <s:path class="big" d="M 1 1 L 2 1"/>
  <path id="moved" transform="translate(100 100)" d="M 0 0 L 1 0"/>
  <line x1="1in" y1="0" x2="10mm" y2="50%"/>
  <g style="display:none"><rect width="1" height="1"/><text>x</text></g>
  <g visibility="hidden"><circle r="1"/><circle r="2" visibility="visible"/></g>
  <clipPath><rect width="5" height="5"/></clipPath>
</svg>"##;
    let read = import(svg);
    let lines: Vec<Vec<[f64; 2]>> = read
        .models
        .iter()
        .map(|m| match m.shape().curve() {
            Some(neutrospline::DynCurve::Planar(c)) => positions(c),
            _ => panic!(),
        })
        .collect();
    // The use: translate(10 0), then x, y.
    assert_eq!(lines[0], [[13.0, 4.0], [14.0, 4.0]]);
    // The symbol: viewBox 10 x 10 meets 20 x 40, scale 2, centred in y: (40 - 20) / 2.
    assert_eq!(lines[1], [[100.0, 10.0], [120.0, 30.0]]);
    // The nested viewport: 4 x 4 meets 40 x 20: scale 5, centred in x: (40 - 20) / 2.
    assert_eq!(lines[2], [[60.0, 60.0], [80.0, 80.0]]);
    // The class rule's CSS transform; the prefixed element is found.
    assert_eq!(lines[3], [[2.0, 2.0], [4.0, 2.0]]);
    // The id rule's CSS transform wins over the attribute.
    assert_eq!(lines[4], [[5.0, 0.0], [6.0, 0.0]]);
    // Units: 1in = 96, 10mm = 37.795..., 50% of the viewBox height 100.
    assert_eq!(lines[5], [[96.0, 0.0], [10.0 * 96.0 / 25.4, 50.0]]);
    // The visible circle inside the hidden group.
    assert_eq!(lines.len(), 7);
    assert_eq!(
        read.report.summary(),
        "imported 7 curves (5 <path>, 1 <line>, 1 <circle>); skipped 0 "
            .replace("skipped 0 ", "")
            .trim_end_matches("; ")
            .to_owned()
            + "; hidden: 1 <rect>, 1 <text>, 1 <circle> (not displayed); not drawn: 1 <rect> in \
               <clipPath> (definitions never used)"
    );
}

#[test]
fn svg_entities_leave_out_the_other_kinds() {
    let svg = "<svg><path d='M0 0 L1 1'/><rect width='1' height='2'/></svg>";
    let mut options = ImportOptions::new(defaults());
    options.entities = Some(["rect".to_owned()].into_iter().collect());
    let read = parse_svg("f.svg", svg.as_bytes(), &options, &Limits::default()).unwrap();
    assert_eq!(read.models.len(), 1);
    assert_eq!(
        read.report.summary(),
        "imported 1 curve (1 <rect>); excluded by --entities: 1 <path>"
    );
}

#[test]
fn svg_a_used_symbol_outside_defs_is_drawn_and_an_unused_one_reported() {
    let svg = "<svg><symbol id='s'><path d='M0 0 L1 1'/></symbol>\
               <symbol id='t'><rect width='1' height='1'/></symbol><use href='#s'/></svg>";
    assert_eq!(
        import(svg).report.summary(),
        "imported 1 curve (1 <path>); not drawn: 1 <rect> in <symbol> (definitions never used)"
    );
}

#[test]
fn svg_use_bombs_are_refused() {
    // Ten levels of ten clones: 10^10 curves.
    let mut svg = String::from("<svg><defs><path id='l0' d='M0 0 L1 1'/>");
    for level in 1..=10 {
        svg.push_str(&format!("<g id='l{level}'>"));
        for _ in 0..10 {
            svg.push_str(&format!("<use href='#l{}'/>", level - 1));
        }
        svg.push_str("</g>");
    }
    svg.push_str("</defs><use href='#l10'/></svg>");
    let mut limits = Limits::default();
    limits.max_control_points = 1000;
    let error = parse_svg(
        "f.svg",
        svg.as_bytes(),
        &ImportOptions::new(defaults()),
        &limits,
    )
    .unwrap_err()
    .to_string();
    assert!(
        error.starts_with("f.svg:1: <path id=\"l0\">: the file's curves hold more than 16000 control points in all"),
        "{error}"
    );
}

proptest! {
    /// Any path data, transform or markup gives curves or a message, never a panic.
    #[test]
    fn svg_never_panics(
        d in "[MmLlHhVvCcSsQqTtAaZzX0-9.eE+, #-]{0,40}",
        transform in "[a-zXY() 0-9.,-]{0,20}",
        markup in "[<>/='\"a-z !?\\[\\]&#;-]{0,30}",
    ) {
        let svg = format!("<svg><g transform='{transform}'><path d='{d}'/></g>{markup}</svg>");
        let _ = parse_svg("p.svg", svg.as_bytes(), &ImportOptions::new(defaults()), &Limits::default()).map(|i| i.models);
        let svg = format!("<svg><path d='{d}'/>{markup}<polyline points='{d}'/></svg>");
        let _ = parse_svg("p.svg", svg.as_bytes(), &ImportOptions::new(defaults()), &Limits::default()).map(|i| i.models);
    }

    /// Any lengths, viewBoxes, styles and references on the elements give curves or a
    /// message, never a panic.
    #[test]
    fn svg_elements_never_panic(
        a in "[0-9a-z.%# -]{0,8}",
        b in "[0-9a-z.%# -]{0,8}",
        style in "[a-z:;()0-9 .-]{0,24}",
    ) {
        let svg = format!(
            "<svg viewBox='{a}' width='{b}'><style>rect {{ {style} }}</style>\
             <rect id='r' x='{a}' width='{b}' height='{a}' rx='{b}' style='{style}'/>\
             <circle r='{a}' transform='{style}'/><ellipse rx='{b}' ry='{a}'/>\
             <line x2='{a}' y2='{b}'/><use href='#{a}' x='{b}' width='{a}'/>\
             <svg width='{a}' height='{b}' viewBox='{b}' preserveAspectRatio='{style}'><use href='#r'/></svg>\
             <symbol id='{a}' viewBox='{a}'><use href='#{b}'/></symbol><g id='{b}'><use href='#{a}'/></g>\
             </svg>"
        );
        let _ = parse_svg("p.svg", svg.as_bytes(), &ImportOptions::new(defaults()), &Limits::default());
    }
}
