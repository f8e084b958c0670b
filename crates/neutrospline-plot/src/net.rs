//! The control net of a surface over its mesh: dashed edges and point markers, cut where the
//! surface hides them (drawn faint there) and shown in full where they lie in front of it.

use neutrospline::uniform_parameter;

use crate::axes3::Axes3;
use crate::ctx::Ctx;
use crate::drawing::Painter;
use crate::layout::median_spacing;
use crate::model::Mesh;
use crate::style::{Color, Style};
use crate::theme::{self, marker_style, Theme};

/// Pieces each control-net edge is cut into to find where the surface hides it.
const NET_PIECES: usize = 16;

/// The control net as screen points, row by row.
fn net_points(ctx: &Ctx, axes: &Axes3) -> Vec<(f64, f64, f64)> {
    ctx.controls.iter().map(|p| axes.screen(p.pos)).collect()
}

/// The net's edges as index pairs, rows first.
pub(crate) fn net_edges(grid: (usize, usize)) -> Vec<(usize, usize)> {
    let (rows, cols) = grid;
    let mut e = Vec::new();
    for i in 0..rows {
        for j in 0..cols {
            let k = i * cols + j;
            if j + 1 < cols {
                e.push((k, k + 1));
            }
            if i + 1 < rows {
                e.push((k, k + cols));
            }
        }
    }
    e
}

/// Which screen points the mesh hides: the faces as triangles in pixels with their depths.
struct Occluder {
    tris: Vec<[(f64, f64, f64); 3]>,
    /// Depth difference below which a point counts as lying on the surface.
    tol: f64,
}

impl Occluder {
    fn new(axes: &Axes3, mesh: &Mesh) -> Occluder {
        let n = mesh.n;
        let px: Vec<(f64, f64, f64)> = mesh.points.iter().map(|p| axes.screen(p.pos)).collect();
        let at = |a: usize, b: usize| px[a * n + b];
        let mut tris = Vec::new();
        for a in 0..n.saturating_sub(1) {
            for b in 0..n.saturating_sub(1) {
                let q = [at(a, b), at(a + 1, b), at(a + 1, b + 1), at(a, b + 1)];
                tris.push([q[0], q[1], q[2]]);
                tris.push([q[0], q[2], q[3]]);
            }
        }
        Occluder { tris, tol: 0.01 }
    }

    /// Whether some face lies in front of the point `p` (pixels and depth).
    fn hides(&self, p: (f64, f64, f64)) -> bool {
        self.tris.iter().any(|t| {
            let (a, b, c) = (t[0], t[1], t[2]);
            if p.0 < a.0.min(b.0).min(c.0)
                || p.0 > a.0.max(b.0).max(c.0)
                || p.1 < a.1.min(b.1).min(c.1)
                || p.1 > a.1.max(b.1).max(c.1)
            {
                return false;
            }
            let det = (b.0 - a.0) * (c.1 - a.1) - (c.0 - a.0) * (b.1 - a.1);
            if det.abs() < 1e-9 {
                return false;
            }
            let l1 = ((p.0 - a.0) * (c.1 - a.1) - (c.0 - a.0) * (p.1 - a.1)) / det;
            let l2 = ((b.0 - a.0) * (p.1 - a.1) - (p.0 - a.0) * (b.1 - a.1)) / det;
            let l0 = 1.0 - l1 - l2;
            let e = -1e-9;
            if l0 < e || l1 < e || l2 < e {
                return false;
            }
            let depth = l0 * a.2 + l1 * b.2 + l2 * c.2;
            depth > p.2 + self.tol
        })
    }
}

/// The control net over the mesh: dashed edges and markers, in full where they are in front
/// of the surface and faint where it hides them. `fill` gives each point's colour.
fn add_net(
    svg: &mut Painter,
    th: &Theme,
    pts: &[(f64, f64, f64)],
    grid: (usize, usize),
    occluder: &Occluder,
    color: Color,
    fill: &dyn Fn(usize) -> Color,
) {
    let (on, off) = th.dash();
    let solid = Style::stroke(color, th.polygon_w())
        .with_dash(on, off)
        .with_class("control-net");
    let mut faint = Style::stroke(color, th.thin_w())
        .with_dash(on, off)
        .with_class("control-net hidden");
    faint.stroke_opacity = 0.45;
    // Smaller markers where the points crowd (a dense net in a small panel).
    let flat_pts: Vec<(f64, f64)> = pts.iter().map(|p| (p.0, p.1)).collect();
    let r = th.marker_r() * (median_spacing(&flat_pts) / (3.0 * th.marker_r())).clamp(0.55, 1.0);
    svg.begin_group("control-net");
    let mut hidden_runs = Vec::new();
    let mut shown_runs = Vec::new();
    for (a, b) in net_edges(grid) {
        let (p, q) = (pts[a], pts[b]);
        let lerp = |t: f64| {
            (
                p.0 + (q.0 - p.0) * t,
                p.1 + (q.1 - p.1) * t,
                p.2 + (q.2 - p.2) * t,
            )
        };
        // Cut the edge where it passes behind the surface or comes out again.
        let mut run = vec![(p.0, p.1)];
        let mut run_hidden = None;
        for k in 0..NET_PIECES {
            let t0 = uniform_parameter(k, NET_PIECES + 1, 0.0..1.0);
            let t1 = uniform_parameter(k + 1, NET_PIECES + 1, 0.0..1.0);
            let hidden = occluder.hides(lerp((t0 + t1) / 2.0));
            let end = lerp(t1);
            if run_hidden.is_some_and(|h| h != hidden) {
                let last = *run.last().unwrap_or(&(p.0, p.1));
                let done = std::mem::replace(&mut run, vec![last]);
                if run_hidden == Some(true) {
                    hidden_runs.push(done);
                } else {
                    shown_runs.push(done);
                }
            }
            run_hidden = Some(hidden);
            run.push((end.0, end.1));
        }
        if run_hidden == Some(true) {
            hidden_runs.push(run);
        } else {
            shown_runs.push(run);
        }
    }
    for run in &hidden_runs {
        svg.polyline(run, &faint);
    }
    for run in &shown_runs {
        svg.polyline(run, &solid);
    }
    let mut ring = Style::stroke(theme::CRISP, th.s * 1.5).with_class("control-point hidden");
    ring.stroke_opacity = 0.45;
    for (k, p) in pts.iter().enumerate() {
        let style = if occluder.hides(*p) {
            ring.clone()
        } else {
            marker_style(th, fill(k)).with_class("control-point")
        };
        svg.circle((p.0, p.1), r, &style);
    }
    svg.end_group();
}

/// Draws the control net of `ctx` (a `rows x cols` grid) seen in `axes` over `mesh`: dashed
/// edges in `color` and markers filled by `fill` (a colour per point), faint where the
/// surface hides them. Returns the points on screen (pixels and depth), row by row.
pub(crate) fn draw_net(
    svg: &mut Painter,
    ctx: &Ctx,
    axes: &Axes3,
    mesh: &Mesh,
    grid: (usize, usize),
    color: Color,
    fill: &dyn Fn(usize) -> Color,
) -> Vec<(f64, f64, f64)> {
    let pts = net_points(ctx, axes);
    let occluder = Occluder::new(axes, mesh);
    add_net(svg, &ctx.theme, &pts, grid, &occluder, color, fill);
    pts
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn surface_net_edges_of_grid() {
        assert_eq!(net_edges((2, 2)), vec![(0, 1), (0, 2), (1, 3), (2, 3)]);
        assert!(net_edges((1, 1)).is_empty());
        assert_eq!(net_edges((1, 3)), vec![(0, 1), (1, 2)]);
    }
}
