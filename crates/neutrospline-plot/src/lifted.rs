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
pub(crate) struct Look<'a> {
    /// The name of the vertical axis.
    pub axis: &'a str,
    /// Whether a translucent curtain hangs from each lifted curve down to the floor.
    pub curtain: bool,
    /// The width of the lifted control polygons.
    pub polygon_w: f64,
    /// The marker of the lifted control points of a quantity.
    pub marker: fn(Quantity) -> Marker,
    /// Whether the control polygon is lifted to the control points' values: only where the
    /// quantity is affine in the blended values, so that the lifted curve is the curve of the
    /// lifted control polygon (a non-affine family score, such as `T^2 - F^2`, is not; its
    /// curve is sampled, and no lifted polygon is drawn).
    pub lift_controls: bool,
}

/// The crisp control polygon (dashed, with small markers) and the crisp curve on the
/// quantity-0 floor, `s3` mapping a point at a height to the screen; the curve is added to
/// the `obstacles` of the labels. Returns the screen points of the floor's control polygon
/// and curve.
#[allow(clippy::type_complexity)]
fn crisp_floor(
    scene: &mut Scene,
    obstacles: &mut Vec<crate::callout::Obstacle>,
    ctx: &Ctx,
    s3: &dyn Fn(&Pt, f64) -> (f64, f64, f64),
) -> (Vec<(f64, f64, f64)>, Vec<(f64, f64, f64)>) {
    let th = &ctx.theme;
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
    (fl_ctrl, fl_curve)
}

/// Paper Fig. 2-5: the space curves (x, y, q) of the quantities `kinds` above the crisp
/// curve, with the legend `entries` (the view's curves and control polygons; the crisp curve
/// and control polygon are added after them) and `notes`. The vertical axis spans the first
/// quantity's range (\[0, 1\], or \[-1, 1\] for a signed score, the crisp curve then in the
/// middle at 0).
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
    let (z0, z1) = kinds.first().map_or((0.0, 1.0), |q| q.range());
    let signed = z0 < 0.0;
    let zt = if signed {
        ticks_inside(z0, z1, 4)
    } else {
        ticks_inside(z0, z1, 5)
    };
    let len = box_lengths([&xt, &yt], if signed { 0.8 } else { 0.62 });
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
    let (fl_ctrl, fl_curve) = crisp_floor(&mut scene, &mut obstacles, ctx, &s3);
    // Drop lines from each lifted control point (the farthest from 0 of the kinds) to the
    // floor; the names sit at the crisp control points when the polygon is not lifted.
    let tops: Vec<(f64, f64, f64)> = ctx
        .controls
        .iter()
        .map(|p| {
            let top =
                kinds
                    .iter()
                    .map(|q| q.height(p))
                    .fold(0.0, |a: f64, b| if b.abs() > a.abs() { b } else { a });
            s3(p, if look.lift_controls { top } else { 0.0 })
        })
        .collect();
    if look.lift_controls {
        for (a, b) in tops.iter().zip(&fl_ctrl) {
            obstacles.extend(drop_line(&mut scene, th, *a, *b));
        }
    }
    for &kind in kinds {
        let c = kind.color();
        let lifted: Vec<(f64, f64, f64)> =
            ctx.curve.iter().map(|p| s3(p, kind.height(p))).collect();
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
        scene.polyline(
            DATA,
            &lifted,
            CHUNK,
            &Style::stroke(c, th.curve_w()).with_class(&format!("curve {}", kind.name())),
        );
        obstacles.extend(obstacles_of(&flat(&lifted), th.curve_w() / 2.0));
        if !look.lift_controls {
            continue;
        }
        let lifted_ctrl: Vec<(f64, f64, f64)> =
            ctx.controls.iter().map(|p| s3(p, kind.height(p))).collect();
        scene.polyline(
            DATA,
            &lifted_ctrl,
            1,
            &Style::stroke(c, look.polygon_w)
                .with_dash(th.dash().0, th.dash().1)
                .with_class(&format!("control-polygon {}", kind.name())),
        );
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

/// A translucent fill between two lifted polylines (screen points with depth, joined at equal
/// indices): the edges, the fill opacity and the class.
type Fill<'a> = (
    &'a [(f64, f64, f64)],
    &'a [(f64, f64, f64)],
    f64,
    &'static str,
);

/// How the two lanes of a wide family are drawn by [`wide_figure`].
pub(crate) struct WideLook {
    /// The name of the vertical axis.
    pub axis: String,
    /// Whether the second lane is the negated negative degrees of a bipolar family (drawn
    /// below the crisp plane, z in \[-1, 0\]); else the upper degrees of an interval-valued
    /// family (the band between the lower and upper curves is filled).
    pub bipolar: bool,
    /// Whether one degree is drawn (heavier fills: the band, or the curtains of a bipolar
    /// degree) rather than all of them.
    pub single: bool,
    /// The marker of the lifted control points of a degree.
    pub marker: fn(Quantity) -> Marker,
}

/// The height of degree `q` of a sample of lane `lane` of a wide model: the value in its
/// slot, negated for the second lane of a bipolar family (whose slots hold the negative
/// degrees negated, docs/model.md "Lanes"), so that the negative degrees lie below the crisp
/// plane.
pub(crate) fn lane_height(q: Quantity, p: &Pt, lane: usize, bipolar: bool) -> f64 {
    let v = theme::unit(q.at(p));
    if lane == 1 && bipolar {
        -v
    } else {
        v
    }
}

/// The lifted curves of a wide (two-lane) 2-D model, one pair per degree of `kinds`: for an
/// interval-valued family, the lower curve `(x, y, lower(t))` dashed and the upper curve
/// `(x, y, upper(t))` solid with a translucent ruled strip between them (the band: quads
/// joining the two curves at equal parameters); for the bipolar family, the positive degree
/// solid above the crisp plane and the negative degree `(x, y, -|negative(t)|)` dashed below
/// it, each with a curtain to the plane when one degree is drawn, on a vertical axis over
/// \[-1, 1\]. Each lane's lifted control polygon and points; the crisp curve and control
/// polygon on the z = 0 plane; drop lines through each control point spanning its values.
/// `second` is the second lane's samples and control points, at the parameters and positions
/// of `ctx.curve` and `ctx.controls`; `entries` are the view's legend entries (the crisp
/// curve and control polygon are added after them).
pub(crate) fn wide_figure(
    ctx: &Ctx,
    second: (&[Pt], &[Pt]),
    kinds: &[Quantity],
    mut entries: Vec<Entry>,
    look: &WideLook,
) -> Drawing {
    let th = &ctx.theme;
    let (second_curve, second_controls) = second;
    entries.push(Entry::line(
        theme::CRISP,
        th.crisp_w(),
        None,
        &format!(
            "crisp curve ({} 0)",
            if look.axis == "membership" {
                "membership"
            } else {
                "degree"
            }
        ),
    ));
    entries.push(Entry::line(
        theme::SHADOW,
        th.thin_w(),
        Some(th.dash()),
        "crisp control polygon",
    ));
    let legend = Legend {
        entries,
        notes: Vec::new(),
        colorbar: None,
    };
    let frame = ctx.frame(legend, LegendPlace::Corner);
    let avoid = frame.legend_rect(th);
    let (x0, x1) = padded(ctx.extent(0).0, ctx.extent(0).1, 0.03);
    let (y0, y1) = padded(ctx.extent(1).0, ctx.extent(1).1, 0.03);
    let xt = ticks_loose(x0, x1, 5);
    let yt = ticks_loose(y0, y1, 5);
    let zt = if look.bipolar {
        ticks_inside(-1.0, 1.0, 4)
    } else {
        ticks_inside(0.0, 1.0, 5)
    };
    let len = box_lengths([&xt, &yt], if look.bipolar { 0.8 } else { 0.62 });
    let plane = [xt.lo, xt.hi, yt.lo, yt.hi];
    let axes = Axes3::new(
        frame.plot,
        [xt, yt, zt],
        len,
        ["x", "y", &look.axis],
        ctx.cam(),
        th,
        avoid,
    );
    let mut svg = ctx.svg();
    axes.draw(&mut svg, th);
    let mut scene = Scene::default();
    let mut obstacles = Vec::new();
    let s3 = |p: &Pt, z: f64| axes.screen([p.pos[0], p.pos[1], z]);
    if look.bipolar {
        // The crisp plane z = 0 across the box: positive degrees above, negative below.
        let corners = [
            [plane[0], plane[2]],
            [plane[1], plane[2]],
            [plane[1], plane[3]],
            [plane[0], plane[3]],
        ]
        .map(|[x, y]| axes.screen([x, y, 0.0]));
        let depth = corners.iter().map(|c| c.2).sum::<f64>() / 4.0;
        scene.push(
            FLOOR,
            depth,
            Shape::Polygon(
                corners.iter().map(|c| (c.0, c.1)).collect(),
                Style::stroke(theme::SHADOW, th.thin_w())
                    .with_fill(theme::SHADOW)
                    .with_fill_opacity(0.12)
                    .with_class("crisp-plane"),
            ),
        );
    }
    let (_, fl_curve) = crisp_floor(&mut scene, &mut obstacles, ctx, &s3);
    // Drop lines through each control point, from its highest value to its lowest (or to
    // the plane).
    let mut tops = Vec::with_capacity(ctx.controls.len());
    for (k, p) in ctx.controls.iter().enumerate() {
        let heights: Vec<f64> = kinds
            .iter()
            .flat_map(|&q| {
                [
                    lane_height(q, p, 0, look.bipolar),
                    second_controls
                        .get(k)
                        .map_or(0.0, |s| lane_height(q, s, 1, look.bipolar)),
                ]
            })
            .collect();
        let top = heights.iter().copied().fold(0.0, f64::max);
        let bottom = heights.iter().copied().fold(0.0, f64::min);
        let (a, b) = (s3(p, top), s3(p, bottom));
        obstacles.extend(drop_line(&mut scene, th, a, b));
        tops.push(a);
    }
    let long_dash = (1.8 * th.dash().0, 1.2 * th.dash().1);
    for &kind in kinds {
        let c = kind.color();
        let light = c.mix(crate::style::Color::WHITE, 0.55);
        let lanes: [(&[Pt], &[Pt]); 2] =
            [(&ctx.curve, ctx.controls), (second_curve, second_controls)];
        let lifted: Vec<Vec<(f64, f64, f64)>> = lanes
            .iter()
            .enumerate()
            .map(|(lane, (curve, _))| {
                curve
                    .iter()
                    .map(|p| s3(p, lane_height(kind, p, lane, look.bipolar)))
                    .collect()
            })
            .collect();
        // The fills: the band between the lower and upper curves, or each bipolar curve's
        // curtain to the crisp plane.
        let fills: Vec<Fill<'_>> = if look.bipolar {
            if look.single {
                vec![
                    (&lifted[0], &fl_curve, 0.13, "curtain"),
                    (&lifted[1], &fl_curve, 0.13, "curtain"),
                ]
            } else {
                Vec::new()
            }
        } else {
            let opacity = if look.single { 0.3 } else { 0.22 };
            vec![(&lifted[0], &lifted[1], opacity, "band")]
        };
        for (edge, other, opacity, class) in fills {
            let n = edge.len().min(other.len());
            let mut i = 0;
            while i + 1 < n {
                let j = (i + CHUNK).min(n - 1);
                let mut poly: Vec<(f64, f64)> = edge[i..=j].iter().map(|p| (p.0, p.1)).collect();
                poly.extend(other[i..=j].iter().rev().map(|p| (p.0, p.1)));
                let depth = (edge[i].2 + edge[j].2 + other[i].2 + other[j].2) / 4.0;
                scene.push(
                    DATA,
                    depth,
                    Shape::Polygon(
                        poly,
                        Style::fill(c)
                            .with_fill_opacity(opacity)
                            .with_class(&format!("{class} {}", kind.name())),
                    ),
                );
                i = j;
            }
        }
        for (lane, (_, controls)) in lanes.iter().enumerate() {
            // The interval's lower lane and the bipolar negative lane are dashed.
            let dashed = (lane == 0) != look.bipolar;
            let lifted_ctrl: Vec<(f64, f64, f64)> = controls
                .iter()
                .map(|p| s3(p, lane_height(kind, p, lane, look.bipolar)))
                .collect();
            scene.polyline(
                DATA,
                &lifted_ctrl,
                1,
                &Style::stroke(c, th.thin_w())
                    .with_dash(th.dash().0, th.dash().1)
                    .with_class(&format!("control-polygon {} lane{lane}", kind.name())),
            );
            let mut style = Style::stroke(c, th.curve_w())
                .with_class(&format!("curve {} lane{lane}", kind.name()));
            // A dashed curve in one piece, so that its dashes run on (a piece per chunk would
            // restart the pattern every few samples and look solid).
            let chunk = if dashed {
                style = style.with_dash(long_dash.0, long_dash.1);
                usize::MAX
            } else {
                CHUNK
            };
            scene.polyline(DATA, &lifted[lane], chunk, &style);
            obstacles.extend(obstacles_of(&flat(&lifted[lane]), th.curve_w() / 2.0));
            obstacles.extend(obstacles_of(&flat(&lifted_ctrl), 0.0));
            let shape = (look.marker)(kind);
            let fill = if dashed { light } else { c };
            for p in &lifted_ctrl {
                scene.push(
                    DATA,
                    p.2 + 1e-3,
                    Shape::Marker(
                        shape,
                        (p.0, p.1),
                        th.marker_r(),
                        marker_style(th, fill).with_class("control-point"),
                    ),
                );
            }
        }
    }
    scene.draw(&mut svg);
    ctx.names(&mut svg, &flat(&tops), obstacles, frame.plot, avoid);
    frame.draw(&mut svg, th);
    svg.finish()
}
