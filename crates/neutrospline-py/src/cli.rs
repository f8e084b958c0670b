//! The wheel's `neutrospline` console script: the command line itself, linked into the
//! extension module, so `pip install neutrospline` gives the same command as
//! `cargo install --path crates/neutrospline-cli` (the same arguments, messages and exit
//! statuses; see `neutrospline_cli::run_with_args`).

use pyo3::prelude::*;

/// Runs the `neutrospline` command line with `argv` (the program name first, as `sys.argv`)
/// and returns its exit status. The GIL is released while it runs.
///
/// It is the body of the console script (`neutrospline._cli.main`), which owns its process:
/// the command installs its SIGINT / SIGTERM handlers (so an interrupted `eval -o FILE` leaves
/// the old output untouched) and its resource limits once per process.
#[pyfunction]
pub fn _run_cli(py: Python<'_>, argv: Vec<std::ffi::OsString>) -> u8 {
    py.detach(|| neutrospline_cli::run_with_args(argv))
}
