//! The base class `Shape` of every curve and surface: the model (and, for a curve's
//! derivative, its order) and every method that needs nothing else: the names, the membership
//! rule, saving, the figures, equality and pickling. `Curve` and `Surface` extend it with their
//! geometry; each shared method has this one body (the pattern of a base class holding the
//! shared state and behaviour, see docs/architecture.md).

use std::path::PathBuf;
use std::sync::Arc;

use neutrospline_io::{Model, Operation, TransformRequest};
use neutrospline_plot::FigureRequest;
use pyo3::exceptions::PyDeprecationWarning;
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict};

use crate::errors::invalid;
use crate::model;
use crate::options::set_from_kwargs;

/// A neutrosophic curve or surface: the base class of `Curve` and `Surface`.
///
/// It holds the model; `name`, `description`, `membership`, `save`, `to_svg`, `save_figure`,
/// the inline Jupyter figure, equality and pickling are defined here once for every kind.
///
/// >>> import neutrospline as ns
/// >>> isinstance(ns.example1(), ns.Shape)
/// True
#[pyclass(name = "Shape", subclass, frozen, module = "neutrospline")]
pub struct BaseShape {
    /// The model of the curve or surface (of a derivative: the curve it is the derivative of).
    model: Arc<Model>,
    /// The derivative order: 0 for a model, k for a curve's k-th derivative.
    order: usize,
}

impl BaseShape {
    /// The base of `model`'s shape (`order` > 0: its `order`-th derivative).
    pub fn new(model: Arc<Model>, order: usize) -> BaseShape {
        BaseShape { model, order }
    }

    /// The model, for the methods that save or draw it: a derivative's values are rates of
    /// change, not degrees, so a derivative has none.
    pub fn model(&self) -> PyResult<&Model> {
        match self.order {
            0 => Ok(&self.model),
            order => Err(invalid(format!(
                "this is a derivative (order {order}): its values are rates of change, not \
                 degrees in [0, 1], so it is not a model; apply this to the curve itself"
            ))),
        }
    }
}

#[pymethods]
impl BaseShape {
    /// The membership family: `"neutrosophic"`, `"intuitionistic"`, `"fuzzy"`,
    /// `"pythagorean"`, `"q-rung:4"`, `"interval-neutrosophic"`, `"bipolar-neutrosophic"`,
    /// ... (as `membership=` takes it).
    #[getter]
    fn membership(&self) -> String {
        self.model.membership().to_string()
    }

    /// The names of the degree columns of `evaluate`, `membership_degrees` and
    /// `bounding_box`, after the position columns: `("truth", "indeterminacy", "falsity")`
    /// for a family of one lane, the family's channels for an interval-valued or bipolar
    /// family (`["truth_lower", "truth_upper", "indeterminacy_lower", ...]`, `["truth",
    /// "indeterminacy", "falsity", "negative_truth", ...]`), as a list.
    ///
    /// >>> import neutrospline as ns
    /// >>> ns.example1().channels
    /// ['truth', 'indeterminacy', 'falsity']
    /// >>> ns.Bezier([[0, 0], [1, 1]], [[0.2, 0.4], [0.5, 0.5]], membership="interval-type2").channels
    /// ['truth_lower', 'truth_upper']
    #[getter]
    fn channels(&self) -> Vec<&'static str> {
        model::degree_columns(self.model.membership())
    }

    /// The model's name, if any.
    #[getter]
    fn name(&self) -> Option<String> {
        self.model.name().map(str::to_owned)
    }

    /// The model's description, if any.
    #[getter]
    fn description(&self) -> Option<String> {
        self.model.description().map(str::to_owned)
    }

    /// Deprecated alias of `membership_degrees` (the control points' truth, indeterminacy,
    /// falsity, not the polynomial `degree`): warns with a `DeprecationWarning` and returns
    /// the same array. It will be removed in the next release.
    #[getter]
    fn degrees<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyAny>> {
        let py = slf.py();
        PyErr::warn(
            py,
            &py.get_type::<PyDeprecationWarning>(),
            c"`degrees` is deprecated, use `membership_degrees` (the truth, indeterminacy and \
              falsity of the control points; `degree` is the polynomial degree)",
            1,
        )?;
        slf.getattr("membership_degrees")
    }

    /// Writes the model to `path`: TOML, JSON or CSV by the extension, replaced atomically;
    /// `neutrospline.load(path)` gives back an equal curve or surface.
    fn save(&self, path: PathBuf) -> PyResult<()> {
        model::save(self.model()?, &path)
    }

    /// The SVG text of the figure `view` (`all`, `controls`, `truth`, `indeterminacy`,
    /// `falsity`, `plane`, `score`, `band`), as `neutrospline plot` draws it. The other figure
    /// options are keyword arguments named as `neutrospline plot`'s flags, with its defaults
    /// and messages (`figure_options()` lists them): `width`, `height`, `title`, `caption`,
    /// `azimuth`, `elevation`, `samples`, `alpha`.
    ///
    /// >>> import neutrospline as ns
    /// >>> svg = ns.example1().to_svg("truth")
    /// >>> svg.startswith("<?xml") and "curve: truth</title>" in svg
    /// True
    #[pyo3(signature = (view = None, **options))]
    fn to_svg(
        &self,
        py: Python<'_>,
        view: Option<&Bound<'_, PyAny>>,
        options: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<String> {
        model::svg(py, self.model()?, &figure_request(view, options)?)
    }

    /// Writes the figure `view` to `path` (`.svg` or `.png`), atomically; the options as
    /// `to_svg`'s.
    #[pyo3(signature = (path, view = None, **options))]
    fn save_figure(
        &self,
        py: Python<'_>,
        path: PathBuf,
        view: Option<&Bound<'_, PyAny>>,
        options: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<()> {
        model::save_figure(py, self.model()?, &path, &figure_request(view, options)?)
    }

    /// One operation of `neutrospline transform`, with its options as keyword arguments
    /// (`elevate=2`, `insert_knot=[0.5, 0.5]`, `refine=1`, `remove_knot=0.5, tolerance=1e-6,
    /// times=2`, `split=0.3`, `subsegment="0.2:0.7"`, `reverse=True`, `to_bezier=True`,
    /// `reparametrize="0:10"`; surfaces also `direction="u"` or `"v"`;
    /// `transform_options()` lists them). Returns the new curve or surface, or a tuple of
    /// the pieces for `split` and `to_bezier`. The membership rule is kept, point names only
    /// by `reverse` and `reparametrize`, spreads by every exact operation; a knot removal
    /// that could not remove the knot as often as asked says so in a `UserWarning`.
    ///
    /// >>> import neutrospline as ns
    /// >>> spline = ns.load("examples/bspline.toml")
    /// >>> finer = spline.transform(refine=1)
    /// >>> len(finer.knots) - len(spline.knots)
    /// 4
    /// >>> back = finer.transform(remove_knot=0.1, tolerance=1e-12)
    /// >>> 0.1 in finer.knots, 0.1 in back.knots
    /// (True, False)
    /// >>> left, right = spline.transform(split=0.5)
    /// >>> right.domain
    /// (0.5, 1.0)
    #[pyo3(signature = (**options))]
    fn transform(
        &self,
        py: Python<'_>,
        options: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<Py<PyAny>> {
        let mut request = TransformRequest::default();
        set_from_kwargs(&mut request, options)?;
        let operation = request.operation().map_err(invalid)?;
        let model = self.model()?;
        let out = py
            .detach(|| neutrospline_io::transform(model, &operation, request.direction))
            .map_err(invalid)?;
        if let Some((asked, removed)) = out.removals {
            if removed < asked {
                let warning = py.get_type::<pyo3::exceptions::PyUserWarning>();
                PyErr::warn(
                    py,
                    &warning,
                    &std::ffi::CString::new(out.summary.clone())?,
                    1,
                )?;
            }
        }
        let mut shapes = out
            .models
            .into_iter()
            .map(|m| crate::functions::model_into_py(py, m))
            .collect::<PyResult<Vec<_>>>()?;
        if shapes.len() == 1 && !matches!(operation, Operation::Split(_) | Operation::ToBezier) {
            return Ok(shapes.remove(0));
        }
        Ok(pyo3::types::PyTuple::new(py, shapes)?.into_any().unbind())
    }

    /// The inline figure as SVG, shown by Jupyter: the `all` view at a notebook size,
    /// responsive (`width="100%"`), as `inline()` sets it; `None` when it asks for PNG only.
    fn _repr_svg_(&self, py: Python<'_>) -> PyResult<Option<String>> {
        crate::inline::svg(py, self.model()?)
    }

    /// The inline figure as PNG, for the programs that show no SVG (an export to PDF);
    /// `None` when `inline()` asks for SVG only.
    fn _repr_png_<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyBytes>>> {
        crate::inline::png(py, self.model()?)
    }

    /// Equal models (and derivative orders); never equal to anything else.
    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other.cast::<BaseShape>().is_ok_and(|other| {
            let other = other.get();
            self.model == other.model && self.order == other.order
        })
    }

    /// Pickling: the model as exact JSON and the derivative order.
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<(Bound<'py, PyAny>, (String, usize))> {
        let restore = py
            .import("neutrospline._neutrospline")?
            .getattr("_restore")?;
        Ok((restore, (model::to_state(&self.model), self.order)))
    }
}

/// The figure's request from `to_svg`'s or `save_figure`'s arguments: `view` (positional or by
/// name) and the plot crate's other figure options as keyword arguments (`color_by` for
/// `color-by`), with its defaults and messages.
fn figure_request(
    view: Option<&Bound<'_, PyAny>>,
    options: Option<&Bound<'_, PyDict>>,
) -> PyResult<FigureRequest> {
    let mut request = FigureRequest::default();
    if let Some(view) = view.filter(|v| !v.is_none()) {
        let kwargs = PyDict::new(view.py());
        kwargs.set_item("view", view)?;
        set_from_kwargs(&mut request, Some(&kwargs))?;
    }
    set_from_kwargs(&mut request, options)?;
    Ok(request)
}
