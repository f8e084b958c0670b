//! [`proptest`] strategies for degrees, control points and curves (feature `proptest`).
//!
//! Reusable by any crate that tests code built on neutrospline:
//!
//! ```
//! use neutrospline::strategies;
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
use crate::degrees::Degrees;
use crate::point::ControlPoint;

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
