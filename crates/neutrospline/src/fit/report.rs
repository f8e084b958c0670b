//! What a fit reports (docs/model.md section 8).

/// A control value on a bound of the membership rule.
#[derive(Clone, Debug, PartialEq)]
pub struct AtBound {
    /// The control point (0-based; for a closed curve, among the distinct ones).
    pub index: usize,
    /// `truth`, `indeterminacy`, `falsity`, or the rule's sum (`truth + falsity` under the
    /// intuitionistic rule, `truth^2 + falsity^2` under the Pythagorean one, ...).
    pub channel: String,
    /// The bound: 0 or 1.
    pub bound: f64,
}

/// The residuals, conditioning and active bounds of a fit.
///
/// A residual is the curve's value at the point's parameter minus the data value, per
/// channel (positions and degrees); the position residual of a point is the distance between
/// the two positions.
#[derive(Clone, Debug, PartialEq)]
pub struct FitReport {
    /// The number of control points of the fitted curve (a closed curve's distinct ones).
    pub control_points: usize,
    /// The polynomial degree of the fitted curve.
    pub degree: usize,
    /// The largest absolute residual per channel (`x`, `y`, \[`z`,\] `truth`,
    /// `indeterminacy`, `falsity`).
    pub max_error: Vec<(&'static str, f64)>,
    /// The root-mean-square residual per channel (over all points, unweighted).
    pub rms_error: Vec<(&'static str, f64)>,
    /// The point with the largest position residual.
    pub worst_index: usize,
    /// Its parameter.
    pub worst_parameter: f64,
    /// Its position residual.
    pub worst_distance: f64,
    /// Whether the Schoenberg-Whitney conditions hold: every control point has data of its
    /// own (always, unless smoothing made the fit determined without them).
    pub schoenberg_whitney: bool,
    /// An estimate of the 1-norm condition number of the normal matrix `N^T W N + lambda R`
    /// (for interpolation, about the square of the collocation matrix's).
    pub condition_estimate: f64,
    /// The control degrees on a bound (`0`, `1`, or `truth + falsity = 1`).
    pub at_bound: Vec<AtBound>,
    /// For a tolerance fit, the tolerance (given, or the default: 1e-3 of the data's
    /// bounding-box diagonal).
    pub tolerance: Option<f64>,
    /// For a tolerance fit, whether every position residual is within the tolerance.
    pub tolerance_met: Option<bool>,
}

impl FitReport {
    /// The largest absolute residual of a channel, by name.
    pub fn max(&self, channel: &str) -> Option<f64> {
        self.max_error
            .iter()
            .find(|(name, _)| *name == channel)
            .map(|(_, v)| *v)
    }
}
