//! Regressions found by running the real-file check on files its suite had not seen
//! (`NEUTROSPLINE_REALFILES`, tests/realfiles/README.md): each test holds a minimal file
//! transcribed from the real one, with its source.

use neutrospline::Degrees;

use super::{parse_dxf, Limits};
use crate::report::{Import, ImportOptions};

fn import(text: &str) -> Import {
    parse_dxf(
        "u.dxf",
        text.as_bytes(),
        &ImportOptions::new(Degrees::new(1.0, 0.0, 0.0).unwrap()),
        &Limits::default(),
    )
    .unwrap()
}

/// ezdxf's `integration_tests/data/R12_with_trash_beyond_EOF.dxf` (ezdxf 1.4.5 sdist, MIT
/// licence; the whole file, CR LF line ends as written) and Inkscape's
/// `share/extensions/tests/data/io/dxf_polylines.dxf` (text after `0 EOF`) were refused as a
/// whole. What follows `0 EOF` is not read, as CAD programs do, and the report says so; the
/// curves are those of the file without it, and `--strict` refuses the file.
#[test]
fn dxf_text_after_the_end_is_not_read_and_is_reported() {
    let file = "0\r\nSECTION\r\n2\r\nENTITIES\r\n0\r\nCIRCLE\r\n8\r\n\
        Layer_is_a_required_tag\r\n10\r\n0.0\r\n20\r\n0.0\r\n40\r\n1.5\r\n0\r\nENDSEC\r\n\
        0\r\nEOF\r\nignore\r\ninvalid\r\ndata\r\nbeyond\r\nEOF";
    let read = import(file);
    let cut = file.split("ignore").next().unwrap();
    assert_eq!(read.models, import(cut).models);
    assert_eq!(read.models.len(), 1);
    assert_eq!(
        read.report.summary(),
        "imported 1 curve (1 CIRCLE); 1 warning: line 19: the file goes on after its end \
         (`0 EOF` at line 17): the 5 lines from there on are not read, as CAD programs do"
    );
    assert_eq!(read.report.strict_violations().len(), 1);
    assert!(import(cut).report.warnings.is_empty());
}

/// ezdxf's `integration_tests/data/recover01.dxf` (ezdxf 1.4.5 sdist) holds 397 ENTITIES
/// sections, with header variables between them; the import read the first (63 TEXT) and
/// dropped the 1,441 LINEs of the others without a word. Every section's entities are read,
/// in order, with a warning. The structure transcribed, two LINEs for the file's 1,441.
#[test]
fn dxf_every_repeated_entities_section_is_read() {
    let file = "  0\nSECTION\n  2\nENTITIES\n  0\nTEXT\n  8\n0\n 10\n4 \n 20\n1004 \n 40\n10\n\
          1\nLondon Engineers Limited\n  0\nENDSEC\n  9\n$EXTMIN\n 10\n-1099.5\n 20\n686.5375\n\
          0\nENDSEC\n  0\nSECTION\n  2\nENTITIES\n  0\nLINE\n  8\n0\n 62\n 0 \n 10\n-1089.75 \n\
         20\n1444.5 \n 30\n0 \n 11\n-1089.75 \n 21\n1436.5 \n 31\n0 \n  0\nENDSEC\n\
          0\nSECTION\n  2\nENTITIES\n  0\nENDSEC\n  0\nSECTION\n  2\nENTITIES\n  0\nLINE\n\
          8\n0\n 10\n0\n 20\n0\n 11\n3\n 21\n4\n  0\nENDSEC\n  0\nEOF\n";
    let read = import(file);
    assert_eq!(read.models.len(), 2);
    assert_eq!(
        read.report.summary(),
        "imported 2 curves (2 LINE); skipped 1 TEXT (not a curve); 1 warning: the file has 4 \
         ENTITIES sections (the first at line 3): read as one, their content in order"
    );
    let lengths: Vec<f64> = read
        .models
        .iter()
        .map(|m| {
            let curve = m.shape().curve().unwrap().clone();
            curve.arc_length(curve.domain(), 1e-12).unwrap()
        })
        .collect();
    assert_eq!(lengths, [8.0, 5.0]);
}

/// A polyline whose vertices all lie at one point draws a point, as a LINE of length zero
/// does: both are reported as drawing nothing (the LWPOLYLINE was imported as a curve of
/// length zero, the LINE skipped). The LWPOLYLINE 118 of dxf2gcode's `2010-06-13 test.dxf`
/// (tests/realfiles/SOURCES.tsv), and POLYLINEs (2-D, 3-D, spline-fit) of one point.
#[test]
fn dxf_polylines_of_one_point_draw_nothing() {
    let lwpolyline = "  0\nLWPOLYLINE\n  5\n118\n100\nAcDbEntity\n  8\n0\n 62\n7\n100\n\
        AcDbPolyline\n 90\n2\n 70\n0\n 10\n21.861969\n 20\n-23.611595\n 30\n0.0\n 10\n\
        21.861969\n 20\n-23.611595\n 30\n0.0\n";
    let vertex = "  0\nVERTEX\n  8\n0\n 10\n1.5\n 20\n2\n 30\n0\n";
    let frame = "  0\nVERTEX\n  8\n0\n 10\n1.5\n 20\n2\n 30\n0\n 70\n16\n";
    let polyline = |flags: u8, vertices: &str| {
        format!("  0\nPOLYLINE\n  8\n0\n 66\n1\n 70\n{flags}\n{vertices}  0\nSEQEND\n")
    };
    let line = "  0\nLINE\n  8\n0\n 10\n0\n 20\n0\n 11\n1\n 21\n0\n";
    let entities = [
        lwpolyline.to_owned(),
        polyline(0, &vertex.repeat(3)),
        polyline(8, &vertex.repeat(2)),
        polyline(4, &frame.repeat(4)),
        line.to_owned(),
    ]
    .concat();
    let read = import(&format!(
        "  0\nSECTION\n  2\nENTITIES\n{entities}  0\nENDSEC\n  0\nEOF\n"
    ));
    assert_eq!(
        read.report.summary(),
        "imported 1 curve (1 LINE); empty: 1 LWPOLYLINE, 3 POLYLINE (draws nothing)"
    );
}
