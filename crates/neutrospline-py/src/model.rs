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

/// Parses a membership family name (`neutrosophic`, `pythagorean`, `q-rung:4`,
/// `interval-neutrosophic`, ...).
pub fn membership(name: &str) -> PyResult<Family> {
    Family::from_str(name).map_err(|e| invalid_at("membership", e))
}

/// The model of `shape` under `membership`, with the names of `meta`. A family of two lanes
/// (interval-valued, bipolar: docs/model.md, "Lanes") takes its second lane `second`, a shape
/// of the same geometry; a family of one lane takes none.
pub fn model(
    shape: impl Into<Shape>,
    second: Option<Shape>,
    membership: Family,
    meta: Meta,
) -> PyResult<Model> {
    let mut model = Model::new(shape)
        .with_family(membership, second)
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
/// unchanged) for a new shape derived from its shape by `split`, `elevate` and the like (and
/// the same operation's `second` lane for a family of two lanes), with the derived shape's
/// `spreads` when the model is fuzzy.
pub fn derived(
    like: &Model,
    shape: impl Into<Shape>,
    second: Option<Shape>,
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
    let model = model(shape, second, like.membership(), meta)?;
    match spreads {
        Some(spreads) => model.with_spreads(spreads).map_err(invalid),
        None => Ok(model),
    }
}

/// Control points from `positions` (`(n, dimension)`, or `rows x cols` grids when `grid`) and
/// `degrees` (`(n, 3)` as truth, indeterminacy, falsity; `(n, channel_count)` as the family's
/// channels, such as `(n, 2)` truth, falsity under the intuitionistic rule; `(n,)` or `(n, 1)`
/// truth alone under the fuzzy rule). An interval-valued or bipolar family takes exactly its
/// `(n, channel_count)` channels (`Family::channels`), split into its two lanes
/// (`Family::split`, docs/model.md "Lanes").
pub struct PointArrays {
    /// The positions, point-major.
    pub positions: Vec<f64>,
    /// Coordinates per point.
    pub dimension: usize,
    /// The degrees of the first lane, one triple per point.
    pub degrees: Vec<Degrees>,
    /// The degrees of the second lane of a family of two lanes (`upper`, or the negated
    /// `negative` bipolar degrees), one triple per point.
    pub second: Option<Vec<Degrees>>,
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
        let (degrees, second) = read_degrees(&degree_array, &shape[..shape.len() - 1], membership)?;
        debug_assert_eq!(degrees.len(), count);
        Ok(PointArrays {
            positions: flat,
            dimension,
            degrees,
            second,
            grid,
        })
    }

    /// The control points (of the first lane), with `D` equal to [`PointArrays::dimension`].
    pub fn points<const D: usize>(&self) -> Vec<ControlPoint<D>> {
        self.lane_points(&self.degrees)
    }

    /// The control points of the second lane of a family of two lanes: the same positions
    /// with the second lane's degrees.
    pub fn second_points<const D: usize>(&self) -> Option<Vec<ControlPoint<D>>> {
        self.second.as_ref().map(|d| self.lane_points(d))
    }

    fn lane_points<const D: usize>(&self, degrees: &[Degrees]) -> Vec<ControlPoint<D>> {
        self.positions
            .chunks_exact(D)
            .zip(degrees)
            .map(|(p, &d)| {
                let mut position = [0.0; D];
                position.copy_from_slice(p);
                ControlPoint::new(position, d)
            })
            .collect()
    }
}

/// The degrees of the lanes of the two lanes of a family, per point.
type LaneRows = (Vec<Degrees>, Option<Vec<Degrees>>);

/// The degrees of `points` points (the leading shape `points`), one row each, checked under
/// `membership`; a bad value is named as `degrees[i]` (or `degrees[i, j]` on a grid). A
/// family of two lanes gives the second lane's degrees too.
fn read_degrees(
    array: &FloatArray<'_>,
    points: &[usize],
    membership: Family,
) -> PyResult<LaneRows> {
    let shape = array.shape();
    let count = membership.channel_count();
    let wide = membership.lane_count() == 2;
    let columns = match count {
        _ if wide => format!("{count} ({})", membership.channels().join(", ")),
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
    let allowed = width.filter(|&w| w == count || (w == 3 && !wide));
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
    let at = |k: usize| match cols {
        Some(c) if points.len() == 2 => format!("degrees[{}, {}]", k / c, k % c),
        _ => format!("degrees[{k}]"),
    };
    let rows = values.chunks_exact(width).enumerate();
    if wide {
        let mut first = Vec::with_capacity(values.len() / width.max(1));
        let mut second = Vec::with_capacity(first.capacity());
        for (k, row) in rows {
            let (lanes, _) = membership.split(row).map_err(|e| invalid_at(at(k), e))?;
            first.push(lanes[0]);
            second.push(lanes[1]);
        }
        return Ok((first, Some(second)));
    }
    let first = rows
        .map(|(k, row)| {
            match *row {
                [t, i, f] => Degrees::with_membership(membership, t, Some(i), Some(f)),
                _ => membership.to_degrees(row),
            }
            .map_err(|e| invalid_at(at(k), e))
        })
        .collect::<PyResult<_>>()?;
    Ok((first, None))
}

/// Whether `membership` rides in two lanes (the interval-valued and bipolar families).
pub fn is_wide(membership: Family) -> bool {
    membership.lane_count() == 2
}

/// The names of the degree columns of a model's arrays (evaluation, control degrees, bounding
/// boxes): `truth, indeterminacy, falsity` for a family of one lane, the family's channels
/// (`Family::channels`) for one of two lanes.
pub fn degree_columns(membership: Family) -> Vec<&'static str> {
    if is_wide(membership) {
        membership.channels().to_vec()
    } else {
        vec!["truth", "indeterminacy", "falsity"]
    }
}

/// Joins the rows of the lanes of one evaluation (or of derivative rates): `lanes[l]` holds
/// `m` rows of `dimension + 3` values (position, the lane's three slots), row-major; the
/// result holds `m` rows of the position and `degree_columns(membership)` values, the slots
/// of each lane joined into the family's channels (`Family::join_slots`, a linear map, so it
/// serves rates as well as values).
pub fn join_rows(membership: Family, dimension: usize, lanes: &[Vec<f64>]) -> Vec<f64> {
    let stride = dimension + 3;
    let m = lanes.first().map_or(0, |l| l.len() / stride);
    if !is_wide(membership) {
        return lanes.first().cloned().unwrap_or_default();
    }
    let mut out = Vec::with_capacity(m * (dimension + membership.channel_count()));
    for k in 0..m {
        let row = &lanes[0][k * stride..(k + 1) * stride];
        out.extend_from_slice(&row[..dimension]);
        let slots: Vec<[f64; 3]> = lanes
            .iter()
            .map(|lane| {
                let r = &lane[k * stride + dimension..(k + 1) * stride];
                [r[0], r[1], r[2]]
            })
            .collect();
        out.extend_from_slice(&membership.join_slots(&slots));
    }
    out
}

/// Joins the bounds of the lanes: `lanes[l]` is `[min, max]` of a lane's `dimension + 3`
/// columns; the result is `[min, max]` of the position and the family's channels (a negated
/// lane's minimum is the negative of its slot's maximum).
pub fn join_bounds(membership: Family, dimension: usize, lanes: &[[Vec<f64>; 2]]) -> [Vec<f64>; 2] {
    if !is_wide(membership) {
        return lanes[0].clone();
    }
    let count = membership.channel_count();
    let mut low = lanes[0][0][..dimension].to_vec();
    let mut high = lanes[0][1][..dimension].to_vec();
    low.resize(dimension + count, 0.0);
    high.resize(dimension + count, 0.0);
    for (lane, [lo, hi]) in membership.lanes().iter().zip(lanes) {
        for (slot, channel) in lane.slots.iter().enumerate() {
            let Some(c) = channel else { continue };
            let (a, b) = (lo[dimension + slot], hi[dimension + slot]);
            let (a, b) = if lane.negated {
                (0.0 - b, 0.0 - a)
            } else {
                (a, b)
            };
            low[dimension + c] = a;
            high[dimension + c] = b;
        }
    }
    [low, high]
}

/// The control degrees of `model` as rows of `degree_columns` values: the triples of a family
/// of one lane, the channels (`Model::control_channels`) of one of two.
pub fn control_degree_rows(model: &Model) -> Vec<f64> {
    if is_wide(model.membership()) {
        model
            .control_channels()
            .iter()
            .flat_map(|c| c.to_vec())
            .collect()
    } else {
        model
            .shape()
            .control_degrees()
            .iter()
            .flat_map(Degrees::to_array)
            .collect()
    }
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
