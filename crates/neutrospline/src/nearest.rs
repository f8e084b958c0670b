//! The nearest point of a curve to a given point: the global minimum of the distance, by
//! branch and bound on the Bernstein coefficients of the squared distance of each Bézier
//! piece, then a safeguarded Newton iteration on the sign of its derivative.
//!
//! See `docs/model.md`, section 10, for the mathematics.

use core::ops::Range;

use crate::any_curve::AnyCurve;
use crate::bezier::Bezier;
use crate::curve::{ControlPolygon, EvalError, Evaluate};
use crate::point::CurvePoint;
use crate::spline_curve::{BSpline, Nurbs};
use crate::surface::{EvaluateSurface, Surface};

/// The nearest point of a curve to a query point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Nearest<const D: usize> {
    /// The curve's parameter of the nearest point (the smallest such parameter when several
    /// points are equally near, to within [`TIE_TOLERANCE`] of the curve's size).
    pub parameter: f64,
    /// The Euclidean distance from the query point to [`Nearest::point`].
    pub distance: f64,
    /// The curve's point at [`Nearest::parameter`], with its degrees.
    pub point: CurvePoint<D>,
}

/// Why the nearest point cannot be found.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum NearestError {
    /// A coordinate of the query point is NaN or infinite.
    #[error("{axis} = {value} is not a finite number (query coordinates must be finite)", axis = AXES[*axis])]
    PointNotFinite {
        /// Coordinate index: 0 for x, 1 for y, 2 for z.
        axis: usize,
        /// The offending value.
        value: f64,
    },
    /// The differences between the query point and the control points do not fit in a
    /// 64-bit float (coordinates near 1e308 of opposite signs).
    #[error("the distance from the query point overflows a 64-bit float (coordinates too large)")]
    Overflow,
    /// The curve could not be evaluated at the parameter found (an overflowing curve).
    #[error(transparent)]
    Eval(#[from] EvalError),
}

const AXES: [&str; 3] = ["x", "y", "z"];

/// Distances that differ by at most this fraction of the curve's size (the diagonal of its
/// control points' bounding box) count as equal: the smaller parameter is reported.
pub const TIE_TOLERANCE: f64 = 1e-13;

/// The deepest subdivision of one Bézier piece (intervals of width 2^-48 of the piece).
const MAX_DEPTH: usize = 48;

/// Nearest points on a curve of any kind.
///
/// The distance `d(t) = |C(t) - P|` is minimised over the whole domain, ends included: on
/// each Bézier piece (one for a Bézier curve, one per non-empty knot span of a spline) the
/// squared distance is the polynomial (NURBS: the quotient of polynomials)
///
/// ```text
/// d^2(t) = |sum_i B_i(t) w_i (P_i - P)|^2 / (sum_i B_i(t) w_i)^2
///        = sum_k B_{2n,k}(t) a_k / sum_k B_{2n,k}(t) b_k,
/// a_k = sum_{i+j=k} C(n,i) C(n,j) / C(2n,k) w_i w_j (P_i - P).(P_j - P),   b_k likewise with 1
/// ```
///
/// whose coefficients bound it: `min_k a_k / b_k <= d^2 <= max_k a_k / b_k` on the piece
/// (non-negative basis, `b_k > 0`). Pieces and their halves (de Casteljau) are pruned when
/// the lower bound exceeds the best distance found; a half where the derivative's sign
/// polynomial (`a'` for polynomial pieces, `a' b - a b'` for rational ones) changes sign at
/// most once holds at most one minimum, found by Newton's method safeguarded by bisection.
/// Distances within [`TIE_TOLERANCE`] of the curve's size are ties, broken by the smaller
/// parameter: at the centre of a circle every point is nearest and the start is reported.
///
/// ```
/// use neutrospline::NearestPoint;
/// let curve = neutrospline::example1();
/// // Left of the start C(0) = (1, 3), where the curve heads up and to the right.
/// let near = curve.nearest([0.0, 3.0])?;
/// assert_eq!((near.parameter, near.distance), (0.0, 1.0));
/// assert_eq!(near.point.degrees.truth(), 0.3);
/// // A point of the curve is its own nearest point.
/// let on = curve.nearest([4.625, 4.0])?;
/// assert!(on.distance < 1e-12 && (on.parameter - 0.5).abs() < 1e-9);
/// # Ok::<(), neutrospline::NearestError>(())
/// ```
pub trait NearestPoint<const D: usize>:
    Evaluate<Point = CurvePoint<D>> + sealed::BezierPieces<D> + Sized
{
    /// The nearest point of the curve to `point` (see the trait's documentation).
    ///
    /// # Errors
    /// A coordinate of `point` not finite; [`NearestError::Overflow`].
    fn nearest(&self, point: [f64; D]) -> Result<Nearest<D>, NearestError> {
        Projector::new(self).nearest(point)
    }

    /// The curve prepared for many nearest-point queries (its Bézier pieces extracted once).
    fn projector(&self) -> Projector<'_, Self, D> {
        Projector::new(self)
    }
}

impl<const D: usize> NearestPoint<D> for Bezier<D> {}
impl<const D: usize> NearestPoint<D> for BSpline<D> {}
impl<const D: usize> NearestPoint<D> for Nurbs<D> {}
impl<const D: usize> NearestPoint<D> for AnyCurve<D> {}

pub(crate) mod sealed {
    use super::Piece;

    /// The Bézier pieces of a curve in its own parameters (crate-private).
    pub trait BezierPieces<const D: usize> {
        /// The pieces, in order of parameter.
        fn bezier_pieces(&self) -> Vec<Piece<D>>;
    }
}

/// A (rational) Bézier piece of a curve on `[start, end]`: control positions and weights.
#[doc(hidden)]
#[derive(Clone, Debug)]
pub struct Piece<const D: usize> {
    pub(crate) start: f64,
    pub(crate) end: f64,
    pub(crate) points: Vec<[f64; D]>,
    /// `None` for a polynomial piece.
    pub(crate) weights: Option<Vec<f64>>,
    /// The curve jumps at `end` (a knot of multiplicity p + 1): the piece's last point is a
    /// limit from the left, reached by the parameter just below `end`.
    pub(crate) jump_at_end: bool,
}

impl<const D: usize> Piece<D> {
    /// The parameter of the piece's last point on the curve: `end`, or the largest float
    /// below it where the curve jumps (the curve takes the right-hand value at a knot).
    fn end_parameter(&self) -> f64 {
        if self.jump_at_end {
            self.end.next_down()
        } else {
            self.end
        }
    }

    fn new<C: ControlPolygon<D>>(start: f64, end: f64, curve: &C, weights: Option<&[f64]>) -> Self {
        Piece {
            start,
            end,
            points: curve.control_points().iter().map(|p| p.position).collect(),
            weights: weights.map(<[f64]>::to_vec),
            jump_at_end: false,
        }
    }
}

impl<const D: usize> sealed::BezierPieces<D> for Bezier<D> {
    fn bezier_pieces(&self) -> Vec<Piece<D>> {
        vec![Piece::new(0.0, 1.0, self, None)]
    }
}

impl<const D: usize> sealed::BezierPieces<D> for BSpline<D> {
    fn bezier_pieces(&self) -> Vec<Piece<D>> {
        self.to_bezier_segments()
            .iter()
            .map(|s| Piece::new(s.start, s.end, &s.curve, None))
            .collect()
    }
}

impl<const D: usize> sealed::BezierPieces<D> for Nurbs<D> {
    fn bezier_pieces(&self) -> Vec<Piece<D>> {
        self.to_bezier_segments()
            .iter()
            .map(|s| Piece::new(s.start, s.end, &s.curve, s.curve.weights()))
            .collect()
    }
}

impl<const D: usize> sealed::BezierPieces<D> for AnyCurve<D> {
    fn bezier_pieces(&self) -> Vec<Piece<D>> {
        match self {
            AnyCurve::Bezier(c) => c.bezier_pieces(),
            AnyCurve::BSpline(c) => c.bezier_pieces(),
            AnyCurve::Nurbs(c) => c.bezier_pieces(),
        }
    }
}

/// A piece prepared for queries: its control bounding box, the products of binomials and the
/// denominator's coefficients.
#[derive(Clone, Debug)]
struct Prepared<const D: usize> {
    piece: Piece<D>,
    low: [f64; D],
    high: [f64; D],
    /// `C(n,i) C(n,j) / C(2n,i+j)`, row-major `(n + 1) x (n + 1)`.
    products: Vec<f64>,
    /// Coefficients `b_k` of `w(t)^2` in degree `2n` (all 1 for polynomial pieces).
    denominator: Vec<f64>,
}

/// A curve prepared for nearest-point queries: its Bézier pieces with their bounding boxes.
/// Queries take `&self` and may run on many threads at once.
///
/// ```
/// use neutrospline::NearestPoint;
/// let curve = neutrospline::example1();
/// let projector = curve.projector();
/// let a = projector.nearest([1.0, 2.0])?;
/// assert_eq!(a.parameter, 0.0); // below the start, the start is nearest
/// assert_eq!(a.distance, 1.0);
/// # Ok::<(), neutrospline::NearestError>(())
/// ```
#[derive(Clone, Debug)]
pub struct Projector<'a, C, const D: usize> {
    curve: &'a C,
    pieces: Vec<Prepared<D>>,
    domain: Range<f64>,
    /// Absolute tie tolerance of distances: [`TIE_TOLERANCE`] times the curve's size.
    tie: f64,
}

/// A candidate: parameter and distance.
#[derive(Clone, Copy, Debug)]
struct Candidate {
    t: f64,
    distance: f64,
}

/// The candidates whose distance is within the tie tolerance of the best so far.
struct Best {
    tie: f64,
    min: f64,
    near: Vec<Candidate>,
}

impl Best {
    fn offer(&mut self, c: Candidate) {
        if c.distance > self.min + self.tie {
            return;
        }
        if c.distance < self.min {
            self.min = c.distance;
            let limit = self.min + self.tie;
            self.near.retain(|o| o.distance <= limit);
        }
        self.near.push(c);
    }

    /// The smallest parameter among the near candidates.
    fn choice(&self) -> Option<Candidate> {
        self.near.iter().copied().min_by(|a, b| a.t.total_cmp(&b.t))
    }
}

impl<'a, C, const D: usize> Projector<'a, C, D>
where
    C: Evaluate<Point = CurvePoint<D>> + sealed::BezierPieces<D>,
{
    /// Extracts and prepares the pieces of `curve`.
    pub fn new(curve: &'a C) -> Self {
        let mut raw = curve.bezier_pieces();
        mark_jumps(&mut raw);
        let pieces: Vec<Prepared<D>> = raw.into_iter().map(prepare).collect();
        let mut low = [f64::INFINITY; D];
        let mut high = [f64::NEG_INFINITY; D];
        for p in &pieces {
            for a in 0..D {
                low[a] = low[a].min(p.low[a]);
                high[a] = high[a].max(p.high[a]);
            }
        }
        let size = (0..D)
            .map(|a| (high[a] - low[a]).powi(2))
            .sum::<f64>()
            .sqrt();
        Projector {
            curve,
            pieces,
            domain: curve.domain(),
            tie: TIE_TOLERANCE * if size.is_finite() { size } else { f64::MAX },
        }
    }

    /// The nearest point of the curve to `point`: the global minimum of the distance over
    /// the whole domain, ends included; ties (within [`TIE_TOLERANCE`] of the curve's size)
    /// go to the smaller parameter.
    ///
    /// # Errors
    /// A coordinate of `point` not finite; [`NearestError::Overflow`].
    pub fn nearest(&self, point: [f64; D]) -> Result<Nearest<D>, NearestError> {
        if let Some(axis) = point.iter().position(|x| !x.is_finite()) {
            return Err(NearestError::PointNotFinite {
                axis,
                value: point[axis],
            });
        }
        let mut best = Best {
            tie: self.tie,
            min: f64::INFINITY,
            near: Vec::new(),
        };
        // The ends of the pieces first: they give a good bound to prune with. Only those
        // within the tie tolerance of the nearest end can be candidates.
        let mut bounds = Vec::with_capacity(self.pieces.len());
        let mut ends = Vec::with_capacity(self.pieces.len());
        let mut nearest_end = f64::INFINITY;
        for p in &self.pieces {
            let first = distance(&p.piece.points[0], &point);
            let last = distance(&p.piece.points[p.piece.points.len() - 1], &point);
            if !first.is_finite() || !last.is_finite() {
                return Err(NearestError::Overflow);
            }
            nearest_end = nearest_end.min(first).min(last);
            ends.push((first, last));
            bounds.push(box_distance(&p.low, &p.high, &point));
        }
        for (p, &(first, last)) in self.pieces.iter().zip(&ends) {
            if first <= nearest_end + best.tie {
                best.offer(Candidate {
                    t: p.piece.start,
                    distance: first,
                });
            }
            if last <= nearest_end + best.tie {
                best.offer(Candidate {
                    t: p.piece.end_parameter(),
                    distance: last,
                });
            }
        }
        // Then the pieces that can hold a nearer point, nearest box first.
        let mut order: Vec<(f64, usize)> = bounds
            .iter()
            .enumerate()
            .filter(|(_, &b)| b <= best.min + best.tie)
            .map(|(k, &b)| (b, k))
            .collect();
        order.sort_unstable_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        for (bound, k) in order {
            if bound > best.min + best.tie {
                break;
            }
            search_piece(&self.pieces[k], &point, &mut best)?;
        }
        let chosen = best.choice().ok_or(NearestError::Overflow)?;
        let t = chosen.t.clamp(self.domain.start, self.domain.end);
        let found = self.curve.evaluate(t)?;
        let distance = distance(&found.position, &point);
        if !distance.is_finite() {
            return Err(NearestError::Overflow);
        }
        Ok(Nearest {
            parameter: t,
            distance,
            point: found,
        })
    }
}

#[cfg(feature = "parallel")]
impl<C, const D: usize> Projector<'_, C, D>
where
    C: Evaluate<Point = CurvePoint<D>> + sealed::BezierPieces<D> + Sync,
{
    /// The nearest points to every point of `points`, in order (on rayon's threads: the
    /// `parallel` feature is on).
    pub fn nearest_many(&self, points: &[[f64; D]]) -> Vec<Result<Nearest<D>, NearestError>> {
        use rayon::prelude::*;
        points.par_iter().map(|p| self.nearest(*p)).collect()
    }
}

#[cfg(not(feature = "parallel"))]
impl<C, const D: usize> Projector<'_, C, D>
where
    C: Evaluate<Point = CurvePoint<D>> + sealed::BezierPieces<D>,
{
    /// The nearest points to every point of `points`, in order (on the calling thread; with
    /// the `parallel` feature on rayon's threads).
    pub fn nearest_many(&self, points: &[[f64; D]]) -> Vec<Result<Nearest<D>, NearestError>> {
        points.iter().map(|p| self.nearest(*p)).collect()
    }
}

/// The distance from `point` to a (rational) Bézier piece, by the same branch and bound
/// (for the overlap check of intersections); infinite when it overflows.
pub(crate) fn distance_to_piece<const D: usize>(piece: Piece<D>, point: &[f64; D]) -> f64 {
    let n = piece.points.len() - 1;
    let mut best = Best {
        tie: 0.0,
        min: f64::INFINITY,
        near: Vec::new(),
    };
    for (t, q) in [(piece.start, piece.points[0]), (piece.end, piece.points[n])] {
        best.offer(Candidate {
            t,
            distance: distance(&q, point),
        });
    }
    let prepared = prepare(piece);
    match search_piece(&prepared, point, &mut best) {
        Ok(()) => best.min,
        Err(_) => f64::INFINITY,
    }
}

/// Marks the pieces after whose end the curve jumps: the next piece starts elsewhere (more
/// than 1e-9 of the curve's size away, far above the rounding of knot insertion).
fn mark_jumps<const D: usize>(pieces: &mut [Piece<D>]) {
    let mut low = [f64::INFINITY; D];
    let mut high = [f64::NEG_INFINITY; D];
    for p in pieces.iter() {
        for q in &p.points {
            for a in 0..D {
                low[a] = low[a].min(q[a]);
                high[a] = high[a].max(q[a]);
            }
        }
    }
    let size = distance(&low, &high);
    for k in 1..pieces.len() {
        let last = pieces[k - 1].points[pieces[k - 1].points.len() - 1];
        if distance(&last, &pieces[k].points[0]) > 1e-9 * size {
            pieces[k - 1].jump_at_end = true;
        }
    }
}

fn binomial(n: usize, k: usize) -> f64 {
    (0..k).fold(1.0, |acc, r| acc * (n - r) as f64 / (r + 1) as f64)
}

fn prepare<const D: usize>(piece: Piece<D>) -> Prepared<D> {
    let n = piece.points.len() - 1;
    let mut low = [f64::INFINITY; D];
    let mut high = [f64::NEG_INFINITY; D];
    for p in &piece.points {
        for a in 0..D {
            low[a] = low[a].min(p[a]);
            high[a] = high[a].max(p[a]);
        }
    }
    let mut products = vec![0.0; (n + 1) * (n + 1)];
    for i in 0..=n {
        for j in 0..=n {
            products[i * (n + 1) + j] = binomial(n, i) * binomial(n, j) / binomial(2 * n, i + j);
        }
    }
    let mut denominator = vec![0.0; 2 * n + 1];
    match &piece.weights {
        None => denominator.iter_mut().for_each(|b| *b = 1.0),
        Some(w) => {
            // Scaled so that the largest weight is 1 (the quotient does not change).
            let top = w.iter().fold(0.0_f64, |m, &x| m.max(x));
            for i in 0..=n {
                for j in 0..=n {
                    denominator[i + j] += products[i * (n + 1) + j] * (w[i] / top) * (w[j] / top);
                }
            }
        }
    }
    Prepared {
        piece,
        low,
        high,
        products,
        denominator,
    }
}

fn distance<const D: usize>(a: &[f64; D], b: &[f64; D]) -> f64 {
    let mut s = 0.0;
    for k in 0..D {
        let d = a[k] - b[k];
        s += d * d;
    }
    if s.is_finite() {
        s.sqrt()
    } else {
        // Scale to avoid overflow of the squares.
        let m = (0..D).fold(0.0_f64, |m, k| m.max((a[k] - b[k]).abs()));
        if !m.is_finite() {
            return f64::INFINITY;
        }
        m * (0..D)
            .map(|k| ((a[k] - b[k]) / m).powi(2))
            .sum::<f64>()
            .sqrt()
    }
}

/// The distance from `point` to the box `[low, high]` (0 inside).
fn box_distance<const D: usize>(low: &[f64; D], high: &[f64; D], point: &[f64; D]) -> f64 {
    let mut nearest = *point;
    for a in 0..D {
        nearest[a] = point[a].clamp(low[a], high[a]);
    }
    distance(&nearest, point)
}

/// One level of de Casteljau at 1/2: the coefficients of the left and right halves.
fn halves(c: &[f64], left: &mut Vec<f64>, right: &mut Vec<f64>) {
    let n = c.len();
    let mut work = c.to_vec();
    left.clear();
    right.clear();
    left.push(work[0]);
    right.push(work[n - 1]);
    for level in 1..n {
        for i in 0..n - level {
            work[i] = 0.5 * (work[i] + work[i + 1]);
        }
        left.push(work[0]);
        right.push(work[n - level - 1]);
    }
    right.reverse();
}

/// The value and derivative at `x` in [0, 1] of the Bernstein polynomial with coefficients `c`.
fn value_and_slope(c: &[f64], x: f64) -> (f64, f64) {
    let n = c.len() - 1;
    if n == 0 {
        return (c[0], 0.0);
    }
    let mut stack = [0.0; 32];
    let mut heap;
    let work: &mut [f64] = if c.len() <= stack.len() {
        stack[..c.len()].copy_from_slice(c);
        &mut stack[..c.len()]
    } else {
        heap = c.to_vec();
        &mut heap
    };
    for level in 1..n {
        for i in 0..=n - level {
            work[i] = (1.0 - x) * work[i] + x * work[i + 1];
        }
    }
    let (a, b) = (work[0], work[1]);
    ((1.0 - x) * a + x * b, n as f64 * (b - a))
}

/// Sign changes of a coefficient sequence (zeros skipped), and whether the first non-zero
/// coefficient is negative.
fn sign_changes(c: &[f64]) -> (usize, bool) {
    let mut changes = 0;
    let mut last = 0.0_f64;
    let mut first_negative = false;
    for &x in c {
        if x == 0.0 {
            continue;
        }
        if last == 0.0 {
            first_negative = x < 0.0;
        } else if (x < 0.0) != (last < 0.0) {
            changes += 1;
        }
        last = x;
    }
    (changes, first_negative)
}

/// Divides out the roots at 0 and 1 of a Bernstein polynomial (exact zero end coefficients),
/// which keeps the sign inside (0, 1): with `c_m = 0`,
/// `sum_k c_k B_{m,k} = (1 - x) sum_{k<m} c_k m / (m - k) B_{m-1,k}`, and with `c_0 = 0`,
/// `x sum_{k>0} c_k m / k B_{m-1,k-1}`. A zero polynomial is left as one zero.
fn deflate(c: &mut Vec<f64>) {
    while c.len() > 1 {
        let m = c.len() - 1;
        if c[m] == 0.0 {
            c.pop();
            for (k, x) in c.iter_mut().enumerate() {
                *x *= m as f64 / (m - k) as f64;
            }
        } else if c[0] == 0.0 {
            c.remove(0);
            for (k, x) in c.iter_mut().enumerate() {
                *x *= m as f64 / (k + 1) as f64;
            }
        } else {
            break;
        }
    }
}

/// A root of the Bernstein polynomial `c` in [0, 1], where `c(0) < 0 < c(1)` (after
/// [`deflate`]): Newton's
/// method kept inside a shrinking bracket, bisecting when a step leaves it.
fn bracketed_root(c: &[f64]) -> f64 {
    let (mut lo, mut hi) = (0.0_f64, 1.0_f64);
    let (first, last) = (c[0], c[c.len() - 1]);
    let mut x = if last > first {
        (-first / (last - first)).clamp(0.0, 1.0)
    } else {
        0.5
    };
    for _ in 0..100 {
        let (value, slope) = value_and_slope(c, x);
        if value == 0.0 {
            return x;
        }
        if value < 0.0 {
            lo = x;
        } else {
            hi = x;
        }
        let step = value / slope;
        // x lies in [0, 1]: a Newton step of a few ulps of 1 is the end (when the value is
        // rounding noise, bisecting further would only wander inside the bracket).
        if slope != 0.0 && step.abs() <= 4.0 * f64::EPSILON {
            return (x - step).clamp(lo, hi);
        }
        let newton = x - step;
        let next = if slope != 0.0 && newton > lo && newton < hi {
            newton
        } else {
            0.5 * (lo + hi)
        };
        if (next - x).abs() <= 4.0 * f64::EPSILON || hi - lo <= 4.0 * f64::EPSILON {
            return next;
        }
        x = next;
    }
    x
}

/// The sign polynomial of the derivative of `a / b` (both degree `m`): `a'` when `b` is
/// constant, else `a' b - a b'` (degree `2m - 1`).
fn derivative_sign(a: &[f64], b: &[f64], rational: bool, out: &mut Vec<f64>) {
    let m = a.len() - 1;
    out.clear();
    if m == 0 {
        out.push(0.0);
        return;
    }
    if !rational {
        out.extend((0..m).map(|k| a[k + 1] - a[k]));
        return;
    }
    // a' = m sum_k B_{m-1,k} (a_{k+1} - a_k); the factor m is dropped (positive).
    let da: Vec<f64> = (0..m).map(|k| a[k + 1] - a[k]).collect();
    let db: Vec<f64> = (0..m).map(|k| b[k + 1] - b[k]).collect();
    let degree = 2 * m - 1;
    out.resize(degree + 1, 0.0);
    for i in 0..m {
        for j in 0..=m {
            let w = binomial(m - 1, i) * binomial(m, j) / binomial(degree, i + j);
            out[i + j] += w * (da[i] * b[j] - db[i] * a[j]);
        }
    }
}

/// An interval of a piece being searched: the numerator's and denominator's coefficients on
/// it, its ends in the piece's parameter, and its depth.
type Interval = (Vec<f64>, Vec<f64>, f64, f64, usize);

/// Branch and bound over one piece: offers to `best` the minima of the distance on it.
fn search_piece<const D: usize>(
    p: &Prepared<D>,
    point: &[f64; D],
    best: &mut Best,
) -> Result<(), NearestError> {
    let piece = &p.piece;
    let n = piece.points.len() - 1;
    // The differences P_i - P, scaled by a power of two so that their squares cannot overflow.
    let mut largest = 0.0_f64;
    let mut diffs = Vec::with_capacity(n + 1);
    for q in &piece.points {
        let mut d = [0.0; D];
        for a in 0..D {
            d[a] = q[a] - point[a];
            largest = largest.max(d[a].abs());
        }
        diffs.push(d);
    }
    if !largest.is_finite() {
        return Err(NearestError::Overflow);
    }
    if largest == 0.0 {
        // Every control point is the query point.
        best.offer(Candidate {
            t: piece.start,
            distance: 0.0,
        });
        return Ok(());
    }
    let scale = 2.0_f64.powi(largest.log2().ceil() as i32);
    let top = piece
        .weights
        .as_ref()
        .map_or(1.0, |w| w.iter().fold(0.0_f64, |m, &x| m.max(x)));
    for (i, d) in diffs.iter_mut().enumerate() {
        let w = piece.weights.as_ref().map_or(1.0, |w| w[i] / top);
        for x in d.iter_mut() {
            *x = *x / scale * w;
        }
    }
    let mut numerator = vec![0.0; 2 * n + 1];
    for i in 0..=n {
        for j in 0..=n {
            let dot: f64 = (0..D).map(|a| diffs[i][a] * diffs[j][a]).sum();
            numerator[i + j] += p.products[i * (n + 1) + j] * dot;
        }
    }
    let rational = piece.weights.is_some();
    let mut stack: Vec<Interval> = vec![(numerator, p.denominator.clone(), 0.0, 1.0, 0)];
    let mut sign = Vec::new();
    let to_distance = |ratio: f64| ratio.max(0.0).sqrt() * scale;
    while let Some((a, b, lo, hi, depth)) = stack.pop() {
        let ratios = a.iter().zip(&b).map(|(x, y)| x / y);
        let (low, high) = ratios.fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), r| {
            (l.min(r), h.max(r))
        });
        let (lower, upper) = (to_distance(low), to_distance(high));
        if lower > best.min + best.tie {
            continue;
        }
        let ties = lower >= best.min - best.tie && upper <= best.min + best.tie;
        if ties || depth >= MAX_DEPTH {
            // Every point of the interval ties with the best: its start is the candidate.
            offer_at(piece, point, lo, best);
            if depth >= MAX_DEPTH {
                offer_at(piece, point, hi, best);
            }
            continue;
        }
        derivative_sign(&a, &b, rational, &mut sign);
        deflate(&mut sign);
        let (changes, first_negative) = sign_changes(&sign);
        match (changes, first_negative) {
            // Increasing: the minimum is at the start; decreasing: at the end.
            (0, false) => offer_at(piece, point, lo, best),
            (0, true) => offer_at(piece, point, hi, best),
            // Increasing then decreasing: the minimum is at an end.
            (1, false) => {
                offer_at(piece, point, lo, best);
                offer_at(piece, point, hi, best);
            }
            // Decreasing then increasing: one interior minimum.
            (1, true) => {
                let x = bracketed_root(&sign);
                offer_at(piece, point, lo + (hi - lo) * x, best);
            }
            _ => {
                let (mut al, mut ar, mut bl, mut br) =
                    (Vec::new(), Vec::new(), Vec::new(), Vec::new());
                halves(&a, &mut al, &mut ar);
                halves(&b, &mut bl, &mut br);
                let mid = 0.5 * (lo + hi);
                // The left half is searched first (pushed last).
                stack.push((ar, br, mid, hi, depth + 1));
                stack.push((al, bl, lo, mid, depth + 1));
            }
        }
    }
    Ok(())
}

/// Offers the point of `piece` at local parameter `x` in [0, 1].
fn offer_at<const D: usize>(piece: &Piece<D>, point: &[f64; D], x: f64, best: &mut Best) {
    let position = piece_point(piece, x);
    let t = if x <= 0.0 {
        piece.start
    } else if x >= 1.0 {
        piece.end_parameter()
    } else {
        piece.start + (piece.end - piece.start) * x
    };
    best.offer(Candidate {
        t,
        distance: distance(&position, point),
    });
}

/// The position of a (rational) Bézier piece at `x` in [0, 1], by de Casteljau's algorithm on
/// the homogeneous points (the end control points exactly at 0 and 1).
fn piece_point<const D: usize>(piece: &Piece<D>, x: f64) -> [f64; D] {
    let n = piece.points.len() - 1;
    if x <= 0.0 {
        return piece.points[0];
    }
    if x >= 1.0 {
        return piece.points[n];
    }
    let mut work: Vec<([f64; D], f64)> = piece
        .points
        .iter()
        .enumerate()
        .map(|(i, q)| (*q, piece.weights.as_ref().map_or(1.0, |w| w[i])))
        .collect();
    for level in 1..=n {
        for i in 0..=n - level {
            let (q0, w0) = work[i];
            let (q1, w1) = work[i + 1];
            let (l, r) = ((1.0 - x) * w0, x * w1);
            let w = l + r;
            let mut q = [0.0; D];
            for a in 0..D {
                q[a] = (l * q0[a] + r * q1[a]) / w;
            }
            work[i] = (q, w);
        }
    }
    work[0].0
}

// ---------------------------------------------------------------------------------- surfaces

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

/// A candidate on a surface: parameters and distance.
#[derive(Clone, Copy, Debug)]
struct SurfaceCandidate {
    uv: [f64; 2],
    distance: f64,
}

struct SurfaceBest {
    tie: f64,
    /// The smallest exact distance among the candidates.
    min: f64,
    /// An upper bound of the minimum from the coefficients (corners of pieces), for pruning.
    bound: f64,
    near: Vec<SurfaceCandidate>,
}

impl SurfaceBest {
    /// Distances above this cannot be the minimum, nor tie with it.
    fn limit(&self) -> f64 {
        self.min.min(self.bound) + self.tie
    }

    fn offer(&mut self, c: SurfaceCandidate) {
        // NaN distances are never offered.
        if c.distance.is_nan() || c.distance > self.min + self.tie {
            return;
        }
        if c.distance < self.min {
            self.min = c.distance;
            let limit = self.min + self.tie;
            self.near.retain(|o| o.distance <= limit);
        }
        self.near.push(c);
    }

    fn choice(&self) -> Option<SurfaceCandidate> {
        self.near.iter().copied().min_by(|a, b| {
            a.uv[0]
                .total_cmp(&b.uv[0])
                .then(a.uv[1].total_cmp(&b.uv[1]))
        })
    }
}

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
                let mut patch = make_patch(u, v, points, rational.then_some(w), p, q);
                patch.jump = [
                    jumps_at(self.knots_u(), u[1]),
                    jumps_at(self.knots_v(), v[1]),
                ];
                patches.push(patch);
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

fn make_patch(
    u: [f64; 2],
    v: [f64; 2],
    points: Vec<[f64; 3]>,
    weights: Option<Vec<f64>>,
    p: usize,
    q: usize,
) -> Patch {
    let mut low = [f64::INFINITY; 3];
    let mut high = [f64::NEG_INFINITY; 3];
    for pt in &points {
        for a in 0..3 {
            low[a] = low[a].min(pt[a]);
            high[a] = high[a].max(pt[a]);
        }
    }
    let (tu, tv) = (product_table(p), product_table(q));
    let (nu, nv) = (2 * p + 1, 2 * q + 1);
    let mut denominator = vec![0.0; nu * nv];
    match &weights {
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
    Patch {
        u,
        v,
        points,
        weights,
        p,
        q,
        low,
        high,
        denominator,
        jump: [false, false],
    }
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
        let mut best = SurfaceBest {
            tie: self.tie,
            min: f64::INFINITY,
            bound: f64::INFINITY,
            near: Vec::new(),
        };
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
                best.offer(SurfaceCandidate { uv, distance: d });
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
        for (lower, start) in starts {
            if lower <= best.limit() {
                if let Some(c) = self.newton(start, &point) {
                    best.offer(c);
                }
            }
        }
        let chosen = best.choice().ok_or(NearestError::Overflow)?;
        let [du, dv] = self.surface.domain();
        let uv = [
            chosen.uv[0].clamp(du.start, du.end),
            chosen.uv[1].clamp(dv.start, dv.end),
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
        best: &mut SurfaceBest,
        starts: &mut Vec<(f64, [f64; 2])>,
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
            best.offer(SurfaceCandidate {
                uv: [patch.u[0], patch.v[0]],
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
        while let Some((a, b, su, sv, depth)) = stack.pop() {
            let (low, high) = a
                .iter()
                .zip(&b)
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), (x, y)| {
                    (l.min(x / y), h.max(x / y))
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
                best.offer(SurfaceCandidate {
                    uv,
                    distance: distance(&s.position, point),
                });
                continue;
            }
            if depth >= SURFACE_DEPTH {
                let centre = [
                    global(0.5 * (su[0] + su[1]), patch.u),
                    global(0.5 * (sv[0] + sv[1]), patch.v),
                ];
                starts.push((lower, centre));
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

    /// Projected Newton on `f(u, v) = |S(u, v) - P|^2` from `start`, inside the domain: a
    /// coordinate on an edge of the domain whose gradient points out stays there. Each step
    /// must decrease `f` (halved up to 40 times); `None` if the surface cannot be evaluated.
    fn newton(&self, start: [f64; 2], point: &[f64; 3]) -> Option<SurfaceCandidate> {
        let [du, dv] = self.surface.domain();
        let lo = [du.start, dv.start];
        let hi = [du.end, dv.end];
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
                    step[c] = if h[c][c] > 0.0 {
                        -g[c] / h[c][c]
                    } else {
                        -g[c]
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
        Some(SurfaceCandidate {
            uv: x,
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
