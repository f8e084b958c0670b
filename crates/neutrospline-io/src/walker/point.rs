//! The control points of a TOML or JSON model.

use neutrospline::{DegreeError, DegreeKind, Degrees, Family};

use super::Walker;
use crate::parsed::{
    channel_problem, check_spread_value, duplicate_rule, spread_from_values, spread_hint,
    spread_keys_problem, wide_channel, wide_lanes, Field, Origin, PointRecord, SpreadKey,
    WIDE_CHANNELS,
};
use crate::settings::Kind;
use crate::tree::{Node, Value};
use crate::InputError;

impl Walker<'_> {
    /// Reads control point `index` from `item`, its degrees validated by `membership`.
    pub(super) fn point(
        &self,
        item: &Node,
        index: usize,
        membership: Family,
        kind: Kind,
    ) -> Result<PointRecord, InputError> {
        let path = format!("control_points[{index}]");
        let Value::Table(entries) = &item.value else {
            return Err(self.expected(item, &path, self.table_word()));
        };
        let mut nodes: [Option<&Node>; 8] = Default::default();
        let mut keys: [Option<&str>; 8] = Default::default();
        let mut spread_nodes: [Option<&Node>; 9] = Default::default();
        let mut spread_keys: [Option<&str>; 9] = Default::default();
        let mut first_spread_span = None;
        let mut wide_nodes: [Option<&Node>; 9] = Default::default();
        let repeats = |span, key: &str, previous: &str| {
            self.error(
                span,
                Some(path.clone()),
                format!(
                    "key `{key}` repeats key `{previous}` ({})",
                    duplicate_rule()
                ),
            )
        };
        for entry in entries {
            if let Some(c) = wide_channel(&entry.key, false) {
                if wide_nodes[c].is_some() {
                    return Err(repeats(entry.key_span.as_ref(), &entry.key, &entry.key));
                }
                wide_nodes[c] = Some(&entry.value);
                continue;
            }
            if let Some(key) = SpreadKey::from_name(&entry.key, false) {
                if spread_keys[key.index()].is_some() {
                    return Err(repeats(entry.key_span.as_ref(), &entry.key, &entry.key));
                }
                first_spread_span = first_spread_span.or(entry.key_span.as_ref());
                spread_keys[key.index()] = Some(&entry.key);
                spread_nodes[key.index()] = Some(&entry.value);
                continue;
            }
            let Some(field) = Field::from_name(&entry.key, false) else {
                return Err(self.error(
                    entry.key_span.as_ref(),
                    Some(path.clone()),
                    format!(
                        "unknown key `{}` (known keys: {}){}",
                        entry.key,
                        Field::known_list(),
                        spread_hint(&entry.key)
                    ),
                ));
            };
            if let Some(previous) = keys[field.index()] {
                return Err(repeats(entry.key_span.as_ref(), &entry.key, previous));
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
        if let Some(problem) = spread_keys_problem(&spread_keys, position.len(), kind.is_surface())
        {
            return Err(self.error(
                first_spread_span,
                Some(path.clone()),
                format!("key {problem}"),
            ));
        }
        let mut spreads = [None::<f64>; 9];
        for (k, node) in spread_nodes.iter().enumerate() {
            if let Some(node) = node {
                let field = format!("{path}.{}", spread_keys[k].unwrap_or_default());
                let value = self.number(node, &field)?;
                let value = check_spread_value(value)
                    .map_err(|m| self.error(node.span.as_ref(), Some(field), m))?;
                spreads[k] = Some(value);
            }
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
        let mut present: Vec<&str> = [Field::Truth, Field::Indeterminacy, Field::Falsity]
            .into_iter()
            .filter(|f| node(*f).is_some())
            .map(Field::name)
            .collect();
        present.extend(
            WIDE_CHANNELS
                .iter()
                .zip(&wide_nodes)
                .filter(|(_, n)| n.is_some())
                .map(|(c, _)| *c),
        );
        if let Some(message) = channel_problem(membership, &present, "key") {
            let span = present
                .iter()
                .find(|name| message.starts_with(&format!("key `{name}`")))
                .and_then(|name| match wide_channel(name, false) {
                    Some(c) => wide_nodes[c],
                    None => Field::from_name(name, false).and_then(node),
                })
                .and_then(|n| n.span.as_ref())
                .or(item.span.as_ref());
            return Err(self.error(span, Some(path.clone()), message));
        }
        let (degrees, second) = if membership.fits_degrees() {
            (self.degrees(item, &path, membership, &node, &value)?, None)
        } else {
            let mut values = [0.0; 9 + 3];
            for (c, n) in wide_nodes.iter().enumerate() {
                if let Some(n) = n {
                    values[c] = self.number(n, &format!("{path}.{}", WIDE_CHANNELS[c]))?;
                }
            }
            for (k, f) in [Field::Truth, Field::Indeterminacy, Field::Falsity]
                .into_iter()
                .enumerate()
            {
                values[9 + k] = value(f)?.unwrap_or_default();
            }
            let (first, second) = wide_lanes(membership, |name| {
                wide_channel(name, false)
                    .or_else(|| Field::from_name(name, false).map(|f| 9 + f.index() - 3))
                    .map(|i| values[i])
            })
            .map_err(|e| self.error(item.span.as_ref(), Some(path.clone()), e.to_string()))?;
            (first, Some(second))
        };
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
            second,
            weight,
            origin: Origin {
                line: self.line(item.span.as_ref()),
                field: Some(path),
            },
            weight_origin,
            spread: spread_from_values(&spreads),
        })
    }

    /// The degrees of a control point of a family of one lane, validated by its rule and
    /// located at the key that breaks it.
    fn degrees<'n>(
        &self,
        item: &Node,
        path: &str,
        membership: Family,
        node: &dyn Fn(Field) -> Option<&'n Node>,
        value: &dyn Fn(Field) -> Result<Option<f64>, InputError>,
    ) -> Result<Degrees, InputError> {
        let path = path.to_owned();
        let truth = value(Field::Truth)?.ok_or_else(|| {
            self.error(
                item.span.as_ref(),
                Some(path.clone()),
                "missing key `truth` (every membership rule requires it)".to_owned(),
            )
        })?;
        Degrees::with_membership(
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
                | DegreeError::NotCarried { kind, .. } => (at(*kind), e.to_string()),
                DegreeError::HesitationMismatch { .. } => {
                    (at(DegreeKind::Indeterminacy), e.to_string())
                }
                _ => (item.span.as_ref(), e.to_string()),
            };
            self.error(span, Some(path.clone()), message)
        })
    }
}
