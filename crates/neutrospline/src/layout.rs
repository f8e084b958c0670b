//! The private packed layout shared by every curve kind: each control point is one row of
//! `D + 3` channels, the coordinates then truth, indeterminacy and falsity, so that one
//! algorithm serves positions and degrees alike.

use crate::curve::CurveError;
use crate::degrees::{DegreeKind, Degrees};
use crate::point::{ControlPoint, CurvePoint, DerivativeValue};

/// Channels per control value: `D` coordinates, then truth, indeterminacy, falsity.
pub(crate) const fn stride(d: usize) -> usize {
    d + 3
}

/// Checks that `D` is a dimension the library models (2 or 3).
pub(crate) fn check_dimension<const D: usize>() -> Result<(), CurveError> {
    if D == 2 || D == 3 {
        Ok(())
    } else {
        Err(CurveError::UnsupportedDimension { dimension: D })
    }
}

/// Checks control points (2-D or 3-D, non-empty, finite positions) and packs them
/// point-major.
pub(crate) fn pack_points<const D: usize>(
    points: &[ControlPoint<D>],
) -> Result<Vec<f64>, CurveError> {
    check_dimension::<D>()?;
    if points.is_empty() {
        return Err(CurveError::NoControlPoints);
    }
    let mut data = Vec::with_capacity(points.len() * stride(D));
    for (index, p) in points.iter().enumerate() {
        if let Some((axis, &value)) = p.position.iter().enumerate().find(|(_, v)| !v.is_finite()) {
            return Err(CurveError::PositionNotFinite { index, axis, value });
        }
        data.extend_from_slice(&p.position);
        data.extend_from_slice(&p.degrees.to_array());
    }
    Ok(data)
}

/// A packed row as a point. Degrees are valid by construction (convex combinations).
pub(crate) fn point_from_row<const D: usize>(row: &[f64]) -> CurvePoint<D> {
    let mut position = [0.0; D];
    position.copy_from_slice(&row[..D]);
    CurvePoint::new(
        position,
        Degrees::new_unchecked(row[D], row[D + 1], row[D + 2]),
    )
}

/// A packed row as a derivative value.
pub(crate) fn derivative_from_row<const D: usize>(row: &[f64]) -> DerivativeValue<D> {
    let mut position = [0.0; D];
    position.copy_from_slice(&row[..D]);
    DerivativeValue {
        position,
        truth: row[D],
        indeterminacy: row[D + 1],
        falsity: row[D + 2],
    }
}

/// Rows of a 2-D spline with the chosen degree inserted as a third coordinate.
pub(crate) fn lift_degree(data: &[f64], kind: DegreeKind) -> Vec<f64> {
    let mut out = Vec::with_capacity(data.len() / stride(2) * stride(3));
    for row in data.chunks_exact(stride(2)) {
        out.extend_from_slice(&row[..2]);
        out.push(row[2 + kind.index()]);
        out.extend_from_slice(&row[2..]);
    }
    out
}
