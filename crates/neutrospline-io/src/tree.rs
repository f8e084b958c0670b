//! The untyped document tree that TOML and JSON models are first read into: every value with
//! the byte span it was read from (TOML only), every table's keys in order, repeated keys kept.
//! The walker ([`crate::walker`]) then reads the model out of it, so that an error can name the
//! field path and the line.

use std::fmt;
use std::ops::Range;

use serde::de::{self, Deserialize, Deserializer, MapAccess, SeqAccess, Visitor};

use crate::Format;

/// A value of the document with the byte span it was read from (TOML only).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Node {
    /// The value.
    pub(crate) value: Value,
    /// Where it was read (TOML only).
    pub(crate) span: Option<Range<usize>>,
}

/// A value of the document.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Value {
    Table(Vec<Entry>),
    Array(Vec<Node>),
    Integer(i64),
    Float(f64),
    String(String),
    Bool(bool),
    Datetime,
    Null,
}

/// A key of a table with its value.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Entry {
    /// The key, as written.
    pub(crate) key: String,
    /// Where the key was read (TOML only).
    pub(crate) key_span: Option<Range<usize>>,
    /// The value.
    pub(crate) value: Node,
}

impl Value {
    /// What the value is, for messages (`a table`, `an object`, `a number`, ...).
    pub(crate) fn describe(&self, format: Format) -> &'static str {
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
pub(crate) fn found(value: &Value, format: Format) -> String {
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

pub(crate) struct TomlNode(pub(crate) Node);
pub(crate) struct JsonNode(pub(crate) Node);

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
