//! `band`: the fuzzy position of a curve (control point spreads, SPEC section 9) seen flat.
//!
//! At level alpha each coordinate of the curve at `t` is the interval between the lower and
//! the upper alpha-cut curves, so the curve sweeps the union over `t` of the boxes
//! `[x_lo, x_hi] x [y_lo, y_hi]` (a band). The view fills the band of each alpha level
//! (by default 0, 0.5 and 1), lighter for lower alpha, lowest first; between two samples the
//! swept region is drawn as the convex hull of their two boxes. The crisp curve (the band at
//! alpha = 1) is drawn on top, the centroid curve dashed when it differs from the crisp curve.
//!
//! - 2-D curve: on x-y axes, with the control polygon and the named control points as in
//!   `plane`. Without spreads every band is the crisp curve, and the figure is that curve.
//! - 3-D curve: in the 3-D box, the silhouette of the tube of boxes (the hull of the eight
//!   corners of two consecutive boxes, projected).
//! - Surface: none ([`crate::PlotError::BandOnSurface`], refused before drawing).

use crate::axes2::Scale;
use crate::callout::{obstacles_of, Obstacle};
use crate::ctx::Ctx;
use crate::curve3d::shadowed_box;
use crate::drawing::{Drawing, Painter};
use crate::layout::{Entry, Legend, LegendPlace, Swatch};
use crate::model::Mesh;
use crate::point::Pt;
use crate::style::{Color, Style};
use crate::theme::{self, Theme};

use super::figure::Figure;
use super::{control_polygon_entry, draw_control_polygon, draw_crisp_and_controls};

/// The `band` view.
pub(crate) struct Band;

/// The colour of the band at alpha = 1; lower levels are mixed towards white.
const BAND: Color = Color(0x2b, 0x6c, 0xb0);

/// The fill of the band at level `alpha`: from a pale tint at 0 to [`BAND`] at 1.
fn band_color(alpha: f64) -> Color {
    Color::WHITE.mix(BAND, 0.25 + 0.6 * alpha.clamp(0.0, 1.0))
}

/// A level as text: `0`, `0.5`, `0.25`.
fn level_text(alpha: f64) -> String {
    let text = format!("{alpha:.3}");
    text.trim_end_matches('0').trim_end_matches('.').to_string()
}

impl Figure for Band {
    fn title(&self, label: &str, _surface: bool) -> String {
        format!("{label}: fuzzy band")
    }

    fn curve_2d(&self, ctx: &Ctx) -> Drawing {
        let th = &ctx.theme;
        ctx.figure(legend(ctx, false), LegendPlace::Column, |svg, plot, _| {
            let axes = ctx.axes2(plot, 40.0 * th.s, Scale::Equal);
            axes.draw(svg, th);
            let px = |p: [f64; 3]| axes.map(p[0], p[1]);
            let curve = axes.pixels(&ctx.curve);
            let ctrl = axes.pixels(ctx.controls);
            axes.begin_clip(svg);
            draw(svg, ctx, &px, 2, &curve, &ctrl);
            svg.end_group();
            let obstacles = obstacles(ctx, &px, &curve, &ctrl);
            ctx.names(svg, &ctrl, obstacles, axes.frame, None);
        })
    }

    fn curve_3d(&self, ctx: &Ctx) -> Drawing {
        ctx.figure(
            legend(ctx, true),
            LegendPlace::Corner,
            |svg, plot, avoid| {
                let (axes, scene) = shadowed_box(svg, ctx, plot, avoid);
                scene.draw(svg);
                let px = |p: [f64; 3]| axes.px(p);
                let curve: Vec<(f64, f64)> = ctx.curve.iter().map(|p| px(p.pos)).collect();
                let ctrl: Vec<(f64, f64)> = ctx.controls.iter().map(|p| px(p.pos)).collect();
                draw(svg, ctx, &px, 3, &curve, &ctrl);
                let obstacles = obstacles(ctx, &px, &curve, &ctrl);
                ctx.names(svg, &ctrl, obstacles, plot, avoid);
            },
        )
    }

    /// Never called: [`crate::render_svg`] refuses the band view of a surface
    /// ([`crate::PlotError::BandOnSurface`]) before drawing; the plane view's maps stand in.
    fn surface(&self, ctx: &Ctx, mesh: &Mesh, grid: (usize, usize)) -> Drawing {
        super::plane::Plane.surface(ctx, mesh, grid)
    }
}

/// The corners of the box between `lo` and `hi` in `dimension` axes (4 or 8), in pixels.
fn corners(
    px: &dyn Fn([f64; 3]) -> (f64, f64),
    lo: &Pt,
    hi: &Pt,
    dimension: usize,
) -> Vec<(f64, f64)> {
    let count = 1usize << dimension;
    (0..count)
        .map(|bits| {
            let mut p = lo.pos;
            for axis in 0..dimension {
                if bits & (1 << axis) != 0 {
                    p[axis] = hi.pos[axis];
                }
            }
            px(p)
        })
        .collect()
}

/// The convex hull of `points` (Andrew's monotone chain), counter-clockwise in pixels.
fn hull(mut points: Vec<(f64, f64)>) -> Vec<(f64, f64)> {
    points.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
    points.dedup();
    if points.len() < 3 {
        return points;
    }
    let cross = |o: (f64, f64), a: (f64, f64), b: (f64, f64)| {
        (a.0 - o.0) * (b.1 - o.1) - (a.1 - o.1) * (b.0 - o.0)
    };
    let mut lower: Vec<(f64, f64)> = Vec::new();
    for &p in &points {
        while lower.len() >= 2 && cross(lower[lower.len() - 2], lower[lower.len() - 1], p) <= 0.0 {
            lower.pop();
        }
        lower.push(p);
    }
    let mut upper: Vec<(f64, f64)> = Vec::new();
    for &p in points.iter().rev() {
        while upper.len() >= 2 && cross(upper[upper.len() - 2], upper[upper.len() - 1], p) <= 0.0 {
            upper.pop();
        }
        upper.push(p);
    }
    lower.pop();
    upper.pop();
    lower.extend(upper);
    lower
}

/// Whether the band of a level has any width on the screen (a crisp curve's has none).
fn has_width(px: &dyn Fn([f64; 3]) -> (f64, f64), lo: &[Pt], hi: &[Pt]) -> bool {
    lo.iter().zip(hi).any(|(a, b)| {
        let (p, q) = (px(a.pos), px(b.pos));
        (p.0 - q.0).abs() > 0.25 || (p.1 - q.1).abs() > 0.25
    })
}

/// The band of each level (lowest alpha first), the centroid curve (dashed, when it differs
/// from the crisp curve), the control polygon, the crisp curve and the control points.
fn draw(
    svg: &mut Painter,
    ctx: &Ctx,
    px: &dyn Fn([f64; 3]) -> (f64, f64),
    dimension: usize,
    curve: &[(f64, f64)],
    ctrl: &[(f64, f64)],
) {
    let th = &ctx.theme;
    if let Some(band) = &ctx.band {
        for (alpha, lo, hi) in &band.levels {
            if !has_width(px, lo, hi) {
                continue;
            }
            let color = band_color(*alpha);
            // Each piece is outlined in its fill colour, so that neighbours meet without a seam.
            let style = Style::stroke(color, 0.75 * th.s).with_fill(color);
            svg.begin_group(&format!("band alpha-{}", level_text(*alpha)));
            for k in 0..lo.len().saturating_sub(1) {
                let mut points = corners(px, &lo[k], &hi[k], dimension);
                points.extend(corners(px, &lo[k + 1], &hi[k + 1], dimension));
                let piece = hull(points);
                if piece.len() >= 3 {
                    svg.polygon(&piece, &style);
                }
            }
            svg.end_group();
        }
        let centroid: Vec<(f64, f64)> = band.centroid.iter().map(|p| px(p.pos)).collect();
        if differs(&centroid, curve) {
            svg.polyline(
                &centroid,
                &Style::stroke(theme::CENTROID, th.thin_w())
                    .with_dash(th.dash().0, th.dash().1)
                    .with_class("curve centroid"),
            );
        }
    }
    draw_control_polygon(svg, th, ctrl);
    draw_crisp_and_controls(svg, th, curve, ctrl);
}

/// Whether two pixel polylines differ by more than a quarter pixel somewhere.
fn differs(a: &[(f64, f64)], b: &[(f64, f64)]) -> bool {
    a.iter()
        .zip(b)
        .any(|(p, q)| (p.0 - q.0).abs() > 0.25 || (p.1 - q.1).abs() > 0.25)
}

/// The legend: one swatch per alpha level that has width, the crisp curve, the centroid
/// curve when it differs, the control polygon, and a note on what the band is.
fn legend(ctx: &Ctx, spatial: bool) -> Legend {
    let th: &Theme = &ctx.theme;
    let mut entries = Vec::new();
    let mut widths = false;
    let mut centroid = false;
    if let Some(band) = &ctx.band {
        for (alpha, lo, hi) in &band.levels {
            let wide = lo.iter().zip(hi).any(|(a, b)| a.pos != b.pos);
            if wide {
                widths = true;
                entries.push(Entry {
                    swatch: Swatch::Patch {
                        color: band_color(*alpha),
                    },
                    label: format!("alpha = {}", level_text(*alpha)),
                });
            }
        }
        centroid = band
            .centroid
            .iter()
            .zip(&ctx.curve)
            .any(|(a, b)| a.pos != b.pos);
    }
    entries.push(Entry::line(
        theme::CRISP,
        th.thin_w(),
        None,
        "crisp curve (alpha = 1)",
    ));
    if centroid {
        entries.push(Entry::line(
            theme::CENTROID,
            th.thin_w(),
            Some(th.dash()),
            "centroid curve",
        ));
    }
    entries.push(control_polygon_entry(th));
    let note = match (widths, spatial) {
        (false, _) => {
            "The control points carry no spreads: the curve is crisp at every alpha.".to_string()
        }
        (true, false) => "At level alpha the curve sweeps the filled region: at each t the box \
                          of its coordinates' alpha-cuts (lighter for lower alpha)."
            .to_string(),
        (true, true) => "At level alpha the curve sweeps a tube of boxes (its coordinates' \
                         alpha-cuts at each t); the filled region is the tube's silhouette, \
                         lighter for lower alpha."
            .to_string(),
    };
    Legend {
        entries,
        notes: vec![note],
        colorbar: None,
    }
}

/// What names must keep clear of: the widest band, the curve and the control polygon.
fn obstacles(
    ctx: &Ctx,
    px: &dyn Fn([f64; 3]) -> (f64, f64),
    curve: &[(f64, f64)],
    ctrl: &[(f64, f64)],
) -> Vec<Obstacle> {
    let mut o = obstacles_of(curve, 4.0 * ctx.theme.s);
    if let Some((_, lo, hi)) = ctx.band.as_ref().and_then(|b| b.levels.first()) {
        o.extend(obstacles_of(
            &lo.iter().map(|p| px(p.pos)).collect::<Vec<_>>(),
            0.0,
        ));
        o.extend(obstacles_of(
            &hi.iter().map(|p| px(p.pos)).collect::<Vec<_>>(),
            0.0,
        ));
    }
    o.extend(obstacles_of(ctrl, 0.0));
    o
}
