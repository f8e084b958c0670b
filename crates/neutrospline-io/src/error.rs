//! The errors of reading and writing: [`InputError`] (an invalid file, located), [`ReadError`]
//! (everything [`crate::load`] and [`crate::parse`] can fail with), [`WriteError`] and
//! [`UnsupportedFormat`].

use std::fmt;
use std::io;

use crate::Format;

/// An invalid input file: where and what.
///
/// Displays as `FILE[:LINE][: FIELD]: MESSAGE` on one line (the command line adds `error: `):
/// the message names the value and the rule it breaks, for example
/// `bad.csv:2: truth = 1.2 is outside [0, 1] (every degree must be in [0, 1])`.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct InputError {
    /// The file as named by the caller (a path, or a label such as `<stdin>`).
    pub file: String,
    /// The physical, 1-based line in the file, when known.
    pub line: Option<usize>,
    /// The field: a CSV column (`` column `truth` ``), a model path (`control_points[2].x`), or
    /// the command-line option that gave a setting (`--degree`).
    pub field: Option<String>,
    /// What is wrong, naming the value and the rule.
    pub message: String,
}

impl InputError {
    /// An error in `file` (the name shown), at its 1-based `line` and in its `field` when they
    /// are known: `message` names the value and the rule it breaks. For a reader of another
    /// format whose errors should read as this crate's (the DXF and SVG importers).
    pub fn new(
        file: &str,
        line: Option<usize>,
        field: Option<String>,
        message: String,
    ) -> InputError {
        InputError {
            file: file.to_owned(),
            line,
            field,
            message,
        }
    }
}

impl fmt::Display for InputError {
    /// One line: control characters that a file put into a name or value (a newline inside a
    /// quoted CSV heading or TOML key, a NUL) are written as escapes such as `\n` and `\0`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write_escaped(f, &self.file)?;
        if let Some(line) = self.line {
            write!(f, ":{line}")?;
        }
        if let Some(field) = &self.field {
            f.write_str(": ")?;
            write_escaped(f, field)?;
        }
        f.write_str(": ")?;
        write_escaped(f, &self.message)
    }
}

/// Writes `text` with its control characters escaped (`\n`, `\0`, `\u{1b}`).
fn write_escaped(f: &mut fmt::Formatter<'_>, text: &str) -> fmt::Result {
    for c in text.chars() {
        if c.is_control() {
            write!(f, "{}", c.escape_debug())?;
        } else {
            write!(f, "{c}")?;
        }
    }
    Ok(())
}

impl std::error::Error for InputError {}

/// A file name whose extension names no format ([`Format::from_path`]).
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct UnsupportedFormat {
    /// The path as given.
    pub path: String,
    /// The extension, without its dot (`None`: the name has no extension).
    pub extension: Option<String>,
    /// What the reader accepts, for [`Display`](fmt::Display) (`None`: [`Format::ACCEPTED`]).
    pub accepted: Option<&'static str>,
}

impl UnsupportedFormat {
    /// `path`, whose extension (lowercased; `None` if it has none) names no format of the
    /// caller's: [`Format::from_path`] gives it, and so does a front end choosing among formats
    /// of its own (the export formats).
    pub fn new(path: impl AsRef<std::path::Path>) -> UnsupportedFormat {
        let path = path.as_ref();
        UnsupportedFormat {
            path: path.display().to_string(),
            extension: path
                .extension()
                .map(|e| e.to_string_lossy().to_ascii_lowercase()),
            accepted: None,
        }
    }

    /// The same, displayed with `accepted` as the list of what is accepted.
    pub fn accepting(mut self, accepted: &'static str) -> UnsupportedFormat {
        self.accepted = Some(accepted);
        self
    }

    /// Whether the extension is a spreadsheet's (`.xlsx`, `.xlsm`, `.xls`, `.ods`).
    pub fn is_spreadsheet(&self) -> bool {
        matches!(
            self.extension.as_deref(),
            Some("xlsx" | "xlsm" | "xls" | "ods")
        )
    }

    /// The message with `accepted` as the list of what is accepted: a front end that accepts
    /// more (standard input, say) says so. [`Display`](fmt::Display) uses
    /// [`Format::ACCEPTED`].
    /// A spreadsheet gets one message, the same from every command that refuses it: tables
    /// are read from spreadsheets, but nothing else is, and nothing is written to one.
    pub fn describe(&self, accepted: &str) -> String {
        if self.is_spreadsheet() {
            let ext = self.extension.as_deref().unwrap_or_default();
            return format!(
                "{}: a spreadsheet (.{ext}) is read only as a table (control points, data, \
                 query points) and never written: give {accepted} (a .csv file opens in every \
                 spreadsheet)",
                self.path
            );
        }
        match &self.extension {
            Some(ext) => format!(
                "{}: unsupported file extension `.{ext}` (accepted: {accepted})",
                self.path
            ),
            None => format!(
                "{}: the file name has no extension (accepted: {accepted})",
                self.path
            ),
        }
    }
}

impl fmt::Display for UnsupportedFormat {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.describe(self.accepted.unwrap_or(Format::ACCEPTED)))
    }
}

impl std::error::Error for UnsupportedFormat {}

/// Why a model could not be read.
///
/// [`ReadError::is_usage`] tells the caller's mistakes (an extension, options that do not fit
/// together; the command line exits with status 2 for them) from a bad or unreadable file.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ReadError {
    /// The file's content is invalid: located at its line and field.
    #[error(transparent)]
    Input(#[from] InputError),
    /// The file name's extension names no format.
    #[error(transparent)]
    Format(#[from] UnsupportedFormat),
    /// The [`ReadOptions`](crate::ReadOptions) do not fit together or do not fit the kind,
    /// found before the file is read (`--rows does not apply to kind `bspline` ...`).
    #[error("{0}")]
    Options(String),
    /// The file could not be opened or read. Displays as `PATH: cannot read: ERROR`: the
    /// message includes its [`source`](std::error::Error::source), so a report that walks the
    /// chain of causes should print only this one.
    #[error("{path}: cannot read: {error}")]
    Io {
        /// The path as given.
        path: String,
        /// The cause.
        #[source]
        error: io::Error,
    },
    /// The path names a directory. Displays as `PATH: cannot read: it is a directory (give
    /// EXPECTED)`, `EXPECTED` naming what the reader reads (`a .dxf file`).
    #[error("{path}: cannot read: it is a directory (give {expected})")]
    IsDirectory {
        /// The path as given.
        path: String,
        /// What the reader expected in its place: `a .csv, .toml or .json file` for models,
        /// `a .csv file` for data and query points, `a .dxf file`, `a .svg file`.
        expected: String,
    },
}

impl ReadError {
    /// Whether the caller made the mistake (an unsupported extension, options that do not fit
    /// together) rather than the file.
    pub fn is_usage(&self) -> bool {
        matches!(self, ReadError::Format(_) | ReadError::Options(_))
    }
}

/// Why a model could not be written.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum WriteError {
    /// The file name's extension names no format ([`crate::save`]).
    #[error(transparent)]
    Format(#[from] UnsupportedFormat),
    /// The model holds something the format cannot (a control point name that a CSV cell
    /// would lose). Displays as `[PATH: ]cannot write FORMAT: MESSAGE`.
    #[error("{}cannot write {format}: {message}", prefix(path.as_deref()))]
    Unrepresentable {
        /// The file, when writing one.
        path: Option<String>,
        /// The format.
        format: Format,
        /// What cannot be written, and why.
        message: String,
    },
    /// The file could not be written; it was left as it was. Displays as
    /// `PATH: cannot write: ERROR` (the cause included, as for [`ReadError::Io`]).
    #[error("{path}: cannot write: {error}")]
    Io {
        /// The path as given.
        path: String,
        /// The cause.
        #[source]
        error: io::Error,
    },
}

/// `PATH: ` or nothing.
fn prefix(path: Option<&str>) -> String {
    path.map(|p| format!("{p}: ")).unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn input_error_display() {
        let e = InputError::new(
            "a.toml",
            Some(7),
            Some("control_points[2].x".into()),
            "expected a number, found a string".into(),
        );
        assert_eq!(
            e.to_string(),
            "a.toml:7: control_points[2].x: expected a number, found a string"
        );
        let e = InputError::new("a.json", None, None, "m".into());
        assert_eq!(e.to_string(), "a.json: m");
    }

    #[test]
    fn input_error_display_escapes_control_characters() {
        let e = InputError::new(
            "a.csv",
            Some(1),
            None,
            "unknown column `a\nb\0\u{1b}[31m`".into(),
        );
        assert_eq!(
            e.to_string(),
            "a.csv:1: unknown column `a\\nb\\0\\u{1b}[31m`"
        );
    }

    #[test]
    fn read_error_display_and_usage() {
        let e = ReadError::Io {
            path: "a.csv".into(),
            error: io::Error::new(io::ErrorKind::NotFound, "gone"),
        };
        assert_eq!(e.to_string(), "a.csv: cannot read: gone");
        assert!(!e.is_usage());
        assert!(ReadError::Options("x".into()).is_usage());
        let e = ReadError::from(UnsupportedFormat {
            path: "a.txt".into(),
            extension: Some("txt".into()),
            accepted: None,
        });
        assert!(e.is_usage());
        assert_eq!(
            e.to_string(),
            "a.txt: unsupported file extension `.txt` (accepted: .csv, .toml, .json)"
        );
    }

    #[test]
    fn write_error_display() {
        let e = WriteError::Unrepresentable {
            path: Some("a.csv".into()),
            format: Format::Csv,
            message: "m".into(),
        };
        assert_eq!(e.to_string(), "a.csv: cannot write CSV: m");
        let e = WriteError::Unrepresentable {
            path: None,
            format: Format::Csv,
            message: "m".into(),
        };
        assert_eq!(e.to_string(), "cannot write CSV: m");
    }
}
