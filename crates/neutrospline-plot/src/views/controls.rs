//! `controls` (paper Fig. 1): the control points with their degrees.
//!
//! - 2-D curve: the control polygon and points on x-y axes, each point with a callout of its
//!   name and three degree bars, the crisp curve in light grey for context.
//! - 3-D curve: the same in the 3-D box, with drop lines and the curve's shadow on the floor.
//! - Surface: the control net over the surface in grey, each control point drawn as a degree
//!   glyph (a regular subset on large nets), the corners named.

use neutrospline::DegreeKind;

use crate::axes2::Scale;
use crate::callout::{draw_callouts, draw_names, obstacles_of, Keep};
use crate::ctx::Ctx;
use crate::curve3d::{control_polygon_3d, drop_lines, shadowed_box};
use crate::drawing::{Drawing, Painter};
use crate::glyph::{draw_glyphs, glyph_subset};
use crate::layout::{Entry, Legend, LegendPlace, Rect, Swatch};
use crate::mesh::{draw_mesh, Paint};
use crate::model::Mesh;
use crate::net::{draw_net, net_edges};
use crate::scene::{flat, Shape, CHUNK, DATA, OVER};
use crate::style::{Color, Style};
use crate::theme::{self, marker_style, Marker, Theme};

use super::figure::Figure;

/// The `controls` view.
pub(crate) struct Controls;

impl Figure for Controls {
    fn title(&self, _label: &str, surface: bool) -> String {
        if surface {
            "Neutrosophic control net".to_string()
        } else {
            "Neutrosophic control points".to_string()
        }
    }

    fn curve_2d(&self, ctx: &Ctx) -> Drawing {
        let th = &ctx.theme;
        ctx.figure(
            curve_legend(th),
            LegendPlace::Column,
            |svg, plot, legend| {
                let axes = ctx.axes2(plot, 6.0 * th.callout(), Scale::Equal);
                axes.draw(svg, th);
                let (curve, ctrl) = (axes.pixels(&ctx.curve), axes.pixels(ctx.controls));
                axes.begin_clip(svg);
                svg.polyline(
                    &curve,
                    &Style::stroke(theme::SHADOW, th.crisp_w()).with_class("curve crisp"),
                );
                svg.polyline(
                    &ctrl,
                    &Style::stroke(theme::CRISP, th.polygon_w())
                        .with_dash(th.dash().0, th.dash().1)
                        .with_class("control-polygon"),
                );
                for p in &ctrl {
                    svg.circle(
                        *p,
                        th.marker_r(),
                        &marker_style(th, Color::WHITE).with_class("control-point"),
                    );
                }
                svg.end_group();
                // A box may reach past the frame into the margin, never over the legend.
                callouts(svg, ctx, &curve, &ctrl, axes.frame, legend);
            },
        )
    }

    fn curve_3d(&self, ctx: &Ctx) -> Drawing {
        let th = &ctx.theme;
        ctx.figure(curve_legend(th), LegendPlace::Corner, |svg, plot, avoid| {
            let (axes, mut scene) = shadowed_box(svg, ctx, plot, avoid);
            drop_lines(&mut scene, ctx, &axes);
            let curve: Vec<(f64, f64, f64)> =
                ctx.curve.iter().map(|p| axes.screen(p.pos)).collect();
            scene.polyline(
                DATA,
                &curve,
                CHUNK,
                &Style::stroke(theme::SHADOW, th.crisp_w()).with_class("curve crisp"),
            );
            let ctrl = control_polygon_3d(&mut scene, ctx, &axes, theme::CRISP);
            for p in &ctrl {
                scene.push(
                    OVER,
                    p.2,
                    Shape::Marker(
                        Marker::Circle,
                        (p.0, p.1),
                        th.marker_r(),
                        marker_style(th, Color::WHITE).with_class("control-point"),
                    ),
                );
            }
            scene.draw(svg);
            callouts(svg, ctx, &flat(&curve), &flat(&ctrl), plot, avoid);
        })
    }

    fn surface(&self, ctx: &Ctx, mesh: &Mesh, grid: (usize, usize)) -> Drawing {
        let th = &ctx.theme;
        let (chosen, step) = glyph_subset(grid);
        let legend = net_legend(th, step);
        ctx.figure(legend, LegendPlace::Corner, |svg, plot, avoid| {
            let axes = ctx.draw_box(svg, plot, avoid);
            draw_mesh(svg, th, &axes, mesh, Paint::Neutral);
            let white = |_| Color::WHITE;
            let pts = draw_net(svg, ctx, &axes, mesh, grid, theme::CRISP, &white);
            let mut keep_out = draw_glyphs(svg, th, &pts, ctx.controls, &chosen);
            keep_out.extend(avoid);
            name_corners(svg, ctx, grid, &flat(&pts), plot, keep_out);
        })
    }
}

/// Callouts of the control points at `ctrl` (pixels), clear of the curve and the control
/// polygon, inside `bounds` and off `avoid`.
fn callouts(
    svg: &mut Painter,
    ctx: &Ctx,
    curve: &[(f64, f64)],
    ctrl: &[(f64, f64)],
    bounds: Rect,
    avoid: Option<Rect>,
) {
    let mut obstacles = obstacles_of(curve, 0.0);
    obstacles.extend(obstacles_of(ctrl, 0.0));
    let keep = Keep::new(obstacles, bounds, avoid);
    let shown = ctx.labelled.min(ctrl.len());
    let degs: Vec<[f64; 3]> = ctx.controls[..shown].iter().map(|p| p.deg).collect();
    let names = callout_names(ctx);
    draw_callouts(
        svg,
        &ctx.theme,
        &ctrl[..shown],
        &degs,
        &names[..shown.min(names.len())],
        &keep,
    );
}

/// Names the corners of the net (at `pts`, pixels), clear of its edges, inside `bounds` and
/// off `keep_out` (the glyphs and the legend).
fn name_corners(
    svg: &mut Painter,
    ctx: &Ctx,
    grid: (usize, usize),
    pts: &[(f64, f64)],
    bounds: Rect,
    keep_out: Vec<Rect>,
) {
    let names = point_names(ctx, grid);
    let named = corners(grid);
    let keep = Keep {
        obstacles: net_edges(grid)
            .iter()
            .flat_map(|&(a, b)| obstacles_of(&[pts[a], pts[b]], 0.0))
            .collect(),
        bounds,
        avoid: keep_out,
    };
    let at: Vec<(f64, f64)> = named.iter().map(|&k| pts[k]).collect();
    let labels: Vec<String> = named.iter().map(|&k| names[k].clone()).collect();
    draw_names(svg, &ctx.theme, &at, &labels, &keep);
}

/// The entries of both legends: the control polygon or net named `polygon`, what is drawn
/// under it, and a band per degree named with its letter (as in the callouts and glyphs).
fn entries(th: &Theme, polygon: &str, under: Entry) -> Vec<Entry> {
    let mut entries = vec![
        Entry::polygon(th, theme::CRISP, Marker::Circle, Color::WHITE, polygon),
        under,
    ];
    entries.extend(Entry::bands(|kind: DegreeKind| {
        format!("{} ({})", kind.name(), theme::degree_letter(kind))
    }));
    entries
}

/// The legend of a curve's control points.
fn curve_legend(th: &Theme) -> Legend {
    let crisp = Entry::line(theme::SHADOW, th.crisp_w(), None, "crisp curve");
    Legend {
        entries: entries(th, "control polygon", crisp),
        notes: vec!["Bars show each point's degrees; a full bar is 1.".to_string()],
        colorbar: None,
    }
}

/// Names for callouts: the given ones, else `P0`, `P1`, ...
fn callout_names(ctx: &Ctx) -> Vec<String> {
    if ctx.names.is_empty() {
        (0..ctx.controls.len()).map(|i| format!("P{i}")).collect()
    } else {
        ctx.names.to_vec()
    }
}

/// The legend of a surface's control net; `step` > 1 when only a subset of the points has
/// glyphs.
fn net_legend(th: &Theme, step: usize) -> Legend {
    let surface = Entry {
        swatch: Swatch::Patch {
            color: theme::SURFACE,
        },
        label: "surface".to_string(),
    };
    let mut notes = vec![
        "Each control point is drawn as its three degrees, T, I, F from the left; a full bar is 1. Corners are named P(row)(column).".to_string(),
    ];
    if step > 1 {
        notes.push(format!(
            "Degrees shown at every {} point in each direction.",
            ordinal(step)
        ));
    }
    Legend {
        entries: entries(th, "control net", surface),
        notes,
        colorbar: None,
    }
}

/// `1st`, `2nd`, `3rd`, `4th`, ...
fn ordinal(n: usize) -> String {
    let suffix = match (n % 10, n % 100) {
        (1, 11) | (2, 12) | (3, 13) => "th",
        (1, _) => "st",
        (2, _) => "nd",
        (3, _) => "rd",
        _ => "th",
    };
    format!("{n}{suffix}")
}

/// Names of the control points: the model's, else `P{i}{j}` (`P{i},{j}` past 10 rows or
/// columns).
fn point_names(ctx: &Ctx, grid: (usize, usize)) -> Vec<String> {
    if !ctx.names.is_empty() {
        return ctx.names.to_vec();
    }
    let (rows, cols) = grid;
    let comma = rows > 10 || cols > 10;
    (0..rows * cols)
        .map(|k| {
            let (i, j) = (k / cols, k % cols);
            if comma {
                format!("P{i},{j}")
            } else {
                format!("P{i}{j}")
            }
        })
        .collect()
}

/// The corners of the net (the points that are named), without repeats.
fn corners(grid: (usize, usize)) -> Vec<usize> {
    let (rows, cols) = grid;
    let mut c = vec![0, cols - 1, (rows - 1) * cols, rows * cols - 1];
    c.sort_unstable();
    c.dedup();
    c
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn surface_corners() {
        assert_eq!(corners((1, 1)), vec![0]);
        assert_eq!(corners((1, 4)), vec![0, 3]);
        assert_eq!(corners((3, 2)), vec![0, 1, 4, 5]);
    }

    #[test]
    fn surface_names_and_ordinals() {
        assert_eq!(ordinal(2), "2nd");
        assert_eq!(ordinal(3), "3rd");
        assert_eq!(ordinal(11), "11th");
        assert_eq!(ordinal(4), "4th");
    }
}
