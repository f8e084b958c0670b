//! Intersections of plane curves (`intersections`, `self_intersections`) against an
//! independent reference (`scripts/reference/make_intersection_reference.py`: polyline
//! crossings and near contacts of dense samples polished by Newton's method or the tangency
//! system in mpmath at 50 digits; `tests/data/intersections.json`): a line through the unit
//! circle, tangent circles, a cubic's self-intersection loop, cubics meeting at their ends,
//! random pairs; closed forms; overlap; and the symmetry of swapping the curves.

use neutrospline::strategies;
use neutrospline::{
    intersections, self_intersections, AnyCurve, BSpline, Bezier, ControlPoint, Degrees, Evaluate,
    IntersectError, KnotVector, Nurbs, Split,
};
use proptest::prelude::*;
use serde::Deserialize;

#[derive(Deserialize)]
struct Data {
    cases: Vec<Case>,
}

#[derive(Deserialize)]
struct Case {
    name: String,
    same: bool,
    a: CurveJson,
    b: CurveJson,
    intersections: Vec<Expected>,
}

#[derive(Deserialize)]
struct CurveJson {
    kind: String,
    degree: usize,
    knots: Vec<String>,
    weights: Option<Vec<String>>,
    control_points: Vec<Vec<String>>,
}

#[derive(Deserialize)]
struct Expected {
    t_a: String,
    t_b: String,
    x: String,
    y: String,
}

fn numbers(texts: &[String]) -> Vec<f64> {
    texts.iter().map(|s| s.parse().expect(s)).collect()
}

fn curve(c: &CurveJson) -> AnyCurve<2> {
    let d = Degrees::new(0.5, 0.25, 0.125).unwrap();
    let points: Vec<ControlPoint<2>> = c
        .control_points
        .iter()
        .map(|row| {
            let v = numbers(row);
            ControlPoint::new([v[0], v[1]], d)
        })
        .collect();
    let knots = || KnotVector::new(numbers(&c.knots), c.degree, points.len()).unwrap();
    match c.kind.as_str() {
        "bezier" => Bezier::new(points.clone()).unwrap().into(),
        "bspline" => BSpline::new(points.clone(), knots()).unwrap().into(),
        "nurbs" => Nurbs::new(
            points.clone(),
            numbers(c.weights.as_ref().unwrap()),
            knots(),
        )
        .unwrap()
        .into(),
        other => panic!("kind {other}"),
    }
}

#[test]
fn intersections_match_the_reference() {
    let data: Data =
        serde_json::from_str(include_str!("data/intersections.json")).expect("reference parses");
    let mut total = 0;
    for case in &data.cases {
        let (a, b) = (curve(&case.a), curve(&case.b));
        let found = if case.same {
            self_intersections(&a).unwrap()
        } else {
            intersections(&a, &b).unwrap()
        };
        let got: Vec<(f64, f64)> = found
            .iter()
            .map(|i| (i.parameter_a, i.parameter_b))
            .collect();
        assert_eq!(
            found.len(),
            case.intersections.len(),
            "{}: got {got:?}",
            case.name
        );
        for (i, want) in found.iter().zip(&case.intersections) {
            let (ta, tb): (f64, f64) = (want.t_a.parse().unwrap(), want.t_b.parse().unwrap());
            assert!(
                (i.parameter_a - ta).abs() <= 1e-10 && (i.parameter_b - tb).abs() <= 1e-10,
                "{}: got {got:?}, want ({ta}, {tb})",
                case.name
            );
            let (x, y): (f64, f64) = (want.x.parse().unwrap(), want.y.parse().unwrap());
            assert!((i.point_a.position[0] - x).abs() <= 1e-12 * 10.0);
            assert!((i.point_a.position[1] - y).abs() <= 1e-12 * 10.0);
            total += 1;
        }
    }
    assert!(total >= 12, "{total} intersections checked");
}

fn segment(p: [f64; 2], q: [f64; 2]) -> Bezier<2> {
    let d = Degrees::new(0.5, 0.25, 0.125).unwrap();
    Bezier::new(vec![ControlPoint::new(p, d), ControlPoint::new(q, d)]).unwrap()
}

#[test]
fn intersections_closed_forms_and_ends() {
    // The cubic loop [(0,0), (4,2), (-1,2), (3,0)] crosses itself at s = (3 - sqrt 3) / 6,
    // t = 1 - s (by its symmetry about x = 1.5).
    let data: Data = serde_json::from_str(include_str!("data/intersections.json")).unwrap();
    let looped = curve(&data.cases.iter().find(|c| c.same).unwrap().a);
    let found = self_intersections(&looped).unwrap();
    let s = (3.0 - 3f64.sqrt()) / 6.0;
    assert_eq!(found.len(), 1);
    assert!(
        (found[0].parameter_a - s).abs() < 1e-14
            && (found[0].parameter_b - (1.0 - s)).abs() < 1e-14
    );
    // Segments sharing an end: reported once, at their ends.
    let a = segment([0.0, 0.0], [1.0, 1.0]);
    let b = segment([1.0, 1.0], [2.0, 0.0]);
    let found = intersections(&a, &b).unwrap();
    assert_eq!(found.len(), 1);
    assert_eq!((found[0].parameter_a, found[0].parameter_b), (1.0, 0.0));
    // Parallel segments apart: none.
    let c = segment([0.0, 1.0], [1.0, 2.0]);
    assert!(intersections(&a, &c).unwrap().is_empty());
}

#[test]
fn intersections_report_an_overlap_once() {
    let a = segment([0.0, 0.0], [2.0, 2.0]);
    let b = segment([1.0, 1.0], [3.0, 3.0]);
    match intersections(&a, &b) {
        Err(IntersectError::Overlap { a: ra, b: rb }) => {
            assert!(
                ra.start >= 0.45 && ra.start <= 0.55 && ra.end > 0.95,
                "{ra:?}"
            );
            assert!(
                rb.start < 0.05 && rb.end >= 0.45 && rb.end <= 0.55,
                "{rb:?}"
            );
        }
        other => panic!("{other:?}"),
    }
    // A curve and a piece of itself overlap.
    let curve = neutrospline::example1();
    let piece = curve.subsegment(0.25, 0.75).unwrap();
    let e = intersections(&curve, &piece).unwrap_err();
    assert!(
        e.to_string().starts_with("the curves overlap: t_a in ["),
        "{e}"
    );
}

fn any_curve() -> impl Strategy<Value = AnyCurve<2>> {
    prop_oneof![
        strategies::bezier::<2>(1..=4).prop_map(AnyCurve::from),
        strategies::bspline::<2>(1..=3).prop_map(AnyCurve::from),
        strategies::nurbs::<2>(2..=3).prop_map(AnyCurve::from),
    ]
}

/// The diagonal of the box around both curves' control points.
fn size(a: &AnyCurve<2>, b: &AnyCurve<2>) -> f64 {
    use neutrospline::Bounded;
    let (p, q) = (a.control_bounding_box(), b.control_bounding_box());
    let span = |k: usize| {
        p.position[k].max.max(q.position[k].max) - p.position[k].min.min(q.position[k].min)
    };
    span(0).hypot(span(1))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Swapping the curves swaps the parameters of every intersection; each found point is on
    /// both curves.
    #[test]
    fn intersections_are_symmetric(a in any_curve(), b in any_curve()) {
        let (Ok(ab), Ok(ba)) = (intersections(&a, &b), intersections(&b, &a)) else {
            return Ok(());
        };
        let mut swapped: Vec<(f64, f64)> = ba.iter().map(|i| (i.parameter_b, i.parameter_a)).collect();
        swapped.sort_by(|p, q| p.0.total_cmp(&q.0));
        prop_assert_eq!(ab.len(), swapped.len(), "{:?} vs {:?}", ab, ba);
        for (i, (sa, sb)) in ab.iter().zip(&swapped) {
            prop_assert!((i.parameter_a - sa).abs() < 1e-8 && (i.parameter_b - sb).abs() < 1e-8);
            let (p, q) = (a.evaluate(i.parameter_a).unwrap().position, b.evaluate(i.parameter_b).unwrap().position);
            let gap = (p[0] - q[0]).hypot(p[1] - q[1]);
            prop_assert!(gap <= 1e-12 * size(&a, &b), "gap {gap}");
        }
    }

    /// Every self-intersection is a pair s < t where the curve passes through one point.
    #[test]
    fn self_intersections_are_ordered_pairs_of_one_point(a in any_curve()) {
        let Ok(found) = self_intersections(&a) else {
            return Ok(());
        };
        let size = size(&a, &a);
        for pair in found.windows(2) {
            prop_assert!(pair[0].parameter_a <= pair[1].parameter_a);
        }
        for i in &found {
            prop_assert!(i.parameter_a < i.parameter_b);
            let (p, q) = (i.point_a.position, i.point_b.position);
            prop_assert!((p[0] - q[0]).hypot(p[1] - q[1]) <= 1e-12 * size);
        }
    }
}

#[test]
fn intersections_on_the_seam_of_closed_curves_are_reported_once() {
    let data: Data = serde_json::from_str(include_str!("data/intersections.json")).unwrap();
    let tangent = data
        .cases
        .iter()
        .find(|c| c.name == "tangent circles")
        .unwrap();
    let circle = curve(&tangent.a);
    // A closed curve does not cross itself at its seam.
    assert!(self_intersections(&circle).unwrap().is_empty());
    // The circle of radius 1/2 inside it, touching at (1, 0): both seams meet there; one row.
    let h = std::f64::consts::FRAC_1_SQRT_2;
    let d = Degrees::new(0.5, 0.5, 0.5).unwrap();
    let ring = [
        (1.0, 0.0),
        (1.0, 1.0),
        (0.0, 1.0),
        (-1.0, 1.0),
        (-1.0, 0.0),
        (-1.0, -1.0),
        (0.0, -1.0),
        (1.0, -1.0),
        (1.0, 0.0),
    ];
    let points = ring
        .iter()
        .map(|&(x, y)| ControlPoint::new([0.5 + 0.5 * x, 0.5 * y], d))
        .collect();
    let weights = vec![1.0, h, 1.0, h, 1.0, h, 1.0, h, 1.0];
    let knots = KnotVector::new(
        vec![
            0.0, 0.0, 0.0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1.0, 1.0, 1.0,
        ],
        2,
        9,
    )
    .unwrap();
    let small = AnyCurve::from(Nurbs::new(points, weights, knots).unwrap());
    let found = intersections(&circle, &small).unwrap();
    assert_eq!(found.len(), 1, "{found:?}");
    assert_eq!((found[0].parameter_a, found[0].parameter_b), (0.0, 0.0));
    assert_eq!(found[0].point_a.position, [1.0, 0.0]);
}
