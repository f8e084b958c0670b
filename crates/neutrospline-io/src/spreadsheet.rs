//! Spreadsheets (`.xlsx`, `.xlsm`, `.xls`, `.ods`) read as tables: one sheet (the first, or
//! the one [`TableInput::sheet`] names) becomes the text of a table that the CSV reader reads,
//! so a sheet is read by the same rules, with the same messages, as the CSV file it would be
//! saved as (docs/formats.md, "Spreadsheets").
//!
//! - Row `r` of the sheet (1-based, as the spreadsheet shows it) is line `r` of the table, so a
//!   message names the row the user sees: `survey.xlsx[Data]:4: column `truth`: ...`. Rows
//!   above the first used cell and empty rows are empty lines, which the reader skips.
//! - A number cell is written in shortest round-trip form (`ryu`), so it reads back to the
//!   same `f64`; with `decimal-comma` its point is written as a comma. An integer cell is
//!   written as it is.
//! - Text cells are read as text: a number typed as text (`'0.3`, `0,3`) is read as a CSV cell
//!   holding it would be; a formula's error (`#DIV/0!`), a date, a time or a boolean is written
//!   as the text the spreadsheet shows, and the reader refuses it where a number is needed,
//!   naming the row and column.
//! - Trailing empty cells of a row are dropped (a header formatted further to the right than
//!   its headings).

use std::fmt::Write as _;
use std::path::Path;

use calamine::{open_workbook_auto, Data, Reader};

use crate::{ReadError, TableInput};

/// The extensions read as spreadsheets, lowercase.
pub(crate) const SPREADSHEET_EXTENSIONS: [&str; 4] = ["xlsx", "xlsm", "xls", "ods"];

/// The delimiter between the cells of a sheet's text: a tab (text cells are quoted, so a tab
/// inside one is kept).
pub(crate) const SHEET_DELIMITER: u8 = b'\t';

/// Whether `path`'s extension is a spreadsheet's ([`SPREADSHEET_EXTENSIONS`]).
pub(crate) fn is_spreadsheet(path: &Path) -> bool {
    path.extension().is_some_and(|e| {
        SPREADSHEET_EXTENSIONS
            .iter()
            .any(|k| e.eq_ignore_ascii_case(k))
    })
}

/// The sheet of the spreadsheet at `path` that `input` names (the first by default) as the
/// text of a tab-separated table, with the name messages give it (`PATH[SHEET]`), and the
/// table options to read that text with (the tab as delimiter).
///
/// # Errors
/// [`ReadError::Options`] for a `delimiter` (a sheet has cells, not a delimiter) or a sheet
/// that the workbook does not have (naming the ones it has); [`ReadError::IsDirectory`];
/// [`ReadError::Io`] for a file that cannot be opened or is not a readable workbook.
pub(crate) fn read_sheet(
    path: &Path,
    expected: &str,
    input: &TableInput,
) -> Result<(String, Vec<u8>, TableInput), ReadError> {
    let shown = path.display().to_string();
    if let Some(delimiter) = input.delimiter {
        return Err(ReadError::Options(format!(
            "{shown}: delimiter = {} does not apply to a spreadsheet: its cells are read as \
             cells (leave out --delimiter)",
            crate::table_input::delimiter_name(delimiter)
        )));
    }
    // The directory and missing-file messages of every reader.
    crate::read::open_file(path, expected)?;
    let cannot = |error: String| ReadError::Io {
        path: shown.clone(),
        error: std::io::Error::new(std::io::ErrorKind::InvalidData, error),
    };
    // The workbook readers panic on some damaged files (a cut .xls): read under a guard
    // that turns a panic into this file's error.
    let mut workbook = guarded(|| open_workbook_auto(path))
        .map_err(&cannot)?
        .map_err(|e| cannot(e.to_string()))?;
    let names = workbook.sheet_names();
    let name = match &input.sheet {
        Some(wanted) => names
            .iter()
            .find(|n| *n == wanted)
            .or_else(|| names.iter().find(|n| n.eq_ignore_ascii_case(wanted)))
            .cloned()
            .ok_or_else(|| {
                ReadError::Options(format!(
                    "{shown}: sheet = {wanted}: the workbook has no such sheet (its sheets: {})",
                    names.join(", ")
                ))
            })?,
        None => names
            .first()
            .cloned()
            .ok_or_else(|| cannot("the workbook has no sheet".to_owned()))?,
    };
    let range = guarded(|| workbook.worksheet_range(&name))
        .map_err(&cannot)?
        .map_err(|e| cannot(format!("sheet {name}: {e}")))?;
    let mut text = String::new();
    if let Some((first_row, _)) = range.start() {
        for _ in 0..first_row {
            text.push('\n');
        }
    }
    for row in range.rows() {
        let used = row.iter().rposition(|c| !matches!(c, Data::Empty));
        for (k, cell) in row[..used.map_or(0, |u| u + 1)].iter().enumerate() {
            if k > 0 {
                text.push(char::from(SHEET_DELIMITER));
            }
            write_cell(&mut text, cell, input.decimal_comma);
        }
        text.push('\n');
    }
    let mut options = input.clone();
    options.delimiter = Some(SHEET_DELIMITER);
    Ok((format!("{shown}[{name}]"), text.into_bytes(), options))
}

thread_local! {
    /// Whether a panic on this thread is a workbook reader's, caught by [`guarded`].
    static GUARDED: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// Runs a workbook reader's `read`, turning a panic into the message of a damaged file. The
/// panic is not printed: a hook (installed once, in front of the one that was there) stays
/// silent while a guarded read runs on its thread and passes every other panic on.
fn guarded<T>(read: impl FnOnce() -> T) -> Result<T, String> {
    static HOOK: std::sync::Once = std::sync::Once::new();
    HOOK.call_once(|| {
        let previous = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            if !GUARDED.with(std::cell::Cell::get) {
                previous(info);
            }
        }));
    });
    GUARDED.with(|g| g.set(true));
    let result = std::panic::catch_unwind(std::panic::AssertUnwindSafe(read));
    GUARDED.with(|g| g.set(false));
    result.map_err(|payload| {
        let cause = payload
            .downcast_ref::<&str>()
            .map(|s| (*s).to_owned())
            .or_else(|| payload.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "an inconsistency".to_owned());
        format!("the workbook is damaged (its reader stopped at: {cause})")
    })
}

/// Writes one cell as the table's text: numbers bare, everything else quoted.
fn write_cell(text: &mut String, cell: &Data, decimal_comma: bool) {
    match cell {
        Data::Empty => {}
        Data::Int(i) => {
            let _ = write!(text, "{i}");
        }
        Data::Float(f) if f.is_finite() => {
            let mut buffer = ryu::Buffer::new();
            let written = buffer.format_finite(*f);
            let written = written.strip_suffix(".0").unwrap_or(written);
            if decimal_comma {
                text.push_str(&written.replace('.', ","));
            } else {
                text.push_str(written);
            }
        }
        other => {
            text.push('"');
            text.push_str(&other.to_string().replace('"', "\"\""));
            text.push('"');
        }
    }
}
