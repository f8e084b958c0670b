//! Colours and styles of the primitives, and the SVG encoding of a [`Drawing`]: the figure
//! file.
//!
//! Coordinates and lengths are written with at most two decimals (trailing zeros removed,
//! `-0` written as `0`); a non-finite number is written as `0`, so no output ever contains
//! `NaN` or `inf`. Element order is the order of the calls, so equal input gives equal bytes.

use std::fmt::Write as _;

use neutrospline::uniform_parameter;

use crate::drawing::{Drawing, Element};
use crate::font::FONT_FAMILY_CSS;

/// An sRGB colour.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Color(pub u8, pub u8, pub u8);

impl Color {
    pub(crate) const WHITE: Color = Color(255, 255, 255);

    /// Linear interpolation in sRGB between `self` (at 0) and `other` (at 1).
    pub(crate) fn mix(self, other: Color, t: f64) -> Color {
        let t = if t.is_finite() {
            t.clamp(0.0, 1.0)
        } else {
            0.0
        };
        let f = |a: u8, b: u8| (f64::from(a) + (f64::from(b) - f64::from(a)) * t).round() as u8;
        Color(f(self.0, other.0), f(self.1, other.1), f(self.2, other.2))
    }

    pub(crate) fn hex(self) -> String {
        format!("#{:02x}{:02x}{:02x}", self.0, self.1, self.2)
    }
}

/// Formats a number with at most two decimals, deterministically: `format!("{v:.2}")` (which
/// rounds the exact binary value), trailing zeros and a trailing point removed, `-0` as `0`,
/// and a non-finite number as `0`.
pub(crate) fn num(v: f64) -> String {
    if !v.is_finite() {
        return "0".to_string();
    }
    // Fast path (figures write hundreds of thousands of numbers): hundredths as an integer,
    // when rounding `100 v` cannot differ from rounding the exact decimal expansion of `v`:
    // `100 v` is computed with a relative error below 2^-52, so below 1e9 its absolute error
    // is under 1e-6, and only fractions within that of one half could round differently.
    let scaled = v * 100.0;
    let fraction = scaled - scaled.floor();
    if scaled.abs() < 1e9 && (fraction - 0.5).abs() > 1e-6 {
        let hundredths = scaled.round() as i64;
        if hundredths == 0 {
            return "0".to_string();
        }
        let (whole, cents) = (hundredths.abs() / 100, hundredths.abs() % 100);
        let sign = if hundredths < 0 { "-" } else { "" };
        return match (cents / 10, cents % 10) {
            (0, 0) => format!("{sign}{whole}"),
            (tenths, 0) => format!("{sign}{whole}.{tenths}"),
            _ => format!("{sign}{whole}.{cents:02}"),
        };
    }
    num_by_format(v)
}

/// [`num`] the slow way, which defines it: `format!("{v:.2}")`, trailing zeros and a trailing
/// point removed, `-0` as `0`.
fn num_by_format(v: f64) -> String {
    let s = format!("{v:.2}");
    let s = if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    };
    if s == "-0" {
        "0".to_string()
    } else {
        s
    }
}

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

/// Stroke and fill of a shape.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Style {
    pub stroke: Option<Color>,
    pub stroke_width: f64,
    pub dash: Option<[f64; 2]>,
    pub fill: Option<Color>,
    pub fill_opacity: f64,
    pub stroke_opacity: f64,
    /// Round caps and joins (else butt caps, miter joins).
    pub round: bool,
    pub class: Option<String>,
}

impl Style {
    pub(crate) fn stroke(color: Color, width: f64) -> Style {
        Style {
            stroke: Some(color),
            stroke_width: width,
            dash: None,
            fill: None,
            fill_opacity: 1.0,
            stroke_opacity: 1.0,
            round: true,
            class: None,
        }
    }

    pub(crate) fn fill(color: Color) -> Style {
        Style {
            stroke: None,
            stroke_width: 0.0,
            dash: None,
            fill: Some(color),
            fill_opacity: 1.0,
            stroke_opacity: 1.0,
            round: true,
            class: None,
        }
    }

    pub(crate) fn with_fill(mut self, color: Color) -> Style {
        self.fill = Some(color);
        self
    }

    pub(crate) fn with_dash(mut self, on: f64, off: f64) -> Style {
        self.dash = Some([on, off]);
        self
    }

    pub(crate) fn with_fill_opacity(mut self, a: f64) -> Style {
        self.fill_opacity = a;
        self
    }

    pub(crate) fn square(mut self) -> Style {
        self.round = false;
        self
    }

    pub(crate) fn with_class(mut self, class: &str) -> Style {
        self.class = Some(class.to_string());
        self
    }

    fn write_attrs(&self, out: &mut String) {
        if let Some(class) = &self.class {
            let _ = write!(out, " class=\"{}\"", escape(class));
        }
        match self.fill {
            Some(c) => {
                let _ = write!(out, " fill=\"{}\"", c.hex());
                if self.fill_opacity < 1.0 {
                    let _ = write!(out, " fill-opacity=\"{}\"", num(self.fill_opacity));
                }
            }
            None => out.push_str(" fill=\"none\""),
        }
        if let Some(c) = self.stroke {
            let _ = write!(
                out,
                " stroke=\"{}\" stroke-width=\"{}\"",
                c.hex(),
                num(self.stroke_width)
            );
            if self.stroke_opacity < 1.0 {
                let _ = write!(out, " stroke-opacity=\"{}\"", num(self.stroke_opacity));
            }
            if self.round {
                out.push_str(" stroke-linecap=\"round\" stroke-linejoin=\"round\"");
            } else {
                out.push_str(" stroke-linejoin=\"miter\"");
            }
            if let Some([on, off]) = self.dash {
                let _ = write!(out, " stroke-dasharray=\"{} {}\"", num(on), num(off));
            }
        }
    }
}

/// Horizontal alignment of a text run relative to its anchor point.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Anchor {
    Start,
    Middle,
    End,
}

/// How a text run is set.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct TextStyle {
    pub size: f64,
    pub bold: bool,
    pub color: Color,
    pub anchor: Anchor,
    /// Rotation in degrees about the anchor point (negative is counter-clockwise on screen).
    pub rotate: f64,
    /// Width of a white halo drawn behind the glyphs (0 for none).
    pub halo: f64,
    pub class: Option<String>,
}

impl TextStyle {
    pub(crate) fn new(size: f64, color: Color) -> TextStyle {
        TextStyle {
            size,
            bold: false,
            color,
            anchor: Anchor::Start,
            rotate: 0.0,
            halo: 0.0,
            class: None,
        }
    }

    pub(crate) fn bold(mut self) -> TextStyle {
        self.bold = true;
        self
    }

    pub(crate) fn anchor(mut self, anchor: Anchor) -> TextStyle {
        self.anchor = anchor;
        self
    }

    pub(crate) fn rotate(mut self, degrees: f64) -> TextStyle {
        self.rotate = degrees;
        self
    }

    pub(crate) fn halo(mut self, width: f64) -> TextStyle {
        self.halo = width;
        self
    }

    pub(crate) fn with_class(mut self, class: &str) -> TextStyle {
        self.class = Some(class.to_string());
        self
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
        w.header(self.width, self.height, &self.title);
        for element in &self.elements {
            w.element(element);
        }
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
    fn header(&mut self, width: u32, height: u32, title: &str) {
        let out = &mut self.out;
        out.push_str("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
        let _ = writeln!(
            out,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"{width}\" \
             height=\"{height}\" viewBox=\"0 0 {width} {height}\" font-family=\"{FONT_FAMILY_CSS}\">"
        );
        if !title.is_empty() {
            let _ = writeln!(out, "<title>{}</title>", escape(title));
        }
        let _ = writeln!(
            out,
            "<rect x=\"0\" y=\"0\" width=\"{width}\" height=\"{height}\" fill=\"#ffffff\"/>"
        );
    }

    fn indent(&mut self) {
        for _ in 0..self.depth {
            self.out.push(' ');
        }
    }

    fn element(&mut self, element: &Element) {
        if matches!(element, Element::End) {
            self.depth = self.depth.saturating_sub(1);
        }
        self.indent();
        let out = &mut self.out;
        match element {
            Element::Group(class) => {
                let _ = writeln!(out, "<g class=\"{}\">", escape(class));
                self.depth += 1;
            }
            Element::MeshGroup(class, width) => {
                let _ = writeln!(
                    out,
                    "<g class=\"{}\" fill=\"none\" stroke-width=\"{}\" stroke-linejoin=\"round\">",
                    escape(class),
                    num(*width)
                );
                self.depth += 1;
            }
            Element::Clip(id, [x, y, w, h]) => {
                let _ = writeln!(
                    out,
                    "<clipPath id=\"{id}\"><rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"/></clipPath>",
                    num(*x),
                    num(*y),
                    num(w.max(0.0)),
                    num(h.max(0.0))
                );
                self.indent();
                let _ = writeln!(self.out, "<g clip-path=\"url(#{id})\">");
                self.depth += 1;
            }
            Element::End => out.push_str("</g>\n"),
            Element::Rect([x, y, w, h], style) => {
                let _ = write!(
                    out,
                    "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"",
                    num(*x),
                    num(*y),
                    num(w.max(0.0)),
                    num(h.max(0.0))
                );
                style.write_attrs(out);
                out.push_str("/>\n");
            }
            Element::Line(a, b, style) => {
                let _ = write!(
                    out,
                    "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\"",
                    num(a.0),
                    num(a.1),
                    num(b.0),
                    num(b.1)
                );
                style.write_attrs(out);
                out.push_str("/>\n");
            }
            Element::Polyline(points, style) | Element::Polygon(points, style) => {
                out.push_str(if matches!(element, Element::Polygon(..)) {
                    "<polygon"
                } else {
                    "<polyline"
                });
                points_attr(out, points);
                style.write_attrs(out);
                out.push_str("/>\n");
            }
            Element::Circle(c, r, style) => {
                let _ = write!(
                    out,
                    "<circle cx=\"{}\" cy=\"{}\" r=\"{}\"",
                    num(c.0),
                    num(c.1),
                    num(r.max(0.0))
                );
                style.write_attrs(out);
                out.push_str("/>\n");
            }
            Element::Text(x, y, text, style) => text_element(out, *x, *y, text, style),
            Element::Face(points, color) => {
                out.push_str("<polygon");
                points_attr(out, points);
                let hex = color.hex();
                let _ = writeln!(out, " fill=\"{hex}\" stroke=\"{hex}\"/>");
            }
            Element::Edge(a, b, color) => {
                let _ = writeln!(
                    out,
                    "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"{}\"/>",
                    num(a.0),
                    num(a.1),
                    num(b.0),
                    num(b.1),
                    color.hex()
                );
            }
            Element::Gradient(id, stops) => {
                let _ = writeln!(
                    out,
                    "<defs><linearGradient id=\"{id}\" x1=\"0\" y1=\"1\" x2=\"0\" y2=\"0\">"
                );
                for (i, c) in stops.iter().enumerate() {
                    self.indent();
                    let _ = writeln!(
                        self.out,
                        " <stop offset=\"{}\" stop-color=\"{}\"/>",
                        num(uniform_parameter(i, stops.len(), 0.0..1.0)),
                        c.hex()
                    );
                }
                self.indent();
                self.out.push_str("</linearGradient></defs>\n");
            }
            Element::GradientRect(id, [x, y, w, h]) => {
                let _ = writeln!(
                    out,
                    "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"url(#{id})\"/>",
                    num(*x),
                    num(*y),
                    num(w.max(0.0)),
                    num(h.max(0.0))
                );
            }
        }
    }
}

fn points_attr(out: &mut String, points: &[(f64, f64)]) {
    out.push_str(" points=\"");
    for (i, p) in points.iter().enumerate() {
        if i > 0 {
            out.push(' ');
        }
        let _ = write!(out, "{},{}", num(p.0), num(p.1));
    }
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
    fn num_formats_two_decimals() {
        assert_eq!(num(1.0), "1");
        assert_eq!(num(1.234), "1.23");
        assert_eq!(num(1.5), "1.5");
        assert_eq!(num(-0.001), "0");
        assert_eq!(num(-2.0), "-2");
        assert_eq!(num(f64::NAN), "0");
        assert_eq!(num(f64::INFINITY), "0");
        assert_eq!(num(100.0), "100");
        assert_eq!(num(-0.004), "0");
        assert_eq!(num(-0.005), "-0.01");
        assert_eq!(num(0.125), "0.12");
        assert_eq!(num(-12.34), "-12.34");
        assert_eq!(num(1e12 + 0.25), "1000000000000.25");
    }

    /// The fast path agrees with `format!("{v:.2}")` trimmed, on numbers of every size and on
    /// the ties and near-ties of the rounding.
    #[test]
    fn num_matches_the_formatter() {
        let slow = num_by_format;
        let mut state = 0x2545_f491_4f6c_dd1d_u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        for _ in 0..200_000 {
            let r = next();
            let magnitude = 10f64.powi((r % 14) as i32 - 4);
            let unit = (next() >> 11) as f64 / (1u64 << 53) as f64;
            let v = (unit - 0.5) * magnitude;
            assert_eq!(num(v), slow(v), "{v:e}");
            // Ties in hundredths: x.xx5 and its neighbours.
            let tie = ((next() % 2_000_000) as f64 - 1_000_000.0 + 0.5) / 100.0;
            for w in [
                tie,
                f64::from_bits(tie.to_bits() + 1),
                f64::from_bits(tie.to_bits() - 1),
            ] {
                assert_eq!(num(w), slow(w), "{w:e}");
            }
        }
    }

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

    #[test]
    fn color_mix_endpoints() {
        let a = Color(0, 0, 0);
        let b = Color(200, 100, 50);
        assert_eq!(a.mix(b, 0.0), a);
        assert_eq!(a.mix(b, 1.0), b);
        assert_eq!(a.mix(b, 0.5), Color(100, 50, 25));
    }
}
