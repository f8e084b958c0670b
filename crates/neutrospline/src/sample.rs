//! Sampling curves and surfaces into polylines and triangle meshes, for formats that hold
//! samples rather than the exact curve (glTF, PLY, OBJ, DXF meshes).
//!
//! - Curves: [`uniform_parameters`] (N evenly spaced parameters, the same as every other front
//!   end's through [`uniform_parameter`]) or [`adaptive_parameters`] (a polyline within a chord
//!   tolerance of the curve, proved by the convex hull property).
//! - Surfaces: a [`SurfaceGrid`] of points and unit normals at a tensor grid of parameters,
//!   with its [`triangles`](SurfaceGrid::triangles); [`adaptive_surface_parameters`] chooses
//!   the grid from the iso-parameter curves.
//!
//! ```
//! use neutrospline::sample::{adaptive_parameters, chord_tolerance};
//! use neutrospline::{AnyCurve, Evaluate};
//!
//! let curve = AnyCurve::from(neutrospline::example1());
//! let tolerance = chord_tolerance(&curve); // 1e-3 of the bounding box's diagonal
//! let ts = adaptive_parameters(&curve, tolerance);
//! assert_eq!((ts[0], ts[ts.len() - 1]), (0.0, 1.0));
//! assert!(ts.windows(2).all(|w| w[0] < w[1]));
//! # Ok::<(), neutrospline::EvalError>(())
//! ```

use core::ops::Range;

use crate::any_curve::AnyCurve;
use crate::curve::{Bounded, ControlPolygon, EvalError, Evaluate, Split};
use crate::point::{BoundingBox, CurvePoint};
use crate::surface::{Direction, EvaluateSurface, Surface};
use crate::uniform_parameter;

/// The default chord tolerance, relative: a sampled curve stays within this fraction of the
/// diagonal of its bounding box ([`chord_tolerance`]).
pub const CHORD_TOLERANCE: f64 = 1e-3;

/// How often a Bézier piece is halved at most by [`adaptive_parameters`] (a piece is never cut
/// into more than 2^20 segments, whatever the tolerance).
pub const MAX_SUBDIVISION_DEPTH: u32 = 20;

/// `count` evenly spaced parameters over `domain`, ends exact ([`uniform_parameter`]).
pub fn uniform_parameters(domain: Range<f64>, count: usize) -> Vec<f64> {
    (0..count)
        .map(|k| uniform_parameter(k, count, domain.clone()))
        .collect()
}

/// The length of the diagonal of a box.
pub fn diagonal<const D: usize>(bounds: &BoundingBox<D>) -> f64 {
    bounds
        .position
        .iter()
        .map(|i| i.length() * i.length())
        .sum::<f64>()
        .sqrt()
}

/// [`CHORD_TOLERANCE`] times the diagonal of the curve's (tight) bounding box.
pub fn chord_tolerance<const D: usize>(curve: &AnyCurve<D>) -> f64 {
    CHORD_TOLERANCE * diagonal(&curve.bounding_box())
}

/// The distance from `p` to the segment `a b` (to `a` when the segment is a point).
fn segment_distance<const D: usize>(p: &[f64; D], a: &[f64; D], b: &[f64; D]) -> f64 {
    let mut ab2 = 0.0;
    let mut dot = 0.0;
    for k in 0..D {
        ab2 += (b[k] - a[k]) * (b[k] - a[k]);
        dot += (p[k] - a[k]) * (b[k] - a[k]);
    }
    let s = if ab2 > 0.0 {
        (dot / ab2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (0..D)
        .map(|k| {
            let d = p[k] - (a[k] + s * (b[k] - a[k]));
            d * d
        })
        .sum::<f64>()
        .sqrt()
}

/// Whether every control point of a Bézier piece (polynomial or rational, whose first and last
/// control points are its ends) lies within `tolerance` of its chord: then the whole piece
/// does, by the convex hull property (the points within a distance of a segment form a
/// convex set).
fn flat<const D: usize>(piece: &impl ControlPolygon<D>, tolerance: f64) -> bool {
    let n = piece.len();
    let (a, b) = (
        piece.control_point(0).position,
        piece.control_point(n - 1).position,
    );
    (1..n - 1).all(|i| segment_distance(&piece.control_point(i).position, &a, &b) <= tolerance)
}

/// Appends to `out` the parameters after the start of a Bézier piece that covers `[a, b]` of
/// the curve: halves it until each half is [`flat`].
fn subdivide<const D: usize, C>(piece: C, a: f64, b: f64, tolerance: f64, out: &mut Vec<f64>)
where
    C: ControlPolygon<D> + Split + Evaluate,
{
    // Depth-first, left before right: a stack of pieces still to look at, rightmost at the
    // bottom.
    let mut stack = vec![(piece, a, b, 0u32)];
    while let Some((piece, a, b, depth)) = stack.pop() {
        let domain = piece.domain();
        let mid = 0.5 * (domain.start + domain.end);
        let halves = if depth < MAX_SUBDIVISION_DEPTH && !flat(&piece, tolerance) {
            (domain.start < mid && mid < domain.end)
                .then(|| piece.split(mid).ok())
                .flatten()
        } else {
            None
        };
        match halves {
            Some((left, right)) => {
                let m = 0.5 * (a + b);
                stack.push((right, m, b, depth + 1));
                stack.push((left, a, m, depth + 1));
            }
            None => out.push(b),
        }
    }
}

/// Parameters of a polyline through the curve that stays within `tolerance` of it, in
/// increasing order, from the start of the domain to its end (both exact), with every knot of
/// the domain's interior among them.
///
/// The curve is cut into its Bézier pieces (polynomial or rational), and each piece is halved
/// (de Casteljau) until its control points lie within `tolerance` of the chord between its
/// ends. The curve lies in the convex hull of those control points (the weights are positive),
/// so each chord of the polyline through the curve's points at these parameters is within
/// `tolerance` of the curve piece it spans: a guarantee, not an estimate from a few samples. A
/// piece is halved at most [`MAX_SUBDIVISION_DEPTH`] times; a `tolerance` of 0 or less gives
/// the straight pieces' ends and that finest level elsewhere.
pub fn adaptive_parameters<const D: usize>(curve: &AnyCurve<D>, tolerance: f64) -> Vec<f64> {
    let domain = curve.domain();
    let mut out = vec![domain.start];
    match curve {
        AnyCurve::Bezier(c) => subdivide(c.clone(), domain.start, domain.end, tolerance, &mut out),
        AnyCurve::BSpline(c) => {
            for s in c.to_bezier_segments() {
                subdivide(s.curve, s.start, s.end, tolerance, &mut out);
            }
        }
        AnyCurve::Nurbs(c) => {
            for s in c.to_bezier_segments() {
                subdivide(s.curve, s.start, s.end, tolerance, &mut out);
            }
        }
    }
    // The last piece ends at the end of the domain; the midpoints stay inside their pieces.
    if let Some(last) = out.last_mut() {
        *last = domain.end;
    }
    out.dedup();
    out
}

/// Sample points and unit normals of a surface at a tensor grid of parameters: point `(i, j)`
/// at `(u[i], v[j])`, stored row by row (index `i * v.len() + j`, the row index along u as in
/// the surface's control grid).
#[derive(Clone, Debug, PartialEq)]
pub struct SurfaceGrid {
    u: Vec<f64>,
    v: Vec<f64>,
    points: Vec<CurvePoint<3>>,
    normals: Vec<[f64; 3]>,
}

impl SurfaceGrid {
    /// Evaluates `surface` at every pair of `u` and `v`.
    ///
    /// Each normal is the surface's unit normal `S_u x S_v / |S_u x S_v|`
    /// ([`Surface::normal`]); where the surface has none (a collapsed edge, a cone's apex), it
    /// is the normalised sum of the normals of the grid triangles around the point, and
    /// `[0, 0, 1]` when those vanish too (a surface collapsed to a line or a point). The
    /// triangles of [`SurfaceGrid::triangles`] face the same way as the normals.
    ///
    /// # Errors
    /// A parameter that is not finite or outside the surface's domain.
    pub fn new(surface: &Surface, u: Vec<f64>, v: Vec<f64>) -> Result<SurfaceGrid, EvalError> {
        let mut points = Vec::with_capacity(u.len() * v.len());
        let mut exact = Vec::with_capacity(u.len() * v.len());
        for &pu in &u {
            for &pv in &v {
                points.push(surface.evaluate(pu, pv)?);
                exact.push(surface.normal(pu, pv)?);
            }
        }
        let mut grid = SurfaceGrid {
            u,
            v,
            points,
            normals: Vec::new(),
        };
        let fallback = if exact.iter().any(Option::is_none) {
            grid.mesh_normals()
        } else {
            Vec::new()
        };
        grid.normals = exact
            .iter()
            .enumerate()
            .map(|(k, n)| n.unwrap_or_else(|| fallback[k]))
            .collect();
        Ok(grid)
    }

    /// The u parameters (rows of the grid).
    pub fn u(&self) -> &[f64] {
        &self.u
    }

    /// The v parameters (columns of the grid).
    pub fn v(&self) -> &[f64] {
        &self.v
    }

    /// The points, row by row.
    pub fn points(&self) -> &[CurvePoint<3>] {
        &self.points
    }

    /// The unit normals, one per point.
    pub fn normals(&self) -> &[[f64; 3]] {
        &self.normals
    }

    /// The two triangles of each grid cell `(i, j)`, as indices into [`SurfaceGrid::points`],
    /// counter-clockwise seen from the side the normals point to: `(i, j), (i + 1, j),
    /// (i + 1, j + 1)` and `(i, j), (i + 1, j + 1), (i, j + 1)`. A triangle with two equal
    /// points (at a collapsed edge) is left out.
    pub fn triangles(&self) -> Vec<[usize; 3]> {
        let (rows, cols) = (self.u.len(), self.v.len());
        let mut out = Vec::with_capacity(2 * rows.saturating_sub(1) * cols.saturating_sub(1));
        for i in 0..rows.saturating_sub(1) {
            for j in 0..cols.saturating_sub(1) {
                let [a, b, c, d] = [
                    i * cols + j,
                    (i + 1) * cols + j,
                    (i + 1) * cols + j + 1,
                    i * cols + j + 1,
                ];
                for t in [[a, b, c], [a, c, d]] {
                    let p = t.map(|k| self.points[k].position);
                    if p[0] != p[1] && p[1] != p[2] && p[0] != p[2] {
                        out.push(t);
                    }
                }
            }
        }
        out
    }

    /// For each point, the normalised sum of the normals of the grid triangles around it
    /// (their cross products, so larger triangles weigh more), or `[0, 0, 1]`.
    fn mesh_normals(&self) -> Vec<[f64; 3]> {
        let mut sums = vec![[0.0; 3]; self.points.len()];
        for t in self.triangles() {
            let [a, b, c] = t.map(|q| self.points[q].position);
            let n = cross(sub(b, a), sub(c, a));
            for k in t {
                for axis in 0..3 {
                    sums[k][axis] += n[axis];
                }
            }
        }
        sums.into_iter()
            .map(|sum| {
                let len = (sum[0] * sum[0] + sum[1] * sum[1] + sum[2] * sum[2]).sqrt();
                if len > 0.0 && len.is_finite() {
                    sum.map(|x| x / len)
                } else {
                    [0.0, 0.0, 1.0]
                }
            })
            .collect()
    }
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

/// [`CHORD_TOLERANCE`] times the diagonal of the surface's control bounding box (which
/// contains the surface).
pub fn surface_tolerance(surface: &Surface) -> f64 {
    CHORD_TOLERANCE * diagonal(&surface.control_bounding_box())
}

/// The breakpoints of one direction's domain (its ends and interior knots) and the midpoints
/// between them: where the iso-parameter curves of [`adaptive_surface_parameters`] are taken.
fn iso_stations(knots: &crate::KnotVector) -> Vec<f64> {
    let domain = knots.domain();
    let mut breaks = vec![domain.start];
    breaks.extend(knots.interior_breakpoints());
    breaks.push(domain.end);
    let mut out = Vec::with_capacity(2 * breaks.len());
    for w in breaks.windows(2) {
        out.push(w[0]);
        out.push(0.5 * (w[0] + w[1]));
    }
    out.push(domain.end);
    out.dedup();
    out
}

/// The u and v parameters of a surface grid whose iso-parameter lines are sampled to
/// `tolerance`: for each direction, the union of the [`adaptive_parameters`] of the surface's
/// iso-parameter curves along it, taken at the other direction's knots and the midpoints
/// between them.
///
/// Along those curves the polylines of the grid are within `tolerance` of the surface; between
/// them the grid is as fine as the finest of them, which makes the triangles follow the
/// surface to about the same tolerance (an estimate, not a bound as for curves).
///
/// # Errors
/// Only if the surface cannot be evaluated at its own knots ([`EvalError`]).
pub fn adaptive_surface_parameters(
    surface: &Surface,
    tolerance: f64,
) -> Result<[Vec<f64>; 2], EvalError> {
    let mut out: [Vec<f64>; 2] = [Vec::new(), Vec::new()];
    // Along u: curves at fixed v; along v: curves at fixed u.
    for (k, fixed, knots) in [
        (0, Direction::V, surface.knots_v()),
        (1, Direction::U, surface.knots_u()),
    ] {
        let mut all = Vec::new();
        for value in iso_stations(knots) {
            all.extend(adaptive_parameters(
                &surface.iso_curve(fixed, value)?,
                tolerance,
            ));
        }
        all.sort_by(f64::total_cmp);
        all.dedup();
        out[k] = all;
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{example1, BSpline, ControlPoint, Degrees, KnotVector, Nurbs, SurfaceKind};

    fn max_chord_error<const D: usize>(curve: &AnyCurve<D>, ts: &[f64]) -> f64 {
        // Dense check between consecutive parameters.
        let mut worst: f64 = 0.0;
        for w in ts.windows(2) {
            let (a, b) = (
                curve.evaluate(w[0]).unwrap().position,
                curve.evaluate(w[1]).unwrap().position,
            );
            for k in 1..50 {
                let t = w[0] + (w[1] - w[0]) * f64::from(k) / 50.0;
                let p = curve.evaluate(t).unwrap().position;
                worst = worst.max(segment_distance(&p, &a, &b));
            }
        }
        worst
    }

    #[test]
    fn uniform_parameters_match_uniform_parameter() {
        assert_eq!(uniform_parameters(0.0..1.0, 5), [0.0, 0.25, 0.5, 0.75, 1.0]);
        assert_eq!(uniform_parameters(2.0..3.0, 1), [2.0]);
        assert!(uniform_parameters(0.0..1.0, 0).is_empty());
    }

    #[test]
    fn adaptive_bezier_is_within_tolerance() {
        let curve = AnyCurve::from(example1());
        let tolerance = chord_tolerance(&curve);
        // Diagonal of the tight box: x in [1, 9], y in about [3, 4.19..5].
        assert!((tolerance - 1e-3 * (64.0f64 + 4.0).sqrt()).abs() < 1e-5);
        let ts = adaptive_parameters(&curve, tolerance);
        assert!(ts.len() > 8 && ts.len() < 100, "{}", ts.len());
        assert!(max_chord_error(&curve, &ts) <= tolerance);
        // Coarser tolerance, fewer points; a straight line needs none inside.
        assert!(adaptive_parameters(&curve, 10.0 * tolerance).len() < ts.len());
        let p = |x| ControlPoint::new([x, 2.0 * x], Degrees::new(0.5, 0.5, 0.5).unwrap());
        let line = AnyCurve::from(crate::Bezier::new(vec![p(0.0), p(1.0), p(3.0)]).unwrap());
        assert_eq!(adaptive_parameters(&line, 0.0), [0.0, 1.0]);
    }

    #[test]
    fn adaptive_spline_keeps_knots_and_tolerance() {
        let d = Degrees::new(0.2, 0.3, 0.4).unwrap();
        let points: Vec<_> = [[0.0, 0.0], [1.0, 3.0], [2.0, -1.0], [4.0, 2.0], [5.0, 0.0]]
            .into_iter()
            .map(|p| ControlPoint::new(p, d))
            .collect();
        let knots = KnotVector::new(vec![0.0, 0.0, 0.0, 0.3, 0.7, 1.0, 1.0, 1.0], 2, 5).unwrap();
        let curve = AnyCurve::from(BSpline::new(points.clone(), knots.clone()).unwrap());
        let tolerance = chord_tolerance(&curve);
        let ts = adaptive_parameters(&curve, tolerance);
        assert!(ts.contains(&0.3) && ts.contains(&0.7));
        assert!(max_chord_error(&curve, &ts) <= tolerance);
        let weights = vec![1.0, 4.0, 0.5, 2.0, 1.0];
        let rational = AnyCurve::from(Nurbs::new(points, weights, knots).unwrap());
        let tolerance = chord_tolerance(&rational);
        let ts = adaptive_parameters(&rational, tolerance);
        assert!(max_chord_error(&rational, &ts) <= tolerance);
        assert_eq!((ts[0], *ts.last().unwrap()), (0.0, 1.0));
    }

    #[test]
    fn adaptive_depth_is_bounded() {
        let curve = AnyCurve::from(example1());
        let ts = adaptive_parameters(&curve, 0.0);
        // Almost every piece is cut to the deepest level (a few tiny ones come out exactly
        // straight in floating point first).
        assert!(ts.len() <= (1 << MAX_SUBDIVISION_DEPTH) + 1);
        assert!(ts.len() > (1 << (MAX_SUBDIVISION_DEPTH - 1)));
        assert!(ts.windows(2).all(|w| w[0] < w[1]));
    }

    fn bilinear_with_collapsed_edge() -> Surface {
        // Row 0 collapses to the apex (0, 0, 1): a cone-like patch.
        let d = Degrees::new(0.5, 0.25, 0.0).unwrap();
        let grid = [
            [0.0, 0.0, 1.0],
            [0.0, 0.0, 1.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
        ]
        .map(|p| ControlPoint::new(p, d));
        Surface::bezier(2, 2, grid.to_vec()).unwrap()
    }

    #[test]
    fn surface_grid_normals_and_triangles() {
        let surface = bilinear_with_collapsed_edge();
        let grid = SurfaceGrid::new(
            &surface,
            uniform_parameters(0.0..1.0, 3),
            uniform_parameters(0.0..1.0, 3),
        )
        .unwrap();
        assert_eq!(grid.points().len(), 9);
        assert_eq!(grid.points()[8].position, [0.0, 1.0, 0.0]);
        for n in grid.normals() {
            let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            assert!((len - 1.0).abs() < 1e-12);
        }
        // The apex row has no surface normal: the mesh gives one facing the same way as the
        // plane x + y + z = 1's side of the other normals.
        assert!(surface.normal(0.0, 0.5).unwrap().is_none());
        let apex = grid.normals()[1];
        let other = grid.normals()[7];
        assert!(apex[0] * other[0] + apex[1] * other[1] + apex[2] * other[2] > 0.5);
        // 2 x 2 cells, the two triangles at the apex row with two apex points left out.
        let triangles = grid.triangles();
        assert_eq!(triangles.len(), 6);
        for t in &triangles {
            let [a, b, c] = t.map(|k| grid.points()[k].position);
            let n = cross(sub(b, a), sub(c, a));
            let m = grid.normals()[t[0]];
            assert!(
                n[0] * m[0] + n[1] * m[1] + n[2] * m[2] > 0.0,
                "winding of {t:?}"
            );
        }
    }

    #[test]
    fn adaptive_surface_grid_follows_the_knots() {
        // Quadratic along u with an interior knot at 0.5, straight along v.
        let d = Degrees::new(0.5, 0.25, 0.0).unwrap();
        let grid: Vec<_> = (0..4)
            .flat_map(|i| {
                let z = [0.0, 2.0, -1.0, 0.5][i];
                (0..2).map(move |j| ControlPoint::new([i as f64, j as f64, z], d))
            })
            .collect();
        let knots_u = KnotVector::new(vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0], 2, 4).unwrap();
        let knots_v = KnotVector::clamped_uniform(1, 2).unwrap();
        let surface = Surface::bspline(4, 2, grid, knots_u, knots_v).unwrap();
        let tolerance = surface_tolerance(&surface);
        let [u, v] = adaptive_surface_parameters(&surface, tolerance).unwrap();
        assert_eq!(surface.kind(), SurfaceKind::BSpline);
        assert!(u.contains(&0.5), "the interior knot along u");
        assert_eq!((u[0], *u.last().unwrap()), (0.0, 1.0));
        assert_eq!(v, [0.0, 1.0], "straight along v");
    }
}
