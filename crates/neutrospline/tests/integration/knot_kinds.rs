//! Unclamped, uniform (`KnotVector::uniform`) and periodic (`BSpline::periodic`,
//! `Nurbs::periodic`) curves against scipy's `BSpline` (periodic ones with
//! `extrapolate="periodic"`), on 18 random curves of degrees 1 to 5, half of them NURBS (data:
//! tests/data/knot_kinds_scipy.json, made by scripts/reference/make_knot_kinds_reference.py).
//! The knot vectors the library builds equal those the script builds from the definition to
//! 1e-15 of the period; the rows of the curve and of its first two derivatives agree at both
//! domain ends and at random and knot parameters within 1e-12 of their scale. The periodic
//! curves close: the end of the domain gives the start (the peers' most common periodic bug).

use neutrospline::{AnyCurve, BSpline, ControlPoint, Degrees, DynCurve, KnotVector, Nurbs};
use serde::Deserialize;

use crate::reference_common::read_data;

#[derive(Deserialize)]
struct Case {
    kind: String,
    rational: bool,
    degree: usize,
    knots: Vec<f64>,
    breakpoints: Option<Vec<f64>>,
    rows: Vec<Vec<f64>>,
    weights: Option<Vec<f64>>,
    t: Vec<f64>,
    values: Vec<Vec<f64>>,
    d1: Vec<Vec<f64>>,
    d2: Vec<Vec<f64>>,
}

#[derive(Deserialize)]
struct File {
    cases: Vec<Case>,
}

fn points(rows: &[Vec<f64>]) -> Vec<ControlPoint<2>> {
    rows.iter()
        .map(|r| ControlPoint::new([r[0], r[1]], Degrees::new(r[2], r[3], r[4]).unwrap()))
        .collect()
}

fn build(case: &Case) -> AnyCurve<2> {
    let p = case.degree;
    let pts = points(&case.rows);
    match (case.breakpoints.as_deref(), &case.weights) {
        (Some(b), None) => BSpline::periodic(pts, p, b).unwrap().into(),
        (Some(b), Some(w)) => Nurbs::periodic(pts, w.clone(), p, b).unwrap().into(),
        (None, weights) => {
            let knots = if case.kind == "uniform" {
                KnotVector::uniform(p, pts.len()).unwrap()
            } else {
                KnotVector::new(case.knots.clone(), p, pts.len()).unwrap()
            };
            match weights {
                None => BSpline::new(pts, knots).unwrap().into(),
                Some(w) => Nurbs::new(pts, w.clone(), knots).unwrap().into(),
            }
        }
    }
}

fn scale(rows: &[Vec<f64>]) -> f64 {
    rows.iter().flatten().fold(1.0f64, |m, v| m.max(v.abs()))
}

#[test]
fn unclamped_and_periodic_curves_match_scipy() {
    let text = read_data("knot_kinds_scipy.json", "make_knot_kinds_reference.py");
    let cases = serde_json::from_str::<File>(&text).unwrap().cases;
    assert_eq!(cases.len(), 18);
    let mut kinds = std::collections::BTreeSet::new();
    for (index, case) in cases.iter().enumerate() {
        kinds.insert((case.kind.clone(), case.rational));
        let curve = build(case);
        let knots = curve.knots().unwrap().knots();
        let period = knots[knots.len() - 1] - knots[0];
        assert_eq!(knots.len(), case.knots.len(), "case {index}");
        for (k, (a, b)) in knots.iter().zip(&case.knots).enumerate() {
            assert!(
                (a - b).abs() <= 1e-15 * period.max(1.0),
                "case {index} knot {k}: {a} vs {b}"
            );
        }
        assert_eq!(
            curve.periodic_count(),
            case.breakpoints.as_ref().map(|b| b.len() - 1),
            "case {index}"
        );
        let dynamic = DynCurve::from(curve);
        let derivatives = [dynamic.nth_derivative(1), dynamic.nth_derivative(2)];
        for (order, (want, derivative)) in [&case.d1, &case.d2]
            .into_iter()
            .zip(&derivatives)
            .enumerate()
        {
            let s = scale(want).max(scale(&case.values));
            for (t, row) in case.t.iter().zip(want) {
                // At a knot of multiplicity m the derivatives of order r > p - m jump: the two
                // one-sided values differ (scipy takes the right one, and wraps the end of a
                // periodic domain to its start; we take the left one at the end).
                let multiplicity = case.knots.iter().filter(|&&k| k == *t).count();
                if order + 1 + multiplicity > case.degree {
                    continue;
                }
                let got = derivative.evaluate_row(*t).unwrap();
                for (c, (g, w)) in got.iter().zip(row).enumerate() {
                    assert!(
                        (g - w).abs() <= 1e-12 * s,
                        "case {index} ({} {}, p = {}) derivative {} at t = {t}, channel {c}: {g} vs {w}",
                        case.kind, if case.rational { "nurbs" } else { "bspline" }, case.degree, order + 1
                    );
                }
            }
        }
        let s = scale(&case.values);
        for (t, row) in case.t.iter().zip(&case.values) {
            let got = dynamic.evaluate_row(*t).unwrap();
            for (c, (g, w)) in got.iter().zip(row).enumerate() {
                assert!(
                    (g - w).abs() <= 1e-12 * s,
                    "case {index} ({}) at t = {t}, channel {c}: {g} vs {w}",
                    case.kind
                );
            }
        }
        if case.breakpoints.is_some() {
            let domain = dynamic.domain();
            let (start, end) = (
                dynamic.evaluate_row(domain.start).unwrap(),
                dynamic.evaluate_row(domain.end).unwrap(),
            );
            for (a, b) in start.iter().zip(&end) {
                assert!(
                    (a - b).abs() <= 1e-13 * s,
                    "case {index}: the curve does not close"
                );
            }
        }
    }
    assert_eq!(
        kinds.len(),
        6,
        "every knot kind, B-spline and NURBS: {kinds:?}"
    );
}

mod properties {
    //! Periodic curves under the operations that keep them periodic, against the original:
    //! insertion then removal gives it back, refinement and reversal keep the curve, and
    //! every result is periodic again (to the last bit of its knots) with valid degrees.

    use neutrospline::strategies::{control_point, weight};
    use neutrospline::{AnyCurve, BSpline, ControlPolygon, Evaluate, Nurbs};
    use proptest::prelude::*;

    /// A periodic B-spline or NURBS curve of degree 1 to 6 with 1 to `p + 6` distinct
    /// control points (fewer than the degree too: the copies of a knot then share control
    /// points) over random breakpoints.
    fn periodic() -> impl Strategy<Value = AnyCurve<2>> {
        (1usize..=6, 0usize..=12, any::<bool>()).prop_flat_map(|(p, size, rational)| {
            let n = 1 + size % (p + 6);
            (
                prop::collection::vec(control_point::<2>(), n),
                prop::collection::vec(0.02f64..1.0, n),
                prop::collection::vec(weight(), n),
                Just((p, rational)),
            )
                .prop_map(|(points, steps, weights, (p, rational))| {
                    let mut breakpoints = vec![0.0];
                    for s in steps {
                        breakpoints.push(breakpoints.last().unwrap() + s);
                    }
                    if rational {
                        Nurbs::periodic(points, weights, p, &breakpoints)
                            .unwrap()
                            .into()
                    } else {
                        BSpline::periodic(points, p, &breakpoints).unwrap().into()
                    }
                })
        })
    }

    /// The largest difference of `a(t)` and `b(map(t))` over 201 parameters, in every
    /// channel, relative to the size of `a`'s control positions (at least 1).
    fn max_gap(a: &AnyCurve<2>, b: &AnyCurve<2>, map: impl Fn(f64) -> f64) -> f64 {
        let scale = a
            .control_points()
            .iter()
            .flat_map(|p| p.position)
            .fold(1.0f64, |m, v| m.max(v.abs()));
        let domain = a.domain();
        (0..=200)
            .map(|k| {
                let t = (domain.start + (domain.end - domain.start) * f64::from(k) / 200.0)
                    .min(domain.end);
                let other = b.domain();
                let (x, y) = (
                    a.evaluate(t).unwrap(),
                    b.evaluate(map(t).clamp(other.start, other.end)).unwrap(),
                );
                let mut gap = (x.position[0] - y.position[0])
                    .abs()
                    .max((x.position[1] - y.position[1]).abs());
                for (d, e) in x.degrees.to_array().iter().zip(y.degrees.to_array()) {
                    gap = gap.max((d - e).abs());
                }
                gap / scale
            })
            .fold(0.0, f64::max)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(128))]

        #[test]
        fn insertion_then_removal_is_the_original(curve in periodic(), at in 0.01f64..0.99, times in 1usize..=2) {
            let n = curve.periodic_count().unwrap();
            let domain = curve.domain();
            let u = domain.start + (domain.end - domain.start) * at;
            let p = curve.degree();
            let times = times.min(p.saturating_sub(curve.knots().unwrap().multiplicity(u)).max(1));
            prop_assume!(curve.knots().unwrap().multiplicity(u) + times <= p);
            let inserted = curve.with_knots_inserted(&vec![u; times]).unwrap();
            prop_assert_eq!(inserted.periodic_count(), Some(n + times));
            prop_assert!(max_gap(&curve, &inserted, |t| t) < 1e-12);
            let removal = inserted.without_knot(u, times, 1e-9).unwrap();
            prop_assert_eq!(removal.removed, times);
            let back = removal.curve;
            prop_assert_eq!(back.periodic_count(), Some(n));
            prop_assert_eq!(back.knots(), curve.knots());
            for (a, b) in back.control_points().iter().zip(curve.control_points()) {
                for (x, y) in a.position.iter().zip(b.position) {
                    prop_assert!((x - y).abs() < 1e-9, "{a:?} {b:?}");
                }
            }
            prop_assert!(max_gap(&curve, &back, |t| t) < 1e-9);
        }

        #[test]
        fn refinement_and_reversal_keep_it_periodic(curve in periodic()) {
            let n = curve.periodic_count().unwrap();
            let refined = curve.refined(2);
            prop_assert!(refined.periodic_count().unwrap() >= n);
            prop_assert!(max_gap(&curve, &refined, |t| t) < 1e-12);
            let domain = curve.domain();
            let reversed = curve.reversed();
            prop_assert_eq!(reversed.periodic_count(), Some(n));
            prop_assert!(max_gap(&curve, &reversed, |t| domain.start + domain.end - t) < 1e-12);
            let moved = curve.reparametrized(-3.0, 5.0).unwrap();
            prop_assert_eq!(moved.periodic_count(), Some(n));
            // The curve closes: its start and end agree.
            let (a, b) = (curve.evaluate(domain.start).unwrap(), curve.evaluate(domain.end).unwrap());
            prop_assert!((a.position[0] - b.position[0]).abs() < 1e-12);
            prop_assert!((a.degrees.truth() - b.degrees.truth()).abs() < 1e-12);
        }
    }
}
