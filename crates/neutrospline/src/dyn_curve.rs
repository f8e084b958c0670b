//! [`Dimensional`]: a value for the plane or for space, the dimension known at run time, and
//! [`DynCurve`], a curve of any kind and either dimension, with row-level evaluation,
//! derivatives, nearest points, geometry and intersections, so that front ends which read the
//! dimension from data never match on it for a job the core can do (docs/architecture.md,
//! "one definition of every option").
//!
//! Code generic over the dimension reaches the value inside with [`on_dimension!`](crate::on_dimension) (one body
//! for both dimensions) and builds a new one with [`map_dimension!`](crate::map_dimension).

use core::ops::Range;

use crate::any_curve::{AnyCurve, CurveKind};
use crate::curve::{Bounded, ControlPolygon, Derivative, EvalError, Evaluate};
use crate::degrees::Degrees;
use crate::derivative::CurveDerivative;
use crate::geometry::{ArcAverages, CurveGeometry, GeometryError};
use crate::intersect::{intersections, self_intersections, IntersectError, Intersection};
use crate::knots::KnotVector;
use crate::nearest::{NearestError, NearestPoint};
use crate::point::{CurvePoint, DerivativeValue, Interval};

/// A value for the plane (`P`, 2-D) or for space (`S`, 3-D): the one place where the
/// dimension, known only at run time, becomes a type. [`DynCurve`] is the curve of either
/// dimension; front ends hold their own per-dimension state the same way (a prepared batch
/// evaluator, a derivative) and reach it with [`on_dimension!`](crate::on_dimension).
///
/// ```
/// use neutrospline::{on_dimension, Dimensional};
/// let value: Dimensional<[f64; 2], [f64; 3]> = Dimensional::Spatial([1.0, 2.0, 2.0]);
/// assert_eq!(value.dimension(), 3);
/// // One body for both dimensions: here the Euclidean norm.
/// let norm = on_dimension!(&value, p => p.iter().map(|x| x * x).sum::<f64>().sqrt());
/// assert_eq!(norm, 3.0);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Dimensional<P, S> {
    /// In the plane (x, y).
    Planar(P),
    /// In space (x, y, z).
    Spatial(S),
}

/// Evaluates `$body` with `$bind` bound to the value inside a [`Dimensional`], whichever
/// dimension it is: the body is compiled once per dimension, so it may call code generic over
/// `const D: usize`.
///
/// ```
/// use neutrospline::{on_dimension, AnyCurve, DynCurve, Evaluate};
/// let curve = DynCurve::from(AnyCurve::from(neutrospline::example1()));
/// let end = on_dimension!(&curve, c => c.evaluate(1.0).map(|p| p.position.to_vec()));
/// assert_eq!(end?, [9.0, 5.0]);
/// # Ok::<(), neutrospline::EvalError>(())
/// ```
#[macro_export]
macro_rules! on_dimension {
    ($value:expr, $bind:pat => $body:expr) => {
        match $value {
            $crate::Dimensional::Planar($bind) => $body,
            $crate::Dimensional::Spatial($bind) => $body,
        }
    };
}

/// Builds a [`Dimensional`] of the same dimension as `$value` from `$body`, evaluated with
/// `$bind` bound to the value inside (as [`on_dimension!`](crate::on_dimension) does).
///
/// ```
/// use neutrospline::{map_dimension, AnyCurve, Derivative, DynCurve, DynDerivative};
/// let curve = DynCurve::from(AnyCurve::from(neutrospline::example1()));
/// let speed: DynDerivative = map_dimension!(&curve, c => c.derivative());
/// assert_eq!(speed.dimension(), 2);
/// ```
#[macro_export]
macro_rules! map_dimension {
    ($value:expr, $bind:pat => $body:expr) => {
        match $value {
            $crate::Dimensional::Planar($bind) => $crate::Dimensional::Planar($body),
            $crate::Dimensional::Spatial($bind) => $crate::Dimensional::Spatial($body),
        }
    };
}

impl<P, S> Dimensional<P, S> {
    /// 2 or 3.
    pub const fn dimension(&self) -> usize {
        match self {
            Dimensional::Planar(_) => 2,
            Dimensional::Spatial(_) => 3,
        }
    }

    /// The value inside, by reference.
    pub const fn as_ref(&self) -> Dimensional<&P, &S> {
        match self {
            Dimensional::Planar(p) => Dimensional::Planar(p),
            Dimensional::Spatial(s) => Dimensional::Spatial(s),
        }
    }

    /// The planar value, if this is one.
    pub const fn planar(&self) -> Option<&P> {
        match self {
            Dimensional::Planar(p) => Some(p),
            Dimensional::Spatial(_) => None,
        }
    }

    /// The spatial value, if this is one.
    pub const fn spatial(&self) -> Option<&S> {
        match self {
            Dimensional::Planar(_) => None,
            Dimensional::Spatial(s) => Some(s),
        }
    }
}

/// A curve of any kind, 2-D or 3-D: what a data file or an array of unknown width holds or
/// fits to. Its row-level methods take and give points as `x, y[, z]` rows.
///
/// ```
/// use neutrospline::{DynCurve, AnyCurve};
/// let curve = DynCurve::from(AnyCurve::from(neutrospline::example1()));
/// assert_eq!(curve.dimension(), 2);
/// // x, y, truth, indeterminacy, falsity.
/// let row = curve.evaluate_row(0.0)?;
/// assert_eq!(row[..2], [1.0, 3.0]);
/// assert_eq!(row.len(), 5);
/// # Ok::<(), neutrospline::EvalError>(())
/// ```
pub type DynCurve = Dimensional<AnyCurve<2>, AnyCurve<3>>;

/// The derivative of a [`DynCurve`] (of any order): rates of change of the position and of
/// the degrees, as rows.
pub type DynDerivative = Dimensional<CurveDerivative<2>, CurveDerivative<3>>;

impl From<AnyCurve<2>> for DynCurve {
    fn from(curve: AnyCurve<2>) -> DynCurve {
        Dimensional::Planar(curve)
    }
}

impl From<AnyCurve<3>> for DynCurve {
    fn from(curve: AnyCurve<3>) -> DynCurve {
        Dimensional::Spatial(curve)
    }
}

/// Points given as rows of coordinates that do not fit the curve's dimension.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{values} coordinates are not rows of {dimension} (the curve is {dimension}-D)")]
pub struct RowLengthError {
    /// The curve's dimension.
    pub dimension: usize,
    /// The number of coordinates given.
    pub values: usize,
}

/// A point of a [`DynCurve`]: its position (2 or 3 coordinates) and its degrees.
#[derive(Clone, Debug, PartialEq)]
pub struct DynPoint {
    /// `x, y[, z]`.
    pub position: Vec<f64>,
    /// Truth, indeterminacy and falsity.
    pub degrees: Degrees,
}

impl DynPoint {
    /// The point as a row: `x, y[, z], truth, indeterminacy, falsity`.
    pub fn row(&self) -> Vec<f64> {
        let mut row = Vec::with_capacity(self.position.len() + 3);
        row.extend_from_slice(&self.position);
        row.extend_from_slice(&self.degrees.to_array());
        row
    }
}

impl<const D: usize> From<CurvePoint<D>> for DynPoint {
    fn from(point: CurvePoint<D>) -> DynPoint {
        DynPoint {
            position: point.position.to_vec(),
            degrees: point.degrees,
        }
    }
}

/// The nearest point of a [`DynCurve`] to a query row ([`DynCurve::nearest_rows`]).
#[derive(Clone, Debug, PartialEq)]
pub struct NearestRow {
    /// The curve's parameter of the nearest point ([`crate::Nearest::parameter`]).
    pub parameter: f64,
    /// The Euclidean distance from the query point.
    pub distance: f64,
    /// The nearest point, with its degrees.
    pub point: DynPoint,
}

/// `dx, dy[, dz], dtruth, dindeterminacy, dfalsity` of a derivative value.
fn rate_row<const D: usize>(rate: &DerivativeValue<D>) -> Vec<f64> {
    let mut row = Vec::with_capacity(D + 3);
    row.extend_from_slice(&rate.position);
    row.extend_from_slice(&[rate.truth, rate.indeterminacy, rate.falsity]);
    row
}

impl DynCurve {
    /// Bézier, B-spline or NURBS.
    pub fn kind(&self) -> CurveKind {
        on_dimension!(self, c => c.kind())
    }

    /// The polynomial degree.
    pub fn degree(&self) -> usize {
        on_dimension!(self, c => c.degree())
    }

    /// The number of control points (never 0).
    pub fn len(&self) -> usize {
        on_dimension!(self, c => c.len())
    }

    /// Always `false`: a curve has at least one control point (for clippy's `len` rule).
    pub fn is_empty(&self) -> bool {
        false
    }

    /// The knot vector of a B-spline or NURBS curve.
    pub fn knots(&self) -> Option<&KnotVector> {
        on_dimension!(self, c => c.knots())
    }

    /// The weights of a NURBS curve.
    pub fn weights(&self) -> Option<&[f64]> {
        on_dimension!(self, c => c.weights())
    }

    /// The parameter domain.
    pub fn domain(&self) -> Range<f64> {
        on_dimension!(self, c => c.domain())
    }

    /// The control points as rows `x, y[, z], truth, indeterminacy, falsity`, in order.
    pub fn control_rows(&self) -> Vec<Vec<f64>> {
        on_dimension!(self, c => c
            .control_points()
            .iter()
            .map(|p| {
                let mut row = p.position.to_vec();
                row.extend_from_slice(&p.degrees.to_array());
                row
            })
            .collect())
    }

    /// The degrees of every control point, in order.
    pub fn control_degrees(&self) -> Vec<Degrees> {
        on_dimension!(self, c => c.control_points().iter().map(|p| p.degrees).collect())
    }

    /// The range (min, max) of truth, indeterminacy and falsity over the control points
    /// (which bound them on the whole curve: docs/model.md, the convex hull property).
    pub fn degree_ranges(&self) -> [Interval; 3] {
        on_dimension!(self, c => {
            let b = c.control_bounding_box();
            [b.truth, b.indeterminacy, b.falsity]
        })
    }

    /// The point at `t` as a row: `x, y[, z], truth, indeterminacy, falsity`.
    ///
    /// # Errors
    /// `t` not finite or outside the domain; an overflow.
    pub fn evaluate_row(&self, t: f64) -> Result<Vec<f64>, EvalError> {
        self.evaluate_point(t).map(|p| p.row())
    }

    /// The point at `t`, with its degrees.
    ///
    /// # Errors
    /// `t` not finite or outside the domain; an overflow.
    pub fn evaluate_point(&self, t: f64) -> Result<DynPoint, EvalError> {
        on_dimension!(self, c => c.evaluate(t).map(DynPoint::from))
    }

    /// The first derivative `dC/dt` (position and degrees), itself differentiable.
    pub fn derivative(&self) -> DynDerivative {
        map_dimension!(self, c => c.derivative())
    }

    /// The derivative of order `order` (>= 1; order 0 is taken as 1).
    pub fn nth_derivative(&self, order: usize) -> DynDerivative {
        let mut derivative = self.derivative();
        for _ in 1..order {
            derivative = derivative.derivative();
        }
        derivative
    }

    /// The nearest points of the curve to `points`, given as rows of [`Self::dimension`]
    /// coordinates one after another, in order (one search per point, as
    /// [`NearestPoint::nearest`]; in parallel with the `parallel` feature).
    ///
    /// ```
    /// use neutrospline::{DynCurve, AnyCurve};
    /// let curve = DynCurve::from(AnyCurve::from(neutrospline::example1()));
    /// let found = curve.nearest_rows(&[0.0, 3.0, 4.625, 4.0])?;
    /// let first = found[0].as_ref().unwrap();
    /// assert_eq!((first.parameter, first.distance), (0.0, 1.0));
    /// assert!(found[1].as_ref().unwrap().distance < 1e-12);
    /// # Ok::<(), neutrospline::RowLengthError>(())
    /// ```
    ///
    /// # Errors
    /// [`RowLengthError`] when `points` is not whole rows; each point's own
    /// [`NearestError`] (a coordinate not finite, an overflow) in its place.
    #[allow(clippy::type_complexity)]
    pub fn nearest_rows(
        &self,
        points: &[f64],
    ) -> Result<Vec<Result<NearestRow, NearestError>>, RowLengthError> {
        fn rows<const D: usize>(
            curve: &AnyCurve<D>,
            points: &[f64],
        ) -> Vec<Result<NearestRow, NearestError>> {
            let queries: Vec<[f64; D]> = points
                .chunks_exact(D)
                .map(|row| core::array::from_fn(|a| row[a]))
                .collect();
            curve
                .projector()
                .nearest_many(&queries)
                .into_iter()
                .map(|found| {
                    found.map(|n| NearestRow {
                        parameter: n.parameter,
                        distance: n.distance,
                        point: n.point.into(),
                    })
                })
                .collect()
        }
        let dimension = self.dimension();
        if !points.len().is_multiple_of(dimension) {
            return Err(RowLengthError {
                dimension,
                values: points.len(),
            });
        }
        Ok(on_dimension!(self, c => rows(c, points)))
    }

    /// The arc length over `range` to the relative `accuracy` ([`CurveGeometry::arc_length`]).
    ///
    /// # Errors
    /// As [`CurveGeometry::arc_length`].
    pub fn arc_length(&self, range: Range<f64>, accuracy: f64) -> Result<f64, GeometryError> {
        on_dimension!(self, c => c.arc_length(range, accuracy))
    }

    /// The parameter at arc length `s` from the start ([`CurveGeometry::parameter_at_length`]).
    ///
    /// # Errors
    /// As [`CurveGeometry::parameter_at_length`].
    pub fn parameter_at_length(&self, s: f64, accuracy: f64) -> Result<f64, GeometryError> {
        on_dimension!(self, c => c.parameter_at_length(s, accuracy))
    }

    /// The parameters of `count` points evenly spaced by arc length
    /// ([`CurveGeometry::arc_length_parameters`]).
    ///
    /// # Errors
    /// As [`CurveGeometry::arc_length_parameters`].
    pub fn arc_length_parameters(
        &self,
        count: usize,
        accuracy: f64,
    ) -> Result<Vec<f64>, GeometryError> {
        on_dimension!(self, c => c.arc_length_parameters(count, accuracy))
    }

    /// The length and the length-weighted averages of the degrees and the score
    /// ([`CurveGeometry::arc_averages`]).
    ///
    /// # Errors
    /// As [`CurveGeometry::arc_averages`].
    pub fn arc_averages(&self, accuracy: f64) -> Result<ArcAverages, GeometryError> {
        on_dimension!(self, c => c.arc_averages(accuracy))
    }

    /// The curvature at `t` ([`CurveGeometry::curvature`]).
    ///
    /// # Errors
    /// As [`CurveGeometry::curvature`] (a stationary point has none).
    pub fn curvature(&self, t: f64) -> Result<f64, GeometryError> {
        on_dimension!(self, c => c.curvature(t))
    }

    /// The points where this plane curve meets the plane curve `other` ([`intersections`];
    /// docs/model.md, section 11). A curve overlaps itself everywhere: its crossings with
    /// itself are [`DynCurve::self_intersections`].
    ///
    /// # Errors
    /// [`IntersectError::NotPlanar`] for a 3-D curve; as [`intersections`] (overlapping
    /// curves, an overflow).
    pub fn intersections(&self, other: &DynCurve) -> Result<Vec<Intersection>, IntersectError> {
        intersections(plane(self, "first")?, plane(other, "second")?)
    }

    /// The points where this plane curve crosses or touches itself ([`self_intersections`]).
    ///
    /// # Errors
    /// [`IntersectError::NotPlanar`] for a 3-D curve; as [`self_intersections`].
    pub fn self_intersections(&self) -> Result<Vec<Intersection>, IntersectError> {
        self_intersections(plane(self, "first")?)
    }
}

/// The plane curve inside `curve`, or [`IntersectError::NotPlanar`] naming it as `which`.
fn plane<'a>(curve: &'a DynCurve, which: &'static str) -> Result<&'a AnyCurve<2>, IntersectError> {
    curve.planar().ok_or(IntersectError::NotPlanar {
        which,
        dimension: curve.dimension(),
    })
}

impl DynDerivative {
    /// The parameter domain (the curve's).
    pub fn domain(&self) -> Range<f64> {
        on_dimension!(self, d => d.domain())
    }

    /// The rates at `t` as a row: `dx, dy[, dz], dtruth, dindeterminacy, dfalsity`.
    ///
    /// # Errors
    /// `t` not finite or outside the domain; an overflow.
    pub fn evaluate_row(&self, t: f64) -> Result<Vec<f64>, EvalError> {
        on_dimension!(self, d => d.evaluate(t).map(|rate| rate_row(&rate)))
    }

    /// The next derivative.
    pub fn derivative(&self) -> DynDerivative {
        map_dimension!(self, d => d.derivative())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{BSpline, ControlPoint, Nurbs};

    fn spatial_helix_like() -> DynCurve {
        let d = Degrees::new(0.5, 0.25, 0.125).unwrap();
        let points = (0..4)
            .map(|i| {
                let t = f64::from(i);
                ControlPoint::new([t, t * t, 1.0 - t], d)
            })
            .collect();
        let knots = KnotVector::new(vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0], 2, 4).unwrap();
        DynCurve::from(AnyCurve::BSpline(BSpline::new(points, knots).unwrap()))
    }

    #[test]
    fn rows_of_a_spatial_curve() {
        let curve = spatial_helix_like();
        assert_eq!((curve.dimension(), curve.degree(), curve.len()), (3, 2, 4));
        assert_eq!(curve.kind(), CurveKind::BSpline);
        // Clamped: C(0) = P0 = (0, 0, 1), degrees constant.
        assert_eq!(
            curve.evaluate_row(0.0).unwrap(),
            [0.0, 0.0, 1.0, 0.5, 0.25, 0.125]
        );
        // C'(0) = p / (u_{p+1} - u_1) (P1 - P0) = 2 / 0.5 (1, 1, -1); the degrees do not move.
        assert_eq!(
            curve.derivative().evaluate_row(0.0).unwrap(),
            [4.0, 4.0, -4.0, 0.0, 0.0, 0.0]
        );
        assert_eq!(curve.control_rows()[3], [3.0, 9.0, -2.0, 0.5, 0.25, 0.125]);
        assert_eq!(curve.degree_ranges()[1].max, 0.25);
        // A point of the curve is its own nearest point; a row of 2 is refused.
        let at = curve.evaluate_row(0.75).unwrap();
        let near = curve.nearest_rows(&at[..3]).unwrap().remove(0).unwrap();
        assert!((near.parameter - 0.75).abs() < 1e-9 && near.distance < 1e-12);
        assert_eq!(
            curve.nearest_rows(&[1.0, 2.0]).unwrap_err().to_string(),
            "2 coordinates are not rows of 3 (the curve is 3-D)"
        );
        assert_eq!(
            curve.intersections(&curve).unwrap_err().to_string(),
            "the first curve is 3-D (intersections are of plane curves)"
        );
    }

    #[test]
    fn the_second_derivative_of_a_quarter_circle() {
        // The rational quadratic quarter circle: |C''| / |C'|^2 = curvature 1 at t = 0,
        // where C'(0) = 2 (w1 / w0)(P1 - P0) = (0, 2 / sqrt 2) ... checked via curvature.
        let d = Degrees::new(1.0, 0.0, 0.0).unwrap();
        let points = vec![
            ControlPoint::new([1.0, 0.0], d),
            ControlPoint::new([1.0, 1.0], d),
            ControlPoint::new([0.0, 1.0], d),
        ];
        let knots = KnotVector::new(vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0], 2, 3).unwrap();
        let w = core::f64::consts::FRAC_1_SQRT_2;
        let curve = DynCurve::from(AnyCurve::Nurbs(
            Nurbs::new(points, vec![1.0, w, 1.0], knots).unwrap(),
        ));
        assert!((curve.curvature(0.3).unwrap() - 1.0).abs() < 1e-12);
        let length = curve.arc_length(0.0..1.0, 1e-12).unwrap();
        assert!((length - core::f64::consts::FRAC_PI_2).abs() < 1e-11);
        // C'(0) = 2 w (P1 - P0) / 1 = (0, sqrt 2).
        let speed = curve.nth_derivative(1).evaluate_row(0.0).unwrap();
        assert!(speed[0].abs() < 1e-15 && (speed[1] - 2.0 * w).abs() < 1e-15);
        assert_eq!(curve.self_intersections().unwrap(), []);
        // A curve meets itself everywhere.
        assert!(matches!(
            curve.intersections(&curve),
            Err(IntersectError::Overlap { .. })
        ));
    }
}
