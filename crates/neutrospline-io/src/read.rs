//! Reading: [`load`] a file, [`parse`] bytes held in memory, or [`read_csv`] a stream.

use std::io::{BufRead, BufReader, Read};
use std::path::Path;

use crate::format::{too_large, too_many_points};
use crate::parsed::Parsed;
use crate::{
    csv, spreadsheet, walker, Format, InputError, Model, ReadError, ReadOptions, TableInput,
};

/// Parses a model held in memory: the contents of `file` (the name used in messages) in
/// `format`, for a program that has the bytes already (an upload, an editor buffer).
///
/// The `options` are checked first (as by [`load`]); the TOML and JSON size limit and the limit
/// on control points apply.
///
/// # Errors
/// [`ReadError::Options`] for options that do not fit together, [`ReadError::Input`] naming
/// the file, line or field, value and rule.
pub fn parse(
    file: &str,
    format: Format,
    bytes: &[u8],
    options: &ReadOptions,
) -> Result<Model, ReadError> {
    options.check(format)?;
    let limit = options.limits.max_file_size;
    if format != Format::Csv && bytes.len() as u64 > limit {
        return Err(InputError::new(file, None, None, too_large(limit)).into());
    }
    let parsed = match format {
        Format::Csv => csv::parse(file, bytes, options),
        Format::Toml => walker::parse_toml(file, bytes, options),
        Format::Json => walker::parse_json(file, bytes, options),
    }?;
    build(parsed, options)
}

/// Reads a CSV table from a stream (standard input, a socket), line by line: an error is
/// reported as soon as its line is read, without reading further, and only the control points
/// are kept in memory (at most `options.limits.max_control_points` of them). `file` names the
/// stream in messages (`<stdin>`).
///
/// # Errors
/// As [`parse`]; a read error is an [`InputError`] at the line it happened on.
pub fn read_csv(
    file: &str,
    reader: impl BufRead,
    options: &ReadOptions,
) -> Result<Model, ReadError> {
    options.check(Format::Csv)?;
    let parsed = csv::parse_reader(file, reader, options)?;
    build(parsed, options)
}

/// Reads and parses the file at `path`, its format chosen by the extension
/// ([`Format::from_path`]); messages name the file as `path` displays.
///
/// CSV is read as a stream ([`read_csv`]) and refused at its first bad line; TOML and JSON
/// documents are read whole, up to `options.limits.max_file_size` bytes (checked before reading
/// and while reading, for a file that grows).
///
/// # Errors
/// [`ReadError::Format`] for an unsupported extension and [`ReadError::Options`] for options
/// that do not fit together (both before the file is opened), [`ReadError::Io`] and
/// [`ReadError::IsDirectory`] when the file cannot be read, [`ReadError::Input`] for invalid
/// content.
pub fn load(path: impl AsRef<Path>, options: &ReadOptions) -> Result<Model, ReadError> {
    let path = path.as_ref();
    let format = if is_tsv(path) || spreadsheet::is_spreadsheet(path) {
        Format::Csv
    } else {
        Format::from_path(path)?
    };
    options.check(format)?;
    if format == Format::Csv {
        let source = open_table_source(path, MODEL_FILE, &options.table)?;
        let mut options = options.clone();
        options.table = source.input;
        return read_csv(&source.shown, source.reader, &options);
    }
    if let Some(sheet) = &options.table.sheet {
        return Err(not_a_spreadsheet(path, sheet));
    }
    let (shown, bytes) = read_whole(path, options.limits.max_file_size, MODEL_FILE)?;
    parse(&shown, format, &bytes, options)
}

/// What [`load`] reads, for the message of a directory in its place.
const MODEL_FILE: &str = "a .csv, .tsv, .toml or .json file, or a spreadsheet";

/// The extensions of a table of data or query points ([`crate::load_data`],
/// [`crate::load_points`]), for messages.
pub(crate) const TABLE_EXTENSIONS: &str = ".csv, .tsv, .txt, .xlsx, .xlsm, .xls, .ods";

/// Whether `path` names a tab-separated table (`.tsv`, case-insensitive).
fn is_tsv(path: &Path) -> bool {
    path.extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("tsv"))
}

/// The table options for the file at `path`: a `.tsv` file's delimiter is a tab unless one
/// is given.
pub(crate) fn table_input_for(path: &Path, input: &TableInput) -> TableInput {
    let mut input = input.clone();
    if input.delimiter.is_none() && is_tsv(path) {
        input.delimiter = Some(b'\t');
    }
    input
}

/// A table opened for reading: its text, the name messages give it, and the options to read
/// it with.
pub(crate) struct TableSource {
    /// The table's text: the file, or a spreadsheet's sheet written as text.
    pub(crate) reader: Box<dyn BufRead>,
    /// The name in messages: the path as it displays, `PATH[SHEET]` for a spreadsheet.
    pub(crate) shown: String,
    /// The options to read the text with ([`table_input_for`]; a sheet's are tab-separated).
    pub(crate) input: TableInput,
}

/// Opens a table of data, query points or an axis set: refuses an extension other than
/// [`TABLE_EXTENSIONS`] before opening it; a spreadsheet's sheet is read whole.
pub(crate) fn open_table(
    path: &Path,
    expected: &str,
    input: &TableInput,
) -> Result<TableSource, ReadError> {
    let known = path.extension().is_some_and(|e| {
        ["csv", "tsv", "txt"]
            .iter()
            .any(|k| e.eq_ignore_ascii_case(k))
    });
    if !known && !spreadsheet::is_spreadsheet(path) {
        return Err(crate::UnsupportedFormat::new(path)
            .accepting(TABLE_EXTENSIONS)
            .into());
    }
    open_table_source(path, expected, input)
}

/// Opens the CSV text or the spreadsheet at `path` as a table ([`TableSource`]).
fn open_table_source(
    path: &Path,
    expected: &str,
    input: &TableInput,
) -> Result<TableSource, ReadError> {
    if spreadsheet::is_spreadsheet(path) {
        let (shown, text, input) = spreadsheet::read_sheet(path, expected, input)?;
        return Ok(TableSource {
            reader: Box::new(std::io::Cursor::new(text)),
            shown,
            input,
        });
    }
    if let Some(sheet) = &input.sheet {
        return Err(not_a_spreadsheet(path, sheet));
    }
    let (file, shown) = open_file(path, expected)?;
    Ok(TableSource {
        reader: Box::new(BufReader::new(file)),
        shown,
        input: table_input_for(path, input),
    })
}

/// The refusal of `sheet` for a file that has no sheets.
fn not_a_spreadsheet(path: &Path, sheet: &str) -> ReadError {
    ReadError::Options(format!(
        "{}: sheet = {sheet} applies to a spreadsheet (.xlsx, .xlsm, .xls, .ods); this file has \
         no sheets (leave out --sheet)",
        path.display()
    ))
}

/// Reads the file at `path` whole, at most `limit` bytes: refused before reading when its size
/// is larger, and while reading when it grows (a FIFO, a file being written; one byte more
/// than the limit is read at most). Returns the path as messages show it and the bytes; the
/// one way the model reader and the drawing importers read a file whole. `expected` names
/// what the caller reads (`a .dxf file`), for the message of a directory.
///
/// # Errors
/// [`ReadError::Io`], [`ReadError::IsDirectory`] (naming `expected`), and a located
/// [`ReadError::Input`] naming the limit for a file larger than `limit`.
pub fn read_whole(path: &Path, limit: u64, expected: &str) -> Result<(String, Vec<u8>), ReadError> {
    let (file, shown) = open_file(path, expected)?;
    let cannot = |error: std::io::Error| ReadError::Io {
        path: shown.clone(),
        error,
    };
    let too_large = || InputError::new(&shown, None, None, too_large(limit)).into();
    let size = file.metadata().map_err(cannot)?.len();
    if size > limit {
        return Err(too_large());
    }
    let mut bytes = Vec::with_capacity(usize::try_from(size).unwrap_or(0));
    file.take(limit.saturating_add(1))
        .read_to_end(&mut bytes)
        .map_err(cannot)?;
    if bytes.len() as u64 > limit {
        return Err(too_large());
    }
    Ok((shown, bytes))
}

/// Opens `path` for reading, refusing a directory (the message naming the `expected` file):
/// the file and the path as messages show it.
pub(crate) fn open_file(path: &Path, expected: &str) -> Result<(std::fs::File, String), ReadError> {
    let shown = path.display().to_string();
    let cannot = |error: std::io::Error| ReadError::Io {
        path: shown.clone(),
        error,
    };
    let file = std::fs::File::open(path).map_err(cannot)?;
    if file.metadata().map_err(cannot)?.is_dir() {
        return Err(ReadError::IsDirectory {
            path: shown,
            expected: expected.to_owned(),
        });
    }
    Ok((file, shown))
}

/// Refuses a model with more control points than the limit, then builds the shape.
fn build(parsed: Parsed, options: &ReadOptions) -> Result<Model, ReadError> {
    let limit = options.limits.max_control_points;
    if parsed.points.len() as u64 > limit {
        let index = usize::try_from(limit).unwrap_or(usize::MAX);
        let origin = parsed.points[index].origin.clone();
        return Err(parsed.error_at(&origin, too_many_points(limit)).into());
    }
    Ok(parsed.into_model()?)
}
