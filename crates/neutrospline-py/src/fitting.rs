//! `neutrospline.fit`: the command line's `fit` from Python, on arrays or a data file.

use std::path::PathBuf;

use neutrospline::fit::{
    fit_rows, DataWeights, DynFit, FitError, FitOptions, FitReport, FitRequest, SurfaceFitData,
    SurfaceFitRequest,
};
use neutrospline::options::{OptionSet, OptionValue};
use neutrospline::{Degrees, Family};
use neutrospline_io::{load_data_with, read_data_with, DataTable, Model, TableInput};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyString, PyTuple};

use crate::arrays::{float_array, new_array, vector};
use crate::curve;
use crate::errors::{invalid, invalid_at};
use crate::frame::{self, Frame};
use crate::model::PointArrays;
use crate::options;

/// Where the data comes from: arrays, or a table: a CSV data file (its errors located by
/// line) or a DataFrame read as one (its errors located by row).
enum Source {
    Arrays {
        positions: Vec<f64>,
        dimension: usize,
        degrees: Vec<Degrees>,
        /// The second lane of an interval-valued or bipolar family.
        second: Option<Vec<Degrees>>,
    },
    File(DataTable, Option<Box<Frame>>),
}

impl Source {
    fn len(&self) -> usize {
        match self {
            Source::Arrays { degrees, .. } => degrees.len(),
            Source::File(table, _) => table.len(),
        }
    }

    /// The fit of the points, with the given parameters and weights.
    fn fit(
        &self,
        parameters: Option<Vec<f64>>,
        weights: Option<Vec<f64>>,
        options: &FitOptions,
    ) -> Result<DynFit, FitError> {
        match self {
            Source::Arrays {
                positions,
                dimension,
                degrees,
                second,
            } => fit_rows(
                *dimension,
                positions,
                degrees.clone(),
                second.clone(),
                parameters,
                weights,
                options,
            ),
            Source::File(table, _) => {
                let d = table.dimension();
                let rows: Vec<f64> = table
                    .positions()
                    .iter()
                    .flat_map(|p| p[..d].to_vec())
                    .collect();
                fit_rows(
                    d,
                    &rows,
                    table.degrees().to_vec(),
                    table.second_lane().map(<[Degrees]>::to_vec),
                    parameters,
                    weights,
                    options,
                )
            }
        }
    }

    /// The message of a fitting error: located in the file, or as the core says it.
    fn message(&self, py: Python<'_>, error: &FitError) -> String {
        match self {
            Source::Arrays { .. } => error.to_string(),
            Source::File(table, None) => table.locate(error).to_string(),
            Source::File(table, Some(frame)) => frame.message(py, &table.locate(error)),
        }
    }
}

/// The report as the dictionary of `neutrospline fit --report json`, plus the fitted
/// parameters of the points. The channels are those the report lists, by name (the positions
/// and the family's channels).
fn report_dict<'py>(
    py: Python<'py>,
    report: &FitReport,
    parameters: &[f64],
) -> PyResult<Bound<'py, PyDict>> {
    let channels = |values: &[(&'static str, f64)]| -> PyResult<Bound<'py, PyDict>> {
        let dict = PyDict::new(py);
        for (name, v) in values {
            dict.set_item(*name, *v)?;
        }
        Ok(dict)
    };
    let dict = PyDict::new(py);
    dict.set_item("control_points", report.control_points)?;
    dict.set_item("degree", report.degree)?;
    dict.set_item("max_error", channels(&report.max_error)?)?;
    dict.set_item("rms_error", channels(&report.rms_error)?)?;
    dict.set_item("worst_index", report.worst_index)?;
    dict.set_item("worst_parameter", report.worst_parameter)?;
    dict.set_item("worst_distance", report.worst_distance)?;
    dict.set_item("schoenberg_whitney", report.schoenberg_whitney)?;
    dict.set_item("condition_estimate", report.condition_estimate)?;
    let at_bound = PyList::empty(py);
    for a in &report.at_bound {
        let entry = PyDict::new(py);
        entry.set_item("index", a.index)?;
        entry.set_item("channel", &a.channel)?;
        entry.set_item("bound", a.bound)?;
        at_bound.append(entry)?;
    }
    dict.set_item("at_bound", at_bound)?;
    dict.set_item("tolerance", report.tolerance)?;
    dict.set_item("tolerance_met", report.tolerance_met)?;
    dict.set_item("parameters", vector(py, parameters.to_vec()))?;
    Ok(dict)
}

/// Fits a curve to data points, as `neutrospline fit` does, and returns `(curve, report)`.
///
/// `data` is an array of positions of shape (m, 2) or (m, 3) with `degrees` of shape (m, 3)
/// (or as the membership rule allows, see `Bezier`; for the interval-valued and bipolar
/// families one column per channel, shape (m, channel count), fitted jointly under the whole
/// rule), the path of a CSV data file (columns `x, y[, z], truth, indeterminacy, falsity[,
/// parameter, weight, name]`, or the family's channels such as `truth_lower, truth_upper`,
/// errors named by line), or a pandas DataFrame with those columns (read as that file would be: names in any
/// case and order, `T`, `I`, `F` for the degrees, other columns left out; errors named by
/// row). A table's columns are read as the command line's `--columns`, `--ignore-columns` and
/// `--ignore-unknown-columns` say: `columns={"truth": "mu", "parameter": "t"}` (or
/// `"truth=mu,parameter=t"`) reads the table's column `mu` as truth and `t` as the
/// parameters, `ignore_columns=["note"]` leaves a column out, `ignore_unknown_columns` leaves
/// out every column that names nothing (default: True for a DataFrame, False for a file).
/// The target is one of `control_points=N` (least squares), `tolerance=E` (least
/// squares refined until every position residual is at most E) and `interpolate=True`;
/// without one, a tolerance of 1e-3 of the data's bounding-box diagonal. `weights` is None,
/// `"score"` (each point by its score), `"column"` (the file's weight column) or one weight
/// per point. The report is the dictionary of `neutrospline fit --report json` with the
/// points' fitted `parameters` added.
///
/// The fit's options are keyword arguments named as the command line's flags
/// (`control_points` for `--control-points`), with the library's defaults and messages:
/// `fit_options()` lists them (degree 3, chord-length parameters, ...).
///
/// >>> import numpy as np, neutrospline as ns
/// >>> t = np.linspace(0.0, 1.0, 50)
/// >>> positions = np.column_stack([t, t * t])
/// >>> degrees = np.column_stack([t, 0.5 * np.ones_like(t), 1 - t])
/// >>> curve, report = ns.fit(positions, degrees, control_points=4, degree=2, parametrization="uniform")
/// >>> type(curve).__name__, report["control_points"], report["max_error"]["y"] < 1e-14
/// ('BSpline', 4, True)
#[pyfunction]
#[pyo3(signature = (data, degrees = None, *, parameters = None, weights = None, name = None, columns = None, ignore_columns = None, ignore_unknown_columns = None, **options))]
#[allow(clippy::too_many_arguments)]
pub fn fit<'py>(
    py: Python<'py>,
    data: &Bound<'py, PyAny>,
    degrees: Option<&Bound<'py, PyAny>>,
    parameters: Option<&Bound<'py, PyAny>>,
    weights: Option<&Bound<'py, PyAny>>,
    name: Option<String>,
    columns: Option<&Bound<'py, PyAny>>,
    ignore_columns: Option<&Bound<'py, PyAny>>,
    ignore_unknown_columns: Option<bool>,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyTuple>> {
    let table = frame::column_options(py, columns, ignore_columns, ignore_unknown_columns)?;
    let input = frame::table_input(Some(&table), frame::is_frame(data))?;
    let mut request = FitRequest::default();
    options::set_from_kwargs(&mut request, options)?;
    if let Some(rule) = weights.filter(|w| w.is_instance_of::<PyString>()) {
        request
            .set("weights", OptionValue::Text(rule.extract()?))
            .map_err(invalid)?;
    }
    let membership_rule = request.membership;
    let source = read_source(data, degrees, membership_rule, input)?;
    let description = match &source {
        Source::File(table, None) => format!(
            "Fitted to {} ({} points) by neutrospline fit",
            table.file(),
            table.len()
        ),
        Source::File(table, Some(_)) => format!(
            "Fitted to a DataFrame ({} points) by neutrospline.fit",
            table.len()
        ),
        Source::Arrays { .. } => format!("Fitted to {} points by neutrospline.fit", source.len()),
    };
    let parameters = parameters
        .map(|p| float_array(p, "parameters")?.values().map(<[f64]>::to_vec))
        .transpose()?
        .or_else(|| match &source {
            Source::File(table, _) => table.parameters().map(<[f64]>::to_vec),
            Source::Arrays { .. } => None,
        });
    let weight_values = read_weights(weights, &mut request, &source)?;
    let options = request.validate().map_err(invalid)?;
    let fitted = py
        .detach(|| source.fit(parameters, weight_values, &options))
        .map_err(|e| invalid(source.message(py, &e)))?;
    let report = report_dict(py, &fitted.report, &fitted.parameters)?;
    let mut model = Model::new(fitted.curve)
        .with_family(membership_rule, fitted.second_lane)
        .map_err(invalid)?
        .with_description(description);
    if let Some(name) = name {
        model = model.with_name(name);
    }
    let curve = curve::model_into_py(py, model)?;
    PyTuple::new(py, [curve, report.into_any().unbind()])
}

/// Reads the data: a path (str or os.PathLike) to a CSV data file or a DataFrame, read as
/// `input` says, or arrays.
fn read_source(
    data: &Bound<'_, PyAny>,
    degrees: Option<&Bound<'_, PyAny>>,
    membership: Family,
    input: TableInput,
) -> PyResult<Source> {
    if frame::is_frame(data) {
        if degrees.is_some() {
            return Err(invalid_at(
                "degrees",
                "the DataFrame's columns give the degrees (truth, indeterminacy, falsity): give \
                 a DataFrame or arrays, not both",
            ));
        }
        let frame = Frame::read(data, input)?;
        let table = read_data_with(frame::LABEL, frame.text(), membership, frame.input())
            .map_err(|e| frame.read_error(data.py(), e))?;
        return Ok(Source::File(table, Some(Box::new(frame))));
    }
    let is_path = data.is_instance_of::<pyo3::types::PyString>()
        || data.hasattr("__fspath__").unwrap_or(false);
    if is_path {
        if degrees.is_some() {
            return Err(invalid_at(
                "degrees",
                "the data file gives the degrees (its truth, indeterminacy, falsity columns)",
            ));
        }
        let path: PathBuf = data.extract()?;
        let table = load_data_with(&path, membership, &input).map_err(invalid)?;
        return Ok(Source::File(table, None));
    }
    refuse_table_options(&input)?;
    let degrees = degrees.ok_or_else(|| {
        invalid_at(
            "degrees",
            "missing: give the degrees of the data points (or a data file instead of arrays)",
        )
    })?;
    let arrays = PointArrays::read(data, "data", degrees, membership, false)?;
    Ok(Source::Arrays {
        positions: arrays.positions,
        dimension: arrays.dimension,
        degrees: arrays.degrees,
        second: arrays.second,
    })
}

/// The data's weights: an array of weights (then the `weights` option is `column`), or the
/// file's weight column, which the `weights` option must ask for (and only then).
fn read_weights(
    weights: Option<&Bound<'_, PyAny>>,
    request: &mut FitRequest,
    source: &Source,
) -> PyResult<Option<Vec<f64>>> {
    if let Some(array) = weights.filter(|w| !w.is_instance_of::<PyString>()) {
        request
            .set("weights", OptionValue::Text("column".into()))
            .map_err(invalid)?;
        return Ok(Some(float_array(array, "weights")?.values()?.to_vec()));
    }
    match source {
        Source::File(table, _) => {
            request
                .check_data_weights(table.file(), table.weights().is_some())
                .map_err(invalid)?;
            Ok(table
                .weights()
                .filter(|_| request.weights == DataWeights::Given)
                .map(<[f64]>::to_vec))
        }
        Source::Arrays { .. } if request.weights == DataWeights::Given => Err(invalid_at(
            "weights",
            "\"column\" reads a data file's weight column; with arrays, give the weights",
        )),
        Source::Arrays { .. } => Ok(None),
    }
}

/// The options of `fit`, from the library that defines them: one dictionary per option with
/// its keyword `name`, the command line's `option`, `kind`, `choices`, `default`,
/// `default_text` (as the command line writes it) and `help`.
///
/// >>> import neutrospline as ns
/// >>> [o["default"] for o in ns.fit_options() if o["name"] == "degree"]
/// [3]
#[pyfunction]
pub fn fit_options(py: Python<'_>) -> PyResult<Bound<'_, PyList>> {
    options::table::<FitRequest>(py)
}

/// The options of a figure (`to_svg`, `save_figure`), from the plot crate that defines them,
/// as `fit_options()` lists the fit's.
///
/// >>> import neutrospline as ns
/// >>> [o["default"] for o in ns.figure_options() if o["name"] == "width"]
/// [1600]
#[pyfunction]
pub fn figure_options(py: Python<'_>) -> PyResult<Bound<'_, PyList>> {
    options::table::<neutrospline_plot::FigureRequest>(py)
}

/// Fits a tensor-product B-spline surface to data points, as `neutrospline fit --surface`
/// does, and returns `(surface, report)`.
///
/// `data` is an array of positions of shape (rows, cols, 3) (a grid: rows along u, with
/// `degrees` of shape (rows, cols, 3)) or (n, 3) (scattered points, or a grid row by row with
/// `grid=(rows, cols)`), a pandas DataFrame (read as the data file with its columns would be:
/// names in any order and case, `x`, `y`, `z`, `truth` / `T`, `indeterminacy` / `I`,
/// `falsity` / `F`, optionally `u`, `v`, `weight`, `name`; others left out; errors named by
/// row), or the path of a CSV data file (columns `x, y, z, truth, indeterminacy, falsity[, u,
/// v, weight]`, errors named by line). `columns`, `ignore_columns` and
/// `ignore_unknown_columns` say how a table's columns are read, as for `fit`. `parameters` gives each
/// point's `(u, v)` (shape (n, 2)); `weights` is None, `"score"`, `"column"` (the file's weight
/// column) or one weight per point. The report is the dictionary of `neutrospline fit --surface
/// --report json` with the points' fitted `parameters` (n, 2) added.
///
/// The options are keyword arguments named as the command line's flags, with the library's
/// defaults and messages (`fit_surface_options()` lists them): `degree` (3 or `(p, q)`),
/// `control_points` (`(m, n)`), `tolerance`, `interpolate`, `grid` (`(rows, cols)` or
/// `"ROWSxCOLS"`), `scattered`, `smoothing`, `parametrization`, `projection`, `membership`.
///
/// >>> import numpy as np, neutrospline as ns
/// >>> u, v = np.meshgrid(np.linspace(0, 1, 6), np.linspace(0, 1, 5), indexing="ij")
/// >>> points = np.stack([u, v, u * v], axis=-1)
/// >>> degrees = np.stack([0.2 + 0.5 * u, 0.1 + 0 * u, 0.6 - 0.5 * v], axis=-1)
/// >>> surface, report = ns.fit_surface(points, degrees, interpolate=True)
/// >>> report["control_points"], bool(abs(surface.evaluate(0.4, 0.5)[2] - 0.2) < 1e-12)
/// ([6, 5], True)
#[pyfunction]
#[pyo3(signature = (data, degrees = None, *, parameters = None, weights = None, name = None, columns = None, ignore_columns = None, ignore_unknown_columns = None, **options))]
#[allow(clippy::too_many_arguments)]
pub fn fit_surface<'py>(
    py: Python<'py>,
    data: &Bound<'py, PyAny>,
    degrees: Option<&Bound<'py, PyAny>>,
    parameters: Option<&Bound<'py, PyAny>>,
    weights: Option<&Bound<'py, PyAny>>,
    name: Option<String>,
    columns: Option<&Bound<'py, PyAny>>,
    ignore_columns: Option<&Bound<'py, PyAny>>,
    ignore_unknown_columns: Option<bool>,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyTuple>> {
    let mut request = SurfaceFitRequest::default();
    // A grid given as a pair (rows, cols) is the command line's `ROWSxCOLS`.
    if let Some(options) = options {
        if let Some(grid) = options.get_item("grid")? {
            if let Ok((rows, cols)) = grid.extract::<(usize, usize)>() {
                options.set_item("grid", format!("{rows}x{cols}"))?;
            }
        }
    }
    let is_frame = frame::is_frame(data);
    let table = frame::column_options(py, columns, ignore_columns, ignore_unknown_columns)?;
    let input = frame::table_input(Some(&table), is_frame)?;
    options::set_from_kwargs(&mut request, options)?;
    let array_weights = match weights {
        Some(rule) if rule.is_instance_of::<PyString>() => {
            request
                .set("weights", OptionValue::Text(rule.extract()?))
                .map_err(invalid)?;
            None
        }
        Some(array) => {
            request
                .set("weights", OptionValue::Text("column".into()))
                .map_err(invalid)?;
            Some(float_array(array, "weights")?.values()?.to_vec())
        }
        None => None,
    };
    let membership = request.membership;
    let fit_options = request.validate().map_err(invalid)?;
    let uv = parameters
        .map(|p| {
            let array = float_array(p, "parameters")?;
            match array.shape() {
                [_, 2] => Ok(array
                    .values()?
                    .chunks_exact(2)
                    .map(|c| [c[0], c[1]])
                    .collect::<Vec<[f64; 2]>>()),
                shape => Err(invalid_at(
                    "parameters",
                    format!("expected an array of shape (n, 2) (u, v of each point), got shape {shape:?}"),
                )),
            }
        })
        .transpose()?;
    let is_path = data.is_instance_of::<PyString>() || data.hasattr("__fspath__").unwrap_or(false);
    let (fitted, description, data_name) = if is_frame {
        // A table with named columns (a pandas DataFrame), read as a data file is.
        refuse_arrays(
            [degrees.is_some(), uv.is_some(), array_weights.is_some()],
            "the DataFrame's columns give it: give a DataFrame or arrays, not both",
            "the DataFrame's `weight` column gives the weights (weights=\"column\"), not an array",
        )?;
        let frame = Frame::read(data, input)?;
        let table = read_data_with(frame::LABEL, frame.text(), membership, frame.input())
            .map_err(|e| frame.read_error(py, e))?;
        if table.dimension() != 3 {
            return Err(invalid_at(
                "data",
                format!(
                    "the DataFrame has no column `z` (its columns: {}; a surface needs x, y, z)",
                    frame.columns_text()
                ),
            ));
        }
        request
            .weights
            .check_data(table.file(), table.weights().is_some())
            .map_err(invalid)?;
        let fitted = py
            .detach(|| table.fit_surface(request.grid, &fit_options))
            .map_err(|e| invalid(frame.message(py, &e)))?;
        let description = format!(
            "Fitted to a DataFrame ({} points) by neutrospline.fit_surface",
            table.len()
        );
        (fitted, description, frame::LABEL.to_owned())
    } else if is_path {
        refuse_arrays(
            [degrees.is_some(), uv.is_some(), array_weights.is_some()],
            "the data file gives it (its columns): give arrays or a file, not both",
            "the data file's weight column gives the weights (weights=\"column\")",
        )?;
        let path: PathBuf = data.extract()?;
        let table = load_data_with(&path, membership, &input).map_err(invalid)?;
        request
            .weights
            .check_data(table.file(), table.weights().is_some())
            .map_err(invalid)?;
        let fitted = py
            .detach(|| table.fit_surface(request.grid, &fit_options))
            .map_err(invalid)?;
        let description = format!(
            "Fitted to {} ({} points) by neutrospline.fit_surface",
            table.file(),
            table.len()
        );
        (fitted, description, table.file().to_owned())
    } else {
        refuse_table_options(&input)?;
        let degrees = degrees.ok_or_else(|| {
            invalid_at(
                "degrees",
                "missing: give the degrees of the data points (or a data file instead of arrays)",
            )
        })?;
        let shape = float_array(data, "data")?.shape().to_vec();
        let arrays = PointArrays::read(data, "data", degrees, membership, shape.len() == 3)?;
        if arrays.dimension != 3 {
            return Err(invalid_at(
                "data",
                format!(
                    "a surface is fitted to points in 3-D: expected shape (n, 3) or (rows, cols, 3), got shape {shape:?}"
                ),
            ));
        }
        if request.weights == DataWeights::Given && array_weights.is_none() {
            return Err(invalid_at(
                "weights",
                "\"column\" reads a data file's weight column; with arrays, give the weights",
            ));
        }
        let positions: Vec<[f64; 3]> = arrays
            .positions
            .chunks_exact(3)
            .map(|c| [c[0], c[1], c[2]])
            .collect();
        let count = positions.len();
        let grid = arrays.grid.map(|(r, c)| [r, c]).or(request.grid);
        let mut fit_data = match grid {
            Some([rows, cols]) => SurfaceFitData::grid(rows, cols, positions, arrays.degrees),
            None => SurfaceFitData::scattered(positions, arrays.degrees),
        }
        .map_err(invalid)?;
        if let Some(second) = arrays.second {
            fit_data = fit_data.with_second_lane(second).map_err(invalid)?;
        }
        if let Some(uv) = uv {
            fit_data = fit_data.with_parameters(uv).map_err(invalid)?;
        }
        if let Some(w) = array_weights {
            fit_data = fit_data.with_weights(w).map_err(invalid)?;
        }
        let fitted = py
            .detach(|| neutrospline::fit::fit_surface(&fit_data, &fit_options))
            .map_err(invalid)?;
        (
            fitted,
            format!("Fitted to {count} points by neutrospline.fit_surface"),
            "data".to_owned(),
        )
    };
    if let Some(warning) = neutrospline_io::surface_fit_warning(&data_name, &fitted.report) {
        let category = py.get_type::<pyo3::exceptions::PyRuntimeWarning>();
        PyErr::warn(py, &category, &std::ffi::CString::new(warning)?, 1)?;
    }
    let report = py.import("json")?.call_method1(
        "loads",
        (neutrospline_io::surface_fit_report_json(&fitted.report),),
    )?;
    let flat: Vec<f64> = fitted.parameters.iter().flatten().copied().collect();
    let rows = fitted.parameters.len();
    report.set_item("parameters", new_array(py, flat, &[rows, 2])?)?;
    let mut model = Model::new(fitted.surface)
        .with_family(membership, fitted.second_lane)
        .map_err(invalid)?
        .with_description(description);
    if let Some(name) = name {
        model = model.with_name(name);
    }
    let surface = crate::surface::model_into_py(py, model)?;
    PyTuple::new(py, [surface, report.unbind()])
}

/// The options of `fit_surface`, from the library that defines them (`SurfaceFitRequest`),
/// as `fit_options()` lists the curve fit's.
///
/// >>> import neutrospline as ns
/// >>> [o["default"] for o in ns.fit_surface_options() if o["name"] == "smoothing"]
/// [0.0]
#[pyfunction]
pub fn fit_surface_options(py: Python<'_>) -> PyResult<Bound<'_, PyList>> {
    options::table::<SurfaceFitRequest>(py)
}

/// Refuses the table options (`columns`, ...) for arrays, which have no named columns.
fn refuse_table_options(input: &TableInput) -> PyResult<()> {
    if *input == TableInput::default() {
        return Ok(());
    }
    let name =
        TableInput::OPTIONS
            .iter()
            .map(|spec| spec.name)
            .find(|name| {
                input.value_text(name).ok().flatten().is_some_and(|v| {
                    Some(v) != TableInput::default().value_text(name).ok().flatten()
                })
            })
            .unwrap_or("columns");
    Err(invalid_at(
        name.replace('-', "_"),
        "is an option of a table (a DataFrame or a data file), not of arrays",
    ))
}

/// Refuses arrays (`[degrees, parameters, weights]` given) next to a table that holds them:
/// `columns` for degrees or parameters, `weights` for weights.
fn refuse_arrays(given: [bool; 3], columns: &str, weights: &str) -> PyResult<()> {
    for (given, what) in [(given[0], "degrees"), (given[1], "parameters")] {
        if given {
            return Err(invalid_at(what, columns));
        }
    }
    if given[2] {
        return Err(invalid_at("weights", weights));
    }
    Ok(())
}
