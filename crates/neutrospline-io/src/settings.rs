//! What a file (or the command line) says about the shape besides its control points: the
//! kind, degrees, knots and grid size, and the rules that say which of them a kind takes.

use std::fmt;

use neutrospline::{CurveKind, SurfaceKind};

use crate::number::format_number as number;
use crate::text::{join, parse_number, Origin};

/// The kinds of shape a file may declare with `kind = "..."` (or `--kind`): the core's curve
/// and surface kinds.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Kind {
    /// A curve: `bezier`, `bspline` or `nurbs`.
    Curve(CurveKind),
    /// A tensor-product surface: `bezier-surface`, `bspline-surface` or `nurbs-surface`.
    Surface(SurfaceKind),
}

impl Kind {
    /// Every kind, in the order they are listed in messages.
    pub const ALL: [Kind; 6] = [
        Kind::Curve(CurveKind::Bezier),
        Kind::Curve(CurveKind::BSpline),
        Kind::Curve(CurveKind::Nurbs),
        Kind::Surface(SurfaceKind::Bezier),
        Kind::Surface(SurfaceKind::BSpline),
        Kind::Surface(SurfaceKind::Nurbs),
    ];

    /// The kind of a CSV file without `--kind`.
    pub const DEFAULT: Kind = Kind::Curve(CurveKind::Bezier);

    /// The name used in files and on the command line (the core's names).
    pub const fn name(self) -> &'static str {
        match self {
            Kind::Curve(k) => k.name(),
            Kind::Surface(k) => k.name(),
        }
    }

    /// Parses an exact kind name.
    pub fn from_name(name: &str) -> Option<Kind> {
        Kind::ALL.into_iter().find(|k| k.name() == name)
    }

    /// `bezier, bspline, ...`: the known kinds, for messages.
    pub fn known_list() -> String {
        join(Kind::ALL.iter().map(|k| k.name()))
    }

    /// Whether this is a surface kind.
    pub const fn is_surface(self) -> bool {
        matches!(self, Kind::Surface(_))
    }

    /// Whether the control points carry weights (`nurbs`, `nurbs-surface`).
    pub const fn is_rational(self) -> bool {
        matches!(
            self,
            Kind::Curve(CurveKind::Nurbs) | Kind::Surface(SurfaceKind::Nurbs)
        )
    }

    /// Whether knots are involved (everything but the two Bézier kinds).
    pub const fn has_knots(self) -> bool {
        !matches!(
            self,
            Kind::Curve(CurveKind::Bezier) | Kind::Surface(SurfaceKind::Bezier)
        )
    }

    /// `nurbs, nurbs-surface`: the kinds that take weights, for messages.
    pub fn rational_list() -> String {
        join(
            Kind::ALL
                .iter()
                .filter(|k| k.is_rational())
                .map(|k| k.name()),
        )
    }
}

impl fmt::Display for Kind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// The named ways of choosing knots, mapping to the core's `KnotVector` constructors.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum KnotRule {
    /// `KnotVector::clamped_uniform`: clamped, evenly spaced on \[0, 1\].
    ClampedUniform,
    /// `KnotVector::chord_length`: clamped, spaced like the control polygon's edges.
    ChordLength,
    /// `KnotVector::centripetal`: clamped, spaced like the square roots of the edges.
    Centripetal,
    /// `KnotVector::uniform`: unclamped, evenly spaced, the domain \[0, 1\].
    Uniform,
}

impl KnotRule {
    /// Every rule, in the order they are listed in messages.
    pub const ALL: [KnotRule; 4] = [
        KnotRule::ClampedUniform,
        KnotRule::ChordLength,
        KnotRule::Centripetal,
        KnotRule::Uniform,
    ];

    /// The name used in files and on the command line.
    pub const fn name(self) -> &'static str {
        match self {
            KnotRule::ClampedUniform => "clamped-uniform",
            KnotRule::ChordLength => "chord-length",
            KnotRule::Centripetal => "centripetal",
            KnotRule::Uniform => "uniform",
        }
    }

    /// Parses an exact rule name.
    pub fn from_name(name: &str) -> Option<KnotRule> {
        KnotRule::ALL.into_iter().find(|k| k.name() == name)
    }

    /// `clamped-uniform, chord-length, centripetal, uniform`.
    pub fn known_list() -> String {
        join(KnotRule::ALL.iter().map(|k| k.name()))
    }
}

/// Knots as given: a rule, or the knot values themselves.
#[derive(Debug, Clone, PartialEq)]
pub enum KnotSpec {
    /// Computed by a rule from the degree and the control points.
    Rule(KnotRule),
    /// Given explicitly (validated by `KnotVector::new`).
    Explicit(Vec<f64>),
}

impl fmt::Display for KnotSpec {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            KnotSpec::Rule(rule) => f.write_str(rule.name()),
            KnotSpec::Explicit(knots) => {
                let items: Vec<String> = knots.iter().map(|&k| number(k)).collect();
                write!(f, "[{}]", items.join(", "))
            }
        }
    }
}

impl KnotSpec {
    /// Parses `--knots`: a rule name, or comma-separated finite numbers.
    ///
    /// # Errors
    /// A message naming the bad item.
    pub fn parse_option(text: &str) -> Result<KnotSpec, String> {
        let text = text.trim();
        if let Some(rule) = KnotRule::from_name(text) {
            return Ok(KnotSpec::Rule(rule));
        }
        if text.starts_with(|c: char| c.is_ascii_alphabetic()) && !text.contains(',') {
            let lower = text.to_ascii_lowercase();
            if !matches!(lower.as_str(), "nan" | "inf" | "infinity") {
                return Err(format!(
                    "unknown knot rule `{text}` (expected one of: {}, or knot values K0,K1,...)",
                    KnotRule::known_list()
                ));
            }
        }
        text.split(',')
            .map(|item| {
                let item = item.trim();
                parse_number(item).map_err(|m| format!("knot {m}"))
            })
            .collect::<Result<_, _>>()
            .map(KnotSpec::Explicit)
    }
}

/// A value with where it was declared: a key of the file, or a command-line option.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Setting<T> {
    /// The value.
    pub value: T,
    /// Its line and field (`degree`, `--degree`, ...).
    pub origin: Origin,
}

/// Knots with where they were declared, and the line of each explicit knot when known.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct KnotsSetting {
    /// The knots or their rule.
    pub spec: KnotSpec,
    /// Where they were declared.
    pub origin: Origin,
    /// For explicit knots read from TOML: the line of each knot.
    pub lines: Vec<Option<usize>>,
}

impl KnotsSetting {
    /// The line of explicit knot `index`, else the line of the declaration.
    pub fn line_of_knot(&self, index: usize) -> Option<usize> {
        self.lines
            .get(index)
            .copied()
            .flatten()
            .or(self.origin.line)
    }
}

/// The structure settings of a model besides its control points.
// One per model: boxing the larger variant would buy nothing.
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Structure {
    /// A curve: its degree (required for `bspline` and `nurbs`; for `bezier` it must equal
    /// n if given) and knots (default clamped uniform).
    Curve {
        /// The polynomial degree.
        degree: Option<Setting<usize>>,
        /// The knots (of a periodic curve: its breakpoints).
        knots: Option<KnotsSetting>,
        /// Whether the curve is periodic (closed).
        periodic: Option<Setting<bool>>,
    },
    /// A surface over a `rows x cols` grid.
    Surface {
        /// Control points along u.
        rows: Setting<usize>,
        /// Control points along v.
        cols: Setting<usize>,
        /// Degree in u.
        degree_u: Option<Setting<usize>>,
        /// Degree in v.
        degree_v: Option<Setting<usize>>,
        /// Knots in u.
        knots_u: Option<KnotsSetting>,
        /// Knots in v.
        knots_v: Option<KnotsSetting>,
        /// Whether the surface is periodic (closed) along u.
        periodic_u: Option<Setting<bool>>,
        /// Whether the surface is periodic (closed) along v.
        periodic_v: Option<Setting<bool>>,
    },
}

/// The structure keys of a model file, each with its command-line option.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Key {
    /// `degree` / `--degree`.
    Degree,
    /// `knots` / `--knots`.
    Knots,
    /// `rows` / `--rows`.
    Rows,
    /// `cols` / `--cols`.
    Cols,
    /// `degree_u` / `--degree-u`.
    DegreeU,
    /// `degree_v` / `--degree-v`.
    DegreeV,
    /// `knots_u` / `--knots-u`.
    KnotsU,
    /// `knots_v` / `--knots-v`.
    KnotsV,
    /// `periodic` / `--periodic`.
    Periodic,
    /// `periodic_u` / `--periodic-u`.
    PeriodicU,
    /// `periodic_v` / `--periodic-v`.
    PeriodicV,
}

impl Key {
    /// Every key, in file order.
    pub const ALL: [Key; 11] = [
        Key::Degree,
        Key::Knots,
        Key::Rows,
        Key::Cols,
        Key::DegreeU,
        Key::DegreeV,
        Key::KnotsU,
        Key::KnotsV,
        Key::Periodic,
        Key::PeriodicU,
        Key::PeriodicV,
    ];

    /// The key in files.
    pub const fn name(self) -> &'static str {
        match self {
            Key::Degree => "degree",
            Key::Knots => "knots",
            Key::Rows => "rows",
            Key::Cols => "cols",
            Key::DegreeU => "degree_u",
            Key::DegreeV => "degree_v",
            Key::KnotsU => "knots_u",
            Key::KnotsV => "knots_v",
            Key::Periodic => "periodic",
            Key::PeriodicU => "periodic_u",
            Key::PeriodicV => "periodic_v",
        }
    }

    /// The command-line option.
    pub const fn option(self) -> &'static str {
        match self {
            Key::Degree => "--degree",
            Key::Knots => "--knots",
            Key::Rows => "--rows",
            Key::Cols => "--cols",
            Key::DegreeU => "--degree-u",
            Key::DegreeV => "--degree-v",
            Key::KnotsU => "--knots-u",
            Key::KnotsV => "--knots-v",
            Key::Periodic => "--periodic",
            Key::PeriodicU => "--periodic-u",
            Key::PeriodicV => "--periodic-v",
        }
    }

    /// Whether the key means something for `kind`.
    pub fn applies_to(self, kind: Kind) -> bool {
        match self {
            Key::Degree => !kind.is_surface(),
            Key::Knots | Key::Periodic => !kind.is_surface() && kind.has_knots(),
            Key::Rows | Key::Cols | Key::DegreeU | Key::DegreeV => kind.is_surface(),
            Key::KnotsU | Key::KnotsV | Key::PeriodicU | Key::PeriodicV => {
                kind.is_surface() && kind.has_knots()
            }
        }
    }

    /// Whether `kind` cannot do without it.
    pub fn required_for(self, kind: Kind) -> bool {
        match self {
            Key::Degree => {
                kind == Kind::Curve(CurveKind::BSpline) || kind == Kind::Curve(CurveKind::Nurbs)
            }
            Key::Rows | Key::Cols => kind.is_surface(),
            Key::DegreeU | Key::DegreeV => kind.is_surface() && kind.has_knots(),
            Key::Knots
            | Key::KnotsU
            | Key::KnotsV
            | Key::Periodic
            | Key::PeriodicU
            | Key::PeriodicV => false,
        }
    }

    /// `bspline, nurbs`: the kinds the key applies to.
    pub fn kinds_list(self) -> String {
        join(
            Kind::ALL
                .iter()
                .filter(|&&k| self.applies_to(k))
                .map(|k| k.name()),
        )
    }

    /// Why the key is needed, for a "missing" message.
    pub fn purpose(self) -> &'static str {
        match self {
            Key::Degree => "the polynomial degree",
            Key::Rows => "the number of control points along u",
            Key::Cols => "the number of control points along v",
            Key::DegreeU => "the polynomial degree along u",
            Key::DegreeV => "the polynomial degree along v",
            Key::Knots | Key::KnotsU | Key::KnotsV => "the knots",
            Key::Periodic | Key::PeriodicU | Key::PeriodicV => "whether the shape is closed",
        }
    }

    /// Whether the value is a count of control points (at least 1) rather than a degree.
    pub const fn is_count(self) -> bool {
        matches!(self, Key::Rows | Key::Cols)
    }

    /// Whether the value is knots rather than a number.
    pub const fn is_knots(self) -> bool {
        matches!(self, Key::Knots | Key::KnotsU | Key::KnotsV)
    }

    /// Whether the value is `true` or `false`.
    pub const fn is_flag(self) -> bool {
        matches!(self, Key::Periodic | Key::PeriodicU | Key::PeriodicV)
    }
}

/// A value of a structure key: a number, or knots.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum KeyValue {
    /// A degree or a count.
    Number(usize),
    /// Knots.
    Knots(KnotSpec),
    /// `true` or `false`.
    Flag(bool),
}

impl fmt::Display for KeyValue {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            KeyValue::Number(n) => write!(f, "{n}"),
            KeyValue::Knots(k) => write!(f, "{k}"),
            KeyValue::Flag(b) => write!(f, "{b}"),
        }
    }
}

/// Which value applies: the file's declaration, else the command line's. A declaration that
/// contradicts the command line is an error (`Err` carries the message).
pub(crate) fn resolve<T: PartialEq + fmt::Display>(
    what: &str,
    option: &str,
    declared: Option<T>,
    cli: Option<T>,
) -> Result<Option<T>, String> {
    match (declared, cli) {
        (Some(d), Some(c)) if d != c => Err(format!(
            "the file declares {what} `{d}` but {option} is `{c}` \
             (omit {option} or make them agree)"
        )),
        (Some(d), _) => Ok(Some(d)),
        (None, c) => Ok(c),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kind_names_round_trip() {
        for kind in Kind::ALL {
            assert_eq!(Kind::from_name(kind.name()), Some(kind));
        }
        assert_eq!(
            Kind::known_list(),
            "bezier, bspline, nurbs, bezier-surface, bspline-surface, nurbs-surface"
        );
        assert_eq!(Kind::rational_list(), "nurbs, nurbs-surface");
        assert_eq!(Kind::from_name("Bezier"), None);
    }

    #[test]
    fn key_applicability() {
        assert_eq!(Key::Knots.kinds_list(), "bspline, nurbs");
        assert_eq!(Key::Degree.kinds_list(), "bezier, bspline, nurbs");
        assert_eq!(
            Key::Rows.kinds_list(),
            "bezier-surface, bspline-surface, nurbs-surface"
        );
        assert_eq!(Key::KnotsV.kinds_list(), "bspline-surface, nurbs-surface");
        assert!(Key::Degree.required_for(Kind::Curve(CurveKind::Nurbs)));
        assert!(!Key::Degree.required_for(Kind::Curve(CurveKind::Bezier)));
        assert!(!Key::DegreeU.required_for(Kind::Surface(SurfaceKind::Bezier)));
        assert!(Key::DegreeU.required_for(Kind::Surface(SurfaceKind::BSpline)));
    }

    #[test]
    fn knot_spec_parse_option() {
        assert_eq!(
            KnotSpec::parse_option("chord-length"),
            Ok(KnotSpec::Rule(KnotRule::ChordLength))
        );
        assert_eq!(
            KnotSpec::parse_option("0, 0,0.5,1,1"),
            Ok(KnotSpec::Explicit(vec![0.0, 0.0, 0.5, 1.0, 1.0]))
        );
        assert_eq!(
            KnotSpec::parse_option("uniform"),
            Ok(KnotSpec::Rule(KnotRule::Uniform))
        );
        assert_eq!(
            KnotSpec::parse_option("open").unwrap_err(),
            "unknown knot rule `open` (expected one of: clamped-uniform, chord-length, centripetal, uniform, or knot values K0,K1,...)"
        );
        assert_eq!(
            KnotSpec::parse_option("0,x,1").unwrap_err(),
            "knot value `x` is not a number"
        );
        assert_eq!(
            KnotSpec::parse_option("0,NaN").unwrap_err(),
            "knot value `NaN` is not a finite number (NaN and infinities are not allowed)"
        );
        assert_eq!(
            KnotSpec::Explicit(vec![0.0, 0.5, 1.0]).to_string(),
            "[0, 0.5, 1]"
        );
    }

    #[test]
    fn resolve_rules() {
        assert_eq!(resolve::<usize>("degree", "--degree", None, None), Ok(None));
        assert_eq!(resolve("degree", "--degree", Some(2), None), Ok(Some(2)));
        assert_eq!(resolve("degree", "--degree", None, Some(3)), Ok(Some(3)));
        assert_eq!(resolve("degree", "--degree", Some(3), Some(3)), Ok(Some(3)));
        assert_eq!(
            resolve("degree", "--degree", Some(2), Some(3)).unwrap_err(),
            "the file declares degree `2` but --degree is `3` (omit --degree or make them agree)"
        );
    }
}
