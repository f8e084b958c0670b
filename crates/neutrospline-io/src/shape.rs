//! [`Shape`]: the core's curve (planar or spatial) or surface that a model file describes.

use core::ops::Range;

use neutrospline::{
    on_dimension, AnyCurve, ControlPoint, ControlPolygon, DynCurve, Interval, KnotVector, Surface,
};

use crate::Kind;

/// A curve or surface of any kind, as a model file holds it.
#[derive(Debug, Clone, PartialEq)]
pub enum Shape {
    /// A curve in the plane or in space.
    Curve(DynCurve),
    /// A tensor-product surface in space.
    Surface(Surface),
}

impl From<AnyCurve<2>> for Shape {
    fn from(curve: AnyCurve<2>) -> Shape {
        Shape::Curve(curve.into())
    }
}

impl From<AnyCurve<3>> for Shape {
    fn from(curve: AnyCurve<3>) -> Shape {
        Shape::Curve(curve.into())
    }
}

impl From<DynCurve> for Shape {
    fn from(curve: DynCurve) -> Shape {
        Shape::Curve(curve)
    }
}

impl From<Surface> for Shape {
    fn from(surface: Surface) -> Shape {
        Shape::Surface(surface)
    }
}

/// One control point in any dimension: position (2 or 3 coordinates), degrees and weight.
pub(crate) struct PointData {
    pub(crate) position: Vec<f64>,
    pub(crate) degrees: neutrospline::Degrees,
    pub(crate) weight: Option<f64>,
}

fn point_data<const D: usize>(
    points: Vec<ControlPoint<D>>,
    weights: Option<&[f64]>,
) -> Vec<PointData> {
    points
        .into_iter()
        .enumerate()
        .map(|(i, p)| PointData {
            position: p.position.to_vec(),
            degrees: p.degrees,
            weight: weights.and_then(|w| w.get(i).copied()),
        })
        .collect()
}

impl Shape {
    /// The kind, as named in files.
    pub fn kind(&self) -> Kind {
        match self {
            Shape::Curve(c) => Kind::Curve(c.kind()),
            Shape::Surface(s) => Kind::Surface(s.kind()),
        }
    }

    /// 2 or 3.
    pub fn dimension(&self) -> usize {
        match self {
            Shape::Curve(c) => c.dimension(),
            Shape::Surface(_) => 3,
        }
    }

    /// Whether this is a surface.
    pub fn is_surface(&self) -> bool {
        matches!(self, Shape::Surface(_))
    }

    /// The curve, if this is one.
    pub fn curve(&self) -> Option<&DynCurve> {
        match self {
            Shape::Curve(c) => Some(c),
            Shape::Surface(_) => None,
        }
    }

    /// Number of control points (never 0; surfaces rows x cols).
    pub fn control_count(&self) -> usize {
        match self {
            Shape::Curve(c) => c.len(),
            Shape::Surface(s) => s.rows() * s.cols(),
        }
    }

    /// The polynomial degree of a curve.
    pub fn curve_degree(&self) -> Option<usize> {
        self.curve().map(DynCurve::degree)
    }

    /// The knot vector of a B-spline or NURBS curve.
    pub fn curve_knots(&self) -> Option<&KnotVector> {
        self.curve().and_then(DynCurve::knots)
    }

    /// The domain of a curve.
    pub fn curve_domain(&self) -> Option<Range<f64>> {
        self.curve().map(DynCurve::domain)
    }

    /// The weights of a NURBS curve or surface (surfaces row by row).
    pub fn weights(&self) -> Option<&[f64]> {
        match self {
            Shape::Curve(c) => c.weights(),
            Shape::Surface(s) => s.weights(),
        }
    }

    /// Range (min, max) of truth, indeterminacy and falsity over the control points.
    pub fn degree_ranges(&self) -> [Interval; 3] {
        match self {
            Shape::Curve(c) => c.degree_ranges(),
            Shape::Surface(s) => {
                let b = s.control_bounding_box();
                [b.truth, b.indeterminacy, b.falsity]
            }
        }
    }

    /// The degrees of every control point, in order (surfaces row by row).
    pub fn control_degrees(&self) -> Vec<neutrospline::Degrees> {
        match self {
            Shape::Curve(c) => c.control_degrees(),
            Shape::Surface(s) => s.control_points().iter().map(|p| p.degrees).collect(),
        }
    }

    /// Every control point with its weight, for the writers.
    /// Whether `other` has the same kind, positions, weights, degree, knots and grid: the
    /// same geometry, whatever its degrees (the lanes of a wide family, see
    /// `Family::lanes`).
    pub fn same_geometry(&self, other: &Shape) -> bool {
        let same_points = || {
            let (a, b) = (self.point_data(), other.point_data());
            a.len() == b.len()
                && a.iter()
                    .zip(&b)
                    .all(|(p, q)| p.position == q.position && p.weight == q.weight)
        };
        let same_knots = match (self, other) {
            (Shape::Curve(_), Shape::Curve(_)) => {
                self.curve_degree() == other.curve_degree()
                    && self.curve_knots() == other.curve_knots()
            }
            (Shape::Surface(a), Shape::Surface(b)) => {
                (a.rows(), a.cols(), a.degree_u(), a.degree_v())
                    == (b.rows(), b.cols(), b.degree_u(), b.degree_v())
                    && a.knots_u() == b.knots_u()
                    && a.knots_v() == b.knots_v()
            }
            _ => false,
        };
        self.kind() == other.kind()
            && self.dimension() == other.dimension()
            && same_knots
            && same_points()
    }

    pub(crate) fn point_data(&self) -> Vec<PointData> {
        match self {
            Shape::Curve(c) => on_dimension!(c, c => point_data(c.control_points(), c.weights())),
            Shape::Surface(s) => point_data(s.control_points(), s.weights()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use neutrospline::{BSpline, CurveKind, Degrees, SurfaceKind};

    #[test]
    fn shape_accessors() {
        let d = Degrees::new(0.5, 0.25, 0.0).unwrap();
        let points = (0..5)
            .map(|i| ControlPoint::new([f64::from(i), 0.0], d))
            .collect();
        let knots = KnotVector::new((0..8).map(f64::from).collect(), 2, 5).unwrap();
        let shape = Shape::from(AnyCurve::BSpline(BSpline::new(points, knots).unwrap()));
        assert_eq!(shape.kind(), Kind::Curve(CurveKind::BSpline));
        assert_eq!(shape.dimension(), 2);
        assert_eq!(shape.control_count(), 5);
        assert_eq!(shape.curve_degree(), Some(2));
        assert_eq!(shape.curve_domain(), Some(2.0..5.0));
        assert_eq!(shape.weights(), None);
        assert_eq!(shape.degree_ranges()[0].max, 0.5);
        let surface = Surface::bezier(1, 1, vec![ControlPoint::new([0.0; 3], d)]).unwrap();
        let shape = Shape::from(surface);
        assert_eq!(shape.kind(), Kind::Surface(SurfaceKind::Bezier));
        assert!(shape.is_surface());
        assert_eq!(shape.curve_degree(), None);
    }
}
