//! Neutrosophic B-spline curves (SPEC section 6).

use crate::bernstein::Packed;
use crate::bezier::Bezier;
use crate::curve::{
    check_parameter, Bounded, CurveError, Derivative, Elevate, EvalError, Evaluate,
};
use crate::degrees::DegreeKind;
use crate::knots::{KnotError, KnotVector};
use crate::layout::{derivative_from_row, lift_degree, pack_points, point_from_row, stride};
use crate::point::{Affine, BoundingBox, ControlPoint, CurvePoint, DerivativeValue};
use crate::spline::Spline;

/// Evaluates a spline at every parameter into channel-major `out` (see
/// [`Bezier::evaluate_channels`]), checking each parameter against `domain`.
pub(crate) fn spline_channels(
    spline: &Spline,
    domain: (f64, f64),
    ts: &[f64],
    out: &mut [f64],
) -> Result<(), EvalError> {
    let count = ts.len();
    assert_eq!(
        out.len(),
        spline.stride * count,
        "evaluate_channels: out must hold (D + 3) * ts.len() values"
    );
    let mut scratch = Vec::new();
    let mut row = [0.0; 6];
    for (k, &t) in ts.iter().enumerate() {
        check_parameter(t, domain)?;
        spline.evaluate(t, &mut scratch, &mut row);
        for (c, &v) in row[..spline.stride].iter().enumerate() {
            out[c * count + k] = v;
        }
    }
    Ok(())
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
/// affine maps commute. Evaluation is de Boor's algorithm on all channels at once.
///
/// ```
/// use neutrospline::{BSpline, ControlPoint, Degrees, KnotVector};
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
#[derive(Clone, Debug, PartialEq)]
pub struct BSpline<const D: usize> {
    spline: Spline,
}

impl<const D: usize> BSpline<D> {
    /// The curve with these control points over `knots`, whose degree is the curve's.
    ///
    /// # Errors
    /// No control points, a non-finite position, or knots made for another number of control
    /// points ([`CurveError::Knots`]).
    pub fn new(
        control_points: Vec<ControlPoint<D>>,
        knots: KnotVector,
    ) -> Result<Self, CurveError> {
        let data = pack_points(&control_points)?;
        if knots.control_count() != control_points.len() {
            return Err(KnotError::WrongLength {
                got: knots.knots().len(),
                expected: control_points.len() + knots.degree() + 1,
            }
            .into());
        }
        Ok(BSpline {
            spline: Spline {
                knots,
                stride: stride(D),
                data,
                weights: None,
            },
        })
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

    pub(crate) fn spline(&self) -> &Spline {
        &self.spline
    }

    /// The polynomial degree p.
    pub fn degree(&self) -> usize {
        self.spline.degree()
    }

    /// The knot vector.
    pub fn knots(&self) -> &KnotVector {
        &self.spline.knots
    }

    /// The parameter domain `[u_p, u_{m-p}]`.
    pub fn domain(&self) -> (f64, f64) {
        self.spline.knots.domain()
    }

    /// Number of control points.
    pub fn len(&self) -> usize {
        self.spline.count()
    }

    /// Always `false`: a curve has at least one control point.
    pub fn is_empty(&self) -> bool {
        false
    }

    /// Control point `i`.
    ///
    /// # Panics
    /// If `i >= len()`.
    pub fn control_point(&self, i: usize) -> ControlPoint<D> {
        point_from_row(self.spline.row(i))
    }

    /// All control points, in order.
    pub fn control_points(&self) -> Vec<ControlPoint<D>> {
        (0..self.len()).map(|i| self.control_point(i)).collect()
    }

    /// The point at `t` in the domain, by de Boor's algorithm.
    ///
    /// # Errors
    /// `t` not finite or outside the domain.
    pub fn evaluate(&self, t: f64) -> Result<CurvePoint<D>, EvalError> {
        check_parameter(t, self.domain())?;
        let mut row = [0.0; 6];
        self.spline.evaluate(t, &mut Vec::new(), &mut row);
        Ok(point_from_row(&row))
    }

    /// Evaluates at every parameter into channel-major `out` (layout of
    /// [`Bezier::evaluate_channels`]).
    ///
    /// # Errors
    /// The first parameter not finite or outside the domain.
    ///
    /// # Panics
    /// If `out.len() != (D + 3) * ts.len()`.
    pub fn evaluate_channels(&self, ts: &[f64], out: &mut [f64]) -> Result<(), EvalError> {
        spline_channels(&self.spline, self.domain(), ts, out)
    }

    /// The derivative: a B-spline of degree `p - 1` on the knots without their first and
    /// last, with control values `p (P_{i+1} - P_i) / (u_{i+p+1} - u_{i+1})`.
    pub fn derivative(&self) -> BSplineDerivative<D> {
        BSplineDerivative {
            spline: self.spline.derivative(),
            domain: self.domain(),
        }
    }

    /// The same curve with the knot `u` inserted once (Boehm's algorithm).
    ///
    /// # Errors
    /// `u` outside the domain, or its multiplicity would exceed `p + 1`.
    pub fn insert_knot(&self, u: f64) -> Result<Self, KnotError> {
        Ok(BSpline {
            spline: self.spline.insert_knot(u)?,
        })
    }

    /// The polynomial pieces of the curve as Bézier curves, one per non-empty knot span of the
    /// domain, in order.
    pub fn to_bezier_segments(&self) -> Vec<BezierSegment<Bezier<D>>> {
        self.spline
            .bezier_segments()
            .into_iter()
            .map(|s| BezierSegment {
                start: s.start,
                end: s.end,
                curve: Bezier::from_packed(s.packed),
            })
            .collect()
    }

    /// Degree elevation: the same curve as a B-spline of degree `p + 1`, each interior knot's
    /// multiplicity raised by one, clamped on the domain.
    pub fn elevate(&self) -> Self {
        BSpline {
            spline: self.spline.elevate(D..D + 3),
        }
    }

    /// Tight bounds of positions and degrees (union of the bounds of the Bézier pieces).
    pub fn bounding_box(&self) -> BoundingBox<D> {
        self.to_bezier_segments()
            .iter()
            .map(|s| s.curve.bounding_box())
            .reduce(|a, b| a.union(&b))
            .unwrap_or_else(|| self.control_bounding_box())
    }

    /// Bounds of the control values: contain the curve; loose.
    pub fn control_bounding_box(&self) -> BoundingBox<D> {
        BoundingBox::from_channel_ranges(|c| {
            Packed::new(self.spline.stride, self.spline.data.clone()).control_range(c)
        })
    }

    /// The curve with an affine map applied to its control positions; degrees unchanged.
    ///
    /// # Errors
    /// A mapped position overflows.
    pub fn transform(&self, map: &Affine<D>) -> Result<Self, CurveError> {
        let points = self
            .control_points()
            .into_iter()
            .map(|p| ControlPoint::new(map.apply(p.position), p.degrees))
            .collect();
        BSpline::new(points, self.spline.knots.clone())
    }
}

impl BSpline<2> {
    /// The space curve `(C(t), degree(t))` of one degree: control points
    /// `(x_i, y_i, degree_i)` over the same knots.
    pub fn degree_curve(&self, kind: DegreeKind) -> BSpline<3> {
        BSpline {
            spline: Spline {
                knots: self.spline.knots.clone(),
                stride: stride(3),
                data: lift_degree(&self.spline.data, kind),
                weights: None,
            },
        }
    }
}

/// The derivative of a [`BSpline`]: rates of change, which may be any real number.
#[derive(Clone, Debug, PartialEq)]
pub struct BSplineDerivative<const D: usize> {
    spline: Spline,
    domain: (f64, f64),
}

impl<const D: usize> BSplineDerivative<D> {
    /// Polynomial degree of the derivative.
    pub fn degree(&self) -> usize {
        self.spline.degree()
    }

    /// The derivative at `t` in the curve's domain. At a knot where the derivative jumps, the
    /// value from the right is returned (from the left at the domain end).
    ///
    /// # Errors
    /// `t` not finite or outside the domain; [`EvalError::Overflow`].
    pub fn evaluate(&self, t: f64) -> Result<DerivativeValue<D>, EvalError> {
        check_parameter(t, self.domain)?;
        let mut row = [0.0; 6];
        self.spline.evaluate(t, &mut Vec::new(), &mut row);
        if row[..stride(D)].iter().any(|v| !v.is_finite()) {
            return Err(EvalError::Overflow { t });
        }
        Ok(derivative_from_row(&row))
    }

    /// The next derivative.
    pub fn derivative(&self) -> BSplineDerivative<D> {
        BSplineDerivative {
            spline: self.spline.derivative(),
            domain: self.domain,
        }
    }
}

impl<const D: usize> Evaluate<D> for BSpline<D> {
    fn domain(&self) -> (f64, f64) {
        BSpline::domain(self)
    }
    fn evaluate(&self, t: f64) -> Result<CurvePoint<D>, EvalError> {
        BSpline::evaluate(self, t)
    }
    fn start(&self) -> CurvePoint<D> {
        let mut row = [0.0; 6];
        self.spline
            .evaluate(self.domain().0, &mut Vec::new(), &mut row);
        point_from_row(&row)
    }
    fn end(&self) -> CurvePoint<D> {
        let mut row = [0.0; 6];
        self.spline
            .evaluate(self.domain().1, &mut Vec::new(), &mut row);
        point_from_row(&row)
    }
    fn evaluate_many(&self, ts: &[f64], out: &mut [CurvePoint<D>]) -> Result<(), EvalError> {
        assert_eq!(
            ts.len(),
            out.len(),
            "evaluate_many: ts and out differ in length"
        );
        let mut scratch = Vec::new();
        let mut row = [0.0; 6];
        for (&t, slot) in ts.iter().zip(out.iter_mut()) {
            check_parameter(t, self.domain())?;
            self.spline.evaluate(t, &mut scratch, &mut row);
            *slot = point_from_row(&row);
        }
        Ok(())
    }
}

impl<const D: usize> Derivative for BSpline<D> {
    type Output = BSplineDerivative<D>;
    fn derivative(&self) -> BSplineDerivative<D> {
        BSpline::derivative(self)
    }
}

impl<const D: usize> Elevate for BSpline<D> {
    fn elevate(&self) -> Self {
        BSpline::elevate(self)
    }
}

impl<const D: usize> Bounded<D> for BSpline<D> {
    fn bounding_box(&self) -> BoundingBox<D> {
        BSpline::bounding_box(self)
    }
    fn control_bounding_box(&self) -> BoundingBox<D> {
        BSpline::control_bounding_box(self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::degrees::Degrees;

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
}
