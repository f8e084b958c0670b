//! Property tests of fitting (docs/model.md section 8): interpolation reproduces the data,
//! a sampled curve refitted on its own knots comes back, the degree channels stay valid under
//! every membership rule for adversarial data (and are optimal among feasible neighbours),
//! closed fits are C^(p-1) where they close, tolerance fits meet their tolerance or say so,
//! end tangents are met, score weights pull less for doubtful points; and the errors.

use neutrospline::fit::{
    fit, DataWeights, FitData, FitError, FitKind, FitOptions, FitTarget, Parametrization,
};
use neutrospline::strategies::bspline;
use neutrospline::{AnyCurve, ControlPolygon, Degrees, Derivative, Evaluate, Family, KnotVector};
use proptest::prelude::*;

/// Points along a wavy path, `m` of them, with degrees from `degree(k)`.
fn path<const D: usize>(m: usize, seed: f64, degree: impl Fn(usize) -> Degrees) -> FitData<D> {
    let positions: Vec<[f64; D]> = (0..m)
        .map(|k| {
            let s = k as f64 / (m - 1).max(1) as f64;
            core::array::from_fn(|a| match a {
                0 => 10.0 * s + (seed * 7.0 + s * 5.0).sin(),
                1 => 4.0 * (3.0 * s + seed).sin() + 0.1 * k as f64,
                _ => (2.0 * s + seed).cos(),
            })
        })
        .collect();
    let degrees = (0..m).map(degree).collect();
    FitData::new(positions, degrees).unwrap()
}

fn scale<const D: usize>(data: &FitData<D>) -> f64 {
    data.positions()
        .iter()
        .flat_map(|p| p.iter())
        .fold(1.0_f64, |m, v| m.max(v.abs()))
}

fn smooth_degrees(k: usize) -> Degrees {
    let s = k as f64 * 0.37;
    Degrees::new(
        0.5 + 0.3 * s.sin(),
        0.4 + 0.2 * s.cos(),
        0.3 + 0.1 * (2.0 * s).sin(),
    )
    .unwrap()
}

/// Degrees that jump 0 -> 1 -> 0: the interpolant of such data leaves [0, 1].
fn jumping(membership: Family) -> impl Fn(usize) -> Degrees {
    move |k| {
        let high = (k / 2) % 2 == 0;
        let v = if high { 1.0 } else { 0.0 };
        match membership {
            Family::Neutrosophic => Degrees::new(v, 1.0 - v, v).unwrap(),
            Family::Intuitionistic => Degrees::intuitionistic(v, 1.0 - v).unwrap(),
            family => {
                let mut values: Vec<f64> = carried(family)
                    .iter()
                    .map(|&c| if c == 1 { 1.0 - v } else { v })
                    .collect();
                family.project(&mut values);
                family.to_degrees(&values).unwrap()
            }
        }
    }
}

/// The slots (0 truth, 1 indeterminacy, 2 falsity) of the degrees `family` carries.
fn carried(family: Family) -> Vec<usize> {
    neutrospline::DegreeKind::ALL
        .into_iter()
        .filter(|k| family.carries(*k))
        .map(neutrospline::DegreeKind::index)
        .collect()
}

fn parametrization() -> impl Strategy<Value = Parametrization> {
    prop::sample::select(vec![
        Parametrization::Uniform,
        Parametrization::ChordLength,
        Parametrization::Centripetal,
    ])
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn interpolation_reproduces_the_data(
        p in 1usize..=7,
        extra in 0usize..30,
        seed in -3.0..3.0f64,
        param in parametrization(),
        three in any::<bool>(),
    ) {
        let m = p + 1 + extra;
        let options = FitOptions::default()
            .with_degree(p)
            .with_target(FitTarget::Interpolate)
            .with_parametrization(param);
        if three {
            check_interpolation(&path::<3>(m, seed, smooth_degrees), &options)?;
        } else {
            check_interpolation(&path::<2>(m, seed, smooth_degrees), &options)?;
        }
    }

    #[test]
    fn refit_on_own_knots_comes_back(
        curve in bspline::<2>(1..=5),
        count in 0usize..40,
    ) {
        let knots = curve.knots().clone();
        let n = curve.len();
        let domain = curve.domain();
        // Enough samples in every span: uniform over the domain plus the knots themselves.
        let mut ts: Vec<f64> = (0..(4 * n + count))
            .map(|k| neutrospline::uniform_parameter(k, 4 * n + count, domain.clone()))
            .collect();
        ts.extend(knots.interior_breakpoints());
        ts.sort_by(f64::total_cmp);
        let points: Vec<_> = ts.iter().map(|&t| curve.evaluate(t).unwrap()).collect();
        let data = FitData::new(
            points.iter().map(|q| q.position).collect(),
            points.iter().map(|q| q.degrees).collect(),
        )
        .unwrap()
        .with_parameters(ts.clone())
        .unwrap();
        let options = FitOptions::default()
            .with_degree(knots.degree())
            .with_knots(knots.knots().to_vec());
        let fitted = match fit(&data, &options) {
            Ok(f) => f,
            // Knots of multiplicity p + 1 inside the domain, or spans without samples,
            // leave control points undetermined: the fit must say so, not guess.
            Err(FitError::SchoenbergWhitney { .. } | FitError::Singular) => return Ok(()),
            Err(e) => return Err(TestCaseError::fail(e.to_string())),
        };
        let s = curve.control_points().iter().flat_map(|q| q.position).fold(1.0_f64, |m, v| m.max(v.abs()));
        let cond = fitted.report.condition_estimate;
        prop_assume!(cond < 1e8);
        for (got, want) in fitted.curve.control_points().iter().zip(curve.control_points()) {
            for a in 0..2 {
                prop_assert!((got.position[a] - want.position[a]).abs() <= 1e-10 * s,
                    "{} vs {} (cond {cond:e})", got.position[a], want.position[a]);
            }
            for (g, w) in got.degrees.to_array().iter().zip(want.degrees.to_array()) {
                prop_assert!((g - w).abs() <= 1e-10, "{g} vs {w}");
            }
        }
    }

    #[test]
    fn degrees_stay_valid_for_adversarial_data(
        p in 1usize..=5,
        extra in 0usize..40,
        rule in prop::sample::select(vec![Family::Neutrosophic, Family::Intuitionistic, Family::Fuzzy]),
        interpolate in any::<bool>(),
        closed in any::<bool>(),
        t in 0.0..1.0f64,
    ) {
        let m = 2 * p + 3 + extra;
        let data = path::<2>(m, 0.4, jumping(rule));
        let target = if interpolate { FitTarget::Interpolate } else { FitTarget::ControlPoints((m / 2).max(2 * p + 2)) };
        let options = FitOptions::default()
            .with_degree(p)
            .with_target(target)
            .with_membership(rule)
            .with_closed(closed);
        let fitted = fit(&data, &options).map_err(|e| TestCaseError::fail(e.to_string()))?;
        for q in fitted.curve.control_points() {
            prop_assert!(q.degrees.check_membership(rule).is_ok(), "{:?}", q.degrees);
        }
        let domain = fitted.curve.domain();
        let at = domain.start + t * (domain.end - domain.start);
        let d = fitted.curve.evaluate(at.min(domain.end)).unwrap().degrees;
        prop_assert!(d.to_array().iter().all(|v| (0.0..=1.0).contains(v)));
        if rule == Family::Intuitionistic {
            prop_assert!(d.truth() + d.falsity() <= 1.0 + 1e-12);
        }
        check_optimal(&data, &fitted.curve, &fitted.parameters, rule, closed)?;
    }

    #[test]
    fn closed_fits_are_smooth_where_they_close(
        p in 1usize..=5,
        extra in 0usize..20,
        interpolate in any::<bool>(),
    ) {
        let m = 2 * p + 4 + extra;
        // Points round an ellipse.
        let positions: Vec<[f64; 2]> = (0..m)
            .map(|k| {
                let a = 2.0 * core::f64::consts::PI * k as f64 / m as f64;
                [3.0 * a.cos() + 0.2 * (3.0 * a).sin(), 2.0 * a.sin()]
            })
            .collect();
        let data = FitData::new(positions, (0..m).map(smooth_degrees).collect()).unwrap();
        let target = if interpolate { FitTarget::Interpolate } else { FitTarget::ControlPoints(2 * p + 2 + extra / 2) };
        let fitted = fit(&data, &FitOptions::default().with_degree(p).with_closed(true).with_target(target))
            .map_err(|e| TestCaseError::fail(e.to_string()))?;
        let c = &fitted.curve;
        let d = c.domain();
        let (a, b) = (c.evaluate(d.start).unwrap(), c.evaluate(d.end).unwrap());
        prop_assert!((a.position[0] - b.position[0]).abs() < 1e-12 && (a.position[1] - b.position[1]).abs() < 1e-12);
        let mut derivative = c.derivative();
        for order in 1..p {
            let (x, y) = (derivative.evaluate(d.start).unwrap(), derivative.evaluate(d.end).unwrap());
            let size = x.position.iter().fold(1.0_f64, |m, v| m.max(v.abs()));
            for k in 0..2 {
                prop_assert!((x.position[k] - y.position[k]).abs() <= 1e-9 * size,
                    "order {order}: {} vs {}", x.position[k], y.position[k]);
            }
            derivative = derivative.derivative();
        }
        if interpolate {
            for (k, &t) in fitted.parameters.iter().enumerate() {
                let q = c.evaluate(t).unwrap();
                for a in 0..2 {
                    prop_assert!((q.position[a] - data.positions()[k][a]).abs() < 1e-11);
                }
            }
        }
    }

    #[test]
    fn tolerance_fits_meet_the_tolerance_or_say_so(
        p in 1usize..=4,
        m in 20usize..200,
        noise in 0.0..0.2f64,
        tolerance in 1e-4..0.5f64,
        closed in any::<bool>(),
    ) {
        let mut data = path::<2>(m, 1.0, smooth_degrees);
        // Deterministic noise.
        let noisy: Vec<[f64; 2]> = data
            .positions()
            .iter()
            .enumerate()
            .map(|(k, q)| [q[0] + noise * ((k as f64 * 12.9898).sin() * 43758.5453).fract(), q[1]])
            .collect();
        data = FitData::new(noisy, data.degrees().to_vec()).unwrap();
        let options = FitOptions::default()
            .with_degree(p)
            .with_closed(closed && m > 2 * p + 2)
            .with_target(FitTarget::Tolerance(tolerance));
        let fitted = fit(&data, &options).map_err(|e| TestCaseError::fail(e.to_string()))?;
        let worst = fitted
            .parameters
            .iter()
            .zip(data.positions())
            .map(|(&t, q)| {
                let c = fitted.curve.evaluate(t).unwrap().position;
                ((c[0] - q[0]).powi(2) + (c[1] - q[1]).powi(2)).sqrt()
            })
            .fold(0.0, f64::max);
        let met = fitted.report.tolerance_met.unwrap();
        prop_assert!((worst - fitted.report.worst_distance).abs() < 1e-9);
        if met {
            prop_assert!(worst <= tolerance, "{worst} > {tolerance}");
        } else {
            prop_assert!(worst > tolerance);
        }
    }
}

/// Positions (and degrees, where no bound is active) pass through the data.
fn check_interpolation<const D: usize>(
    data: &FitData<D>,
    options: &FitOptions,
) -> Result<(), TestCaseError> {
    let fitted = fit(data, options).map_err(|e| TestCaseError::fail(e.to_string()))?;
    prop_assert_eq!(fitted.curve.len(), data.len());
    let s = scale(data);
    for (k, &t) in fitted.parameters.iter().enumerate() {
        let q = fitted.curve.evaluate(t).unwrap();
        for a in 0..D {
            prop_assert!(
                (q.position[a] - data.positions()[k][a]).abs() <= 1e-12 * s,
                "point {k}, axis {a}: {} vs {}",
                q.position[a],
                data.positions()[k][a]
            );
        }
        if fitted.report.at_bound.is_empty() {
            for (g, w) in q
                .degrees
                .to_array()
                .iter()
                .zip(data.degrees()[k].to_array())
            {
                prop_assert!((g - w).abs() <= 1e-12, "point {k}: degree {g} vs {w}");
            }
        }
    }
    Ok(())
}

/// The weighted sum of squared degree residuals of the fitted curve is no larger than that of
/// feasible neighbours (each control value moved by +-1e-4 inside the rule's set): the
/// constrained optimum, checked without the solver.
fn check_optimal(
    data: &FitData<2>,
    curve: &AnyCurve<2>,
    params: &[f64],
    rule: Family,
    closed: bool,
) -> Result<(), TestCaseError> {
    let AnyCurve::BSpline(spline) = curve else {
        return Ok(());
    };
    let objective = |points: &[neutrospline::ControlPoint<2>]| -> f64 {
        let c = neutrospline::BSpline::new(points.to_vec(), spline.knots().clone()).unwrap();
        params
            .iter()
            .zip(data.degrees())
            .map(|(&t, d)| {
                let got = c.evaluate(t).unwrap().degrees.to_array();
                let want = d.to_array();
                carried(rule)
                    .iter()
                    .map(|&c| (got[c] - want[c]).powi(2))
                    .sum::<f64>()
            })
            .sum()
    };
    let points = spline.control_points();
    let base = objective(&points);
    // A closed curve repeats its first p control points at the end: they move together.
    let p = spline.degree();
    let distinct = if closed {
        points.len() - p
    } else {
        points.len()
    };
    for i in 0..distinct {
        for (c, delta) in [(0usize, 1e-4), (0, -1e-4), (2, 1e-4), (2, -1e-4)] {
            if rule == Family::Fuzzy && c != 0 {
                continue;
            }
            let mut moved = points.clone();
            let mut v = moved[i].degrees.to_array();
            v[c] += delta;
            let d = match rule {
                Family::Neutrosophic => Degrees::new(v[0], v[1], v[2]),
                Family::Intuitionistic => Degrees::intuitionistic(v[0], v[2]),
                family => {
                    family.to_degrees(&carried(family).iter().map(|&c| v[c]).collect::<Vec<_>>())
                }
            };
            let Ok(d) = d else { continue };
            moved[i] = neutrospline::ControlPoint::new(moved[i].position, d);
            if closed && i < p {
                moved[i + distinct] =
                    neutrospline::ControlPoint::new(moved[i + distinct].position, d);
            }
            let value = objective(&moved);
            prop_assert!(
                value >= base - 1e-9 * (1.0 + base),
                "moving control point {i} channel {c} by {delta} lowers the objective: {value} < {base}"
            );
        }
    }
    Ok(())
}

#[test]
fn end_tangents_are_met() {
    let data = path::<2>(12, 0.3, smooth_degrees);
    let options = FitOptions::default()
        .with_target(FitTarget::Interpolate)
        .with_end_tangents(vec![5.0, -2.0], vec![1.0, 8.0]);
    let fitted = fit(&data, &options).unwrap();
    assert_eq!(fitted.curve.len(), 14);
    let d = fitted.curve.derivative();
    let domain = fitted.curve.domain();
    let (a, b) = (
        d.evaluate(domain.start).unwrap(),
        d.evaluate(domain.end).unwrap(),
    );
    for (got, want) in a.position.iter().zip([5.0, -2.0]) {
        assert!((got - want).abs() < 1e-10, "{got} vs {want}");
    }
    for (got, want) in b.position.iter().zip([1.0, 8.0]) {
        assert!((got - want).abs() < 1e-10, "{got} vs {want}");
    }
    for (k, &t) in fitted.parameters.iter().enumerate() {
        let q = fitted.curve.evaluate(t).unwrap().position;
        assert!((q[0] - data.positions()[k][0]).abs() < 1e-11);
    }
}

#[test]
fn score_weights_pull_less_for_doubtful_points() {
    // Two lines of points at y = 0 (trusted) and y = 1 (doubtful), alternating: a straight
    // least-squares line settles nearer the trusted ones with score weights.
    let m = 40;
    let positions: Vec<[f64; 2]> = (0..m).map(|k| [k as f64, (k % 2) as f64]).collect();
    let degrees: Vec<Degrees> = (0..m)
        .map(|k| {
            if k % 2 == 0 {
                Degrees::new(1.0, 0.0, 0.0).unwrap()
            } else {
                Degrees::new(0.1, 0.8, 0.8).unwrap()
            }
        })
        .collect();
    let data = FitData::new(positions, degrees).unwrap();
    let line = |weights| {
        let options = FitOptions::default()
            .with_degree(1)
            .with_target(FitTarget::ControlPoints(2))
            .with_weights(weights)
            .with_parametrization(Parametrization::Uniform);
        fit(&data, &options)
            .unwrap()
            .curve
            .evaluate(0.5)
            .unwrap()
            .position[1]
    };
    let (plain, scored) = (line(DataWeights::None), line(DataWeights::Score));
    assert!((plain - 0.5).abs() < 0.03, "{plain}");
    // Scores 1 and 0.1667: the weighted mean is 0.1667 / 1.1667 = 0.1429.
    assert!((scored - 1.0 / 7.0).abs() < 0.03, "{scored}");
}

#[test]
fn bezier_fits() {
    let data = path::<2>(30, 0.1, smooth_degrees);
    let options = FitOptions::default()
        .with_kind(FitKind::Bezier)
        .with_degree(4)
        .with_target(FitTarget::ControlPoints(5));
    let fitted = fit(&data, &options).unwrap();
    assert!(matches!(fitted.curve, AnyCurve::Bezier(_)));
    assert_eq!(fitted.curve.len(), 5);
    // A tolerance raises the degree until it is met.
    let tolerant = fit(
        &data,
        &FitOptions::default()
            .with_kind(FitKind::Bezier)
            .with_degree(2)
            .with_target(FitTarget::Tolerance(0.05)),
    )
    .unwrap();
    assert_eq!(tolerant.report.tolerance_met, Some(true));
    assert!(tolerant.report.worst_distance <= 0.05);
    assert!(tolerant.curve.degree() > 2);
}

#[test]
fn fit_errors_name_the_problem() {
    let d = Degrees::new(0.5, 0.5, 0.5).unwrap();
    let three = FitData::new(vec![[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]], vec![d; 3]).unwrap();
    let interpolate = FitOptions::default().with_target(FitTarget::Interpolate);
    assert_eq!(
        fit(&three, &interpolate).unwrap_err().to_string(),
        "3 points are too few: interpolation with degree 3 needs at least 4"
    );
    let repeated = FitData::new(
        vec![[0.0, 0.0], [1.0, 1.0], [1.0, 1.0], [2.0, 0.0], [3.0, 1.0]],
        vec![d; 5],
    )
    .unwrap();
    assert!(matches!(
        fit(&repeated, &interpolate),
        Err(FitError::RepeatedPoint {
            index: 2,
            previous: 1,
        })
    ));
    let given = repeated
        .clone()
        .with_parameters(vec![0.0, 0.2, 0.2, 0.6, 1.0])
        .unwrap();
    assert_eq!(
        fit(&given, &interpolate).unwrap_err().to_string(),
        "point 2 repeats the parameter of point 1 (t = 0.2): interpolation passes through every \
         point at its own parameter"
    );
    assert_eq!(
        three
            .clone()
            .with_weights(vec![1.0, 0.0, 2.0])
            .unwrap_err()
            .to_string(),
        "point 1: weight = 0 is not a positive finite number (data weights must be > 0)"
    );
    assert_eq!(
        FitData::new(vec![[0.0, f64::NAN]], vec![d])
            .unwrap_err()
            .to_string(),
        "point 0: y = NaN is not a finite number"
    );
    assert_eq!(
        fit(
            &three,
            &FitOptions::default().with_target(FitTarget::Tolerance(0.0))
        )
        .unwrap_err()
        .to_string(),
        "tolerance = 0 is not a positive finite number"
    );
    assert_eq!(
        fit(
            &three,
            &FitOptions::default().with_degree(1).with_smoothing(0.5)
        )
        .unwrap_err()
        .to_string(),
        "smoothing penalises the second derivative, which a degree-1 curve does not have (use \
         degree 2 or more)"
    );
    let bad = FitData::new(
        vec![[0.0, 0.0], [1.0, 0.0]],
        vec![Degrees::new(0.7, 0.0, 0.6).unwrap(); 2],
    )
    .unwrap();
    assert_eq!(
        fit(&bad, &FitOptions::default().with_degree(1).with_membership(Family::Intuitionistic))
            .unwrap_err()
            .to_string(),
        "point 0: truth + falsity = 0.7 + 0.6 = 1.2999999999999998 exceeds 1 (intuitionistic rule: truth + falsity <= 1)"
    );
    let knots = KnotVector::clamped_uniform(3, 6).unwrap();
    assert!(fit(
        &three,
        &FitOptions::default()
            .with_knots(knots.knots().to_vec())
            .with_target(FitTarget::Interpolate)
    )
    .is_err());
}

/// A case proptest found: refining toward 1e-4 through noise of 0.15 reaches a layout whose
/// system is singular in double precision although the Schoenberg-Whitney conditions hold.
/// The fit keeps the last solvable layout and says the tolerance is not met.
#[test]
fn tolerance_refinement_stops_before_a_singular_system() {
    let (p, m, noise, tolerance) = (2usize, 83usize, 0.15140413279227788f64, 0.0001f64);
    let mut data = path::<2>(m, 1.0, smooth_degrees);
    let noisy: Vec<[f64; 2]> = data
        .positions()
        .iter()
        .enumerate()
        .map(|(k, q)| {
            [
                q[0] + noise * ((k as f64 * 12.9898).sin() * 43758.5453).fract(),
                q[1],
            ]
        })
        .collect();
    data = FitData::new(noisy, data.degrees().to_vec()).unwrap();
    let options = FitOptions::default()
        .with_degree(p)
        .with_target(FitTarget::Tolerance(tolerance));
    let fitted = fit(&data, &options).unwrap();
    assert_eq!(fitted.report.tolerance_met, Some(false));
    assert!(fitted.report.worst_distance > tolerance);
    assert!(fitted.report.control_points > 3 && fitted.report.control_points < m);
}
