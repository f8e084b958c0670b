//! The control-point table reader: values, columns, membership rules and line numbers.

use super::*;

use neutrospline::Family;

fn rule(membership: Family) -> ReadOptions {
    ReadOptions {
        membership: Some(membership),
        ..ReadOptions::default()
    }
}

fn parse_ok(text: &str) -> Parsed {
    parse("t.csv", text.as_bytes(), &rule(Family::Neutrosophic)).unwrap()
}

fn parse_err(text: &[u8], membership: Family) -> String {
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
    let err = parse("t.csv", text.as_bytes(), &rule(Family::Neutrosophic)).unwrap_err();
    assert_eq!(
        err.to_string(),
        "t.csv:3: `#1,3,6,0.8,0.1,0.1` starts with `#`, so it is a comment, yet it holds a \
         full row (6 cells, as the header): a name that starts with `#` must be quoted \
         (`\"#1\"`), and a row to leave out must be deleted (a comment would drop it \
         without a word)"
    );
    // The same at the end of the file, without a line end.
    let last = "name,x,y,truth,indeterminacy,falsity\nC0,1,3,0.3,0.6,0.1\nC1,3,6,0.8,0.1,0.1\n# C3, 9, 5, 0.2, 0.4, 0.4";
    let err = parse("t.csv", last.as_bytes(), &rule(Family::Neutrosophic)).unwrap_err();
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
        parse_err(text.as_bytes(), Family::Neutrosophic),
        "t.csv:6: truth = 1.5 is outside [0, 1] (every degree must be in [0, 1])"
    );
}

#[test]
fn csv_parse_errors() {
    use Family::*;
    let cases: &[(&[u8], Family, &str)] = &[
        (b"", Neutrosophic, "t.csv: empty file (expected a header row such as `x,y,truth,indeterminacy,falsity`)"),
        (b"# only a comment\n", Neutrosophic, "t.csv: empty file (expected a header row such as `x,y,truth,indeterminacy,falsity`)"),
        (b"x,y,truth,indeterminacy,falsity\n", Neutrosophic, "t.csv: no control points (the header row is not followed by any data row)"),
        (b"x,truth,indeterminacy,falsity\n1,0,0,0\n", Neutrosophic, "t.csv:1: missing column `y` (every file needs x and y)"),
        (b"x,y,indeterminacy,falsity\n1,0,0,0\n", Neutrosophic, "t.csv:1: missing column `truth` (every membership rule requires it)"),
        (b"x,y,truth,falsity\n1,0,0,0\n", Neutrosophic, "t.csv:1: missing column `indeterminacy` (neutrosophic rule requires it; truth and falsity alone are an intuitionistic table (--membership intuitionistic, indeterminacy 1 - T - F), truth alone a fuzzy one (--membership fuzzy))"),
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
        &rule(Family::Intuitionistic),
    )
    .unwrap();
    assert_eq!(m.points[0].degrees.to_array(), [0.5, 0.25, 0.25]);
    let m = parse("t.csv", b"x,y,truth\n0,0,0.5\n", &rule(Family::Fuzzy)).unwrap();
    assert_eq!(m.points[0].degrees.to_array(), [0.5, 0.0, 0.0]);
}

#[test]
fn csv_parse_streams_quoted_newlines_and_counts_lines() {
    let text = "name,x,y,T,I,F\n\"two\nlines\",1,2,0,0,0\n  \n,1,2,0,0,2\n";
    assert_eq!(
        parse_err(text.as_bytes(), Family::Neutrosophic),
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
    let e = parse_reader("t.csv", reader, &rule(Family::Neutrosophic)).unwrap_err();
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
    use Family::*;
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

/// The row after the limit is refused at its line, whatever it holds (here one cell too few),
/// and nothing after it is read; a table of exactly the limit reads.
#[test]
fn csv_parse_refuses_the_row_past_the_limit() {
    let limited = ReadOptions {
        limits: crate::Limits {
            max_control_points: 2,
            ..crate::Limits::default()
        },
        ..rule(Family::Neutrosophic)
    };
    let two = "x,y,T,I,F\n0,0,1,0,0\n# c\n1,1,1,0,0\n";
    assert_eq!(
        parse("t.csv", two.as_bytes(), &limited)
            .unwrap()
            .points
            .len(),
        2
    );
    let three = format!("{two}2,2,1,0\nnot, read\n");
    assert_eq!(
        parse("t.csv", three.as_bytes(), &limited)
            .unwrap_err()
            .to_string(),
        "t.csv:5: more than 2 control points (the limit; raise it with --max-control-points or \
         NEUTROSPLINE_MAX_CONTROL_POINTS)"
    );
}
