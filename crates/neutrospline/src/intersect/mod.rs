//! Intersections of plane curves of any kinds: Bézier subdivision on the curves' pieces with
//! a Newton polish (as dhermes/bezier does), tangential and end-point intersections included,
//! overlapping pieces reported as such. See `docs/model.md`, section 11.

mod contact;
mod overlap;
mod search;
mod sub;

use core::ops::Range;

use crate::curve::{Derivative, EvalError, Evaluate};
use crate::derivative::CurveDerivative;
use crate::nearest::{NearestError, NearestPoint};
use crate::point::CurvePoint;
use search::Search;

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
    /// A curve is not a plane curve ([`crate::DynCurve::intersections`]).
    #[error("the {which} curve is {dimension}-D (intersections are of plane curves)")]
    NotPlanar {
        /// `first` or `second`.
        which: &'static str,
        /// The curve's dimension.
        dimension: usize,
    },
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
