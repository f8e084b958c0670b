//! The validity rule of a family: the check with its typed error, and the rule as constraints
//! for fitting (linear inequalities plus, for the round families, one power-sum rule).

use super::{Family, FamilyValues, Shape};

/// The tolerance a caller may give [`Family::check_within`] for values computed by blending:
/// a blend of valid values is valid in exact arithmetic (the rules are convex), and rounding
/// can move a sum that is exactly 1 by a few units in the last place.
pub const RULE_TOLERANCE: f64 = 1e-12;

/// Why channel values break their family's rule. The message names the channels, the values
/// and the rule.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum RuleError {
    /// The number of values differs from the family's channel count.
    #[error("{given} values given; the {family} family has {expected} channels ({names})", names = family.channels().join(", "))]
    ChannelCount {
        /// The family.
        family: Family,
        /// Its channel count.
        expected: usize,
        /// The number of values given.
        given: usize,
    },
    /// A value is NaN or infinite.
    #[error("{channel} = {value} is not a finite number ({family} rule)")]
    NotFinite {
        /// The family.
        family: Family,
        /// The channel's name.
        channel: &'static str,
        /// The value.
        value: f64,
    },
    /// A value is outside its channel's box (\[0, 1\], or \[-1, 0\] for negative degrees).
    #[error("{channel} = {value} is outside [{low}, {high}] ({family} rule)")]
    OutOfRange {
        /// The family.
        family: Family,
        /// The channel's name.
        channel: &'static str,
        /// The value.
        value: f64,
        /// The lower end of the box.
        low: f64,
        /// The upper end of the box.
        high: f64,
    },
    /// The lower bound of an interval-valued degree exceeds its upper bound.
    #[error(
        "{lower} = {lower_value} exceeds {upper} = {upper_value} ({family} rule: lower <= upper)"
    )]
    Order {
        /// The family.
        family: Family,
        /// The lower channel's name.
        lower: &'static str,
        /// Its value.
        lower_value: f64,
        /// The upper channel's name.
        upper: &'static str,
        /// Its value.
        upper_value: f64,
    },
    /// The sum of powers of the rule exceeds 1 (`truth + falsity`, `truth^2 + falsity^2`, ...).
    #[error("{} = {} exceeds 1 ({family} rule)", terms(channels, *power), fifteen_digits(*sum))]
    SumExceeds {
        /// The family.
        family: Family,
        /// The channels summed.
        channels: Vec<&'static str>,
        /// The exponent (1 for a plain sum).
        power: u32,
        /// The sum of the powers.
        sum: f64,
    },
}

/// `value` rounded to 15 significant digits, in shortest form: a sum of rounded powers
/// (0.6^2 + 0.1^2 + 0.8^2 = 1.0100000000000002) printed as the decimals gave it (1.01). Any
/// sum that would print as 1 prints in full (1.0000000000000002).
fn fifteen_digits(value: f64) -> f64 {
    let rounded: f64 = format!("{value:.14e}").parse().unwrap_or(value);
    if rounded == 1.0 {
        value
    } else {
        rounded
    }
}

/// `channels` as the terms of a sum of powers: `truth + falsity` (`power = 1`), `truth^2 +
/// falsity^2`, ...
pub(super) fn terms(channels: &[&str], power: u32) -> String {
    let term = |c: &&str| {
        if power == 1 {
            (*c).to_owned()
        } else {
            format!("{c}^{power}")
        }
    };
    channels.iter().map(term).collect::<Vec<_>>().join(" + ")
}

/// `x^p` by repeated squaring: the same sequence of roundings wherever it runs, so the check
/// and the projection agree to the last bit.
pub(super) fn pow_int(x: f64, p: u32) -> f64 {
    let (mut base, mut e, mut acc) = (x, p, 1.0);
    while e > 0 {
        if e & 1 == 1 {
            acc *= base;
        }
        e >>= 1;
        if e > 0 {
            base *= base;
        }
    }
    acc
}

/// `sum_{c in channels} values[c]^p`, left to right.
pub(super) fn power_sum(values: &[f64], channels: &[usize], p: u32) -> f64 {
    channels.iter().map(|&c| pow_int(values[c], p)).sum()
}

/// One linear inequality of a rule: `sum_c coefficients[c] * x_c <= bound` over the channel
/// vector.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LinearConstraint {
    /// One coefficient per channel.
    pub coefficients: FamilyValues,
    /// The right-hand side.
    pub bound: f64,
}

impl LinearConstraint {
    /// `bound - coefficients . x`: non-negative when `x` satisfies the constraint.
    pub fn slack(&self, x: &[f64]) -> f64 {
        self.bound
            - self
                .coefficients
                .iter()
                .zip(x)
                .map(|(a, v)| a * v)
                .sum::<f64>()
    }
}

/// The round part of a rule: `sum_{c in channels} x_c^power <= 1` with `power >= 2` (the
/// channels are also `>= 0`, a linear constraint of [`Family::linear_constraints`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PowerRule {
    /// The exponent, at least 2.
    pub power: u32,
    /// The channel indices summed.
    pub channels: &'static [usize],
}

impl Shape {
    fn is_pair_lower(&self, c: usize) -> bool {
        self.pairs.iter().any(|&(l, _)| l == c)
    }

    fn is_pair_upper(&self, c: usize) -> bool {
        self.pairs.iter().any(|&(_, u)| u == c)
    }
}

impl Family {
    /// Checks channel values against the rule exactly (see [`Family::check_within`]).
    ///
    /// ```
    /// use neutrospline::Family;
    /// assert!(Family::Spherical.check(&[0.6, 0.0, 0.8]).is_ok()); // 0.36 + 0.64 = 1
    /// assert_eq!(
    ///     Family::IntervalType2.check(&[0.6, 0.4]).unwrap_err().to_string(),
    ///     "truth_lower = 0.6 exceeds truth_upper = 0.4 (interval-type2 rule: lower <= upper)"
    /// );
    /// ```
    ///
    /// # Errors
    /// The first rule broken, checked in the order: channel count, finiteness and box of each
    /// channel (in channel order), lower <= upper of each interval, the sum rule.
    pub fn check(&self, values: &[f64]) -> Result<(), RuleError> {
        self.check_within(values, 0.0)
    }

    /// Checks channel values against the rule, each inequality allowed to be broken by at
    /// most `tolerance` (for blended values use [`RULE_TOLERANCE`]).
    ///
    /// # Errors
    /// As [`Family::check`].
    pub fn check_within(&self, values: &[f64], tolerance: f64) -> Result<(), RuleError> {
        let family = *self;
        let shape = self.shape();
        if values.len() != shape.channels.len() {
            return Err(RuleError::ChannelCount {
                family,
                expected: shape.channels.len(),
                given: values.len(),
            });
        }
        for (c, (&channel, &value)) in shape.channels.iter().zip(values).enumerate() {
            if !value.is_finite() {
                return Err(RuleError::NotFinite {
                    family,
                    channel,
                    value,
                });
            }
            let (low, high) = self.channel_range(c);
            if value < low - tolerance || value > high + tolerance {
                return Err(RuleError::OutOfRange {
                    family,
                    channel,
                    value,
                    low,
                    high,
                });
            }
        }
        for &(l, u) in shape.pairs {
            if values[l] > values[u] + tolerance {
                return Err(RuleError::Order {
                    family,
                    lower: shape.channels[l],
                    lower_value: values[l],
                    upper: shape.channels[u],
                    upper_value: values[u],
                });
            }
        }
        if let Some(power) = self.power() {
            let sum = power_sum(values, shape.sum, power);
            if sum > 1.0 + tolerance {
                return Err(RuleError::SumExceeds {
                    family,
                    channels: shape.sum.iter().map(|&c| shape.channels[c]).collect(),
                    power,
                    sum,
                });
            }
        }
        Ok(())
    }

    /// The linear inequalities of the rule, without redundant ones: the box of each channel
    /// (an upper end implied by the sum rule or by lower <= upper is left out, and so is the
    /// lower end of an interval's upper bound), `lower - upper <= 0` for each interval, and
    /// the sum `sum x_c <= 1` of the intuitionistic, picture and interval-intuitionistic rules.
    /// For a linear family ([`Family::is_linear`]) they are the whole rule; a round family adds
    /// its [`Family::power_rule`].
    ///
    /// ```
    /// use neutrospline::Family;
    /// let rule = Family::Intuitionistic.linear_constraints();
    /// // -truth <= 0, -falsity <= 0, truth + falsity <= 1
    /// assert_eq!(rule.len(), 3);
    /// assert_eq!(&*rule[2].coefficients, &[1.0, 1.0]);
    /// assert_eq!(rule[2].slack(&[0.25, 0.5]), 0.25);
    /// ```
    pub fn linear_constraints(&self) -> Vec<LinearConstraint> {
        let shape = self.shape();
        let k = shape.channels.len();
        let unit = |c: usize, a: f64| {
            let mut coefficients = FamilyValues::from_slice(&[0.0; super::MAX_CHANNELS][..k]);
            coefficients[c] = a;
            coefficients
        };
        let mut out = Vec::new();
        for c in 0..k {
            let (low, high) = self.channel_range(c);
            if !shape.is_pair_upper(c) {
                out.push(LinearConstraint {
                    coefficients: unit(c, -1.0),
                    bound: -low,
                });
            }
            if !shape.sum.contains(&c) && !shape.is_pair_lower(c) {
                out.push(LinearConstraint {
                    coefficients: unit(c, 1.0),
                    bound: high,
                });
            }
        }
        for &(l, u) in shape.pairs {
            let mut coefficients = unit(l, 1.0);
            coefficients[u] = -1.0;
            out.push(LinearConstraint {
                coefficients,
                bound: 0.0,
            });
        }
        if self.power() == Some(1) {
            let mut coefficients = unit(0, 0.0);
            for &c in shape.sum {
                coefficients[c] = 1.0;
            }
            out.push(LinearConstraint {
                coefficients,
                bound: 1.0,
            });
        }
        out
    }

    /// The round part of the rule, `sum x_c^p <= 1` with `p >= 2` (Pythagorean, Fermatean,
    /// q-rung with q >= 2, spherical, T-spherical with n >= 2), or `None` for a linear family.
    pub fn power_rule(&self) -> Option<PowerRule> {
        match self.power() {
            Some(power) if power >= 2 => Some(PowerRule {
                power,
                channels: self.shape().sum,
            }),
            _ => None,
        }
    }

    /// The rule's sum `sum x_c^p` over its summed channels (`truth + falsity` under the
    /// intuitionistic rule, `truth^2 + falsity^2` under the Pythagorean one, ...), with its
    /// terms written out, or `None` for the families without a sum rule. The sum is computed
    /// as [`Family::check`] computes it.
    ///
    /// ```
    /// use neutrospline::Family;
    /// let (terms, sum) = Family::Pythagorean.rule_sum(&[0.6, 0.8]).unwrap();
    /// assert_eq!(terms, "truth^2 + falsity^2");
    /// assert!((sum - 1.0).abs() < 1e-15);
    /// assert!(Family::Neutrosophic.rule_sum(&[0.1, 0.2, 0.3]).is_none());
    /// ```
    ///
    /// # Panics
    /// If `values` has fewer entries than the family has channels.
    pub fn rule_sum(&self, values: &[f64]) -> Option<(String, f64)> {
        let shape = self.shape();
        let power = self.power()?;
        let names: Vec<&str> = shape.sum.iter().map(|&c| shape.channels[c]).collect();
        Some((terms(&names, power), power_sum(values, shape.sum, power)))
    }
}
