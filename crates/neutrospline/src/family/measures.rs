//! The degrees derived from a family's channels and the score and accuracy functions of its
//! literature (SPEC section 10; docs/model.md, "Membership families").

use super::rule::{pow_int, power_sum};
use super::{Family, FamilyValues};

impl Family {
    fn expect_len(&self, values: &[f64]) {
        assert_eq!(
            values.len(),
            self.channel_count(),
            "channel values of the {self} family"
        );
    }

    /// The derived degrees, named by [`Family::derived_names`], computed from the channels
    /// (blend the channels, then derive: the round ones are not linear and must not be
    /// blended themselves):
    ///
    /// | family | derived |
    /// |---|---|
    /// | intuitionistic | hesitation `1 - T - F` |
    /// | pythagorean, fermatean, q-rung | hesitation `(1 - T^q - F^q)^(1/q)` |
    /// | picture | refusal `1 - T - I - F` |
    /// | spherical, t-spherical | hesitation `(1 - T^n - I^n - F^n)^(1/n)` |
    /// | interval-intuitionistic | hesitation_lower `1 - T_U - F_U`, hesitation_upper `1 - T_L - F_L` |
    /// | interval-type2 | type_reduced `(M_L + M_U) / 2`, footprint `M_U - M_L` |
    ///
    /// A residual `1 - sum` below 0 (values outside the rule by rounding) counts as 0, so a
    /// derived degree is always in \[0, 1\] for values within [`super::RULE_TOLERANCE`].
    ///
    /// ```
    /// use neutrospline::Family;
    /// let h = Family::Pythagorean.derived(&[0.6, 0.0]);
    /// assert!((h[0] - 0.8).abs() < 1e-15); // sqrt(1 - 0.36)
    /// let t2 = Family::IntervalType2.derived(&[0.25, 0.75]);
    /// assert_eq!(&*t2, &[0.5, 0.5]);
    /// ```
    ///
    /// # Panics
    /// If `values.len()` differs from [`Family::channel_count`].
    pub fn derived(&self, values: &[f64]) -> FamilyValues {
        self.expect_len(values);
        let rest = |sum: f64| (1.0 - sum).max(0.0);
        match self {
            Family::IntervalIntuitionistic => FamilyValues::from_slice(&[
                rest(values[1] + values[3]),
                rest(values[0] + values[2]),
            ]),
            Family::IntervalType2 => {
                FamilyValues::from_slice(&[0.5 * (values[0] + values[1]), values[1] - values[0]])
            }
            _ => match self.power() {
                Some(1) => FamilyValues::from_slice(&[rest(values.iter().sum())]),
                Some(p) => {
                    let left = rest(power_sum(values, self.shape().sum, p));
                    let root = match p {
                        2 => left.sqrt(),
                        3 => left.cbrt(),
                        _ => left.powf(1.0 / f64::from(p)),
                    };
                    FamilyValues::from_slice(&[root])
                }
                None => FamilyValues::default(),
            },
        }
    }

    /// The score that ranks values of this family (SPEC section 10), in \[-1, 1\] for the
    /// orthopair, picture, spherical and interval-intuitionistic families and in \[0, 1\] for
    /// the others:
    ///
    /// | family | score |
    /// |---|---|
    /// | neutrosophic | `(2 + T - I - F) / 3` (Smarandache; docs/model.md section 7) |
    /// | intuitionistic, picture | `T - F` (Chen and Tan; Cuong) |
    /// | fuzzy | `T` |
    /// | pythagorean, fermatean, q-rung | `T^q - F^q` (Yager; Senapati and Yager; Liu and Wang) |
    /// | spherical, t-spherical | `T^n - F^n` (Kutlu Gundogdu and Kahraman; Mahmood et al.) |
    /// | interval-neutrosophic | `(4 + T_L + T_U - I_L - I_U - F_L - F_U) / 6` |
    /// | interval-intuitionistic | `(T_L - F_L + T_U - F_U) / 2` (Xu) |
    /// | interval-type2 | `(M_L + M_U) / 2`, the type-reduced membership |
    /// | bipolar-neutrosophic | `(3 + T+ - I+ - F+ + T- - I- - F-) / 6` (Deli, Ali and Smarandache) |
    ///
    /// ```
    /// use neutrospline::Family;
    /// assert_eq!(Family::Fermatean.score(&[0.5, 0.5]), 0.0);
    /// assert_eq!(Family::BipolarNeutrosophic.score(&[1.0, 0.0, 0.0, 0.0, -1.0, -1.0]), 1.0);
    /// ```
    ///
    /// # Panics
    /// If `values.len()` differs from [`Family::channel_count`].
    pub fn score(&self, values: &[f64]) -> f64 {
        self.expect_len(values);
        let v = values;
        match self {
            Family::Neutrosophic => (2.0 + v[0] - v[1] - v[2]) / 3.0,
            Family::Fuzzy => v[0],
            Family::IntervalNeutrosophic => (4.0 + v[0] + v[1] - v[2] - v[3] - v[4] - v[5]) / 6.0,
            Family::IntervalIntuitionistic => (v[0] - v[2] + v[1] - v[3]) / 2.0,
            Family::IntervalType2 => 0.5 * (v[0] + v[1]),
            Family::BipolarNeutrosophic => (3.0 + v[0] - v[1] - v[2] + v[3] - v[4] - v[5]) / 6.0,
            _ => {
                // The orthopair and spherical families: T^p - F^p, falsity the last channel.
                let p = self.power().unwrap_or(1);
                pow_int(v[0], p) - pow_int(v[v.len() - 1], p)
            }
        }
    }

    /// The accuracy that breaks ties of the score (SPEC section 10), or `None` for the
    /// families whose literature ranks by the score alone (fuzzy, interval-neutrosophic,
    /// interval-type2, bipolar-neutrosophic):
    ///
    /// | family | accuracy |
    /// |---|---|
    /// | neutrosophic | `T - F` (docs/model.md section 7) |
    /// | intuitionistic, picture | `T + F`, `T + I + F` |
    /// | pythagorean, fermatean, q-rung | `T^q + F^q` |
    /// | spherical, t-spherical | `T^n + I^n + F^n` |
    /// | interval-intuitionistic | `(T_L + T_U + F_L + F_U) / 2` (Xu) |
    ///
    /// ```
    /// use neutrospline::Family;
    /// assert_eq!(Family::Spherical.accuracy(&[0.5, 0.5, 0.5]), Some(0.75));
    /// assert_eq!(Family::IntervalType2.accuracy(&[0.2, 0.4]), None);
    /// ```
    ///
    /// # Panics
    /// If `values.len()` differs from [`Family::channel_count`].
    pub fn accuracy(&self, values: &[f64]) -> Option<f64> {
        self.expect_len(values);
        let v = values;
        match self {
            Family::Neutrosophic => Some(v[0] - v[2]),
            Family::IntervalIntuitionistic => Some((v[0] + v[1] + v[2] + v[3]) / 2.0),
            Family::Fuzzy
            | Family::IntervalNeutrosophic
            | Family::IntervalType2
            | Family::BipolarNeutrosophic => None,
            _ => {
                let p = self.power().unwrap_or(1);
                Some(power_sum(v, self.shape().sum, p))
            }
        }
    }
}
