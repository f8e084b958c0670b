//! Type reduction of interval-valued memberships (docs/model.md, "Type reduction"): the
//! centroid interval of an interval type-2 fuzzy set sampled at points.
//!
//! An interval type-2 fuzzy set sampled at points `x_1, ..., x_N` has at each `x_k` a
//! membership interval `[L_k, U_k]` (`0 <= L_k <= U_k`: the lower and upper membership, the
//! footprint of uncertainty between them). Every choice of weights `w_k` in `[L_k, U_k]` is an
//! *embedded* type-1 set, with centroid `sum x_k w_k / sum w_k`. The centroid of the type-2
//! set is the interval `[c_l, c_r]` of those centroids:
//!
//! ```text
//! c_l = min over w in [L, U] (sum w > 0) of sum x_k w_k / sum w_k
//! c_r = max over the same of              sum x_k w_k / sum w_k
//! ```
//!
//! and its type-reduced (defuzzified) value is the midpoint `(c_l + c_r) / 2`.
//!
//! The centroid is linear-fractional in `w`, so each extreme is taken at a vertex of the box
//! (every `w_k` at `L_k` or `U_k`), and with the points sorted by `x` the optimal vertex
//! switches once: `c_l` takes the upper memberships left of a switch point and the lower ones
//! right of it (weight pulls the centroid left), `c_r` the reverse. The switch point is what
//! the Karnik-Mendel iterations converge to; [`centroid_interval`] finds it exactly by scanning
//! every switch point `s = 0..=N` with prefix sums of `x_k U_k`, `x_k L_k`, `U_k` and `L_k`:
//! `O(N log N)` for the sort, `O(N)` for the scan.

use thiserror::Error;

/// The centroid interval `[c_l, c_r]` of an interval type-2 fuzzy set (module
/// documentation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CentroidInterval {
    /// `c_l`: the smallest centroid of an embedded type-1 set.
    pub lower: f64,
    /// `c_r`: the largest centroid of an embedded type-1 set.
    pub upper: f64,
}

impl CentroidInterval {
    /// The type-reduced value `(c_l + c_r) / 2`.
    pub fn midpoint(&self) -> f64 {
        0.5 * (self.lower + self.upper)
    }
}

/// Why a centroid interval cannot be formed.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum TypeReductionError {
    /// The three slices differ in length.
    #[error(
        "the points, lower memberships and upper memberships differ in number ({points}, \
         {lower} and {upper}); each point needs one lower and one upper membership"
    )]
    LengthMismatch {
        /// The number of points.
        points: usize,
        /// The number of lower memberships.
        lower: usize,
        /// The number of upper memberships.
        upper: usize,
    },
    /// A point or membership is NaN or infinite.
    #[error("{what} {index} is {value}, not a finite number")]
    NotFinite {
        /// `point`, `lower membership` or `upper membership`.
        what: &'static str,
        /// Its index.
        index: usize,
        /// The value.
        value: f64,
    },
    /// A lower membership is negative.
    #[error("lower membership {index} is {value}; memberships are at least 0")]
    Negative {
        /// Its index.
        index: usize,
        /// The value.
        value: f64,
    },
    /// A lower membership exceeds its upper one.
    #[error(
        "at point {index} the lower membership {lower} exceeds the upper membership {upper} \
         (lower <= upper)"
    )]
    Order {
        /// The index of the point.
        index: usize,
        /// Its lower membership.
        lower: f64,
        /// Its upper membership.
        upper: f64,
    },
    /// Every upper membership is 0 (or there are no points): every embedded set is empty and
    /// has no centroid.
    #[error(
        "every upper membership is 0 (or there are no points): the set is empty and has no \
         centroid"
    )]
    NoMembership,
}

/// Checks the input of [`centroid_interval`].
fn validate(x: &[f64], lower: &[f64], upper: &[f64]) -> Result<(), TypeReductionError> {
    if x.len() != lower.len() || x.len() != upper.len() {
        return Err(TypeReductionError::LengthMismatch {
            points: x.len(),
            lower: lower.len(),
            upper: upper.len(),
        });
    }
    for (index, ((&xk, &l), &u)) in x.iter().zip(lower).zip(upper).enumerate() {
        for (what, value) in [
            ("point", xk),
            ("lower membership", l),
            ("upper membership", u),
        ] {
            if !value.is_finite() {
                return Err(TypeReductionError::NotFinite { what, index, value });
            }
        }
        if l < 0.0 {
            return Err(TypeReductionError::Negative { index, value: l });
        }
        if l > u {
            return Err(TypeReductionError::Order {
                index,
                lower: l,
                upper: u,
            });
        }
    }
    if upper.iter().all(|&u| u == 0.0) {
        return Err(TypeReductionError::NoMembership);
    }
    Ok(())
}

/// The centroid interval `[c_l, c_r]` of the interval type-2 fuzzy set with lower memberships
/// `lower[k]` and upper memberships `upper[k]` at the points `x[k]` (in any order; equal
/// points allowed), computed exactly by the switch-point scan of the module documentation.
///
/// ```
/// use neutrospline::centroid_interval;
/// // Constant memberships [0.25, 1] at symmetric points: a symmetric interval.
/// let c = centroid_interval(&[-1.0, 0.0, 1.0], &[0.25; 3], &[1.0; 3])?;
/// assert!((c.lower + c.upper).abs() < 1e-15 && c.lower < 0.0);
/// // The lower end puts U at -1 and L at 0 and 1: (-1 + 0.25) / 1.5.
/// assert!((c.lower - (-0.5)).abs() < 1e-15);
/// assert!(c.midpoint().abs() < 1e-15);
/// # Ok::<(), neutrospline::TypeReductionError>(())
/// ```
///
/// # Errors
/// [`TypeReductionError`]: slices of different lengths, a value that is not finite, a
/// negative lower membership, a lower membership above its upper one, or no membership at
/// all (every upper membership 0: no embedded set has a centroid).
pub fn centroid_interval(
    x: &[f64],
    lower: &[f64],
    upper: &[f64],
) -> Result<CentroidInterval, TypeReductionError> {
    validate(x, lower, upper)?;
    let mut order: Vec<usize> = (0..x.len()).collect();
    order.sort_by(|&a, &b| x[a].total_cmp(&x[b]));
    // Measured from the middle of the points: the sums then cancel less.
    let (first, last) = (x[order[0]], x[order[order.len() - 1]]);
    let center = 0.5 * first + 0.5 * last;
    // Prefix sums, in x order, of the moments and masses of each membership.
    let n = order.len();
    let mut upper_moment = vec![0.0; n + 1];
    let mut upper_mass = vec![0.0; n + 1];
    let mut lower_moment = vec![0.0; n + 1];
    let mut lower_mass = vec![0.0; n + 1];
    for (k, &i) in order.iter().enumerate() {
        let offset = x[i] - center;
        upper_moment[k + 1] = upper_moment[k] + offset * upper[i];
        upper_mass[k + 1] = upper_mass[k] + upper[i];
        lower_moment[k + 1] = lower_moment[k] + offset * lower[i];
        lower_mass[k + 1] = lower_mass[k] + lower[i];
    }
    // The centroid of the vertex taking `left` memberships at the first `s` points and
    // `right` ones at the rest, if its total weight is positive.
    let centroid = |s: usize, left: (&[f64], &[f64]), right: (&[f64], &[f64])| {
        let mass = left.1[s] + (right.1[n] - right.1[s]);
        (mass > 0.0).then(|| (left.0[s] + (right.0[n] - right.0[s])) / mass)
    };
    let upper_sums = (upper_moment.as_slice(), upper_mass.as_slice());
    let lower_sums = (lower_moment.as_slice(), lower_mass.as_slice());
    let mut smallest = f64::INFINITY;
    let mut largest = f64::NEG_INFINITY;
    for s in 0..=n {
        if let Some(c) = centroid(s, upper_sums, lower_sums) {
            smallest = smallest.min(c);
        }
        if let Some(c) = centroid(s, lower_sums, upper_sums) {
            largest = largest.max(c);
        }
    }
    // s = n (all upper memberships) has positive weight, so both were found; a centroid is a
    // convex combination of the points: clamp rounding into [first, last].
    Ok(CentroidInterval {
        lower: (smallest + center).clamp(first, last),
        upper: (largest + center).clamp(first, last),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// The extremes over every vertex of the box (2^N choices), directly.
    fn brute_force(x: &[f64], lower: &[f64], upper: &[f64]) -> Option<(f64, f64)> {
        let n = x.len();
        let mut found: Option<(f64, f64)> = None;
        for mask in 0u32..(1 << n) {
            let (mut moment, mut mass) = (0.0, 0.0);
            for k in 0..n {
                let w = if mask >> k & 1 == 1 {
                    upper[k]
                } else {
                    lower[k]
                };
                moment += x[k] * w;
                mass += w;
            }
            if mass > 0.0 {
                let c = moment / mass;
                found = Some(match found {
                    None => (c, c),
                    Some((lo, hi)) => (lo.min(c), hi.max(c)),
                });
            }
        }
        found
    }

    fn set() -> impl Strategy<Value = (Vec<f64>, Vec<f64>, Vec<f64>)> {
        (1usize..=12).prop_flat_map(|n| {
            (
                // Few distinct values: equal points (ties) happen.
                prop::collection::vec(
                    prop_oneof![(-4i32..=4).prop_map(f64::from), -10.0..10.0f64],
                    n,
                ),
                prop::collection::vec(
                    prop_oneof![Just(0.0), Just(1.0), 0.0..1.0f64, 0.0..1.0f64],
                    n,
                ),
                prop::collection::vec(
                    prop_oneof![Just(0.0), Just(1.0), 0.0..1.0f64, 0.0..1.0f64],
                    n,
                ),
            )
                .prop_map(|(x, a, b)| {
                    let lower = a.iter().zip(&b).map(|(a, b)| a.min(*b)).collect();
                    let upper = a.iter().zip(&b).map(|(a, b)| a.max(*b)).collect();
                    (x, lower, upper)
                })
        })
    }

    proptest! {
        #[test]
        fn switch_scan_equals_brute_force((x, lower, upper) in set()) {
            match brute_force(&x, &lower, &upper) {
                None => prop_assert_eq!(
                    centroid_interval(&x, &lower, &upper),
                    Err(TypeReductionError::NoMembership)
                ),
                Some((lo, hi)) => {
                    let c = centroid_interval(&x, &lower, &upper).unwrap();
                    prop_assert!((c.lower - lo).abs() <= 1e-12 * 10.0, "{c:?} vs {lo}");
                    prop_assert!((c.upper - hi).abs() <= 1e-12 * 10.0, "{c:?} vs {hi}");
                    prop_assert!(c.lower <= c.upper);
                }
            }
        }
    }

    #[test]
    fn equal_memberships_give_the_type1_centroid() {
        let x = [3.0, -1.0, 0.5, 2.0];
        let w = [0.2, 0.9, 0.4, 0.0];
        let c = centroid_interval(&x, &w, &w).unwrap();
        let type1 = (3.0 * 0.2 - 0.9 + 0.5 * 0.4) / (0.2 + 0.9 + 0.4);
        assert!((c.lower - type1).abs() < 1e-15 && (c.upper - type1).abs() < 1e-15);
    }

    #[test]
    fn constant_memberships_on_symmetric_points_are_symmetric() {
        // x = -2..2, L = 0.5, U = 1: c_l puts U on -2, -1 and L on 0, 1, 2 (0 lies right of
        // the centroid, so weight there pulls it right): (-3 + 0.5 * 3) / (2 + 1.5) = -3/7.
        let x = [2.0, 1.0, 0.0, -1.0, -2.0];
        let c = centroid_interval(&x, &[0.5; 5], &[1.0; 5]).unwrap();
        let want = -3.0 / 7.0;
        assert!((c.lower - want).abs() < 1e-15, "{c:?}");
        assert!((c.upper + want).abs() < 1e-15, "{c:?}");
        assert_eq!(c.midpoint(), 0.0);
    }

    #[test]
    fn zero_lower_memberships_reach_the_extreme_points() {
        // L = 0: one point alone is an embedded set, so [c_l, c_r] spans the support.
        let c = centroid_interval(&[0.0, 1.0, 2.0, 3.0], &[0.0; 4], &[0.0, 0.5, 0.5, 0.0]).unwrap();
        assert_eq!((c.lower, c.upper), (1.0, 2.0));
    }

    #[test]
    fn refusals_name_the_value() {
        assert_eq!(
            centroid_interval(&[0.0, 1.0], &[0.0, 0.0], &[0.0, 0.0]),
            Err(TypeReductionError::NoMembership)
        );
        assert_eq!(
            centroid_interval(&[], &[], &[]),
            Err(TypeReductionError::NoMembership)
        );
        assert_eq!(
            centroid_interval(&[0.0, 1.0], &[0.0, 0.7], &[0.5, 0.6])
                .unwrap_err()
                .to_string(),
            "at point 1 the lower membership 0.7 exceeds the upper membership 0.6 (lower <= upper)"
        );
        assert_eq!(
            centroid_interval(&[0.0], &[0.0, 0.1], &[0.5])
                .unwrap_err()
                .to_string(),
            "the points, lower memberships and upper memberships differ in number (1, 2 and 1); \
             each point needs one lower and one upper membership"
        );
        assert_eq!(
            centroid_interval(&[f64::NAN], &[0.0], &[0.5])
                .unwrap_err()
                .to_string(),
            "point 0 is NaN, not a finite number"
        );
        assert_eq!(
            centroid_interval(&[0.0], &[-0.1], &[0.5])
                .unwrap_err()
                .to_string(),
            "lower membership 0 is -0.1; memberships are at least 0"
        );
    }
}
