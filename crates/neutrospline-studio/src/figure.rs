//! Figures of a model, drawn the way `neutrospline plot` draws them: one code path for the
//! command and the studio, so that the studio's "export SVG" writes the command's bytes.

use neutrospline_plot::Drawing;

/// Where the control points of a curve are drawn in a `plane` view, and how dragging one
/// moves it.
#[derive(Debug, Clone, PartialEq)]
pub struct Handles {
    /// The centre of each control point's marker, in SVG pixels, in order.
    pub pixels: Vec<[f64; 2]>,
    /// For a plane curve, the map from model coordinates to pixels: `[sx, sy, ox, oy]` with
    /// `px = ox + sx x`, `py = oy + sy y`; `None` for a space curve or when the points do not
    /// determine it.
    pub frame: Option<[f64; 4]>,
    /// How a move of the pointer by `(dx, dy)` figure pixels moves a control point: coordinate
    /// `a` (x, y, then z) changes by `drag[a][0] dx + drag[a][1] dy`. For a plane curve the
    /// inverse of `frame`; for a space curve (drawn by an orthographic camera, so pixels are an
    /// affine map `A p + b` of the position) the least move whose picture is the pointer's
    /// move, `Aᵀ (A Aᵀ)⁻¹`. `None` when the points do not determine it (a space curve whose
    /// control points lie in one plane).
    pub drag: Option<Vec<[f64; 2]>>,
}

/// The handles of a `plane` view `drawing` of a 2-D curve with control positions `points`:
/// the pixels of its control-point markers (circles of class `control-point`), and the scale
/// and offset on each axis from the two points farthest apart along it (the plane view draws
/// x and y at one scale, which stands in for an axis on which all points coincide).
pub fn handles(drawing: &Drawing, points: &[[f64; 2]]) -> Handles {
    let pixels = drawing.circle_centres("control-point");
    let frame = (pixels.len() == points.len() && !points.is_empty())
        .then(|| {
            let axis = |a: usize| -> Option<f64> {
                let (lo, hi) = (0..points.len()).fold((0, 0), |(lo, hi), i| {
                    (
                        if points[i][a] < points[lo][a] { i } else { lo },
                        if points[i][a] > points[hi][a] { i } else { hi },
                    )
                });
                let d = points[hi][a] - points[lo][a];
                (d > 0.0).then(|| (pixels[hi][a] - pixels[lo][a]) / d)
            };
            let (sx, sy) = match (axis(0), axis(1)) {
                (Some(sx), Some(sy)) => (sx, sy),
                (Some(sx), None) => (sx, -sx),
                (None, Some(sy)) => (-sy, sy),
                (None, None) => return None,
            };
            let (ox, oy) = (
                pixels[0][0] - sx * points[0][0],
                pixels[0][1] - sy * points[0][1],
            );
            [sx, sy, ox, oy]
                .iter()
                .all(|v| v.is_finite())
                .then_some([sx, sy, ox, oy])
        })
        .flatten();
    let drag = frame.map(|[sx, sy, _, _]| vec![[1.0 / sx, 0.0], [0.0, 1.0 / sy]]);
    Handles {
        pixels,
        frame,
        drag,
    }
}

/// The handles of a `plane` view `drawing` of a space curve with control positions `points`:
/// the pixels of its control-point markers, and the drag map from the affine map of positions
/// to pixels fitted by least squares (exact for the view's orthographic camera; `None` when
/// the points lie in one plane or do not fit an affine map to 0.01 pixel).
pub fn space_handles(drawing: &Drawing, points: &[[f64; 3]]) -> Handles {
    let pixels = drawing.circle_centres("control-point");
    let drag = (pixels.len() == points.len())
        .then(|| affine_fit(points, &pixels))
        .flatten()
        .and_then(|a| least_move(&a));
    Handles {
        pixels,
        frame: None,
        drag,
    }
}

/// `A` (2 x 3) of the affine map `pixel = A p + b` through the pairs, by least squares on the
/// centred points; `None` when the points do not span space or the map misses a pixel by more
/// than 0.01.
fn affine_fit(points: &[[f64; 3]], pixels: &[[f64; 2]]) -> Option<[[f64; 3]; 2]> {
    let n = points.len() as f64;
    let mean_p = (0..3).map(|a| points.iter().map(|p| p[a]).sum::<f64>() / n);
    let mean_p: Vec<f64> = mean_p.collect();
    let mean_u: Vec<f64> = (0..2)
        .map(|a| pixels.iter().map(|u| u[a]).sum::<f64>() / n)
        .collect();
    let q: Vec<[f64; 3]> = points
        .iter()
        .map(|p| [p[0] - mean_p[0], p[1] - mean_p[1], p[2] - mean_p[2]])
        .collect();
    // The normal equations (sum q q^T) a_k = sum q u_k, one right-hand side per pixel axis.
    let mut m = [[0.0; 3]; 3];
    let mut rhs = [[0.0; 3]; 2];
    for (qi, ui) in q.iter().zip(pixels) {
        for r in 0..3 {
            for c in 0..3 {
                m[r][c] += qi[r] * qi[c];
            }
            for k in 0..2 {
                rhs[k][r] += qi[r] * (ui[k] - mean_u[k]);
            }
        }
    }
    let a = [solve3(m, rhs[0])?, solve3(m, rhs[1])?];
    let fits = q.iter().zip(pixels).all(|(qi, ui)| {
        (0..2).all(|k| {
            let predicted = mean_u[k] + (0..3).map(|c| a[k][c] * qi[c]).sum::<f64>();
            (predicted - ui[k]).abs() <= 0.01
        })
    });
    fits.then_some(a)
}

/// The solution of the symmetric 3 x 3 system `m x = b` by elimination with partial pivoting;
/// `None` when a pivot falls below 1e-12 of the matrix's largest diagonal entry (the points
/// lie in a plane or on a line).
fn solve3(mut m: [[f64; 3]; 3], mut b: [f64; 3]) -> Option<[f64; 3]> {
    let scale = (0..3).map(|i| m[i][i].abs()).fold(0.0, f64::max);
    if !scale.is_finite() || scale <= 0.0 {
        return None;
    }
    for col in 0..3 {
        let pivot = (col..3).max_by(|&i, &j| m[i][col].abs().total_cmp(&m[j][col].abs()))?;
        if m[pivot][col].abs() <= 1e-12 * scale {
            return None;
        }
        m.swap(col, pivot);
        b.swap(col, pivot);
        for row in col + 1..3 {
            let f = m[row][col] / m[col][col];
            for c in col..3 {
                m[row][c] -= f * m[col][c];
            }
            b[row] -= f * b[col];
        }
    }
    let mut x = [0.0; 3];
    for row in (0..3).rev() {
        let tail: f64 = (row + 1..3).map(|c| m[row][c] * x[c]).sum();
        x[row] = (b[row] - tail) / m[row][row];
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}

/// `Aᵀ (A Aᵀ)⁻¹` (3 x 2): the least move of a point whose picture under `A` is a given move of
/// the pointer.
fn least_move(a: &[[f64; 3]; 2]) -> Option<Vec<[f64; 2]>> {
    let dot = |u: &[f64; 3], v: &[f64; 3]| u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    let (g00, g01, g11) = (dot(&a[0], &a[0]), dot(&a[0], &a[1]), dot(&a[1], &a[1]));
    let det = g00 * g11 - g01 * g01;
    if !det.is_finite() || det <= 1e-12 * g00 * g11 {
        return None;
    }
    let inv = [[g11 / det, -g01 / det], [-g01 / det, g00 / det]];
    Some(
        (0..3)
            .map(|r| {
                [
                    a[0][r] * inv[0][0] + a[1][r] * inv[1][0],
                    a[0][r] * inv[0][1] + a[1][r] * inv[1][1],
                ]
            })
            .collect(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use neutrospline::ControlPolygon;
    use neutrospline_plot::{render_drawing, PlotModel, PlotOptions, View};

    /// A space curve's drag map: a pointer move, mapped to a model move, is that move again
    /// when projected by the fitted map.
    #[test]
    fn space_handles_move_points_under_the_pointer() {
        let file = concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/helix3d.toml");
        let model = neutrospline_io::load(file, &neutrospline_io::ReadOptions::default()).unwrap();
        let Some(neutrospline::DynCurve::Spatial(curve)) = model.shape().curve() else {
            panic!("a space curve")
        };
        let points: Vec<[f64; 3]> = curve.control_points().iter().map(|p| p.position).collect();
        let plot = PlotModel::from_model(&model).unwrap();
        let options = PlotOptions::default();
        let drawing = render_drawing(&plot, View::Plane, &options).unwrap();
        let h = space_handles(&drawing, &points);
        assert_eq!(h.pixels.len(), 4);
        let a = affine_fit(&points, &h.pixels).unwrap();
        let m = h.drag.unwrap();
        for (dx, dy) in [(10.0, 0.0), (0.0, -7.5), (3.0, 4.0)] {
            let delta: Vec<f64> = m.iter().map(|r| r[0] * dx + r[1] * dy).collect();
            let seen: Vec<f64> = a
                .iter()
                .map(|row| row.iter().zip(&delta).map(|(x, d)| x * d).sum())
                .collect();
            assert!(
                (seen[0] - dx).abs() < 1e-9 && (seen[1] - dy).abs() < 1e-9,
                "{seen:?}"
            );
        }
        // Points in one plane do not determine the map.
        let flat: Vec<[f64; 3]> = points.iter().map(|p| [p[0], p[1], 0.0]).collect();
        assert_eq!(affine_fit(&flat, &h.pixels), None);
        assert_eq!(
            solve3(
                [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 0.0]],
                [1.0; 3]
            ),
            None
        );
        let x = solve3(
            [[2.0, 1.0, 0.0], [1.0, 3.0, 1.0], [0.0, 1.0, 4.0]],
            [3.0, 5.0, 5.0],
        );
        assert!(x.unwrap().iter().all(|v| (v - 1.0).abs() < 1e-12), "{x:?}");
    }

    #[test]
    fn handles_map_model_to_pixels() {
        let curve = neutrospline::example1();
        let model = PlotModel::from(&curve);
        let drawing = render_drawing(&model, View::Plane, &PlotOptions::default()).unwrap();
        let points: Vec<[f64; 2]> = curve.control_points().iter().map(|p| p.position).collect();
        let h = handles(&drawing, &points);
        assert_eq!(h.pixels.len(), 4);
        let [sx, sy, ox, oy] = h.frame.unwrap();
        // Equal scale on both axes, y down.
        assert!((sx + sy).abs() < 1e-3 * sx, "{sx} {sy}");
        for (p, px) in points.iter().zip(&h.pixels) {
            assert!((ox + sx * p[0] - px[0]).abs() < 1e-6, "{p:?} {px:?}");
            assert!((oy + sy * p[1] - px[1]).abs() < 1e-6, "{p:?} {px:?}");
        }
    }
}
