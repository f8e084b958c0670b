//! Evaluating a curve or its derivative into numpy arrays through the batch engine.

use neutrospline::{BatchOptions, BatchParams, CurveBatch, EvalError, Evaluate};
use numpy::PyArrayMethods;
use pyo3::prelude::*;

use neutrospline::on_dimension;

use super::{Curve, State};
use crate::arrays::{Output, Params, Writer};
use crate::errors::invalid_at;

/// Parameters evaluated per block when the output is not Fortran-ordered: the block is
/// evaluated column by column into cache-resident scratch, then written row by row.
const BLOCK: usize = 1 << 14;

/// The message of an evaluation error, naming the first bad parameter `t[k]`.
pub(super) fn parameter_error(
    ts: &[f64],
    scalar: bool,
    domain: &std::ops::Range<f64>,
    e: EvalError,
) -> PyErr {
    if scalar {
        return invalid_at("t", e);
    }
    let bad = ts
        .iter()
        .position(|t| !t.is_finite() || *t < domain.start || *t > domain.end);
    match bad {
        Some(k) => invalid_at(format!("t[{k}]"), e),
        None => invalid_at("t", e),
    }
}

/// Evaluates a model curve through the batch engine: straight into a Fortran-ordered output,
/// by cache-sized blocks into any other. The outer error is one of the output array, the
/// inner one of a parameter.
pub(super) fn evaluate_batch<const D: usize>(
    py: Python<'_>,
    batch: &CurveBatch<D>,
    ts: &[f64],
    writer: &mut Writer<'_>,
) -> PyResult<Result<(), EvalError>> {
    let options = BatchOptions::default();
    if ts.is_empty() {
        return Ok(Ok(()));
    }
    if let Some(columns) = writer.columns()? {
        return Ok(py.detach(|| batch.evaluate(BatchParams::Values(ts), columns, &options)));
    }
    let mut view = writer.view();
    Ok(py.detach(|| {
        let mut scratch = vec![0.0; (D + 3) * BLOCK.min(ts.len())];
        for (b, block) in ts.chunks(BLOCK).enumerate() {
            let m = block.len();
            let scratch = &mut scratch[..(D + 3) * m];
            batch.evaluate(BatchParams::Values(block), scratch, &options)?;
            for c in 0..D + 3 {
                for k in 0..m {
                    view[[b * BLOCK + k, c]] = scratch[c * m + k];
                }
            }
        }
        Ok(())
    }))
}

/// Evaluates `value` at every parameter into the rows of `writer`.
pub(super) fn evaluate_rows(
    py: Python<'_>,
    ts: &[f64],
    writer: &mut Writer<'_>,
    columns: usize,
    value: impl Fn(f64) -> Result<[f64; 6], EvalError> + Send + Sync,
) -> Result<(), EvalError> {
    let mut view = writer.view();
    py.detach(|| {
        for (k, &t) in ts.iter().enumerate() {
            let row = value(t)?;
            for (c, &v) in row[..columns].iter().enumerate() {
                view[[k, c]] = v;
            }
        }
        Ok(())
    })
}

/// The rows `x, y[, z], truth, indeterminacy, falsity` of one lane at `ts`, row-major.
fn lane_rows<const D: usize>(batch: &CurveBatch<D>, ts: &[f64]) -> Result<Vec<f64>, EvalError> {
    let m = ts.len();
    if m == 0 {
        return Ok(Vec::new());
    }
    let mut columns = vec![0.0; (D + 3) * m];
    batch.evaluate(
        BatchParams::Values(ts),
        &mut columns,
        &BatchOptions::default(),
    )?;
    Ok((0..m)
        .flat_map(|k| (0..D + 3).map(move |c| (k, c)))
        .map(|(k, c)| columns[c * m + k])
        .collect())
}

/// Writes the rows `rows(ts)` (row-major, `columns` each) into `writer`, computed without the
/// GIL.
fn write_rows(
    py: Python<'_>,
    ts: &[f64],
    writer: &mut Writer<'_>,
    columns: usize,
    rows: impl Fn(&[f64]) -> Result<Vec<f64>, EvalError> + Send + Sync,
) -> Result<(), EvalError> {
    let values = py.detach(|| rows(ts))?;
    let mut view = writer.view();
    for (k, row) in values.chunks_exact(columns).enumerate() {
        for (c, &v) in row.iter().enumerate() {
            view[[k, c]] = v;
        }
    }
    Ok(())
}

/// The row `x, y[, z], truth, indeterminacy, falsity` of a derivative value (the first
/// `D + 3` of the six values).
pub(super) fn derivative_row<const D: usize>(v: neutrospline::DerivativeValue<D>) -> [f64; 6] {
    let mut row = [0.0; 6];
    row[..D].copy_from_slice(&v.position);
    row[D..D + 3].copy_from_slice(&[v.truth, v.indeterminacy, v.falsity]);
    row
}

impl Curve {
    pub(super) fn evaluate_impl(
        &self,
        py: Python<'_>,
        t: &Bound<'_, PyAny>,
        out: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Py<PyAny>> {
        let params = Params::read(t, "t")?;
        let scalar = matches!(params, Params::Scalar(_));
        let ts = params.values()?;
        let columns = self.state.columns();
        // A scalar parameter's result is one row: an `out` of that shape (columns,) gets it,
        // checked before anything is evaluated.
        let row_out = match (scalar, out) {
            (true, Some(out)) => Some(crate::arrays::checked_out(out, &[columns])?),
            _ => None,
        };
        let output = Output::new(py, if scalar { None } else { out }, ts.len(), columns)?;
        let mut writer = output.write()?;
        let domain = self.domain_range();
        let result = match &self.state {
            _ if self.state.wide() => {
                write_rows(py, ts, &mut writer, columns, |ts| self.rows_at(ts))
            }
            State::Model { curve, .. } => {
                on_dimension!(curve, c => evaluate_batch(py, &c.batch, ts, &mut writer))?
            }
            State::Derivative { derivative, .. } => on_dimension!(derivative, d => {
                evaluate_rows(py, ts, &mut writer, columns, |t| d.evaluate(t).map(derivative_row))
            }),
        };
        drop(writer);
        result.map_err(|e| parameter_error(ts, scalar, &domain, e))?;
        if let Some(target) = row_out {
            let values = output.array().try_readonly()?;
            target
                .try_readwrite()
                .map_err(|e| invalid_at("out", format!("cannot write into the array ({e})")))?
                .as_array_mut()
                .assign(&values.as_array().row(0));
            drop(values);
            return Ok(target.into_any().unbind());
        }
        output.finish(scalar)
    }

    /// The rows `x, y[, z], degree columns` at the parameters `ts`, row-major: every lane
    /// evaluated (or differentiated) and the lanes joined into the family's channels
    /// (`Family::join_slots`, docs/model.md "Lanes"); the three degrees of a family of one
    /// lane.
    pub(super) fn rows_at(&self, ts: &[f64]) -> Result<Vec<f64>, EvalError> {
        let dimension = self.state.dimension();
        let lanes = match &self.state {
            State::Model { curve, second, .. } => core::iter::once(curve)
                .chain(second.as_deref())
                .map(|lane| on_dimension!(lane, c => lane_rows(&c.batch, ts)))
                .collect::<Result<Vec<_>, EvalError>>()?,
            State::Derivative {
                derivative, second, ..
            } => core::iter::once(derivative)
                .chain(second.as_ref())
                .map(|lane| {
                    on_dimension!(lane, d => {
                        let mut rows = Vec::with_capacity(ts.len() * (dimension + 3));
                        for &t in ts {
                            rows.extend_from_slice(&derivative_row(d.evaluate(t)?)[..dimension + 3]);
                        }
                        Ok(rows)
                    })
                })
                .collect::<Result<Vec<_>, EvalError>>()?,
        };
        Ok(crate::model::join_rows(
            self.state.membership(),
            dimension,
            &lanes,
        ))
    }

    pub(super) fn domain_range(&self) -> std::ops::Range<f64> {
        match &self.state {
            State::Model { curve, .. } => on_dimension!(curve, c => c.curve.domain()),
            State::Derivative { derivative, .. } => on_dimension!(derivative, d => d.domain()),
        }
    }
}
