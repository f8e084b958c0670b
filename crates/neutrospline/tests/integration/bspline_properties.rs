//! Property tests of neutrosophic B-spline curves (`BSpline<2>`, `BSpline<3>`): every check of
//! `spline_common` over knot vectors that are clamped or unclamped, with repeated interior
//! knots up to multiplicity `p` and sometimes `p + 1`; high degrees; knot errors.

use crate::spline_common::*;

curve_properties!(
    bspline_2d,
    BSpline<2>,
    2,
    bspline::<2>(0..=7),
    knots_of_bspline::<2>,
    CurveKind::BSpline
);
curve_properties!(
    bspline_3d,
    BSpline<3>,
    3,
    bspline::<3>(0..=7),
    knots_of_bspline::<3>,
    CurveKind::BSpline
);

/// High degrees (8 to 15): the operations whose rounding grows with the degree.
mod high_degree {
    use super::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(24))]

        #[test]
        fn bspline_operations_leave_the_curve_unchanged(
            (c, ts) in with_parameters(bspline::<2>(8..=15), knots_of_bspline::<2>, 2..5),
        ) {
            check_degree_bounds(&c, ts[0])?;
            check_insertion(&c, ts[0], &ts[1..])?;
            check_elevation(&c, &ts)?;
            check_pieces(&c, &ts)?;
        }
    }
}

#[test]
fn elevation_of_many_spans_stays_accurate() {
    // Regression: elevation by knot removal chained every new control point to its
    // neighbours, and the error grew exponentially with the number of spans: a uniform
    // degree-6 B-spline with 40 control points came back off by 1e10 times its size.
    let d = Degrees::new(0.25, 0.5, 0.75).unwrap();
    for p in [5, 6, 7, 12] {
        let points: Vec<_> = (0..40)
            .map(|i| ControlPoint::new([((i * 7919) % 13) as f64 - 6.0, i as f64], d))
            .collect();
        let curve = BSpline::clamped_uniform(points.clone(), p).unwrap();
        let weights = (0..40).map(|i| [0.5, 2.0, 1.0][i % 3]).collect();
        let rational = Nurbs::new(points, weights, curve.knots().clone()).unwrap();
        let (e, en) = (curve.elevate(), rational.elevate());
        for k in 0..=200 {
            let t = k as f64 / 200.0;
            for (got, want) in [
                (e.evaluate(t).unwrap(), curve.evaluate(t).unwrap()),
                (en.evaluate(t).unwrap(), rational.evaluate(t).unwrap()),
            ] {
                for a in 0..2 {
                    let err = (got.position[a] - want.position[a]).abs();
                    assert!(err <= 1e-12 * 40.0, "p = {p}, t = {t}: error {err:e}");
                }
            }
        }
    }
}

#[test]
fn knot_vector_errors_name_the_problem() {
    assert_eq!(
        KnotVector::new(vec![0.0, 0.0, 0.5, 0.4, 1.0, 1.0], 1, 4)
            .unwrap_err()
            .to_string(),
        "knot 3 = 0.4 is less than knot 2 = 0.5 (knots must be non-decreasing)"
    );
    assert_eq!(
        KnotVector::new(vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0], 2, 4)
            .unwrap_err()
            .to_string(),
        "knot vector has 6 knots, expected 7 (number of control points + degree + 1)"
    );
    assert_eq!(
        KnotVector::new(vec![0.0, 0.0, 0.0, 0.5, 0.5, 0.5, 0.5, 1.0, 1.0, 1.0], 2, 7)
            .unwrap_err()
            .to_string(),
        "knot 0.5 appears 4 times, more than degree + 1 = 3"
    );
    assert_eq!(
        KnotVector::new(vec![0.0, 1.0, 1.0, 1.0, 2.0], 1, 3)
            .unwrap_err()
            .to_string(),
        "knot 1 appears 3 times, more than degree + 1 = 2"
    );
    assert_eq!(
        KnotVector::new(vec![0.0, 0.0, f64::INFINITY, 1.0], 1, 2)
            .unwrap_err()
            .to_string(),
        "knot 2 = inf is not a finite number"
    );
    assert_eq!(
        KnotVector::new(vec![0.0, 1.0, 1.0, 2.0], 1, 2)
            .unwrap_err()
            .to_string(),
        "the domain [knot 1, knot 2] = [1, 1] is empty (the knots there must differ)"
    );
    assert_eq!(
        KnotVector::clamped_uniform(3, 2).unwrap_err().to_string(),
        "2 control points are too few for degree 3 (need at least degree + 1 = 4)"
    );
    // A knot of multiplicity p + 1 inside the domain is allowed (a discontinuity).
    assert!(KnotVector::new(vec![0.0, 0.0, 0.5, 0.5, 1.0, 1.0], 1, 4).is_ok());
}

#[test]
fn insertion_errors_name_the_knot() {
    let d = Degrees::new(0.1, 0.2, 0.3).unwrap();
    let pts: Vec<_> = (0..4)
        .map(|i| ControlPoint::new([i as f64, 0.0], d))
        .collect();
    let c = BSpline::clamped_uniform(pts, 2).unwrap();
    assert_eq!(
        c.insert_knot(1.5).unwrap_err().to_string(),
        "parameter 1.5 is outside the domain [0, 1]"
    );
    assert_eq!(
        c.insert_knot(0.0).unwrap_err().to_string(),
        "knot 0 appears 4 times, more than degree + 1 = 3"
    );
    let twice = c.insert_knot(0.5).unwrap().insert_knot(0.5).unwrap();
    assert_eq!(twice.knots().multiplicity(0.5), 3);
    assert!(matches!(
        twice.insert_knot(0.5),
        Err(KnotError::MultiplicityTooHigh {
            multiplicity: 4,
            max: 3,
            ..
        })
    ));
}
