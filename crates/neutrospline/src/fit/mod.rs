//! Fitting neutrosophic curves to data (docs/model.md section 8): interpolation and weighted
//! least squares (with a number of control points, or refined until a tolerance is met),
//! optional smoothing, open or closed, with the degree channels fitted under the bounds of the
//! membership rule so that the curve is valid everywhere.
//!
//! One basis matrix serves every channel: positions and the three degrees are least-squares
//! problems with the same normal matrix `M = N^T W N + lambda R` (`N` the B-spline basis at
//! the data parameters, `W` the data weights, `R` the Gram matrix of second derivatives). `M`
//! is banded (cyclically for closed curves), factored once by a banded Cholesky; the
//! positions are its solutions, refined against the data residuals; the degree channels
//! minimise the same quadratic under `0 <= value <= 1` (and `truth + falsity <= 1` under the
//! intuitionistic rule) by an active-set method on the same band.
//!
//! ```
//! use neutrospline::fit::{fit, FitData, FitOptions, FitTarget};
//! use neutrospline::{ControlPolygon, Degrees, Evaluate};
//!
//! // Seven points on a parabola with degrees that change along it.
//! let xs = [0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0];
//! let positions: Vec<[f64; 2]> = xs.iter().map(|&x| [x, x * x / 6.0]).collect();
//! let degrees: Vec<Degrees> = xs
//!     .iter()
//!     .map(|&x| Degrees::new(x / 6.0, 0.2, 1.0 - x / 6.0))
//!     .collect::<Result<_, _>>()?;
//! let data = FitData::new(positions, degrees)?;
//! let fitted = fit(&data, &FitOptions::default().with_target(FitTarget::Interpolate))?;
//! let p = fitted.curve.evaluate(fitted.parameters[3])?;
//! assert!((p.position[0] - 3.0).abs() < 1e-12 && (p.position[1] - 1.5).abs() < 1e-12);
//! assert!((p.degrees.truth() - 0.5).abs() < 1e-12);
//! assert!(fitted.report.max_error.iter().all(|(_, e)| *e < 1e-12));
//! assert_eq!(fitted.curve.len(), 7);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub(crate) mod banded;
mod basis;
mod bounds;
mod choose;
pub(crate) mod convex;
#[doc(hidden)]
pub use convex::RuleFitBench;
pub(crate) mod knots;
pub(crate) mod qp;
mod report;
mod request;
mod solve;
mod surface;
mod system;
mod width;

use core::fmt;

use crate::any_curve::AnyCurve;
use crate::curve::CurveError;
use crate::degrees::{DegreeError, DegreeKind, Degrees, Family};
use crate::dyn_curve::DynCurve;
use crate::surface::SurfaceError;

pub use knots::Parametrization;
pub use report::{AtBound, FitReport};
pub use request::FitRequest;
pub use surface::{
    fit_surface, Projection, SurfaceFit, SurfaceFitData, SurfaceFitOptions, SurfaceFitReport,
    SurfaceFitRequest, SurfaceShape, SurfaceTarget,
};

/// Data to fit: points with their degrees, and optionally their parameters and weights.
///
/// The data of an interval-valued or bipolar family (two lanes, docs/model.md "Lanes") holds
/// each point's first lane in `degrees` and its second in [`FitData::with_second_lane`]; the
/// fit then solves every channel jointly under the family's whole rule and returns the second
/// lane as a curve of the same geometry ([`Fit::second_lane`]).
#[derive(Clone, Debug, PartialEq)]
pub struct FitData<const D: usize> {
    positions: Vec<[f64; D]>,
    degrees: Vec<Degrees>,
    second_lane: Option<Vec<Degrees>>,
    parameters: Option<Vec<f64>>,
    weights: Option<Vec<f64>>,
}

impl<const D: usize> FitData<D> {
    /// Points and their degrees (as many of each).
    ///
    /// # Errors
    /// [`FitError::NoData`], [`FitError::Count`], [`FitError::NotFinite`] for a coordinate,
    /// [`FitError::Curve`] for a dimension other than 2 or 3.
    pub fn new(positions: Vec<[f64; D]>, degrees: Vec<Degrees>) -> Result<Self, FitError> {
        if D != 2 && D != 3 {
            return Err(CurveError::UnsupportedDimension { dimension: D }.into());
        }
        if positions.is_empty() {
            return Err(FitError::NoData);
        }
        if degrees.len() != positions.len() {
            return Err(FitError::Count {
                what: "degree triples",
                count: degrees.len(),
                points: positions.len(),
            });
        }
        for (index, p) in positions.iter().enumerate() {
            if let Some((axis, &value)) = p.iter().enumerate().find(|(_, v)| !v.is_finite()) {
                return Err(FitError::NotFinite {
                    index,
                    field: ["x", "y", "z"][axis],
                    value,
                });
            }
        }
        Ok(FitData {
            positions,
            degrees,
            second_lane: None,
            parameters: None,
            weights: None,
        })
    }

    /// The points' own parameters, non-decreasing (open curves) or increasing in `[0, 1)`
    /// (closed curves, period 1).
    ///
    /// # Errors
    /// [`FitError::Count`], [`FitError::NotFinite`], [`FitError::ParameterDecreasing`].
    pub fn with_parameters(mut self, parameters: Vec<f64>) -> Result<Self, FitError> {
        if parameters.len() != self.positions.len() {
            return Err(FitError::Count {
                what: "parameters",
                count: parameters.len(),
                points: self.positions.len(),
            });
        }
        for (index, &value) in parameters.iter().enumerate() {
            if !value.is_finite() {
                return Err(FitError::NotFinite {
                    index,
                    field: "parameter",
                    value,
                });
            }
            if index > 0 && value < parameters[index - 1] {
                return Err(FitError::ParameterDecreasing {
                    index,
                    value,
                    previous: parameters[index - 1],
                });
            }
        }
        self.parameters = Some(parameters);
        Ok(self)
    }

    /// The second lane of each point's degrees, for a family of two lanes ([`Family::lanes`]:
    /// `upper` of the interval-valued families, `negative` of the bipolar one, whose negative
    /// degrees are held negated, in \[0, 1\]); [`FitData::new`]'s degrees are then the first
    /// lane. The rule joining the lanes (`lower <= upper`, `T_U + F_U <= 1`) is checked by the
    /// fit, which knows the family.
    ///
    /// ```
    /// use neutrospline::fit::{fit, FitData, FitOptions, FitTarget};
    /// use neutrospline::{Degrees, Evaluate, Family};
    /// // Interval type-2 memberships: lower M_L in the truth slot of lane 0, upper M_U of lane 1.
    /// let lower = [0.2, 0.5, 0.3].map(|m| Degrees::new(m, 0.0, 0.0).unwrap()).to_vec();
    /// let upper = [0.4, 0.7, 0.6].map(|m| Degrees::new(m, 0.0, 0.0).unwrap()).to_vec();
    /// let data = FitData::new(vec![[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]], lower)?
    ///     .with_second_lane(upper)?;
    /// let options = FitOptions::default()
    ///     .with_degree(2)
    ///     .with_target(FitTarget::Interpolate)
    ///     .with_membership(Family::IntervalType2);
    /// let fitted = fit(&data, &options)?;
    /// let upper_curve = fitted.second_lane.expect("two lanes");
    /// assert!((upper_curve.evaluate(0.0)?.degrees.truth() - 0.4).abs() < 1e-12);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// [`FitError::Count`].
    pub fn with_second_lane(mut self, degrees: Vec<Degrees>) -> Result<Self, FitError> {
        self.second_lane = Some(second_lane(degrees, self.positions.len())?);
        Ok(self)
    }

    /// The points' weights (each finite and > 0), used with [`DataWeights::Given`].
    ///
    /// # Errors
    /// [`FitError::Count`], [`FitError::WeightNotPositive`].
    pub fn with_weights(mut self, weights: Vec<f64>) -> Result<Self, FitError> {
        if weights.len() != self.positions.len() {
            return Err(FitError::Count {
                what: "weights",
                count: weights.len(),
                points: self.positions.len(),
            });
        }
        if let Some((index, &value)) = weights
            .iter()
            .enumerate()
            .find(|(_, w)| !(w.is_finite() && **w > 0.0))
        {
            return Err(FitError::WeightNotPositive { index, value });
        }
        self.weights = Some(weights);
        Ok(self)
    }

    /// The number of points.
    pub fn len(&self) -> usize {
        self.positions.len()
    }

    /// Always `false` (data has at least one point).
    pub fn is_empty(&self) -> bool {
        false
    }

    /// The positions.
    pub fn positions(&self) -> &[[f64; D]] {
        &self.positions
    }

    /// The degrees (of a family of two lanes: the first lane).
    pub fn degrees(&self) -> &[Degrees] {
        &self.degrees
    }

    /// The second lane's degrees, when given ([`FitData::with_second_lane`]).
    pub fn second_lane(&self) -> Option<&[Degrees]> {
        self.second_lane.as_deref()
    }

    /// The given parameters, if any.
    pub fn parameters(&self) -> Option<&[f64]> {
        self.parameters.as_deref()
    }

    /// The given weights, if any.
    pub fn weights(&self) -> Option<&[f64]> {
        self.weights.as_deref()
    }
}

/// The second lane's degrees, checked to be one triple per point.
fn second_lane(degrees: Vec<Degrees>, points: usize) -> Result<Vec<Degrees>, FitError> {
    if degrees.len() != points {
        return Err(FitError::Count {
            what: "second-lane degree triples",
            count: degrees.len(),
            points,
        });
    }
    Ok(degrees)
}

/// What the fit aims for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FitTarget {
    /// Through every point (as many control points as points; two more with end tangents).
    Interpolate,
    /// Weighted least squares with this many control points.
    ControlPoints(usize),
    /// Weighted least squares, knots refined where the position residual is largest until
    /// every position residual (the distance from the point to the curve at its parameter) is
    /// at most this; a Bézier segment raises its degree instead.
    Tolerance(f64),
}

/// How the data points are weighted in least squares.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum DataWeights {
    /// Every point counts the same.
    #[default]
    None,
    /// The data's own weights ([`FitData::with_weights`]).
    Given,
    /// Each point by its own score `(2 + T - I - F) / 3` (docs/model.md section 7), so that
    /// doubtful points pull less (a point of score 0 not at all).
    Score,
}

/// The kind of curve fitted.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum FitKind {
    /// A B-spline (clamped; periodic when closed).
    #[default]
    BSpline,
    /// One Bézier segment.
    Bezier,
}

/// Settings of a fit; `FitOptions::default()` is a cubic chord-length least-squares fit to a
/// tolerance of 1e-3 of the data's bounding-box diagonal.
#[derive(Clone, Debug, PartialEq)]
pub struct FitOptions {
    degree: usize,
    target: Option<FitTarget>,
    parametrization: Parametrization,
    closed: bool,
    smoothing: f64,
    weights: DataWeights,
    membership: Family,
    kind: FitKind,
    tangents: Option<[Vec<f64>; 2]>,
    knots: Option<Vec<f64>>,
}

impl Default for FitOptions {
    fn default() -> Self {
        FitOptions {
            degree: 3,
            target: None,
            parametrization: Parametrization::ChordLength,
            closed: false,
            smoothing: 0.0,
            weights: DataWeights::None,
            membership: Family::Neutrosophic,
            kind: FitKind::BSpline,
            tangents: None,
            knots: None,
        }
    }
}

impl FitOptions {
    /// The polynomial degree (default 3).
    pub fn with_degree(mut self, degree: usize) -> Self {
        self.degree = degree;
        self
    }

    /// Interpolate, a number of control points, or a tolerance (default: a tolerance of 1e-3
    /// of the data's bounding-box diagonal).
    pub fn with_target(mut self, target: FitTarget) -> Self {
        self.target = Some(target);
        self
    }

    /// How parameters are chosen when the data has none (default chord length).
    pub fn with_parametrization(mut self, parametrization: Parametrization) -> Self {
        self.parametrization = parametrization;
        self
    }

    /// A closed curve: periodic, `C^(p-1)` where it closes (default open).
    pub fn with_closed(mut self, closed: bool) -> Self {
        self.closed = closed;
        self
    }

    /// The weight `lambda >= 0` of the penalty on the second derivative, `lambda int |C''|^2`
    /// (default 0; needs degree 2 or more).
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

    /// A B-spline (default) or one Bézier segment.
    pub fn with_kind(mut self, kind: FitKind) -> Self {
        self.kind = kind;
        self
    }

    /// Tangents (derivatives with respect to the parameter) at the start and the end, for
    /// interpolation of an open curve: `D` values each.
    pub fn with_end_tangents(mut self, start: Vec<f64>, end: Vec<f64>) -> Self {
        self.tangents = Some([start, end]);
        self
    }

    /// Least squares on these knots (an open B-spline with `knots.len() - degree - 1` control
    /// points, clamped or not; the data's parameters must lie in its domain), as scipy's
    /// `make_lsq_spline` takes them. The target must then be left unset or be
    /// [`FitTarget::ControlPoints`] with that count.
    pub fn with_knots(mut self, knots: Vec<f64>) -> Self {
        self.knots = Some(knots);
        self
    }

    /// The degree.
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The membership rule.
    pub fn membership(&self) -> Family {
        self.membership
    }

    /// The target, or `None` for the default (a tolerance of 1e-3 of the data's diagonal).
    pub fn target(&self) -> Option<FitTarget> {
        self.target
    }
}

/// A fitted curve, the parameters of the data on it and the report.
#[derive(Clone, Debug, PartialEq)]
pub struct Fit<const D: usize> {
    /// The curve: a B-spline (a periodic one, unclamped, for a closed curve) or a Bézier curve.
    pub curve: AnyCurve<D>,
    /// The parameter of each data point on the curve.
    pub parameters: Vec<f64>,
    /// Errors, conditioning and active bounds.
    pub report: FitReport,
    /// For a family of two lanes, the second lane: a curve with the same positions, weights,
    /// degree and knots as [`Fit::curve`], whose degrees hold the second lane's channels
    /// (docs/model.md, "Lanes"); `None` for a family of one lane.
    pub second_lane: Option<AnyCurve<D>>,
}

/// Why data cannot be fitted.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum FitError {
    /// There are no points.
    #[error("no data points")]
    NoData,
    /// A list does not have one entry per point.
    #[error("{count} {what} for {points} points (one per point)")]
    Count {
        /// What was counted.
        what: &'static str,
        /// How many were given.
        count: usize,
        /// The number of points.
        points: usize,
    },
    /// A value is NaN or infinite.
    #[error("point {index}: {field} = {value} is not a finite number")]
    NotFinite {
        /// The point (0-based).
        index: usize,
        /// The field.
        field: &'static str,
        /// The value.
        value: f64,
    },
    /// A weight is zero, negative or not finite.
    #[error("point {index}: weight = {value} is not a positive finite number (data weights must be > 0)")]
    WeightNotPositive {
        /// The point.
        index: usize,
        /// The weight.
        value: f64,
    },
    /// Given parameters decrease.
    #[error("point {index}: parameter {value} is less than the previous point's {previous} (parameters must be non-decreasing)")]
    ParameterDecreasing {
        /// The point.
        index: usize,
        /// Its parameter.
        value: f64,
        /// The previous point's.
        previous: f64,
    },
    /// A point's degrees break the membership rule.
    #[error("point {index}: {source}")]
    Degrees {
        /// The point.
        index: usize,
        /// The rule broken.
        source: DegreeError,
    },
    /// Too few points for the degree and target.
    #[error("{points} points are too few: {why}")]
    TooFewPoints {
        /// The number of points.
        points: usize,
        /// What is needed and why.
        why: String,
    },
    /// Two points share a parameter where interpolation needs distinct ones, or repeat a
    /// position under chord-length or centripetal parameters.
    #[error("point {index} repeats the parameter of point {previous} (t = {value}): {rule}")]
    RepeatedParameter {
        /// The point.
        index: usize,
        /// The point it repeats.
        previous: usize,
        /// The parameter.
        value: f64,
        /// The rule broken.
        rule: &'static str,
    },
    /// A point repeats the previous point's position, so chord-length and centripetal
    /// parameters would repeat (for a closed curve, `previous` of point 0 is the last point).
    #[error("point {index} repeats the position of point {previous}: chord-length and centripetal parameters need distinct consecutive points (remove it, give parameters, or use uniform ones)")]
    RepeatedPoint {
        /// The point.
        index: usize,
        /// The point it repeats.
        previous: usize,
    },
    /// The data and knots violate the Schoenberg-Whitney conditions (some control point is
    /// not determined by the data).
    #[error("the data does not determine every control point (the Schoenberg-Whitney conditions fail: {detail}); use fewer control points, different parameters, or smoothing")]
    SchoenbergWhitney {
        /// Which control point has no data of its own.
        detail: String,
    },
    /// An option is out of range or does not fit the others.
    #[error("{0}")]
    Option(String),
    /// Positions that are not rows of 2 or 3 coordinates.
    #[error("{values} coordinates are not rows of {dimension} (a fit needs points of 2 or 3 coordinates)")]
    Dimension {
        /// The coordinates per point given.
        dimension: usize,
        /// The number of coordinates.
        values: usize,
    },
    /// The normal equations are not numerically positive definite.
    #[error("the least-squares system is singular (condition beyond double precision); use fewer control points or smoothing")]
    Singular,
    /// The fitted curve could not be built (a value overflowed).
    #[error(transparent)]
    Curve(#[from] CurveError),
    /// A grid whose size is not the number of points.
    #[error("a grid of {rows} x {cols} points does not hold {points} points (rows x cols must be the number of points, each at least 1)")]
    GridShape {
        /// The rows given.
        rows: usize,
        /// The columns given.
        cols: usize,
        /// The number of points.
        points: usize,
    },
    /// A control point of a surface has no data in its support and there is no smoothing to
    /// determine it.
    #[error("control point (row {row}, column {col}) has no data in its support [{}, {}] x [{}, {}] of (u, v) and there is no smoothing: give smoothing, fewer control points, or data there", u[0], u[1], v[0], v[1])]
    EmptyCell {
        /// The control point's row (along u).
        row: usize,
        /// Its column (along v).
        col: usize,
        /// Its support along u.
        u: [f64; 2],
        /// Its support along v.
        v: [f64; 2],
    },
    /// The fitted surface could not be built.
    #[error(transparent)]
    Surface(#[from] SurfaceError),
}

/// Fits a curve to `data`.
///
/// # Errors
/// Data that does not obey the membership rule, too few points for the degree, repeated
/// parameters where interpolation needs distinct ones, data that leaves a control point
/// undetermined (Schoenberg-Whitney), options out of range ([`FitError`]).
pub fn fit<const D: usize>(data: &FitData<D>, options: &FitOptions) -> Result<Fit<D>, FitError> {
    solve::run(data, options)
}

impl fmt::Display for FitTarget {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            FitTarget::Interpolate => f.write_str("interpolation"),
            FitTarget::ControlPoints(n) => write!(f, "least squares with {n} control points"),
            FitTarget::Tolerance(e) => write!(f, "least squares to a tolerance of {e}"),
        }
    }
}

/// A fitted curve of either dimension ([`fit_rows`]), with the parameters of the data on it
/// and the report.
#[derive(Clone, Debug, PartialEq)]
pub struct DynFit {
    /// The curve.
    pub curve: DynCurve,
    /// The parameter of each data point on the curve.
    pub parameters: Vec<f64>,
    /// The error report.
    pub report: FitReport,
    /// The second lane of a family of two lanes ([`Fit::second_lane`]).
    pub second_lane: Option<DynCurve>,
}

impl<const D: usize> From<Fit<D>> for DynFit
where
    DynCurve: From<AnyCurve<D>>,
{
    fn from(fit: Fit<D>) -> DynFit {
        DynFit {
            curve: fit.curve.into(),
            parameters: fit.parameters,
            report: fit.report,
            second_lane: fit.second_lane.map(DynCurve::from),
        }
    }
}

/// Fits a curve to points given as rows of `dimension` (2 or 3) coordinates, `positions`
/// holding them one row after another: [`fit`] for a dimension known at run time, with
/// optional second-lane degrees, parameters and weights as [`FitData::with_second_lane`],
/// [`FitData::with_parameters`] and [`FitData::with_weights`] take them.
///
/// ```
/// use neutrospline::fit::{fit_rows, FitOptions, FitTarget};
/// use neutrospline::Degrees;
/// let positions = [0.0, 0.0, 1.0, 1.0, 2.0, 0.0];
/// let degrees = vec![Degrees::new(0.5, 0.2, 0.1)?; 3];
/// let options = FitOptions::default().with_degree(2).with_target(FitTarget::Interpolate);
/// let fitted = fit_rows(2, &positions, degrees, None, None, None, &options)?;
/// assert_eq!(fitted.curve.dimension(), 2);
/// assert_eq!(fitted.parameters.len(), 3);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// [`FitError::Dimension`] for a dimension other than 2 or 3 or positions that are not whole
/// rows; the errors of [`FitData`] and [`fit`].
pub fn fit_rows(
    dimension: usize,
    positions: &[f64],
    degrees: Vec<Degrees>,
    second_lane: Option<Vec<Degrees>>,
    parameters: Option<Vec<f64>>,
    weights: Option<Vec<f64>>,
    options: &FitOptions,
) -> Result<DynFit, FitError> {
    /// What each point has besides its position.
    struct Rest {
        degrees: Vec<Degrees>,
        second_lane: Option<Vec<Degrees>>,
        parameters: Option<Vec<f64>>,
        weights: Option<Vec<f64>>,
    }
    fn rows<const D: usize>(
        positions: &[f64],
        rest: Rest,
        options: &FitOptions,
    ) -> Result<Fit<D>, FitError> {
        let points = positions
            .chunks_exact(D)
            .map(|row| core::array::from_fn(|a| row[a]))
            .collect();
        let mut data = FitData::new(points, rest.degrees)?;
        if let Some(second_lane) = rest.second_lane {
            data = data.with_second_lane(second_lane)?;
        }
        if let Some(parameters) = rest.parameters {
            data = data.with_parameters(parameters)?;
        }
        if let Some(weights) = rest.weights {
            data = data.with_weights(weights)?;
        }
        fit(&data, options)
    }
    if !(dimension == 2 || dimension == 3) || !positions.len().is_multiple_of(dimension) {
        return Err(FitError::Dimension {
            dimension,
            values: positions.len(),
        });
    }
    let rest = Rest {
        degrees,
        second_lane,
        parameters,
        weights,
    };
    Ok(if dimension == 3 {
        rows::<3>(positions, rest, options)?.into()
    } else {
        rows::<2>(positions, rest, options)?.into()
    })
}

/// The channel names of a `D`-dimensional fit: `x`, `y`, \[`z`,\] `truth`, `indeterminacy`,
/// `falsity`.
pub fn channel_names(dimension: usize) -> Vec<&'static str> {
    ["x", "y", "z"][..dimension]
        .iter()
        .copied()
        .chain(DegreeKind::ALL.iter().map(|k| k.name()))
        .collect()
}
