//! Capabilities shared by every curve kind, as small traits, and the errors they report.

use crate::point::{BoundingBox, CurvePoint};

/// Why a curve cannot be built from the given control data.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum CurveError {
    /// No control points were given (a curve needs at least one; one point is a degree-0 curve).
    #[error("no control points (a curve needs at least one)")]
    NoControlPoints,
    /// A coordinate of a control point is NaN or infinite.
    #[error("control point {index}: {axis} = {value} is not a finite number (positions must be finite)", axis = axis_name(*axis))]
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

/// Why a curve cannot be evaluated at a parameter.
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
    /// The result does not fit in a 64-bit float (for example the derivative of a curve whose
    /// control points are near 1e308).
    #[error("the value at t = {t} overflows a 64-bit float (control values too large)")]
    Overflow {
        /// The parameter.
        t: f64,
    },
}

/// `x`, `y`, `z` for coordinate indices 0, 1, 2.
pub fn axis_name(axis: usize) -> &'static str {
    ["x", "y", "z"].get(axis).copied().unwrap_or("coordinate")
}

/// Checks that `t` is finite and inside `[start, end]`.
///
/// # Errors
/// [`EvalError::ParameterNotFinite`] or [`EvalError::ParameterOutOfDomain`].
pub(crate) fn check_parameter(t: f64, (start, end): (f64, f64)) -> Result<(), EvalError> {
    if !t.is_finite() {
        Err(EvalError::ParameterNotFinite { t })
    } else if t < start || t > end {
        Err(EvalError::ParameterOutOfDomain { t, start, end })
    } else {
        Ok(())
    }
}

/// Evaluation of a neutrosophic curve: position and the three degrees at a parameter.
///
/// Every point returned is a valid neutrosophic point: its degrees are convex combinations of
/// the control degrees, so they stay within the control range and inside \[0, 1\].
pub trait Evaluate<const D: usize> {
    /// The parameter interval `(start, end)`.
    fn domain(&self) -> (f64, f64);

    /// The point at parameter `t`.
    ///
    /// # Errors
    /// `t` not finite or outside [`Evaluate::domain`].
    fn evaluate(&self, t: f64) -> Result<CurvePoint<D>, EvalError>;

    /// The point at the start of the domain.
    fn start(&self) -> CurvePoint<D>;

    /// The point at the end of the domain.
    fn end(&self) -> CurvePoint<D>;

    /// Evaluates at every parameter of `ts` into `out` (same length), without allocating per
    /// point.
    ///
    /// # Errors
    /// The first parameter that fails; `out` is then partly written.
    ///
    /// # Panics
    /// If `out.len() != ts.len()`.
    fn evaluate_many(&self, ts: &[f64], out: &mut [CurvePoint<D>]) -> Result<(), EvalError>;
}

/// The derivative (with respect to the parameter) of a curve, as another curve-like object.
pub trait Derivative {
    /// The type of the derivative.
    type Output;

    /// The derivative of positions and degrees.
    fn derivative(&self) -> Self::Output;
}

/// Splitting a curve into pieces that together reproduce it exactly.
pub trait Split: Sized {
    /// The two pieces on `[start, t]` and `[t, end]`, each reparametrised to the full domain.
    ///
    /// # Errors
    /// `t` not finite or outside the domain.
    fn split(&self, t: f64) -> Result<(Self, Self), EvalError>;

    /// The piece on `[t0, t1]` (reversed when `t0 > t1`), reparametrised to the full domain.
    ///
    /// # Errors
    /// A parameter not finite or outside the domain.
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
