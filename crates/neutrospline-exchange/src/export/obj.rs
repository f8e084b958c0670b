//! Wavefront OBJ: `v x y z r g b` (positions, a plane curve with `z = 0`, and the common
//! vertex-colour extension: the viridis colour of the chosen value, each channel in \[0, 1\]
//! to 6 decimals), `vn` and `f a//a b//b c//c` for a surface's triangles, `l` lines for a
//! curve's polyline (at most [`LINE_LENGTH`] vertices each, consecutive lines sharing their
//! end vertex). OBJ has no place for other vertex data: the degrees follow in a comment
//! block, one `#deg truth indeterminacy falsity` line per vertex in order (for an
//! interval-valued or bipolar family its channels, named in the header's comment), numbers in
//! the shortest form that reads back to the same `f64`.

use std::fmt::Write as _;

use super::{comment_text, title, ColorBy, Samples};
use neutrospline_io::format_number as number;
use neutrospline_io::Model;

/// The most vertices of one `l` line.
pub(crate) const LINE_LENGTH: usize = 64;

/// A colour channel in \[0, 1\] to 6 decimals, without trailing zeros.
fn channel(byte: u8) -> String {
    let text = format!("{:.6}", f64::from(byte) / 255.0);
    let text = text.trim_end_matches('0').trim_end_matches('.');
    text.to_owned()
}

/// The OBJ file.
pub(super) fn obj(model: &Model, samples: &Samples, by: ColorBy) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "# neutrospline export of a {}",
        comment_text(&title(model), false)
    );
    if let Some(description) = model.description() {
        let _ = writeln!(out, "# description: {}", comment_text(description, false));
    }
    let _ = writeln!(out, "# membership: {}", model.membership());
    let _ = writeln!(out, "# v x y z r g b: r g b is the viridis colour of {by}");
    let (names, rows) = samples.value_columns();
    let _ = writeln!(
        out,
        "# degrees: the #deg lines at the end, one per vertex in order: {}",
        names.join(" ")
    );
    let name = model.name().unwrap_or(model.kind().name());
    let _ = writeln!(out, "o {}", comment_text(name, false));
    for (p, c) in samples.positions.iter().zip(samples.colors(by)) {
        let _ = writeln!(
            out,
            "v {} {} {} {} {} {}",
            number(p[0]),
            number(p[1]),
            number(p[2]),
            channel(c[0]),
            channel(c[1]),
            channel(c[2])
        );
    }
    if let Some(normals) = &samples.normals {
        for n in normals {
            let _ = writeln!(out, "vn {} {} {}", number(n[0]), number(n[1]), number(n[2]));
        }
    }
    match &samples.triangles {
        Some(triangles) => {
            for t in triangles {
                let [a, b, c] = t.map(|k| k + 1);
                let _ = writeln!(out, "f {a}//{a} {b}//{b} {c}//{c}");
            }
        }
        None => {
            let count = samples.positions.len();
            let mut start = 0;
            while start + 1 < count {
                let end = (start + LINE_LENGTH).min(count);
                out.push('l');
                for k in start..end {
                    let _ = write!(out, " {}", k + 1);
                }
                out.push('\n');
                start = end - 1;
            }
        }
    }
    for row in &rows {
        out.push_str("#deg");
        for v in row {
            let _ = write!(out, " {}", number(*v));
        }
        out.push('\n');
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn channels() {
        assert_eq!(channel(0), "0");
        assert_eq!(channel(255), "1");
        assert_eq!(channel(68), "0.266667");
    }
}
