//! Reading: [`load`] a file, [`parse`] bytes held in memory, or [`read_csv`] a stream.

use std::io::{BufRead, BufReader, Read};
use std::path::Path;

use crate::format::{too_large, too_many_points};
use crate::parsed::Parsed;
use crate::{csv, walker, Format, InputError, Model, ReadError, ReadOptions, TableInput};

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
    let format = if is_tsv(path) {
        Format::Csv
    } else {
        Format::from_path(path)?
    };
    options.check(format)?;
    if format == Format::Csv {
        let (file, shown) = open_file(path, MODEL_FILE)?;
        let mut options = options.clone();
        options.table = table_input_for(path, &options.table);
        return read_csv(&shown, BufReader::new(file), &options);
    }
    let (shown, bytes) = read_whole(path, options.limits.max_file_size, MODEL_FILE)?;
    parse(&shown, format, &bytes, options)
}

/// What [`load`] reads, for the message of a directory in its place.
const MODEL_FILE: &str = "a .csv, .tsv, .toml or .json file";

/// The extensions of a table of data or query points ([`crate::load_data`],
/// [`crate::load_points`]), for messages.
pub(crate) const TABLE_EXTENSIONS: &str = ".csv, .tsv, .txt";

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

/// Opens a table of data or query points: refuses an extension other than
/// [`TABLE_EXTENSIONS`] (a spreadsheet with its own message) before opening it.
pub(crate) fn open_table(
    path: &Path,
    expected: &str,
) -> Result<(std::fs::File, String), ReadError> {
    let known = path.extension().is_some_and(|e| {
        ["csv", "tsv", "txt"]
            .iter()
            .any(|k| e.eq_ignore_ascii_case(k))
    });
    if !known {
        return Err(crate::UnsupportedFormat::new(path)
            .accepting(TABLE_EXTENSIONS)
            .into());
    }
    open_file(path, expected)
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
