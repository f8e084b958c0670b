//! CSV tables: a header row, then one control point per row.
//!
//! Columns (case-insensitive): `x`, `y`, optional `z` (required for surfaces), `truth`,
//! `indeterminacy`, `falsity` (aliases `T`, `I`, `F`), `weight` (exactly for the NURBS kinds)
//! and an optional `name`. Lines starting with `#` are comments, empty lines are skipped, cells
//! are trimmed, CRLF line ends and a UTF-8 byte order mark are accepted. Line numbers in errors
//! are physical lines of the file (1-based, comments counted).
//!
//! A CSV file lists control points only: the kind, degree, knots and grid come from the
//! [`ReadOptions`](crate::ReadOptions) (the command line's `--kind`, `--degree`, `--knots`,
//! `--rows`, ...).

use neutrospline::{DegreeError, Degrees};

use std::io::{BufRead, Read};

use crate::format::{too_many_points, MAX_CSV_LINE};
use crate::parsed::{
    check_spread_value, duplicate_rule, line_of, missing_degree, parse_number, spread_from_values,
    spread_hint, spread_keys_problem, Field, Origin, Parsed, PointRecord, SpreadKey,
};
use crate::settings::{Key, Kind, KnotSpec, KnotsSetting, Setting, Structure};
use crate::{InputError, ReadOptions};

/// Parses a CSV table held in memory; see [`parse_reader`].
pub(crate) fn parse(file: &str, bytes: &[u8], options: &ReadOptions) -> Result<Parsed, InputError> {
    parse_reader(file, bytes, options)
}

/// A reading error: the line and the message.
pub(crate) type LineError = (usize, String);

/// Reads the records of a CSV stream one physical line at a time (a quoted cell may span
/// lines), never holding more than one record in memory.
pub(crate) struct Records<R> {
    reader: R,
    /// The physical line last read.
    line: usize,
    /// The current record, line ends removed.
    buffer: Vec<u8>,
}

impl<R: BufRead> Records<R> {
    /// Records from the start of `reader`.
    pub(crate) fn new(reader: R) -> Records<R> {
        Records {
            reader,
            line: 0,
            buffer: Vec::new(),
        }
    }

    /// Appends the next physical line to the buffer (at most [`MAX_CSV_LINE`] bytes in all);
    /// `false` at the end of the input.
    fn read_line(&mut self) -> Result<bool, LineError> {
        let room = (MAX_CSV_LINE + 1).saturating_sub(self.buffer.len()) as u64;
        let read = (&mut self.reader)
            .take(room)
            .read_until(b'\n', &mut self.buffer)
            .map_err(|e| (self.line + 1, format!("cannot read: {e}")))?;
        if read == 0 {
            return Ok(false);
        }
        self.line += 1;
        if self.buffer.len() > MAX_CSV_LINE {
            return Err((
                self.line,
                format!(
                    "the line is longer than {MAX_CSV_LINE} bytes (a row of control point values \
                     is short; is this a CSV file?)"
                ),
            ));
        }
        Ok(true)
    }

    /// The next record that is neither empty nor a comment, with the line it starts on.
    pub(crate) fn next_record(&mut self) -> Result<Option<(usize, &[u8])>, LineError> {
        loop {
            self.buffer.clear();
            if !self.read_line()? {
                return Ok(None);
            }
            let start = self.line;
            if start == 1 {
                if let Some(rest) = self.buffer.strip_prefix(b"\xEF\xBB\xBF") {
                    self.buffer = rest.to_vec();
                }
            }
            // A quoted cell continues on the next line while its quotes are unbalanced.
            while self.buffer.iter().filter(|&&b| b == b'"').count() % 2 == 1
                && self.buffer.ends_with(b"\n")
            {
                if !self.read_line()? {
                    break;
                }
            }
            while let Some(b'\n' | b'\r') = self.buffer.last() {
                self.buffer.pop();
            }
            // Every line must be UTF-8, comments included.
            if let Err(e) = std::str::from_utf8(&self.buffer) {
                return Err((
                    start + line_of(&self.buffer, e.valid_up_to()) - 1,
                    "invalid UTF-8 (the file must be UTF-8 encoded)".to_owned(),
                ));
            }
            if self.buffer.trim_ascii().is_empty() || self.buffer.starts_with(b"#") {
                continue;
            }
            return Ok(Some((start, &self.buffer)));
        }
    }
}

impl<R: BufRead> Records<R> {
    /// The next record split into trimmed cells, with the line it starts on; errors located
    /// in `file`.
    pub(crate) fn next_cells(
        &mut self,
        file: &str,
    ) -> Result<Option<(usize, ::csv::StringRecord)>, InputError> {
        let at = |line: usize, message: String| InputError::new(file, Some(line), None, message);
        let Some((line, bytes)) = self.next_record().map_err(|(line, m)| at(line, m))? else {
            return Ok(None);
        };
        let text = std::str::from_utf8(bytes).map_err(|e| {
            at(
                line + line_of(bytes, e.valid_up_to()) - 1,
                "invalid UTF-8 (the file must be UTF-8 encoded)".to_owned(),
            )
        })?;
        let cells = cells(text).map_err(|m| at(line, m))?;
        Ok(Some((line, cells)))
    }
}

/// Splits one record (UTF-8, line ends removed) into trimmed cells.
///
/// A record without a quote character is split at its commas directly (what the CSV reader
/// does with it, without building a reader per line: 100,000 lines read in a fraction of the
/// time); quoted records go through the `csv` crate.
fn cells(record: &str) -> Result<::csv::StringRecord, String> {
    if !record.is_empty() && !record.contains('"') {
        return Ok(record.split(',').map(str::trim).collect());
    }
    let mut reader = ::csv::ReaderBuilder::new()
        .has_headers(false)
        .trim(::csv::Trim::All)
        .flexible(true)
        .from_reader(record.as_bytes());
    let mut cells = ::csv::StringRecord::new();
    reader
        .read_record(&mut cells)
        .map_err(|e| format!("malformed CSV: {e}"))?;
    Ok(cells)
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

    #[test]
    fn cells_without_quotes_split_as_the_csv_reader_does() {
        let by_reader = |record: &str| {
            let mut reader = ::csv::ReaderBuilder::new()
                .has_headers(false)
                .trim(::csv::Trim::All)
                .flexible(true)
                .from_reader(record.as_bytes());
            let mut cells = ::csv::StringRecord::new();
            reader.read_record(&mut cells).unwrap();
            cells
        };
        for record in [
            "x,y",
            " 1 , 2.5 ,\t3",
            ",,",
            "a",
            "\u{a0}x\u{a0},y",
            "name,C0,1e-3, -0 ",
        ] {
            assert_eq!(cells(record).unwrap(), by_reader(record), "{record:?}");
        }
        assert_eq!(cells("\"a,b\",c").unwrap(), by_reader("\"a,b\",c"));
    }
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
