//! Accuracy at degrees 100, 400 and 2000 against mpmath (`tests/data/accuracy.json`, written
//! by `scripts/reference/make_accuracy_reference.py`): the compensated scalar evaluation of
//! every kind within 5e-16 of the exact value, scaled by the channel's largest control value,
//! in every channel; the compensated batch bit for bit the scalar one. Prints the README's
//! table (`cargo test -p neutrospline --lib accuracy -- --nocapture`).

use serde_json::Value;

use crate::any_curve::AnyCurve;
use crate::batch::{Accuracy, BatchOptions, BatchParams, CurveBatch};
use crate::bezier::Bezier;
use crate::curve::Evaluate;
use crate::degrees::Degrees;
use crate::knots::KnotVector;
use crate::point::ControlPoint;
use crate::spline_curve::{BSpline, Nurbs};

/// The bound of the compensated evaluation: scaled error at most this, every channel.
const BOUND: f64 = 5e-16;

fn float(v: &Value) -> f64 {
    match v.as_str().map(str::parse::<f64>) {
        Some(Ok(x)) => x,
        _ => panic!("not a float string: {v}"),
    }
}

fn floats(v: &Value) -> Vec<f64> {
    v.as_array().expect("an array").iter().map(float).collect()
}

/// Scaled error per channel: `max_k |value - (hi + lo)| / max_i |c_i|`.
fn scaled(values: &[[f64; 5]], exact: &[[(f64, f64); 5]], scale: &[f64; 5]) -> [f64; 5] {
    let mut out = [0.0f64; 5];
    for (v, e) in values.iter().zip(exact) {
        for c in 0..5 {
            let (hi, lo) = e[c];
            out[c] = out[c].max(((v[c] - hi) - lo).abs() / scale[c]);
        }
    }
    out
}

fn max(e: &[f64; 5]) -> f64 {
    e.iter().copied().fold(0.0, f64::max)
}

#[test]
fn accuracy_against_mpmath_at_high_degree() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/accuracy.json");
    let text = std::fs::read_to_string(path).expect("the accuracy data");
    let data: Value = serde_json::from_str(&text).expect("valid JSON");
    let unit = 2f64.powi(data["scale_exponent"].as_i64().expect("an exponent") as i32);
    let sets = data["sets"].as_array().expect("sets");
    println!("| kind | degree | compensated (scalar, default) | plain scalar (before) | fast batch | scipy | scipy / compensated |");
    println!("|---|---|---|---|---|---|---|");
    let mut checked = 0;
    for case in data["cases"].as_array().expect("cases") {
        let kind = case["kind"].as_str().expect("a kind");
        let p = case["degree"].as_u64().expect("a degree") as usize;
        let set = sets
            .iter()
            .find(|s| s["degree"].as_u64() == Some(p as u64))
            .expect("the case's set");
        let ints = set["rows"].as_array().expect("rows");
        let rows: Vec<f64> = ints
            .iter()
            .map(|v| v.as_i64().expect("an integer") as f64 * unit)
            .collect();
        let count = if kind == "bezier" { p + 1 } else { p + 4 };
        let points: Vec<ControlPoint<2>> = rows[..5 * count]
            .chunks_exact(5)
            .map(|r| {
                let d = Degrees::new(r[2], r[3], r[4]).expect("valid degrees");
                ControlPoint::new([r[0], r[1]], d)
            })
            .collect();
        let mut knots = vec![0.0; p + 1];
        knots.extend(floats(&set["interior_knots"]));
        knots.extend(vec![1.0; p + 1]);
        let weights: Vec<f64> = set["weights"].as_array().expect("weights")[..count]
            .iter()
            .map(|v| v.as_i64().expect("an integer") as f64 * unit)
            .collect();
        let curve: AnyCurve<2> = match kind {
            "bezier" => AnyCurve::Bezier(Bezier::new(points).expect("a curve")),
            "bspline" => AnyCurve::BSpline(
                BSpline::new(points, KnotVector::new(knots, p, count).expect("knots"))
                    .expect("a curve"),
            ),
            _ => AnyCurve::Nurbs(
                Nurbs::new(
                    points,
                    weights,
                    KnotVector::new(knots, p, count).expect("knots"),
                )
                .expect("a curve"),
            ),
        };
        let ts = floats(&case["parameters"]);
        let exact: Vec<[(f64, f64); 5]> = case["exact"]
            .as_array()
            .expect("exact values")
            .iter()
            .map(|point| {
                let channels = point.as_array().expect("channels");
                core::array::from_fn(|c| (float(&channels[c][0]), float(&channels[c][1])))
            })
            .collect();
        let mut scale = [0.0f64; 5];
        for r in rows[..5 * count].chunks_exact(5) {
            for (m, v) in scale.iter_mut().zip(r) {
                *m = m.max(v.abs());
            }
        }
        let row = |p: crate::point::CurvePoint<2>| {
            let [x, y] = p.position;
            let [a, b, c] = p.degrees.to_array();
            [x, y, a, b, c]
        };
        let ours: Vec<[f64; 5]> = ts
            .iter()
            .map(|&t| row(curve.evaluate(t).expect("in the domain")))
            .collect();
        let plain: Vec<[f64; 5]> = ts
            .iter()
            .map(|&t| {
                let mut out = [0.0; 5];
                match &curve {
                    AnyCurve::Bezier(c) => c.packed().evaluate(t, &mut out),
                    AnyCurve::BSpline(c) => {
                        c.spline().evaluate_plain(t, &mut out);
                    }
                    AnyCurve::Nurbs(c) => {
                        c.spline().evaluate_plain(t, &mut out);
                    }
                }
                out
            })
            .collect();
        // Preparing a batch (the Bézier pieces of a spline by blossoming) costs O(p^3): the
        // batch columns are skipped for the splines of degree 2000 (too slow unoptimised).
        let prepared = (kind == "bezier" || p <= 400).then(|| CurveBatch::from(&curve));
        let batch = |batch: &CurveBatch<2>, accuracy: Accuracy| -> Vec<[f64; 5]> {
            let mut out = vec![0.0; 5 * ts.len()];
            let options = BatchOptions::default().with_accuracy(accuracy);
            batch
                .evaluate(BatchParams::Values(&ts), &mut out, &options)
                .expect("in the domain");
            (0..ts.len())
                .map(|k| core::array::from_fn(|c| out[c * ts.len() + k]))
                .collect()
        };
        let e_ours = scaled(&ours, &exact, &scale);
        let e_plain = scaled(&plain, &exact, &scale);
        let fast = match &prepared {
            Some(b) => {
                assert_eq!(
                    batch(b, Accuracy::Compensated),
                    ours,
                    "{kind} {p}: compensated batch"
                );
                format!(
                    "{:.1e}",
                    max(&scaled(&batch(b, Accuracy::Fast), &exact, &scale))
                )
            }
            None => "(not run)".to_owned(),
        };
        let e_scipy: Vec<f64> = floats_of(&case["scipy_scaled_error"]);
        for (c, e) in e_ours.iter().enumerate() {
            assert!(
                *e <= BOUND,
                "{kind} degree {p} channel {c}: scaled error {e:.2e}"
            );
        }
        let scipy = e_scipy.iter().copied().fold(0.0, f64::max);
        println!(
            "| {kind} | {p} | {:.1e} | {:.1e} | {fast} | {:.1e} | {:.0}x |",
            max(&e_ours),
            max(&e_plain),
            scipy,
            scipy / max(&e_ours).max(f64::MIN_POSITIVE)
        );
        checked += 1;
    }
    assert_eq!(checked, 9, "three kinds at three degrees");
}

fn floats_of(v: &Value) -> Vec<f64> {
    v.as_array()
        .expect("an array")
        .iter()
        .map(|x| x.as_f64().expect("a number"))
        .collect()
}
