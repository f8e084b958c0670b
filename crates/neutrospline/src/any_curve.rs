//! A curve of any kind, for code that handles Bézier, B-spline and NURBS curves alike.

use core::fmt;

use crate::bezier::{Bezier, BezierDerivative};
use crate::bspline::{BSpline, BSplineDerivative};
use crate::curve::{Bounded, CurveError, EvalError, Evaluate};
use crate::degrees::DegreeKind;
use crate::knots::KnotVector;
use crate::nurbs::{Nurbs, NurbsDerivative};
use crate::point::{Affine, BoundingBox, ControlPoint, CurvePoint, DerivativeValue};

/// The kinds of curve the library models.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CurveKind {
    /// [`Bezier`].
    Bezier,
    /// [`BSpline`].
    BSpline,
    /// [`Nurbs`].
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

/// A curve of any kind; each method forwards to the kind's own.
///
/// ```
/// use neutrospline::{AnyCurve, CurveKind};
/// let curve = AnyCurve::from(neutrospline::example1());
/// assert_eq!(curve.kind(), CurveKind::Bezier);
/// assert_eq!(curve.evaluate(0.5)?.position, [4.625, 4.0]);
/// # Ok::<(), neutrospline::EvalError>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub enum AnyCurve<const D: usize> {
    /// A Bézier curve.
    Bezier(Bezier<D>),
    /// A B-spline curve.
    BSpline(BSpline<D>),
    /// A NURBS curve.
    Nurbs(Nurbs<D>),
}

macro_rules! forward {
    ($self:ident, $c:ident => $e:expr) => {
        match $self {
            AnyCurve::Bezier($c) => $e,
            AnyCurve::BSpline($c) => $e,
            AnyCurve::Nurbs($c) => $e,
        }
    };
}

impl<const D: usize> AnyCurve<D> {
    /// Which kind of curve this is.
    pub fn kind(&self) -> CurveKind {
        match self {
            AnyCurve::Bezier(_) => CurveKind::Bezier,
            AnyCurve::BSpline(_) => CurveKind::BSpline,
            AnyCurve::Nurbs(_) => CurveKind::Nurbs,
        }
    }

    /// The polynomial degree.
    pub fn degree(&self) -> usize {
        forward!(self, c => c.degree())
    }

    /// The parameter domain.
    pub fn domain(&self) -> (f64, f64) {
        forward!(self, c => Evaluate::domain(c))
    }

    /// Number of control points.
    pub fn len(&self) -> usize {
        forward!(self, c => c.len())
    }

    /// Always `false`: a curve has at least one control point.
    pub fn is_empty(&self) -> bool {
        false
    }

    /// All control points, in order.
    pub fn control_points(&self) -> Vec<ControlPoint<D>> {
        forward!(self, c => c.control_points())
    }

    /// The knot vector (B-spline and NURBS curves).
    pub fn knots(&self) -> Option<&KnotVector> {
        match self {
            AnyCurve::Bezier(_) => None,
            AnyCurve::BSpline(c) => Some(c.knots()),
            AnyCurve::Nurbs(c) => Some(c.knots()),
        }
    }

    /// The weights (NURBS curves).
    pub fn weights(&self) -> Option<&[f64]> {
        match self {
            AnyCurve::Nurbs(c) => Some(c.weights()),
            _ => None,
        }
    }

    /// The point at `t` in the domain.
    ///
    /// # Errors
    /// `t` not finite or outside the domain.
    pub fn evaluate(&self, t: f64) -> Result<CurvePoint<D>, EvalError> {
        forward!(self, c => c.evaluate(t))
    }

    /// Evaluates at every parameter into channel-major `out` (layout of
    /// [`Bezier::evaluate_channels`]).
    ///
    /// # Errors
    /// The first parameter not finite or outside the domain.
    ///
    /// # Panics
    /// If `out.len() != (D + 3) * ts.len()`.
    pub fn evaluate_channels(&self, ts: &[f64], out: &mut [f64]) -> Result<(), EvalError> {
        forward!(self, c => c.evaluate_channels(ts, out))
    }

    /// The first derivative, as an object to evaluate at many parameters.
    pub fn derivative(&self) -> AnyDerivative<D> {
        match self {
            AnyCurve::Bezier(c) => AnyDerivative::Bezier(c.derivative()),
            AnyCurve::BSpline(c) => AnyDerivative::BSpline(c.derivative()),
            AnyCurve::Nurbs(c) => AnyDerivative::Nurbs(c.derivative()),
        }
    }

    /// The first derivative at `t`. For many parameters, build [`AnyCurve::derivative`] once.
    ///
    /// # Errors
    /// `t` not finite or outside the domain; [`EvalError::Overflow`].
    pub fn derivative_at(&self, t: f64) -> Result<DerivativeValue<D>, EvalError> {
        self.derivative().evaluate(t)
    }

    /// Tight bounds of positions and degrees.
    pub fn bounding_box(&self) -> BoundingBox<D> {
        forward!(self, c => c.bounding_box())
    }

    /// Bounds of the control values.
    pub fn control_bounding_box(&self) -> BoundingBox<D> {
        forward!(self, c => c.control_bounding_box())
    }

    /// Degree elevation (same curve, degree + 1).
    pub fn elevate(&self) -> Self {
        match self {
            AnyCurve::Bezier(c) => AnyCurve::Bezier(c.elevate()),
            AnyCurve::BSpline(c) => AnyCurve::BSpline(c.elevate()),
            AnyCurve::Nurbs(c) => AnyCurve::Nurbs(c.elevate()),
        }
    }

    /// The curve with an affine map applied to its positions.
    ///
    /// # Errors
    /// A mapped position overflows.
    pub fn transform(&self, map: &Affine<D>) -> Result<Self, CurveError> {
        Ok(match self {
            AnyCurve::Bezier(c) => AnyCurve::Bezier(c.transform(map)?),
            AnyCurve::BSpline(c) => AnyCurve::BSpline(c.transform(map)?),
            AnyCurve::Nurbs(c) => AnyCurve::Nurbs(c.transform(map)?),
        })
    }
}

impl AnyCurve<2> {
    /// The paper's space curve `(C(t), degree(t))` for one degree, of the same kind.
    pub fn degree_curve(&self, kind: DegreeKind) -> AnyCurve<3> {
        match self {
            AnyCurve::Bezier(c) => AnyCurve::Bezier(c.degree_curve(kind)),
            AnyCurve::BSpline(c) => AnyCurve::BSpline(c.degree_curve(kind)),
            AnyCurve::Nurbs(c) => AnyCurve::Nurbs(c.degree_curve(kind)),
        }
    }
}

/// The first derivative of an [`AnyCurve`], of the matching kind.
#[derive(Clone, Debug, PartialEq)]
pub enum AnyDerivative<const D: usize> {
    /// Of a Bézier curve.
    Bezier(BezierDerivative<D>),
    /// Of a B-spline curve.
    BSpline(BSplineDerivative<D>),
    /// Of a NURBS curve.
    Nurbs(NurbsDerivative<D>),
}

impl<const D: usize> AnyDerivative<D> {
    /// The derivative at `t` in the curve's domain.
    ///
    /// # Errors
    /// `t` not finite or outside the domain; [`EvalError::Overflow`].
    pub fn evaluate(&self, t: f64) -> Result<DerivativeValue<D>, EvalError> {
        match self {
            AnyDerivative::Bezier(d) => d.evaluate(t),
            AnyDerivative::BSpline(d) => d.evaluate(t),
            AnyDerivative::Nurbs(d) => d.evaluate(t),
        }
    }
}

impl<const D: usize> Evaluate<D> for AnyCurve<D> {
    fn domain(&self) -> (f64, f64) {
        AnyCurve::domain(self)
    }
    fn evaluate(&self, t: f64) -> Result<CurvePoint<D>, EvalError> {
        AnyCurve::evaluate(self, t)
    }
    fn start(&self) -> CurvePoint<D> {
        forward!(self, c => Evaluate::start(c))
    }
    fn end(&self) -> CurvePoint<D> {
        forward!(self, c => Evaluate::end(c))
    }
    fn evaluate_many(&self, ts: &[f64], out: &mut [CurvePoint<D>]) -> Result<(), EvalError> {
        forward!(self, c => Evaluate::evaluate_many(c, ts, out))
    }
}

impl<const D: usize> Bounded<D> for AnyCurve<D> {
    fn bounding_box(&self) -> BoundingBox<D> {
        AnyCurve::bounding_box(self)
    }
    fn control_bounding_box(&self) -> BoundingBox<D> {
        AnyCurve::control_bounding_box(self)
    }
}

impl<const D: usize> From<Bezier<D>> for AnyCurve<D> {
    fn from(c: Bezier<D>) -> Self {
        AnyCurve::Bezier(c)
    }
}

impl<const D: usize> From<BSpline<D>> for AnyCurve<D> {
    fn from(c: BSpline<D>) -> Self {
        AnyCurve::BSpline(c)
    }
}

impl<const D: usize> From<Nurbs<D>> for AnyCurve<D> {
    fn from(c: Nurbs<D>) -> Self {
        AnyCurve::Nurbs(c)
    }
}
