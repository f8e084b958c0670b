//! A sampled surface drawn as a mesh of quads: each face painted by a quantity (a degree or
//! the score; viridis) or a neutral grey and shaded by its normal, with iso-parameter lines
//! and a dark boundary, all depth-sorted; a surface that shows no area is drawn as a coloured
//! curve or a point. Also the panel of the single-quantity views and of each panel of `all`:
//! the mesh coloured by one quantity with the control net over it.

use crate::axes3::Axes3;
use crate::ctx::Ctx;
use crate::drawing::Painter;
use crate::layout::{ColorBar, Entry, Legend, Rect, Swatch};
use crate::model::Mesh;
use crate::net::draw_net;
use crate::quantity::Quantity;
use crate::scene::{Scene, Shape, DATA};
use crate::style::{Color, Style};
use crate::theme::{self, Marker, Theme};

/// Light direction in camera coordinates (right, up, towards the viewer): from the upper
/// left, in front.
const LIGHT: [f64; 3] = [-0.36, 0.48, 0.8];
/// How much the darkest face is darkened towards black (the brightest is not).
const SHADE: f64 = 0.34;

/// About this many iso-parameter lines are drawn on the mesh in each direction.
const ISO_LINES: usize = 8;

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

/// How faces are painted: by a quantity (a degree or the score), or a neutral grey.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Paint {
    By(Quantity),
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
                Paint::By(q) => q.colour_of(mesh.cell_value(a, b, q)),
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

/// Draws the mesh seen in `axes`, painted by `paint`, far to near into `svg`, in a group
/// `mesh` whose seams and iso-parameter lines are [`mesh_line`] wide.
pub(crate) fn draw_mesh(svg: &mut Painter, th: &Theme, axes: &Axes3, mesh: &Mesh, paint: Paint) {
    let mut scene = Scene::default();
    add_mesh(&mut scene, th, axes, mesh, paint);
    svg.begin_mesh_group("mesh", mesh_line(th));
    scene.draw(svg);
    svg.end_group();
}

fn net_entry(th: &Theme, fill: Color) -> Entry {
    Entry::polygon(th, theme::CONSTRUCTION, Marker::Circle, fill, "control net")
}

/// The legend of a mesh coloured by a quantity: surface, control net, and the colour bar
/// labelled `bar`; the note says the colour is the `noun` ("degree" or "score") and adds
/// `notes`.
pub(crate) fn quantity_legend(th: &Theme, bar: &str, noun: &str, notes: Vec<String>) -> Legend {
    let mut all_notes = vec![format!(
        "Surface and control points coloured by the {noun}; shading shows the shape."
    )];
    all_notes.extend(notes);
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
        notes: all_notes,
        colorbar: Some(ColorBar {
            label: bar.to_string(),
            length: 0.62,
            range: (0.0, 1.0),
        }),
    }
}

/// One box with the mesh coloured by `q` and the control net.
pub(crate) fn mesh_panel(
    svg: &mut Painter,
    ctx: &Ctx,
    mesh: &Mesh,
    grid: (usize, usize),
    area: Rect,
    q: Quantity,
    avoid: Option<Rect>,
) {
    let th = &ctx.theme;
    let axes = ctx.draw_box(svg, area, avoid);
    draw_mesh(svg, th, &axes, mesh, Paint::By(q));
    let colour = |k: usize| q.colour_of(q.at(&ctx.controls[k]));
    draw_net(svg, ctx, &axes, mesh, grid, theme::CONSTRUCTION, &colour);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn surface_iso_step() {
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
