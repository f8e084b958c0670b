//! [`DynCurve`]: a curve of any kind in the plane or in space, the dimension known at run time,
//! for front ends that read it from data (docs/architecture.md, "one definition of every
//! option").

use core::ops::Range;

use crate::any_curve::{AnyCurve, CurveKind};
use crate::curve::{EvalError, Evaluate};

/// A curve of any kind, 2-D or 3-D: what a data file or an array of unknown width fits to.
/// Its row-level methods take and give points as `x, y[, z]` rows, so no front end matches on
/// the dimension for a job the core can do.
///
/// ```
/// use neutrospline::{DynCurve, AnyCurve};
/// let curve = DynCurve::from(AnyCurve::from(neutrospline::example1()));
/// assert_eq!(curve.dimension(), 2);
/// // x, y, truth, indeterminacy, falsity.
/// let row = curve.evaluate_row(0.0)?;
/// assert_eq!(row[..2], [1.0, 3.0]);
/// assert_eq!(row.len(), 5);
/// # Ok::<(), neutrospline::EvalError>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub enum DynCurve {
    /// A curve in the plane (x, y).
    Planar(AnyCurve<2>),
    /// A curve in space (x, y, z).
    Spatial(AnyCurve<3>),
}

impl From<AnyCurve<2>> for DynCurve {
    fn from(curve: AnyCurve<2>) -> DynCurve {
        DynCurve::Planar(curve)
    }
}

impl From<AnyCurve<3>> for DynCurve {
    fn from(curve: AnyCurve<3>) -> DynCurve {
        DynCurve::Spatial(curve)
    }
}

impl DynCurve {
    /// 2 or 3.
    pub fn dimension(&self) -> usize {
        match self {
            DynCurve::Planar(_) => 2,
            DynCurve::Spatial(_) => 3,
        }
    }

    /// Bézier, B-spline or NURBS.
    pub fn kind(&self) -> CurveKind {
        match self {
            DynCurve::Planar(c) => c.kind(),
            DynCurve::Spatial(c) => c.kind(),
        }
    }

    /// The parameter domain.
    pub fn domain(&self) -> Range<f64> {
        match self {
            DynCurve::Planar(c) => c.domain(),
            DynCurve::Spatial(c) => c.domain(),
        }
    }

    /// The point at `t` as a row: `x, y[, z], truth, indeterminacy, falsity`.
    ///
    /// # Errors
    /// `t` not finite or outside the domain.
    pub fn evaluate_row(&self, t: f64) -> Result<Vec<f64>, EvalError> {
        fn row<const D: usize>(curve: &AnyCurve<D>, t: f64) -> Result<Vec<f64>, EvalError> {
            let point = curve.evaluate(t)?;
            let mut row = point.position.to_vec();
            row.extend_from_slice(&point.degrees.to_array());
            Ok(row)
        }
        match self {
            DynCurve::Planar(c) => row(c, t),
            DynCurve::Spatial(c) => row(c, t),
        }
    }
}
