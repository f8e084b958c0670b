//! Property tests that relate the kinds: a single-span B-spline is the Bézier curve, a
//! single-span NURBS curve the rational Bézier curve, equal weights make a NURBS curve the
//! B-spline, the paper's degree curves project onto the crisp curve, knot vectors from
//! control polygons; the strategies generate valid data of every kind.

use crate::spline_common::*;
use neutrospline::ControlPolygon;

// ------------------------------------------------------------------------ across kinds

/// Bernstein basis value with a binomial from a product (small n only).
fn bernstein(n: usize, i: usize, t: f64) -> f64 {
    let c = (0..i).fold(1.0, |acc, k| acc * (n - k) as f64 / (k + 1) as f64);
    c * t.powi(i as i32) * (1.0 - t).powi((n - i) as i32)
}

fn interval() -> impl Strategy<Value = (f64, f64)> {
    (-10.0..=10.0f64, 0.01..=20.0f64).prop_map(|(a, len)| (a, a + len))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    #[test]
    fn single_segment_clamped_bspline_is_the_bezier_curve(
        points in prop::collection::vec(control_point::<3>(), 1..=12),
        (a, b) in interval(),
        s in strategies::parameter(),
    ) {
        let p = points.len() - 1;
        let bezier = Bezier::new(points.clone()).unwrap();
        let spline = BSpline::new(points.clone(), bezier_knots(p, a, b)).unwrap();
        let unit = BSpline::clamped_uniform(points.clone(), p).unwrap();
        let t = (a + s * (b - a)).clamp(a, b);
        let mm = scale(&points);
        let want = bezier.evaluate(s).unwrap();
        // On [0, 1] the de Boor and de Casteljau triangles are the same computation.
        prop_assert_eq!(unit.evaluate(s).unwrap(), want);
        // On [a, b] only the parameter's rounding differs.
        let got = spline.evaluate(t).unwrap();
        let slope = 2.0 * p as f64; // |C'| <= 2 p M on [0, 1]
        let dt = 4.0 * EPS * (a.abs().max(b.abs()) / (b - a) + 1.0);
        assert_close("single segment", &got, &want, p, mm, 16.0 + slope * dt / EPS)?;
        // Its one Bézier piece is the Bézier curve.
        let pieces = spline.to_bezier_segments();
        prop_assert_eq!(pieces.len(), 1);
        for i in 0..=p {
            assert_close("piece control point", &pieces[0].curve.control_point(i), &points[i], p, mm, 16.0)?;
        }
    }

    #[test]
    fn single_segment_nurbs_is_the_rational_bezier_curve(
        cps in prop::collection::vec((control_point::<2>(), weight()), 1..=10),
        s in 0.0..=1.0f64,
    ) {
        let (points, weights): (Vec<_>, Vec<_>) = cps.into_iter().unzip();
        let p = points.len() - 1;
        let curve = Nurbs::new(points.clone(), weights.clone(), bezier_knots(p, 0.0, 1.0)).unwrap();
        let got = curve.evaluate(s).unwrap();
        // The rational Bézier formula, summed directly.
        let den: f64 = (0..=p).map(|i| weights[i] * bernstein(p, i, s)).sum();
        let mm = scale(&points);
        for a in 0..2 {
            let num: f64 = (0..=p).map(|i| weights[i] * bernstein(p, i, s) * points[i].position[a]).sum();
            let tol = 1e-13 * mm * weight_ratio(&weights) * (p as f64 + 1.0);
            prop_assert!((got.position[a] - num / den).abs() <= tol, "axis {a}: {} vs {}", got.position[a], num / den);
        }
        for k in DegreeKind::ALL {
            let num: f64 = (0..=p).map(|i| weights[i] * bernstein(p, i, s) * points[i].degree(k)).sum();
            let tol = 1e-13 * weight_ratio(&weights) * (p as f64 + 1.0);
            prop_assert!((got.degree(k) - num / den).abs() <= tol);
        }
    }

    #[test]
    fn equal_weights_make_nurbs_the_bspline(
        (c, t) in with_parameter(bspline::<3>(0..=7), knots_of_bspline::<3>),
        w in weight(),
    ) {
        let mm = scale(&c.control_points());
        let p = c.degree();
        let want = c.evaluate(t).unwrap();
        let equal = Nurbs::new(c.control_points(), vec![w; c.len()], c.knots().clone()).unwrap();
        let ones = Nurbs::from_bspline(&c);
        prop_assert_eq!(ones.weights(), Some(&vec![1.0; c.len()][..]));
        for n in [&equal, &ones] {
            assert_close("equal weights", &n.evaluate(t).unwrap(), &want, p, mm, 8.0)?;
            let (d, e) = (n.derivative().evaluate(t).unwrap(), c.derivative().evaluate(t).unwrap());
            let h = c.knots().knots().windows(2).map(|w| w[1] - w[0]).filter(|&g| g > 0.0).fold(f64::INFINITY, f64::min);
            let bound = 2.0 * p as f64 / h;
            for (ch, (x, y)) in derivative_channels(&d).iter().zip(derivative_channels(&e)).enumerate() {
                let tol = 64.0 * (p as f64 + 1.0) * EPS * bound * if ch < 3 { mm } else { 1.0 };
                prop_assert!((x - y).abs() <= tol, "derivative channel {ch}: {x} vs {y}");
            }
        }
    }

    #[test]
    fn degree_curve_projects_onto_the_crisp_curve(
        (c, t) in with_parameter(bspline::<2>(0..=7), knots_of_bspline::<2>),
        weights in prop::collection::vec(weight(), 40),
    ) {
        let n = Nurbs::new(c.control_points(), weights[..c.len()].to_vec(), c.knots().clone()).unwrap();
        let (p, q) = (c.evaluate(t).unwrap(), n.evaluate(t).unwrap());
        for k in DegreeKind::ALL {
            // The lifted channel runs through the same convex steps: identical bits.
            let (lift, lift_n) = (c.degree_curve(k).evaluate(t).unwrap(), n.degree_curve(k).evaluate(t).unwrap());
            prop_assert_eq!(&lift.position[..2], &p.position[..]);
            prop_assert_eq!(lift.position[2], p.degree(k));
            prop_assert_eq!(lift.degrees, p.degrees);
            prop_assert_eq!(&lift_n.position[..2], &q.position[..]);
            prop_assert_eq!(lift_n.position[2], q.degree(k));
            prop_assert_eq!(lift_n.degrees, q.degrees);
            let any = AnyCurve::from(n.clone()).degree_curve(k);
            prop_assert_eq!(any.evaluate(t).unwrap(), lift_n);
        }
    }

    #[test]
    fn bspline_reproduces_linear_functions(
        (c, t) in with_parameter(bspline::<2>(1..=7), knots_of_bspline::<2>),
    ) {
        // Control x_i at the Greville abscissae (u_{i+1} + ... + u_{i+p}) / p: x(t) = t.
        let p = c.degree();
        let u = c.knots().knots();
        let points: Vec<_> = c.control_points().iter().enumerate().map(|(i, q)| {
            let g = u[i + 1..=i + p].iter().sum::<f64>() / p as f64;
            ControlPoint::new([g, q.position[1]], q.degrees)
        }).collect();
        let x = BSpline::new(points.clone(), c.knots().clone()).unwrap().evaluate(t).unwrap().position[0];
        let mm = scale(&points);
        prop_assert!((x - t).abs() <= 16.0 * (p as f64 + 1.0) * EPS * mm, "x({t}) = {x}");
    }

    #[test]
    fn knot_vectors_from_control_polygons_are_valid_and_clamped(
        p in 0usize..=6,
        raw in prop::collection::vec((prop::array::uniform3(coordinate()), 0usize..4), 1..14),
    ) {
        // Repeat some points (0 to 3 extra copies each): coincident consecutive points give
        // zero-length steps of the control polygon.
        let pts: Vec<[f64; 3]> = raw.iter().flat_map(|&(q, r)| core::iter::repeat_n(q, 1 + r)).collect();
        let n = pts.len();
        for (name, knots) in [
            ("chord_length", KnotVector::chord_length(p, &pts)),
            ("centripetal", KnotVector::centripetal(p, &pts)),
        ] {
            if n < p + 1 {
                prop_assert_eq!(knots.unwrap_err(), KnotError::TooFewControlPoints { count: n, degree: p });
                continue;
            }
            let k = match knots {
                Ok(k) => k,
                Err(e) => { prop_assert!(false, "{name}(p = {p}, {n} points): {e}"); unreachable!() }
            };
            prop_assert_eq!(k.degree(), p);
            prop_assert_eq!(k.control_count(), n);
            prop_assert!(k.is_clamped(), "{name}: not clamped: {:?}", k.knots());
            prop_assert_eq!(k.domain(), 0.0..1.0);
            prop_assert!(KnotVector::new(k.knots().to_vec(), p, n).is_ok());
            // And the curve on them is a curve.
            let cps = pts.iter().map(|&q| ControlPoint::new(q, Degrees::new(0.5, 0.5, 0.5).unwrap())).collect();
            let curve = BSpline::new(cps, k).unwrap();
            prop_assert_eq!(curve.start().unwrap().position, pts[0]);
            prop_assert_eq!(curve.end().unwrap().position, pts[n - 1]);
        }
    }

    #[test]
    fn chord_length_follows_the_control_polygon(
        pts in prop::collection::vec(prop::array::uniform2(coordinate()), 2..10),
    ) {
        // Degree 1: the interior knots are the normalised cumulative chord lengths.
        let k = KnotVector::chord_length(1, &pts).unwrap();
        let steps: Vec<f64> = pts.windows(2).map(|w| (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1])).collect();
        let total: f64 = steps.iter().sum();
        prop_assume!(steps.iter().all(|&s| s > 1e-9 * total));
        let mut acc = 0.0;
        for (j, s) in steps[..steps.len() - 1].iter().enumerate() {
            acc += s;
            prop_assert!((k.knots()[j + 2] - acc / total).abs() <= 1e-14, "knot {}", j + 2);
        }
    }
}

#[test]
fn strategies_generate_valid_knots_of_every_kind() {
    // The generators reach clamped and unclamped vectors, repeated interior knots and
    // discontinuities (interior multiplicity p + 1).
    use proptest::strategy::ValueTree;
    use proptest::test_runner::TestRunner;
    let mut runner = TestRunner::deterministic();
    let (mut clamped, mut unclamped, mut repeated, mut jump) = (0, 0, 0, 0);
    for _ in 0..400 {
        let k = knot_vector(3, 9).new_tree(&mut runner).unwrap().current();
        if k.is_clamped() {
            clamped += 1;
        } else {
            unclamped += 1;
        }
        let m = k
            .interior_breakpoints()
            .iter()
            .map(|&b| k.multiplicity(b))
            .max()
            .unwrap_or(0);
        if m >= 2 {
            repeated += 1;
        }
        if m == 4 {
            jump += 1;
        }
    }
    assert!(
        clamped > 40 && unclamped > 40 && repeated > 40 && jump > 10,
        "{clamped} clamped, {unclamped} unclamped, {repeated} repeated, {jump} discontinuous"
    );
    let _ = degrees();
}
