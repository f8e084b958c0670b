//! A job's options from Python keyword arguments: one reader over the library's
//! [`OptionSet`], so that names, defaults and messages are those of the command line and the
//! studio (docs/architecture.md, "one definition of every option").

use neutrospline::options::{OptionSet, OptionValue, ValueKind};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};

use crate::errors::invalid;

/// The Python value as the library's [`OptionValue`], kept as it was given: `True` is a
/// flag, `5` an integer, `5.0` a number, `"score"` text, a list or tuple a list (a numpy
/// array of numbers too); anything else is refused with the
/// option's name and what it expects.
fn option_value(name: &str, kind: ValueKind, value: &Bound<'_, PyAny>) -> PyResult<OptionValue> {
    // bool before int: True is an int in Python.
    if value.is_instance_of::<PyBool>() {
        return Ok(OptionValue::Flag(value.extract()?));
    }
    if value.is_instance_of::<PyInt>() {
        return Ok(match value.extract::<i64>() {
            Ok(n) => OptionValue::Integer(n),
            Err(_) => OptionValue::Number(value.extract()?),
        });
    }
    if value.is_instance_of::<PyFloat>() {
        return Ok(OptionValue::Number(value.extract()?));
    }
    if value.is_instance_of::<PyString>() {
        return Ok(OptionValue::Text(value.extract()?));
    }
    if value.is_instance_of::<PyList>() || value.is_instance_of::<PyTuple>() {
        return value
            .try_iter()?
            .map(|item| option_value(name, kind, &item?))
            .collect::<PyResult<_>>()
            .map(OptionValue::List);
    }
    // A numpy array as its list; numpy scalars: an integer type has __index__, a float type
    // __float__.
    if value.hasattr("dtype")? && value.getattr("ndim")?.extract::<usize>()? > 0 {
        return option_value(name, kind, &value.call_method0("tolist")?);
    }
    if value.hasattr("__index__")? {
        return Ok(OptionValue::Integer(
            value.call_method0("__index__")?.extract()?,
        ));
    }
    if value.hasattr("dtype")? && value.hasattr("__float__")? {
        return Ok(OptionValue::Number(value.extract()?));
    }
    Err(invalid(format!(
        "{name} = {}: {}",
        value.repr()?,
        kind.expected()
    )))
}

/// Sets every keyword argument of `options` on `request`: `control_points` is the option
/// `control-points`; `None` leaves the library's default.
///
/// # Errors
/// `ModelError` with the library's message for an unknown name, a value of another kind or
/// not one of the choices.
pub fn set_from_kwargs<R: OptionSet>(
    request: &mut R,
    options: Option<&Bound<'_, PyDict>>,
) -> PyResult<()> {
    let Some(options) = options else {
        return Ok(());
    };
    for (key, value) in options.iter() {
        let name = key.extract::<String>()?.replace('_', "-");
        if value.is_none() {
            continue;
        }
        let kind = R::OPTIONS
            .iter()
            .find(|spec| spec.name == name)
            .map_or(ValueKind::Text, |spec| spec.kind);
        let value = option_value(&name, kind, &value)?;
        request.set(&name, value).map_err(invalid)?;
    }
    Ok(())
}

/// The options of `R` as a list of dictionaries: `name` (the keyword argument), `option`
/// (the command line's name), `kind`, `choices`, `default` (the library's, as Python values;
/// `None` when unset), `default_text` (as the command line writes it) and `help`.
pub fn table<'py, R: OptionSet>(py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
    let defaults = R::default();
    let list = PyList::empty(py);
    for spec in R::OPTIONS {
        let entry = PyDict::new(py);
        entry.set_item("name", spec.python_name())?;
        entry.set_item("option", spec.name)?;
        let default = defaults.value_text(spec.name).map_err(invalid)?;
        entry.set_item("default_text", default.clone())?;
        let (kind, choices, default): (&str, Option<Vec<&str>>, Py<PyAny>) = match spec.kind {
            ValueKind::Flag => (
                "bool",
                None,
                default
                    .map(|d| d == "true")
                    .into_pyobject(py)?
                    .into_any()
                    .unbind(),
            ),
            ValueKind::Whole => (
                "int",
                None,
                default
                    .map(|d| d.parse::<usize>())
                    .transpose()
                    .map_err(invalid)?
                    .into_pyobject(py)?
                    .into_any()
                    .unbind(),
            ),
            ValueKind::Number => (
                "float",
                None,
                default
                    .map(|d| d.parse::<f64>())
                    .transpose()
                    .map_err(invalid)?
                    .into_pyobject(py)?
                    .into_any()
                    .unbind(),
            ),
            ValueKind::Numbers => (
                "list[float]",
                None,
                default
                    .map(|d| {
                        d.split(',')
                            .map(str::parse::<f64>)
                            .collect::<Result<Vec<_>, _>>()
                    })
                    .transpose()
                    .map_err(invalid)?
                    .into_pyobject(py)?
                    .into_any()
                    .unbind(),
            ),
            ValueKind::Choice(names) => (
                "str",
                Some(names.to_vec()),
                default.into_pyobject(py)?.into_any().unbind(),
            ),
            ValueKind::Text => ("str", None, default.into_pyobject(py)?.into_any().unbind()),
        };
        entry.set_item("kind", kind)?;
        entry.set_item("choices", choices)?;
        entry.set_item("default", default)?;
        entry.set_item("help", spec.help)?;
        list.append(entry)?;
    }
    Ok(list)
}
