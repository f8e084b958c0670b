//! The frame every CSV table of this crate shares (control points, fitting data, query
//! points): a header row that names each column once, then rows of one cell per column, read
//! from [`Records`] one at a time, every error located at its line.

use std::io::BufRead;

use neutrospline::{DegreeError, Degrees, Family};

use super::Records;
use crate::format::too_many_points;
use crate::parsed::{missing_degree, parse_number, Field};
use crate::{InputError, TableInput};

/// A CSV table being read: its header read, its rows read one at a time by
/// [`Table::next_row`]. `C` is what a column holds (each reader has its own columns).
pub(crate) struct Table<'f, R, C> {
    file: &'f str,
    records: Records<R>,
    header: ::csv::StringRecord,
    header_line: usize,
    /// One per cell of the header; `None` for a column left out.
    columns: Vec<Option<C>>,
    /// Numbers have a decimal comma.
    decimal_comma: bool,
    /// At most this many rows are read; the next one is refused.
    max_rows: Option<u64>,
    /// The rows read so far.
    rows: u64,
    /// What the rows are ([`Columns::rows`]).
    rows_name: String,
}

/// How a reader names its columns: what [`Table::open`] needs to read a header.
pub(crate) struct Columns<'a, C> {
    /// A header row for the empty-file message (`` `x,y` or `x,y,z` ``).
    pub(crate) example: &'a str,
    /// The column a heading names, or the message for an unknown heading.
    pub(crate) column: &'a dyn Fn(&str) -> Result<C, String>,
    /// Why a column may not repeat, for the message of a repeated column.
    pub(crate) repeat_rule: &'a str,
    /// What the rows are (`query points`), for the message of a table without rows.
    pub(crate) rows: &'a str,
}

impl<'f, R: BufRead, C: Copy + PartialEq> Table<'f, R, C> {
    /// Reads the header row of `reader` (the first row that is not a comment or empty),
    /// `file` naming it in errors.
    ///
    /// # Errors
    /// An empty file (no header row), a heading that names no column, a column named twice
    /// (`column 4 `T` repeats column 3 `truth``), a column that `input` maps or leaves out
    /// but the header does not have, and every error of [`Records`]. `input` gives the
    /// delimiter, the decimal comma, and which columns are read as which or left out.
    pub(crate) fn open(
        file: &'f str,
        reader: R,
        columns: &Columns<'_, C>,
        input: &TableInput,
    ) -> Result<Table<'f, R, C>, InputError> {
        let mut records = Records::new(reader, input.delimiter);
        let Some((header_line, header)) = records.next_cells(file)? else {
            return Err(InputError::new(
                file,
                None,
                None,
                format!(
                    "empty file (expected a header row such as {})",
                    columns.example
                ),
            ));
        };
        let mut table = Table {
            file,
            records,
            header: ::csv::StringRecord::new(),
            header_line,
            columns: Vec::with_capacity(header.len()),
            decimal_comma: input.decimal_comma,
            max_rows: None,
            rows: 0,
            rows_name: columns.rows.to_owned(),
        };
        if input.decimal_comma && table.records.delimiter() == b',' {
            return Err(table.header_error(
                "the cells are separated by commas, so numbers cannot have a decimal comma \
                 (--decimal-comma): save the file with another delimiter, such as ;"
                    .to_owned(),
            ));
        }
        let has = |name: &str| header.iter().any(|h| h.eq_ignore_ascii_case(name));
        for (ours, theirs) in &input.columns {
            if !has(theirs) {
                return Err(table.header_error(format!(
                    "--columns {ours}={theirs}: the header has no column `{theirs}`"
                )));
            }
        }
        if let Some(name) = input.ignore_columns.iter().find(|name| !has(name)) {
            return Err(table.header_error(format!(
                "--ignore-columns {name}: the header has no column `{name}`"
            )));
        }
        for (i, heading) in header.iter().enumerate() {
            if input.ignores(heading) {
                table.columns.push(None);
                continue;
            }
            let column = match (columns.column)(input.ours(heading).unwrap_or(heading)) {
                Ok(column) => column,
                Err(_) if input.ignore_unknown_columns => {
                    table.columns.push(None);
                    continue;
                }
                Err(m) => return Err(table.header_error(unknown_hint(m, heading))),
            };
            if let Some(j) = table.columns.iter().position(|&c| c == Some(column)) {
                return Err(table.header_error(format!(
                    "column {} `{heading}` repeats column {} `{}` ({})",
                    i + 1,
                    j + 1,
                    header.get(j).unwrap_or_default(),
                    columns.repeat_rule
                )));
            }
            table.columns.push(Some(column));
        }
        table.header = header;
        Ok(table)
    }

    /// The same table, refusing any row after the first `max_rows` ([`too_many_points`]).
    pub(crate) fn with_max_rows(mut self, max_rows: u64) -> Table<'f, R, C> {
        self.max_rows = Some(max_rows);
        self
    }

    /// The columns read (not left out), each with its heading, in the header's order.
    pub(crate) fn named_columns(&self) -> impl Iterator<Item = (C, &str)> {
        self.columns
            .iter()
            .zip(self.header.iter())
            .filter_map(|(c, h)| c.map(|c| (c, h)))
    }

    /// Whether the header names `column`.
    pub(crate) fn has(&self, column: C) -> bool {
        self.columns.contains(&Some(column))
    }

    /// An error at the header's line.
    pub(crate) fn header_error(&self, message: String) -> InputError {
        InputError::new(self.file, Some(self.header_line), None, message)
    }

    /// Refuses a header without `column`: `missing column `name` (why)`.
    pub(crate) fn require(&self, column: C, name: &str, why: &str) -> Result<(), InputError> {
        if self.has(column) {
            return Ok(());
        }
        Err(self.header_error(format!("missing column `{name}` ({why})")))
    }

    /// The next row (comments and empty lines skipped), `None` at the end of the file.
    ///
    /// # Errors
    /// A file without rows (`no query points (the header row is not followed by any data
    /// row)`), a row past the limit of [`Table::with_max_rows`], a row with another number of
    /// cells than the header, and every error of [`Records`].
    pub(crate) fn next_row(&mut self) -> Result<Option<Row<'_, C>>, InputError> {
        let Some((line, cells)) = self.records.next_cells(self.file)? else {
            if self.rows == 0 {
                return Err(InputError::new(
                    self.file,
                    None,
                    None,
                    format!(
                        "no {} (the header row is not followed by any data row)",
                        self.rows_name
                    ),
                ));
            }
            return Ok(None);
        };
        let row = Row {
            file: self.file,
            line,
            columns: &self.columns,
            headings: &self.header,
            decimal_comma: self.decimal_comma,
            cells,
        };
        if let Some(max) = self.max_rows.filter(|&max| self.rows >= max) {
            return Err(row.error(None, too_many_points(max)));
        }
        if row.cells.len() != self.columns.len() {
            return Err(row.error(
                None,
                format!(
                    "the row has {} cells but the header has {} (every row needs one cell per \
                     column)",
                    row.cells.len(),
                    self.columns.len()
                ),
            ));
        }
        self.rows += 1;
        Ok(Some(row))
    }
}

/// A row of a [`Table`]: one cell per column, with the line it starts on.
pub(crate) struct Row<'t, C> {
    file: &'t str,
    line: usize,
    columns: &'t [Option<C>],
    headings: &'t ::csv::StringRecord,
    decimal_comma: bool,
    cells: ::csv::StringRecord,
}

impl<C: Copy> Row<'_, C> {
    /// The physical line (1-based) the row starts on.
    pub(crate) fn line(&self) -> usize {
        self.line
    }

    /// Each cell (trimmed) of a column read, with its column and the column's heading, in
    /// the header's order.
    pub(crate) fn cells(&self) -> impl Iterator<Item = Cell<'_, C>> {
        self.columns
            .iter()
            .zip(self.cells.iter())
            .zip(self.headings.iter())
            .filter_map(|((&column, text), heading)| {
                column.map(|column| Cell {
                    column,
                    text,
                    heading,
                })
            })
    }

    /// The text of a number in `cell` with a decimal point: with a decimal comma, the comma
    /// becomes a point (a cell with a point then is refused: no thousands separators).
    ///
    /// # Errors
    /// With a decimal comma, a cell that holds a point.
    pub(crate) fn number_text<'c>(
        &self,
        cell: &Cell<'c, C>,
    ) -> Result<std::borrow::Cow<'c, str>, InputError> {
        if !self.decimal_comma {
            return Ok(cell.text.into());
        }
        if cell.text.contains('.') {
            return Err(self.cell_error(
                cell,
                format!(
                    "value `{}` has a point, but --decimal-comma reads numbers with a decimal \
                     comma (and no thousands separators)",
                    cell.text
                ),
            ));
        }
        Ok(cell.text.replace(',', ".").into())
    }

    /// An error at the row's line, in `field` when given.
    pub(crate) fn error(&self, field: Option<String>, message: String) -> InputError {
        InputError::new(self.file, Some(self.line), field, message)
    }

    /// An error about `cell`, at the row's line in the field `column `heading``.
    pub(crate) fn cell_error(&self, cell: &Cell<'_, C>, message: String) -> InputError {
        self.error(Some(format!("column `{}`", cell.heading)), message)
    }

    /// The finite number in `cell` ([`parse_number`]).
    ///
    /// # Errors
    /// A cell that is not a finite number, located at its column.
    pub(crate) fn number(&self, cell: &Cell<'_, C>) -> Result<f64, InputError> {
        let text = self.number_text(cell)?;
        parse_number(&text).map_err(|m| {
            let comma = !self.decimal_comma
                && text.contains(',')
                && text.replace(',', ".").parse::<f64>().is_ok();
            let hint = if comma {
                " (a decimal comma? give --decimal-comma)"
            } else {
                ""
            };
            self.cell_error(cell, format!("{m}{hint}"))
        })
    }
}

/// One cell of a [`Row`].
pub(crate) struct Cell<'r, C> {
    /// What the column holds.
    pub(crate) column: C,
    /// The cell's text, trimmed.
    pub(crate) text: &'r str,
    /// The column's heading as the header writes it.
    pub(crate) heading: &'r str,
}

/// The message for an unknown heading, with a hint when the header looks like one cell of
/// a table with another delimiter.
fn unknown_hint(message: String, heading: &str) -> String {
    if heading.contains([';', '\t', ',']) {
        format!("{message}: the header was read as one cell; give the delimiter with --delimiter")
    } else {
        message
    }
}

/// Refuses a header without a degree column that the `membership` rule requires (`falsity`
/// under the intuitionistic rule, `indeterminacy` and `falsity` under the neutrosophic one);
/// `column` is the table's column of a field.
pub(crate) fn require_degrees<R: BufRead, C: Copy + PartialEq>(
    table: &Table<'_, R, C>,
    membership: Family,
    column: impl Fn(Field) -> C,
) -> Result<(), InputError> {
    let has = |f: Field| table.has(column(f));
    match missing_degree(membership, has(Field::Indeterminacy), has(Field::Falsity)) {
        Some(DegreeError::Missing { kind, membership }) => {
            let hint = if membership == Family::Neutrosophic && !has(Field::Indeterminacy) {
                "; truth and falsity alone are an intuitionistic table (--membership \
                 intuitionistic, indeterminacy 1 - T - F), truth alone a fuzzy one (--membership \
                 fuzzy)"
            } else {
                ""
            };
            Err(table.header_error(format!(
                "missing column `{kind}` ({membership} rule requires it{hint})"
            )))
        }
        _ => Ok(()),
    }
}

/// The degrees of a row from its `values` (indexed by [`Field::index`]), valid under the
/// `membership` rule; a missing truth reads as 0 (the header has the column, so it is never
/// missing in a row that was read).
///
/// # Errors
/// Degrees that break the rule, located at the row's line.
pub(crate) fn read_degrees<C: Copy>(
    row: &Row<'_, C>,
    membership: Family,
    values: &[Option<f64>],
) -> Result<Degrees, InputError> {
    let get = |f: Field| values[f.index()];
    Degrees::with_membership(
        membership,
        get(Field::Truth).unwrap_or_default(),
        get(Field::Indeterminacy),
        get(Field::Falsity),
    )
    .map_err(|e| row.error(None, e.to_string()))
}
