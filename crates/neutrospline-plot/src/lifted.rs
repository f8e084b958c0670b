//! 2-D models seen in 3-D: a quantity (a degree, or the score) becomes the height above the
//! x-y plane, as in the paper's figures 2-5. Each space curve `(x(t), y(t), q(t))` is drawn
//! with its lifted control polygon (the control points' values of the quantity) above the
//! crisp curve and control polygon on the q = 0 floor, with drop lines from the control
//! points (the single-quantity views and `all`).

use crate::axes3::{box_lengths, Axes3};
use crate::callout::obstacles_of;
use crate::ctx::Ctx;
use crate::curve3d::drop_line;
use crate::drawing::Drawing;
use crate::layout::{Entry, Legend, LegendPlace};
use crate::point::Pt;
use crate::quantity::Quantity;
use crate::scene::{flat, Scene, Shape, CHUNK, DATA, FLOOR};
use crate::style::Style;
use crate::theme::{self, marker_style, Marker};
use crate::ticks::{padded, ticks_inside, ticks_loose};

/// How the lifted curves of a view look.
pub(crate) struct Look {
    /// The name of the vertical axis.
    pub axis: &'static str,
    /// Whether a translucent curtain hangs from each lifted curve down to the floor.
    pub curtain: bool,
    /// The width of the lifted control polygons.
    pub polygon_w: f64,
    /// The marker of the lifted control points of a quantity.
    pub marker: fn(Quantity) -> Marker,
}

/// Paper Fig. 2-5: the space curves (x, y, q) of the quantities `kinds` above the crisp
/// curve, with the legend `entries` (the view's curves and control polygons; the crisp curve
/// and control polygon are added after them) and `notes`.
pub(crate) fn figure(
    ctx: &Ctx,
    kinds: &[Quantity],
    mut entries: Vec<Entry>,
    notes: Vec<String>,
    look: &Look,
) -> Drawing {
    let th = &ctx.theme;
    let floor = kinds.first().map_or("degree", |q| q.noun());
    entries.push(Entry::line(
        theme::CRISP,
        th.crisp_w(),
        None,
        &format!("crisp curve ({floor} 0)"),
    ));
    entries.push(Entry::line(
        theme::SHADOW,
        th.thin_w(),
        Some(th.dash()),
        "crisp control polygon",
    ));
    let legend = Legend {
        entries,
        notes,
        colorbar: None,
    };
    let frame = ctx.frame(legend, LegendPlace::Corner);
    let avoid = frame.legend_rect(th);
    let (x0, x1) = padded(ctx.extent(0).0, ctx.extent(0).1, 0.03);
    let (y0, y1) = padded(ctx.extent(1).0, ctx.extent(1).1, 0.03);
    let xt = ticks_loose(x0, x1, 5);
    let yt = ticks_loose(y0, y1, 5);
    let zt = ticks_inside(0.0, 1.0, 5);
    let len = box_lengths([&xt, &yt], 0.62);
    let axes = Axes3::new(
        frame.plot,
        [xt, yt, zt],
        len,
        ["x", "y", look.axis],
        ctx.cam(),
        th,
        avoid,
    );
    let mut svg = ctx.svg();
    axes.draw(&mut svg, th);
    let mut scene = Scene::default();
    let mut obstacles = Vec::new();
    let s3 = |p: &Pt, z: f64| axes.screen([p.pos[0], p.pos[1], z]);
    // Crisp control polygon and crisp curve on the degree-0 plane.
    let fl_ctrl: Vec<(f64, f64, f64)> = ctx.controls.iter().map(|p| s3(p, 0.0)).collect();
    scene.polyline(
        FLOOR,
        &fl_ctrl,
        1,
        &Style::stroke(theme::SHADOW, th.thin_w())
            .with_dash(th.dash().0, th.dash().1)
            .with_class("control-polygon crisp"),
    );
    for p in &fl_ctrl {
        scene.push(
            FLOOR,
            p.2,
            Shape::Marker(
                Marker::Circle,
                (p.0, p.1),
                0.55 * th.marker_r(),
                Style::fill(theme::SHADOW),
            ),
        );
    }
    let fl_curve: Vec<(f64, f64, f64)> = ctx.curve.iter().map(|p| s3(p, 0.0)).collect();
    scene.polyline(
        FLOOR,
        &fl_curve,
        usize::MAX,
        &Style::stroke(theme::CRISP, th.crisp_w()).with_class("curve crisp"),
    );
    obstacles.extend(obstacles_of(&flat(&fl_curve), th.crisp_w()));
    // Drop lines from each lifted control point (the highest of the kinds) to the floor.
    let tops: Vec<(f64, f64, f64)> = ctx
        .controls
        .iter()
        .map(|p| {
            let top = kinds
                .iter()
                .map(|q| theme::unit(q.at(p)))
                .fold(0.0, f64::max);
            s3(p, top)
        })
        .collect();
    for (a, b) in tops.iter().zip(&fl_ctrl) {
        obstacles.extend(drop_line(&mut scene, th, *a, *b));
    }
    for &kind in kinds {
        let c = kind.color();
        let lifted: Vec<(f64, f64, f64)> = ctx
            .curve
            .iter()
            .map(|p| s3(p, theme::unit(kind.at(p))))
            .collect();
        if look.curtain {
            // A translucent curtain between the space curve and its shadow.
            let mut i = 0;
            while i + 1 < lifted.len() {
                let j = (i + CHUNK).min(lifted.len() - 1);
                let mut poly: Vec<(f64, f64)> = lifted[i..=j].iter().map(|p| (p.0, p.1)).collect();
                poly.extend(fl_curve[i..=j].iter().rev().map(|p| (p.0, p.1)));
                let depth = (lifted[i].2 + lifted[j].2 + fl_curve[i].2 + fl_curve[j].2) / 4.0;
                scene.push(
                    DATA,
                    depth,
                    Shape::Polygon(
                        poly,
                        Style::fill(c).with_fill_opacity(0.13).with_class("curtain"),
                    ),
                );
                i = j;
            }
        }
        let lifted_ctrl: Vec<(f64, f64, f64)> = ctx
            .controls
            .iter()
            .map(|p| s3(p, theme::unit(kind.at(p))))
            .collect();
        scene.polyline(
            DATA,
            &lifted_ctrl,
            1,
            &Style::stroke(c, look.polygon_w)
                .with_dash(th.dash().0, th.dash().1)
                .with_class(&format!("control-polygon {}", kind.name())),
        );
        scene.polyline(
            DATA,
            &lifted,
            CHUNK,
            &Style::stroke(c, th.curve_w()).with_class(&format!("curve {}", kind.name())),
        );
        obstacles.extend(obstacles_of(&flat(&lifted), th.curve_w() / 2.0));
        obstacles.extend(obstacles_of(&flat(&lifted_ctrl), 0.0));
        let shape = (look.marker)(kind);
        for p in &lifted_ctrl {
            scene.push(
                DATA,
                p.2 + 1e-3,
                Shape::Marker(
                    shape,
                    (p.0, p.1),
                    th.marker_r(),
                    marker_style(th, c).with_class("control-point"),
                ),
            );
        }
    }
    scene.draw(&mut svg);
    ctx.names(&mut svg, &flat(&tops), obstacles, frame.plot, avoid);
    frame.draw(&mut svg, th);
    svg.finish()
}
