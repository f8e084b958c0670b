//! The SVG encoding of a [`Drawing`]: the figure file.
//!
//! One element per line, indented by group depth, in the order of the drawing calls, so equal
//! drawings give equal bytes. Numbers are written by [`num`] (at most two decimals, never
//! `NaN` or `inf`); colours and styles come from `style`.

use std::fmt::Write as _;

use neutrospline::uniform_parameter;

use crate::drawing::Drawing;
use crate::encode::Encoder;
use crate::font::FONT_FAMILY_CSS;
use crate::page::Length;
use crate::style::{num, write_points, Anchor, Color, Style, TextStyle};

/// Escapes text for XML content and attribute values.
pub(crate) fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            c if (c as u32) < 0x20 && c != '\t' => out.push(' '),
            c => out.push(c),
        }
    }
    out
}

/// Writes the SVG presentation attributes of `style`: class, fill (and its opacity), stroke
/// (width, opacity, caps and joins, dashes).
fn style_attrs(out: &mut String, style: &Style) {
    if let Some(class) = &style.class {
        let _ = write!(out, " class=\"{}\"", escape(class));
    }
    match style.fill {
        Some(c) => {
            let _ = write!(out, " fill=\"{}\"", c.hex());
            if style.fill_opacity < 1.0 {
                let _ = write!(out, " fill-opacity=\"{}\"", num(style.fill_opacity));
            }
        }
        None => out.push_str(" fill=\"none\""),
    }
    if let Some(c) = style.stroke {
        let _ = write!(
            out,
            " stroke=\"{}\" stroke-width=\"{}\"",
            c.hex(),
            num(style.stroke_width)
        );
        if style.stroke_opacity < 1.0 {
            let _ = write!(out, " stroke-opacity=\"{}\"", num(style.stroke_opacity));
        }
        if style.round {
            out.push_str(" stroke-linecap=\"round\" stroke-linejoin=\"round\"");
        } else {
            out.push_str(" stroke-linejoin=\"miter\"");
        }
        if let Some([on, off]) = style.dash {
            let _ = write!(out, " stroke-dasharray=\"{} {}\"", num(on), num(off));
        }
    }
}

impl Drawing {
    /// The drawing as an SVG document: the figure file.
    ///
    /// Deterministic (equal drawings give equal bytes); `<text>` elements use the bundled
    /// font's family ([`FONT_FAMILY`](crate::FONT_FAMILY)).
    pub fn to_svg(&self) -> String {
        let mut w = SvgText {
            out: String::with_capacity(64 * 1024),
            depth: 1,
        };
        w.header(self.width, self.height, self.print, &self.title);
        self.encode(&mut w);
        w.out.push_str("</svg>\n");
        w.out
    }
}

/// The SVG text of a drawing being written, one element per line, indented by group depth.
struct SvgText {
    out: String,
    depth: usize,
}

impl SvgText {
    fn header(&mut self, width: u32, height: u32, print: Option<(Length, Length)>, title: &str) {
        let out = &mut self.out;
        out.push_str("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
        // A print size is stated in its units; the canvas (in points) is the view box.
        let (w, h) = match print {
            Some((w, h)) => (w.to_string(), h.to_string()),
            None => (width.to_string(), height.to_string()),
        };
        let _ = writeln!(
            out,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"{w}\" \
             height=\"{h}\" viewBox=\"0 0 {width} {height}\" font-family=\"{FONT_FAMILY_CSS}\">"
        );
        if !title.is_empty() {
            let _ = writeln!(out, "<title>{}</title>", escape(title));
        }
        let _ = writeln!(
            out,
            "<rect x=\"0\" y=\"0\" width=\"{width}\" height=\"{height}\" fill=\"#ffffff\"/>"
        );
    }

    /// Starts a line: indents it by the group depth and returns the text to write it to.
    fn line_start(&mut self) -> &mut String {
        for _ in 0..self.depth {
            self.out.push(' ');
        }
        &mut self.out
    }

    /// Writes a shape: `<{tag}` and its geometry (`geometry` writes the attributes), the
    /// style's attributes, and the closing `/>`.
    fn shape(&mut self, tag: &str, style: &Style, geometry: impl FnOnce(&mut String)) {
        let out = self.line_start();
        out.push('<');
        out.push_str(tag);
        geometry(out);
        style_attrs(out, style);
        out.push_str("/>\n");
    }
}

impl<'a> Encoder<'a> for SvgText {
    fn group(&mut self, class: &'a str) {
        let _ = writeln!(self.line_start(), "<g class=\"{}\">", escape(class));
        self.depth += 1;
    }

    fn mesh_group(&mut self, class: &'a str, stroke_width: f64) {
        let _ = writeln!(
            self.line_start(),
            "<g class=\"{}\" fill=\"none\" stroke-width=\"{}\" stroke-linejoin=\"round\">",
            escape(class),
            num(stroke_width)
        );
        self.depth += 1;
    }

    fn clip(&mut self, id: &'a str, rect: [f64; 4]) {
        let out = self.line_start();
        let _ = write!(out, "<clipPath id=\"{id}\"><rect");
        rect_attrs(out, rect);
        out.push_str("/></clipPath>\n");
        let _ = writeln!(self.line_start(), "<g clip-path=\"url(#{id})\">");
        self.depth += 1;
    }

    fn end(&mut self) {
        self.depth = self.depth.saturating_sub(1);
        self.line_start().push_str("</g>\n");
    }

    fn rect(&mut self, rect: [f64; 4], style: &'a Style) {
        self.shape("rect", style, |out| rect_attrs(out, rect));
    }

    fn line(&mut self, a: (f64, f64), b: (f64, f64), style: &'a Style) {
        self.shape("line", style, |out| line_attrs(out, a, b));
    }

    fn polyline(&mut self, points: &'a [(f64, f64)], style: &'a Style) {
        self.shape("polyline", style, |out| points_attr(out, points));
    }

    fn polygon(&mut self, points: &'a [(f64, f64)], style: &'a Style) {
        self.shape("polygon", style, |out| points_attr(out, points));
    }

    fn circle(&mut self, centre: (f64, f64), radius: f64, style: &'a Style) {
        self.shape("circle", style, |out| {
            let _ = write!(
                out,
                " cx=\"{}\" cy=\"{}\" r=\"{}\"",
                num(centre.0),
                num(centre.1),
                num(radius)
            );
        });
    }

    fn text(&mut self, x: f64, y: f64, text: &'a str, style: &'a TextStyle) {
        text_element(self.line_start(), x, y, text, style);
    }

    fn face(&mut self, points: &'a [(f64, f64)], color: Color) {
        let out = self.line_start();
        out.push_str("<polygon");
        points_attr(out, points);
        let hex = color.hex();
        let _ = writeln!(out, " fill=\"{hex}\" stroke=\"{hex}\"/>");
    }

    fn edge(&mut self, a: (f64, f64), b: (f64, f64), color: Color) {
        let out = self.line_start();
        out.push_str("<line");
        line_attrs(out, a, b);
        let _ = writeln!(out, " stroke=\"{}\"/>", color.hex());
    }

    fn gradient(&mut self, id: &'a str, stops: &'a [Color]) {
        let _ = writeln!(
            self.line_start(),
            "<defs><linearGradient id=\"{id}\" x1=\"0\" y1=\"1\" x2=\"0\" y2=\"0\">"
        );
        for (i, c) in stops.iter().enumerate() {
            let _ = writeln!(
                self.line_start(),
                " <stop offset=\"{}\" stop-color=\"{}\"/>",
                num(uniform_parameter(i, stops.len(), 0.0..1.0)),
                c.hex()
            );
        }
        self.line_start().push_str("</linearGradient></defs>\n");
    }

    fn gradient_rect(&mut self, id: &'a str, rect: [f64; 4]) {
        let out = self.line_start();
        out.push_str("<rect");
        rect_attrs(out, rect);
        let _ = writeln!(out, " fill=\"url(#{id})\"/>");
    }
}

/// ` x=".." y=".." width=".." height=".."` of `[x, y, w, h]`.
fn rect_attrs(out: &mut String, [x, y, w, h]: [f64; 4]) {
    let _ = write!(
        out,
        " x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"",
        num(x),
        num(y),
        num(w),
        num(h)
    );
}

/// ` x1=".." y1=".." x2=".." y2=".."` of the line from `a` to `b`.
fn line_attrs(out: &mut String, a: (f64, f64), b: (f64, f64)) {
    let _ = write!(
        out,
        " x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\"",
        num(a.0),
        num(a.1),
        num(b.0),
        num(b.1)
    );
}

/// ` points="x0,y0 x1,y1 ..."`.
fn points_attr(out: &mut String, points: &[(f64, f64)]) {
    out.push_str(" points=\"");
    write_points(out, points, ' ');
    out.push('"');
}

fn text_element(out: &mut String, x: f64, y: f64, text: &str, style: &TextStyle) {
    let _ = write!(out, "<text x=\"{}\" y=\"{}\"", num(x), num(y));
    if let Some(class) = &style.class {
        let _ = write!(out, " class=\"{}\"", escape(class));
    }
    let _ = write!(
        out,
        " font-size=\"{}\" fill=\"{}\"",
        num(style.size),
        style.color.hex()
    );
    if style.bold {
        out.push_str(" font-weight=\"bold\"");
    }
    match style.anchor {
        Anchor::Start => {}
        Anchor::Middle => out.push_str(" text-anchor=\"middle\""),
        Anchor::End => out.push_str(" text-anchor=\"end\""),
    }
    if style.rotate != 0.0 {
        let _ = write!(
            out,
            " transform=\"rotate({} {} {})\"",
            num(style.rotate),
            num(x),
            num(y)
        );
    }
    if style.halo > 0.0 {
        let _ = write!(
            out,
            " stroke=\"#ffffff\" stroke-width=\"{}\" stroke-linejoin=\"round\" paint-order=\"stroke\"",
            num(style.halo)
        );
    }
    let _ = writeln!(out, ">{}</text>", escape(text));
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::drawing::Painter;

    #[test]
    fn escape_xml() {
        assert_eq!(escape("a<b & \"c\""), "a&lt;b &amp; &quot;c&quot;");
    }

    #[test]
    fn writer_document_is_closed() {
        let mut w = Painter::new(10, 20, "t");
        w.begin_group("g");
        w.polyline(
            &[(0.0, 0.0), (1.0, 1.0)],
            &Style::stroke(Color(0, 0, 0), 1.0),
        );
        let s = w.finish().to_svg();
        assert!(s.starts_with("<?xml"));
        assert!(s.ends_with("</g>\n</svg>\n"));
        assert!(s.contains("points=\"0,0 1,1\""));
    }
}
