//! The Python package `neutrospline`: the engine of the workspace from numpy and Jupyter.
//!
//! A thin layer over the core (`neutrospline`), the formats (`neutrospline-io`) and the
//! figures (`neutrospline-plot`): arrays in and out, the batch evaluator with the GIL released,
//! models saved and loaded through the shared formats, figures as SVG and PNG. Invalid input
//! raises `neutrospline.ModelError` (a `ValueError`) with the command line's message. The
//! Python side (`python/neutrospline`) re-exports this module and holds the type stubs. See
//! docs/architecture.md.

use pyo3::prelude::*;

mod arrays;
mod cli;
mod curve;
mod errors;
mod fitting;
mod frame;
mod functions;
mod inline;
mod model;
mod options;
mod shape;
mod surface;
mod type_reduction;

/// The extension module `neutrospline._neutrospline`.
#[pymodule]
fn _neutrospline(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("ModelError", py.get_type::<errors::ModelError>())?;
    m.add_class::<shape::BaseShape>()?;
    m.add_class::<curve::Curve>()?;
    m.add_class::<curve::Bezier>()?;
    m.add_class::<curve::BSpline>()?;
    m.add_class::<curve::Nurbs>()?;
    m.add_class::<surface::Surface>()?;
    m.add_class::<surface::BezierSurface>()?;
    m.add_class::<surface::BSplineSurface>()?;
    m.add_class::<surface::NurbsSurface>()?;
    m.add_function(wrap_pyfunction!(functions::load, m)?)?;
    m.add_function(wrap_pyfunction!(functions::example1, m)?)?;
    m.add_function(wrap_pyfunction!(functions::score, m)?)?;
    m.add_function(wrap_pyfunction!(functions::accuracy, m)?)?;
    m.add_function(wrap_pyfunction!(functions::certainty, m)?)?;
    m.add_function(wrap_pyfunction!(functions::derived_degrees, m)?)?;
    m.add_function(wrap_pyfunction!(functions::family_rule, m)?)?;
    m.add_function(wrap_pyfunction!(functions::largest_relation, m)?)?;
    m.add_function(wrap_pyfunction!(functions::check_relation, m)?)?;
    m.add_function(wrap_pyfunction!(functions::_restore, m)?)?;
    m.add_function(wrap_pyfunction!(fitting::fit, m)?)?;
    m.add_function(wrap_pyfunction!(fitting::fit_options, m)?)?;
    m.add_function(wrap_pyfunction!(fitting::figure_options, m)?)?;
    m.add_function(wrap_pyfunction!(functions::import_options, m)?)?;
    m.add_function(wrap_pyfunction!(functions::table_options, m)?)?;
    m.add_function(wrap_pyfunction!(functions::transform_options, m)?)?;
    m.add_function(wrap_pyfunction!(inline::inline, m)?)?;
    m.add_function(wrap_pyfunction!(fitting::fit_surface, m)?)?;
    m.add_function(wrap_pyfunction!(fitting::fit_surface_options, m)?)?;
    m.add_function(wrap_pyfunction!(cli::_run_cli, m)?)?;
    m.add_function(wrap_pyfunction!(type_reduction::centroid_interval, m)?)?;
    m.add("instruction_set", neutrospline::batch::instruction_set())?;
    // The workspace's version (Cargo.toml), which is also the wheel's.
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
