//! Fits against scipy (`tests/data/fit_scipy.json`, made by
//! `scripts/reference/make_fit_reference.py`): the same parameters and knots, computed
//! independently in Python, and control values from `make_lsq_spline` (weighted least
//! squares), `make_interp_spline` (interpolation), the penalised normal equations in numpy
//! (smoothing) and periodic `make_interp_spline` compared by value (closed curves). The data
//! keep every degree coefficient inside (0, 1), so the bounded fit must equal scipy's
//! unconstrained one: within 1e-10 of each channel's largest coefficient.

use neutrospline::fit::{fit, DataWeights, FitData, FitOptions, FitTarget, Parametrization};
use neutrospline::{AnyCurve, ControlPolygon, Degrees, Evaluate};
use serde::Deserialize;

#[derive(Deserialize)]
struct File {
    cases: Vec<Case>,
}

#[derive(Deserialize)]
struct Case {
    name: String,
    target: String,
    #[serde(default)]
    control_points: usize,
    degree: usize,
    dimension: usize,
    parametrization: String,
    smoothing: f64,
    #[serde(default)]
    closed: bool,
    points: Vec<Vec<f64>>,
    degrees: Vec<[f64; 3]>,
    parameters: Vec<f64>,
    #[serde(default)]
    knots: Vec<f64>,
    #[serde(default)]
    coefficients: Vec<Vec<f64>>,
    #[serde(default)]
    weights: Option<Vec<f64>>,
    #[serde(default)]
    samples: Vec<f64>,
    #[serde(default)]
    values: Vec<Vec<f64>>,
}

fn options(case: &Case) -> FitOptions {
    let parametrization = match case.parametrization.as_str() {
        "uniform" => Parametrization::Uniform,
        "centripetal" => Parametrization::Centripetal,
        _ => Parametrization::ChordLength,
    };
    let target = match case.target.as_str() {
        "interpolate" => FitTarget::Interpolate,
        _ => FitTarget::ControlPoints(case.control_points),
    };
    FitOptions::default()
        .with_degree(case.degree)
        .with_target(target)
        .with_parametrization(parametrization)
        .with_smoothing(case.smoothing)
        .with_closed(case.closed)
        .with_weights(if case.weights.is_some() {
            DataWeights::Given
        } else {
            DataWeights::None
        })
}

/// The channels of a control point: coordinates, then truth, indeterminacy, falsity.
fn channels<const D: usize>(curve: &AnyCurve<D>) -> Vec<Vec<f64>> {
    curve
        .control_points()
        .iter()
        .map(|p| {
            p.position
                .iter()
                .copied()
                .chain(p.degrees.to_array())
                .collect()
        })
        .collect()
}

fn run<const D: usize>(case: &Case) {
    let positions: Vec<[f64; D]> = case
        .points
        .iter()
        .map(|p| core::array::from_fn(|a| p[a]))
        .collect();
    let degrees = case
        .degrees
        .iter()
        .map(|&[t, i, f]| Degrees::new(t, i, f).unwrap())
        .collect();
    let mut data = FitData::new(positions, degrees).unwrap();
    if let Some(w) = &case.weights {
        data = data.with_weights(w.clone()).unwrap();
    }
    let fitted = fit(&data, &options(case)).unwrap_or_else(|e| panic!("{}: {e}", case.name));
    for (k, (got, want)) in fitted.parameters.iter().zip(&case.parameters).enumerate() {
        assert!(
            (got - want).abs() <= 1e-14,
            "{}: parameter {k}: {got} vs {want}",
            case.name
        );
    }
    let channels_count = D + 3;
    if case.closed {
        for (t, want) in case.samples.iter().zip(&case.values) {
            let p = fitted.curve.evaluate(*t).unwrap();
            let got: Vec<f64> = p
                .position
                .iter()
                .copied()
                .chain(p.degrees.to_array())
                .collect();
            for c in 0..channels_count {
                let scale = case
                    .values
                    .iter()
                    .fold(1e-300_f64, |m, v| m.max(v[c].abs()));
                assert!(
                    (got[c] - want[c]).abs() <= 1e-10 * scale,
                    "{}: t = {t}, channel {c}: {} vs {}",
                    case.name,
                    got[c],
                    want[c]
                );
            }
        }
        return;
    }
    let knots = fitted.curve.knots().unwrap().knots();
    assert_eq!(knots.len(), case.knots.len(), "{}: knot count", case.name);
    for (j, (got, want)) in knots.iter().zip(&case.knots).enumerate() {
        assert!(
            (got - want).abs() <= 1e-14,
            "{}: knot {j}: {got} vs {want}",
            case.name
        );
    }
    let got = channels(&fitted.curve);
    assert_eq!(
        got.len(),
        case.coefficients.len(),
        "{}: control points",
        case.name
    );
    for c in 0..channels_count {
        let scale = case
            .coefficients
            .iter()
            .fold(1e-300_f64, |m, row| m.max(row[c].abs()));
        for (i, (g, w)) in got.iter().zip(&case.coefficients).enumerate() {
            assert!(
                (g[c] - w[c]).abs() <= 1e-10 * scale,
                "{}: control point {i}, channel {c}: {} vs {} (difference {:e}, scale {scale})",
                case.name,
                g[c],
                w[c],
                (g[c] - w[c]).abs()
            );
        }
    }
    // Nothing sits on a bound here, and the report agrees.
    assert!(fitted.report.at_bound.is_empty(), "{}", case.name);
    assert!(fitted.report.schoenberg_whitney);
}

#[test]
fn fits_match_scipy() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/fit_scipy.json"
    ))
    .unwrap();
    let file: File = serde_json::from_str(&text).unwrap();
    assert_eq!(file.cases.len(), 14);
    for case in &file.cases {
        match case.dimension {
            2 => run::<2>(case),
            _ => run::<3>(case),
        }
    }
}
