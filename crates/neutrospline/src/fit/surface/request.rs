//! [`SurfaceFitRequest`]: the options of a surface fit, defined once for the command line and
//! Python, with the curve fit's names where the two share an option.

use super::super::request::{parse_membership, MEMBERSHIP, WEIGHTS};
use super::super::{DataWeights, Parametrization};
use super::{Projection, SurfaceFitOptions, SurfaceTarget};
use crate::options::{find, OptionError, OptionSet, OptionSpec, OptionValue, Read, ValueKind};
use crate::Family;

/// The options of a surface fit as every front end gives them, set by name and checked by
/// [`SurfaceFitRequest::validate`].
///
/// `SurfaceFitRequest::default()`: degrees 3 and 3, no target (a tolerance of 1e-3 of the
/// data's bounding-box diagonal), scattered data projected on the best-fitting plane,
/// chord-length parameters for a grid, unweighted, no smoothing, neutrosophic degrees.
///
/// ```
/// use neutrospline::fit::{SurfaceFitRequest, SurfaceTarget};
/// use neutrospline::options::{OptionSet, OptionValue};
/// let mut request = SurfaceFitRequest::default();
/// request.set("degree", OptionValue::Word("3,2".into()))?;
/// request.set("control-points", OptionValue::Word("8,6".into()))?;
/// request.set("grid", OptionValue::Word("20x15".into()))?;
/// let options = request.validate()?;
/// assert_eq!(options.degrees(), [3, 2]);
/// assert_eq!(options.target(), Some(SurfaceTarget::ControlPoints([8, 6])));
/// assert_eq!(request.grid, Some([20, 15]));
/// request.set("scattered", OptionValue::Flag(true))?;
/// assert_eq!(
///     request.validate().unwrap_err().to_string(),
///     "grid and scattered exclude each other (the data is a grid of ROWSxCOLS points or \
///      scattered points)"
/// );
/// # Ok::<(), neutrospline::options::OptionError>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct SurfaceFitRequest {
    /// `degree`: `[p, q]` (one number gives both).
    pub degree: [usize; 2],
    /// `interpolate`: through every point of a grid.
    pub interpolate: bool,
    /// `control-points`: least squares with `[m, n]` control points (one number, both).
    pub control_points: Option<[usize; 2]>,
    /// `tolerance`: least squares, knots refined until every position residual is at most
    /// this (absolute).
    pub tolerance: Option<f64>,
    /// `grid`: the data is a grid of `[rows, cols]` points, row by row.
    pub grid: Option<[usize; 2]>,
    /// `scattered`: the data is scattered points (the default without `grid`).
    pub scattered: bool,
    /// `parametrization`: how grid points get parameters when the data gives none.
    pub parametrization: Parametrization,
    /// `projection`: how scattered points get parameters when the data gives none.
    pub projection: Projection,
    /// `weights`: how points are weighted in least squares.
    pub weights: DataWeights,
    /// `smoothing`: the weight of the thin-plate penalty.
    pub smoothing: f64,
    /// `membership`: the rule of the data's degrees and of the fitted surface's.
    pub membership: Family,
}

impl Default for SurfaceFitRequest {
    fn default() -> Self {
        SurfaceFitRequest {
            degree: [3, 3],
            interpolate: false,
            control_points: None,
            tolerance: None,
            grid: None,
            scattered: false,
            parametrization: Parametrization::ChordLength,
            projection: Projection::Plane,
            weights: DataWeights::None,
            smoothing: 0.0,
            membership: Family::Neutrosophic,
        }
    }
}

const TARGET_RULE: &str = "give one target: interpolate, control-points or tolerance";
const SHAPE_RULE: &str = "the data is a grid of ROWSxCOLS points or scattered points";

/// One or two whole numbers (`3` or `3,2`), the one given for both.
fn pair(name: &'static str, values: &[f64], rule: &'static str) -> Result<[usize; 2], OptionError> {
    let whole = |x: f64| x >= 0.0 && x.fract() == 0.0 && x < 1e9;
    let shown = || {
        values
            .iter()
            .map(|v| v.to_string())
            .collect::<Vec<_>>()
            .join(",")
    };
    match values {
        [a] if whole(*a) => Ok([*a as usize; 2]),
        [a, b] if whole(*a) && whole(*b) => Ok([*a as usize, *b as usize]),
        _ => Err(OptionError::OutOfRange {
            name,
            given: shown(),
            rule,
        }),
    }
}

impl OptionSet for SurfaceFitRequest {
    /// Every option of a surface fit, in the order front ends list them.
    const OPTIONS: &'static [OptionSpec] = &[
        OptionSpec {
            name: "degree",
            kind: ValueKind::Numbers,
            value_name: "P[,Q]",
            help: "Degrees of the fitted surface along u and v (one number: both)",
        },
        OptionSpec {
            name: "interpolate",
            kind: ValueKind::Flag,
            value_name: "",
            help: "Interpolate: the surface passes through every point of the grid",
        },
        OptionSpec {
            name: "control-points",
            kind: ValueKind::Numbers,
            value_name: "M[,N]",
            help: "Least squares with M x N control points (one number: both)",
        },
        OptionSpec {
            name: "tolerance",
            kind: ValueKind::Number,
            value_name: "E",
            help: "Least squares to this tolerance: every position residual at most E (absolute)",
        },
        OptionSpec {
            name: "grid",
            kind: ValueKind::Text,
            value_name: "ROWSxCOLS",
            help: "The data is a grid of ROWS x COLS points, row by row (rows along u)",
        },
        OptionSpec {
            name: "scattered",
            kind: ValueKind::Flag,
            value_name: "",
            help: "The data is scattered points (the default without --grid)",
        },
        OptionSpec {
            name: "parametrization",
            kind: ValueKind::Choice(&["uniform", "chord-length", "centripetal"]),
            value_name: "RULE",
            help: "How grid points get parameters when the data gives none (averaged over rows \
                   and columns)",
        },
        OptionSpec {
            name: "projection",
            kind: ValueKind::Choice(&["plane", "xy"]),
            value_name: "PLANE",
            help: "How scattered points get (u, v) when the data gives none: the best-fitting \
                   plane, or x and y (height data)",
        },
        WEIGHTS,
        OptionSpec {
            name: "smoothing",
            kind: ValueKind::Number,
            value_name: "LAMBDA",
            help: "Smoothing: LAMBDA times the thin-plate energy (S_uu^2 + 2 S_uv^2 + S_vv^2 over \
                   the parameter domain)",
        },
        MEMBERSHIP,
    ];

    fn set(&mut self, name: &str, value: OptionValue) -> Result<(), OptionError> {
        let spec = find(Self::OPTIONS, name)?;
        let read = spec.read(&value)?;
        match (spec.name, read) {
            ("degree", Read::Numbers(v)) => {
                self.degree = pair(
                    "degree",
                    &v,
                    "a degree is one or two whole numbers (P or P,Q)",
                )?;
            }
            ("control-points", Read::Numbers(v)) => {
                self.control_points = Some(pair(
                    "control-points",
                    &v,
                    "control points are one or two whole numbers (M or M,N)",
                )?);
            }
            ("tolerance", Read::Number(x)) => self.tolerance = Some(x),
            ("interpolate", Read::Flag(on)) => self.interpolate = on,
            ("grid", Read::Text(text)) => self.grid = Some(parse_grid(&text)?),
            ("scattered", Read::Flag(on)) => self.scattered = on,
            ("smoothing", Read::Number(x)) => self.smoothing = x,
            ("parametrization", Read::Choice(word)) => self.parametrization = parse(word),
            ("projection", Read::Choice(word)) => self.projection = parse(word),
            ("weights", Read::Choice(word)) => self.weights = parse(word),
            ("membership", Read::Text(word)) => self.membership = parse_membership(&word)?,
            (other, read) => unreachable!("option {other} read as {read:?}"),
        }
        Ok(())
    }

    fn value_text(&self, name: &str) -> Result<Option<String>, OptionError> {
        let spec = find(Self::OPTIONS, name)?;
        let both = |[a, b]: [usize; 2]| {
            if a == b {
                a.to_string()
            } else {
                format!("{a},{b}")
            }
        };
        Ok(match spec.name {
            "degree" => Some(both(self.degree)),
            "control-points" => self.control_points.map(both),
            "tolerance" => self.tolerance.map(|x| x.to_string()),
            "interpolate" => Some(self.interpolate.to_string()),
            "grid" => self.grid.map(|[r, c]| format!("{r}x{c}")),
            "scattered" => Some(self.scattered.to_string()),
            "smoothing" => Some(self.smoothing.to_string()),
            "parametrization" => Some(self.parametrization.to_string()),
            "projection" => Some(self.projection.to_string()),
            "weights" => Some(self.weights.to_string()),
            "membership" => Some(self.membership.to_string()),
            other => unreachable!("option {other} has no value"),
        })
    }
}

/// `ROWSxCOLS`, each a whole number >= 1.
fn parse_grid(text: &str) -> Result<[usize; 2], OptionError> {
    let error = || OptionError::OutOfRange {
        name: "grid",
        given: text.to_owned(),
        rule: "a grid is ROWSxCOLS, two whole numbers >= 1 (for example 20x15)",
    };
    let (rows, cols) = text.trim().split_once(['x', 'X']).ok_or_else(error)?;
    let read = |s: &str| s.trim().parse::<usize>().ok().filter(|&n| n >= 1);
    Ok([read(rows).ok_or_else(error)?, read(cols).ok_or_else(error)?])
}

fn parse<T: core::str::FromStr>(word: &str) -> T
where
    T::Err: core::fmt::Debug,
{
    word.parse()
        .unwrap_or_else(|e| unreachable!("choice {word} not parsed: {e:?}"))
}

impl SurfaceFitRequest {
    /// The fit's options, once the rules between the options hold: at most one target, not
    /// both `grid` and `scattered`, a positive finite tolerance, a non-negative finite
    /// smoothing weight.
    ///
    /// # Errors
    /// [`OptionError::Conflict`], [`OptionError::OutOfRange`].
    pub fn validate(&self) -> Result<SurfaceFitOptions, OptionError> {
        let given = [
            ("interpolate", self.interpolate),
            ("control-points", self.control_points.is_some()),
            ("tolerance", self.tolerance.is_some()),
        ];
        let mut targets = given.iter().filter(|(_, on)| *on).map(|(name, _)| *name);
        if let (Some(first), Some(second)) = (targets.next(), targets.next()) {
            return Err(OptionError::Conflict {
                first,
                second,
                rule: TARGET_RULE,
            });
        }
        if self.grid.is_some() && self.scattered {
            return Err(OptionError::Conflict {
                first: "grid",
                second: "scattered",
                rule: SHAPE_RULE,
            });
        }
        if let Some(e) = self.tolerance {
            if !(e > 0.0 && e.is_finite()) {
                return Err(OptionError::OutOfRange {
                    name: "tolerance",
                    given: e.to_string(),
                    rule: "the tolerance must be a positive finite number",
                });
            }
        }
        if !(self.smoothing >= 0.0 && self.smoothing.is_finite()) {
            return Err(OptionError::OutOfRange {
                name: "smoothing",
                given: self.smoothing.to_string(),
                rule: "the smoothing weight must be a non-negative finite number",
            });
        }
        let [p, q] = self.degree;
        let mut options = SurfaceFitOptions::default()
            .with_degrees(p, q)
            .with_parametrization(self.parametrization)
            .with_projection(self.projection)
            .with_weights(self.weights)
            .with_smoothing(self.smoothing)
            .with_membership(self.membership);
        let target = if self.interpolate {
            Some(SurfaceTarget::Interpolate)
        } else if let Some(counts) = self.control_points {
            Some(SurfaceTarget::ControlPoints(counts))
        } else {
            self.tolerance.map(SurfaceTarget::Tolerance)
        };
        if let Some(target) = target {
            options = options.with_target(target);
        }
        Ok(options)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_option_round_trips_through_its_text() {
        let mut request = SurfaceFitRequest::default();
        request
            .set("degree", OptionValue::Word("3,2".into()))
            .unwrap();
        request
            .set("grid", OptionValue::Word("4x5".into()))
            .unwrap();
        request
            .set("control-points", OptionValue::Word("4".into()))
            .unwrap();
        for spec in SurfaceFitRequest::OPTIONS {
            if let Some(text) = request.value_text(spec.name).unwrap() {
                let mut again = request.clone();
                let value = match spec.kind {
                    ValueKind::Flag => OptionValue::Flag(text == "true"),
                    _ => OptionValue::Word(text),
                };
                again.set(spec.name, value).unwrap();
                assert_eq!(again, request, "{}", spec.name);
            }
        }
        assert_eq!(request.control_points, Some([4, 4]));
    }

    #[test]
    fn bad_pairs_and_grids_are_refused_with_the_value() {
        let mut request = SurfaceFitRequest::default();
        assert_eq!(
            request
                .set("degree", OptionValue::Word("3,2,1".into()))
                .unwrap_err()
                .to_string(),
            "degree = 3,2,1: a degree is one or two whole numbers (P or P,Q)"
        );
        assert_eq!(
            request
                .set("grid", OptionValue::Word("20by3".into()))
                .unwrap_err()
                .to_string(),
            "grid = 20by3: a grid is ROWSxCOLS, two whole numbers >= 1 (for example 20x15)"
        );
    }
}
