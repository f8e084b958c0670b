//! Arrays in and out: any array-like of numbers in (lists, tuples, float32, strided or read-only
//! arrays, converted by numpy only when they are not float64 already), float64 arrays out, and
//! the `out=` convention of numpy's ufuncs.

use numpy::ndarray::ArrayViewMut2;
use numpy::{
    IntoPyArray, PyArray, PyArray1, PyArray2, PyArrayDyn, PyArrayMethods, PyReadonlyArrayDyn,
    PyReadwriteArray2, PyUntypedArrayMethods,
};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::errors::invalid_at;

/// `numpy.asarray(obj, dtype=numpy.float64)` (no copy when `obj` is a float64 array already),
/// read-only. `what` names the argument in messages.
pub fn float_array<'py>(
    obj: &Bound<'py, PyAny>,
    what: &str,
) -> PyResult<PyReadonlyArrayDyn<'py, f64>> {
    let py = obj.py();
    let numpy = py.import("numpy")?;
    let kwargs = PyDict::new(py);
    kwargs.set_item("dtype", numpy.getattr("float64")?)?;
    let array = numpy
        .call_method("asarray", (obj,), Some(&kwargs))
        .map_err(|e| invalid_at(what, format!("not an array of numbers ({})", e.value(py))))?;
    let array = array.cast_into::<PyArrayDyn<f64>>()?;
    Ok(array.try_readonly()?)
}

/// The parameters of an evaluation: one number, or a 1-D array of them.
pub enum Params<'py> {
    /// A float (or a 0-d array): the result drops the parameter axis.
    Scalar(f64),
    /// A 1-D array, contiguous (numpy copies a strided one once).
    Array(PyReadonlyArrayDyn<'py, f64>),
}

impl<'py> Params<'py> {
    /// Reads `t` (named `what` in messages).
    pub fn read(t: &Bound<'py, PyAny>, what: &str) -> PyResult<Params<'py>> {
        let array = float_array(t, what)?;
        match array.ndim() {
            0 => Ok(Params::Scalar(
                *array.as_array().first().unwrap_or(&f64::NAN),
            )),
            1 if array.is_c_contiguous() => Ok(Params::Array(array)),
            1 => {
                let py = t.py();
                let contiguous = py
                    .import("numpy")?
                    .call_method1("ascontiguousarray", (array.as_any(),))?
                    .cast_into::<PyArrayDyn<f64>>()?;
                Ok(Params::Array(contiguous.try_readonly()?))
            }
            n => Err(invalid_at(
                what,
                format!(
                    "expected a number or a 1-D array of numbers, got a {n}-D array of shape {:?}",
                    array.shape()
                ),
            )),
        }
    }

    /// The parameters as a slice (one for a scalar).
    pub fn values(&self) -> &[f64] {
        match self {
            Params::Scalar(t) => std::slice::from_ref(t),
            Params::Array(a) => a.as_slice().unwrap_or(&[]),
        }
    }
}

/// Where an evaluation writes: a new or the caller's `(n, columns)` float64 array.
pub struct Output<'py> {
    array: Bound<'py, PyArray2<f64>>,
}

impl<'py> Output<'py> {
    /// The caller's `out`, checked (float64, shape `(n, columns)`, writeable), or a new
    /// Fortran-ordered array (each column contiguous, as the engine writes them).
    pub fn new(
        py: Python<'py>,
        out: Option<&Bound<'py, PyAny>>,
        n: usize,
        columns: usize,
    ) -> PyResult<Output<'py>> {
        let Some(out) = out else {
            return Ok(Output {
                array: PyArray2::zeros(py, [n, columns], true),
            });
        };
        let array = out.cast::<PyArray2<f64>>().map_err(|_| {
            let described = describe(out);
            invalid_at(
                "out",
                format!("expected a float64 array of shape ({n}, {columns}), got {described}"),
            )
        })?;
        if array.shape() != [n, columns] {
            return Err(invalid_at(
                "out",
                format!(
                    "expected shape ({n}, {columns}), got {:?} (one row per parameter, one \
                     column per coordinate and degree)",
                    array.shape()
                ),
            ));
        }
        Ok(Output {
            array: array.clone(),
        })
    }

    /// Borrows the array for writing.
    pub fn write(&self) -> PyResult<Writer<'py>> {
        Ok(Writer {
            fortran: self.array.is_fortran_contiguous(),
            array: self
                .array
                .try_readwrite()
                .map_err(|e| invalid_at("out", format!("cannot write into the array ({e})")))?,
        })
    }

    /// The output array.
    pub fn array(&self) -> &Bound<'py, PyArray2<f64>> {
        &self.array
    }

    /// The array, or its only row for a scalar parameter.
    pub fn finish(self, scalar: bool) -> PyResult<Py<PyAny>> {
        if scalar {
            Ok(self.array.get_item(0)?.unbind())
        } else {
            Ok(self.array.into_any().unbind())
        }
    }
}

/// Text describing a Python object for messages: its type, and a numpy array's dtype and
/// shape.
fn describe(obj: &Bound<'_, PyAny>) -> String {
    let dtype = obj.getattr("dtype").map(|d| d.to_string());
    let shape = obj.getattr("shape").map(|s| s.to_string());
    match (dtype, shape) {
        (Ok(dtype), Ok(shape)) => format!("an array of dtype {dtype} and shape {shape}"),
        _ => format!(
            "an object of type {}",
            obj.get_type()
                .name()
                .map_or_else(|_| "?".into(), |n| n.to_string())
        ),
    }
}

/// A borrowed output array: channel-major memory when it is Fortran-ordered (the layout the
/// batch engine writes), an element view otherwise.
pub struct Writer<'py> {
    fortran: bool,
    array: PyReadwriteArray2<'py, f64>,
}

impl Writer<'_> {
    /// The memory as channel-major columns (`column c, row k` at `c * n + k`) when the array
    /// is Fortran-contiguous.
    pub fn columns(&mut self) -> Option<&mut [f64]> {
        if self.fortran {
            self.array.as_slice_mut().ok()
        } else {
            None
        }
    }

    /// The array as an element view.
    pub fn view(&mut self) -> ArrayViewMut2<'_, f64> {
        self.array.as_array_mut()
    }
}

/// A read-only float64 array of `shape` holding `values` (row-major).
pub fn readonly_array<'py>(
    py: Python<'py>,
    values: Vec<f64>,
    shape: &[usize],
) -> PyResult<Bound<'py, PyAny>> {
    let array = values.into_pyarray(py).reshape(shape.to_vec())?;
    freeze(array.as_any())?;
    Ok(array.into_any())
}

/// Marks an array read-only (`array.flags.writeable = False`).
pub fn freeze(array: &Bound<'_, PyAny>) -> PyResult<()> {
    let kwargs = PyDict::new(array.py());
    kwargs.set_item("write", false)?;
    array.call_method("setflags", (), Some(&kwargs))?;
    Ok(())
}

/// A new float64 array of `shape` (row-major) from `values`.
pub fn new_array<'py>(
    py: Python<'py>,
    values: Vec<f64>,
    shape: &[usize],
) -> PyResult<Bound<'py, PyAny>> {
    Ok(values.into_pyarray(py).reshape(shape.to_vec())?.into_any())
}

/// A 1-D float64 array.
pub fn vector<'py>(py: Python<'py>, values: Vec<f64>) -> Bound<'py, PyArray1<f64>> {
    PyArray::from_vec(py, values)
}
