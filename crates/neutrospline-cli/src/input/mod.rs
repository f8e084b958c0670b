//! Reading model files: CSV tables of control points and TOML / JSON models.
//!
//! Every format is parsed into the neutral [`Model`] (kind, name, description, membership rule,
//! dimension, control points with optional names and weights, and the [`Structure`]: degree,
//! knots, grid); [`Model::into_shape`] then builds the core library's curve or surface. The
//! degrees of each control point are validated by the core ([`Degrees::with_membership`])
//! while parsing, and knots by the core's `KnotVector` while building, so that an error can
//! name its line or field. Every failure is an [`InputError`], whose message names the file,
//! the line and / or field, the value and the rule.

mod build;
mod csv;
mod model;
mod settings;

use std::fmt;
use std::path::Path;

use neutrospline::{DegreeError, Degrees, Membership};

pub use settings::{
    resolve, Key, KeyValue, Kind, KnotRule, KnotSpec, KnotsSetting, Overrides, Setting, Structure,
};

/// The largest degree or count of control points accepted, in files and on the command line
/// (larger values are surely mistakes; every integer up to it is exact in a 64-bit float).
pub const MAX_INTEGER: u64 = 1_000_000_000;

/// The name used for standard input in messages.
pub const STDIN_NAME: &str = "<stdin>";

/// The file extensions the command accepts, with `-` meaning CSV on standard input.
pub const ACCEPTED_EXTENSIONS: &str = ".csv, .toml, .json; `-` reads CSV from standard input";

/// An invalid input file: where and what.
///
/// Displays as `FILE[:LINE][: FIELD]: MESSAGE`, the `error: ` prefix being added by `main`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct InputError {
    /// The file as given on the command line (or [`STDIN_NAME`]).
    pub file: String,
    /// The physical, 1-based line in the file, when known.
    pub line: Option<usize>,
    /// The field: a CSV column (`` column `truth` ``) or a model path (`control_points[2].x`).
    pub field: Option<String>,
    /// What is wrong, naming the value and the rule.
    pub message: String,
}

impl fmt::Display for InputError {
    /// One line: control characters that a file put into a name or value (a newline inside a
    /// quoted CSV heading or TOML key, a NUL) are written as escapes such as `\n` and `\0`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write_escaped(f, &self.file)?;
        if let Some(line) = self.line {
            write!(f, ":{line}")?;
        }
        if let Some(field) = &self.field {
            f.write_str(": ")?;
            write_escaped(f, field)?;
        }
        f.write_str(": ")?;
        write_escaped(f, &self.message)
    }
}

/// Writes `text` with its control characters escaped (`\n`, `\0`, `\u{1b}`).
fn write_escaped(f: &mut fmt::Formatter<'_>, text: &str) -> fmt::Result {
    for c in text.chars() {
        if c.is_control() {
            write!(f, "{}", c.escape_debug())?;
        } else {
            write!(f, "{c}")?;
        }
    }
    Ok(())
}

impl std::error::Error for InputError {}

/// An error in the command line that only shows once the arguments are interpreted
/// (for example an unsupported file extension). `main` exits with status 2 for it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct UsageError(pub String);

impl fmt::Display for UsageError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for UsageError {}

/// The file formats, chosen by extension.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// A CSV table (`.csv`, or standard input).
    Csv,
    /// A TOML model (`.toml`).
    Toml,
    /// A JSON model (`.json`).
    Json,
}

impl Format {
    /// The format of `path` by its extension (case-insensitive); `-` is CSV on standard input.
    ///
    /// # Errors
    /// A [`UsageError`] naming the accepted extensions.
    pub fn from_path(path: &str) -> Result<Format, UsageError> {
        if path == "-" {
            return Ok(Format::Csv);
        }
        let ext = Path::new(path)
            .extension()
            .map(|e| e.to_string_lossy().to_ascii_lowercase());
        match ext.as_deref() {
            Some("csv") => Ok(Format::Csv),
            Some("toml") => Ok(Format::Toml),
            Some("json") => Ok(Format::Json),
            Some(other) => Err(UsageError(format!(
                "{path}: unsupported file extension `.{other}` (accepted: {ACCEPTED_EXTENSIONS})"
            ))),
            None => Err(UsageError(format!(
                "{path}: the file name has no extension (accepted: {ACCEPTED_EXTENSIONS})"
            ))),
        }
    }
}

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

/// Explains why two names of the same field clash.
pub(crate) fn duplicate_rule() -> &'static str {
    "each field may appear once; T, I and F are aliases of truth, indeterminacy and falsity"
}

/// One control point as read from a file, its degrees already validated by its rule.
#[derive(Debug, Clone, PartialEq)]
pub struct PointRecord {
    /// The optional name (`C0`, ...).
    pub name: Option<String>,
    /// `x`, `y` and, for 3-D input, `z`.
    pub position: Vec<f64>,
    /// The validated degrees.
    pub degrees: Degrees,
    /// The NURBS weight (present exactly for the NURBS kinds; checked when the shape is built).
    pub weight: Option<f64>,
    /// Where the point was read, for errors found later.
    pub origin: Origin,
    /// Where the weight was read (`control_points[2].weight`, `` column `weight` ``).
    pub weight_origin: Origin,
}

/// Where something was read: the line and the field path of a point.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Origin {
    /// Physical 1-based line, when known.
    pub line: Option<usize>,
    /// Field path such as `control_points[2]`, for models.
    pub field: Option<String>,
}

/// A model file in the neutral form shared by every format.
#[derive(Debug, Clone, PartialEq)]
pub struct Model {
    /// The file as named in messages.
    pub file: String,
    /// The format it was read in.
    pub format: Format,
    /// The kind of curve or surface.
    pub kind: Kind,
    /// Optional name.
    pub name: Option<String>,
    /// Optional free-text description.
    pub description: Option<String>,
    /// The rule the degrees were validated with.
    pub membership: Membership,
    /// 2 or 3 (always 3 for surfaces).
    pub dimension: usize,
    /// The control points, in order (at least one; surfaces row by row).
    pub points: Vec<PointRecord>,
    /// Degree, knots and grid, as declared.
    pub structure: Structure,
}

impl Model {
    /// An error located at `origin` in this model's file.
    pub(crate) fn error_at(&self, origin: &Origin, message: String) -> InputError {
        InputError {
            file: self.file.clone(),
            line: origin.line,
            field: origin.field.clone(),
            message,
        }
    }
}

/// Which membership rule applies: the file's own declaration, else the command line's, else
/// neutrosophic. A declaration that contradicts the command line is an error (`Err` carries the
/// message).
pub fn resolve_membership(
    declared: Option<Membership>,
    cli: Option<Membership>,
) -> Result<Membership, String> {
    resolve("membership", "--membership", declared, cli).map(Option::unwrap_or_default)
}

/// The degree that `membership` requires but that is absent when only the degrees flagged
/// present are given, as decided by the core's own rule (probed with zeros).
pub(crate) fn missing_degree(
    membership: Membership,
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

/// Parses a number written in a file; NaN and infinities are rejected (message only).
pub(crate) fn parse_number(text: &str) -> Result<f64, String> {
    match text.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        Ok(_) => Err(format!(
            "value `{text}` is not a finite number (NaN and infinities are not allowed)"
        )),
        Err(_) => Err(format!("value `{text}` is not a number")),
    }
}

/// Message for a non-finite number that arrived already parsed (TOML `nan`, `inf`).
pub(crate) fn not_finite_message(value: f64) -> String {
    format!("value {value} is not a finite number (NaN and infinities are not allowed)")
}

/// The 1-based line of byte `offset` in `text`.
pub(crate) fn line_of(text: &[u8], offset: usize) -> usize {
    let end = offset.min(text.len());
    text[..end].iter().filter(|&&b| b == b'\n').count() + 1
}

/// Removes a leading UTF-8 byte order mark.
pub(crate) fn strip_bom(bytes: &[u8]) -> &[u8] {
    bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes)
}

/// `a, b, c`.
pub(crate) fn join<'a>(items: impl IntoIterator<Item = &'a str>) -> String {
    items.into_iter().collect::<Vec<_>>().join(", ")
}

/// Parses the contents of `file` (already read) in `format`.
///
/// `overrides` are the command line's shape options (`--membership`, `--kind`, `--degree`,
/// ...): for CSV they are the only source; for models they apply when the file declares
/// nothing, and must agree with the file otherwise. The limit on control points
/// ([`crate::limits::current`]) applies.
///
/// # Errors
/// An [`InputError`] naming the file, line or field, value and rule.
pub fn parse(
    file: &str,
    format: Format,
    bytes: &[u8],
    overrides: &Overrides,
) -> Result<Model, InputError> {
    let model = match format {
        Format::Csv => csv::parse(file, bytes, overrides),
        Format::Toml => model::parse_toml(file, bytes, overrides),
        Format::Json => model::parse_json(file, bytes, overrides),
    }?;
    check_point_count(model)
}

/// Refuses a model with more control points than the limit.
fn check_point_count(model: Model) -> Result<Model, InputError> {
    let limit = crate::limits::current().max_control_points;
    if model.points.len() as u64 > limit {
        let index = usize::try_from(limit).unwrap_or(usize::MAX);
        let origin = model.points[index].origin.clone();
        return Err(model.error_at(&origin, crate::limits::too_many_points(limit)));
    }
    Ok(model)
}

/// Checks the command-line options among themselves, before any file is read: each option
/// must apply to `--kind` when it is given, and a CSV file (which declares nothing) needs the
/// kind's required options.
///
/// # Errors
/// A [`UsageError`].
pub fn check_overrides(format: Format, overrides: &Overrides) -> Result<(), UsageError> {
    let kind = match (overrides.kind, format) {
        (Some(kind), _) => kind,
        (None, Format::Csv) => Kind::DEFAULT,
        (None, _) => return Ok(()),
    };
    if let Some(message) = overrides.inapplicable(kind) {
        let message = if overrides.kind.is_none() {
            format!("{message}; choose the kind with --kind")
        } else {
            message
        };
        return Err(UsageError(message));
    }
    if format == Format::Csv {
        if let Some(key) = Key::ALL
            .into_iter()
            .find(|&k| k.required_for(kind) && overrides.get(k).is_none())
        {
            return Err(UsageError(format!(
                "kind `{kind}` needs {} for a CSV file ({}; a CSV file only lists control points)",
                key.option(),
                key.purpose()
            )));
        }
    }
    Ok(())
}

/// Reads and parses `path` (`-` for CSV on standard input).
///
/// CSV is read as a stream, line by line, and refused at its first bad line without reading
/// further; TOML and JSON documents are read whole, up to `--max-file-size` bytes.
///
/// # Errors
/// [`UsageError`] for an unsupported extension or options that do not fit together, an I/O
/// error with context, or [`InputError`].
pub fn load(path: &str, overrides: &Overrides) -> anyhow::Result<Model> {
    use std::io::{BufReader, Read};

    let format = Format::from_path(path)?;
    check_overrides(format, overrides)?;
    if path == "-" {
        // `Format::from_path` makes standard input CSV.
        let stdin = std::io::stdin().lock();
        return Ok(csv::parse_reader(STDIN_NAME, stdin, overrides)?);
    }
    let cannot = |e: std::io::Error| anyhow::anyhow!("{path}: cannot read: {e}");
    let file = std::fs::File::open(path).map_err(cannot)?;
    let meta = file.metadata().map_err(cannot)?;
    if meta.is_dir() {
        anyhow::bail!("{path}: cannot read: it is a directory (give a .csv, .toml or .json file)");
    }
    if format == Format::Csv {
        return Ok(csv::parse_reader(path, BufReader::new(file), overrides)?);
    }
    let limit = crate::limits::current().max_file_size;
    let too_large = || InputError {
        file: path.to_owned(),
        line: None,
        field: None,
        message: format!(
            "the file is larger than {limit} bytes, the limit for a TOML or JSON file (raise it \
             with --max-file-size or NEUTROSPLINE_MAX_FILE_SIZE; CSV files are streamed and \
             have no size limit)"
        ),
    };
    if meta.len() > limit {
        return Err(too_large().into());
    }
    // The size may grow while reading (a FIFO, a file being written): read one byte more than
    // the limit at most.
    let mut bytes = Vec::with_capacity(usize::try_from(meta.len()).unwrap_or(0));
    file.take(limit.saturating_add(1))
        .read_to_end(&mut bytes)
        .map_err(cannot)?;
    if bytes.len() as u64 > limit {
        return Err(too_large().into());
    }
    Ok(parse(path, format, &bytes, overrides)?)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn format_from_path_by_extension() {
        assert_eq!(Format::from_path("a.csv"), Ok(Format::Csv));
        assert_eq!(Format::from_path("dir/a.TOML"), Ok(Format::Toml));
        assert_eq!(Format::from_path("a.json"), Ok(Format::Json));
        assert_eq!(Format::from_path("-"), Ok(Format::Csv));
        assert_eq!(
            Format::from_path("a.txt").unwrap_err().to_string(),
            "a.txt: unsupported file extension `.txt` (accepted: .csv, .toml, .json; `-` reads CSV from standard input)"
        );
        assert!(Format::from_path("noext").is_err());
    }

    #[test]
    fn input_error_display() {
        let e = InputError {
            file: "a.toml".into(),
            line: Some(7),
            field: Some("control_points[2].x".into()),
            message: "expected a number, found a string".into(),
        };
        assert_eq!(
            e.to_string(),
            "a.toml:7: control_points[2].x: expected a number, found a string"
        );
        let e = InputError {
            file: "a.json".into(),
            line: None,
            field: None,
            message: "m".into(),
        };
        assert_eq!(e.to_string(), "a.json: m");
    }

    #[test]
    fn input_error_display_escapes_control_characters() {
        let e = InputError {
            file: "a.csv".into(),
            line: Some(1),
            field: None,
            message: "unknown column `a\nb\0\u{1b}[31m`".into(),
        };
        assert_eq!(
            e.to_string(),
            "a.csv:1: unknown column `a\\nb\\0\\u{1b}[31m`"
        );
    }

    #[test]
    fn resolve_membership_rules() {
        use Membership::*;
        assert_eq!(resolve_membership(None, None), Ok(Neutrosophic));
        assert_eq!(resolve_membership(None, Some(Fuzzy)), Ok(Fuzzy));
        assert_eq!(resolve_membership(Some(Fuzzy), Some(Fuzzy)), Ok(Fuzzy));
        assert_eq!(resolve_membership(Some(Fuzzy), None), Ok(Fuzzy));
        assert!(resolve_membership(Some(Fuzzy), Some(Intuitionistic)).is_err());
    }

    #[test]
    fn missing_degree_follows_core_rule() {
        use Membership::*;
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
