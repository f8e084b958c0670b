//! Stanford PLY, binary little-endian or ASCII: one `vertex` element with the properties
//! `x y z` (double), `nx ny nz` (double, surfaces), `red green blue` (uchar, the viridis
//! colour of the chosen value) and `truth indeterminacy falsity` (double; for an
//! interval-valued or bipolar family its channels by name, `truth_lower truth_upper ...`), then a `face`
//! element (surfaces: `list uchar uint vertex_indices`, triangles) or an `edge` element
//! (curves: `uint vertex1`, `uint vertex2`, the segments of the polyline). The header's
//! comments name the model and the colouring (in ASCII, as the header must be).

use std::fmt::Write as _;

use super::{comment_text, title, ColorBy, Samples};
use neutrospline_io::push_number;
use neutrospline_io::Model;

/// The header, up to and including `end_header`.
fn header(model: &Model, samples: &Samples, by: ColorBy, ascii: bool) -> String {
    let mut h = String::from("ply\n");
    h.push_str(if ascii {
        "format ascii 1.0\n"
    } else {
        "format binary_little_endian 1.0\n"
    });
    let _ = writeln!(
        h,
        "comment neutrospline export of a {}",
        comment_text(&title(model), true)
    );
    if let Some(description) = model.description() {
        let _ = writeln!(
            h,
            "comment description: {}",
            comment_text(description, true)
        );
    }
    let _ = writeln!(h, "comment membership: {}", model.membership());
    let _ = writeln!(h, "comment red green blue: viridis of {by}");
    let _ = writeln!(h, "element vertex {}", samples.positions.len());
    let mut names = vec!["x", "y", "z"];
    if samples.normals.is_some() {
        names.extend(["nx", "ny", "nz"]);
    }
    for name in names {
        let _ = writeln!(h, "property double {name}");
    }
    for name in ["red", "green", "blue"] {
        let _ = writeln!(h, "property uchar {name}");
    }
    for name in samples.value_columns().0 {
        let _ = writeln!(h, "property double {name}");
    }
    match &samples.triangles {
        Some(t) => {
            let _ = writeln!(h, "element face {}", t.len());
            h.push_str("property list uchar uint vertex_indices\n");
        }
        None => {
            let _ = writeln!(h, "element edge {}", samples.edges().len());
            h.push_str("property uint vertex1\nproperty uint vertex2\n");
        }
    }
    h.push_str("end_header\n");
    h
}

/// One value of a row: a double, a byte or an index.
enum Value {
    Double(f64),
    Byte(u8),
    Index(u32),
}

/// Writes the values of one element, in ASCII (separated by spaces, a line each) or binary.
fn row(out: &mut Vec<u8>, values: &[Value], ascii: bool) {
    for (k, value) in values.iter().enumerate() {
        if ascii {
            if k > 0 {
                out.push(b' ');
            }
            match value {
                Value::Double(v) => push_number(out, *v),
                Value::Byte(b) => out.extend_from_slice(b.to_string().as_bytes()),
                Value::Index(i) => out.extend_from_slice(i.to_string().as_bytes()),
            }
        } else {
            match value {
                Value::Double(v) => out.extend_from_slice(&v.to_le_bytes()),
                Value::Byte(b) => out.push(*b),
                Value::Index(i) => out.extend_from_slice(&i.to_le_bytes()),
            }
        }
    }
    if ascii {
        out.push(b'\n');
    }
}

/// The PLY file.
pub(super) fn ply(model: &Model, samples: &Samples, by: ColorBy, ascii: bool) -> Vec<u8> {
    let mut out = header(model, samples, by, ascii).into_bytes();
    let colors = samples.colors(by);
    let (_, degree_rows) = samples.value_columns();
    let mut values = Vec::with_capacity(15);
    for k in 0..samples.positions.len() {
        values.clear();
        values.extend(samples.positions[k].map(Value::Double));
        if let Some(normals) = &samples.normals {
            values.extend(normals[k].map(Value::Double));
        }
        values.extend(colors[k].map(Value::Byte));
        values.extend(degree_rows[k].iter().copied().map(Value::Double));
        row(&mut out, &values, ascii);
    }
    match &samples.triangles {
        Some(triangles) => {
            for t in triangles {
                let mut face = vec![Value::Byte(3)];
                face.extend(t.map(Value::Index));
                row(&mut out, &face, ascii);
            }
        }
        None => {
            for e in samples.edges() {
                row(&mut out, &e.map(Value::Index), ascii);
            }
        }
    }
    out
}
