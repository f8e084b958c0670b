//! Writing a [`Drawing`] out: the one walk over its primitives, in drawing order, that every
//! encoding shares.
//!
//! An encoding (the SVG figure file in `svg`, the canvas display list in `display_list`)
//! implements [`Encoder`], one method per kind of primitive, and [`Drawing::encode`] calls
//! them in the order the primitives were drawn. Widths, heights and radii reach the encoder
//! clamped to at least 0 (a negative size draws nothing in either encoding), so both
//! encodings write the same numbers.

use crate::drawing::{Drawing, Element};
use crate::style::{Color, Style, TextStyle};

/// One encoding of a drawing's primitives. `'a` is the drawing's lifetime: an encoder may keep
/// references to the styles it is given (the display list's style tables do).
///
/// Rectangles are `[x, y, width, height]` with the width and height at least 0; points are
/// figure pixels `(x, y)`, y down.
pub(crate) trait Encoder<'a> {
    /// Opens a group of CSS class `class` (structure only).
    fn group(&mut self, class: &'a str);

    /// Opens a group of CSS class `class` whose faces and edges draw with this stroke width,
    /// round joins and no fill.
    fn mesh_group(&mut self, class: &'a str, stroke_width: f64);

    /// Opens a group clipped to `rect` (clip path `id`).
    fn clip(&mut self, id: &'a str, rect: [f64; 4]);

    /// Closes the innermost group.
    fn end(&mut self);

    /// A rectangle.
    fn rect(&mut self, rect: [f64; 4], style: &'a Style);

    /// A line from `a` to `b`.
    fn line(&mut self, a: (f64, f64), b: (f64, f64), style: &'a Style);

    /// An open polyline through `points` (at least two).
    fn polyline(&mut self, points: &'a [(f64, f64)], style: &'a Style);

    /// A closed polygon through `points` (at least three).
    fn polygon(&mut self, points: &'a [(f64, f64)], style: &'a Style);

    /// A circle about `centre` of radius `radius` (at least 0).
    fn circle(&mut self, centre: (f64, f64), radius: f64, style: &'a Style);

    /// `text` with its baseline at `y`, anchored at `x`.
    fn text(&mut self, x: f64, y: f64, text: &'a str, style: &'a TextStyle);

    /// A mesh face through `points`, filled and outlined in `color`.
    fn face(&mut self, points: &'a [(f64, f64)], color: Color);

    /// A mesh edge from `a` to `b` in `color`.
    fn edge(&mut self, a: (f64, f64), b: (f64, f64), color: Color);

    /// A vertical gradient `id` from the bottom to the top through evenly spaced `stops`.
    fn gradient(&mut self, id: &'a str, stops: &'a [Color]);

    /// A rectangle filled with gradient `id`.
    fn gradient_rect(&mut self, id: &'a str, rect: [f64; 4]);
}

/// `[x, y, w, h]` with the width and height clamped to at least 0.
fn clamped([x, y, w, h]: [f64; 4]) -> [f64; 4] {
    [x, y, w.max(0.0), h.max(0.0)]
}

impl Drawing {
    /// Hands every primitive, in drawing order, to `encoder`: the one `match` over
    /// [`Element`].
    pub(crate) fn encode<'a>(&'a self, encoder: &mut impl Encoder<'a>) {
        for element in &self.elements {
            match element {
                Element::Group(class) => encoder.group(class),
                Element::MeshGroup(class, width) => encoder.mesh_group(class, *width),
                Element::Clip(id, rect) => encoder.clip(id, clamped(*rect)),
                Element::End => encoder.end(),
                Element::Rect(rect, style) => encoder.rect(clamped(*rect), style),
                Element::Line(a, b, style) => encoder.line(*a, *b, style),
                Element::Polyline(points, style) => encoder.polyline(points, style),
                Element::Polygon(points, style) => encoder.polygon(points, style),
                Element::Circle(c, r, style) => encoder.circle(*c, r.max(0.0), style),
                Element::Text(x, y, text, style) => encoder.text(*x, *y, text, style),
                Element::Face(points, color) => encoder.face(points, *color),
                Element::Edge(a, b, color) => encoder.edge(*a, *b, *color),
                Element::Gradient(id, stops) => encoder.gradient(id, stops),
                Element::GradientRect(id, rect) => encoder.gradient_rect(id, clamped(*rect)),
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::drawing::Painter;

    /// Writes each call as one line: the method and its numbers.
    #[derive(Default)]
    struct Calls(Vec<String>);

    impl<'a> Encoder<'a> for Calls {
        fn group(&mut self, class: &'a str) {
            self.0.push(format!("group {class}"));
        }
        fn mesh_group(&mut self, class: &'a str, stroke_width: f64) {
            self.0.push(format!("mesh_group {class} {stroke_width}"));
        }
        fn clip(&mut self, id: &'a str, rect: [f64; 4]) {
            self.0.push(format!("clip {id} {rect:?}"));
        }
        fn end(&mut self) {
            self.0.push("end".into());
        }
        fn rect(&mut self, rect: [f64; 4], _: &'a Style) {
            self.0.push(format!("rect {rect:?}"));
        }
        fn line(&mut self, a: (f64, f64), b: (f64, f64), _: &'a Style) {
            self.0.push(format!("line {a:?} {b:?}"));
        }
        fn polyline(&mut self, points: &'a [(f64, f64)], _: &'a Style) {
            self.0.push(format!("polyline {points:?}"));
        }
        fn polygon(&mut self, points: &'a [(f64, f64)], _: &'a Style) {
            self.0.push(format!("polygon {points:?}"));
        }
        fn circle(&mut self, centre: (f64, f64), radius: f64, _: &'a Style) {
            self.0.push(format!("circle {centre:?} {radius}"));
        }
        fn text(&mut self, x: f64, y: f64, text: &'a str, _: &'a TextStyle) {
            self.0.push(format!("text {x} {y} {text}"));
        }
        fn face(&mut self, points: &'a [(f64, f64)], color: Color) {
            self.0.push(format!("face {points:?} {}", color.hex()));
        }
        fn edge(&mut self, a: (f64, f64), b: (f64, f64), color: Color) {
            self.0.push(format!("edge {a:?} {b:?} {}", color.hex()));
        }
        fn gradient(&mut self, id: &'a str, stops: &'a [Color]) {
            self.0.push(format!("gradient {id} {}", stops.len()));
        }
        fn gradient_rect(&mut self, id: &'a str, rect: [f64; 4]) {
            self.0.push(format!("gradient_rect {id} {rect:?}"));
        }
    }

    /// Every primitive reaches its own method, in drawing order, with negative sizes as 0.
    #[test]
    fn each_primitive_reaches_its_method_in_order() {
        let black = Color(0, 0, 0);
        let style = Style::stroke(black, 1.0);
        let mut p = Painter::new(10, 10, "t");
        p.begin_group("g");
        p.begin_mesh_group("m", 0.5);
        p.begin_clip("c", 1.0, 2.0, -3.0, 4.0);
        p.rect(1.0, 2.0, 3.0, -4.0, &style);
        p.line((0.0, 1.0), (2.0, 3.0), &style);
        p.polyline(&[(0.0, 0.0), (1.0, 1.0)], &style);
        p.polygon(&[(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)], &style);
        p.circle((5.0, 6.0), -2.0, &style);
        p.text(7.0, 8.0, "hi", &TextStyle::new(12.0, black));
        p.face(&[(0.0, 0.0), (2.0, 0.0), (0.0, 2.0)], Color(255, 0, 0));
        p.edge((1.0, 1.0), (2.0, 2.0), Color(0, 255, 0));
        p.vertical_gradient("v", &[black, Color::WHITE]);
        p.gradient_rect("v", 0.0, 0.0, -1.0, 5.0);
        let drawing = p.finish();
        let mut calls = Calls::default();
        drawing.encode(&mut calls);
        assert_eq!(
            calls.0,
            [
                "group g",
                "mesh_group m 0.5",
                "clip c [1.0, 2.0, 0.0, 4.0]",
                "rect [1.0, 2.0, 3.0, 0.0]",
                "line (0.0, 1.0) (2.0, 3.0)",
                "polyline [(0.0, 0.0), (1.0, 1.0)]",
                "polygon [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)]",
                "circle (5.0, 6.0) 0",
                "text 7 8 hi",
                "face [(0.0, 0.0), (2.0, 0.0), (0.0, 2.0)] #ff0000",
                "edge (1.0, 1.0) (2.0, 2.0) #00ff00",
                "gradient v 2",
                "gradient_rect v [0.0, 0.0, 0.0, 5.0]",
                "end",
                "end",
                "end",
            ]
        );
    }
}
