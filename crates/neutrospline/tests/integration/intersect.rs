//! Intersections of plane curves (`intersections`, `self_intersections`) against an
//! independent reference (`scripts/reference/make_intersection_reference.py`: polyline
//! crossings and near contacts of dense samples polished by Newton's method or the tangency
//! system in mpmath at 50 digits; `tests/data/intersections.json`): a line through the unit
//! circle, tangent circles, a cubic's self-intersection loop, cubics meeting at their ends,
//! random pairs; closed forms; overlap; and the symmetry of swapping the curves.

use neutrospline::strategies;
use neutrospline::{
    intersections, self_intersections, AnyCurve, BSpline, Bezier, Contact, ControlPoint, Degrees,
    Evaluate, IntersectError, Intersection, KnotVector, Nurbs, Split,
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
        serde_json::from_str(include_str!("../data/intersections.json")).expect("reference parses");
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
    let data: Data = serde_json::from_str(include_str!("../data/intersections.json")).unwrap();
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

/// The documented root tolerance (`intersections`): 1e-12 of the size, or what the floats
/// `s` and `t` can resolve there, `2 eps (|s| |A'(s)| + |t| |B'(t)|)`, when that is more (a
/// short knot span far from 0 with large weights moves the point by more per ulp of `s`).
fn root_tolerance(a: &AnyCurve<2>, b: &AnyCurve<2>, s: f64, t: f64, size: f64) -> f64 {
    use neutrospline::Derivative;
    let va = a.derivative().evaluate(s).unwrap().position;
    let vb = b.derivative().evaluate(t).unwrap().position;
    1e-12 * size
        + 2.0 * f64::EPSILON * (s.abs() * va[0].hypot(va[1]) + t.abs() * vb[0].hypot(vb[1]))
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
            let tolerance = root_tolerance(&a, &b, i.parameter_a, i.parameter_b, size(&a, &b));
            prop_assert!(gap <= tolerance, "gap {gap} > {tolerance}");
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
            let tolerance = root_tolerance(&a, &a, i.parameter_a, i.parameter_b, size);
            prop_assert!((p[0] - q[0]).hypot(p[1] - q[1]) <= tolerance);
        }
    }
}

#[test]
fn intersections_on_the_seam_of_closed_curves_are_reported_once() {
    let data: Data = serde_json::from_str(include_str!("../data/intersections.json")).unwrap();
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

fn bezier(points: &[[f64; 2]]) -> Bezier<2> {
    let d = Degrees::new(0.5, 0.25, 0.125).unwrap();
    Bezier::new(points.iter().map(|p| ControlPoint::new(*p, d)).collect()).unwrap()
}

/// The graph of `y = x^k` on `[-1, 1]` as a Bézier curve of degree `k` in `t = (x + 1) / 2`:
/// `x^k = (2t - 1)^k = sum_i B_{k,i}(t) (-1)^(k - i)`, and `x` has the control values
/// `-1 + 2i/k`.
fn power_graph(k: usize) -> Bezier<2> {
    let points: Vec<[f64; 2]> = (0..=k)
        .map(|i| {
            let sign = if (k - i).is_multiple_of(2) { 1.0 } else { -1.0 };
            [-1.0 + 2.0 * i as f64 / k as f64, sign]
        })
        .collect();
    bezier(&points)
}

fn one_contact(found: &[Intersection], s: f64, t: f64, contact: Contact, within: f64) {
    assert_eq!(found.len(), 1, "{found:?}");
    let i = &found[0];
    assert!(
        (i.parameter_a - s).abs() <= within && (i.parameter_b - t).abs() <= within,
        "{i:?}, want ({s}, {t})"
    );
    assert_eq!(i.contact, contact, "{i:?}");
}

/// Tangential contacts of every order are one row each, of contact `tangent`: `y = x^k`
/// touches (k even) or crosses tangentially (k odd) the line `y = 0` at `x = 0`, a contact
/// of order k - 1. The curves are within 1e-12 of each other where `|x| < 1e-12^(1/k)`, so
/// the parameter is known to that (3e-2 at k = 8); the old search gave an overlap for k >= 3.
#[test]
fn intersections_tangential_contacts_of_every_order_are_one_row() {
    let axis = bezier(&[[-1.0, 0.0], [1.0, 0.0]]);
    for k in 2..=8 {
        let found = intersections(&power_graph(k), &axis).unwrap();
        let within = 0.5 * 1e-12_f64.powf(1.0 / k as f64);
        one_contact(&found, 0.5, 0.5, Contact::Tangent, within);
        let swapped = intersections(&axis, &power_graph(k)).unwrap();
        one_contact(&swapped, 0.5, 0.5, Contact::Tangent, within);
    }
}

/// Two parabolas that touch with different curvatures (`y = x^2` and `y = -x^2`, and
/// `y = x^2` and `y = 2x^2`), parametrised so that the contact is at neither curve's middle,
/// and a tangent line: one row each, at the closed-form parameters.
#[test]
fn intersections_simple_tangencies_are_one_row_at_the_touching_point() {
    // y = c x^2 on x in [a, b]: control points (a, c a^2), ((a + b) / 2, c a b), (b, c b^2);
    // x = a + (b - a) t.
    let parabola = |c: f64, a: f64, b: f64| {
        bezier(&[[a, c * a * a], [0.5 * (a + b), c * a * b], [b, c * b * b]])
    };
    let upper = parabola(1.0, -0.3, 1.7);
    for (other, t) in [
        (parabola(-1.0, -1.1, 0.7), 1.1 / 1.8),
        (parabola(2.0, -0.45, 0.85), 0.45 / 1.3),
    ] {
        let found = intersections(&upper, &other).unwrap();
        one_contact(&found, 0.15, t, Contact::Tangent, 1e-7);
    }
    // The tangent y = 0.8 x - 0.16 touches y = x^2 at x = 0.4.
    let tangent = bezier(&[[-1.0, -0.96], [2.0, 1.44]]);
    let found = intersections(&upper, &tangent).unwrap();
    one_contact(&found, 0.35, 1.4 / 3.0, Contact::Tangent, 1e-7);
}

/// Osculating curves (a contact of order 3): `y = x^2` and its circle of curvature at the
/// origin, `x^2 + (y - 1/2)^2 = 1/4`, as a rational quadratic arc (the lower half, weight
/// 0 at the middle control point is avoided by two quarter arcs).
#[test]
fn intersections_osculating_circle_is_one_tangent_row() {
    let d = Degrees::new(0.5, 0.25, 0.125).unwrap();
    let w = core::f64::consts::FRAC_1_SQRT_2;
    let points: Vec<ControlPoint<2>> =
        [[-0.5, 0.5], [-0.5, 0.0], [0.0, 0.0], [0.5, 0.0], [0.5, 0.5]]
            .iter()
            .map(|p| ControlPoint::new(*p, d))
            .collect();
    let knots = KnotVector::new(vec![0.0, 0.0, 0.0, 0.5, 0.5, 1.0, 1.0, 1.0], 2, 5).unwrap();
    let circle = Nurbs::new(points, vec![1.0, w, 1.0, w, 1.0], knots).unwrap();
    let parabola = bezier(&[[-0.5, 0.25], [0.0, -0.25], [0.5, 0.25]]);
    let found = intersections(&parabola, &circle).unwrap();
    // The separation grows like x^4 / 4 + ...: within 1e-12 for |x| < 1.4e-3.
    one_contact(&found, 0.5, 0.5, Contact::Tangent, 3e-3);
}

/// Crossings near a tangency stay apart: `y = x^2` and `y = eps` cross at `x = +-sqrt(eps)`,
/// where the curves separate by `eps` between them, far above the root tolerance.
#[test]
fn intersections_crossings_near_a_tangency_are_kept_apart() {
    let parabola = bezier(&[[-1.0, 1.0], [0.0, -1.0], [1.0, 1.0]]);
    for eps in [1e-2, 1e-4, 1e-6, 1e-8, 1e-10] {
        let line = bezier(&[[-1.0, eps], [1.0, eps]]);
        let found = intersections(&parabola, &line).unwrap();
        assert_eq!(found.len(), 2, "eps = {eps}: {found:?}");
        let root = eps.sqrt();
        for (i, x) in found.iter().zip([-root, root]) {
            let t = 0.5 * (x + 1.0);
            assert!((i.parameter_a - t).abs() <= 1e-9, "eps = {eps}: {i:?}");
            assert!((i.parameter_b - t).abs() <= 1e-9, "eps = {eps}: {i:?}");
            let want = if eps >= 1e-10 {
                Contact::Crossing
            } else {
                Contact::Tangent
            };
            assert_eq!(i.contact, want, "eps = {eps}: {i:?}");
        }
    }
}

/// The contact column: crossings, and ends (segments sharing an end point; a segment that
/// ends on the other curve's interior), and a closed curve's seam is no end.
#[test]
fn intersections_name_their_contact() {
    let a = bezier(&[[0.0, 0.0], [2.0, 2.0]]);
    let b = bezier(&[[0.0, 2.0], [2.0, 0.0]]);
    one_contact(
        &intersections(&a, &b).unwrap(),
        0.5,
        0.5,
        Contact::Crossing,
        0.0,
    );
    let c = bezier(&[[2.0, 2.0], [3.0, 0.0]]);
    one_contact(&intersections(&a, &c).unwrap(), 1.0, 0.0, Contact::End, 0.0);
    let d = bezier(&[[1.0, 1.0], [1.0, 3.0]]);
    one_contact(&intersections(&a, &d).unwrap(), 0.5, 0.0, Contact::End, 0.0);
    let names: Vec<String> = Contact::ALL.iter().map(|c| c.to_string()).collect();
    assert_eq!(names, ["crossing", "tangent", "end"]);
    assert_eq!("tangent".parse::<Contact>(), Ok(Contact::Tangent));
    assert_eq!(
        "touch".parse::<Contact>(),
        Err("unknown contact `touch` (expected crossing, tangent or end)".to_owned())
    );
}

/// Overlaps whose sub-pieces do not align with the other curve's (a piece cut at 0.3 and
/// 0.7, not at dyadic parameters; a reversed piece; segments offset by 0.35) are still
/// refused, with the stretch they share.
#[test]
fn intersections_report_overlaps_that_do_not_align() {
    let curve = neutrospline::example1();
    let piece = curve.subsegment(0.3, 0.7).unwrap();
    for other in [piece.clone(), piece.reversed()] {
        match intersections(&curve, &other) {
            Err(IntersectError::Overlap { a, b }) => {
                assert!(
                    (a.start - 0.3).abs() < 0.02 && (a.end - 0.7).abs() < 0.02,
                    "{a:?}"
                );
                assert!(b.start < 0.03 && b.end > 0.97, "{b:?}");
            }
            other => panic!("{other:?}"),
        }
    }
    let a = segment([0.0, 0.0], [2.0, 2.0]);
    let b = segment([0.7, 0.7], [3.1, 3.1]);
    assert!(matches!(
        intersections(&a, &b),
        Err(IntersectError::Overlap { .. })
    ));
}

/// The cubic (0, 0), (1 + d, 1), (-d, 1), (1, 0): for d = 0 a cusp at t = 1/2 and no
/// self-intersection (x(t) = 3t(1-t)^2 + t^3 has x' = 3(1 - 2t)^2 >= 0, so x is increasing and
/// C(s) = C(t) only for s = t), although C(1/2 - h) and C(1/2 + h) agree to rounding for h up
/// to about 1e-5 (8 h^3 apart); for d > 0 a loop, whose crossing has y(s) = y(t) with
/// y = 3t(1 - t), so t = 1 - s: the same point at parameters symmetric about 1/2.
#[test]
fn a_cusp_is_no_self_intersection_and_a_loop_is_one() {
    let cubic = |d: f64| {
        let degrees = Degrees::new(0.5, 0.25, 0.125).unwrap();
        Bezier::new(
            [[0.0, 0.0], [1.0 + d, 1.0], [-d, 1.0], [1.0, 0.0]]
                .into_iter()
                .map(|p| ControlPoint::new(p, degrees))
                .collect(),
        )
        .unwrap()
    };
    assert_eq!(self_intersections(&cubic(0.0)).unwrap(), []);
    for d in [1e-2, 0.3] {
        let found = self_intersections(&cubic(d)).unwrap();
        assert_eq!(found.len(), 1, "d = {d}: {found:?}");
        let (s, t) = (found[0].parameter_a, found[0].parameter_b);
        // Symmetric about 1/2, the same point.
        assert!((s + t - 1.0).abs() < 1e-12, "d = {d}: {s} {t}");
        let (p, q) = (found[0].point_a.position, found[0].point_b.position);
        assert!((p[0] - q[0]).abs() < 1e-12 && (p[1] - q[1]).abs() < 1e-12);
    }
}
