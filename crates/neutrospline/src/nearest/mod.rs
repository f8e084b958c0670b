//! The nearest point of a curve to a given point: the global minimum of the distance, by
//! branch and bound on the Bernstein coefficients of the squared distance of each Bézier
//! piece, then a safeguarded Newton iteration on the sign of its derivative.
//!
//! See `docs/model.md`, section 10, for the mathematics.

use core::ops::Range;

use crate::any_curve::AnyCurve;
use crate::bernstein_scalar::{binomial, bracketed_root, deflate, halves, sign_changes};
use crate::bezier::Bezier;
use crate::curve::{ControlPolygon, EvalError, Evaluate};
use crate::point::CurvePoint;
use crate::spline_curve::{BSpline, Nurbs};

mod surface;
pub use surface::{SurfaceNearest, SurfaceProjector};

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

/// A point of a search: its parameter (`t` on a curve, `[u, v]` on a surface) and its
/// distance to the query.
#[derive(Clone, Copy, Debug)]
pub(super) struct Candidate<P> {
    pub(super) at: P,
    pub(super) distance: f64,
}

/// Parameters in the order that breaks ties: the smallest first (lexicographic for `[u, v]`).
pub(super) trait Parameter: Copy {
    fn order(&self, other: &Self) -> core::cmp::Ordering;
}

impl Parameter for f64 {
    fn order(&self, other: &Self) -> core::cmp::Ordering {
        self.total_cmp(other)
    }
}

impl Parameter for [f64; 2] {
    fn order(&self, other: &Self) -> core::cmp::Ordering {
        self[0]
            .total_cmp(&other[0])
            .then(self[1].total_cmp(&other[1]))
    }
}

/// The candidates whose distance is within the tie tolerance of the best so far, for curves
/// and surfaces alike.
pub(super) struct Best<P> {
    pub(super) tie: f64,
    /// The smallest exact distance among the candidates.
    pub(super) min: f64,
    /// An upper bound of the minimum from the coefficients (corners of surface pieces), for
    /// pruning; infinite where none is known.
    pub(super) bound: f64,
    pub(super) near: Vec<Candidate<P>>,
}

impl<P: Parameter> Best<P> {
    pub(super) fn new(tie: f64) -> Self {
        Best {
            tie,
            min: f64::INFINITY,
            bound: f64::INFINITY,
            near: Vec::new(),
        }
    }

    /// Distances above this cannot be the minimum, nor tie with it.
    pub(super) fn limit(&self) -> f64 {
        self.min.min(self.bound) + self.tie
    }

    /// Keeps `c` if it is within the tie tolerance of the best (NaN distances never are).
    pub(super) fn offer(&mut self, c: Candidate<P>) {
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

    /// The candidate with the smallest parameter among the near ones.
    pub(super) fn choice(&self) -> Option<Candidate<P>> {
        self.near.iter().copied().min_by(|a, b| a.at.order(&b.at))
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
        let mut best = Best::new(self.tie);
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
                    at: p.piece.start,
                    distance: first,
                });
            }
            if last <= nearest_end + best.tie {
                best.offer(Candidate {
                    at: p.piece.end_parameter(),
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
        let t = chosen.at.clamp(self.domain.start, self.domain.end);
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
    let mut best = Best::new(0.0);
    for (t, q) in [(piece.start, piece.points[0]), (piece.end, piece.points[n])] {
        best.offer(Candidate {
            at: t,
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
    best: &mut Best<f64>,
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
            at: piece.start,
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
    // The rounding error of the ratios `a_k / b_k`: the scaled differences are at most 1 in
    // size and the products of binomials of one coefficient sum to 1 (Vandermonde), so each
    // `a_k` is a sum of at most 2n + D + 2 rounded terms, each at most its share of `b_k`
    // (the same products of the weights), and each halving adds at most one rounding of the
    // same size. The lower bound is lowered by it: where the bound is uncertain (a flat piece,
    // a query point on the curve) the interval is kept, never pruned on rounding noise.
    let rounding = |depth: usize| (2 * n + D + 4 + 2 * depth) as f64 * f64::EPSILON;
    while let Some((a, b, lo, hi, depth)) = stack.pop() {
        let slack = rounding(depth);
        let (low, high) = a
            .iter()
            .zip(&b)
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), (x, y)| {
                (l.min(x / y), h.max(x / y))
            });
        let (lower, upper) = (to_distance(low - slack), to_distance(high + slack));
        if lower > best.min + best.tie {
            continue;
        }
        if high - low <= 4.0 * slack {
            // The squared distance is flat on the interval to within its rounding: the
            // coefficients cannot order its points any more (a far query point, the centre of
            // a circle, a query point on the curve near the zero). The true distance decides.
            offer_flat(piece, point, lo, hi, best);
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

/// Offers the ends of `[lo, hi]` (local parameters of `piece`) and the minimum of the true
/// distance on it by golden-section search, where the coefficients of the squared distance no
/// longer tell its points apart.
fn offer_flat<const D: usize>(
    piece: &Piece<D>,
    point: &[f64; D],
    lo: f64,
    hi: f64,
    best: &mut Best<f64>,
) {
    offer_at(piece, point, lo, best);
    offer_at(piece, point, hi, best);
    let at = |x: f64| distance(&piece_point(piece, x), point);
    let ratio = 0.5 * (5.0_f64.sqrt() - 1.0);
    let (mut a, mut b) = (lo, hi);
    let (mut c, mut d) = (b - ratio * (b - a), a + ratio * (b - a));
    let (mut fc, mut fd) = (at(c), at(d));
    for _ in 0..80 {
        if b - a <= 4.0 * f64::EPSILON * b.abs().max(f64::MIN_POSITIVE) {
            break;
        }
        if fc <= fd {
            b = d;
            d = c;
            fd = fc;
            c = b - ratio * (b - a);
            fc = at(c);
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + ratio * (b - a);
            fd = at(d);
        }
    }
    offer_at(piece, point, if fc <= fd { c } else { d }, best);
}

/// Offers the point of `piece` at local parameter `x` in [0, 1].
fn offer_at<const D: usize>(piece: &Piece<D>, point: &[f64; D], x: f64, best: &mut Best<f64>) {
    let position = piece_point(piece, x);
    let t = if x <= 0.0 {
        piece.start
    } else if x >= 1.0 {
        piece.end_parameter()
    } else {
        piece.start + (piece.end - piece.start) * x
    };
    best.offer(Candidate {
        at: t,
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
