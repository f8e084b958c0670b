//! Data tables for fitting: measured points with their degrees, one per CSV row.
//!
//! Columns (case-insensitive): `x`, `y`, optional `z`, `truth`, `indeterminacy`, `falsity`
//! (aliases `T`, `I`, `F`; which degrees are required follows the membership rule, as for
//! control points; the interval-valued and bipolar families have their channels instead:
//! `truth_lower, truth_upper, ...`, `negative_truth, ...`), and the optional `parameter` (the
//! point's parameter on the curve; `t` reads as the alias of truth), `weight` (a positive
//! number: how strongly the point pulls) and `name`. Comments, empty lines, quoting, CRLF and a byte order mark as in control-point
//! CSV files (see [`crate::read_csv`]); line numbers in errors are physical lines.
//!
//! ```
//! use neutrospline::Family;
//! use neutrospline_io::read_data;
//!
//! let csv = "x,y,T,I,F,weight\n0,0,0.9,0.1,0.0,1\n1,2,0.8,0.2,0.1,2\n2,1,0.7,0.2,0.1,1\n";
//! let table = read_data("survey.csv", csv.as_bytes(), Family::Neutrosophic)?;
//! assert_eq!((table.len(), table.dimension()), (3, 2));
//! assert_eq!(table.weights(), Some(&[1.0, 2.0, 1.0][..]));
//! assert_eq!(table.line(2), 4);
//!
//! let bad = "x,y,T,I,F,weight\n0,0,0.9,0.1,0.0,0\n";
//! let error = read_data("survey.csv", bad.as_bytes(), Family::Neutrosophic).unwrap_err();
//! assert_eq!(
//!     error.to_string(),
//!     "survey.csv:2: column `weight`: weight = 0 is not positive (a data weight scales how \
//!      strongly the point pulls the curve: it must be a positive finite number)"
//! );
//! # Ok::<(), neutrospline_io::ReadError>(())
//! ```

use std::io::BufRead;
use std::path::Path;

use neutrospline::fit::{
    fit_rows, fit_surface, DynFit, FitError, FitOptions, SurfaceFit, SurfaceFitData,
    SurfaceFitOptions,
};
use neutrospline::{Degrees, Family};

use crate::csv::{read_degrees, require_degrees, Columns, Table};
use crate::parsed::{
    channel_problem, duplicate_rule, present_channels, wide_channel, wide_lanes, Field,
    WIDE_CHANNELS,
};
use crate::path_order::{path_disorder, PathDisorder};
use crate::read::open_table;
use crate::{InputError, PointTable, ReadError, TableInput};

/// The columns of a data table: a control-point field, a channel of the interval-valued and
/// bipolar families (index in [`WIDE_CHANNELS`]) or the point's parameter.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Column {
    Field(Field),
    Channel(usize),
    Parameter,
    /// A surface's parameters `u` and `v`.
    U,
    V,
}

impl Column {
    fn from_name(text: &str) -> Option<Column> {
        for (name, column) in [
            ("parameter", Column::Parameter),
            ("u", Column::U),
            ("v", Column::V),
        ] {
            if text.eq_ignore_ascii_case(name) {
                return Some(column);
            }
        }
        Field::from_name(text, true)
            .map(Column::Field)
            .or_else(|| wide_channel(text, true).map(Column::Channel))
    }

    /// The known columns, with the channels of `membership` when it has two lanes.
    fn known_list(membership: Family) -> String {
        let channels = if membership.lane_count() == 2 {
            format!(
                " (membership {membership}: {})",
                membership.channels().join(", ")
            )
        } else {
            String::new()
        };
        format!("{}, parameter, u, v{channels}", Field::known_list())
    }
}

/// Measured points read from a CSV file: positions, degrees and, when the file has them,
/// parameters, weights and names, with the line each point was read from.
#[derive(Debug, Clone, PartialEq)]
pub struct DataTable {
    /// The file, the positions and their lines: what a table of query points holds.
    points: PointTable,
    degrees: Vec<Degrees>,
    second_lane: Option<Vec<Degrees>>,
    parameters: Option<Vec<f64>>,
    surface_parameters: Option<Vec<[f64; 2]>>,
    weights: Option<Vec<f64>>,
    names: Vec<Option<String>>,
}

impl DataTable {
    /// The file as named by the caller.
    pub fn file(&self) -> &str {
        self.points.file()
    }

    /// 2 (columns `x`, `y`) or 3 (with `z`).
    pub fn dimension(&self) -> usize {
        self.points.dimension()
    }

    /// The number of points.
    pub fn len(&self) -> usize {
        self.points.len()
    }

    /// Whether there are no points (never true for a table that was read).
    pub fn is_empty(&self) -> bool {
        self.points.is_empty()
    }

    /// The positions, `z = 0` for 2-D data.
    pub fn positions(&self) -> &[[f64; 3]] {
        self.points.positions()
    }

    /// The degrees, valid under the membership rule they were read with (of an
    /// interval-valued or bipolar family: the first lane, docs/model.md "Lanes").
    pub fn degrees(&self) -> &[Degrees] {
        &self.degrees
    }

    /// The second lane's degrees of an interval-valued or bipolar family's data (`upper`, or
    /// the negated `negative` degrees); `None` for a family of one lane.
    pub fn second_lane(&self) -> Option<&[Degrees]> {
        self.second_lane.as_deref()
    }

    /// The `u` and `v` columns (a surface's parameters), when the file has them.
    pub fn surface_parameters(&self) -> Option<&[[f64; 2]]> {
        self.surface_parameters.as_deref()
    }

    /// The `parameter` column, when the file has one.
    pub fn parameters(&self) -> Option<&[f64]> {
        self.parameters.as_deref()
    }

    /// The `weight` column, when the file has one (every weight positive and finite).
    pub fn weights(&self) -> Option<&[f64]> {
        self.weights.as_deref()
    }

    /// The `name` column's cells (`None` for an empty cell or without the column).
    pub fn names(&self) -> &[Option<String>] {
        &self.names
    }

    /// How far the points are from an ordered path, when far enough to warn that a curve
    /// fitted through them in the order of the rows zigzags ([`path_disorder`]).
    pub fn path_disorder(&self) -> Option<PathDisorder> {
        path_disorder(self.positions())
    }

    /// The physical line (1-based) point `index` was read from.
    ///
    /// # Panics
    /// When `index` is not a point of the table.
    pub fn line(&self, index: usize) -> usize {
        self.points.line(index)
    }

    /// Fits a curve of the table's dimension to its points, with its parameters and weights:
    /// [`fit_rows`], its errors located in the file ([`DataTable::locate`]).
    ///
    /// # Errors
    /// The located [`FitError`].
    pub fn fit(&self, options: &FitOptions) -> Result<DynFit, InputError> {
        if self.surface_parameters.is_some() {
            return Err(self.file_error(
                "columns `u` and `v` are a surface's parameters: fit a surface (--surface), or \
                 give a curve's `parameter` column",
            ));
        }
        fit_rows(
            self.dimension(),
            &self.points.flat_positions(),
            self.degrees.clone(),
            self.second_lane.clone(),
            self.parameters.clone(),
            self.weights.clone(),
            options,
        )
        .map_err(|e| self.locate(&e))
    }

    /// Fits a surface to the table's points (which need a `z` column): a grid of
    /// `[rows, cols]` points in the order of the rows, or scattered points; with the `u`, `v`
    /// columns as the points' parameters and the `weight` column as their weights, when the
    /// file has them. Errors are located in the file ([`DataTable::locate`]).
    ///
    /// ```
    /// use neutrospline::fit::{SurfaceFitOptions, SurfaceTarget};
    /// use neutrospline::Family;
    /// use neutrospline_io::read_data;
    /// let mut csv = String::from("x,y,z,T,I,F\n");
    /// for k in 0..4 {
    ///     for l in 0..3 {
    ///         csv.push_str(&format!("{k},{l},{},0.5,0.2,0.1\n", k * l));
    ///     }
    /// }
    /// let table = read_data("grid.csv", csv.as_bytes(), Family::Neutrosophic)?;
    /// let options = SurfaceFitOptions::default()
    ///     .with_degrees(3, 2)
    ///     .with_target(SurfaceTarget::Interpolate);
    /// let fitted = table.fit_surface(Some([4, 3]), &options)?;
    /// assert_eq!(fitted.report.control_points, [4, 3]);
    /// let wrong = table.fit_surface(Some([5, 3]), &options).unwrap_err();
    /// assert_eq!(
    ///     wrong.to_string(),
    ///     "grid.csv: a grid of 5 x 3 points does not hold 12 points (rows x cols must be the \
    ///      number of points, each at least 1)"
    /// );
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// No `z` column, a `parameter` column (a curve's), the located [`FitError`].
    pub fn fit_surface(
        &self,
        grid: Option<[usize; 2]>,
        options: &SurfaceFitOptions,
    ) -> Result<SurfaceFit, InputError> {
        if self.dimension() != 3 {
            return Err(self
                .file_error("a surface is fitted to points in 3-D: the data needs a `z` column"));
        }
        if self.parameters.is_some() {
            return Err(self.file_error(
                "column `parameter` is a curve's parameter: give a surface's parameters as \
                 columns `u` and `v`",
            ));
        }
        let positions = self.positions().to_vec();
        let degrees = self.degrees.clone();
        let data = match grid {
            Some([rows, cols]) => SurfaceFitData::grid(rows, cols, positions, degrees),
            None => SurfaceFitData::scattered(positions, degrees),
        };
        let mut data = data.map_err(|e| self.locate(&e))?;
        if let Some(second) = &self.second_lane {
            data = data
                .with_second_lane(second.clone())
                .map_err(|e| self.locate(&e))?;
        }
        if let Some(uv) = &self.surface_parameters {
            data = data
                .with_parameters(uv.clone())
                .map_err(|e| self.locate(&e))?;
        }
        if let Some(weights) = &self.weights {
            data = data
                .with_weights(weights.clone())
                .map_err(|e| self.locate(&e))?;
        }
        fit_surface(&data, options).map_err(|e| self.locate(&e))
    }

    /// An error about the whole file.
    fn file_error(&self, message: &str) -> InputError {
        InputError::new(self.file(), None, None, message.to_owned())
    }

    /// A fitting error located in this file: an error about one point names the point's line
    /// (`data.csv:7: repeats the parameter of line 6 ...`), any other names the file.
    pub fn locate(&self, error: &FitError) -> InputError {
        let at = |index: usize, field: Option<&str>, message: String| {
            let line = self.line_at(index);
            InputError::new(self.file(), line, field.map(str::to_owned), message)
        };
        match error {
            FitError::NotFinite {
                index,
                field,
                value,
            } => at(
                *index,
                Some(&format!("column `{field}`")),
                format!("{field} = {value} is not a finite number"),
            ),
            FitError::WeightNotPositive { index, value } => {
                at(*index, Some("column `weight`"), weight_message(*value))
            }
            FitError::ParameterDecreasing {
                index,
                value,
                previous,
            } => at(
                *index,
                Some("column `parameter`"),
                format!(
                    "parameter = {value} is less than the previous point's {previous} \
                     (parameters must be non-decreasing, in the order of the rows)"
                ),
            ),
            FitError::Degrees { index, source } => at(*index, None, source.to_string()),
            FitError::RepeatedParameter {
                index,
                previous,
                value,
                rule,
            } => {
                let previous = self.line_at(*previous).unwrap_or_default();
                at(
                    *index,
                    None,
                    format!("repeats the parameter of line {previous} (t = {value}): {rule}"),
                )
            }
            FitError::RepeatedPoint { index, previous } => {
                let previous = self.line_at(*previous).unwrap_or_default();
                at(
                    *index,
                    None,
                    format!(
                        "repeats the position of line {previous}: chord-length and centripetal \
                         parameters need distinct consecutive points (remove it, give a \
                         `parameter` column, or use uniform parameters)"
                    ),
                )
            }
            other => InputError::new(self.file(), None, None, other.to_string()),
        }
    }

    /// The line of point `index`, when it is a point of the table.
    fn line_at(&self, index: usize) -> Option<usize> {
        (index < self.len()).then(|| self.line(index))
    }
}

/// The message for a data weight that is not a positive finite number.
fn weight_message(value: f64) -> String {
    format!(
        "weight = {value} is not positive (a data weight scales how strongly the point pulls \
         the curve: it must be a positive finite number)"
    )
}

/// Reads a data table from a CSV file.
///
/// # Errors
/// The file cannot be read, or is invalid: see [`read_data`].
pub fn load_data(path: impl AsRef<Path>, membership: Family) -> Result<DataTable, ReadError> {
    load_data_with(path, membership, &TableInput::default())
}

/// Reads a data table from a CSV file (`.csv`, `.txt`; `.tsv` tab-separated) as `input`
/// says ([`TableInput`]: delimiter, decimal comma, columns mapped or left out).
///
/// # Errors
/// Another extension ([`ReadError::Format`]; a spreadsheet says how to save it as CSV), the
/// file cannot be read, or is invalid: see [`read_data`].
pub fn load_data_with(
    path: impl AsRef<Path>,
    membership: Family,
    input: &TableInput,
) -> Result<DataTable, ReadError> {
    let path = path.as_ref();
    let source = open_table(path, "a .csv file of data points", input)?;
    read_data_with(&source.shown, source.reader, membership, &source.input)
}

/// Reads a data table from a CSV stream, one line at a time; `file` names it in errors.
///
/// # Errors
/// A located [`InputError`]: an empty file, a missing, unknown or repeated column, a row with
/// the wrong number of cells, a value that is not a finite number, degrees that break the
/// membership rule, a weight that is not positive, no data rows; or the stream cannot be read.
pub fn read_data(
    file: &str,
    reader: impl BufRead,
    membership: Family,
) -> Result<DataTable, ReadError> {
    read_data_with(file, reader, membership, &TableInput::default())
}

/// [`read_data`] as `input` says ([`TableInput`]).
///
/// # Errors
/// As [`read_data`]; a column that `input` maps or leaves out but the header lacks.
pub fn read_data_with(
    file: &str,
    reader: impl BufRead,
    membership: Family,
    input: &TableInput,
) -> Result<DataTable, ReadError> {
    let column = |heading: &str| {
        Column::from_name(heading).ok_or_else(|| {
            format!(
                "unknown column `{heading}` (known columns: {})",
                Column::known_list(membership)
            )
        })
    };
    let columns = Columns {
        example: "`x,y,truth,indeterminacy,falsity`",
        column: &column,
        repeat_rule: duplicate_rule(),
        rows: "data points",
    };
    let mut rows = Table::open(file, reader, &columns, input)?;
    for f in [Field::X, Field::Y] {
        rows.require(
            Column::Field(f),
            f.name(),
            "every data point needs x, y and its truth",
        )?;
    }
    // The degree columns the family needs: truth and the rule's others, or a wide family's
    // channels; a channel of another family is refused by name.
    let present = present_channels(
        |f| rows.has(Column::Field(f)),
        |c| rows.has(Column::Channel(c)),
    );
    if let Some(message) = channel_problem(membership, &present, "column") {
        return Err(rows.header_error(message).into());
    }
    if membership.fits_degrees() {
        rows.require(
            Column::Field(Field::Truth),
            Field::Truth.name(),
            "every data point needs x, y and its truth",
        )?;
        require_degrees(&rows, membership, Column::Field)?;
    }
    for (given, missing) in [(Column::U, "v"), (Column::V, "u")] {
        if rows.has(given) && !rows.has(if missing == "v" { Column::V } else { Column::U }) {
            let given = if missing == "v" { "u" } else { "v" };
            return Err(InputError::new(
                file,
                None,
                None,
                format!(
                    "column `{given}` without column `{missing}`: a surface's parameters are \
                     given as both"
                ),
            )
            .into());
        }
    }
    let dimension = if rows.has(Column::Field(Field::Z)) {
        3
    } else {
        2
    };
    let mut table = DataTable {
        points: PointTable::new(file, dimension),
        degrees: Vec::new(),
        parameters: rows.has(Column::Parameter).then(Vec::new),
        surface_parameters: rows.has(Column::U).then(Vec::new),
        weights: rows.has(Column::Field(Field::Weight)).then(Vec::new),
        names: Vec::new(),
        second_lane: (!membership.fits_degrees()).then(Vec::new),
    };
    while let Some(row) = rows.next_row()? {
        let mut values = [None::<f64>; Field::ALL.len()];
        let mut wide = [None::<f64>; WIDE_CHANNELS.len()];
        let mut parameter = None;
        let mut uv = [0.0; 2];
        let mut name = None;
        for cell in row.cells() {
            if cell.column == Column::Field(Field::Name) {
                name = (!cell.text.is_empty()).then(|| cell.text.to_owned());
                continue;
            }
            let value = row.number(&cell)?;
            match cell.column {
                Column::Parameter => parameter = Some(value),
                Column::Channel(c) => wide[c] = Some(value),
                Column::U => uv[0] = value,
                Column::V => uv[1] = value,
                Column::Field(Field::Weight) if value <= 0.0 => {
                    return Err(row.cell_error(&cell, weight_message(value)).into())
                }
                Column::Field(field) => values[field.index()] = Some(value),
            }
        }
        let get = |f: Field| values[f.index()];
        match &mut table.second_lane {
            None => table.degrees.push(read_degrees(&row, membership, &values)?),
            Some(second) => {
                let value = |name: &str| match wide_channel(name, false) {
                    Some(c) => wide[c],
                    None => Field::from_name(name, false).and_then(|f| values[f.index()]),
                };
                let (first, other) =
                    wide_lanes(membership, value).map_err(|e| row.error(None, e.to_string()))?;
                table.degrees.push(first);
                second.push(other);
            }
        }
        table.points.push(
            [
                get(Field::X).unwrap_or_default(),
                get(Field::Y).unwrap_or_default(),
                get(Field::Z).unwrap_or_default(),
            ],
            row.line(),
        );
        if let (Some(list), Some(value)) = (&mut table.parameters, parameter) {
            list.push(value);
        }
        if let Some(list) = &mut table.surface_parameters {
            list.push(uv);
        }
        if let (Some(list), Some(value)) = (&mut table.weights, get(Field::Weight)) {
            list.push(value);
        }
        table.names.push(name);
    }
    Ok(table)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn read(text: &str, membership: Family) -> Result<DataTable, String> {
        read_data("d.csv", text.as_bytes(), membership).map_err(|e| e.to_string())
    }

    #[test]
    fn reads_columns_in_any_order_with_comments() {
        let table = read(
            "# survey\nname,parameter,F,I,T,z,y,x,weight\n\nA,0,0.1,0.2,0.7,3,2,1,0.5\n\
             # gap\n,0.5,0,0,1,6,5,4,2\n",
            Family::Neutrosophic,
        )
        .unwrap();
        assert_eq!(table.dimension(), 3);
        assert_eq!(table.positions(), &[[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]]);
        assert_eq!(table.degrees()[0].to_array(), [0.7, 0.2, 0.1]);
        assert_eq!(table.parameters(), Some(&[0.0, 0.5][..]));
        assert_eq!(table.weights(), Some(&[0.5, 2.0][..]));
        assert_eq!(table.names(), &[Some("A".to_owned()), None]);
        assert_eq!((table.line(0), table.line(1)), (4, 6));
    }

    #[test]
    fn intuitionistic_data_needs_no_indeterminacy_column() {
        let table = read("x,y,truth,falsity\n0,0,0.6,0.3\n", Family::Intuitionistic).unwrap();
        let [t, i, f] = table.degrees()[0].to_array();
        assert_eq!((t, f), (0.6, 0.3));
        assert!((i - 0.1).abs() < 1e-15);
    }

    #[test]
    fn errors_are_located() {
        let cases: &[(&str, &str)] = &[
            ("", "d.csv: empty file (expected a header row such as `x,y,truth,indeterminacy,falsity`)"),
            ("x,y,truth,indeterminacy,falsity\n", "d.csv: no data points (the header row is not followed by any data row)"),
            ("x,truth,indeterminacy,falsity\n1,0,0,0\n", "d.csv:1: missing column `y` (every data point needs x, y and its truth)"),
            ("x,y,truth,indeterminacy\n1,2,0,0\n", "d.csv:1: missing column `falsity` (neutrosophic rule requires it)"),
            ("x,y,t,truth,I,F\n", "d.csv:1: column 4 `truth` repeats column 3 `t` (each field may appear once; T, I and F are aliases of truth, indeterminacy and falsity)"),
            ("x,y,T,I,F,q\n", "d.csv:1: unknown column `q` (known columns: x, y, z, truth (T), indeterminacy (I), falsity (F), weight, name, parameter, u, v)"),
            ("x,y,z,T,I,F,u\n", "d.csv: column `u` without column `v`: a surface's parameters are given as both"),
            ("x,y,T,I,F\n1,2,0.5,0.5\n", "d.csv:2: the row has 4 cells but the header has 5 (every row needs one cell per column)"),
            ("x,y,T,I,F\n1,nan,0.5,0.5,0\n", "d.csv:2: column `y`: value `nan` is not a finite number (NaN and infinities are not allowed)"),
            ("x,y,T,I,F\n1,2,1.5,0.5,0\n", "d.csv:2: truth = 1.5 is outside [0, 1] (every degree must be in [0, 1])"),
            ("x,y,T,I,F,weight\n1,2,0.5,0.5,0,1\n1,2,0.5,0.5,0,-2\n", "d.csv:3: column `weight`: weight = -2 is not positive (a data weight scales how strongly the point pulls the curve: it must be a positive finite number)"),
            ("x,y,T,I,F,parameter\n1,2,0.5,0.5,0,inf\n", "d.csv:2: column `parameter`: value `inf` is not a finite number (NaN and infinities are not allowed)"),
        ];
        for (text, want) in cases {
            assert_eq!(
                read(text, Family::Neutrosophic).unwrap_err(),
                *want,
                "{text:?}"
            );
        }
    }

    #[test]
    fn wide_families_read_their_channels_into_two_lanes() {
        let table = read(
            "x,y,negative_falsity,truth,indeterminacy,falsity,negative_truth,\
             negative_indeterminacy\n0,0,-0.1,0.7,0.2,0.1,-0.3,-0.4\n",
            Family::BipolarNeutrosophic,
        )
        .unwrap();
        assert_eq!(table.degrees()[0].to_array(), [0.7, 0.2, 0.1]);
        // The negative lane holds the negative degrees negated.
        assert_eq!(table.second_lane().unwrap()[0].to_array(), [0.3, 0.4, 0.1]);
        let one = read("x,y,T,I,F\n0,0,0.5,0.2,0.1\n", Family::Neutrosophic).unwrap();
        assert!(one.second_lane().is_none());
        let cases: &[(&str, Family, &str)] = &[
            (
                "x,y,truth_lower\n0,0,0.1\n",
                Family::IntervalType2,
                "d.csv:1: missing column `truth_upper` (interval-type2 rule requires it)",
            ),
            (
                "x,y,truth_lower,truth_upper,truth\n",
                Family::IntervalType2,
                "d.csv:1: column `truth` does not apply to membership interval-type2 (its \
                 channels: truth_lower, truth_upper)",
            ),
            (
                "x,y,truth_lower,truth_upper\n0,0,0.6,0.4\n",
                Family::IntervalType2,
                "d.csv:2: truth_lower = 0.6 exceeds truth_upper = 0.4 (interval-type2 rule: \
                 lower <= upper)",
            ),
            (
                "x,y,truth,falsity,truth_upper\n",
                Family::Intuitionistic,
                "d.csv:1: column `truth_upper` does not apply to membership intuitionistic (its \
                 channels: truth, falsity); `truth_upper` is a channel of \
                 interval-neutrosophic, interval-intuitionistic, interval-type2",
            ),
        ];
        for (text, family, want) in cases {
            assert_eq!(read(text, *family).unwrap_err(), *want, "{text:?}");
        }
    }

    #[test]
    fn fit_errors_name_the_line() {
        let table = read(
            "x,y,T,I,F,parameter\n0,0,1,0,0,0\n# note\n1,1,1,0,0,0.5\n2,0,1,0,0,0.25\n",
            Family::Neutrosophic,
        )
        .unwrap();
        let error = table.fit(&FitOptions::default()).unwrap_err();
        assert_eq!(
            error.to_string(),
            "d.csv:5: column `parameter`: parameter = 0.25 is less than the previous point's \
             0.5 (parameters must be non-decreasing, in the order of the rows)"
        );
    }
}
