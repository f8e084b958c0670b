//! A curve of any kind, for code that handles Bézier, B-spline and NURBS curves alike.

use core::ops::Range;

use crate::bezier::Bezier;
pub use crate::curve::CurveKind;
use crate::curve::{
    Bounded, ControlPolygon, CurveError, Derivative, Elevate, EvalError, Evaluate, Split,
};
use crate::degrees::DegreeKind;
use crate::derivative::CurveDerivative;
use crate::knots::KnotVector;
use crate::point::{Affine, BoundingBox, ControlPoint, CurvePoint};
use crate::spline_curve::{BSpline, Nurbs};

/// A curve of any kind; each method forwards to the kind's own.
///
/// ```
/// use neutrospline::{AnyCurve, CurveKind, Evaluate};
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

    /// The knot vector (B-spline and NURBS curves).
    pub fn knots(&self) -> Option<&KnotVector> {
        match self {
            AnyCurve::Bezier(_) => None,
            AnyCurve::BSpline(c) => Some(c.knots()),
            AnyCurve::Nurbs(c) => Some(c.knots()),
        }
    }

    /// `Some(n)` for a periodic B-spline or NURBS curve with `n` distinct control points
    /// ([`crate::BSpline::periodic_count`]); `None` otherwise.
    pub fn periodic_count(&self) -> Option<usize> {
        match self {
            AnyCurve::Bezier(_) => None,
            AnyCurve::BSpline(c) => c.periodic_count(),
            AnyCurve::Nurbs(c) => c.periodic_count(),
        }
    }

    /// The weights (NURBS curves).
    pub fn weights(&self) -> Option<&[f64]> {
        match self {
            AnyCurve::Bezier(_) => None,
            AnyCurve::BSpline(c) => c.weights(),
            AnyCurve::Nurbs(c) => c.weights(),
        }
    }

    /// The same curve traversed backwards (see each kind's `reversed`).
    pub fn reversed(&self) -> Self {
        forward!(self, c => c.reversed().into())
    }

    /// The curve with an affine map applied to its positions.
    ///
    /// # Errors
    /// A mapped position overflows.
    pub fn transform(&self, map: &Affine<D>) -> Result<Self, CurveError> {
        forward!(self, c => Ok(c.transform(map)?.into()))
    }
}

impl AnyCurve<2> {
    /// The paper's space curve `(C(t), degree(t))` for one degree, of the same kind.
    pub fn degree_curve(&self, kind: DegreeKind) -> AnyCurve<3> {
        forward!(self, c => c.degree_curve(kind).into())
    }
}

impl<const D: usize> ControlPolygon<D> for AnyCurve<D> {
    fn len(&self) -> usize {
        forward!(self, c => c.len())
    }

    fn control_point(&self, i: usize) -> ControlPoint<D> {
        forward!(self, c => c.control_point(i))
    }
}

impl<const D: usize> Evaluate for AnyCurve<D> {
    type Point = CurvePoint<D>;

    fn domain(&self) -> Range<f64> {
        forward!(self, c => c.domain())
    }

    fn evaluate(&self, t: f64) -> Result<CurvePoint<D>, EvalError> {
        forward!(self, c => c.evaluate(t))
    }

    fn evaluate_sum(&self, origin: f64, offset: f64) -> Result<CurvePoint<D>, EvalError> {
        forward!(self, c => c.evaluate_sum(origin, offset))
    }
}

impl<const D: usize> Derivative for AnyCurve<D> {
    type Output = CurveDerivative<D>;

    /// The derivative, of the same type for every kind.
    fn derivative(&self) -> CurveDerivative<D> {
        forward!(self, c => c.derivative())
    }
}

impl<const D: usize> Split for AnyCurve<D> {
    fn split(&self, t: f64) -> Result<(Self, Self), EvalError> {
        forward!(self, c => c.split(t).map(|(a, b)| (a.into(), b.into())))
    }

    fn subsegment(&self, t0: f64, t1: f64) -> Result<Self, EvalError> {
        forward!(self, c => c.subsegment(t0, t1).map(Into::into))
    }
}

impl<const D: usize> Elevate for AnyCurve<D> {
    fn elevate(&self) -> Self {
        forward!(self, c => c.elevate().into())
    }
}

impl<const D: usize> Bounded<D> for AnyCurve<D> {
    fn bounding_box(&self) -> BoundingBox<D> {
        forward!(self, c => c.bounding_box())
    }

    fn control_bounding_box(&self) -> BoundingBox<D> {
        forward!(self, c => c.control_bounding_box())
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
