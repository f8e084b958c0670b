//! The constructors of the curve kinds `Bezier`, `BSpline` and `Nurbs`.

use neutrospline::{
    AnyCurve, BSpline as BSplineCurve, Bezier as BezierCurve, ControlPoint, CurveError, CurveKind,
    KnotVector, Nurbs as NurbsCurve,
};
use neutrospline_io::Shape;
use pyo3::prelude::*;
use pyo3::PyClassInitializer;

use super::{into_py, BSpline, Bezier, Curve, Nurbs, State};
use crate::errors::{invalid, invalid_at};
use crate::model::{self, Meta, PointArrays};

/// What the constructors read: the arrays, the kind's settings and the names.
struct Construction<'a, 'py> {
    positions: &'a Bound<'py, PyAny>,
    degrees: &'a Bound<'py, PyAny>,
    weights: Option<&'a Bound<'py, PyAny>>,
    degree: Option<usize>,
    knots: Option<&'a Bound<'py, PyAny>>,
    periodic: bool,
    membership: &'a str,
    meta: Meta,
}

impl<'a, 'py> Construction<'a, 'py> {
    /// The arrays and names of a Bézier curve: no weights, degree or knots.
    fn plain(
        positions: &'a Bound<'py, PyAny>,
        degrees: &'a Bound<'py, PyAny>,
        membership: &'a str,
        meta: Meta,
    ) -> Self {
        Construction {
            positions,
            degrees,
            weights: None,
            degree: None,
            knots: None,
            periodic: false,
            membership,
            meta,
        }
    }

    /// Builds the curve of `kind` and its model.
    fn build(mut self, kind: CurveKind) -> PyResult<Curve> {
        let membership = model::membership(self.membership)?;
        let arrays =
            PointArrays::read(self.positions, "positions", self.degrees, membership, false)?;
        let weights = self
            .weights
            .map(|w| {
                crate::arrays::float_array(w, "weights")?
                    .values()
                    .map(<[f64]>::to_vec)
            })
            .transpose()?;
        let knots = self
            .knots
            .map(|k| {
                crate::arrays::float_array(k, "knots")?
                    .values()
                    .map(<[f64]>::to_vec)
            })
            .transpose()?;
        let settings = Settings {
            kind,
            weights,
            degree: self.degree,
            knots,
            periodic: self.periodic,
        };
        if self.periodic {
            // Names are given per distinct point; the repeated ones carry them again.
            let extra = self.degree.unwrap_or(3);
            if let Some(names) = self.meta.point_names.as_mut() {
                let n = names.len();
                if n > 0 {
                    let repeated: Vec<Option<String>> =
                        (0..extra).map(|i| names[i % n].clone()).collect();
                    names.extend(repeated);
                }
            }
        }
        // A family of two lanes: the second lane is the same curve (positions, weights,
        // knots) with the second lane's degrees (docs/model.md, "Lanes").
        let (shape, second): (Shape, Option<Shape>) = if arrays.dimension == 2 {
            let second = arrays.second_points::<2>().map(|p| settings.curve(p));
            (
                settings.curve(arrays.points::<2>())?.into(),
                second.transpose()?.map(Into::into),
            )
        } else {
            let second = arrays.second_points::<3>().map(|p| settings.curve(p));
            (
                settings.curve(arrays.points::<3>())?.into(),
                second.transpose()?.map(Into::into),
            )
        };
        let model = model::model(shape, second, membership, self.meta)?;
        Ok(Curve {
            state: State::of_model(model).expect("a curve shape"),
        })
    }
}

/// The kind's settings of a constructor.
struct Settings {
    kind: CurveKind,
    weights: Option<Vec<f64>>,
    degree: Option<usize>,
    knots: Option<Vec<f64>>,
    /// Periodic: the points are the distinct ones and the knots the breakpoints.
    periodic: bool,
}

impl Settings {
    fn curve<const D: usize>(&self, points: Vec<ControlPoint<D>>) -> PyResult<AnyCurve<D>> {
        if self.periodic {
            return self.periodic_curve(points);
        }
        let count = points.len();
        let knots = || -> PyResult<KnotVector> {
            let degree = self.degree.unwrap_or(3);
            match &self.knots {
                Some(knots) => KnotVector::new(knots.clone(), degree, count),
                None => KnotVector::clamped_uniform(degree, count),
            }
            .map_err(|e| invalid_at("knots", e))
        };
        let curve: Result<AnyCurve<D>, CurveError> = match self.kind {
            CurveKind::Bezier => BezierCurve::new(points).map(Into::into),
            CurveKind::BSpline => BSplineCurve::new(points, knots()?).map(Into::into),
            CurveKind::Nurbs => {
                let weights = self.weights.clone().unwrap_or_default();
                NurbsCurve::new(points, weights, knots()?).map(Into::into)
            }
        };
        curve.map_err(invalid)
    }

    /// [`BSplineCurve::periodic`] or [`NurbsCurve::periodic`] over the breakpoints given, or
    /// uniform ones on [0, 1].
    fn periodic_curve<const D: usize>(
        &self,
        points: Vec<ControlPoint<D>>,
    ) -> PyResult<AnyCurve<D>> {
        let degree = self.degree.unwrap_or(3);
        let n = points.len();
        let breakpoints = self
            .knots
            .clone()
            .unwrap_or_else(|| (0..=n).map(|j| j as f64 / n.max(1) as f64).collect());
        if degree == 0 {
            return Err(invalid_at(
                "degree",
                "a periodic spline needs degree >= 1 (degree 0 has nothing to join)",
            ));
        }
        let curve: Result<AnyCurve<D>, CurveError> = match self.kind {
            CurveKind::Nurbs => {
                let weights = self.weights.clone().unwrap_or_default();
                NurbsCurve::periodic(points, weights, degree, &breakpoints).map(Into::into)
            }
            _ => BSplineCurve::periodic(points, degree, &breakpoints).map(Into::into),
        };
        curve.map_err(|e| match e {
            CurveError::Knots(k) => invalid_at("knots", k),
            other => invalid(other),
        })
    }
}

#[pymethods]
impl Bezier {
    /// A Bézier curve from `positions` (shape (n, 2) or (n, 3)) and `degrees` (shape (n, 3):
    /// truth, indeterminacy, falsity; (n, channel_count) the family's channels, such as
    /// (n, 2) truth, falsity under the intuitionistic rule; (n,) truth under the fuzzy rule)
    /// under the family `membership`. An interval-valued or bipolar family
    /// (`interval-neutrosophic`, `interval-intuitionistic`, `interval-type2`,
    /// `bipolar-neutrosophic`) takes exactly (n, channel_count) in its channel order
    /// (`channels`), such as `truth_lower, truth_upper, indeterminacy_lower, ...`.
    #[new]
    #[pyo3(signature = (positions, degrees, membership = "neutrosophic", *, name = None, description = None, point_names = None))]
    fn new(
        positions: &Bound<'_, PyAny>,
        degrees: &Bound<'_, PyAny>,
        membership: &str,
        name: Option<String>,
        description: Option<String>,
        point_names: Option<Vec<Option<String>>>,
    ) -> PyResult<PyClassInitializer<Self>> {
        let curve = Construction::plain(
            positions,
            degrees,
            membership,
            Meta::new(name, description, point_names),
        )
        .build(CurveKind::Bezier)?;
        Ok(curve.initializer().add_subclass(Bezier))
    }

    /// A Bézier curve from the `bezier` package's node layout: `nodes` of shape
    /// (dimension, n), one column per control point; `degrees` as for `Bezier(...)`.
    ///
    /// >>> import neutrospline as ns
    /// >>> curve = ns.Bezier.from_nodes([[0.0, 0.5, 1.0], [0.0, 1.0, 0.0]], [[1, 0, 0]] * 3)
    /// >>> curve(0.5)[:2].tolist()
    /// [0.5, 0.5]
    #[staticmethod]
    #[pyo3(signature = (nodes, degrees, membership = "neutrosophic"))]
    fn from_nodes(
        py: Python<'_>,
        nodes: &Bound<'_, PyAny>,
        degrees: &Bound<'_, PyAny>,
        membership: &str,
    ) -> PyResult<Py<PyAny>> {
        let nodes = crate::arrays::float_array(nodes, "nodes")?;
        let (dimension, count) = match *nodes.shape() {
            [d, n] => (d, n),
            _ => {
                return Err(invalid_at(
                    "nodes",
                    format!(
                        "expected an array of shape (dimension, n) (one column per control \
                         point), got shape {:?}",
                        nodes.shape()
                    ),
                ))
            }
        };
        // Row-major (dimension, n) values read column by column: the (n, dimension) rows.
        let values = nodes.values()?;
        let rows: Vec<f64> = (0..count)
            .flat_map(|k| (0..dimension).map(move |c| values[c * count + k]))
            .collect();
        let positions = crate::arrays::new_array(py, rows, &[count, dimension])?;
        let curve = Construction::plain(positions.as_any(), degrees, membership, Meta::default())
            .build(CurveKind::Bezier)?;
        into_py(py, curve.state)
    }
}

#[pymethods]
impl BSpline {
    /// A B-spline curve of `degree` from `positions` and `degrees` (as for `Bezier`), on
    /// `knots` (n + degree + 1 non-decreasing values) or clamped uniform knots on [0, 1].
    /// With `periodic=True` a closed curve: the points are its distinct control points (the
    /// first `degree` of them follow again) and `knots` its n + 1 breakpoints (default
    /// uniform on [0, 1]).
    ///
    /// >>> import neutrospline as ns
    /// >>> square = [[0, 0], [1, 0], [1, 1], [0, 1]]
    /// >>> ring = ns.BSpline(square, [[0.5, 0.2, 0.1]] * 4, degree=2, periodic=True)
    /// >>> len(ring), ring.periodic_count, ring(0.0).tolist() == ring(1.0).tolist()
    /// (6, 4, True)
    #[new]
    #[pyo3(signature = (positions, degrees, degree = 3, knots = None, membership = "neutrosophic", *, periodic = false, name = None, description = None, point_names = None))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        positions: &Bound<'_, PyAny>,
        degrees: &Bound<'_, PyAny>,
        degree: usize,
        knots: Option<&Bound<'_, PyAny>>,
        membership: &str,
        periodic: bool,
        name: Option<String>,
        description: Option<String>,
        point_names: Option<Vec<Option<String>>>,
    ) -> PyResult<PyClassInitializer<Self>> {
        let curve = Construction {
            degree: Some(degree),
            knots,
            periodic,
            ..Construction::plain(
                positions,
                degrees,
                membership,
                Meta::new(name, description, point_names),
            )
        }
        .build(CurveKind::BSpline)?;
        Ok(curve.initializer().add_subclass(BSpline))
    }
}

#[pymethods]
impl Nurbs {
    /// A NURBS curve of `degree` from `positions`, `degrees` (as for `Bezier`) and one
    /// positive `weights` value per control point, on `knots` or clamped uniform knots;
    /// `periodic=True` as for `BSpline` (one weight per distinct point).
    #[new]
    #[pyo3(signature = (positions, degrees, weights, degree = 3, knots = None, membership = "neutrosophic", *, periodic = false, name = None, description = None, point_names = None))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        positions: &Bound<'_, PyAny>,
        degrees: &Bound<'_, PyAny>,
        weights: &Bound<'_, PyAny>,
        degree: usize,
        knots: Option<&Bound<'_, PyAny>>,
        membership: &str,
        periodic: bool,
        name: Option<String>,
        description: Option<String>,
        point_names: Option<Vec<Option<String>>>,
    ) -> PyResult<PyClassInitializer<Self>> {
        let curve = Construction {
            weights: Some(weights),
            degree: Some(degree),
            knots,
            periodic,
            ..Construction::plain(
                positions,
                degrees,
                membership,
                Meta::new(name, description, point_names),
            )
        }
        .build(CurveKind::Nurbs)?;
        Ok(curve.initializer().add_subclass(Nurbs))
    }
}
