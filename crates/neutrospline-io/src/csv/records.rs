//! The rows of a CSV stream, read by one `csv` reader over [`Input`].

use std::io::BufRead;

use super::input::{Input, Located};
use crate::InputError;

/// The rows of a CSV stream, read by one `csv` reader: cells trimmed, rows of any length,
/// comments (a line starting with `#` where a row could start, up to its `\n`), empty lines
/// and lines of whitespace skipped, a UTF-8 byte order mark dropped, rows ending at `\n`,
/// `\r\n` or `\r` (as Python's `csv` module and spreadsheets read them). Quoting is the `csv`
/// crate's and Python's: a cell that starts with `"` is quoted (`""` inside it is one quote,
/// line ends inside it are kept), a quote anywhere else is an ordinary character (`C"0` is the
/// name `C"0`).
///
/// Only one row is held in memory; every error is located: the rows' lines come from the
/// reader's own [`::csv::Position`], physical lines counted by `\n` (comments and empty lines
/// included), a row's line being the one it starts on.
pub(crate) struct Records<R> {
    pub(super) reader: ::csv::Reader<Input<R>>,
    /// The byte between cells.
    delimiter: u8,
    row: ::csv::StringRecord,
    done: bool,
    /// The number of cells of the first row (the header), once read.
    header_cells: Option<usize>,
}

/// The delimiter of the header row, found in what `reader` has buffered (without consuming
/// it): the first line that is not empty or a comment, outside quotes, holds a comma (`,`),
/// else a tab, else a semicolon (as spreadsheets save CSV in locales with a decimal comma);
/// a comma when it holds none of them or the buffer cannot be read.
pub(crate) fn detect_delimiter(reader: &mut impl BufRead) -> u8 {
    let Ok(buffer) = reader.fill_buf() else {
        return b',';
    };
    let buffer = buffer.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(buffer);
    let header = buffer
        .split(|&b| b == b'\n' || b == b'\r')
        .find(|line| {
            let line = line.trim_ascii_start();
            !line.is_empty() && !line.starts_with(b"#")
        })
        .unwrap_or_default();
    let mut quoted = false;
    let mut found = [false; 3];
    for &b in header {
        match b {
            b'"' => quoted = !quoted,
            b',' if !quoted => found[0] = true,
            b'\t' if !quoted => found[1] = true,
            b';' if !quoted => found[2] = true,
            _ => {}
        }
    }
    [b',', b'\t', b';']
        .into_iter()
        .zip(found)
        .find_map(|(d, f)| f.then_some(d))
        .unwrap_or(b',')
}

impl<R: BufRead> Records<R> {
    /// Records from the start of `reader`, cells separated by `delimiter` (by the one
    /// [`detect_delimiter`] finds when `None`).
    pub(crate) fn new(mut reader: R, delimiter: Option<u8>) -> Records<R> {
        let delimiter = delimiter.unwrap_or_else(|| detect_delimiter(&mut reader));
        let reader = ::csv::ReaderBuilder::new()
            .delimiter(delimiter)
            .has_headers(false)
            .flexible(true)
            .trim(::csv::Trim::None)
            .comment(Some(b'#'))
            .terminator(::csv::Terminator::CRLF)
            .from_reader(Input::new(reader));
        Records {
            reader,
            delimiter,
            row: ::csv::StringRecord::new(),
            done: false,
            header_cells: None,
        }
    }

    /// The byte between cells.
    pub(crate) fn delimiter(&self) -> u8 {
        self.delimiter
    }

    /// Refuses a comment read since the last row that holds a full row after the header: as
    /// many cells as the header, all but the first of them numbers (`#1,3,6,0.8,0.1,0.1`).
    /// Spreadsheets and Python's `csv` module write a name that starts with `#` unquoted, and
    /// the format reads such a line as a comment: the point would be dropped without a word.
    fn refuse_rows_in_comments(&mut self, file: &str) -> Result<(), InputError> {
        let input = self.reader.get_mut();
        let mut comments = std::mem::take(&mut input.comments);
        if self.done && !input.comment.is_empty() {
            // A comment on the last line, without its line end.
            comments.push((
                input.line,
                String::from_utf8_lossy(&input.comment).into_owned(),
            ));
            input.comment.clear();
        }
        let Some(count) = self.header_cells else {
            return Ok(());
        };
        for (line, text) in comments {
            let body = text.trim_end_matches(['\r', '\n']);
            if count < 3 || body.contains('"') {
                continue;
            }
            let cells: Vec<&str> = body
                .split(char::from(self.delimiter))
                .map(str::trim)
                .collect();
            let numbers = cells[1..]
                .iter()
                .all(|c| !c.is_empty() && c.parse::<f64>().is_ok());
            if cells.len() == count && numbers {
                return Err(InputError::new(
                    file,
                    Some(line),
                    None,
                    format!(
                        "`{body}` starts with `#`, so it is a comment, yet it holds a full row \
                         ({count} cells, as the header): a name that starts with `#` must be \
                         quoted (`\"{first}\"`), and a row to leave out must be deleted (a \
                         comment would drop it without a word)",
                        first = cells[0]
                    ),
                ));
            }
        }
        Ok(())
    }

    /// The next row that is not empty, split into trimmed cells, with the line it starts on;
    /// errors located in `file`.
    pub(crate) fn next_cells(
        &mut self,
        file: &str,
    ) -> Result<Option<(usize, ::csv::StringRecord)>, InputError> {
        let at = |line: usize, message: String| InputError::new(file, Some(line), None, message);
        loop {
            if self.done {
                return Ok(None);
            }
            let read = self.reader.read_record(&mut self.row);
            let row_start = self.reader.get_ref().row_start();
            match read {
                Ok(true) => {}
                Ok(false) => {
                    self.done = true;
                    self.refuse_rows_in_comments(file)?;
                    return Ok(None);
                }
                Err(e) => {
                    self.done = true;
                    let line = e.position().map_or(1, |p| p.line() as usize);
                    let line = row_start.unwrap_or(line);
                    let shown = e.to_string();
                    return Err(match e.into_kind() {
                        ::csv::ErrorKind::Io(io) => {
                            match io.get_ref().and_then(|e| e.downcast_ref::<Located>()) {
                                Some(located) => at(located.line, located.message.clone()),
                                None => at(line, format!("cannot read: {io}")),
                            }
                        }
                        ::csv::ErrorKind::Utf8 { .. } => at(
                            line,
                            "invalid UTF-8 (the file must be UTF-8 encoded)".to_owned(),
                        ),
                        _ => at(line, format!("malformed CSV: {shown}")),
                    });
                }
            }
            // The reader's line after the row counts the row's line ends: those inside its
            // quoted cells, and the one that ends it when that is a `\n` (the reader has taken
            // every byte handed over, so it is the last one).
            let end = self.reader.position();
            let inner_ends = self.row.as_slice().bytes().filter(|&b| b == b'\n').count();
            let after = usize::try_from(end.line()).unwrap_or(usize::MAX);
            let input = self.reader.get_ref();
            if input.read_to_the_end(end.byte()) {
                self.done = true;
                if self.row.len() == 1 && &self.row[0] == "\0" {
                    self.refuse_rows_in_comments(file)?;
                    return Ok(None);
                }
                // The file ends inside a quoted cell: the row holds the end mark (a row hidden
                // in a comment before it is the earlier error).
                self.refuse_rows_in_comments(file)?;
                let start = after.saturating_sub(inner_ends);
                debug_assert_eq!(Some(start), row_start);
                return Err(at(
                    start,
                    "the file ends inside a quoted cell of the row starting on this line (a cell \
                     that starts with `\"` ends at the next `\"` that is not doubled)"
                        .to_owned(),
                ));
            }
            let start = after
                .saturating_sub(inner_ends)
                .saturating_sub(usize::from(input.last == b'\n'));
            debug_assert_eq!(Some(start), row_start);
            self.reader.get_mut().row_ended();
            self.row.trim();
            if self.row.len() == 1 && self.row[0].is_empty() {
                continue;
            }
            self.refuse_rows_in_comments(file)?;
            if self.header_cells.is_none() {
                self.header_cells = Some(self.row.len());
            }
            return Ok(Some((start, self.row.clone())));
        }
    }
}
