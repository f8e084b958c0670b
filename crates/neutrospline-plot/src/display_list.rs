//! The display list: a [`Drawing`] encoded as compact JSON for painting on an HTML canvas.
//!
//! The studio paints its frames with it while a point is dragged or a view is turned: six
//! canvases take a few milliseconds where six SVG documents take tens to parse and lay out.
//! The list holds the drawing's primitives in order, with the numbers the SVG encoding writes,
//! so the canvas shows what the SVG file shows. The format, one JSON object:
//!
//! ```text
//! {"width": W, "height": H, "font": CSS font family,
//!  "styles": [{"fill": "#rrggbb" | null, "fillOpacity": a, "stroke": "#rrggbb" | null,
//!              "width": w, "strokeOpacity": a, "round": bool, "dash": [on, off] | null}, ...],
//!  "texts":  [{"size": s, "bold": bool, "color": "#rrggbb", "anchor": "start|middle|end",
//!              "rotate": degrees, "halo": w}, ...],
//!  "ops": [op, ...]}
//! ```
//!
//! where each op is an array whose first item names it; `s` and `t` index `styles` and
//! `texts`, and `[x0, y0, x1, y1, ...]` is a flat list of points:
//! - `["g"]` a group, `["m", w]` a mesh group (faces and edges stroke `w` wide, round joins),
//!   `["c", x, y, w, h]` a group clipped to a rectangle, `["e"]` the end of the innermost group;
//! - `["r", x, y, w, h, s]`, `["l", x0, y0, x1, y1, s]`, `["p", [...], s]` (polyline),
//!   `["P", [...], s]` (closed polygon), `["o", cx, cy, r, s]` (circle): filled, then stroked;
//! - `["t", x, y, text, t]`: text with its baseline at `y`, anchored at `x`, rotated about
//!   `(x, y)`, its white halo stroked under it;
//! - `["f", [...], "#rrggbb"]` a mesh face (filled and outlined), `["k", x0, y0, x1, y1,
//!   "#rrggbb"]` a mesh edge;
//! - `["G", id, ["#rrggbb", ...]]` a vertical gradient from bottom to top through evenly
//!   spaced stops, `["R", id, x, y, w, h]` a rectangle filled with it.

use std::fmt::Write as _;

use crate::drawing::Drawing;
use crate::encode::Encoder;
use crate::font::FONT_FAMILY_CSS;
use crate::style::{num, write_points, Anchor, Color, Style, TextStyle};

impl Drawing {
    /// The drawing as a display list for an HTML canvas (the format is in the module
    /// documentation of `display_list.rs` and in `docs/architecture.md`).
    pub fn to_display_list(&self) -> String {
        let mut list = DisplayList {
            ops: String::with_capacity(32 * 1024),
            styles: Vec::new(),
            texts: Vec::new(),
        };
        self.encode(&mut list);
        let DisplayList { ops, styles, texts } = list;
        let mut out = String::with_capacity(ops.len() + 4096);
        let _ = write!(
            out,
            "{{\"width\":{},\"height\":{},\"font\":",
            self.width, self.height
        );
        json_string(&mut out, FONT_FAMILY_CSS);
        out.push_str(",\"styles\":[");
        for (i, s) in styles.iter().enumerate() {
            if i > 0 {
                out.push(',');
            }
            style_json(&mut out, s);
        }
        out.push_str("],\"texts\":[");
        for (i, t) in texts.iter().enumerate() {
            if i > 0 {
                out.push(',');
            }
            text_style_json(&mut out, t);
        }
        out.push_str("],\"ops\":[");
        out.push_str(&ops);
        out.push_str("]}");
        out
    }
}

/// The display list being written: the ops so far, and the tables of the distinct shape and
/// text styles they index, in order of first use.
struct DisplayList<'a> {
    ops: String,
    styles: Vec<&'a Style>,
    texts: Vec<&'a TextStyle>,
}

impl<'a> DisplayList<'a> {
    /// Starts an op: a comma after the previous one, `[` and the quoted `code`; returns the
    /// text to write its arguments to (each after a comma) and its closing `]`.
    fn op(&mut self, code: &str) -> &mut String {
        if !self.ops.is_empty() {
            self.ops.push(',');
        }
        let _ = write!(self.ops, "[\"{code}\"");
        &mut self.ops
    }

    /// The index of `style` in the shape styles, added when new.
    fn style(&mut self, style: &'a Style) -> usize {
        index_of(&mut self.styles, style)
    }
}

/// The index of `item` in `table`, added when new.
fn index_of<'a, T: PartialEq>(table: &mut Vec<&'a T>, item: &'a T) -> usize {
    match table.iter().position(|t| *t == item) {
        Some(i) => i,
        None => {
            table.push(item);
            table.len() - 1
        }
    }
}

impl<'a> Encoder<'a> for DisplayList<'a> {
    fn group(&mut self, _class: &'a str) {
        self.op("g").push(']');
    }

    fn mesh_group(&mut self, _class: &'a str, stroke_width: f64) {
        let _ = write!(self.op("m"), ",{}]", num(stroke_width));
    }

    fn clip(&mut self, _id: &'a str, rect: [f64; 4]) {
        let out = self.op("c");
        numbers(out, &rect);
        out.push(']');
    }

    fn end(&mut self) {
        self.op("e").push(']');
    }

    fn rect(&mut self, rect: [f64; 4], style: &'a Style) {
        let s = self.style(style);
        let out = self.op("r");
        numbers(out, &rect);
        let _ = write!(out, ",{s}]");
    }

    fn line(&mut self, a: (f64, f64), b: (f64, f64), style: &'a Style) {
        let s = self.style(style);
        let out = self.op("l");
        numbers(out, &[a.0, a.1, b.0, b.1]);
        let _ = write!(out, ",{s}]");
    }

    fn polyline(&mut self, points: &'a [(f64, f64)], style: &'a Style) {
        let s = self.style(style);
        let out = self.op("p");
        flat_points(out, points);
        let _ = write!(out, ",{s}]");
    }

    fn polygon(&mut self, points: &'a [(f64, f64)], style: &'a Style) {
        let s = self.style(style);
        let out = self.op("P");
        flat_points(out, points);
        let _ = write!(out, ",{s}]");
    }

    fn circle(&mut self, centre: (f64, f64), radius: f64, style: &'a Style) {
        let s = self.style(style);
        let out = self.op("o");
        numbers(out, &[centre.0, centre.1, radius]);
        let _ = write!(out, ",{s}]");
    }

    fn text(&mut self, x: f64, y: f64, text: &'a str, style: &'a TextStyle) {
        let t = index_of(&mut self.texts, style);
        let out = self.op("t");
        numbers(out, &[x, y]);
        out.push(',');
        json_string(out, text);
        let _ = write!(out, ",{t}]");
    }

    fn face(&mut self, points: &'a [(f64, f64)], color: Color) {
        let out = self.op("f");
        flat_points(out, points);
        let _ = write!(out, ",\"{}\"]", color.hex());
    }

    fn edge(&mut self, a: (f64, f64), b: (f64, f64), color: Color) {
        let out = self.op("k");
        numbers(out, &[a.0, a.1, b.0, b.1]);
        let _ = write!(out, ",\"{}\"]", color.hex());
    }

    fn gradient(&mut self, id: &'a str, stops: &'a [Color]) {
        let out = self.op("G");
        out.push(',');
        json_string(out, id);
        out.push_str(",[");
        for (i, c) in stops.iter().enumerate() {
            if i > 0 {
                out.push(',');
            }
            let _ = write!(out, "\"{}\"", c.hex());
        }
        out.push_str("]]");
    }

    fn gradient_rect(&mut self, id: &'a str, rect: [f64; 4]) {
        let out = self.op("R");
        out.push(',');
        json_string(out, id);
        numbers(out, &rect);
        out.push(']');
    }
}

/// Writes each of `values` after a comma.
fn numbers(out: &mut String, values: &[f64]) {
    for v in values {
        out.push(',');
        out.push_str(&num(*v));
    }
}

/// Writes `,[x0,y0,x1,y1,...]`: the points as one flat list, after a comma.
fn flat_points(out: &mut String, points: &[(f64, f64)]) {
    out.push_str(",[");
    write_points(out, points, ',');
    out.push(']');
}

fn color_or_null(out: &mut String, color: Option<Color>) {
    match color {
        Some(c) => {
            let _ = write!(out, "\"{}\"", c.hex());
        }
        None => out.push_str("null"),
    }
}

fn style_json(out: &mut String, s: &Style) {
    out.push_str("{\"fill\":");
    color_or_null(out, s.fill);
    let _ = write!(out, ",\"fillOpacity\":{},\"stroke\":", num(s.fill_opacity));
    color_or_null(out, s.stroke);
    let _ = write!(
        out,
        ",\"width\":{},\"strokeOpacity\":{},\"round\":{},\"dash\":",
        num(s.stroke_width),
        num(s.stroke_opacity),
        s.round
    );
    match s.dash {
        Some([on, off]) => {
            let _ = write!(out, "[{},{}]}}", num(on), num(off));
        }
        None => out.push_str("null}"),
    }
}

fn text_style_json(out: &mut String, t: &TextStyle) {
    let anchor = match t.anchor {
        Anchor::Start => "start",
        Anchor::Middle => "middle",
        Anchor::End => "end",
    };
    let _ = write!(
        out,
        "{{\"size\":{},\"bold\":{},\"color\":\"{}\",\"anchor\":\"{anchor}\",\"rotate\":{},\"halo\":{}}}",
        num(t.size),
        t.bold,
        t.color.hex(),
        num(t.rotate),
        num(t.halo)
    );
}

/// Writes `text` as a JSON string.
fn json_string(out: &mut String, text: &str) {
    out.push('"');
    for c in text.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if (c as u32) < 0x20 => {
                let _ = write!(out, "\\u{:04x}", c as u32);
            }
            c => out.push(c),
        }
    }
    out.push('"');
}

#[cfg(test)]
mod tests {
    use crate::drawing::Painter;
    use crate::style::{Color, Style, TextStyle};

    #[test]
    fn ops_styles_and_texts() {
        let mut p = Painter::new(40, 30, "t");
        let red = Style::stroke(Color(255, 0, 0), 1.5).with_dash(2.0, 1.0);
        p.begin_clip("c", 1.0, 2.0, 3.0, 4.0);
        p.polyline(&[(0.0, 0.0), (1.234, -2.0)], &red);
        p.line((0.0, 0.0), (1.0, 1.0), &red);
        p.circle((5.0, 6.0), 2.0, &Style::fill(Color(0, 0, 255)));
        p.text(1.0, 2.0, "a \"b\"\n", &TextStyle::new(12.0, Color(0, 0, 0)));
        let list = p.finish().to_display_list();
        assert!(
            list.starts_with("{\"width\":40,\"height\":30,\"font\":\"'DejaVu Sans', sans-serif\",")
        );
        assert!(list.contains(
            "\"styles\":[{\"fill\":null,\"fillOpacity\":1,\"stroke\":\"#ff0000\",\"width\":1.5,\
             \"strokeOpacity\":1,\"round\":true,\"dash\":[2,1]},{\"fill\":\"#0000ff\""
        ));
        assert!(list.contains(
            "\"texts\":[{\"size\":12,\"bold\":false,\"color\":\"#000000\",\"anchor\":\"start\",\"rotate\":0,\"halo\":0}]"
        ));
        assert!(list.ends_with(
            "\"ops\":[[\"c\",1,2,3,4],[\"p\",[0,0,1.23,-2],0],[\"l\",0,0,1,1,0],[\"o\",5,6,2,1],\
             [\"t\",1,2,\"a \\\"b\\\"\\u000a\",0],[\"e\"]]}"
        ));
    }
}
