//! Fuzzy positions: control points whose coordinates are triangular fuzzy numbers, as in the
//! fuzzy Bézier and B-spline literature (Zakaria, Wahab et al.).
//!
//! A [`Spread`] gives, per axis, a left and a right spread (each >= 0): the coordinate `x` of
//! the control point is then the triangular fuzzy number `(x - left, x, x + right)`. Its
//! alpha-cut is the interval `[x - (1 - alpha) left, x + (1 - alpha) right]` and its centroid
//! is `x + (right - left) / 3`.
//!
//! The basis functions of every kind are non-negative and sum to 1 (the rational NURBS basis
//! `R_i = w_i N_i / sum_j w_j N_j` included, its weights being positive), so the set of values
//! `sum_i R_i(t) x_i` with each `x_i` in its cut `[lo_i, hi_i]` is exactly the interval
//! `[sum_i R_i(t) lo_i, sum_i R_i(t) hi_i]`: the alpha-cut of the curve is bounded by the
//! curves of the cut control points ([`alpha_cut`]), built with the same knots and weights. The
//! centroid (defuzzified) curve is the curve of the control points' centroids
//! ([`centroid_curve`]), by linearity.
//!
//! The curve types are unchanged: spreads are carried beside a curve, one per control point.
//!
//! ```
//! use neutrospline::{alpha_cut, AnyCurve, Bezier, ControlPoint, Degrees, Evaluate, Spread};
//!
//! let d = Degrees::new(1.0, 0.0, 0.0)?;
//! let line = AnyCurve::from(Bezier::new(vec![
//!     ControlPoint::new([0.0, 0.0], d),
//!     ControlPoint::new([4.0, 0.0], d),
//! ])?);
//! let spreads = [Spread::symmetric([0.0, 1.0]), Spread::symmetric([0.0, 3.0])];
//! let (lower, upper) = alpha_cut(&line, &spreads, 0.5)?;
//! assert_eq!(lower.evaluate(0.5)?.position, [2.0, -1.0]);
//! assert_eq!(upper.evaluate(0.5)?.position, [2.0, 1.0]);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use crate::any_curve::AnyCurve;
use crate::bezier::Bezier;
use crate::curve::{ControlPolygon, CurveError};
use crate::point::ControlPoint;
use crate::spline_curve::{BSpline, Nurbs};

/// The names of the axes, for messages.
const AXES: [&str; 3] = ["x", "y", "z"];

/// The spreads of one control point: per axis, how far its triangular fuzzy coordinate reaches
/// to the left (below) and to the right (above) of the crisp coordinate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spread<const D: usize> {
    /// Left spreads, per axis (>= 0).
    pub left: [f64; D],
    /// Right spreads, per axis (>= 0).
    pub right: [f64; D],
}

impl<const D: usize> Default for Spread<D> {
    fn default() -> Self {
        Spread::ZERO
    }
}

impl<const D: usize> Spread<D> {
    /// No spread: a crisp control point.
    pub const ZERO: Spread<D> = Spread {
        left: [0.0; D],
        right: [0.0; D],
    };

    /// Left and right spreads per axis (not checked; see [`Spread::check`]).
    pub const fn new(left: [f64; D], right: [f64; D]) -> Self {
        Spread { left, right }
    }

    /// The same spread on both sides of each axis.
    pub const fn symmetric(spread: [f64; D]) -> Self {
        Spread {
            left: spread,
            right: spread,
        }
    }

    /// Whether every spread is 0.
    pub fn is_zero(&self) -> bool {
        self.left.iter().chain(&self.right).all(|&s| s == 0.0)
    }

    /// The first `E` axes (missing axes have no spread): a planar spread as a spatial one and
    /// back.
    pub fn resize<const E: usize>(&self) -> Spread<E> {
        let mut out = Spread::<E>::ZERO;
        for k in 0..D.min(E) {
            out.left[k] = self.left[k];
            out.right[k] = self.right[k];
        }
        out
    }

    /// Checks that every spread is a finite number >= 0.
    ///
    /// # Errors
    /// [`FuzzyError::Spread`] for the first bad spread (`index` 0).
    pub fn check(&self) -> Result<(), FuzzyError> {
        for (side, values) in [(Side::Left, &self.left), (Side::Right, &self.right)] {
            for (axis, &value) in values.iter().enumerate() {
                if !(value.is_finite() && value >= 0.0) {
                    return Err(FuzzyError::Spread {
                        index: 0,
                        axis: AXES[axis.min(2)],
                        side,
                        value,
                    });
                }
            }
        }
        Ok(())
    }

    /// The alpha-cut `[x - (1 - alpha) left, x + (1 - alpha) right]` of each coordinate of
    /// `position`, as the lower and the upper position.
    pub fn cut(&self, position: [f64; D], alpha: f64) -> ([f64; D], [f64; D]) {
        let mut lo = position;
        let mut hi = position;
        let reach = 1.0 - alpha;
        for k in 0..D {
            lo[k] -= reach * self.left[k];
            hi[k] += reach * self.right[k];
        }
        (lo, hi)
    }

    /// The centroid `x + (right - left) / 3` of each coordinate of `position`.
    pub fn centroid(&self, position: [f64; D]) -> [f64; D] {
        let mut c = position;
        for k in 0..D {
            c[k] += (self.right[k] - self.left[k]) / 3.0;
        }
        c
    }
}

/// Which side of a triangular fuzzy number a spread is on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    /// Below the crisp value.
    Left,
    /// Above the crisp value.
    Right,
}

impl Side {
    /// `left` or `right`.
    pub const fn name(self) -> &'static str {
        match self {
            Side::Left => "left",
            Side::Right => "right",
        }
    }
}

/// Why an alpha-cut or a centroid curve cannot be built.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum FuzzyError {
    /// Not one spread per control point.
    #[error("{spreads} spreads for {points} control points (give one spread per control point)")]
    SpreadCount {
        /// Spreads given.
        spreads: usize,
        /// Control points of the curve.
        points: usize,
    },
    /// A spread is negative or not finite.
    #[error(
        "control point {index}: {side} spread of {axis} = {value} is not a finite number >= 0",
        side = side.name()
    )]
    Spread {
        /// The control point.
        index: usize,
        /// The axis: `x`, `y` or `z`.
        axis: &'static str,
        /// The side.
        side: Side,
        /// The value given.
        value: f64,
    },
    /// Alpha is outside \[0, 1\] (or NaN).
    #[error("alpha = {0} is outside [0, 1]")]
    Alpha(f64),
    /// A shifted control point could not make a curve (a position overflowed).
    #[error(transparent)]
    Curve(#[from] CurveError),
}

/// Checks the spreads against the curve: one per control point, each finite and >= 0.
fn check_spreads<const D: usize>(
    curve: &AnyCurve<D>,
    spreads: &[Spread<D>],
) -> Result<(), FuzzyError> {
    Spread::check_all(spreads, curve.len())
}

impl<const D: usize> Spread<D> {
    /// Checks the spreads of `points` control points: one per point, each finite and >= 0.
    ///
    /// # Errors
    /// [`FuzzyError::SpreadCount`]; [`FuzzyError::Spread`] for the first bad spread, with its
    /// control point's index.
    pub fn check_all(spreads: &[Spread<D>], points: usize) -> Result<(), FuzzyError> {
        if spreads.len() != points {
            return Err(FuzzyError::SpreadCount {
                spreads: spreads.len(),
                points,
            });
        }
        for (index, spread) in spreads.iter().enumerate() {
            spread.check().map_err(|e| match e {
                FuzzyError::Spread {
                    axis, side, value, ..
                } => FuzzyError::Spread {
                    index,
                    axis,
                    side,
                    value,
                },
                other => other,
            })?;
        }
        Ok(())
    }
}

/// The curve of the same kind, degree, knots and weights as `curve`, with control point `i`
/// moved to `position(i, old position)` (degrees kept).
fn moved<const D: usize>(
    curve: &AnyCurve<D>,
    position: impl Fn(usize, [f64; D]) -> [f64; D],
) -> Result<AnyCurve<D>, CurveError> {
    let points: Vec<ControlPoint<D>> = curve
        .control_points()
        .into_iter()
        .enumerate()
        .map(|(i, p)| ControlPoint::new(position(i, p.position), p.degrees))
        .collect();
    Ok(match curve {
        AnyCurve::Bezier(_) => Bezier::new(points)?.into(),
        AnyCurve::BSpline(c) => BSpline::new(points, c.knots().clone())?.into(),
        AnyCurve::Nurbs(c) => {
            let weights = c.weights().map(<[f64]>::to_vec).unwrap_or_default();
            Nurbs::new(points, weights, c.knots().clone())?.into()
        }
    })
}

/// The lower and upper curves of the alpha-cut of `curve` whose control point `i` carries
/// `spreads[i]`: the curves of the control points' lower and upper cut ends, of the same kind,
/// knots and weights. At parameter `t` the alpha-cut of each coordinate of the fuzzy curve is
/// exactly `[lower(t), upper(t)]`; at `alpha = 1` both are `curve`.
///
/// # Errors
/// [`FuzzyError::SpreadCount`], [`FuzzyError::Spread`], [`FuzzyError::Alpha`]; a shifted
/// position that overflows ([`FuzzyError::Curve`]).
pub fn alpha_cut<const D: usize>(
    curve: &AnyCurve<D>,
    spreads: &[Spread<D>],
    alpha: f64,
) -> Result<(AnyCurve<D>, AnyCurve<D>), FuzzyError> {
    if !(0.0..=1.0).contains(&alpha) {
        return Err(FuzzyError::Alpha(alpha));
    }
    check_spreads(curve, spreads)?;
    let lower = moved(curve, |i, p| spreads[i].cut(p, alpha).0)?;
    let upper = moved(curve, |i, p| spreads[i].cut(p, alpha).1)?;
    Ok((lower, upper))
}

/// The centroid (defuzzified) curve: the curve of the control points' centroids
/// `x + (right - left) / 3`, of the same kind, knots and weights as `curve`.
///
/// # Errors
/// [`FuzzyError::SpreadCount`], [`FuzzyError::Spread`]; a shifted position that overflows.
pub fn centroid_curve<const D: usize>(
    curve: &AnyCurve<D>,
    spreads: &[Spread<D>],
) -> Result<AnyCurve<D>, FuzzyError> {
    check_spreads(curve, spreads)?;
    Ok(moved(curve, |i, p| spreads[i].centroid(p))?)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::curve::Evaluate;
    use crate::degrees::Degrees;
    use crate::knots::KnotVector;

    fn points<const D: usize>(positions: &[[f64; D]]) -> Vec<ControlPoint<D>> {
        let d = Degrees::new(0.5, 0.25, 0.25).unwrap();
        positions.iter().map(|&p| ControlPoint::new(p, d)).collect()
    }

    #[test]
    fn cut_and_centroid_of_a_triangular_number() {
        let s = Spread::new([1.0], [4.0]);
        assert_eq!(s.cut([10.0], 0.0), ([9.0], [14.0]));
        assert_eq!(s.cut([10.0], 0.5), ([9.5], [12.0]));
        assert_eq!(s.cut([10.0], 1.0), ([10.0], [10.0]));
        assert_eq!(s.centroid([10.0]), [11.0]);
        assert!(Spread::<2>::ZERO.is_zero());
        assert_eq!(
            Spread::new([1.0, 2.0], [3.0, 4.0]).resize::<3>(),
            Spread::new([1.0, 2.0, 0.0], [3.0, 4.0, 0.0])
        );
    }

    #[test]
    fn a_straight_line_with_spreads_has_straight_cut_curves() {
        // From (0, 0) to (3, 0), degree 3 with evenly spaced control points: C(t) = (3t, 0).
        // The y spreads grow linearly from 0 to 3 (left) and 0 to 6 (right), so the cut
        // curves are the lines y = -(1 - alpha) 3t and y = (1 - alpha) 6t.
        let line = AnyCurve::from(
            Bezier::new(points(&[[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [3.0, 0.0]])).unwrap(),
        );
        let spreads: Vec<Spread<2>> = (0..4)
            .map(|i| Spread::new([0.0, i as f64], [0.0, 2.0 * i as f64]))
            .collect();
        for alpha in [0.0, 0.25, 0.5, 1.0] {
            let (lo, hi) = alpha_cut(&line, &spreads, alpha).unwrap();
            for k in 0..=10 {
                let t = k as f64 / 10.0;
                let l = lo.evaluate(t).unwrap().position;
                let h = hi.evaluate(t).unwrap().position;
                assert!((l[0] - 3.0 * t).abs() < 1e-12 && (h[0] - 3.0 * t).abs() < 1e-12);
                assert!(
                    (l[1] + (1.0 - alpha) * 3.0 * t).abs() < 1e-12,
                    "{alpha} {t}"
                );
                assert!(
                    (h[1] - (1.0 - alpha) * 6.0 * t).abs() < 1e-12,
                    "{alpha} {t}"
                );
            }
        }
        let c = centroid_curve(&line, &spreads).unwrap();
        let p = c.evaluate(0.5).unwrap().position;
        assert!((p[1] - (6.0 - 3.0) * 0.5 / 3.0).abs() < 1e-12);
    }

    #[test]
    fn alpha_one_and_zero_spreads_give_the_crisp_curve_exactly() {
        let pts = points(&[
            [0.0, 1.0, 2.0],
            [3.0, -1.0, 0.5],
            [4.0, 4.0, 1.0],
            [7.0, 0.0, 3.0],
        ]);
        let knots = KnotVector::clamped_uniform(2, 4).unwrap();
        let curve = AnyCurve::from(Nurbs::new(pts, vec![1.0, 2.0, 0.5, 1.0], knots).unwrap());
        let spreads = vec![Spread::new([0.3, 0.1, 2.0], [1.0, 0.0, 0.2]); 4];
        let (lo, hi) = alpha_cut(&curve, &spreads, 1.0).unwrap();
        assert_eq!(lo, curve);
        assert_eq!(hi, curve);
        let zero = vec![Spread::ZERO; 4];
        let (lo, hi) = alpha_cut(&curve, &zero, 0.0).unwrap();
        assert_eq!((&lo, &hi), (&curve, &curve));
        assert_eq!(centroid_curve(&curve, &zero).unwrap(), curve);
        assert_eq!(lo.weights(), curve.weights());
        assert_eq!(lo.knots(), curve.knots());
    }

    #[test]
    fn errors() {
        let curve = AnyCurve::from(Bezier::new(points(&[[0.0, 0.0], [1.0, 1.0]])).unwrap());
        let ok = [Spread::ZERO; 2];
        assert_eq!(
            alpha_cut(&curve, &ok[..1], 0.5).unwrap_err().to_string(),
            "1 spreads for 2 control points (give one spread per control point)"
        );
        for alpha in [-0.1, 1.5, f64::NAN] {
            assert!(matches!(
                alpha_cut(&curve, &ok, alpha),
                Err(FuzzyError::Alpha(_))
            ));
        }
        assert_eq!(
            alpha_cut(&curve, &ok, 2.0).unwrap_err().to_string(),
            "alpha = 2 is outside [0, 1]"
        );
        let bad = [Spread::ZERO, Spread::new([0.0, -1.0], [0.0, 0.0])];
        assert_eq!(
            centroid_curve(&curve, &bad).unwrap_err().to_string(),
            "control point 1: left spread of y = -1 is not a finite number >= 0"
        );
        let bad = [Spread::new([0.0, 0.0], [f64::INFINITY, 0.0]), Spread::ZERO];
        assert_eq!(
            alpha_cut(&curve, &bad, 0.0).unwrap_err().to_string(),
            "control point 0: right spread of x = inf is not a finite number >= 0"
        );
    }
}
