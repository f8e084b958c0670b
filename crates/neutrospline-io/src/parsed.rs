//! What a file holds once parsed and before the core builds its shape: the neutral form shared
//! by every format ([`Parsed`]), with the origin (line, field) of everything, so that an error
//! found later (a knot, a weight) can still be located. Also the control-point fields.

use neutrospline::{DegreeError, Degrees, Family, Side, Spread};

use crate::settings::{resolve, Kind, Structure};
pub(crate) use crate::text::{line_of, not_finite_message, parse_number, strip_bom, Origin};
use crate::InputError;

/// The fields of a control point: CSV columns and model keys.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Field {
    X,
    Y,
    Z,
    Truth,
    Indeterminacy,
    Falsity,
    Weight,
    Name,
}

impl Field {
    /// Every field, in the order they are listed in messages.
    pub(crate) const ALL: [Field; 8] = [
        Field::X,
        Field::Y,
        Field::Z,
        Field::Truth,
        Field::Indeterminacy,
        Field::Falsity,
        Field::Weight,
        Field::Name,
    ];

    /// The canonical name.
    pub(crate) const fn name(self) -> &'static str {
        match self {
            Field::X => "x",
            Field::Y => "y",
            Field::Z => "z",
            Field::Truth => "truth",
            Field::Indeterminacy => "indeterminacy",
            Field::Falsity => "falsity",
            Field::Weight => "weight",
            Field::Name => "name",
        }
    }

    /// The one-letter alias of a degree.
    pub(crate) const fn alias(self) -> Option<&'static str> {
        match self {
            Field::Truth => Some("T"),
            Field::Indeterminacy => Some("I"),
            Field::Falsity => Some("F"),
            _ => None,
        }
    }

    /// Index in [`Field::ALL`].
    pub(crate) fn index(self) -> usize {
        Field::ALL.iter().position(|&f| f == self).unwrap_or(0)
    }

    /// The field called `text` (its name or alias), exactly or ignoring ASCII case.
    pub(crate) fn from_name(text: &str, ignore_case: bool) -> Option<Field> {
        let same = |a: &str| {
            if ignore_case {
                a.eq_ignore_ascii_case(text)
            } else {
                a == text
            }
        };
        Field::ALL
            .into_iter()
            .find(|f| same(f.name()) || f.alias().is_some_and(same))
    }

    /// `x, y, z, truth (T), indeterminacy (I), falsity (F), weight, name`.
    pub(crate) fn known_list() -> String {
        Field::ALL
            .iter()
            .map(|f| match f.alias() {
                Some(a) => format!("{} ({a})", f.name()),
                None => f.name().to_owned(),
            })
            .collect::<Vec<_>>()
            .join(", ")
    }
}

/// How a spread key gives the spread of its axis: both sides, or one.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum SpreadForm {
    /// `spread_x`: the same spread left and right.
    Symmetric,
    /// `spread_x_left` or `spread_x_right`.
    Side(Side),
}

/// A spread key (CSV column, model key): the axis (0, 1, 2) and the form.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct SpreadKey {
    pub(crate) axis: usize,
    pub(crate) form: SpreadForm,
}

/// The spread keys, axis by axis: `spread_x`, `spread_x_left`, `spread_x_right`, `spread_y`, ...
pub(crate) const SPREAD_KEYS: [&str; 9] = [
    "spread_x",
    "spread_x_left",
    "spread_x_right",
    "spread_y",
    "spread_y_left",
    "spread_y_right",
    "spread_z",
    "spread_z_left",
    "spread_z_right",
];

impl SpreadKey {
    /// The key called `text`, exactly or ignoring ASCII case.
    pub(crate) fn from_name(text: &str, ignore_case: bool) -> Option<SpreadKey> {
        let i = SPREAD_KEYS.iter().position(|k| {
            if ignore_case {
                k.eq_ignore_ascii_case(text)
            } else {
                *k == text
            }
        })?;
        let form = match i % 3 {
            0 => SpreadForm::Symmetric,
            1 => SpreadForm::Side(Side::Left),
            _ => SpreadForm::Side(Side::Right),
        };
        Some(SpreadKey { axis: i / 3, form })
    }

    /// Index in [`SPREAD_KEYS`].
    pub(crate) fn index(self) -> usize {
        3 * self.axis
            + match self.form {
                SpreadForm::Symmetric => 0,
                SpreadForm::Side(Side::Left) => 1,
                SpreadForm::Side(Side::Right) => 2,
            }
    }
}

/// A hint for an unknown key that looks like a spread key (empty otherwise), to append to the
/// unknown-key message.
pub(crate) fn spread_hint(text: &str) -> &'static str {
    if text.to_ascii_lowercase().starts_with("spread") {
        " (spreads: spread_x, spread_y, spread_z, or spread_x_left and spread_x_right and so on)"
    } else {
        ""
    }
}

/// Why the spread keys given for one point (or one CSV header) are not allowed: both forms
/// for one axis, or an axis the shape does not have. `given[k]` is whether `SPREAD_KEYS[k]`
/// is present, `names[k]` how it was spelt.
pub(crate) fn spread_keys_problem(
    given: &[Option<&str>; 9],
    dimension: usize,
    surface: bool,
) -> Option<String> {
    if surface {
        if let Some(name) = given.iter().flatten().next() {
            return Some(format!(
                "`{name}` does not apply to surfaces (spreads apply to curves only)"
            ));
        }
    }
    for axis in 0..3 {
        let [both, left, right] = [given[3 * axis], given[3 * axis + 1], given[3 * axis + 2]];
        if axis >= dimension {
            if let Some(name) = both.or(left).or(right) {
                return Some(format!(
                    "`{name}` does not apply to a curve without z (the spread of z needs a z \
                     coordinate)"
                ));
            }
        }
        if let (Some(both), Some(side)) = (both, left.or(right)) {
            return Some(format!(
                "`{both}` and `{side}` are both given (give the symmetric spread `{}` or the \
                 asymmetric `{}` and `{}` for one axis, not both)",
                SPREAD_KEYS[3 * axis],
                SPREAD_KEYS[3 * axis + 1],
                SPREAD_KEYS[3 * axis + 2]
            ));
        }
    }
    None
}

/// Message for a spread value that is negative (finite values only reach here).
pub(crate) fn check_spread_value(value: f64) -> Result<f64, String> {
    if value >= 0.0 {
        Ok(value)
    } else {
        Err(format!(
            "spread {value} is negative (a spread is a distance >= 0)"
        ))
    }
}

/// The spread of a point from its spread values, indexed as [`SPREAD_KEYS`].
pub(crate) fn spread_from_values(values: &[Option<f64>; 9]) -> Spread<3> {
    let mut spread = Spread::<3>::ZERO;
    for axis in 0..3 {
        let [both, left, right] = [values[3 * axis], values[3 * axis + 1], values[3 * axis + 2]];
        spread.left[axis] = both.or(left).unwrap_or(0.0);
        spread.right[axis] = both.or(right).unwrap_or(0.0);
    }
    spread
}

/// Explains why two names of the same field clash.
pub(crate) fn duplicate_rule() -> &'static str {
    "each field may appear once; T, I and F are aliases of truth, indeterminacy and falsity"
}

/// One control point as read from a file, its degrees already validated by its rule.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct PointRecord {
    /// The optional name (`C0`, ...).
    pub(crate) name: Option<String>,
    /// `x`, `y` and, for 3-D input, `z`.
    pub(crate) position: Vec<f64>,
    /// The validated degrees (of a wide family: its first lane, see [`Family::lanes`]).
    pub(crate) degrees: Degrees,
    /// The second lane's degrees of an interval-valued or bipolar family.
    pub(crate) second: Option<Degrees>,
    /// The NURBS weight (present exactly for the NURBS kinds; checked when the shape is built).
    pub(crate) weight: Option<f64>,
    /// Where the point was read, for errors found later.
    pub(crate) origin: Origin,
    /// Where the weight was read (`control_points[2].weight`, `` column `weight` ``).
    pub(crate) weight_origin: Origin,
    /// The spreads of the fuzzy position (zero when none is given; `z` zero for 2-D points).
    pub(crate) spread: Spread<3>,
}

/// A model file in the neutral form shared by every format, before the shape is built.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Parsed {
    /// The file as named in messages.
    pub(crate) file: String,
    /// The kind of curve or surface.
    pub(crate) kind: Kind,
    /// Optional name.
    pub(crate) name: Option<String>,
    /// Optional free-text description.
    pub(crate) description: Option<String>,
    /// The rule the degrees were validated with.
    pub(crate) membership: Family,
    /// 2 or 3 (always 3 for surfaces).
    pub(crate) dimension: usize,
    /// The control points, in order (at least one; surfaces row by row).
    pub(crate) points: Vec<PointRecord>,
    /// Degree, knots and grid, as declared.
    pub(crate) structure: Structure,
}

impl Parsed {
    /// An error located at `origin` in this model's file.
    pub(crate) fn error_at(&self, origin: &Origin, message: String) -> InputError {
        InputError::new(&self.file, origin.line, origin.field.clone(), message)
    }
}

/// Which membership rule applies: the file's own declaration, else the command line's, else
/// neutrosophic. A declaration that contradicts the command line is an error (`Err` carries the
/// message).
pub(crate) fn resolve_membership(
    declared: Option<Family>,
    cli: Option<Family>,
) -> Result<Family, String> {
    Ok(resolve("membership", "--membership", declared, cli)?.unwrap_or_default())
}

/// The channel names of the interval-valued and bipolar families other than truth,
/// indeterminacy and falsity: the extra keys and columns of their control points.
pub(crate) const WIDE_CHANNELS: [&str; 9] = [
    "truth_lower",
    "truth_upper",
    "indeterminacy_lower",
    "indeterminacy_upper",
    "falsity_lower",
    "falsity_upper",
    "negative_truth",
    "negative_indeterminacy",
    "negative_falsity",
];

/// The index in [`WIDE_CHANNELS`] of the channel called `text`, exactly or ignoring ASCII case.
pub(crate) fn wide_channel(text: &str, ignore_case: bool) -> Option<usize> {
    WIDE_CHANNELS.iter().position(|c| {
        if ignore_case {
            c.eq_ignore_ascii_case(text)
        } else {
            *c == text
        }
    })
}

/// The canonical names of the degree columns a table has among `truth`, `indeterminacy`,
/// `falsity` (`has_field`) and [`WIDE_CHANNELS`] (`has_channel`, by index): what
/// [`channel_problem`] judges.
pub(crate) fn present_channels(
    has_field: impl Fn(Field) -> bool,
    has_channel: impl Fn(usize) -> bool,
) -> Vec<&'static str> {
    [Field::Truth, Field::Indeterminacy, Field::Falsity]
        .into_iter()
        .filter(|f| has_field(*f))
        .map(Field::name)
        .chain(
            (0..WIDE_CHANNELS.len())
                .filter(|&c| has_channel(c))
                .map(|c| WIDE_CHANNELS[c]),
        )
        .collect()
}

/// Why the degree keys (or columns) given do not match the channels of `membership`: a
/// channel of the family missing, or a degree given that the family does not have. `present`
/// lists the canonical names given among `truth`, `indeterminacy`, `falsity` and
/// [`WIDE_CHANNELS`]; `word` is `key` or `column`. Families of one lane only meet the second
/// problem for the wide channel names (their truth, indeterminacy and falsity are judged by
/// the core's rule, which knows the derived and absent degrees).
pub(crate) fn channel_problem(membership: Family, present: &[&str], word: &str) -> Option<String> {
    let channels = membership.channels();
    if let Some(extra) = present.iter().find(|name| {
        !channels.contains(name)
            && (!membership.fits_degrees() || wide_channel(name, false).is_some())
    }) {
        let mut carriers: Vec<&str> = Family::EXAMPLES
            .iter()
            .filter(|f| f.channels().contains(extra))
            .map(|f| f.name())
            .collect();
        carriers.dedup();
        let carried_by = if carriers.is_empty() || wide_channel(extra, false).is_none() {
            String::new()
        } else {
            format!("; `{extra}` is a channel of {}", carriers.join(", "))
        };
        return Some(format!(
            "{word} `{extra}` does not apply to membership {membership} (its channels: {}){carried_by}",
            channels.join(", ")
        ));
    }
    if membership.fits_degrees() {
        return None;
    }
    channels
        .iter()
        .find(|c| !present.contains(c))
        .map(|missing| format!("missing {word} `{missing}` ({membership} rule requires it)"))
}

/// The two lanes' degrees of a wide family's control point from its channel values
/// (`value(name)` for each channel; [`channel_problem`] has made sure each is present).
///
/// # Errors
/// The rule broken, with the channels named.
pub(crate) fn wide_lanes(
    membership: Family,
    value: impl Fn(&str) -> Option<f64>,
) -> Result<(Degrees, Degrees), DegreeError> {
    let values: Vec<f64> = membership
        .channels()
        .iter()
        .map(|c| value(c).unwrap_or(f64::NAN))
        .collect();
    let (lanes, _) = membership.split(&values)?;
    Ok((lanes[0], lanes[1]))
}

/// The degree that `membership` requires but that is absent when only the degrees flagged
/// present are given, as decided by the core's own rule (probed with zeros).
pub(crate) fn missing_degree(
    membership: Family,
    has_indeterminacy: bool,
    has_falsity: bool,
) -> Option<DegreeError> {
    match Degrees::with_membership(
        membership,
        0.0,
        has_indeterminacy.then_some(0.0),
        has_falsity.then_some(0.0),
    ) {
        Err(e @ DegreeError::Missing { .. }) => Some(e),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn resolve_membership_rules() {
        use Family::*;
        assert_eq!(resolve_membership(None, None), Ok(Neutrosophic));
        assert_eq!(resolve_membership(None, Some(Fuzzy)), Ok(Fuzzy));
        assert_eq!(resolve_membership(Some(Fuzzy), Some(Fuzzy)), Ok(Fuzzy));
        assert_eq!(resolve_membership(Some(Fuzzy), None), Ok(Fuzzy));
        assert!(resolve_membership(Some(Fuzzy), Some(Intuitionistic)).is_err());
    }

    #[test]
    fn missing_degree_follows_core_rule() {
        use Family::*;
        assert!(missing_degree(Neutrosophic, true, true).is_none());
        assert!(missing_degree(Neutrosophic, false, true).is_some());
        assert!(missing_degree(Neutrosophic, true, false).is_some());
        assert!(missing_degree(Intuitionistic, false, true).is_none());
        assert!(missing_degree(Intuitionistic, true, false).is_some());
        assert!(missing_degree(Fuzzy, false, false).is_none());
    }

    #[test]
    fn parse_number_rejects_non_finite() {
        assert_eq!(parse_number("1.5"), Ok(1.5));
        assert_eq!(parse_number("-2e3"), Ok(-2000.0));
        assert_eq!(
            parse_number("NaN").unwrap_err(),
            "value `NaN` is not a finite number (NaN and infinities are not allowed)"
        );
        assert!(parse_number("inf").is_err());
        assert_eq!(
            parse_number("abc").unwrap_err(),
            "value `abc` is not a number"
        );
        assert_eq!(parse_number("").unwrap_err(), "value `` is not a number");
    }

    #[test]
    fn line_of_counts_newlines() {
        let text = b"a\nb\r\nc";
        assert_eq!(line_of(text, 0), 1);
        assert_eq!(line_of(text, 2), 2);
        assert_eq!(line_of(text, 5), 3);
        assert_eq!(line_of(text, 99), 3);
    }
}
