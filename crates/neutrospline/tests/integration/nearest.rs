//! Nearest points of curves (`NearestPoint`): against an independent reference
//! (`scripts/reference/make_nearest_reference.py`: dense sampling, then golden-section
//! refinement of every near local minimum in mpmath at 70 digits; `tests/data/nearest.json`),
//! with points on the curve, at and beyond its ends, far away, at the centre of the NURBS
//! circle (every point is nearest: the start is reported), on the circle's seam (t = 0 and
//! t = 1 tie: 0 is reported) and at and around a cusp; and property tests over every kind.

use neutrospline::strategies;
use neutrospline::{
    AnyCurve, BSpline, Bezier, ControlPoint, Degrees, Evaluate, EvaluateSurface, KnotVector,
    NearestError, NearestPoint, Nurbs, Surface, SurfaceKind,
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
    kind: String,
    degree: usize,
    dimension: usize,
    scale: String,
    knots: Vec<String>,
    weights: Option<Vec<String>>,
    control_points: Vec<Vec<String>>,
    queries: Vec<Query>,
}

#[derive(Deserialize)]
struct Query {
    point: Vec<String>,
    t: String,
    distance: String,
    unique: bool,
}

fn numbers(texts: &[String]) -> Vec<f64> {
    texts.iter().map(|s| s.parse().expect(s)).collect()
}

fn curve<const D: usize>(case: &Case) -> AnyCurve<D> {
    let d = Degrees::new(0.5, 0.25, 0.125).unwrap();
    let points: Vec<ControlPoint<D>> = case
        .control_points
        .iter()
        .map(|row| {
            let v = numbers(row);
            ControlPoint::new(core::array::from_fn(|a| v[a]), d)
        })
        .collect();
    let knots = || KnotVector::new(numbers(&case.knots), case.degree, points.len()).unwrap();
    match case.kind.as_str() {
        "bezier" => Bezier::new(points.clone()).unwrap().into(),
        "bspline" => BSpline::new(points.clone(), knots()).unwrap().into(),
        "nurbs" => Nurbs::new(
            points.clone(),
            numbers(case.weights.as_ref().unwrap()),
            knots(),
        )
        .unwrap()
        .into(),
        other => panic!("kind {other}"),
    }
}

/// Distances within 1e-12 of the scale (the larger of the curve's size and the distance);
/// parameters within 1e-9 where the minimum is unique.
fn check_case<const D: usize>(case: &Case) -> usize {
    let c = curve::<D>(case);
    let projector = c.projector();
    let scale: f64 = case.scale.parse().unwrap();
    let mut unique = 0;
    for q in &case.queries {
        let p = numbers(&q.point);
        let point: [f64; D] = core::array::from_fn(|a| p[a]);
        let want_t: f64 = q.t.parse().unwrap();
        let want_d: f64 = q.distance.parse().unwrap();
        let got = projector.nearest(point).unwrap();
        let tol = 1e-12 * scale.max(want_d);
        assert!(
            (got.distance - want_d).abs() <= tol,
            "{} at {point:?}: distance {} want {want_d} (t {} want {want_t})",
            case.name,
            got.distance,
            got.parameter
        );
        if q.unique {
            unique += 1;
            assert!(
                (got.parameter - want_t).abs() <= 1e-9,
                "{} at {point:?}: t {} want {want_t}",
                case.name,
                got.parameter
            );
        }
        // The reported point is the curve's at the reported parameter.
        assert_eq!(got.point, c.evaluate(got.parameter).unwrap());
        // The library's one-shot call agrees with the projector.
        assert_eq!(c.nearest(point).unwrap(), got);
    }
    unique
}

#[test]
fn nearest_matches_the_sampled_and_refined_reference() {
    let data: Data =
        serde_json::from_str(include_str!("../data/nearest.json")).expect("reference parses");
    let mut unique = 0;
    let mut queries = 0;
    for case in &data.cases {
        queries += case.queries.len();
        unique += match case.dimension {
            2 => check_case::<2>(case),
            3 => check_case::<3>(case),
            d => panic!("dimension {d}"),
        };
    }
    assert!(
        queries >= 70 && unique >= 60,
        "{queries} queries, {unique} unique"
    );
}

fn unit_circle() -> AnyCurve<2> {
    let data: Data = serde_json::from_str(include_str!("../data/nearest.json")).unwrap();
    let case = data
        .cases
        .iter()
        .find(|c| c.name == "examples/nurbs-circle.toml")
        .unwrap();
    curve::<2>(case)
}

#[test]
fn nearest_on_the_circle_closed_forms() {
    let circle = unit_circle();
    // The centre: every point is at distance 1; the smallest parameter is reported.
    let centre = circle.nearest([0.0, 0.0]).unwrap();
    assert_eq!(centre.parameter, 0.0);
    assert!((centre.distance - 1.0).abs() < 1e-15);
    // On the seam, t = 0 and t = 1 are the same point: 0 is reported.
    let seam = circle.nearest([3.0, 0.0]).unwrap();
    assert_eq!((seam.parameter, seam.distance), (0.0, 2.0));
    // Radially: the distance is | |P| - 1 |, the nearest point P / |P|.
    for (x, y) in [(0.3, 0.4), (-2.0, 1.5), (0.01, -0.02), (-5e3, -1e3)] {
        let r: f64 = f64::hypot(x, y);
        let near = circle.nearest([x, y]).unwrap();
        assert!((near.distance - (r - 1.0).abs()).abs() <= 1e-12 * r.max(1.0));
        let [px, py] = near.point.position;
        assert!((px - x / r).abs() < 1e-12 && (py - y / r).abs() < 1e-12);
    }
}

#[test]
fn nearest_rejects_a_point_that_is_not_finite() {
    let curve = neutrospline::example1();
    assert_eq!(
        curve.nearest([1.0, f64::NAN]).unwrap_err().to_string(),
        "y = NaN is not a finite number (query coordinates must be finite)"
    );
    assert_eq!(
        curve.nearest([f64::INFINITY, 0.0]).unwrap_err(),
        NearestError::PointNotFinite {
            axis: 0,
            value: f64::INFINITY
        }
    );
    // Differences that overflow are reported, never a wrong answer.
    let far = curve.nearest([-1.7e308, 1.7e308]);
    assert!(far.is_ok() || far == Err(NearestError::Overflow));
}

fn any_curve_2d() -> impl Strategy<Value = AnyCurve<2>> {
    prop_oneof![
        strategies::bezier::<2>(1..=6).prop_map(AnyCurve::from),
        strategies::bspline::<2>(1..=5).prop_map(AnyCurve::from),
        strategies::nurbs::<2>(1..=4).prop_map(AnyCurve::from),
    ]
}

fn size(curve: &AnyCurve<2>) -> f64 {
    use neutrospline::Bounded;
    let b = curve.control_bounding_box();
    let [x, y] = [0, 1].map(|a| b.position[a].length());
    x.hypot(y).max(1e-300)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    /// The nearest distance is at most the distance to any sampled curve point (up to the tie
    /// tolerance), and is the distance to the reported point.
    #[test]
    fn nearest_is_no_farther_than_any_sample(
        curve in any_curve_2d(),
        x in -20.0..20.0f64,
        y in -20.0..20.0f64,
    ) {
        let near = curve.nearest([x, y]).unwrap();
        let domain = curve.domain();
        let slack = 1e-12 * size(&curve).max(near.distance);
        for k in 0..=400 {
            let t = neutrospline::uniform_parameter(k, 401, domain.clone());
            let [px, py] = curve.evaluate(t).unwrap().position;
            let d = (px - x).hypot(py - y);
            prop_assert!(near.distance <= d + slack, "t {t}: {d} < {}", near.distance);
        }
        let [px, py] = near.point.position;
        let exact = (px - x).hypot(py - y);
        prop_assert!((near.distance - exact).abs() <= 4.0 * f64::EPSILON * exact);
        prop_assert!(domain.start <= near.parameter && near.parameter <= domain.end);
    }

    /// A point of the curve is found at distance 0 (to rounding).
    #[test]
    fn nearest_to_a_curve_point_is_at_distance_zero(
        curve in any_curve_2d(),
        s in 0.0..=1.0f64,
    ) {
        let domain = curve.domain();
        let t = domain.start + s * (domain.end - domain.start);
        let point = curve.evaluate(t).unwrap().position;
        let near = curve.nearest(point).unwrap();
        prop_assert!(near.distance <= 1e-12 * size(&curve), "{}", near.distance);
    }
}

// ---------------------------------------------------------------------------------- surfaces

#[derive(Deserialize)]
struct SurfaceData {
    cases: Vec<SurfaceCase>,
}

#[derive(Deserialize)]
struct SurfaceCase {
    name: String,
    kind: String,
    rows: usize,
    cols: usize,
    degree_u: usize,
    degree_v: usize,
    scale: String,
    knots_u: Vec<String>,
    knots_v: Vec<String>,
    weights: Option<Vec<String>>,
    control_points: Vec<Vec<String>>,
    queries: Vec<SurfaceQuery>,
}

#[derive(Deserialize)]
struct SurfaceQuery {
    point: Vec<String>,
    u: String,
    v: String,
    distance: String,
    unique: bool,
}

fn surface(case: &SurfaceCase) -> Surface {
    let d = Degrees::new(0.5, 0.25, 0.125).unwrap();
    let points: Vec<ControlPoint<3>> = case
        .control_points
        .iter()
        .map(|row| {
            let v = numbers(row);
            ControlPoint::new([v[0], v[1], v[2]], d)
        })
        .collect();
    let ku = KnotVector::new(numbers(&case.knots_u), case.degree_u, case.rows).unwrap();
    let kv = KnotVector::new(numbers(&case.knots_v), case.degree_v, case.cols).unwrap();
    match case.kind.as_str() {
        "bezier-surface" => Surface::bezier(case.rows, case.cols, points).unwrap(),
        "bspline-surface" => Surface::bspline(case.rows, case.cols, points, ku, kv).unwrap(),
        "nurbs-surface" => Surface::nurbs(
            case.rows,
            case.cols,
            points,
            numbers(case.weights.as_ref().unwrap()),
            ku,
            kv,
        )
        .unwrap(),
        other => panic!("kind {other}"),
    }
}

#[test]
fn surface_nearest_matches_the_sampled_and_refined_reference() {
    let data: SurfaceData = serde_json::from_str(include_str!("../data/surface_nearest.json"))
        .expect("reference parses");
    let (mut queries, mut unique) = (0, 0);
    for case in &data.cases {
        let s = surface(case);
        let projector = s.projector();
        let scale: f64 = case.scale.parse().unwrap();
        for q in &case.queries {
            queries += 1;
            let p = numbers(&q.point);
            let point = [p[0], p[1], p[2]];
            let want_d: f64 = q.distance.parse().unwrap();
            let want = [q.u.parse::<f64>().unwrap(), q.v.parse::<f64>().unwrap()];
            let got = projector.nearest(point).unwrap();
            assert!(
                (got.distance - want_d).abs() <= 1e-12 * scale.max(want_d),
                "{} at {point:?}: distance {} want {want_d} ({:?} want {want:?})",
                case.name,
                got.distance,
                got.parameter
            );
            if q.unique {
                unique += 1;
                for c in 0..2 {
                    assert!(
                        (got.parameter[c] - want[c]).abs() <= 1e-9,
                        "{} at {point:?}: {:?} want {want:?}",
                        case.name,
                        got.parameter
                    );
                }
            }
            assert_eq!(
                got.point,
                s.evaluate(got.parameter[0], got.parameter[1]).unwrap()
            );
        }
    }
    assert!(
        queries >= 18 && unique >= 14,
        "{queries} queries, {unique} unique"
    );
}

#[test]
fn surface_nearest_on_the_quarter_cylinder_closed_forms() {
    let data: SurfaceData =
        serde_json::from_str(include_str!("../data/surface_nearest.json")).unwrap();
    let case = data
        .cases
        .iter()
        .find(|c| c.kind == "nurbs-surface")
        .unwrap();
    let cylinder = surface(case);
    // On the axis every point of the arc at that height is at distance 1: the smallest u.
    let axis = cylinder.nearest([0.0, 0.0, 0.75]).unwrap();
    assert_eq!(axis.parameter[0], 0.0);
    assert!((axis.parameter[1] - 0.375).abs() < 1e-12);
    assert!((axis.distance - 1.0).abs() < 1e-15);
    // Inside the quarter, at heights in [0, 2]: | sqrt(x^2 + y^2) - 1 |.
    for (x, y, z) in [
        (0.3, 0.4, 1.5),
        (2.0, 0.5, 0.25),
        (0.05, 0.02, 1.0),
        (40.0, 30.0, 2.0),
    ] {
        let r: f64 = f64::hypot(x, y);
        let near = cylinder.nearest([x, y, z]).unwrap();
        assert!(
            (near.distance - (r - 1.0).abs()).abs() <= 1e-12 * r.max(2.0),
            "{x} {y} {z}: {}",
            near.distance
        );
    }
    assert_eq!(
        cylinder
            .nearest([0.0, f64::NAN, 0.0])
            .unwrap_err()
            .to_string(),
        "y = NaN is not a finite number (query coordinates must be finite)"
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// The nearest distance of a surface is at most the distance to any sampled point.
    #[test]
    fn surface_nearest_is_no_farther_than_any_sample(
        s in prop_oneof![
            strategies::surface(SurfaceKind::Bezier, 1..=3),
            strategies::surface(SurfaceKind::BSpline, 1..=3),
            strategies::surface(SurfaceKind::Nurbs, 1..=2),
        ],
        x in -20.0..20.0f64,
        y in -20.0..20.0f64,
        z in -20.0..20.0f64,
    ) {
        let near = s.nearest([x, y, z]).unwrap();
        let [du, dv] = s.domain();
        let b = s.control_bounding_box();
        let size = b.position.iter().map(|i| i.length().powi(2)).sum::<f64>().sqrt();
        let slack = 1e-12 * size.max(near.distance);
        for i in 0..=30 {
            for j in 0..=30 {
                let u = neutrospline::uniform_parameter(i, 31, du.clone());
                let v = neutrospline::uniform_parameter(j, 31, dv.clone());
                let [px, py, pz] = s.evaluate(u, v).unwrap().position;
                let d = ((px - x).powi(2) + (py - y).powi(2) + (pz - z).powi(2)).sqrt();
                prop_assert!(near.distance <= d + slack, "({u}, {v}): {d} < {}", near.distance);
            }
        }
    }
}

/// Issue 22's report: a straight stretch drawn as a cubic the way drawing and font programs
/// write it (the first two control points 1e-13 apart, the last two equal). Both ends are
/// stationary, so the derivative's sign polynomial starts with rounding noise and falls at
/// first; the root finder took that for convergence and every query came back at an end,
/// 40 to 200 units away. The curve is the line `P0 + s (P3 - P0)` with `s = 3t^2 - 2t^3`
/// (to 1e-13), so the nearest point of `P0 + s (P3 - P0)` is at distance ~0 and at the `t`
/// solving that cubic (found here by bisection).
#[test]
fn nearest_on_a_cubic_with_stationary_ends_regression_issue_22() {
    let d = Degrees::new(0.5, 0.25, 0.125).unwrap();
    let pts = [
        [461.0, 123.0],
        [461.0 - 6e-14, 123.0 + 4e-14],
        [111.0, 319.0],
        [111.0, 319.0],
    ];
    let curve = Bezier::new(pts.iter().map(|p| ControlPoint::new(*p, d)).collect()).unwrap();
    let size = (350.0_f64).hypot(196.0);
    for k in 1..40 {
        let s = k as f64 / 40.0;
        let q = [461.0 - 350.0 * s, 123.0 + 196.0 * s];
        let (mut lo, mut hi) = (0.0_f64, 1.0_f64);
        for _ in 0..80 {
            let mid = 0.5 * (lo + hi);
            if 3.0 * mid * mid - 2.0 * mid * mid * mid < s {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        let near = curve.nearest(q).unwrap();
        assert!(near.distance <= 1e-12 * size, "s = {s}: {near:?}");
        assert!(
            (near.parameter - lo).abs() <= 1e-9,
            "s = {s}: {near:?}, t = {lo}"
        );
    }
}
