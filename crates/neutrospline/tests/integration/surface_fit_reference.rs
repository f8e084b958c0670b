//! Surface fits against scipy (`tests/data/surface_fit_scipy.json`, made by
//! `scripts/reference/make_surface_fit_reference.py`): the parameters and knots computed
//! independently in Python, and control values from `make_interp_spline` /
//! `make_lsq_spline` along u then v (grids), `LSQBivariateSpline` with the same knots
//! (scattered height data), numpy's `lstsq` (weighted grids) and the penalised normal
//! equations (thin-plate smoothing). Every degree coefficient lies inside (0, 1), so the
//! bounded fit must equal the unconstrained one: within 1e-12 of each channel's largest
//! coefficient. The residuals are never larger than scipy's (beyond rounding).

use neutrospline::fit::{
    fit_surface, DataWeights, Parametrization, Projection, SurfaceFitData, SurfaceFitOptions,
    SurfaceTarget,
};
use neutrospline::{Degrees, EvaluateSurface};
use serde::Deserialize;

#[derive(Deserialize)]
struct File {
    cases: Vec<Case>,
}

#[derive(Deserialize)]
struct Case {
    name: String,
    shape: String,
    rows: usize,
    cols: usize,
    degrees: [usize; 2],
    target: String,
    control_points: [usize; 2],
    parametrization: String,
    smoothing: f64,
    weights: Option<Vec<f64>>,
    points: Vec<[f64; 3]>,
    tfi: Vec<[f64; 3]>,
    params: Vec<[f64; 2]>,
    knots_u: Vec<f64>,
    knots_v: Vec<f64>,
    coefficients: Vec<[f64; 6]>,
}

fn cases() -> Vec<Case> {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/surface_fit_scipy.json"
    ))
    .unwrap();
    serde_json::from_str::<File>(&text).unwrap().cases
}

#[test]
fn surface_fits_match_scipy() {
    let cases = cases();
    assert_eq!(cases.len(), 8);
    for case in cases {
        let degrees: Vec<Degrees> = case
            .tfi
            .iter()
            .map(|[t, i, f]| Degrees::new(*t, *i, *f).unwrap())
            .collect();
        let mut data = if case.shape == "grid" {
            SurfaceFitData::grid(case.rows, case.cols, case.points.clone(), degrees)
        } else {
            SurfaceFitData::scattered(case.points.clone(), degrees)
        }
        .unwrap();
        let mut options = SurfaceFitOptions::default()
            .with_degrees(case.degrees[0], case.degrees[1])
            .with_parametrization(case.parametrization.parse::<Parametrization>().unwrap())
            .with_projection(Projection::Xy)
            .with_smoothing(case.smoothing)
            .with_target(if case.target == "interpolate" {
                SurfaceTarget::Interpolate
            } else {
                SurfaceTarget::ControlPoints(case.control_points)
            });
        if let Some(w) = &case.weights {
            data = data.with_weights(w.clone()).unwrap();
            options = options.with_weights(DataWeights::Given);
        }
        let fitted = fit_surface(&data, &options).unwrap();
        let name = &case.name;
        // Parameters and knots, computed independently.
        for (got, want) in fitted.parameters.iter().zip(&case.params) {
            for a in 0..2 {
                assert!((got[a] - want[a]).abs() < 1e-14, "{name}: {got:?} {want:?}");
            }
        }
        let surface = &fitted.surface;
        for (got, want) in [
            (surface.knots_u().knots(), &case.knots_u),
            (surface.knots_v().knots(), &case.knots_v),
        ] {
            assert_eq!(got.len(), want.len(), "{name}");
            for (g, w) in got.iter().zip(want) {
                assert!((g - w).abs() < 1e-14, "{name}: knots {got:?} {want:?}");
            }
        }
        assert_eq!(
            [surface.rows(), surface.cols()],
            case.control_points,
            "{name}"
        );
        assert!(fitted.report.at_bound.is_empty(), "{name}");
        // Control values within 1e-12 of each channel's largest.
        let got: Vec<[f64; 6]> = surface
            .control_points()
            .iter()
            .map(|p| {
                let [t, i, f] = p.degrees.to_array();
                [p.position[0], p.position[1], p.position[2], t, i, f]
            })
            .collect();
        for c in 0..6 {
            let scale = case
                .coefficients
                .iter()
                .map(|w| w[c].abs())
                .fold(0.0, f64::max);
            for (g, w) in got.iter().zip(&case.coefficients) {
                assert!(
                    (g[c] - w[c]).abs() <= 1e-12 * scale,
                    "{name} channel {c}: {} vs scipy {} (scale {scale})",
                    g[c],
                    w[c]
                );
            }
        }
        // The residuals: no larger than scipy's (a least-squares minimum), to rounding.
        let n = case.control_points[1];
        let scipy_z = |u: f64, v: f64| -> f64 {
            let bu = basis(&case.knots_u, case.degrees[0], u);
            let bv = basis(&case.knots_v, case.degrees[1], v);
            let mut s = 0.0;
            for (i, a) in bu.iter().enumerate() {
                for (j, b) in bv.iter().enumerate() {
                    s += a * b * case.coefficients[i * n + j][2];
                }
            }
            s
        };
        let (mut ours, mut theirs) = (0.0, 0.0);
        for (k, [u, v]) in case.params.iter().enumerate() {
            let w = case.weights.as_ref().map_or(1.0, |w| w[k]);
            let z = case.points[k][2];
            ours += w * (surface.evaluate(*u, *v).unwrap().position[2] - z).powi(2);
            theirs += w * (scipy_z(*u, *v) - z).powi(2);
        }
        if case.smoothing == 0.0 {
            assert!(
                ours <= theirs * (1.0 + 1e-9) + 1e-28,
                "{name}: {ours} > {theirs}"
            );
        }
    }
}

/// Every B-spline basis function of `knots` at `t` (Cox-de Boor, written out here so the
/// check does not use the library's evaluation).
fn basis(knots: &[f64], p: usize, t: f64) -> Vec<f64> {
    let n = knots.len() - p - 1;
    let last = knots[knots.len() - 1];
    let mut b: Vec<f64> = (0..knots.len() - 1)
        .map(|i| {
            let inside = knots[i] <= t && t < knots[i + 1];
            let at_end = t == last && knots[i] < knots[i + 1] && knots[i + 1] == last;
            if inside || at_end {
                1.0
            } else {
                0.0
            }
        })
        .collect();
    for d in 1..=p {
        for i in 0..knots.len() - 1 - d {
            let left = if knots[i + d] > knots[i] {
                (t - knots[i]) / (knots[i + d] - knots[i]) * b[i]
            } else {
                0.0
            };
            let right = if knots[i + d + 1] > knots[i + 1] {
                (knots[i + d + 1] - t) / (knots[i + d + 1] - knots[i + 1]) * b[i + 1]
            } else {
                0.0
            };
            b[i] = left + right;
        }
    }
    b.truncate(n);
    b
}
