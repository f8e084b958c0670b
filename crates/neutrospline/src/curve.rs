//! Capabilities shared by every curve kind, as small traits, and the errors they report.
//!
//! The traits follow kurbo's `ParamCurve` family: each method has one body (a default built on
//! [`Evaluate::evaluate`] unless a kind has a genuinely different algorithm), and the
//! derivative of a curve is again an object with the same capabilities
//! ([`Derivative::Output`] is evaluable and differentiable), so generic code can take the
//! n-th derivative of any curve. See `docs/model.md` for the mathematics.

use core::fmt;
use core::ops::Range;

use crate::point::{BoundingBox, ControlPoint};

/// The kinds of curve the library models.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CurveKind {
    /// [`Bezier`](crate::Bezier).
    Bezier,
    /// [`BSpline`](crate::BSpline).
    BSpline,
    /// [`Nurbs`](crate::Nurbs).
    Nurbs,
}

impl CurveKind {
    /// The name used in files: `bezier`, `bspline` or `nurbs`.
    pub const fn name(self) -> &'static str {
        match self {
            CurveKind::Bezier => "bezier",
            CurveKind::BSpline => "bspline",
            CurveKind::Nurbs => "nurbs",
        }
    }
}

impl fmt::Display for CurveKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Why a curve cannot be built from the given control data.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum CurveError {
    /// No control points were given (a curve needs at least one; one point is a degree-0 curve).
    #[error("no control points (a curve needs at least one)")]
    NoControlPoints,
    /// The positions have a dimension the library does not model.
    #[error("{dimension}-D positions are not supported (curves are 2-D or 3-D, surfaces 3-D)")]
    UnsupportedDimension {
        /// The number of coordinates of each position.
        dimension: usize,
    },
    /// A coordinate of a control point is NaN or infinite.
    #[error("control point {index}: {axis} = {value} is not a finite number (positions must be finite)", axis = AXES[*axis])]
    PositionNotFinite {
        /// Index of the control point (0-based).
        index: usize,
        /// Coordinate index: 0 for x, 1 for y, 2 for z.
        axis: usize,
        /// The offending value.
        value: f64,
    },
    /// A NURBS weight is zero, negative or not finite.
    #[error("control point {index}: weight = {value} is not a positive finite number (NURBS weights must be > 0)")]
    WeightNotPositive {
        /// Index of the control point (0-based).
        index: usize,
        /// The offending weight.
        value: f64,
    },
    /// The number of weights differs from the number of control points.
    #[error("{weights} weights for {points} control points (one weight per control point)")]
    WeightCount {
        /// Number of weights.
        weights: usize,
        /// Number of control points.
        points: usize,
    },
    /// A surface's control grid does not have `rows x cols` points.
    #[error("{points} control points do not fill a grid of {rows} rows x {cols} columns ({expected} points)", expected = rows * cols)]
    GridSize {
        /// Number of control points given.
        points: usize,
        /// Rows declared.
        rows: usize,
        /// Columns declared.
        cols: usize,
    },
    /// The knot vector is invalid for the degree and the number of control points.
    #[error(transparent)]
    Knots(#[from] crate::knots::KnotError),
}

/// Coordinate names by axis index (only 2-D and 3-D positions are ever built).
const AXES: [&str; 3] = ["x", "y", "z"];

/// Why a curve cannot be evaluated (or cut) at a parameter.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum EvalError {
    /// The parameter is NaN or infinite.
    #[error("parameter t = {t} is not a finite number")]
    ParameterNotFinite {
        /// The parameter.
        t: f64,
    },
    /// The parameter lies outside the curve's domain.
    #[error("parameter t = {t} is outside the domain [{start}, {end}]")]
    ParameterOutOfDomain {
        /// The parameter.
        t: f64,
        /// Start of the domain.
        start: f64,
        /// End of the domain.
        end: f64,
    },
    /// A spline piece would have an empty domain: a split at an end of the domain, or a
    /// subsegment between equal parameters (a Bézier curve allows both, its domain is always
    /// \[0, 1\]).
    #[error("the piece [{start}, {end}] of the spline would be a single point (a spline piece needs a non-empty domain)")]
    EmptyPiece {
        /// Start of the requested piece.
        start: f64,
        /// End of the requested piece.
        end: f64,
    },
    /// The result does not fit in a 64-bit float (for example the derivative of a curve whose
    /// control points are near 1e308).
    #[error("the value at t = {t} overflows a 64-bit float (control values too large)")]
    Overflow {
        /// The parameter.
        t: f64,
    },
}

/// Checks that `t` is finite and inside `domain` (ends included).
///
/// # Errors
/// [`EvalError::ParameterNotFinite`] or [`EvalError::ParameterOutOfDomain`].
pub(crate) fn check_parameter(t: f64, domain: &Range<f64>) -> Result<(), EvalError> {
    if !t.is_finite() {
        Err(EvalError::ParameterNotFinite { t })
    } else if t < domain.start || t > domain.end {
        Err(EvalError::ParameterOutOfDomain {
            t,
            start: domain.start,
            end: domain.end,
        })
    } else {
        Ok(())
    }
}

/// The control points of a curve of any kind, in order.
///
/// ```
/// use neutrospline::ControlPolygon;
/// let curve = neutrospline::example1();
/// assert_eq!(curve.len(), 4);
/// assert_eq!(curve.control_point(1).position, [3.0, 6.0]);
/// assert_eq!(curve.control_points()[3].degrees.indeterminacy(), 0.4);
/// ```
pub trait ControlPolygon<const D: usize> {
    /// The number of control points (at least 1: a curve has no empty polygon).
    fn len(&self) -> usize;

    /// Always `false`: a curve has at least one control point.
    fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Control point `i`.
    ///
    /// # Panics
    /// If `i >= len()`.
    fn control_point(&self, i: usize) -> ControlPoint<D>;

    /// All control points, in order.
    fn control_points(&self) -> Vec<ControlPoint<D>> {
        (0..self.len()).map(|i| self.control_point(i)).collect()
    }
}

/// Evaluation of a parametric curve: a neutrosophic curve (whose points are
/// [`CurvePoint`](crate::CurvePoint)s) or the derivative of one (whose values are
/// [`DerivativeValue`](crate::DerivativeValue)s).
///
/// Every point of a neutrosophic curve is a valid neutrosophic point: its degrees are convex
/// combinations of the control degrees, so they stay within the control range and inside
/// \[0, 1\].
///
/// ```
/// use neutrospline::Evaluate;
/// let curve = neutrospline::example1();
/// assert_eq!(curve.domain(), 0.0..1.0);
/// assert_eq!(curve.start()?.position, [1.0, 3.0]);
/// assert_eq!(curve.end()?.position, [9.0, 5.0]);
/// # Ok::<(), neutrospline::EvalError>(())
/// ```
pub trait Evaluate {
    /// What the curve yields at a parameter.
    type Point: Copy;

    /// The parameter interval `start..end`; both ends belong to it (the curve is defined on
    /// the closed interval `[start, end]`).
    fn domain(&self) -> Range<f64>;

    /// The point at parameter `t`.
    ///
    /// # Errors
    /// `t` not finite or outside [`Evaluate::domain`]; [`EvalError::Overflow`] for a
    /// derivative whose value is not representable.
    fn evaluate(&self, t: f64) -> Result<Self::Point, EvalError>;

    /// The point at the exact sum `origin + offset` of two floats, a parameter finer than one
    /// float holds near a large `origin` (the nodes of a quadrature on a knot span of width
    /// `1e-3` at `t = 1e4` are otherwise rounded by `1e-12` of the span). Splines and their
    /// derivatives take each knot difference as `(origin - u_i) + offset`; other kinds
    /// evaluate at the rounded sum, which is as fine on their domain `[0, 1]`.
    ///
    /// ```
    /// use neutrospline::Evaluate;
    /// let curve = neutrospline::example1();
    /// assert_eq!(curve.evaluate_sum(0.25, 0.25)?, curve.evaluate(0.5)?);
    /// # Ok::<(), neutrospline::EvalError>(())
    /// ```
    ///
    /// # Errors
    /// As [`Evaluate::evaluate`] at `origin + offset`.
    fn evaluate_sum(&self, origin: f64, offset: f64) -> Result<Self::Point, EvalError> {
        self.evaluate(origin + offset)
    }

    /// The point at the start of the domain (for every kind of neutrosophic curve with
    /// clamped knots, the first control point exactly).
    ///
    /// # Errors
    /// Only [`EvalError::Overflow`], for a derivative.
    fn start(&self) -> Result<Self::Point, EvalError> {
        self.evaluate(self.domain().start)
    }

    /// The point at the end of the domain.
    ///
    /// # Errors
    /// Only [`EvalError::Overflow`], for a derivative.
    fn end(&self) -> Result<Self::Point, EvalError> {
        self.evaluate(self.domain().end)
    }

    /// Evaluates at every parameter of `ts` into `out` (same length). Evaluation allocates
    /// nothing per point up to high degrees (scratch space on the stack); for many parameters
    /// into flat arrays use [`CurveBatch`](crate::CurveBatch).
    ///
    /// # Errors
    /// The first parameter that fails; `out` is then partly written.
    ///
    /// # Panics
    /// If `out.len() != ts.len()`.
    fn evaluate_many(&self, ts: &[f64], out: &mut [Self::Point]) -> Result<(), EvalError> {
        assert_eq!(
            ts.len(),
            out.len(),
            "evaluate_many: ts and out differ in length"
        );
        for (&t, slot) in ts.iter().zip(out.iter_mut()) {
            *slot = self.evaluate(t)?;
        }
        Ok(())
    }
}

/// The derivative with respect to the parameter, as another curve-like object that can be
/// evaluated and differentiated again.
///
/// ```
/// use neutrospline::{Derivative, Evaluate};
/// let curve = neutrospline::example1();
/// // 6 (P_2 - 2 P_1 + P_0) at t = 0: x = 6 (6 - 6 + 1) = 6, y = 6 (2 - 12 + 3) = -42.
/// let second = curve.derivative().derivative().evaluate(0.0)?;
/// assert_eq!(second.position, [6.0, -42.0]);
/// # Ok::<(), neutrospline::EvalError>(())
/// ```
pub trait Derivative {
    /// The type of the derivative: evaluable, and differentiable again.
    type Output: Evaluate + Derivative;

    /// The derivative of positions and degrees.
    fn derivative(&self) -> Self::Output;
}

/// Cutting a curve into pieces that together reproduce it exactly (up to rounding).
///
/// A Bézier curve's pieces are reparametrised to its domain \[0, 1\]; a spline's pieces keep
/// the curve's own parameters (the piece on `[start, t]` has that domain), so a point of a
/// piece is the curve's point at the same parameter.
pub trait Split: Sized {
    /// The two pieces on `[start, t]` and `[t, end]`.
    ///
    /// # Errors
    /// `t` not finite or outside the domain; for a spline, [`EvalError::EmptyPiece`] when `t`
    /// is an end of the domain.
    fn split(&self, t: f64) -> Result<(Self, Self), EvalError>;

    /// The piece on `[t0, t1]`, traversed from `t0` to `t1` (reversed when `t0 > t1`).
    ///
    /// # Errors
    /// A parameter not finite or outside the domain; for a spline, [`EvalError::EmptyPiece`]
    /// when `t0 == t1`.
    fn subsegment(&self, t0: f64, t1: f64) -> Result<Self, EvalError>;
}

/// Degree elevation: the same curve described with more control points.
pub trait Elevate: Sized {
    /// The same curve with its polynomial degree raised by one.
    fn elevate(&self) -> Self;
}

/// Axis-aligned bounds of positions and degrees.
pub trait Bounded<const D: usize> {
    /// A box that contains every point of the curve and is tight to within
    /// [`BOUNDS_TOLERANCE`] times the largest absolute control value of each channel.
    fn bounding_box(&self) -> BoundingBox<D>;

    /// The box of the control values: contains the curve (convex hull property), cheap, loose.
    fn control_bounding_box(&self) -> BoundingBox<D>;
}

/// Relative accuracy of [`Bounded::bounding_box`].
pub const BOUNDS_TOLERANCE: f64 = 1e-12;
