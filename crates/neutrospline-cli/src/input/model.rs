//! TOML and JSON models.
//!
//! ```toml
//! kind = "bezier"                  # required; known kinds: bezier
//! name = "Example 1"               # optional
//! description = "..."              # optional
//! membership = "neutrosophic"      # optional: neutrosophic (default) | intuitionistic | fuzzy
//!
//! [[control_points]]               # one table per control point, in order
//! name = "C0"                      # optional
//! x = 1.0                          # required
//! y = 3.0                          # required
//! # z = 0.0                        # optional; all points have it or none
//! truth = 0.3                      # or T
//! indeterminacy = 0.6              # or I
//! falsity = 0.1                    # or F
//! ```
//!
//! Keys are case-sensitive; unknown and repeated keys are errors. The document is first read
//! into a small untyped tree ([`Node`]) that keeps every key, in order, with its source span
//! (TOML only), so that errors can name the field path and the line.

use std::fmt;
use std::ops::Range;

use neutrospline::{DegreeError, DegreeKind, Degrees, Membership};
use serde::de::{self, Deserialize, Deserializer, MapAccess, SeqAccess, Visitor};

use super::{
    duplicate_rule, line_of, not_finite_message, resolve_membership, strip_bom, Field, Format,
    InputError, Kind, Model, Origin, PointRecord,
};

/// The keys of a model's top-level table.
const TOP_KEYS: [&str; 5] = [
    "kind",
    "name",
    "description",
    "membership",
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
    membership: Option<Membership>,
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
    walker.model(root.0, membership)
}

/// Parses a JSON model.
pub(super) fn parse_json(
    file: &str,
    bytes: &[u8],
    membership: Option<Membership>,
) -> Result<Model, InputError> {
    let walker = Walker::new(file, bytes, Format::Json)?;
    let root = serde_json::from_str::<JsonNode>(walker.text).map_err(|e| {
        let full = e.to_string();
        let suffix = format!(" at line {} column {}", e.line(), e.column());
        let message = full.strip_suffix(&suffix).unwrap_or(&full);
        InputError {
            file: file.to_owned(),
            line: (e.line() > 0).then_some(e.line()),
            field: None,
            message: format!("invalid JSON: {message} (column {})", e.column()),
        }
    })?;
    walker.model(root.0, membership)
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
            format!(
                "expected {what}, found {}",
                node.value.describe(self.format)
            ),
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

    fn model(&self, root: Node, cli: Option<Membership>) -> Result<Model, InputError> {
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
        let mut top: [Option<&Node>; TOP_KEYS.len()] = Default::default();
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
            top[i] = Some(&entry.value);
        }
        let [kind, name, description, membership, control_points] = top;

        let kind = match kind {
            None => {
                return Err(self.error(
                    None,
                    None,
                    format!("missing key `kind` (known kinds: {})", Kind::known_list()),
                ))
            }
            Some(node) => {
                let text = self.string(node, "kind")?;
                Kind::from_name(&text).ok_or_else(|| {
                    self.error(
                        node.span.as_ref(),
                        Some("kind".to_owned()),
                        format!(
                            "unknown kind `{text}` (known kinds: {})",
                            Kind::known_list()
                        ),
                    )
                })?
            }
        };
        let name = name.map(|n| self.string(n, "name")).transpose()?;
        let description = description
            .map(|n| self.string(n, "description"))
            .transpose()?;
        let declared = match membership {
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
        let membership = resolve_membership(declared, cli).map_err(|m| {
            self.error(
                membership.and_then(|n| n.span.as_ref()),
                Some("membership".to_owned()),
                m,
            )
        })?;

        let Some(list) = control_points else {
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
            let point = self.point(item, i, membership)?;
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
        })
    }

    fn point(
        &self,
        item: &Node,
        index: usize,
        membership: Membership,
    ) -> Result<PointRecord, InputError> {
        let path = format!("control_points[{index}]");
        let Value::Table(entries) = &item.value else {
            return Err(self.expected(item, &path, self.table_word()));
        };
        let mut nodes: [Option<&Node>; 7] = Default::default();
        let mut keys: [Option<&str>; 7] = Default::default();
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
        if let Some(z) = value(Field::Z)? {
            position.push(z);
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
        Ok(PointRecord {
            name,
            position,
            degrees,
            origin: Origin {
                line: self.line(item.span.as_ref()),
                field: Some(path),
            },
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
        parse_toml("m.toml", text.as_bytes(), None)
            .unwrap_err()
            .to_string()
    }

    fn json_err(text: &str) -> String {
        parse_json("m.json", text.as_bytes(), None)
            .unwrap_err()
            .to_string()
    }

    #[test]
    fn model_parse_toml_example1() {
        let m = parse_toml("m.toml", EXAMPLE1_TOML.as_bytes(), None).unwrap();
        assert_eq!(m.kind, Kind::Bezier);
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
        let m = parse_json("m.json", text.as_bytes(), None).unwrap();
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
            "m.toml:24: control_points[2].y: expected a number, found a string"
        );
        let bad = EXAMPLE1_TOML.replace("I = 0.1", "I = 0.1\nweight = 2");
        assert_eq!(
            toml_err(&bad),
            "m.toml:19: control_points[1]: unknown key `weight` (known keys: x, y, z, truth (T), indeterminacy (I), falsity (F), name)"
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
        let bad = EXAMPLE1_TOML.replace("kind = \"bezier\"", "kind = \"nurbs\"");
        assert_eq!(
            toml_err(&bad),
            "m.toml:1: kind: unknown kind `nurbs` (known kinds: bezier)"
        );
        let bad = EXAMPLE1_TOML.replace("kind = \"bezier\"\n", "");
        assert_eq!(
            toml_err(&bad),
            "m.toml: missing key `kind` (known kinds: bezier)"
        );
        let bad = EXAMPLE1_TOML.replace("name = \"Example 1\"", "title = \"Example 1\"");
        assert_eq!(
            toml_err(&bad),
            "m.toml:2: unknown key `title` (known keys: kind, name, description, membership, control_points)"
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
        let m = parse_toml("m.toml", text.as_bytes(), None).unwrap();
        assert_eq!(m.points[0].degrees.to_array(), [0.5, 0.0, 0.0]);
        let e = parse_toml("m.toml", text.as_bytes(), Some(Membership::Neutrosophic))
            .unwrap_err()
            .to_string();
        assert_eq!(
            e,
            "m.toml:2: membership: the file declares membership `fuzzy` but --membership is `neutrosophic` (omit --membership or make them agree)"
        );
        let text = "kind = \"bezier\"\ncontrol_points = [{x = 0, y = 0, truth = 0.5}]\n";
        let m = parse_toml("m.toml", text.as_bytes(), Some(Membership::Fuzzy)).unwrap();
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
            "m.json:1: invalid JSON: number out of range (column 57)"
        );
    }

    #[test]
    fn model_parse_invalid_utf8() {
        let e = parse_json("m.json", b"{\"kind\":\n\"\xff\"}", None).unwrap_err();
        assert_eq!(
            e.to_string(),
            "m.json:2: invalid UTF-8 (the file must be UTF-8 encoded)"
        );
    }
}
