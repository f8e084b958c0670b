//! Tables of the paper's Def. 4 (docs/model.md section 2): an axis set (a neutrosophic set on
//! one axis, one member per row: its coordinate `value`, also called `r` on the first axis M
//! and `s` on the second axis N, and its `truth`, `indeterminacy`, `falsity`, aliases `T`,
//! `I`, `F`, each in \[0, 1\]) and a list of pairs (columns `r`, `s`) that orders a relation.
//! Comments, empty lines, quoting, CRLF and a byte order mark as in control-point CSV files;
//! line numbers in errors are physical lines.
//!
//! ```
//! use neutrospline::AxisSetName;
//! use neutrospline_io::read_axis_set;
//!
//! let m = read_axis_set("m.csv", "r,T,I,F\n1,0.3,0.6,0.1\n2,0.8,0.1,0.1\n".as_bytes(), AxisSetName::M)?;
//! assert_eq!(m.set().degrees_at(2.0).unwrap().truth(), 0.8);
//! assert_eq!(m.line_of(2.0), Some(3));
//!
//! let bad = read_axis_set("m.csv", "value,T,I,F\n1,0.3,0.6,0.1\n1,0.5,0,0\n".as_bytes(), AxisSetName::M);
//! assert_eq!(
//!     bad.unwrap_err().to_string(),
//!     "m.csv:3: column `value`: value = 1 repeats line 2 (a set gives each value one set of degrees)"
//! );
//! # Ok::<(), neutrospline_io::ReadError>(())
//! ```

use std::io::BufRead;
use std::path::Path;

use neutrospline::{AxisSet, AxisSetName, Degrees, RelationError};

use crate::csv::{Columns, Table};
use crate::read::open_table;
use crate::{InputError, ReadError, TableInput};

/// An axis set read from a CSV file, with the line each member was read from.
#[derive(Debug, Clone, PartialEq)]
pub struct AxisTable {
    file: String,
    set: AxisSet,
    lines: Vec<usize>,
}

impl AxisTable {
    /// The file as named by the caller.
    pub fn file(&self) -> &str {
        &self.file
    }

    /// The axis set.
    pub fn set(&self) -> &AxisSet {
        &self.set
    }

    /// The physical line (1-based) of the member whose coordinate is `value`, if any.
    pub fn line_of(&self, value: f64) -> Option<usize> {
        let index = self.set.members().iter().position(|(v, _)| *v == value)?;
        self.lines.get(index).copied()
    }
}

/// A list of pairs `(r, s)` read from a CSV file, in order.
#[derive(Debug, Clone, PartialEq)]
pub struct PairTable {
    file: String,
    pairs: Vec<(f64, f64)>,
    lines: Vec<usize>,
}

impl PairTable {
    /// The file as named by the caller.
    pub fn file(&self) -> &str {
        &self.file
    }

    /// The pairs, in the order of the rows.
    pub fn pairs(&self) -> &[(f64, f64)] {
        &self.pairs
    }

    /// The physical line (1-based) pair `index` was read from.
    ///
    /// # Panics
    /// When `index` is not a pair of the table.
    pub fn line(&self, index: usize) -> usize {
        self.lines[index]
    }
}

/// A column of an axis set: the coordinate, then the three degrees.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum AxisColumn {
    Value,
    Degree(usize),
}

/// The degree columns with their aliases, in the order of [`Degrees::to_array`].
const DEGREE_COLUMNS: [(&str, &str); 3] =
    [("truth", "T"), ("indeterminacy", "I"), ("falsity", "F")];

/// Reads an axis set from a CSV file.
///
/// # Errors
/// The file cannot be read, or is invalid: see [`read_axis_set`].
pub fn load_axis_set(path: impl AsRef<Path>, name: AxisSetName) -> Result<AxisTable, ReadError> {
    load_axis_set_with(path, name, &TableInput::default())
}

/// [`load_axis_set`] as `input` says ([`TableInput`]: delimiter, decimal comma, column
/// names); a `.tsv` file is tab-separated.
///
/// # Errors
/// Another extension than a table's ([`ReadError::Format`]); as [`read_axis_set_with`].
pub fn load_axis_set_with(
    path: impl AsRef<Path>,
    name: AxisSetName,
    input: &TableInput,
) -> Result<AxisTable, ReadError> {
    let path = path.as_ref();
    let source = open_table(path, "a .csv file of an axis set", input)?;
    read_axis_set_with(&source.shown, source.reader, name, &source.input)
}

/// Reads the axis set `name` (M: coordinates `r`, N: `s`) from a CSV stream; `file` names it
/// in errors.
///
/// # Errors
/// A located [`InputError`]: an empty file, a missing, unknown or repeated column, a row with
/// the wrong number of cells, a value that is not a finite number, degrees outside \[0, 1\],
/// a coordinate listed twice, no members; or the stream cannot be read.
pub fn read_axis_set(
    file: &str,
    reader: impl BufRead,
    name: AxisSetName,
) -> Result<AxisTable, ReadError> {
    read_axis_set_with(file, reader, name, &TableInput::default())
}

/// [`read_axis_set`] as `input` says ([`TableInput`]).
///
/// # Errors
/// As [`read_axis_set`]; a column that `input` maps or leaves out but the header lacks.
pub fn read_axis_set_with(
    file: &str,
    reader: impl BufRead,
    name: AxisSetName,
    input: &TableInput,
) -> Result<AxisTable, ReadError> {
    let letter = match name {
        AxisSetName::M => "r",
        AxisSetName::N => "s",
    };
    let column = |heading: &str| {
        if heading.eq_ignore_ascii_case("value") || heading.eq_ignore_ascii_case(letter) {
            return Ok(AxisColumn::Value);
        }
        DEGREE_COLUMNS
            .iter()
            .position(|(full, alias)| heading.eq_ignore_ascii_case(full) || heading == *alias)
            .map(AxisColumn::Degree)
            .ok_or_else(|| {
                format!(
                    "unknown column `{heading}` (known columns of the axis set {name}: value \
                     ({letter}), truth (T), indeterminacy (I), falsity (F))"
                )
            })
    };
    let example = format!("`value,truth,indeterminacy,falsity` or `{letter},T,I,F`");
    let rows_name = format!("members of the axis set {name}");
    let columns = Columns {
        example: &example,
        column: &column,
        repeat_rule: "each column may appear once",
        rows: &rows_name,
    };
    let mut rows = Table::open(file, reader, &columns, input)?;
    rows.require(
        AxisColumn::Value,
        "value",
        "every member of an axis set needs its coordinate",
    )?;
    for (k, (full, _)) in DEGREE_COLUMNS.iter().enumerate() {
        rows.require(
            AxisColumn::Degree(k),
            full,
            "the paper's Def. 4 gives every member truth, indeterminacy and falsity",
        )?;
    }
    let mut members = Vec::new();
    let mut lines: Vec<usize> = Vec::new();
    while let Some(row) = rows.next_row()? {
        let mut value = 0.0;
        let mut degrees = [0.0; 3];
        for cell in row.cells() {
            let number = row.number(&cell)?;
            match cell.column {
                AxisColumn::Value => value = number,
                AxisColumn::Degree(k) => degrees[k] = number,
            }
        }
        let degrees = Degrees::new(degrees[0], degrees[1], degrees[2])
            .map_err(|e| row.error(None, e.to_string()))?;
        if let Some(first) = members.iter().position(|(v, _)| *v == value) {
            return Err(row
                .error(
                    Some("column `value`".to_owned()),
                    format!(
                        "value = {value} repeats line {} (a set gives each value one set of \
                         degrees)",
                        lines[first]
                    ),
                )
                .into());
        }
        members.push((value, degrees));
        lines.push(row.line());
    }
    let set = AxisSet::new(name, members).map_err(|e| unlocated(file, &e))?;
    Ok(AxisTable {
        file: file.to_owned(),
        set,
        lines,
    })
}

/// Reads a list of pairs from a CSV file.
///
/// # Errors
/// The file cannot be read, or is invalid: see [`read_pairs`].
pub fn load_pairs(path: impl AsRef<Path>) -> Result<PairTable, ReadError> {
    load_pairs_with(path, &TableInput::default())
}

/// [`load_pairs`] as `input` says ([`TableInput`]); a `.tsv` file is tab-separated.
///
/// # Errors
/// Another extension than a table's ([`ReadError::Format`]); as [`read_pairs_with`].
pub fn load_pairs_with(path: impl AsRef<Path>, input: &TableInput) -> Result<PairTable, ReadError> {
    let path = path.as_ref();
    let source = open_table(path, "a .csv file of pairs (r, s)", input)?;
    read_pairs_with(&source.shown, source.reader, &source.input)
}

/// Reads a list of pairs (columns `r`, `s`) from a CSV stream; `file` names it in errors.
///
/// # Errors
/// A located [`InputError`]: an empty file, a missing, unknown or repeated column, a row with
/// the wrong number of cells, a value that is not a finite number, no pairs; or the stream
/// cannot be read.
pub fn read_pairs(file: &str, reader: impl BufRead) -> Result<PairTable, ReadError> {
    read_pairs_with(file, reader, &TableInput::default())
}

/// [`read_pairs`] as `input` says ([`TableInput`]).
///
/// # Errors
/// As [`read_pairs`]; a column that `input` maps or leaves out but the header lacks.
pub fn read_pairs_with(
    file: &str,
    reader: impl BufRead,
    input: &TableInput,
) -> Result<PairTable, ReadError> {
    let column = |heading: &str| {
        ["r", "s"]
            .iter()
            .position(|c| c.eq_ignore_ascii_case(heading))
            .ok_or_else(|| format!("unknown column `{heading}` (known columns of pairs: r, s)"))
    };
    let columns = Columns {
        example: "`r,s`",
        column: &column,
        repeat_rule: "each column may appear once",
        rows: "pairs",
    };
    let mut rows = Table::open(file, reader, &columns, input)?;
    for (k, name) in ["r", "s"].iter().enumerate() {
        rows.require(k, name, "every pair needs r and s")?;
    }
    let mut table = PairTable {
        file: file.to_owned(),
        pairs: Vec::new(),
        lines: Vec::new(),
    };
    while let Some(row) = rows.next_row()? {
        let mut pair = [0.0; 2];
        for cell in row.cells() {
            pair[cell.column] = row.number(&cell)?;
        }
        table.pairs.push((pair[0], pair[1]));
        table.lines.push(row.line());
    }
    Ok(table)
}

/// An error of a whole set (never reached for a set read row by row, whose rows are checked
/// as they are read), named by its file.
fn unlocated(file: &str, error: &RelationError) -> ReadError {
    InputError::new(file, None, None, error.to_string()).into()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn axis(text: &str, name: AxisSetName) -> Result<AxisTable, String> {
        read_axis_set("a.csv", text.as_bytes(), name).map_err(|e| e.to_string())
    }

    #[test]
    fn axis_sets_read_in_any_column_order_with_either_coordinate_name() {
        let m = axis(
            "# M\nF,I,T,r\n0.1,0.6,0.3,1\n\n0.2,0.1,0.7,2.5\n",
            AxisSetName::M,
        )
        .unwrap();
        let members = m.set().members();
        assert_eq!(members.len(), 2);
        assert_eq!(members[1].0, 2.5);
        assert_eq!(members[1].1.to_array(), [0.7, 0.1, 0.2]);
        assert_eq!(
            (m.line_of(1.0), m.line_of(2.5), m.line_of(3.0)),
            (Some(3), Some(5), None)
        );
        let n = axis(
            "s,truth,indeterminacy,falsity\n3,0.5,0.2,0.4\n",
            AxisSetName::N,
        )
        .unwrap();
        assert_eq!(n.set().name(), AxisSetName::N);
        assert_eq!(n.file(), "a.csv");
    }

    #[test]
    fn axis_set_errors_are_located() {
        let cases: &[(&str, AxisSetName, &str)] = &[
            ("", AxisSetName::M, "a.csv: empty file (expected a header row such as `value,truth,indeterminacy,falsity` or `r,T,I,F`)"),
            ("r,T,I,F\n", AxisSetName::M, "a.csv: no members of the axis set M (the header row is not followed by any data row)"),
            ("s,T,I,F\n", AxisSetName::M, "a.csv:1: unknown column `s` (known columns of the axis set M: value (r), truth (T), indeterminacy (I), falsity (F))"),
            ("s,T,I\n1,0,0\n", AxisSetName::N, "a.csv:1: missing column `falsity` (the paper's Def. 4 gives every member truth, indeterminacy and falsity)"),
            ("T,I,F\n1,0,0\n", AxisSetName::N, "a.csv:1: missing column `value` (every member of an axis set needs its coordinate)"),
            ("s,T,I,F\n1,0.5,0,1.5\n", AxisSetName::N, "a.csv:2: falsity = 1.5 is outside [0, 1] (every degree must be in [0, 1])"),
            ("s,T,I,F\n1,0.5,0,x\n", AxisSetName::N, "a.csv:2: column `F`: value `x` is not a number"),
        ];
        for (text, name, want) in cases {
            assert_eq!(axis(text, *name).unwrap_err(), *want, "{text:?}");
        }
    }

    #[test]
    fn pairs_read_in_order() {
        let t = read_pairs("p.csv", "s,r\n3,1\n# c\n4,2\n".as_bytes()).unwrap();
        assert_eq!(t.pairs(), &[(1.0, 3.0), (2.0, 4.0)]);
        assert_eq!((t.line(0), t.line(1)), (2, 4));
        let bad = read_pairs("p.csv", "r,t\n".as_bytes()).unwrap_err();
        assert_eq!(
            bad.to_string(),
            "p.csv:1: unknown column `t` (known columns of pairs: r, s)"
        );
    }
}
