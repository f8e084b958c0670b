//! Fitting under every membership family that curves carry (docs/model.md, "Membership
//! families"; "Fitting under every rule"): adversarial data on and beyond the boundary of the
//! round rules, every fitted control value obeys the rule exactly (`Family::check`, no
//! tolerance), the curve stays inside it at 2,000 parameters, and the fitted channels are
//! optimal: moving any control point's channels toward another valid value never lowers the
//! least-squares objective (the variational inequality of a convex problem, checked by
//! brute force with the public evaluation only).

use neutrospline::fit::{fit, FitData, FitOptions, FitTarget};
use neutrospline::{
    AnyCurve, ControlPolygon, DegreeKind, Degrees, Evaluate, Family, RULE_TOLERANCE,
};
use proptest::prelude::*;

/// The families beyond the original three whose channels curves carry.
fn family() -> impl Strategy<Value = Family> {
    prop_oneof![
        Just(Family::Pythagorean),
        Just(Family::Fermatean),
        (1u32..=9).prop_map(|q| Family::q_rung(q).unwrap()),
        Just(Family::Picture),
        Just(Family::Spherical),
        (1u32..=6).prop_map(|n| Family::t_spherical(n).unwrap()),
    ]
}

/// The channel values of `family` in `degrees`.
fn channels(family: Family, degrees: &Degrees) -> Vec<f64> {
    DegreeKind::ALL
        .into_iter()
        .filter(|k| family.carries(*k))
        .map(|k| degrees.get(k))
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 40, ..ProptestConfig::default() })]

    #[test]
    fn fitted_channels_obey_the_rule_exactly_and_are_optimal(
        family in family(),
        raw in prop::collection::vec(prop::collection::vec(0.0..=1.3f64, 3), 12..40),
        boundary in prop::collection::vec(any::<bool>(), 40),
        control_points in 8usize..14,
        closed in any::<bool>(),
    ) {
        let n = raw.len();
        // Channel values: on the boundary (projected from outside) or anywhere inside, with
        // jumps between neighbours, so that the unconstrained fit overshoots the rule.
        let degrees: Vec<Degrees> = raw
            .iter()
            .enumerate()
            .map(|(k, row)| {
                let mut values: Vec<f64> = row[..family.channel_count()].to_vec();
                if boundary[k % boundary.len()] {
                    values.iter_mut().for_each(|v| *v += 1.0);
                }
                family.project(&mut values);
                family.to_degrees(&values).unwrap()
            })
            .collect();
        let positions: Vec<[f64; 2]> = (0..n)
            .map(|k| {
                let a = k as f64 / n as f64 * std::f64::consts::TAU;
                [3.0 * a.cos() + 0.1 * k as f64, 2.0 * a.sin()]
            })
            .collect();
        let data = FitData::new(positions, degrees.clone()).unwrap();
        let options = FitOptions::default()
            .with_membership(family)
            .with_closed(closed)
            .with_target(FitTarget::ControlPoints(control_points.min(n - 1)));
        let fitted = fit(&data, &options).unwrap();
        let AnyCurve::BSpline(curve) = &fitted.curve else {
            panic!("a B-spline fit");
        };
        let points = curve.control_points();
        for (i, p) in points.iter().enumerate() {
            let values = channels(family, &p.degrees);
            prop_assert!(family.check(&values).is_ok(), "{family}: control point {i}: {values:?}");
            for kind in DegreeKind::ALL {
                if !family.carries(kind) {
                    prop_assert_eq!(p.degrees.get(kind), 0.0);
                }
            }
        }
        let domain = curve.domain();
        for k in 0..2000 {
            let t = domain.start + (domain.end - domain.start) * k as f64 / 1999.0;
            let p = curve.evaluate(t).unwrap();
            let values = channels(family, &p.degrees);
            prop_assert!(family.check_within(&values, RULE_TOLERANCE).is_ok(), "{family} at {t}: {values:?}");
        }
        // Optimality: the objective sum_k |channels(C(t_k)) - channels(d_k)|^2 does not
        // drop when one control point's channels move toward another valid value.
        let objective = |points: &[neutrospline::ControlPoint<2>]| -> f64 {
            let c = neutrospline::BSpline::new(points.to_vec(), curve.knots().clone()).unwrap();
            fitted
                .parameters
                .iter()
                .zip(&degrees)
                .map(|(&t, d)| {
                    let got = channels(family, &c.evaluate(t).unwrap().degrees);
                    got.iter().zip(channels(family, d)).map(|(a, b)| (a - b).powi(2)).sum::<f64>()
                })
                .sum()
        };
        let base = objective(&points);
        let p = curve.degree();
        let distinct = if closed { points.len() - p } else { points.len() };
        for i in 0..distinct {
            for (j, target) in raw.iter().take(3).enumerate() {
                let mut y = target[..family.channel_count()].to_vec();
                family.project(&mut y);
                let x = channels(family, &points[i].degrees);
                let step = 1e-3 * (j + 1) as f64;
                let moved_values: Vec<f64> = x.iter().zip(&y).map(|(a, b)| a + step * (b - a)).collect();
                let Ok(d) = family.to_degrees(&moved_values) else { continue };
                let mut moved = points.clone();
                moved[i] = neutrospline::ControlPoint::new(moved[i].position, d);
                if closed && i < p {
                    moved[i + distinct] = neutrospline::ControlPoint::new(moved[i + distinct].position, d);
                }
                let value = objective(&moved);
                prop_assert!(
                    value >= base - 1e-9 * (1.0 + base),
                    "{family}: moving control point {i} toward {y:?} lowers the objective: {value} < {base}"
                );
            }
        }
    }
}
