//! Arrays in and out: one reading path for every array argument ([`float_array`]), float64
//! arrays out, and the `out=` convention of numpy's ufuncs.
//!
//! What the reading path accepts: any numpy array or array-like of real numbers (lists,
//! tuples, nested sequences, objects with `__array__`), of any layout numpy makes (aligned or
//! not, native or byte-swapped, C, Fortran or strided, read-only or writeable) and of any real
//! dtype (float16/32/64, signed and unsigned integers). An aligned, C-contiguous, native-endian
//! float64 array is borrowed without a copy; anything else is converted by numpy's own cast into
//! a fresh aligned C-contiguous float64 array. The cast is exact: float16 and float32 widen
//! exactly, integers of up to 53 bits are exact, and a value that a float64 cannot hold exactly
//! (a 64-bit integer above 2^53, a long double with more digits) is refused, naming the element.
//! Booleans, complex numbers, strings, `None` and other objects are refused the same way: no
//! input is ever read as an empty, default or NaN value.

use numpy::ndarray::ArrayViewMut2;
use numpy::{
    IntoPyArray, PyArray, PyArray1, PyArray2, PyArrayDescrMethods, PyArrayDyn, PyArrayMethods,
    PyReadonlyArrayDyn, PyReadwriteArray2, PyUntypedArray, PyUntypedArrayMethods,
};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyBytes, PyDict, PyFloat, PyInt, PyString};
use pyo3::PyTypeInfo;

use crate::errors::{invalid, invalid_at};

/// An array argument read as float64 values: aligned, C-contiguous (row-major) and
/// native-endian, borrowed from the caller's array or a fresh exact copy of it.
pub struct FloatArray<'py> {
    array: PyReadonlyArrayDyn<'py, f64>,
    what: String,
}

impl<'py> FloatArray<'py> {
    /// The shape.
    pub fn shape(&self) -> &[usize] {
        self.array.shape()
    }

    /// The number of axes.
    pub fn ndim(&self) -> usize {
        self.array.ndim()
    }

    /// The values in row-major order (one for a 0-d array).
    pub fn values(&self) -> PyResult<&[f64]> {
        // The reading path made the array aligned and C-contiguous, so this holds; an error
        // here would name the argument rather than read nothing.
        self.array.as_slice().map_err(|e| {
            invalid_at(
                &self.what,
                format!("cannot read the array's memory as float64 values ({e})"),
            )
        })
    }
}

/// Reads the array argument `obj` (named `what` in messages) as float64 values; see the
/// module's documentation for what is accepted. The fast path (an aligned, C-contiguous,
/// native float64 array) borrows without copying.
pub fn float_array<'py>(obj: &Bound<'py, PyAny>, what: &str) -> PyResult<FloatArray<'py>> {
    let py = obj.py();
    if let Some(ready) = borrow_ready(obj, what)? {
        return Ok(ready);
    }
    let numpy = py.import("numpy")?;
    let unmasked = unmask(&numpy, obj, what)?;
    let obj = &unmasked;
    let array = match obj.cast::<PyUntypedArray>() {
        Ok(array) => array.clone(),
        Err(_) => {
            let array = numpy.call_method1("asarray", (obj,)).map_err(|e| {
                invalid_at(what, format!("not an array of numbers ({})", e.value(py)))
            })?;
            if let Some(ready) = borrow_ready(&array, what)? {
                return Ok(ready);
            }
            array.cast_into::<PyUntypedArray>().map_err(|_| {
                invalid_at(
                    what,
                    "not an array of numbers (numpy.asarray gave no array)",
                )
            })?
        }
    };
    let dtype = array.dtype();
    let kind = dtype.kind();
    let described = || {
        format!(
            "dtype {}",
            dtype.str().map_or_else(|_| "?".into(), |s| s.to_string())
        )
    };
    match kind {
        b'f' | b'i' | b'u' => {}
        b'O' => check_objects(&array, what)?,
        b'b' => {
            return Err(invalid_at(
                what,
                format!("expected numbers, got booleans ({})", described()),
            ))
        }
        b'c' => {
            return Err(invalid_at(
                what,
                format!(
                    "expected real numbers, got complex numbers ({}); pass the real part \
                     (numpy.real) if that is what is meant",
                    described()
                ),
            ))
        }
        b'U' | b'S' => {
            return Err(invalid_at(
                what,
                format!("expected numbers, got strings ({})", described()),
            ))
        }
        _ => {
            return Err(invalid_at(
                what,
                format!("expected numbers, got an array of {}", described()),
            ))
        }
    }
    let kwargs = PyDict::new(py);
    kwargs.set_item("dtype", numpy.getattr("float64")?)?;
    kwargs.set_item("order", "C")?;
    kwargs.set_item("copy", true)?;
    let fresh = numpy
        .call_method("array", (&array,), Some(&kwargs))
        .map_err(|e| invalid_at(what, format!("not an array of numbers ({})", e.value(py))))?;
    // 64-bit integers and long doubles may hold values a float64 rounds: cast back and refuse
    // the first value that did not survive.
    if (matches!(kind, b'i' | b'u') && dtype.itemsize() > 4)
        || (kind == b'f' && dtype.itemsize() > 8)
    {
        check_round_trip(&numpy, &array, &fresh, what)?;
    }
    let fresh = fresh
        .cast_into::<PyArrayDyn<f64>>()
        .map_err(|_| invalid_at(what, "numpy's float64 cast gave no float64 array"))?;
    let array = fresh
        .try_readonly()
        .map_err(|e| invalid_at(what, format!("cannot read the array ({e})")))?;
    Ok(FloatArray {
        array,
        what: what.to_owned(),
    })
}

/// The data of a numpy masked array without masked elements (refusing the first masked
/// one: it has no value); any other object unchanged.
fn unmask<'py>(
    numpy: &Bound<'py, PyModule>,
    obj: &Bound<'py, PyAny>,
    what: &str,
) -> PyResult<Bound<'py, PyAny>> {
    let ma = numpy.getattr("ma")?;
    if !obj.is_instance(&ma.getattr("MaskedArray")?)? {
        return Ok(obj.clone());
    }
    let mask = ma.call_method1("getmaskarray", (obj,))?;
    let masked = numpy.call_method1("flatnonzero", (mask,))?;
    if masked.len()? > 0 {
        let k: usize = masked.get_item(0)?.extract()?;
        let shape: Vec<usize> = obj.getattr("shape")?.extract()?;
        return Err(invalid(format!(
            "{} is masked: a masked element has no value (fill it, or drop it)",
            element_name(what, k, &shape)
        )));
    }
    obj.getattr("data")
}

/// `obj` borrowed when it is a plain numpy array (not a subclass, which may carry a mask)
/// that is aligned, C-contiguous, native-endian float64 (the fast path, no copy); `None`
/// otherwise.
fn borrow_ready<'py>(obj: &Bound<'py, PyAny>, what: &str) -> PyResult<Option<FloatArray<'py>>> {
    if !obj.get_type().is(PyUntypedArray::type_object(obj.py())) {
        return Ok(None);
    }
    let Ok(array) = obj.cast::<PyArrayDyn<f64>>() else {
        return Ok(None);
    };
    let native = array.dtype().is_native_byteorder() != Some(false);
    if !(native && array.is_aligned() && array.is_c_contiguous()) {
        return Ok(None);
    }
    let array = array
        .try_readonly()
        .map_err(|e| invalid_at(what, format!("cannot read the array ({e})")))?;
    Ok(Some(FloatArray {
        array,
        what: what.to_owned(),
    }))
}

/// The name of element `k` (row-major) of an array of `shape` argument `what`: `t[3]`,
/// `points[1, 2]`, or `what` itself for a 0-d array.
pub fn element_name(what: &str, mut k: usize, shape: &[usize]) -> String {
    if shape.is_empty() {
        return what.to_owned();
    }
    let mut index = vec![0; shape.len()];
    for (slot, &size) in index.iter_mut().zip(shape).rev() {
        *slot = k % size.max(1);
        k /= size.max(1);
    }
    let parts: Vec<String> = index.iter().map(ToString::to_string).collect();
    format!("{what}[{}]", parts.join(", "))
}

/// Refuses the first element of an object array that is not a real number: `None`, a bool, a
/// string, bytes, a complex number, a sequence, or an integer (Python's or numpy's) that a
/// float64 cannot hold exactly.
fn check_objects(array: &Bound<'_, PyUntypedArray>, what: &str) -> PyResult<()> {
    let shape = array.shape().to_vec();
    let py = array.py();
    let numbers = py.import("numbers")?;
    let (integral, complex, real) = (
        numbers.getattr("Integral")?,
        numbers.getattr("Complex")?,
        numbers.getattr("Real")?,
    );
    let int = py.get_type::<PyInt>();
    let flat = array.call_method0("ravel")?;
    for (k, item) in flat.try_iter()?.enumerate() {
        let item = item?;
        let name = || element_name(what, k, &shape);
        let refuse = |why: &str| -> PyResult<()> {
            let shown = item.repr().map_or_else(|_| "?".into(), |r| r.to_string());
            Err(invalid(format!("{} = {shown} {why}", name())))
        };
        if item.is_none() {
            return refuse("is not a number");
        }
        if item.is_instance_of::<PyBool>()
            || item
                .getattr("dtype")
                .is_ok_and(|d| d.getattr("kind").is_ok_and(|k| k.to_string() == "b"))
        {
            return refuse("is a boolean, not a number");
        }
        if item.is_instance_of::<PyString>() || item.is_instance_of::<PyBytes>() {
            return refuse("is a string, not a number");
        }
        if item.is_instance_of::<PyFloat>() {
            continue;
        }
        if item.is_instance(&integral)? {
            // Python and numpy integers: exact when converting to float64 and back gives the
            // same integer (every one up to 2^53, and larger ones of few significant bits).
            let Ok(nearest) = item.call_method0("__float__") else {
                return refuse("is an integer too large for a float64");
            };
            let back = int.call1((&nearest,))?;
            if !back.eq(&item)? {
                return refuse("is an integer a float64 cannot hold exactly (beyond 2^53)");
            }
            continue;
        }
        if item.is_instance(&complex)? && !item.is_instance(&real)? {
            return refuse("is a complex number, not a real number");
        }
        if !item.hasattr("__float__")? {
            return refuse("is not a number");
        }
    }
    Ok(())
}

/// Refuses the first value of `original` that its float64 cast `fresh` does not hold exactly.
fn check_round_trip(
    numpy: &Bound<'_, PyModule>,
    original: &Bound<'_, PyUntypedArray>,
    fresh: &Bound<'_, PyAny>,
    what: &str,
) -> PyResult<()> {
    // Casting back may overflow for values near the integer type's ends: those differ anyway,
    // so numpy's warnings about them are silenced.
    let quiet = PyDict::new(numpy.py());
    quiet.set_item("all", "ignore")?;
    let errstate = numpy.call_method("errstate", (), Some(&quiet))?;
    errstate.call_method0("__enter__")?;
    let back = fresh.call_method1("astype", (original.dtype(),));
    errstate.call_method1(
        "__exit__",
        (numpy.py().None(), numpy.py().None(), numpy.py().None()),
    )?;
    let back = back?;
    let same = numpy.call_method1("equal", (&back, original))?;
    let both_nan = numpy.call_method1(
        "logical_and",
        (
            numpy.call_method1("isnan", (original,))?,
            numpy.call_method1("isnan", (fresh,))?,
        ),
    )?;
    let kept = numpy.call_method1("logical_or", (same, both_nan))?;
    let lost = numpy.call_method1(
        "flatnonzero",
        (numpy.call_method1("logical_not", (kept,))?,),
    )?;
    if lost.len()? == 0 {
        return Ok(());
    }
    let k: usize = lost.get_item(0)?.extract()?;
    let shape = original.shape().to_vec();
    let value = original.call_method0("ravel")?.get_item(k)?;
    let nearest: f64 = fresh.call_method0("ravel")?.get_item(k)?.extract()?;
    Err(invalid(format!(
        "{} = {} ({}) is not exactly a float64 (the nearest is {nearest:?}): refused rather \
         than rounded",
        element_name(what, k, &shape),
        value.str()?,
        original.dtype().str()?,
    )))
}

/// The parameters of an evaluation: one number, or a 1-D array of them.
pub enum Params<'py> {
    /// A float (or a 0-d array): the result drops the parameter axis.
    Scalar(f64),
    /// A 1-D array of parameters (empty: no rows).
    Array(FloatArray<'py>),
}

impl<'py> Params<'py> {
    /// Reads `t` (named `what` in messages): a Python float, a 0-d array (a scalar
    /// parameter) or a 1-D array of any layout the reading path accepts ([`float_array`]).
    pub fn read(t: &Bound<'py, PyAny>, what: &str) -> PyResult<Params<'py>> {
        if t.is_instance_of::<PyFloat>() {
            return Ok(Params::Scalar(t.extract::<f64>()?));
        }
        let array = float_array(t, what)?;
        match array.ndim() {
            0 => {
                let value = array.values()?.first().copied().ok_or_else(|| {
                    invalid_at(what, "a 0-d array without a value (numpy always has one)")
                })?;
                Ok(Params::Scalar(value))
            }
            1 => Ok(Params::Array(array)),
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
    pub fn values(&self) -> PyResult<&[f64]> {
        match self {
            Params::Scalar(t) => Ok(std::slice::from_ref(t)),
            Params::Array(a) => a.values(),
        }
    }
}

/// The caller's `out` array checked for writing `shape` float64 values in place: a float64
/// array of native byte order, of that shape, aligned and writeable (strides may be any).
/// Anything else raises `ModelError` naming `out`: nothing is ever written elsewhere or
/// silently skipped.
pub fn checked_out<'py>(
    out: &Bound<'py, PyAny>,
    shape: &[usize],
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let shown = shape_text(shape);
    let array = out.cast::<PyArrayDyn<f64>>().map_err(|_| {
        invalid_at(
            "out",
            format!(
                "expected a float64 array of shape {shown}, got {}",
                describe(out)
            ),
        )
    })?;
    if array.shape() != shape {
        return Err(invalid_at(
            "out",
            format!("expected shape {shown}, got {:?}", array.shape()),
        ));
    }
    if array.dtype().is_native_byteorder() == Some(false) {
        return Err(invalid_at(
            "out",
            format!(
                "expected a float64 array of native byte order, got {} (the values are \
                 written in place, so they cannot be byte-swapped)",
                describe(out)
            ),
        ));
    }
    if !array.is_aligned() {
        return Err(invalid_at(
            "out",
            "cannot write into the array in place: its memory is not aligned to 8 bytes (give \
             an aligned float64 array, such as numpy.empty makes)",
        ));
    }
    if array.len() > 0 && array.strides().iter().any(|&s| s % 8 != 0) {
        return Err(invalid_at(
            "out",
            format!(
                "cannot write into the array in place: its strides {:?} are not multiples of 8 \
                 bytes",
                array.strides()
            ),
        ));
    }
    Ok(array.clone())
}

/// `(a, b)` for messages.
fn shape_text(shape: &[usize]) -> String {
    let parts: Vec<String> = shape.iter().map(ToString::to_string).collect();
    if parts.len() == 1 {
        format!("({},)", parts[0])
    } else {
        format!("({})", parts.join(", "))
    }
}

/// Where an evaluation writes: a new or the caller's `(n, columns)` float64 array.
pub struct Output<'py> {
    array: Bound<'py, PyArray2<f64>>,
}

impl<'py> Output<'py> {
    /// The caller's `out`, checked by [`checked_out`] for shape `(n, columns)`, or a new
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
        let array = checked_out(out, &[n, columns])?;
        let array = array.into_any().cast_into::<PyArray2<f64>>().map_err(|_| {
            invalid_at(
                "out",
                format!("expected a 2-D array of shape ({n}, {columns})"),
            )
        })?;
        Ok(Output { array })
    }

    /// Borrows the array for writing.
    pub fn write(&self) -> PyResult<Writer<'py>> {
        let array = self
            .array
            .try_readwrite()
            .map_err(|e| invalid_at("out", format!("cannot write into the array ({e})")))?;
        Ok(if self.array.is_fortran_contiguous() {
            Writer::Columns(array)
        } else {
            Writer::Elements(array)
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

/// A borrowed, checked (aligned, native float64) output array.
pub enum Writer<'py> {
    /// Fortran-contiguous: channel-major memory, the layout the batch engine writes.
    Columns(PyReadwriteArray2<'py, f64>),
    /// Any other strides: written element by element.
    Elements(PyReadwriteArray2<'py, f64>),
}

impl Writer<'_> {
    /// The memory as channel-major columns (`column c, row k` at `c * n + k`) when the array
    /// is Fortran-contiguous, `None` for other strides.
    pub fn columns(&mut self) -> PyResult<Option<&mut [f64]>> {
        match self {
            Writer::Columns(array) => array
                .as_slice_mut()
                .map(Some)
                .map_err(|e| invalid_at("out", format!("cannot write into the array ({e})"))),
            Writer::Elements(_) => Ok(None),
        }
    }

    /// The array as an element view.
    pub fn view(&mut self) -> ArrayViewMut2<'_, f64> {
        match self {
            Writer::Columns(array) | Writer::Elements(array) => array.as_array_mut(),
        }
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
