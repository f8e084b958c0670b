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

#[test]
fn svg_errors_are_located() {
    let huge = message("<svg><path d='M 1e308 0 l 1e308 0'/></svg>");
    assert_eq!(
        huge,
        "f.svg:1: <path> (element 1): control point 1: x = inf is not a finite number (positions must be finite)"
    );
    let path = |d: &str| format!("<svg>\n<path d=\"{d}\"/>\n</svg>");
    assert_eq!(
        message(&path("M0 0 X 1")),
        "f.svg:2: <path> (element 1): d: unknown command `X` at character 6 (known: M, L, H, V, C, S, Q, T, A, Z and their lower-case relative forms)"
    );
    assert_eq!(
        message(&path("M 0 0 L 1")),
        "f.svg:2: <path> (element 1): d: a number is missing at character 10 (the data ends)"
    );
    assert_eq!(
        message(&path("M0 0 A 1 1 0 2 1 3 3")),
        "f.svg:2: <path> (element 1): d: an arc flag at character 14 is not 0 or 1"
    );
    assert_eq!(
        message(&path("L 1 1")),
        "f.svg:2: <path> (element 1): d: the path data starts with `L`, not with a moveto (M or m)"
    );
    assert_eq!(
        message(&path("M 0 0 L 1 #")),
        "f.svg:2: <path> (element 1): d: expected a number at character 11, found `#`"
    );
    assert_eq!(
        message("<svg>\n<path/>\n</svg>"),
        "f.svg:2: <path> (element 1): it has no path data (attribute d)"
    );
    assert_eq!(
        message("<svg>\n\n<path d='M0 0 L1 1'"),
        "f.svg:3: a tag `<` is not closed (no `>`)"
    );
    assert_eq!(message("<svg><g transform='spin(3)'><path d='M0 0 L1 1'/></g></svg>"), "f.svg:1: <g> transform: `spin` is not a transform (known: matrix, translate, scale, rotate, skewX, skewY)");
    assert_eq!(message("<svg><rect width='3' height='4'/></svg>"), "f.svg: the file has no curve to import (no drawn <path>, <polyline> or <polygon> that draws a segment)");
    assert_eq!(message("<svg></g></svg>"), "f.svg:1: `</g>` closes `<svg>`");
    assert_eq!(
        message("<svg><path transform=')scale(2' d='M0 0 L1 1'/></svg>"),
        "f.svg:1: <path> transform: `)scale(2` is not closed"
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
}
