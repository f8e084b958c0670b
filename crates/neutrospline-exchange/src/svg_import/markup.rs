//! The element walk: the drawn `<path>`, `<polyline>` and `<polygon>` elements of the
//! markup, their attributes, lines and the matrices of their `transform`s.

use neutrospline_io::{InputError, ReadError};

use super::transform::{compose, transform, Matrix, IDENTITY};

/// Elements whose content is not drawn where it stands.
pub(super) const NOT_DRAWN: [&str; 6] = ["defs", "clipPath", "mask", "marker", "pattern", "symbol"];

/// A drawn element with curves: its name, attributes and the line of its `<`.
pub(super) struct Element {
    pub(super) name: String,
    pub(super) attributes: Vec<(String, String)>,
    pub(super) line: usize,
    pub(super) matrix: Matrix,
}

/// The text with `&amp;`, `&lt;`, `&gt;`, `&quot;`, `&apos;` and character references
/// replaced; an unknown entity is kept as written.
pub(super) fn unescape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(at) = rest.find('&') {
        out.push_str(&rest[..at]);
        rest = &rest[at..];
        let end = rest.find(';').unwrap_or(0);
        let entity = &rest[1..end.max(1)];
        let c = match entity {
            "amp" => Some('&'),
            "lt" => Some('<'),
            "gt" => Some('>'),
            "quot" => Some('"'),
            "apos" => Some('\''),
            _ => entity
                .strip_prefix("#x")
                .map(|h| u32::from_str_radix(h, 16).ok())
                .or_else(|| entity.strip_prefix('#').map(|d| d.parse::<u32>().ok()))
                .flatten()
                .and_then(char::from_u32),
        };
        match (end, c) {
            (end, Some(c)) if end > 0 => {
                out.push(c);
                rest = &rest[end + 1..];
            }
            _ => {
                out.push('&');
                rest = &rest[1..];
            }
        }
    }
    out.push_str(rest);
    out
}

/// Where each line starts, to turn byte offsets into line numbers.
pub(super) struct Lines(Vec<usize>);

impl Lines {
    fn new(text: &str) -> Lines {
        let mut starts = vec![0];
        starts.extend(text.match_indices('\n').map(|(k, _)| k + 1));
        Lines(starts)
    }

    /// The 1-based line of byte `offset`.
    fn of(&self, offset: usize) -> usize {
        self.0.partition_point(|&s| s <= offset)
    }
}

/// The drawn `<path>`, `<polyline>` and `<polygon>` elements, in document order, each with the
/// matrix of its own and its ancestors' `transform`s.
pub(super) fn elements(file: &str, text: &str) -> Result<Vec<Element>, ReadError> {
    let lines = Lines::new(text);
    let at = |offset: usize, message: String| -> ReadError {
        InputError::new(file, Some(lines.of(offset)), None, message).into()
    };
    // Open elements: name, matrix, whether drawn.
    let mut stack: Vec<(String, Matrix, bool)> = Vec::new();
    let mut out = Vec::new();
    let mut k = 0;
    while let Some(found) = text[k..].find('<') {
        let start = k + found;
        let rest = &text[start..];
        let skip_to = |end: &str, what: &str| -> Result<usize, ReadError> {
            rest.find(end)
                .map(|e| start + e + end.len())
                .ok_or_else(|| at(start, format!("{what} is not closed (no `{end}`)")))
        };
        if rest.starts_with("<!--") {
            k = skip_to("-->", "a comment `<!--`")?;
            continue;
        }
        if rest.starts_with("<![CDATA[") {
            k = skip_to("]]>", "a CDATA section")?;
            continue;
        }
        if rest.starts_with("<?") {
            k = skip_to("?>", "a processing instruction `<?`")?;
            continue;
        }
        if rest.starts_with("<!") {
            // A document type declaration, possibly with an internal subset in brackets.
            let mut depth = 0usize;
            let end = rest.char_indices().find(|&(_, c)| {
                match c {
                    '[' => depth += 1,
                    ']' => depth = depth.saturating_sub(1),
                    '>' if depth == 0 => return true,
                    _ => {}
                }
                false
            });
            k = start
                + end
                    .ok_or_else(|| at(start, "a declaration `<!` is not closed".to_owned()))?
                    .0
                + 1;
            continue;
        }
        // A tag: find its end outside quoted attribute values.
        let mut quote = None;
        let end = rest
            .char_indices()
            .skip(1)
            .find(|&(_, c)| {
                match (quote, c) {
                    (None, '"' | '\'') => quote = Some(c),
                    (Some(q), c) if c == q => quote = None,
                    (None, '>') => return true,
                    _ => {}
                }
                false
            })
            .ok_or_else(|| at(start, "a tag `<` is not closed (no `>`)".to_owned()))?
            .0;
        k = start + end + 1;
        let tag = &rest[1..end];
        if let Some(name) = tag.strip_prefix('/') {
            let name = name.trim();
            match stack.pop() {
                Some((open, _, _)) if open == name => {}
                Some((open, _, _)) => {
                    return Err(at(start, format!("`</{name}>` closes `<{open}>`")));
                }
                None => return Err(at(start, format!("`</{name}>` closes no element"))),
            }
            continue;
        }
        let self_closing = tag.ends_with('/');
        let tag = tag.strip_suffix('/').unwrap_or(tag);
        let name_end = tag.find(|c: char| c.is_whitespace()).unwrap_or(tag.len());
        let name = &tag[..name_end];
        let attributes =
            attributes(&tag[name_end..]).map_err(|m| at(start, format!("<{name}>: {m}")))?;
        let (parent_matrix, parent_drawn) =
            stack.last().map_or((IDENTITY, true), |(_, m, d)| (*m, *d));
        let own = match attributes.iter().find(|(n, _)| n == "transform") {
            Some((_, value)) => {
                transform(value).map_err(|m| at(start, format!("<{name}> transform: {m}")))?
            }
            None => IDENTITY,
        };
        let matrix = compose(&parent_matrix, &own);
        let drawn = parent_drawn && !NOT_DRAWN.contains(&name);
        if drawn && matches!(name, "path" | "polyline" | "polygon") {
            out.push(Element {
                name: name.to_owned(),
                attributes: attributes.clone(),
                line: lines.of(start),
                matrix,
            });
        }
        if !self_closing {
            stack.push((name.to_owned(), matrix, drawn));
        }
    }
    Ok(out)
}

/// The attributes of a tag: `name="value"` or `name='value'`, values unescaped.
pub(super) fn attributes(text: &str) -> Result<Vec<(String, String)>, String> {
    let mut out = Vec::new();
    let mut rest = text.trim_start();
    while !rest.is_empty() {
        let eq = rest
            .find('=')
            .ok_or_else(|| format!("attribute `{}` has no value", rest.trim()))?;
        let name = rest[..eq].trim();
        let after = rest[eq + 1..].trim_start();
        let quote = after
            .chars()
            .next()
            .filter(|c| *c == '"' || *c == '\'')
            .ok_or_else(|| format!("the value of attribute `{name}` is not in quotes"))?;
        let close = after[1..]
            .find(quote)
            .ok_or_else(|| format!("the value of attribute `{name}` is not closed"))?;
        out.push((name.to_owned(), unescape(&after[1..1 + close])));
        rest = after[close + 2..].trim_start();
    }
    Ok(out)
}
