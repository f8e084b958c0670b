//! Degree-0 splines (piecewise constant), from three of the four cases proptest once shrank to
//! (kept in an orphaned `spline_properties.proptest-regressions` whose test no longer existed;
//! the fourth is a rational spline of weights 1, which the rational case covers): at a
//! parameter in `[u_k, u_{k+1})` the curve is control point `k` (right-continuous), at the end
//! of the domain the last one; the batch evaluator agrees with the scalar one. The expected
//! values are the control points themselves, not a computation of the library.

use neutrospline::{
    AnyCurve, BSpline, BatchOptions, BatchParams, ControlPoint, CurveBatch, Degrees, DynCurve,
    KnotVector, Nurbs,
};

/// A degree-0 spline: its knots, its control rows `x, y[, z], truth, indeterminacy, falsity`,
/// its weights (rational) and the parameters to check.
struct Case {
    knots: &'static [f64],
    rows: &'static [f64],
    dimension: usize,
    weights: Option<&'static [f64]>,
    ts: &'static [f64],
}

#[rustfmt::skip]
const CASES: [Case; 3] = [
    Case {
        knots: &[5.139306359997727, 55.139306359997725, 91.34846498360456, 141.34846498360457,
            200.17902558765002, 250.17902558765002, 308.3698875598127, 358.3698875598127],
        rows: &[0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
            0.0, 0.0, 0.0, 0.05084248932908626, 349.02156512707916, 399.6802903620185, 1.0, 0.6,
            0.6762930193969059, -919.2338093649784, -531.301913459415, 1.0, 0.7506984096069135,
            1.0, 152.2409826942907, -816.0097682756909, 0.6547545733168906, 0.2, 0.0],
        dimension: 2,
        weights: None,
        // Interior knots, the end of the domain and a parameter inside a span.
        ts: &[250.17902558765002, 91.34846498360456, 358.3698875598127, 112.58829006501865],
    },
    Case {
        knots: &[-0.17692702190172438, -0.17182621806203144, -0.16245346976935157,
            -0.15745346976935157, -0.14861905737958042, -0.1417884226834406,
            -0.13678842268344063],
        rows: &[0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -72.84227689772354,
            -596.8863804487064, -942.6340148318662, 0.8001661937101966, 0.4667847160680241, 0.1,
            -252.63920963282484, -374.2140799606432, 537.6935058554818, 0.3, 0.1932516057828049,
            0.7491046074115536, 71.43162203743064, 297.80773450910306, 120.88971764988204,
            0.3086839255491557, 0.3885626710363342, 0.16695464623046907, 28.2202975780276,
            -2.0826943714511166, -39.4031568142752, 0.6693459797656997, 0.8, 0.12984957059297061],
        dimension: 3,
        weights: None,
        ts: &[-0.16245346976935157, -0.13678842268344063],
    },
    Case {
        knots: &[-2.9934269825002633, -2.4934269825002633, -1.9934269825002633,
            -1.4934269825002633, -1.233388694991765],
        rows: &[-342.49282852087407, 981.6221775706671, 0.7049445964309348, 0.5436466739703493,
            0.46909258737301435, -796.6151601982301, -217.11528937742222, 0.8,
            0.22993015979386827, 0.666693677555343, -520.3402544633736, 696.3772938270596,
            0.628502417095574, 0.0, 0.5236276236492569, -747.1611635032498, 90.49074358568213,
            0.6065996614019031, 0.6479870119136582, 0.05888943553675081],
        dimension: 2,
        weights: Some(&[0.1, 1.0, 10.0, 1.0632794331401547]),
        // One rounding above an interior knot, and inside a span.
        ts: &[-2.493426982500263, -2.874462065796029],
    },
];

/// The control point whose span holds `t`: the last `k` with `u_k <= t`, at most `n - 1`.
fn span_of(knots: &[f64], t: f64) -> usize {
    let n = knots.len() - 1;
    (0..n)
        .rev()
        .find(|&k| knots[k] <= t)
        .expect("t in the domain")
}

fn curve<const D: usize>(case: &Case) -> AnyCurve<D> {
    let points: Vec<ControlPoint<D>> = case
        .rows
        .chunks_exact(D + 3)
        .map(|r| {
            let degrees = Degrees::new(r[D], r[D + 1], r[D + 2]).expect("valid degrees");
            ControlPoint::new(core::array::from_fn(|a| r[a]), degrees)
        })
        .collect();
    let knots = KnotVector::new(case.knots.to_vec(), 0, points.len()).unwrap();
    match case.weights {
        Some(w) => AnyCurve::Nurbs(Nurbs::new(points, w.to_vec(), knots).unwrap()),
        None => AnyCurve::BSpline(BSpline::new(points, knots).unwrap()),
    }
}

fn batch<const D: usize>(curve: &AnyCurve<D>, ts: &[f64]) -> Vec<f64> {
    let mut out = vec![0.0; (D + 3) * ts.len()];
    CurveBatch::new(curve)
        .evaluate(BatchParams::Values(ts), &mut out, &BatchOptions::default())
        .expect("batch evaluation");
    out
}

#[test]
fn degree_zero_splines_take_the_control_point_of_their_span() {
    for case in &CASES {
        let (curve, batch): (DynCurve, _) = match case.dimension {
            2 => {
                let c = curve::<2>(case);
                let b = batch(&c, case.ts);
                (c.into(), b)
            }
            _ => {
                let c = curve::<3>(case);
                let b = batch(&c, case.ts);
                (c.into(), b)
            }
        };
        let width = case.dimension + 3;
        for (i, &t) in case.ts.iter().enumerate() {
            let want = &case.rows[span_of(case.knots, t) * width..][..width];
            let got = curve.evaluate_row(t).expect("scalar evaluation");
            for c in 0..width {
                let tol = 1e-13 * want[c].abs().max(1.0);
                assert!(
                    (got[c] - want[c]).abs() <= tol,
                    "t = {t}: {got:?} != {want:?}"
                );
                let b = batch[c * case.ts.len() + i];
                assert!(
                    (b - want[c]).abs() <= tol,
                    "batch, t = {t}, channel {c}: {b}"
                );
            }
        }
    }
}
