//! The pieces of a 3-D curve in its box: the shadow on the floor, drop lines, the control
//! polygon and points, the curve coloured by one quantity (a degree or the score), and the
//! panel that combines them (the single-quantity views and each panel of `all`).

use crate::axes3::Axes3;
use crate::callout::{obstacles_of, Obstacle};
use crate::ctx::Ctx;
use crate::drawing::Painter;
use crate::layout::{ColorBar, Entry, Legend, Rect};
use crate::quantity::Quantity;
use crate::scene::{flat, Scene, Shape, CHUNK, DATA, FLOOR, OVER};
use crate::style::{Color, Style};
use crate::theme::{self, marker_style, Marker, Theme};

/// The 3-D box of a curve fitted into `area` clear of `avoid` and drawn into `svg`, and a
/// scene that holds the curve's shadow on the floor of the box, for the rest of the drawing.
pub(crate) fn shadowed_box(
    svg: &mut Painter,
    ctx: &Ctx,
    area: Rect,
    avoid: Option<Rect>,
) -> (Axes3, Scene) {
    let axes = ctx.draw_box(svg, area, avoid);
    let mut scene = Scene::default();
    add_shadow(&mut scene, ctx, &axes);
    (axes, scene)
}

/// The model projected onto the floor of the box, as its shadow.
fn add_shadow(scene: &mut Scene, ctx: &Ctx, axes: &Axes3) {
    let th = &ctx.theme;
    let floor = axes.floor();
    let shadow: Vec<(f64, f64, f64)> = ctx
        .curve
        .iter()
        .map(|p| axes.screen([p.pos[0], p.pos[1], floor]))
        .collect();
    scene.polyline(
        FLOOR,
        &shadow,
        usize::MAX,
        &Style::stroke(theme::SHADOW, th.crisp_w()).with_class("curve shadow"),
    );
}

/// Dotted lines from the control points down to the floor; returns them as obstacles.
pub(crate) fn drop_lines(scene: &mut Scene, ctx: &Ctx, axes: &Axes3) -> Vec<Obstacle> {
    let th = &ctx.theme;
    let floor = axes.floor();
    let mut obstacles = Vec::new();
    for p in ctx.controls {
        let a = axes.screen(p.pos);
        let b = axes.screen([p.pos[0], p.pos[1], floor]);
        obstacles.extend(drop_line(scene, th, a, b));
        scene.push(
            FLOOR,
            b.2,
            Shape::Marker(
                Marker::Circle,
                (b.0, b.1),
                0.5 * th.marker_r(),
                Style::fill(theme::SHADOW),
            ),
        );
    }
    obstacles
}

/// A dotted drop line from `a` down to `b` (pixels and depth); returns it as obstacles.
pub(crate) fn drop_line(
    scene: &mut Scene,
    th: &Theme,
    a: (f64, f64, f64),
    b: (f64, f64, f64),
) -> Vec<Obstacle> {
    scene.push(
        DATA,
        a.2.min(b.2),
        Shape::Polyline(
            vec![(a.0, a.1), (b.0, b.1)],
            Style::stroke(theme::SHADOW, th.thin_w()).with_dash(th.dot().0, th.dot().1),
        ),
    );
    obstacles_of(&[(a.0, a.1), (b.0, b.1)], 0.0)
}

/// The dashed control polygon in `color`; returns the control points on screen (pixels and
/// depth).
pub(crate) fn control_polygon_3d(
    scene: &mut Scene,
    ctx: &Ctx,
    axes: &Axes3,
    color: Color,
) -> Vec<(f64, f64, f64)> {
    let th = &ctx.theme;
    let ctrl: Vec<(f64, f64, f64)> = ctx.controls.iter().map(|p| axes.screen(p.pos)).collect();
    scene.polyline(
        DATA,
        &ctrl,
        1,
        &Style::stroke(color, th.polygon_w())
            .with_dash(th.dash().0, th.dash().1)
            .with_class("control-polygon"),
    );
    ctrl
}

/// A 3-D curve coloured by one quantity: a dark casing under coloured segments.
fn coloured_curve(scene: &mut Scene, ctx: &Ctx, axes: &Axes3, q: Quantity) -> Vec<(f64, f64)> {
    let th = &ctx.theme;
    let pts: Vec<(f64, f64, f64)> = ctx.curve.iter().map(|p| axes.screen(p.pos)).collect();
    scene.polyline(
        DATA,
        &pts,
        CHUNK,
        &Style::stroke(theme::CRISP, th.curve_w() + 3.0 * th.s).with_class("curve casing"),
    );
    let class = format!("curve {}", q.name());
    if pts.len() == 1 {
        let p = pts[0];
        let c = q.colour_of(q.at(&ctx.curve[0]));
        scene.push(
            OVER,
            p.2,
            Shape::Polyline(
                vec![(p.0, p.1)],
                Style::stroke(c, th.curve_w()).with_class(&class),
            ),
        );
    }
    for k in 0..pts.len().saturating_sub(1) {
        let v = (q.at(&ctx.curve[k]) + q.at(&ctx.curve[k + 1])) / 2.0;
        let (a, b) = (pts[k], pts[k + 1]);
        scene.push(
            OVER,
            (a.2 + b.2) / 2.0,
            Shape::Polyline(
                vec![(a.0, a.1), (b.0, b.1)],
                Style::stroke(q.colour_of(v), th.curve_w()).with_class(&class),
            ),
        );
    }
    flat(&pts)
}

/// The control points as markers coloured by the quantity `q`.
fn colour_markers(scene: &mut Scene, ctx: &Ctx, ctrl: &[(f64, f64, f64)], q: Quantity) {
    let th = &ctx.theme;
    for (p, c) in ctrl.iter().zip(ctx.controls) {
        scene.push(
            OVER,
            p.2 + 1e-3,
            Shape::Marker(
                Marker::Circle,
                (p.0, p.1),
                th.marker_r(),
                marker_style(th, q.colour_of(q.at(c))).with_class("control-point"),
            ),
        );
    }
}

/// The legend of a 3-D curve coloured by a quantity: control polygon, shadow, and the colour
/// bar labelled `bar`; the note says the colour is the `noun` ("degree" or "score") and adds
/// `notes`.
pub(crate) fn coloured_legend(th: &Theme, bar: &str, noun: &str, notes: Vec<String>) -> Legend {
    let mut all_notes = vec![format!("Curve and points coloured by the {noun}.")];
    all_notes.extend(notes);
    Legend {
        entries: vec![
            Entry::polygon(
                th,
                theme::CONSTRUCTION,
                Marker::Circle,
                theme::colormap(0.5),
                "control polygon",
            ),
            Entry::line(theme::SHADOW, th.crisp_w(), None, "shadow on the floor"),
        ],
        notes: all_notes,
        colorbar: Some(ColorBar {
            label: bar.to_string(),
            length: 0.62,
            range: (0.0, 1.0),
        }),
    }
}

/// One box of a 3-D model coloured by `q`, drawn into `svg`.
pub(crate) fn coloured_panel(
    svg: &mut Painter,
    ctx: &Ctx,
    area: Rect,
    q: Quantity,
    avoid: Option<Rect>,
) {
    let th = &ctx.theme;
    let (axes, mut scene) = shadowed_box(svg, ctx, area, avoid);
    let mut obstacles = drop_lines(&mut scene, ctx, &axes);
    let ctrl = control_polygon_3d(&mut scene, ctx, &axes, theme::CONSTRUCTION);
    let curve = coloured_curve(&mut scene, ctx, &axes, q);
    colour_markers(&mut scene, ctx, &ctrl, q);
    scene.draw(svg);
    obstacles.extend(obstacles_of(&curve, th.curve_w()));
    obstacles.extend(obstacles_of(&flat(&ctrl), 0.0));
    ctx.names(svg, &flat(&ctrl), obstacles, area, avoid);
}
