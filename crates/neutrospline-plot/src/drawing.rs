//! A figure as a list of primitives, before it is written out.
//!
//! Every view draws through a [`Painter`], which records what is drawn, in order, as a
//! [`Drawing`]. A drawing has two encodings of the same primitives:
//! - [`Drawing::to_svg`], the figure file (`neutrospline plot`, exports, PNG through resvg);
//! - [`Drawing::to_display_list`], a compact JSON list that a page paints on an HTML canvas
//!   (the studio's frames while a point is dragged), documented in `docs/architecture.md`.
//!
//! Both walk the primitives through `encode::Encoder` and write numbers with at most two
//! decimals ([`num`](crate::style::num)), so they place every primitive on the same pixel.

use crate::page::Length;
use crate::style::{Color, Style, TextStyle};

/// One recorded drawing call.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Element {
    /// `<g class>`: structure only.
    Group(String),
    /// A group whose faces and edges draw with this stroke width, round joins and no fill.
    MeshGroup(String, f64),
    /// A group clipped to the rectangle `x, y, w, h` (clip path `id` in SVG).
    Clip(String, [f64; 4]),
    /// Closes the innermost group.
    End,
    Rect([f64; 4], Style),
    Line((f64, f64), (f64, f64), Style),
    Polyline(Vec<(f64, f64)>, Style),
    Polygon(Vec<(f64, f64)>, Style),
    Circle((f64, f64), f64, Style),
    /// Text with its baseline at `y`, anchored at `x`.
    Text(f64, f64, String, TextStyle),
    /// A mesh face, filled and outlined in one colour.
    Face(Vec<(f64, f64)>, Color),
    /// A mesh edge.
    Edge((f64, f64), (f64, f64), Color),
    /// A vertical gradient `id` from the bottom to the top through evenly spaced stops.
    Gradient(String, Vec<Color>),
    /// A rectangle filled with gradient `id`.
    GradientRect(String, [f64; 4]),
}

/// A figure: its size, title and primitives in drawing order.
///
/// Made by [`render_drawing`](crate::render_drawing); written out by [`Drawing::to_svg`] or
/// [`Drawing::to_display_list`].
#[derive(Debug, Clone, PartialEq)]
pub struct Drawing {
    pub(crate) width: u32,
    pub(crate) height: u32,
    /// The print size, when the canvas is one in points (the SVG states it).
    pub(crate) print: Option<(Length, Length)>,
    pub(crate) title: String,
    pub(crate) elements: Vec<Element>,
}

impl Drawing {
    /// The figure's width in pixels.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// The figure's height in pixels.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// The centres of the circles of CSS class `class` (the control points are
    /// `control-point`), in drawing order, in figure pixels.
    ///
    /// ```
    /// use neutrospline_plot::{render_drawing, PlotModel, PlotOptions, View};
    /// let model = PlotModel::from(&neutrospline::example1());
    /// let drawing = render_drawing(&model, View::Plane, &PlotOptions::default())?;
    /// assert_eq!(drawing.circle_centres("control-point").len(), 4);
    /// # Ok::<(), neutrospline_plot::PlotError>(())
    /// ```
    pub fn circle_centres(&self, class: &str) -> Vec<[f64; 2]> {
        self.elements
            .iter()
            .filter_map(|e| match e {
                Element::Circle(c, _, style) if style.class.as_deref() == Some(class) => {
                    Some([c.0, c.1])
                }
                _ => None,
            })
            .collect()
    }
}

/// Records drawing calls into a [`Drawing`].
///
/// Groups nest: every `begin_*` is closed by [`Painter::end_group`], and
/// [`Painter::finish`] closes the groups left open.
pub(crate) struct Painter {
    drawing: Drawing,
    depth: usize,
}

impl Painter {
    /// Starts a figure of `width` x `height` pixels (on white) with `title`.
    pub(crate) fn new(width: u32, height: u32, title: &str) -> Painter {
        Painter {
            drawing: Drawing {
                width,
                height,
                print: None,
                title: title.to_string(),
                elements: Vec::with_capacity(512),
            },
            depth: 1,
        }
    }

    fn push(&mut self, element: Element) {
        self.drawing.elements.push(element);
    }

    /// Opens a group with the given class (for structure and for tests).
    pub(crate) fn begin_group(&mut self, class: &str) {
        self.push(Element::Group(class.to_string()));
        self.depth += 1;
    }

    /// Opens a group whose children inherit the given stroke width, round joins and no fill
    /// unless they set their own: the many faces and edges of a mesh ([`Painter::face`],
    /// [`Painter::edge`]).
    pub(crate) fn begin_mesh_group(&mut self, class: &str, stroke_width: f64) {
        self.push(Element::MeshGroup(class.to_string(), stroke_width));
        self.depth += 1;
    }

    /// A polygon filled and outlined in `color` (the outline, of the inherited width, closes
    /// the hairline seams between neighbouring faces). Fewer than three points draw nothing.
    pub(crate) fn face(&mut self, points: &[(f64, f64)], color: Color) {
        if points.len() >= 3 {
            self.push(Element::Face(points.to_vec(), color));
        }
    }

    /// A line in `color` of the inherited width.
    pub(crate) fn edge(&mut self, a: (f64, f64), b: (f64, f64), color: Color) {
        self.push(Element::Edge(a, b, color));
    }

    /// Closes the innermost group.
    pub(crate) fn end_group(&mut self) {
        self.depth = self.depth.saturating_sub(1);
        self.push(Element::End);
    }

    /// Opens a group clipped to the rectangle; closed by `end_group`.
    pub(crate) fn begin_clip(&mut self, id: &str, x: f64, y: f64, w: f64, h: f64) {
        self.push(Element::Clip(id.to_string(), [x, y, w, h]));
        self.depth += 1;
    }

    pub(crate) fn rect(&mut self, x: f64, y: f64, w: f64, h: f64, style: &Style) {
        self.push(Element::Rect([x, y, w, h], style.clone()));
    }

    pub(crate) fn line(&mut self, a: (f64, f64), b: (f64, f64), style: &Style) {
        self.push(Element::Line(a, b, style.clone()));
    }

    /// A polyline; a single point is a zero-length line (its round cap shows as a dot).
    pub(crate) fn polyline(&mut self, points: &[(f64, f64)], style: &Style) {
        match points {
            [] => {}
            [p] => self.line(*p, *p, style),
            _ => self.push(Element::Polyline(points.to_vec(), style.clone())),
        }
    }

    /// A closed polygon; fewer than three points draw nothing.
    pub(crate) fn polygon(&mut self, points: &[(f64, f64)], style: &Style) {
        if points.len() >= 3 {
            self.push(Element::Polygon(points.to_vec(), style.clone()));
        }
    }

    pub(crate) fn circle(&mut self, c: (f64, f64), r: f64, style: &Style) {
        self.push(Element::Circle(c, r, style.clone()));
    }

    /// Writes `text` with its baseline at `y`; `x` is the anchor (start, middle or end).
    pub(crate) fn text(&mut self, x: f64, y: f64, text: &str, style: &TextStyle) {
        self.push(Element::Text(x, y, text.to_string(), style.clone()));
    }

    /// A vertical linear gradient (bottom to top) from evenly spaced colour stops.
    pub(crate) fn vertical_gradient(&mut self, id: &str, stops: &[Color]) {
        self.push(Element::Gradient(id.to_string(), stops.to_vec()));
    }

    /// A rectangle filled with the gradient `id`.
    pub(crate) fn gradient_rect(&mut self, id: &str, x: f64, y: f64, w: f64, h: f64) {
        self.push(Element::GradientRect(id.to_string(), [x, y, w, h]));
    }

    /// Closes the open groups and returns the drawing.
    pub(crate) fn finish(mut self) -> Drawing {
        while self.depth > 1 {
            self.end_group();
        }
        self.drawing
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finish_closes_open_groups() {
        let mut p = Painter::new(10, 20, "t");
        p.begin_group("a");
        p.begin_clip("c", 0.0, 0.0, 1.0, 1.0);
        p.polyline(&[(0.0, 0.0)], &Style::stroke(Color(0, 0, 0), 1.0));
        p.polygon(&[(0.0, 0.0), (1.0, 1.0)], &Style::fill(Color(0, 0, 0)));
        let d = p.finish();
        assert_eq!(d.elements.len(), 5);
        assert!(matches!(d.elements[2], Element::Line(a, b, _) if a == b));
        assert_eq!(d.elements[3..], [Element::End, Element::End]);
    }

    #[test]
    fn circle_centres_by_class() {
        let mut p = Painter::new(10, 20, "t");
        let s = Style::fill(Color(0, 0, 0));
        p.circle((1.0, 2.0), 3.0, &s.clone().with_class("control-point"));
        p.circle((4.0, 5.0), 3.0, &s);
        assert_eq!(p.finish().circle_centres("control-point"), vec![[1.0, 2.0]]);
    }
}
