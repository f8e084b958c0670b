//! `plane`: the degrees seen flat.
//!
//! - 2-D curve: the crisp curve with three lanes along it, one per degree (truth,
//!   indeterminacy, falsity from the left of the direction of travel), each filled to a width
//!   proportional to the degree (a full grey lane is 1).
//! - 3-D curve: the same lanes along the curve's projection in the 3-D box (flat on the
//!   screen; the box keeps the 3-D context).
//! - Surface: the parameter domain seen from above: one heat map per degree over (u, v), `u`
//!   across and `v` up, with the interior knot lines of a spline surface, arranged like `all`.

use neutrospline::DegreeKind;

use crate::axes2::{Axes2, Scale};
use crate::callout::{obstacles_of, Obstacle};
use crate::ctx::Ctx;
use crate::curve3d::shadowed_box;
use crate::drawing::{Drawing, Painter};
use crate::layout::{ColorBar, Entry, Legend, LegendPlace, Rect, Swatch};
use crate::model::Mesh;
use crate::panels;
use crate::style::Style;
use crate::theme::{self, Theme};

use super::figure::Figure;
use super::{control_polygon_entry, draw_control_polygon, draw_crisp_and_controls};

/// The `plane` view.
pub(crate) struct Plane;

impl Figure for Plane {
    fn title(&self, label: &str, surface: bool) -> String {
        if surface {
            format!("{label}: degree maps")
        } else {
            format!("{label}: degree bands")
        }
    }

    fn curve_2d(&self, ctx: &Ctx) -> Drawing {
        let th = &ctx.theme;
        ctx.figure(band_legend(th), LegendPlace::Column, |svg, plot, _| {
            let axes = ctx.axes2(plot, 75.0 * th.s, Scale::Equal);
            axes.draw(svg, th);
            let (curve, ctrl) = (axes.pixels(&ctx.curve), axes.pixels(ctx.controls));
            axes.begin_clip(svg);
            plane_data(svg, ctx, &curve, &ctrl);
            svg.end_group();
            let obstacles = plane_obstacles(th, &curve, &ctrl);
            ctx.names(svg, &ctrl, obstacles, axes.frame, None);
        })
    }

    fn curve_3d(&self, ctx: &Ctx) -> Drawing {
        let th = &ctx.theme;
        ctx.figure(band_legend(th), LegendPlace::Corner, |svg, plot, avoid| {
            let (axes, scene) = shadowed_box(svg, ctx, plot, avoid);
            scene.draw(svg);
            let curve: Vec<(f64, f64)> = ctx.curve.iter().map(|p| axes.px(p.pos)).collect();
            let ctrl: Vec<(f64, f64)> = ctx.controls.iter().map(|p| axes.px(p.pos)).collect();
            plane_data(svg, ctx, &curve, &ctrl);
            let obstacles = plane_obstacles(th, &curve, &ctrl);
            ctx.names(svg, &ctrl, obstacles, plot, avoid);
        })
    }

    fn surface(&self, ctx: &Ctx, mesh: &Mesh, _grid: (usize, usize)) -> Drawing {
        let th = &ctx.theme;
        let legend = map_legend(th, !(mesh.knots[0].is_empty() && mesh.knots[1].is_empty()));
        let fit = |area: Rect| {
            let axes = domain_axes(th, mesh, area);
            (axes.scale(), axes.outer(th).y)
        };
        panels::figure(ctx, &legend, &fit, &|svg, area, kind| {
            heat_map(svg, th, mesh, &domain_axes(th, mesh, area), kind);
        })
    }
}

// ---------------------------------------------------------------------------------------------
// Curves: lanes along the crisp curve

/// Lane geometry of the plane view: (band full width, lane pitch) in pixels.
fn lanes(th: &Theme) -> (f64, f64) {
    (24.0 * th.s, 29.0 * th.s)
}

/// Offset bands along a pixel polyline: lane `j` centred `pitch * (1 - j)` pixels to the left
/// of the direction of travel, of full width `width`; band width = degree * width.
fn draw_bands(svg: &mut Painter, th: &Theme, pts: &[(f64, f64)], degs: &[[f64; 3]]) {
    let n = pts.len();
    if n < 2 {
        return;
    }
    let mut normals = Vec::with_capacity(n);
    let mut last = None;
    for k in 0..n {
        let a = pts[k.saturating_sub(1)];
        let b = pts[(k + 1).min(n - 1)];
        let (tx, ty) = (b.0 - a.0, b.1 - a.1);
        let len = (tx * tx + ty * ty).sqrt();
        if len > 1e-9 {
            last = Some((ty / len, -tx / len));
        }
        normals.push(last);
    }
    // Points before the first usable direction take the first one found; a curve that is a
    // single pixel has no direction and gets no bands.
    let Some(first) = normals.iter().flatten().next().copied() else {
        return;
    };
    let normals: Vec<(f64, f64)> = normals.iter().map(|n| n.unwrap_or(first)).collect();
    let (width, pitch) = lanes(th);
    let offset = |k: usize, c: f64| (pts[k].0 + normals[k].0 * c, pts[k].1 + normals[k].1 * c);
    svg.begin_group("bands");
    for j in 0..3 {
        let centre = pitch * (1.0 - j as f64);
        let mut track: Vec<(f64, f64)> = (0..n).map(|k| offset(k, centre + width / 2.0)).collect();
        track.extend((0..n).rev().map(|k| offset(k, centre - width / 2.0)));
        svg.polygon(&track, &Style::fill(theme::TRACK).with_class("track"));
    }
    for (j, kind) in DegreeKind::ALL.iter().enumerate() {
        let centre = pitch * (1.0 - j as f64);
        let half = |k: usize| theme::unit(degs[k][kind.index()]) * width / 2.0;
        let mut band: Vec<(f64, f64)> = (0..n).map(|k| offset(k, centre + half(k))).collect();
        band.extend((0..n).rev().map(|k| offset(k, centre - half(k))));
        svg.polygon(
            &band,
            &Style::fill(theme::degree_color(*kind)).with_class(&format!("band {}", kind.name())),
        );
    }
    svg.end_group();
}

/// The legend of the bands along a curve.
fn band_legend(th: &Theme) -> Legend {
    let mut entries = Entry::bands(|kind| kind.name().to_string());
    entries.push(Entry::line(theme::CRISP, th.thin_w(), None, "crisp curve"));
    entries.push(control_polygon_entry(th));
    Legend {
        entries,
        notes: vec![
            "Band width shows the degree; a full grey lane is 1. Seen along the curve, truth runs on its left, falsity on its right.".to_string(),
        ],
        colorbar: None,
    }
}

/// The control polygon, the bands along the curve, the crisp curve and the control points,
/// at pixels `curve` (one per sample of `ctx.curve`) and `ctrl`.
fn plane_data(svg: &mut Painter, ctx: &Ctx, curve: &[(f64, f64)], ctrl: &[(f64, f64)]) {
    let th = &ctx.theme;
    let degs: Vec<[f64; 3]> = ctx.curve.iter().map(|p| p.deg).collect();
    draw_control_polygon(svg, th, ctrl);
    draw_bands(svg, th, curve, &degs);
    draw_crisp_and_controls(svg, th, curve, ctrl);
}

/// What names must keep clear of: the lanes along the curve and the control polygon.
fn plane_obstacles(th: &Theme, curve: &[(f64, f64)], ctrl: &[(f64, f64)]) -> Vec<Obstacle> {
    let (width, pitch) = lanes(th);
    let mut o = obstacles_of(curve, pitch + width / 2.0);
    o.extend(obstacles_of(ctrl, 0.0));
    o
}

// ---------------------------------------------------------------------------------------------
// Surfaces: heat maps over the parameter domain

/// The legend of the heat maps, with an entry for the knot lines when there are any.
fn map_legend(th: &Theme, knots: bool) -> Legend {
    let mut entries = Vec::new();
    if knots {
        entries.push(Entry {
            swatch: Swatch::LineOnPatch {
                patch: theme::colormap(0.3),
                line: theme::KNOT,
                width: th.thin_w(),
                dash: th.dash(),
            },
            label: "knot lines".to_string(),
        });
    }
    Legend {
        entries,
        notes: Vec::new(),
        colorbar: Some(ColorBar {
            label: "degree".to_string(),
            length: 0.62,
            range: (0.0, 1.0),
        }),
    }
}

/// The axes of a heat map over the parameter domain of `mesh`, fitted into `area`.
fn domain_axes(th: &Theme, mesh: &Mesh, area: Rect) -> Axes2 {
    let n = mesh.n;
    Axes2::exact(
        area,
        (mesh.u[0], mesh.u[n - 1]),
        (mesh.v[0], mesh.v[n - 1]),
        th,
        ("u", "v"),
    )
}

/// One heat map: the degree `kind` over (u, v), cells of the sample grid coloured by the
/// mean of their corners.
fn heat_map(svg: &mut Painter, th: &Theme, mesh: &Mesh, axes: &Axes2, kind: DegreeKind) {
    let n = mesh.n;
    axes.draw(svg, th);
    let f = axes.frame;
    svg.begin_clip(&format!("heat-clip-{}", kind.name()), f.x, f.y, f.w, f.h);
    svg.begin_group(&format!("heat-map {}", kind.name()));
    // Cells reach a pixel into their neighbours, so that every pixel along a boundary is
    // covered in full by one of them and no lighter seam shows.
    let bleed = 1.0;
    for a in 0..n.saturating_sub(1) {
        for b in 0..n.saturating_sub(1) {
            let v = mesh.cell_value(a, b, kind.into());
            let (x0, y1) = axes.map(mesh.u[a], mesh.v[b]);
            let (x1, y0) = axes.map(mesh.u[a + 1], mesh.v[b + 1]);
            svg.rect(
                x0 - bleed,
                y0 - bleed,
                x1 - x0 + 2.0 * bleed,
                y1 - y0 + 2.0 * bleed,
                &Style::fill(theme::colormap(v)),
            );
        }
    }
    svg.end_group();
    let knot = Style::stroke(theme::KNOT, th.thin_w())
        .with_dash(th.dash().0, th.dash().1)
        .with_class("knot-line");
    let (u0, u1, v0, v1) = (mesh.u[0], mesh.u[n - 1], mesh.v[0], mesh.v[n - 1]);
    for &u in &mesh.knots[0] {
        svg.line(axes.map(u, v0), axes.map(u, v1), &knot);
    }
    for &v in &mesh.knots[1] {
        svg.line(axes.map(u0, v), axes.map(u1, v), &knot);
    }
    svg.end_group();
    axes.draw_frame(svg, th);
}
