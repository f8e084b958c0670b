//! Derivatives of orders 1 to 3 of every curve kind and the mixed partials of total order 1
//! to 3 of every surface kind, against exact symbolic differentiation.
//!
//! `tests/data/higher_derivatives.json` is produced by
//! `scripts/reference/make_higher_derivative_reference.py`: sympy differentiates the explicit
//! basis sums (Bernstein, Cox-de Boor, the rational quotient for NURBS) on the exact rational
//! values of the double inputs and rounds once. Tolerance: `1e-11` times the largest
//! magnitude of the case's reference values of that order (at least 1), which the rounding of
//! de Boor's algorithm and Leibniz's rule stays far below; a wrong binomial, sign or order
//! misses it by many orders of magnitude.

use neutrospline::{
    AnyCurve, BSpline, Bezier, ControlPoint, Degrees, Derivative, DerivativeValue, Evaluate,
    KnotVector, Nurbs, Surface,
};
use serde::Deserialize;

#[derive(Deserialize)]
struct Data {
    curves: Vec<CurveCase>,
    surfaces: Vec<SurfaceCase>,
}

#[derive(Deserialize)]
struct CurveCase {
    name: String,
    kind: String,
    degree: usize,
    dimension: usize,
    knots: Option<Vec<String>>,
    weights: Option<Vec<String>>,
    control_points: Vec<Vec<String>>,
    evaluations: Vec<CurveEvaluation>,
}

#[derive(Deserialize)]
struct CurveEvaluation {
    t: String,
    d1: Vec<String>,
    d2: Vec<String>,
    d3: Vec<String>,
}

#[derive(Deserialize)]
struct SurfaceCase {
    name: String,
    kind: String,
    rows: usize,
    cols: usize,
    degree_u: usize,
    degree_v: usize,
    knots_u: Vec<String>,
    knots_v: Vec<String>,
    weights: Option<Vec<String>>,
    control_points: Vec<Vec<String>>,
    evaluations: Vec<SurfaceEvaluation>,
}

#[derive(Deserialize)]
struct SurfaceEvaluation {
    u: String,
    v: String,
    partials: std::collections::BTreeMap<String, Vec<String>>,
}

/// Parsed with `str::parse` (correctly rounded), as the model files are.
fn numbers(texts: &[String]) -> Vec<f64> {
    texts.iter().map(|s| s.parse().expect(s)).collect()
}

fn data() -> Data {
    let text = include_str!("../data/higher_derivatives.json");
    serde_json::from_str(text).expect("reference data parses")
}

fn control_points<const D: usize>(rows: &[Vec<String>]) -> Vec<ControlPoint<D>> {
    rows.iter()
        .map(|row| {
            let v = numbers(row);
            let mut position = [0.0; D];
            position.copy_from_slice(&v[..D]);
            ControlPoint::new(position, Degrees::new(v[D], v[D + 1], v[D + 2]).unwrap())
        })
        .collect()
}

fn curve<const D: usize>(case: &CurveCase) -> AnyCurve<D> {
    let points = control_points::<D>(&case.control_points);
    let knots = || {
        KnotVector::new(
            numbers(case.knots.as_ref().unwrap()),
            case.degree,
            points.len(),
        )
        .unwrap()
    };
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
        other => panic!("unknown kind {other}"),
    }
}

fn channels<const D: usize>(d: &DerivativeValue<D>) -> Vec<f64> {
    let mut v = d.position.to_vec();
    v.extend([d.truth, d.indeterminacy, d.falsity]);
    v
}

/// `1e-11` times the largest magnitude among `values` (at least 1).
fn tolerance<'a>(values: impl Iterator<Item = &'a Vec<String>>) -> f64 {
    let scale = values
        .flat_map(|v| numbers(v))
        .fold(1.0_f64, |m, x| m.max(x.abs()));
    1e-11 * scale
}

fn check_curve<const D: usize>(case: &CurveCase) -> usize {
    let c = curve::<D>(case);
    let d1 = c.derivative();
    let d2 = d1.derivative();
    let d3 = d2.derivative();
    let mut checked = 0;
    for (order, derivative) in [(1, &d1), (2, &d2), (3, &d3)] {
        let want_of = |e: &CurveEvaluation| match order {
            1 => e.d1.clone(),
            2 => e.d2.clone(),
            _ => e.d3.clone(),
        };
        let wants: Vec<Vec<String>> = case.evaluations.iter().map(want_of).collect();
        let tol = tolerance(wants.iter());
        for (e, want) in case.evaluations.iter().zip(&wants) {
            let t: f64 = e.t.parse().unwrap();
            let got = channels(&derivative.evaluate(t).unwrap());
            for (channel, (g, w)) in got.iter().zip(numbers(want)).enumerate() {
                assert!(
                    (g - w).abs() <= tol,
                    "{}: order {order} at t = {t}, channel {channel}: got {g}, want {w} (tolerance {tol:e})",
                    case.name
                );
                checked += 1;
            }
        }
    }
    checked
}

#[test]
fn curve_derivatives_of_orders_1_to_3_match_symbolic_differentiation() {
    let data = data();
    let mut checked = 0;
    let mut kinds = std::collections::BTreeSet::new();
    for case in &data.curves {
        kinds.insert(case.kind.clone());
        checked += match case.dimension {
            2 => check_curve::<2>(case),
            3 => check_curve::<3>(case),
            d => panic!("dimension {d}"),
        };
    }
    assert_eq!(kinds.len(), 3, "every curve kind is covered: {kinds:?}");
    assert!(checked > 300, "{checked} values checked");
}

fn surface(case: &SurfaceCase) -> Surface {
    let points = control_points::<3>(&case.control_points);
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
        other => panic!("unknown kind {other}"),
    }
}

#[test]
fn surface_mixed_partials_of_total_order_1_to_3_match_symbolic_differentiation() {
    let data = data();
    let mut checked = 0;
    let mut kinds = std::collections::BTreeSet::new();
    for case in &data.surfaces {
        kinds.insert(case.kind.clone());
        let s = surface(case);
        for order in 1..=3 {
            let keys: Vec<String> = (0..=order)
                .map(|j| format!("{}{}", "u".repeat(order - j), "v".repeat(j)))
                .collect();
            let tol = tolerance(
                case.evaluations
                    .iter()
                    .flat_map(|e| keys.iter().map(|k| &e.partials[k])),
            );
            for e in &case.evaluations {
                let (u, v): (f64, f64) = (e.u.parse().unwrap(), e.v.parse().unwrap());
                let got = s.mixed_partials(u, v, order).unwrap();
                assert_eq!(got.len(), order + 1);
                if order == 1 {
                    // The first-order partials agree with `partial_derivatives`.
                    let first = s.partial_derivatives(u, v).unwrap();
                    for (a, b) in [(&got[0], &first.du), (&got[1], &first.dv)] {
                        for (x, y) in channels(a).iter().zip(channels(b)) {
                            assert!((x - y).abs() <= tol, "{}: {x} vs {y}", case.name);
                        }
                    }
                }
                for (key, value) in keys.iter().zip(&got) {
                    let want = numbers(&e.partials[key]);
                    for (channel, (g, w)) in channels(value).iter().zip(&want).enumerate() {
                        assert!(
                            (g - w).abs() <= tol,
                            "{}: d_{key} at ({u}, {v}), channel {channel}: got {g}, want {w} (tolerance {tol:e})",
                            case.name
                        );
                        checked += 1;
                    }
                }
            }
        }
    }
    assert_eq!(kinds.len(), 3, "every surface kind is covered: {kinds:?}");
    assert!(checked > 500, "{checked} values checked");
}

#[test]
fn surface_mixed_partials_order_0_is_the_point() {
    let data = data();
    let s = surface(&data.surfaces[1]);
    let p = neutrospline::EvaluateSurface::evaluate(&s, 0.3, 0.2).unwrap();
    let zero = s.mixed_partials(0.3, 0.2, 0).unwrap();
    assert_eq!(zero.len(), 1);
    for (a, b) in zero[0].position.iter().zip(p.position) {
        assert!((a - b).abs() < 1e-15);
    }
    assert!((zero[0].truth - p.degrees.truth()).abs() < 1e-15);
    assert!(s.mixed_partials(1.5, 0.2, 2).is_err());
}
