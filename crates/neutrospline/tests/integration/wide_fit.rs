//! Fitting the data of the interval-valued and bipolar families, which ride in two lanes
//! (docs/model.md, "Lanes" and "Fitting under every rule"): the fit solves every channel of
//! both lanes at once under the family's whole rule.
//!
//! - Against `scripts/reference/make_wide_fit_reference.py`: data on the rule's boundary with
//!   jumps (the unconstrained fit breaks the rule), fixed knots and parameters; the fitted
//!   channels' objective, computed here from the public evaluation of both lanes, within 1e-9
//!   relative of a conic solver's optimum (cvxpy with Clarabel), and the curve inside the rule
//!   at 10,000 parameters.
//! - Data whose free fit keeps the rule: the two lanes are two independent neutrosophic fits.
//! - Surfaces: the same through the tensor-product fit.
//! - Refusals: a missing second lane, a second lane for a family of one, a point that breaks
//!   `lower <= upper`, with their messages.

use neutrospline::fit::{
    fit, fit_surface, FitData, FitError, FitOptions, FitTarget, SurfaceFitData, SurfaceFitOptions,
    SurfaceTarget,
};
use neutrospline::{AnyCurve, ControlPolygon, Degrees, Evaluate, Family};
use serde::Deserialize;

#[derive(Deserialize)]
struct Case {
    family: String,
    seed: u32,
    degree: usize,
    knots: Vec<f64>,
    parameters: Vec<f64>,
    positions: Vec<[f64; 2]>,
    channels: Vec<String>,
    values: Vec<Vec<f64>>,
    objective: f64,
    free_objective: f64,
}

#[derive(Deserialize)]
struct Reference {
    cases: Vec<Case>,
}

/// The two lanes of each row of channel values.
fn lanes(family: Family, values: &[Vec<f64>]) -> (Vec<Degrees>, Vec<Degrees>) {
    values
        .iter()
        .map(|row| {
            let (lanes, count) = family.split(row).expect("reference data obey the rule");
            assert_eq!(count, 2);
            (lanes[0], lanes[1])
        })
        .unzip()
}

/// The channels of both lanes at `t`.
fn channels_at(family: Family, lanes: [&AnyCurve<2>; 2], t: f64) -> Vec<f64> {
    let points = lanes.map(|curve| curve.evaluate(t).unwrap().degrees);
    family.join(&points).to_vec()
}

#[test]
fn wide_fits_reach_the_conic_solvers_optimum() {
    let text = include_str!("../data/wide_fit_reference.json");
    let reference: Reference = serde_json::from_str(text).unwrap();
    assert_eq!(reference.cases.len(), 8);
    for case in &reference.cases {
        let family: Family = case.family.parse().unwrap();
        let name = format!("{} seed {}", case.family, case.seed);
        assert_eq!(family.channels(), case.channels, "{name}");
        let (first, second) = lanes(family, &case.values);
        let data = FitData::new(case.positions.clone(), first)
            .unwrap()
            .with_second_lane(second)
            .unwrap()
            .with_parameters(case.parameters.clone())
            .unwrap();
        let options = FitOptions::default()
            .with_degree(case.degree)
            .with_knots(case.knots.clone())
            .with_membership(family);
        let fitted = fit(&data, &options).unwrap();
        let second = fitted.second_lane.as_ref().expect("a second lane");
        // Both lanes share the geometry.
        let (AnyCurve::BSpline(a), AnyCurve::BSpline(b)) = (&fitted.curve, second) else {
            panic!("{name}: B-spline lanes");
        };
        assert_eq!(a.knots(), b.knots(), "{name}");
        let (pa, pb) = (a.control_points(), b.control_points());
        for (i, (p, q)) in pa.iter().zip(&pb).enumerate() {
            assert_eq!(p.position, q.position, "{name}: control point {i}");
            // Every control point obeys the whole rule exactly.
            let values = family.join(&[p.degrees, q.degrees]);
            assert!(
                family.check(&values).is_ok(),
                "{name}: control point {i}: {values:?}"
            );
        }
        // The objective of the degree channels, from the public evaluation.
        let objective: f64 = case
            .parameters
            .iter()
            .zip(&case.values)
            .map(|(&t, want)| {
                let got = channels_at(family, [&fitted.curve, second], t);
                got.iter()
                    .zip(want)
                    .map(|(g, w)| (g - w) * (g - w))
                    .sum::<f64>()
            })
            .sum::<f64>()
            * 0.5;
        let relative = (objective - case.objective) / case.objective;
        assert!(
            relative.abs() <= 1e-9,
            "{name}: objective {objective} vs the conic solver's {} (relative {relative:e})",
            case.objective
        );
        assert!(objective > case.free_objective, "{name}: the rule binds");
        // The curve stays inside the rule (convexity) at 10,000 parameters.
        for k in 0..=10_000 {
            let t = k as f64 / 10_000.0;
            let values = channels_at(family, [&fitted.curve, second], t);
            assert!(
                family.check_within(&values, 1e-12).is_ok(),
                "{name}: t = {t}: {values:?}"
            );
        }
        // The report names the family's channels.
        let names: Vec<&str> = fitted.report.max_error.iter().map(|(n, _)| *n).collect();
        let mut want = vec!["x", "y"];
        want.extend(family.channels());
        assert_eq!(names, want, "{name}");
        assert!(
            !fitted.report.at_bound.is_empty(),
            "{name}: values on a bound"
        );
    }
}

/// Interval-neutrosophic data well inside the rule (lower + 0.3 <= upper, away from 0 and 1)
/// with smooth values: the free fit keeps the rule, so each lane is the neutrosophic fit of
/// its own degrees, to the last bit.
#[test]
fn lanes_inside_the_rule_fit_as_two_independent_neutrosophic_fits() {
    let m = 30;
    let positions: Vec<[f64; 2]> = (0..m)
        .map(|k| {
            let t = k as f64 / (m - 1) as f64;
            [4.0 * t, (2.0 * t).sin()]
        })
        .collect();
    let lower: Vec<Degrees> = (0..m)
        .map(|k| {
            let t = k as f64 / (m - 1) as f64;
            Degrees::new(0.2 + 0.1 * t, 0.1 + 0.05 * t * t, 0.3 - 0.1 * t).unwrap()
        })
        .collect();
    let upper: Vec<Degrees> = lower
        .iter()
        .map(|d| {
            Degrees::new(d.truth() + 0.4, d.indeterminacy() + 0.3, d.falsity() + 0.35).unwrap()
        })
        .collect();
    let options = FitOptions::default().with_target(FitTarget::ControlPoints(7));
    let wide = fit(
        &FitData::new(positions.clone(), lower.clone())
            .unwrap()
            .with_second_lane(upper.clone())
            .unwrap(),
        &options
            .clone()
            .with_membership(Family::IntervalNeutrosophic),
    )
    .unwrap();
    let alone = |degrees: Vec<Degrees>| {
        fit(&FitData::new(positions.clone(), degrees).unwrap(), &options)
            .unwrap()
            .curve
    };
    assert_eq!(wide.curve, alone(lower));
    assert_eq!(wide.second_lane.unwrap(), alone(upper));
    assert!(wide.report.at_bound.is_empty());
}

#[test]
fn wide_data_refusals_name_the_rule() {
    let positions = vec![[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]];
    let lower = vec![Degrees::new(0.2, 0.0, 0.0).unwrap(); 3];
    let mut upper = vec![Degrees::new(0.5, 0.0, 0.0).unwrap(); 3];
    let options = FitOptions::default()
        .with_degree(2)
        .with_target(FitTarget::Interpolate)
        .with_membership(Family::IntervalType2);
    let missing = fit(
        &FitData::new(positions.clone(), lower.clone()).unwrap(),
        &options,
    );
    assert_eq!(
        missing.unwrap_err().to_string(),
        "membership interval-type2 has 2 channels (truth_lower, truth_upper) in two lanes: the \
         data needs the second lane's degrees (`upper`) as well as the first (`lower`)"
    );
    let one_lane = fit(
        &FitData::new(positions.clone(), lower.clone())
            .unwrap()
            .with_second_lane(upper.clone())
            .unwrap(),
        &options.clone().with_membership(Family::Pythagorean),
    );
    assert!(matches!(one_lane, Err(FitError::Option(_))));
    assert_eq!(
        one_lane.unwrap_err().to_string(),
        "the data has a second lane of degrees, but membership pythagorean rides in one lane \
         (only the interval-valued and bipolar families have two)"
    );
    upper[1] = Degrees::new(0.1, 0.0, 0.0).unwrap();
    let crossed = fit(
        &FitData::new(positions.clone(), lower)
            .unwrap()
            .with_second_lane(upper)
            .unwrap(),
        &options,
    );
    let error = crossed.unwrap_err();
    assert!(matches!(error, FitError::Degrees { index: 1, .. }));
    assert_eq!(
        error.to_string(),
        format!(
            "point 1: {}",
            Family::IntervalType2.check(&[0.2, 0.1]).unwrap_err()
        )
    );
    let short = FitData::new(positions, vec![Degrees::new(0.2, 0.0, 0.0).unwrap(); 3])
        .unwrap()
        .with_second_lane(vec![Degrees::new(0.2, 0.0, 0.0).unwrap(); 2]);
    assert_eq!(
        short.unwrap_err().to_string(),
        "2 second-lane degree triples for 3 points (one per point)"
    );
}

/// A bipolar surface fitted to a grid whose degrees jump between the boxes' ends: every
/// control point obeys the rule, both lanes share the net, and data well inside the boxes fit
/// as two independent neutrosophic surfaces.
#[test]
fn wide_surfaces_fit_both_lanes_under_the_rule() {
    let (rows, cols) = (7, 6);
    let mut positions = Vec::new();
    let (mut positive, mut negative) = (Vec::new(), Vec::new());
    for k in 0..rows {
        for l in 0..cols {
            let (x, y) = (k as f64, l as f64);
            positions.push([x, y, 0.1 * x * y]);
            let high = (k + l) % 3 == 0;
            let (p, n) = if high {
                ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0])
            } else {
                ([0.0, 1.0, 1.0], [1.0, 0.0, 1.0])
            };
            // The negative lane holds the negated negative degrees, in [0, 1].
            positive.push(Degrees::new(p[0], p[1], p[2]).unwrap());
            negative.push(Degrees::new(n[0], n[1], n[2]).unwrap());
        }
    }
    let family = Family::BipolarNeutrosophic;
    let data = SurfaceFitData::grid(rows, cols, positions.clone(), positive)
        .unwrap()
        .with_second_lane(negative)
        .unwrap();
    let options = SurfaceFitOptions::default()
        .with_degrees(3, 3)
        .with_target(SurfaceTarget::ControlPoints([5, 5]))
        .with_membership(family);
    let fitted = fit_surface(&data, &options).unwrap();
    let second = fitted.second_lane.as_ref().expect("a second lane");
    assert_eq!([second.rows(), second.cols()], [5, 5]);
    for (i, (p, q)) in fitted
        .surface
        .control_points()
        .iter()
        .zip(second.control_points())
        .enumerate()
    {
        assert_eq!(p.position, q.position);
        let values = family.join(&[p.degrees, q.degrees]);
        assert!(
            family.check(&values).is_ok(),
            "control point {i}: {values:?}"
        );
    }
    assert!(!fitted.report.at_bound.is_empty());
    let names: Vec<&str> = fitted.report.max_error.iter().map(|(n, _)| *n).collect();
    assert_eq!(
        names,
        [
            "x",
            "y",
            "z",
            "truth",
            "indeterminacy",
            "falsity",
            "negative_truth",
            "negative_indeterminacy",
            "negative_falsity"
        ]
    );

    // Smooth degrees inside the boxes: two independent neutrosophic fits, to the last bit.
    let smooth = |k: usize, shift: f64| {
        let (x, y) = (
            (k / cols) as f64 / rows as f64,
            (k % cols) as f64 / cols as f64,
        );
        Degrees::new(0.3 + 0.2 * x + shift, 0.4 - 0.1 * y, 0.2 + 0.1 * x * y).unwrap()
    };
    let first: Vec<Degrees> = (0..rows * cols).map(|k| smooth(k, 0.0)).collect();
    let other: Vec<Degrees> = (0..rows * cols).map(|k| smooth(k, 0.1)).collect();
    let wide = fit_surface(
        &SurfaceFitData::grid(rows, cols, positions.clone(), first.clone())
            .unwrap()
            .with_second_lane(other.clone())
            .unwrap(),
        &options,
    )
    .unwrap();
    let neutrosophic = options.clone().with_membership(Family::Neutrosophic);
    let alone = |degrees: Vec<Degrees>| {
        fit_surface(
            &SurfaceFitData::grid(rows, cols, positions.clone(), degrees).unwrap(),
            &neutrosophic,
        )
        .unwrap()
        .surface
    };
    assert_eq!(wide.surface, alone(first));
    assert_eq!(wide.second_lane.unwrap(), alone(other));
}
