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

use crate::drawing::{Drawing, Element};
use crate::font::FONT_FAMILY_CSS;
use crate::svg::{num, Anchor, Style, TextStyle};

impl Drawing {
    /// The drawing as a display list for an HTML canvas (the format is in the module
    /// documentation of `display_list.rs` and in `docs/architecture.md`).
    pub fn to_display_list(&self) -> String {
        let mut styles: Vec<&Style> = Vec::new();
        let mut texts: Vec<&TextStyle> = Vec::new();
        let mut ops = String::with_capacity(32 * 1024);
        for (i, element) in self.elements.iter().enumerate() {
            if i > 0 {
                ops.push(',');
            }
            op(&mut ops, element, &mut styles, &mut texts);
        }
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

fn op<'a>(
    out: &mut String,
    element: &'a Element,
    styles: &mut Vec<&'a Style>,
    texts: &mut Vec<&'a TextStyle>,
) {
    match element {
        Element::Group(_) => out.push_str("[\"g\"]"),
        Element::MeshGroup(_, width) => {
            let _ = write!(out, "[\"m\",{}]", num(*width));
        }
        Element::Clip(_, [x, y, w, h]) => {
            let _ = write!(
                out,
                "[\"c\",{},{},{},{}]",
                num(*x),
                num(*y),
                num(w.max(0.0)),
                num(h.max(0.0))
            );
        }
        Element::End => out.push_str("[\"e\"]"),
        Element::Rect([x, y, w, h], style) => {
            let _ = write!(
                out,
                "[\"r\",{},{},{},{},{}]",
                num(*x),
                num(*y),
                num(w.max(0.0)),
                num(h.max(0.0)),
                index_of(styles, style)
            );
        }
        Element::Line(a, b, style) => {
            let _ = write!(
                out,
                "[\"l\",{},{},{},{},{}]",
                num(a.0),
                num(a.1),
                num(b.0),
                num(b.1),
                index_of(styles, style)
            );
        }
        Element::Polyline(points, style) | Element::Polygon(points, style) => {
            let code = if matches!(element, Element::Polygon(..)) {
                "P"
            } else {
                "p"
            };
            let _ = write!(out, "[\"{code}\",");
            flat_points(out, points);
            let _ = write!(out, ",{}]", index_of(styles, style));
        }
        Element::Circle(c, r, style) => {
            let _ = write!(
                out,
                "[\"o\",{},{},{},{}]",
                num(c.0),
                num(c.1),
                num(r.max(0.0)),
                index_of(styles, style)
            );
        }
        Element::Text(x, y, text, style) => {
            let _ = write!(out, "[\"t\",{},{},", num(*x), num(*y));
            json_string(out, text);
            let _ = write!(out, ",{}]", index_of(texts, style));
        }
        Element::Face(points, color) => {
            out.push_str("[\"f\",");
            flat_points(out, points);
            let _ = write!(out, ",\"{}\"]", color.hex());
        }
        Element::Edge(a, b, color) => {
            let _ = write!(
                out,
                "[\"k\",{},{},{},{},\"{}\"]",
                num(a.0),
                num(a.1),
                num(b.0),
                num(b.1),
                color.hex()
            );
        }
        Element::Gradient(id, stops) => {
            out.push_str("[\"G\",");
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
        Element::GradientRect(id, [x, y, w, h]) => {
            out.push_str("[\"R\",");
            json_string(out, id);
            let _ = write!(
                out,
                ",{},{},{},{}]",
                num(*x),
                num(*y),
                num(w.max(0.0)),
                num(h.max(0.0))
            );
        }
    }
}

fn flat_points(out: &mut String, points: &[(f64, f64)]) {
    out.push('[');
    for (i, p) in points.iter().enumerate() {
        if i > 0 {
            out.push(',');
        }
        let _ = write!(out, "{},{}", num(p.0), num(p.1));
    }
    out.push(']');
}

fn color_or_null(out: &mut String, color: Option<crate::svg::Color>) {
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
    use crate::svg::{Color, Style, TextStyle};

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
