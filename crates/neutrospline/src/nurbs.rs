//! Neutrosophic NURBS curves (SPEC section 6).

use crate::bernstein::Packed;
use crate::bspline::{spline_channels, BSpline, BezierSegment};
use crate::curve::{
    check_parameter, Bounded, CurveError, Derivative, Elevate, EvalError, Evaluate,
};
use crate::degrees::DegreeKind;
use crate::knots::{KnotError, KnotVector};
use crate::layout::{derivative_from_row, lift_degree, pack_points, point_from_row, stride};
use crate::point::{Affine, BoundingBox, ControlPoint, CurvePoint, DerivativeValue};
use crate::spline::Spline;
use crate::BOUNDS_TOLERANCE;

/// A neutrosophic NURBS curve: a B-spline with a positive weight per control point.
///
/// Positions and degrees are blended with the rational basis
/// `R_i(t) = w_i N_{i,p}(t) / sum_j w_j N_{j,p}(t)`, which is non-negative with unit sum:
///
/// ```text
/// C(t) = sum_i R_i(t) P_i,  T(t) = sum_i R_i(t) T_i,  (same for I and F)
/// ```
///
/// so every invariant of the Bézier model carries over. Evaluation is the rational de Boor
/// algorithm in Euclidean form: each step forms a new weight and a convex combination.
///
/// ```
/// use neutrospline::{ControlPoint, Degrees, KnotVector, Nurbs};
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
#[derive(Clone, Debug, PartialEq)]
pub struct Nurbs<const D: usize> {
    spline: Spline,
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
        let data = pack_points(&control_points)?;
        if weights.len() != control_points.len() {
            return Err(CurveError::WeightCount {
                weights: weights.len(),
                points: control_points.len(),
            });
        }
        if let Some((index, &value)) = weights
            .iter()
            .enumerate()
            .find(|(_, w)| !(w.is_finite() && **w > 0.0))
        {
            return Err(CurveError::WeightNotPositive { index, value });
        }
        if knots.control_count() != control_points.len() {
            return Err(KnotError::WrongLength {
                got: knots.knots().len(),
                expected: control_points.len() + knots.degree() + 1,
            }
            .into());
        }
        Ok(Nurbs {
            spline: Spline {
                knots,
                stride: stride(D),
                data,
                weights: Some(weights),
            },
        })
    }

    /// A NURBS curve with every weight 1: the same curve as `curve`.
    pub fn from_bspline(curve: &BSpline<D>) -> Self {
        let mut spline = curve.spline().clone();
        spline.weights = Some(vec![1.0; spline.count()]);
        Nurbs { spline }
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

    /// The weights, one per control point.
    pub fn weights(&self) -> &[f64] {
        self.spline.weights.as_deref().unwrap_or(&[])
    }

    /// The point at `t` in the domain (rational de Boor).
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
    /// [`crate::Bezier::evaluate_channels`]).
    ///
    /// # Errors
    /// The first parameter not finite or outside the domain.
    ///
    /// # Panics
    /// If `out.len() != (D + 3) * ts.len()`.
    pub fn evaluate_channels(&self, ts: &[f64], out: &mut [f64]) -> Result<(), EvalError> {
        spline_channels(&self.spline, self.domain(), ts, out)
    }

    /// The first derivative, by the quotient rule on the homogeneous form
    /// `A(t) = sum N_i w_i P_i`, `w(t) = sum N_i w_i`: `C' = (A' - w' C) / w`.
    pub fn derivative(&self) -> NurbsDerivative<D> {
        let homogeneous = self.spline.homogeneous();
        NurbsDerivative {
            derivative: homogeneous.derivative(),
            homogeneous,
            domain: self.domain(),
        }
    }

    /// The same curve with the knot `u` inserted once (Boehm's algorithm, rational form).
    ///
    /// # Errors
    /// `u` outside the domain, or its multiplicity would exceed `p + 1`.
    pub fn insert_knot(&self, u: f64) -> Result<Self, KnotError> {
        Ok(Nurbs {
            spline: self.spline.insert_knot(u)?,
        })
    }

    /// The rational Bézier pieces, one per non-empty knot span of the domain, each as a NURBS
    /// curve on Bézier knots over \[0, 1\].
    pub fn to_bezier_segments(&self) -> Vec<BezierSegment<Nurbs<D>>> {
        let p = self.degree();
        self.spline
            .bezier_segments()
            .into_iter()
            .map(|s| {
                let knots = KnotVector::from_parts_unchecked(
                    p,
                    core::iter::repeat_n(0.0, p + 1)
                        .chain(core::iter::repeat_n(1.0, p + 1))
                        .collect(),
                );
                BezierSegment {
                    start: s.start,
                    end: s.end,
                    curve: Nurbs {
                        spline: Spline {
                            knots,
                            stride: stride(D),
                            data: s.packed.data().to_vec(),
                            weights: s.weights,
                        },
                    },
                }
            })
            .collect()
    }

    /// Degree elevation: the same curve with degree `p + 1` (homogeneous elevation), each
    /// interior knot's multiplicity raised by one, clamped on the domain.
    pub fn elevate(&self) -> Self {
        Nurbs {
            spline: self.spline.elevate(D..D + 3),
        }
    }

    /// Tight bounds of positions and degrees: branch and bound on each rational Bézier piece
    /// (positive weights keep the convex hull property).
    pub fn bounding_box(&self) -> BoundingBox<D> {
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

    /// Bounds of the control values: contain the curve; loose.
    pub fn control_bounding_box(&self) -> BoundingBox<D> {
        let packed = Packed::new(self.spline.stride, self.spline.data.clone());
        BoundingBox::from_channel_ranges(|c| packed.control_range(c))
    }

    /// The curve with an affine map applied to its control positions; weights and degrees
    /// unchanged (NURBS are affine invariant).
    ///
    /// # Errors
    /// A mapped position overflows.
    pub fn transform(&self, map: &Affine<D>) -> Result<Self, CurveError> {
        let points = self
            .control_points()
            .into_iter()
            .map(|p| ControlPoint::new(map.apply(p.position), p.degrees))
            .collect();
        Nurbs::new(points, self.weights().to_vec(), self.spline.knots.clone())
    }
}

impl Nurbs<2> {
    /// The space curve `(C(t), degree(t))` of one degree: control points
    /// `(x_i, y_i, degree_i)` with the same weights and knots.
    pub fn degree_curve(&self, kind: DegreeKind) -> Nurbs<3> {
        Nurbs {
            spline: Spline {
                knots: self.spline.knots.clone(),
                stride: stride(3),
                data: lift_degree(&self.spline.data, kind),
                weights: self.spline.weights.clone(),
            },
        }
    }
}

/// The first derivative of a [`Nurbs`] curve.
#[derive(Clone, Debug, PartialEq)]
pub struct NurbsDerivative<const D: usize> {
    homogeneous: Spline,
    derivative: Spline,
    domain: (f64, f64),
}

impl<const D: usize> NurbsDerivative<D> {
    /// The derivative at `t` in the domain (from the right at interior knots where it jumps).
    ///
    /// # Errors
    /// `t` not finite or outside the domain; [`EvalError::Overflow`].
    pub fn evaluate(&self, t: f64) -> Result<DerivativeValue<D>, EvalError> {
        check_parameter(t, self.domain)?;
        let s = stride(D);
        let mut a = [0.0; 7];
        let mut da = [0.0; 7];
        let mut scratch = Vec::new();
        self.homogeneous.evaluate(t, &mut scratch, &mut a);
        self.derivative.evaluate(t, &mut scratch, &mut da);
        let (w, dw) = (a[s], da[s]);
        let mut row = [0.0; 6];
        for c in 0..s {
            row[c] = (da[c] - dw * (a[c] / w)) / w;
        }
        if row[..s].iter().any(|v| !v.is_finite()) {
            return Err(EvalError::Overflow { t });
        }
        Ok(derivative_from_row(&row))
    }
}

impl<const D: usize> Evaluate<D> for Nurbs<D> {
    fn domain(&self) -> (f64, f64) {
        Nurbs::domain(self)
    }
    fn evaluate(&self, t: f64) -> Result<CurvePoint<D>, EvalError> {
        Nurbs::evaluate(self, t)
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

impl<const D: usize> Derivative for Nurbs<D> {
    type Output = NurbsDerivative<D>;
    fn derivative(&self) -> NurbsDerivative<D> {
        Nurbs::derivative(self)
    }
}

impl<const D: usize> Elevate for Nurbs<D> {
    fn elevate(&self) -> Self {
        Nurbs::elevate(self)
    }
}

impl<const D: usize> Bounded<D> for Nurbs<D> {
    fn bounding_box(&self) -> BoundingBox<D> {
        Nurbs::bounding_box(self)
    }
    fn control_bounding_box(&self) -> BoundingBox<D> {
        Nurbs::control_bounding_box(self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::degrees::Degrees;
    use core::f64::consts::FRAC_1_SQRT_2;

    fn quarter_circle() -> Nurbs<2> {
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
