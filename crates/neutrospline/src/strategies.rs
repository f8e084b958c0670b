//! [`mod@proptest`] strategies for degrees, control points and curves (feature `proptest`).
//!
//! Reusable by any crate that tests code built on neutrospline:
//!
//! ```
//! use neutrospline::{strategies, Evaluate};
//! use proptest::prelude::*;
//!
//! proptest!(|(curve in strategies::bezier::<2>(0..=8), t in strategies::parameter())| {
//!     let point = curve.evaluate(t).unwrap();
//!     prop_assert!((0.0..=1.0).contains(&point.degrees.truth()));
//! });
//! ```

use core::ops::RangeInclusive;

use proptest::prelude::*;

use crate::bezier::Bezier;
use crate::curve::ControlPolygon;
use crate::degrees::Degrees;
use crate::knots::KnotVector;
use crate::point::ControlPoint;
use crate::spline_curve::{BSpline, Nurbs};
use crate::surface::{Surface, SurfaceKind};

/// One degree in \[0, 1\], with the end values 0 and 1 and a few classic decimals weighted in.
pub fn degree() -> impl Strategy<Value = f64> {
    prop_oneof![
        6 => 0.0..=1.0f64,
        1 => Just(0.0),
        1 => Just(1.0),
        1 => prop::sample::select(vec![0.1, 0.2, 0.3, 0.4, 0.6, 0.7, 0.8, 0.9]),
    ]
}

/// Valid neutrosophic degrees.
pub fn degrees() -> impl Strategy<Value = Degrees> {
    (degree(), degree(), degree()).prop_map(|(t, i, f)| Degrees::new_unchecked(t, i, f))
}

/// A coordinate of moderate size, in \[-1000, 1000\].
pub fn coordinate() -> impl Strategy<Value = f64> {
    -1000.0..=1000.0f64
}

/// A control point with coordinates from [`coordinate`] and degrees from [`degrees`].
pub fn control_point<const D: usize>() -> impl Strategy<Value = ControlPoint<D>> {
    (prop::array::uniform::<_, D>(coordinate()), degrees())
        .prop_map(|(position, degrees)| ControlPoint::new(position, degrees))
}

/// A Bézier curve whose polynomial degree lies in `degree` (e.g. `0..=20`).
pub fn bezier<const D: usize>(degree: RangeInclusive<usize>) -> impl Strategy<Value = Bezier<D>> {
    let (lo, hi) = (*degree.start(), *degree.end());
    prop::collection::vec(control_point::<D>(), lo + 1..=hi + 1).prop_map(
        |points| match Bezier::new(points) {
            Ok(curve) => curve,
            Err(e) => unreachable!("generated control points are valid: {e}"),
        },
    )
}

/// A parameter in \[0, 1\], with the ends and values very close to them weighted in.
pub fn parameter() -> impl Strategy<Value = f64> {
    prop_oneof![
        8 => 0.0..=1.0f64,
        1 => Just(0.0),
        1 => Just(1.0),
        1 => prop::sample::select(vec![1e-300, 1e-12, 0.5, 1.0 - 1e-12, 1.0 - f64::EPSILON]),
    ]
}

// ------------------------------------------------------------------ splines and surfaces

/// A knot vector for `degree` and `count` control points (`count >= degree + 1`).
///
/// A mix of clamped uniform, clamped random and unclamped random knots, starting anywhere in
/// \[-10, 10\] with gaps on scales from 0.01 to 100. Interior knots repeat: mostly up to
/// multiplicity `degree` (the curve stays continuous), sometimes up to `degree + 1` (a
/// discontinuity). Every vector passes [`KnotVector::new`].
///
/// # Panics
/// If `count < degree + 1`.
pub fn knot_vector(degree: usize, count: usize) -> impl Strategy<Value = KnotVector> {
    assert!(
        count > degree,
        "knot_vector: {count} control points are too few for degree {degree}"
    );
    let p = degree;
    let m = count + p; // index of the last knot
    let gap = prop_oneof![3 => 0.1..=1.0f64, 1 => Just(0.0)];
    let interior_limit = prop_oneof![4 => Just(p.max(1)), 1 => Just(p + 1)];
    prop_oneof![
        1 => Just(KnotStyle::Uniform),
        2 => Just(KnotStyle::Clamped),
        2 => Just(KnotStyle::Unclamped),
    ]
    .prop_flat_map(move |style| {
        (
            Just(style),
            prop::collection::vec(gap.clone(), m),
            -10.0..=10.0f64,
            prop::sample::select(vec![0.01, 1.0, 100.0]),
            (interior_limit.clone(), any::<prop::sample::Index>()),
        )
    })
    .prop_map(move |(style, gaps, start, scale, (limit, jump))| {
        let knots = match style {
            KnotStyle::Uniform => {
                let segments = (count - p) as f64;
                core::iter::repeat_n(start, p + 1)
                    .chain((1..count - p).map(|j| start + scale * j as f64 / segments))
                    .chain(core::iter::repeat_n(start + scale, p + 1))
                    .collect()
            }
            KnotStyle::Clamped | KnotStyle::Unclamped => {
                let clamped = style == KnotStyle::Clamped;
                let jump = (limit > p).then_some(jump);
                knots_from_gaps(p, m, &gaps, start, scale, (limit, jump), clamped)
            }
        };
        match KnotVector::new(knots, p, count) {
            Ok(k) => k,
            Err(e) => unreachable!("generated knots are valid: {e}"),
        }
    })
    .boxed()
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum KnotStyle {
    Uniform,
    Clamped,
    Unclamped,
}

/// Knots `start + scale * cumsum(gaps)`, with the gaps fixed up so that: clamped vectors
/// have `p + 1` equal knots at each end; with `jump`, one interior knot (where room allows)
/// has multiplicity `p + 1`; no interior run exceeds `limit` knots and no run `p + 1`; the
/// domain `[u_p, u_{m-p}]` is not empty.
fn knots_from_gaps(
    p: usize,
    m: usize,
    gaps: &[f64],
    start: f64,
    scale: f64,
    (limit, jump): (usize, Option<prop::sample::Index>),
    clamped: bool,
) -> Vec<f64> {
    let mut gaps = gaps.to_vec();
    // Knots j ..= j + p equal and strictly inside the domain: p + 1 <= j <= m - 2p - 1.
    if let (Some(jump), true) = (jump, m >= 3 * p + 2) {
        let j = p + 1 + jump.index(m - 3 * p - 1);
        gaps[j - 1] = gaps[j - 1].max(0.5);
        gaps[j + p] = gaps[j + p].max(0.5);
        for g in &mut gaps[j..j + p] {
            *g = 0.0;
        }
    }
    if clamped {
        for g in 0..p {
            gaps[g] = 0.0;
            gaps[m - 1 - g] = 0.0;
        }
        // The interior must not join the clamped ends.
        gaps[p] = gaps[p].max(0.5);
        gaps[m - 1 - p] = gaps[m - 1 - p].max(0.5);
    }
    // Run lengths: knot j starts a new run when gap j - 1 is positive.
    let mut run = 1;
    for g in 0..m {
        if gaps[g] == 0.0 {
            // Knot g + 1 would join the run ending at knot g.
            let end_run = g < p || g + 1 > m - p;
            let max = if end_run { p + 1 } else { limit.min(p + 1) };
            if run + 1 > max {
                gaps[g] = 0.5;
                run = 1;
            } else {
                run += 1;
            }
        } else {
            run = 1;
        }
    }
    if gaps[p..m - p].iter().all(|&g| g == 0.0) {
        gaps[p] = 0.5;
    }
    let mut knots = Vec::with_capacity(m + 1);
    let mut acc = 0.0;
    knots.push(start);
    for g in gaps {
        acc += g;
        knots.push(start + scale * acc);
    }
    knots
}

/// A NURBS weight in \[0.1, 10\], log-uniform, with 1 and the ends weighted in.
pub fn weight() -> impl Strategy<Value = f64> {
    prop_oneof![
        6 => (-1.0..=1.0f64).prop_map(|e| 10f64.powf(e).clamp(0.1, 10.0)),
        1 => Just(1.0),
        1 => Just(0.1),
        1 => Just(10.0),
    ]
}

/// A B-spline curve whose polynomial degree lies in `degree`, with `degree + 1 ..= degree + 8`
/// control points over a [`knot_vector`] (and now and then up to `degree + 31`, for many
/// spans).
pub fn bspline<const D: usize>(degree: RangeInclusive<usize>) -> impl Strategy<Value = BSpline<D>> {
    let extra = prop_oneof![6 => 0usize..=7, 1 => 8usize..=30];
    (degree, extra)
        .prop_flat_map(|(p, extra)| {
            let count = p + 1 + extra;
            (
                prop::collection::vec(control_point::<D>(), count),
                knot_vector(p, count),
            )
        })
        .prop_map(|(points, knots)| match BSpline::new(points, knots) {
            Ok(curve) => curve,
            Err(e) => unreachable!("generated B-spline data is valid: {e}"),
        })
}

/// A NURBS curve: a [`bspline`] with a [`weight`] per control point.
pub fn nurbs<const D: usize>(degree: RangeInclusive<usize>) -> impl Strategy<Value = Nurbs<D>> {
    bspline::<D>(degree)
        .prop_flat_map(|curve| {
            let count = curve.len();
            (Just(curve), prop::collection::vec(weight(), count))
        })
        .prop_map(|(curve, weights)| {
            match Nurbs::new(curve.control_points(), weights, curve.knots().clone()) {
                Ok(c) => c,
                Err(e) => unreachable!("generated NURBS data is valid: {e}"),
            }
        })
}

/// A parameter in the domain of `knots`: the domain ends, the knots inside it, values just
/// beside a knot, and uniform values.
pub fn domain_parameter(knots: &KnotVector) -> impl Strategy<Value = f64> {
    let core::ops::Range { start: a, end: b } = knots.domain();
    let inside: Vec<f64> = knots
        .knots()
        .iter()
        .copied()
        .filter(|&k| a <= k && k <= b)
        .collect();
    let beside = inside.clone();
    prop_oneof![
        6 => a..=b,
        1 => Just(a),
        1 => Just(b),
        2 => prop::sample::select(inside),
        1 => (prop::sample::select(beside), prop::sample::select(vec![-1e-9, 1e-9, -f64::EPSILON, f64::EPSILON]))
            .prop_map(move |(k, d)| (k + d * k.abs().max(1.0)).clamp(a, b)),
    ]
}

/// A tensor-product surface of `kind` with degrees in `degree` in both directions, 1 to 4
/// more control points than the minimum per direction (Bézier: exactly `degree + 1`), knots
/// from [`knot_vector`] and, for NURBS, weights from [`weight`].
pub fn surface(kind: SurfaceKind, degree: RangeInclusive<usize>) -> impl Strategy<Value = Surface> {
    let extra = if kind == SurfaceKind::Bezier {
        0..=0usize
    } else {
        0..=3usize
    };
    (degree.clone(), degree, extra.clone(), extra)
        .prop_flat_map(move |(pu, pv, eu, ev)| {
            let (rows, cols) = (pu + 1 + eu, pv + 1 + ev);
            (
                prop::collection::vec(control_point::<3>(), rows * cols),
                prop::collection::vec(weight(), rows * cols),
                knot_vector(pu, rows),
                knot_vector(pv, cols),
                Just((rows, cols)),
            )
        })
        .prop_map(move |(points, weights, ku, kv, (rows, cols))| {
            let built = match kind {
                SurfaceKind::Bezier => Surface::bezier(rows, cols, points),
                SurfaceKind::BSpline => Surface::bspline(rows, cols, points, ku, kv),
                SurfaceKind::Nurbs => Surface::nurbs(rows, cols, points, weights, ku, kv),
            };
            match built {
                Ok(s) => s,
                Err(e) => unreachable!("generated surface data is valid: {e}"),
            }
        })
        .boxed()
}
