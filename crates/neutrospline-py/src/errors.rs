//! `neutrospline.ModelError` and the conversion of the engine's errors into Python
//! exceptions: invalid input is a `ModelError` (a `ValueError`) with the one-line message the
//! command line prints; a failed write of a file is an `OSError`.

use std::fmt::Display;

use pyo3::exceptions::PyOSError;
use pyo3::PyErr;

pyo3::create_exception!(
    neutrospline,
    ModelError,
    pyo3::exceptions::PyValueError,
    "Invalid input: a model, an array, a parameter or an option that breaks a rule of the model.\n\n\
     The message is the one the command line prints: it names the file and line, or the array\n\
     and index, the value and the rule. A subclass of ValueError."
);

/// A [`ModelError`] with `message`.
pub fn invalid(message: impl Display) -> PyErr {
    ModelError::new_err(message.to_string())
}

/// A [`ModelError`] naming the argument or array element `what` first.
pub fn invalid_at(what: impl Display, message: impl Display) -> PyErr {
    ModelError::new_err(format!("{what}: {message}"))
}

/// A write error: unrepresentable models and formats are invalid input, I/O failures `OSError`.
pub fn write_error(error: neutrospline_io::WriteError) -> PyErr {
    match error {
        neutrospline_io::WriteError::Io { .. } => PyOSError::new_err(error.to_string()),
        other => invalid(other),
    }
}
