//! Property tests of neutrosophic NURBS curves (`Nurbs<2>`, `Nurbs<3>`): every check of
//! `spline_common` with weights over several orders of magnitude; high degrees; the exact
//! circle; weight errors.

use crate::spline_common::*;

curve_properties!(
    nurbs_2d,
    Nurbs<2>,
    2,
    nurbs::<2>(0..=7),
    knots_of_nurbs::<2>,
    CurveKind::Nurbs
);
curve_properties!(
    nurbs_3d,
    Nurbs<3>,
    3,
    nurbs::<3>(0..=7),
    knots_of_nurbs::<3>,
    CurveKind::Nurbs
);

/// High degrees (8 to 15): the operations whose rounding grows with the degree.
mod high_degree {
    use super::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(24))]

        #[test]
        fn nurbs_operations_leave_the_curve_unchanged(
            (c, ts) in with_parameters(nurbs::<3>(8..=15), knots_of_nurbs::<3>, 2..5),
        ) {
            check_degree_bounds(&c, ts[0])?;
            check_insertion(&c, ts[0], &ts[1..])?;
            check_elevation(&c, &ts)?;
            check_pieces(&c, &ts)?;
        }
    }
}

// ------------------------------------------------------------------------ the circle

fn circle_weight() -> f64 {
    core::f64::consts::FRAC_1_SQRT_2
}

fn quarter_circle() -> Nurbs<2> {
    let d = |t: f64| Degrees::new(t, 0.5, 1.0 - t).unwrap();
    Nurbs::new(
        vec![
            ControlPoint::new([1.0, 0.0], d(0.0)),
            ControlPoint::new([1.0, 1.0], d(1.0)),
            ControlPoint::new([0.0, 1.0], d(0.5)),
        ],
        vec![1.0, circle_weight(), 1.0],
        KnotVector::clamped_uniform(2, 3).unwrap(),
    )
    .unwrap()
}

fn full_circle() -> Nurbs<2> {
    let xy = [
        [1.0, 0.0],
        [1.0, 1.0],
        [0.0, 1.0],
        [-1.0, 1.0],
        [-1.0, 0.0],
        [-1.0, -1.0],
        [0.0, -1.0],
        [1.0, -1.0],
        [1.0, 0.0],
    ];
    let points = xy
        .iter()
        .enumerate()
        .map(|(i, &q)| ControlPoint::new(q, Degrees::new(i as f64 / 8.0, 0.25, 0.75).unwrap()))
        .collect();
    let w = circle_weight();
    let knots = vec![
        0.0, 0.0, 0.0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1.0, 1.0, 1.0,
    ];
    Nurbs::new(
        points,
        vec![1.0, w, 1.0, w, 1.0, w, 1.0, w, 1.0],
        KnotVector::new(knots, 2, 9).unwrap(),
    )
    .unwrap()
}

fn assert_on_circle(c: &Nurbs<2>, t: f64, tol: f64) -> Result<(), TestCaseError> {
    let [x, y] = c.evaluate(t).unwrap().position;
    let r = x.hypot(y);
    prop_assert!((r - 1.0).abs() <= tol, "t = {t}: |C| - 1 = {:e}", r - 1.0);
    // The tangent is perpendicular to the radius.
    let d = c.derivative().evaluate(t).unwrap().position;
    let dot = (d[0] * x + d[1] * y) / d[0].hypot(d[1]);
    prop_assert!(
        dot.abs() <= 64.0 * EPS,
        "t = {t}: tangent . radius = {dot:e}"
    );
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn nurbs_quarter_circle_is_exactly_on_the_circle(t in strategies::parameter()) {
        assert_on_circle(&quarter_circle(), t, 2.0 * EPS)?;
        assert_on_circle(&full_circle(), t, 2.0 * EPS)?;
    }

    #[test]
    fn circle_stays_a_circle_under_insertion_and_elevation(
        t in strategies::parameter(),
        u in 0.0..=1.0f64,
    ) {
        for c in [quarter_circle(), full_circle()] {
            let refined = if c.knots().multiplicity(u) < 3 { c.insert_knot(u).unwrap() } else { c.clone() };
            let elevated = c.elevate();
            let twice = elevated.elevate();
            for e in [&refined, &elevated, &twice] {
                assert_on_circle(e, t, 8.0 * EPS)?;
            }
        }
    }
}

#[test]
fn quarter_circle_midpoint_and_arc() {
    let c = quarter_circle();
    let [x, y] = c.evaluate(0.5).unwrap().position;
    assert_eq!([x, y], [circle_weight(), circle_weight()]);
    // The arc angle is 2 atan(t / (1 + (sqrt 2 - 1)(1 - t)))... check monotone angle instead:
    let mut last = -1.0;
    for k in 0..=64 {
        let [x, y] = c.evaluate(k as f64 / 64.0).unwrap().position;
        let angle = y.atan2(x);
        assert!(angle > last, "angle decreases at {k}");
        last = angle;
    }
    assert!((last - core::f64::consts::FRAC_PI_2).abs() < 1e-15);
    let f = full_circle();
    for (t, want) in [
        (0.0, [1.0, 0.0]),
        (0.25, [0.0, 1.0]),
        (0.5, [-1.0, 0.0]),
        (0.75, [0.0, -1.0]),
        (1.0, [1.0, 0.0]),
    ] {
        assert_eq!(f.evaluate(t).unwrap().position, want, "t = {t}");
    }
}

#[test]
fn nurbs_weight_errors_name_the_point() {
    let d = Degrees::new(0.1, 0.2, 0.3).unwrap();
    let pts = vec![ControlPoint::new([0.0, 0.0], d); 3];
    let k = KnotVector::clamped_uniform(2, 3).unwrap();
    let err = |w: Vec<f64>| Nurbs::new(pts.clone(), w, k.clone()).unwrap_err();
    assert_eq!(
        err(vec![1.0, 0.0, 1.0]).to_string(),
        "control point 1: weight = 0 is not a positive finite number (NURBS weights must be > 0)"
    );
    assert_eq!(
        err(vec![1.0, 1.0, -2.5]).to_string(),
        "control point 2: weight = -2.5 is not a positive finite number (NURBS weights must be > 0)"
    );
    assert!(matches!(
        err(vec![f64::NAN, 1.0, 1.0]),
        CurveError::WeightNotPositive { index: 0, .. }
    ));
    assert!(matches!(
        err(vec![1.0, f64::INFINITY, 1.0]),
        CurveError::WeightNotPositive { index: 1, .. }
    ));
    assert_eq!(
        err(vec![1.0, 1.0]).to_string(),
        "2 weights for 3 control points (one weight per control point)"
    );
    // Knots for another number of control points.
    assert_eq!(
        Nurbs::new(
            pts.clone(),
            vec![1.0; 3],
            KnotVector::clamped_uniform(2, 4).unwrap()
        )
        .unwrap_err()
        .to_string(),
        "knot vector has 7 knots, expected 6 (number of control points + degree + 1)"
    );
    assert_eq!(
        BSpline::<2>::new(vec![], KnotVector::clamped_uniform(0, 1).unwrap())
            .unwrap_err()
            .to_string(),
        "no control points (a curve needs at least one)"
    );
}
