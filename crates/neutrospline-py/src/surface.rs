//! The surface classes: `Surface` (extending the base `Shape`, which holds the model and the
//! methods shared with curves) holding the tensor-product surface and every surface method,
//! and the kinds `BezierSurface`, `BSplineSurface` and `NurbsSurface` that add only their
//! constructors, shaped as the curve kinds' (`Bezier`, `BSpline`, `Nurbs`). The factories
//! `Surface.bezier`, `Surface.bspline` and `Surface.nurbs` are aliases of those constructors.

use std::sync::Arc;

use neutrospline::{EvaluateSurface, KnotVector, Surface as CoreSurface, SurfaceKind};
use neutrospline_io::{Model, Shape};
use numpy::ndarray::{ArrayView, IxDyn};
use numpy::PyArrayMethods;
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use pyo3::PyClassInitializer;

use crate::arrays::{float_array, readonly_array};
use crate::errors::{invalid, invalid_at};
use crate::model::{self, Meta, PointArrays};
use crate::shape::BaseShape;

/// A neutrosophic tensor-product surface `S(u, v) = sum_i sum_j B_i(u) B_j(v) P_ij` (Bézier,
/// B-spline or NURBS) in space, the degrees blended as extra coordinates: the base class of
/// `BezierSurface`, `BSplineSurface` and `NurbsSurface`, built from grids of shape
/// (rows, cols, 3).
///
/// >>> import neutrospline as ns
/// >>> grid = [[[0, 0, 0], [1, 0, 0]], [[0, 1, 0], [1, 1, 1]]]
/// >>> degrees = [[[1, 0, 0], [1, 0, 0]], [[0, 0, 1], [0, 0, 1]]]
/// >>> patch = ns.BezierSurface(grid, degrees)
/// >>> patch.evaluate(0.5, 0.5).tolist()
/// [0.5, 0.5, 0.25, 0.5, 0.0, 0.5]
#[pyclass(extends = BaseShape, subclass, frozen, module = "neutrospline")]
pub struct Surface {
    model: Arc<Model>,
    surface: CoreSurface,
    /// The second lane of a family of two lanes (docs/model.md, "Lanes"): the same geometry
    /// with the second lane's degrees.
    second: Option<CoreSurface>,
}

/// A Bézier surface `S(u, v) = sum_i sum_j B_i^m(u) B_j^n(v) P_ij` over [0, 1] x [0, 1].
///
/// >>> import neutrospline as ns
/// >>> patch = ns.BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 0]]], [[[1, 0, 0]] * 2] * 2)
/// >>> patch(0.25, 0.5).tolist()
/// [0.25, 0.5, 0.0, 1.0, 0.0, 0.0]
#[pyclass(extends = Surface, frozen, module = "neutrospline")]
pub struct BezierSurface;

/// A B-spline surface `S(u, v) = sum_i sum_j N_{i,p}(u) N_{j,q}(v) P_ij` on the knot vectors
/// `knots_u` and `knots_v` (clamped uniform unless given).
#[pyclass(extends = Surface, frozen, module = "neutrospline")]
pub struct BSplineSurface;

/// A NURBS surface `S(u, v) = sum_ij N_{i,p}(u) N_{j,q}(v) w_ij P_ij / sum_ij N_{i,p}(u)
/// N_{j,q}(v) w_ij`, positive weights.
#[pyclass(extends = Surface, frozen, module = "neutrospline")]
pub struct NurbsSurface;

impl Surface {
    /// The surface of a surface model (`None` for a curve).
    pub fn of_model(model: Model) -> Option<Surface> {
        let second = match model.lanes().get(1) {
            Some(Shape::Surface(s)) => Some(s.clone()),
            _ => None,
        };
        match model.shape() {
            Shape::Surface(s) => Some(Surface {
                surface: s.clone(),
                second,
                model: Arc::new(model),
            }),
            _ => None,
        }
    }

    /// The lanes: the surface, and the second lane of a family of two lanes.
    fn lanes(&self) -> Vec<&CoreSurface> {
        core::iter::once(&self.surface)
            .chain(self.second.as_ref())
            .collect()
    }

    /// The number of degree columns: 3, or the channel count of a family of two lanes.
    fn degree_columns(&self) -> usize {
        model::degree_columns(self.model.membership()).len()
    }

    /// The row `x, y, z, degree columns` at `(u, v)`: the lanes evaluated and joined.
    fn row_at(&self, u: f64, v: f64) -> Result<Vec<f64>, neutrospline::EvalError> {
        let lanes = self
            .lanes()
            .into_iter()
            .map(|lane| {
                let p = lane.evaluate(u, v)?;
                let mut row = p.position.to_vec();
                row.extend_from_slice(&p.degrees.to_array());
                Ok(row)
            })
            .collect::<Result<Vec<_>, neutrospline::EvalError>>()?;
        Ok(model::join_rows(self.model.membership(), 3, &lanes))
    }

    /// The class chain of this surface: the base `Shape` (the model) and the surface.
    fn initializer(self) -> PyClassInitializer<Surface> {
        PyClassInitializer::from(BaseShape::new(self.model.clone(), 0)).add_subclass(self)
    }
}

/// The Python object of the kind's class for `surface`.
pub fn into_py(py: Python<'_>, surface: Surface) -> PyResult<Py<PyAny>> {
    let kind = surface.surface.kind();
    let base = surface.initializer();
    Ok(match kind {
        SurfaceKind::Bezier => Py::new(py, base.add_subclass(BezierSurface))?.into_any(),
        SurfaceKind::BSpline => Py::new(py, base.add_subclass(BSplineSurface))?.into_any(),
        SurfaceKind::Nurbs => Py::new(py, base.add_subclass(NurbsSurface))?.into_any(),
    })
}

/// The Python object of a surface model.
pub fn model_into_py(py: Python<'_>, model: Model) -> PyResult<Py<PyAny>> {
    let surface = Surface::of_model(model).ok_or_else(|| invalid("a curve is not a surface"))?;
    into_py(py, surface)
}

/// What the constructors read besides the grids.
struct Settings<'a, 'py> {
    kind: SurfaceKind,
    weights: Option<&'a Bound<'py, PyAny>>,
    degree: (usize, usize),
    knots: (Option<&'a Bound<'py, PyAny>>, Option<&'a Bound<'py, PyAny>>),
}

/// Reads `degree`: one number for both directions, or `(degree_u, degree_v)`.
fn degrees_uv(degree: &Bound<'_, PyAny>) -> PyResult<(usize, usize)> {
    if let Ok(p) = degree.extract::<usize>() {
        return Ok((p, p));
    }
    degree.extract::<(usize, usize)>().map_err(|_| {
        invalid_at(
            "degree",
            format!("expected a degree or a pair (degree_u, degree_v), got {degree}"),
        )
    })
}

fn knot_vector(
    knots: Option<&Bound<'_, PyAny>>,
    degree: usize,
    count: usize,
    what: &str,
) -> PyResult<KnotVector> {
    match knots {
        Some(k) => {
            let values = float_array(k, what)?.values()?.to_vec();
            KnotVector::new(values, degree, count)
        }
        None => KnotVector::clamped_uniform(degree, count),
    }
    .map_err(|e| invalid_at(what, e))
}

fn build(
    positions: &Bound<'_, PyAny>,
    degrees: &Bound<'_, PyAny>,
    membership: &str,
    settings: Settings<'_, '_>,
    meta: Meta,
) -> PyResult<Surface> {
    let membership = model::membership(membership)?;
    let arrays = PointArrays::read(positions, "positions", degrees, membership, true)?;
    let (rows, cols) = arrays
        .grid
        .ok_or_else(|| invalid_at("positions", "expected a grid of shape (rows, cols, 3)"))?;
    let surface = grid_surface(&settings, rows, cols, arrays.points::<3>())?;
    // A family of two lanes: the second lane is the same surface with the second lane's
    // degrees (docs/model.md, "Lanes").
    let second = arrays
        .second_points::<3>()
        .map(|points| grid_surface(&settings, rows, cols, points))
        .transpose()?;
    let model = model::model(surface, second.map(Shape::from), membership, meta)?;
    Ok(Surface::of_model(model).expect("a surface shape"))
}

/// The surface of the kind of `settings` through the control grid `points`.
fn grid_surface(
    settings: &Settings<'_, '_>,
    rows: usize,
    cols: usize,
    points: Vec<neutrospline::ControlPoint<3>>,
) -> PyResult<CoreSurface> {
    let surface = match settings.kind {
        SurfaceKind::Bezier => CoreSurface::bezier(rows, cols, points),
        kind => {
            let knots_u = knot_vector(settings.knots.0, settings.degree.0, rows, "knots_u")?;
            let knots_v = knot_vector(settings.knots.1, settings.degree.1, cols, "knots_v")?;
            if kind == SurfaceKind::Nurbs {
                let weights = settings
                    .weights
                    .map(|w| float_array(w, "weights"))
                    .transpose()?;
                let weights = match weights {
                    Some(w) if w.shape() == [rows, cols] => w.values()?.to_vec(),
                    Some(w) => {
                        return Err(invalid_at(
                            "weights",
                            format!(
                                "expected an array of shape ({rows}, {cols}) (one weight per \
                                 control point), got shape {:?}",
                                w.shape()
                            ),
                        ))
                    }
                    None => Vec::new(),
                };
                CoreSurface::nurbs(rows, cols, points, weights, knots_u, knots_v)
            } else {
                CoreSurface::bspline(rows, cols, points, knots_u, knots_v)
            }
        }
    }
    .map_err(invalid)?;
    Ok(surface)
}

/// `u` and `v` as flat parameter lists of one shape.
fn parameters(u: &Bound<'_, PyAny>, v: &Bound<'_, PyAny>) -> PyResult<(Vec<[f64; 2]>, Vec<usize>)> {
    let u = float_array(u, "u")?;
    let v = float_array(v, "v")?;
    if u.shape() != v.shape() {
        return Err(invalid_at(
            "v",
            format!(
                "u and v must have the same shape, got {:?} and {:?}",
                u.shape(),
                v.shape()
            ),
        ));
    }
    let shape = u.shape().to_vec();
    let params = u
        .values()?
        .iter()
        .zip(v.values()?)
        .map(|(&u, &v)| [u, v])
        .collect();
    Ok((params, shape))
}

/// The position in a flat list as an index into `shape`, for messages (`[i, j]`).
fn index_text(mut k: usize, shape: &[usize]) -> String {
    let mut index = vec![0; shape.len()];
    for (slot, &size) in index.iter_mut().zip(shape).rev() {
        *slot = k % size.max(1);
        k /= size.max(1);
    }
    let parts: Vec<String> = index.iter().map(ToString::to_string).collect();
    format!("[{}]", parts.join(", "))
}

/// Writes `values` (`shape + [columns]`, row-major) into `out` or a new array.
fn emit<'py>(
    py: Python<'py>,
    values: Vec<f64>,
    shape: &[usize],
    columns: usize,
    out: Option<&Bound<'py, PyAny>>,
) -> PyResult<Py<PyAny>> {
    let mut full = shape.to_vec();
    full.push(columns);
    let Some(out) = out else {
        return Ok(crate::arrays::new_array(py, values, &full)?.unbind());
    };
    let array = crate::arrays::checked_out(out, &full)?;
    let source = ArrayView::from_shape(IxDyn(&full), &values).map_err(invalid)?;
    array
        .try_readwrite()
        .map_err(|e| invalid_at("out", format!("cannot write into the array ({e})")))?
        .as_array_mut()
        .assign(&source);
    Ok(array.clone().into_any().unbind())
}

/// The settings of a B-spline or NURBS surface: `degree` (one number for both directions, or
/// `(degree_u, degree_v)`; 3 when omitted) and the knot vectors.
fn spline_settings<'a, 'py>(
    kind: SurfaceKind,
    weights: Option<&'a Bound<'py, PyAny>>,
    degree: Option<&Bound<'py, PyAny>>,
    knots_u: Option<&'a Bound<'py, PyAny>>,
    knots_v: Option<&'a Bound<'py, PyAny>>,
) -> PyResult<Settings<'a, 'py>> {
    Ok(Settings {
        kind,
        weights,
        degree: degree.map(degrees_uv).transpose()?.unwrap_or((3, 3)),
        knots: (knots_u, knots_v),
    })
}

/// The model's names of a constructor (surfaces have no point names).
fn names(name: Option<String>, description: Option<String>) -> Meta {
    Meta::new(name, description, None)
}

#[pymethods]
impl BezierSurface {
    /// A Bézier surface from `positions` of shape (rows, cols, 3) and `degrees` of shape
    /// (rows, cols, 3) (truth, indeterminacy, falsity; (rows, cols, channel_count) the
    /// family's channels, such as (rows, cols, 2) truth, falsity under the intuitionistic
    /// rule; (rows, cols) truth under the fuzzy rule). An interval-valued or bipolar family
    /// takes exactly (rows, cols, channel_count), in the order of its `channels`.
    #[new]
    #[pyo3(signature = (positions, degrees, membership = "neutrosophic", *, name = None, description = None))]
    fn new(
        positions: &Bound<'_, PyAny>,
        degrees: &Bound<'_, PyAny>,
        membership: &str,
        name: Option<String>,
        description: Option<String>,
    ) -> PyResult<PyClassInitializer<Self>> {
        let settings = Settings {
            kind: SurfaceKind::Bezier,
            weights: None,
            degree: (0, 0),
            knots: (None, None),
        };
        let meta = names(name, description);
        let surface = build(positions, degrees, membership, settings, meta)?;
        Ok(surface.initializer().add_subclass(BezierSurface))
    }
}

#[pymethods]
impl BSplineSurface {
    /// A B-spline surface of `degree` (one number, or `(degree_u, degree_v)`; 3 when omitted)
    /// from `positions` and `degrees` (as for `BezierSurface`), on `knots_u` and `knots_v`
    /// (clamped uniform by default).
    #[new]
    #[pyo3(signature = (positions, degrees, degree = None, knots_u = None, knots_v = None, membership = "neutrosophic", *, name = None, description = None))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        positions: &Bound<'_, PyAny>,
        degrees: &Bound<'_, PyAny>,
        degree: Option<&Bound<'_, PyAny>>,
        knots_u: Option<&Bound<'_, PyAny>>,
        knots_v: Option<&Bound<'_, PyAny>>,
        membership: &str,
        name: Option<String>,
        description: Option<String>,
    ) -> PyResult<PyClassInitializer<Self>> {
        let settings = spline_settings(SurfaceKind::BSpline, None, degree, knots_u, knots_v)?;
        let meta = names(name, description);
        let surface = build(positions, degrees, membership, settings, meta)?;
        Ok(surface.initializer().add_subclass(BSplineSurface))
    }
}

#[pymethods]
impl NurbsSurface {
    /// A NURBS surface: as `BSplineSurface`, with positive `weights` of shape (rows, cols).
    #[new]
    #[pyo3(signature = (positions, degrees, weights, degree = None, knots_u = None, knots_v = None, membership = "neutrosophic", *, name = None, description = None))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        positions: &Bound<'_, PyAny>,
        degrees: &Bound<'_, PyAny>,
        weights: &Bound<'_, PyAny>,
        degree: Option<&Bound<'_, PyAny>>,
        knots_u: Option<&Bound<'_, PyAny>>,
        knots_v: Option<&Bound<'_, PyAny>>,
        membership: &str,
        name: Option<String>,
        description: Option<String>,
    ) -> PyResult<PyClassInitializer<Self>> {
        let weights = Some(weights);
        let settings = spline_settings(SurfaceKind::Nurbs, weights, degree, knots_u, knots_v)?;
        let meta = names(name, description);
        let surface = build(positions, degrees, membership, settings, meta)?;
        Ok(surface.initializer().add_subclass(NurbsSurface))
    }
}

#[pymethods]
impl Surface {
    /// Evaluates at `(u, v)` (numbers, or arrays of one shape S, of any layout and real dtype
    /// as for `Curve.evaluate`): an array of shape S + (6,), columns x, y, z, truth,
    /// indeterminacy, falsity (S + (3 + channel_count,) for an interval-valued or bipolar
    /// family: x, y, z and its `channels`); written into `out` (an aligned, writeable, native
    /// float64 array of that shape) when given. The GIL is released while the engine runs.
    #[pyo3(signature = (u, v, out = None))]
    fn evaluate(
        &self,
        py: Python<'_>,
        u: &Bound<'_, PyAny>,
        v: &Bound<'_, PyAny>,
        out: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Py<PyAny>> {
        let (params, shape) = parameters(u, v)?;
        let columns = 3 + self.degree_columns();
        let values = py
            .detach(|| {
                let mut values = Vec::with_capacity(params.len() * columns);
                for (k, &[u, v]) in params.iter().enumerate() {
                    values.extend(self.row_at(u, v).map_err(|e| (k, e))?);
                }
                Ok(values)
            })
            .map_err(|(k, e)| invalid_at(format!("(u, v){}", index_text(k, &shape)), e))?;
        emit(py, values, &shape, columns, out)
    }

    /// `surface(u, v)` is `surface.evaluate(u, v)`.
    #[pyo3(signature = (u, v, out = None))]
    fn __call__(
        &self,
        py: Python<'_>,
        u: &Bound<'_, PyAny>,
        v: &Bound<'_, PyAny>,
        out: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Py<PyAny>> {
        self.evaluate(py, u, v, out)
    }

    /// The unit normal `S_u x S_v / |S_u x S_v|` at `(u, v)`: shape S + (3,), NaN where the
    /// surface is degenerate (the partial derivatives parallel).
    ///
    /// >>> import neutrospline as ns
    /// >>> flat = ns.BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 0]]], [[[1, 0, 0]] * 2] * 2)
    /// >>> flat.normal(0.5, 0.5).tolist()
    /// [0.0, 0.0, 1.0]
    fn normal(
        &self,
        py: Python<'_>,
        u: &Bound<'_, PyAny>,
        v: &Bound<'_, PyAny>,
    ) -> PyResult<Py<PyAny>> {
        let (params, shape) = parameters(u, v)?;
        let surface = &self.surface;
        let values = py
            .detach(|| {
                let mut values = Vec::with_capacity(params.len() * 3);
                for (k, &[u, v]) in params.iter().enumerate() {
                    let n = surface.normal(u, v).map_err(|e| (k, e))?;
                    values.extend_from_slice(&n.unwrap_or([f64::NAN; 3]));
                }
                Ok(values)
            })
            .map_err(|(k, e)| invalid_at(format!("(u, v){}", index_text(k, &shape)), e))?;
        emit(py, values, &shape, 3, None)
    }

    /// The nearest points of the surface to query `points` (shape (m, 3), or one point of
    /// shape (3,)): the global minimum, as `neutrospline query`. Returns `(uv, distance,
    /// rows)`: the parameters (m, 2), the distances (m,) and the surface's rows there (m, 6),
    /// or (m, 3 + channel_count) for an interval-valued or bipolar family; one of each for a
    /// single point.
    ///
    /// >>> import neutrospline as ns
    /// >>> flat = ns.BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 0]]], [[[1, 0, 0]] * 2] * 2)
    /// >>> uv, distance, row = flat.nearest([0.25, 0.5, 2.0])
    /// >>> uv.round(12).tolist(), round(distance, 12)
    /// ([0.25, 0.5], 2.0)
    fn nearest<'py>(
        &self,
        py: Python<'py>,
        points: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyTuple>> {
        let array = float_array(points, "points")?;
        let shape = array.shape().to_vec();
        let single = shape.len() == 1;
        if shape.last() != Some(&3) || shape.len() > 2 {
            return Err(invalid_at(
                "points",
                format!("expected an array of shape (m, 3) or (3,), got shape {shape:?}"),
            ));
        }
        let queries: Vec<[f64; 3]> = array
            .values()?
            .chunks_exact(3)
            .map(|p| [p[0], p[1], p[2]])
            .collect();
        let surface = &self.surface;
        let found = py.detach(|| surface.projector().nearest_many(&queries));
        let mut uv = Vec::with_capacity(found.len() * 2);
        let mut distance = Vec::with_capacity(found.len());
        let columns = 3 + self.degree_columns();
        let mut rows = Vec::with_capacity(found.len() * columns);
        for (k, result) in found.into_iter().enumerate() {
            let n = result.map_err(|e| invalid_at(format!("points[{k}]"), e))?;
            uv.extend_from_slice(&n.parameter);
            distance.push(n.distance);
            if self.second.is_some() {
                let [u, v] = n.parameter;
                let row = self
                    .row_at(u, v)
                    .map_err(|e| invalid_at(format!("points[{k}]"), e))?;
                rows.extend(row);
            } else {
                rows.extend_from_slice(&n.point.position);
                rows.extend_from_slice(&n.point.degrees.to_array());
            }
        }
        let m = distance.len();
        let (uv, distance, rows) = if single {
            (
                crate::arrays::new_array(py, uv, &[2])?,
                distance[0].into_pyobject(py)?.into_any(),
                crate::arrays::new_array(py, rows, &[columns])?,
            )
        } else {
            (
                crate::arrays::new_array(py, uv, &[m, 2])?,
                crate::arrays::new_array(py, distance, &[m])?,
                crate::arrays::new_array(py, rows, &[m, columns])?,
            )
        };
        PyTuple::new(py, [uv, distance, rows])
    }

    /// The parameter domains `((u0, u1), (v0, v1))`.
    #[getter]
    fn domain(&self) -> ((f64, f64), (f64, f64)) {
        let [u, v] = EvaluateSurface::domain(&self.surface);
        ((u.start, u.end), (v.start, v.end))
    }

    /// `"bezier"`, `"bspline"` or `"nurbs"`.
    #[getter]
    fn kind(&self) -> &'static str {
        self.surface.kind().name()
    }

    /// `(degree_u, degree_v)`.
    #[getter]
    fn degree(&self) -> (usize, usize) {
        (self.surface.degree_u(), self.surface.degree_v())
    }

    /// 3.
    #[getter]
    fn dimension(&self) -> usize {
        3
    }

    /// The control grid's positions, shape (rows, cols, 3), read-only.
    #[getter]
    fn positions<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let (positions, _) = model::point_rows(&self.surface.control_points());
        readonly_array(
            py,
            positions,
            &[self.surface.rows(), self.surface.cols(), 3],
        )
    }

    /// The control grid's membership degrees, shape (rows, cols, 3): truth, indeterminacy,
    /// falsity (rows, cols, channel_count) for an interval-valued or bipolar family: its
    /// `channels`), read-only. Not the polynomial `degree`.
    #[getter]
    fn membership_degrees<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let degrees = model::control_degree_rows(&self.model);
        let shape = [
            self.surface.rows(),
            self.surface.cols(),
            self.degree_columns(),
        ];
        readonly_array(py, degrees, &shape)
    }

    /// The NURBS weights, shape (rows, cols), read-only; None for other kinds.
    #[getter]
    fn weights<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyAny>>> {
        let shape = [self.surface.rows(), self.surface.cols()];
        self.surface
            .weights()
            .map(|w| readonly_array(py, w.to_vec(), &shape))
            .transpose()
    }

    /// The knots along u, read-only.
    #[getter]
    fn knots_u<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let knots = self.surface.knots_u().knots().to_vec();
        let n = knots.len();
        readonly_array(py, knots, &[n])
    }

    /// The knots along v, read-only.
    #[getter]
    fn knots_v<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let knots = self.surface.knots_v().knots().to_vec();
        let n = knots.len();
        readonly_array(py, knots, &[n])
    }

    /// A box holding the surface: the control grid's (the surface lies in its convex hull),
    /// shape (2, 6), rows minimum and maximum of x, y, z, truth, indeterminacy, falsity (of
    /// x, y, z and the `channels` for an interval-valued or bipolar family: (2, 3 +
    /// channel_count)).
    fn bounding_box<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let lanes: Vec<[Vec<f64>; 2]> = self
            .lanes()
            .iter()
            .map(|lane| lane.control_bounding_box().min_max_rows())
            .collect();
        let rows = model::join_bounds(self.model.membership(), 3, &lanes).concat();
        readonly_array(py, rows, &[2, 3 + self.degree_columns()])
    }

    fn __repr__(&self) -> String {
        let mut text = format!(
            "Surface(kind='{}', rows={}, cols={}, degree=({}, {}), membership='{}'",
            self.surface.kind().name(),
            self.surface.rows(),
            self.surface.cols(),
            self.surface.degree_u(),
            self.surface.degree_v(),
            self.model.membership()
        );
        if let Some(name) = self.model.name() {
            text.push_str(&format!(", name={name:?}"));
        }
        text.push(')');
        text
    }
}
