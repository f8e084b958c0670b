//! Blending keeps every membership family's rule (docs/model.md, "Membership families"): for
//! every family of SPEC section 10 and every kind (Bézier, B-spline on clamped, unclamped or
//! periodic knots, NURBS with random weights), control values on the boundary of the rule
//! (random values projected onto it) blend, through the library's own evaluation, to values
//! inside the rule at 10,000 parameters, lower bounds of intervals stay at or below their
//! upper bounds, and the derived degrees computed from the blend are in [0, 1]. The channels
//! ride as the coordinates of 3-D curves that share one basis (knots and weights), three
//! channels per curve, so this is the engine's blend, not a copy of it.

use neutrospline::{
    AnyCurve, BSpline, Bezier, ControlPoint, ControlPolygon, Degrees, Evaluate, Family, KnotVector,
    Nurbs, RULE_TOLERANCE,
};
use proptest::prelude::*;

/// How the curves of one case are built: kind 0 Bézier, 1 B-spline, 2 NURBS; knots 0 clamped,
/// 1 unclamped, 2 periodic.
#[derive(Clone, Debug)]
struct Layout {
    kind: usize,
    knots: usize,
    degree: usize,
    count: usize,
    weights: Vec<f64>,
}

fn layout() -> impl Strategy<Value = Layout> {
    (0usize..3, 0usize..3, 1usize..=5, 0usize..=5).prop_flat_map(|(kind, knots, degree, extra)| {
        let count = degree + 1 + extra;
        prop::collection::vec(0.05f64..20.0, count).prop_map(move |weights| Layout {
            kind,
            knots,
            degree,
            count,
            weights,
        })
    })
}

/// Channel vectors on the boundary of `family`'s rule: random values from a box larger than
/// the rule's, projected onto it.
fn boundary_values(family: Family, count: usize, seed: &[f64]) -> Vec<Vec<f64>> {
    let c = family.channel_count();
    (0..count)
        .map(|i| {
            let mut v: Vec<f64> = (0..c).map(|k| seed[(i * c + k) % seed.len()]).collect();
            family.project(&mut v);
            family.check(&v).unwrap();
            v
        })
        .collect()
}

/// The curves carrying `values` (three channels each, the last padded with 0), one basis.
fn curves(layout: &Layout, values: &[Vec<f64>]) -> Vec<AnyCurve<3>> {
    let c = values[0].len();
    let dummy = Degrees::new(0.5, 0.5, 0.5).unwrap();
    let n = values.len();
    (0..c.div_ceil(3))
        .map(|part| {
            let points: Vec<ControlPoint<3>> = values
                .iter()
                .map(|v| {
                    let mut position = [0.0; 3];
                    for (k, slot) in position.iter_mut().enumerate() {
                        *slot = v.get(part * 3 + k).copied().unwrap_or(0.0);
                    }
                    ControlPoint::new(position, dummy)
                })
                .collect();
            if layout.kind == 0 {
                return Bezier::new(points).unwrap().into();
            }
            let p = layout.degree;
            let (points, weights, knots) = match layout.knots {
                0 => (
                    points,
                    layout.weights.clone(),
                    KnotVector::clamped_uniform(p, n).unwrap(),
                ),
                1 => (
                    points,
                    layout.weights.clone(),
                    KnotVector::uniform(p, n).unwrap(),
                ),
                _ => {
                    let breakpoints: Vec<f64> = (0..=n).map(|j| (j as f64).sqrt()).collect();
                    let wrap = |i: usize| i % n;
                    let knots = KnotVector::periodic(p, &breakpoints).unwrap();
                    (
                        (0..n + p).map(|i| points[wrap(i)]).collect(),
                        (0..n + p).map(|i| layout.weights[wrap(i)]).collect(),
                        knots,
                    )
                }
            };
            if layout.kind == 1 {
                BSpline::new(points, knots).unwrap().into()
            } else {
                Nurbs::new(points, weights, knots).unwrap().into()
            }
        })
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(6))]

    #[test]
    fn every_family_stays_inside_its_rule(
        layout in layout(),
        seed in prop::collection::vec(-0.6f64..1.6, 37),
    ) {
        for family in Family::EXAMPLES {
            let count = if layout.kind == 0 { layout.degree + 1 } else { layout.count };
            let values = boundary_values(family, count, &seed);
            let parts = curves(&layout, &values);
            let domain = parts[0].domain();
            let c = family.channel_count();
            for k in 0..10_000u32 {
                let t = (domain.start + (domain.end - domain.start) * f64::from(k) / 9_999.0).min(domain.end);
                let mut blend = Vec::with_capacity(6);
                for curve in &parts {
                    blend.extend_from_slice(&curve.evaluate(t).unwrap().position);
                }
                blend.truncate(c);
                prop_assert!(
                    family.check_within(&blend, RULE_TOLERANCE).is_ok(),
                    "{family} at t = {t}: {blend:?}: {}",
                    family.check_within(&blend, RULE_TOLERANCE).unwrap_err()
                );
                for &(lower, upper) in family.interval_pairs() {
                    prop_assert!(blend[lower] <= blend[upper] + RULE_TOLERANCE);
                }
                for d in family.derived(&blend).iter() {
                    prop_assert!((0.0..=1.0).contains(d), "{family}: derived {d}");
                }
            }
        }
    }
}

/// The curves of `layout` whose control points carry `lanes[i]` as degrees and `positions[i]`
/// as positions: one curve per lane of a wide family, one geometry.
fn lane_curves(layout: &Layout, family: Family, values: &[Vec<f64>]) -> Vec<AnyCurve<3>> {
    let split: Vec<[Degrees; 2]> = values.iter().map(|v| family.split(v).unwrap().0).collect();
    (0..family.lane_count())
        .map(|lane| {
            // The lane's degrees ride in the degree slots; the positions are any fixed points.
            let carrier: Vec<Vec<f64>> = (0..values.len())
                .map(|i| vec![i as f64, (i * i) as f64 * 0.5, 1.0 - i as f64])
                .collect();
            let mut curve = curves(layout, &carrier).remove(0);
            let degrees: Vec<Degrees> = split.iter().map(|lanes| lanes[lane]).collect();
            curve = with_degrees(curve, &degrees);
            curve
        })
        .collect()
}

/// `curve` with the control degrees `degrees` (periodic layouts repeat the first ones).
fn with_degrees(curve: AnyCurve<3>, degrees: &[Degrees]) -> AnyCurve<3> {
    let n = degrees.len();
    let points: Vec<ControlPoint<3>> = curve
        .control_points()
        .iter()
        .enumerate()
        .map(|(i, p)| ControlPoint::new(p.position, degrees[i % n]))
        .collect();
    match curve {
        AnyCurve::Bezier(_) => Bezier::new(points).unwrap().into(),
        AnyCurve::BSpline(c) => BSpline::new(points, c.knots().clone()).unwrap().into(),
        AnyCurve::Nurbs(c) => Nurbs::new(points, c.weights().unwrap().to_vec(), c.knots().clone())
            .unwrap()
            .into(),
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(6))]

    /// The wide families ride in two lanes of degree slots (docs/model.md, "Lanes"): the
    /// degrees of each lane's curve, joined, equal the channels blended as coordinates (an
    /// independent path through the engine) and keep the rule at 10,000 parameters.
    #[test]
    fn wide_families_blend_through_their_lanes(
        layout in layout(),
        seed in prop::collection::vec(-1.6f64..1.6, 37),
    ) {
        for family in Family::EXAMPLES.into_iter().filter(|f| f.lane_count() == 2) {
            let count = if layout.kind == 0 { layout.degree + 1 } else { layout.count };
            let values = boundary_values(family, count, &seed);
            let coordinates = curves(&layout, &values);
            let lanes = lane_curves(&layout, family, &values);
            let domain = coordinates[0].domain();
            for k in 0..10_000u32 {
                let t = (domain.start + (domain.end - domain.start) * f64::from(k) / 9_999.0)
                    .min(domain.end);
                let at: Vec<Degrees> = lanes.iter().map(|c| c.evaluate(t).unwrap().degrees).collect();
                let joined = family.join(&at);
                let mut blend = Vec::with_capacity(6);
                for curve in &coordinates {
                    blend.extend_from_slice(&curve.evaluate(t).unwrap().position);
                }
                for (c, (a, b)) in joined.iter().zip(&blend).enumerate() {
                    prop_assert!((a - b).abs() <= 1e-12, "{family} channel {c} at t = {t}: {a} vs {b}");
                }
                prop_assert!(
                    family.check_within(&joined, RULE_TOLERANCE).is_ok(),
                    "{family} at t = {t}: {joined:?}"
                );
            }
        }
    }
}
