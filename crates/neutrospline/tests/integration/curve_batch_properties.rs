//! Property tests of the batch evaluation of B-spline and NURBS curves ([`CurveBatch`])
//! against the scalar de Boor evaluation.
//!
//! Accuracy contract: per channel, `|batch - scalar| <= tol * max_i |c_i|` over the channel's
//! control values, with `tol = 1e-14` up to degree 15 and `1e-12` up to degree 400 for
//! B-splines; NURBS (homogeneous form, then a division) within `1e-13` up to degree 15 with
//! weights in \[0.1, 10\]. Parameters anywhere in the domain (knots, values beside them, the
//! ends), in order or not; degrees inside their control range; non-rational values at the
//! knots exactly de Boor's.

use neutrospline::strategies::{bspline, domain_parameter, nurbs};
use neutrospline::{
    uniform_parameter, AnyCurve, BSpline, BatchOptions, BatchParams, ControlPoint, ControlPolygon,
    CurveBatch, Degrees, Evaluate, KnotVector, Nurbs,
};
use proptest::prelude::*;

/// Channel-major reference values from the scalar path.
fn scalar<const D: usize>(curve: &AnyCurve<D>, ts: &[f64]) -> Vec<f64> {
    let mut out = vec![0.0; (D + 3) * ts.len()];
    for (k, &t) in ts.iter().enumerate() {
        let p = curve.evaluate(t).unwrap();
        let channels = p.position.into_iter().chain(p.degrees.to_array());
        for (c, v) in channels.enumerate() {
            out[c * ts.len() + k] = v;
        }
    }
    out
}

/// Control values of channel `c` (positions, then truth, indeterminacy, falsity).
fn channel<const D: usize>(curve: &AnyCurve<D>, c: usize) -> Vec<f64> {
    curve
        .control_points()
        .iter()
        .map(|p| {
            if c < D {
                p.position[c]
            } else {
                p.degrees.to_array()[c - D]
            }
        })
        .collect()
}

fn batch<const D: usize>(curve: &AnyCurve<D>, params: BatchParams<'_>) -> Vec<f64> {
    let mut out = vec![0.0; (D + 3) * params.len()];
    CurveBatch::new(curve)
        .evaluate(params, &mut out, &BatchOptions::default())
        .unwrap();
    out
}

/// Checks `got` against the scalar evaluation at `ts`: the accuracy bound per channel, the
/// control range of every channel, and (non-rational curves) exact values at the knots.
fn check<const D: usize>(
    curve: &AnyCurve<D>,
    ts: &[f64],
    got: &[f64],
    tol: f64,
) -> Result<(), TestCaseError> {
    let want = scalar(curve, ts);
    let count = ts.len();
    let knots = curve
        .knots()
        .map(|k| k.knots().to_vec())
        .unwrap_or_default();
    let rational = curve.weights().is_some();
    for c in 0..D + 3 {
        let values = channel(curve, c);
        let scale = values.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        let lo = values.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        for (k, &t) in ts.iter().enumerate() {
            let (g, w) = (got[c * count + k], want[c * count + k]);
            prop_assert!(
                (g - w).abs() <= tol * scale,
                "{:?} degree {}, channel {c}, t = {t:e}: batch {g:e} vs scalar {w:e} \
                 (difference {:e} = {:.2} x scale, allowed {tol:e})",
                curve.kind(),
                curve.degree(),
                (g - w).abs(),
                (g - w).abs() / scale,
            );
            prop_assert!(
                lo <= g && g <= hi,
                "channel {c}, t = {t}: {g} outside [{lo}, {hi}]"
            );
            // At a knot the batch gives the plain de Boor value exactly (the piece's end
            // control value); the scalar evaluation is compensated: a rounding or so apart.
            if !rational && knots.contains(&t) {
                let ulps = (curve.degree() + 1) as f64 * f64::EPSILON * scale;
                prop_assert!(
                    (g - w).abs() <= ulps,
                    "channel {}, at the knot {}: {} vs {}",
                    c,
                    t,
                    g,
                    w
                );
            }
        }
    }
    Ok(())
}

/// A curve and parameters in its domain (`count` of them), from the shared strategies.
fn with_parameters<const D: usize>(
    curve: impl Strategy<Value = AnyCurve<D>>,
    count: std::ops::RangeInclusive<usize>,
) -> impl Strategy<Value = (AnyCurve<D>, Vec<f64>)> {
    curve.prop_flat_map(move |curve| {
        let knots = curve.knots().expect("a spline").clone();
        (
            Just(curve),
            prop::collection::vec(domain_parameter(&knots), count.clone()),
        )
    })
}

fn bsplines<const D: usize>(
    degree: std::ops::RangeInclusive<usize>,
) -> impl Strategy<Value = AnyCurve<D>> {
    bspline::<D>(degree).prop_map(AnyCurve::from)
}

fn nurbses<const D: usize>(
    degree: std::ops::RangeInclusive<usize>,
) -> impl Strategy<Value = AnyCurve<D>> {
    nurbs::<D>(degree).prop_map(AnyCurve::from)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn bspline_values_within_1e14_up_to_degree_15(
        (curve, ts) in with_parameters(bsplines::<2>(0..=15), 1..=60),
    ) {
        let got = batch(&curve, BatchParams::Values(&ts));
        check(&curve, &ts, &got, 1e-14)?;
        // The same parameters in increasing order (the in-place path).
        let mut sorted = ts.clone();
        sorted.sort_by(f64::total_cmp);
        let got = batch(&curve, BatchParams::Values(&sorted));
        check(&curve, &sorted, &got, 1e-14)?;
    }

    #[test]
    fn bspline_uniform_within_1e14_up_to_degree_15(
        curve in bsplines::<3>(0..=15),
        count in 1usize..=500,
    ) {
        let domain = curve.domain();
        let ts: Vec<f64> = (0..count).map(|k| uniform_parameter(k, count, domain.clone())).collect();
        let got = batch(&curve, BatchParams::Uniform(count));
        check(&curve, &ts, &got, 1e-14)?;
    }

    #[test]
    fn nurbs_values_within_1e13_up_to_degree_15(
        (curve, ts) in with_parameters(nurbses::<2>(0..=15), 1..=60),
    ) {
        let got = batch(&curve, BatchParams::Values(&ts));
        check(&curve, &ts, &got, 1e-13)?;
    }

    #[test]
    fn nurbs_3d_uniform_within_1e13_up_to_degree_15(
        curve in nurbses::<3>(0..=15),
        count in 1usize..=300,
    ) {
        let domain = curve.domain();
        let ts: Vec<f64> = (0..count).map(|k| uniform_parameter(k, count, domain.clone())).collect();
        let got = batch(&curve, BatchParams::Uniform(count));
        check(&curve, &ts, &got, 1e-13)?;
    }

    #[test]
    fn uniform_parameters_are_uniform_parameter(
        curve in prop_oneof![bsplines::<2>(0..=7), nurbses::<2>(0..=7)],
        count in 1usize..=9000,
        threads in 1usize..=3,
    ) {
        // Evenly spaced parameters (generated block by block, split between threads) are
        // exactly `uniform_parameter`'s, and give exactly the values of those parameters.
        let domain = curve.domain();
        let ts: Vec<f64> = (0..count).map(|k| uniform_parameter(k, count, domain.clone())).collect();
        let batch = CurveBatch::new(&curve);
        let options = BatchOptions::default().with_threads(threads).with_parallel_threshold(0);
        let mut uniform = vec![0.0; 5 * count];
        batch.evaluate(BatchParams::Uniform(count), &mut uniform, &options).unwrap();
        let mut values = vec![0.0; 5 * count];
        batch.evaluate(BatchParams::Values(&ts), &mut values, &options).unwrap();
        prop_assert_eq!(uniform, values);
    }

    #[test]
    fn threads_and_curves_change_nothing(
        curves in prop::collection::vec(prop_oneof![bsplines::<2>(0..=9), nurbses::<2>(0..=9)], 1..=4),
        count in 1usize..=3000,
        threads in 1usize..=4,
    ) {
        let batches: Vec<CurveBatch<2>> = curves.iter().map(CurveBatch::new).collect();
        let mut alone = Vec::new();
        for b in &batches {
            let mut out = vec![0.0; 5 * count];
            b.evaluate(BatchParams::Uniform(count), &mut out, &BatchOptions::default().with_threads(1))
                .unwrap();
            alone.extend(out);
        }
        let mut together = vec![0.0; batches.len() * 5 * count];
        let options = BatchOptions::default().with_threads(threads).with_parallel_threshold(0);
        CurveBatch::evaluate_all(&batches, BatchParams::Uniform(count), &mut together, &options)
            .unwrap();
        prop_assert_eq!(alone, together);
    }
}

proptest! {
    // High degrees are slow in the scalar reference (O(n^2) per point): fewer cases.
    #![proptest_config(ProptestConfig::with_cases(10))]

    #[test]
    fn bspline_within_1e12_up_to_degree_400(
        (curve, ts) in with_parameters(bsplines::<2>(16..=400), 1..=9),
    ) {
        let got = batch(&curve, BatchParams::Values(&ts));
        check(&curve, &ts, &got, 1e-12)?;
    }
}

/// A clamped cubic B-spline with `count` control points on \[0, count - 3\].
fn long_spline(count: usize) -> BSpline<2> {
    let points = (0..count)
        .map(|i| {
            let x = i as f64;
            let d =
                Degrees::new((x * 0.37).fract(), (x * 0.71).fract(), (x * 0.13).fract()).unwrap();
            ControlPoint::new([x, (x * 0.7).sin() * 5.0], d)
        })
        .collect();
    let knots: Vec<f64> = (0..count + 4)
        .map(|i| i.saturating_sub(3).min(count - 3) as f64)
        .collect();
    BSpline::new(points, KnotVector::new(knots, 3, count).unwrap()).unwrap()
}

/// Parameters in reverse and scrambled order, over a curve with more pieces than a block has
/// parameters (the comparison-sort path) and with fewer (the counting sort), and blocks
/// (4096 parameters) in between.
#[test]
fn parameters_out_of_order_many_pieces() {
    for (count, points) in [(300, 7), (300, 9000), (20, 5000)] {
        let curve = AnyCurve::from(long_spline(count));
        let (a, b) = (curve.domain().start, curve.domain().end);
        let ts: Vec<f64> = (0..points)
            .map(|k| {
                let j = (k * 7919) % points;
                a + (b - a) * j as f64 / (points - 1) as f64
            })
            .collect();
        let got = batch(&curve, BatchParams::Values(&ts));
        check(&curve, &ts, &got, 1e-14).unwrap();
        let reversed: Vec<f64> = ts.iter().rev().copied().collect();
        let got = batch(&curve, BatchParams::Values(&reversed));
        check(&curve, &reversed, &got, 1e-14).unwrap();
    }
}

/// A Bézier curve's evenly spaced parameters are generated inside the kernels (its one piece
/// is on \[0, 1\], `u = t`): exactly the values at the parameters `k / (count - 1)`, on one
/// thread or several.
#[test]
fn bezier_uniform_parameters_are_generated_exactly() {
    let curve = AnyCurve::from(neutrospline::example1());
    for count in [1, 2, 7, 1001, 70_001] {
        let ts: Vec<f64> = (0..count)
            .map(|k| uniform_parameter(k, count, 0.0..1.0))
            .collect();
        for threads in [1, 2] {
            let batch = CurveBatch::new(&curve);
            let options = BatchOptions::default()
                .with_threads(threads)
                .with_parallel_threshold(0);
            let mut uniform = vec![0.0; 5 * count];
            batch
                .evaluate(BatchParams::Uniform(count), &mut uniform, &options)
                .unwrap();
            let mut values = vec![0.0; 5 * count];
            batch
                .evaluate(BatchParams::Values(&ts), &mut values, &options)
                .unwrap();
            assert_eq!(uniform, values, "{count} parameters, {threads} threads");
        }
        let got = batch(&curve, BatchParams::Uniform(count));
        check(&curve, &ts, &got, 1e-14).unwrap();
    }
}

/// Equal weights: the NURBS curve is its B-spline, and the ends of each piece come out as the
/// B-spline's up to the scaled weights' rounding (none here: all weights scale to 1).
#[test]
fn nurbs_with_equal_weights_is_the_bspline() {
    let spline = long_spline(40);
    let rational = Nurbs::new(
        spline.control_points(),
        vec![2.5; 40],
        spline.knots().clone(),
    )
    .unwrap();
    let count = 10_000;
    let a = batch(&AnyCurve::from(spline), BatchParams::Uniform(count));
    let b = batch(&AnyCurve::from(rational), BatchParams::Uniform(count));
    assert_eq!(a, b);
}

/// A parameter outside the domain is reported with the lowest index and the domain; with
/// several curves, the curve's own domain.
#[test]
fn parameters_outside_the_domain() {
    let curve = CurveBatch::from(&long_spline(10)); // domain [0, 7]
    let mut ts = vec![3.5; 10_000];
    ts[9000] = f64::NAN;
    ts[7000] = 7.5;
    ts[8000] = -1.0;
    let mut out = vec![0.0; 5 * ts.len()];
    for threads in [1, 2, 3] {
        let options = BatchOptions::default()
            .with_threads(threads)
            .with_parallel_threshold(0);
        let err = curve
            .evaluate(BatchParams::Values(&ts), &mut out, &options)
            .unwrap_err();
        assert_eq!(
            err.to_string(),
            "parameter t = 7.5 is outside the domain [0, 7]"
        );
    }
    let short = CurveBatch::from(&long_spline(5)); // domain [0, 2]
    let both = [curve, short];
    let mut out = vec![0.0; 2 * 5 * 3];
    let err = CurveBatch::evaluate_all(
        &both,
        BatchParams::Values(&[1.0, 5.0, 9.0]),
        &mut out,
        &BatchOptions::default(),
    )
    .unwrap_err();
    assert_eq!(
        err.to_string(),
        "parameter t = 5 is outside the domain [0, 2]"
    );
    assert_eq!(both[0].domain(), 0.0..7.0);
    assert_eq!((both[1].pieces(), both[1].degree()), (2, 3));
    assert!(!both[1].is_rational());
}

/// Weights far apart (some below the normal range once scaled, where the batch divides
/// instead of multiplying by the reciprocal) and very large: the values stay de Boor's.
#[test]
fn nurbs_with_extreme_weights() {
    let spline = long_spline(12);
    for weights in [
        [1e-310, 1.0, 3e-320, 2.0, 1e-300, 1.0],
        [1e300, 1.0, 1e-8, 1e308, 5.0, 1e-300],
        [0.1, 10.0, 0.1, 10.0, 0.1, 10.0],
    ] {
        let weights: Vec<f64> = weights.iter().cycle().take(12).copied().collect();
        let curve = AnyCurve::from(
            Nurbs::new(spline.control_points(), weights, spline.knots().clone()).unwrap(),
        );
        let count = 2001;
        let domain = curve.domain();
        let mut ts: Vec<f64> = (0..count)
            .map(|k| uniform_parameter(k, count, domain.clone()))
            .collect();
        let got = batch(&curve, BatchParams::Uniform(count));
        check(&curve, &ts, &got, 1e-13).unwrap();
        ts.reverse();
        let got = batch(&curve, BatchParams::Values(&ts));
        check(&curve, &ts, &got, 1e-13).unwrap();
    }
}
