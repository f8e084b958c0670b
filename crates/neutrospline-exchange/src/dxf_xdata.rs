//! What a DXF entity cannot hold of a model, kept as extended data (XDATA) under the
//! application name `NEUTROSPLINE`: written by the DXF exporter, read back by the importer.
//!
//! The layout (group code, value), after `1001 NEUTROSPLINE`:
//!
//! ```text
//! 1000 neutrospline 1            the layout's version
//! 1000 kind          1000 bezier | bspline | nurbs | bezier-surface | ...
//! 1000 dimension     1070 2 | 3
//! 1000 membership    1000 the family: neutrosophic | intuitionistic | fuzzy | pythagorean | q-rung:4 | ...
//! 1000 name          1071 K, then K strings 1000          (optional)
//! 1000 description   1071 K, then K strings 1000          (optional)
//! 1000 degrees       1071 N, then N times 1040 truth, 1040 indeterminacy, 1040 falsity
//! 1000 truth_lower   1071 N, then N times 1040 (a family of two lanes, `Family::lanes`:
//!                    one such key per channel, by its name, in place of `degrees`)
//! 1000 point names   1071 N, then per point 1071 K (-1: no name) and K strings 1000 (optional)
//! ```
//!
//! A string is cut into pieces of at most 255 bytes (AutoCAD's limit for a 1000 string), in
//! ASCII: `^` followed by a character for a control character (`^J` a line feed, `^ ` the
//! caret itself) and `\U+XXXX` for a backslash and every character outside ASCII (UTF-16
//! surrogate pairs beyond U+FFFF), as DXF R2000 writes text. Reals are written in the shortest
//! form that reads back to the same `f64`, so the degrees come back to the last bit.

use neutrospline::{Degrees, Family};

use neutrospline_io::Kind;

/// The application name of the extended data.
pub(crate) const APP: &str = "NEUTROSPLINE";
/// The first string of the extended data: its layout and version.
pub(crate) const VERSION: &str = "neutrospline 1";
/// The most bytes of a 1000 string.
const MAX_STRING: usize = 255;

/// A value of the extended data, with its group code.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum XValue {
    /// 1000: a string.
    Text(String),
    /// 1070: a 16-bit integer.
    Short(i16),
    /// 1071: a 32-bit integer.
    Long(i32),
    /// 1040: a real.
    Real(f64),
}

#[cfg(test)]
impl XValue {
    /// The group code.
    pub(crate) fn code(&self) -> u16 {
        match self {
            XValue::Text(_) => 1000,
            XValue::Short(_) => 1070,
            XValue::Long(_) => 1071,
            XValue::Real(_) => 1040,
        }
    }
}

/// What the extended data of a curve (or a mesh) says about its model.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct ModelInfo {
    pub kind: Kind,
    pub dimension: usize,
    pub membership: Family,
    pub name: Option<String>,
    pub description: Option<String>,
    /// One triple per control point (empty for a mesh, whose vertices carry their own).
    pub degrees: Vec<Degrees>,
    /// One per control point, or empty when no point has a name.
    pub point_names: Vec<Option<String>>,
    /// A family of two lanes: each channel by its name, with one value per control point
    /// (in place of `degrees`); empty otherwise.
    pub channels: Vec<(String, Vec<f64>)>,
}

/// `text` in the escaped ASCII form, in pieces of at most [`MAX_STRING`] bytes.
pub(crate) fn encode_text(text: &str) -> Vec<String> {
    let mut pieces = vec![String::new()];
    let mut units = [0u16; 2];
    for c in text.chars() {
        let token = match c {
            '^' => "^ ".to_owned(),
            '\u{7f}' => "^?".to_owned(),
            c if u32::from(c) < 0x20 => format!("^{}", char::from(c as u8 + 64)),
            c if c.is_ascii() && c != '\\' => c.to_string(),
            c => c
                .encode_utf16(&mut units)
                .iter()
                .map(|u| format!("\\U+{u:04X}"))
                .collect(),
        };
        let last = pieces.last_mut().expect("one piece at least");
        if last.len() + token.len() > MAX_STRING {
            pieces.push(token);
        } else {
            last.push_str(&token);
        }
    }
    pieces
}

/// The text of escaped pieces ([`encode_text`]); a `\U+` not followed by four hexadecimal
/// digits, and a lone surrogate, are kept as written.
pub(crate) fn decode_text(pieces: &[&str]) -> String {
    let joined: String = pieces.concat();
    let chars: Vec<char> = joined.chars().collect();
    let mut units: Vec<u16> = Vec::with_capacity(chars.len());
    let mut k = 0;
    let hex = |k: usize| -> Option<u16> {
        let digits: String = chars.get(k + 3..k + 7)?.iter().collect();
        (chars[k + 1] == 'U' && chars[k + 2] == '+' && digits.len() == 4)
            .then(|| u16::from_str_radix(&digits, 16).ok())
            .flatten()
    };
    while k < chars.len() {
        let c = chars[k];
        match (c, chars.get(k + 1)) {
            ('^', Some(' ')) => {
                units.push(u16::from(b'^'));
                k += 2;
            }
            ('^', Some('?')) => {
                units.push(0x7f);
                k += 2;
            }
            ('^', Some(&n)) if ('@'..='_').contains(&n) => {
                units.push(n as u16 - 64);
                k += 2;
            }
            ('\\', Some('U')) if hex(k).is_some() => {
                units.extend(hex(k));
                k += 7;
            }
            (c, _) => {
                let mut buf = [0u16; 2];
                units.extend_from_slice(c.encode_utf16(&mut buf));
                k += 1;
            }
        }
    }
    String::from_utf16_lossy(&units)
}

impl ModelInfo {
    /// The extended data, after `1001 NEUTROSPLINE`.
    pub(crate) fn to_values(&self) -> Vec<XValue> {
        let text = |s: &str| XValue::Text(s.to_owned());
        let count = |n: usize| XValue::Long(i32::try_from(n).unwrap_or(i32::MAX));
        let mut out = vec![
            text(VERSION),
            text("kind"),
            text(self.kind.name()),
            text("dimension"),
            XValue::Short(if self.dimension == 2 { 2 } else { 3 }),
            text("membership"),
            text(&self.membership.to_string()),
        ];
        let long_text = |out: &mut Vec<XValue>, value: &str| {
            let pieces = encode_text(value);
            out.push(count(pieces.len()));
            out.extend(pieces.into_iter().map(XValue::Text));
        };
        for (key, value) in [("name", &self.name), ("description", &self.description)] {
            if let Some(value) = value {
                out.push(text(key));
                long_text(&mut out, value);
            }
        }
        if !self.degrees.is_empty() {
            out.push(text("degrees"));
            out.push(count(self.degrees.len()));
            for d in &self.degrees {
                out.extend(d.to_array().map(XValue::Real));
            }
        }
        for (name, values) in &self.channels {
            out.push(text(name));
            out.push(count(values.len()));
            out.extend(values.iter().copied().map(XValue::Real));
        }
        if self.point_names.iter().any(Option::is_some) {
            out.push(text("point names"));
            out.push(count(self.point_names.len()));
            for name in &self.point_names {
                match name {
                    Some(name) => long_text(&mut out, name),
                    None => out.push(XValue::Long(-1)),
                }
            }
        }
        out
    }
}

/// One tag of the extended data as read: group code, value, line of the group code.
pub(crate) type XTag<'a> = (u16, &'a str, usize);

/// Reads [`ModelInfo::to_values`] back. `tags` follow `1001 NEUTROSPLINE`; `fallback_line` is
/// where an error is reported when the data ends early.
///
/// # Errors
/// The line and a message for the first tag that is not where the layout has it.
pub(crate) fn read(tags: &[XTag<'_>], fallback_line: usize) -> Result<ModelInfo, (usize, String)> {
    let mut reader = Reader {
        tags,
        next: 0,
        fallback_line,
    };
    let version = reader.text()?;
    if version.1 != VERSION {
        return Err((
            version.0,
            format!(
                "extended data `{}` of an unknown layout (this version reads `{VERSION}`)",
                version.1
            ),
        ));
    }
    let mut info = ModelInfo {
        kind: Kind::DEFAULT,
        dimension: 3,
        membership: Family::Neutrosophic,
        name: None,
        description: None,
        degrees: Vec::new(),
        point_names: Vec::new(),
        channels: Vec::new(),
    };
    let mut seen_kind = false;
    while reader.next < tags.len() {
        let (line, key) = reader.text()?;
        match key {
            "kind" => {
                let (line, name) = reader.text()?;
                info.kind = Kind::from_name(name).ok_or_else(|| {
                    (
                        line,
                        format!("kind `{name}` is not known (known: {})", Kind::known_list()),
                    )
                })?;
                seen_kind = true;
            }
            "dimension" => {
                let (line, d) = reader.number(1070)?;
                if d != 2 && d != 3 {
                    return Err((line, format!("dimension {d} is neither 2 nor 3")));
                }
                info.dimension = d as usize;
            }
            "membership" => {
                let (line, name) = reader.text()?;
                info.membership = name.parse().map_err(|e| (line, format!("{e}")))?;
            }
            "name" => info.name = reader.long_text()?,
            "description" => info.description = reader.long_text()?,
            "degrees" => {
                let (_, n) = reader.count()?;
                info.degrees = (0..n)
                    .map(|_| {
                        let (line, t) = reader.real()?;
                        let (_, i) = reader.real()?;
                        let (_, f) = reader.real()?;
                        Degrees::new(t, i, f).map_err(|e| (line, e.to_string()))
                    })
                    .collect::<Result<_, _>>()?;
            }
            "point names" => {
                let (_, n) = reader.count()?;
                info.point_names = (0..n)
                    .map(|_| reader.long_text())
                    .collect::<Result<_, _>>()?;
            }
            channel
                if info.membership.lane_count() == 2
                    && info.membership.channels().contains(&channel) =>
            {
                if info.channels.iter().any(|(name, _)| name == channel) {
                    return Err((line, format!("the channel `{channel}` is given twice")));
                }
                let (_, n) = reader.count()?;
                let values = (0..n)
                    .map(|_| reader.real().map(|(_, v)| v))
                    .collect::<Result<_, _>>()?;
                info.channels.push((channel.to_owned(), values));
            }
            other => {
                let channels = if info.membership.lane_count() == 2 {
                    format!(", {}", info.membership.channels().join(", "))
                } else {
                    String::new()
                };
                return Err((
                    line,
                    format!(
                        "unknown key `{other}` (known: kind, dimension, membership, name, \
                         description, degrees, point names{channels})"
                    ),
                ));
            }
        }
    }
    if !seen_kind {
        return Err((fallback_line, "the extended data has no `kind`".to_owned()));
    }
    Ok(info)
}

struct Reader<'a, 'b> {
    tags: &'b [XTag<'a>],
    next: usize,
    fallback_line: usize,
}

impl<'a> Reader<'a, '_> {
    fn take(&mut self, code: u16, what: &str) -> Result<(usize, &'a str), (usize, String)> {
        match self.tags.get(self.next) {
            Some(&(c, value, line)) if c == code => {
                self.next += 1;
                Ok((line, value))
            }
            Some(&(c, value, line)) => Err((
                line,
                format!("group code {c} = `{value}` where the extended data has {what} (group code {code})"),
            )),
            None => Err((
                self.fallback_line,
                format!("the extended data ends where it has {what} (group code {code})"),
            )),
        }
    }

    fn text(&mut self) -> Result<(usize, &'a str), (usize, String)> {
        self.take(1000, "a string")
    }

    fn number(&mut self, code: u16) -> Result<(usize, i64), (usize, String)> {
        let (line, value) = self.take(code, "an integer")?;
        let n = value.trim().parse::<i64>().map_err(|_| {
            (
                line,
                format!("group code {code} = `{value}` is not an integer"),
            )
        })?;
        Ok((line, n))
    }

    fn count(&mut self) -> Result<(usize, usize), (usize, String)> {
        let (line, n) = self.number(1071)?;
        let n = usize::try_from(n).map_err(|_| (line, format!("count {n} is negative")))?;
        // Every counted item takes a tag at least: a count beyond the tags left is wrong.
        if n > self.tags.len() - self.next {
            return Err((
                line,
                format!(
                    "count {n} is more than the {} tags that follow",
                    self.tags.len() - self.next
                ),
            ));
        }
        Ok((line, n))
    }

    fn real(&mut self) -> Result<(usize, f64), (usize, String)> {
        let (line, value) = self.take(1040, "a real")?;
        let v = value
            .trim()
            .parse::<f64>()
            .map_err(|_| (line, format!("group code 1040 = `{value}` is not a number")))?;
        Ok((line, v))
    }

    fn long_text(&mut self) -> Result<Option<String>, (usize, String)> {
        let (line, k) = self.number(1071)?;
        if k == -1 {
            return Ok(None);
        }
        let k = usize::try_from(k)
            .map_err(|_| (line, format!("count {k} is negative (-1 is no text)")))?;
        let pieces = (0..k)
            .map(|_| self.text().map(|t| t.1))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Some(decode_text(&pieces)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use neutrospline::CurveKind;

    #[test]
    fn text_round_trip() {
        for text in [
            "",
            "Example 1",
            "a^b\\U+0041\nc\t\u{7f}",
            "caf\u{e9} \u{1F600} \u{4e2d}",
            &"x".repeat(600),
            &"\u{e9}".repeat(100),
        ] {
            let pieces = encode_text(text);
            assert!(
                pieces.iter().all(|p| p.len() <= MAX_STRING && p.is_ascii()),
                "{pieces:?}"
            );
            let refs: Vec<&str> = pieces.iter().map(String::as_str).collect();
            assert_eq!(decode_text(&refs), text);
        }
        assert_eq!(encode_text("a\nb^"), ["a^Jb^ "]);
        assert_eq!(encode_text("\u{e9}"), ["\\U+00E9"]);
        assert_eq!(decode_text(&["\\U+12", "x^"]), "\\U+12x^");
    }

    /// The tags of `values` as a reader sees them (lines 100, 102, ...).
    fn texts(values: &[XValue]) -> Vec<String> {
        values
            .iter()
            .map(|v| match v {
                XValue::Text(s) => s.clone(),
                XValue::Short(n) => n.to_string(),
                XValue::Long(n) => n.to_string(),
                XValue::Real(r) => neutrospline_io::format_number(*r),
            })
            .collect()
    }

    /// A family of two lanes: every channel by its name, read back to the bit; a channel
    /// missing from the family's names is an unknown key naming the channels, and a channel
    /// given twice is refused.
    #[test]
    fn channels_of_a_wide_family_round_trip() {
        let info = ModelInfo {
            kind: Kind::Curve(CurveKind::Bezier),
            dimension: 2,
            membership: Family::IntervalType2,
            name: None,
            description: None,
            degrees: Vec::new(),
            point_names: Vec::new(),
            channels: vec![
                ("truth_lower".into(), vec![0.1, 0.30000000000000004]),
                ("truth_upper".into(), vec![0.2, 0.7]),
            ],
        };
        let values = info.to_values();
        let strings = texts(&values);
        assert_eq!(
            strings[7..],
            [
                "truth_lower",
                "2",
                "0.1",
                "0.30000000000000004",
                "truth_upper",
                "2",
                "0.2",
                "0.7"
            ]
        );
        let tags: Vec<XTag<'_>> = values
            .iter()
            .zip(&strings)
            .enumerate()
            .map(|(k, (v, t))| (v.code(), t.as_str(), 100 + 2 * k))
            .collect();
        assert_eq!(read(&tags, 99), Ok(info.clone()));
        // `falsity_upper` is not an interval-type2 channel.
        let mut other = strings.clone();
        other[7] = "falsity_upper".into();
        let tags: Vec<XTag<'_>> = values
            .iter()
            .zip(&other)
            .enumerate()
            .map(|(k, (v, t))| (v.code(), t.as_str(), 100 + 2 * k))
            .collect();
        assert_eq!(
            read(&tags, 99).unwrap_err(),
            (
                114,
                "unknown key `falsity_upper` (known: kind, dimension, membership, name, \
                 description, degrees, point names, truth_lower, truth_upper)"
                    .to_owned()
            )
        );
        let mut twice = strings;
        twice[11] = "truth_lower".into();
        let tags: Vec<XTag<'_>> = values
            .iter()
            .zip(&twice)
            .enumerate()
            .map(|(k, (v, t))| (v.code(), t.as_str(), 100 + 2 * k))
            .collect();
        assert_eq!(
            read(&tags, 99).unwrap_err(),
            (122, "the channel `truth_lower` is given twice".to_owned())
        );
    }

    #[test]
    fn model_info_round_trip() {
        let info = ModelInfo {
            kind: Kind::Curve(CurveKind::Nurbs),
            dimension: 2,
            membership: Family::Fuzzy,
            name: Some("n\u{e9}".into()),
            description: None,
            degrees: vec![
                Degrees::fuzzy(0.1).unwrap(),
                Degrees::fuzzy(0.30000000000000004).unwrap(),
            ],
            point_names: vec![None, Some("P1".into())],
            channels: Vec::new(),
        };
        let values = info.to_values();
        let texts: Vec<String> = values
            .iter()
            .map(|v| match v {
                XValue::Text(s) => s.clone(),
                XValue::Short(n) => n.to_string(),
                XValue::Long(n) => n.to_string(),
                XValue::Real(r) => neutrospline_io::format_number(*r),
            })
            .collect();
        let tags: Vec<XTag<'_>> = values
            .iter()
            .zip(&texts)
            .enumerate()
            .map(|(k, (v, t))| (v.code(), t.as_str(), 100 + 2 * k))
            .collect();
        assert_eq!(read(&tags, 99), Ok(info));
        assert_eq!(
            read(&tags[..4], 99).unwrap_err(),
            (
                99,
                "the extended data ends where it has an integer (group code 1070)".to_owned()
            )
        );
    }
}
