//! The file formats and the size limits of reading.

use std::fmt;
use std::path::Path;

use crate::UnsupportedFormat;

/// The file formats, chosen by extension.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Format {
    /// A CSV table of control points (`.csv`); the kind, degree, knots and grid come from the
    /// [`ReadOptions`](crate::ReadOptions).
    Csv,
    /// A TOML model (`.toml`).
    Toml,
    /// A JSON model (`.json`).
    Json,
}

impl Format {
    /// Every format.
    pub const ALL: [Format; 3] = [Format::Csv, Format::Toml, Format::Json];

    /// The extensions [`Format::from_path`] accepts, for messages.
    pub const ACCEPTED: &'static str = ".csv, .toml, .json";

    /// The extension, without its dot (`csv`, `toml`, `json`).
    pub const fn extension(self) -> &'static str {
        match self {
            Format::Csv => "csv",
            Format::Toml => "toml",
            Format::Json => "json",
        }
    }

    /// The format of an extension (without its dot, case-insensitive).
    pub fn from_extension(extension: &str) -> Option<Format> {
        Format::ALL
            .into_iter()
            .find(|f| f.extension().eq_ignore_ascii_case(extension))
    }

    /// The format of `path` by its extension (case-insensitive).
    ///
    /// # Errors
    /// [`UnsupportedFormat`] for another extension or none.
    pub fn from_path(path: impl AsRef<Path>) -> Result<Format, UnsupportedFormat> {
        let path = path.as_ref();
        let extension = path.extension().map(|e| e.to_string_lossy());
        match extension.as_deref().map(Format::from_extension) {
            Some(Some(format)) => Ok(format),
            _ => Err(UnsupportedFormat::new(path)),
        }
    }
}

impl fmt::Display for Format {
    /// `CSV`, `TOML`, `JSON`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Format::Csv => "CSV",
            Format::Toml => "TOML",
            Format::Json => "JSON",
        })
    }
}

/// Default of [`Limits::max_control_points`].
pub const DEFAULT_MAX_CONTROL_POINTS: u64 = 1_000_000;
/// Default of [`Limits::max_file_size`], 256 MiB.
pub const DEFAULT_MAX_FILE_SIZE: u64 = 256 * 1024 * 1024;
/// The longest line (or quoted multi-line record) a CSV file may have, in bytes: a control
/// point row is a few dozen bytes.
pub(crate) const MAX_CSV_LINE: usize = 1024 * 1024;
/// The largest degree or count of control points accepted in files (larger values are surely
/// mistakes; every integer up to it is exact in a 64-bit float). A front end that takes a
/// degree or a count as an option (`--degree`, `--rows`) accepts the same range.
pub const MAX_INTEGER: u64 = 1_000_000_000;

/// Resource limits of reading, so that an absurd input is refused with a clear error instead
/// of exhausting memory.
///
/// CSV is read as a stream, line by line, so its size is not limited: a CSV file is refused at
/// the first bad line, or at the line that exceeds the control-point limit, without reading
/// further. TOML and JSON documents must be read whole to be parsed, hence the size limit.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub struct Limits {
    /// The most control points a model may have (surfaces: rows x cols).
    pub max_control_points: u64,
    /// The largest TOML or JSON file, in bytes.
    pub max_file_size: u64,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            max_control_points: DEFAULT_MAX_CONTROL_POINTS,
            max_file_size: DEFAULT_MAX_FILE_SIZE,
        }
    }
}

impl Limits {
    /// The message refusing a model with more than [`Limits::max_control_points`] control
    /// points, naming the option and the environment variable that raise the limit: a reader of
    /// another format (DXF, SVG) refuses with the same words, located in its file
    /// ([`InputError::new`](crate::InputError::new)).
    ///
    /// ```
    /// let limits = neutrospline_io::Limits::default();
    /// assert!(limits.too_many_control_points().starts_with("more than 1000000 control points"));
    /// ```
    pub fn too_many_control_points(&self) -> String {
        too_many_points(self.max_control_points)
    }
}

/// The message for a model with too many control points.
pub(crate) fn too_many_points(limit: u64) -> String {
    format!(
        "more than {limit} control points (the limit; raise it with --max-control-points or \
         NEUTROSPLINE_MAX_CONTROL_POINTS)"
    )
}

/// The message for a file read whole (TOML, JSON, DXF, SVG) over the size limit.
pub(crate) fn too_large(limit: u64) -> String {
    format!(
        "the file is larger than {limit} bytes, the limit for a file read whole (TOML, JSON, \
         DXF, SVG; raise it with --max-file-size or NEUTROSPLINE_MAX_FILE_SIZE; CSV files are \
         streamed and have no size limit)"
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn format_from_path_by_extension() {
        assert_eq!(Format::from_path("a.csv"), Ok(Format::Csv));
        assert_eq!(Format::from_path("dir/a.TOML"), Ok(Format::Toml));
        assert_eq!(Format::from_path("a.json"), Ok(Format::Json));
        assert_eq!(
            Format::from_path("a.txt").unwrap_err().to_string(),
            "a.txt: unsupported file extension `.txt` (accepted: .csv, .toml, .json)"
        );
        assert_eq!(
            Format::from_path("noext").unwrap_err().to_string(),
            "noext: the file name has no extension (accepted: .csv, .toml, .json)"
        );
        assert_eq!(
            Format::from_path("-").unwrap_err().extension,
            None,
            "standard input is the caller's business"
        );
    }
}
