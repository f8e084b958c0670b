//! Fuzzy positions (SPEC section 9): the alpha-cut curves are the curves of the cut control
//! points, equal the crisp curve at alpha = 1, and contain every "instance" curve whose control
//! points lie inside their cuts, for every kind, in 2-D and 3-D.

use neutrospline::strategies::{bezier, bspline, nurbs, parameter};
use neutrospline::{
    alpha_cut, centroid_curve, AnyCurve, ControlPoint, ControlPolygon, Evaluate, Spread,
};
use proptest::prelude::*;

/// A spread in [0, 50] per side and axis, zero now and then.
fn spread<const D: usize>() -> impl Strategy<Value = Spread<D>> {
    let one = prop_oneof![4 => 0.0..=50.0f64, 1 => Just(0.0)];
    (
        prop::array::uniform::<_, D>(one.clone()),
        prop::array::uniform::<_, D>(one),
    )
        .prop_map(|(left, right)| Spread::new(left, right))
}

/// A curve of any kind with one spread per control point, an alpha, and per control point and
/// axis a fraction in [0, 1] choosing an instance coordinate inside the cut.
fn case<const D: usize>() -> impl Strategy<Value = (AnyCurve<D>, Vec<Spread<D>>, f64, Vec<[f64; D]>)>
{
    let curve = prop_oneof![
        bezier::<D>(0..=6).prop_map(AnyCurve::from),
        bspline::<D>(1..=4).prop_map(AnyCurve::from),
        nurbs::<D>(1..=4).prop_map(AnyCurve::from),
    ];
    let alpha = prop_oneof![3 => 0.0..=1.0f64, 1 => Just(0.0), 1 => Just(0.5), 1 => Just(1.0)];
    (curve, alpha).prop_flat_map(|(curve, alpha)| {
        let n = curve.len();
        (
            Just(curve),
            prop::collection::vec(spread::<D>(), n),
            Just(alpha),
            prop::collection::vec(prop::array::uniform::<_, D>(0.0..=1.0f64), n),
        )
    })
}

/// A parameter in the curve's domain from one in [0, 1].
fn at<const D: usize>(curve: &AnyCurve<D>, s: f64) -> f64 {
    let d = curve.domain();
    (d.start + s * (d.end - d.start)).clamp(d.start, d.end)
}

fn check_band<const D: usize>(
    curve: &AnyCurve<D>,
    spreads: &[Spread<D>],
    alpha: f64,
    fractions: &[[f64; D]],
    samples: &[f64],
) -> Result<(), TestCaseError> {
    let (lower, upper) = alpha_cut(curve, spreads, alpha).unwrap();
    // The instance: each coordinate drawn inside its cut.
    let points: Vec<ControlPoint<D>> = curve
        .control_points()
        .iter()
        .zip(spreads.iter().zip(fractions))
        .map(|(p, (s, f))| {
            let (lo, hi) = s.cut(p.position, alpha);
            let mut q = lo;
            for k in 0..D {
                q[k] = (lo[k] + f[k] * (hi[k] - lo[k])).clamp(lo[k], hi[k]);
            }
            ControlPoint::new(q, p.degrees)
        })
        .collect();
    let instance = match curve {
        AnyCurve::Bezier(_) => neutrospline::Bezier::new(points).unwrap().into(),
        AnyCurve::BSpline(c) => neutrospline::BSpline::new(points, c.knots().clone())
            .unwrap()
            .into(),
        AnyCurve::Nurbs(c) => {
            neutrospline::Nurbs::new(points, c.weights().unwrap().to_vec(), c.knots().clone())
                .unwrap()
                .into()
        }
    };
    let instance: AnyCurve<D> = instance;
    for &s in samples {
        let t = at(curve, s);
        let lo = lower.evaluate(t).unwrap().position;
        let hi = upper.evaluate(t).unwrap().position;
        let p = instance.evaluate(t).unwrap().position;
        let c = curve.evaluate(t).unwrap().position;
        for k in 0..D {
            let tol = 1e-9 * (1.0 + lo[k].abs().max(hi[k].abs()));
            prop_assert!(lo[k] <= hi[k] + tol, "lower above upper at t = {t}");
            prop_assert!(
                lo[k] - tol <= p[k] && p[k] <= hi[k] + tol,
                "instance outside the band at t = {t}, axis {k}: {} not in [{}, {}]",
                p[k],
                lo[k],
                hi[k]
            );
            prop_assert!(lo[k] - tol <= c[k] && c[k] <= hi[k] + tol, "crisp outside");
        }
    }
    Ok(())
}

fn check_cut_is_curve_of_cut_points<const D: usize>(
    curve: &AnyCurve<D>,
    spreads: &[Spread<D>],
    alpha: f64,
) -> Result<(), TestCaseError> {
    let (lower, upper) = alpha_cut(curve, spreads, alpha).unwrap();
    prop_assert_eq!(lower.kind(), curve.kind());
    prop_assert_eq!(lower.knots(), curve.knots());
    prop_assert_eq!(upper.weights(), curve.weights());
    for (i, s) in spreads.iter().enumerate() {
        let (lo, hi) = s.cut(curve.control_point(i).position, alpha);
        prop_assert_eq!(lower.control_point(i).position, lo);
        prop_assert_eq!(upper.control_point(i).position, hi);
        prop_assert_eq!(
            lower.control_point(i).degrees,
            curve.control_point(i).degrees
        );
    }
    let (one_lo, one_hi) = alpha_cut(curve, spreads, 1.0).unwrap();
    prop_assert_eq!(&one_lo, curve);
    prop_assert_eq!(&one_hi, curve);
    let centroid = centroid_curve(curve, spreads).unwrap();
    for (i, s) in spreads.iter().enumerate() {
        prop_assert_eq!(
            centroid.control_point(i).position,
            s.centroid(curve.control_point(i).position)
        );
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn instances_stay_inside_the_band_2d(
        (curve, spreads, alpha, fractions) in case::<2>(),
        samples in prop::collection::vec(parameter(), 1..24),
    ) {
        check_band(&curve, &spreads, alpha, &fractions, &samples)?;
    }

    #[test]
    fn instances_stay_inside_the_band_3d(
        (curve, spreads, alpha, fractions) in case::<3>(),
        samples in prop::collection::vec(parameter(), 1..24),
    ) {
        check_band(&curve, &spreads, alpha, &fractions, &samples)?;
    }

    #[test]
    fn cut_curves_are_the_curves_of_the_cut_points_2d((curve, spreads, alpha, _f) in case::<2>()) {
        check_cut_is_curve_of_cut_points(&curve, &spreads, alpha)?;
    }

    #[test]
    fn cut_curves_are_the_curves_of_the_cut_points_3d((curve, spreads, alpha, _f) in case::<3>()) {
        check_cut_is_curve_of_cut_points(&curve, &spreads, alpha)?;
    }
}
