//! The bytes the `csv` reader sees: the stream checked line by line (UTF-8, line and row
//! lengths), its comments kept, with the line each row starts on.

use std::io::{BufRead, Read};

use crate::format::MAX_CSV_LINE;

/// The bytes the CSV reader adds after the end of the input, one per `read`: a line end that
/// ends the last row when the file does not, and a NUL byte. The NUL byte reads as a row of
/// its own, unless the file ends inside a quoted cell: then both bytes are in that cell, and
/// the row is refused (the `csv` crate itself ends such a cell at the end of the input without
/// a word).
const END_MARK: &[u8] = b"\n\0";

/// A located problem found by [`Input`]: the line and the message. It travels through the
/// `csv` reader as the payload of an [`std::io::Error`].
#[derive(Debug, Clone)]
pub(super) struct Located {
    pub(super) line: usize,
    pub(super) message: String,
}

impl std::fmt::Display for Located {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "line {}: {}", self.line, self.message)
    }
}

impl std::error::Error for Located {}

/// Where [`Input`] is: between rows (empty lines), in a comment, or in a row.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Place {
    Between,
    Comment,
    /// In the row that starts on line `start`, `bytes` long so far (line ends included).
    Row {
        start: usize,
        bytes: usize,
    },
}

/// The input as the CSV reader sees it: the stream without its UTF-8 byte order mark, handed
/// over in pieces that end at the first `\r` or `\n` at most, then [`END_MARK`]. On the way it
/// refuses, with the line: bytes that are not UTF-8 (comments included), a line longer than
/// [`MAX_CSV_LINE`] bytes, and a row (a quoted cell may span lines) longer than that.
///
/// A row ends at a `\r` or `\n` outside quotes, the last byte of a piece, so when the CSV
/// reader returns a row it has taken every byte handed over (and [`Input::row_ended`] is
/// called): what follows starts a row, or something the reader skips between rows (a `\r` or
/// `\n`, or a comment: `#` first, up to the next `\n`). So the input knows where each row
/// starts, and counts its bytes.
pub(super) struct Input<R> {
    pub(super) inner: R,
    /// The physical line (1-based, lines end at `\n`) of the next byte.
    pub(super) line: usize,
    /// The bytes of the current physical line so far.
    line_bytes: usize,
    /// Whether the last piece ended with `\r` or `\n` (true at the start).
    piece_start: bool,
    /// The last byte handed over.
    pub(super) last: u8,
    place: Place,
    /// Whether the byte order mark has been looked for.
    began: bool,
    /// The last bytes handed over when they end inside a UTF-8 sequence (at most 3).
    partial: Vec<u8>,
    /// The bytes handed over, [`END_MARK`] included.
    handed: u64,
    /// How much of [`END_MARK`] has been handed over.
    end_mark: usize,
    /// The first problem: every later `read` repeats it.
    failed: Option<Located>,
    /// The comment being read, and the comments read since the last row, with their lines.
    pub(super) comment: Vec<u8>,
    pub(super) comments: Vec<(usize, String)>,
}

impl<R: BufRead> Input<R> {
    pub(super) fn new(inner: R) -> Input<R> {
        Input {
            inner,
            line: 1,
            line_bytes: 0,
            piece_start: true,
            last: b'\n',
            place: Place::Between,
            began: false,
            partial: Vec::new(),
            handed: 0,
            end_mark: 0,
            failed: None,
            comment: Vec::new(),
            comments: Vec::new(),
        }
    }

    /// The reader has read a row: what follows is between rows.
    pub(super) fn row_ended(&mut self) {
        self.place = Place::Between;
    }

    /// The line the current row started on, when in a row.
    pub(super) fn row_start(&self) -> Option<usize> {
        match self.place {
            Place::Row { start, .. } => Some(start),
            Place::Between | Place::Comment => None,
        }
    }

    /// Whether the CSV reader, having read `consumed` bytes, has read all of [`END_MARK`].
    pub(super) fn read_to_the_end(&self, consumed: u64) -> bool {
        self.end_mark == END_MARK.len() && consumed == self.handed
    }

    fn fail(&mut self, line: usize, message: String) -> std::io::Error {
        let located = Located { line, message };
        self.failed = Some(located.clone());
        std::io::Error::new(std::io::ErrorKind::InvalidData, located)
    }

    fn invalid_utf8(&mut self) -> std::io::Error {
        self.fail(
            self.line,
            "invalid UTF-8 (the file must be UTF-8 encoded)".to_owned(),
        )
    }

    /// Checks that `piece` continues valid UTF-8 (a sequence may be cut at its end).
    fn check_utf8(&mut self, piece: &[u8]) -> std::io::Result<()> {
        let joined;
        let bytes = if self.partial.is_empty() {
            piece
        } else {
            joined = [self.partial.as_slice(), piece].concat();
            &joined
        };
        match std::str::from_utf8(bytes) {
            Ok(_) => self.partial.clear(),
            Err(e) if e.error_len().is_none() => self.partial = bytes[e.valid_up_to()..].to_vec(),
            Err(_) => return Err(self.invalid_utf8()),
        }
        Ok(())
    }

    /// Follows the CSV reader's rule for what `piece` is (`::csv::ReaderBuilder::comment`,
    /// `Terminator::CRLF`), and refuses a line or a row over the limit.
    fn account(&mut self, piece: &[u8]) -> std::io::Result<()> {
        if self.piece_start && self.place == Place::Between {
            self.place = match piece[0] {
                b'\r' | b'\n' => Place::Between,
                b'#' => Place::Comment,
                _ => Place::Row {
                    start: self.line,
                    bytes: 0,
                },
            };
        }
        self.line_bytes += piece.len();
        if self.line_bytes > MAX_CSV_LINE {
            return Err(self.fail(
                self.line,
                format!(
                    "the line is longer than {MAX_CSV_LINE} bytes (a row of control point values \
                     is short; is this a CSV file?)"
                ),
            ));
        }
        if let Place::Row { start, bytes } = &mut self.place {
            *bytes += piece.len();
            if *bytes > MAX_CSV_LINE {
                let start = *start;
                return Err(self.fail(
                    start,
                    format!(
                        "the row starting on this line is longer than {MAX_CSV_LINE} bytes at \
                         line {} (a row of control point values is short; is a quoted cell \
                         never closed?)",
                        self.line
                    ),
                ));
            }
        }
        self.check_utf8(piece)?;
        if self.place == Place::Comment {
            self.comment.extend_from_slice(piece);
        }
        let last = piece[piece.len() - 1];
        self.piece_start = matches!(last, b'\r' | b'\n');
        if last == b'\n' {
            if self.place == Place::Comment {
                self.place = Place::Between;
                let text = String::from_utf8_lossy(&self.comment).into_owned();
                self.comments.push((self.line, text));
                self.comment.clear();
            }
            self.line += 1;
            self.line_bytes = 0;
        }
        self.last = last;
        self.handed += piece.len() as u64;
        Ok(())
    }
}

impl<R: BufRead> Read for Input<R> {
    fn read(&mut self, out: &mut [u8]) -> std::io::Result<usize> {
        if let Some(located) = &self.failed {
            return Err(std::io::Error::new(
                std::io::ErrorKind::InvalidData,
                located.clone(),
            ));
        }
        if out.is_empty() || self.end_mark == END_MARK.len() {
            return Ok(0);
        }
        if self.end_mark > 0 {
            out[0] = END_MARK[self.end_mark];
            self.end_mark += 1;
            self.last = out[0];
            self.handed += 1;
            return Ok(1);
        }
        let line = self.line;
        let available = match self.inner.fill_buf() {
            Ok(available) => available,
            Err(e) => return Err(self.fail(line, format!("cannot read: {e}"))),
        };
        if !self.began {
            self.began = true;
            if available.starts_with(b"\xEF\xBB\xBF") {
                self.inner.consume(3);
                return self.read(out);
            }
        }
        if available.is_empty() {
            if !self.partial.is_empty() {
                return Err(self.invalid_utf8());
            }
            out[0] = END_MARK[0];
            self.end_mark = 1;
            self.last = out[0];
            self.handed += 1;
            return Ok(1);
        }
        let length = available
            .iter()
            .position(|&b| matches!(b, b'\r' | b'\n'))
            .map_or(available.len(), |i| i + 1)
            .min(out.len());
        out[..length].copy_from_slice(&available[..length]);
        self.inner.consume(length);
        self.account(&out[..length])?;
        Ok(length)
    }
}
