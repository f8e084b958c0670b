//! Reading the model file named on the command line, through `neutrospline-io`: `-` is CSV on
//! standard input, the shape options and the limits become [`ReadOptions`], and the library's
//! errors become the command's (a [`UsageError`] exits with status 2).

use std::fmt;

use neutrospline::Membership;
use neutrospline_io::{DataTable, Model, ReadError, ReadOptions};

use crate::commands::options::ModelArgs;

/// The name used for standard input in messages.
pub const STDIN_NAME: &str = "<stdin>";

/// The file extensions the command accepts, with `-` meaning CSV on standard input.
pub const ACCEPTED_EXTENSIONS: &str = ".csv, .toml, .json; `-` reads CSV from standard input";

/// An error in the command line that only shows once the arguments are interpreted
/// (for example an unsupported file extension). `main` exits with status 2 for it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct UsageError(pub String);

impl fmt::Display for UsageError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for UsageError {}

/// The name of `file` in messages: the path as given, or [`STDIN_NAME`] for `-`.
pub fn label(file: &str) -> &str {
    if file == "-" {
        STDIN_NAME
    } else {
        file
    }
}

/// The options of `args` with the limits in force ([`crate::limits::current`]).
pub fn read_options(args: &ModelArgs) -> ReadOptions {
    let mut options = args.read_options();
    options.limits = crate::limits::current().file_limits();
    options
}

/// Reads and validates `file` (`-` for CSV on standard input, streamed).
///
/// # Errors
/// A [`UsageError`] for an unsupported extension or options that do not fit together; the
/// library's message (file, line, field, value and rule; or the I/O error) otherwise.
pub fn read_model(file: &str, args: &ModelArgs) -> anyhow::Result<Model> {
    let options = read_options(args);
    let result = if file == "-" {
        neutrospline_io::read_csv(STDIN_NAME, std::io::stdin().lock(), &options)
    } else {
        neutrospline_io::load(file, &options)
    };
    result.map_err(|e| match e {
        ReadError::Format(e) => UsageError(e.describe(ACCEPTED_EXTENSIONS)).into(),
        e if e.is_usage() => UsageError(e.to_string()).into(),
        // The message already names the cause (`PATH: cannot read: ERROR`): no error chain,
        // which `main` would print a second time.
        e => anyhow::Error::msg(e.to_string()),
    })
}

/// Reads a data file (or standard input for `-`).
///
/// # Errors
/// The located error of the io crate.
pub fn read_data(file: &str, membership: Membership) -> anyhow::Result<DataTable> {
    let result = if file == "-" {
        neutrospline_io::read_data(STDIN_NAME, std::io::stdin().lock(), membership)
    } else {
        neutrospline_io::load_data(file, membership)
    };
    result.map_err(|e| anyhow::Error::msg(e.to_string()))
}
