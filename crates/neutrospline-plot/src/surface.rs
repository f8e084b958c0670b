//! The views of a tensor-product surface.
//!
//! - `truth`, `indeterminacy`, `falsity`: the surface as a shaded mesh of quads from the
//!   sample grid, coloured by the degree (viridis) and lit by its normals so that the shape
//!   reads without hiding the colour; the control net as a dashed grey wire with its points
//!   coloured alike; drawn far to near (painter's algorithm), with the hidden parts of the net
//!   shown faintly through the surface.
//! - `all`: three such panels, arranged like the curves' (see `panels`).
//! - `controls`: the net over a neutral grey mesh, each control point drawn as a small box of
//!   three bars (its degrees; for nets of more than 64 points, a regular subset), the corners
//!   named.
//! - `plane`: the three degrees over the parameter domain, one heat map per degree, `u`
//!   across and `v` up, with the knot lines of a spline surface.

use neutrospline::{uniform_parameter, DegreeKind};

use crate::axes2::Axes2;
use crate::axes3::Axes3;
use crate::callout::{obstacles_of, place_names, Keep};
use crate::layout::{text_centred, ColorBar, Entry, Legend, LegendPlace, Rect, Swatch};
use crate::model::Mesh;
use crate::panels::{self, Panels};
use crate::render::{axes3_for, flat, marker_style, name_style, panel_title, polygon_entry, Ctx};
use crate::scene::{Scene, Shape, DATA};
use crate::svg::{Color, Style, SvgWriter};
use crate::theme::{self, Marker, Theme};
use crate::view::View;

/// Most control points drawn with their degrees; larger nets show a regular subset.
const MAX_GLYPHS: usize = 64;
/// Pieces each control-net edge is cut into to find where the surface hides it.
const NET_PIECES: usize = 16;
/// About this many iso-parameter lines are drawn on the mesh in each direction.
const ISO_LINES: usize = 8;

/// Draws `view` of a surface sampled as `mesh`, with a `rows x cols` control net.
pub(crate) fn render(ctx: &Ctx, mesh: &Mesh, grid: (usize, usize), view: View) -> String {
    match view {
        View::Controls => controls(ctx, mesh, grid),
        View::Plane => plane(ctx, mesh),
        View::All => all(ctx, mesh, grid),
        View::Truth | View::Indeterminacy | View::Falsity => {
            single(ctx, mesh, grid, view.degree().unwrap_or(DegreeKind::Truth))
        }
    }
}

/// Light direction in camera coordinates (right, up, towards the viewer): from the upper
/// left, in front.
const LIGHT: [f64; 3] = [-0.36, 0.48, 0.8];
/// How much the darkest face is darkened towards black (the brightest is not).
const SHADE: f64 = 0.34;

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// The normal of the face with corners `c` (in order around it): the mean of the surface
/// normals at the corners (oriented alike), else the cross product of the diagonals.
fn face_normal(mesh: &Mesh, c: [(usize, usize); 4]) -> [f64; 3] {
    let mut sum = [0.0; 3];
    let mut first: Option<[f64; 3]> = None;
    for &(a, b) in &c {
        if let Some(n) = mesh.normal(a, b) {
            let n = match first {
                Some(f) if dot(f, n) < 0.0 => n.map(|x| -x),
                Some(_) => n,
                None => {
                    first = Some(n);
                    n
                }
            };
            for k in 0..3 {
                sum[k] += n[k];
            }
        }
    }
    if dot(sum, sum) > 1e-24 {
        return sum;
    }
    let p = |i: usize| mesh.at(c[i].0, c[i].1).pos;
    cross(sub(p(2), p(0)), sub(p(3), p(1)))
}

/// Lambert factor in [0, 1] of a data-space normal, lit from both sides.
fn lambert(axes: &Axes3, n: [f64; 3]) -> f64 {
    let l = LIGHT;
    let norm = dot(l, l).sqrt();
    match axes.view_normal(n) {
        Some(v) => (dot(v, l) / norm).abs(),
        None => 1.0,
    }
}

/// `base` darkened by the shading of a face with Lambert factor `k`.
fn shaded(base: Color, k: f64) -> Color {
    base.mix(Color(0, 0, 0), SHADE * (1.0 - k))
}

/// How faces are painted: by a degree, or a neutral grey.
#[derive(Debug, Clone, Copy)]
enum Paint {
    Degree(DegreeKind),
    Neutral,
}

/// Step between iso-parameter lines: about [`ISO_LINES`] intervals.
fn iso_step(n: usize) -> usize {
    (n.saturating_sub(1)).div_ceil(ISO_LINES).max(1)
}

/// Adds the faces of the mesh to `scene`, and the iso-parameter lines and the boundary along
/// their edges, each edge drawn right after the nearer of its two faces.
fn add_mesh(scene: &mut Scene, th: &Theme, axes: &Axes3, mesh: &Mesh, paint: Paint) {
    let n = mesh.n;
    let px: Vec<(f64, f64, f64)> = mesh.points.iter().map(|p| axes.screen(p.pos)).collect();
    let at = |a: usize, b: usize| px[a * n + b];
    let faces = n.saturating_sub(1);
    let mut depth = vec![0.0; faces * faces];
    let mut colour = vec![Color::WHITE; faces * faces];
    for a in 0..faces {
        for b in 0..faces {
            let c = [(a, b), (a + 1, b), (a + 1, b + 1), (a, b + 1)];
            let q = c.map(|(i, j)| at(i, j));
            let base = match paint {
                Paint::Degree(kind) => {
                    let v = c
                        .iter()
                        .map(|&(i, j)| mesh.at(i, j).deg[kind.index()])
                        .sum::<f64>()
                        / 4.0;
                    theme::colormap(v)
                }
                Paint::Neutral => theme::SURFACE,
            };
            let fill = shaded(base, lambert(axes, face_normal(mesh, c)));
            let d = q.iter().map(|p| p.2).sum::<f64>() / 4.0;
            depth[a * faces + b] = d;
            colour[a * faces + b] = fill;
            scene.push(
                DATA,
                d,
                Shape::Face(q.iter().map(|p| (p.0, p.1)).collect(), fill),
            );
        }
    }
    // Edges: along u at fixed v index `b` (between faces (a, b - 1) and (a, b)), and along v
    // at fixed u index `a`.
    let step = iso_step(n);
    let rim = Style::stroke(theme::AXIS, 1.8 * th.s);
    for fixed in 0..n {
        let boundary = fixed == 0 || fixed + 1 == n;
        if !(boundary || fixed % step == 0) {
            continue;
        }
        for k in 0..faces {
            for along_u in [true, false] {
                // Corners and the faces on either side.
                let (p, q, sides) = if along_u {
                    (
                        at(k, fixed),
                        at(k + 1, fixed),
                        [(k, fixed.wrapping_sub(1)), (k, fixed)],
                    )
                } else {
                    (
                        at(fixed, k),
                        at(fixed, k + 1),
                        [(fixed.wrapping_sub(1), k), (fixed, k)],
                    )
                };
                let near = sides
                    .iter()
                    .filter(|&&(a, b)| a < faces && b < faces)
                    .map(|&(a, b)| a * faces + b)
                    .max_by(|&x, &y| depth[x].total_cmp(&depth[y]));
                let Some(face) = near else { continue };
                let shape = if boundary {
                    Shape::Polyline(vec![(p.0, p.1), (q.0, q.1)], rim.clone())
                } else {
                    Shape::Edge(
                        (p.0, p.1),
                        (q.0, q.1),
                        colour[face].mix(Color(0, 0, 0), 0.4),
                    )
                };
                scene.push(DATA, depth[face], shape);
            }
        }
    }
    let area: f64 = (0..faces * faces)
        .map(|k| {
            let (a, b) = (k / faces, k % faces);
            let q = [at(a, b), at(a + 1, b), at(a + 1, b + 1), at(a, b + 1)];
            let cross =
                (q[2].0 - q[0].0) * (q[3].1 - q[1].1) - (q[2].1 - q[0].1) * (q[3].0 - q[1].0);
            cross.abs() / 2.0
        })
        .sum();
    if area < 1.0 {
        // The surface shows no area (it collapsed to a curve or a point, or is seen edge on):
        // draw its grid lines as a coloured curve, and a point as a square.
        let width = th.curve_w();
        for a in 0..n {
            for b in 0..n {
                let k = (a.min(faces.saturating_sub(1))) * faces + b.min(faces.saturating_sub(1));
                let c = colour.get(k).copied().unwrap_or(theme::SURFACE);
                for (i, j) in [(a + 1, b), (a, b + 1)] {
                    if i < n && j < n {
                        let (p, q) = (at(a, b), at(i, j));
                        scene.push(
                            DATA,
                            (p.2 + q.2) / 2.0,
                            Shape::Polyline(
                                vec![(p.0, p.1), (q.0, q.1)],
                                Style::stroke(c, width).with_class("face"),
                            ),
                        );
                    }
                }
            }
        }
        if mesh.points.iter().all(|p| p.pos == mesh.points[0].pos) {
            let p = px[0];
            scene.push(
                DATA,
                p.2,
                Shape::Marker(
                    Marker::Square,
                    (p.0, p.1),
                    0.8 * th.marker_r(),
                    Style::stroke(theme::AXIS, th.thin_w())
                        .with_fill(colour.first().copied().unwrap_or(theme::SURFACE)),
                ),
            );
        }
    }
}

/// Width of the seams and iso-parameter lines of a mesh (inherited from its group).
fn mesh_line(th: &Theme) -> f64 {
    0.9 * th.s
}

/// The control net as screen points, row by row.
fn net_points(ctx: &Ctx, axes: &Axes3) -> Vec<(f64, f64, f64)> {
    ctx.controls.iter().map(|p| axes.screen(p.pos)).collect()
}

/// The net's edges as index pairs, rows first.
fn net_edges(grid: (usize, usize)) -> Vec<(usize, usize)> {
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
    svg: &mut SvgWriter,
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
            let t0 = uniform_parameter(k, NET_PIECES + 1, (0.0, 1.0));
            let t1 = uniform_parameter(k + 1, NET_PIECES + 1, (0.0, 1.0));
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

fn net_entry(th: &Theme, fill: Color) -> Entry {
    polygon_entry(th, theme::CONSTRUCTION, Marker::Circle, fill, "control net")
}

fn degree_legend(th: &Theme, bar: &str) -> Legend {
    Legend {
        entries: vec![
            Entry {
                swatch: Swatch::Patch {
                    color: theme::colormap(0.55),
                },
                label: "surface".to_string(),
            },
            net_entry(th, theme::colormap(0.55)),
        ],
        notes: vec![
            "Surface and control points coloured by the degree; shading shows the shape."
                .to_string(),
        ],
        colorbar: Some(ColorBar {
            label: bar.to_string(),
            length: 0.62,
        }),
    }
}

/// One box with the mesh coloured by `kind` and the control net.
fn mesh_panel(
    svg: &mut SvgWriter,
    ctx: &Ctx,
    mesh: &Mesh,
    grid: (usize, usize),
    area: Rect,
    kind: DegreeKind,
    avoid: Option<Rect>,
) {
    let th = &ctx.theme;
    let axes = axes3_for(ctx, area, 5, avoid);
    axes.draw(svg, th);
    let mut scene = Scene::default();
    add_mesh(&mut scene, th, &axes, mesh, Paint::Degree(kind));
    svg.begin_mesh_group("mesh", mesh_line(th));
    scene.draw(svg);
    svg.end_group();
    let pts = net_points(ctx, &axes);
    let colour = |k: usize| theme::colormap(ctx.controls[k].deg[kind.index()]);
    let occluder = Occluder::new(&axes, mesh);
    add_net(svg, th, &pts, grid, &occluder, theme::CONSTRUCTION, &colour);
}

/// The surface coloured by one degree.
fn single(ctx: &Ctx, mesh: &Mesh, grid: (usize, usize), kind: DegreeKind) -> String {
    let th = &ctx.theme;
    let frame = ctx.frame(degree_legend(th, kind.name()), LegendPlace::Corner);
    let mut svg = ctx.svg();
    mesh_panel(
        &mut svg,
        ctx,
        mesh,
        grid,
        frame.plot,
        kind,
        frame.legend_rect(th),
    );
    frame.draw(&mut svg, th);
    svg.finish()
}

/// Three meshes, one per degree, sharing the legend.
fn all(ctx: &Ctx, mesh: &Mesh, grid: (usize, usize)) -> String {
    let th = &ctx.theme;
    let mut legend = degree_legend(th, "degree");
    legend.notes.clear();
    let layout = panels::choose(
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
        panel_title(&mut svg, th, layout.title_centre(j, th), *kind);
        mesh_panel(&mut svg, ctx, mesh, grid, layout.area(j, th), *kind, None);
    }
    layout.frame.draw(&mut svg, th);
    svg.finish()
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

/// Indices along one direction of `count` that get a glyph: every `step`-th and the last.
fn every(count: usize, step: usize) -> Vec<usize> {
    let mut v: Vec<usize> = (0..count).step_by(step.max(1)).collect();
    if v.last() != Some(&(count - 1)) {
        v.push(count - 1);
    }
    v
}

/// The control points that get a degree glyph, and the stride between them (1: all).
fn glyph_subset(grid: (usize, usize)) -> (Vec<usize>, usize) {
    let (rows, cols) = grid;
    let mut step = 1;
    loop {
        let (ri, ci) = (every(rows, step), every(cols, step));
        if ri.len() * ci.len() <= MAX_GLYPHS || step >= rows.max(cols) {
            let chosen = ri
                .iter()
                .flat_map(|&i| ci.iter().map(move |&j| i * cols + j))
                .collect();
            return (chosen, step);
        }
        step += 1;
    }
}

/// The corners of the net (the points that are named), without repeats.
fn corners(grid: (usize, usize)) -> Vec<usize> {
    let (rows, cols) = grid;
    let mut c = vec![0, cols - 1, (rows - 1) * cols, rows * cols - 1];
    c.sort_unstable();
    c.dedup();
    c
}

fn controls_legend(th: &Theme, step: usize) -> Legend {
    let mut entries = vec![
        polygon_entry(
            th,
            theme::CRISP,
            Marker::Circle,
            Color::WHITE,
            "control net",
        ),
        Entry {
            swatch: Swatch::Patch {
                color: theme::SURFACE,
            },
            label: "surface".to_string(),
        },
    ];
    for kind in DegreeKind::ALL {
        entries.push(Entry {
            swatch: Swatch::Band {
                color: theme::degree_color(kind),
            },
            label: format!("{} ({})", kind.name(), theme::degree_letter(kind)),
        });
    }
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
        entries,
        notes,
        colorbar: None,
    }
}

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

/// Size of a degree glyph: (width, height) for the unit `u` (a font size).
fn glyph_size(u: f64) -> (f64, f64) {
    (
        3.0 * 0.42 * u + 2.0 * 0.16 * u + 2.0 * 0.26 * u,
        1.5 * u + 2.0 * 0.26 * u,
    )
}

/// The median distance in pixels from a point to its nearest neighbour (infinite for fewer
/// than two points): how crowded the control points are on screen.
fn median_spacing(at: &[(f64, f64)]) -> f64 {
    if at.len() < 2 {
        return f64::INFINITY;
    }
    let mut nearest: Vec<f64> = at
        .iter()
        .enumerate()
        .map(|(i, p)| {
            at.iter()
                .enumerate()
                .filter(|(j, _)| *j != i)
                .map(|(_, q)| ((p.0 - q.0).powi(2) + (p.1 - q.1).powi(2)).sqrt())
                .fold(f64::INFINITY, f64::min)
        })
        .collect();
    nearest.sort_by(f64::total_cmp);
    nearest[nearest.len() / 2]
}

/// The unit of the glyphs: the note font size, smaller when the points crowd each other (down
/// to 55 %), so that neighbouring glyphs rarely overlap.
fn glyph_unit(th: &Theme, at: &[(f64, f64)]) -> f64 {
    let full = th.note();
    let (w, _) = glyph_size(1.0);
    (0.9 * median_spacing(at) / w).clamp(0.55 * full, full)
}

/// A control point drawn as its degrees: a white box centred on it with three bars.
fn glyph(svg: &mut SvgWriter, th: &Theme, c: (f64, f64), deg: [f64; 3], u: f64) {
    let (w, h) = glyph_size(u);
    let (x, y) = (c.0 - w / 2.0, c.1 - h / 2.0);
    svg.rect(
        x,
        y,
        w,
        h,
        &Style::stroke(theme::CRISP, th.s * 1.6)
            .with_fill(Color::WHITE)
            .square()
            .with_class("degree-glyph"),
    );
    let (bw, gap, pad, bh) = (0.42 * u, 0.16 * u, 0.26 * u, 1.5 * u);
    let mut bx = x + pad;
    for kind in DegreeKind::ALL {
        let v = theme::unit(deg[kind.index()]);
        svg.rect(bx, y + pad, bw, bh, &Style::fill(theme::TRACK).square());
        svg.rect(
            bx,
            y + pad + bh * (1.0 - v),
            bw,
            bh * v,
            &Style::fill(theme::degree_color(kind))
                .square()
                .with_class(&format!("bar {}", kind.name())),
        );
        bx += bw + gap;
    }
}

/// The control net with the degrees of its points, over the surface in grey.
fn controls(ctx: &Ctx, mesh: &Mesh, grid: (usize, usize)) -> String {
    let th = &ctx.theme;
    let (chosen, step) = glyph_subset(grid);
    let frame = ctx.frame(controls_legend(th, step), LegendPlace::Corner);
    let avoid = frame.legend_rect(th);
    let axes = axes3_for(ctx, frame.plot, 5, avoid);
    let mut svg = ctx.svg();
    axes.draw(&mut svg, th);
    let mut scene = Scene::default();
    add_mesh(&mut scene, th, &axes, mesh, Paint::Neutral);
    svg.begin_mesh_group("mesh", mesh_line(th));
    scene.draw(&mut svg);
    svg.end_group();
    let pts = net_points(ctx, &axes);
    let occluder = Occluder::new(&axes, mesh);
    add_net(&mut svg, th, &pts, grid, &occluder, theme::CRISP, &|_| {
        Color::WHITE
    });
    // Glyphs far to near, so that nearer ones overlap farther ones.
    let mut order = chosen.clone();
    order.sort_by(|&a, &b| pts[a].2.total_cmp(&pts[b].2).then(a.cmp(&b)));
    let flat_pts = flat(&pts);
    let u = glyph_unit(th, &chosen.iter().map(|&k| flat_pts[k]).collect::<Vec<_>>());
    let (gw, gh) = glyph_size(u);
    svg.begin_group("degree-glyphs");
    for &k in &order {
        glyph(&mut svg, th, flat_pts[k], ctx.controls[k].deg, u);
    }
    svg.end_group();
    // Names of the corners, clear of the glyphs, the net and the legend.
    let names = point_names(ctx, grid);
    let named = corners(grid);
    let mut keep_out: Vec<Rect> = chosen
        .iter()
        .map(|&k| Rect::new(flat_pts[k].0 - gw / 2.0, flat_pts[k].1 - gh / 2.0, gw, gh))
        .collect();
    keep_out.extend(avoid);
    let keep = Keep {
        obstacles: net_edges(grid)
            .iter()
            .flat_map(|&(a, b)| obstacles_of(&[flat_pts[a], flat_pts[b]], 0.0))
            .collect(),
        bounds: frame.plot,
        avoid: keep_out,
    };
    let at: Vec<(f64, f64)> = named.iter().map(|&k| flat_pts[k]).collect();
    let labels: Vec<String> = named.iter().map(|&k| names[k].clone()).collect();
    let centres = place_names(th, &at, &labels, &keep);
    svg.begin_group("point-names");
    for (c, name) in centres.iter().zip(&labels) {
        text_centred(&mut svg, *c, name, &name_style(th));
    }
    svg.end_group();
    frame.draw(&mut svg, th);
    svg.finish()
}

fn plane_legend(th: &Theme, knots: bool) -> Legend {
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
fn heat_map(svg: &mut SvgWriter, th: &Theme, mesh: &Mesh, axes: &Axes2, kind: DegreeKind) {
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
            let v = [(a, b), (a + 1, b), (a + 1, b + 1), (a, b + 1)]
                .iter()
                .map(|&(i, j)| mesh.at(i, j).deg[kind.index()])
                .sum::<f64>()
                / 4.0;
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
    svg.rect(
        f.x,
        f.y,
        f.w,
        f.h,
        &Style::stroke(theme::AXIS, th.axis_w()).square(),
    );
}

/// The three degrees over the parameter domain, side by side.
fn plane(ctx: &Ctx, mesh: &Mesh) -> String {
    let th = &ctx.theme;
    let legend = plane_legend(th, !(mesh.knots[0].is_empty() && mesh.knots[1].is_empty()));
    let layout: Panels = panels::choose(
        th,
        &legend,
        &|legend, place| ctx.frame(legend, place),
        &|area| {
            let axes = domain_axes(th, mesh, area);
            (axes.scale(), axes.outer(th).y)
        },
    );
    let mut svg = ctx.svg();
    for (j, kind) in DegreeKind::ALL.iter().enumerate() {
        panel_title(&mut svg, th, layout.title_centre(j, th), *kind);
        let axes = domain_axes(th, mesh, layout.area(j, th));
        heat_map(&mut svg, th, mesh, &axes, *kind);
    }
    layout.frame.draw(&mut svg, th);
    svg.finish()
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

    #[test]
    fn surface_glyph_subset() {
        let (all, step) = glyph_subset((4, 4));
        assert_eq!((all.len(), step), (16, 1));
        let (some, step) = glyph_subset((12, 12));
        assert!(some.len() <= MAX_GLYPHS && step > 1);
        assert!(some.contains(&0) && some.contains(&143) && some.contains(&11));
        assert_eq!(glyph_subset((1, 1)).0, vec![0]);
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
        assert_eq!(iso_step(40), 5);
        assert_eq!(iso_step(2), 1);
    }

    #[test]
    fn surface_shading_is_modest() {
        let base = Color(200, 100, 50);
        assert_eq!(shaded(base, 1.0), base);
        let dark = shaded(base, 0.0);
        assert!(dark.0 >= 130 && dark.0 < 200);
    }
}
