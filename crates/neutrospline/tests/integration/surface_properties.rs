//! Property tests of tensor-product surfaces (Bézier, B-spline, NURBS): degrees within the
//! local control range, corners, curves of curves, iso-parameter curves, partial derivatives,
//! kinds that agree; surface errors.

use crate::spline_common::*;

// ------------------------------------------------------------------------ surfaces

fn surfaces(kind: SurfaceKind) -> impl Strategy<Value = Surface> {
    strategies::surface(kind, 0..=4)
}

fn any_surface() -> impl Strategy<Value = Surface> {
    prop_oneof![
        surfaces(SurfaceKind::Bezier),
        surfaces(SurfaceKind::BSpline),
        surfaces(SurfaceKind::Nurbs),
    ]
}

/// A surface with a parameter pair of its domain.
fn surface_with_point() -> impl Strategy<Value = (Surface, f64, f64)> {
    any_surface().prop_flat_map(|s| {
        let (u, v) = (domain_parameter(s.knots_u()), domain_parameter(s.knots_v()));
        (Just(s), u, v)
    })
}

fn surface_scale(s: &Surface) -> f64 {
    scale(&s.control_points())
}

fn surface_weight_ratio(s: &Surface) -> f64 {
    s.weights().map_or(1.0, weight_ratio)
}

/// The control points that act at `(u, v)`.
fn surface_active(s: &Surface, u: f64, v: f64) -> Vec<ControlPoint<3>> {
    let (ru, rv) = (active(s.knots_u(), u), active(s.knots_v(), v));
    ru.flat_map(|i| rv.clone().map(move |j| (i, j)))
        .map(|(i, j)| s.control_point(i, j))
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    #[test]
    fn surface_degrees_stay_in_local_control_range((s, u, v) in surface_with_point()) {
        let p = s.evaluate(u, v).unwrap();
        let all = s.control_points();
        let local = surface_active(&s, u, v);
        for k in DegreeKind::ALL {
            for set in [&all, &local] {
                let lo = set.iter().map(|q| q.degree(k)).fold(f64::INFINITY, f64::min);
                let hi = set.iter().map(|q| q.degree(k)).fold(f64::NEG_INFINITY, f64::max);
                prop_assert!(lo <= p.degree(k) && p.degree(k) <= hi, "{k} = {} not in [{lo}, {hi}]", p.degree(k));
            }
        }
        // Positions in the local control box (convex hull, axis directions).
        let tol = 64.0 * 10.0 * EPS * surface_scale(&s);
        for a in 0..3 {
            let lo = local.iter().map(|q| q.position[a]).fold(f64::INFINITY, f64::min);
            let hi = local.iter().map(|q| q.position[a]).fold(f64::NEG_INFINITY, f64::max);
            prop_assert!(lo - tol <= p.position[a] && p.position[a] <= hi + tol);
        }
        let [tr, i, f] = p.degrees.to_array();
        prop_assert!(Degrees::new(tr, i, f).is_ok());
    }

    #[test]
    fn constant_surface_is_exact((s, u, v) in surface_with_point(), q in control_point::<3>()) {
        let n = s.rows() * s.cols();
        let built = match s.kind() {
            SurfaceKind::Bezier => Surface::bezier(s.rows(), s.cols(), vec![q; n]),
            SurfaceKind::BSpline => Surface::bspline(s.rows(), s.cols(), vec![q; n], s.knots_u().clone(), s.knots_v().clone()),
            SurfaceKind::Nurbs => Surface::nurbs(s.rows(), s.cols(), vec![q; n], s.weights().unwrap().to_vec(), s.knots_u().clone(), s.knots_v().clone()),
        }.unwrap();
        prop_assert_eq!(built.evaluate(u, v).unwrap(), q);
    }

    #[test]
    fn clamped_surfaces_interpolate_their_corners(s in any_surface()) {
        prop_assume!(s.knots_u().is_clamped() && s.knots_v().is_clamped());
        let [du, dv] = s.domain();
        let ((a, b), (c, d)) = ((du.start, du.end), (dv.start, dv.end));
        let (r, k) = (s.rows() - 1, s.cols() - 1);
        prop_assert_eq!(s.evaluate(a, c).unwrap(), s.control_point(0, 0));
        prop_assert_eq!(s.evaluate(a, d).unwrap(), s.control_point(0, k));
        prop_assert_eq!(s.evaluate(b, c).unwrap(), s.control_point(r, 0));
        prop_assert_eq!(s.evaluate(b, d).unwrap(), s.control_point(r, k));
    }

    #[test]
    fn surface_is_a_curve_of_curves((s, u, v) in surface_with_point()) {
        // Evaluate every row along v with the curve kind, then the resulting column along u.
        let rows: Vec<ControlPoint<3>> = (0..s.rows()).map(|i| {
            let row: Vec<_> = (0..s.cols()).map(|j| s.control_point(i, j)).collect();
            match s.kind() {
                SurfaceKind::Bezier => Bezier::new(row).unwrap().evaluate(v).unwrap(),
                _ => BSpline::new(row, s.knots_v().clone()).unwrap().evaluate(v).unwrap(),
            }
        }).collect();
        prop_assume!(s.kind() != SurfaceKind::Nurbs); // the column weights are not public
        let want = match s.kind() {
            SurfaceKind::Bezier => Bezier::new(rows).unwrap().evaluate(u).unwrap(),
            _ => BSpline::new(rows, s.knots_u().clone()).unwrap().evaluate(u).unwrap(),
        };
        let p = s.degree_u() + s.degree_v();
        assert_close("curve of curves", &s.evaluate(u, v).unwrap(), &want, p, surface_scale(&s), 16.0)?;
    }

    #[test]
    fn iso_curves_pass_through_the_surface((s, u, v) in surface_with_point()) {
        let p = s.evaluate(u, v).unwrap();
        let iu = s.iso_curve(Direction::U, u).unwrap();
        let iv = s.iso_curve(Direction::V, v).unwrap();
        let kind = match s.kind() {
            SurfaceKind::Bezier => CurveKind::Bezier,
            SurfaceKind::BSpline => CurveKind::BSpline,
            SurfaceKind::Nurbs => CurveKind::Nurbs,
        };
        prop_assert_eq!((iu.kind(), iv.kind()), (kind, kind));
        prop_assert_eq!((iu.degree(), iv.degree()), (s.degree_v(), s.degree_u()));
        let [du, dv] = s.domain();
        prop_assert_eq!((iu.domain(), iv.domain()), (dv, du));
        let deg = s.degree_u() + s.degree_v();
        let f = 16.0 * surface_weight_ratio(&s);
        assert_close("iso u", &iu.evaluate(v).unwrap(), &p, deg, surface_scale(&s), f)?;
        assert_close("iso v", &iv.evaluate(u).unwrap(), &p, deg, surface_scale(&s), f)?;
    }

    #[test]
    fn equal_weights_make_the_nurbs_surface_the_bspline_surface(
        (s, u, v) in surface_with_point(),
        w in weight(),
    ) {
        prop_assume!(s.kind() == SurfaceKind::BSpline);
        let n = Surface::nurbs(s.rows(), s.cols(), s.control_points(), vec![w; s.rows() * s.cols()], s.knots_u().clone(), s.knots_v().clone()).unwrap();
        let p = s.degree_u() + s.degree_v();
        assert_close("equal weights", &n.evaluate(u, v).unwrap(), &s.evaluate(u, v).unwrap(), p, surface_scale(&s), 8.0)?;
    }

    #[test]
    fn single_span_clamped_bspline_surface_is_the_bezier_surface(
        s in surfaces(SurfaceKind::Bezier),
        u in strategies::parameter(),
        v in strategies::parameter(),
    ) {
        let ku = bezier_knots(s.degree_u(), 0.0, 1.0);
        let kv = bezier_knots(s.degree_v(), 0.0, 1.0);
        let b = Surface::bspline(s.rows(), s.cols(), s.control_points(), ku.clone(), kv.clone()).unwrap();
        prop_assert_eq!(b.evaluate(u, v).unwrap(), s.evaluate(u, v).unwrap());
        let ones = Surface::nurbs(s.rows(), s.cols(), s.control_points(), vec![1.0; s.rows() * s.cols()], ku, kv).unwrap();
        let p = s.degree_u() + s.degree_v();
        assert_close("rational, weights 1", &ones.evaluate(u, v).unwrap(), &s.evaluate(u, v).unwrap(), p, surface_scale(&s), 8.0)?;
    }

    #[test]
    fn surface_partials_match_finite_differences(
        s in any_surface(),
        iu in any::<prop::sample::Index>(),
        iv in any::<prop::sample::Index>(),
        fu in 0.2..=0.8f64,
        fv in 0.2..=0.8f64,
    ) {
        let (su, sv) = (spans(s.knots_u()), spans(s.knots_v()));
        let ((a, b), (c, d)) = (su[iu.index(su.len())], sv[iv.index(sv.len())]);
        let (u, v) = (a + fu * (b - a), c + fv * (d - c));
        let (hu, hv) = (1e-6 * (b - a), 1e-6 * (d - c));
        let der = s.partial_derivatives(u, v).unwrap();
        let r = surface_weight_ratio(&s);
        let mm = surface_scale(&s);
        for (h, len, p, got, step) in [
            (hu, b - a, s.degree_u(), der.du, [hu, 0.0]),
            (hv, d - c, s.degree_v(), der.dv, [0.0, hv]),
        ] {
            let lo = channels(&s.evaluate(u - step[0], v - step[1]).unwrap());
            let hi = channels(&s.evaluate(u + step[0], v + step[1]).unwrap());
            let got = derivative_channels(&got);
            let bound = 2.0 * p as f64 * r / len;
            for ch in 0..6 {
                let fd = (hi[ch] - lo[ch]) / (2.0 * h);
                let tol = 1e-6 * bound * if ch < 3 { mm } else { 1.0 } + 1e-9;
                prop_assert!((fd - got[ch]).abs() <= tol, "channel {ch}: fd {fd:e} vs {:e}", got[ch]);
            }
        }
        // The normal is a unit vector perpendicular to both partials.
        if let Some(n) = s.normal(u, v).unwrap() {
            let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            prop_assert!((len - 1.0).abs() <= 4.0 * EPS);
            for t in [der.du.position, der.dv.position] {
                let tl = (t[0] * t[0] + t[1] * t[1] + t[2] * t[2]).sqrt();
                if tl > 0.0 {
                    let dot = (n[0] * t[0] + n[1] * t[1] + n[2] * t[2]) / tl;
                    prop_assert!(dot.abs() <= 1e-9, "normal . tangent = {dot:e}");
                }
            }
        }
    }
}

#[test]
fn surface_errors_name_the_problem() {
    let d = Degrees::new(0.1, 0.2, 0.3).unwrap();
    let grid = |n: usize| vec![ControlPoint::new([0.0, 0.0, 0.0], d); n];
    assert_eq!(
        Surface::bezier(3, 2, grid(5)).unwrap_err().to_string(),
        "5 control points do not fill a grid of 3 rows x 2 columns (6 points)"
    );
    assert_eq!(
        Surface::bezier(0, 2, grid(0)).unwrap_err().to_string(),
        "0 control points do not fill a grid of 0 rows x 2 columns (0 points)"
    );
    let k = |p, n| KnotVector::clamped_uniform(p, n).unwrap();
    assert_eq!(
        Surface::bspline(3, 4, grid(11), k(2, 3), k(2, 4))
            .unwrap_err()
            .to_string(),
        "11 control points do not fill a grid of 3 rows x 4 columns (12 points)"
    );
    assert_eq!(
        Surface::bspline(3, 4, grid(12), k(1, 4), k(2, 4))
            .unwrap_err()
            .to_string(),
        "knots_u: knot vector has 6 knots, expected 5 (number of control points + degree + 1)"
    );
    assert!(matches!(
        Surface::bspline(3, 4, grid(12), k(1, 3), k(2, 5)),
        Err(SurfaceError::Knots {
            direction: Direction::V,
            ..
        })
    ));
    assert_eq!(
        Surface::nurbs(2, 2, grid(4), vec![1.0, 1.0, 0.0, 1.0], k(1, 2), k(1, 2))
            .unwrap_err()
            .to_string(),
        "control point 2: weight = 0 is not a positive finite number (NURBS weights must be > 0)"
    );
    assert_eq!(
        Surface::nurbs(2, 2, grid(4), vec![1.0; 3], k(1, 2), k(1, 2))
            .unwrap_err()
            .to_string(),
        "3 weights for 4 control points (one weight per control point)"
    );
    // Evaluation outside the domain.
    let s = Surface::bezier(2, 2, grid(4)).unwrap();
    assert!(s.evaluate(1.5, 0.5).is_err());
    assert!(s.partial_derivatives(0.5, -0.1).is_err());
    assert!(s.iso_curve(Direction::U, f64::NAN).is_err());
}
