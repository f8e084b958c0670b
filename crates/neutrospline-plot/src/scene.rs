//! Depth-sorted drawing of 3-D primitives (painter's algorithm).

use crate::drawing::Painter;
use crate::layout::marker;
use crate::style::{Color, Style};
use crate::theme::Marker;

/// Segments per depth-sorted chunk of a curve.
pub(crate) const CHUNK: usize = 6;

/// Something to draw, already projected to pixels.
pub(crate) enum Shape {
    Polyline(Vec<(f64, f64)>, Style),
    Polygon(Vec<(f64, f64)>, Style),
    Marker(Marker, (f64, f64), f64, Style),
    /// A mesh face: filled and outlined in one colour, outline width inherited.
    Face(Vec<(f64, f64)>, Color),
    /// A mesh edge of the inherited width.
    Edge((f64, f64), (f64, f64), Color),
}

struct Prim {
    layer: u8,
    depth: f64,
    seq: usize,
    shape: Shape,
}

/// Primitives drawn by layer, then far to near within a layer, then in insertion order.
#[derive(Default)]
pub(crate) struct Scene {
    prims: Vec<Prim>,
}

/// Layer of things lying on the floor or behind everything.
pub(crate) const FLOOR: u8 = 0;
/// Layer of the data.
pub(crate) const DATA: u8 = 1;
/// Layer drawn over the data (marker outlines, coloured curve over its casing).
pub(crate) const OVER: u8 = 2;

impl Scene {
    pub(crate) fn push(&mut self, layer: u8, depth: f64, shape: Shape) {
        let seq = self.prims.len();
        self.prims.push(Prim {
            layer,
            depth: if depth.is_finite() { depth } else { 0.0 },
            seq,
            shape,
        });
    }

    /// Adds a polyline given as pixel points with depths, cut into chunks of `chunk` segments
    /// that are sorted separately.
    pub(crate) fn polyline(
        &mut self,
        layer: u8,
        pts: &[(f64, f64, f64)],
        chunk: usize,
        style: &Style,
    ) {
        if pts.len() == 1 {
            let p = pts[0];
            self.push(layer, p.2, Shape::Polyline(vec![(p.0, p.1)], style.clone()));
            return;
        }
        let chunk = chunk.max(1);
        let mut i = 0;
        while i + 1 < pts.len() {
            let j = (i + chunk).min(pts.len() - 1);
            let part = &pts[i..=j];
            let depth = part.iter().map(|p| p.2).sum::<f64>() / part.len() as f64;
            self.push(
                layer,
                depth,
                Shape::Polyline(part.iter().map(|p| (p.0, p.1)).collect(), style.clone()),
            );
            i = j;
        }
    }

    pub(crate) fn draw(mut self, svg: &mut Painter) {
        self.prims.sort_by(|a, b| {
            a.layer
                .cmp(&b.layer)
                .then(a.depth.total_cmp(&b.depth))
                .then(a.seq.cmp(&b.seq))
        });
        for p in self.prims {
            draw_shape(svg, p.shape);
        }
    }
}

/// Projected points (pixels and depth) as pixels.
pub(crate) fn flat(pts: &[(f64, f64, f64)]) -> Vec<(f64, f64)> {
    pts.iter().map(|p| (p.0, p.1)).collect()
}

fn draw_shape(svg: &mut Painter, shape: Shape) {
    match shape {
        Shape::Polyline(pts, style) => svg.polyline(&pts, &style),
        Shape::Polygon(pts, style) => svg.polygon(&pts, &style),
        Shape::Marker(shape, c, r, style) => marker(svg, shape, c, r, &style),
        Shape::Face(pts, color) => svg.face(&pts, color),
        Shape::Edge(a, b, color) => svg.edge(a, b, color),
    }
}
