//! Tables of query points: positions only, one per CSV row (columns `x`, `y`, optional `z`
//! and an optional `name`), for commands that ask questions about a model at given points
//! (the nearest point of a curve or surface). Comments, empty lines, quoting, CRLF and a byte
//! order mark as in control-point CSV files; line numbers in errors are physical lines.
//!
//! ```
//! use neutrospline_io::read_points;
//!
//! let table = read_points("q.csv", "x,y\n0,0\n# a comment\n1.5,2\n".as_bytes())?;
//! assert_eq!((table.len(), table.dimension()), (2, 2));
//! assert_eq!(table.positions()[1], [1.5, 2.0, 0.0]);
//! assert_eq!(table.line(1), 4);
//!
//! let bad = read_points("q.csv", "x,y\n0,inf\n".as_bytes()).unwrap_err();
//! assert_eq!(
//!     bad.to_string(),
//!     "q.csv:2: column `y`: value `inf` is not a finite number (NaN and infinities are not allowed)"
//! );
//! # Ok::<(), neutrospline_io::ReadError>(())
//! ```

use std::io::BufRead;
use std::path::Path;

use crate::csv::{Columns, Table};
use crate::read::open_table;
use crate::{ReadError, TableInput};

/// Query points read from a CSV file, with the line each was read from.
#[derive(Debug, Clone, PartialEq)]
pub struct PointTable {
    file: String,
    dimension: usize,
    positions: Vec<[f64; 3]>,
    lines: Vec<usize>,
}

impl PointTable {
    /// The file as named by the caller.
    pub fn file(&self) -> &str {
        &self.file
    }

    /// 2 (columns `x`, `y`) or 3 (with `z`).
    pub fn dimension(&self) -> usize {
        self.dimension
    }

    /// The number of points.
    pub fn len(&self) -> usize {
        self.positions.len()
    }

    /// Whether there are no points (never true for a table that was read).
    pub fn is_empty(&self) -> bool {
        self.positions.is_empty()
    }

    /// The positions, `z = 0` for 2-D points.
    pub fn positions(&self) -> &[[f64; 3]] {
        &self.positions
    }

    /// The physical line (1-based) point `index` was read from.
    ///
    /// # Panics
    /// When `index` is not a point of the table.
    pub fn line(&self, index: usize) -> usize {
        self.lines[index]
    }
}

/// The columns of a point table.
const COLUMNS: [&str; 4] = ["x", "y", "z", "name"];

impl PointTable {
    /// A table of `file` without points yet.
    pub(crate) fn new(file: &str, dimension: usize) -> PointTable {
        PointTable {
            file: file.to_owned(),
            dimension,
            positions: Vec::new(),
            lines: Vec::new(),
        }
    }

    /// The positions' first [`PointTable::dimension`] coordinates, point after point (the
    /// layout of [`neutrospline::fit::fit_rows`]).
    pub(crate) fn flat_positions(&self) -> Vec<f64> {
        let d = self.dimension;
        self.positions
            .iter()
            .flat_map(|p| p[..d].to_vec())
            .collect()
    }

    /// Adds the point at `position` read from `line`.
    pub(crate) fn push(&mut self, position: [f64; 3], line: usize) {
        self.positions.push(position);
        self.lines.push(line);
    }
}

/// Reads a table of query points from a CSV file.
///
/// # Errors
/// The file cannot be read, or is invalid: see [`read_points`].
pub fn load_points(path: impl AsRef<Path>) -> Result<PointTable, ReadError> {
    load_points_with(path, &TableInput::default())
}

/// Reads a table of query points from a CSV file (`.csv`, `.txt`; `.tsv` tab-separated) as
/// `input` says ([`TableInput`]).
///
/// # Errors
/// Another extension ([`ReadError::Format`]), the file cannot be read, or is invalid: see
/// [`read_points`].
pub fn load_points_with(
    path: impl AsRef<Path>,
    input: &TableInput,
) -> Result<PointTable, ReadError> {
    let path = path.as_ref();
    let source = open_table(path, "a .csv file of query points", input)?;
    read_points_with(&source.shown, source.reader, &source.input)
}

/// Reads a table of query points from a CSV stream, one line at a time; `file` names it in
/// errors.
///
/// # Errors
/// A located [`InputError`](crate::InputError): an empty file, a missing, unknown or repeated
/// column, a row with the wrong number of cells, a value that is not a finite number, no
/// points; or the stream cannot be read.
pub fn read_points(file: &str, reader: impl BufRead) -> Result<PointTable, ReadError> {
    read_points_with(file, reader, &TableInput::default())
}

/// [`read_points`] as `input` says ([`TableInput`]).
///
/// # Errors
/// As [`read_points`]; a column that `input` maps or leaves out but the header lacks.
pub fn read_points_with(
    file: &str,
    reader: impl BufRead,
    input: &TableInput,
) -> Result<PointTable, ReadError> {
    // A column is its index in COLUMNS.
    let column = |heading: &str| {
        COLUMNS
            .iter()
            .position(|c| c.eq_ignore_ascii_case(heading))
            .ok_or_else(|| {
                format!("unknown column `{heading}` (known columns of query points: x, y, z, name)")
            })
    };
    let columns = Columns {
        example: "`x,y` or `x,y,z`",
        column: &column,
        repeat_rule: "each column may appear once",
        rows: "query points",
    };
    let mut rows = Table::open(file, reader, &columns, input)?;
    for (k, name) in COLUMNS[..2].iter().enumerate() {
        rows.require(k, name, "every query point needs x and y")?;
    }
    let mut table = PointTable::new(file, if rows.has(2) { 3 } else { 2 });
    while let Some(row) = rows.next_row()? {
        let mut position = [0.0; 3];
        for cell in row.cells().filter(|cell| cell.column != 3) {
            position[cell.column] = row.number(&cell)?;
        }
        table.push(position, row.line());
    }
    Ok(table)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn read(text: &str) -> Result<PointTable, String> {
        read_points("q.csv", text.as_bytes()).map_err(|e| e.to_string())
    }

    #[test]
    fn point_table_reads_columns_in_any_order() {
        let t = read("\u{feff}name,Z,y,X\r\nA,3,2,1\r\n\r\n,6,5,4\r\n").unwrap();
        assert_eq!(t.dimension(), 3);
        assert_eq!(t.positions(), &[[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]]);
        assert_eq!((t.line(0), t.line(1)), (2, 4));
        assert_eq!(t.file(), "q.csv");
    }

    #[test]
    fn point_table_errors_are_located() {
        let cases: &[(&str, &str)] = &[
            ("", "q.csv: empty file (expected a header row such as `x,y` or `x,y,z`)"),
            ("x,y\n", "q.csv: no query points (the header row is not followed by any data row)"),
            ("x,z\n1,2\n", "q.csv:1: missing column `y` (every query point needs x and y)"),
            ("x,y,truth\n", "q.csv:1: unknown column `truth` (known columns of query points: x, y, z, name)"),
            ("x,y,X\n", "q.csv:1: column 3 `X` repeats column 1 `x` (each column may appear once)"),
            ("x,y\n1,2,3\n", "q.csv:2: the row has 3 cells but the header has 2 (every row needs one cell per column)"),
            ("x,y\n1,2\n1,two\n", "q.csv:3: column `y`: value `two` is not a number"),
        ];
        for (text, want) in cases {
            assert_eq!(read(text).unwrap_err(), *want, "{text:?}");
        }
    }
}
