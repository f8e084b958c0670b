//! Intersections of plane curves of any kinds: Bézier subdivision on the curves' pieces with
//! a Newton polish (as dhermes/bezier does), tangential and end-point intersections included,
//! overlapping pieces reported as such. See `docs/model.md`, section 11.

use core::ops::Range;

use crate::curve::{Derivative, EvalError, Evaluate};
use crate::derivative::CurveDerivative;
use crate::nearest::{distance_to_piece, NearestPoint, Piece};
use crate::point::CurvePoint;

/// A point where two curves meet.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Intersection {
    /// The parameter on the first curve.
    pub parameter_a: f64,
    /// The parameter on the second curve.
    pub parameter_b: f64,
    /// The first curve's point at [`Intersection::parameter_a`] (position and degrees).
    pub point_a: CurvePoint<2>,
    /// The second curve's point at [`Intersection::parameter_b`].
    pub point_b: CurvePoint<2>,
}

/// Why the intersections cannot be listed.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum IntersectError {
    /// A stretch of one curve lies on the other: the curves share infinitely many points.
    #[error("the curves overlap: t_a in [{}, {}] lies on the other curve (t_b in [{}, {}]), so they meet in infinitely many points", a.start, a.end, b.start, b.end)]
    Overlap {
        /// The overlapping parameters of the first curve.
        a: Range<f64>,
        /// The matching parameters of the second curve.
        b: Range<f64>,
    },
    /// A curve cannot be evaluated (its values overflow).
    #[error(transparent)]
    Eval(#[from] EvalError),
}

/// Sub-pieces smaller than this fraction of the curves' size are polished by Newton's method.
const SMALL: f64 = 1e-7;
/// The deepest subdivision of a piece.
const MAX_DEPTH: usize = 60;
/// Pairs of sub-pieces alive at one time beyond which overlap is suspected and checked.
const CROWD: usize = 4096;
/// Intersections closer than this (in each parameter, relative to its domain) are one.
const SAME: f64 = 1e-9;

/// Intersections of plane curves.
///
/// Every point where `a` and `b` meet, ordered by the parameter on `a`: the pieces of both
/// curves (one per Bézier piece) are paired; a pair whose control-point boxes do not overlap
/// cannot meet (convex hull property) and is dropped, any other has its larger piece split at
/// its middle (de Casteljau), until both are smaller than 1e-7 of the curves' size. From
/// there Newton's method on `A(s) - B(t) = 0` polishes each candidate; where the curves are
/// tangent (the Jacobian `[A', -B']` nearly singular) the tangency system
/// `A'(s) x B'(t) = 0`, `(A(s) - B(t)) . A'(s) = 0` is solved instead, and the point is kept
/// when the curves are within 1e-12 of their size there. Tangential and end-point
/// intersections are included, each reported once (a root within 1e-9 of an end of a domain
/// is put on the end when the curves meet there; on a closed curve, whose end is its start, a
/// root at the end is reported at the start). When the pairs crowd (more than 4,096
/// alive), the pairs whose first sub-piece lies on the second (nine points within 1e-9 of the
/// size, by the branch and bound of [`NearestPoint`]) are counted; if they are at least a
/// quarter, the stretch they span is reported as [`IntersectError::Overlap`].
///
/// For the self-intersections of one curve use [`self_intersections`].
///
/// ```
/// use neutrospline::{intersections, Bezier, ControlPoint, Degrees};
/// let d = Degrees::new(0.5, 0.25, 0.0)?;
/// let line = |p: [f64; 2], q: [f64; 2]| Bezier::new(vec![ControlPoint::new(p, d), ControlPoint::new(q, d)]);
/// let a = line([0.0, 0.0], [2.0, 2.0])?;
/// let b = line([0.0, 2.0], [2.0, 0.0])?;
/// let found = intersections(&a, &b)?;
/// assert_eq!(found.len(), 1);
/// assert_eq!((found[0].parameter_a, found[0].parameter_b), (0.5, 0.5));
/// assert_eq!(found[0].point_a.position, [1.0, 1.0]);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// [`IntersectError::Overlap`] when the curves share a stretch; [`IntersectError::Eval`] when
/// a curve's values overflow.
pub fn intersections<A, B>(a: &A, b: &B) -> Result<Vec<Intersection>, IntersectError>
where
    A: NearestPoint<2> + Derivative<Output = CurveDerivative<2>>,
    B: NearestPoint<2> + Derivative<Output = CurveDerivative<2>>,
{
    Search::new(a, b, false).run()
}

/// The self-intersections of a plane curve: every pair of parameters `t_a < t_b` where the
/// curve passes through the same point, ordered by `t_a`, each once (the loop of a cubic). A
/// closed curve (its end is its start) is not self-intersecting at its seam. As [`intersections`], with sub-pieces that cannot
/// cross themselves skipped: a piece whose control-point differences `P_j - P_i` (`i < j`)
/// all lie in an open half-plane moves monotonically in one direction.
///
/// ```
/// use neutrospline::{self_intersections, Bezier, ControlPoint, Degrees};
/// let d = Degrees::new(0.5, 0.25, 0.0)?;
/// // A cubic with a loop: it crosses itself at x = 1.5.
/// let loop_ = Bezier::new([[0.0, 0.0], [4.0, 2.0], [-1.0, 2.0], [3.0, 0.0]]
///     .map(|p| ControlPoint::new(p, d)).to_vec())?;
/// let found = self_intersections(&loop_)?;
/// assert_eq!(found.len(), 1);
/// assert!((found[0].parameter_a + found[0].parameter_b - 1.0).abs() < 1e-12); // symmetric
/// assert!((found[0].point_a.position[0] - 1.5).abs() < 1e-12);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// As [`intersections`].
pub fn self_intersections<A>(a: &A) -> Result<Vec<Intersection>, IntersectError>
where
    A: NearestPoint<2> + Derivative<Output = CurveDerivative<2>>,
{
    Search::new(a, a, true).run()
}

/// A sub-piece: homogeneous control data, and its parameters on the curve.
#[derive(Clone, Debug)]
struct Sub {
    points: Vec<[f64; 2]>,
    weights: Option<Vec<f64>>,
    range: [f64; 2],
    low: [f64; 2],
    high: [f64; 2],
    depth: usize,
    /// The index of the piece it came from (self-intersections: adjacency).
    piece: usize,
}

impl Sub {
    fn new(piece: &Piece<2>, index: usize) -> Sub {
        Sub::with(
            piece.points.clone(),
            piece.weights.clone(),
            [piece.start, piece.end],
            0,
            index,
        )
    }

    fn with(
        points: Vec<[f64; 2]>,
        weights: Option<Vec<f64>>,
        range: [f64; 2],
        depth: usize,
        piece: usize,
    ) -> Sub {
        let mut low = [f64::INFINITY; 2];
        let mut high = [f64::NEG_INFINITY; 2];
        for p in &points {
            for a in 0..2 {
                low[a] = low[a].min(p[a]);
                high[a] = high[a].max(p[a]);
            }
        }
        Sub {
            points,
            weights,
            range,
            low,
            high,
            depth,
            piece,
        }
    }

    fn size(&self) -> f64 {
        (self.high[0] - self.low[0]).hypot(self.high[1] - self.low[1])
    }

    fn overlaps(&self, other: &Sub, slack: f64) -> bool {
        (0..2).all(|a| self.low[a] <= other.high[a] + slack && other.low[a] <= self.high[a] + slack)
    }

    /// The halves at the middle (de Casteljau on the homogeneous points).
    fn halves(&self) -> (Sub, Sub) {
        let n = self.points.len() - 1;
        let mut work: Vec<([f64; 2], f64)> = self
            .points
            .iter()
            .enumerate()
            .map(|(i, p)| {
                let w = self.weights.as_ref().map_or(1.0, |w| w[i]);
                ([p[0] * w, p[1] * w], w)
            })
            .collect();
        let mut left = vec![work[0]];
        let mut right = vec![work[n]];
        for level in 1..=n {
            for i in 0..=n - level {
                let (a, wa) = work[i];
                let (b, wb) = work[i + 1];
                work[i] = ([0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])], 0.5 * (wa + wb));
            }
            left.push(work[0]);
            right.push(work[n - level]);
        }
        right.reverse();
        let mid = 0.5 * (self.range[0] + self.range[1]);
        let unpack = |rows: Vec<([f64; 2], f64)>| -> (Vec<[f64; 2]>, Option<Vec<f64>>) {
            let points = rows.iter().map(|(p, w)| [p[0] / w, p[1] / w]).collect();
            let weights = self
                .weights
                .as_ref()
                .map(|_| rows.iter().map(|(_, w)| *w).collect());
            (points, weights)
        };
        let (lp, lw) = unpack(left);
        let (rp, rw) = unpack(right);
        (
            Sub::with(lp, lw, [self.range[0], mid], self.depth + 1, self.piece),
            Sub::with(rp, rw, [mid, self.range[1]], self.depth + 1, self.piece),
        )
    }

    /// Whether the piece moves monotonically in some direction: every difference
    /// `P_j - P_i` (`i < j`) of its control points lies in one open half-plane (then it cannot
    /// cross itself). `others` are control points that follow it (an adjacent piece).
    fn monotone_with(&self, others: &[[f64; 2]]) -> bool {
        let all: Vec<[f64; 2]> = self.points.iter().chain(others).copied().collect();
        let mut angles = Vec::new();
        for i in 0..all.len() {
            for j in i + 1..all.len() {
                let d = [all[j][0] - all[i][0], all[j][1] - all[i][1]];
                if d != [0.0, 0.0] {
                    angles.push(d[1].atan2(d[0]));
                }
            }
        }
        if angles.is_empty() {
            return true;
        }
        angles.sort_by(f64::total_cmp);
        let mut gap = angles[0] + 2.0 * core::f64::consts::PI - angles[angles.len() - 1];
        for w in angles.windows(2) {
            gap = gap.max(w[1] - w[0]);
        }
        // A half-plane leaves a gap of more than pi (with a margin for rounding).
        gap > core::f64::consts::PI + 1e-9
    }
}

struct Search<'c, A, B> {
    a: &'c A,
    b: &'c B,
    same: bool,
    da: CurveDerivative<2>,
    db: CurveDerivative<2>,
    scale: f64,
}

/// `A(s) - B(t)`, `A'(s)` and `B'(t)` at a parameter pair.
type State = ([f64; 2], [f64; 2], [f64; 2]);

/// A polished candidate: parameters.
#[derive(Clone, Copy, Debug)]
struct Root {
    s: f64,
    t: f64,
}

impl<'c, A, B> Search<'c, A, B>
where
    A: NearestPoint<2> + Derivative<Output = CurveDerivative<2>>,
    B: NearestPoint<2> + Derivative<Output = CurveDerivative<2>>,
{
    fn new(a: &'c A, b: &'c B, same: bool) -> Self {
        Search {
            a,
            b,
            same,
            da: a.derivative(),
            db: b.derivative(),
            scale: 1.0,
        }
    }

    fn run(mut self) -> Result<Vec<Intersection>, IntersectError> {
        let pa: Vec<Sub> = self
            .a
            .bezier_pieces()
            .iter()
            .enumerate()
            .map(|(i, p)| Sub::new(p, i))
            .collect();
        let pb: Vec<Sub> = if self.same {
            pa.clone()
        } else {
            self.b
                .bezier_pieces()
                .iter()
                .enumerate()
                .map(|(i, p)| Sub::new(p, i))
                .collect()
        };
        let mut low = [f64::INFINITY; 2];
        let mut high = [f64::NEG_INFINITY; 2];
        for s in pa.iter().chain(&pb) {
            for c in 0..2 {
                low[c] = low[c].min(s.low[c]);
                high[c] = high[c].max(s.high[c]);
            }
        }
        let size = (high[0] - low[0]).hypot(high[1] - low[1]);
        self.scale = if size > 0.0 && size.is_finite() {
            size
        } else {
            1.0
        };
        let slack = 1e-12 * self.scale;
        let mut pairs: Vec<(Sub, Sub)> = Vec::new();
        for (i, x) in pa.iter().enumerate() {
            for (j, y) in pb.iter().enumerate() {
                if self.same && j < i {
                    continue;
                }
                pairs.push((x.clone(), y.clone()));
            }
        }
        let mut roots: Vec<Root> = Vec::new();
        let mut crowd = CROWD;
        while !pairs.is_empty() {
            if pairs.len() > crowd {
                self.check_overlap(&pairs)?;
                if pairs.len() > 64 * CROWD {
                    // Still crowding after the check: the curves nearly coincide there.
                    return Err(overlap(&pairs));
                }
                crowd = 4 * pairs.len();
            }
            let mut next = Vec::new();
            for (x, y) in pairs {
                let identical = self.same && x.range == y.range;
                let adjacent = self.same && x.range[1] == y.range[0];
                if identical {
                    if x.monotone_with(&[]) {
                        continue;
                    }
                    let (l, r) = x.halves();
                    next.push((l.clone(), l.clone()));
                    next.push((r.clone(), r.clone()));
                    next.push((l, r));
                    continue;
                }
                if adjacent && x.monotone_with(&y.points[1..]) {
                    continue;
                }
                if !x.overlaps(&y, slack) {
                    continue;
                }
                let small = SMALL * self.scale;
                let (xs, ys) = (x.size(), y.size());
                if (xs <= small && ys <= small) || x.depth.max(y.depth) >= MAX_DEPTH {
                    let start = [
                        0.5 * (x.range[0] + x.range[1]),
                        0.5 * (y.range[0] + y.range[1]),
                    ];
                    if let Some(root) = self.polish(start)? {
                        roots.push(root);
                    }
                    continue;
                }
                if xs >= ys {
                    let (l, r) = x.halves();
                    next.push((l, y.clone()));
                    next.push((r, y));
                } else {
                    let (l, r) = y.halves();
                    next.push((x.clone(), l));
                    next.push((x, r));
                }
            }
            pairs = next;
        }
        self.collect(roots)
    }

    /// Orders, merges and evaluates the roots.
    fn collect(&self, mut roots: Vec<Root>) -> Result<Vec<Intersection>, IntersectError> {
        let (ra, rb) = (self.a.domain(), self.b.domain());
        let (wa, wb) = (width(&ra), width(&rb));
        // A closed curve (its end is its start) meets at its end where it meets at its start:
        // the root is reported at the start, once.
        let (closed_a, closed_b) = (self.closed(self.a)?, self.closed(self.b)?);
        for r in &mut roots {
            if closed_a && r.s == ra.end {
                r.s = ra.start;
            }
            if closed_b && r.t == rb.end {
                r.t = rb.start;
            }
        }
        if self.same {
            // Self-intersections: t_a < t_b, the trivial s = t dropped.
            roots = roots
                .into_iter()
                .map(|r| {
                    if r.s <= r.t {
                        r
                    } else {
                        Root { s: r.t, t: r.s }
                    }
                })
                .filter(|r| r.t - r.s > SAME * wa.max(1e-300) * 1e3)
                .collect();
        }
        roots.sort_by(|p, q| p.s.total_cmp(&q.s).then(p.t.total_cmp(&q.t)));
        let mut kept: Vec<Root> = Vec::new();
        for r in roots {
            let duplicate = kept.iter().any(|k| {
                (k.s - r.s).abs() <= SAME * wa.max(1e-300) * 1e3
                    && (k.t - r.t).abs() <= SAME * wb.max(1e-300) * 1e3
            });
            if !duplicate {
                kept.push(r);
            }
        }
        kept.iter()
            .map(|r| {
                Ok(Intersection {
                    parameter_a: r.s,
                    parameter_b: r.t,
                    point_a: self.a.evaluate(r.s)?,
                    point_b: self.b.evaluate(r.t)?,
                })
            })
            .collect()
    }

    /// Whether `curve` ends where it starts (to 1e-12 of the size).
    fn closed<C: Evaluate<Point = CurvePoint<2>>>(&self, curve: &C) -> Result<bool, EvalError> {
        let (p, q) = (curve.start()?.position, curve.end()?.position);
        Ok((p[0] - q[0]).hypot(p[1] - q[1]) <= 1e-12 * self.scale)
    }

    /// `A(s) - B(t)`, `A'(s)` and `B'(t)`.
    fn state(&self, s: f64, t: f64) -> Result<State, EvalError> {
        let pa = self.a.evaluate(s)?.position;
        let pb = self.b.evaluate(t)?.position;
        let va = self.da.evaluate(s)?.position;
        let vb = self.db.evaluate(t)?.position;
        Ok(([pa[0] - pb[0], pa[1] - pb[1]], va, vb))
    }

    /// [`Search::newton`], with a root next to an end of a domain moved onto the end when the
    /// curves meet there too (curves that meet at their ends, the seam of a closed curve).
    fn polish(&self, start: [f64; 2]) -> Result<Option<Root>, IntersectError> {
        let Some(root) = self.newton(start)? else {
            return Ok(None);
        };
        let (ra, rb) = (self.a.domain(), self.b.domain());
        let near = |x: f64, r: &Range<f64>| {
            let close = 1e-9 * width(r);
            if (x - r.start).abs() <= close {
                r.start
            } else if (x - r.end).abs() <= close {
                r.end
            } else {
                x
            }
        };
        let snapped = Root {
            s: near(root.s, &ra),
            t: near(root.t, &rb),
        };
        if (snapped.s, snapped.t) != (root.s, root.t) {
            let (f, _, _) = self.state(snapped.s, snapped.t)?;
            if f[0].hypot(f[1]) <= 1e-12 * self.scale {
                return Ok(Some(snapped));
            }
        }
        Ok(Some(root))
    }

    /// Newton's method from `start` on `A(s) - B(t) = 0`, then, where the curves are nearly
    /// tangent, on the tangency system; `None` when the curves do not meet there.
    fn newton(&self, start: [f64; 2]) -> Result<Option<Root>, IntersectError> {
        let (ra, rb) = (self.a.domain(), self.b.domain());
        let clamp = |s: f64, t: f64| (s.clamp(ra.start, ra.end), t.clamp(rb.start, rb.end));
        let tolerance = 1e-12 * self.scale;
        let (mut s, mut t) = (start[0], start[1]);
        let mut best: Option<(f64, f64, f64)> = None;
        for _ in 0..60 {
            let (f, va, vb) = self.state(s, t)?;
            let gap = f[0].hypot(f[1]);
            if best.is_none_or(|(g, _, _)| gap < g) {
                best = Some((gap, s, t));
            }
            // Solve [va, -vb] (ds, dt) = -f.
            let det = -va[0] * vb[1] + vb[0] * va[1];
            let norm = va[0].hypot(va[1]) * vb[0].hypot(vb[1]);
            if det.abs() <= 1e-10 * norm || norm == 0.0 {
                break;
            }
            let ds = (vb[0] * f[1] - f[0] * vb[1]) / det;
            let dt = (va[0] * f[1] - f[0] * va[1]) / det;
            let (ns, nt) = clamp(s - ds, t - dt);
            if ns == s && nt == t {
                break;
            }
            s = ns;
            t = nt;
        }
        let (gap, bs, bt) = best.unwrap_or((f64::INFINITY, s, t));
        let (_, va, vb) = self.state(bs, bt)?;
        let cross = (va[0] * vb[1] - va[1] * vb[0]).abs();
        let norm = va[0].hypot(va[1]) * vb[0].hypot(vb[1]);
        if gap <= tolerance && cross > 1e-6 * norm {
            return Ok(Some(Root { s: bs, t: bt }));
        }
        // Nearly tangent: A' x B' = 0 and (A - B) . A' = 0.
        let (mut s, mut t) = (bs, bt);
        let (ha, hb) = (self.da.derivative(), self.db.derivative());
        for _ in 0..60 {
            let (f, va, vb) = self.state(s, t)?;
            let aa = ha.evaluate(s)?.position;
            let bb = hb.evaluate(t)?.position;
            let cross = |p: [f64; 2], q: [f64; 2]| p[0] * q[1] - p[1] * q[0];
            let dot = |p: [f64; 2], q: [f64; 2]| p[0] * q[0] + p[1] * q[1];
            let g = [cross(va, vb), dot(f, va)];
            let j = [
                [cross(aa, vb), cross(va, bb)],
                [dot(va, va) + dot(f, aa), -dot(vb, va)],
            ];
            let det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
            if det == 0.0 || !det.is_finite() {
                break;
            }
            let ds = (g[0] * j[1][1] - j[0][1] * g[1]) / det;
            let dt = (j[0][0] * g[1] - j[1][0] * g[0]) / det;
            let (ns, nt) = clamp(s - ds, t - dt);
            if ns == s && nt == t {
                break;
            }
            s = ns;
            t = nt;
        }
        let (f, _, _) = self.state(s, t)?;
        if f[0].hypot(f[1]) <= tolerance {
            return Ok(Some(Root { s, t }));
        }
        Ok(if gap <= tolerance {
            Some(Root { s: bs, t: bt })
        } else {
            None
        })
    }

    /// Pairs crowd: look for pairs where one sub-piece lies on the other (9 points of the
    /// first within 1e-9 of the size of the second sub-piece); when at least a quarter of the
    /// pairs do, the curves share a stretch: it is reported with the parameters it spans.
    fn check_overlap(&self, pairs: &[(Sub, Sub)]) -> Result<(), IntersectError> {
        let mut on: Vec<&(Sub, Sub)> = Vec::new();
        for pair in pairs {
            let (x, y) = pair;
            if self.same && x.range == y.range {
                continue;
            }
            let piece = Piece {
                start: y.range[0],
                end: y.range[1],
                points: y.points.clone(),
                weights: y.weights.clone(),
                jump_at_end: false,
            };
            let mut all = true;
            for k in 0..=8 {
                let s = x.range[0] + (x.range[1] - x.range[0]) * k as f64 / 8.0;
                let p = self.a.evaluate(s)?.position;
                if distance_to_piece(piece.clone(), &p) > 1e-9 * self.scale {
                    all = false;
                    break;
                }
            }
            if all {
                on.push(pair);
            }
        }
        if on.is_empty() || on.len() * 4 < pairs.len() {
            return Ok(());
        }
        let owned: Vec<(Sub, Sub)> = on.into_iter().cloned().collect();
        Err(overlap(&owned))
    }
}

/// The parameter ranges covered by crowding pairs.
fn overlap(pairs: &[(Sub, Sub)]) -> IntersectError {
    let span = |f: fn(&(Sub, Sub)) -> [f64; 2]| {
        pairs.iter().fold(f64::INFINITY, |m, p| m.min(f(p)[0]))
            ..pairs.iter().fold(f64::NEG_INFINITY, |m, p| m.max(f(p)[1]))
    };
    IntersectError::Overlap {
        a: span(|p| p.0.range),
        b: span(|p| p.1.range),
    }
}

fn width(r: &Range<f64>) -> f64 {
    r.end - r.start
}
