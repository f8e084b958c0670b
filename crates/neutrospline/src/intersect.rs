//! Intersections of plane curves of any kinds: Bézier subdivision on the curves' pieces with
//! a Newton polish (as dhermes/bezier does), tangential and end-point intersections included,
//! overlapping pieces reported as such. See `docs/model.md`, section 11.

use core::ops::Range;

use crate::curve::{Derivative, EvalError, Evaluate};
use crate::derivative::CurveDerivative;
use crate::nearest::{distance_to_piece, NearestError, NearestPoint, Piece};
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
    /// How the curves meet there.
    pub contact: Contact,
}

/// How two curves meet at an [`Intersection`].
///
/// With `theta` the angle between the curves' tangents `A'(s)` and `B'(t)` at the point:
/// a crossing has `|sin theta| > 1e-6` ([`TANGENT_SINE`]); a tangential contact has
/// `|sin theta| <= 1e-6` or a vanishing tangent, or is a cluster of roots between which the
/// curves stay within 1e-12 of their size of each other (touching, osculating and tangential
/// crossings alike, each reported once). A point at an end of either curve's domain is an end
/// contact, whatever the angle (a closed curve's seam is no end).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Contact {
    /// The curves cross at an angle.
    Crossing,
    /// The tangents agree: the curves touch, osculate or cross tangentially.
    Tangent,
    /// The point is an end of either curve (of an open curve's domain).
    End,
}

impl Contact {
    /// Every contact, in the order of [`Contact::name`]'s documentation.
    pub const ALL: [Contact; 3] = [Contact::Crossing, Contact::Tangent, Contact::End];

    /// The name used in tables and files: `crossing`, `tangent` or `end`.
    pub const fn name(self) -> &'static str {
        match self {
            Contact::Crossing => "crossing",
            Contact::Tangent => "tangent",
            Contact::End => "end",
        }
    }
}

impl core::fmt::Display for Contact {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(self.name())
    }
}

impl core::str::FromStr for Contact {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Contact::ALL
            .into_iter()
            .find(|c| c.name() == s)
            .ok_or_else(|| format!("unknown contact `{s}` (expected crossing, tangent or end)"))
    }
}

/// The largest `|sin theta|` between the tangents at which two curves count as tangent
/// ([`Contact::Tangent`]): below it a crossing cannot be told from a touch at the precision of
/// the roots (a root within 1e-12 of the curves' size moves by up to `1e-12 / sin theta`).
pub const TANGENT_SINE: f64 = 1e-6;

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
/// Roots within this of each other (in each parameter, relative to its domain) may be one
/// tangential contact ([`Search::collect`]); also the sine above which a root is a clear
/// crossing for that purpose.
const NEAR: f64 = 1e-3;
/// Sample points of one curve within this fraction of the size of the other are on it (the
/// overlap check; coincident curves agree to rounding, about 1e-15).
const ON: f64 = 1e-12;

/// Intersections of plane curves.
///
/// Every point where `a` and `b` meet, ordered by the parameter on `a`: the pieces of both
/// curves (one per Bézier piece) are paired; a pair whose control-point boxes do not overlap
/// cannot meet (convex hull property) and is dropped, any other has its larger piece split at
/// its middle (de Casteljau), until both are smaller than 1e-7 of the curves' size. From
/// there Newton's method on `A(s) - B(t) = 0` polishes each candidate; where the curves are
/// tangent (the Jacobian `[A', -B']` nearly singular) the tangency system
/// `A'(s) x B'(t) = 0`, `(A(s) - B(t)) . A'(s) = 0` is solved instead, and the point is kept
/// when the curves are within 1e-12 of their size there (or within what the floats `s` and
/// `t` resolve, `2 eps (|s| |A'(s)| + |t| |B'(t)|)`, when that is more: a short knot span far
/// from 0). Roots are then grouped into contacts, each with its [`Contact`]. Tangential and end-point
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

    /// Whether the control points of `self` and `other` lie in disjoint bands across the
    /// chord of `self` (more than `slack` apart along its normal): then the pieces cannot
    /// meet (each lies in the convex hull of its control points, positive weights included).
    /// Boxes along the axes cannot part two nearly coincident pieces at 45 degrees until they
    /// are as small as their distance; these bands can (an osculating pair of curves, 1e-9
    /// apart at 1e-3 of the size from their contact, is parted at once, not after 10^5 pieces).
    fn apart_across(&self, other: &Sub, slack: f64) -> bool {
        let (first, last) = (self.points[0], self.points[self.points.len() - 1]);
        let chord = [last[0] - first[0], last[1] - first[1]];
        let length = chord[0].hypot(chord[1]);
        if !(length > 0.0 && length.is_finite()) {
            return false;
        }
        let normal = [-chord[1] / length, chord[0] / length];
        let band = |points: &[[f64; 2]]| {
            points
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
                    let along = (p[0] - first[0]) * normal[0] + (p[1] - first[1]) * normal[1];
                    (lo.min(along), hi.max(along))
                })
        };
        let (a, b) = (band(&self.points), band(&other.points));
        a.1 + slack < b.0 || b.1 + slack < a.0
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
    /// `A''` and `B''`, for projecting onto the curves.
    ha: CurveDerivative<2>,
    hb: CurveDerivative<2>,
    scale: f64,
}

/// `A(s) - B(t)`, `A'(s)` and `B'(t)` at a parameter pair.
type State = ([f64; 2], [f64; 2], [f64; 2]);

/// A stretch two curves share: its parameters on `A` and on `B`.
type Stretch = (Range<f64>, Range<f64>);

/// The parameters on `A` and on `B` of a sub-piece of `A` that lies on `B`.
type Spans = ([f64; 2], [f64; 2]);

/// How two roots are one contact.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Joined {
    /// They are the same point (to 1e-6 of each domain).
    Same,
    /// The curves stay within the root tolerance of each other between them.
    Along,
}

/// A polished candidate: parameters, and `|sin theta|` of the tangents there (1 where a
/// tangent vanishes is not known: 0, tangent).
#[derive(Clone, Copy, Debug)]
struct Root {
    s: f64,
    t: f64,
    sine: f64,
}

impl<'c, A, B> Search<'c, A, B>
where
    A: NearestPoint<2> + Derivative<Output = CurveDerivative<2>>,
    B: NearestPoint<2> + Derivative<Output = CurveDerivative<2>>,
{
    fn new(a: &'c A, b: &'c B, same: bool) -> Self {
        let (da, db) = (a.derivative(), b.derivative());
        Search {
            a,
            b,
            same,
            ha: da.derivative(),
            hb: db.derivative(),
            da,
            db,
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
        let mut terminal: Vec<(Sub, Sub)> = Vec::new();
        let mut crowd = CROWD;
        let mut small = SMALL * self.scale;
        while !pairs.is_empty() {
            if pairs.len() > crowd {
                self.check_overlap(&pairs, &pa, &pb)?;
                if pairs.len() > 16 * CROWD {
                    // Still crowding, and no overlap: a contact of high order, where the curves
                    // stay within the boxes' slack of each other along a stretch. The pairs
                    // alive are polished where they are; halving them further would only
                    // multiply them. Their roots are one contact (`collect`).
                    small = pairs
                        .iter()
                        .fold(small, |m, (x, y)| m.max(x.size()).max(y.size()));
                    crowd = usize::MAX;
                } else {
                    crowd = 4 * pairs.len();
                }
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
                if !x.overlaps(&y, slack) || x.apart_across(&y, slack) || y.apart_across(&x, slack)
                {
                    continue;
                }
                let (xs, ys) = (x.size(), y.size());
                if (xs <= small && ys <= small)
                    || x.depth.max(y.depth) >= MAX_DEPTH
                    || (xs.max(ys) <= NEAR * self.scale && self.touching(&x, &y)?)
                {
                    terminal.push((x, y));
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
        let mut roots = self.polish_terminal(terminal)?;
        if !self.same {
            roots.extend(self.end_roots()?);
        }
        self.collect(roots, &pa, &pb)
    }

    /// The ends of each curve that lie on the other (within 1e-12 of the size), found by the
    /// global nearest point: curves joined end to end, or an end resting on the other curve.
    /// Where the curves meet there tangentially (a smooth join), subdivision and Newton's
    /// method cannot settle on the end (the systems are singular at the domain's edge); the
    /// nearest point can.
    fn end_roots(&self) -> Result<Vec<Root>, IntersectError> {
        let tolerance = 1e-12 * self.scale;
        let (ra, rb) = (self.a.domain(), self.b.domain());
        let mut roots = Vec::new();
        let on_b = self.b.projector();
        for s in [ra.start, ra.end] {
            let near = on_b
                .nearest(self.a.evaluate(s)?.position)
                .map_err(nearest_failure(s))?;
            if near.distance <= tolerance {
                roots.push((s, near.parameter));
            }
        }
        let on_a = self.a.projector();
        for t in [rb.start, rb.end] {
            let near = on_a
                .nearest(self.b.evaluate(t)?.position)
                .map_err(nearest_failure(t))?;
            if near.distance <= tolerance {
                roots.push((near.parameter, t));
            }
        }
        roots
            .into_iter()
            .map(|(s, t)| {
                Ok(Root {
                    s,
                    t,
                    sine: self.sine(s, t)?,
                })
            })
            .collect()
    }

    /// Polishes the pairs that subdivision left (both sub-pieces below 1e-7 of the size):
    /// pairs whose ranges touch in both parameters form a cluster, and a cluster is polished
    /// from each of its pairs when it has at most four (a crossing on the boundary of
    /// sub-pieces), else from its first and last pairs and from the pair whose middles are
    /// nearest each other. Large clusters come from shallow crossings and from tangential
    /// contacts, where the curves stay within the boxes' slack along a stretch (`y = x^4`
    /// and `y = 0`: 2 x 10^4 pairs); Newton's method from any of their pairs reaches the same
    /// point, so polishing each would only repeat it.
    fn polish_terminal(&self, mut terminal: Vec<(Sub, Sub)>) -> Result<Vec<Root>, IntersectError> {
        terminal.sort_by(|p, q| {
            p.0.range[0]
                .total_cmp(&q.0.range[0])
                .then(p.1.range[0].total_cmp(&q.1.range[0]))
        });
        // (s end, t low, t high, members)
        let mut clusters: Vec<(f64, f64, f64, Vec<usize>)> = Vec::new();
        for (k, (x, y)) in terminal.iter().enumerate() {
            let home = clusters
                .iter_mut()
                .rev()
                .find(|c| x.range[0] <= c.0 && y.range[0] <= c.2 && y.range[1] >= c.1);
            match home {
                Some(c) => {
                    c.0 = c.0.max(x.range[1]);
                    c.1 = c.1.min(y.range[0]);
                    c.2 = c.2.max(y.range[1]);
                    c.3.push(k);
                }
                None => clusters.push((x.range[1], y.range[0], y.range[1], vec![k])),
            }
        }
        let middle = |k: usize| {
            let (x, y) = &terminal[k];
            [
                0.5 * (x.range[0] + x.range[1]),
                0.5 * (y.range[0] + y.range[1]),
            ]
        };
        let mut roots: Vec<Root> = Vec::new();
        for (_, _, _, members) in &clusters {
            // A cluster that holds a root found from an earlier one (Newton's method converges
            // to a contact from the pairs all around it) adds nothing.
            let holds = |r: &Root| {
                members.iter().any(|&k| {
                    let (x, y) = &terminal[k];
                    x.range[0] <= r.s && r.s <= x.range[1] && y.range[0] <= r.t && r.t <= y.range[1]
                })
            };
            if roots.iter().any(holds) {
                continue;
            }
            let starts: Vec<usize> = if members.len() <= 4 {
                members.clone()
            } else {
                let mut nearest = (f64::INFINITY, members[0]);
                for &k in members {
                    let [s, t] = middle(k);
                    let (f, _, _) = self.state(s, t)?;
                    let gap = f[0].hypot(f[1]);
                    if gap < nearest.0 {
                        nearest = (gap, k);
                    }
                }
                vec![members[0], nearest.1, members[members.len() - 1]]
            };
            for k in starts {
                if let Some((s, t)) = self.polish(middle(k))? {
                    roots.push(Root {
                        s,
                        t,
                        sine: self.sine(s, t)?,
                    });
                }
            }
        }
        Ok(roots)
    }

    /// Groups the roots into contacts, orders them by `s` and evaluates them.
    ///
    /// Two roots are one contact when they are the same point (within 1e-9 of each domain,
    /// times 1e3), or when they lie within 1e-3 of each domain of each other, at least one is
    /// nearly tangent (`|sin theta| <= 1e-3`) and the curves stay within the root tolerance
    /// (1e-12 of the size) of each other half-way between them: the roots that Newton's method
    /// finds from every sub-piece along a tangential contact, where the curves separate only
    /// at second or higher order. Distinct crossings near a tangency are apart by more than
    /// that (the curves separate between them). A group of several roots is a tangential
    /// contact, reported at its most tangent root (an end of a curve, when one is in it).
    ///
    /// A tangential contact may be a stretch the curves share: [`Search::shared_stretch`]
    /// decides, and the stretch is refused as [`IntersectError::Overlap`].
    fn collect(
        &self,
        mut roots: Vec<Root>,
        pieces_a: &[Sub],
        pieces_b: &[Sub],
    ) -> Result<Vec<Intersection>, IntersectError> {
        let (ra, rb) = (self.a.domain(), self.b.domain());
        let wa = width(&ra);
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
                        Root {
                            s: r.t,
                            t: r.s,
                            sine: r.sine,
                        }
                    }
                })
                .filter(|r| r.t - r.s > SAME * wa.max(1e-300) * 1e3)
                .collect();
        }
        roots.sort_by(|p, q| p.s.total_cmp(&q.s).then(p.t.total_cmp(&q.t)));
        // Each group: its roots, and whether two of them are distinct points joined because the
        // curves stay together between them (a tangential contact).
        let mut groups: Vec<(Vec<Root>, bool)> = Vec::new();
        for r in roots {
            let mut home = None;
            for (k, (g, _)) in groups.iter().enumerate().rev() {
                let last = g[g.len() - 1];
                if r.s - last.s > NEAR * wa.max(1e-300) {
                    continue;
                }
                if let Some(joined) = self.one_contact(&last, &r)? {
                    home = Some((k, joined));
                    break;
                }
            }
            match home {
                Some((k, joined)) => {
                    groups[k].0.push(r);
                    groups[k].1 |= joined == Joined::Along;
                }
                None => groups.push((vec![r], false)),
            }
        }
        let at_end = |r: &Root| {
            (!closed_a && (r.s == ra.start || r.s == ra.end))
                || (!closed_b && (r.t == rb.start || r.t == rb.end))
        };
        let mut found = Vec::with_capacity(groups.len());
        for (g, along) in &groups {
            let chosen = g
                .iter()
                .find(|r| at_end(r))
                .or_else(|| g.iter().min_by(|p, q| p.sine.total_cmp(&q.sine)))
                .copied()
                .expect("a group holds a root");
            let tangent = *along || chosen.sine <= TANGENT_SINE;
            if tangent {
                if let Some((a, b)) = self.shared_stretch(chosen, pieces_a, pieces_b)? {
                    return Err(IntersectError::Overlap { a, b });
                }
            }
            let contact = if at_end(&chosen) {
                Contact::End
            } else if tangent {
                Contact::Tangent
            } else {
                Contact::Crossing
            };
            found.push(Intersection {
                parameter_a: chosen.s,
                parameter_b: chosen.t,
                point_a: self.a.evaluate(chosen.s)?,
                point_b: self.b.evaluate(chosen.t)?,
                contact,
            });
        }
        found.sort_by(|p, q| {
            p.parameter_a
                .total_cmp(&q.parameter_a)
                .then(p.parameter_b.total_cmp(&q.parameter_b))
        });
        Ok(found)
    }

    /// Whether roots `p` and `q` (`p.s <= q.s`) are one contact (see [`Search::collect`]),
    /// and how.
    fn one_contact(&self, p: &Root, q: &Root) -> Result<Option<Joined>, EvalError> {
        let (wa, wb) = (
            width(&self.a.domain()).max(1e-300),
            width(&self.b.domain()).max(1e-300),
        );
        let (ds, dt) = ((q.s - p.s).abs(), (q.t - p.t).abs());
        if ds <= SAME * wa * 1e3 && dt <= SAME * wb * 1e3 {
            return Ok(Some(Joined::Same));
        }
        if ds > NEAR * wa || dt > NEAR * wb || p.sine.min(q.sine) > NEAR {
            return Ok(None);
        }
        let middle = self.a.evaluate(0.5 * (p.s + q.s))?.position;
        let (lo, hi) = (p.t.min(q.t), p.t.max(q.t));
        Ok(
            (self.gap_to_b(middle, 0.5 * (lo + hi), lo, hi)? <= 1e-12 * self.scale)
                .then_some(Joined::Along),
        )
    }

    /// The distance from `point` to `B` on `[lo, hi]`, by Newton's method on
    /// `(B(t) - point) . B'(t) = 0` from `t` (the smallest distance met).
    fn gap_to_b(&self, point: [f64; 2], t: f64, lo: f64, hi: f64) -> Result<f64, EvalError> {
        Ok(self.project_on_b(point, t, lo, hi)?.0)
    }

    /// [`Search::gap_to_b`], with the parameter on `B` where it is met.
    fn project_on_b(
        &self,
        point: [f64; 2],
        t: f64,
        lo: f64,
        hi: f64,
    ) -> Result<(f64, f64), EvalError> {
        project(self.b, &self.db, &self.hb, point, t, lo, hi)
    }

    /// The stretch the curves share around the tangential contact `root`, if they share one:
    /// `A` is followed from `root` in both directions to the end of its piece (at 64 evenly
    /// spaced points and at distances halving down to 2^-40 of the way), each point projected
    /// onto `B`; the curves share the stretch when every point lies on `B` (within 1e-12 of
    /// the size) until the end of `A`'s piece, or until `B`'s projection reaches the end of a
    /// piece of `B` (for one curve: until it turns back onto itself, `s = t`). Two polynomial
    /// (or rational) pieces that agree along an interval agree along the whole of both, so a
    /// shared stretch can only stop where a piece stops; a contact of high order (`y = x^4` on
    /// `y = 0`) stops in the middle of the pieces, where the curves separate.
    fn shared_stretch(
        &self,
        root: Root,
        pieces_a: &[Sub],
        pieces_b: &[Sub],
    ) -> Result<Option<Stretch>, EvalError> {
        let rb = self.b.domain();
        let wb = width(&rb).max(1e-300);
        let on = ON * self.scale;
        let boundary_near = |t: f64, reach: f64| {
            pieces_b
                .iter()
                .any(|p| (t - p.range[0]).abs() <= reach || (t - p.range[1]).abs() <= reach)
        };
        let mut ends = [(root.s, root.t); 2];
        for (k, forward) in [false, true].into_iter().enumerate() {
            let Some(piece) = pieces_a
                .iter()
                .find(|p| p.range[0] <= root.s && root.s <= p.range[1])
            else {
                return Ok(None);
            };
            let limit = if forward {
                piece.range[1]
            } else {
                piece.range[0]
            };
            let mut fractions: Vec<f64> = (1..=64)
                .map(|i| f64::from(i) / 64.0)
                .chain((1..=40).map(|i| 0.5_f64.powi(i)))
                .collect();
            fractions.sort_by(f64::total_cmp);
            let (mut last, mut before) = ((root.s, root.t), root.t);
            let mut reached = root.s == limit;
            for f in fractions {
                if reached {
                    break;
                }
                let s = root.s + (limit - root.s) * f;
                let point = self.a.evaluate(s)?.position;
                let (gap, t) = self.project_on_b(point, last.1, rb.start, rb.end)?;
                let step = (last.1 - before).abs() + 1e-9 * wb;
                if gap > on {
                    // The curves part between `last` and `s`: where, by bisection.
                    let mut parted = s;
                    for _ in 0..60 {
                        let middle = 0.5 * (last.0 + parted);
                        if middle == last.0 || middle == parted {
                            break;
                        }
                        let point = self.a.evaluate(middle)?.position;
                        let (gap, t) = self.project_on_b(point, last.1, rb.start, rb.end)?;
                        if gap > on {
                            parted = middle;
                        } else {
                            last = (middle, t);
                        }
                    }
                    // A shared stretch ends here only at the end of a piece of B (or, for one
                    // curve, where it turns back onto itself).
                    reached = boundary_near(last.1, 2.0 * step)
                        || (self.same && (last.0 - last.1).abs() <= 2.0 * step);
                    break;
                }
                before = last.1;
                last = (s, t);
                reached = f == 1.0;
            }
            if !reached {
                return Ok(None);
            }
            ends[k] = last;
        }
        // Ends within 1e-9 of a piece's end are on it.
        let snap = |x: f64, pieces: &[Sub], w: f64| {
            pieces
                .iter()
                .flat_map(|p| p.range)
                .find(|&e| (x - e).abs() <= 1e-9 * w)
                .unwrap_or(x)
        };
        let wa = width(&self.a.domain()).max(1e-300);
        let mut snapped = [(0.0, 0.0); 2];
        for (k, (s, t)) in ends.into_iter().enumerate() {
            let (s, t) = (snap(s, pieces_a, wa), snap(t, pieces_b, wb));
            // At the end of a piece of B, the end on A is where A passes B's end point.
            let at_a = pieces_a.iter().any(|p| p.range.contains(&s));
            let s = if !at_a && pieces_b.iter().any(|p| p.range.contains(&t)) {
                let ra = self.a.domain();
                let point = self.b.evaluate(t)?.position;
                let (gap, on_a) = project(self.a, &self.da, &self.ha, point, s, ra.start, ra.end)?;
                if gap <= on {
                    snap(on_a, pieces_a, wa)
                } else {
                    s
                }
            } else {
                s
            };
            snapped[k] = (s, t);
        }
        let ends = snapped;
        let (s0, s1) = (ends[0].0.min(ends[1].0), ends[0].0.max(ends[1].0));
        let (t0, t1) = (ends[0].1.min(ends[1].1), ends[0].1.max(ends[1].1));
        if s1 - s0 <= SAME * 1e3 * width(&self.a.domain()) {
            // A point, not a stretch (the contact is at the end of both pieces).
            return Ok(None);
        }
        Ok(Some((s0..s1, t0..t1)))
    }

    /// Whether the middle of `x` lies on `y` (within the root tolerance, 1e-12 of the size):
    /// a pair inside a tangential contact, where the curves stay together along a stretch.
    /// Such a pair is polished where it is; halving it would only multiply the pairs of the
    /// contact (the subdivision of `y = x^8` touching `y = 0` down to 1e-7 makes 3 x 10^5).
    /// A crossing inside it is found by the polish (and a second one, if the curves stay
    /// within the tolerance of each other between them, is the same contact).
    fn touching(&self, x: &Sub, y: &Sub) -> Result<bool, EvalError> {
        let middle = self.a.evaluate(0.5 * (x.range[0] + x.range[1]))?.position;
        let gap = self.gap_to_b(
            middle,
            0.5 * (y.range[0] + y.range[1]),
            y.range[0],
            y.range[1],
        )?;
        Ok(gap <= 1e-12 * self.scale)
    }

    /// The root tolerance at `(s, t)`: 1e-12 of the size, or what the parameters can resolve
    /// there when that is more (a domain far from 0 and narrow, `[1e4, 1e4 + 1e-3]`, moves
    /// the point by `|A'(s)| ulp(s)` per step of the float `s`).
    fn tolerance(&self, s: f64, t: f64, va: [f64; 2], vb: [f64; 2]) -> f64 {
        let resolution =
            2.0 * f64::EPSILON * (s.abs() * va[0].hypot(va[1]) + t.abs() * vb[0].hypot(vb[1]));
        1e-12 * self.scale
            + if resolution.is_finite() {
                resolution
            } else {
                0.0
            }
    }

    /// `|sin theta|` between `A'(s)` and `B'(t)`; 0 where a tangent vanishes.
    fn sine(&self, s: f64, t: f64) -> Result<f64, EvalError> {
        let (_, va, vb) = self.state(s, t)?;
        let norm = va[0].hypot(va[1]) * vb[0].hypot(vb[1]);
        Ok(if norm > 0.0 && norm.is_finite() {
            ((va[0] * vb[1] - va[1] * vb[0]) / norm).abs()
        } else {
            0.0
        })
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
    fn polish(&self, start: [f64; 2]) -> Result<Option<(f64, f64)>, IntersectError> {
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
        let snapped = (near(root.0, &ra), near(root.1, &rb));
        if snapped != root {
            let (f, _, _) = self.state(snapped.0, snapped.1)?;
            if f[0].hypot(f[1]) <= 1e-12 * self.scale {
                return Ok(Some(snapped));
            }
        }
        Ok(Some(root))
    }

    /// Newton's method from `start` on `A(s) - B(t) = 0`, then, where the curves are nearly
    /// tangent, on the tangency system; `None` when the curves do not meet there.
    fn newton(&self, start: [f64; 2]) -> Result<Option<(f64, f64)>, IntersectError> {
        let (ra, rb) = (self.a.domain(), self.b.domain());
        let clamp = |s: f64, t: f64| (s.clamp(ra.start, ra.end), t.clamp(rb.start, rb.end));
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
        let tolerance = self.tolerance(bs, bt, va, vb);
        let cross = (va[0] * vb[1] - va[1] * vb[0]).abs();
        let norm = va[0].hypot(va[1]) * vb[0].hypot(vb[1]);
        if gap <= tolerance && cross > 1e-6 * norm {
            return Ok(Some((bs, bt)));
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
            return Ok(Some((s, t)));
        }
        if gap <= tolerance {
            return Ok(Some((bs, bt)));
        }
        // Both systems are singular where the curves run together (an overlap, a contact of
        // high order, parallel lines): the start's point of A projected onto B.
        let (s, t) = clamp(start[0], start[1]);
        let point = self.a.evaluate(s)?.position;
        let (gap, t) = self.project_on_b(point, t, rb.start, rb.end)?;
        Ok((gap <= tolerance).then_some((s, t)))
    }

    /// Pairs crowd: look for sub-pieces of `A` that lie on `B`: nine points of each within
    /// 1e-12 of the size of the sub-pieces of `B` it is paired with (at most 512 sub-pieces of
    /// `A`, evenly spread in `s`, are tested; each test is nine nearest-point searches). The
    /// curves share a stretch when at least a quarter of the tested sub-pieces lie on `B` and
    /// the stretch they span ends, at both of its ends, where a piece of either curve ends
    /// (or, for one curve, where it turns back onto itself, `s = t`): two polynomial (or
    /// rational) pieces that agree along an interval agree along the whole of both pieces, so
    /// a shared stretch can only stop where a piece stops. A contact of high order (`y = x^4`
    /// touching `y = 0`) crowds the pairs too, but in the middle of the pieces: it is no
    /// overlap, and its roots are one contact.
    fn check_overlap(
        &self,
        pairs: &[(Sub, Sub)],
        pieces_a: &[Sub],
        pieces_b: &[Sub],
    ) -> Result<(), IntersectError> {
        // The pairs grouped by their sub-piece of A, in order of s.
        let mut sorted: Vec<&(Sub, Sub)> = pairs
            .iter()
            .filter(|(x, y)| !(self.same && x.range == y.range))
            .collect();
        sorted.sort_by(|p, q| {
            p.0.range[0]
                .total_cmp(&q.0.range[0])
                .then(p.0.range[1].total_cmp(&q.0.range[1]))
        });
        let mut groups: Vec<&[&(Sub, Sub)]> = Vec::new();
        let mut start = 0;
        for k in 1..=sorted.len() {
            if k == sorted.len() || sorted[k].0.range != sorted[start].0.range {
                groups.push(&sorted[start..k]);
                start = k;
            }
        }
        if groups.is_empty() {
            return Ok(());
        }
        let stride = groups.len().div_ceil(512);
        let tested: Vec<&[&(Sub, Sub)]> = groups.iter().step_by(stride).copied().collect();
        // (s range, t range) of each tested sub-piece of A that lies on B.
        let mut on: Vec<Spans> = Vec::new();
        for group in &tested {
            let x = &group[0].0;
            let pieces: Vec<Piece<2>> = group
                .iter()
                .map(|(_, y)| Piece {
                    start: y.range[0],
                    end: y.range[1],
                    points: y.points.clone(),
                    weights: y.weights.clone(),
                    jump_at_end: false,
                })
                .collect();
            let mut all = true;
            for k in 0..=8 {
                let s = x.range[0] + (x.range[1] - x.range[0]) * k as f64 / 8.0;
                let p = self.a.evaluate(s)?.position;
                let gap = pieces
                    .iter()
                    .map(|piece| distance_to_piece(piece.clone(), &p))
                    .fold(f64::INFINITY, f64::min);
                if gap > ON * self.scale {
                    all = false;
                    break;
                }
            }
            if all {
                let t = group
                    .iter()
                    .fold([f64::INFINITY, f64::NEG_INFINITY], |m, (_, y)| {
                        [m[0].min(y.range[0]), m[1].max(y.range[1])]
                    });
                on.push((x.range, t));
            }
        }
        if on.is_empty() || on.len() * 4 < tested.len() {
            return Ok(());
        }
        let a = on.iter().fold(f64::INFINITY, |m, p| m.min(p.0[0]))
            ..on.iter().fold(f64::NEG_INFINITY, |m, p| m.max(p.0[1]));
        let b = on.iter().fold(f64::INFINITY, |m, p| m.min(p.1[0]))
            ..on.iter().fold(f64::NEG_INFINITY, |m, p| m.max(p.1[1]));
        // The stretch's ends, as (s, t): B runs along A or against it (`on` is in order of s).
        let along = on[0].1[0] <= on[on.len() - 1].1[0];
        let ends = if along {
            [(a.start, b.start), (a.end, b.end)]
        } else {
            [(a.start, b.end), (a.end, b.start)]
        };
        // How far the tested stretch may stop short of its true end: the widths of the
        // sub-pieces and the spacing of the tested ones.
        let reach = |range: fn(&Spans) -> [f64; 2]| {
            let mut starts: Vec<f64> = on.iter().map(|p| range(p)[0]).collect();
            starts.sort_by(f64::total_cmp);
            let gaps = starts.windows(2).fold(0.0_f64, |m, w| m.max(w[1] - w[0]));
            on.iter()
                .fold(gaps, |m, p| m.max(range(p)[1] - range(p)[0]))
        };
        let (reach_s, reach_t) = (reach(|p| p.0), reach(|p| p.1));
        let boundary = |x: f64, pieces: &[Sub], reach: f64| {
            pieces.iter().any(|p| {
                (x - p.range[0]).abs() <= 2.0 * reach || (x - p.range[1]).abs() <= 2.0 * reach
            })
        };
        let stops = |(s, t): (f64, f64)| {
            boundary(s, pieces_a, reach_s)
                || boundary(t, pieces_b, reach_t)
                || (self.same && (s - t).abs() <= 2.0 * (reach_s + reach_t))
        };
        if ends.into_iter().all(stops) {
            Err(IntersectError::Overlap { a, b })
        } else {
            Ok(())
        }
    }
}

/// The distance from `point` to `curve` on `[lo, hi]`, by Newton's method on
/// `(C(t) - point) . C'(t) = 0` from `t` (`first` and `second` are `C'` and `C''`): the
/// smallest distance met, and its parameter.
fn project<C: Evaluate<Point = CurvePoint<2>>>(
    curve: &C,
    first: &CurveDerivative<2>,
    second: &CurveDerivative<2>,
    point: [f64; 2],
    mut t: f64,
    lo: f64,
    hi: f64,
) -> Result<(f64, f64), EvalError> {
    let mut gap = (f64::INFINITY, t);
    for _ in 0..16 {
        let q = curve.evaluate(t)?.position;
        let d = [q[0] - point[0], q[1] - point[1]];
        let here = d[0].hypot(d[1]);
        if here < gap.0 {
            gap = (here, t);
        }
        let v = first.evaluate(t)?.position;
        let acc = second.evaluate(t)?.position;
        let slope = d[0] * v[0] + d[1] * v[1];
        let curvature = v[0] * v[0] + v[1] * v[1] + d[0] * acc[0] + d[1] * acc[1];
        // Not a minimum there (or NaN): stop.
        if curvature.is_nan() || curvature <= 0.0 {
            break;
        }
        let next = (t - slope / curvature).clamp(lo, hi);
        if next == t {
            break;
        }
        t = next;
    }
    Ok(gap)
}

/// A nearest-point search from an end (at parameter `t` of its curve) fails only where the
/// curves' values overflow.
fn nearest_failure(t: f64) -> impl Fn(NearestError) -> IntersectError {
    move |e| match e {
        NearestError::Eval(e) => IntersectError::Eval(e),
        _ => IntersectError::Eval(EvalError::Overflow { t }),
    }
}

fn width(r: &Range<f64>) -> f64 {
    r.end - r.start
}
