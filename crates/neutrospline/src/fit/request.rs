//! [`FitRequest`]: the options of a fit, defined once for the command line, Python and the
//! studio (docs/architecture.md, "one definition of every option").

use core::fmt;
use core::str::FromStr;

use super::{DataWeights, FitKind, FitOptions, FitTarget, Parametrization};
use crate::options::{find, OptionError, OptionSet, OptionSpec, OptionValue, Read, ValueKind};
use crate::{Family, ParseNameError};

/// The options of a fit as every front end gives them: one field per option of
/// [`OptionSet::OPTIONS`], set by name with [`OptionSet::set`] and checked by
/// [`FitRequest::validate`], which owns the rules between them.
///
/// `FitRequest::default()` holds the defaults every front end shows: degree 3, no target
/// (then a tolerance of 1e-3 of the data's bounding-box diagonal), open, chord-length
/// parameters, unweighted, no smoothing, a B-spline, neutrosophic degrees.
///
/// ```
/// use neutrospline::fit::{FitRequest, FitTarget};
/// use neutrospline::options::{OptionSet, OptionValue};
/// let mut request = FitRequest::default();
/// request.set("control-points", OptionValue::Integer(6))?;
/// request.set("parametrization", OptionValue::Text("centripetal".into()))?;
/// let options = request.validate()?;
/// assert_eq!(options.target(), Some(FitTarget::ControlPoints(6)));
/// // Two targets are a contradiction, with one message in every front end.
/// request.set("interpolate", OptionValue::Flag(true))?;
/// assert_eq!(
///     request.validate().unwrap_err().to_string(),
///     "interpolate and control-points exclude each other (give one target: \
///      interpolate, control-points or tolerance)"
/// );
/// # Ok::<(), neutrospline::options::OptionError>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct FitRequest {
    /// `degree`: the polynomial degree (default 3).
    pub degree: usize,
    /// `control-points`: least squares with this many control points.
    pub control_points: Option<usize>,
    /// `tolerance`: least squares, knots refined until every position residual is at most
    /// this (absolute).
    pub tolerance: Option<f64>,
    /// `interpolate`: through every data point.
    pub interpolate: bool,
    /// `closed`: a periodic curve, `C^(p-1)` at the seam.
    pub closed: bool,
    /// `parametrization`: how points get parameters when the data gives none.
    pub parametrization: Parametrization,
    /// `weights`: how points are weighted in least squares.
    pub weights: DataWeights,
    /// `smoothing`: the weight `lambda >= 0` of the penalty `lambda int |C''|^2`.
    pub smoothing: f64,
    /// `kind`: a B-spline or one Bézier segment.
    pub kind: FitKind,
    /// `membership`: the rule of the data's degrees and of the fitted curve's.
    pub membership: Family,
}

impl Default for FitRequest {
    fn default() -> Self {
        FitRequest {
            degree: 3,
            control_points: None,
            tolerance: None,
            interpolate: false,
            closed: false,
            parametrization: Parametrization::ChordLength,
            weights: DataWeights::None,
            smoothing: 0.0,
            kind: FitKind::BSpline,
            membership: Family::Neutrosophic,
        }
    }
}

/// The three targets, in the order of [`OptionSet::OPTIONS`].
const TARGET_RULE: &str = "give one target: interpolate, control-points or tolerance";

/// The option `membership` of curve and surface fits: every family (docs/model.md,
/// "Membership families"; the interval-valued and bipolar ones fitted in two lanes).
pub(crate) const MEMBERSHIP: OptionSpec = OptionSpec {
    name: "membership",
    kind: ValueKind::Text,
    value_name: "FAMILY",
    help: "Membership family of the data's degrees and of the fitted model's: neutrosophic, \
           intuitionistic, fuzzy, pythagorean, fermatean, q-rung:Q, picture, spherical, \
           t-spherical:N, interval-neutrosophic, interval-intuitionistic, interval-type2, \
           bipolar-neutrosophic",
};

/// The option `weights` of curve and surface fits.
pub(crate) const WEIGHTS: OptionSpec = OptionSpec {
    name: "weights",
    kind: ValueKind::Choice(&["none", "column", "score"]),
    value_name: "WEIGHTS",
    help: "How the points are weighted in least squares: equally, by the data's weight \
           column, or by their score ((2 + T - I - F) / 3; a two-lane family's own score)",
};

/// Reads the value of [`MEMBERSHIP`].
pub(crate) fn parse_membership(word: &str) -> Result<Family, OptionError> {
    word.parse()
        .map_err(|e: crate::ParseFamilyError| OptionError::Invalid {
            name: MEMBERSHIP.name,
            given: format!("{word:?}"),
            expected: e.to_string(),
        })
}

impl OptionSet for FitRequest {
    /// Every option of a fit, in the order front ends list them.
    const OPTIONS: &'static [OptionSpec] = &[
        OptionSpec {
            name: "degree",
            kind: ValueKind::Whole,
            value_name: "P",
            help: "Degree of the fitted curve",
        },
        OptionSpec {
            name: "interpolate",
            kind: ValueKind::Flag,
            value_name: "",
            help: "Interpolate: the curve passes through every data point",
        },
        OptionSpec {
            name: "control-points",
            kind: ValueKind::Whole,
            value_name: "N",
            help: "Least squares with this many control points",
        },
        OptionSpec {
            name: "tolerance",
            kind: ValueKind::Number,
            value_name: "E",
            help: "Least squares to this tolerance: every position residual at most E (absolute)",
        },
        OptionSpec {
            name: "closed",
            kind: ValueKind::Flag,
            value_name: "",
            help: "A closed (periodic) curve, C^(p-1) at the seam",
        },
        OptionSpec {
            name: "parametrization",
            kind: ValueKind::Choice(&["uniform", "chord-length", "centripetal"]),
            value_name: "RULE",
            help: "How data points get parameters when the data gives none",
        },
        WEIGHTS,
        OptionSpec {
            name: "smoothing",
            kind: ValueKind::Number,
            value_name: "LAMBDA",
            help: "Smoothing: a penalty LAMBDA times the integral of the squared second derivative",
        },
        OptionSpec {
            name: "kind",
            kind: ValueKind::Choice(&["bspline", "bezier"]),
            value_name: "KIND",
            help: "The kind of curve fitted",
        },
        MEMBERSHIP,
    ];

    /// Sets the option `name`; a value of another kind (`degree = 5.0`, `closed = "yes"`)
    /// is refused.
    fn set(&mut self, name: &str, value: OptionValue) -> Result<(), OptionError> {
        let spec = find(Self::OPTIONS, name)?;
        let read = spec.read(&value)?;
        match (spec.name, read) {
            ("degree", Read::Whole(n)) => self.degree = n,
            ("control-points", Read::Whole(n)) => self.control_points = Some(n),
            ("tolerance", Read::Number(x)) => self.tolerance = Some(x),
            ("interpolate", Read::Flag(on)) => self.interpolate = on,
            ("closed", Read::Flag(on)) => self.closed = on,
            ("smoothing", Read::Number(x)) => self.smoothing = x,
            ("parametrization", Read::Choice(word)) => self.parametrization = parse(word),
            ("weights", Read::Choice(word)) => self.weights = parse(word),
            ("kind", Read::Choice(word)) => self.kind = parse(word),
            ("membership", Read::Text(word)) => self.membership = parse_membership(&word)?,
            (other, read) => unreachable!("option {other} read as {read:?}"),
        }
        Ok(())
    }

    /// The value as a command-line word: `3`, `chord-length`, `false`.
    fn value_text(&self, name: &str) -> Result<Option<String>, OptionError> {
        let spec = find(Self::OPTIONS, name)?;
        Ok(match spec.name {
            "degree" => Some(self.degree.to_string()),
            "control-points" => self.control_points.map(|n| n.to_string()),
            "tolerance" => self.tolerance.map(|x| x.to_string()),
            "interpolate" => Some(self.interpolate.to_string()),
            "closed" => Some(self.closed.to_string()),
            "smoothing" => Some(self.smoothing.to_string()),
            "parametrization" => Some(self.parametrization.to_string()),
            "weights" => Some(self.weights.to_string()),
            "kind" => Some(self.kind.to_string()),
            "membership" => Some(self.membership.to_string()),
            other => unreachable!("option {other} has no value"),
        })
    }
}

impl FitRequest {
    /// The fit's options, once the rules between the options hold: at most one target
    /// (`interpolate`, `control-points`, `tolerance`), a positive finite tolerance, a
    /// non-negative finite smoothing weight.
    ///
    /// # Errors
    /// [`OptionError::Conflict`] for two targets, [`OptionError::OutOfRange`] for a value out
    /// of its range.
    pub fn validate(&self) -> Result<FitOptions, OptionError> {
        let given = [
            ("interpolate", self.interpolate),
            ("control-points", self.control_points.is_some()),
            ("tolerance", self.tolerance.is_some()),
        ];
        let mut targets = given.iter().filter(|(_, on)| *on).map(|(name, _)| *name);
        if let (Some(first), Some(second)) = (targets.next(), targets.next()) {
            let (first, second) = in_list_order(first, second);
            return Err(OptionError::Conflict {
                first,
                second,
                rule: TARGET_RULE,
            });
        }
        if let Some(e) = self.tolerance {
            if !(e > 0.0 && e.is_finite()) {
                return Err(OptionError::OutOfRange {
                    name: "tolerance",
                    given: shown(e),
                    rule: "the tolerance must be a positive finite number",
                });
            }
        }
        if !(self.smoothing >= 0.0 && self.smoothing.is_finite()) {
            return Err(OptionError::OutOfRange {
                name: "smoothing",
                given: shown(self.smoothing),
                rule: "the smoothing weight must be a non-negative finite number",
            });
        }
        let mut options = FitOptions::default()
            .with_degree(self.degree)
            .with_closed(self.closed)
            .with_parametrization(self.parametrization)
            .with_weights(self.weights)
            .with_smoothing(self.smoothing)
            .with_kind(self.kind)
            .with_membership(self.membership);
        let target = if self.interpolate {
            Some(FitTarget::Interpolate)
        } else if let Some(n) = self.control_points {
            Some(FitTarget::ControlPoints(n))
        } else {
            self.tolerance.map(FitTarget::Tolerance)
        };
        if let Some(target) = target {
            options = options.with_target(target);
        }
        Ok(options)
    }
}

/// A number as a message shows it: `0`, `-1`, `0.5`, `1e-9`, `inf`.
fn shown(x: f64) -> String {
    if x.fract() == 0.0 && x.abs() < 1e15 {
        format!("{x}")
    } else {
        format!("{x:?}")
    }
}

impl FitRequest {
    /// Whether the data's own weights and the `weights` option agree: a data source (named
    /// `source` in the message) with a weight column is fitted with `weights = column` only,
    /// and `weights = column` needs the column, so that no column is silently left unused.
    ///
    /// ```
    /// use neutrospline::fit::{DataWeights, FitRequest};
    /// let request = FitRequest::default();
    /// assert_eq!(
    ///     request.check_data_weights("d.csv", true).unwrap_err().to_string(),
    ///     "d.csv has a `weight` column: set weights to column to use it (or remove the column)"
    /// );
    /// let column = FitRequest { weights: DataWeights::Given, ..FitRequest::default() };
    /// assert!(column.check_data_weights("d.csv", true).is_ok());
    /// ```
    ///
    /// # Errors
    /// [`OptionError::Data`].
    pub fn check_data_weights(&self, source: &str, has_weights: bool) -> Result<(), OptionError> {
        self.weights.check_data(source, has_weights)
    }
}

impl DataWeights {
    /// Whether these weights and a data source's own agree: a source with a weight column
    /// is fitted with `column` only, and `column` needs the column (the rule of
    /// [`FitRequest::check_data_weights`], shared by surface fits).
    ///
    /// # Errors
    /// [`OptionError::Data`].
    pub fn check_data(self, source: &str, has_weights: bool) -> Result<(), OptionError> {
        match (self == DataWeights::Given, has_weights) {
            (true, false) => Err(OptionError::Data(format!(
                "weights = column: {source} has no `weight` column"
            ))),
            (false, true) => Err(OptionError::Data(format!(
                "{source} has a `weight` column: set weights to column to use it (or remove the \
                 column)"
            ))),
            _ => Ok(()),
        }
    }
}

/// The two names in the order of [`OptionSet::OPTIONS`].
fn in_list_order(a: &'static str, b: &'static str) -> (&'static str, &'static str) {
    let position = |name| FitRequest::OPTIONS.iter().position(|s| s.name == name);
    if position(a) <= position(b) {
        (a, b)
    } else {
        (b, a)
    }
}

/// A choice word that [`OptionSpec::read`] accepted, as its enum.
fn parse<T: FromStr>(word: &str) -> T
where
    T::Err: fmt::Debug,
{
    word.parse()
        .unwrap_or_else(|e| unreachable!("choice {word} not parsed: {e:?}"))
}

/// `uniform`, `chord-length`, `centripetal`.
impl fmt::Display for Parametrization {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Parametrization {
    type Err = ParseNameError;

    /// Parses `uniform`, `chord-length` or `centripetal` (case-insensitive).
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        [
            Parametrization::Uniform,
            Parametrization::ChordLength,
            Parametrization::Centripetal,
        ]
        .into_iter()
        .find(|p| p.name().eq_ignore_ascii_case(s.trim()))
        .ok_or_else(|| {
            ParseNameError::new("parametrization", s, "uniform, chord-length, centripetal")
        })
    }
}

impl DataWeights {
    /// The name used by every front end: `none`, `column` (the data's own weights), `score`.
    pub const fn name(self) -> &'static str {
        match self {
            DataWeights::None => "none",
            DataWeights::Given => "column",
            DataWeights::Score => "score",
        }
    }
}

/// `none`, `column`, `score`.
impl fmt::Display for DataWeights {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for DataWeights {
    type Err = ParseNameError;

    /// Parses `none`, `column` or `score` (case-insensitive).
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        [DataWeights::None, DataWeights::Given, DataWeights::Score]
            .into_iter()
            .find(|w| w.name().eq_ignore_ascii_case(s.trim()))
            .ok_or_else(|| ParseNameError::new("weights", s, "none, column, score"))
    }
}

impl FitKind {
    /// The name used by every front end: `bspline`, `bezier`.
    pub const fn name(self) -> &'static str {
        match self {
            FitKind::BSpline => "bspline",
            FitKind::Bezier => "bezier",
        }
    }
}

/// `bspline`, `bezier`.
impl fmt::Display for FitKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for FitKind {
    type Err = ParseNameError;

    /// Parses `bspline` or `bezier` (case-insensitive).
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        [FitKind::BSpline, FitKind::Bezier]
            .into_iter()
            .find(|k| k.name().eq_ignore_ascii_case(s.trim()))
            .ok_or_else(|| ParseNameError::new("kind of fit", s, "bspline, bezier"))
    }
}

#[cfg(feature = "serde")]
mod serde_impl {
    //! A request as a map of canonical names to values. Reading goes through
    //! [`FitRequest::set`] and [`FitRequest::validate`], so an unknown key, a value of another
    //! type or a contradiction is refused with the same message as on the command line.

    use serde::de;
    use serde::ser::SerializeMap;
    use serde::{Deserialize, Deserializer, Serialize, Serializer};

    use super::FitRequest;

    impl Serialize for FitRequest {
        fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
            let mut map = serializer.serialize_map(None)?;
            if let Some(n) = self.control_points {
                map.serialize_entry("control-points", &n)?;
            }
            if let Some(e) = self.tolerance {
                map.serialize_entry("tolerance", &e)?;
            }
            map.serialize_entry("degree", &self.degree)?;
            map.serialize_entry("interpolate", &self.interpolate)?;
            map.serialize_entry("closed", &self.closed)?;
            map.serialize_entry("parametrization", self.parametrization.name())?;
            map.serialize_entry("weights", self.weights.name())?;
            map.serialize_entry("smoothing", &self.smoothing)?;
            map.serialize_entry("kind", self.kind.name())?;
            map.serialize_entry("membership", &self.membership.to_string())?;
            map.end()
        }
    }

    impl<'de> Deserialize<'de> for FitRequest {
        fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
            let request: FitRequest = crate::options::deserialize(deserializer)?;
            request.validate().map_err(de::Error::custom)?;
            Ok(request)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_option_has_a_value_text_and_round_trips_through_set() {
        let defaults = FitRequest::default();
        for spec in FitRequest::OPTIONS {
            let text = defaults.value_text(spec.name).unwrap();
            if let Some(text) = text {
                let mut request = FitRequest::default();
                request.set(spec.name, OptionValue::Word(text)).unwrap();
                assert_eq!(request, defaults, "{}", spec.name);
            }
        }
    }

    #[test]
    fn choices_are_the_enums_names() {
        let names = |name: &str| match find(FitRequest::OPTIONS, name).unwrap().kind {
            ValueKind::Choice(names) => names,
            _ => unreachable!(),
        };
        for word in names("parametrization") {
            assert_eq!(word.parse::<Parametrization>().unwrap().name(), *word);
        }
        for word in names("weights") {
            assert_eq!(word.parse::<DataWeights>().unwrap().name(), *word);
        }
        for word in names("kind") {
            assert_eq!(word.parse::<FitKind>().unwrap().name(), *word);
        }
    }

    #[test]
    fn each_pair_of_targets_is_a_conflict_named_in_list_order() {
        let pairs = [
            ("control-points", "tolerance"),
            ("interpolate", "control-points"),
            ("interpolate", "tolerance"),
        ];
        for (a, b) in pairs {
            let mut request = FitRequest::default();
            for name in [a, b] {
                let value = match name {
                    "interpolate" => OptionValue::Flag(true),
                    "control-points" => OptionValue::Integer(5),
                    _ => OptionValue::Number(0.1),
                };
                request.set(name, value).unwrap();
            }
            let message = request.validate().unwrap_err().to_string();
            let (first, second) = in_list_order(a, b);
            assert_eq!(
                message,
                format!("{first} and {second} exclude each other ({TARGET_RULE})")
            );
        }
    }

    #[test]
    fn ranges_are_checked_with_the_value() {
        let mut request = FitRequest::default();
        request.set("tolerance", OptionValue::Number(-1.0)).unwrap();
        assert_eq!(
            request.validate().unwrap_err().to_string(),
            "tolerance = -1: the tolerance must be a positive finite number"
        );
        let mut request = FitRequest::default();
        request
            .set("smoothing", OptionValue::Word("inf".into()))
            .unwrap();
        assert_eq!(
            request.validate().unwrap_err().to_string(),
            "smoothing = inf: the smoothing weight must be a non-negative finite number"
        );
    }
}
