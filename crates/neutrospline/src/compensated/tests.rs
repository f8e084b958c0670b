use proptest::prelude::*;

use super::*;
use crate::bernstein::Packed;
use crate::knots::KnotVector;
use crate::spline::{bezier_knots, Spline};

const U: f64 = f64::EPSILON / 2.0;

#[test]
fn two_sum_and_two_product_are_exact() {
    // 1 + 2^-60 is not a float: the sum rounds to 1 and the error is 2^-60.
    let tiny = 2f64.powi(-60);
    assert_eq!(two_sum(1.0, tiny), (1.0, tiny));
    assert_eq!(two_sum(tiny, 1.0), (1.0, tiny));
    // (1 + 2^-30)^2 = 1 + 2^-29 + 2^-60.
    let a = 1.0 + 2f64.powi(-30);
    assert_eq!(two_product(a, a), (1.0 + 2f64.powi(-29), tiny));
    // 1 / 3 = q + e with the residual 1 - 3 q exact.
    let q = 1.0 / 3.0;
    let e = quotient_error(q, 1.0, 0.0, 3.0, 0.0);
    assert_eq!(3.0f64.mul_add(q, 3.0 * e), 1.0);
    assert!(e != 0.0 && e.abs() < U * q);
}

/// `(t - 3/4)^n` has the Bernstein coefficients `c_i = (-3/4)^(n-i) (1/4)^i` (exact), of
/// alternating signs: near `t = 3/4` the value is tiny beside `sum |c_i| B_i(t) =
/// (3/4 - t/2)^n`, the classical ill-conditioned case. Compensated, the error is at most about
/// `u |p| + 4 n^2 u^2 sum |c_i| B_i`; plain, it is of order `n u sum |c_i| B_i`.
#[test]
fn ill_conditioned_polynomial_near_its_root() {
    for n in [5usize, 9, 13] {
        let data: Vec<f64> = (0..=n)
            .map(|i| (-0.75f64).powi((n - i) as i32) * 0.25f64.powi(i as i32))
            .collect();
        let packed = Packed::new(1, data.clone());
        let t: f64 = 0.75 + 1.0 / 3072.0;
        let exact = (t - 0.75).powi(n as i32); // t - 3/4 is exact; powi within n u
        let absolute = (0.75 - 0.5 * t).powi(n as i32);
        let mut out = [0.0];
        let step = Step::casteljau(t);
        assert!(evaluate(1, &data, None, |_, _| step, &mut out));
        let bound = 5.0 * (n * n) as f64 * U * U * absolute + (n + 3) as f64 * U * exact.abs();
        assert!(
            (out[0] - exact).abs() <= bound,
            "n = {n}: {} vs {exact}",
            out[0]
        );
        let mut plain = [0.0];
        packed.evaluate(t, &mut plain);
        assert!(
            (plain[0] - exact).abs() > 10.0 * bound,
            "n = {n}: the plain form is less accurate"
        );
    }
}

#[test]
fn de_boor_step_weights_sum_to_one_with_errors() {
    // alpha + beta = 1 exactly, errors included, to second order.
    for &(t, lo, hi) in &[
        (0.3, 0.1, 0.7),
        (0.123456789, 0.0, 1.0 / 3.0),
        (2.0 / 3.0, 0.2, 0.9),
    ] {
        let s = Step::de_boor(t, 0.0, lo, hi);
        let (sum, rounding) = two_sum(s.alpha.value, s.beta.value);
        let total = (sum - 1.0) + rounding + s.alpha.error + s.beta.error;
        assert!(total.abs() < 4.0 * U * U, "{t} {lo} {hi}: {total}");
    }
    // At the ends of the span the weights are exactly 0 and 1, without error.
    let s = Step::de_boor(0.1, 0.0, 0.1, 0.7);
    assert_eq!(
        (s.alpha.value, s.alpha.error, s.beta.value, s.beta.error),
        (0.0, 0.0, 1.0, 0.0)
    );
    let s = Step::de_boor(0.7, 0.0, 0.1, 0.7);
    assert_eq!(
        (s.alpha.value, s.alpha.error, s.beta.value, s.beta.error),
        (1.0, 0.0, 0.0, 0.0)
    );
}

/// A packed row set of `count` rows: 2-D positions in [-10, 10] and degrees in [0, 1].
fn rows(count: usize) -> impl Strategy<Value = Vec<f64>> {
    prop::collection::vec(
        (
            -10.0..10.0f64,
            -10.0..10.0f64,
            0.0..=1.0f64,
            0.0..=1.0f64,
            0.0..=1.0f64,
        )
            .prop_map(|(x, y, a, b, c)| vec![x, y, a, b, c]),
        count,
    )
    .prop_map(|r| r.concat())
}

/// A clamped spline of degree `p` with `p + 1 + extra` rows, increasing interior knots, and
/// weights in [0.5, 2] when `rational`.
fn spline(rational: bool) -> impl Strategy<Value = Spline> {
    (1usize..=24, 0usize..=5)
        .prop_flat_map(move |(p, extra)| {
            let count = p + 1 + extra;
            (
                Just(p),
                rows(count),
                prop::collection::vec(0.01..0.99f64, extra),
                prop::collection::vec(0.5..2.0f64, count),
            )
        })
        .prop_map(move |(p, data, mut interior, weights)| {
            interior.sort_by(f64::total_cmp);
            let mut knots = vec![0.0; p + 1];
            knots.extend(interior);
            knots.extend(vec![1.0; p + 1]);
            Spline {
                knots: KnotVector::from_parts_unchecked(p, knots),
                stride: 5,
                data,
                weights: rational.then_some(weights),
            }
        })
}

/// Largest absolute value of each of the 5 channels.
fn scales(data: &[f64]) -> [f64; 5] {
    let mut s = [0.0f64; 5];
    for row in data.chunks_exact(5) {
        for (m, v) in s.iter_mut().zip(row) {
            *m = m.max(v.abs());
        }
    }
    s
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// Compensated de Casteljau agrees with the plain algorithm within the plain one's error
    /// bound (`2 n u max |c|`, plus one rounding), the ends exactly.
    #[test]
    fn casteljau_compensated_agrees_with_plain(
        (n, data) in (0usize..=40).prop_flat_map(|n| (Just(n), rows(n + 1))),
        t in 0.0..=1.0f64,
    ) {
        let packed = Packed::new(5, data.clone());
        let (mut ours, mut plain) = ([0.0; 5], [0.0; 5]);
        let step = Step::casteljau(t);
        prop_assert!(evaluate(5, &data, None, |_, _| step, &mut ours));
        packed.evaluate(t, &mut plain);
        for (c, m) in scales(&data).iter().enumerate() {
            let bound = (2 * n + 2) as f64 * U * m;
            prop_assert!((ours[c] - plain[c]).abs() <= bound, "{c}: {} {}", ours[c], plain[c]);
        }
        for (t, row) in [(0.0, 0), (1.0, n)] {
            let step = Step::casteljau(t);
            prop_assert!(evaluate(5, &data, None, |_, _| step, &mut ours));
            prop_assert_eq!(&ours[..], packed.row(row));
        }
    }

    /// Compensated de Boor (B-spline and NURBS) agrees with plain de Boor within the plain
    /// error bound; at the domain ends it gives the end control rows exactly, and the
    /// degrees stay in [0, 1].
    #[test]
    fn de_boor_compensated_agrees_with_plain(
        curve in prop_oneof![spline(false), spline(true)],
        t in 0.0..=1.0f64,
    ) {
        let p = curve.degree();
        let (mut ours, mut plain) = ([0.0; 5], [0.0; 5]);
        curve.evaluate(t, &mut ours);
        curve.evaluate_plain(t, &mut plain);
        // The plain algorithm's error: at each of its p levels, alpha = (t - u_i) / (u_{i+p} -
        // u_i) and 1 - alpha carry up to four roundings, each scaled by |a| + |b| <= 2 max |c|
        // in the lerp (1 - alpha) a + alpha b, so 4 (p + 1) u max |c| in all (a quadratic
        // with y = -8.53 and 6.97 at t = 0.985 errs by 6.6 u max |c|; the regression test
        // below). The plain rational form adds errors of the order of the weight ratio (4
        // here).
        let factor = if curve.weights.is_some() { 16.0 } else { 4.0 };
        for (c, m) in scales(&curve.data).iter().enumerate() {
            let bound = factor * (p + 1) as f64 * U * m;
            prop_assert!((ours[c] - plain[c]).abs() <= bound, "{c}: {} {}", ours[c], plain[c]);
        }
        prop_assert!(ours[2..].iter().all(|d| (0.0..=1.0).contains(d)));
        curve.evaluate(0.0, &mut ours);
        prop_assert_eq!(&ours[..], curve.row(0));
        curve.evaluate(1.0, &mut ours);
        prop_assert_eq!(&ours[..], curve.row(curve.count() - 1));
    }

    /// A Bézier polynomial evaluated by compensated de Boor on Bézier knots and by
    /// compensated de Casteljau: the same operations, the same bits.
    #[test]
    fn de_boor_on_bezier_knots_is_de_casteljau(
        (n, data) in (1usize..=30).prop_flat_map(|n| (Just(n), rows(n + 1))),
        t in 0.0..=1.0f64,
    ) {
        let spline = Spline { knots: bezier_knots(n), stride: 5, data: data.clone(), weights: None };
        let (mut a, mut b) = ([0.0; 5], [0.0; 5]);
        spline.evaluate(t, &mut a);
        let step = Step::casteljau(t);
        prop_assert!(evaluate(5, &data, None, |_, _| step, &mut b));
        prop_assert_eq!(a, b);
    }
}

/// Control values near the largest float may overflow in the products of the compensated
/// form (`fl((1 - t) M) + fl(t M) > M`); the plain convex form then gives the value.
#[test]
fn near_overflow_values_stay_finite() {
    let big = f64::MAX;
    let data = vec![big, -big, 0.0, 0.0, 0.0, big, big, 1.0, 1.0, 1.0];
    for weights in [None, Some(vec![1.0, 3.0])] {
        let spline = Spline {
            knots: bezier_knots(1),
            stride: 5,
            data: data.clone(),
            weights,
        };
        for k in 0..=100 {
            let mut out = [0.0; 5];
            spline.evaluate(k as f64 / 100.0, &mut out);
            assert_eq!(out[0], big, "{k}");
            assert!(out.iter().all(|v| v.is_finite()), "{k}: {out:?}");
        }
    }
}

/// The case proptest found in CI: the plain de Boor value of this quadratic errs by 6.6 u
/// max |c| (more than the 2 (p + 1) u max |c| the property first allowed), while the
/// compensated value is the exact value correctly rounded (de Boor's recurrence in exact
/// rational arithmetic, Python's `fractions`, gives 6.3701511376916695).
#[test]
fn plain_de_boor_error_within_its_bound_on_a_cancelling_quadratic() {
    let mut data = vec![0.0; 20];
    data[11] = -8.526395240601786;
    data[16] = 6.9672011146351815;
    let curve = Spline {
        knots: KnotVector::from_parts_unchecked(
            2,
            vec![0.0, 0.0, 0.0, 0.2545950538070519, 1.0, 1.0, 1.0],
        ),
        stride: 5,
        data,
        weights: None,
    };
    let t = 0.9854371988329119;
    let (mut ours, mut plain) = ([0.0; 5], [0.0; 5]);
    curve.evaluate(t, &mut ours);
    curve.evaluate_plain(t, &mut plain);
    let m = 8.526395240601786;
    assert_eq!(ours[1], 6.3701511376916695);
    assert!((ours[1] - plain[1]).abs() <= 12.0 * U * m);
    assert!((ours[1] - plain[1]).abs() > 6.0 * U * m);
}
