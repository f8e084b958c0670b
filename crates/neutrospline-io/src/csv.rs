//! CSV tables: a header row, then one control point per row.
//!
//! Columns (case-insensitive): `x`, `y`, optional `z` (required for surfaces), `truth`,
//! `indeterminacy`, `falsity` (aliases `T`, `I`, `F`), `weight` (exactly for the NURBS kinds)
//! and an optional `name`. Lines starting with `#` are comments, empty lines are skipped, cells
//! are trimmed, rows end at LF, CRLF or CR, and a UTF-8 byte order mark is accepted. Quoting is
//! that of spreadsheets and Python's `csv` module: a cell starting with `"` is quoted (`""` in
//! it is a quote; commas and line ends in it are kept), a quote elsewhere is a character
//! (`C"0`); a file that ends inside a quoted cell is refused. One `csv` reader reads the whole
//! stream ([`Records`]). Line numbers in errors are physical lines of the file (1-based,
//! counted by LF, comments counted); a row's line is the one it starts on.
//!
//! A CSV file lists control points only: the kind, degree, knots and grid come from the
//! [`ReadOptions`](crate::ReadOptions) (the command line's `--kind`, `--degree`, `--knots`,
//! `--rows`, ...).

use neutrospline::{DegreeError, Degrees};

use std::io::{BufRead, Read};

use crate::format::{too_many_points, MAX_CSV_LINE};
use crate::parsed::{
    check_spread_value, duplicate_rule, missing_degree, parse_number, spread_from_values,
    spread_hint, spread_keys_problem, Field, Origin, Parsed, PointRecord, SpreadKey,
};
use crate::settings::{Key, Kind, KnotSpec, KnotsSetting, Setting, Structure};
use crate::{InputError, ReadOptions};

/// Parses a CSV table held in memory; see [`parse_reader`].
pub(crate) fn parse(file: &str, bytes: &[u8], options: &ReadOptions) -> Result<Parsed, InputError> {
    parse_reader(file, bytes, options)
}

/// The bytes the CSV reader adds after the end of the input, one per `read`: a line end that
/// ends the last row when the file does not, and a NUL byte. The NUL byte reads as a row of
/// its own, unless the file ends inside a quoted cell: then both bytes are in that cell, and
/// the row is refused (the `csv` crate itself ends such a cell at the end of the input without
/// a word).
const END_MARK: &[u8] = b"\n\0";

/// A located problem found by [`Input`]: the line and the message. It travels through the
/// `csv` reader as the payload of an [`std::io::Error`].
#[derive(Debug, Clone)]
struct Located {
    line: usize,
    message: String,
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
struct Input<R> {
    inner: R,
    /// The physical line (1-based, lines end at `\n`) of the next byte.
    line: usize,
    /// The bytes of the current physical line so far.
    line_bytes: usize,
    /// Whether the last piece ended with `\r` or `\n` (true at the start).
    piece_start: bool,
    /// The last byte handed over.
    last: u8,
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
    comment: Vec<u8>,
    comments: Vec<(usize, String)>,
}

impl<R: BufRead> Input<R> {
    fn new(inner: R) -> Input<R> {
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
    fn row_ended(&mut self) {
        self.place = Place::Between;
    }

    /// The line the current row started on, when in a row.
    fn row_start(&self) -> Option<usize> {
        match self.place {
            Place::Row { start, .. } => Some(start),
            Place::Between | Place::Comment => None,
        }
    }

    /// Whether the CSV reader, having read `consumed` bytes, has read all of [`END_MARK`].
    fn read_to_the_end(&self, consumed: u64) -> bool {
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
    reader: ::csv::Reader<Input<R>>,
    row: ::csv::StringRecord,
    done: bool,
    /// The number of cells of the first row (the header), once read.
    header_cells: Option<usize>,
}

impl<R: BufRead> Records<R> {
    /// Records from the start of `reader`.
    pub(crate) fn new(reader: R) -> Records<R> {
        let reader = ::csv::ReaderBuilder::new()
            .has_headers(false)
            .flexible(true)
            .trim(::csv::Trim::None)
            .comment(Some(b'#'))
            .terminator(::csv::Terminator::CRLF)
            .from_reader(Input::new(reader));
        Records {
            reader,
            row: ::csv::StringRecord::new(),
            done: false,
            header_cells: None,
        }
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
            let cells: Vec<&str> = body.split(',').map(str::trim).collect();
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

/// Parses a CSV table from a stream, line by line: an error is reported as soon as its line is
/// read, without reading further, and only the control points are kept in memory (at most
/// `max_control_points` of them). The `options` give the kind, the membership rule the
/// degrees must obey, and the structure.
pub(crate) fn parse_reader(
    file: &str,
    reader: impl BufRead,
    options: &ReadOptions,
) -> Result<Parsed, InputError> {
    let kind = options.kind.unwrap_or(Kind::DEFAULT);
    let membership = options.membership.unwrap_or_default();
    let max_points = options.limits.max_control_points;
    let error = |line: Option<usize>, field: Option<String>, message: String| InputError {
        file: file.to_owned(),
        line,
        field,
        message,
    };
    let mut records = Records::new(reader);
    // The next record as text and cells, with its line.
    let mut next = || records.next_cells(file);

    let Some((header_line, header)) = next()? else {
        return Err(error(
            None,
            None,
            "empty file (expected a header row such as `x,y,truth,indeterminacy,falsity`)"
                .to_owned(),
        ));
    };
    let header_line = Some(header_line);
    let columns = read_header(&header).map_err(|m| error(header_line, None, m))?;
    let has = |f: Field| columns.contains(&Column::Field(f));
    for f in [Field::X, Field::Y] {
        if !has(f) {
            return Err(error(
                header_line,
                None,
                format!("missing column `{}` (every file needs x and y)", f.name()),
            ));
        }
    }
    if !has(Field::Truth) {
        return Err(error(
            header_line,
            None,
            "missing column `truth` (every membership rule requires it)".to_owned(),
        ));
    }
    if let Some(DegreeError::Missing { kind, membership }) =
        missing_degree(membership, has(Field::Indeterminacy), has(Field::Falsity))
    {
        return Err(error(
            header_line,
            None,
            format!("missing column `{kind}` ({membership} rule requires it)"),
        ));
    }
    if kind.is_surface() && !has(Field::Z) {
        return Err(error(
            header_line,
            None,
            "missing column `z` (surfaces are 3-D: every control point needs x, y and z)"
                .to_owned(),
        ));
    }
    if kind.is_rational() && !has(Field::Weight) {
        return Err(error(
            header_line,
            None,
            format!(
                "missing column `weight` (kind `{kind}` needs a positive weight for every control point)"
            ),
        ));
    }
    if !kind.is_rational() && has(Field::Weight) {
        return Err(error(
            header_line,
            None,
            format!(
                "column `weight` does not apply to kind `{kind}` (weights only apply to NURBS: \
                 --kind nurbs or --kind nurbs-surface)"
            ),
        ));
    }
    let dimension = if has(Field::Z) { 3 } else { 2 };
    let mut spread_columns: [Option<&str>; 9] = [None; 9];
    for (column, heading) in columns.iter().zip(header.iter()) {
        if let Column::Spread(key) = column {
            spread_columns[key.index()] = Some(heading);
        }
    }
    if let Some(problem) = spread_keys_problem(&spread_columns, dimension, kind.is_surface()) {
        return Err(error(header_line, None, format!("column {problem}")));
    }

    let mut points = Vec::new();
    while let Some((line, record)) = next()? {
        let line = Some(line);
        if points.len() as u64 >= max_points {
            return Err(error(line, None, too_many_points(max_points)));
        }
        if record.len() != columns.len() {
            return Err(error(
                line,
                None,
                format!(
                    "the row has {} cells but the header has {} (every row needs one cell per column)",
                    record.len(),
                    columns.len()
                ),
            ));
        }
        let mut values = [None::<f64>; 8];
        let mut spreads = [None::<f64>; 9];
        let mut name = None;
        for ((&column, cell), heading) in columns.iter().zip(record.iter()).zip(header.iter()) {
            let field = match column {
                Column::Field(field) => field,
                Column::Spread(key) => {
                    let value = parse_number(cell)
                        .and_then(check_spread_value)
                        .map_err(|m| error(line, Some(format!("column `{heading}`")), m))?;
                    spreads[key.index()] = Some(value);
                    continue;
                }
            };
            if field == Field::Name {
                name = (!cell.is_empty()).then(|| cell.to_owned());
                continue;
            }
            let value = match (field, cell.parse::<f64>()) {
                // Any number, NaN and infinities included: the core's NURBS weight rule judges it.
                (Field::Weight, Ok(w)) => w,
                _ => parse_number(cell)
                    .map_err(|m| error(line, Some(format!("column `{heading}`")), m))?,
            };
            values[field.index()] = Some(value);
        }
        let get = |f: Field| values[f.index()];
        let degrees = Degrees::with_membership(
            membership,
            get(Field::Truth).unwrap_or_default(),
            get(Field::Indeterminacy),
            get(Field::Falsity),
        )
        .map_err(|e| error(line, None, e.to_string()))?;
        let position = [Field::X, Field::Y, Field::Z][..dimension]
            .iter()
            .map(|&f| get(f).unwrap_or_default())
            .collect();
        points.push(PointRecord {
            name,
            position,
            degrees,
            weight: get(Field::Weight),
            origin: Origin { line, field: None },
            weight_origin: Origin {
                line,
                field: Some("column `weight`".to_owned()),
            },
            spread: spread_from_values(&spreads),
        });
    }
    if points.is_empty() {
        return Err(error(
            None,
            None,
            "no control points (the header row is not followed by any data row)".to_owned(),
        ));
    }
    Ok(Parsed {
        file: file.to_owned(),
        kind,
        name: None,
        description: None,
        membership,
        dimension,
        points,
        structure: structure(kind, options),
    })
}

/// The structure given on the command line (`--degree`, `--knots`, `--rows`, ...).
fn structure(kind: Kind, options: &ReadOptions) -> Structure {
    let number = |key: Key, value: Option<usize>| {
        value.map(|value| Setting {
            value,
            origin: Origin {
                line: None,
                field: Some(key.option().to_owned()),
            },
        })
    };
    let knots = |key: Key, spec: &Option<KnotSpec>| {
        spec.clone().map(|spec| KnotsSetting {
            spec,
            origin: Origin {
                line: None,
                field: Some(key.option().to_owned()),
            },
            lines: Vec::new(),
        })
    };
    if kind.is_surface() {
        // `ReadOptions::check` made sure that --rows and --cols are given for surface kinds.
        let count = |key: Key, value: Option<usize>| {
            number(key, value).unwrap_or(Setting {
                value: 0,
                origin: Origin {
                    line: None,
                    field: Some(key.option().to_owned()),
                },
            })
        };
        Structure::Surface {
            rows: count(Key::Rows, options.rows),
            cols: count(Key::Cols, options.cols),
            degree_u: number(Key::DegreeU, options.degree_u),
            degree_v: number(Key::DegreeV, options.degree_v),
            knots_u: knots(Key::KnotsU, &options.knots_u),
            knots_v: knots(Key::KnotsV, &options.knots_v),
        }
    } else {
        Structure::Curve {
            degree: number(Key::Degree, options.degree),
            knots: knots(Key::Knots, &options.knots),
        }
    }
}

/// What a header cell names: a field of the control point, or a spread.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Column {
    Field(Field),
    Spread(SpreadKey),
}

/// The column of each header cell; the message explains an unknown or repeated column.
fn read_header(header: &::csv::StringRecord) -> Result<Vec<Column>, String> {
    let mut columns: Vec<Column> = Vec::with_capacity(header.len());
    for (i, heading) in header.iter().enumerate() {
        let field = Field::from_name(heading, true)
            .map(Column::Field)
            .or_else(|| SpreadKey::from_name(heading, true).map(Column::Spread))
            .ok_or_else(|| {
                format!(
                    "unknown column `{heading}` (known columns: {}){}",
                    Field::known_list(),
                    spread_hint(heading)
                )
            })?;
        if let Some(j) = columns.iter().position(|&f| f == field) {
            return Err(format!(
                "column {} `{heading}` repeats column {} `{}` ({})",
                i + 1,
                j + 1,
                header.get(j).unwrap_or_default(),
                duplicate_rule()
            ));
        }
        columns.push(field);
    }
    Ok(columns)
}

#[cfg(test)]
mod tests {
    use super::*;

    use neutrospline::Membership;

    fn rule(membership: Membership) -> ReadOptions {
        ReadOptions {
            membership: Some(membership),
            ..ReadOptions::default()
        }
    }

    fn parse_ok(text: &str) -> Parsed {
        parse("t.csv", text.as_bytes(), &rule(Membership::Neutrosophic)).unwrap()
    }

    fn parse_err(text: &[u8], membership: Membership) -> String {
        parse("t.csv", text, &rule(membership))
            .unwrap_err()
            .to_string()
    }

    const EXAMPLE1: &str = "name,x,y,truth,indeterminacy,falsity\n\
        C0,1,3,0.3,0.6,0.1\nC1,3,6,0.8,0.1,0.1\nC2,6,2,0.7,0.1,0.2\nC3,9,5,0.2,0.4,0.4\n";

    #[test]
    fn csv_parse_example1() {
        let m = parse_ok(EXAMPLE1);
        assert_eq!(m.dimension, 2);
        assert_eq!(m.points.len(), 4);
        assert_eq!(m.points[3].name.as_deref(), Some("C3"));
        assert_eq!(m.points[3].position, vec![9.0, 5.0]);
        assert_eq!(m.points[3].degrees.to_array(), [0.2, 0.4, 0.4]);
        assert_eq!(m.points[2].origin.line, Some(4));
    }

    #[test]
    fn csv_parse_bom_crlf_comments_aliases_whitespace() {
        let text =
            "\u{FEFF}# a comment\r\n X , Y ,z, t , I,F\r\n\r\n# another\r\n 1 , 2,3,0.5,0.25,0\r\n";
        let m = parse_ok(text);
        assert_eq!(m.dimension, 3);
        assert_eq!(m.points[0].position, vec![1.0, 2.0, 3.0]);
        assert_eq!(m.points[0].degrees.to_array(), [0.5, 0.25, 0.0]);
        assert_eq!(m.points[0].origin.line, Some(5));
    }

    /// A spreadsheet writes a name that starts with `#` unquoted; the format reads that line
    /// as a comment, which would drop the point with exit 0. Such a comment (as many cells as
    /// the header, numbers after the first) is refused with its line; prose, a commented
    /// header and quoted `#` names are not.
    #[test]
    fn csv_parse_refuses_a_row_hidden_in_a_comment() {
        let text = "name,x,y,truth,indeterminacy,falsity\nC0,1,3,0.3,0.6,0.1\n#1,3,6,0.8,0.1,0.1\nC2,6,2,0.7,0.1,0.2\n";
        let err = parse("t.csv", text.as_bytes(), &rule(Membership::Neutrosophic)).unwrap_err();
        assert_eq!(
            err.to_string(),
            "t.csv:3: `#1,3,6,0.8,0.1,0.1` starts with `#`, so it is a comment, yet it holds a \
             full row (6 cells, as the header): a name that starts with `#` must be quoted \
             (`\"#1\"`), and a row to leave out must be deleted (a comment would drop it \
             without a word)"
        );
        // The same at the end of the file, without a line end.
        let last = "name,x,y,truth,indeterminacy,falsity\nC0,1,3,0.3,0.6,0.1\nC1,3,6,0.8,0.1,0.1\n# C3, 9, 5, 0.2, 0.4, 0.4";
        let err = parse("t.csv", last.as_bytes(), &rule(Membership::Neutrosophic)).unwrap_err();
        assert!(
            err.to_string()
                .starts_with("t.csv:4: `# C3, 9, 5, 0.2, 0.4, 0.4` starts with"),
            "{err}"
        );
        // Prose, a commented header and a quoted name are fine.
        let fine = "# The paper's Example 1, with 4 points, 2 of them, 1, 2\nname,x,y,truth,indeterminacy,falsity\n# name,x,y,truth,indeterminacy,falsity\nC0,1,3,0.3,0.6,0.1\n\"#1\",3,6,0.8,0.1,0.1\n# note: 1, 2, 3\n";
        let parsed = parse_ok(fine);
        let names: Vec<Option<&str>> = parsed.points.iter().map(|p| p.name.as_deref()).collect();
        assert_eq!(names, [Some("C0"), Some("#1")]);
    }

    #[test]
    fn csv_parse_line_numbers_count_comments() {
        let text = "x,y,truth,indeterminacy,falsity\n# c\n1,2,0,0,0\n# c\n\n1,2,1.5,0,0\n";
        assert_eq!(
            parse_err(text.as_bytes(), Membership::Neutrosophic),
            "t.csv:6: truth = 1.5 is outside [0, 1] (every degree must be in [0, 1])"
        );
    }

    #[test]
    fn csv_parse_errors() {
        use Membership::*;
        let cases: &[(&[u8], Membership, &str)] = &[
            (b"", Neutrosophic, "t.csv: empty file (expected a header row such as `x,y,truth,indeterminacy,falsity`)"),
            (b"# only a comment\n", Neutrosophic, "t.csv: empty file (expected a header row such as `x,y,truth,indeterminacy,falsity`)"),
            (b"x,y,truth,indeterminacy,falsity\n", Neutrosophic, "t.csv: no control points (the header row is not followed by any data row)"),
            (b"x,truth,indeterminacy,falsity\n1,0,0,0\n", Neutrosophic, "t.csv:1: missing column `y` (every file needs x and y)"),
            (b"x,y,indeterminacy,falsity\n1,0,0,0\n", Neutrosophic, "t.csv:1: missing column `truth` (every membership rule requires it)"),
            (b"x,y,truth,falsity\n1,0,0,0\n", Neutrosophic, "t.csv:1: missing column `indeterminacy` (neutrosophic rule requires it)"),
            (b"x,y,truth\n1,0,0\n", Intuitionistic, "t.csv:1: missing column `falsity` (intuitionistic rule requires it)"),
            (b"x,y,truth,T,indeterminacy,falsity\n", Neutrosophic, "t.csv:1: column 4 `T` repeats column 3 `truth` (each field may appear once; T, I and F are aliases of truth, indeterminacy and falsity)"),
            (b"x,y,x\n", Neutrosophic, "t.csv:1: column 3 `x` repeats column 1 `x` (each field may appear once; T, I and F are aliases of truth, indeterminacy and falsity)"),
            (b"x,y,w\n", Neutrosophic, "t.csv:1: unknown column `w` (known columns: x, y, z, truth (T), indeterminacy (I), falsity (F), weight, name)"),
            (b"x,y,truth,indeterminacy,falsity\n1,2,abc,0,0\n", Neutrosophic, "t.csv:2: column `truth`: value `abc` is not a number"),
            (b"x,y,truth,indeterminacy,falsity\n1,NaN,0,0,0\n", Neutrosophic, "t.csv:2: column `y`: value `NaN` is not a finite number (NaN and infinities are not allowed)"),
            (b"x,y,truth,indeterminacy,falsity\n1,2,0,0,inf\n", Neutrosophic, "t.csv:2: column `falsity`: value `inf` is not a finite number (NaN and infinities are not allowed)"),
            (b"x,y,truth,indeterminacy,falsity\n1,2,0,0\n", Neutrosophic, "t.csv:2: the row has 4 cells but the header has 5 (every row needs one cell per column)"),
            (b"x,y,truth,indeterminacy,falsity\n1,2,0,0,0,9\n", Neutrosophic, "t.csv:2: the row has 6 cells but the header has 5 (every row needs one cell per column)"),
            (b"x,y,truth,indeterminacy,falsity\n1,2,0,0,0\n1,\xff,0,0,0\n", Neutrosophic, "t.csv:3: invalid UTF-8 (the file must be UTF-8 encoded)"),
            (b"x,y,truth,falsity\n1,2,0.7,0.6\n", Intuitionistic, "t.csv:2: truth + falsity = 0.7 + 0.6 = 1.2999999999999998 exceeds 1 (intuitionistic rule: truth + falsity <= 1)"),
            (b"x,y,truth,falsity\n1,2,0.7,0.1\n", Fuzzy, "t.csv:2: falsity = 0.1 is not allowed (fuzzy rule: only truth is given; falsity must be absent or 0)"),
        ];
        for (text, membership, expected) in cases {
            assert_eq!(
                &parse_err(text, *membership),
                expected,
                "input {:?}",
                String::from_utf8_lossy(text)
            );
        }
    }

    #[test]
    fn csv_parse_membership_rules() {
        let m = parse(
            "t.csv",
            b"x,y,truth,falsity\n0,0,0.5,0.25\n",
            &rule(Membership::Intuitionistic),
        )
        .unwrap();
        assert_eq!(m.points[0].degrees.to_array(), [0.5, 0.25, 0.25]);
        let m = parse("t.csv", b"x,y,truth\n0,0,0.5\n", &rule(Membership::Fuzzy)).unwrap();
        assert_eq!(m.points[0].degrees.to_array(), [0.5, 0.0, 0.0]);
    }

    #[test]
    fn csv_parse_streams_quoted_newlines_and_counts_lines() {
        let text = "name,x,y,T,I,F\n\"two\nlines\",1,2,0,0,0\n  \n,1,2,0,0,2\n";
        assert_eq!(
            parse_err(text.as_bytes(), Membership::Neutrosophic),
            "t.csv:5: falsity = 2 is outside [0, 1] (every degree must be in [0, 1])"
        );
        let m = parse_ok("name,x,y,T,I,F\n\"two\nlines\",1,2,0,0,0\n");
        assert_eq!(m.points[0].name.as_deref(), Some("two\nlines"));
        assert_eq!(m.points[0].origin.line, Some(2));
    }

    #[test]
    fn csv_parse_reader_stops_at_the_first_bad_line() {
        // A reader that fails if read past the bad line 3: the error comes first.
        struct Endless(Vec<u8>);
        impl std::io::Read for Endless {
            fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
                if self.0.is_empty() {
                    panic!("read past the bad line");
                }
                let n = buf.len().min(self.0.len());
                buf[..n].copy_from_slice(&self.0[..n]);
                self.0.drain(..n);
                Ok(n)
            }
        }
        let reader = std::io::BufReader::with_capacity(
            8,
            Endless(b"x,y,truth,indeterminacy,falsity\n1,2,0,0,0\n1,2,0,x,0\n".to_vec()),
        );
        let e = parse_reader("t.csv", reader, &rule(Membership::Neutrosophic)).unwrap_err();
        assert_eq!(
            e.to_string(),
            "t.csv:3: column `indeterminacy`: value `x` is not a number"
        );
    }

    #[test]
    fn csv_parse_spreads() {
        let m = parse_ok("x,y,T,I,F,SPREAD_X,spread_y_left,spread_y_right\n0,0,1,0,0,0.5,1,2\n");
        assert_eq!(m.points[0].spread.left, [0.5, 1.0, 0.0]);
        assert_eq!(m.points[0].spread.right, [0.5, 2.0, 0.0]);
        let m = parse_ok("x,y,T,I,F\n0,0,1,0,0\n");
        assert!(m.points[0].spread.is_zero());
        use Membership::*;
        let cases: &[(&[u8], &str)] = &[
            (b"x,y,T,I,F,spread_x,spread_x_right\n", "t.csv:1: column `spread_x` and `spread_x_right` are both given (give the symmetric spread `spread_x` or the asymmetric `spread_x_left` and `spread_x_right` for one axis, not both)"),
            (b"x,y,T,I,F,spread_z\n", "t.csv:1: column `spread_z` does not apply to a curve without z (the spread of z needs a z coordinate)"),
            (b"x,y,T,I,F,spread_x,spread_x\n", "t.csv:1: column 7 `spread_x` repeats column 6 `spread_x` (each field may appear once; T, I and F are aliases of truth, indeterminacy and falsity)"),
            (b"x,y,T,I,F,spread\n", "t.csv:1: unknown column `spread` (known columns: x, y, z, truth (T), indeterminacy (I), falsity (F), weight, name) (spreads: spread_x, spread_y, spread_z, or spread_x_left and spread_x_right and so on)"),
            (b"x,y,T,I,F,spread_y\n0,0,1,0,0,1\n0,0,1,0,0,-2\n", "t.csv:3: column `spread_y`: spread -2 is negative (a spread is a distance >= 0)"),
            (b"x,y,T,I,F,spread_y\n0,0,1,0,0,inf\n", "t.csv:2: column `spread_y`: value `inf` is not a finite number (NaN and infinities are not allowed)"),
        ];
        for (text, expected) in cases {
            assert_eq!(&parse_err(text, Neutrosophic), expected);
        }
        let surface = ReadOptions {
            kind: Some(Kind::Surface(neutrospline::SurfaceKind::Bezier)),
            rows: Some(1),
            cols: Some(1),
            ..rule(Neutrosophic)
        };
        assert_eq!(
            parse("t.csv", b"x,y,z,T,I,F,spread_x\n0,0,0,1,0,0,1\n", &surface)
                .unwrap_err()
                .to_string(),
            "t.csv:1: column `spread_x` does not apply to surfaces (spreads apply to curves only)"
        );
    }

    #[test]
    fn csv_parse_quoted_name_and_empty_name() {
        let m = parse_ok("name,x,y,T,I,F\n\"a, b\",1,2,0,0,0\n,1,2,0,0,0\n");
        assert_eq!(m.points[0].name.as_deref(), Some("a, b"));
        assert_eq!(m.points[1].name, None);
    }
}

#[cfg(test)]
mod framing_tests {
    //! The framing of rows: one `csv` reader over the whole stream (issue 22). Expected rows
    //! are written out by hand, as a spreadsheet and Python's `csv` module read them.
    use super::*;

    /// The rows of `text` as (line, cells), or the error message.
    fn rows(text: &[u8]) -> Result<Vec<(usize, Vec<String>)>, String> {
        let mut records = Records::new(text);
        let mut out = Vec::new();
        while let Some((line, cells)) = records.next_cells("t.csv").map_err(|e| e.to_string())? {
            out.push((line, cells.iter().map(str::to_owned).collect()));
        }
        Ok(out)
    }

    fn row(line: usize, cells: &[&str]) -> (usize, Vec<String>) {
        (line, cells.iter().map(|&c| c.to_owned()).collect())
    }

    #[test]
    fn a_stray_quote_inside_an_unquoted_name_is_a_character() {
        // Issue 22: `C"0` made the old framer join the rest of the file to the row, and the
        // per-row reader kept the first line only: one control point instead of four.
        let text = "name,x,y,truth,indeterminacy,falsity\nC\"0,1,3,0.3,0.6,0.1\n\
                    C1,3,6,0.8,0.1,0.1\nC2,6,2,0.7,0.1,0.2\nC3,9,5,0.2,0.4,0.4\n";
        let m = parse("t.csv", text.as_bytes(), &ReadOptions::default()).unwrap();
        let names: Vec<_> = m.points.iter().map(|p| p.name.as_deref()).collect();
        assert_eq!(names, [Some("C\"0"), Some("C1"), Some("C2"), Some("C3")]);
        let lines: Vec<_> = m.points.iter().map(|p| p.origin.line).collect();
        assert_eq!(lines, [Some(2), Some(3), Some(4), Some(5)]);
        assert_eq!(m.points[0].position, vec![1.0, 3.0]);
        assert_eq!(m.points[3].position, vec![9.0, 5.0]);
    }

    #[test]
    fn quotes_read_as_spreadsheets_read_them() {
        let text = b"a,b\n\"x\"\"y\",\"p\"q\n a\"b , \"c,d\"\n\"\",\"e\"\"\"\n";
        assert_eq!(
            rows(text).unwrap(),
            [
                row(1, &["a", "b"]),
                row(2, &["x\"y", "pq"]),
                // A quote after a space is an ordinary character, as is the comma after it.
                row(3, &["a\"b", "\"c", "d\""]),
                row(4, &["", "e\""]),
            ]
        );
    }

    #[test]
    fn quoted_line_ends_crlf_bom_comments_and_blank_lines() {
        let text = "\u{feff}# it's a \"comment\r\nname,x\r\n\r\n   \r\n\"two\r\nlines\",1\r\n\
                    # \"\r\n\"#not a comment\",2\r\n\"\"\"\n\nx\",3";
        assert_eq!(
            rows(text.as_bytes()).unwrap(),
            [
                row(2, &["name", "x"]),
                row(5, &["two\r\nlines", "1"]),
                row(8, &["#not a comment", "2"]),
                row(9, &["\"\n\nx", "3"]),
            ]
        );
    }

    #[test]
    fn a_lone_carriage_return_ends_a_row_as_in_spreadsheets() {
        // Rows end at `\r` too (old Mac files, and Python's csv writer leaves a `\r` in a cell
        // unquoted when its line end is `\n`); lines are counted by `\n`. A comment runs to
        // the `\n`.
        assert_eq!(
            rows(b"a,b\rc,d\r\ne,f\n# x\ry\n\"g\rh\",i\r").unwrap(),
            [
                row(1, &["a", "b"]),
                row(1, &["c", "d"]),
                row(2, &["e", "f"]),
                row(4, &["g\rh", "i"]),
            ]
        );
        let text = b"name,x,y,T,I,F\nC\r0,1,2,0,0,0\n";
        assert_eq!(
            parse("t.csv", text, &ReadOptions::default()).unwrap_err().to_string(),
            "t.csv:2: the row has 1 cells but the header has 6 (every row needs one cell per column)"
        );
    }

    #[test]
    fn trailing_commas_and_short_rows_keep_their_cells() {
        assert_eq!(
            rows(b"a,b,c\n1,2,\n1,\n,,\n").unwrap(),
            [
                row(1, &["a", "b", "c"]),
                row(2, &["1", "2", ""]),
                row(3, &["1", ""]),
                row(4, &["", "", ""]),
            ]
        );
        let text = b"name,x,y,T,I,F\nC0,1,2,0,0,0,\n";
        assert_eq!(
            parse("t.csv", text, &ReadOptions::default()).unwrap_err().to_string(),
            "t.csv:2: the row has 7 cells but the header has 6 (every row needs one cell per column)"
        );
    }

    #[test]
    fn a_quoted_cell_that_never_closes_is_refused_with_its_line() {
        let message = "the file ends inside a quoted cell of the row starting on this line (a \
                       cell that starts with `\"` ends at the next `\"` that is not doubled)";
        for (text, line) in [
            (&b"name,x\nC0,1\n\"C1,2\nC2,3\nC3,4\n"[..], 3),
            (b"name,x\nC0,1\n\"C1,2", 3),
            (b"name,x\nC0,\"1\n", 2),
            (b"\"name,x\n", 1),
            (b"name,x\n\"a\nb\",1\n# c\nC0,\"1\n\n", 5),
        ] {
            assert_eq!(
                rows(text).unwrap_err(),
                format!("t.csv:{line}: {message}"),
                "{:?}",
                String::from_utf8_lossy(text)
            );
        }
        // A NUL byte is a character like any other, at the end too.
        assert_eq!(rows(b"a\n\0").unwrap(), [row(1, &["a"]), row(2, &["\0"])]);
        assert_eq!(rows(b"a\n\0\n").unwrap(), [row(1, &["a"]), row(2, &["\0"])]);
        assert_eq!(rows(b"\"a\"").unwrap(), [row(1, &["a"])]);
    }

    #[test]
    fn invalid_utf8_is_refused_on_its_line_comments_included() {
        for (text, line) in [
            (&b"a\n# caf\xe9\nb\n"[..], 2),
            (b"a\n\"x\ny\xff\",1\n", 3),
            (b"a\nb\n\xe2\x82", 3),
            (b"a\n\xe2\x82\nb\n", 2),
        ] {
            assert_eq!(
                rows(text).unwrap_err(),
                format!("t.csv:{line}: invalid UTF-8 (the file must be UTF-8 encoded)")
            );
        }
        assert_eq!(
            rows("a\n\u{20ac}\n".as_bytes()).unwrap()[1],
            row(2, &["\u{20ac}"])
        );
    }

    #[test]
    fn long_lines_and_long_rows_are_refused_with_their_line() {
        let mut text = b"a\n# c\n".to_vec();
        text.extend(std::iter::repeat_n(b'x', MAX_CSV_LINE));
        text.push(b'\n');
        assert_eq!(
            rows(&text).unwrap_err(),
            format!(
                "t.csv:3: the line is longer than {MAX_CSV_LINE} bytes (a row of control point \
                 values is short; is this a CSV file?)"
            )
        );
        // A line of exactly the limit, its line end included, reads.
        text.truncate(text.len() - 2);
        text.push(b'\n');
        assert_eq!(rows(&text).unwrap().len(), 2);
        // A quoted cell spanning many short lines: the row is refused where it starts.
        let mut text = b"a\n\n\"".to_vec();
        for _ in 0..=MAX_CSV_LINE / 8 {
            text.extend(b"1234567\n");
        }
        text.extend(b"\"\n");
        assert_eq!(
            rows(&text).unwrap_err(),
            format!(
                "t.csv:3: the row starting on this line is longer than {MAX_CSV_LINE} bytes at \
                 line {} (a row of control point values is short; is a quoted cell never \
                 closed?)",
                // The quote and 8 bytes a line: past the limit on the row's line MAX / 8.
                2 + MAX_CSV_LINE / 8
            )
        );
        // Comment lines do not count towards a row.
        let mut text = b"a\n".to_vec();
        for _ in 0..=MAX_CSV_LINE / 8 {
            text.extend(b"# 34567\n");
        }
        text.extend(b"b\n");
        assert_eq!(rows(&text).unwrap()[1].1, ["b"]);
    }

    #[test]
    fn reading_stops_at_the_error_without_reading_further() {
        // One byte per read: the framing never asks for more than it needs.
        struct Trickle(Vec<u8>, usize);
        impl std::io::Read for Trickle {
            fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
                assert!(self.1 < self.0.len(), "read past the unclosed quote's row");
                buf[0] = self.0[self.1];
                self.1 += 1;
                Ok(1)
            }
        }
        let mut text = b"a,b\n1,2\n3,4,5\n".to_vec();
        let end = text.len();
        text.extend(b"never read\n");
        let mut records = Records::new(std::io::BufReader::with_capacity(1, Trickle(text, 0)));
        assert_eq!(records.next_cells("t.csv").unwrap().unwrap().0, 1);
        assert_eq!(records.next_cells("t.csv").unwrap().unwrap().0, 2);
        let (line, cells) = records.next_cells("t.csv").unwrap().unwrap();
        assert_eq!((line, cells.len()), (3, 3));
        assert_eq!(records.reader.get_ref().inner.get_ref().1, end);
    }
}
