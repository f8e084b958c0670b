//! Neutrosophic degrees: truth, indeterminacy and falsity (docs/model.md section 1).

use core::fmt;
use core::str::FromStr;

pub(crate) use crate::family::Family;
use crate::family::{RuleError, RULE_TOLERANCE};

/// Tolerance used when a file gives the indeterminacy of an intuitionistic fuzzy value and the
/// library checks it against the derived hesitation `1 - truth - falsity`.
pub const HESITATION_TOLERANCE: f64 = 1e-9;

/// One of the three degrees of a neutrosophic value.
///
/// The order `Truth, Indeterminacy, Falsity` is the order used everywhere in the library:
/// in tables, in channel-major buffers and in [`Degrees::to_array`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "lowercase"))]
pub enum DegreeKind {
    /// The truth degree T.
    Truth,
    /// The indeterminacy degree I.
    Indeterminacy,
    /// The falsity degree F.
    Falsity,
}

impl DegreeKind {
    /// The three kinds in the library's order.
    pub const ALL: [DegreeKind; 3] = [
        DegreeKind::Truth,
        DegreeKind::Indeterminacy,
        DegreeKind::Falsity,
    ];

    /// The lowercase name: `"truth"`, `"indeterminacy"` or `"falsity"`.
    ///
    /// ```
    /// assert_eq!(neutrospline::DegreeKind::Falsity.name(), "falsity");
    /// ```
    pub const fn name(self) -> &'static str {
        match self {
            DegreeKind::Truth => "truth",
            DegreeKind::Indeterminacy => "indeterminacy",
            DegreeKind::Falsity => "falsity",
        }
    }

    /// Position of this kind in [`DegreeKind::ALL`] (0, 1 or 2).
    pub const fn index(self) -> usize {
        match self {
            DegreeKind::Truth => 0,
            DegreeKind::Indeterminacy => 1,
            DegreeKind::Falsity => 2,
        }
    }
}

impl fmt::Display for DegreeKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Error returned when a string names no [`DegreeKind`] or [`Family`].
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("unknown {what} `{given}` (expected one of: {expected})")]
pub struct ParseNameError {
    what: &'static str,
    given: String,
    expected: &'static str,
}

impl ParseNameError {
    /// The error for `given`, which is not a `what` (one of `expected`).
    pub(crate) fn new(what: &'static str, given: &str, expected: &'static str) -> Self {
        ParseNameError {
            what,
            given: given.to_owned(),
            expected,
        }
    }
}

impl FromStr for DegreeKind {
    type Err = ParseNameError;

    /// Parses `truth`, `indeterminacy` or `falsity` (case-insensitive; `t`, `i`, `f` also accepted).
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        match s.trim().to_ascii_lowercase().as_str() {
            "truth" | "t" => Ok(DegreeKind::Truth),
            "indeterminacy" | "i" => Ok(DegreeKind::Indeterminacy),
            "falsity" | "f" => Ok(DegreeKind::Falsity),
            _ => Err(ParseNameError {
                what: "degree",
                given: s.to_owned(),
                expected: "truth, indeterminacy, falsity",
            }),
        }
    }
}

/// Why a triple of degrees is invalid. The message names the degree, the value and the rule.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum DegreeError {
    /// A degree is NaN or infinite.
    #[error("{kind} = {value} is not a finite number (every degree must be a number in [0, 1])")]
    NotFinite {
        /// Which degree.
        kind: DegreeKind,
        /// The offending value.
        value: f64,
    },
    /// A degree is below 0 or above 1.
    #[error("{kind} = {value} is outside [0, 1] (every degree must be in [0, 1])")]
    OutOfRange {
        /// Which degree.
        kind: DegreeKind,
        /// The offending value.
        value: f64,
    },
    /// Intuitionistic rule: membership plus non-membership exceeds 1.
    #[error(
        "truth + falsity = {truth} + {falsity} = {sum} exceeds 1 (intuitionistic rule: truth + falsity <= 1)",
        sum = truth + falsity
    )]
    IntuitionisticSum {
        /// The truth (membership) degree.
        truth: f64,
        /// The falsity (non-membership) degree.
        falsity: f64,
    },
    /// Intuitionistic rule: a given indeterminacy differs from the hesitation 1 - T - F.
    #[error(
        "indeterminacy = {given} differs from the hesitation 1 - truth - falsity = {hesitation} (intuitionistic rule: indeterminacy is derived; omit it or give 1 - truth - falsity)"
    )]
    HesitationMismatch {
        /// The indeterminacy that was given.
        given: f64,
        /// The hesitation derived from truth and falsity.
        hesitation: f64,
    },
    /// A degree is required by the rule but missing.
    #[error("{kind} is missing ({membership} rule requires it)")]
    Missing {
        /// Which degree.
        kind: DegreeKind,
        /// The rule that requires it.
        membership: Family,
    },
    /// A degree the rule does not carry is given with a non-zero value (indeterminacy or
    /// falsity under the fuzzy rule, indeterminacy under the orthopair rules).
    #[error("{kind} = {value} is not allowed ({membership} rule: only {given} given; {kind} must be absent or 0)", given = carried(*membership))]
    NotCarried {
        /// Which degree.
        kind: DegreeKind,
        /// The offending value.
        value: f64,
        /// The rule.
        membership: Family,
    },
    /// The values break the family's rule (a sum of powers above 1, ...).
    #[error(transparent)]
    Rule(#[from] RuleError),
    /// The family's channels do not fit in truth, indeterminacy and falsity (interval-valued
    /// and bipolar families carry up to six).
    #[error("the {membership} family has {count} channels ({names}); a truth, indeterminacy, falsity triple cannot hold them", count = membership.channel_count(), names = membership.channels().join(", "))]
    TooManyChannels {
        /// The family.
        membership: Family,
    },
}

/// "truth is", "truth and falsity are", ...: the degrees `membership` carries.
fn carried(membership: Family) -> String {
    let names: Vec<&str> = DegreeKind::ALL
        .into_iter()
        .filter(|k| membership.carries(*k))
        .map(DegreeKind::name)
        .collect();
    match names.as_slice() {
        [one] => format!("{one} is"),
        [init @ .., last] => format!("{} and {last} are", init.join(", ")),
        [] => "nothing is".to_owned(),
    }
}

/// A neutrosophic value: the triple (truth, indeterminacy, falsity), each in \[0, 1\].
///
/// The three degrees are independent, so `0 <= T + I + F <= 3`. Fields are private: every
/// `Degrees` is valid, because every constructor except [`Degrees::new_unchecked`] checks.
///
/// # Examples
/// ```
/// use neutrospline::Degrees;
/// let d = Degrees::new(0.3, 0.6, 0.1)?;
/// assert_eq!(d.to_array(), [0.3, 0.6, 0.1]);
/// assert!(Degrees::new(1.2, 0.0, 0.0).is_err());
/// # Ok::<(), neutrospline::DegreeError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(try_from = "RawDegrees", into = "RawDegrees"))]
pub struct Degrees {
    truth: f64,
    indeterminacy: f64,
    falsity: f64,
}

/// The unchecked serde form of [`Degrees`].
#[cfg(feature = "serde")]
#[derive(serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct RawDegrees {
    truth: f64,
    indeterminacy: f64,
    falsity: f64,
}

#[cfg(feature = "serde")]
impl TryFrom<RawDegrees> for Degrees {
    type Error = DegreeError;
    fn try_from(raw: RawDegrees) -> Result<Self, DegreeError> {
        Degrees::new(raw.truth, raw.indeterminacy, raw.falsity)
    }
}

#[cfg(feature = "serde")]
impl From<Degrees> for RawDegrees {
    fn from(d: Degrees) -> Self {
        RawDegrees {
            truth: d.truth,
            indeterminacy: d.indeterminacy,
            falsity: d.falsity,
        }
    }
}

fn check_unit(kind: DegreeKind, value: f64) -> Result<f64, DegreeError> {
    if !value.is_finite() {
        Err(DegreeError::NotFinite { kind, value })
    } else if !(0.0..=1.0).contains(&value) {
        Err(DegreeError::OutOfRange { kind, value })
    } else {
        // Normalise -0.0 to 0.0 so that equal degrees print and compare identically.
        Ok(value + 0.0)
    }
}

impl Degrees {
    /// Neutrosophic degrees: each of `truth`, `indeterminacy`, `falsity` finite and in \[0, 1\].
    ///
    /// # Errors
    /// [`DegreeError::NotFinite`] or [`DegreeError::OutOfRange`] for the first offending degree,
    /// checked in the order truth, indeterminacy, falsity.
    pub fn new(truth: f64, indeterminacy: f64, falsity: f64) -> Result<Self, DegreeError> {
        Ok(Degrees {
            truth: check_unit(DegreeKind::Truth, truth)?,
            indeterminacy: check_unit(DegreeKind::Indeterminacy, indeterminacy)?,
            falsity: check_unit(DegreeKind::Falsity, falsity)?,
        })
    }

    /// Builds degrees without any check.
    ///
    /// The caller promises each value is finite and in \[0, 1\]; the library's algorithms rely
    /// on it (for example, a curve's degrees are convex combinations of its control degrees).
    pub const fn new_unchecked(truth: f64, indeterminacy: f64, falsity: f64) -> Self {
        Degrees {
            truth,
            indeterminacy,
            falsity,
        }
    }

    /// Intuitionistic fuzzy degrees: membership `truth` and non-membership `falsity` with
    /// `truth + falsity <= 1`; the indeterminacy is the hesitation `1 - truth - falsity`.
    ///
    /// ```
    /// let d = neutrospline::Degrees::intuitionistic(0.5, 0.25)?;
    /// assert_eq!(d.indeterminacy(), 0.25);
    /// # Ok::<(), neutrospline::DegreeError>(())
    /// ```
    ///
    /// # Errors
    /// A degree outside \[0, 1\] or not finite, or [`DegreeError::IntuitionisticSum`].
    pub fn intuitionistic(truth: f64, falsity: f64) -> Result<Self, DegreeError> {
        let truth = check_unit(DegreeKind::Truth, truth)?;
        let falsity = check_unit(DegreeKind::Falsity, falsity)?;
        if truth + falsity > 1.0 {
            return Err(DegreeError::IntuitionisticSum { truth, falsity });
        }
        // 1 - T - F is in [0, 1] because T + F <= 1 and both are >= 0; max() only removes -0.0.
        let hesitation = (1.0 - truth - falsity).max(0.0);
        Ok(Degrees {
            truth,
            indeterminacy: hesitation,
            falsity,
        })
    }

    /// Fuzzy degrees: a single membership degree `truth` in \[0, 1\]; indeterminacy and falsity
    /// are 0.
    ///
    /// # Errors
    /// `truth` outside \[0, 1\] or not finite.
    pub fn fuzzy(truth: f64) -> Result<Self, DegreeError> {
        Ok(Degrees {
            truth: check_unit(DegreeKind::Truth, truth)?,
            indeterminacy: 0.0,
            falsity: 0.0,
        })
    }

    /// Builds degrees under the given rule from the values a file or user supplied. The
    /// degrees the family carries ([`Family::carries`]) are required; the others must be
    /// absent or 0 and are stored as 0, except under the intuitionistic rule, whose stored
    /// indeterminacy is the hesitation `1 - truth - falsity` (when given, it must equal it
    /// within [`HESITATION_TOLERANCE`]). Then the family's rule is checked ([`Family::check`];
    /// a round rule's sum of powers may exceed 1 by [`RULE_TOLERANCE`], the rounding of
    /// decimals on its boundary).
    ///
    /// ```
    /// use neutrospline::{Degrees, Family};
    /// let d = Degrees::with_membership(Family::Fuzzy, 0.7, None, None)?;
    /// assert_eq!(d.to_array(), [0.7, 0.0, 0.0]);
    /// let p = Degrees::with_membership(Family::Pythagorean, 0.8, None, Some(0.6))?;
    /// assert_eq!(p.to_array(), [0.8, 0.0, 0.6]);
    /// let e = Degrees::with_membership(Family::Pythagorean, 0.9, None, Some(0.7)).unwrap_err();
    /// assert_eq!(e.to_string(), "truth^2 + falsity^2 = 1.3 exceeds 1 (pythagorean rule)");
    /// # Ok::<(), neutrospline::DegreeError>(())
    /// ```
    ///
    /// # Errors
    /// The first rule broken, as a [`DegreeError`]: a missing or out-of-range degree (checked
    /// in the order truth, indeterminacy, falsity), a degree the family does not carry, the
    /// family's rule, or a family whose channels are not truth, indeterminacy and falsity.
    pub fn with_membership(
        membership: Family,
        truth: f64,
        indeterminacy: Option<f64>,
        falsity: Option<f64>,
    ) -> Result<Self, DegreeError> {
        if !membership.fits_degrees() {
            return Err(DegreeError::TooManyChannels { membership });
        }
        if membership == Family::Intuitionistic {
            let falsity = falsity.ok_or(DegreeError::Missing {
                kind: DegreeKind::Falsity,
                membership,
            })?;
            let d = Degrees::intuitionistic(truth, falsity)?;
            if let Some(given) = indeterminacy {
                let given = check_unit(DegreeKind::Indeterminacy, given)?;
                if (given - d.indeterminacy).abs() > HESITATION_TOLERANCE {
                    return Err(DegreeError::HesitationMismatch {
                        given,
                        hesitation: d.indeterminacy,
                    });
                }
            }
            return Ok(d);
        }
        let mut triple = [0.0; 3];
        for (kind, value) in DegreeKind::ALL
            .into_iter()
            .zip([Some(truth), indeterminacy, falsity])
        {
            if membership.carries(kind) {
                let value = value.ok_or(DegreeError::Missing { kind, membership })?;
                triple[kind.index()] = check_unit(kind, value)?;
            } else if let Some(value) = value.filter(|v| *v != 0.0) {
                return Err(DegreeError::NotCarried {
                    kind,
                    value,
                    membership,
                });
            }
        }
        let degrees = Degrees::new_unchecked(triple[0], triple[1], triple[2]);
        if let Some(values) = membership.from_degrees(&degrees) {
            // A round rule's sum of powers is rarely exact in binary: decimals on the boundary
            // (0.28^2 + 0.96^2 = 1) may sum to 1 + 2e-16. Such rounding is accepted.
            let tolerance = if membership.power_rule().is_some() {
                RULE_TOLERANCE
            } else {
                0.0
            };
            membership.check_within(&values, tolerance)?;
        }
        Ok(degrees)
    }

    /// Checks that these degrees also obey `membership` (every `Degrees` obeys the
    /// neutrosophic rule; the intuitionistic rule adds T + F <= 1 and I = 1 - T - F).
    ///
    /// # Errors
    /// The rule broken, as in [`Degrees::with_membership`].
    pub fn check_membership(&self, membership: Family) -> Result<(), DegreeError> {
        Degrees::with_membership(
            membership,
            self.truth,
            Some(self.indeterminacy),
            Some(self.falsity),
        )
        .map(|_| ())
    }

    /// The truth degree T.
    pub const fn truth(&self) -> f64 {
        self.truth
    }

    /// The indeterminacy degree I.
    pub const fn indeterminacy(&self) -> f64 {
        self.indeterminacy
    }

    /// The falsity degree F.
    pub const fn falsity(&self) -> f64 {
        self.falsity
    }

    /// The degree of the given kind.
    pub const fn get(&self, kind: DegreeKind) -> f64 {
        match kind {
            DegreeKind::Truth => self.truth,
            DegreeKind::Indeterminacy => self.indeterminacy,
            DegreeKind::Falsity => self.falsity,
        }
    }

    /// The score `s = (2 + T - I - F) / 3`, in `[0, 1]`: 1 fully true, 0 fully false
    /// (docs/model.md section 7). Affine in the degrees, so the score of a curve at `t` is the
    /// blend of its control points' scores.
    ///
    /// ```
    /// use neutrospline::Degrees;
    /// let d = Degrees::new(0.7, 0.1, 0.2)?;
    /// assert!((d.score() - 0.8).abs() < 1e-15);
    /// assert!((d.accuracy() - 0.5).abs() < 1e-15);
    /// assert_eq!(d.certainty(), 0.7);
    /// # Ok::<(), neutrospline::DegreeError>(())
    /// ```
    pub fn score(&self) -> f64 {
        (2.0 + self.truth - self.indeterminacy - self.falsity) / 3.0
    }

    /// The accuracy `a = T - F`, in `[-1, 1]` (docs/model.md section 7).
    pub fn accuracy(&self) -> f64 {
        self.truth - self.falsity
    }

    /// The certainty `c = T`, in `[0, 1]` (docs/model.md section 7).
    pub const fn certainty(&self) -> f64 {
        self.truth
    }

    /// The ranking of docs/model.md section 7: by score, then accuracy, then certainty (a
    /// total order: the degrees are finite).
    ///
    /// ```
    /// use std::cmp::Ordering;
    /// use neutrospline::Degrees;
    /// let a = Degrees::new(0.5, 0.25, 0.25)?; // score 2/3, accuracy 0.25
    /// let b = Degrees::new(0.25, 0.0, 0.25)?; // score 2/3, accuracy 0
    /// let c = Degrees::new(0.75, 0.5, 0.0)?; // score 0.75
    /// assert_eq!(a.score(), b.score());
    /// assert_eq!(a.rank_cmp(&b), Ordering::Greater);
    /// assert_eq!(c.rank_cmp(&a), Ordering::Greater);
    /// # Ok::<(), neutrospline::DegreeError>(())
    /// ```
    pub fn rank_cmp(&self, other: &Degrees) -> core::cmp::Ordering {
        self.score()
            .total_cmp(&other.score())
            .then(self.accuracy().total_cmp(&other.accuracy()))
            .then(self.certainty().total_cmp(&other.certainty()))
    }

    /// `[truth, indeterminacy, falsity]`.
    pub const fn to_array(&self) -> [f64; 3] {
        [self.truth, self.indeterminacy, self.falsity]
    }

    /// Builds degrees from `[truth, indeterminacy, falsity]`, with the checks of [`Degrees::new`].
    ///
    /// # Errors
    /// As [`Degrees::new`].
    pub fn from_array(values: [f64; 3]) -> Result<Self, DegreeError> {
        Degrees::new(values[0], values[1], values[2])
    }

    /// Degree-wise minimum: the largest value below both (used by the Def. 4 relation).
    pub fn min(self, other: Degrees) -> Degrees {
        Degrees {
            truth: self.truth.min(other.truth),
            indeterminacy: self.indeterminacy.min(other.indeterminacy),
            falsity: self.falsity.min(other.falsity),
        }
    }
}

impl fmt::Display for Degrees {
    /// `(T, I, F)` with the shortest round-trip representation of each degree.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "(truth {}, indeterminacy {}, falsity {})",
            self.truth, self.indeterminacy, self.falsity
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scores_have_their_closed_forms_and_ranges() {
        // (T, I, F) -> (score, accuracy, certainty), by hand.
        let cases = [
            ([1.0, 0.0, 0.0], [1.0, 1.0, 1.0]),
            ([0.0, 1.0, 1.0], [0.0, -1.0, 0.0]),
            ([0.5, 0.5, 0.5], [0.5, 0.0, 0.5]),
            ([0.25, 0.5, 0.75], [1.0 / 3.0, -0.5, 0.25]),
        ];
        for (degrees, [score, accuracy, certainty]) in cases {
            let d = Degrees::from_array(degrees).unwrap();
            assert!((d.score() - score).abs() < 1e-15, "{d}");
            assert_eq!(d.accuracy(), accuracy);
            assert_eq!(d.certainty(), certainty);
        }
        // Intuitionistic: the score is (1 + 2T) / 3 and does not see F.
        let i = Degrees::intuitionistic(0.4, 0.5).unwrap();
        assert!((i.score() - (1.0 + 0.8) / 3.0).abs() < 1e-15);
        // The order: score first, then accuracy, then certainty.
        let low = Degrees::new(0.2, 0.5, 0.5).unwrap();
        let high = Degrees::new(0.9, 0.0, 0.1).unwrap();
        assert_eq!(low.rank_cmp(&high), core::cmp::Ordering::Less);
        assert_eq!(high.rank_cmp(&high), core::cmp::Ordering::Equal);
    }

    #[test]
    fn degrees_new_accepts_bounds() {
        let d = Degrees::new(0.0, 1.0, 0.5).unwrap();
        assert_eq!(d.to_array(), [0.0, 1.0, 0.5]);
        assert_eq!(Degrees::new(-0.0, 0.0, 0.0).unwrap().truth().to_bits(), 0);
    }

    #[test]
    fn degrees_new_rejects_out_of_range_with_message() {
        let e = Degrees::new(0.2, 1.5, 0.0).unwrap_err();
        assert_eq!(
            e.to_string(),
            "indeterminacy = 1.5 is outside [0, 1] (every degree must be in [0, 1])"
        );
        let e = Degrees::new(0.2, 0.5, -0.1).unwrap_err();
        assert_eq!(
            e,
            DegreeError::OutOfRange {
                kind: DegreeKind::Falsity,
                value: -0.1
            }
        );
    }

    #[test]
    fn degrees_new_rejects_nan_and_infinity() {
        for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            let e = Degrees::new(bad, 0.0, 0.0).unwrap_err();
            assert!(matches!(
                e,
                DegreeError::NotFinite {
                    kind: DegreeKind::Truth,
                    ..
                }
            ));
        }
        assert_eq!(
            Degrees::new(f64::NAN, 0.0, 0.0).unwrap_err().to_string(),
            "truth = NaN is not a finite number (every degree must be a number in [0, 1])"
        );
    }

    #[test]
    fn degrees_intuitionistic_derives_hesitation() {
        let d = Degrees::intuitionistic(0.5, 0.25).unwrap();
        assert_eq!(d.to_array(), [0.5, 0.25, 0.25]);
        let e = Degrees::intuitionistic(0.7, 0.6).unwrap_err();
        assert_eq!(
            e.to_string(),
            "truth + falsity = 0.7 + 0.6 = 1.2999999999999998 exceeds 1 (intuitionistic rule: truth + falsity <= 1)"
        );
        // Boundary: exactly 1 is allowed, hesitation 0.
        assert_eq!(
            Degrees::intuitionistic(0.75, 0.25).unwrap().indeterminacy(),
            0.0
        );
    }

    #[test]
    fn degrees_with_membership_rules() {
        use Family::*;
        assert!(Degrees::with_membership(Neutrosophic, 0.1, Some(0.2), Some(0.3)).is_ok());
        assert_eq!(
            Degrees::with_membership(Neutrosophic, 0.1, None, Some(0.3)).unwrap_err(),
            DegreeError::Missing {
                kind: DegreeKind::Indeterminacy,
                membership: Neutrosophic
            }
        );
        assert!(Degrees::with_membership(Intuitionistic, 0.5, Some(0.3), Some(0.2)).is_ok());
        let e = Degrees::with_membership(Intuitionistic, 0.5, Some(0.4), Some(0.2)).unwrap_err();
        assert!(matches!(e, DegreeError::HesitationMismatch { given, .. } if given == 0.4));
        assert_eq!(
            Degrees::with_membership(Fuzzy, 0.4, Some(0.0), None)
                .unwrap()
                .to_array(),
            [0.4, 0.0, 0.0]
        );
        assert_eq!(
            Degrees::with_membership(Fuzzy, 0.4, None, Some(0.3))
                .unwrap_err()
                .to_string(),
            "falsity = 0.3 is not allowed (fuzzy rule: only truth is given; falsity must be absent or 0)"
        );
    }

    #[test]
    fn degrees_check_membership() {
        let d = Degrees::new(0.5, 0.3, 0.2).unwrap();
        assert!(d.check_membership(Family::Intuitionistic).is_ok());
        let d = Degrees::new(0.5, 0.5, 0.2).unwrap();
        assert!(d.check_membership(Family::Intuitionistic).is_err());
        assert!(d.check_membership(Family::Fuzzy).is_err());
    }

    #[test]
    fn membership_and_kind_parse() {
        assert_eq!("Fuzzy".parse::<Family>().unwrap(), Family::Fuzzy);
        assert_eq!(
            "crisp".parse::<Family>().unwrap_err().to_string(),
            "unknown membership family `crisp` (no such family; expected one of: neutrosophic, \
             intuitionistic, fuzzy, pythagorean, fermatean, q-rung:Q, picture, spherical, \
             t-spherical:N, interval-neutrosophic, interval-intuitionistic, interval-type2, \
             bipolar-neutrosophic (Q and N integers >= 1))"
        );
        assert_eq!(
            "I".parse::<DegreeKind>().unwrap(),
            DegreeKind::Indeterminacy
        );
        for k in DegreeKind::ALL {
            assert_eq!(k.name().parse::<DegreeKind>().unwrap(), k);
            assert_eq!(DegreeKind::ALL[k.index()], k);
        }
    }
}
