//! Membership families: which degree channels a value carries, the rule they obey, the degrees
//! derived from them and the scores that rank them (docs/model.md, "Membership families";
//! SPEC section 10).
//!
//! A [`Family`] is one of the thirteen rules below. Every method has one body for all of them:
//! the families are described by data (channel names, boxes, lower/upper pairs and one
//! power-sum group), and the check, the constraints, the projection, the derived degrees and
//! the scores read that data.
//!
//! | family | channels | rule |
//! |---|---|---|
//! | `neutrosophic` | truth, indeterminacy, falsity | each in \[0, 1\] |
//! | `intuitionistic` | truth, falsity | T + F <= 1 |
//! | `fuzzy` | truth | T in \[0, 1\] |
//! | `pythagorean` | truth, falsity | T^2 + F^2 <= 1 |
//! | `fermatean` | truth, falsity | T^3 + F^3 <= 1 |
//! | `q-rung:q` (q >= 1) | truth, falsity | T^q + F^q <= 1 |
//! | `picture` | truth, indeterminacy (neutral), falsity | T + I + F <= 1 |
//! | `spherical` | truth, indeterminacy, falsity | T^2 + I^2 + F^2 <= 1 |
//! | `t-spherical:n` (n >= 1) | truth, indeterminacy, falsity | T^n + I^n + F^n <= 1 |
//! | `interval-neutrosophic` | truth_lower, truth_upper, indeterminacy_lower, ..., falsity_upper | each in \[0, 1\], lower <= upper |
//! | `interval-intuitionistic` | truth_lower, truth_upper, falsity_lower, falsity_upper | lower <= upper, T_U + F_U <= 1 |
//! | `interval-type2` | truth_lower, truth_upper (lower and upper membership) | 0 <= M_L <= M_U <= 1 |
//! | `bipolar-neutrosophic` | truth, indeterminacy, falsity, negative_truth, negative_indeterminacy, negative_falsity | positive in \[0, 1\], negative in \[-1, 0\] |
//!
//! Every channel is also >= 0 (the bipolar negative ones >= -1), so every rule is a convex set;
//! a blend of valid values with non-negative weights summing to 1 is valid.
//! [`Family::rule_text`] states a family's rule in one line, built from the same data.
//!
//! ```
//! use neutrospline::Family;
//! let family: Family = "q-rung:4".parse()?;
//! assert_eq!(family.channels(), ["truth", "falsity"]);
//! assert!(family.check(&[0.9, 0.7]).is_ok()); // 0.9^4 + 0.7^4 = 0.8962
//! assert_eq!(
//!     Family::Pythagorean.check(&[0.9, 0.7]).unwrap_err().to_string(),
//!     "truth^2 + falsity^2 = 1.3 exceeds 1 (pythagorean rule)"
//! );
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod lanes;
mod measures;
mod project;
mod rule;
mod rule_text;

use core::fmt;
use core::num::NonZeroU32;
use core::ops::Deref;
use core::str::FromStr;

use crate::degrees::{DegreeError, DegreeKind, Degrees};

pub use lanes::{Lane, LaneDegrees};
pub use rule::{LinearConstraint, PowerRule, RuleError, RULE_TOLERANCE};

/// The largest number of channels of any family (bipolar and interval neutrosophic: 6).
pub const MAX_CHANNELS: usize = 6;

/// A membership family (SPEC section 10): the channels a value carries and the rule they obey.
///
/// Parsed from and printed as the names used in files and on the command line:
/// `neutrosophic`, `intuitionistic`, `fuzzy`, `pythagorean`, `fermatean`, `q-rung:Q`,
/// `picture`, `spherical`, `t-spherical:N`, `interval-neutrosophic`,
/// `interval-intuitionistic`, `interval-type2`, `bipolar-neutrosophic`. `q-rung:2` keeps its
/// own name but has the Pythagorean rule (likewise `q-rung:1` and intuitionistic, `q-rung:3`
/// and Fermatean, `t-spherical:2` and spherical, `t-spherical:1` and picture).
///
/// ```
/// use neutrospline::Family;
/// let f = Family::q_rung(4)?;
/// assert_eq!(f.to_string(), "q-rung:4");
/// assert_eq!("Q-Rung:4".parse::<Family>()?, f);
/// assert_eq!(Family::Pythagorean.power(), Some(2));
/// # Ok::<(), neutrospline::ParseFamilyError>(())
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Family {
    /// Single-valued neutrosophic: truth, indeterminacy, falsity, each in \[0, 1\].
    #[default]
    Neutrosophic,
    /// Intuitionistic fuzzy (Atanassov): truth + falsity <= 1.
    Intuitionistic,
    /// Fuzzy (Zadeh): one membership degree, stored as truth.
    Fuzzy,
    /// Pythagorean fuzzy (Yager): truth^2 + falsity^2 <= 1.
    Pythagorean,
    /// Fermatean fuzzy (Senapati and Yager): truth^3 + falsity^3 <= 1.
    Fermatean,
    /// q-rung orthopair fuzzy (Yager): truth^q + falsity^q <= 1.
    QRung(NonZeroU32),
    /// Picture fuzzy (Cuong): truth + indeterminacy (neutral) + falsity <= 1.
    Picture,
    /// Spherical fuzzy (Kutlu Gundogdu and Kahraman): T^2 + I^2 + F^2 <= 1.
    Spherical,
    /// T-spherical fuzzy (Mahmood et al.): T^n + I^n + F^n <= 1.
    TSpherical(NonZeroU32),
    /// Interval-valued neutrosophic (Wang et al.): each degree an interval in \[0, 1\].
    IntervalNeutrosophic,
    /// Interval-valued intuitionistic fuzzy (Atanassov and Gargov): intervals with
    /// truth_upper + falsity_upper <= 1.
    IntervalIntuitionistic,
    /// Interval type-2 fuzzy (Mendel): lower and upper membership, 0 <= M_L <= M_U <= 1.
    IntervalType2,
    /// Bipolar neutrosophic (Deli, Ali and Smarandache): positive degrees in \[0, 1\] and
    /// negative ones in \[-1, 0\].
    BipolarNeutrosophic,
}

/// Why a string names no [`Family`]: the message lists the accepted forms.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("unknown membership family `{given}` ({reason}; expected one of: {FAMILY_FORMS})")]
pub struct ParseFamilyError {
    given: String,
    reason: &'static str,
}

/// The accepted forms of a family name, as listed by [`ParseFamilyError`].
pub const FAMILY_FORMS: &str = "neutrosophic, intuitionistic, fuzzy, pythagorean, fermatean, \
q-rung:Q, picture, spherical, t-spherical:N, interval-neutrosophic, interval-intuitionistic, \
interval-type2, bipolar-neutrosophic (Q and N integers >= 1)";

impl ParseFamilyError {
    fn new(given: &str, reason: &'static str) -> Self {
        ParseFamilyError {
            given: given.to_owned(),
            reason,
        }
    }
}

const T: &str = "truth";
const I: &str = "indeterminacy";
const F: &str = "falsity";

/// What a family is made of: everything else is computed from this.
struct Shape {
    channels: &'static [&'static str],
    /// `(lower, upper)` channel indices of interval-valued degrees.
    pairs: &'static [(usize, usize)],
    /// Channels whose `power`-th powers sum to at most 1.
    sum: &'static [usize],
    /// Channels `negative_*` with the box \[-1, 0\] (bipolar); the others have \[0, 1\].
    negative_from: usize,
    derived: &'static [&'static str],
}

const TIF: &[&str] = &[T, I, F];
const TF: &[&str] = &[T, F];

impl Family {
    /// Every family with a fixed name, and `q-rung` and `t-spherical` at their smallest
    /// distinct parameters (4 and 3), in the order of SPEC section 10.
    pub const EXAMPLES: [Family; 13] = [
        Family::Neutrosophic,
        Family::Intuitionistic,
        Family::Fuzzy,
        Family::Pythagorean,
        Family::Fermatean,
        Family::QRung(NonZeroU32::new(4).unwrap()),
        Family::Picture,
        Family::Spherical,
        Family::TSpherical(NonZeroU32::new(3).unwrap()),
        Family::IntervalNeutrosophic,
        Family::IntervalIntuitionistic,
        Family::IntervalType2,
        Family::BipolarNeutrosophic,
    ];

    /// The q-rung orthopair family with `q >= 1`.
    ///
    /// # Errors
    /// `q = 0`.
    pub fn q_rung(q: u32) -> Result<Family, ParseFamilyError> {
        NonZeroU32::new(q)
            .map(Family::QRung)
            .ok_or_else(|| ParseFamilyError::new("q-rung:0", "q must be an integer >= 1"))
    }

    /// The T-spherical family with `n >= 1`.
    ///
    /// # Errors
    /// `n = 0`.
    pub fn t_spherical(n: u32) -> Result<Family, ParseFamilyError> {
        NonZeroU32::new(n)
            .map(Family::TSpherical)
            .ok_or_else(|| ParseFamilyError::new("t-spherical:0", "n must be an integer >= 1"))
    }

    /// The name without parameter: `"q-rung"` for `q-rung:4` ([`Display`](fmt::Display)
    /// adds `:q`).
    pub const fn name(&self) -> &'static str {
        match self {
            Family::Neutrosophic => "neutrosophic",
            Family::Intuitionistic => "intuitionistic",
            Family::Fuzzy => "fuzzy",
            Family::Pythagorean => "pythagorean",
            Family::Fermatean => "fermatean",
            Family::QRung(_) => "q-rung",
            Family::Picture => "picture",
            Family::Spherical => "spherical",
            Family::TSpherical(_) => "t-spherical",
            Family::IntervalNeutrosophic => "interval-neutrosophic",
            Family::IntervalIntuitionistic => "interval-intuitionistic",
            Family::IntervalType2 => "interval-type2",
            Family::BipolarNeutrosophic => "bipolar-neutrosophic",
        }
    }

    /// The exponent of the family's sum rule `sum x^p <= 1` (1 for the linear sums of the
    /// intuitionistic and picture rules), or `None` for the families without a sum rule.
    ///
    /// ```
    /// use neutrospline::Family;
    /// assert_eq!(Family::t_spherical(5)?.power(), Some(5));
    /// assert_eq!(Family::Picture.power(), Some(1));
    /// assert_eq!(Family::Neutrosophic.power(), None);
    /// # Ok::<(), neutrospline::ParseFamilyError>(())
    /// ```
    pub const fn power(&self) -> Option<u32> {
        match self {
            Family::Intuitionistic | Family::Picture | Family::IntervalIntuitionistic => Some(1),
            Family::Pythagorean | Family::Spherical => Some(2),
            Family::Fermatean => Some(3),
            Family::QRung(q) | Family::TSpherical(q) => Some(q.get()),
            _ => None,
        }
    }

    fn shape(&self) -> Shape {
        let plain = |channels, sum, derived| Shape {
            channels,
            pairs: &[],
            sum,
            negative_from: usize::MAX,
            derived,
        };
        match self {
            Family::Neutrosophic => plain(TIF, &[], &[]),
            Family::Fuzzy => plain(&[T], &[], &[]),
            Family::Intuitionistic | Family::Pythagorean | Family::Fermatean | Family::QRung(_) => {
                plain(TF, &[0, 1], &["hesitation"])
            }
            Family::Picture => plain(TIF, &[0, 1, 2], &["refusal"]),
            Family::Spherical | Family::TSpherical(_) => plain(TIF, &[0, 1, 2], &["hesitation"]),
            Family::IntervalNeutrosophic => Shape {
                channels: &[
                    "truth_lower",
                    "truth_upper",
                    "indeterminacy_lower",
                    "indeterminacy_upper",
                    "falsity_lower",
                    "falsity_upper",
                ],
                pairs: &[(0, 1), (2, 3), (4, 5)],
                sum: &[],
                negative_from: usize::MAX,
                derived: &[],
            },
            Family::IntervalIntuitionistic => Shape {
                channels: &[
                    "truth_lower",
                    "truth_upper",
                    "falsity_lower",
                    "falsity_upper",
                ],
                pairs: &[(0, 1), (2, 3)],
                sum: &[1, 3],
                negative_from: usize::MAX,
                derived: &["hesitation_lower", "hesitation_upper"],
            },
            Family::IntervalType2 => Shape {
                channels: &["truth_lower", "truth_upper"],
                pairs: &[(0, 1)],
                sum: &[],
                negative_from: usize::MAX,
                derived: &["type_reduced", "footprint"],
            },
            Family::BipolarNeutrosophic => Shape {
                channels: &[
                    T,
                    I,
                    F,
                    "negative_truth",
                    "negative_indeterminacy",
                    "negative_falsity",
                ],
                pairs: &[],
                sum: &[],
                negative_from: 3,
                derived: &[],
            },
        }
    }

    /// The channel names, in the order of every channel vector of this family.
    ///
    /// ```
    /// use neutrospline::Family;
    /// assert_eq!(Family::IntervalType2.channels(), ["truth_lower", "truth_upper"]);
    /// assert_eq!(Family::BipolarNeutrosophic.channels()[3], "negative_truth");
    /// ```
    pub fn channels(&self) -> &'static [&'static str] {
        self.shape().channels
    }

    /// The number of channels (1 to [`MAX_CHANNELS`]).
    pub fn channel_count(&self) -> usize {
        self.shape().channels.len()
    }

    /// The box of channel `c`: \[0, 1\], or \[-1, 0\] for the negative bipolar degrees.
    ///
    /// # Panics
    /// If `c >= self.channel_count()`.
    pub fn channel_range(&self, c: usize) -> (f64, f64) {
        let shape = self.shape();
        assert!(c < shape.channels.len(), "channel {c} of {self}");
        if c >= shape.negative_from {
            (-1.0, 0.0)
        } else {
            (0.0, 1.0)
        }
    }

    /// The `(lower, upper)` channel indices of the interval-valued degrees (empty for the
    /// single-valued families).
    pub fn interval_pairs(&self) -> &'static [(usize, usize)] {
        self.shape().pairs
    }

    /// The names of the degrees derived from the channels by [`Family::derived`]:
    /// `hesitation` (intuitionistic, orthopair and spherical families), `refusal` (picture),
    /// `hesitation_lower`, `hesitation_upper` (interval intuitionistic), `type_reduced`,
    /// `footprint` (interval type-2); empty for the others.
    pub fn derived_names(&self) -> &'static [&'static str] {
        self.shape().derived
    }

    /// Whether the rule is a set of linear inequalities (a polytope); otherwise it is round
    /// (a power sum with exponent >= 2, see [`Family::power_rule`]).
    pub fn is_linear(&self) -> bool {
        self.power().is_none_or(|p| p == 1)
    }

    /// The family's parameter with its key in model files: `("q", q)` for `q-rung`,
    /// `("n", n)` for `t-spherical`, `None` for the others.
    ///
    /// ```
    /// use neutrospline::Family;
    /// assert_eq!(Family::q_rung(4)?.parameter(), Some(("q", 4)));
    /// assert_eq!(Family::Spherical.parameter(), None);
    /// # Ok::<(), neutrospline::ParseFamilyError>(())
    /// ```
    pub const fn parameter(&self) -> Option<(&'static str, u32)> {
        match self {
            Family::QRung(q) => Some(("q", q.get())),
            Family::TSpherical(n) => Some(("n", n.get())),
            _ => None,
        }
    }

    /// The family named `name` (as in [`Family::name`]) with the parameter `value` of
    /// [`Family::parameter`]: `with_parameter("q-rung", 4)` is `q-rung:4`.
    ///
    /// # Errors
    /// `name` names no family, the family takes no parameter, or `value` is 0.
    pub fn with_parameter(name: &str, value: u32) -> Result<Family, ParseFamilyError> {
        format!("{}:{value}", name.trim()).parse()
    }

    /// Whether the family carries the degree `kind` as one of its channels.
    ///
    /// ```
    /// use neutrospline::{DegreeKind, Family};
    /// assert!(Family::Pythagorean.carries(DegreeKind::Falsity));
    /// assert!(!Family::Pythagorean.carries(DegreeKind::Indeterminacy));
    /// assert!(!Family::IntervalType2.carries(DegreeKind::Truth));
    /// ```
    pub fn carries(&self, kind: DegreeKind) -> bool {
        self.channels().contains(&kind.name())
    }

    /// Whether every channel is one of truth, indeterminacy and falsity, so that a value of
    /// the family is held by [`Degrees`] (all families but the interval-valued and bipolar
    /// ones). A degree the family does not carry is stored as 0, except the intuitionistic
    /// indeterminacy, which is the hesitation `1 - T - F` (linear, so it blends exactly).
    pub fn fits_degrees(&self) -> bool {
        self.channels()
            .iter()
            .all(|c| DegreeKind::ALL.iter().any(|k| k.name() == *c))
    }

    /// The channel values held by `degrees`, in the family's channel order (`[T, F]` for
    /// the orthopair families, `[T, I, F]` for picture and spherical ones), or `None` when the
    /// family does not [fit](Family::fits_degrees) in degrees. The values are not re-checked:
    /// see [`Degrees::check_membership`].
    ///
    /// ```
    /// use neutrospline::{Degrees, Family};
    /// let d = Degrees::intuitionistic(0.5, 0.25)?;
    /// let values = Family::Intuitionistic.from_degrees(&d).unwrap();
    /// assert_eq!(&*values, &[0.5, 0.25]);
    /// assert_eq!(Family::Intuitionistic.to_degrees(&values)?, d);
    /// # Ok::<(), neutrospline::DegreeError>(())
    /// ```
    pub fn from_degrees(&self, degrees: &Degrees) -> Option<FamilyValues> {
        if !self.fits_degrees() {
            return None;
        }
        let carried: Vec<f64> = DegreeKind::ALL
            .into_iter()
            .filter(|k| self.carries(*k))
            .map(|k| degrees.get(k))
            .collect();
        Some(FamilyValues::from_slice(&carried))
    }

    /// [`Degrees`] from the family's channel values, checked by
    /// [`Degrees::with_membership`]; the inverse of [`Family::from_degrees`].
    ///
    /// # Errors
    /// The rule broken; [`DegreeError::Missing`] when `values` is too short;
    /// [`DegreeError::TooManyChannels`] for a family that does not fit in degrees.
    pub fn to_degrees(&self, values: &[f64]) -> Result<Degrees, DegreeError> {
        if !self.fits_degrees() {
            return Err(DegreeError::TooManyChannels { membership: *self });
        }
        let mut given = [None; 3];
        let mut next = values.iter().copied();
        for kind in DegreeKind::ALL {
            if self.carries(kind) {
                given[kind.index()] = next.next();
            }
        }
        let truth = given[0].ok_or(DegreeError::Missing {
            kind: DegreeKind::Truth,
            membership: *self,
        })?;
        Degrees::with_membership(*self, truth, given[1], given[2])
    }
}

impl fmt::Display for Family {
    /// The name, with `:q` or `:n` for the parametrised families (`q-rung:4`).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Family::QRung(p) | Family::TSpherical(p) => write!(f, "{}:{p}", self.name()),
            _ => f.write_str(self.name()),
        }
    }
}

impl FromStr for Family {
    type Err = ParseFamilyError;

    /// Parses the forms of [`FAMILY_FORMS`] (case-insensitive, surrounding blanks ignored).
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let lower = s.trim().to_ascii_lowercase();
        let (name, parameter) = match lower.split_once(':') {
            Some((name, parameter)) => (name.trim(), Some(parameter.trim())),
            None => (lower.as_str(), None),
        };
        let fixed = match name {
            "neutrosophic" => Some(Family::Neutrosophic),
            "intuitionistic" => Some(Family::Intuitionistic),
            "fuzzy" => Some(Family::Fuzzy),
            "pythagorean" => Some(Family::Pythagorean),
            "fermatean" => Some(Family::Fermatean),
            "picture" => Some(Family::Picture),
            "spherical" => Some(Family::Spherical),
            "interval-neutrosophic" => Some(Family::IntervalNeutrosophic),
            "interval-intuitionistic" => Some(Family::IntervalIntuitionistic),
            "interval-type2" => Some(Family::IntervalType2),
            "bipolar-neutrosophic" => Some(Family::BipolarNeutrosophic),
            _ => None,
        };
        if let Some(family) = fixed {
            return match parameter {
                None => Ok(family),
                Some(_) => Err(ParseFamilyError::new(s, "this family takes no parameter")),
            };
        }
        let make: fn(NonZeroU32) -> Family = match name {
            "q-rung" => Family::QRung,
            "t-spherical" => Family::TSpherical,
            _ => return Err(ParseFamilyError::new(s, "no such family")),
        };
        let Some(parameter) = parameter else {
            return Err(ParseFamilyError::new(
                s,
                "the parameter is missing, as in q-rung:4 or t-spherical:3",
            ));
        };
        parameter
            .parse::<NonZeroU32>()
            .map(make)
            .map_err(|_| ParseFamilyError::new(s, "the parameter must be an integer >= 1"))
    }
}

/// The values of up to [`MAX_CHANNELS`] channels (or derived degrees), without allocation;
/// dereferences to a slice.
///
/// ```
/// let v = neutrospline::FamilyValues::from_slice(&[0.5, 0.25]);
/// assert_eq!(v.len(), 2);
/// assert_eq!(v[1], 0.25);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct FamilyValues {
    values: [f64; MAX_CHANNELS],
    len: usize,
}

impl FamilyValues {
    /// Copies `values`.
    ///
    /// # Panics
    /// If `values` has more than [`MAX_CHANNELS`] entries.
    pub fn from_slice(values: &[f64]) -> Self {
        assert!(values.len() <= MAX_CHANNELS, "{} values", values.len());
        let mut out = FamilyValues {
            values: [0.0; MAX_CHANNELS],
            len: values.len(),
        };
        out.values[..values.len()].copy_from_slice(values);
        out
    }
}

impl Deref for FamilyValues {
    type Target = [f64];
    fn deref(&self) -> &[f64] {
        &self.values[..self.len]
    }
}

impl core::ops::DerefMut for FamilyValues {
    fn deref_mut(&mut self) -> &mut [f64] {
        &mut self.values[..self.len]
    }
}

#[cfg(test)]
mod tests;
