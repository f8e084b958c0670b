//! The framing of rows: one `csv` reader over the whole stream (issue 22). Expected rows
//! are written out by hand, as a spreadsheet and Python's `csv` module read them.

use super::*;

use crate::format::MAX_CSV_LINE;

/// The rows of `text` as (line, cells), or the error message.
fn rows(text: &[u8]) -> Result<Vec<(usize, Vec<String>)>, String> {
    let mut records = Records::new(text, Some(b','));
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
        parse("t.csv", text, &ReadOptions::default())
            .unwrap_err()
            .to_string(),
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
        parse("t.csv", text, &ReadOptions::default())
            .unwrap_err()
            .to_string(),
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
    let mut records = Records::new(
        std::io::BufReader::with_capacity(1, Trickle(text, 0)),
        Some(b','),
    );
    assert_eq!(records.next_cells("t.csv").unwrap().unwrap().0, 1);
    assert_eq!(records.next_cells("t.csv").unwrap().unwrap().0, 2);
    let (line, cells) = records.next_cells("t.csv").unwrap().unwrap();
    assert_eq!((line, cells.len()), (3, 3));
    assert_eq!(records.reader.get_ref().inner.get_ref().1, end);
}
