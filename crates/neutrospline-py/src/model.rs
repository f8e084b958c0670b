//! What curves and surfaces share: building a [`Model`] from arrays (positions, degrees under
//! a membership rule, names), saving it through the formats crate, drawing it with the plot
//! crate, and carrying it through pickle.

use std::path::Path;
use std::str::FromStr;

use neutrospline::{ControlPoint, Degrees, Family};
use neutrospline_io::{write_atomically, Format, Model, ReadOptions, Shape};
use neutrospline_plot::{
    render_figure, render_svg, FigureFormat, FigureRequest, PlotModel, PlotOptions, View,
};
use pyo3::exceptions::PyOSError;
use pyo3::prelude::*;

use crate::arrays::{float_array, FloatArray};
use crate::errors::{invalid, invalid_at, write_error};

/// The name, description and point names given with the arrays.
#[derive(Default)]
pub struct Meta {
    pub name: Option<String>,
    pub description: Option<String>,
    pub point_names: Option<Vec<Option<String>>>,
}

impl Meta {
    /// The names given to a constructor.
    pub fn new(
        name: Option<String>,
        description: Option<String>,
        point_names: Option<Vec<Option<String>>>,
    ) -> Meta {
        Meta {
            name,
            description,
            point_names,
        }
    }
}

/// Parses a membership rule name (`neutrosophic`, `intuitionistic`, `fuzzy`).
pub fn membership(name: &str) -> PyResult<Family> {
    Family::from_str(name).map_err(|e| invalid_at("membership", e))
}

/// The model of `shape` under `membership`, with the names of `meta`.
pub fn model(shape: impl Into<Shape>, membership: Family, meta: Meta) -> PyResult<Model> {
    let mut model = Model::new(shape)
        .with_membership(membership)
        .map_err(invalid)?;
    if let Some(name) = meta.name {
        model = model.with_name(name);
    }
    if let Some(description) = meta.description {
        model = model.with_description(description);
    }
    if let Some(names) = meta.point_names {
        model = model
            .with_point_names(names)
            .map_err(|e| invalid_at("point_names", e))?;
    }
    Ok(model)
}

/// A model like `like` (membership, name, description; point names when the count is
/// unchanged) for a new shape derived from its shape by `split`, `elevate` and the like, with
/// the derived shape's `spreads` when the model is fuzzy.
pub fn derived(
    like: &Model,
    shape: impl Into<Shape>,
    spreads: Option<Vec<neutrospline::Spread<3>>>,
) -> PyResult<Model> {
    let shape = shape.into();
    let names = like.point_names();
    let meta = Meta {
        name: like.name().map(str::to_owned),
        description: like.description().map(str::to_owned),
        point_names: (names.len() == shape.control_count() && names.iter().any(Option::is_some))
            .then(|| names.to_vec()),
    };
    let model = model(shape, like.membership(), meta)?;
    match spreads {
        Some(spreads) => model.with_spreads(spreads).map_err(invalid),
        None => Ok(model),
    }
}

/// Control points from `positions` (`(n, dimension)`, or `rows x cols` grids when `grid`) and
/// `degrees` (`(n, 3)` as truth, indeterminacy, falsity; `(n, 2)` as truth, falsity under
/// the intuitionistic rule; `(n,)` or `(n, 1)` truth alone under the fuzzy rule).
pub struct PointArrays {
    /// The positions, point-major.
    pub positions: Vec<f64>,
    /// Coordinates per point.
    pub dimension: usize,
    /// The degrees, one triple per point.
    pub degrees: Vec<Degrees>,
    /// `(rows, cols)` of a grid.
    pub grid: Option<(usize, usize)>,
}

impl PointArrays {
    /// Reads and checks the arrays (the positions named `what` in messages: `positions`, or
    /// `data` for fitting); `grid` reads `(rows, cols, 3)` positions.
    pub fn read(
        positions: &Bound<'_, PyAny>,
        what: &str,
        degrees: &Bound<'_, PyAny>,
        membership: Family,
        grid: bool,
    ) -> PyResult<PointArrays> {
        let positions = float_array(positions, what)?;
        let degree_array = float_array(degrees, "degrees")?;
        let shape = positions.shape().to_vec();
        let (count, dimension, grid) = match (grid, shape.as_slice()) {
            (false, &[n, d]) if d == 2 || d == 3 => (n, d, None),
            (true, &[rows, cols, 3]) => (rows * cols, 3, Some((rows, cols))),
            (false, _) => {
                return Err(invalid_at(
                    what,
                    format!(
                        "expected an array of shape (n, 2) or (n, 3) (one row x, y[, z] per \
                         control point), got shape {shape:?}"
                    ),
                ))
            }
            (true, _) => {
                return Err(invalid_at(
                    what,
                    format!(
                        "expected an array of shape (rows, cols, 3) (x, y, z of each control \
                         point of the grid), got shape {shape:?}"
                    ),
                ))
            }
        };
        let flat = positions.values()?.to_vec();
        let degrees = read_degrees(&degree_array, &shape[..shape.len() - 1], membership)?;
        debug_assert_eq!(degrees.len(), count);
        Ok(PointArrays {
            positions: flat,
            dimension,
            degrees,
            grid,
        })
    }

    /// The control points, with `D` equal to [`PointArrays::dimension`].
    pub fn points<const D: usize>(&self) -> Vec<ControlPoint<D>> {
        self.positions
            .chunks_exact(D)
            .zip(&self.degrees)
            .map(|(p, &d)| {
                let mut position = [0.0; D];
                position.copy_from_slice(p);
                ControlPoint::new(position, d)
            })
            .collect()
    }
}

/// The degrees of `points` points (the leading shape `points`), one row each, checked under
/// `membership`; a bad value is named as `degrees[i]` (or `degrees[i, j]` on a grid).
fn read_degrees(
    array: &FloatArray<'_>,
    points: &[usize],
    membership: Family,
) -> PyResult<Vec<Degrees>> {
    let shape = array.shape();
    let count = membership.channel_count();
    let columns = match count {
        3 => "3 (truth, indeterminacy, falsity)".to_owned(),
        1 => "1 (truth) or 3 (truth, 0, 0), or no last axis".to_owned(),
        _ => format!(
            "3 (truth, indeterminacy, falsity) or {count} ({})",
            membership.channels().join(", ")
        ),
    };
    let width = if shape.len() == points.len() + 1 && shape[..points.len()] == *points {
        Some(shape[points.len()])
    } else if shape == points && membership == Family::Fuzzy {
        Some(1)
    } else {
        None
    };
    let allowed = width.filter(|&w| w == 3 || w == count);
    let Some(width) = allowed else {
        return Err(invalid_at(
            "degrees",
            format!(
                "expected one row per control point (leading shape {points:?}) of {columns} \
                 columns under the {membership} rule, got shape {shape:?}"
            ),
        ));
    };
    let values = array.values()?;
    let cols = points.get(1).copied();
    values
        .chunks_exact(width)
        .enumerate()
        .map(|(k, row)| {
            let at = || match cols {
                Some(c) if points.len() == 2 => format!("degrees[{}, {}]", k / c, k % c),
                _ => format!("degrees[{k}]"),
            };
            match *row {
                [t, i, f] => Degrees::with_membership(membership, t, Some(i), Some(f)),
                _ => membership.to_degrees(row),
            }
            .map_err(|e| invalid_at(at(), e))
        })
        .collect()
}

/// Positions, degrees and weights of control points as row-major values.
pub fn point_rows<const D: usize>(points: &[ControlPoint<D>]) -> (Vec<f64>, Vec<f64>) {
    let positions = points.iter().flat_map(|p| p.position).collect();
    let degrees = points.iter().flat_map(|p| p.degrees.to_array()).collect();
    (positions, degrees)
}

/// The format of `path` by its extension, for saving a model.
fn model_format(path: &Path) -> PyResult<Format> {
    Format::from_path(path).map_err(invalid)
}

/// Saves `model` to `path` (TOML, JSON or CSV by the extension), atomically.
pub fn save(model: &Model, path: &Path) -> PyResult<()> {
    model_format(path)?;
    neutrospline_io::save(model, path).map_err(write_error)
}

/// The figure asked for by `request` (the plot crate's, as `neutrospline plot` reads it):
/// the view (`all` unless given), the options, the model's description as the caption unless
/// one is given.
pub fn prepare(model: &Model, request: &FigureRequest) -> PyResult<(PlotModel, View, PlotOptions)> {
    let options = if model.shape().is_surface() {
        request.surface_plot_options()
    } else {
        request.plot_options()
    }
    .map_err(invalid)?;
    let options = match (options.caption(), model.description()) {
        (None, Some(description)) => options.with_caption(description),
        _ => options,
    };
    let figure = PlotModel::from_model(model).map_err(invalid)?;
    Ok((figure, request.view(false), options))
}

/// The SVG text of a figure of `model`.
pub fn svg(py: Python<'_>, model: &Model, request: &FigureRequest) -> PyResult<String> {
    let (figure, view, options) = prepare(model, request)?;
    py.detach(|| render_svg(&figure, view, &options))
        .map_err(invalid)
}

/// Writes a figure of `model` to `path` (`.svg`, `.png` or `.pdf`, by the extension),
/// atomically.
pub fn save_figure(
    py: Python<'_>,
    model: &Model,
    path: &Path,
    request: &FigureRequest,
) -> PyResult<()> {
    let format = FigureFormat::from_path(path).map_err(invalid)?;
    let (figure, view, options) = prepare(model, request)?;
    let bytes = py
        .detach(|| render_figure(&figure, view, &options, format))
        .map_err(invalid)?;
    let failed =
        |e: std::io::Error| PyOSError::new_err(format!("{}: cannot write: {e}", path.display()));
    write_atomically(path, &bytes).map_err(failed)
}

/// The model as JSON text (17 significant digits: the round trip is exact), for pickle.
pub fn to_state(model: &Model) -> String {
    neutrospline_io::to_json_string(model)
}

/// The model of [`to_state`] text.
pub fn from_state(text: &str) -> PyResult<Model> {
    let mut options = ReadOptions::default();
    options.limits.max_control_points = u64::MAX;
    options.limits.max_file_size = u64::MAX;
    neutrospline_io::parse("<pickle>", Format::Json, text.as_bytes(), &options).map_err(invalid)
}
