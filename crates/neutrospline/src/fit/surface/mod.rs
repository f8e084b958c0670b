//! Fitting tensor-product neutrosophic B-spline surfaces of degrees `(p, q)` to data
//! (docs/model.md, "Surface fitting"), over the curve fit's machinery: its parameters and
//! knots, its banded normal equations, its bounded degree channels.
//!
//! A surface `S(u, v) = sum_ij N_i,p(u) M_j,q(v) P_ij` is linear in its control values, so
//! every channel (`x`, `y`, `z`, `truth`, `indeterminacy`, `falsity`) is the weighted
//! least-squares solution of one system `(B^T W B + lambda R) P = B^T W Q`, `B` the tensor
//! basis at the data's `(u, v)`, `R` the thin-plate penalty
//! `int int S_uu^2 + 2 S_uv^2 + S_vv^2`:
//!
//! - **gridded data** (`rows x cols` points, rows along `u`): parameters averaged over the
//!   columns (for `u`) and rows (for `v`) (The NURBS Book 9.2.5); interpolation or least
//!   squares to `(m, n)` control points. Unweighted and unsmoothed, `B = N (x) M` and the
//!   solution is `P = N^+ Q M^+T`: two passes of the curve solver, rows then columns;
//! - **scattered data**: given `(u, v)`, or the projection on the best-fitting plane (or on
//!   `x, y` for height data); knots at the quantiles of the parameters (the data's density);
//!   the system solved whole (banded, `p n + q` sub-diagonals);
//! - **the degree channels** are solved under the membership rule's bounds, so the surface
//!   is valid everywhere.
//!
//! ```
//! use neutrospline::fit::{fit_surface, SurfaceFitData, SurfaceFitOptions, SurfaceTarget};
//! use neutrospline::{Degrees, EvaluateSurface};
//!
//! // A 5 x 4 grid on z = x y with degrees that vary over it.
//! let (mut positions, mut degrees) = (Vec::new(), Vec::new());
//! for k in 0..5 {
//!     for l in 0..4 {
//!         let (x, y) = (k as f64, l as f64);
//!         positions.push([x, y, x * y / 4.0]);
//!         degrees.push(Degrees::new(0.2 + 0.1 * x, 0.1, 0.5 - 0.1 * y)?);
//!     }
//! }
//! let data = SurfaceFitData::grid(5, 4, positions, degrees)?;
//! let options = SurfaceFitOptions::default()
//!     .with_degrees(3, 2)
//!     .with_target(SurfaceTarget::Interpolate);
//! let fitted = fit_surface(&data, &options)?;
//! let [u, v] = fitted.parameters[2 * 4 + 1];
//! let p = fitted.surface.evaluate(u, v)?;
//! assert!((p.position[2] - 0.5).abs() < 1e-12);
//! assert!((p.degrees.truth() - 0.4).abs() < 1e-12);
//! assert_eq!(fitted.report.control_points, [5, 4]);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod params;
mod request;
mod solve;
mod tensor;

use core::fmt;
use core::str::FromStr;

use super::{DataWeights, FitError, Parametrization};
use crate::degrees::{Degrees, Family};
use crate::surface::Surface;
use crate::ParseNameError;

pub use super::report::AtBound;
pub use request::SurfaceFitRequest;

/// How the data points are arranged.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SurfaceShape {
    /// `rows x cols` points, row by row: point `k cols + l` is on row `k` (along `u`) and
    /// column `l` (along `v`).
    Grid {
        /// Rows (points along `u`).
        rows: usize,
        /// Columns (points along `v`).
        cols: usize,
    },
    /// Points in no particular order.
    Scattered,
}

/// Data to fit a surface to: points with their degrees, and optionally their `(u, v)` and
/// weights.
#[derive(Clone, Debug, PartialEq)]
pub struct SurfaceFitData {
    positions: Vec<[f64; 3]>,
    degrees: Vec<Degrees>,
    second_lane: Option<Vec<Degrees>>,
    shape: SurfaceShape,
    parameters: Option<Vec<[f64; 2]>>,
    weights: Option<Vec<f64>>,
}

impl SurfaceFitData {
    /// A grid of `rows x cols` points, row by row.
    ///
    /// # Errors
    /// [`FitError::GridShape`] when `rows cols` is not the number of points (or is 0); the
    /// errors of [`SurfaceFitData::scattered`].
    pub fn grid(
        rows: usize,
        cols: usize,
        positions: Vec<[f64; 3]>,
        degrees: Vec<Degrees>,
    ) -> Result<Self, FitError> {
        let mut data = SurfaceFitData::scattered(positions, degrees)?;
        if rows == 0 || cols == 0 || rows.checked_mul(cols) != Some(data.len()) {
            return Err(FitError::GridShape {
                rows,
                cols,
                points: data.len(),
            });
        }
        data.shape = SurfaceShape::Grid { rows, cols };
        Ok(data)
    }

    /// Scattered points and their degrees (as many of each).
    ///
    /// # Errors
    /// [`FitError::NoData`], [`FitError::Count`], [`FitError::NotFinite`].
    pub fn scattered(positions: Vec<[f64; 3]>, degrees: Vec<Degrees>) -> Result<Self, FitError> {
        // The curve's checks, once.
        let curve = super::FitData::new(positions, degrees)?;
        Ok(SurfaceFitData {
            positions: curve.positions,
            degrees: curve.degrees,
            second_lane: None,
            shape: SurfaceShape::Scattered,
            parameters: None,
            weights: None,
        })
    }

    /// The points' own `(u, v)`. On a grid, `u` must be the same along each row and `v` along
    /// each column, increasing.
    ///
    /// # Errors
    /// [`FitError::Count`], [`FitError::NotFinite`], [`FitError::Option`] for grid parameters
    /// that are not a grid's.
    pub fn with_parameters(mut self, parameters: Vec<[f64; 2]>) -> Result<Self, FitError> {
        if parameters.len() != self.positions.len() {
            return Err(FitError::Count {
                what: "parameter pairs",
                count: parameters.len(),
                points: self.positions.len(),
            });
        }
        for (index, uv) in parameters.iter().enumerate() {
            if let Some((a, &value)) = uv.iter().enumerate().find(|(_, t)| !t.is_finite()) {
                return Err(FitError::NotFinite {
                    index,
                    field: ["u", "v"][a],
                    value,
                });
            }
        }
        if let SurfaceShape::Grid { rows, cols } = self.shape {
            params::check_grid_parameters(&parameters, rows, cols)?;
        }
        self.parameters = Some(parameters);
        Ok(self)
    }

    /// The second lane of each point's degrees, for a family of two lanes, as
    /// [`FitData::with_second_lane`](super::FitData::with_second_lane) takes it; the fitted
    /// surface's second lane is then [`SurfaceFit::second_lane`].
    ///
    /// # Errors
    /// [`FitError::Count`].
    pub fn with_second_lane(mut self, degrees: Vec<Degrees>) -> Result<Self, FitError> {
        self.second_lane = Some(super::second_lane(degrees, self.positions.len())?);
        Ok(self)
    }

    /// The second lane's degrees, when given.
    pub fn second_lane(&self) -> Option<&[Degrees]> {
        self.second_lane.as_deref()
    }

    /// The points' weights (each finite and > 0), used with [`DataWeights::Given`].
    ///
    /// # Errors
    /// [`FitError::Count`], [`FitError::WeightNotPositive`].
    pub fn with_weights(mut self, weights: Vec<f64>) -> Result<Self, FitError> {
        let curve = super::FitData::new(self.positions, self.degrees)?.with_weights(weights);
        match curve {
            Ok(curve) => {
                self.positions = curve.positions;
                self.degrees = curve.degrees;
                self.weights = curve.weights;
                Ok(self)
            }
            Err(e) => Err(e),
        }
    }

    /// The number of points.
    pub fn len(&self) -> usize {
        self.positions.len()
    }

    /// Always `false` (data has at least one point).
    pub fn is_empty(&self) -> bool {
        false
    }

    /// The arrangement of the points.
    pub fn shape(&self) -> SurfaceShape {
        self.shape
    }

    /// The positions.
    pub fn positions(&self) -> &[[f64; 3]] {
        &self.positions
    }

    /// The degrees.
    pub fn degrees(&self) -> &[Degrees] {
        &self.degrees
    }

    /// The given parameters, if any.
    pub fn parameters(&self) -> Option<&[[f64; 2]]> {
        self.parameters.as_deref()
    }

    /// The given weights, if any.
    pub fn weights(&self) -> Option<&[f64]> {
        self.weights.as_deref()
    }
}

/// What a surface fit aims for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SurfaceTarget {
    /// Through every point of a grid (as many control points as points).
    Interpolate,
    /// Weighted least squares with `[m, n]` control points (`m` along `u`, `n` along `v`).
    ControlPoints([usize; 2]),
    /// Weighted least squares, knots refined where the position residual is largest until
    /// every position residual (the distance from the point to the surface at its `(u, v)`)
    /// is at most this.
    Tolerance(f64),
}

impl fmt::Display for SurfaceTarget {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SurfaceTarget::Interpolate => f.write_str("interpolation"),
            SurfaceTarget::ControlPoints([m, n]) => {
                write!(f, "least squares with {m} x {n} control points")
            }
            SurfaceTarget::Tolerance(e) => write!(f, "least squares to a tolerance of {e}"),
        }
    }
}

/// How scattered points get `(u, v)` when the data gives none.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Projection {
    /// The projection on the best-fitting plane (through the centroid, spanned by the two
    /// principal axes of the points), scaled to `[0, 1]^2`.
    #[default]
    Plane,
    /// `(x, y)` scaled to `[0, 1]^2`: height data, `z` a function of `(x, y)`.
    Xy,
}

impl Projection {
    /// The name used by every front end: `plane`, `xy`.
    pub const fn name(self) -> &'static str {
        match self {
            Projection::Plane => "plane",
            Projection::Xy => "xy",
        }
    }
}

impl fmt::Display for Projection {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Projection {
    type Err = ParseNameError;

    /// Parses `plane` or `xy` (case-insensitive).
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        [Projection::Plane, Projection::Xy]
            .into_iter()
            .find(|p| p.name().eq_ignore_ascii_case(s.trim()))
            .ok_or_else(|| ParseNameError::new("projection", s, "plane, xy"))
    }
}

/// Settings of a surface fit; `SurfaceFitOptions::default()` is a bicubic chord-length
/// least-squares fit to a tolerance of 1e-3 of the data's bounding-box diagonal.
#[derive(Clone, Debug, PartialEq)]
pub struct SurfaceFitOptions {
    degrees: [usize; 2],
    target: Option<SurfaceTarget>,
    parametrization: Parametrization,
    projection: Projection,
    smoothing: f64,
    weights: DataWeights,
    membership: Family,
}

impl Default for SurfaceFitOptions {
    fn default() -> Self {
        SurfaceFitOptions {
            degrees: [3, 3],
            target: None,
            parametrization: Parametrization::ChordLength,
            projection: Projection::Plane,
            smoothing: 0.0,
            weights: DataWeights::None,
            membership: Family::Neutrosophic,
        }
    }
}

impl SurfaceFitOptions {
    /// The degrees `p` (along `u`) and `q` (along `v`) (default 3 and 3).
    pub fn with_degrees(mut self, p: usize, q: usize) -> Self {
        self.degrees = [p, q];
        self
    }

    /// Interpolate, a number of control points, or a tolerance (default: a tolerance of 1e-3
    /// of the data's bounding-box diagonal).
    pub fn with_target(mut self, target: SurfaceTarget) -> Self {
        self.target = Some(target);
        self
    }

    /// How grid points get parameters when the data gives none (default chord length).
    pub fn with_parametrization(mut self, parametrization: Parametrization) -> Self {
        self.parametrization = parametrization;
        self
    }

    /// How scattered points get parameters when the data gives none (default: the
    /// best-fitting plane).
    pub fn with_projection(mut self, projection: Projection) -> Self {
        self.projection = projection;
        self
    }

    /// The weight `lambda >= 0` of the thin-plate penalty
    /// `lambda int int S_uu^2 + 2 S_uv^2 + S_vv^2` over the parameter domain (default 0).
    pub fn with_smoothing(mut self, lambda: f64) -> Self {
        self.smoothing = lambda;
        self
    }

    /// How the points are weighted (default: equally).
    pub fn with_weights(mut self, weights: DataWeights) -> Self {
        self.weights = weights;
        self
    }

    /// The rule the degrees obey (default neutrosophic): the data must obey it, and the fitted
    /// control values do.
    pub fn with_membership(mut self, membership: Family) -> Self {
        self.membership = membership;
        self
    }

    /// The degrees `[p, q]`.
    pub fn degrees(&self) -> [usize; 2] {
        self.degrees
    }

    /// The target, or `None` for the default.
    pub fn target(&self) -> Option<SurfaceTarget> {
        self.target
    }

    /// The membership rule.
    pub fn membership(&self) -> Family {
        self.membership
    }
}

/// The residuals, conditioning and active bounds of a surface fit (as
/// [`FitReport`](super::FitReport) for curves).
#[derive(Clone, Debug, PartialEq)]
pub struct SurfaceFitReport {
    /// The control net `[m, n]` (`m` along `u`).
    pub control_points: [usize; 2],
    /// The degrees `[p, q]`.
    pub degrees: [usize; 2],
    /// The largest absolute residual per channel (`x`, `y`, `z`, `truth`, `indeterminacy`,
    /// `falsity`).
    pub max_error: Vec<(&'static str, f64)>,
    /// The root-mean-square residual per channel (over all points, unweighted).
    pub rms_error: Vec<(&'static str, f64)>,
    /// The point with the largest position residual.
    pub worst_index: usize,
    /// Its `(u, v)`.
    pub worst_parameters: [f64; 2],
    /// Its position residual.
    pub worst_distance: f64,
    /// Whether every control point's support holds a point of positive weight (without
    /// smoothing this always holds, or the fit is refused).
    pub data_in_every_support: bool,
    /// Whether the system was solved as two passes of the curve solver (gridded data,
    /// unweighted, unsmoothed) rather than whole.
    pub two_pass: bool,
    /// An estimate of the 1-norm condition number of the normal matrix (for two passes, the
    /// product of the two curve systems', which is the Kronecker product's).
    pub condition_estimate: f64,
    /// The control degrees on a bound; `index` is the control point `i n + j` (row `i`,
    /// column `j`).
    pub at_bound: Vec<AtBound>,
    /// For a tolerance fit, the tolerance.
    pub tolerance: Option<f64>,
    /// For a tolerance fit, whether every position residual is within it.
    pub tolerance_met: Option<bool>,
}

impl SurfaceFitReport {
    /// The largest absolute residual of a channel, by name.
    pub fn max(&self, channel: &str) -> Option<f64> {
        self.max_error
            .iter()
            .find(|(name, _)| *name == channel)
            .map(|(_, v)| *v)
    }
}

/// A fitted surface, the data's `(u, v)` on it and the report.
#[derive(Clone, Debug, PartialEq)]
pub struct SurfaceFit {
    /// The B-spline surface.
    pub surface: Surface,
    /// The `(u, v)` of each data point.
    pub parameters: Vec<[f64; 2]>,
    /// Errors, conditioning and active bounds.
    pub report: SurfaceFitReport,
    /// For a family of two lanes, the second lane: a surface with the same positions, degrees
    /// and knots as [`SurfaceFit::surface`] whose degrees hold the second lane's channels
    /// (docs/model.md, "Lanes"); `None` for a family of one lane.
    pub second_lane: Option<Surface>,
}

/// Fits a B-spline surface to `data`.
///
/// # Errors
/// Data that does not obey the membership rule, too few points for the degrees and target,
/// repeated grid parameters where interpolation needs distinct ones, a control point with no
/// data in its support and no smoothing ([`FitError::EmptyCell`]), options out of range.
pub fn fit_surface(
    data: &SurfaceFitData,
    options: &SurfaceFitOptions,
) -> Result<SurfaceFit, FitError> {
    solve::run(data, options)
}

#[cfg(test)]
mod tests;
