//! The rule of a family in one line of text, built from the family's data (docs/model.md,
//! "Membership families"): every front end that states a rule reads it from here.

use super::rule::terms;
use super::Family;

impl Family {
    /// The family's rule in one line: `NAME: ` and then, separated by `; `, the box of every
    /// channel (channels with the same box grouped, `a, b each in [0, 1]`), the `lower <=
    /// upper` of every interval-valued degree, the sum rule `x_1^p + ... + x_k^p <= 1` (the
    /// terms of [`Family::rule_sum`]; `p = 1` written as a plain sum), and the names of the
    /// degrees derived from the channels (`derived: ...`, [`Family::derived_names`]). It is
    /// built from the family's data ([`Family::channels`], [`Family::channel_range`],
    /// [`Family::interval_pairs`], the sum rule's channels and exponent), so it states exactly
    /// the rule [`Family::check`] enforces. Per family (SPEC section 10; T, I, F are truth,
    /// indeterminacy, falsity, `_L`/`_U` the lower/upper bounds):
    ///
    /// | family | domain of the channels | rule |
    /// |---|---|---|
    /// | `neutrosophic` | T, I, F in \[0, 1\] | none beyond the box |
    /// | `intuitionistic` | T, F in \[0, 1\] | T + F <= 1 |
    /// | `fuzzy` | T in \[0, 1\] | none beyond the box |
    /// | `pythagorean` | T, F in \[0, 1\] | T^2 + F^2 <= 1 |
    /// | `fermatean` | T, F in \[0, 1\] | T^3 + F^3 <= 1 |
    /// | `q-rung:q` | T, F in \[0, 1\] | T^q + F^q <= 1 |
    /// | `picture` | T, I, F in \[0, 1\] | T + I + F <= 1 |
    /// | `spherical` | T, I, F in \[0, 1\] | T^2 + I^2 + F^2 <= 1 |
    /// | `t-spherical:n` | T, I, F in \[0, 1\] | T^n + I^n + F^n <= 1 |
    /// | `interval-neutrosophic` | T_L, T_U, I_L, I_U, F_L, F_U in \[0, 1\] | T_L <= T_U, I_L <= I_U, F_L <= F_U |
    /// | `interval-intuitionistic` | T_L, T_U, F_L, F_U in \[0, 1\] | T_L <= T_U, F_L <= F_U, T_U + F_U <= 1 |
    /// | `interval-type2` | M_L, M_U in \[0, 1\] | M_L <= M_U |
    /// | `bipolar-neutrosophic` | T+, I+, F+ in \[0, 1\]; T-, I-, F- in \[-1, 0\] | none beyond the boxes |
    ///
    /// ```
    /// use neutrospline::Family;
    /// assert_eq!(
    ///     Family::Pythagorean.rule_text(),
    ///     "pythagorean: truth, falsity each in [0, 1]; truth^2 + falsity^2 <= 1; \
    ///      derived: hesitation"
    /// );
    /// assert_eq!(
    ///     Family::IntervalType2.rule_text(),
    ///     "interval-type2: truth_lower, truth_upper each in [0, 1]; \
    ///      truth_lower <= truth_upper; derived: type_reduced, footprint"
    /// );
    /// assert_eq!(Family::Fuzzy.rule_text(), "fuzzy: truth in [0, 1]");
    /// ```
    pub fn rule_text(&self) -> String {
        let shape = self.shape();
        let channels = shape.channels;
        // The boxes in the order of their first channel, each with its channels.
        let mut boxes: Vec<((f64, f64), Vec<&str>)> = Vec::new();
        for (c, &name) in channels.iter().enumerate() {
            let range = self.channel_range(c);
            match boxes.iter_mut().find(|(r, _)| *r == range) {
                Some((_, names)) => names.push(name),
                None => boxes.push((range, vec![name])),
            }
        }
        let mut parts: Vec<String> = boxes
            .iter()
            .map(|((low, high), names)| {
                let each = if names.len() > 1 { " each" } else { "" };
                format!("{}{each} in [{low}, {high}]", names.join(", "))
            })
            .collect();
        if !shape.pairs.is_empty() {
            let pairs: Vec<String> = shape
                .pairs
                .iter()
                .map(|&(lower, upper)| format!("{} <= {}", channels[lower], channels[upper]))
                .collect();
            parts.push(pairs.join(", "));
        }
        if let Some(power) = self.power() {
            let summed: Vec<&str> = shape.sum.iter().map(|&c| channels[c]).collect();
            parts.push(format!("{} <= 1", terms(&summed, power)));
        }
        if !shape.derived.is_empty() {
            parts.push(format!("derived: {}", shape.derived.join(", ")));
        }
        format!("{self}: {}", parts.join("; "))
    }
}
