//! Tables with named columns (a pandas DataFrame) read as the command line reads a table.
//!
//! A DataFrame becomes the text of a tab-separated table that neutrospline-io's CSV readers
//! read, exactly as a spreadsheet's sheet does (neutrospline-io's `spreadsheet` module): so
//! `load`, `fit` and `fit_surface` read a DataFrame by the same rules and with the same
//! options as a CSV file with the same columns (names in any case and order, the aliases `T`,
//! `I`, `F`, `columns={"truth": "mu"}`, `ignore_columns`, the membership rules, `weight`,
//! `name`, `parameter`, `u`, `v`), and no second reader of columns exists. Numbers are written
//! in shortest round-trip form, so they read back to the same `f64`; text cells are quoted.
//! Messages name the DataFrame's row (its position, and its index label when that differs)
//! and, for a missing column, the columns it has.

use neutrospline::options::OptionSet;
use neutrospline_io::{InputError, ReadError, TableInput};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyString, PyTuple};

use crate::errors::{invalid, invalid_at};

/// How a DataFrame is named in messages.
pub const LABEL: &str = "DataFrame";

/// The line of the header row in the table's text; row `k` is line `k + 2`.
const HEADER_LINE: usize = 1;

/// Whether `data` is a table with named columns (a pandas DataFrame: it has `columns`).
pub fn is_frame(data: &Bound<'_, PyAny>) -> bool {
    !data.is_instance_of::<PyString>()
        && !data.hasattr("__fspath__").unwrap_or(false)
        && data.hasattr("columns").unwrap_or(false)
        && data.hasattr("__getitem__").unwrap_or(false)
}

/// The table options (neutrospline-io's `TableInput`: `columns`, `ignore_columns`,
/// `ignore_unknown_columns`, `delimiter`, `decimal_comma`, `sheet`) taken out of the keyword
/// arguments `options`, which keep the others. `columns` may be a mapping `{ours: theirs}`
/// as well as the command line's text `"truth=mu,falsity=nu"`, `ignore_columns` a list as
/// well as `"a,b"`. For a DataFrame (`frame`), columns that name nothing are left out unless
/// `ignore_unknown_columns=False`, and the options of a file's text (`delimiter`,
/// `decimal_comma`, `sheet`) are refused.
///
/// # Errors
/// `ModelError` with the library's message for a value it refuses.
pub fn table_input(options: Option<&Bound<'_, PyDict>>, frame: bool) -> PyResult<TableInput> {
    let mut input = TableInput {
        ignore_unknown_columns: frame,
        ..TableInput::default()
    };
    let Some(options) = options else {
        return Ok(input);
    };
    for spec in TableInput::OPTIONS {
        let key = spec.name.replace('-', "_");
        let Some(value) = options.get_item(&key)? else {
            continue;
        };
        options.del_item(&key)?;
        if value.is_none() {
            continue;
        }
        if frame && matches!(spec.name, "delimiter" | "decimal-comma" | "sheet") {
            return Err(invalid_at(
                &key,
                "does not apply to a DataFrame: its cells are read as cells (it is an option \
                 of a table file)",
            ));
        }
        let value = match spec.name {
            "columns" => mapping_text(&value)?,
            "ignore-columns" => list_text(&value)?,
            _ => value,
        };
        let one = PyDict::new(options.py());
        one.set_item(&key, value)?;
        crate::options::set_from_kwargs(&mut input, Some(&one))?;
    }
    input.validate().map_err(invalid)?;
    Ok(input)
}

/// The column options of `fit` and `fit_surface` as keyword arguments for [`table_input`].
pub fn column_options<'py>(
    py: Python<'py>,
    columns: Option<&Bound<'py, PyAny>>,
    ignore_columns: Option<&Bound<'py, PyAny>>,
    ignore_unknown_columns: Option<bool>,
) -> PyResult<Bound<'py, PyDict>> {
    let options = PyDict::new(py);
    options.set_item("columns", columns)?;
    options.set_item("ignore_columns", ignore_columns)?;
    options.set_item("ignore_unknown_columns", ignore_unknown_columns)?;
    Ok(options)
}

/// A `columns` mapping `{ours: theirs}` as the text `ours=theirs,...` (text is kept).
fn mapping_text<'py>(value: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
    if !value.hasattr("items")? {
        return Ok(value.clone());
    }
    let mut pairs = Vec::new();
    for item in value.call_method0("items")?.try_iter()? {
        let (ours, theirs): (String, String) = item?.extract().map_err(|_| {
            invalid_at(
                "columns",
                "expected a mapping of our column names to the table's, such as \
                 {\"truth\": \"mu\"}",
            )
        })?;
        pairs.push(format!("{ours}={theirs}"));
    }
    Ok(PyString::new(value.py(), &pairs.join(",")).into_any())
}

/// An `ignore_columns` list as the text `a,b,...` (text is kept).
fn list_text<'py>(value: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
    if !(value.is_instance_of::<PyList>() || value.is_instance_of::<PyTuple>()) {
        return Ok(value.clone());
    }
    let names: Vec<String> = value
        .extract()
        .map_err(|_| invalid_at("ignore_columns", "expected a list of column names"))?;
    Ok(PyString::new(value.py(), &names.join(",")).into_any())
}

/// A DataFrame as the text of a table, with the options to read it.
pub struct Frame {
    /// The DataFrame, for the index labels of messages.
    data: Py<PyAny>,
    /// Its column names, in order.
    headings: Vec<String>,
    /// The tab-separated text: a header row, then one line per row.
    text: Vec<u8>,
    /// How the text is read: the caller's table options, the tab as delimiter.
    input: TableInput,
}

/// One column's cells.
enum Cells {
    /// A numeric column, as float64 (a missing value is NaN).
    Numbers(Vec<f64>),
    /// Any other column: each cell a number, text, or empty (None, NaN).
    Mixed(Vec<Cell>),
}

enum Cell {
    Number(f64),
    Text(String),
    Empty,
}

impl Frame {
    /// Writes the DataFrame `data` as a table's text, read as `input` says.
    ///
    /// # Errors
    /// `ModelError` when `data` has no columns to read, or a column cannot be read.
    pub fn read(data: &Bound<'_, PyAny>, mut input: TableInput) -> PyResult<Frame> {
        let headings: Vec<String> = data
            .getattr("columns")?
            .try_iter()?
            .map(|c| c?.str().map(|s| s.to_string()))
            .collect::<PyResult<_>>()?;
        let rows = data.len()?;
        let by_position = data.hasattr("iloc")?;
        let mut columns = Vec::with_capacity(headings.len());
        for (j, heading) in headings.iter().enumerate() {
            let series = if by_position {
                let all = pyo3::types::PySlice::full(data.py());
                data.getattr("iloc")?.get_item((all, j))?
            } else {
                data.get_item(heading)?
            };
            columns.push(read_cells(&series, heading, rows)?);
        }
        let mut text = Vec::with_capacity(rows * headings.len() * 12 + 64);
        for (j, heading) in headings.iter().enumerate() {
            if j > 0 {
                text.push(b'\t');
            }
            push_text(&mut text, heading);
        }
        text.push(b'\n');
        for r in 0..rows {
            for (j, column) in columns.iter().enumerate() {
                if j > 0 {
                    text.push(b'\t');
                }
                match column {
                    Cells::Numbers(values) => neutrospline_io::push_number(&mut text, values[r]),
                    Cells::Mixed(cells) => match &cells[r] {
                        Cell::Number(v) => neutrospline_io::push_number(&mut text, *v),
                        Cell::Text(t) => push_text(&mut text, t),
                        Cell::Empty => {}
                    },
                }
            }
            text.push(b'\n');
        }
        input.delimiter = Some(b'\t');
        Ok(Frame {
            data: data.clone().unbind(),
            headings,
            text,
            input,
        })
    }

    /// The table's text.
    pub fn text(&self) -> &[u8] {
        &self.text
    }

    /// The options to read the text with.
    pub fn input(&self) -> &TableInput {
        &self.input
    }

    /// The DataFrame's columns, as a message lists them.
    pub fn columns_text(&self) -> String {
        if self.headings.is_empty() {
            "none".to_owned()
        } else {
            self.headings.join(", ")
        }
    }

    /// The message of an error of the table reader or of a fit located in the table: the
    /// row of the DataFrame (`DataFrame row 3: ...`, with ` (index 'b')` when the index
    /// label differs from the position), a missing column with the columns present.
    pub fn message(&self, py: Python<'_>, error: &InputError) -> String {
        let field = error
            .field
            .as_ref()
            .map(|f| format!("{f}: "))
            .unwrap_or_default();
        let message = &error.message;
        match error.line {
            Some(HEADER_LINE) => self.header_message(message),
            Some(line) if line > HEADER_LINE => {
                let row = line - HEADER_LINE - 1;
                let index = self
                    .index_label(py, row)
                    .filter(|label| *label != row.to_string())
                    .map(|label| format!(" (index {label})"))
                    .unwrap_or_default();
                format!("{LABEL} row {row}{index}: {field}{message}")
            }
            _ => format!("{LABEL}: {field}{message}"),
        }
    }

    /// An error of the header row: a missing column names the columns the DataFrame has.
    fn header_message(&self, message: &str) -> String {
        let columns = self.columns_text();
        if let Some(rest) = message.strip_prefix("missing column `") {
            if let Some((name, why)) = rest.split_once("` (") {
                return format!(
                    "the {LABEL} has no column `{name}` (its columns: {columns}; {why}"
                );
            }
        }
        for option in ["columns", "ignore-columns"] {
            let prefix = format!("--{option} ");
            if let Some(rest) = message.strip_prefix(&prefix) {
                let rest = rest.replace("the header has no column", "the DataFrame has no column");
                return format!(
                    "{} {rest} (its columns: {columns})",
                    option.replace('-', "_")
                );
            }
        }
        // A column `t` (a parameter, as `eval` and `to_dataframe` name it) is truth's alias.
        let hint = if message.contains("repeats column")
            && self.headings.iter().any(|h| h.eq_ignore_ascii_case("t"))
        {
            "; `t` reads as truth (T): leave it out with ignore_columns=[\"t\"], or read it \
             as the parameters of a fit with columns={\"parameter\": \"t\"}"
        } else {
            ""
        };
        format!("{LABEL}: {message} (its columns: {columns}{hint})")
    }

    /// The index label of the row at `position`, as `repr` shows it.
    fn index_label(&self, py: Python<'_>, position: usize) -> Option<String> {
        let label = self
            .data
            .bind(py)
            .getattr("index")
            .and_then(|index| index.get_item(position))
            .ok()?;
        if let Ok(n) = label.extract::<i64>() {
            return Some(n.to_string());
        }
        label.repr().ok().map(|r| r.to_string())
    }

    /// A `ModelError` for a read error of the table.
    pub fn read_error(&self, py: Python<'_>, error: ReadError) -> PyErr {
        match error {
            ReadError::Input(e) => invalid(self.message(py, &e)),
            other => invalid(other),
        }
    }
}

/// The cells of one column (`series`, with `rows` cells).
fn read_cells(series: &Bound<'_, PyAny>, heading: &str, rows: usize) -> PyResult<Cells> {
    let values = series.call_method0("to_numpy")?;
    let kind: String = values.getattr("dtype")?.getattr("kind")?.extract()?;
    if matches!(kind.as_str(), "f" | "i" | "u") {
        let floats = values.call_method1("astype", ("float64",))?;
        let array = crate::arrays::float_array(&floats, heading)?;
        return Ok(Cells::Numbers(array.values()?.to_vec()));
    }
    let mut cells = Vec::with_capacity(rows);
    for item in values.try_iter()? {
        let item = item?;
        let cell = if item.is_none() {
            Cell::Empty
        } else if item.is_instance_of::<PyString>() {
            Cell::Text(item.extract()?)
        } else if item.is_instance_of::<pyo3::types::PyBool>() || kind == "b" {
            Cell::Text(item.str()?.to_string())
        } else if let Ok(v) = item.extract::<f64>() {
            if v.is_nan() {
                Cell::Empty
            } else {
                Cell::Number(v)
            }
        } else {
            Cell::Text(item.str()?.to_string())
        };
        cells.push(cell);
    }
    Ok(Cells::Mixed(cells))
}

/// Appends `text` as a quoted cell (`"` doubled), so that a tab, a line end, a leading `#`
/// or a quote in it is read as part of the cell.
fn push_text(out: &mut Vec<u8>, text: &str) {
    out.push(b'"');
    for b in text.bytes() {
        if b == b'"' {
            out.push(b'"');
        }
        out.push(b);
    }
    out.push(b'"');
}
