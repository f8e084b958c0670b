//! Callouts of the `controls` view: next to each control point, a box with its name and
//! three bars (truth, indeterminacy, falsity) whose lengths are the degrees, with the values.
//! Boxes are placed where they cover the least of the drawing.

use neutrospline::DegreeKind;

use crate::drawing::Painter;
use crate::font::text_width;
use crate::layout::{support, text_centred, Rect, BASELINE_FROM_CENTRE};
use crate::style::{Anchor, Color, Style, TextStyle};
use crate::theme::{self, Theme};

/// Above this many control points the callouts shrink to three bars and the name.
pub(crate) const MAX_FULL_CALLOUTS: usize = 10;

/// A degree value for display: up to three decimals, trailing zeros removed ("0.3", "0.625").
pub(crate) fn format_degree(v: f64) -> String {
    let s = format!("{:.3}", theme::unit(v));
    let s = s.trim_end_matches('0');
    if s.ends_with('.') {
        format!("{s}0")
    } else {
        s.to_string()
    }
}

struct Content {
    name: Option<String>,
    deg: [f64; 3],
}

struct Dims {
    fs: f64,
    pad: f64,
    row: f64,
    letter: f64,
    bar: f64,
    value: f64,
    compact: bool,
}

impl Dims {
    fn new(theme: &Theme, compact: bool, contents: &[Content]) -> Dims {
        let fs = if compact {
            theme.note()
        } else {
            theme.callout()
        };
        let value = contents
            .iter()
            .flat_map(|c| {
                c.deg
                    .iter()
                    .map(|&v| text_width(&format_degree(v), fs, false))
            })
            .fold(0.0, f64::max);
        Dims {
            fs,
            pad: 0.45 * fs,
            row: 1.3 * fs,
            letter: text_width("I", fs, true)
                .max(text_width("T", fs, true))
                .max(text_width("F", fs, true)),
            bar: 3.6 * fs,
            value,
            compact,
        }
    }

    fn size(&self, c: &Content) -> (f64, f64) {
        if self.compact {
            // Three vertical bars, name above.
            let name_w = c
                .name
                .as_deref()
                .map_or(0.0, |n| text_width(n, self.fs, true));
            let bars_w = 3.0 * 0.45 * self.fs + 2.0 * 0.15 * self.fs;
            let h = 1.6 * self.fs + if c.name.is_some() { self.row } else { 0.0 };
            (name_w.max(bars_w) + 2.0 * self.pad, h + 2.0 * self.pad)
        } else {
            let name_w = c
                .name
                .as_deref()
                .map_or(0.0, |n| text_width(n, self.fs * 1.1, true));
            let rows_w = self.letter + 0.4 * self.fs + self.bar + 0.4 * self.fs + self.value;
            let rows = 3.0 + if c.name.is_some() { 1.0 } else { 0.0 };
            (
                name_w.max(rows_w) + 2.0 * self.pad,
                rows * self.row + 2.0 * self.pad,
            )
        }
    }
}

/// What labels placed around points keep clear of: segments (with clearances), rectangles
/// (such as the legend), and the outside of `bounds`.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Keep {
    pub obstacles: Vec<Obstacle>,
    pub bounds: Rect,
    pub avoid: Vec<Rect>,
}

impl Keep {
    /// What to keep clear of: `obstacles`, inside `bounds`, off `avoid` if any.
    pub(crate) fn new(obstacles: Vec<Obstacle>, bounds: Rect, avoid: Option<Rect>) -> Keep {
        Keep {
            obstacles,
            bounds,
            avoid: avoid.into_iter().collect(),
        }
    }

    /// Badness of covering `rect`: area outside the bounds, area over avoided rectangles, and
    /// the number of obstacle segments it meets (weighted by `per_hit`).
    fn cost(&self, rect: &Rect, per_hit: f64) -> f64 {
        let hits = self
            .obstacles
            .iter()
            .filter(|o| {
                let c = o.clearance;
                Rect::new(rect.x - c, rect.y - c, rect.w + 2.0 * c, rect.h + 2.0 * c)
                    .hits_segment(o.a, o.b)
            })
            .count() as f64;
        rect.outside(&self.bounds) * OUTSIDE
            + self.avoid.iter().map(|o| o.overlap(rect)).sum::<f64>() * OVER_LEGEND
            + hits * per_hit
    }
}

/// Places and draws callouts for points at pixel positions `at` with degrees `deg` and
/// names, keeping clear of what `keep` says.
pub(crate) fn draw_callouts(
    svg: &mut Painter,
    theme: &Theme,
    at: &[(f64, f64)],
    deg: &[[f64; 3]],
    names: &[String],
    keep: &Keep,
) {
    // Points drawn at the same place with the same values (the ends of a closed curve)
    // share one callout that names them all.
    let mut groups: Vec<(usize, Vec<String>)> = Vec::new();
    for (i, p) in at.iter().enumerate() {
        let shown = deg[i].map(format_degree);
        let same = groups.iter_mut().find(|(k, _)| {
            let q = at[*k];
            (p.0 - q.0).abs() < 0.5
                && (p.1 - q.1).abs() < 0.5
                && deg[*k].map(format_degree) == shown
        });
        match same {
            Some((_, members)) => members.extend(names.get(i).cloned()),
            None => groups.push((i, names.get(i).cloned().into_iter().collect())),
        }
    }
    let at: Vec<(f64, f64)> = groups.iter().map(|(k, _)| at[*k]).collect();
    let contents: Vec<Content> = groups
        .iter()
        .map(|(k, members)| Content {
            name: (!members.is_empty()).then(|| members.join(" = ")),
            deg: deg[*k],
        })
        .collect();
    let r = theme.marker_r();
    let marker_boxes: Vec<Rect> = at
        .iter()
        .map(|p| Rect::new(p.0 - r, p.1 - r, 2.0 * r, 2.0 * r))
        .collect();
    let base = r + 1.2 * theme.gap();
    // Full callouts (name, bars and values) where they fit clear of the legend, the markers
    // and each other; compact ones (name and three bars) where they fit better or where
    // there are many points.
    let placed = |compact: bool| {
        let dims = Dims::new(theme, compact, &contents);
        let sizes: Vec<(f64, f64)> = contents.iter().map(|c| dims.size(c)).collect();
        let placement = Placement {
            at: &at,
            sizes: &sizes,
            marker_boxes: &marker_boxes,
            keep,
            base,
        };
        let rects = placement.place();
        let conflicts = placement.conflicts(&rects);
        (dims, rects, conflicts)
    };
    let (dims, rects, conflicts) = placed(at.len() > MAX_FULL_CALLOUTS);
    let (dims, rects) = if conflicts > 0 && !dims.compact {
        let compact = placed(true);
        if compact.2 < conflicts {
            (compact.0, compact.1)
        } else {
            (dims, rects)
        }
    } else {
        (dims, rects)
    };
    svg.begin_group("callouts");
    for ((p, c), (rect, d)) in at.iter().zip(&contents).zip(rects) {
        if d > base * 1.01 {
            // Leader from the marker's edge to the nearest point of the box.
            let q = (
                p.0.clamp(rect.x, rect.right()),
                p.1.clamp(rect.y, rect.bottom()),
            );
            let (dx, dy) = (q.0 - p.0, q.1 - p.1);
            let n = (dx * dx + dy * dy).sqrt().max(1e-9);
            svg.line(
                (p.0 + dx / n * r, p.1 + dy / n * r),
                q,
                &Style::stroke(theme::CONSTRUCTION, theme.s * 1.5),
            );
        }
        draw_box(svg, theme, &dims, c, rect);
    }
    svg.end_group();
}

/// The badness of a callout over another point's marker: it hides data, so it is taken only
/// when every other place does too.
const OVER_MARKER: f64 = 1.0e8;
/// The badness of a callout outside its bounds (the frame: over the title, the ticks or past
/// the canvas), per square pixel.
const OUTSIDE: f64 = 1.0e3;
/// The badness of a callout over the legend, per square pixel.
const OVER_LEGEND: f64 = 1.0e4;
/// The badness of two callouts over each other, per square pixel.
const OVER_CALLOUT: f64 = 3.0e3;
/// The badness of a callout crossing a segment of the curve or the control polygon.
const OVER_SEGMENT: f64 = 2.0e4;
/// The badness of a leader crossing a segment of the curve or the control polygon.
const LEADER_ACROSS: f64 = 5.0e3;
/// Rounds of improvement after the first, greedy placement.
const ROUNDS: usize = 3;

/// Where callouts go: around each point at `at` (pixels), a box of its size, clear of the
/// other points' markers, the legend, the other boxes and the drawing.
struct Placement<'a> {
    at: &'a [(f64, f64)],
    sizes: &'a [(f64, f64)],
    marker_boxes: &'a [Rect],
    keep: &'a Keep,
    /// The distance of the nearest box from its point's centre.
    base: f64,
}

impl Placement<'_> {
    /// Each box and its distance from its point: first placed greedily in the points' order,
    /// then each placed again, the others fixed, while that lowers its badness (a box placed
    /// early no longer blocks a later one's only clear place).
    fn place(&self) -> Vec<(Rect, f64)> {
        let mut placed: Vec<(Rect, f64, f64)> = Vec::with_capacity(self.at.len());
        for i in 0..self.at.len() {
            let others: Vec<Rect> = placed.iter().map(|(rect, _, _)| *rect).collect();
            placed.push(self.best(i, &others));
        }
        for _ in 0..ROUNDS {
            let mut moved = false;
            for i in 0..placed.len() {
                let others: Vec<Rect> = placed
                    .iter()
                    .enumerate()
                    .filter(|(j, _)| *j != i)
                    .map(|(_, (rect, _, _))| *rect)
                    .collect();
                let now = self.cost(i, &placed[i].0, placed[i].1, &others);
                let candidate = self.best(i, &others);
                if candidate.2 < now - 1e-9 {
                    placed[i] = candidate;
                    moved = true;
                }
            }
            if !moved {
                break;
            }
        }
        placed.into_iter().map(|(rect, d, _)| (rect, d)).collect()
    }

    /// How many boxes of `rects` lie over the legend, over another point's marker or over
    /// another box.
    fn conflicts(&self, rects: &[(Rect, f64)]) -> usize {
        rects
            .iter()
            .enumerate()
            .filter(|(i, (rect, _))| {
                self.keep.avoid.iter().any(|a| a.overlap(rect) > 0.0)
                    || self
                        .marker_boxes
                        .iter()
                        .enumerate()
                        .any(|(j, m)| j != *i && m.overlap(rect) > 0.0)
                    || rects
                        .iter()
                        .enumerate()
                        .any(|(j, (o, _))| j != *i && o.overlap(rect) > 0.0)
            })
            .count()
    }

    /// The least bad box for point `i` with `others` placed: its rectangle, distance and
    /// badness.
    fn best(&self, i: usize, others: &[Rect]) -> (Rect, f64, f64) {
        let (p, (w, h)) = (self.at[i], self.sizes[i]);
        let mut best: Option<(Rect, f64, f64)> = None;
        for dist in [1.0, 2.0, 3.5, 5.5, 8.0, 11.0, 15.0] {
            for k in 0..16 {
                let a = (k as f64) * std::f64::consts::PI / 8.0 - std::f64::consts::FRAC_PI_2;
                let dir = (a.cos(), a.sin());
                let d = self.base * dist;
                let s = support(dir, w, h);
                let cx = p.0 + dir.0 * (d + s);
                let cy = p.1 + dir.1 * (d + s);
                let rect = Rect::new(cx - w / 2.0, cy - h / 2.0, w, h);
                let score = self.cost(i, &rect, d, others) + (dir.1 + 1.0) * 20.0;
                if best.as_ref().is_none_or(|b| score < b.2) {
                    best = Some((rect, d, score));
                }
            }
        }
        best.expect("candidates are tried")
    }

    /// The badness of `rect` at distance `d` as point `i`'s box.
    fn cost(&self, i: usize, rect: &Rect, d: f64, others: &[Rect]) -> f64 {
        let over_markers = self
            .marker_boxes
            .iter()
            .enumerate()
            .filter(|(j, m)| *j != i && m.overlap(rect) > 0.0)
            .count() as f64;
        // The leader from the point to the box's nearest point, through other boxes.
        let p = self.at[i];
        let q = (
            p.0.clamp(rect.x, rect.right()),
            p.1.clamp(rect.y, rect.bottom()),
        );
        let leader_through = others.iter().filter(|o| o.hits_segment(p, q)).count() as f64;
        // ... and across the curve and the polygon (the segments at the point itself aside).
        let leader_across = if self.at.len() > 1 && d > self.base * 1.01 {
            self.keep
                .obstacles
                .iter()
                .filter(|o| o.a != p && o.b != p && segments_cross(p, q, o.a, o.b))
                .count() as f64
        } else {
            0.0
        };
        self.keep.cost(rect, OVER_SEGMENT)
            + others.iter().map(|o| o.overlap(rect)).sum::<f64>() * OVER_CALLOUT
            + over_markers * OVER_MARKER
            + leader_through * OVER_SEGMENT
            + leader_across * LEADER_ACROSS
            + d * 30.0
    }
}

fn draw_box(svg: &mut Painter, theme: &Theme, dims: &Dims, c: &Content, rect: Rect) {
    svg.rect(
        rect.x,
        rect.y,
        rect.w,
        rect.h,
        &Style::stroke(theme::PANE_EDGE, theme.s * 1.5)
            .with_fill(Color::WHITE)
            .with_fill_opacity(0.92)
            .square()
            .with_class("callout"),
    );
    let fs = dims.fs;
    let x = rect.x + dims.pad;
    let mut y = rect.y + dims.pad;
    if dims.compact {
        if let Some(name) = &c.name {
            svg.text(
                rect.x + rect.w / 2.0,
                y + dims.row / 2.0 + BASELINE_FROM_CENTRE * fs,
                name,
                &TextStyle::new(fs, theme::INK)
                    .bold()
                    .anchor(Anchor::Middle)
                    .with_class("point-name"),
            );
            y += dims.row;
        }
        let bw = 0.45 * fs;
        let total = 3.0 * bw + 2.0 * 0.15 * fs;
        let full = 1.6 * fs;
        let mut bx = rect.x + (rect.w - total) / 2.0;
        for kind in DegreeKind::ALL {
            let v = theme::unit(c.deg[kind.index()]);
            svg.rect(bx, y, bw, full, &Style::fill(theme::TRACK).square());
            svg.rect(
                bx,
                y + full * (1.0 - v),
                bw,
                full * v,
                &Style::fill(theme::degree_color(kind)).square(),
            );
            bx += bw + 0.15 * fs;
        }
        return;
    }
    if let Some(name) = &c.name {
        svg.text(
            x,
            y + dims.row / 2.0 + BASELINE_FROM_CENTRE * fs * 1.1,
            name,
            &TextStyle::new(fs * 1.1, theme::INK)
                .bold()
                .with_class("point-name"),
        );
        y += dims.row;
    }
    for kind in DegreeKind::ALL {
        let v = c.deg[kind.index()];
        let cy = y + dims.row / 2.0;
        let color = theme::degree_color(kind);
        svg.text(
            x + dims.letter / 2.0,
            cy + BASELINE_FROM_CENTRE * fs,
            theme::degree_letter(kind),
            &TextStyle::new(fs, color).bold().anchor(Anchor::Middle),
        );
        let bx = x + dims.letter + 0.4 * fs;
        let bh = 0.62 * fs;
        svg.rect(
            bx,
            cy - bh / 2.0,
            dims.bar,
            bh,
            &Style::fill(theme::TRACK).square(),
        );
        svg.rect(
            bx,
            cy - bh / 2.0,
            dims.bar * theme::unit(v),
            bh,
            &Style::fill(color)
                .square()
                .with_class(&format!("bar {}", kind.name())),
        );
        svg.text(
            bx + dims.bar + 0.4 * fs + dims.value,
            cy + BASELINE_FROM_CENTRE * fs,
            &format_degree(v),
            &TextStyle::new(fs, theme::INK).anchor(Anchor::End),
        );
        y += dims.row;
    }
}

/// The style of a point's name: bold, on a halo that keeps it readable over the drawing.
fn name_style(theme: &Theme) -> TextStyle {
    TextStyle::new(theme.name(), theme::INK)
        .bold()
        .halo(theme.s * 7.0)
        .with_class("point-name")
}

/// Draws `names` of the points at `at` (pixels), each placed by [`place_names`], in a group
/// `point-names`.
pub(crate) fn draw_names(
    svg: &mut Painter,
    theme: &Theme,
    at: &[(f64, f64)],
    names: &[String],
    keep: &Keep,
) {
    svg.begin_group("point-names");
    let centres = place_names(theme, at, names, keep);
    for (c, name) in centres.iter().zip(names) {
        text_centred(svg, *c, name, &name_style(theme));
    }
    svg.end_group();
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn format_degree_values() {
        assert_eq!(format_degree(0.3), "0.3");
        assert_eq!(format_degree(0.625), "0.625");
        assert_eq!(format_degree(1.0), "1.0");
        assert_eq!(format_degree(0.0), "0.0");
        assert_eq!(format_degree(f64::NAN), "0.0");
    }
}

/// A segment that labels should not cover, with a clearance in pixels on each side.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Obstacle {
    pub a: (f64, f64),
    pub b: (f64, f64),
    pub clearance: f64,
}

/// Whether the segments `a b` and `c d` cross (touching counts; parallel ones never do).
fn segments_cross(a: (f64, f64), b: (f64, f64), c: (f64, f64), d: (f64, f64)) -> bool {
    let side = |p: (f64, f64), q: (f64, f64), r: (f64, f64)| {
        (q.0 - p.0) * (r.1 - p.1) - (q.1 - p.1) * (r.0 - p.0)
    };
    let (d1, d2) = (side(c, d, a), side(c, d, b));
    let (d3, d4) = (side(a, b, c), side(a, b, d));
    d1 * d2 <= 0.0 && d3 * d4 <= 0.0 && (d1 != d2 || d3 != d4) && !(d1 == 0.0 && d2 == 0.0)
}

/// Obstacles along a polyline.
pub(crate) fn obstacles_of(pts: &[(f64, f64)], clearance: f64) -> Vec<Obstacle> {
    pts.windows(2)
        .map(|w| Obstacle {
            a: w[0],
            b: w[1],
            clearance,
        })
        .collect()
}

/// Centres for the names of points at `at`: each among 8 spots around its point, chosen to
/// keep clear of what `keep` says and of the other points and names.
fn place_names(theme: &Theme, at: &[(f64, f64)], names: &[String], keep: &Keep) -> Vec<(f64, f64)> {
    let r = theme.marker_r();
    let fs = theme.name();
    let h = crate::layout::TEXT_BOX * fs;
    let mut placed: Vec<Rect> = Vec::new();
    let mut out = Vec::new();
    for (i, (p, name)) in at.iter().zip(names).enumerate() {
        let w = text_width(name, fs, true);
        let mut best: Option<(f64, Rect)> = None;
        // Up-right first (the usual place), then the other diagonals and sides.
        let dirs: [(f64, f64); 8] = [
            (1.0, -1.0),
            (-1.0, -1.0),
            (1.0, 1.0),
            (-1.0, 1.0),
            (0.0, -1.0),
            (1.0, 0.0),
            (0.0, 1.0),
            (-1.0, 0.0),
        ];
        for (rank, (dx, dy)) in dirs.iter().enumerate() {
            for step in [1.0, 2.2] {
                let n: f64 = (dx * dx + dy * dy).sqrt();
                let dir = (dx / n, dy / n);
                let d = (r + 0.6 * theme.gap()) * step + support(dir, w, h);
                let c = (p.0 + dir.0 * d, p.1 + dir.1 * d);
                let rect = Rect::new(c.0 - w / 2.0, c.1 - h / 2.0, w, h);
                let mut score = keep.cost(&rect, 1.0e3);
                score += placed.iter().map(|o| o.overlap(&rect)).sum::<f64>() * 100.0;
                score += at
                    .iter()
                    .enumerate()
                    .filter(|(j, q)| {
                        *j != i
                            && Rect::new(q.0 - r, q.1 - r, 2.0 * r, 2.0 * r).overlap(&rect) > 0.0
                    })
                    .count() as f64
                    * 1.0e5;
                score += rank as f64 * 10.0 + (step - 1.0) * 400.0;
                if best.as_ref().is_none_or(|b| score < b.0) {
                    best = Some((score, rect));
                }
            }
        }
        let rect = best.map_or(Rect::new(p.0, p.1, w, h), |b| b.1);
        out.push(rect.centre());
        placed.push(rect);
    }
    out
}
