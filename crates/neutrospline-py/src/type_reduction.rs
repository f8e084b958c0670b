//! `neutrospline.centroid_interval`: type reduction of an interval type-2 fuzzy set
//! (docs/model.md, "Type reduction").

use pyo3::prelude::*;

use crate::errors::invalid;

/// The centroid interval of an interval type-2 fuzzy set sampled at the points `x` with lower
/// memberships `lower` and upper memberships `upper` (sequences or 1-D arrays of one length,
/// `0 <= lower[k] <= upper[k]`), as `(c_l, c_r, midpoint)`:
///
/// `c_l` and `c_r` are the smallest and largest centroid `sum x_k w_k / sum w_k` over every
/// embedded set `lower[k] <= w_k <= upper[k]`, and `midpoint = (c_l + c_r) / 2` is the
/// type-reduced value. Computed exactly (the Karnik-Mendel switch point, found by a scan over
/// the points sorted by x). Raises `ModelError` for sequences of different lengths, a value
/// that is not finite, a negative lower membership, `lower > upper`, or every upper
/// membership 0 (no centroid).
///
/// >>> import neutrospline as ns
/// >>> ns.centroid_interval([-1.0, 0.0, 1.0], [0.25, 0.25, 0.25], [1.0, 1.0, 1.0])
/// (-0.5, 0.5, 0.0)
#[pyfunction]
pub fn centroid_interval(
    x: Vec<f64>,
    lower: Vec<f64>,
    upper: Vec<f64>,
) -> PyResult<(f64, f64, f64)> {
    let c = neutrospline::centroid_interval(&x, &lower, &upper).map_err(invalid)?;
    Ok((c.lower, c.upper, c.midpoint()))
}
