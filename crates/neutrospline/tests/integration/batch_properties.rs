//! Property tests of batch evaluation against the scalar de Casteljau evaluation.
//!
//! Accuracy contract: per channel, `|batch - scalar| <= tol * max_i |c_i|` with `tol = 1e-14`
//! up to degree 15 and `1e-12` up to degree 400, at any parameter in \[0, 1\] (the ends and
//! values within an ulp of them included); the ends exact; degrees inside their control range.

use neutrospline::strategies::{bezier, parameter};
use neutrospline::{
    BatchOptions, BatchParams, Bezier, ControlPoint, ControlPolygon, CurveBatch, Degrees, Evaluate,
};
use proptest::prelude::*;

/// Channel-major reference values from the scalar path.
fn scalar(curve: &Bezier<2>, ts: &[f64]) -> Vec<f64> {
    let mut out = vec![0.0; 5 * ts.len()];
    for (k, &t) in ts.iter().enumerate() {
        let p = curve.evaluate(t).unwrap();
        let channels = p.position.into_iter().chain(p.degrees.to_array());
        for (c, v) in channels.enumerate() {
            out[c * ts.len() + k] = v;
        }
    }
    out
}

/// Control values of channel `c` (x, y, truth, indeterminacy, falsity).
fn channel(curve: &Bezier<2>, c: usize) -> Vec<f64> {
    curve
        .control_points()
        .iter()
        .map(|p| match c {
            0 | 1 => p.position[c],
            _ => p.degrees.to_array()[c - 2],
        })
        .collect()
}

/// Checks `got` against the scalar evaluation at `ts`: the accuracy bound per channel, the
/// control range of every channel, exact end points.
fn check(curve: &Bezier<2>, ts: &[f64], got: &[f64], tol: f64) -> Result<(), TestCaseError> {
    let want = scalar(curve, ts);
    let count = ts.len();
    let last = curve.degree();
    for c in 0..5 {
        let values = channel(curve, c);
        let scale = values.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        let lo = values.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        for (k, &t) in ts.iter().enumerate() {
            let (g, w) = (got[c * count + k], want[c * count + k]);
            prop_assert!(
                (g - w).abs() <= tol * scale,
                "degree {last}, channel {c}, t = {t:e}: batch {g:e} vs scalar {w:e} \
                 (difference {:e}, allowed {:e})",
                (g - w).abs(),
                tol * scale
            );
            prop_assert!(
                lo <= g && g <= hi,
                "channel {c}, t = {t}: {g} outside [{lo}, {hi}]"
            );
            if t == 0.0 {
                prop_assert_eq!(g, values[0]);
            }
            if t == 1.0 {
                prop_assert_eq!(g, values[last]);
            }
        }
    }
    Ok(())
}

/// Parameters from the shared strategy plus values a few ulps from each end.
fn parameters(count: std::ops::RangeInclusive<usize>) -> impl Strategy<Value = Vec<f64>> {
    let near_ends = prop::sample::select(vec![
        f64::MIN_POSITIVE,
        4.9e-324,
        1e-17,
        2.0 * f64::EPSILON,
        1.0 - f64::EPSILON / 2.0,
        1.0 - 3.0 * f64::EPSILON,
        0.5 - f64::EPSILON,
    ]);
    prop::collection::vec(prop_oneof![4 => parameter(), 1 => near_ends], count)
}

/// A curve from the shared strategy with its positions scaled by `10^e`, `e` in \[-3, 6\].
fn scaled_curve(degree: std::ops::RangeInclusive<usize>) -> impl Strategy<Value = Bezier<2>> {
    (bezier::<2>(degree), -3i32..=6).prop_map(|(curve, e)| {
        let f = 10f64.powi(e);
        Bezier::new(
            curve
                .control_points()
                .into_iter()
                .map(|p| ControlPoint::new([p.position[0] * f, p.position[1] * f], p.degrees))
                .collect(),
        )
        .unwrap()
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn batch_values_within_1e14_up_to_degree_15(
        curve in scaled_curve(0..=15),
        ts in parameters(1..=40),
    ) {
        let mut got = vec![0.0; 5 * ts.len()];
        CurveBatch::from(&curve)
            .evaluate(BatchParams::Values(&ts), &mut got, &BatchOptions::default())
            .unwrap();
        check(&curve, &ts, &got, 1e-14)?;
    }

    #[test]
    fn batch_uniform_within_1e14_up_to_degree_15(
        curve in scaled_curve(0..=15),
        count in 1usize..=300,
    ) {
        let ts: Vec<f64> = (0..count)
            .map(|k| if count == 1 { 0.0 } else { k as f64 / (count - 1) as f64 })
            .collect();
        let mut got = vec![0.0; 5 * count];
        CurveBatch::from(&curve)
            .evaluate(BatchParams::Uniform(count), &mut got, &BatchOptions::default())
            .unwrap();
        check(&curve, &ts, &got, 1e-14)?;
    }

    #[test]
    fn batch_threads_and_curves_change_nothing(
        curves in prop::collection::vec(bezier::<2>(0..=12), 1..=5),
        count in 1usize..=2000,
        threads in 1usize..=4,
    ) {
        let batches: Vec<CurveBatch<2>> = curves.iter().map(CurveBatch::from).collect();
        let mut alone = Vec::new();
        for b in &batches {
            let mut out = vec![0.0; 5 * count];
            b.evaluate(BatchParams::Uniform(count), &mut out, &BatchOptions::default().with_threads(1))
                .unwrap();
            alone.extend(out);
        }
        let mut together = vec![0.0; batches.len() * 5 * count];
        let options = BatchOptions::default().with_threads(threads).with_parallel_threshold(0);
        CurveBatch::evaluate_all(&batches, BatchParams::Uniform(count), &mut together, &options).unwrap();
        prop_assert_eq!(alone, together);
    }
}

proptest! {
    // High degrees are slow in the scalar reference (O(n^2) per point): fewer cases.
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn batch_within_1e12_up_to_degree_400(
        curve in scaled_curve(16..=400),
        ts in parameters(1..=9),
    ) {
        let mut got = vec![0.0; 5 * ts.len()];
        CurveBatch::from(&curve)
            .evaluate(BatchParams::Values(&ts), &mut got, &BatchOptions::default())
            .unwrap();
        check(&curve, &ts, &got, 1e-12)?;
    }
}

/// The kernel boundaries (Bernstein weights in per-degree kernels up to degree 15, in a
/// scratch buffer up to 1000, de Casteljau above) at the parameters where the Bernstein form is weakest:
/// many tiny or near-1 values.
#[test]
fn batch_degree_64_and_65_near_the_ends() {
    for n in [15, 16, 64, 65, 400, 1000, 1001] {
        let pts = (0..=n)
            .map(|i| {
                let x = i as f64;
                let d = Degrees::new((x * 0.37).fract(), (x * 0.71).fract(), (x * 0.13).fract())
                    .unwrap();
                ControlPoint::new([1e6 * (x * 1.3).sin(), -1e6 * (x * 0.7).cos()], d)
            })
            .collect();
        let curve = Bezier::new(pts).unwrap();
        // Fewer exponents at the highest degrees: the scalar reference is O(n^2) per point.
        let ts: Vec<f64> = (0..60)
            .step_by(if n > 400 { 5 } else { 1 })
            .flat_map(|e| {
                let small = 2f64.powi(-e * 17);
                [
                    small,
                    1.0 - small.max(f64::EPSILON / 2.0),
                    0.5 + small / 4.0,
                ]
            })
            .collect();
        let mut got = vec![0.0; 5 * ts.len()];
        CurveBatch::from(&curve)
            .evaluate(BatchParams::Values(&ts), &mut got, &BatchOptions::default())
            .unwrap();
        check(&curve, &ts, &got, 1e-12).unwrap();
    }
}
