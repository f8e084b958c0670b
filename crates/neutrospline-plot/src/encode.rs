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
