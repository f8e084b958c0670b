//! Module-level functions: loading models, Example 1, the scores of degree arrays, the point
//! relation of the paper's Def. 4, and the restoring end of pickle.

use std::path::PathBuf;

use neutrospline::options::OptionSet;
use neutrospline::{AxisSet, AxisSetName, Degrees, Family, PointRelation};
use neutrospline_exchange::{ImportReport, ImportRequest, SourceFormat};
use neutrospline_io::{Format, Kind, KnotSpec, Model, ReadOptions, TableInput};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyTuple};

use crate::arrays::{float_array, new_array};
use crate::curve;
use crate::errors::{invalid, invalid_at};
use crate::frame::{self, Frame};
use crate::model;
use crate::surface;

/// The Python object of any model: a `Bezier`, `BSpline`, `Nurbs`, `BezierSurface`,
/// `BSplineSurface` or `NurbsSurface`.
pub fn model_into_py(py: Python<'_>, model: Model) -> PyResult<Py<PyAny>> {
    if model.shape().is_surface() {
        surface::model_into_py(py, model)
    } else {
        curve::model_into_py(py, model)
    }
}

/// Loads a model file: TOML, JSON, CSV (or TSV) or a spreadsheet's sheet (`.xlsx`, `.xlsm`,
/// `.xls`, `.ods`) by the extension, or a pandas DataFrame of control points, checked as `neutrospline check` checks it. A table is
/// read as the keyword options `sheet`, `columns` (`"truth=mu,falsity=nu"`),
/// `ignore_columns`, `ignore_unknown_columns`, `delimiter` and `decimal_comma` say (the
/// command line's `--sheet`, ...). Returns a `Bezier`, `BSpline`, `Nurbs` or `Surface`; an invalid file raises
/// `ModelError` with the command line's message (file, line, field, value and rule).
///
/// A drawing (`.svg`, `.dxf`) is imported as `neutrospline import` imports it: the result is
/// the pair `(curves, report)`, the list of curves in file order and the import report, a
/// dictionary with `summary` (the line the command line prints), `imported` (curves by the
/// kind of element or entity: `{"<path>": 10}`), `skipped` (a list of `{"kind", "reason",
/// "count"}`, reasons `not-a-curve`, `unsupported`, `hidden`, `not-drawn`, `empty`,
/// `excluded`) and `warnings`. Its options are the command line's (`import_options()` lists
/// them): `truth`, `indeterminacy`, `falsity` (the degrees of control points without their
/// own), `entities` (the kinds to import, `"SPLINE,LWPOLYLINE"` or `"path,rect"`) and `strict`
/// (raise `ModelError` when a drawn shape is left out).
///
/// A pandas DataFrame is read as the CSV table with its columns would be (`x, y[, z], truth,
/// indeterminacy, falsity[, weight, name]`, names in any case and order, `T`, `I`, `F` for the
/// degrees; other columns are left out unless `ignore_unknown_columns=False`; `columns` may be
/// a mapping `{"truth": "mu"}`), its errors naming the row (`DataFrame row 2: ...`) or the
/// missing column and the columns it has.
///
/// The keyword options are the command line's `--kind`, `--degree`, `--knots`, `--membership`,
/// `--rows`, `--cols`, `--degree-u`, `--degree-v`, `--knots-u`, `--knots-v`: a CSV table holds
/// only the control points, so these say what it is (`knots` a rule name such as
/// `"clamped-uniform"`, or the knot values).
///
/// >>> import neutrospline as ns
/// >>> ns.load("examples/example1.toml") == ns.example1()
/// True
/// >>> knots = [0, 0, 0, 0, 0.2, 0.5, 0.7, 1, 1, 1, 1]
/// >>> spline = ns.load("examples/bspline.csv", kind="bspline", degree=3, knots=knots)
/// >>> spline.kind, spline.knots.tolist() == knots
/// ('bspline', True)
/// >>> import pandas as pd
/// >>> frame = pd.DataFrame({"x": [1, 3, 6, 9], "y": [3, 6, 2, 5], "mu": [0.3, 0.8, 0.7, 0.2],
/// ...                       "I": [0.6, 0.1, 0.1, 0.4], "F": [0.1, 0.1, 0.2, 0.4]})
/// >>> ns.load(frame, columns={"truth": "mu"}).positions.tolist() == ns.example1().positions.tolist()
/// True
/// >>> curves, report = ns.load("examples/drawing.svg", truth=0.8, indeterminacy=0.1)
/// >>> len(curves), report["imported"], report["skipped"][0]
/// (2, {'<path>': 1, '<rect>': 1}, {'kind': '<text>', 'reason': 'not-a-curve', 'count': 1})
#[pyfunction]
#[pyo3(signature = (path, *, kind = None, degree = None, knots = None, membership = None, rows = None, cols = None, degree_u = None, degree_v = None, knots_u = None, knots_v = None, periodic = None, periodic_u = None, periodic_v = None, **options))]
#[allow(clippy::too_many_arguments)]
pub fn load(
    py: Python<'_>,
    path: &Bound<'_, PyAny>,
    kind: Option<&str>,
    degree: Option<usize>,
    knots: Option<&Bound<'_, PyAny>>,
    membership: Option<&str>,
    rows: Option<usize>,
    cols: Option<usize>,
    degree_u: Option<usize>,
    degree_v: Option<usize>,
    knots_u: Option<&Bound<'_, PyAny>>,
    knots_v: Option<&Bound<'_, PyAny>>,
    periodic: Option<bool>,
    periodic_u: Option<bool>,
    periodic_v: Option<bool>,
    options: Option<&Bound<'_, PyDict>>,
) -> PyResult<Py<PyAny>> {
    let data = path.clone();
    let frame_given = frame::is_frame(&data);
    let path: PathBuf = if frame_given {
        PathBuf::from(frame::LABEL)
    } else {
        path.extract()?
    };
    let extension = path
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase());
    let source = match extension.as_deref() {
        Some("svg") if !frame_given => Some(SourceFormat::Svg),
        Some("dxf") if !frame_given => Some(SourceFormat::Dxf),
        _ => None,
    };
    if let Some(source) = source {
        let given = [
            ("kind", kind.is_some()),
            ("degree", degree.is_some()),
            ("knots", knots.is_some()),
            ("membership", membership.is_some()),
            ("rows", rows.is_some()),
            ("cols", cols.is_some()),
            ("degree_u", degree_u.is_some()),
            ("degree_v", degree_v.is_some()),
            ("knots_u", knots_u.is_some()),
            ("knots_v", knots_v.is_some()),
            ("periodic", periodic.is_some()),
            ("periodic_u", periodic_u.is_some()),
            ("periodic_v", periodic_v.is_some()),
        ];
        if let Some((name, _)) = given.iter().find(|(_, on)| *on) {
            return Err(invalid_at(
                name,
                "is an option of a model table (.csv, .toml, .json), not of a drawing (the \
                 options of .svg and .dxf files are import_options())",
            ));
        }
        return import_drawing(py, &path, source, options);
    }
    // The other keyword options say how a table is read (the command line's `--sheet`,
    // `--columns`, `--decimal-comma`, ...: neutrospline-io's `TableInput`).
    if let Some(options) = options {
        for key in options.keys() {
            let name = key.extract::<String>()?;
            let known = TableInput::OPTIONS
                .iter()
                .any(|spec| spec.name == name.replace('_', "-"));
            if !known {
                return Err(invalid_at(
                    name,
                    "is an option of a drawing (.svg, .dxf), not of a model file (the options \
                     of a table are table_options())",
                ));
            }
        }
    }
    let mut read = ReadOptions::default();
    read.table = frame::table_input(options, frame_given)?;
    if let Some(kind) = kind {
        read.kind = Some(Kind::from_name(kind).ok_or_else(|| {
            invalid_at(
                "kind",
                format!("{kind:?} is not a kind (one of {})", Kind::known_list()),
            )
        })?);
    }
    read.membership = membership.map(model::membership).transpose()?;
    read.degree = degree;
    read.rows = rows;
    read.cols = cols;
    read.degree_u = degree_u;
    read.degree_v = degree_v;
    read.knots = knots.map(|k| knot_spec(k, "knots")).transpose()?;
    read.knots_u = knots_u.map(|k| knot_spec(k, "knots_u")).transpose()?;
    read.knots_v = knots_v.map(|k| knot_spec(k, "knots_v")).transpose()?;
    read.periodic = periodic;
    read.periodic_u = periodic_u;
    read.periodic_v = periodic_v;
    let model = if frame_given {
        // A DataFrame: the rows of a CSV model table, read by the same reader.
        let frame = Frame::read(&data, read.table.clone())?;
        read.table = frame.input().clone();
        neutrospline_io::read_csv(frame::LABEL, frame.text(), &read)
            .map_err(|e| frame.read_error(py, e))?
    } else {
        py.detach(|| neutrospline_io::load(&path, &read))
            .map_err(invalid)?
    };
    model_into_py(py, model)
}

/// The curves of a drawing and the import report ([`load`]).
fn import_drawing(
    py: Python<'_>,
    path: &std::path::Path,
    source: SourceFormat,
    options: Option<&Bound<'_, PyDict>>,
) -> PyResult<Py<PyAny>> {
    let mut request = ImportRequest::default();
    crate::options::set_from_kwargs(&mut request, options)?;
    let resolved = request.options(source).map_err(invalid)?;
    let limits = neutrospline_io::Limits::default();
    let imported = py
        .detach(|| match source {
            SourceFormat::Svg => neutrospline_exchange::load_svg(path, &resolved, &limits),
            SourceFormat::Dxf => neutrospline_exchange::load_dxf(path, &resolved, &limits),
        })
        .map_err(invalid)?;
    let imported = if request.strict {
        imported
            .strict(&path.display().to_string())
            .map_err(invalid)?
    } else {
        imported
    };
    let report = report_dict(py, &imported.report)?;
    let curves = PyList::empty(py);
    for model in imported.models {
        curves.append(model_into_py(py, model)?)?;
    }
    Ok(PyTuple::new(py, [curves.into_any(), report.into_any()])?
        .into_any()
        .unbind())
}

/// The import report as a dictionary ([`load`]).
fn report_dict<'py>(py: Python<'py>, report: &ImportReport) -> PyResult<Bound<'py, PyDict>> {
    let dict = PyDict::new(py);
    dict.set_item("summary", report.summary())?;
    let imported = PyDict::new(py);
    for (kind, count) in &report.imported {
        imported.set_item(kind, count)?;
    }
    dict.set_item("imported", imported)?;
    let skipped = PyList::empty(py);
    for skip in &report.skipped {
        let entry = PyDict::new(py);
        entry.set_item("kind", &skip.kind)?;
        entry.set_item("reason", skip.reason.name())?;
        entry.set_item("count", skip.count)?;
        skipped.append(entry)?;
    }
    dict.set_item("skipped", skipped)?;
    dict.set_item("warnings", report.warnings.clone())?;
    Ok(dict)
}

/// The options of `load` for a drawing (`.svg`, `.dxf`), from the exchange library that
/// defines them, as `fit_options()` lists the fit's.
///
/// >>> import neutrospline as ns
/// >>> [o["name"] for o in ns.import_options()]
/// ['truth', 'indeterminacy', 'falsity', 'entities', 'strict']
#[pyfunction]
pub fn import_options(py: Python<'_>) -> PyResult<Bound<'_, PyList>> {
    crate::options::table::<ImportRequest>(py)
}

/// The options of `load` for a table (CSV, TSV, a spreadsheet's sheet), from the file library
/// that defines them (neutrospline-io's `TableInput`), as `fit_options()` lists the fit's.
///
/// >>> import neutrospline as ns
/// >>> [o["name"] for o in ns.table_options()]
/// ['delimiter', 'decimal_comma', 'columns', 'ignore_columns', 'ignore_unknown_columns', 'sheet']
#[pyfunction]
pub fn table_options(py: Python<'_>) -> PyResult<Bound<'_, PyList>> {
    crate::options::table::<TableInput>(py)
}

/// The options of `Curve.transform` / `Surface.transform` (`neutrospline transform`'s):
/// name, kind, default and help of each, as `fit_options()` lists its own.
///
/// >>> import neutrospline as ns
/// >>> [o["name"] for o in ns.transform_options()][:3]
/// ['elevate', 'reduce', 'insert_knot']
#[pyfunction]
pub fn transform_options(py: Python<'_>) -> PyResult<Bound<'_, PyList>> {
    crate::options::table::<neutrospline_io::TransformRequest>(py)
}

/// A knot option: a rule name, or the knot values.
fn knot_spec(knots: &Bound<'_, PyAny>, what: &str) -> PyResult<KnotSpec> {
    if let Ok(text) = knots.extract::<String>() {
        return KnotSpec::parse_option(&text).map_err(|e| invalid_at(what, e));
    }
    let values = float_array(knots, what)?.values()?.to_vec();
    Ok(KnotSpec::Explicit(values))
}

/// The paper's Example 1: the cubic neutrosophic Bézier curve of Table 1, with its name,
/// description and point names C0..C3 (the model of `examples/example1.toml`).
///
/// >>> import neutrospline as ns
/// >>> ns.example1()
/// Bezier(control_points=4, degree=3, dimension=2, membership='neutrosophic', name="Example 1")
#[pyfunction]
pub fn example1(py: Python<'_>) -> PyResult<Py<PyAny>> {
    let text = include_str!("../../../examples/example1.toml");
    let model = neutrospline_io::parse(
        "example1.toml",
        Format::Toml,
        text.as_bytes(),
        &ReadOptions::default(),
    )
    .map_err(invalid)?;
    curve::model_into_py(py, model)
}

/// Restores a pickled curve or surface.
#[pyfunction]
pub fn _restore(py: Python<'_>, text: &str, order: usize) -> PyResult<Py<PyAny>> {
    if order == 0 {
        model_into_py(py, model::from_state(text)?)
    } else {
        curve::restore(py, text, order)
    }
}

/// Applies `measure` to every degree triple of `degrees` (shape (..., 3)), checking each.
fn measure(
    py: Python<'_>,
    degrees: &Bound<'_, PyAny>,
    measure: fn(&Degrees) -> f64,
) -> PyResult<Py<PyAny>> {
    let array = float_array(degrees, "degrees")?;
    let shape = array.shape().to_vec();
    if shape.last() != Some(&3) {
        return Err(invalid_at(
            "degrees",
            format!(
                "expected an array of shape (..., 3) (truth, indeterminacy, falsity in the last \
                 axis), got shape {shape:?}"
            ),
        ));
    }
    let values = array.values()?;
    let results = values
        .chunks_exact(3)
        .enumerate()
        .map(|(k, row)| {
            Degrees::new(row[0], row[1], row[2])
                .map(|d| measure(&d))
                .map_err(|e| invalid_at(format!("degrees[{k}]"), e))
        })
        .collect::<PyResult<Vec<f64>>>()?;
    let outer = &shape[..shape.len() - 1];
    if outer.is_empty() {
        Ok(results[0].into_pyobject(py)?.into_any().unbind())
    } else {
        Ok(new_array(py, results, outer)?.unbind())
    }
}

/// Applies `measure` to the channel values of every row of `degrees` (shape (...,
/// channel_count), the family's channels in the last axis), each checked against the rule;
/// `measure` gives the values of one row (or a refusal).
fn measure_channels(
    py: Python<'_>,
    degrees: &Bound<'_, PyAny>,
    membership: &str,
    width: usize,
    measure: impl Fn(Family, &[f64]) -> PyResult<Vec<f64>>,
) -> PyResult<Py<PyAny>> {
    let family = model::membership(membership)?;
    let array = float_array(degrees, "degrees")?;
    let shape = array.shape().to_vec();
    let count = family.channel_count();
    if shape.last() != Some(&count) {
        return Err(invalid_at(
            "degrees",
            format!(
                "expected an array of shape (..., {count}) (the {family} channels {} in the last \
                 axis), got shape {shape:?}",
                family.channels().join(", ")
            ),
        ));
    }
    let values = array.values()?;
    let mut results = Vec::with_capacity(values.len() / count * width);
    for (k, row) in values.chunks_exact(count).enumerate() {
        family
            .check(row)
            .map_err(|e| invalid_at(format!("degrees[{k}]"), e))?;
        results.extend(measure(family, row)?);
    }
    let mut outer = shape[..shape.len() - 1].to_vec();
    if width != 1 {
        outer.push(width);
    }
    if outer.is_empty() {
        Ok(results[0].into_pyobject(py)?.into_any().unbind())
    } else {
        Ok(new_array(py, results, &outer)?.unbind())
    }
}

/// The score of degree values, in [0, 1]: without `membership`, the neutrosophic score
/// `(2 + truth - indeterminacy - falsity) / 3` of triples (an array of shape (..., 3); a
/// float for one triple), 1 fully true, 0 fully false. With `membership`, the family's score
/// (docs/model.md, "Membership families") of its channel values (shape (...,
/// channel_count), in the order of its `channels`), such as `(4 + T_L + T_U - I_L - I_U -
/// F_L - F_U) / 6` for `interval-neutrosophic` and `(3 + T+ - I+ - F+ + T- - I- - F-) / 6`
/// for `bipolar-neutrosophic`; each row is checked against the family's rule.
///
/// >>> import neutrospline as ns
/// >>> round(ns.score([0.7, 0.1, 0.2]), 15)
/// 0.8
/// >>> ns.score([[1, 0, 0], [0, 1, 1]]).tolist()
/// [1.0, 0.0]
/// >>> ns.score([0.25, 0.75], membership="interval-type2")
/// 0.5
#[pyfunction]
#[pyo3(signature = (degrees, *, membership = None))]
pub fn score(
    py: Python<'_>,
    degrees: &Bound<'_, PyAny>,
    membership: Option<&str>,
) -> PyResult<Py<PyAny>> {
    match membership {
        None => measure(py, degrees, Degrees::score),
        Some(name) => measure_channels(py, degrees, name, 1, |family, row| {
            Ok(vec![family.score(row)])
        }),
    }
}

/// The accuracy that breaks ties of the score: without `membership`, `truth - falsity` of
/// degree triples (shape (..., 3)), in [-1, 1]; with `membership`, the family's accuracy of
/// its channel values (shape (..., channel_count)), such as `(T_L + T_U + F_L + F_U) / 2` for
/// `interval-intuitionistic`. The families whose literature ranks by the score alone (fuzzy,
/// interval-neutrosophic, interval-type2, bipolar-neutrosophic) have none: `ModelError`.
///
/// >>> import neutrospline as ns
/// >>> round(ns.accuracy([0.7, 0.1, 0.2]), 15)
/// 0.5
#[pyfunction]
#[pyo3(signature = (degrees, *, membership = None))]
pub fn accuracy(
    py: Python<'_>,
    degrees: &Bound<'_, PyAny>,
    membership: Option<&str>,
) -> PyResult<Py<PyAny>> {
    match membership {
        None => measure(py, degrees, Degrees::accuracy),
        Some(name) => measure_channels(py, degrees, name, 1, |family, row| {
            family.accuracy(row).map(|a| vec![a]).ok_or_else(|| {
                invalid_at(
                    "membership",
                    format!(
                        "the {family} family has no accuracy: its literature ranks its values \
                         by the score alone"
                    ),
                )
            })
        }),
    }
}

/// The rule of the membership family `membership` in one line (the core's
/// `Family::rule_text`, which the studio and `neutrospline check` show too): the name, then,
/// separated by `; `, the box of every channel, each interval's `lower <= upper`, the sum rule
/// and the derived degrees. An unknown family raises `ModelError` listing the accepted names.
///
/// >>> import neutrospline as ns
/// >>> ns.family_rule("q-rung:4")
/// 'q-rung:4: truth, falsity each in [0, 1]; truth^4 + falsity^4 <= 1; derived: hesitation'
/// >>> ns.family_rule("interval-type2")
/// 'interval-type2: truth_lower, truth_upper each in [0, 1]; truth_lower <= truth_upper; derived: type_reduced, footprint'
#[pyfunction]
pub fn family_rule(membership: &str) -> PyResult<String> {
    Ok(model::membership(membership)?.rule_text())
}

/// The degrees derived from a family's channel values (shape (..., channel_count), in the
/// order of its `channels`), as an array of shape (..., len(names)) with their `names`
/// (`Family::derived`): `hesitation` (intuitionistic, orthopair and spherical families),
/// `refusal` (picture), `hesitation_lower, hesitation_upper` (interval-intuitionistic: `1 -
/// T_U - F_U`, `1 - T_L - F_L`), `type_reduced, footprint` (interval-type2: `(M_L + M_U) /
/// 2`, `M_U - M_L`). Returns the pair `(values, names)`; a family without derived degrees
/// raises `ModelError`.
///
/// >>> import neutrospline as ns
/// >>> values, names = ns.derived_degrees([[0.25, 0.75]], membership="interval-type2")
/// >>> values.tolist(), names
/// ([[0.5, 0.5]], ['type_reduced', 'footprint'])
#[pyfunction]
#[pyo3(signature = (degrees, *, membership))]
pub fn derived_degrees<'py>(
    py: Python<'py>,
    degrees: &Bound<'py, PyAny>,
    membership: &str,
) -> PyResult<Bound<'py, PyTuple>> {
    let family = model::membership(membership)?;
    let names = family.derived_names();
    if names.is_empty() {
        return Err(invalid_at(
            "membership",
            format!("the {family} family derives no degrees from its channels"),
        ));
    }
    let values = measure_channels(py, degrees, membership, names.len(), |family, row| {
        Ok(family.derived(row).to_vec())
    })?;
    PyTuple::new(
        py,
        [values.into_bound(py), PyList::new(py, names)?.into_any()],
    )
}

/// The certainty `truth` of degree triples (shape (..., 3)), in [0, 1].
///
/// >>> import neutrospline as ns
/// >>> ns.certainty([0.7, 0.1, 0.2])
/// 0.7
#[pyfunction]
pub fn certainty(py: Python<'_>, degrees: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
    measure(py, degrees, Degrees::certainty)
}

/// An axis set of Def. 4 from pairs `(value, (truth, indeterminacy, falsity))`.
fn axis_set(name: AxisSetName, members: &Bound<'_, PyAny>) -> PyResult<AxisSet> {
    let what = name.to_string();
    let pairs: Vec<(f64, (f64, f64, f64))> = members.extract().map_err(|_| {
        invalid_at(
            &what,
            "expected a sequence of (value, (truth, indeterminacy, falsity)) pairs",
        )
    })?;
    let members = pairs
        .into_iter()
        .enumerate()
        .map(|(k, (value, (t, i, f)))| {
            Degrees::new(t, i, f)
                .map(|d| (value, d))
                .map_err(|e| invalid_at(format!("{what}[{k}]"), e))
        })
        .collect::<PyResult<Vec<_>>>()?;
    AxisSet::new(name, members).map_err(invalid)
}

/// The relation's entries as arrays `(positions (k, 2), degrees (k, 3))`.
fn relation_arrays<'py>(
    py: Python<'py>,
    relation: &PointRelation,
) -> PyResult<Bound<'py, PyTuple>> {
    let entries = relation.entries();
    let positions = entries.iter().flat_map(|e| e.position).collect();
    let degrees = entries.iter().flat_map(|e| e.degrees.to_array()).collect();
    let positions = new_array(py, positions, &[entries.len(), 2])?;
    let degrees = new_array(py, degrees, &[entries.len(), 3])?;
    PyTuple::new(py, [positions, degrees])
}

/// `pairs`: an array or sequence of shape (k, 2), one `(r, s)` per row.
fn read_pairs(pairs: &Bound<'_, PyAny>) -> PyResult<Vec<(f64, f64)>> {
    let array = float_array(pairs, "pairs")?;
    match *array.shape() {
        [_, 2] => Ok(array
            .values()?
            .chunks_exact(2)
            .map(|p| (p[0], p[1]))
            .collect()),
        [0] => Ok(Vec::new()),
        _ => Err(invalid_at(
            "pairs",
            format!(
                "expected an array of shape (k, 2) (one pair (r, s) per row), got shape {:?}",
                array.shape()
            ),
        )),
    }
}

/// The largest neutrosophic point relation of the axis sets `m` and `n` (the paper's Def. 4):
/// each pair `(r, s)` gets the smaller of the two sets' degrees, degree by degree. The sets
/// are sequences of `(value, (truth, indeterminacy, falsity))`; `pairs` (a sequence of
/// `(r, s)`) restricts and orders the result, otherwise every pair of `m x n` in order.
/// Returns `(positions, degrees)` arrays, ready for `Bezier(positions, degrees)`.
///
/// >>> import neutrospline as ns
/// >>> positions, degrees = ns.largest_relation([(1.0, (0.3, 0.6, 0.1))], [(3.0, (0.5, 0.2, 0.4))])
/// >>> positions.tolist(), degrees.tolist()
/// ([[1.0, 3.0]], [[0.3, 0.2, 0.1]])
#[pyfunction]
#[pyo3(signature = (m, n, pairs = None))]
pub fn largest_relation<'py>(
    py: Python<'py>,
    m: &Bound<'py, PyAny>,
    n: &Bound<'py, PyAny>,
    pairs: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyTuple>> {
    let m = axis_set(AxisSetName::M, m)?;
    let n = axis_set(AxisSetName::N, n)?;
    let pairs = pairs.map(read_pairs).transpose()?;
    let relation = match pairs {
        Some(pairs) => PointRelation::largest_on_pairs(&m, &n, &pairs).map_err(invalid)?,
        None => PointRelation::largest(&m, &n),
    };
    relation_arrays(py, &relation)
}

/// Checks that the points `(positions (k, 2), degrees (k, 3))` form a neutrosophic point
/// relation of the axis sets `m` and `n` (Def. 4): every degree of every pair at most the same
/// degree of `m` at `r` and of `n` at `s`. Raises `ModelError` naming the first violating pair,
/// the degree, both values and the axis set.
///
/// >>> import neutrospline as ns
/// >>> m, n = [(1.0, (0.3, 0.6, 0.1))], [(3.0, (0.5, 0.2, 0.4))]
/// >>> ns.check_relation([[1.0, 3.0]], [[0.3, 0.2, 0.1]], m, n)
/// >>> ns.check_relation([[1.0, 3.0]], [[0.4, 0.2, 0.1]], m, n)
/// Traceback (most recent call last):
///   ...
/// neutrospline.ModelError: pair 0 at (1, 3): truth = 0.4 exceeds 0.3, the truth of M at r = 1 (Def. 4: each degree of the relation must be <= the same degree of M at r and of N at s)
#[pyfunction]
pub fn check_relation(
    positions: &Bound<'_, PyAny>,
    degrees: &Bound<'_, PyAny>,
    m: &Bound<'_, PyAny>,
    n: &Bound<'_, PyAny>,
) -> PyResult<()> {
    let m = axis_set(AxisSetName::M, m)?;
    let n = axis_set(AxisSetName::N, n)?;
    let arrays = model::PointArrays::read(
        positions,
        "positions",
        degrees,
        neutrospline::Family::Neutrosophic,
        false,
    )?;
    if arrays.dimension != 2 {
        return Err(invalid_at(
            "positions",
            "a point relation has two coordinates (r, s) per pair",
        ));
    }
    let relation = PointRelation::new(arrays.points::<2>());
    relation.check_admissible(&m, &n).map_err(invalid)
}
