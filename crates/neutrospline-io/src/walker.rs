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
//! field path and the line; the [`Walker`] reads the model out of it (the control points in
//! `point.rs`).

mod point;
#[cfg(test)]
mod tests;

use std::ops::Range;

use neutrospline::Family;

use crate::format::MAX_INTEGER;
use crate::number::format_number as number;
use crate::parsed::{
    line_of, not_finite_message, resolve_membership, strip_bom, Origin, Parsed, PointRecord,
};
use crate::settings::{
    resolve, Key, KeyValue, Kind, KnotRule, KnotSpec, KnotsSetting, Setting, Structure,
};
use crate::tree::{found, Entry, JsonNode, Node, TomlNode, Value};
use crate::{Format, InputError, ReadOptions};

/// The keys of a model's top-level table.
const TOP_KEYS: [&str; 18] = [
    "kind",
    "name",
    "description",
    "membership",
    "q",
    "n",
    "degree",
    "knots",
    "rows",
    "cols",
    "degree_u",
    "degree_v",
    "knots_u",
    "knots_v",
    "periodic",
    "periodic_u",
    "periodic_v",
    "control_points",
];

/// Parses a TOML model.
pub(crate) fn parse_toml(
    file: &str,
    bytes: &[u8],
    options: &ReadOptions,
) -> Result<Parsed, InputError> {
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
    walker.model(root.0, options)
}

/// Parses a JSON model.
pub(crate) fn parse_json(
    file: &str,
    bytes: &[u8],
    options: &ReadOptions,
) -> Result<Parsed, InputError> {
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
    walker.model(root.0, options)
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

/// Turns the untyped tree into a [`Parsed`] model, with located errors.
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

    /// The membership family named by `found` (`"pythagorean"`, `"q-rung:4"`), its
    /// parameter given in the name or by the top-level key `q` (`q-rung`) or `n`
    /// (`t-spherical`) that `parameter` looks up.
    fn family<'n>(
        &self,
        found: &Node,
        parameter: &dyn Fn(&str) -> Option<&'n Node>,
    ) -> Result<Family, InputError> {
        let text = self.string(found, "membership")?;
        let at = |message: String| {
            self.error(found.span.as_ref(), Some("membership".to_owned()), message)
        };
        let name = text.trim().to_ascii_lowercase();
        let key = match name.split(':').next().map(str::trim) {
            Some("q-rung") => Some("q"),
            Some("t-spherical") => Some("n"),
            _ => None,
        };
        let given = match key.and_then(|k| parameter(k).map(|p| (k, p))) {
            None => None,
            Some((key, p)) => match p.value {
                Value::Integer(v) if (1..=i64::from(u32::MAX)).contains(&v) => {
                    Some((key, v as u32))
                }
                _ => {
                    return Err(self.error(
                        p.span.as_ref(),
                        Some(key.to_owned()),
                        format!(
                            "`{key}` must be an integer >= 1 (the parameter of membership \"{name}\"), found {}",
                            match p.value {
                                Value::Integer(v) => v.to_string(),
                                _ => p.value.describe(self.format).to_owned(),
                            }
                        ),
                    ))
                }
            },
        };
        match (key, given) {
            (Some(key), None) if !name.contains(':') => Err(at(format!(
                "membership \"{name}\" needs its parameter: add `{key} = 4` (an integer >= 1) or write \"{name}:4\""
            ))),
            (Some(_), Some((_, value))) if !name.contains(':') => {
                Family::with_parameter(&name, value).map_err(|e| at(e.to_string()))
            }
            _ => {
                let family = text.parse::<Family>().map_err(|e| at(e.to_string()))?;
                match (family.parameter(), given) {
                    (Some((key, inside)), Some((_, outside))) if inside != outside => Err(at(format!(
                        "membership \"{text}\" has {key} = {inside} but key `{key}` says {outside}"
                    ))),
                    _ => Ok(family),
                }
            }
        }
    }

    fn model(&self, root: Node, cli: &ReadOptions) -> Result<Parsed, InputError> {
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
            Some(found) => Some(self.family(found, &node)?),
        };
        for key in ["q", "n"] {
            if let Some(given) = node(key) {
                let applies = declared.and_then(|f| f.parameter()).map(|(k, _)| k);
                if applies != Some(key) {
                    let family = if key == "q" { "q-rung" } else { "t-spherical" };
                    return Err(self.error(
                        given.span.as_ref(),
                        Some(key.to_owned()),
                        format!(
                            "key `{key}` is the parameter of membership \"{family}\"; this model's membership is {}",
                            declared.map_or("not declared".to_owned(), |f| format!("\"{}\"", f.name()))
                        ),
                    ));
                }
            }
        }
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
        Ok(Parsed {
            file: self.file.to_owned(),
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
        cli: &ReadOptions,
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
                KeyValue::Knots(_) | KeyValue::Flag(_) => None,
            })
        };
        let flag = |v: Option<Declared>| {
            v.and_then(|d| match d.value {
                KeyValue::Flag(value) => Some(Setting {
                    value,
                    origin: d.origin,
                }),
                KeyValue::Knots(_) | KeyValue::Number(_) => None,
            })
        };
        let knots = |v: Option<Declared>| {
            v.and_then(|d| match d.value {
                KeyValue::Knots(spec) => Some(KnotsSetting {
                    spec,
                    origin: d.origin,
                    lines: d.lines,
                }),
                KeyValue::Number(_) | KeyValue::Flag(_) => None,
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
                periodic_u: flag(take(Key::PeriodicU)),
                periodic_v: flag(take(Key::PeriodicV)),
            })
        } else {
            Ok(Structure::Curve {
                degree: number(take(Key::Degree)),
                knots: knots(take(Key::Knots)),
                periodic: flag(take(Key::Periodic)),
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
        if key.is_flag() {
            return match node.value {
                Value::Bool(value) => Ok((KeyValue::Flag(value), Vec::new())),
                _ => Err(self.expected(node, path, "true or false")),
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
        let max = MAX_INTEGER as f64;
        match value {
            Some(v) if v.fract() == 0.0 && v >= min as f64 && v <= max => {
                Ok((KeyValue::Number(v as usize), Vec::new()))
            }
            Some(v) if v.fract() == 0.0 && v > max => Err(self.error(
                node.span.as_ref(),
                Some(path.to_owned()),
                format!("{} is too large (at most {})", number(v), MAX_INTEGER),
            )),
            Some(v) => Err(self.error(
                node.span.as_ref(),
                Some(path.to_owned()),
                format!("expected {what}, found {}", number(v)),
            )),
            None => Err(self.expected(node, path, what)),
        }
    }
}
