//! Neutrosophic B-spline and NURBS curves: one generic type, [`SplineCurve`], whose
//! weighting ([`Polynomial`] or [`Rational`]) is a type parameter, so every algorithm is
//! written once for both kinds (see `docs/model.md`, "B-spline and NURBS curves").

use core::fmt::Debug;
use core::hash::Hash;
use core::marker::PhantomData;
use core::ops::Range;

use crate::bernstein::Packed;
use crate::bezier::Bezier;
use crate::curve::CurveKind;
use crate::curve::{
    check_parameter, Bounded, ControlPolygon, CurveError, Derivative, Elevate, EvalError, Evaluate,
    Split, BOUNDS_TOLERANCE,
};
use crate::degrees::DegreeKind;
use crate::derivative::CurveDerivative;
use crate::knots::{KnotError, KnotVector};
use crate::layout::{lift_degree, pack_points, point_from_row, stride};
use crate::point::{Affine, BoundingBox, ControlPoint, CurvePoint};
use crate::spline::Spline;

mod sealed {
    pub trait Sealed {}
    impl Sealed for super::Polynomial {}
    impl Sealed for super::Rational {}
}

/// Whether a [`SplineCurve`] is rational: [`Polynomial`] (B-spline) or [`Rational`] (NURBS).
/// Sealed: these are the only two.
pub trait Weighting:
    sealed::Sealed + Copy + Debug + PartialEq + Eq + Hash + Send + Sync + 'static
{
    /// `true` for NURBS curves, whose control points carry weights.
    const RATIONAL: bool;
    /// The kind of curve.
    const KIND: CurveKind;
}

/// The weighting of B-spline curves: no weights (every weight is 1).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Polynomial {}

/// The weighting of NURBS curves: a positive weight per control point.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Rational {}

impl Weighting for Polynomial {
    const RATIONAL: bool = false;
    const KIND: CurveKind = CurveKind::BSpline;
}

impl Weighting for Rational {
    const RATIONAL: bool = true;
    const KIND: CurveKind = CurveKind::Nurbs;
}

/// A neutrosophic B-spline curve of degree `p` in `D` dimensions.
///
/// With the B-spline basis `N_{i,p}` over the knot vector `u_0 <= ... <= u_m`:
///
/// ```text
/// C(t) = sum_i N_{i,p}(t) P_i,  T(t) = sum_i N_{i,p}(t) T_i,  (same for I and F)
/// ```
///
/// for `t` in the domain `[u_p, u_{m-p}]`. The basis is non-negative with unit sum, so every
/// property of a neutrosophic Bézier curve holds: degrees stay within the control range,
/// the curve lies in the convex hull of its control points (locally, of `p + 1` of them), and
/// affine maps commute. Evaluation is the compensated de Boor algorithm on all channels at
/// once.
///
/// ```
/// use neutrospline::{BSpline, ControlPoint, Degrees, Evaluate, KnotVector};
/// let d = Degrees::new(0.2, 0.4, 0.6)?;
/// let pts: Vec<_> = [[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]]
///     .into_iter()
///     .map(|p| ControlPoint::new(p, d))
///     .collect();
/// let curve = BSpline::new(pts, KnotVector::clamped_uniform(2, 4)?)?;
/// assert_eq!(curve.evaluate(0.0)?.position, [0.0, 0.0]);
/// assert_eq!(curve.evaluate(0.5)?.position, [2.0, 2.0]);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub type BSpline<const D: usize> = SplineCurve<D, Polynomial>;

/// A neutrosophic NURBS curve: a B-spline with a positive weight per control point.
///
/// Positions and degrees are blended with the rational basis
/// `R_i(t) = w_i N_{i,p}(t) / sum_j w_j N_{j,p}(t)`, which is non-negative with unit sum:
///
/// ```text
/// C(t) = sum_i R_i(t) P_i,  T(t) = sum_i R_i(t) T_i,  (same for I and F)
/// ```
///
/// so every invariant of the Bézier model carries over. Evaluation is the compensated de Boor
/// algorithm on the homogeneous rows `(w P, w)`, then a compensated division; the result is
/// projected onto the range of the span's control values, which contains the exact value.
///
/// ```
/// use neutrospline::{ControlPoint, Degrees, Evaluate, KnotVector, Nurbs};
/// // A quarter of the unit circle.
/// let d = Degrees::new(1.0, 0.0, 0.0)?;
/// let pts = vec![
///     ControlPoint::new([1.0, 0.0], d),
///     ControlPoint::new([1.0, 1.0], d),
///     ControlPoint::new([0.0, 1.0], d),
/// ];
/// let w = std::f64::consts::FRAC_1_SQRT_2;
/// let arc = Nurbs::new(pts, vec![1.0, w, 1.0], KnotVector::clamped_uniform(2, 3)?)?;
/// let [x, y] = arc.evaluate(0.3)?.position;
/// assert!((x * x + y * y - 1.0).abs() < 1e-15);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub type Nurbs<const D: usize> = SplineCurve<D, Rational>;

/// A spline curve of degree `p` in `D` dimensions (`D` = 2 or 3), polynomial ([`BSpline`])
/// or rational ([`Nurbs`]); use those two names.
///
/// Positions and the three degrees are channels of one packed array blended by one
/// (compensated) de Boor routine, and every computed point is projected onto the range of
/// its span's control values, so its degrees stay between their inputs. A B-spline is the
/// NURBS curve whose weights are all 1, and gives bit for bit the same values.
#[derive(Clone, Debug, PartialEq)]
pub struct SplineCurve<const D: usize, W: Weighting> {
    spline: Spline,
    weighting: PhantomData<W>,
}

/// A Bézier piece of a spline curve: the curve on `[start, end]`, reparametrised to \[0, 1\].
#[derive(Clone, Debug, PartialEq)]
pub struct BezierSegment<C> {
    /// Parameter where the piece starts on the spline.
    pub start: f64,
    /// Parameter where the piece ends on the spline.
    pub end: f64,
    /// The piece.
    pub curve: C,
}

impl<const D: usize> BSpline<D> {
    /// The curve with these control points over `knots`, whose degree is the curve's.
    ///
    /// # Errors
    /// No control points, a non-finite position, a dimension other than 2 or 3, or knots made
    /// for another number of control points ([`CurveError::Knots`]).
    pub fn new(
        control_points: Vec<ControlPoint<D>>,
        knots: KnotVector,
    ) -> Result<Self, CurveError> {
        Self::build(control_points, None, knots)
    }

    /// The curve of `degree` with clamped uniform knots on \[0, 1\].
    ///
    /// # Errors
    /// As [`BSpline::new`]; too few control points for the degree.
    pub fn clamped_uniform(
        control_points: Vec<ControlPoint<D>>,
        degree: usize,
    ) -> Result<Self, CurveError> {
        let knots = KnotVector::clamped_uniform(degree, control_points.len())?;
        BSpline::new(control_points, knots)
    }

    /// The periodic (closed) curve of `degree` with the `n` distinct control points
    /// `control_points` over the breakpoints `tau_0 <= ... <= tau_n` (`n + 1` of them): the
    /// B-spline over [`KnotVector::periodic`] whose control points are these followed by the
    /// first `degree` of them again (docs/model.md, "Knot vectors"). The domain is
    /// `[tau_0, tau_n]`, and the curve, its degrees and its first `degree - 1` derivatives
    /// agree at the two ends.
    ///
    /// ```
    /// use neutrospline::{BSpline, ControlPoint, ControlPolygon, Degrees, Evaluate};
    /// let d = Degrees::new(0.5, 0.25, 0.125)?;
    /// let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
    ///     .map(|p| ControlPoint::new(p, d))
    ///     .to_vec();
    /// let curve = BSpline::periodic(square, 2, &[0.0, 0.25, 0.5, 0.75, 1.0])?;
    /// assert_eq!(curve.control_points().len(), 6);
    /// assert_eq!(curve.periodic_count(), Some(4));
    /// assert_eq!(curve.evaluate(0.0)?.position, [0.5, 0.0]);
    /// assert_eq!(curve.evaluate(1.0)?.position, [0.5, 0.0]);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// As [`KnotVector::periodic`] (as [`CurveError::Knots`]); a breakpoint count other than
    /// the number of control points + 1; as [`BSpline::new`].
    pub fn periodic(
        control_points: Vec<ControlPoint<D>>,
        degree: usize,
        breakpoints: &[f64],
    ) -> Result<Self, CurveError> {
        let (points, _, knots) = periodic_parts(control_points, None, degree, breakpoints)?;
        BSpline::new(points, knots)
    }

    /// The polynomial pieces of the curve as Bézier curves, one per non-empty knot span of the
    /// domain, in order.
    pub fn to_bezier_segments(&self) -> Vec<BezierSegment<Bezier<D>>> {
        self.segments(|packed, _| Bezier::from_packed(packed))
    }
}

impl<const D: usize> Nurbs<D> {
    /// The curve with these control points, one positive weight each, over `knots`.
    ///
    /// # Errors
    /// As [`BSpline::new`]; [`CurveError::WeightCount`]; [`CurveError::WeightNotPositive`]
    /// for a weight that is not a positive finite number.
    pub fn new(
        control_points: Vec<ControlPoint<D>>,
        weights: Vec<f64>,
        knots: KnotVector,
    ) -> Result<Self, CurveError> {
        Self::build(control_points, Some(weights), knots)
    }

    /// The periodic (closed) NURBS curve of `degree` with the `n` distinct control points and
    /// weights over the breakpoints `tau_0 <= ... <= tau_n`, as [`BSpline::periodic`].
    ///
    /// # Errors
    /// As [`BSpline::periodic`] and [`Nurbs::new`].
    pub fn periodic(
        control_points: Vec<ControlPoint<D>>,
        weights: Vec<f64>,
        degree: usize,
        breakpoints: &[f64],
    ) -> Result<Self, CurveError> {
        let (points, weights, knots) =
            periodic_parts(control_points, Some(weights), degree, breakpoints)?;
        Nurbs::new(points, weights.unwrap_or_default(), knots)
    }

    /// A NURBS curve with every weight 1: the same curve as `curve`.
    pub fn from_bspline(curve: &BSpline<D>) -> Self {
        let mut spline = curve.spline.clone();
        spline.weights = Some(vec![1.0; spline.count()]);
        SplineCurve::from_spline(spline)
    }

    /// The rational Bézier pieces, one per non-empty knot span of the domain, each as a NURBS
    /// curve on Bézier knots over \[0, 1\].
    pub fn to_bezier_segments(&self) -> Vec<BezierSegment<Nurbs<D>>> {
        self.segments(|packed, weights| {
            SplineCurve::from_spline(Spline::from_bezier(&packed, weights))
        })
    }
}

impl<const D: usize, W: Weighting> SplineCurve<D, W> {
    /// Checks and packs the control data; `weights` is `Some` exactly for NURBS.
    fn build(
        control_points: Vec<ControlPoint<D>>,
        weights: Option<Vec<f64>>,
        knots: KnotVector,
    ) -> Result<Self, CurveError> {
        let data = pack_points(&control_points)?;
        if let Some(weights) = &weights {
            check_weights(weights, control_points.len())?;
        }
        if knots.control_count() != control_points.len() {
            return Err(KnotError::WrongLength {
                got: knots.knots().len(),
                expected: control_points.len() + knots.degree() + 1,
            }
            .into());
        }
        Ok(SplineCurve::from_spline(Spline {
            knots,
            stride: stride(D),
            data,
            weights,
        }))
    }

    /// Wraps checked control data (weights present exactly when `W` is rational).
    pub(crate) fn from_spline(spline: Spline) -> Self {
        debug_assert_eq!(spline.weights.is_some(), W::RATIONAL);
        SplineCurve {
            spline,
            weighting: PhantomData,
        }
    }

    pub(crate) fn spline(&self) -> &Spline {
        &self.spline
    }

    /// The kind: [`CurveKind::BSpline`] or [`CurveKind::Nurbs`].
    pub fn kind(&self) -> CurveKind {
        W::KIND
    }

    /// The polynomial degree p.
    pub fn degree(&self) -> usize {
        self.spline.degree()
    }

    /// `Some(n)` when the curve is periodic ([`BSpline::periodic`]): its knots are
    /// [`KnotVector::periodic`] of their breakpoints (to the last bit) and its last `degree`
    /// control points (and weights) repeat its first ones, `n` being the distinct ones.
    pub fn periodic_count(&self) -> Option<usize> {
        self.spline.periodic_count()
    }

    /// The knot vector.
    pub fn knots(&self) -> &KnotVector {
        &self.spline.knots
    }

    /// The weights, one per control point (NURBS); `None` for a B-spline, whose weights are
    /// all 1.
    pub fn weights(&self) -> Option<&[f64]> {
        self.spline.weights.as_deref()
    }

    /// The same curve with the knot `u` inserted once (Boehm's algorithm; for NURBS in
    /// rational form, each new point a convex combination).
    ///
    /// # Errors
    /// `u` outside the domain, or its multiplicity would exceed `p + 1`.
    pub fn insert_knot(&self, u: f64) -> Result<Self, KnotError> {
        Ok(SplineCurve::from_spline(self.spline.insert_knot(u)?))
    }

    /// The same curve traversed backwards on the same domain `[a, b]`: its point at `t` is
    /// this curve's point at `a + b - t` (control points and weights in reverse order, knots
    /// reflected).
    pub fn reversed(&self) -> Self {
        SplineCurve::from_spline(self.spline.reversed())
    }

    /// The curve with an affine map applied to its control positions; weights and degrees
    /// unchanged (B-spline and NURBS curves are affine invariant).
    ///
    /// # Errors
    /// A mapped position overflows.
    pub fn transform(&self, map: &Affine<D>) -> Result<Self, CurveError> {
        let data = pack_points(&map.apply_to_points(self.control_points()))?;
        Ok(SplineCurve::from_spline(Spline {
            data,
            ..self.spline.clone()
        }))
    }

    /// The Bézier pieces of the control data, one per non-empty knot span, each made by
    /// `piece` from its packed control rows and (for NURBS) weights.
    fn segments<C>(&self, piece: impl Fn(Packed, Option<Vec<f64>>) -> C) -> Vec<BezierSegment<C>> {
        self.spline
            .bezier_segments()
            .into_iter()
            .map(|s| BezierSegment {
                start: s.start,
                end: s.end,
                curve: piece(s.packed, s.weights),
            })
            .collect()
    }
}

impl<W: Weighting> SplineCurve<2, W> {
    /// The space curve `(C(t), degree(t))` of one degree: control points
    /// `(x_i, y_i, degree_i)` with the same knots (and weights).
    pub fn degree_curve(&self, kind: DegreeKind) -> SplineCurve<3, W> {
        SplineCurve::from_spline(Spline {
            knots: self.spline.knots.clone(),
            stride: stride(3),
            data: lift_degree(&self.spline.data, kind),
            weights: self.spline.weights.clone(),
        })
    }
}

/// Checks one positive finite weight per control point.
pub(crate) fn check_weights(weights: &[f64], points: usize) -> Result<(), CurveError> {
    if weights.len() != points {
        return Err(CurveError::WeightCount {
            weights: weights.len(),
            points,
        });
    }
    match weights
        .iter()
        .enumerate()
        .find(|(_, w)| !(w.is_finite() && **w > 0.0))
    {
        Some((index, &value)) => Err(CurveError::WeightNotPositive { index, value }),
        None => Ok(()),
    }
}

impl<const D: usize, W: Weighting> ControlPolygon<D> for SplineCurve<D, W> {
    fn len(&self) -> usize {
        self.spline.count()
    }

    fn control_point(&self, i: usize) -> ControlPoint<D> {
        point_from_row(self.spline.row(i))
    }
}

impl<const D: usize, W: Weighting> Evaluate for SplineCurve<D, W> {
    type Point = CurvePoint<D>;

    /// The domain `u_p..u_{m-p}`.
    fn domain(&self) -> Range<f64> {
        self.spline.knots.domain()
    }

    /// The point at `t` in the domain, by the compensated de Boor algorithm (error-free
    /// transformations; for NURBS the homogeneous numerator and weight compensated, then a
    /// compensated division): about one rounding of the exact value at any degree (scaled
    /// error below 5e-16 at degree 2000, tested against mpmath).
    ///
    /// # Errors
    /// `t` not finite or outside the domain.
    fn evaluate(&self, t: f64) -> Result<CurvePoint<D>, EvalError> {
        self.evaluate_sum(t, 0.0)
    }

    /// The point at the exact sum `origin + offset`, each knot difference taken as
    /// `(origin - u_i) + offset`.
    ///
    /// # Errors
    /// `origin + offset` not finite or outside the domain.
    fn evaluate_sum(&self, origin: f64, offset: f64) -> Result<CurvePoint<D>, EvalError> {
        check_parameter(origin + offset, &self.domain())?;
        let mut row = [0.0; 6];
        self.spline.evaluate_sum(origin, offset, &mut row);
        Ok(point_from_row(&row))
    }
}

impl<const D: usize, W: Weighting> Derivative for SplineCurve<D, W> {
    type Output = CurveDerivative<D>;

    /// The derivative: for a B-spline, a B-spline of degree `p - 1` on the knots without
    /// their first and last, with control values `p (P_{i+1} - P_i) / (u_{i+p+1} - u_{i+1})`;
    /// for NURBS, the quotient rule on the homogeneous form
    /// `A(t) = sum N_i w_i P_i`, `w(t) = sum N_i w_i`: `C' = (A' - w' C) / w`.
    fn derivative(&self) -> CurveDerivative<D> {
        CurveDerivative::of_spline(&self.spline, self.domain())
    }
}

impl<const D: usize, W: Weighting> Split for SplineCurve<D, W> {
    /// The pieces on `[a, t]` and `[t, b]` of the domain `[a, b]`, keeping the parameters:
    /// `t` is inserted until its multiplicity is `p + 1`.
    fn split(&self, t: f64) -> Result<(Self, Self), EvalError> {
        let domain = self.domain();
        check_parameter(t, &domain)?;
        if t == domain.start || t == domain.end {
            return Err(EvalError::EmptyPiece {
                start: if t == domain.start { domain.start } else { t },
                end: if t == domain.start { t } else { domain.end },
            });
        }
        let (left, right) = self.spline.split(t);
        Ok((
            SplineCurve::from_spline(left),
            SplineCurve::from_spline(right),
        ))
    }

    /// The piece on `[t0, t1]` with the curve's parameters; for `t0 > t1`, the piece on
    /// `[t1, t0]` reversed (its point at `t` is the curve's at `t0 + t1 - t`).
    fn subsegment(&self, t0: f64, t1: f64) -> Result<Self, EvalError> {
        let domain = self.domain();
        check_parameter(t0, &domain)?;
        check_parameter(t1, &domain)?;
        if t0 == t1 {
            return Err(EvalError::EmptyPiece { start: t0, end: t1 });
        }
        let piece = SplineCurve::from_spline(self.spline.restricted(t0.min(t1), t0.max(t1)));
        Ok(if t0 > t1 { piece.reversed() } else { piece })
    }
}

impl<const D: usize, W: Weighting> Elevate for SplineCurve<D, W> {
    /// Degree elevation: the same curve with degree `p + 1` (homogeneous elevation for NURBS),
    /// each interior knot's multiplicity raised by one, clamped on the domain.
    fn elevate(&self) -> Self {
        SplineCurve::from_spline(self.spline.elevate(D..D + 3))
    }
}

impl<const D: usize, W: Weighting> Bounded<D> for SplineCurve<D, W> {
    /// Branch and bound on each (rational) Bézier piece; positive weights keep the convex
    /// hull property.
    fn bounding_box(&self) -> BoundingBox<D> {
        self.spline
            .bezier_segments()
            .iter()
            .map(|s| {
                BoundingBox::from_channel_ranges(|c| {
                    s.packed
                        .channel_range(c, s.weights.as_deref(), BOUNDS_TOLERANCE)
                })
            })
            .reduce(|a, b| a.union(&b))
            .unwrap_or_else(|| self.control_bounding_box())
    }

    fn control_bounding_box(&self) -> BoundingBox<D> {
        BoundingBox::from_channel_ranges(|c| self.spline.channel_range(c))
    }
}

impl<const D: usize> Bezier<D> {
    /// The same curve as a clamped B-spline: the same control points over `n + 1` knots 0
    /// then `n + 1` knots 1 (one span on \[0, 1\]).
    ///
    /// ```
    /// use neutrospline::Evaluate;
    /// let spline = neutrospline::example1().to_bspline();
    /// assert_eq!(spline.knots().knots(), &[0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0]);
    /// assert_eq!(spline.evaluate(0.5)?.position, [4.625, 4.0]);
    /// # Ok::<(), neutrospline::EvalError>(())
    /// ```
    pub fn to_bspline(&self) -> BSpline<D> {
        BSpline::from_spline(Spline::from_bezier(self.packed(), None))
    }
}

/// The control points (and weights) of a periodic curve, the distinct ones followed by the
/// first `degree` again (cyclically), and its knots: [`BSpline::periodic`].
type PeriodicParts<const D: usize> = (Vec<ControlPoint<D>>, Option<Vec<f64>>, KnotVector);

fn periodic_parts<const D: usize>(
    control_points: Vec<ControlPoint<D>>,
    weights: Option<Vec<f64>>,
    degree: usize,
    breakpoints: &[f64],
) -> Result<PeriodicParts<D>, CurveError> {
    let n = control_points.len();
    if n == 0 {
        return Err(CurveError::NoControlPoints);
    }
    if breakpoints.len() != n + 1 {
        return Err(CurveError::Knots(KnotError::BreakpointCount {
            got: breakpoints.len(),
            count: n,
        }));
    }
    let knots = KnotVector::periodic(degree, breakpoints)?;
    let wrap = |i: usize| i % n;
    let points = (0..n + degree).map(|i| control_points[wrap(i)]).collect();
    let weights = weights.map(|w| {
        if w.len() == n {
            (0..n + degree).map(|i| w[wrap(i)]).collect()
        } else {
            w
        }
    });
    Ok((points, weights, knots))
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::degrees::Degrees;
    use core::f64::consts::FRAC_1_SQRT_2;

    fn pts2(coords: &[[f64; 2]]) -> Vec<ControlPoint<2>> {
        coords
            .iter()
            .enumerate()
            .map(|(i, &p)| {
                let v = i as f64 / coords.len() as f64;
                ControlPoint::new(p, Degrees::new(v, 1.0 - v, 0.5 * v).unwrap())
            })
            .collect()
    }

    #[test]
    fn bspline_quadratic_closed_form() {
        // Uniform clamped quadratic with knots 0 0 0 1/2 1 1 1 on P0..P3. On [0, 1/2], with
        // s = 2t: N0 = (1-s)^2, N1 = s(1-s) + s(1-s)/2... use the closed form at t = 1/4:
        // basis (0.25, 0.625, 0.125, 0).
        let c =
            BSpline::clamped_uniform(pts2(&[[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]]), 2)
                .unwrap();
        let p = c.evaluate(0.25).unwrap();
        let want_x = 0.25 * 0.0 + 0.625 * 1.0 + 0.125 * 3.0;
        let want_y = 0.625 * 2.0 + 0.125 * 2.0;
        assert!((p.position[0] - want_x).abs() < 1e-15 && (p.position[1] - want_y).abs() < 1e-15);
        // Truth control values 0, 0.25, 0.5, 0.75.
        let want_t = 0.625 * 0.25 + 0.125 * 0.5;
        assert!((p.degrees.truth() - want_t).abs() < 1e-15);
    }

    #[test]
    fn bspline_single_segment_equals_bezier() {
        let points = pts2(&[[0.0, 1.0], [2.0, 5.0], [4.0, -1.0], [7.0, 3.0]]);
        let b = BSpline::clamped_uniform(points.clone(), 3).unwrap();
        let z = Bezier::new(points).unwrap();
        for k in 0..=10 {
            let t = k as f64 / 10.0;
            let (p, q) = (b.evaluate(t).unwrap(), z.evaluate(t).unwrap());
            for a in 0..2 {
                assert!((p.position[a] - q.position[a]).abs() < 1e-14);
            }
        }
    }

    #[test]
    fn bspline_segments_insert_elevate_reproduce() {
        let points = pts2(&[
            [0.0, 0.0],
            [1.0, 3.0],
            [2.0, -1.0],
            [4.0, 2.0],
            [5.0, 5.0],
            [7.0, 0.0],
        ]);
        let knots =
            KnotVector::new(vec![0.0, 0.0, 0.0, 0.3, 0.3, 0.7, 1.0, 1.0, 1.0], 2, 6).unwrap();
        let c = BSpline::new(points, knots).unwrap();
        let segs = c.to_bezier_segments();
        assert_eq!(segs.len(), 3);
        let ins = c.insert_knot(0.5).unwrap();
        assert_eq!(ins.len(), 7);
        let e = c.elevate();
        assert_eq!(e.degree(), 3);
        // Interior multiplicities 2 and 1 become 3 and 2: 4 + 3 + 2 + 4 = 13 knots, 9 points.
        assert_eq!(
            e.knots().knots(),
            &[0.0, 0.0, 0.0, 0.0, 0.3, 0.3, 0.3, 0.7, 0.7, 1.0, 1.0, 1.0, 1.0]
        );
        for k in 0..=20 {
            let t = k as f64 / 20.0;
            let p = c.evaluate(t).unwrap();
            let seg = segs.iter().find(|s| s.start <= t && t <= s.end).unwrap();
            let q = seg
                .curve
                .evaluate((t - seg.start) / (seg.end - seg.start))
                .unwrap();
            for other in [q, ins.evaluate(t).unwrap(), e.evaluate(t).unwrap()] {
                for a in 0..2 {
                    assert!((p.position[a] - other.position[a]).abs() < 1e-13, "t {t}");
                }
                assert!((p.degrees.truth() - other.degrees.truth()).abs() < 1e-14);
            }
        }
    }

    #[test]
    fn bspline_rejects_wrong_knots() {
        let e = BSpline::new(
            pts2(&[[0.0, 0.0], [1.0, 1.0]]),
            KnotVector::clamped_uniform(1, 3).unwrap(),
        )
        .unwrap_err();
        assert_eq!(
            e.to_string(),
            "knot vector has 5 knots, expected 4 (number of control points + degree + 1)"
        );
    }

    /// A quarter of the unit circle, truth 0, 1, 1/2 at the control points, indeterminacy and
    /// falsity constant (1/2, 1/4).
    pub(crate) fn quarter_circle() -> Nurbs<2> {
        let d = |t| Degrees::new(t, 0.5, 0.25).unwrap();
        Nurbs::new(
            vec![
                ControlPoint::new([1.0, 0.0], d(0.0)),
                ControlPoint::new([1.0, 1.0], d(1.0)),
                ControlPoint::new([0.0, 1.0], d(0.5)),
            ],
            vec![1.0, FRAC_1_SQRT_2, 1.0],
            KnotVector::clamped_uniform(2, 3).unwrap(),
        )
        .unwrap()
    }

    #[test]
    fn nurbs_quarter_circle_is_exact() {
        let c = quarter_circle();
        for k in 0..=100 {
            let t = k as f64 / 100.0;
            let [x, y] = c.evaluate(t).unwrap().position;
            assert!(
                (x.hypot(y) - 1.0).abs() <= 2.0 * f64::EPSILON,
                "t {t}: {x} {y}"
            );
            // Tangent is perpendicular to the radius.
            let d = c.derivative().evaluate(t).unwrap();
            let dot = d.position[0] * x + d.position[1] * y;
            assert!(dot.abs() < 1e-14, "t {t}: {dot}");
        }
        // At t = 1/2 the B-spline basis is (1/4, 1/2, 1/4), so R = (1/4, w/2, 1/4) / den with
        // den = (1 + w) / 2; truth = 0 R_0 + 1 R_1 + 0.5 R_2.
        let w = FRAC_1_SQRT_2;
        let want = (w / 2.0 + 0.5 * 0.25) / ((1.0 + w) / 2.0);
        assert!((c.evaluate(0.5).unwrap().degrees.truth() - want).abs() < 1e-15);
        // Midpoint of the arc.
        let [x, y] = c.evaluate(0.5).unwrap().position;
        assert!((x - FRAC_1_SQRT_2).abs() < 1e-15 && (y - FRAC_1_SQRT_2).abs() < 1e-15);
    }

    #[test]
    fn nurbs_operations_preserve_circle() {
        let c = quarter_circle();
        let e = c.elevate();
        let i = c.insert_knot(0.3).unwrap();
        assert_eq!((e.degree(), i.len()), (3, 4));
        for k in 0..=20 {
            let t = k as f64 / 20.0;
            let p = c.evaluate(t).unwrap();
            for q in [e.evaluate(t).unwrap(), i.evaluate(t).unwrap()] {
                assert!((p.position[0] - q.position[0]).abs() < 1e-14);
                assert!((p.position[1] - q.position[1]).abs() < 1e-14);
                assert!((p.degrees.truth() - q.degrees.truth()).abs() < 1e-14);
            }
        }
        let b = c.bounding_box();
        assert!((b.position[0].min - 0.0).abs() < 1e-12 && (b.position[0].max - 1.0).abs() < 1e-12);
    }

    #[test]
    fn nurbs_rejects_bad_weights() {
        let d = Degrees::new(0.0, 0.0, 0.0).unwrap();
        let pts = vec![ControlPoint::new([0.0, 0.0], d); 2];
        let k = KnotVector::clamped_uniform(1, 2).unwrap();
        assert_eq!(
            Nurbs::new(pts.clone(), vec![1.0, 0.0], k.clone()).unwrap_err().to_string(),
            "control point 1: weight = 0 is not a positive finite number (NURBS weights must be > 0)"
        );
        assert!(Nurbs::new(pts.clone(), vec![-1.0, 1.0], k.clone()).is_err());
        assert_eq!(
            Nurbs::new(pts, vec![1.0], k).unwrap_err().to_string(),
            "1 weights for 2 control points (one weight per control point)"
        );
    }
}
