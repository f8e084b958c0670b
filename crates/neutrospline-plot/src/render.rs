//! The views: from a model and options to SVG text.

use neutrospline::DegreeKind;

use crate::axes2::Axes2;
use crate::axes3::Axes3;
use crate::callout::{draw_callouts, obstacles_of, place_names, Keep, Obstacle};
use crate::camera::Camera;
use crate::error::PlotError;
use crate::layout::{text_centred, ColorBar, Entry, Frame, Legend, LegendPlace, Rect, Swatch};
use crate::model::{PlotModel, Pt};
use crate::options::PlotOptions;
use crate::panels;
use crate::scene::{Scene, Shape, DATA, FLOOR, OVER};
use crate::surface;
use crate::svg::{Color, Style, SvgWriter, TextStyle};
use crate::theme::{self, Marker, Theme};
use crate::ticks::{padded, ticks_inside, ticks_loose, Ticks};
use crate::view::View;

/// Segments per depth-sorted chunk of a curve.
const CHUNK: usize = 6;

/// Everything a view needs.
pub(crate) struct Ctx<'a> {
    pub theme: Theme,
    pub options: &'a PlotOptions,
    /// The curve samples (for a surface: the mesh points, so that extents cover them).
    pub curve: Vec<Pt>,
    pub controls: &'a [Pt],
    pub names: &'a [String],
    pub title: String,
    pub caption: String,
}

impl Ctx<'_> {
    pub(crate) fn cam(&self) -> Camera {
        Camera::new(self.options.azimuth(), self.options.elevation())
    }

    fn all_points(&self) -> impl Iterator<Item = &Pt> {
        self.curve.iter().chain(self.controls.iter())
    }

    /// (min, max) of coordinate `axis` over curve and control points.
    pub(crate) fn extent(&self, axis: usize) -> (f64, f64) {
        self.all_points()
            .map(|p| p.pos[axis])
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
                (lo.min(v), hi.max(v))
            })
    }

    pub(crate) fn frame(&self, legend: Legend, place: LegendPlace) -> Frame {
        Frame::new(
            self.options.width(),
            self.options.height(),
            &self.theme,
            &self.title,
            &self.caption,
            legend,
            place,
        )
    }

    /// Draws the names of points at pixel positions `at`, clear of `obstacles`, inside
    /// `bounds` and off `avoid`.
    fn names(
        &self,
        svg: &mut SvgWriter,
        at: &[(f64, f64)],
        obstacles: Vec<Obstacle>,
        bounds: Rect,
        avoid: Option<Rect>,
    ) {
        if self.names.is_empty() {
            return;
        }
        svg.begin_group("point-names");
        let keep = Keep {
            obstacles,
            bounds,
            avoid: avoid.into_iter().collect(),
        };
        let centres = place_names(&self.theme, at, self.names, &keep);
        for (c, name) in centres.iter().zip(self.names) {
            text_centred(svg, *c, name, &name_style(&self.theme));
        }
        svg.end_group();
    }

    pub(crate) fn svg(&self) -> SvgWriter {
        SvgWriter::new(self.options.width(), self.options.height(), &self.title)
    }
}

fn default_title(label: &str, view: View, surface: bool) -> String {
    match view {
        View::Controls if surface => "Neutrosophic control net".to_string(),
        View::Plane if surface => format!("{label}: degree maps"),
        View::Controls => "Neutrosophic control points".to_string(),
        View::Truth | View::Indeterminacy | View::Falsity => format!("{label}: {view}"),
        View::All => format!("{label}: all three degrees"),
        View::Plane => format!("{label}: degree bands"),
    }
}

/// Draws `view` of `model` as an SVG document.
///
/// The SVG is `options.width()` x `options.height()` pixels, uses only the bundled font
/// (family "DejaVu Sans", generic fallback `sans-serif`), and depends only on its inputs:
/// equal inputs give byte-identical output. Texts (title, axis names, legend, point names)
/// are real SVG `<text>` elements.
///
/// # Errors
/// Invalid options ([`PlotOptions::validate`]; for a surface
/// [`PlotOptions::validate_surface`], which caps the samples per direction), a curve or
/// surface that cannot be sampled
/// ([`PlotError::Evaluate`], [`PlotError::NotFinite`]), or coordinates whose range overflows
/// ([`PlotError::RangeTooLarge`]).
///
/// # Examples
/// ```
/// use neutrospline_plot::{render_svg, PlotModel, PlotOptions, View};
/// let model = PlotModel::from(&neutrospline::example1()).with_names(neutrospline::EXAMPLE1_NAMES)?;
/// let svg = render_svg(&model, View::Truth, &PlotOptions::default())?;
/// assert!(svg.contains("truth"));
/// # Ok::<(), neutrospline_plot::PlotError>(())
/// ```
pub fn render_svg(
    model: &PlotModel,
    view: View,
    options: &PlotOptions,
) -> Result<String, PlotError> {
    if model.is_surface() {
        options.validate_surface()?;
    } else {
        options.validate()?;
    }
    let mesh = model.mesh(options.surface_samples())?;
    let curve = match &mesh {
        Some(mesh) => mesh.points.clone(),
        None => model.curve_points(options.samples())?,
    };
    let title = match options.title() {
        Some(t) => t.to_string(),
        None => default_title(model.label(), view, model.is_surface()),
    };
    let ctx = Ctx {
        theme: Theme::new(options.width(), options.height()),
        options,
        curve,
        controls: model.controls(),
        names: model.names(),
        title,
        caption: options.caption().unwrap_or("").to_string(),
    };
    for axis in 0..model.dimension() {
        let (lo, hi) = ctx.extent(axis);
        if !(hi - lo).is_finite()
            || !(lo / 2.0 + hi / 2.0).is_finite()
            || (hi - lo) * 1.2 > f64::MAX / 4.0
        {
            return Err(PlotError::RangeTooLarge {
                axis: ["x", "y", "z"][axis],
            });
        }
    }
    if let (Some(mesh), Some(grid)) = (&mesh, model.grid()) {
        return Ok(surface::render(&ctx, mesh, grid, view));
    }
    let svg = match (model.dimension(), view) {
        (2, View::Controls) => controls_2d(&ctx),
        (2, View::Plane) => plane_2d(&ctx),
        (2, View::All) => degrees_2d(&ctx, &DegreeKind::ALL),
        (2, v) => degrees_2d(&ctx, &[v.degree().unwrap_or(DegreeKind::Truth)]),
        (_, View::Controls) => controls_3d(&ctx),
        (_, View::Plane) => plane_3d(&ctx),
        (_, View::All) => all_3d(&ctx),
        (_, v) => coloured_3d(&ctx, v.degree().unwrap_or(DegreeKind::Truth)),
    };
    Ok(svg)
}

pub(crate) fn line_entry(color: Color, width: f64, dash: Option<(f64, f64)>, label: &str) -> Entry {
    Entry {
        swatch: Swatch::Line {
            color,
            width,
            dash,
            marker: None,
        },
        label: label.to_string(),
    }
}

pub(crate) fn polygon_entry(
    theme: &Theme,
    color: Color,
    shape: Marker,
    fill: Color,
    label: &str,
) -> Entry {
    Entry {
        swatch: Swatch::Line {
            color,
            width: theme.polygon_w(),
            dash: Some(theme.dash()),
            marker: Some((shape, fill)),
        },
        label: label.to_string(),
    }
}

pub(crate) fn marker_style(theme: &Theme, fill: Color) -> Style {
    Style::stroke(theme::CRISP, theme.s * 1.8).with_fill(fill)
}

pub(crate) fn name_style(theme: &Theme) -> TextStyle {
    TextStyle::new(theme.name(), theme::INK)
        .bold()
        .halo(theme.s * 7.0)
        .with_class("point-name")
}

pub(crate) fn flat(pts: &[(f64, f64, f64)]) -> Vec<(f64, f64)> {
    pts.iter().map(|p| (p.0, p.1)).collect()
}

// ---------------------------------------------------------------------------------------------
// 2-D models

fn axes2_for(ctx: &Ctx, plot: Rect, inner: f64) -> Axes2 {
    Axes2::new(
        plot,
        ctx.extent(0),
        ctx.extent(1),
        inner,
        &ctx.theme,
        ("x", "y"),
    )
}

/// Names for callouts: the given ones, else `P0`, `P1`, ...
fn callout_names(ctx: &Ctx) -> Vec<String> {
    if ctx.names.is_empty() {
        (0..ctx.controls.len()).map(|i| format!("P{i}")).collect()
    } else {
        ctx.names.to_vec()
    }
}

fn controls_legend(th: &Theme) -> Legend {
    let mut entries = vec![
        polygon_entry(
            th,
            theme::CRISP,
            Marker::Circle,
            Color::WHITE,
            "control polygon",
        ),
        line_entry(theme::SHADOW, th.crisp_w(), None, "crisp curve"),
    ];
    for kind in DegreeKind::ALL {
        entries.push(Entry {
            swatch: Swatch::Band {
                color: theme::degree_color(kind),
            },
            label: format!("{} ({})", kind.name(), theme::degree_letter(kind)),
        });
    }
    Legend {
        entries,
        notes: vec!["Bars show each point's degrees; a full bar is 1.".to_string()],
        colorbar: None,
    }
}

/// Paper Fig. 1: control polygon and points with callouts of their degrees.
fn controls_2d(ctx: &Ctx) -> String {
    let th = &ctx.theme;
    let frame = ctx.frame(controls_legend(th), LegendPlace::Column);
    let inner = 6.0 * th.callout();
    let axes = axes2_for(ctx, frame.plot, inner);
    let mut svg = ctx.svg();
    axes.draw(&mut svg, th);
    let curve: Vec<(f64, f64)> = ctx
        .curve
        .iter()
        .map(|p| axes.map(p.pos[0], p.pos[1]))
        .collect();
    let ctrl: Vec<(f64, f64)> = ctx
        .controls
        .iter()
        .map(|p| axes.map(p.pos[0], p.pos[1]))
        .collect();
    svg.begin_clip(
        "plot-clip",
        axes.frame.x,
        axes.frame.y,
        axes.frame.w,
        axes.frame.h,
    );
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
    let mut obstacles = obstacles_of(&curve, 0.0);
    obstacles.extend(obstacles_of(&ctrl, 0.0));
    let keep = Keep {
        obstacles,
        bounds: axes.frame,
        avoid: Vec::new(),
    };
    let degs: Vec<[f64; 3]> = ctx.controls.iter().map(|p| p.deg).collect();
    draw_callouts(&mut svg, th, &ctrl, &degs, &callout_names(ctx), &keep);
    frame.draw(&mut svg, th);
    svg.finish()
}

/// Paper Fig. 2-5: space curves (x, y, degree) above the crisp curve.
fn degrees_2d(ctx: &Ctx, kinds: &[DegreeKind]) -> String {
    let th = &ctx.theme;
    let single = kinds.len() == 1;
    let mut entries = Vec::new();
    for &kind in kinds {
        let c = theme::degree_color(kind);
        let mut e = line_entry(c, th.curve_w(), None, &format!("{} curve", kind.name()));
        if !single {
            e.swatch = Swatch::Line {
                color: c,
                width: th.curve_w(),
                dash: None,
                marker: Some((theme::degree_marker(kind), c)),
            };
        }
        entries.push(e);
    }
    if single {
        let c = theme::degree_color(kinds[0]);
        entries.push(polygon_entry(th, c, Marker::Circle, c, "control polygon"));
    } else {
        entries.push(line_entry(
            theme::CONSTRUCTION,
            th.polygon_w(),
            Some(th.dash()),
            "control polygons",
        ));
    }
    entries.push(line_entry(
        theme::CRISP,
        th.crisp_w(),
        None,
        "crisp curve (degree 0)",
    ));
    entries.push(line_entry(
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
    let zt = ticks_inside(0.0, 1.0, 5);
    let len = box_lengths([&xt, &yt], 0.62);
    let zname = if single { kinds[0].name() } else { "degree" };
    let axes = Axes3::new(
        frame.plot,
        [xt, yt, zt],
        len,
        ["x", "y", zname],
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
                .map(|k| theme::unit(p.deg[k.index()]))
                .fold(0.0, f64::max);
            s3(p, top)
        })
        .collect();
    for (a, b) in tops.iter().zip(&fl_ctrl) {
        scene.push(
            DATA,
            a.2.min(b.2),
            Shape::Polyline(
                vec![(a.0, a.1), (b.0, b.1)],
                Style::stroke(theme::SHADOW, th.thin_w()).with_dash(th.dot().0, th.dot().1),
            ),
        );
        obstacles.extend(obstacles_of(&[(a.0, a.1), (b.0, b.1)], 0.0));
    }
    for &kind in kinds {
        let k = kind.index();
        let c = theme::degree_color(kind);
        let lifted: Vec<(f64, f64, f64)> = ctx
            .curve
            .iter()
            .map(|p| s3(p, theme::unit(p.deg[k])))
            .collect();
        if single {
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
            .map(|p| s3(p, theme::unit(p.deg[k])))
            .collect();
        let poly_w = if single { th.polygon_w() } else { th.thin_w() };
        scene.polyline(
            DATA,
            &lifted_ctrl,
            1,
            &Style::stroke(c, poly_w)
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
        let shape = if single {
            Marker::Circle
        } else {
            theme::degree_marker(kind)
        };
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

/// Relative box edge lengths: the longer horizontal axis is 1, the other follows the data
/// (at least 0.45), and the vertical axis is `z`.
fn box_lengths(t: [&Ticks; 2], z: f64) -> [f64; 3] {
    let (xr, yr) = (t[0].hi - t[0].lo, t[1].hi - t[1].lo);
    let m = xr.max(yr);
    [(xr / m).max(0.45), (yr / m).max(0.45), z]
}

/// Relative box edge lengths following the data (each at least 0.45 of the longest).
fn box_lengths3(t: [&Ticks; 3]) -> [f64; 3] {
    let r = t.map(|t| t.hi - t.lo);
    let m = r[0].max(r[1]).max(r[2]);
    r.map(|v| (v / m).max(0.45))
}

/// Lane geometry of the plane view: (band full width, lane pitch) in pixels.
fn lanes(th: &Theme) -> (f64, f64) {
    (24.0 * th.s, 29.0 * th.s)
}

/// Offset bands along a pixel polyline: lane `j` centred `pitch * (1 - j)` pixels to the left
/// of the direction of travel, of full width `width`; band width = degree * width.
fn draw_bands(svg: &mut SvgWriter, th: &Theme, pts: &[(f64, f64)], degs: &[[f64; 3]]) {
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

fn plane_legend(th: &Theme) -> Legend {
    let mut entries = Vec::new();
    for kind in DegreeKind::ALL {
        entries.push(Entry {
            swatch: Swatch::Band {
                color: theme::degree_color(kind),
            },
            label: kind.name().to_string(),
        });
    }
    entries.push(line_entry(theme::CRISP, th.thin_w(), None, "crisp curve"));
    entries.push(polygon_entry(
        th,
        theme::CONSTRUCTION,
        Marker::Circle,
        Color::WHITE,
        "control polygon",
    ));
    Legend {
        entries,
        notes: vec![
            "Band width shows the degree; a full grey lane is 1. Seen along the curve, truth runs on its left, falsity on its right.".to_string(),
        ],
        colorbar: None,
    }
}

fn plane_data(
    svg: &mut SvgWriter,
    th: &Theme,
    curve: &[(f64, f64)],
    ctrl: &[(f64, f64)],
    degs: &[[f64; 3]],
) {
    svg.polyline(
        ctrl,
        &Style::stroke(theme::CONSTRUCTION, th.polygon_w())
            .with_dash(th.dash().0, th.dash().1)
            .with_class("control-polygon"),
    );
    draw_bands(svg, th, curve, degs);
    svg.polyline(
        curve,
        &Style::stroke(theme::CRISP, th.thin_w()).with_class("curve crisp"),
    );
    for p in ctrl {
        svg.circle(
            *p,
            th.marker_r(),
            &marker_style(th, Color::WHITE).with_class("control-point"),
        );
    }
}

fn plane_obstacles(th: &Theme, curve: &[(f64, f64)], ctrl: &[(f64, f64)]) -> Vec<Obstacle> {
    let (width, pitch) = lanes(th);
    let mut o = obstacles_of(curve, pitch + width / 2.0);
    o.extend(obstacles_of(ctrl, 0.0));
    o
}

/// A flat view: bands along the crisp curve.
fn plane_2d(ctx: &Ctx) -> String {
    let th = &ctx.theme;
    let frame = ctx.frame(plane_legend(th), LegendPlace::Column);
    let axes = axes2_for(ctx, frame.plot, 75.0 * th.s);
    let mut svg = ctx.svg();
    axes.draw(&mut svg, th);
    let curve: Vec<(f64, f64)> = ctx
        .curve
        .iter()
        .map(|p| axes.map(p.pos[0], p.pos[1]))
        .collect();
    let ctrl: Vec<(f64, f64)> = ctx
        .controls
        .iter()
        .map(|p| axes.map(p.pos[0], p.pos[1]))
        .collect();
    let degs: Vec<[f64; 3]> = ctx.curve.iter().map(|p| p.deg).collect();
    svg.begin_clip(
        "plot-clip",
        axes.frame.x,
        axes.frame.y,
        axes.frame.w,
        axes.frame.h,
    );
    plane_data(&mut svg, th, &curve, &ctrl, &degs);
    svg.end_group();
    ctx.names(
        &mut svg,
        &ctrl,
        plane_obstacles(th, &curve, &ctrl),
        axes.frame,
        None,
    );
    frame.draw(&mut svg, th);
    svg.finish()
}

// ---------------------------------------------------------------------------------------------
// 3-D models

pub(crate) fn axes3_for(ctx: &Ctx, area: Rect, target: usize, avoid: Option<Rect>) -> Axes3 {
    let t: [Ticks; 3] = [0, 1, 2].map(|a| {
        let (lo, hi) = ctx.extent(a);
        let (lo, hi) = padded(lo, hi, 0.03);
        ticks_loose(lo, hi, target)
    });
    let len = box_lengths3([&t[0], &t[1], &t[2]]);
    Axes3::new(area, t, len, ["x", "y", "z"], ctx.cam(), &ctx.theme, avoid)
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
fn drop_lines(scene: &mut Scene, ctx: &Ctx, axes: &Axes3) -> Vec<Obstacle> {
    let th = &ctx.theme;
    let floor = axes.floor();
    let mut obstacles = Vec::new();
    for p in ctx.controls {
        let a = axes.screen(p.pos);
        let b = axes.screen([p.pos[0], p.pos[1], floor]);
        scene.push(
            DATA,
            a.2.min(b.2),
            Shape::Polyline(
                vec![(a.0, a.1), (b.0, b.1)],
                Style::stroke(theme::SHADOW, th.thin_w()).with_dash(th.dot().0, th.dot().1),
            ),
        );
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
        obstacles.extend(obstacles_of(&[(a.0, a.1), (b.0, b.1)], 0.0));
    }
    obstacles
}

fn control_polygon_3d(
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

/// A 3-D curve coloured by one degree: a dark casing under coloured segments.
fn coloured_curve(scene: &mut Scene, ctx: &Ctx, axes: &Axes3, kind: DegreeKind) -> Vec<(f64, f64)> {
    let th = &ctx.theme;
    let pts: Vec<(f64, f64, f64)> = ctx.curve.iter().map(|p| axes.screen(p.pos)).collect();
    scene.polyline(
        DATA,
        &pts,
        CHUNK,
        &Style::stroke(theme::CRISP, th.curve_w() + 3.0 * th.s).with_class("curve casing"),
    );
    let class = format!("curve {}", kind.name());
    if pts.len() == 1 {
        let p = pts[0];
        let c = theme::colormap(ctx.curve[0].deg[kind.index()]);
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
        let v = (ctx.curve[k].deg[kind.index()] + ctx.curve[k + 1].deg[kind.index()]) / 2.0;
        let (a, b) = (pts[k], pts[k + 1]);
        scene.push(
            OVER,
            (a.2 + b.2) / 2.0,
            Shape::Polyline(
                vec![(a.0, a.1), (b.0, b.1)],
                Style::stroke(theme::colormap(v), th.curve_w()).with_class(&class),
            ),
        );
    }
    flat(&pts)
}

pub(crate) fn colour_markers(
    scene: &mut Scene,
    ctx: &Ctx,
    ctrl: &[(f64, f64, f64)],
    kind: DegreeKind,
) {
    let th = &ctx.theme;
    for (p, c) in ctrl.iter().zip(ctx.controls) {
        scene.push(
            OVER,
            p.2 + 1e-3,
            Shape::Marker(
                Marker::Circle,
                (p.0, p.1),
                th.marker_r(),
                marker_style(th, theme::colormap(c.deg[kind.index()])).with_class("control-point"),
            ),
        );
    }
}

fn coloured_legend(th: &Theme, bar: &str) -> Legend {
    Legend {
        entries: vec![
            polygon_entry(
                th,
                theme::CONSTRUCTION,
                Marker::Circle,
                theme::colormap(0.5),
                "control polygon",
            ),
            line_entry(theme::SHADOW, th.crisp_w(), None, "shadow on the floor"),
        ],
        notes: vec!["Curve and points coloured by the degree.".to_string()],
        colorbar: Some(ColorBar {
            label: bar.to_string(),
            length: 0.62,
        }),
    }
}

/// One box of a 3-D model coloured by `kind`, drawn into `svg`.
fn coloured_panel(
    svg: &mut SvgWriter,
    ctx: &Ctx,
    area: Rect,
    kind: DegreeKind,
    avoid: Option<Rect>,
) {
    let th = &ctx.theme;
    let axes = axes3_for(ctx, area, 5, avoid);
    axes.draw(svg, th);
    let mut scene = Scene::default();
    add_shadow(&mut scene, ctx, &axes);
    let mut obstacles = drop_lines(&mut scene, ctx, &axes);
    let ctrl = control_polygon_3d(&mut scene, ctx, &axes, theme::CONSTRUCTION);
    let curve = coloured_curve(&mut scene, ctx, &axes, kind);
    colour_markers(&mut scene, ctx, &ctrl, kind);
    scene.draw(svg);
    obstacles.extend(obstacles_of(&curve, th.curve_w()));
    obstacles.extend(obstacles_of(&flat(&ctrl), 0.0));
    ctx.names(svg, &flat(&ctrl), obstacles, area, avoid);
}

/// A 3-D curve coloured by one degree.
fn coloured_3d(ctx: &Ctx, kind: DegreeKind) -> String {
    let th = &ctx.theme;
    let frame = ctx.frame(coloured_legend(th, kind.name()), LegendPlace::Corner);
    let mut svg = ctx.svg();
    coloured_panel(&mut svg, ctx, frame.plot, kind, frame.legend_rect(th));
    frame.draw(&mut svg, th);
    svg.finish()
}

/// Three panels (truth, indeterminacy, falsity) and the shared legend, arranged by
/// [`panels::choose`].
fn all_3d(ctx: &Ctx) -> String {
    let th = &ctx.theme;
    let mut legend = coloured_legend(th, "degree");
    legend.notes.clear();
    let grid = panels::choose(
        th,
        &legend,
        &|legend, place| ctx.frame(legend, place),
        &|area| {
            let axes = axes3_for(ctx, area, 5, None);
            (axes.scale(), axes.bounds().y)
        },
    );
    let mut svg = ctx.svg();
    for (j, kind) in DegreeKind::ALL.iter().enumerate() {
        panel_title(&mut svg, th, grid.title_centre(j, th), *kind);
        coloured_panel(&mut svg, ctx, grid.area(j, th), *kind, None);
    }
    grid.frame.draw(&mut svg, th);
    svg.finish()
}

/// The title of one panel of an `all` figure: the degree's name in its colour.
pub(crate) fn panel_title(svg: &mut SvgWriter, th: &Theme, at: (f64, f64), kind: DegreeKind) {
    text_centred(
        svg,
        at,
        kind.name(),
        &TextStyle::new(th.subtitle(), theme::degree_color(kind))
            .bold()
            .with_class("panel-title"),
    );
}

/// Control points of a 3-D model with callouts.
fn controls_3d(ctx: &Ctx) -> String {
    let th = &ctx.theme;
    let frame = ctx.frame(controls_legend(th), LegendPlace::Corner);
    let avoid = frame.legend_rect(th);
    let axes = axes3_for(ctx, frame.plot, 5, avoid);
    let mut svg = ctx.svg();
    axes.draw(&mut svg, th);
    let mut scene = Scene::default();
    add_shadow(&mut scene, ctx, &axes);
    drop_lines(&mut scene, ctx, &axes);
    let curve: Vec<(f64, f64, f64)> = ctx.curve.iter().map(|p| axes.screen(p.pos)).collect();
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
    scene.draw(&mut svg);
    let c2 = flat(&curve);
    let k2 = flat(&ctrl);
    let mut obstacles = obstacles_of(&c2, 0.0);
    obstacles.extend(obstacles_of(&k2, 0.0));
    let keep = Keep {
        obstacles,
        bounds: frame.plot,
        avoid: avoid.into_iter().collect(),
    };
    let degs: Vec<[f64; 3]> = ctx.controls.iter().map(|p| p.deg).collect();
    draw_callouts(&mut svg, th, &k2, &degs, &callout_names(ctx), &keep);
    frame.draw(&mut svg, th);
    svg.finish()
}

/// Bands along the projection of a 3-D curve.
fn plane_3d(ctx: &Ctx) -> String {
    let th = &ctx.theme;
    let frame = ctx.frame(plane_legend(th), LegendPlace::Corner);
    let avoid = frame.legend_rect(th);
    let axes = axes3_for(ctx, frame.plot, 5, avoid);
    let mut svg = ctx.svg();
    axes.draw(&mut svg, th);
    let mut scene = Scene::default();
    add_shadow(&mut scene, ctx, &axes);
    scene.draw(&mut svg);
    let curve: Vec<(f64, f64)> = ctx.curve.iter().map(|p| axes.px(p.pos)).collect();
    let ctrl: Vec<(f64, f64)> = ctx.controls.iter().map(|p| axes.px(p.pos)).collect();
    let degs: Vec<[f64; 3]> = ctx.curve.iter().map(|p| p.deg).collect();
    plane_data(&mut svg, th, &curve, &ctrl, &degs);
    ctx.names(
        &mut svg,
        &ctrl,
        plane_obstacles(th, &curve, &ctrl),
        frame.plot,
        avoid,
    );
    frame.draw(&mut svg, th);
    svg.finish()
}
