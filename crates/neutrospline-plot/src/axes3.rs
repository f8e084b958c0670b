//! The 3-D axis box: back panes with grids, ticked edges and labels, fitted with its labels
//! into an area (away from a legend), and the projection of data points to pixels.

use crate::camera::{Camera, Projected};
use crate::drawing::Painter;
use crate::font::text_width;
use crate::layout::{support, text_centred, Rect, TEXT_BOX};
use crate::style::{Style, TextStyle};
use crate::theme::{self, Theme};
use crate::ticks::{ticks_inside, Ticks};

/// A label box to fit: anchored at a unit-scale screen point (y up), offset in pixels.
struct Item {
    p: (f64, f64),
    /// Box relative to the anchor after scaling, pixels, y down: (x0, y0, x1, y1).
    b: (f64, f64, f64, f64),
}

/// A tick or axis label of the 3-D box, placed in pixels relative to a scene point.
#[derive(Debug, Clone)]
struct Label3 {
    at: [f64; 3],
    /// Centre offset in pixels (y down).
    off: (f64, f64),
    text: String,
    size: f64,
    vertical: bool,
    class: &'static str,
    /// Order in which labels keep their place when they collide (lower wins).
    priority: u8,
    hidden: bool,
}

/// A box edge that carries an axis: from `a` to `b` (data coordinates), ticks pointing along
/// the unit screen direction `dir` (y down).
#[derive(Debug, Clone, Copy)]
struct AxisEdge {
    a: [f64; 3],
    b: [f64; 3],
    dir: (f64, f64),
}

/// Where an axis goes: edge from `a` to `b`, outward direction `out` in box units.
#[derive(Debug, Clone, Copy)]
struct EdgeSpec {
    a: [f64; 3],
    b: [f64; 3],
    out: [f64; 3],
    axis: usize,
}

/// The 3-D axis box: data ranges, box proportions and the camera.
pub(crate) struct Axes3 {
    pub ticks: [Ticks; 3],
    len: [f64; 3],
    cam: Camera,
    scale: f64,
    origin: (f64, f64),
    back: [usize; 3],
    labels: Vec<Label3>,
    axis_edges: Vec<AxisEdge>,
    /// Pixel bounds of the box and its labels, as fitted.
    bounds: Rect,
}

fn lerp_axis(t: &Ticks, side: usize) -> f64 {
    if side == 0 {
        t.lo
    } else {
        t.hi
    }
}

impl Axes3 {
    /// A box for the given axis ticks (their ranges become the box), with relative edge
    /// lengths `len`, axis names, seen by `cam`, fitted with its labels into `area`.
    pub(crate) fn new(
        area: Rect,
        ticks: [Ticks; 3],
        len: [f64; 3],
        names: [&str; 3],
        cam: Camera,
        theme: &Theme,
        avoid: Option<Rect>,
    ) -> Axes3 {
        let toward = cam.toward();
        // Back side of each axis: the one away from the viewer (0 = low end, 1 = high end).
        let back: [usize; 3] = [0, 1, 2].map(|a| if toward[a] > 0.0 { 0 } else { 1 });
        let front = back.map(|b| 1 - b);
        let mut axes = Axes3 {
            ticks,
            len,
            cam,
            scale: 1.0,
            origin: (0.0, 0.0),
            back,
            labels: Vec::new(),
            axis_edges: Vec::new(),
            bounds: area,
        };
        // Edges that carry ticks: x along (y front, z back), y along (x front, z back),
        // z at whichever side corner is leftmost on screen.
        let t = &axes.ticks;
        let zb = lerp_axis(&t[2], back[2]);
        let x_edge_y = lerp_axis(&t[1], front[1]);
        let y_edge_x = lerp_axis(&t[0], front[0]);
        let corners = [
            (lerp_axis(&t[0], back[0]), lerp_axis(&t[1], front[1])),
            (lerp_axis(&t[0], front[0]), lerp_axis(&t[1], back[1])),
        ];
        let zc = if axes.project([corners[0].0, corners[0].1, zb]).x
            <= axes.project([corners[1].0, corners[1].1, zb]).x
        {
            corners[0]
        } else {
            corners[1]
        };
        let centre = [0, 1, 2].map(|a| t[a].lo / 2.0 + t[a].hi / 2.0);
        // Outward directions in box units.
        let sgn = |v: f64, c: f64| if v >= c { 1.0 } else { -1.0 };
        let out_x = [0.0, sgn(x_edge_y, centre[1]), 0.0];
        let out_y = [sgn(y_edge_x, centre[0]), 0.0, 0.0];
        let out_z = [sgn(zc.0, centre[0]), sgn(zc.1, centre[1]), 0.0];
        let edges = [
            EdgeSpec {
                a: [t[0].lo, x_edge_y, zb],
                b: [t[0].hi, x_edge_y, zb],
                out: out_x,
                axis: 0,
            },
            EdgeSpec {
                a: [y_edge_x, t[1].lo, zb],
                b: [y_edge_x, t[1].hi, zb],
                out: out_y,
                axis: 1,
            },
            EdgeSpec {
                a: [zc.0, zc.1, t[2].lo],
                b: [zc.0, zc.1, t[2].hi],
                out: out_z,
                axis: 2,
            },
        ];
        // Fit, then thin the ticks of any axis whose labels run into each other, and refit.
        for _ in 0..4 {
            axes.build_labels(&edges, names, theme);
            axes.fit(area, theme, avoid);
            let mut changed = false;
            for axis in 0..3 {
                if axes.crowded(axis) {
                    let t = &axes.ticks[axis];
                    let intervals = ((t.hi - t.lo) / t.step).round().max(1.0) as usize;
                    if intervals > 1 {
                        let thinner = ticks_inside(t.lo, t.hi, (intervals / 2).max(1));
                        if thinner.step > t.step {
                            axes.ticks[axis] = thinner;
                            changed = true;
                        }
                    }
                }
            }
            if !changed {
                break;
            }
        }
        axes.hide_colliding_labels();
        axes
    }

    /// Tick and axis labels for the three labelled edges.
    fn build_labels(&mut self, edges: &[EdgeSpec; 3], names: [&str; 3], theme: &Theme) {
        self.labels.clear();
        self.axis_edges.clear();
        let axes = self;
        let tick = theme.tick();
        let h = TEXT_BOX * tick;
        for &EdgeSpec { a, b, out, axis } in edges {
            let dir = axes.screen_dir(out, axis == 2);
            let mut reach: f64 = 0.0;
            let tick_labels = axes.ticks[axis].labels();
            for (v, text) in axes.ticks[axis].values.clone().iter().zip(tick_labels) {
                let mut at = a;
                at[axis] = *v;
                let w = text_width(&text, tick, false);
                let sup = support(dir, w, h);
                reach = reach.max(2.0 * sup);
                let d = theme.tick_len() + theme.gap() + sup;
                axes.labels.push(Label3 {
                    at,
                    off: (dir.0 * d, dir.1 * d),
                    text,
                    size: tick,
                    vertical: false,
                    class: "tick-label",
                    priority: [2, 3, 1][axis],
                    hidden: false,
                });
            }
            let mut mid = a;
            mid[axis] = a[axis] / 2.0 + b[axis] / 2.0;
            let name = names[axis].to_string();
            let lw = text_width(&name, theme.label(), false);
            let lh = TEXT_BOX * theme.label();
            let vertical = axis == 2;
            let (bw, bh) = if vertical { (lh, lw) } else { (lw, lh) };
            let d = theme.tick_len()
                + 2.0 * theme.gap()
                + reach
                + 1.2 * theme.gap()
                + support(dir, bw, bh);
            axes.labels.push(Label3 {
                at: mid,
                off: (dir.0 * d, dir.1 * d),
                text: name,
                size: theme.label(),
                vertical,
                class: "axis-label",
                priority: 0,
                hidden: false,
            });
            axes.axis_edges.push(AxisEdge { a, b, dir });
        }
    }

    /// Whether neighbouring tick labels of `axis` overlap (at the fitted scale).
    fn crowded(&self, axis: usize) -> bool {
        let rects: Vec<Rect> = self
            .labels
            .iter()
            .filter(|l| l.class == "tick-label" && l.priority == [2, 3, 1][axis])
            .map(|l| self.label_rect(l))
            .collect();
        let margin = 0.25 * self.labels.first().map_or(0.0, |l| l.size);
        rects.windows(2).any(|w| {
            let a = Rect::new(
                w[0].x - margin,
                w[0].y - margin,
                w[0].w + 2.0 * margin,
                w[0].h + 2.0 * margin,
            );
            a.overlap(&w[1]) > 0.0
        })
    }

    fn label_rect(&self, l: &Label3) -> Rect {
        let q = self.px(l.at);
        let w = text_width(&l.text, l.size, false);
        let h = TEXT_BOX * l.size;
        let (bw, bh) = if l.vertical { (h, w) } else { (w, h) };
        Rect::new(q.0 + l.off.0 - bw / 2.0, q.1 + l.off.1 - bh / 2.0, bw, bh)
    }

    /// Unit screen direction (y down) of the box-space direction `out`; falls back to straight
    /// down (or left for the vertical axis) when `out` points at the viewer.
    fn screen_dir(&self, out: [f64; 3], vertical_axis: bool) -> (f64, f64) {
        let (x, y) = self.cam.project_dir(out);
        let (x, y) = (x, -y);
        let n = (x * x + y * y).sqrt();
        if n > 0.2 {
            (x / n, y / n)
        } else if vertical_axis {
            (-1.0, 0.0)
        } else {
            (0.0, 1.0)
        }
    }

    /// A data-space normal `n` as a unit vector in camera coordinates (screen right, screen
    /// up, towards the viewer), after the box's per-axis scaling; `None` for a zero vector.
    pub(crate) fn view_normal(&self, n: [f64; 3]) -> Option<[f64; 3]> {
        // Box coordinates scale axis a by len[a] / span[a]; normals scale by the inverse.
        let b = [0, 1, 2].map(|a| n[a] * (self.ticks[a].hi - self.ticks[a].lo) / self.len[a]);
        let q = self.cam.project(b);
        let v = [q.x, q.y, q.depth];
        let len = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        (len > 0.0 && len.is_finite()).then(|| v.map(|x| x / len))
    }

    /// Box coordinates (centred, edge lengths `len`) of a data point.
    fn to_box(&self, p: [f64; 3]) -> [f64; 3] {
        [0, 1, 2].map(|a| (self.ticks[a].unit(p[a]) - 0.5) * self.len[a])
    }

    /// Unit-scale projection (y up).
    fn project(&self, p: [f64; 3]) -> Projected {
        self.cam.project(self.to_box(p))
    }

    /// Pixel position and depth of a data point.
    pub(crate) fn screen(&self, p: [f64; 3]) -> (f64, f64, f64) {
        let q = self.project(p);
        (
            self.origin.0 + self.scale * q.x,
            self.origin.1 - self.scale * q.y,
            q.depth,
        )
    }

    /// Pixel position of a data point.
    pub(crate) fn px(&self, p: [f64; 3]) -> (f64, f64) {
        let (x, y, _) = self.screen(p);
        (x, y)
    }

    /// Pixels per box unit: how large the box is drawn.
    pub(crate) fn scale(&self) -> f64 {
        self.scale
    }

    /// Pixel bounds of the box with its tick and axis labels.
    pub(crate) fn bounds(&self) -> Rect {
        self.bounds
    }

    /// The floor height: the back side of the z axis (the low end when seen from above).
    pub(crate) fn floor(&self) -> f64 {
        lerp_axis(&self.ticks[2], self.back[2])
    }

    /// Chooses scale and origin so that the box and every label fit in `area` and stay clear
    /// of `avoid`.
    fn fit(&mut self, area: Rect, theme: &Theme, avoid: Option<Rect>) {
        let mut corners = Vec::new();
        for i in 0..8 {
            let c = [0, 1, 2].map(|a| lerp_axis(&self.ticks[a], (i >> a) & 1));
            let q = self.project(c);
            corners.push((q.x, q.y));
        }
        let mut items: Vec<Item> = corners
            .iter()
            .map(|&p| Item {
                p,
                b: (0.0, 0.0, 0.0, 0.0),
            })
            .collect();
        for l in &self.labels {
            let q = self.project(l.at);
            let w = text_width(&l.text, l.size, false);
            let h = TEXT_BOX * l.size;
            let (bw, bh) = if l.vertical { (h, w) } else { (w, h) };
            items.push(Item {
                p: (q.x, q.y),
                b: (
                    l.off.0 - bw / 2.0,
                    l.off.1 - bh / 2.0,
                    l.off.0 + bw / 2.0,
                    l.off.1 + bh / 2.0,
                ),
            });
        }
        let hull = convex_hull(&corners);
        let pad = theme.gap();
        let avoid = avoid.map(|r| {
            let g = 2.0 * theme.gap();
            Rect::new(r.x - g, r.y - g, r.w + 2.0 * g, r.h + 2.0 * g)
        });
        let extent = |s: f64| {
            let mut e = (
                f64::INFINITY,
                f64::INFINITY,
                f64::NEG_INFINITY,
                f64::NEG_INFINITY,
            );
            for it in &items {
                let x = s * it.p.0;
                let y = -s * it.p.1;
                e.0 = e.0.min(x + it.b.0);
                e.1 = e.1.min(y + it.b.1);
                e.2 = e.2.max(x + it.b.2);
                e.3 = e.3.max(y + it.b.3);
            }
            e
        };
        // The origin that fits the drawing at scale `s`, if any: centred first, then pushed
        // left and/or down, away from a legend in the top-right corner.
        let place = |s: f64| -> Option<(f64, f64)> {
            let e = extent(s);
            if e.2 - e.0 > area.w - 2.0 * pad || e.3 - e.1 > area.h - 2.0 * pad {
                return None;
            }
            let (cx, cy) = area.centre();
            let xs = [cx - (e.0 + e.2) / 2.0, area.x + pad - e.0];
            let ys = [cy - (e.1 + e.3) / 2.0, area.bottom() - pad - e.3];
            let Some(avoid) = avoid else {
                return Some((xs[0], ys[0]));
            };
            for (ox, oy) in [
                (xs[0], ys[0]),
                (xs[1], ys[0]),
                (xs[0], ys[1]),
                (xs[1], ys[1]),
            ] {
                let poly: Vec<(f64, f64)> =
                    hull.iter().map(|p| (ox + s * p.0, oy - s * p.1)).collect();
                let hits_hull = polygon_meets_rect(&poly, &avoid);
                let hits_label = items.iter().skip(8).any(|it| {
                    let x = ox + s * it.p.0;
                    let y = oy - s * it.p.1;
                    let r = Rect::new(x + it.b.0, y + it.b.1, it.b.2 - it.b.0, it.b.3 - it.b.1);
                    r.overlap(&avoid) > 0.0
                });
                if !hits_hull && !hits_label {
                    return Some((ox, oy));
                }
            }
            None
        };
        let (mut lo, mut hi) = (1e-6, 1e7);
        let mut best = place(lo);
        if best.is_some() {
            for _ in 0..80 {
                let mid = (lo * hi).sqrt();
                match place(mid) {
                    Some(o) => {
                        lo = mid;
                        best = Some(o);
                    }
                    None => hi = mid,
                }
            }
        }
        self.scale = lo;
        let e = extent(lo);
        self.origin = best.unwrap_or_else(|| {
            let (cx, cy) = area.centre();
            (cx - (e.0 + e.2) / 2.0, cy - (e.1 + e.3) / 2.0)
        });
        self.bounds = Rect::new(
            self.origin.0 + e.0,
            self.origin.1 + e.1,
            e.2 - e.0,
            e.3 - e.1,
        );
    }

    /// Hides tick labels that overlap a label of higher priority (for example the lowest
    /// z label and the first x label at the shared corner).
    fn hide_colliding_labels(&mut self) {
        let rects: Vec<Rect> = self.labels.iter().map(|l| self.label_rect(l)).collect();
        let mut order: Vec<usize> = (0..self.labels.len()).collect();
        order.sort_by_key(|&i| self.labels[i].priority);
        let mut kept: Vec<usize> = Vec::new();
        for i in order {
            let clash = kept.iter().any(|&k| rects[k].overlap(&rects[i]) > 0.0);
            if clash && self.labels[i].priority > 0 {
                self.labels[i].hidden = true;
            } else {
                kept.push(i);
            }
        }
    }

    /// Back panes, grid, tick edges, tick labels and axis labels.
    pub(crate) fn draw(&self, svg: &mut Painter, theme: &Theme) {
        svg.begin_group("axes3d");
        let t = &self.ticks;
        let b = self.back.map(|s| s);
        let pane_style = Style::stroke(theme::PANE_EDGE, theme.grid_w())
            .with_fill(theme::PANE)
            .square();
        let grid = Style::stroke(theme::GRID, theme.grid_w()).square();
        // Pane perpendicular to axis `a` at its back side; spanned by the other two axes.
        for a in [2, 0, 1] {
            let (u, v) = match a {
                0 => (1, 2),
                1 => (0, 2),
                _ => (0, 1),
            };
            let at = lerp_axis(&t[a], b[a]);
            let corner = |su: usize, sv: usize| {
                let mut p = [0.0; 3];
                p[a] = at;
                p[u] = lerp_axis(&t[u], su);
                p[v] = lerp_axis(&t[v], sv);
                self.px(p)
            };
            svg.polygon(
                &[corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)],
                &pane_style.clone().with_class("pane"),
            );
            for (axis, other) in [(u, v), (v, u)] {
                for &val in &t[axis].values {
                    let mut p = [0.0; 3];
                    p[a] = at;
                    p[axis] = val;
                    p[other] = t[other].lo;
                    let p0 = self.px(p);
                    p[other] = t[other].hi;
                    let p1 = self.px(p);
                    svg.line(p0, p1, &grid);
                }
            }
        }
        let axis_style = Style::stroke(theme::AXIS, theme.axis_w()).square();
        for (k, AxisEdge { a, b: bb, dir }) in self.axis_edges.iter().enumerate() {
            svg.line(self.px(*a), self.px(*bb), &axis_style);
            for &val in &t[k].values {
                let mut p = *a;
                p[k] = val;
                let q = self.px(p);
                svg.line(
                    q,
                    (
                        q.0 + dir.0 * theme.tick_len(),
                        q.1 + dir.1 * theme.tick_len(),
                    ),
                    &axis_style,
                );
            }
        }
        for l in self.labels.iter().filter(|l| !l.hidden) {
            let q = self.px(l.at);
            let c = (q.0 + l.off.0, q.1 + l.off.1);
            let mut style = TextStyle::new(l.size, theme::INK).with_class(l.class);
            if l.vertical {
                style = style.rotate(-90.0);
            }
            text_centred(svg, c, &l.text, &style);
        }
        svg.end_group();
    }
}

/// Relative box edge lengths: the longer horizontal axis is 1, the other follows the data
/// (at least 0.45), and the vertical axis is `z`.
pub(crate) fn box_lengths(t: [&Ticks; 2], z: f64) -> [f64; 3] {
    let (xr, yr) = (t[0].hi - t[0].lo, t[1].hi - t[1].lo);
    let m = xr.max(yr);
    [(xr / m).max(0.45), (yr / m).max(0.45), z]
}

/// Relative box edge lengths following the data (each at least 0.45 of the longest).
pub(crate) fn box_lengths3(t: [&Ticks; 3]) -> [f64; 3] {
    let r = t.map(|t| t.hi - t.lo);
    let m = r[0].max(r[1]).max(r[2]);
    r.map(|v| (v / m).max(0.45))
}

/// Convex hull (counter-clockwise in a y-up frame) of a few points.
fn convex_hull(points: &[(f64, f64)]) -> Vec<(f64, f64)> {
    let mut p: Vec<(f64, f64)> = points.to_vec();
    p.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
    p.dedup();
    if p.len() < 3 {
        return p;
    }
    let cross = |o: (f64, f64), a: (f64, f64), b: (f64, f64)| {
        (a.0 - o.0) * (b.1 - o.1) - (a.1 - o.1) * (b.0 - o.0)
    };
    let mut hull: Vec<(f64, f64)> = Vec::new();
    for pass in 0..2 {
        let start = hull.len();
        let iter: Box<dyn Iterator<Item = &(f64, f64)>> = if pass == 0 {
            Box::new(p.iter())
        } else {
            Box::new(p.iter().rev())
        };
        for &q in iter {
            while hull.len() >= start + 2
                && cross(hull[hull.len() - 2], hull[hull.len() - 1], q) <= 0.0
            {
                hull.pop();
            }
            hull.push(q);
        }
        hull.pop();
    }
    hull
}

/// Whether a convex polygon (pixels) and a rectangle intersect.
fn polygon_meets_rect(poly: &[(f64, f64)], r: &Rect) -> bool {
    if poly.iter().any(|&p| r.contains(p)) {
        return true;
    }
    let n = poly.len();
    if (0..n).any(|i| r.hits_segment(poly[i], poly[(i + 1) % n])) {
        return true;
    }
    // The rectangle inside the polygon: its centre on the same side of every edge.
    let c = r.centre();
    if n < 3 {
        return false;
    }
    let side = |i: usize| {
        let (a, b) = (poly[i], poly[(i + 1) % n]);
        (b.0 - a.0) * (c.1 - a.1) - (b.1 - a.1) * (c.0 - a.0)
    };
    let first = side(0);
    (1..n).all(|i| side(i) * first > 0.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hull_of_square_with_inner_point() {
        let h = convex_hull(&[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0), (0.5, 0.5)]);
        assert_eq!(h.len(), 4);
        assert!(!h.contains(&(0.5, 0.5)));
    }

    #[test]
    fn polygon_rect_intersection() {
        let poly = [(0.0, 0.0), (10.0, 0.0), (10.0, 10.0), (0.0, 10.0)];
        assert!(polygon_meets_rect(&poly, &Rect::new(2.0, 2.0, 1.0, 1.0)));
        assert!(polygon_meets_rect(
            &poly,
            &Rect::new(-5.0, -5.0, 30.0, 30.0)
        ));
        assert!(!polygon_meets_rect(&poly, &Rect::new(20.0, 20.0, 5.0, 5.0)));
    }
}
