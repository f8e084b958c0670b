//! The curve classes: `Curve` (extending the base `Shape`, which holds the model and the
//! methods shared with surfaces) holding the evaluator and every curve method, and the kinds
//! `Bezier`, `BSpline` and `Nurbs` that add only their constructors. A curve is immutable;
//! operations return new curves (of the class the result is: a Bézier curve with a knot
//! inserted is a B-spline).
//!
//! The constructors are in `construction`, evaluation in `evaluation`, the derived curves
//! (split, elevate, insert_knot) in `derived`.

use std::sync::Arc;

use neutrospline::{
    map_dimension, on_dimension, AnyCurve, BatchOptions, BatchParams, Bounded, ControlPolygon,
    CurveBatch, CurveDerivative, CurveKind, Dimensional, DynCurve, Elevate, Evaluate, Family,
    Split,
};
use neutrospline_io::Model;
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use pyo3::PyClassInitializer;

use crate::arrays::{readonly_array, vector, Output, Params};
use crate::errors::{invalid, invalid_at};
use crate::model;
use crate::shape::BaseShape;

mod construction;
mod derived;
use derived::bezier_as_bspline;
mod evaluation;

/// The core curves of a model's lanes (one, or two for an interval-valued or bipolar family),
/// of one dimension.
type LaneCurves<'a> = Dimensional<Vec<&'a AnyCurve<2>>, Vec<&'a AnyCurve<3>>>;

/// A model curve with its prepared batch evaluator.
#[derive(Clone, Debug)]
pub struct Prepared<const D: usize> {
    pub curve: AnyCurve<D>,
    batch: CurveBatch<D>,
}

impl<const D: usize> Prepared<D> {
    fn new(curve: AnyCurve<D>) -> Self {
        let batch = CurveBatch::new(&curve);
        Prepared { curve, batch }
    }
}

/// What a Python curve is.
#[derive(Clone, Debug)]
pub enum State {
    /// A curve of a model: control points with degrees, saved and drawn as a model.
    Model {
        model: Arc<Model>,
        curve: Dimensional<Prepared<2>, Prepared<3>>,
        /// The second lane of a family of two lanes (docs/model.md, "Lanes"): the same
        /// geometry with the second lane's degrees.
        second: Option<Box<Dimensional<Prepared<2>, Prepared<3>>>>,
    },
    /// The derivative of order `order` of the curve of `base`: evaluable and differentiable;
    /// its values are rates of change, not degrees.
    Derivative {
        base: Arc<Model>,
        order: usize,
        derivative: Dimensional<CurveDerivative<2>, CurveDerivative<3>>,
        /// The derivative of the second lane of a family of two lanes.
        second: Option<Dimensional<CurveDerivative<2>, CurveDerivative<3>>>,
    },
}

impl State {
    /// The state of a curve model (`None` for a surface).
    pub fn of_model(model: Model) -> Option<State> {
        let curve = map_dimension!(model.shape().curve()?, c => Prepared::new(c.clone()));
        let second = model
            .lanes()
            .get(1)
            .and_then(|lane| lane.curve())
            .map(|lane| Box::new(map_dimension!(lane, c => Prepared::new(c.clone()))));
        Some(State::Model {
            model: Arc::new(model),
            curve,
            second,
        })
    }

    /// The derivative of order `order` (>= 1) of the curve of `base` (of each lane).
    fn derivative_of(base: Arc<Model>, order: usize) -> Option<State> {
        let derivative = base.shape().curve()?.nth_derivative(order);
        let second = base
            .lanes()
            .get(1)
            .and_then(|lane| lane.curve())
            .map(|lane| lane.nth_derivative(order));
        Some(State::Derivative {
            base,
            order,
            derivative,
            second,
        })
    }

    /// The membership family of the model.
    fn membership(&self) -> Family {
        self.base().membership()
    }

    /// The columns of an evaluation: the dimension and the degree columns (3, or the channel
    /// count of a family of two lanes).
    fn columns(&self) -> usize {
        self.dimension() + model::degree_columns(self.membership()).len()
    }

    /// Whether the model rides in two lanes.
    fn wide(&self) -> bool {
        model::is_wide(self.membership())
    }

    fn base(&self) -> &Arc<Model> {
        match self {
            State::Model { model, .. } => model,
            State::Derivative { base, .. } => base,
        }
    }

    fn kind(&self) -> CurveKind {
        self.base()
            .shape()
            .curve()
            .map_or(CurveKind::Bezier, DynCurve::kind)
    }

    fn dimension(&self) -> usize {
        self.base().shape().dimension()
    }

    fn order(&self) -> usize {
        match self {
            State::Model { .. } => 0,
            State::Derivative { order, .. } => *order,
        }
    }
}

/// A neutrosophic curve: the base class of `Bezier`, `BSpline` and `Nurbs`.
///
/// Evaluating gives one row per parameter with the columns `x, y[, z], truth,
/// indeterminacy, falsity` (the command line's `eval` columns); a curve of an interval-valued
/// or bipolar family gives `x, y[, z]` and its `channels` (the two lanes evaluated and joined,
/// docs/model.md "Lanes").
#[pyclass(extends = BaseShape, subclass, frozen, module = "neutrospline")]
pub struct Curve {
    pub(crate) state: State,
}

/// A Bézier curve: `C(t) = sum_i B_i^n(t) P_i` over t in [0, 1], the degrees blended as extra
/// coordinates.
///
/// >>> import neutrospline as ns
/// >>> curve = ns.Bezier([[1, 3], [3, 6], [6, 5], [4, 1]],
/// ...                   [[0.3, 0.6, 0.1], [0.8, 0.1, 0.2], [0.5, 0.4, 0.3], [0.3, 0.4, 0.6]])
/// >>> curve(0.5).round(12).tolist()
/// [4.0, 4.625, 0.5625, 0.3125, 0.275]
#[pyclass(extends = Curve, frozen, module = "neutrospline")]
pub struct Bezier;

/// A B-spline curve: `C(t) = sum_i N_{i,p}(t) P_i` on a knot vector (clamped uniform unless
/// `knots` are given).
///
/// >>> import neutrospline as ns
/// >>> curve = ns.BSpline([[0, 0], [1, 2], [3, 2], [4, 0]], [[0.2, 0.2, 0.2]] * 4, degree=2)
/// >>> curve.knots.tolist()
/// [0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0]
/// >>> curve(0.5).tolist()
/// [2.0, 2.0, 0.2, 0.2, 0.2]
#[pyclass(extends = Curve, frozen, module = "neutrospline")]
pub struct BSpline;

/// A NURBS curve: `C(t) = sum_i N_{i,p}(t) w_i P_i / sum_i N_{i,p}(t) w_i`, positive weights.
///
/// >>> import neutrospline as ns
/// >>> quarter = ns.Nurbs([[1, 0], [1, 1], [0, 1]], [[1, 0, 0]] * 3, [1, 2 ** -0.5, 1], degree=2)
/// >>> x, y = quarter(0.5)[:2]
/// >>> round(float(x * x + y * y), 15)
/// 1.0
#[pyclass(extends = Curve, frozen, module = "neutrospline")]
pub struct Nurbs;

/// The Python object of the right class for `state`.
pub fn into_py(py: Python<'_>, state: State) -> PyResult<Py<PyAny>> {
    let kind = state.kind();
    let base = Curve { state }.initializer();
    Ok(match kind {
        CurveKind::Bezier => Py::new(py, base.add_subclass(Bezier))?.into_any(),
        CurveKind::BSpline => Py::new(py, base.add_subclass(BSpline))?.into_any(),
        CurveKind::Nurbs => Py::new(py, base.add_subclass(Nurbs))?.into_any(),
    })
}

/// The Python object of a curve model.
pub fn model_into_py(py: Python<'_>, model: Model) -> PyResult<Py<PyAny>> {
    match State::of_model(model) {
        Some(state) => into_py(py, state),
        None => Err(invalid("a surface is not a curve")),
    }
}

impl Curve {
    /// The class chain of this curve: the base `Shape` (the model and the derivative order)
    /// and the curve.
    fn initializer(self) -> PyClassInitializer<Curve> {
        let base = BaseShape::new(self.state.base().clone(), self.state.order());
        PyClassInitializer::from(base).add_subclass(self)
    }

    /// The model's curve; an error for a derivative (see `Curve::model`).
    fn curve(&self) -> PyResult<&DynCurve> {
        let (model, _) = self.model()?;
        model
            .shape()
            .curve()
            .ok_or_else(|| invalid("a surface is not a curve"))
    }

    /// The model's lanes as core curves of one dimension: the curve, and the second lane of a
    /// family of two lanes (docs/model.md, "Lanes"); an error for a derivative.
    fn lane_curves(&self) -> PyResult<LaneCurves<'_>> {
        let (_, curve) = self.model()?;
        let second = match &self.state {
            State::Model { second, .. } => second.as_deref(),
            State::Derivative { .. } => None,
        };
        Ok(match (curve, second) {
            (Dimensional::Planar(a), None) => Dimensional::Planar(vec![&a.curve]),
            (Dimensional::Spatial(a), None) => Dimensional::Spatial(vec![&a.curve]),
            (Dimensional::Planar(a), Some(Dimensional::Planar(b))) => {
                Dimensional::Planar(vec![&a.curve, &b.curve])
            }
            (Dimensional::Spatial(a), Some(Dimensional::Spatial(b))) => {
                Dimensional::Spatial(vec![&a.curve, &b.curve])
            }
            _ => return Err(invalid("the lanes of the model differ in dimension")),
        })
    }

    /// The model and its curve; an error for a derivative (see `BaseShape::model`).
    fn model(&self) -> PyResult<(&Model, &Dimensional<Prepared<2>, Prepared<3>>)> {
        match &self.state {
            State::Model { model, curve, .. } => Ok((&**model, curve)),
            State::Derivative { order, .. } => Err(invalid(format!(
                "this is a derivative (order {order}): its values are rates of change, not \
                 degrees in [0, 1], so it is not a model; apply this to the curve itself"
            ))),
        }
    }
}

impl Curve {
    /// The points of [`Curve::sample`].
    fn sample_points(
        &self,
        py: Python<'_>,
        count: usize,
        out: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Py<PyAny>> {
        let domain = self.domain_range();
        let columns = self.state.columns();
        let output = Output::new(py, out, count, columns)?;
        let mut writer = output.write()?;
        if let (
            State::Model {
                curve,
                second: None,
                ..
            },
            Some(columns),
            true,
        ) = (&self.state, writer.columns()?, count > 0)
        {
            let options = BatchOptions::default();
            let result = on_dimension!(curve, c => py.detach(|| {
                c.batch.evaluate(BatchParams::Uniform(count), columns, &options)
            }));
            drop(writer);
            result.map_err(invalid)?;
            return output.finish(false);
        }
        drop(writer);
        let ts: Vec<f64> = (0..count)
            .map(|k| neutrospline::uniform_parameter(k, count, domain.clone()))
            .collect();
        let t = vector(py, ts);
        self.evaluate_impl(py, t.as_any(), Some(output.array().as_any()))
    }
}

#[pymethods]
impl Curve {
    /// Evaluates at `t` (a float or 0-d array, or a 1-D array or sequence of any layout and
    /// real dtype: unaligned, byte-swapped, strided, read-only, float16/32/64, integers; the
    /// answer is the one for a fresh aligned float64 copy): an array of shape (len(t),
    /// dimension + 3), columns x, y[, z], truth, indeterminacy, falsity (dimension +
    /// channel_count, x, y[, z] and the `channels`, for an interval-valued or bipolar
    /// family: each channel blended with the same basis, `sum_i B_i(t) c_i`) (a 1-D row for a
    /// scalar `t`; no rows for an empty `t`). `None`, complex, boolean and string values raise
    /// `ModelError` naming the element (`t[3] = None is not a number`). The result is
    /// Fortran-ordered (each column contiguous); with `out` (an aligned, writeable, native
    /// float64 array of that shape, any strides) it is written there and `out` is returned,
    /// without allocating; an `out` that cannot be written in place raises `ModelError`. The
    /// GIL is released while the engine runs.
    ///
    /// >>> import numpy as np, neutrospline as ns
    /// >>> curve = ns.example1()
    /// >>> curve.evaluate(np.array([0.0, 1.0])).tolist()
    /// [[1.0, 3.0, 0.3, 0.6, 0.1], [9.0, 5.0, 0.2, 0.4, 0.4]]
    #[pyo3(signature = (t, out = None))]
    fn evaluate(
        &self,
        py: Python<'_>,
        t: &Bound<'_, PyAny>,
        out: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Py<PyAny>> {
        self.evaluate_impl(py, t, out)
    }

    /// `curve(t)` is `curve.evaluate(t)`.
    #[pyo3(signature = (t, out = None))]
    fn __call__(
        &self,
        py: Python<'_>,
        t: &Bound<'_, PyAny>,
        out: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Py<PyAny>> {
        self.evaluate_impl(py, t, out)
    }

    /// Evaluates at `count` evenly spaced parameters over the domain, both ends included
    /// (`t_k = a + k (b - a) / (count - 1)`, exactly `a` and `b` at the ends); `out` as for
    /// `evaluate`. With `parameters=True` the result is the pair `(t, points)`, the
    /// parameters (shape (count,)) with the points.
    ///
    /// >>> import neutrospline as ns
    /// >>> ns.example1().sample(3)[:, 0].tolist()
    /// [1.0, 4.625, 9.0]
    /// >>> t, points = ns.example1().sample(3, parameters=True)
    /// >>> t.tolist(), points[:, 0].tolist()
    /// ([0.0, 0.5, 1.0], [1.0, 4.625, 9.0])
    #[pyo3(signature = (count, out = None, *, parameters = false))]
    fn sample(
        &self,
        py: Python<'_>,
        count: usize,
        out: Option<&Bound<'_, PyAny>>,
        parameters: bool,
    ) -> PyResult<Py<PyAny>> {
        let points = self.sample_points(py, count, out)?;
        if !parameters {
            return Ok(points);
        }
        let domain = self.domain_range();
        let ts: Vec<f64> = (0..count)
            .map(|k| neutrospline::uniform_parameter(k, count, domain.clone()))
            .collect();
        Ok(
            PyTuple::new(py, [vector(py, ts).into_any().unbind(), points])?
                .into_any()
                .unbind(),
        )
    }

    /// The derivative of order `order` (default 1) as a curve of the same class: evaluable
    /// (rates of change of the coordinates and of the degrees) and differentiable again.
    ///
    /// >>> import neutrospline as ns
    /// >>> ns.example1().derivative()(0.0).tolist()
    /// [6.0, 9.0, 1.5, -1.5, 0.0]
    #[pyo3(signature = (order = 1))]
    fn derivative(&self, py: Python<'_>, order: usize) -> PyResult<Py<PyAny>> {
        if order == 0 {
            return Err(invalid_at(
                "order",
                "0 is not a derivative order (give 1 or more)",
            ));
        }
        let state = State::derivative_of(self.state.base().clone(), self.state.order() + order)
            .ok_or_else(|| invalid("a surface has no curve derivative"))?;
        into_py(py, state)
    }

    /// Splits at `t` inside the domain: two curves of the same class, on `[a, t]` and `[t, b]`
    /// (Bézier curves re-parametrised to [0, 1]), that together trace this one.
    ///
    /// >>> import neutrospline as ns
    /// >>> left, right = ns.example1().split(0.5)
    /// >>> import numpy as np
    /// >>> np.allclose(left(1.0), ns.example1()(0.5), rtol=0, atol=1e-15), np.allclose(right(0.0), left(1.0), rtol=0, atol=1e-15)
    /// (True, True)
    fn split<'py>(&self, py: Python<'py>, t: f64) -> PyResult<Bound<'py, PyTuple>> {
        let lanes = self.lane_curves()?;
        let pieces = on_dimension!(&lanes, c => self.derive(py, c, |c| {
            let (left, right) = c.split(t).map_err(|e| invalid_at("t", e))?;
            Ok(vec![left, right])
        }))?;
        PyTuple::new(py, pieces)
    }

    /// Raises the degree `times` times (default once); the curve is unchanged.
    ///
    /// >>> import neutrospline as ns
    /// >>> ns.example1().elevate().degree
    /// 4
    #[pyo3(signature = (times = 1))]
    fn elevate(&self, py: Python<'_>, times: usize) -> PyResult<Py<PyAny>> {
        let lanes = self.lane_curves()?;
        let mut curves = on_dimension!(&lanes, c => self.derive(py, c, |c| {
            let mut elevated = c.clone();
            for _ in 0..times {
                elevated = elevated.elevate();
            }
            Ok(vec![elevated])
        }))?;
        Ok(curves.remove(0))
    }

    /// Inserts the knot `u` `times` times (default once); the curve is unchanged. A Bézier
    /// curve becomes the B-spline it is, with the knot inserted.
    ///
    /// >>> import neutrospline as ns
    /// >>> spline = ns.example1().insert_knot(0.5)
    /// >>> type(spline).__name__, spline.knots.tolist()
    /// ('BSpline', [0.0, 0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0, 1.0])
    #[pyo3(signature = (u, times = 1))]
    fn insert_knot(&self, py: Python<'_>, u: f64, times: usize) -> PyResult<Py<PyAny>> {
        let lanes = self.lane_curves()?;
        let mut curves = on_dimension!(&lanes, c => self.derive(py, c, |c| {
            let mut spline = c.clone();
            for _ in 0..times {
                spline = match spline {
                    AnyCurve::Bezier(b) => bezier_as_bspline(&b)?.insert_knot(u).map(AnyCurve::from),
                    AnyCurve::BSpline(s) => s.insert_knot(u).map(AnyCurve::from),
                    AnyCurve::Nurbs(s) => s.insert_knot(u).map(AnyCurve::from),
                }
                .map_err(|e| invalid_at("u", e))?;
            }
            Ok(vec![spline])
        }))?;
        Ok(curves.remove(0))
    }

    /// The tight bounding box of the curve: an array of shape (2, dimension + 3), the rows
    /// the minimum and the maximum of each column (x, y[, z], truth, indeterminacy, falsity;
    /// of an interval-valued or bipolar family: x, y[, z] and its `channels`, shape (2,
    /// dimension + channel_count)).
    ///
    /// >>> import neutrospline as ns
    /// >>> ns.example1().bounding_box()[:, 0].tolist()
    /// [1.0, 9.0]
    fn bounding_box<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let lanes = self.lane_curves()?;
        let bounds: Vec<[Vec<f64>; 2]> = on_dimension!(&lanes, c => {
            c.iter().map(|lane| lane.bounding_box().min_max_rows()).collect()
        });
        let (membership, dimension) = (self.state.membership(), self.state.dimension());
        let rows = model::join_bounds(membership, dimension, &bounds).concat();
        readonly_array(py, rows, &[2, self.state.columns()])
    }

    /// The length of the curve, to the relative `accuracy` (adaptive Gauss-Legendre on the
    /// pieces).
    ///
    /// >>> import neutrospline as ns
    /// >>> round(ns.example1().length(), 12)
    /// 8.78673070784
    #[pyo3(signature = (accuracy = neutrospline::DEFAULT_ACCURACY))]
    fn length(&self, accuracy: f64) -> PyResult<f64> {
        let domain = self.domain_range();
        self.curve()?.arc_length(domain, accuracy).map_err(invalid)
    }

    /// The arc length from `t0` to `t1`, to the relative `accuracy`.
    #[pyo3(signature = (t0, t1, accuracy = neutrospline::DEFAULT_ACCURACY))]
    fn arc_length(&self, t0: f64, t1: f64, accuracy: f64) -> PyResult<f64> {
        self.curve()?.arc_length(t0..t1, accuracy).map_err(invalid)
    }

    /// The parameter at arc length `s` from the start of the domain (0 <= s <= length), to
    /// `accuracy` of the length (inverse arc length: safeguarded Newton on the arc length).
    ///
    /// >>> import neutrospline as ns
    /// >>> circle = ns.load("examples/nurbs-circle.toml")
    /// >>> import math
    /// >>> circle.parameter_at_length(math.pi)
    /// 0.5
    #[pyo3(signature = (s, accuracy = neutrospline::DEFAULT_ACCURACY))]
    fn parameter_at_length(&self, s: f64, accuracy: f64) -> PyResult<f64> {
        let t = self
            .curve()?
            .parameter_at_length(s, accuracy)
            .map_err(invalid)?;
        Ok(t)
    }

    /// The parameters of `count` points evenly spaced along the curve by arc length (the
    /// parameters at arc lengths k L / (count - 1), ends exact), as a 1-D array: `eval
    /// --arc-length-samples`'s `t` column. `curve(curve.arc_length_parameters(n))` gives the
    /// points.
    ///
    /// >>> import neutrospline as ns
    /// >>> ns.load("examples/nurbs-circle.toml").arc_length_parameters(5).tolist()
    /// [0.0, 0.25, 0.5, 0.75, 1.0]
    #[pyo3(signature = (count, accuracy = neutrospline::DEFAULT_ACCURACY))]
    fn arc_length_parameters<'py>(
        &self,
        py: Python<'py>,
        count: usize,
        accuracy: f64,
    ) -> PyResult<Bound<'py, PyAny>> {
        let curve = self.curve()?;
        let ts = py
            .detach(|| curve.arc_length_parameters(count, accuracy))
            .map_err(invalid)?;
        let n = ts.len();
        readonly_array(py, ts, &[n])
    }

    /// The curvature at `t` (a float or a 1-D array): `|C' x C''| / |C'|^3` in the plane
    /// (signed: positive turning left), its magnitude in space; NaN where the curve stops
    /// (`C' = 0`).
    ///
    /// >>> import neutrospline as ns
    /// >>> circle = ns.load("examples/nurbs-circle.toml")
    /// >>> round(float(circle.curvature(0.3)), 12)
    /// 1.0
    fn curvature(&self, py: Python<'_>, t: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        let curve = self.curve()?;
        let params = Params::read(t, "t")?;
        let ts = params.values()?;
        let mut values = Vec::with_capacity(ts.len());
        for (k, &t) in ts.iter().enumerate() {
            let value = match curve.curvature(t) {
                Ok(kappa) => kappa,
                Err(neutrospline::GeometryError::Stationary { .. }) => f64::NAN,
                Err(e) => return Err(invalid_at(format!("t[{k}]"), e)),
            };
            values.push(value);
        }
        match params {
            Params::Scalar(_) => Ok(values[0].into_pyobject(py)?.into_any().unbind()),
            Params::Array(_) => Ok(vector(py, values).into_any().unbind()),
        }
    }

    /// The nearest points of the curve to query `points` (shape (m, dimension), or one point
    /// of shape (dimension,)): the global minimum of the distance, ends included, ties to the
    /// smaller parameter (as `neutrospline query`). Returns `(t, distance, rows)`: the
    /// parameters (m,), the distances (m,) and the curve's rows there (m, dimension + 3);
    /// floats and one row for a single point.
    ///
    /// >>> import neutrospline as ns
    /// >>> t, distance, row = ns.example1().nearest([4.625, 4.0])
    /// >>> round(t, 9), distance < 1e-12
    /// (0.5, True)
    fn nearest<'py>(
        &self,
        py: Python<'py>,
        points: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyTuple>> {
        let curve = self.curve()?;
        let dimension = self.state.dimension();
        let array = crate::arrays::float_array(points, "points")?;
        let single = array.ndim() == 1;
        let shape = array.shape().to_vec();
        if shape.last() != Some(&dimension) || array.ndim() > 2 || array.ndim() == 0 {
            return Err(invalid_at(
                "points",
                format!(
                    "expected an array of shape (m, {dimension}) or ({dimension},), got shape \
                     {shape:?}"
                ),
            ));
        }
        let flat = array.values()?;
        let found = py
            .detach(|| curve.nearest_rows(flat))
            .map_err(|e| invalid_at("points", e))?;
        let columns = self.state.columns();
        let mut t = Vec::with_capacity(found.len());
        let mut distance = Vec::with_capacity(found.len());
        let mut rows = Vec::with_capacity(found.len() * columns);
        for (k, result) in found.into_iter().enumerate() {
            let n = result.map_err(|e| invalid_at(format!("points[{k}]"), e))?;
            t.push(n.parameter);
            distance.push(n.distance);
            rows.extend(n.point.row());
        }
        if self.state.wide() {
            // The rows of both lanes at the nearest parameters, joined into the channels.
            rows = py
                .detach(|| self.rows_at(&t))
                .map_err(|e| invalid_at("points", e))?;
        }
        if single {
            let row = vector(py, rows).into_any();
            return PyTuple::new(
                py,
                [
                    t[0].into_pyobject(py)?.into_any(),
                    distance[0].into_pyobject(py)?.into_any(),
                    row,
                ],
            );
        }
        let m = t.len();
        PyTuple::new(
            py,
            [
                vector(py, t).into_any(),
                vector(py, distance).into_any(),
                crate::arrays::new_array(py, rows, &[m, columns])?,
            ],
        )
    }

    /// The intersections of this plane curve with `other` (another plane curve; omitted: the
    /// curve's self-intersections), as `neutrospline intersect`: an array of shape (k, 10),
    /// columns `t_a, t_b, x, y, truth_a, indeterminacy_a, falsity_a, truth_b,
    /// indeterminacy_b, falsity_b` (a curve of an interval-valued or bipolar family gives its
    /// `channels` at its parameter instead of the three degrees: shape (k, 4 + its degree
    /// columns + the other's)), ordered by `t_a`, one row per contact; curves that
    /// overlap raise `ModelError`. With `contacts=True`, the pair `(array, contacts)`, where
    /// `contacts[k]` is how the curves meet at row k, the `contact` column of `intersect`:
    /// `"crossing"` (at an angle), `"tangent"` (the tangents agree: touching, osculating or
    /// crossing tangentially) or `"end"` (an end of either curve).
    ///
    /// >>> import neutrospline as ns
    /// >>> line = ns.Bezier([[-2, 0], [2, 0]], [[1, 0, 0], [0, 0, 1]])
    /// >>> circle = ns.load("examples/nurbs-circle.toml")
    /// >>> line.intersections(circle)[:, :4].round(12).tolist()
    /// [[0.25, 0.5, -1.0, 0.0], [0.75, 0.0, 1.0, 0.0]]
    /// >>> tangent = ns.Bezier([[-2, 1], [2, 1]], [[1, 0, 0], [0, 0, 1]])
    /// >>> rows, contacts = tangent.intersections(circle, contacts=True)
    /// >>> rows[:, :4].round(12).tolist(), contacts
    /// ([[0.5, 0.25, 0.0, 1.0]], ['tangent'])
    #[pyo3(signature = (other = None, *, contacts = false))]
    fn intersections<'py>(
        &self,
        py: Python<'py>,
        other: Option<&Bound<'py, Curve>>,
        contacts: bool,
    ) -> PyResult<Bound<'py, PyAny>> {
        fn planar<'a>(curve: &'a Curve, what: &str) -> PyResult<&'a DynCurve> {
            let found = curve.curve()?;
            match found.planar() {
                Some(_) => Ok(found),
                None => Err(invalid_at(
                    what,
                    "intersections are of plane curves (this one is 3-D)",
                )),
            }
        }
        let a = planar(self, "self")?;
        let found = match other {
            Some(other) => {
                let b = planar(other.get(), "other")?;
                py.detach(|| a.intersections(b))
            }
            None => py.detach(|| a.self_intersections()),
        }
        .map_err(invalid)?;
        let b_curve = other.map_or(self, |o| o.get());
        let (width_a, width_b) = (self.state.columns() - 2, b_curve.state.columns() - 2);
        let columns = 4 + width_a + width_b;
        let mut rows = Vec::with_capacity(found.len() * columns);
        if self.state.wide() || b_curve.state.wide() {
            // Each curve's degree columns (its channels, for two lanes) at its parameter.
            let ta: Vec<f64> = found.iter().map(|hit| hit.parameter_a).collect();
            let tb: Vec<f64> = found.iter().map(|hit| hit.parameter_b).collect();
            let a_rows = py.detach(|| self.rows_at(&ta)).map_err(invalid)?;
            let b_rows = py.detach(|| b_curve.rows_at(&tb)).map_err(invalid)?;
            for (k, hit) in found.iter().enumerate() {
                rows.extend_from_slice(&[hit.parameter_a, hit.parameter_b]);
                rows.extend_from_slice(&hit.point_a.position);
                rows.extend_from_slice(&a_rows[k * (width_a + 2) + 2..(k + 1) * (width_a + 2)]);
                rows.extend_from_slice(&b_rows[k * (width_b + 2) + 2..(k + 1) * (width_b + 2)]);
            }
        } else {
            for hit in &found {
                rows.extend_from_slice(&[hit.parameter_a, hit.parameter_b]);
                rows.extend_from_slice(&hit.point_a.position);
                rows.extend_from_slice(&hit.point_a.degrees.to_array());
                rows.extend_from_slice(&hit.point_b.degrees.to_array());
            }
        }
        let array = crate::arrays::new_array(py, rows, &[found.len(), columns])?;
        if !contacts {
            return Ok(array);
        }
        let names: Vec<&str> = found.iter().map(|hit| hit.contact.name()).collect();
        Ok((array, names).into_pyobject(py)?.into_any())
    }

    /// The parameter domain `(a, b)`.
    #[getter]
    fn domain(&self) -> (f64, f64) {
        let d = self.domain_range();
        (d.start, d.end)
    }

    /// `"bezier"`, `"bspline"` or `"nurbs"`.
    #[getter]
    fn kind(&self) -> &'static str {
        self.state.kind().name()
    }

    /// The polynomial degree (of the derivative, for a derivative).
    #[getter]
    fn degree(&self) -> usize {
        match &self.state {
            State::Model { curve, .. } => on_dimension!(curve, c => c.curve.degree()),
            State::Derivative { derivative, .. } => on_dimension!(derivative, d => d.degree()),
        }
    }

    /// 2 or 3.
    #[getter]
    fn dimension(&self) -> usize {
        self.state.dimension()
    }

    /// The derivative order: 0 for a curve, k for its k-th derivative.
    #[getter]
    fn order(&self) -> usize {
        self.state.order()
    }

    /// The control points' names (None for an unnamed one).
    #[getter]
    fn point_names(&self) -> PyResult<Vec<Option<String>>> {
        let (model, curve) = self.model()?;
        let names = model.point_names();
        let count = on_dimension!(curve, c => c.curve.len());
        Ok(if names.is_empty() {
            vec![None; count]
        } else {
            names.to_vec()
        })
    }

    /// The control points' positions, shape (n, dimension), read-only (of a polynomial
    /// derivative: its control values).
    #[getter]
    fn positions<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let (positions, _, n, d) = self.control_rows()?;
        readonly_array(py, positions, &[n, d])
    }

    /// The control points' membership degrees, shape (n, 3): truth, indeterminacy, falsity
    /// (of an interval-valued or bipolar family: shape (n, channel_count), its `channels`),
    /// read-only (of a polynomial derivative: their rates of change). Not the polynomial
    /// `degree`.
    ///
    /// >>> import neutrospline as ns
    /// >>> ns.example1().membership_degrees[0].tolist()
    /// [0.3, 0.6, 0.1]
    #[getter]
    fn membership_degrees<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let (_, degrees, n, _) = self.control_rows()?;
        let width = self.state.columns() - self.state.dimension();
        readonly_array(py, degrees, &[n, width])
    }

    /// The NURBS weights, shape (n,), read-only; None for other kinds.
    #[getter]
    fn weights<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyAny>>> {
        let weights = match &self.state {
            State::Model { curve, .. } => {
                on_dimension!(curve, c => c.curve.weights().map(<[f64]>::to_vec))
            }
            State::Derivative { .. } => None,
        };
        weights
            .map(|w| {
                let n = w.len();
                readonly_array(py, w, &[n])
            })
            .transpose()
    }

    /// The number of distinct control points of a periodic (closed) curve, whose last
    /// `degree` control points repeat its first; None for any other curve.
    #[getter]
    fn periodic_count(&self) -> Option<usize> {
        match &self.state {
            State::Model { curve, .. } => on_dimension!(curve, c => c.curve.periodic_count()),
            State::Derivative { .. } => None,
        }
    }

    /// The knot vector, read-only; None for a Bézier curve.
    #[getter]
    fn knots<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyAny>>> {
        let knots = match &self.state {
            State::Model { curve, .. } => {
                on_dimension!(curve, c => c.curve.knots().map(|k| k.knots().to_vec()))
            }
            State::Derivative { derivative, .. } => {
                on_dimension!(derivative, d => d.knots().map(|k| k.knots().to_vec()))
            }
        };
        knots
            .map(|k| {
                let n = k.len();
                readonly_array(py, k, &[n])
            })
            .transpose()
    }

    /// The number of control points.
    fn __len__(&self) -> PyResult<usize> {
        let (_, _, n, _) = self.control_rows()?;
        Ok(n)
    }

    fn __repr__(&self) -> String {
        let model = self.state.base();
        let class = class_name(self.state.kind());
        let count = model.shape().control_count();
        let mut text = format!(
            "{class}(control_points={count}, degree={}, dimension={}, membership='{}'",
            model.shape().curve_degree().unwrap_or(0),
            self.state.dimension(),
            model.membership()
        );
        if let Some(name) = model.name() {
            text.push_str(&format!(", name={name:?}"));
        }
        text.push(')');
        match self.state.order() {
            0 => text,
            k => format!("<derivative of order {k} of {text}>"),
        }
    }
}

impl Curve {
    /// Positions and degrees of the control points (of a polynomial derivative: its control
    /// values), with their count and dimension.
    fn control_rows(&self) -> PyResult<(Vec<f64>, Vec<f64>, usize, usize)> {
        let dim = self.state.dimension();
        match &self.state {
            State::Model { curve, model, .. } => Ok(on_dimension!(curve, c => {
                let points = c.curve.control_points();
                let (p, d) = model::point_rows(&points);
                let d = if self.state.wide() { model::control_degree_rows(model) } else { d };
                (p, d, points.len(), c.curve.start().map_or(0, |s| s.position.len()))
            })),
            State::Derivative {
                derivative,
                order,
                second,
                ..
            } => {
                let rational = || {
                    invalid(format!(
                        "the derivative (order {order}) of a NURBS curve is rational: it has no \
                         control points of its own (evaluate it instead)"
                    ))
                };
                // Each lane's control values as rows x, y[, z], dT, dI, dF.
                let lanes = core::iter::once(derivative)
                    .chain(second.as_ref())
                    .map(|lane| {
                        on_dimension!(lane, d => {
                            let values = d.control_values().ok_or_else(rational)?;
                            Ok(values
                                .iter()
                                .flat_map(|v| {
                                    v.position
                                        .into_iter()
                                        .chain([v.truth, v.indeterminacy, v.falsity])
                                })
                                .collect::<Vec<f64>>())
                        })
                    })
                    .collect::<PyResult<Vec<Vec<f64>>>>()?;
                let n = lanes[0].len() / (dim + 3);
                let positions = lanes[0]
                    .chunks_exact(dim + 3)
                    .flat_map(|row| row[..dim].to_vec())
                    .collect();
                let joined = model::join_rows(self.state.membership(), dim, &lanes);
                let width = self.state.columns();
                let degrees = joined
                    .chunks_exact(width)
                    .flat_map(|row| row[dim..].to_vec())
                    .collect();
                Ok((positions, degrees, n, dim))
            }
        }
    }
}

/// The Python class name of a kind.
fn class_name(kind: CurveKind) -> &'static str {
    match kind {
        CurveKind::Bezier => "Bezier",
        CurveKind::BSpline => "BSpline",
        CurveKind::Nurbs => "Nurbs",
    }
}

/// Restores a pickled curve: the model's JSON text and the derivative order.
pub fn restore(py: Python<'_>, text: &str, order: usize) -> PyResult<Py<PyAny>> {
    let model = model::from_state(text)?;
    let state = if order == 0 {
        State::of_model(model)
    } else {
        State::derivative_of(Arc::new(model), order)
    }
    .ok_or_else(|| invalid("a surface is not a curve"))?;
    into_py(py, state)
}
