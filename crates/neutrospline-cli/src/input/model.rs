//! TOML and JSON models.
//!
//! ```toml
//! kind = "bspline"                 # required (or --kind): bezier | bspline | nurbs |
//!                                  #   bezier-surface | bspline-surface | nurbs-surface
//! name = "Example"                 # optional
//! description = "..."              # optional
//! membership = "neutrosophic"      # optional: neutrosophic (default) | intuitionistic | fuzzy
//!
//! # Curves
//! degree = 3                       # bspline, nurbs: required; bezier: optional, must be n
//! knots = [0, 0, 0, 0, 0.5, 1, 1, 1, 1]  # bspline, nurbs: optional; an array of n + p + 2
//!                                  #   values, or "clamped-uniform" (default) |
//!                                  #   "chord-length" | "centripetal"
//! # Surfaces (control points row by row: the row index runs along u, the column along v)
//! rows = 4                         # required: control points along u
//! cols = 4                         # required: control points along v
//! degree_u = 3                     # bspline-/nurbs-surface: required; bezier-surface:
//! degree_v = 3                     #   optional, must be rows - 1 and cols - 1
//! knots_u = "clamped-uniform"      # bspline-/nurbs-surface: optional, an array or
//! knots_v = [0, 0, 0, 0, 1, 1, 1, 1]  #   "clamped-uniform" (default)
//!
//! [[control_points]]               # one table per control point, in order
//! name = "C0"                      # optional
//! x = 1.0                          # required
//! y = 3.0                          # required
//! z = 0.0                          # optional for curves (all points or none); surfaces: required
//! truth = 0.3                      # or T
//! indeterminacy = 0.6              # or I
//! falsity = 0.1                    # or F
//! weight = 1.0                     # nurbs, nurbs-surface: required (> 0); other kinds: an error
//! ```
//!
//! Keys are case-sensitive; unknown and repeated keys are errors, and so are keys that do not
//! apply to the kind. The document is first read into a small untyped tree ([`Node`]) that
//! keeps every key, in order, with its source span (TOML only), so that errors can name the
//! field path and the line.

use std::fmt;
use std::ops::Range;

use neutrospline::{DegreeError, DegreeKind, Degrees, Membership};
use serde::de::{self, Deserialize, Deserializer, MapAccess, SeqAccess, Visitor};

use super::{
    duplicate_rule, line_of, not_finite_message, resolve, resolve_membership, strip_bom, Field,
    Format, InputError, Key, KeyValue, Kind, KnotRule, KnotSpec, KnotsSetting, Model, Origin,
    Overrides, PointRecord, Setting, Structure,
};
use crate::output::number;

/// The keys of a model's top-level table.
const TOP_KEYS: [&str; 13] = [
    "kind",
    "name",
    "description",
    "membership",
    "degree",
    "knots",
    "rows",
    "cols",
    "degree_u",
    "degree_v",
    "knots_u",
    "knots_v",
    "control_points",
];

/// A value of the document with the byte span it was read from (TOML only).
#[derive(Debug, Clone, PartialEq)]
struct Node {
    value: Value,
    span: Option<Range<usize>>,
}

#[derive(Debug, Clone, PartialEq)]
enum Value {
    Table(Vec<Entry>),
    Array(Vec<Node>),
    Integer(i64),
    Float(f64),
    String(String),
    Bool(bool),
    Datetime,
    Null,
}

#[derive(Debug, Clone, PartialEq)]
struct Entry {
    key: String,
    key_span: Option<Range<usize>>,
    value: Node,
}

impl Value {
    fn describe(&self, format: Format) -> &'static str {
        match self {
            Value::Table(_) if format == Format::Json => "an object",
            Value::Table(_) => "a table",
            Value::Array(_) => "an array",
            Value::Integer(_) | Value::Float(_) => "a number",
            Value::String(_) => "a string",
            Value::Bool(_) => "a boolean",
            Value::Datetime => "a datetime",
            Value::Null => "null",
        }
    }
}

/// What a value is, for messages: its type, and its text when short (`the string "abc"`,
/// `the boolean true`).
fn found(value: &Value, format: Format) -> String {
    const SHOWN: usize = 40;
    match value {
        Value::String(text) if text.chars().count() <= SHOWN => format!("the string {text:?}"),
        Value::String(text) => {
            let head: String = text.chars().take(SHOWN).collect();
            format!("the string {:?}...", head)
        }
        Value::Bool(b) => format!("the boolean {b}"),
        other => other.describe(format).to_owned(),
    }
}

/// The magic key under which `toml` hands a datetime to `deserialize_any`.
const TOML_DATETIME_KEY: &str = "$__toml_private_datetime";

/// Reads any value; `SPANNED` asks the (TOML) deserializer for the span of every value.
struct NodeVisitor<const SPANNED: bool>;

struct TomlNode(Node);
struct JsonNode(Node);

impl<'de> Deserialize<'de> for TomlNode {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(NodeVisitor::<true>).map(TomlNode)
    }
}

impl<'de> Deserialize<'de> for JsonNode {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(NodeVisitor::<false>).map(JsonNode)
    }
}

fn plain(value: Value) -> Node {
    Node { value, span: None }
}

impl<const SPANNED: bool> NodeVisitor<SPANNED> {
    fn next_value<'de, A: MapAccess<'de>>(map: &mut A) -> Result<Node, A::Error> {
        if SPANNED {
            let v = map.next_value::<toml::Spanned<TomlNode>>()?;
            let span = v.span();
            Ok(Node {
                span: Some(span),
                ..v.into_inner().0
            })
        } else {
            Ok(map.next_value::<JsonNode>()?.0)
        }
    }
}

impl<'de, const SPANNED: bool> Visitor<'de> for NodeVisitor<SPANNED> {
    type Value = Node;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("any value")
    }

    fn visit_bool<E: de::Error>(self, v: bool) -> Result<Node, E> {
        Ok(plain(Value::Bool(v)))
    }

    fn visit_i64<E: de::Error>(self, v: i64) -> Result<Node, E> {
        Ok(plain(Value::Integer(v)))
    }

    fn visit_u64<E: de::Error>(self, v: u64) -> Result<Node, E> {
        Ok(plain(match i64::try_from(v) {
            Ok(v) => Value::Integer(v),
            Err(_) => Value::Float(v as f64),
        }))
    }

    fn visit_f64<E: de::Error>(self, v: f64) -> Result<Node, E> {
        Ok(plain(Value::Float(v)))
    }

    fn visit_str<E: de::Error>(self, v: &str) -> Result<Node, E> {
        Ok(plain(Value::String(v.to_owned())))
    }

    fn visit_string<E: de::Error>(self, v: String) -> Result<Node, E> {
        Ok(plain(Value::String(v)))
    }

    fn visit_unit<E: de::Error>(self) -> Result<Node, E> {
        Ok(plain(Value::Null))
    }

    fn visit_none<E: de::Error>(self) -> Result<Node, E> {
        Ok(plain(Value::Null))
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Node, A::Error> {
        let mut items = Vec::new();
        if SPANNED {
            while let Some(v) = seq.next_element::<toml::Spanned<TomlNode>>()? {
                let span = v.span();
                items.push(Node {
                    span: Some(span),
                    ..v.into_inner().0
                });
            }
        } else {
            while let Some(v) = seq.next_element::<JsonNode>()? {
                items.push(v.0);
            }
        }
        Ok(plain(Value::Array(items)))
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Node, A::Error> {
        let mut entries = Vec::new();
        loop {
            let (key, key_span) = if SPANNED {
                match map.next_key::<toml::Spanned<String>>()? {
                    Some(k) => {
                        let span = k.span();
                        (k.into_inner(), Some(span))
                    }
                    None => break,
                }
            } else {
                match map.next_key::<String>()? {
                    Some(k) => (k, None),
                    None => break,
                }
            };
            if SPANNED && key == TOML_DATETIME_KEY {
                map.next_value::<de::IgnoredAny>()?;
                return Ok(plain(Value::Datetime));
            }
            let value = Self::next_value(&mut map)?;
            entries.push(Entry {
                key,
                key_span,
                value,
            });
        }
        Ok(plain(Value::Table(entries)))
    }
}

/// Parses a TOML model.
pub(super) fn parse_toml(
    file: &str,
    bytes: &[u8],
    overrides: &Overrides,
) -> Result<Model, InputError> {
    let walker = Walker::new(file, bytes, Format::Toml)?;
    let text = walker.text;
    let root = toml::from_str::<TomlNode>(text).map_err(|e| {
        let message = e
            .message()
            .lines()
            .map(str::trim)
            .filter(|l| !l.is_empty())
            .collect::<Vec<_>>()
            .join("; ");
        walker.error(e.span().as_ref(), None, format!("invalid TOML: {message}"))
    })?;
    walker.model(root.0, overrides)
}

/// Parses a JSON model.
pub(super) fn parse_json(
    file: &str,
    bytes: &[u8],
    overrides: &Overrides,
) -> Result<Model, InputError> {
    let walker = Walker::new(file, bytes, Format::Json)?;
    let root = serde_json::from_str::<JsonNode>(walker.text).map_err(|e| {
        let full = e.to_string();
        let suffix = format!(" at line {} column {}", e.line(), e.column());
        let message = full.strip_suffix(&suffix).unwrap_or(&full);
        let hint = json_hint(walker.text, message, e.line(), e.column());
        InputError {
            file: file.to_owned(),
            line: (e.line() > 0).then_some(e.line()),
            field: None,
            message: format!("invalid JSON: {message} (column {}{hint})", e.column()),
        }
    })?;
    walker.model(root.0, overrides)
}

/// An explanation of a JSON syntax error that a number causes: NaN and infinities (which
/// other programs write but JSON does not have) and numbers beyond the 64-bit range.
fn json_hint(text: &str, message: &str, line: usize, column: usize) -> &'static str {
    if message.starts_with("number out of range") {
        return "; the number does not fit a 64-bit float";
    }
    let at = text
        .lines()
        .nth(line.saturating_sub(1))
        .and_then(|l| l.get(column.saturating_sub(1)..))
        .unwrap_or_default();
    let word = at.trim_start_matches(['-', '+']).to_ascii_lowercase();
    if word.starts_with("nan") || word.starts_with("inf") {
        "; JSON has no NaN or infinities"
    } else {
        ""
    }
}

/// A structure key's value, where it was declared, and the lines of explicit knots.
struct Declared {
    value: KeyValue,
    origin: Origin,
    lines: Vec<Option<usize>>,
}

/// Turns the untyped tree into a [`Model`], with located errors.
struct Walker<'a> {
    file: &'a str,
    text: &'a str,
    format: Format,
}

impl<'a> Walker<'a> {
    fn new(file: &'a str, bytes: &'a [u8], format: Format) -> Result<Self, InputError> {
        let bytes = strip_bom(bytes);
        let text = std::str::from_utf8(bytes).map_err(|e| InputError {
            file: file.to_owned(),
            line: Some(line_of(bytes, e.valid_up_to())),
            field: None,
            message: "invalid UTF-8 (the file must be UTF-8 encoded)".to_owned(),
        })?;
        Ok(Walker { file, text, format })
    }

    fn error(
        &self,
        span: Option<&Range<usize>>,
        field: Option<String>,
        message: String,
    ) -> InputError {
        InputError {
            file: self.file.to_owned(),
            line: self.line(span),
            field,
            message,
        }
    }

    fn line(&self, span: Option<&Range<usize>>) -> Option<usize> {
        span.map(|s| line_of(self.text.as_bytes(), s.start))
    }

    fn expected(&self, node: &Node, path: &str, what: &str) -> InputError {
        self.error(
            node.span.as_ref(),
            Some(path.to_owned()),
            format!("expected {what}, found {}", found(&node.value, self.format)),
        )
    }

    fn table_word(&self) -> &'static str {
        match self.format {
            Format::Json => "an object",
            _ => "a table",
        }
    }

    fn string(&self, node: &Node, path: &str) -> Result<String, InputError> {
        match &node.value {
            Value::String(s) => Ok(s.clone()),
            _ => Err(self.expected(node, path, "a string")),
        }
    }

    fn number(&self, node: &Node, path: &str) -> Result<f64, InputError> {
        match node.value {
            Value::Integer(v) => Ok(v as f64),
            Value::Float(v) if v.is_finite() => Ok(v),
            Value::Float(v) => Err(self.error(
                node.span.as_ref(),
                Some(path.to_owned()),
                not_finite_message(v),
            )),
            _ => Err(self.expected(node, path, "a number")),
        }
    }

    fn model(&self, root: Node, cli: &Overrides) -> Result<Model, InputError> {
        let Value::Table(entries) = &root.value else {
            return Err(self.error(
                root.span.as_ref(),
                None,
                format!(
                    "expected {} at the top level, found {}",
                    self.table_word(),
                    root.value.describe(self.format)
                ),
            ));
        };
        let mut top: [Option<&Entry>; TOP_KEYS.len()] = Default::default();
        for entry in entries {
            let Some(i) = TOP_KEYS.iter().position(|&k| k == entry.key) else {
                return Err(self.error(
                    entry.key_span.as_ref(),
                    None,
                    format!(
                        "unknown key `{}` (known keys: {})",
                        entry.key,
                        TOP_KEYS.join(", ")
                    ),
                ));
            };
            if top[i].is_some() {
                return Err(self.error(
                    entry.key_span.as_ref(),
                    None,
                    format!("duplicated key `{}` (each key may appear once)", entry.key),
                ));
            }
            top[i] = Some(entry);
        }
        let entry = |key: &str| top[TOP_KEYS.iter().position(|&k| k == key).unwrap_or(0)];
        let node = |key: &str| entry(key).map(|e| &e.value);

        let kind_node = node("kind");
        let declared_kind = match kind_node {
            None => None,
            Some(node) => {
                let text = self.string(node, "kind")?;
                Some(Kind::from_name(&text).ok_or_else(|| {
                    self.error(
                        node.span.as_ref(),
                        Some("kind".to_owned()),
                        format!(
                            "unknown kind `{text}` (known kinds: {})",
                            Kind::known_list()
                        ),
                    )
                })?)
            }
        };
        let kind_error = |message: String| {
            self.error(
                kind_node.and_then(|n| n.span.as_ref()),
                kind_node.map(|_| "kind".to_owned()),
                message,
            )
        };
        let kind = resolve("kind", "--kind", declared_kind, cli.kind)
            .map_err(kind_error)?
            .ok_or_else(|| {
                self.error(
                    None,
                    None,
                    format!("missing key `kind` (known kinds: {})", Kind::known_list()),
                )
            })?;
        if let Some(message) = cli.inapplicable(kind) {
            return Err(kind_error(message));
        }

        let name = node("name").map(|n| self.string(n, "name")).transpose()?;
        let description = node("description")
            .map(|n| self.string(n, "description"))
            .transpose()?;
        let membership_node = node("membership");
        let declared = match membership_node {
            None => None,
            Some(node) => {
                let text = self.string(node, "membership")?;
                Some(text.parse::<Membership>().map_err(|e| {
                    self.error(
                        node.span.as_ref(),
                        Some("membership".to_owned()),
                        e.to_string(),
                    )
                })?)
            }
        };
        let membership = resolve_membership(declared, cli.membership).map_err(|m| {
            self.error(
                membership_node.and_then(|n| n.span.as_ref()),
                Some("membership".to_owned()),
                m,
            )
        })?;

        let structure = self.structure(kind, &|key| entry(key.name()), cli)?;

        let Some(list) = node("control_points") else {
            return Err(self.error(
                None,
                None,
                "missing key `control_points` (the list of control points)".to_owned(),
            ));
        };
        let Value::Array(items) = &list.value else {
            return Err(self.expected(list, "control_points", "an array"));
        };
        if items.is_empty() {
            return Err(self.error(
                list.span.as_ref(),
                Some("control_points".to_owned()),
                "no control points (a curve needs at least one)".to_owned(),
            ));
        }
        let mut points: Vec<PointRecord> = Vec::with_capacity(items.len());
        for (i, item) in items.iter().enumerate() {
            let point = self.point(item, i, membership, kind)?;
            if let Some(first) = points.first() {
                if first.position.len() != point.position.len() {
                    let (has, other) = if point.position.len() == 3 {
                        ("has `z`", "none")
                    } else {
                        ("has no `z`", "one")
                    };
                    return Err(self.error(
                        item.span.as_ref(),
                        Some(format!("control_points[{i}]")),
                        format!(
                            "{has} but control_points[0] has {other} \
                             (all control points must have the same dimension)"
                        ),
                    ));
                }
            }
            points.push(point);
        }
        let dimension = points[0].position.len();
        Ok(Model {
            file: self.file.to_owned(),
            format: self.format,
            kind,
            name,
            description,
            membership,
            dimension,
            points,
            structure,
        })
    }

    /// Reads the structure keys that `kind` takes, merged with the command line's options.
    fn structure<'e>(
        &self,
        kind: Kind,
        entry: &dyn Fn(Key) -> Option<&'e Entry>,
        cli: &Overrides,
    ) -> Result<Structure, InputError> {
        let mut values: Vec<Option<Declared>> = Vec::new();
        for key in Key::ALL {
            let found = entry(key);
            if let Some(e) = found {
                if !key.applies_to(kind) {
                    return Err(self.error(
                        e.key_span.as_ref(),
                        None,
                        format!(
                            "key `{}` does not apply to kind `{kind}` ({} is for: {})",
                            key.name(),
                            key.name(),
                            key.kinds_list()
                        ),
                    ));
                }
            }
            let declared = found.map(|e| self.key_value(key, &e.value)).transpose()?;
            let origin = Origin {
                line: found.and_then(|e| self.line(e.value.span.as_ref())),
                field: Some(key.name().to_owned()),
            };
            let (value, lines) = match declared {
                Some((value, lines)) => (Some(value), lines),
                None => (None, Vec::new()),
            };
            let from_file = value.is_some();
            let value = resolve(key.name(), key.option(), value, cli.get(key)).map_err(|m| {
                self.error(
                    found.and_then(|e| e.value.span.as_ref()),
                    Some(key.name().to_owned()),
                    m,
                )
            })?;
            if value.is_none() && key.required_for(kind) {
                return Err(self.error(
                    None,
                    None,
                    format!(
                        "missing key `{}` (kind `{kind}` needs {}; or give {})",
                        key.name(),
                        key.purpose(),
                        key.option()
                    ),
                ));
            }
            let origin = if from_file {
                origin
            } else {
                Origin {
                    line: None,
                    field: Some(key.option().to_owned()),
                }
            };
            values.push(value.map(|value| Declared {
                value,
                origin,
                lines,
            }));
        }
        let mut take =
            |key: Key| values[Key::ALL.iter().position(|&k| k == key).unwrap_or(0)].take();
        let number = |v: Option<Declared>| {
            v.and_then(|d| match d.value {
                KeyValue::Number(value) => Some(Setting {
                    value,
                    origin: d.origin,
                }),
                KeyValue::Knots(_) => None,
            })
        };
        let knots = |v: Option<Declared>| {
            v.and_then(|d| match d.value {
                KeyValue::Knots(spec) => Some(KnotsSetting {
                    spec,
                    origin: d.origin,
                    lines: d.lines,
                }),
                KeyValue::Number(_) => None,
            })
        };
        if kind.is_surface() {
            let count = |v: Option<Setting<usize>>, key: Key| {
                // Required for every surface kind: checked above.
                v.unwrap_or(Setting {
                    value: 0,
                    origin: Origin {
                        line: None,
                        field: Some(key.name().to_owned()),
                    },
                })
            };
            Ok(Structure::Surface {
                rows: count(number(take(Key::Rows)), Key::Rows),
                cols: count(number(take(Key::Cols)), Key::Cols),
                degree_u: number(take(Key::DegreeU)),
                degree_v: number(take(Key::DegreeV)),
                knots_u: knots(take(Key::KnotsU)),
                knots_v: knots(take(Key::KnotsV)),
            })
        } else {
            Ok(Structure::Curve {
                degree: number(take(Key::Degree)),
                knots: knots(take(Key::Knots)),
            })
        }
    }

    /// The value of a structure key, with the line of each knot for explicit knots.
    fn key_value(
        &self,
        key: Key,
        node: &Node,
    ) -> Result<(KeyValue, Vec<Option<usize>>), InputError> {
        let path = key.name();
        if key.is_knots() {
            return match &node.value {
                Value::String(text) => {
                    let rule = KnotRule::from_name(text).ok_or_else(|| {
                        self.error(
                            node.span.as_ref(),
                            Some(path.to_owned()),
                            format!(
                                "unknown knot rule `{text}` (expected one of: {}, or an array of knot values)",
                                KnotRule::known_list()
                            ),
                        )
                    })?;
                    Ok((KeyValue::Knots(KnotSpec::Rule(rule)), Vec::new()))
                }
                Value::Array(items) => {
                    let mut knots = Vec::with_capacity(items.len());
                    let mut lines = Vec::with_capacity(items.len());
                    for (i, item) in items.iter().enumerate() {
                        knots.push(self.number(item, &format!("{path}[{i}]"))?);
                        lines.push(self.line(item.span.as_ref()));
                    }
                    Ok((KeyValue::Knots(KnotSpec::Explicit(knots)), lines))
                }
                _ => Err(self.expected(
                    node,
                    path,
                    &format!(
                        "an array of knot values or one of: {}",
                        KnotRule::known_list()
                    ),
                )),
            };
        }
        let (min, what) = if key.is_count() {
            (1, "a positive integer")
        } else {
            (0, "a non-negative integer")
        };
        let value = match node.value {
            Value::Integer(v) => Some(v as f64),
            Value::Float(v) => Some(v),
            _ => None,
        };
        let max = super::MAX_INTEGER as f64;
        match value {
            Some(v) if v.fract() == 0.0 && v >= min as f64 && v <= max => {
                Ok((KeyValue::Number(v as usize), Vec::new()))
            }
            Some(v) if v.fract() == 0.0 && v > max => Err(self.error(
                node.span.as_ref(),
                Some(path.to_owned()),
                format!(
                    "{} is too large (at most {})",
                    number(v),
                    super::MAX_INTEGER
                ),
            )),
            Some(v) => Err(self.error(
                node.span.as_ref(),
                Some(path.to_owned()),
                format!("expected {what}, found {}", number(v)),
            )),
            None => Err(self.expected(node, path, what)),
        }
    }

    fn point(
        &self,
        item: &Node,
        index: usize,
        membership: Membership,
        kind: Kind,
    ) -> Result<PointRecord, InputError> {
        let path = format!("control_points[{index}]");
        let Value::Table(entries) = &item.value else {
            return Err(self.expected(item, &path, self.table_word()));
        };
        let mut nodes: [Option<&Node>; 8] = Default::default();
        let mut keys: [Option<&str>; 8] = Default::default();
        for entry in entries {
            let Some(field) = Field::from_name(&entry.key, false) else {
                return Err(self.error(
                    entry.key_span.as_ref(),
                    Some(path.clone()),
                    format!(
                        "unknown key `{}` (known keys: {})",
                        entry.key,
                        Field::known_list()
                    ),
                ));
            };
            if let Some(previous) = keys[field.index()] {
                return Err(self.error(
                    entry.key_span.as_ref(),
                    Some(path.clone()),
                    format!(
                        "key `{}` repeats key `{previous}` ({})",
                        entry.key,
                        duplicate_rule()
                    ),
                ));
            }
            if field == Field::Weight && !kind.is_rational() {
                return Err(self.error(
                    entry.key_span.as_ref(),
                    Some(path.clone()),
                    format!(
                        "key `weight` does not apply to kind `{kind}` (weights only apply to NURBS: {})",
                        Kind::rational_list()
                    ),
                ));
            }
            keys[field.index()] = Some(&entry.key);
            nodes[field.index()] = Some(&entry.value);
        }
        let node = |f: Field| nodes[f.index()];
        let value = |f: Field| -> Result<Option<f64>, InputError> {
            node(f)
                .map(|n| {
                    self.number(
                        n,
                        &format!("{path}.{}", keys[f.index()].unwrap_or(f.name())),
                    )
                })
                .transpose()
        };

        let name = node(Field::Name)
            .map(|n| self.string(n, &format!("{path}.name")))
            .transpose()?;
        let mut position = Vec::with_capacity(3);
        for f in [Field::X, Field::Y] {
            position.push(value(f)?.ok_or_else(|| {
                self.error(
                    item.span.as_ref(),
                    Some(path.clone()),
                    format!(
                        "missing key `{}` (every control point needs x and y)",
                        f.name()
                    ),
                )
            })?);
        }
        match value(Field::Z)? {
            Some(z) => position.push(z),
            None if kind.is_surface() => {
                return Err(self.error(
                    item.span.as_ref(),
                    Some(path.clone()),
                    "missing key `z` (surfaces are 3-D: every control point needs x, y and z)"
                        .to_owned(),
                ))
            }
            None => {}
        }
        // Any number, NaN and infinities included: the core's NURBS weight rule judges it.
        let weight = match node(Field::Weight) {
            None => None,
            Some(n) => match n.value {
                Value::Integer(v) => Some(v as f64),
                Value::Float(v) => Some(v),
                _ => return Err(self.expected(n, &format!("{path}.weight"), "a number")),
            },
        };
        if weight.is_none() && kind.is_rational() {
            return Err(self.error(
                item.span.as_ref(),
                Some(path.clone()),
                format!(
                    "missing key `weight` (kind `{kind}` needs a positive weight for every control point)"
                ),
            ));
        }
        let truth = value(Field::Truth)?.ok_or_else(|| {
            self.error(
                item.span.as_ref(),
                Some(path.clone()),
                "missing key `truth` (every membership rule requires it)".to_owned(),
            )
        })?;
        let degrees = Degrees::with_membership(
            membership,
            truth,
            value(Field::Indeterminacy)?,
            value(Field::Falsity)?,
        )
        .map_err(|e| {
            let at = |kind: DegreeKind| {
                let field = match kind {
                    DegreeKind::Truth => Field::Truth,
                    DegreeKind::Indeterminacy => Field::Indeterminacy,
                    DegreeKind::Falsity => Field::Falsity,
                };
                node(field)
                    .and_then(|n| n.span.as_ref())
                    .or(item.span.as_ref())
            };
            let (span, message) = match &e {
                DegreeError::Missing { kind, membership } => (
                    item.span.as_ref(),
                    format!("missing key `{kind}` ({membership} rule requires it)"),
                ),
                DegreeError::OutOfRange { kind, .. }
                | DegreeError::NotFinite { kind, .. }
                | DegreeError::FuzzyExtra { kind, .. } => (at(*kind), e.to_string()),
                DegreeError::HesitationMismatch { .. } => {
                    (at(DegreeKind::Indeterminacy), e.to_string())
                }
                _ => (item.span.as_ref(), e.to_string()),
            };
            self.error(span, Some(path.clone()), message)
        })?;
        let weight_origin = Origin {
            line: self.line(
                node(Field::Weight)
                    .and_then(|n| n.span.as_ref())
                    .or(item.span.as_ref()),
            ),
            field: Some(format!("{path}.weight")),
        };
        Ok(PointRecord {
            name,
            position,
            degrees,
            weight,
            origin: Origin {
                line: self.line(item.span.as_ref()),
                field: Some(path),
            },
            weight_origin,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn with_membership(membership: Option<Membership>) -> Overrides {
        Overrides {
            membership,
            ..Overrides::default()
        }
    }

    const EXAMPLE1_TOML: &str = r#"kind = "bezier"
name = "Example 1"
description = "Paper's Example 1"

[[control_points]]
name = "C0"
x = 1
y = 3
truth = 0.3
indeterminacy = 0.6
falsity = 0.1

[[control_points]]
name = "C1"
x = 3
y = 6
T = 0.8
I = 0.1
F = 0.1

[[control_points]]
name = "C2"
x = 6.0
y = 2.0
truth = 0.7
indeterminacy = 0.1
falsity = 0.2

[[control_points]]
name = "C3"
x = 9
y = 5
truth = 0.2
indeterminacy = 0.4
falsity = 0.4
"#;

    fn toml_err(text: &str) -> String {
        parse_toml("m.toml", text.as_bytes(), &Overrides::default())
            .unwrap_err()
            .to_string()
    }

    fn json_err(text: &str) -> String {
        parse_json("m.json", text.as_bytes(), &Overrides::default())
            .unwrap_err()
            .to_string()
    }

    #[test]
    fn model_parse_toml_example1() {
        let m = parse_toml("m.toml", EXAMPLE1_TOML.as_bytes(), &Overrides::default()).unwrap();
        assert_eq!(m.kind, Kind::DEFAULT);
        assert_eq!(m.name.as_deref(), Some("Example 1"));
        assert_eq!(m.membership, Membership::Neutrosophic);
        assert_eq!(m.dimension, 2);
        assert_eq!(m.points.len(), 4);
        assert_eq!(m.points[1].degrees.to_array(), [0.8, 0.1, 0.1]);
        assert_eq!(m.points[2].position, vec![6.0, 2.0]);
        assert_eq!(m.points[3].name.as_deref(), Some("C3"));
    }

    #[test]
    fn model_parse_json_inline() {
        let text = r#"{"kind": "bezier", "membership": "intuitionistic",
            "control_points": [{"x": 0, "y": 0, "z": 1, "truth": 0.5, "falsity": 0.25},
                               {"x": 1, "y": 0, "z": 2, "T": 0.25, "F": 0.5, "I": 0.25}]}"#;
        let m = parse_json("m.json", text.as_bytes(), &Overrides::default()).unwrap();
        assert_eq!(m.dimension, 3);
        assert_eq!(m.membership, Membership::Intuitionistic);
        assert_eq!(m.points[0].degrees.to_array(), [0.5, 0.25, 0.25]);
        assert_eq!(m.points[1].position, vec![1.0, 0.0, 2.0]);
    }

    #[test]
    fn model_parse_toml_errors_name_path_and_line() {
        let bad = EXAMPLE1_TOML.replace("truth = 0.7", "truth = 1.7");
        assert_eq!(
            toml_err(&bad),
            "m.toml:25: control_points[2]: truth = 1.7 is outside [0, 1] (every degree must be in [0, 1])"
        );
        let bad = EXAMPLE1_TOML.replace("y = 2.0", "y = \"two\"");
        assert_eq!(
            toml_err(&bad),
            "m.toml:24: control_points[2].y: expected a number, found the string \"two\""
        );
        let bad = EXAMPLE1_TOML.replace("I = 0.1", "I = 0.1\nw = 2");
        assert_eq!(
            toml_err(&bad),
            "m.toml:19: control_points[1]: unknown key `w` (known keys: x, y, z, truth (T), indeterminacy (I), falsity (F), weight, name)"
        );
        let bad = EXAMPLE1_TOML.replace("I = 0.1", "I = 0.1\nweight = 2");
        assert_eq!(
            toml_err(&bad),
            "m.toml:19: control_points[1]: key `weight` does not apply to kind `bezier` (weights only apply to NURBS: nurbs, nurbs-surface)"
        );
        let bad = EXAMPLE1_TOML.replace("T = 0.8", "T = 0.8\ntruth = 0.8");
        assert_eq!(
            toml_err(&bad),
            "m.toml:18: control_points[1]: key `truth` repeats key `T` (each field may appear once; T, I and F are aliases of truth, indeterminacy and falsity)"
        );
        let bad = EXAMPLE1_TOML.replace("falsity = 0.4\n", "");
        assert_eq!(
            toml_err(&bad),
            "m.toml:29: control_points[3]: missing key `falsity` (neutrosophic rule requires it)"
        );
        let bad = EXAMPLE1_TOML.replace("x = 9\n", "x = 9\nz = 1\n");
        assert_eq!(
            toml_err(&bad),
            "m.toml:29: control_points[3]: has `z` but control_points[0] has none (all control points must have the same dimension)"
        );
        let bad = EXAMPLE1_TOML.replace("x = 3\n", "x = nan\n");
        assert_eq!(
            toml_err(&bad),
            "m.toml:15: control_points[1].x: value NaN is not a finite number (NaN and infinities are not allowed)"
        );
        let bad = EXAMPLE1_TOML.replace("kind = \"bezier\"", "kind = \"spline\"");
        assert_eq!(
            toml_err(&bad),
            "m.toml:1: kind: unknown kind `spline` (known kinds: bezier, bspline, nurbs, bezier-surface, bspline-surface, nurbs-surface)"
        );
        let bad = EXAMPLE1_TOML.replace("kind = \"bezier\"\n", "");
        assert_eq!(
            toml_err(&bad),
            "m.toml: missing key `kind` (known kinds: bezier, bspline, nurbs, bezier-surface, bspline-surface, nurbs-surface)"
        );
        let bad = EXAMPLE1_TOML.replace("name = \"Example 1\"", "title = \"Example 1\"");
        assert_eq!(
            toml_err(&bad),
            "m.toml:2: unknown key `title` (known keys: kind, name, description, membership, degree, knots, rows, cols, degree_u, degree_v, knots_u, knots_v, control_points)"
        );
    }

    #[test]
    fn model_parse_toml_syntax_error_has_line() {
        let e = toml_err("kind = \"bezier\"\nx = = 1\n");
        assert!(e.starts_with("m.toml:2: invalid TOML: "), "{e}");
        assert!(!e.contains('\n'), "{e}");
    }

    #[test]
    fn model_parse_membership_conflict_and_default() {
        let text = "kind = \"bezier\"\nmembership = \"fuzzy\"\ncontrol_points = [{x = 0, y = 0, truth = 0.5}]\n";
        let m = parse_toml("m.toml", text.as_bytes(), &Overrides::default()).unwrap();
        assert_eq!(m.points[0].degrees.to_array(), [0.5, 0.0, 0.0]);
        let e = parse_toml(
            "m.toml",
            text.as_bytes(),
            &with_membership(Some(Membership::Neutrosophic)),
        )
        .unwrap_err()
        .to_string();
        assert_eq!(
            e,
            "m.toml:2: membership: the file declares membership `fuzzy` but --membership is `neutrosophic` (omit --membership or make them agree)"
        );
        let text = "kind = \"bezier\"\ncontrol_points = [{x = 0, y = 0, truth = 0.5}]\n";
        let m = parse_toml(
            "m.toml",
            text.as_bytes(),
            &with_membership(Some(Membership::Fuzzy)),
        )
        .unwrap();
        assert_eq!(m.membership, Membership::Fuzzy);
    }

    #[test]
    fn model_parse_json_errors() {
        assert_eq!(
            json_err(r#"{"kind": "bezier", "kind": "bezier", "control_points": []}"#),
            "m.json: duplicated key `kind` (each key may appear once)"
        );
        assert_eq!(
            json_err(r#"{"kind": "bezier", "control_points": []}"#),
            "m.json: control_points: no control points (a curve needs at least one)"
        );
        assert_eq!(
            json_err(
                r#"{"kind": "bezier", "control_points": [{"x": 1, "y": 2, "truth": 0.5, "indeterminacy": 0.5, "falsity": 0.5}, 3]}"#
            ),
            "m.json: control_points[1]: expected an object, found a number"
        );
        assert_eq!(
            json_err(
                r#"{"kind": "bezier", "control_points": [{"x": 1, "y": null, "truth": 0.5}]}"#
            ),
            "m.json: control_points[0].y: expected a number, found null"
        );
        assert_eq!(
            json_err(r#"{"kind": "bezier", "control_points": [{"x": 1, "truth": 0.5}]}"#),
            "m.json: control_points[0]: missing key `y` (every control point needs x and y)"
        );
        assert_eq!(
            json_err("[1, 2]"),
            "m.json: expected an object at the top level, found an array"
        );
        assert_eq!(
            json_err("{\n  \"kind\": \"bezier\",\n  \"control_points\": [\n}"),
            "m.json:4: invalid JSON: expected value (column 1)"
        );
        assert_eq!(
            json_err(
                r#"{"kind": "bezier", "control_points": [{"x": 1, "y": 1e999, "truth": 0.5}]}"#
            ),
            "m.json:1: invalid JSON: number out of range (column 57; the number does not fit a 64-bit float)"
        );
    }

    #[test]
    fn model_parse_json_numbers_round_trip_exactly() {
        // Regression: serde_json's default float parser was 2 ULP off for this value, so a
        // JSON model evaluated differently from the same TOML model.
        let y = -1.7669093114403063_f64;
        let text = format!(
            r#"{{"kind": "bezier", "control_points": [{{"x": 0, "y": {y}, "T": 1, "I": 0, "F": 0}}]}}"#
        );
        let m = parse_json("m.json", text.as_bytes(), &Overrides::default()).unwrap();
        assert_eq!(m.points[0].position[1].to_bits(), y.to_bits());
    }

    #[test]
    fn model_parse_structure_keys_and_knot_lines() {
        let text = "kind = \"nurbs\"\ndegree = 1\nknots = [\n  0, 0,\n  1, 1,\n]\n\
                    control_points = [{ x = 0, y = 0, T = 1, I = 0, F = 0, weight = 2 },\n\
                    { x = 1, y = 0, T = 1, I = 0, F = 0, weight = 0.5 }]\n";
        let m = parse_toml("m.toml", text.as_bytes(), &Overrides::default()).unwrap();
        let Structure::Curve { degree, knots } = &m.structure else {
            panic!("a curve")
        };
        assert_eq!(degree.as_ref().map(|d| d.value), Some(1));
        let knots = knots.as_ref().unwrap();
        assert_eq!(knots.spec, KnotSpec::Explicit(vec![0.0, 0.0, 1.0, 1.0]));
        assert_eq!(knots.origin.line, Some(3));
        assert_eq!(knots.lines, [Some(4), Some(4), Some(5), Some(5)]);
        assert_eq!(m.points[1].weight, Some(0.5));
        assert_eq!(m.points[1].weight_origin.line, Some(8));
    }

    #[test]
    fn model_parse_invalid_utf8() {
        let e = parse_json("m.json", b"{\"kind\":\n\"\xff\"}", &Overrides::default()).unwrap_err();
        assert_eq!(
            e.to_string(),
            "m.json:2: invalid UTF-8 (the file must be UTF-8 encoded)"
        );
    }
}
