//! Checks the Bézier evaluator against independent reference data.
//!
//! The data in `tests/data/` is produced by `scripts/reference/make_bezier_reference.py`
//! (exact rationals for the paper's Example 1; an explicit Bernstein sum with exact
//! binomials in mpmath at 60 digits for the random curves). See
//! `scripts/reference/README.md` for how to regenerate it and for the tolerances:
//!
//! * position: `1e-12 * M`, with `M` the largest |position coordinate| of the control points;
//! * truth / indeterminacy / falsity: `1e-12` absolute;
//! * first derivative: the same times the degree `n` (the hodograph scales by `n`);
//! * degree 2000: `1e-11` in place of `1e-12`.

use neutrospline::{
    Bezier, ControlPoint, CurvePoint, Degrees, Derivative, Evaluate, NeutrosophicPoint,
};
use serde::Deserialize;

use crate::reference_common::{channel_name, point_channels, read_data, Checker};

// ------------------------------------------------------------------------ data files

#[derive(Debug, Deserialize)]
struct ControlPointJson {
    position: Vec<f64>,
    truth: f64,
    indeterminacy: f64,
    falsity: f64,
}

#[derive(Debug, Deserialize)]
struct DerivativeJson {
    position: Vec<f64>,
    truth: f64,
    indeterminacy: f64,
    falsity: f64,
}

#[derive(Debug, Deserialize)]
struct EvaluationJson {
    t: f64,
    /// example1.json only: how the parameter was chosen ("1/4", "1/10 (as double)", ...)
    #[serde(default)]
    t_label: Option<String>,
    position: Vec<f64>,
    truth: f64,
    indeterminacy: f64,
    falsity: f64,
    derivative: DerivativeJson,
}

#[derive(Debug, Deserialize)]
struct CaseJson {
    name: String,
    dimension: usize,
    degree: usize,
    control_points: Vec<ControlPointJson>,
    evaluations: Vec<EvaluationJson>,
}

#[derive(Debug, Deserialize)]
struct CaseFile {
    cases: Vec<CaseJson>,
}

#[derive(Debug, Deserialize)]
struct Example1Json {
    dimension: usize,
    degree: usize,
    control_points: Vec<ControlPointJson>,
    quarters: Vec<EvaluationJson>,
    grid: Vec<EvaluationJson>,
}

fn load_cases(name: &str) -> Vec<CaseJson> {
    let file: CaseFile = serde_json::from_str(&read_data(name, "make_bezier_reference.py"))
        .unwrap_or_else(|e| panic!("cannot parse tests/data/{name}: {e}"));
    assert!(!file.cases.is_empty(), "{name} holds no cases");
    file.cases
}

fn build_curve<const D: usize>(name: &str, cps: &[ControlPointJson]) -> Bezier<D> {
    let points: Vec<ControlPoint<D>> = cps
        .iter()
        .enumerate()
        .map(|(i, cp)| {
            let position: [f64; D] = cp.position.as_slice().try_into().unwrap_or_else(|_| {
                panic!(
                    "{name}: control point {i} has {} coordinates, expected {D}",
                    cp.position.len()
                )
            });
            let degrees = Degrees::new(cp.truth, cp.indeterminacy, cp.falsity)
                .unwrap_or_else(|e| panic!("{name}: control point {i}: {e}"));
            NeutrosophicPoint::new(position, degrees)
        })
        .collect();
    Bezier::new(points).unwrap_or_else(|e| panic!("{name}: Bezier::new failed: {e}"))
}

// ------------------------------------------------------------------------ comparison

/// Tolerances of one curve: `value` for position channels, 1 for degrees, times `rel`.
#[derive(Clone, Copy, Debug)]
struct Tolerance {
    rel: f64,
    position_scale: f64,
    degree: usize,
}

impl Tolerance {
    fn value(&self, channel: usize, dim: usize) -> f64 {
        if channel < dim {
            self.rel * self.position_scale
        } else {
            self.rel
        }
    }

    fn derivative(&self, channel: usize, dim: usize) -> f64 {
        self.value(channel, dim) * self.degree.max(1) as f64
    }
}

fn expected_channels(e: &EvaluationJson) -> (Vec<f64>, Vec<f64>) {
    let mut value = e.position.clone();
    value.extend_from_slice(&[e.truth, e.indeterminacy, e.falsity]);
    let d = &e.derivative;
    let mut deriv = d.position.clone();
    deriv.extend_from_slice(&[d.truth, d.indeterminacy, d.falsity]);
    (value, deriv)
}

/// Evaluates `curve` with `evaluate`, `evaluate_many` and the derivative, checks the two
/// evaluators agree bitwise and match the reference.
fn check_curve<const D: usize>(
    checker: &mut Checker,
    band: &str,
    case: &str,
    curve: &Bezier<D>,
    evaluations: &[EvaluationJson],
    tol: Tolerance,
) {
    let ts: Vec<f64> = evaluations.iter().map(|e| e.t).collect();
    let channels = D + 3;

    let single: Vec<CurvePoint<D>> = ts
        .iter()
        .map(|&t| {
            curve
                .evaluate(t)
                .unwrap_or_else(|e| panic!("{case}: evaluate({t:e}) failed: {e}"))
        })
        .collect();

    let mut many = single.clone(); // overwritten below
    curve
        .evaluate_many(&ts, &mut many)
        .unwrap_or_else(|e| panic!("{case}: evaluate_many failed: {e}"));

    let derivative = curve.derivative();

    for (k, e) in evaluations.iter().enumerate() {
        let t = e.t;
        let at = format!("{case}: t = {t:e}");
        assert_eq!(
            e.position.len(),
            D,
            "{case}: reference position has the wrong dimension"
        );
        let (want, want_d) = expected_channels(e);
        let got = point_channels(&single[k]);
        let got_many = point_channels(&many[k]);
        let d = derivative
            .evaluate(t)
            .unwrap_or_else(|err| panic!("{case}: derivative().evaluate({t:e}) failed: {err}"));
        let mut got_d = d.position.to_vec();
        got_d.extend_from_slice(&[d.truth, d.indeterminacy, d.falsity]);

        for c in 0..channels {
            let name = channel_name(c, D);
            checker.same_bits(
                &format!("{at}, {name}"),
                "evaluate_many != evaluate",
                got_many[c],
                got[c],
            );
            checker.close(band, &at, "value", name, got[c], want[c], tol.value(c, D));
            checker.close(
                band,
                &at,
                "derivative",
                name,
                got_d[c],
                want_d[c],
                tol.derivative(c, D),
            );
        }
    }
}

/// Labels padded so that they sort by degree in the summary.
fn degree_band(n: usize) -> &'static str {
    match n {
        0..=5 => "degree   1..5",
        6..=20 => "degree   7..20",
        21..=100 => "degree  30..100",
        101..=400 => "degree 200..400",
        _ => "degree 2000 (> 400)",
    }
}

fn check_case(checker: &mut Checker, case: &CaseJson, rel: f64) {
    assert_eq!(
        case.control_points.len(),
        case.degree + 1,
        "{}: control point count does not match the degree",
        case.name
    );
    let position_scale = case
        .control_points
        .iter()
        .flat_map(|cp| cp.position.iter())
        .fold(0.0_f64, |m, v| m.max(v.abs()));
    let tol = Tolerance {
        rel,
        position_scale,
        degree: case.degree,
    };
    let band = degree_band(case.degree);
    match case.dimension {
        2 => {
            let curve = build_curve::<2>(&case.name, &case.control_points);
            assert_eq!(curve.degree(), case.degree, "{}: degree()", case.name);
            check_curve(checker, band, &case.name, &curve, &case.evaluations, tol);
        }
        3 => {
            let curve = build_curve::<3>(&case.name, &case.control_points);
            assert_eq!(curve.degree(), case.degree, "{}: degree()", case.name);
            check_curve(checker, band, &case.name, &curve, &case.evaluations, tol);
        }
        d => panic!("{}: unsupported dimension {d}", case.name),
    }
}

// ------------------------------------------------------------------------ tests

#[test]
fn example1_exact_values() {
    let data: Example1Json =
        serde_json::from_str(&read_data("example1.json", "make_bezier_reference.py"))
            .expect("cannot parse tests/data/example1.json");
    assert_eq!(data.dimension, 2);
    assert_eq!(data.degree, 3);
    let curve = build_curve::<2>("example1", &data.control_points);
    assert_eq!(
        neutrospline::example1(),
        curve,
        "neutrospline::example1() differs from docs/model.md section 5 / Table 1 (C3 indeterminacy 0.4)"
    );
    assert_eq!(data.quarters.len(), 5);

    // docs/model.md section 5: at t = 0.5 the curve is at (4.625, 4.0), T = 0.625, I = 0.2, F = 0.175
    let half = &data.quarters[2];
    assert_eq!(half.t, 0.5);
    assert_eq!(half.position, [4.625, 4.0]);
    assert_eq!(
        [half.truth, half.indeterminacy, half.falsity],
        [0.625, 0.2, 0.175]
    );

    let tol = Tolerance {
        rel: 1e-12,
        position_scale: 1.0,
        degree: 1,
    }; // 1e-12 absolute
    let mut checker = Checker::default();
    for (band, evals) in [
        ("t = k/4", &data.quarters),
        ("t = k/10 (as double)", &data.grid),
    ] {
        assert!(
            evals.iter().all(|e| e.t_label.is_some()),
            "example1.json: t_label missing"
        );
        check_curve(&mut checker, band, "example1", &curve, evals, tol);
    }
    checker.finish("example1_exact_values");
}

#[test]
fn random_curves_match_mpmath() {
    let cases = load_cases("bezier_random.json");
    let mut checker = Checker::default();
    for case in &cases {
        check_case(&mut checker, case, 1e-12);
    }
    checker.finish("random_curves_match_mpmath");
}

#[test]
fn degree_2000_is_finite_and_accurate() {
    let cases = load_cases("bezier_degree2000.json");
    let mut checker = Checker::default();
    for case in &cases {
        assert!(
            case.degree >= 2000,
            "{}: expected a degree-2000 case",
            case.name
        );
        check_case(&mut checker, case, 1e-11);
    }
    checker.finish("degree_2000_is_finite_and_accurate");
}
