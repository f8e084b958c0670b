//! Where a value was read ([`Origin`]: the line, the field path) and the small text helpers every
//! reader shares: numbers as written in files, line numbers, the byte order mark, lists in
//! messages. A leaf module: it imports nothing of the crate.

/// Where something was read: the line and the field path of a point.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub(crate) struct Origin {
    /// Physical 1-based line, when known.
    pub(crate) line: Option<usize>,
    /// Field path such as `control_points[2]`, for models.
    pub(crate) field: Option<String>,
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
