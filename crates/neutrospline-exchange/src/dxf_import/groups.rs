//! The groups of a DXF file: code / value pairs of its text.

/// One group: its code, its value and the line of its code (1-based).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Group<'a> {
    pub code: u16,
    pub value: &'a str,
    pub line: usize,
}

/// The groups of a DXF text: alternate lines of a group code (an integer, spaces allowed
/// around it) and a value (`\r\n` line ends allowed), up to the `0 EOF` group that ends the
/// file. After it only blank lines and DOS end-of-file bytes (0x1A) may follow, as programs
/// write them (Inkscape's R12 files end with a blank line); a file without `0 EOF` may end
/// with 0x1A bytes.
///
/// # Errors
/// A line and a message for a group code that is not an integer, a code without a value, or
/// something other than blank lines after `0 EOF`.
pub(crate) fn groups(text: &str) -> Result<Vec<Group<'_>>, (usize, String)> {
    let mut lines: Vec<&str> = text.lines().collect();
    let end = lines
        .chunks_exact(2)
        .position(|pair| pair[0].trim() == "0" && pair[1].trim() == "EOF");
    match end {
        Some(k) => {
            let after = 2 * k + 2;
            if let Some(extra) = lines[after..].iter().position(|line| {
                !line
                    .trim_matches(|c: char| c.is_whitespace() || c == '\u{1a}')
                    .is_empty()
            }) {
                return Err((
                    after + extra + 1,
                    "the file goes on after its end (`0 EOF`): only blank lines may follow it"
                        .to_owned(),
                ));
            }
            lines.truncate(after);
        }
        None => {
            // A DOS end-of-file byte ends the text.
            while lines.last().is_some_and(|line| {
                line.trim_end_matches('\u{1a}').is_empty() && line.contains('\u{1a}')
            }) {
                lines.pop();
            }
            if let Some(last) = lines.last_mut() {
                *last = last.trim_end_matches('\u{1a}');
            }
        }
    }
    if !lines.len().is_multiple_of(2) {
        return Err((
            lines.len(),
            format!(
                "group code `{}` has no value (the file ends)",
                lines[lines.len() - 1].trim()
            ),
        ));
    }
    lines
        .chunks_exact(2)
        .enumerate()
        .map(|(k, pair)| {
            let line = 2 * k + 1;
            let code = pair[0].trim().parse::<u16>().map_err(|_| {
                (
                    line,
                    format!(
                        "group code `{}` is not an integer from 0 to 1071",
                        pair[0].trim()
                    ),
                )
            })?;
            Ok(Group {
                code,
                value: pair[1],
                line,
            })
        })
        .collect()
}
