//! Reading the model file named on the command line, through `neutrospline-io`: `-` is CSV on
//! standard input, the shape options and the limits become [`ReadOptions`], and the library's
//! errors become the command's (a [`UsageError`] exits with status 2).

use std::fmt;

use neutrospline::Family;
use neutrospline_io::{DataTable, Model, ReadError, ReadOptions, TableInput};

use crate::commands::options::ModelArgs;

/// The name used for standard input in messages.
pub const STDIN_NAME: &str = "<stdin>";

/// The file extensions the command accepts, with `-` meaning CSV on standard input.
pub const ACCEPTED_EXTENSIONS: &str = ".csv, .tsv, .toml, .json; `-` reads CSV from standard input";

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
///
/// # Errors
/// A [`UsageError`] for table options that do not fit together.
pub fn read_options(args: &ModelArgs) -> Result<ReadOptions, UsageError> {
    let mut options = args.read_options();
    options.limits = crate::limits::current().file_limits();
    options.table = args.table_input()?;
    Ok(options)
}

/// Reads and validates `file` (`-` for CSV on standard input, streamed).
///
/// # Errors
/// A [`UsageError`] for an unsupported extension or options that do not fit together; the
/// library's message (file, line, field, value and rule; or the I/O error) otherwise.
pub fn read_model(file: &str, args: &ModelArgs) -> anyhow::Result<Model> {
    let options = read_options(args)?;
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

/// Refuses a model of an interval-valued or bipolar family (two lanes, docs/model.md "Lanes")
/// in a command that reads the families of one lane only, with the reason.
///
/// # Errors
/// The model's family has two lanes.
pub fn one_lane(file: &str, model: Model, command: &str, reason: &str) -> anyhow::Result<Model> {
    let family = model.membership();
    if family.lane_count() == 1 {
        return Ok(model);
    }
    Err(anyhow::anyhow!(
        "{}: membership {family}: `neutrospline {command}` {reason}",
        label(file)
    ))
}

/// Reads a data file (or standard input for `-`) as `input` says.
///
/// # Errors
/// A [`UsageError`] for an extension that is not a table's; the located error of the io
/// crate.
pub fn read_data(file: &str, membership: Family, input: &TableInput) -> anyhow::Result<DataTable> {
    let result = if file == "-" {
        neutrospline_io::read_data_with(STDIN_NAME, std::io::stdin().lock(), membership, input)
    } else {
        neutrospline_io::load_data_with(file, membership, input)
    };
    result.map_err(table_error)
}

/// A table reader's error as the command's: an extension that is not a table's, and options
/// that do not fit the file (`--sheet` of a CSV file), are usage errors (exit 2), with the
/// same message in every command.
pub fn table_error(error: ReadError) -> anyhow::Error {
    match error {
        ReadError::Format(e) => UsageError(e.to_string()).into(),
        e if e.is_usage() => UsageError(e.to_string()).into(),
        e => anyhow::Error::msg(e.to_string()),
    }
}
