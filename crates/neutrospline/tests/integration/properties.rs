//! Property tests for the invariants of docs/model.md section 4 and for the CAGD operations.

use neutrospline::strategies::{bezier, control_point, degrees, parameter};
use neutrospline::{
    Affine, AxisSet, AxisSetName, Bezier, Bounded, ControlPolygon, CurvePoint, DegreeKind, Degrees,
    Derivative, Elevate, Evaluate, NeutrosophicPoint, PointRelation, Split,
};
use proptest::prelude::*;

/// Largest absolute position coordinate of the control points (at least 1).
fn scale<const D: usize>(c: &Bezier<D>) -> f64 {
    c.control_points()
        .iter()
        .flat_map(|p| p.position)
        .fold(1.0_f64, |m, v| m.max(v.abs()))
}

/// Rounding allowance for positions of a degree-n evaluation at this scale: de Casteljau's
/// forward error is bounded by about 2 n u times the scale (u = 2^-53).
fn position_tolerance<const D: usize>(c: &Bezier<D>) -> f64 {
    8.0 * (c.degree() as f64 + 1.0) * f64::EPSILON * scale(c)
}

fn degree_tolerance<const D: usize>(c: &Bezier<D>) -> f64 {
    8.0 * (c.degree() as f64 + 1.0) * f64::EPSILON
}

/// Asserts two curve points agree within the curve's rounding allowances.
fn assert_close<const D: usize>(
    c: &Bezier<D>,
    got: &CurvePoint<D>,
    want: &CurvePoint<D>,
    factor: f64,
) -> Result<(), TestCaseError> {
    let (pt, dt) = (factor * position_tolerance(c), factor * degree_tolerance(c));
    for a in 0..D {
        prop_assert!(
            (got.position[a] - want.position[a]).abs() <= pt,
            "axis {a}: {} vs {} (tol {pt})",
            got.position[a],
            want.position[a]
        );
    }
    for k in DegreeKind::ALL {
        prop_assert!(
            (got.degree(k) - want.degree(k)).abs() <= dt,
            "{k}: {} vs {} (tol {dt})",
            got.degree(k),
            want.degree(k)
        );
    }
    Ok(())
}

/// All channels of a point: coordinates, then truth, indeterminacy, falsity.
fn channels<const D: usize>(p: &NeutrosophicPoint<D>) -> Vec<f64> {
    p.position
        .iter()
        .copied()
        .chain(p.degrees.to_array())
        .collect()
}

fn check_degrees_in_control_range<const D: usize>(
    c: &Bezier<D>,
    t: f64,
) -> Result<(), TestCaseError> {
    let p = c.evaluate(t).unwrap();
    for k in DegreeKind::ALL {
        let values: Vec<f64> = c.control_points().iter().map(|q| q.degree(k)).collect();
        let lo = values.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        let v = p.degree(k);
        // Exact: no tolerance. Every de Casteljau step is projected onto its segment.
        prop_assert!(
            lo <= v && v <= hi,
            "{k} = {v} outside [{lo}, {hi}] at t = {t}"
        );
        prop_assert!((0.0..=1.0).contains(&v));
    }
    // The point is valid under the library's own check.
    let [tr, i, f] = p.degrees.to_array();
    prop_assert!(Degrees::new(tr, i, f).is_ok());
    Ok(())
}

fn check_convex_hull<const D: usize>(
    c: &Bezier<D>,
    t: f64,
    directions: &[Vec<f64>],
) -> Result<(), TestCaseError> {
    // p is in the hull of the P_i iff u.p <= max_i u.P_i for every direction u; test the axis
    // directions (both signs) and random ones, over positions and degrees together.
    let p = channels(&c.evaluate(t).unwrap());
    let controls: Vec<Vec<f64>> = c.control_points().iter().map(channels).collect();
    let tol = position_tolerance(c) * 4.0;
    let dims = D + 3;
    let axes = (0..dims).flat_map(|a| {
        [1.0, -1.0].map(|sign| (0..dims).map(|b| if a == b { sign } else { 0.0 }).collect())
    });
    for u in axes.chain(directions.iter().cloned()) {
        let dot = |v: &[f64]| v.iter().zip(&u).map(|(a, b)| a * b).sum::<f64>();
        let support = controls
            .iter()
            .map(|q| dot(q))
            .fold(f64::NEG_INFINITY, f64::max);
        prop_assert!(dot(&p) <= support + tol, "outside hull along {u:?}");
    }
    Ok(())
}

fn directions(dims: usize) -> impl Strategy<Value = Vec<Vec<f64>>> {
    prop::collection::vec(prop::collection::vec(-1.0..=1.0f64, dims), 8)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn degrees_stay_in_control_range_2d(c in bezier::<2>(0..=30), t in parameter()) {
        check_degrees_in_control_range(&c, t)?;
    }

    #[test]
    fn degrees_stay_in_control_range_3d(c in bezier::<3>(0..=30), t in parameter()) {
        check_degrees_in_control_range(&c, t)?;
    }

    #[test]
    fn endpoints_interpolate_exactly(c in bezier::<3>(0..=40)) {
        prop_assert_eq!(c.evaluate(0.0).unwrap(), c.control_point(0));
        prop_assert_eq!(c.evaluate(1.0).unwrap(), c.control_point(c.degree()));
    }

    #[test]
    fn curve_lies_in_convex_hull_2d(c in bezier::<2>(1..=20), t in parameter(), u in directions(5)) {
        check_convex_hull(&c, t, &u)?;
    }

    #[test]
    fn curve_lies_in_convex_hull_3d(c in bezier::<3>(1..=20), t in parameter(), u in directions(6)) {
        check_convex_hull(&c, t, &u)?;
    }

    #[test]
    fn affine_maps_commute_with_evaluation(
        c in bezier::<2>(0..=15),
        t in parameter(),
        m in prop::array::uniform4(-3.0..=3.0f64),
        shift in prop::array::uniform2(-100.0..=100.0f64),
    ) {
        let map = Affine::new([[m[0], m[1]], [m[2], m[3]]], shift);
        let mapped = c.transform(&map).unwrap();
        let got = mapped.evaluate(t).unwrap();
        let p = c.evaluate(t).unwrap();
        let want = map.apply(p.position);
        // Degrees are untouched by the map: identical bits.
        prop_assert_eq!(got.degrees, p.degrees);
        let tol = 20.0 * position_tolerance(&c) + 1e-12 * shift[0].abs().max(shift[1].abs());
        for a in 0..2 {
            prop_assert!((got.position[a] - want[a]).abs() <= tol, "{} vs {}", got.position[a], want[a]);
        }
    }

    #[test]
    fn split_halves_reproduce_the_curve(c in bezier::<3>(0..=25), t in parameter(), u in parameter()) {
        let (left, right) = c.split(t).unwrap();
        prop_assert_eq!(left.degree(), c.degree());
        assert_close(&c, &left.evaluate(u).unwrap(), &c.evaluate(t * u).unwrap(), 4.0)?;
        let v = t + (1.0 - t) * u;
        assert_close(&c, &right.evaluate(u).unwrap(), &c.evaluate(v.min(1.0)).unwrap(), 4.0)?;
        // The halves meet exactly at the split point.
        prop_assert_eq!(left.control_point(left.degree()), right.control_point(0));
    }

    #[test]
    fn subsegment_reproduces_the_curve(c in bezier::<2>(0..=20), a in parameter(), b in parameter(), u in parameter()) {
        let piece = c.subsegment(a, b).unwrap();
        let t = (a + (b - a) * u).clamp(0.0, 1.0);
        assert_close(&c, &piece.evaluate(u).unwrap(), &c.evaluate(t).unwrap(), 16.0)?;
    }

    #[test]
    fn elevation_leaves_the_curve_unchanged(c in bezier::<2>(0..=30), t in parameter()) {
        let e = c.elevate();
        prop_assert_eq!(e.degree(), c.degree() + 1);
        assert_close(&c, &e.evaluate(t).unwrap(), &c.evaluate(t).unwrap(), 4.0)?;
        let twice = e.elevate();
        assert_close(&c, &twice.evaluate(t).unwrap(), &c.evaluate(t).unwrap(), 8.0)?;
    }

    #[test]
    fn derivative_matches_finite_differences(c in bezier::<2>(1..=12), t in 0.01..=0.99f64) {
        // Central difference with step h: truncation error h^2/6 |C'''| <= h^2/6 n^3 8 scale,
        // rounding error about u scale / h. h = 1e-5 balances them for n <= 12.
        let h = 1e-5;
        let d = c.derivative().evaluate(t).unwrap();
        let (p0, p1) = (c.evaluate(t - h).unwrap(), c.evaluate(t + h).unwrap());
        let n = c.degree() as f64;
        let tol_for = |s: f64| h * h / 6.0 * n.powi(3) * 8.0 * s + 1e3 * f64::EPSILON * s / h;
        for a in 0..2 {
            let fd = (p1.position[a] - p0.position[a]) / (2.0 * h);
            let tol = tol_for(scale(&c));
            prop_assert!((fd - d.position[a]).abs() <= tol, "axis {a}: fd {fd} vs {} (tol {tol})", d.position[a]);
        }
        for k in DegreeKind::ALL {
            let fd = (p1.degree(k) - p0.degree(k)) / (2.0 * h);
            let tol = tol_for(1.0);
            prop_assert!((fd - d.degree(k)).abs() <= tol, "{k}: fd {fd} vs {} (tol {tol})", d.degree(k));
        }
    }

    #[test]
    fn evaluate_many_is_bitwise_single(c in bezier::<3>(0..=20), ts in prop::collection::vec(parameter(), 0..20)) {
        let mut pts = vec![c.control_point(0); ts.len()];
        c.evaluate_many(&ts, &mut pts).unwrap();
        for (k, &t) in ts.iter().enumerate() {
            prop_assert_eq!(pts[k], c.evaluate(t).unwrap());
        }
    }

    #[test]
    fn bounding_box_contains_curve_and_sits_in_control_box(c in bezier::<2>(0..=15), ts in prop::collection::vec(parameter(), 1..30)) {
        let b = c.bounding_box();
        let cb = c.control_bounding_box();
        for t in ts {
            let p = c.evaluate(t).unwrap();
            prop_assert!(b.contains(&p), "{p:?} not in {b:?}");
        }
        for a in 0..2 {
            prop_assert!(cb.position[a].min <= b.position[a].min && b.position[a].max <= cb.position[a].max);
        }
        for k in DegreeKind::ALL {
            prop_assert!(cb.degree(k).min <= b.degree(k).min && b.degree(k).max <= cb.degree(k).max);
        }
    }

    #[test]
    fn bounding_box_is_tight(c in bezier::<2>(1..=10)) {
        // Dense sampling gives attained values; the box may not exceed them by more than the
        // sampling gap allows (second-order: |C''| h^2 / 8 with h = 1/2000).
        let b = c.bounding_box();
        let n = c.degree() as f64;
        let slack = n * n * 4.0 * scale(&c) / (8.0 * 2000.0 * 2000.0) + 1e-9 * scale(&c);
        let mut lo = [f64::INFINITY; 2];
        let mut hi = [f64::NEG_INFINITY; 2];
        for k in 0..=2000 {
            let p = c.evaluate(k as f64 / 2000.0).unwrap();
            for a in 0..2 {
                lo[a] = lo[a].min(p.position[a]);
                hi[a] = hi[a].max(p.position[a]);
            }
        }
        for a in 0..2 {
            prop_assert!(b.position[a].min >= lo[a] - slack && b.position[a].max <= hi[a] + slack);
        }
    }

    #[test]
    fn degree_curve_projects_to_crisp_curve(c in bezier::<2>(0..=15), t in parameter()) {
        let p = c.evaluate(t).unwrap();
        for k in DegreeKind::ALL {
            let q = c.degree_curve(k).evaluate(t).unwrap();
            prop_assert_eq!(&q.position[..2], &p.position[..]);
            prop_assert_eq!(q.position[2], p.degree(k));
            prop_assert_eq!(q.degrees, p.degrees);
        }
    }

    #[test]
    fn reversed_runs_backwards(c in bezier::<2>(0..=15), t in parameter()) {
        let r = c.reversed();
        assert_close(&c, &r.evaluate(1.0 - t).unwrap(), &c.evaluate(t).unwrap(), 4.0)?;
    }

    #[test]
    fn largest_relation_is_admissible_and_maximal(
        m in prop::collection::vec(degrees(), 1..5),
        n in prop::collection::vec(degrees(), 1..5),
        bump in 1e-9..0.5f64,
        which in 0usize..3,
    ) {
        let m = AxisSet::new(AxisSetName::M, m.into_iter().enumerate().map(|(i, d)| (i as f64, d)).collect()).unwrap();
        let n = AxisSet::new(AxisSetName::N, n.into_iter().enumerate().map(|(i, d)| (10.0 + i as f64, d)).collect()).unwrap();
        let rel = PointRelation::largest(&m, &n);
        prop_assert_eq!(rel.entries().len(), m.members().len() * n.members().len());
        prop_assert!(rel.check_admissible(&m, &n).is_ok());
        // Raising any degree of any entry above the minimum breaks admissibility.
        let mut entries = rel.entries().to_vec();
        let mut arr = entries[0].degrees.to_array();
        if arr[which] + bump <= 1.0 {
            arr[which] += bump;
            entries[0].degrees = Degrees::from_array(arr).unwrap();
            prop_assert!(PointRelation::new(entries).check_admissible(&m, &n).is_err());
        }
    }

    #[test]
    fn control_points_round_trip(points in prop::collection::vec(control_point::<3>(), 1..20)) {
        let c = Bezier::new(points.clone()).unwrap();
        prop_assert_eq!(c.control_points(), points);
    }
}

#[test]
fn high_degree_evaluation_is_finite_and_bounded() {
    // Degree 400 with alternating control values: binomial coefficients near 1e119 would
    // make a naive Bernstein sum lose everything; de Casteljau stays in the hull.
    let points: Vec<_> = (0..=400)
        .map(|i| {
            let sign = if i % 2 == 0 { 1.0 } else { -1.0 };
            neutrospline::ControlPoint::new(
                [sign * 5.0, i as f64],
                Degrees::new(if i % 2 == 0 { 1.0 } else { 0.0 }, 0.5, 0.0).unwrap(),
            )
        })
        .collect();
    let c = Bezier::new(points).unwrap();
    // x(t) = 5 sum (-1)^i B_i(t) = 5 (1 - 2t)^400: at t = 0.5 exactly 0, at 0.25 5 * 2^-400.
    let mid = c.evaluate(0.5).unwrap();
    assert!(mid.position[0].abs() < 1e-12, "{}", mid.position[0]);
    // y(t) = sum i B_i(t) = 400 t (linear precision).
    assert!((mid.position[1] - 200.0).abs() < 1e-11);
    // T(t) = (1 + (1 - 2t)^400) / 2.
    assert!((mid.degrees.truth() - 0.5).abs() < 1e-15);
    let p = c.evaluate(0.3).unwrap();
    assert!((p.position[1] - 120.0).abs() < 1e-11);
}
