//! The PDF encoding of a [`Drawing`]: a one-page vector figure for a LaTeX paper, with the
//! bundled font embedded.
//!
//! The page is the figure's size in points; the drawing's units are mapped onto it by one
//! transformation (`cm`), y flipped, so every primitive keeps the coordinates the SVG has.
//! Shapes and text follow the SVG's rules: fills are non-zero, strokes have butt caps and
//! miter joins (limit 4) or round caps and joins, dashes start at 0, opacities come from
//! graphics states, a gradient is an axial shading clipped to its rectangle, text is set in
//! the bundled DejaVu Sans (regular and bold) embedded as a subset (CID-keyed TrueType,
//! glyph ids kept, with a `ToUnicode` map so that the text can be searched and copied) and
//! placed with the same advance widths the layout measured. Streams are deflated. Equal
//! drawings give equal bytes (no dates, no random ids).

use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write as _;

use neutrospline::uniform_parameter;

use crate::drawing::Drawing;
use crate::encode::Encoder;
use crate::font::{metrics, postscript_name, text_width, u16_at, Metrics};
use crate::style::{num, Anchor, Color, Style, TextStyle};
use crate::subset::subset;

/// The control-point distance of a cubic Bézier quarter circle, as a fraction of the radius.
const KAPPA: f64 = 0.552_284_749_830_793_4;

impl Drawing {
    /// The drawing as a one-page PDF document of `page_width` x `page_height` points (1/72
    /// inch), the drawing scaled to fill the page.
    ///
    /// ```
    /// use neutrospline_plot::{render_drawing, PlotModel, PlotOptions, View};
    /// let model = PlotModel::from(&neutrospline::example1());
    /// let drawing = render_drawing(&model, View::All, &PlotOptions::default())?;
    /// let pdf = drawing.to_pdf(1200.0, 900.0);
    /// assert!(pdf.starts_with(b"%PDF-1.7"));
    /// assert!(pdf.ends_with(b"%%EOF\n"));
    /// # Ok::<(), neutrospline_plot::PlotError>(())
    /// ```
    pub fn to_pdf(&self, page_width: f64, page_height: f64) -> Vec<u8> {
        let mut content = PdfContent::default();
        let sx = page_width / f64::from(self.width.max(1));
        let sy = page_height / f64::from(self.height.max(1));
        let _ = writeln!(
            content.out,
            "{} 0 0 {} 0 {} cm 4 M",
            real(sx),
            real(-sy),
            real(page_height)
        );
        let _ = writeln!(
            content.out,
            "1 1 1 rg 0 0 {} {} re f",
            self.width, self.height
        );
        self.encode(&mut content);
        content.document(page_width, page_height, &self.title)
    }
}

/// A number with up to six decimals (scales and colour components), trailing zeros removed.
fn real(v: f64) -> String {
    if !v.is_finite() {
        return "0".into();
    }
    let s = format!("{v:.6}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" || s.is_empty() {
        "0".into()
    } else {
        s.to_string()
    }
}

/// `r g b` of a colour, each in \[0, 1\].
fn rgb(c: Color) -> String {
    let channel = |v: u8| real(f64::from(v) / 255.0);
    format!("{} {} {}", channel(c.0), channel(c.1), channel(c.2))
}

/// The content stream being written and the resources it uses.
#[derive(Default)]
struct PdfContent<'a> {
    out: String,
    /// Per face (regular, bold): the glyphs used and a character of each (for `ToUnicode`).
    glyphs: [BTreeMap<u16, char>; 2],
    /// Graphics states by (fill, stroke) opacity in thousandths.
    alphas: BTreeMap<(u16, u16), usize>,
    /// The colour stops of each gradient, by id.
    gradients: BTreeMap<&'a str, &'a [Color]>,
    /// Shadings: the stops and the rectangle each fills.
    shadings: Vec<(&'a [Color], [f64; 4])>,
}

impl<'a> PdfContent<'a> {
    fn point(&mut self, (x, y): (f64, f64), op: &str) {
        let _ = writeln!(self.out, "{} {} {op}", num(x), num(y));
    }

    fn path(&mut self, points: &[(f64, f64)], close: bool) {
        for (i, &p) in points.iter().enumerate() {
            self.point(p, if i == 0 { "m" } else { "l" });
        }
        if close {
            self.out.push_str("h\n");
        }
    }

    /// The graphics state name for these opacities (`None` when both are 1).
    fn alpha(&mut self, fill: f64, stroke: f64) -> Option<usize> {
        let key = |a: f64| (a.clamp(0.0, 1.0) * 1000.0).round() as u16;
        let k = (key(fill), key(stroke));
        if k == (1000, 1000) {
            return None;
        }
        let next = self.alphas.len();
        Some(*self.alphas.entry(k).or_insert(next))
    }

    /// `q`, the style's colours, stroke and opacity; then `path` draws the geometry; then
    /// the paint operator and `Q`.
    fn shape(&mut self, style: &Style, path: impl FnOnce(&mut Self)) {
        self.out.push_str("q\n");
        if let Some(fill) = style.fill {
            let _ = writeln!(self.out, "{} rg", rgb(fill));
        }
        if let Some(stroke) = style.stroke {
            let _ = write!(
                self.out,
                "{} RG {} w {}",
                rgb(stroke),
                num(style.stroke_width),
                if style.round { "1 J 1 j" } else { "0 J 0 j" }
            );
            if let Some([on, off]) = style.dash {
                let _ = write!(self.out, " [{} {}] 0 d", num(on), num(off));
            }
            self.out.push('\n');
        }
        let fill_alpha = if style.fill.is_some() {
            style.fill_opacity
        } else {
            1.0
        };
        let stroke_alpha = if style.stroke.is_some() {
            style.stroke_opacity
        } else {
            1.0
        };
        if let Some(gs) = self.alpha(fill_alpha, stroke_alpha) {
            let _ = writeln!(self.out, "/GS{gs} gs");
        }
        path(self);
        let op = match (style.fill.is_some(), style.stroke.is_some()) {
            (true, true) => "B",
            (true, false) => "f",
            (false, true) => "S",
            (false, false) => "n",
        };
        let _ = writeln!(self.out, "{op}\nQ");
    }

    /// The glyph ids of `text` as a hex string, recording them for the font's subset.
    fn glyph_string(&mut self, text: &str, bold: bool) -> String {
        let face = metrics(bold);
        let used = &mut self.glyphs[usize::from(bold)];
        let mut hex = String::with_capacity(4 * text.len() + 2);
        hex.push('<');
        for c in text.chars() {
            let c = if (c as u32) < 0x20 { ' ' } else { c };
            let g = face.glyph(c);
            used.entry(g).or_insert(c);
            let _ = write!(hex, "{g:04X}");
        }
        hex.push('>');
        hex
    }

    /// The whole document around the content stream.
    fn document(mut self, width: f64, height: f64, title: &str) -> Vec<u8> {
        let mut pdf = PdfWriter::default();
        // Objects 1-5: catalog, pages, page, content, info; fonts from 6.
        let mut fonts = String::new();
        let mut next = 6;
        let mut font_objects = Vec::new();
        for bold in [false, true] {
            let used = std::mem::take(&mut self.glyphs[usize::from(bold)]);
            if used.is_empty() {
                continue;
            }
            let _ = write!(fonts, "/F{} {next} 0 R ", usize::from(bold));
            font_objects.push((next, bold, used));
            next += 5;
        }
        let mut resources = format!("<< /Font << {fonts}>>");
        if !self.alphas.is_empty() {
            resources.push_str(" /ExtGState <<");
            for (&(fill, stroke), &k) in &self.alphas {
                let _ = write!(
                    resources,
                    " /GS{k} << /ca {} /CA {} >>",
                    real(f64::from(fill) / 1000.0),
                    real(f64::from(stroke) / 1000.0)
                );
            }
            resources.push_str(" >>");
        }
        if !self.shadings.is_empty() {
            resources.push_str(" /Shading <<");
            for (k, (stops, [x, y, _, h])) in self.shadings.iter().enumerate() {
                let _ = write!(
                    resources,
                    " /Sh{k} << /ShadingType 2 /ColorSpace /DeviceRGB /Coords [{} {} {} {}] \
                     /Function {} /Extend [true true] >>",
                    num(*x),
                    num(y + h),
                    num(*x),
                    num(*y),
                    gradient_function(stops)
                );
            }
            resources.push_str(" >>");
        }
        resources.push_str(" >>");

        pdf.object(1, "<< /Type /Catalog /Pages 2 0 R >>");
        pdf.object(2, "<< /Type /Pages /Kids [3 0 R] /Count 1 >>");
        pdf.object(
            3,
            &format!(
                "<< /Type /Page /Parent 2 0 R /MediaBox [0 0 {} {}] /Resources {resources} \
                 /Contents 4 0 R >>",
                real(width),
                real(height)
            ),
        );
        pdf.stream(4, "", self.out.as_bytes());
        pdf.object(
            5,
            &format!(
                "<< /Title {} /Producer (neutrospline-plot {}) >>",
                utf16_text(title),
                env!("CARGO_PKG_VERSION")
            ),
        );
        for (first, bold, used) in font_objects {
            embed_font(&mut pdf, first, bold, &used);
        }
        pdf.finish(next - 1)
    }
}

/// A stitching function through evenly spaced colour stops (bottom to top).
fn gradient_function(stops: &[Color]) -> String {
    let c = |c: Color| format!("[{}]", rgb(c));
    let pieces: Vec<String> = match stops {
        [] => vec![format!(
            "<< /FunctionType 2 /Domain [0 1] /C0 [0 0 0] /C1 [0 0 0] /N 1 >>"
        )],
        [only] => vec![format!(
            "<< /FunctionType 2 /Domain [0 1] /C0 {} /C1 {} /N 1 >>",
            c(*only),
            c(*only)
        )],
        _ => stops
            .windows(2)
            .map(|w| {
                format!(
                    "<< /FunctionType 2 /Domain [0 1] /C0 {} /C1 {} /N 1 >>",
                    c(w[0]),
                    c(w[1])
                )
            })
            .collect(),
    };
    let n = pieces.len();
    let bounds: Vec<String> = (1..n)
        .map(|i| real(uniform_parameter(i, n + 1, 0.0..1.0)))
        .collect();
    let encode: Vec<&str> = (0..n).map(|_| "0 1").collect();
    format!(
        "<< /FunctionType 3 /Domain [0 1] /Functions [{}] /Bounds [{}] /Encode [{}] >>",
        pieces.join(" "),
        bounds.join(" "),
        encode.join(" ")
    )
}

/// A PDF text string: UTF-16BE with its byte order mark, in hex.
fn utf16_text(text: &str) -> String {
    let mut out = String::from("<FEFF");
    for unit in text.encode_utf16() {
        let _ = write!(out, "{unit:04X}");
    }
    out.push('>');
    out
}

/// Six capital letters naming a subset, from its glyphs (the same glyphs, the same tag).
fn subset_tag(used: &BTreeMap<u16, char>) -> String {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for &g in used.keys() {
        for b in g.to_be_bytes() {
            h ^= u64::from(b);
            h = h.wrapping_mul(0x0100_0000_01b3);
        }
    }
    (0..6)
        .map(|i| char::from(b'A' + ((h >> (i * 8)) % 26) as u8))
        .collect()
}

fn i16_at(data: &[u8], at: usize) -> i16 {
    u16_at(data, at).map_or(0, |v| v as i16)
}

/// Writes the five objects of a font from `first`: the Type 0 font, its CID font, the
/// descriptor, the subset font file and the `ToUnicode` map.
fn embed_font(pdf: &mut PdfWriter, first: usize, bold: bool, used: &BTreeMap<u16, char>) {
    let face: &Metrics = metrics(bold);
    let name = format!("{}+{}", subset_tag(used), postscript_name(bold));
    let em = |units: f64| real((units * 1000.0 / face.units_per_em).round());
    let data = face.data;
    let head = Metrics::table(data, b"head").unwrap_or(0);
    let hhea = Metrics::table(data, b"hhea").unwrap_or(0);
    let bbox = [36, 38, 40, 42].map(|o| em(f64::from(i16_at(data, head + o))));
    let ascent = em(f64::from(i16_at(data, hhea + 4)));
    let descent = em(f64::from(i16_at(data, hhea + 6)));
    let cap_height = match Metrics::table(data, b"OS/2") {
        Some(os2) if u16_at(data, os2).unwrap_or(0) >= 2 => em(f64::from(i16_at(data, os2 + 88))),
        _ => ascent.clone(),
    };
    let mut widths = String::new();
    for &g in used.keys() {
        let _ = write!(widths, "{g} [{}] ", em(f64::from(face.glyph_advance(g))));
    }
    pdf.object(
        first,
        &format!(
            "<< /Type /Font /Subtype /Type0 /BaseFont /{name} /Encoding /Identity-H \
             /DescendantFonts [{} 0 R] /ToUnicode {} 0 R >>",
            first + 1,
            first + 4
        ),
    );
    pdf.object(
        first + 1,
        &format!(
            "<< /Type /Font /Subtype /CIDFontType2 /BaseFont /{name} /CIDSystemInfo << \
             /Registry (Adobe) /Ordering (Identity) /Supplement 0 >> /FontDescriptor {} 0 R \
             /W [{widths}] /CIDToGIDMap /Identity >>",
            first + 2
        ),
    );
    pdf.object(
        first + 2,
        &format!(
            "<< /Type /FontDescriptor /FontName /{name} /Flags 32 /FontBBox [{}] /ItalicAngle 0 \
             /Ascent {ascent} /Descent {descent} /CapHeight {cap_height} /StemV {} \
             /FontFile2 {} 0 R >>",
            bbox.join(" "),
            if bold { 140 } else { 80 },
            first + 3
        ),
    );
    let glyphs: BTreeSet<u16> = used.keys().copied().collect();
    // The bundled fonts are TrueType; a subset always succeeds for them (tested), else the
    // whole file is embedded.
    let file = subset(face, &glyphs).unwrap_or_else(|| data.to_vec());
    pdf.stream(first + 3, &format!("/Length1 {}", file.len()), &file);
    let mut cmap = String::from(
        "/CIDInit /ProcSet findresource begin 12 dict begin begincmap /CIDSystemInfo << \
         /Registry (Adobe) /Ordering (UCS) /Supplement 0 >> def /CMapName /Adobe-Identity-UCS \
         def /CMapType 2 def 1 begincodespacerange <0000> <FFFF> endcodespacerange\n",
    );
    let entries: Vec<(&u16, &char)> = used.iter().collect();
    for chunk in entries.chunks(100) {
        let _ = writeln!(cmap, "{} beginbfchar", chunk.len());
        for (g, c) in chunk {
            let mut units = [0u16; 2];
            let hex: String = c
                .encode_utf16(&mut units)
                .iter()
                .map(|u| format!("{u:04X}"))
                .collect();
            let _ = writeln!(cmap, "<{g:04X}> <{hex}>");
        }
        cmap.push_str("endbfchar\n");
    }
    cmap.push_str("endcmap CMapName currentdict /CMap defineresource pop end end\n");
    pdf.stream(first + 4, "", cmap.as_bytes());
}

/// The objects of a PDF file and their offsets.
#[derive(Default)]
struct PdfWriter {
    out: Vec<u8>,
    offsets: BTreeMap<usize, usize>,
}

impl PdfWriter {
    fn start(&mut self, id: usize) {
        if self.out.is_empty() {
            self.out.extend_from_slice(b"%PDF-1.7\n%\xe2\xe3\xcf\xd3\n");
        }
        self.offsets.insert(id, self.out.len());
        self.out
            .extend_from_slice(format!("{id} 0 obj\n").as_bytes());
    }

    fn object(&mut self, id: usize, body: &str) {
        self.start(id);
        self.out.extend_from_slice(body.as_bytes());
        self.out.extend_from_slice(b"\nendobj\n");
    }

    /// A deflated stream with extra dictionary entries `extra`.
    fn stream(&mut self, id: usize, extra: &str, data: &[u8]) {
        let packed = miniz_oxide::deflate::compress_to_vec_zlib(data, 6);
        self.start(id);
        self.out.extend_from_slice(
            format!(
                "<< /Length {} /Filter /FlateDecode {extra} >>\nstream\n",
                packed.len()
            )
            .as_bytes(),
        );
        self.out.extend_from_slice(&packed);
        self.out.extend_from_slice(b"\nendstream\nendobj\n");
    }

    /// The cross-reference table and trailer for objects 1..=last.
    fn finish(mut self, last: usize) -> Vec<u8> {
        let xref = self.out.len();
        let mut table = format!("xref\n0 {}\n0000000000 65535 f \n", last + 1);
        for id in 1..=last {
            match self.offsets.get(&id) {
                Some(offset) => {
                    // Each entry is exactly 20 bytes: the space before the newline belongs to it.
                    let _ = writeln!(table, "{offset:010} 00000 n ");
                }
                None => table.push_str("0000000000 65535 f \n"),
            }
        }
        let _ = write!(
            table,
            "trailer\n<< /Size {} /Root 1 0 R /Info 5 0 R >>\nstartxref\n{xref}\n%%EOF\n",
            last + 1
        );
        self.out.extend_from_slice(table.as_bytes());
        self.out
    }
}

impl<'a> Encoder<'a> for PdfContent<'a> {
    fn group(&mut self, _class: &'a str) {
        self.out.push_str("q\n");
    }

    fn mesh_group(&mut self, _class: &'a str, stroke_width: f64) {
        let _ = writeln!(self.out, "q {} w 0 J 1 j", num(stroke_width));
    }

    fn clip(&mut self, _id: &'a str, [x, y, w, h]: [f64; 4]) {
        let _ = writeln!(
            self.out,
            "q {} {} {} {} re W n",
            num(x),
            num(y),
            num(w),
            num(h)
        );
    }

    fn end(&mut self) {
        self.out.push_str("Q\n");
    }

    fn rect(&mut self, [x, y, w, h]: [f64; 4], style: &'a Style) {
        self.shape(style, |s| {
            let _ = writeln!(s.out, "{} {} {} {} re", num(x), num(y), num(w), num(h));
        });
    }

    fn line(&mut self, a: (f64, f64), b: (f64, f64), style: &'a Style) {
        self.shape(style, |s| s.path(&[a, b], false));
    }

    fn polyline(&mut self, points: &'a [(f64, f64)], style: &'a Style) {
        self.shape(style, |s| s.path(points, false));
    }

    fn polygon(&mut self, points: &'a [(f64, f64)], style: &'a Style) {
        self.shape(style, |s| s.path(points, true));
    }

    fn circle(&mut self, (cx, cy): (f64, f64), r: f64, style: &'a Style) {
        self.shape(style, |s| {
            let k = KAPPA * r;
            s.point((cx + r, cy), "m");
            for (c1, c2, end) in [
                ((cx + r, cy + k), (cx + k, cy + r), (cx, cy + r)),
                ((cx - k, cy + r), (cx - r, cy + k), (cx - r, cy)),
                ((cx - r, cy - k), (cx - k, cy - r), (cx, cy - r)),
                ((cx + k, cy - r), (cx + r, cy - k), (cx + r, cy)),
            ] {
                let _ = writeln!(
                    s.out,
                    "{} {} {} {} {} {} c",
                    num(c1.0),
                    num(c1.1),
                    num(c2.0),
                    num(c2.1),
                    num(end.0),
                    num(end.1)
                );
            }
            s.out.push_str("h\n");
        });
    }

    fn text(&mut self, x: f64, y: f64, text: &'a str, style: &'a TextStyle) {
        let glyphs = self.glyph_string(text, style.bold);
        let (sin, cos) = style.rotate.to_radians().sin_cos();
        let shift = match style.anchor {
            Anchor::Start => 0.0,
            Anchor::Middle => 0.5,
            Anchor::End => 1.0,
        } * text_width(text, style.size, style.bold);
        // Glyph space is y up; the page's user space here is y down (see `to_pdf`), so the
        // text matrix flips y back and turns by the rotation (clockwise on screen).
        let matrix = format!(
            "{} {} {} {} {} {}",
            real(cos),
            real(sin),
            real(sin),
            real(-cos),
            num(x - shift * cos),
            num(y - shift * sin)
        );
        let font = format!("/F{} {} Tf", usize::from(style.bold), num(style.size));
        self.out.push_str("q\n");
        if style.halo > 0.0 {
            let _ = writeln!(
                self.out,
                "1 1 1 RG {} w 1 J 1 j BT {font} {matrix} Tm 1 Tr {glyphs} Tj ET",
                num(style.halo)
            );
        }
        let _ = writeln!(
            self.out,
            "{} rg BT {font} {matrix} Tm 0 Tr {glyphs} Tj ET\nQ",
            rgb(style.color)
        );
    }

    fn face(&mut self, points: &'a [(f64, f64)], color: Color) {
        let c = rgb(color);
        let _ = writeln!(self.out, "{c} rg {c} RG");
        self.path(points, true);
        self.out.push_str("B\n");
    }

    fn edge(&mut self, a: (f64, f64), b: (f64, f64), color: Color) {
        let _ = writeln!(self.out, "{} RG", rgb(color));
        self.path(&[a, b], false);
        self.out.push_str("S\n");
    }

    fn gradient(&mut self, id: &'a str, stops: &'a [Color]) {
        self.gradients.insert(id, stops);
    }

    fn gradient_rect(&mut self, id: &'a str, rect: [f64; 4]) {
        let stops = self.gradients.get(id).copied().unwrap_or(&[]);
        let k = self.shadings.len();
        self.shadings.push((stops, rect));
        let [x, y, w, h] = rect;
        let _ = writeln!(
            self.out,
            "q {} {} {} {} re W n /Sh{k} sh Q",
            num(x),
            num(y),
            num(w),
            num(h)
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::drawing::Painter;

    fn inflate(data: &[u8]) -> Vec<u8> {
        miniz_oxide::inflate::decompress_to_vec_zlib(data).unwrap()
    }

    /// The streams of a PDF, inflated, in order.
    fn streams(pdf: &[u8]) -> Vec<Vec<u8>> {
        let mut out = Vec::new();
        let mut at = 0;
        while let Some(start) = find(&pdf[at..], b"stream\n") {
            let begin = at + start + 7;
            let end = begin + find(&pdf[begin..], b"\nendstream").unwrap();
            out.push(inflate(&pdf[begin..end]));
            at = end + b"\nendstream".len();
        }
        out
    }

    fn find(hay: &[u8], needle: &[u8]) -> Option<usize> {
        hay.windows(needle.len()).position(|w| w == needle)
    }

    #[test]
    fn the_xref_offsets_point_at_their_objects() {
        let mut p = Painter::new(100, 50, "A title é");
        p.rect(1.0, 2.0, 3.0, 4.0, &Style::fill(Color(255, 0, 0)));
        p.text(10.0, 20.0, "Bézier", &TextStyle::new(12.0, Color(0, 0, 0)));
        let pdf = p.finish().to_pdf(75.0, 37.5);
        let text = String::from_utf8_lossy(&pdf);
        let xref: usize = text
            .rsplit("startxref\n")
            .next()
            .unwrap()
            .lines()
            .next()
            .unwrap()
            .parse()
            .unwrap();
        assert!(pdf[xref..].starts_with(b"xref\n"));
        let table = &text[xref..];
        for (id, line) in table
            .lines()
            .skip(3)
            .take_while(|l| l.len() == 18)
            .enumerate()
        {
            let offset: usize = line[..10].parse().unwrap();
            assert!(
                pdf[offset..].starts_with(format!("{} 0 obj", id + 1).as_bytes()),
                "object {}",
                id + 1
            );
        }
        assert!(text.contains("/MediaBox [0 0 75 37.5]"));
        // The content: the page transform, the red rectangle, the text's glyph ids.
        let content = String::from_utf8(streams(&pdf)[0].clone()).unwrap();
        assert!(content.starts_with("0.75 0 0 -0.75 0 37.5 cm"), "{content}");
        assert!(content.contains("1 0 0 rg\n1 2 3 4 re\nf"), "{content}");
        let face = metrics(false);
        let ids: String = "Bézier"
            .chars()
            .map(|c| format!("{:04X}", face.glyph(c)))
            .collect();
        assert!(content.contains(&format!("<{ids}> Tj")), "{content}");
        // The ToUnicode map sends each glyph back to its character.
        let cmap = String::from_utf8(streams(&pdf).last().unwrap().clone()).unwrap();
        assert!(cmap.contains(&format!("<{:04X}> <00E9>", face.glyph('é'))));
    }

    #[test]
    fn anchors_and_rotation_place_the_text_matrix() {
        let mut p = Painter::new(100, 100, "t");
        let mut style = TextStyle::new(10.0, Color(0, 0, 0));
        style.anchor = Anchor::End;
        style.rotate = -90.0;
        p.text(50.0, 60.0, "ab", &style);
        let pdf = p.finish().to_pdf(100.0, 100.0);
        let content = String::from_utf8(streams(&pdf)[0].clone()).unwrap();
        let w = text_width("ab", 10.0, false);
        // Turned a quarter counter-clockwise on screen: the baseline runs up, so the end
        // anchor moves the start down by the width.
        let expected = format!("0 -1 -1 0 {} {} Tm", num(50.0), num(60.0 + w));
        assert!(content.contains(&expected), "{content}\n{expected}");
    }
}
