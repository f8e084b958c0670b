//! The nearest point of a surface: branch and bound on the Bernstein coefficients of the
//! squared distance of its Bézier patches, then a projected Newton iteration.

use super::{box_distance, distance, Best, Candidate, NearestError, TIE_TOLERANCE};
use crate::bernstein_scalar::{binomial, halves};
use crate::curve::ControlPolygon;
use crate::point::CurvePoint;
use crate::spline_curve::Nurbs;
use crate::surface::{EvaluateSurface, Surface};

/// A start of Newton's method: the lower bound of its piece, the point `[u, v]`, and the patch
/// `[[u0, u1], [v0, v1]]` it belongs to.
type Start = (f64, [f64; 2], [[f64; 2]; 2]);

/// The nearest point of a surface to a query point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceNearest {
    /// The parameters `[u, v]` of the nearest point (the smallest `u`, then `v`, when several
    /// points are equally near, to within [`TIE_TOLERANCE`] of the surface's size).
    pub parameter: [f64; 2],
    /// The Euclidean distance from the query point to [`SurfaceNearest::point`].
    pub distance: f64,
    /// The surface's point at [`SurfaceNearest::parameter`], with its degrees.
    pub point: CurvePoint<3>,
}

/// A (rational) Bézier patch of a surface on `[u0, u1] x [v0, v1]`.
#[derive(Clone, Debug)]
struct Patch {
    u: [f64; 2],
    v: [f64; 2],
    /// `(p + 1) x (q + 1)` positions, row-major (row index along u).
    points: Vec<[f64; 3]>,
    weights: Option<Vec<f64>>,
    p: usize,
    q: usize,
    low: [f64; 3],
    high: [f64; 3],
    /// Coefficients of `w^2` in degrees `(2p, 2q)`, row-major (all 1 without weights).
    denominator: Vec<f64>,
    /// The ends `[u1, v1]` reached only as limits from below: the surface jumps there (a knot
    /// of multiplicity degree + 1 inside the domain) and takes the value beyond.
    jump: [bool; 2],
}

impl Patch {
    /// The parameter of the patch's far edge in direction `c` (0: u, 1: v): the edge, or the
    /// float below it where the surface jumps.
    fn far(&self, c: usize) -> f64 {
        let range = if c == 0 { self.u } else { self.v };
        if self.jump[c] {
            range[1].next_down()
        } else {
            range[1]
        }
    }
}

/// Whether a surface with these knots jumps at `x`: an interior knot of multiplicity
/// degree + 1.
fn jumps_at(knots: &crate::knots::KnotVector, x: f64) -> bool {
    let domain = knots.domain();
    x < domain.end && knots.knots().iter().filter(|&&k| k == x).count() > knots.degree()
}

/// Tensor-product product weights `C(n,i) C(n,j) / C(2n,i+j)` of one direction.
fn product_table(n: usize) -> Vec<f64> {
    let mut t = vec![0.0; (n + 1) * (n + 1)];
    for i in 0..=n {
        for j in 0..=n {
            t[i * (n + 1) + j] = binomial(n, i) * binomial(n, j) / binomial(2 * n, i + j);
        }
    }
    t
}

/// A surface prepared for nearest-point queries: its Bézier patches with their bounding
/// boxes. Queries take `&self` and may run on many threads at once.
///
/// The squared distance on a patch is the tensor-product quotient
/// `sum_kl B_{2p,k}(u) B_{2q,l}(v) a_kl / sum_kl B_{2p,k}(u) B_{2q,l}(v) b_kl`, bounded by the
/// extreme ratios `a_kl / b_kl`: patches and their halves (split across the longer side) are
/// pruned when the lower bound exceeds the best distance, down to 1/64 of a patch per side;
/// from each surviving piece a projected Newton iteration on the squared distance (gradient
/// and Hessian from [`Surface::mixed_partials`], coordinates held on the domain's edges when
/// the gradient points out) finds the minimum.
///
/// ```
/// use neutrospline::{ControlPoint, Degrees, Surface};
/// let d = Degrees::new(0.5, 0.25, 0.0)?;
/// let grid = [[0.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0]]
///     .map(|p| ControlPoint::new(p, d));
/// let square = Surface::bezier(2, 2, grid.to_vec())?;
/// let near = square.nearest([0.25, 0.5, 2.0])?;
/// assert_eq!(near.parameter, [0.25, 0.5]);
/// assert_eq!(near.distance, 2.0);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Debug)]
pub struct SurfaceProjector<'a> {
    surface: &'a Surface,
    patches: Vec<Patch>,
    tie: f64,
    table_u: Vec<f64>,
    table_v: Vec<f64>,
}

/// Subdivisions of a patch per side before Newton's method takes over (1/64 of the patch).
const SURFACE_DEPTH: usize = 12;

impl Surface {
    /// The nearest point of the surface to `point` (see [`SurfaceProjector`]).
    ///
    /// # Errors
    /// A coordinate of `point` not finite; [`NearestError::Overflow`].
    pub fn nearest(&self, point: [f64; 3]) -> Result<SurfaceNearest, NearestError> {
        self.projector().nearest(point)
    }

    /// The surface prepared for many nearest-point queries.
    pub fn projector(&self) -> SurfaceProjector<'_> {
        SurfaceProjector::new(self)
    }

    /// The Bézier patches: each row's curve along v cut into its pieces, then each column
    /// of those pieces along u.
    fn bezier_patches(&self) -> Vec<Patch> {
        let weights = self.weights();
        let rational = weights.is_some();
        let rows: Vec<Vec<BezierSegmentParts>> = (0..self.rows())
            .map(|i| {
                let points: Vec<_> = (0..self.cols()).map(|j| self.control_point(i, j)).collect();
                let w: Vec<f64> = (0..self.cols())
                    .map(|j| weights.map_or(1.0, |w| w[i * self.cols() + j]))
                    .collect();
                segment_parts(points, w, self.knots_v().clone())
            })
            .collect();
        let q = self.degree_v();
        let p = self.degree_u();
        let mut patches = Vec::new();
        let v_pieces = rows[0].len();
        let mut columns: Vec<Vec<Vec<BezierSegmentParts>>> = Vec::with_capacity(v_pieces);
        for jp in 0..v_pieces {
            let mut per_b = Vec::with_capacity(q + 1);
            for b in 0..=q {
                let points = rows.iter().map(|r| r[jp].points[b]).collect();
                let w = rows.iter().map(|r| r[jp].weights[b]).collect();
                per_b.push(segment_parts(points, w, self.knots_u().clone()));
            }
            columns.push(per_b);
        }
        for (jp, per_b) in columns.iter().enumerate() {
            let v = [rows[0][jp].start, rows[0][jp].end];
            for ip in 0..per_b[0].len() {
                let u = [per_b[0][ip].start, per_b[0][ip].end];
                let mut points = Vec::with_capacity((p + 1) * (q + 1));
                let mut w = Vec::with_capacity((p + 1) * (q + 1));
                for a in 0..=p {
                    for b in 0..=q {
                        points.push(per_b[b][ip].points[a].position);
                        w.push(per_b[b][ip].weights[a]);
                    }
                }
                let weights = rational.then_some(w);
                let (low, high) = bounds(&points);
                let denominator = squared_weight(weights.as_deref(), p, q);
                let jump = [
                    jumps_at(self.knots_u(), u[1]),
                    jumps_at(self.knots_v(), v[1]),
                ];
                patches.push(Patch {
                    u,
                    v,
                    points,
                    weights,
                    p,
                    q,
                    low,
                    high,
                    denominator,
                    jump,
                });
            }
        }
        patches
    }
}

/// A rational Bézier piece with its control points (degrees included) and weights.
struct BezierSegmentParts {
    start: f64,
    end: f64,
    points: Vec<crate::point::ControlPoint<3>>,
    weights: Vec<f64>,
}

/// The Bézier pieces of the curve with these control points and weights over `knots`.
fn segment_parts(
    points: Vec<crate::point::ControlPoint<3>>,
    weights: Vec<f64>,
    knots: crate::knots::KnotVector,
) -> Vec<BezierSegmentParts> {
    // The data comes from a valid surface, so the curve is valid.
    let curve = Nurbs::new(points, weights, knots)
        .unwrap_or_else(|e| unreachable!("a surface's rows are valid curves: {e}"));
    curve
        .to_bezier_segments()
        .into_iter()
        .map(|s| BezierSegmentParts {
            start: s.start,
            end: s.end,
            points: s.curve.control_points(),
            weights: s.curve.weights().map_or_else(Vec::new, <[f64]>::to_vec),
        })
        .collect()
}

/// The bounding box `(low, high)` of `points`.
fn bounds(points: &[[f64; 3]]) -> ([f64; 3], [f64; 3]) {
    let mut low = [f64::INFINITY; 3];
    let mut high = [f64::NEG_INFINITY; 3];
    for pt in points {
        for a in 0..3 {
            low[a] = low[a].min(pt[a]);
            high[a] = high[a].max(pt[a]);
        }
    }
    (low, high)
}

/// [`Patch::denominator`] of a patch of degrees `(p, q)` with these weights (row-major, or
/// none): the coefficients of `w^2`, the weights scaled by the largest.
fn squared_weight(weights: Option<&[f64]>, p: usize, q: usize) -> Vec<f64> {
    let (tu, tv) = (product_table(p), product_table(q));
    let (nu, nv) = (2 * p + 1, 2 * q + 1);
    let mut denominator = vec![0.0; nu * nv];
    match weights {
        None => denominator.iter_mut().for_each(|b| *b = 1.0),
        Some(w) => {
            let top = w.iter().fold(0.0_f64, |m, &x| m.max(x));
            for i in 0..=p {
                for j in 0..=q {
                    for k in 0..=p {
                        for l in 0..=q {
                            denominator[(i + k) * nv + j + l] += tu[i * (p + 1) + k]
                                * tv[j * (q + 1) + l]
                                * (w[i * (q + 1) + j] / top)
                                * (w[k * (q + 1) + l] / top);
                        }
                    }
                }
            }
        }
    }
    denominator
}

impl<'a> SurfaceProjector<'a> {
    /// Extracts and prepares the patches of `surface`.
    pub fn new(surface: &'a Surface) -> Self {
        let patches = surface.bezier_patches();
        let b = surface.control_bounding_box();
        let size = b
            .position
            .iter()
            .map(|i| i.length().powi(2))
            .sum::<f64>()
            .sqrt();
        SurfaceProjector {
            surface,
            table_u: product_table(surface.degree_u()),
            table_v: product_table(surface.degree_v()),
            patches,
            tie: TIE_TOLERANCE * if size.is_finite() { size } else { f64::MAX },
        }
    }

    /// The nearest point of the surface to `point`: the global minimum of the distance over
    /// the whole domain, edges included; ties (within [`TIE_TOLERANCE`] of the surface's size)
    /// go to the smallest `u`, then `v`.
    ///
    /// # Errors
    /// A coordinate of `point` not finite; [`NearestError::Overflow`].
    pub fn nearest(&self, point: [f64; 3]) -> Result<SurfaceNearest, NearestError> {
        if let Some(axis) = point.iter().position(|x| !x.is_finite()) {
            return Err(NearestError::PointNotFinite {
                axis,
                value: point[axis],
            });
        }
        let mut best = Best::new(self.tie);
        let mut bounds = Vec::with_capacity(self.patches.len());
        for patch in &self.patches {
            let (p, q) = (patch.p, patch.q);
            for (a, b) in [(0, 0), (0, q), (p, 0), (p, q)] {
                let d = distance(&patch.points[a * (q + 1) + b], &point);
                if !d.is_finite() {
                    return Err(NearestError::Overflow);
                }
                let uv = [
                    if a == 0 { patch.u[0] } else { patch.far(0) },
                    if b == 0 { patch.v[0] } else { patch.far(1) },
                ];
                best.offer(Candidate {
                    at: uv,
                    distance: d,
                });
            }
            bounds.push(box_distance(&patch.low, &patch.high, &point));
        }
        let mut order: Vec<usize> = (0..self.patches.len()).collect();
        order.sort_by(|&a, &b| bounds[a].total_cmp(&bounds[b]));
        let mut starts = Vec::new();
        for k in order {
            if bounds[k] > best.limit() {
                break;
            }
            self.search_patch(&self.patches[k], &point, &mut best, &mut starts)?;
        }
        // Newton's method from the surviving pieces whose bound can still beat the best.
        for (lower, start, patch) in starts {
            if lower <= best.limit() {
                if let Some(c) = self.newton(start, &point, patch) {
                    best.offer(c);
                }
            }
        }
        let chosen = best.choice().ok_or(NearestError::Overflow)?;
        let [du, dv] = self.surface.domain();
        let uv = [
            chosen.at[0].clamp(du.start, du.end),
            chosen.at[1].clamp(dv.start, dv.end),
        ];
        let found = self.surface.evaluate(uv[0], uv[1])?;
        let distance = distance(&found.position, &point);
        if !distance.is_finite() {
            return Err(NearestError::Overflow);
        }
        Ok(SurfaceNearest {
            parameter: uv,
            distance,
            point: found,
        })
    }

    /// Branch and bound over one patch: offers the corners of the pieces it visits, and
    /// collects the pieces Newton's method starts from (`(lower bound, [u, v])`).
    fn search_patch(
        &self,
        patch: &Patch,
        point: &[f64; 3],
        best: &mut Best<[f64; 2]>,
        starts: &mut Vec<Start>,
    ) -> Result<(), NearestError> {
        let (p, q) = (patch.p, patch.q);
        let top = patch
            .weights
            .as_ref()
            .map_or(1.0, |w| w.iter().fold(0.0_f64, |m, &x| m.max(x)));
        let mut largest = 0.0_f64;
        let mut diffs: Vec<[f64; 3]> = patch
            .points
            .iter()
            .map(|pt| {
                let d = [pt[0] - point[0], pt[1] - point[1], pt[2] - point[2]];
                largest = largest.max(d[0].abs()).max(d[1].abs()).max(d[2].abs());
                d
            })
            .collect();
        if !largest.is_finite() {
            return Err(NearestError::Overflow);
        }
        if largest == 0.0 {
            best.offer(Candidate {
                at: [patch.u[0], patch.v[0]],
                distance: 0.0,
            });
            return Ok(());
        }
        let scale = 2.0_f64.powi(largest.log2().ceil() as i32);
        for (k, d) in diffs.iter_mut().enumerate() {
            let w = patch.weights.as_ref().map_or(1.0, |w| w[k] / top);
            for x in d.iter_mut() {
                *x = *x / scale * w;
            }
        }
        let nv = 2 * q + 1;
        let mut numerator = vec![0.0; (2 * p + 1) * nv];
        for i in 0..=p {
            for j in 0..=q {
                let a = diffs[i * (q + 1) + j];
                for k in 0..=p {
                    for l in 0..=q {
                        let b = diffs[k * (q + 1) + l];
                        numerator[(i + k) * nv + j + l] += self.table_u[i * (p + 1) + k]
                            * self.table_v[j * (q + 1) + l]
                            * (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
                    }
                }
            }
        }
        let to_distance = |ratio: f64| ratio.max(0.0).sqrt() * scale;
        let mut stack = vec![(
            numerator,
            patch.denominator.clone(),
            [0.0, 1.0],
            [0.0, 1.0],
            0,
        )];
        let global = |x: f64, range: [f64; 2]| {
            if x <= 0.0 {
                range[0]
            } else if x >= 1.0 {
                range[1]
            } else {
                range[0] + (range[1] - range[0]) * x
            }
        };
        // The rounding error of the coefficients, as for curves (`search_piece`): scaled
        // differences of size at most 1, the products of binomials of a coefficient summing
        // to 1, one rounding per halving. The lower bound is lowered by it, so that a patch is
        // never pruned on rounding noise.
        let rounding = |depth: usize| (2 * (p + q) + 3 + 4 + 2 * depth) as f64 * f64::EPSILON;
        while let Some((a, b, su, sv, depth)) = stack.pop() {
            let slack = rounding(depth);
            let (low, high) = a
                .iter()
                .zip(&b)
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), (x, y)| {
                    (l.min(x / y - slack), h.max(x / y + slack))
                });
            let lower = to_distance(low);
            if lower > best.limit() {
                continue;
            }
            let (mu, mv) = (2 * p + 1, nv);
            // The corners' coefficients are the values there: upper bounds of the minimum.
            for k in [0, mv - 1, (mu - 1) * mv, mu * mv - 1] {
                best.bound = best.bound.min(to_distance(a[k] / b[k]));
            }
            let known = best.min.min(best.bound);
            if lower >= known - best.tie && to_distance(high) <= known + best.tie {
                // Every point of the piece ties with the best: its first corner is offered.
                let uv = [global(su[0], patch.u), global(sv[0], patch.v)];
                let s = self.surface.evaluate(uv[0], uv[1])?;
                best.offer(Candidate {
                    at: uv,
                    distance: distance(&s.position, point),
                });
                continue;
            }
            if depth >= SURFACE_DEPTH {
                let centre = [
                    global(0.5 * (su[0] + su[1]), patch.u),
                    global(0.5 * (sv[0] + sv[1]), patch.v),
                ];
                starts.push((lower, centre, [patch.u, patch.v]));
                continue;
            }
            // Split across u at even depths, across v at odd ones.
            let (first, second) = if depth % 2 == 0 {
                let (l, r) = split_grid(&a, mu, mv, true);
                let (bl, br) = split_grid(&b, mu, mv, true);
                let mid = 0.5 * (su[0] + su[1]);
                ((l, bl, [su[0], mid], sv), (r, br, [mid, su[1]], sv))
            } else {
                let (l, r) = split_grid(&a, mu, mv, false);
                let (bl, br) = split_grid(&b, mu, mv, false);
                let mid = 0.5 * (sv[0] + sv[1]);
                ((l, bl, su, [sv[0], mid]), (r, br, su, [mid, sv[1]]))
            };
            stack.push((second.0, second.1, second.2, second.3, depth + 1));
            stack.push((first.0, first.1, first.2, first.3, depth + 1));
        }
        Ok(())
    }

    /// Projected Newton on `f(u, v) = |S(u, v) - P|^2` from `start`, inside the start's patch
    /// `[u0, u1] x [v0, v1]`: a coordinate on an edge of the patch whose gradient points out
    /// stays there. Each step must decrease `f` (halved up to 40 times); `None` if the surface
    /// cannot be evaluated.
    fn newton(
        &self,
        start: [f64; 2],
        point: &[f64; 3],
        patch: [[f64; 2]; 2],
    ) -> Option<Candidate<[f64; 2]>> {
        // Inside the start's patch, where the surface is smooth: across a knot of full
        // multiplicity minus one (a crease) the gradient jumps, and a minimum on the crease is
        // the minimum on the patch's edge, of one patch or the other.
        let lo = [patch[0][0], patch[1][0]];
        let hi = [patch[0][1], patch[1][1]];
        let value = |uv: [f64; 2]| -> Option<f64> {
            let s = self.surface.evaluate(uv[0], uv[1]).ok()?;
            Some(distance(&s.position, point))
        };
        let mut x = start;
        let mut fx = value(x)?;
        for _ in 0..60 {
            let s = self.surface.evaluate(x[0], x[1]).ok()?.position;
            let first = self.surface.mixed_partials(x[0], x[1], 1).ok()?;
            let second = self.surface.mixed_partials(x[0], x[1], 2).ok()?;
            let r = [s[0] - point[0], s[1] - point[1], s[2] - point[2]];
            let dot = |a: &[f64; 3], b: &[f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
            let (su, sv) = (first[0].position, first[1].position);
            let g = [dot(&r, &su), dot(&r, &sv)];
            let h = [
                [
                    dot(&su, &su) + dot(&r, &second[0].position),
                    dot(&su, &sv) + dot(&r, &second[1].position),
                ],
                [0.0, dot(&sv, &sv) + dot(&r, &second[2].position)],
            ];
            let h = [[h[0][0], h[0][1]], [h[0][1], h[1][1]]];
            // Coordinates held on an edge where the gradient points out of the domain.
            let held: [bool; 2] = core::array::from_fn(|c| {
                (x[c] <= lo[c] && g[c] > 0.0) || (x[c] >= hi[c] && g[c] < 0.0)
            });
            let mut step = [0.0; 2];
            match held {
                [true, true] => break,
                [true, false] | [false, true] => {
                    let c = if held[0] { 1 } else { 0 };
                    let tangent = if c == 0 { dot(&su, &su) } else { dot(&sv, &sv) };
                    step[c] = if h[c][c] > 0.0 {
                        -g[c] / h[c][c]
                    } else {
                        // Not convex here: a gradient step scaled by the edge's speed (an
                        // unscaled one is in the wrong units, 1e-10 of the edge on a surface
                        // 1e-5 in size, and stalls at once).
                        -g[c] / h[c][c].abs().max(tangent).max(f64::MIN_POSITIVE)
                    };
                }
                [false, false] => {
                    let det = h[0][0] * h[1][1] - h[0][1] * h[1][0];
                    if h[0][0] > 0.0 && det > 0.0 {
                        step = [
                            -(h[1][1] * g[0] - h[0][1] * g[1]) / det,
                            -(h[0][0] * g[1] - h[1][0] * g[0]) / det,
                        ];
                    } else {
                        // Not convex here: a gradient step scaled by the diagonal.
                        step = [
                            -g[0] / h[0][0].abs().max(dot(&su, &su)).max(f64::MIN_POSITIVE),
                            -g[1] / h[1][1].abs().max(dot(&sv, &sv)).max(f64::MIN_POSITIVE),
                        ];
                    }
                }
            }
            let mut scale = 1.0;
            let mut moved = false;
            for _ in 0..40 {
                let next: [f64; 2] =
                    core::array::from_fn(|c| (x[c] + scale * step[c]).clamp(lo[c], hi[c]));
                if next == x {
                    break;
                }
                let fnext = value(next)?;
                if fnext <= fx {
                    let small = (0..2).all(|c| {
                        (next[c] - x[c]).abs()
                            <= 4.0 * f64::EPSILON * (hi[c] - lo[c]).max(x[c].abs())
                    });
                    x = next;
                    fx = fnext;
                    moved = !small;
                    break;
                }
                scale *= 0.5;
            }
            if !moved {
                break;
            }
        }
        Some(Candidate {
            at: x,
            distance: fx,
        })
    }
}

/// Splits a `rows x cols` grid of Bernstein coefficients at 1/2 across rows (`along_u`) or
/// columns.
fn split_grid(c: &[f64], rows: usize, cols: usize, along_u: bool) -> (Vec<f64>, Vec<f64>) {
    let mut left = vec![0.0; c.len()];
    let mut right = vec![0.0; c.len()];
    let (mut l, mut r) = (Vec::new(), Vec::new());
    if along_u {
        let mut line = vec![0.0; rows];
        for j in 0..cols {
            for i in 0..rows {
                line[i] = c[i * cols + j];
            }
            halves(&line, &mut l, &mut r);
            for i in 0..rows {
                left[i * cols + j] = l[i];
                right[i * cols + j] = r[i];
            }
        }
    } else {
        for i in 0..rows {
            halves(&c[i * cols..(i + 1) * cols], &mut l, &mut r);
            left[i * cols..(i + 1) * cols].copy_from_slice(&l);
            right[i * cols..(i + 1) * cols].copy_from_slice(&r);
        }
    }
    (left, right)
}

#[cfg(feature = "parallel")]
impl SurfaceProjector<'_> {
    /// The nearest points to every point of `points`, in order (on rayon's threads: the
    /// `parallel` feature is on).
    pub fn nearest_many(&self, points: &[[f64; 3]]) -> Vec<Result<SurfaceNearest, NearestError>> {
        use rayon::prelude::*;
        points.par_iter().map(|p| self.nearest(*p)).collect()
    }
}

#[cfg(not(feature = "parallel"))]
impl SurfaceProjector<'_> {
    /// The nearest points to every point of `points`, in order (on the calling thread; with
    /// the `parallel` feature on rayon's threads).
    pub fn nearest_many(&self, points: &[[f64; 3]]) -> Vec<Result<SurfaceNearest, NearestError>> {
        points.iter().map(|p| self.nearest(*p)).collect()
    }
}
