//! Degree glyphs of a surface's control points (the `controls` view of a surface): each point
//! drawn as a small white box of three bars, its truth, indeterminacy and falsity (a full bar
//! is 1); on nets of more than [`MAX_GLYPHS`] points, a regular subset.

use neutrospline::DegreeKind;

use crate::drawing::Painter;
use crate::layout::{median_spacing, Rect};
use crate::point::Pt;
use crate::scene::flat;
use crate::style::{Color, Style};
use crate::theme::{self, Theme};

/// Most control points drawn with their degrees; larger nets show a regular subset.
const MAX_GLYPHS: usize = 64;

/// Indices along one direction of `count` that get a glyph: every `step`-th and the last.
fn every(count: usize, step: usize) -> Vec<usize> {
    let mut v: Vec<usize> = (0..count).step_by(step.max(1)).collect();
    if v.last() != Some(&(count - 1)) {
        v.push(count - 1);
    }
    v
}

/// The control points that get a degree glyph, and the stride between them (1: all).
pub(crate) fn glyph_subset(grid: (usize, usize)) -> (Vec<usize>, usize) {
    let (rows, cols) = grid;
    let mut step = 1;
    loop {
        let (ri, ci) = (every(rows, step), every(cols, step));
        if ri.len() * ci.len() <= MAX_GLYPHS || step >= rows.max(cols) {
            let chosen = ri
                .iter()
                .flat_map(|&i| ci.iter().map(move |&j| i * cols + j))
                .collect();
            return (chosen, step);
        }
        step += 1;
    }
}

/// Size of a degree glyph: (width, height) for the unit `u` (a font size).
fn glyph_size(u: f64) -> (f64, f64) {
    (
        3.0 * 0.42 * u + 2.0 * 0.16 * u + 2.0 * 0.26 * u,
        1.5 * u + 2.0 * 0.26 * u,
    )
}

/// The unit of the glyphs: the note font size, smaller when the points crowd each other (down
/// to 55 %), so that neighbouring glyphs rarely overlap.
fn glyph_unit(th: &Theme, at: &[(f64, f64)]) -> f64 {
    let full = th.note();
    let (w, _) = glyph_size(1.0);
    (0.9 * median_spacing(at) / w).clamp(0.55 * full, full)
}

/// A control point drawn as its degrees: a white box centred on it with three bars.
fn glyph(svg: &mut Painter, th: &Theme, c: (f64, f64), deg: [f64; 3], u: f64) {
    let (w, h) = glyph_size(u);
    let (x, y) = (c.0 - w / 2.0, c.1 - h / 2.0);
    svg.rect(
        x,
        y,
        w,
        h,
        &Style::stroke(theme::CRISP, th.s * 1.6)
            .with_fill(Color::WHITE)
            .square()
            .with_class("degree-glyph"),
    );
    let (bw, gap, pad, bh) = (0.42 * u, 0.16 * u, 0.26 * u, 1.5 * u);
    let mut bx = x + pad;
    for kind in DegreeKind::ALL {
        let v = theme::unit(deg[kind.index()]);
        svg.rect(bx, y + pad, bw, bh, &Style::fill(theme::TRACK).square());
        svg.rect(
            bx,
            y + pad + bh * (1.0 - v),
            bw,
            bh * v,
            &Style::fill(theme::degree_color(kind))
                .square()
                .with_class(&format!("bar {}", kind.name())),
        );
        bx += bw + gap;
    }
}

/// Draws the control points `chosen` (indices into `pts`, their pixels and depths, and
/// `controls`, their degrees) as degree glyphs, far to near so that nearer ones overlap
/// farther ones, shrunk where they crowd. Returns the rectangles they cover.
pub(crate) fn draw_glyphs(
    svg: &mut Painter,
    th: &Theme,
    pts: &[(f64, f64, f64)],
    controls: &[Pt],
    chosen: &[usize],
) -> Vec<Rect> {
    let mut order = chosen.to_vec();
    order.sort_by(|&a, &b| pts[a].2.total_cmp(&pts[b].2).then(a.cmp(&b)));
    let flat_pts = flat(pts);
    let u = glyph_unit(th, &chosen.iter().map(|&k| flat_pts[k]).collect::<Vec<_>>());
    let (gw, gh) = glyph_size(u);
    svg.begin_group("degree-glyphs");
    for &k in &order {
        glyph(svg, th, flat_pts[k], controls[k].deg, u);
    }
    svg.end_group();
    chosen
        .iter()
        .map(|&k| Rect::new(flat_pts[k].0 - gw / 2.0, flat_pts[k].1 - gh / 2.0, gw, gh))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn surface_glyph_subset() {
        let (all, step) = glyph_subset((4, 4));
        assert_eq!((all.len(), step), (16, 1));
        let (some, step) = glyph_subset((12, 12));
        assert!(some.len() <= MAX_GLYPHS && step > 1);
        assert!(some.contains(&0) && some.contains(&143) && some.contains(&11));
        assert_eq!(glyph_subset((1, 1)).0, vec![0]);
    }
}
