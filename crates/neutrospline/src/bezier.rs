//! Neutrosophic Bézier curves (paper Eq. 6-8, docs/model.md section 4).

use core::ops::Range;

use crate::bernstein::Packed;
use crate::compensated::{self, Step};
use crate::curve::{
    check_parameter, Bounded, ControlPolygon, CurveError, Derivative, Elevate, EvalError, Evaluate,
    Split, BOUNDS_TOLERANCE,
};
use crate::degrees::DegreeKind;
use crate::derivative::CurveDerivative;
use crate::layout::{lift_degree, pack_points, point_from_row, stride};
use crate::point::{Affine, BoundingBox, ControlPoint, CurvePoint};
use crate::spline::Spline;

/// A neutrosophic Bézier curve of degree `n` in `D` dimensions (`D` = 2 or 3).
///
/// With the Bernstein polynomials `B_{n,i}(t) = C(n,i) t^i (1-t)^(n-i)`, for `t` in \[0, 1\]:
///
/// ```text
/// position       C(t) = sum_i B_{n,i}(t) P_i
/// truth          T(t) = sum_i B_{n,i}(t) T_i
/// indeterminacy  I(t) = sum_i B_{n,i}(t) I_i
/// falsity        F(t) = sum_i B_{n,i}(t) F_i
/// ```
///
/// Each degree is blended exactly like a coordinate: internally the degrees are three extra
/// channels of every control point, and one de Casteljau routine evaluates all channels.
///
/// Invariants (tested): every evaluated point is a valid neutrosophic point, its degrees within
/// the range of the control degrees; the curve interpolates its end control points, degrees
/// included; it lies in the convex hull of the control points; affine maps of the positions
/// commute with evaluation. Evaluation is the compensated de Casteljau algorithm, stable at
/// any degree (no binomial coefficient is ever formed) and accurate to about one rounding.
///
/// # Examples
/// The paper's Example 1 at t = 0.5:
/// ```
/// use neutrospline::{Bezier, ControlPoint, Degrees, Evaluate};
/// let p = |x, y, t, i, f| ControlPoint::new([x, y], Degrees::new(t, i, f).unwrap());
/// let curve = Bezier::new(vec![
///     p(1.0, 3.0, 0.3, 0.6, 0.1),
///     p(3.0, 6.0, 0.8, 0.1, 0.1),
///     p(6.0, 2.0, 0.7, 0.1, 0.2),
///     p(9.0, 5.0, 0.2, 0.4, 0.4),
/// ])?;
/// let mid = curve.evaluate(0.5)?;
/// assert_eq!(mid.position, [4.625, 4.0]);
/// assert!((mid.degrees.truth() - 0.625).abs() < 1e-15);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Bezier<const D: usize> {
    packed: Packed,
}

impl<const D: usize> Bezier<D> {
    /// The curve with the given control points, in order; its degree is `len - 1`.
    ///
    /// # Errors
    /// [`CurveError::NoControlPoints`] for an empty list; [`CurveError::PositionNotFinite`]
    /// naming the first control point with a NaN or infinite coordinate;
    /// [`CurveError::UnsupportedDimension`] unless `D` is 2 or 3.
    pub fn new(control_points: Vec<ControlPoint<D>>) -> Result<Self, CurveError> {
        Ok(Bezier {
            packed: Packed::new(stride(D), pack_points(&control_points)?),
        })
    }

    pub(crate) fn from_packed(packed: Packed) -> Self {
        Bezier { packed }
    }

    pub(crate) fn packed(&self) -> &Packed {
        &self.packed
    }

    /// The polynomial degree `n` (one less than the number of control points).
    pub fn degree(&self) -> usize {
        self.packed.degree()
    }

    /// The same curve traversed backwards: control points in reverse order.
    pub fn reversed(&self) -> Bezier<D> {
        Bezier {
            packed: self.packed.reversed(),
        }
    }

    /// The curve with an affine map applied to its control positions; degrees unchanged.
    /// Bézier curves are affine invariant, so `map(C(t))` is the new curve at `t`.
    ///
    /// # Errors
    /// [`CurveError::PositionNotFinite`] if a mapped position overflows.
    pub fn transform(&self, map: &Affine<D>) -> Result<Bezier<D>, CurveError> {
        Bezier::new(map.apply_to_points(self.control_points()))
    }
}

impl Bezier<2> {
    /// The paper's space curve for one degree: the 3-D Bézier curve with control points
    /// `(x_i, y_i, degree_i)`, i.e. `(C(t), degree(t))`, whose projection on the plane is the
    /// crisp curve. The control points keep all three of their degrees.
    ///
    /// ```
    /// use neutrospline::{DegreeKind, Evaluate};
    /// let truth_curve = neutrospline::example1().degree_curve(DegreeKind::Truth);
    /// let p = truth_curve.evaluate(0.5)?;
    /// assert_eq!(p.position[..2], [4.625, 4.0]);
    /// assert!((p.position[2] - 0.625).abs() < 1e-15);
    /// # Ok::<(), neutrospline::EvalError>(())
    /// ```
    pub fn degree_curve(&self, kind: DegreeKind) -> Bezier<3> {
        Bezier {
            packed: Packed::new(stride(3), lift_degree(self.packed.data(), kind)),
        }
    }
}

impl<const D: usize> ControlPolygon<D> for Bezier<D> {
    /// `n + 1`.
    fn len(&self) -> usize {
        self.packed.count()
    }

    fn control_point(&self, i: usize) -> ControlPoint<D> {
        point_from_row(self.packed.row(i))
    }
}

impl<const D: usize> Evaluate for Bezier<D> {
    type Point = CurvePoint<D>;

    /// Always \[0, 1\].
    fn domain(&self) -> Range<f64> {
        0.0..1.0
    }

    /// The point at `t` in \[0, 1\], by the compensated de Casteljau algorithm (error-free
    /// transformations; see `crate::compensated`): about one rounding of the exact value at
    /// any degree (scaled error below 5e-16 at degree 2000, tested against mpmath), exactly
    /// the first and last control points at 0 and 1, degrees within their control range.
    ///
    /// # Errors
    /// `t` not finite or outside \[0, 1\].
    fn evaluate(&self, t: f64) -> Result<CurvePoint<D>, EvalError> {
        check_parameter(t, &(0.0..1.0))?;
        let mut row = [0.0; 6];
        let step = Step::casteljau(t);
        let data = self.packed.data();
        if !compensated::evaluate(stride(D), data, None, |_, _| step, &mut row) {
            self.packed.evaluate(t, &mut row);
        }
        Ok(point_from_row(&row))
    }
}

impl<const D: usize> Derivative for Bezier<D> {
    type Output = CurveDerivative<D>;

    /// The derivative `d/dt` of positions and degrees: the hodograph, a Bézier polynomial of
    /// degree `n - 1` with control vectors `n (P_{i+1} - P_i)` (zero for a degree-0 curve).
    fn derivative(&self) -> CurveDerivative<D> {
        CurveDerivative::of_spline(&Spline::from_bezier(&self.packed, None), 0.0..1.0)
    }
}

impl<const D: usize> Split for Bezier<D> {
    /// Splits at `t` (de Casteljau) into the curves on \[0, t\] and \[t, 1\], each
    /// reparametrised to \[0, 1\].
    fn split(&self, t: f64) -> Result<(Self, Self), EvalError> {
        check_parameter(t, &(0.0..1.0))?;
        let (left, right) = self.packed.split(t);
        Ok((Bezier { packed: left }, Bezier { packed: right }))
    }

    /// The piece on \[t0, t1\], reparametrised to \[0, 1\]; reversed if `t0 > t1`; every
    /// control point the same point when `t0 == t1`.
    fn subsegment(&self, t0: f64, t1: f64) -> Result<Self, EvalError> {
        check_parameter(t0, &(0.0..1.0))?;
        check_parameter(t1, &(0.0..1.0))?;
        Ok(Bezier {
            packed: self.packed.subsegment(t0, t1),
        })
    }
}

impl<const D: usize> Elevate for Bezier<D> {
    /// Degree elevation: the same curve as a Bézier curve of degree `n + 1`, with
    /// `Q_i = (i / (n+1)) P_{i-1} + (1 - i / (n+1)) P_i` for `i = 0 ..= n + 1`.
    fn elevate(&self) -> Self {
        Bezier {
            packed: self.packed.elevate(),
        }
    }
}

impl<const D: usize> Bounded<D> for Bezier<D> {
    /// Branch and bound on the convex hull property.
    fn bounding_box(&self) -> BoundingBox<D> {
        BoundingBox::from_channel_ranges(|c| self.packed.channel_range(c, None, BOUNDS_TOLERANCE))
    }

    fn control_bounding_box(&self) -> BoundingBox<D> {
        BoundingBox::from_channel_ranges(|c| self.packed.control_range(c))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::degrees::Degrees;
    use crate::example::example1;

    fn close(a: f64, b: f64, tol: f64) -> bool {
        (a - b).abs() <= tol
    }

    #[test]
    fn bezier_new_rejects_empty_and_non_finite() {
        assert_eq!(Bezier::<2>::new(vec![]), Err(CurveError::NoControlPoints));
        let d = Degrees::new(0.1, 0.2, 0.3).unwrap();
        let e = Bezier::new(vec![
            ControlPoint::new([0.0, 0.0], d),
            ControlPoint::new([1.0, f64::INFINITY], d),
        ])
        .unwrap_err();
        assert_eq!(
            e.to_string(),
            "control point 1: y = inf is not a finite number (positions must be finite)"
        );
    }

    #[test]
    fn bezier_new_rejects_other_dimensions() {
        let d = Degrees::new(0.1, 0.2, 0.3).unwrap();
        assert_eq!(
            Bezier::new(vec![ControlPoint::new([0.0; 4], d)]).unwrap_err(),
            CurveError::UnsupportedDimension { dimension: 4 }
        );
        let e = crate::BSpline::clamped_uniform(vec![ControlPoint::new([0.0], d); 2], 1);
        assert_eq!(
            e.unwrap_err().to_string(),
            "1-D positions are not supported (curves are 2-D or 3-D, surfaces 3-D)"
        );
    }

    #[test]
    fn bezier_evaluate_example1_midpoint() {
        // Hand computation with B_3(1/2) = (1, 3, 3, 1) / 8:
        // x = (1 + 9 + 18 + 9) / 8 = 4.625, y = (3 + 18 + 6 + 5) / 8 = 4,
        // T = (0.3 + 2.4 + 2.1 + 0.2) / 8 = 0.625, I = (0.6 + 0.3 + 0.3 + 0.4) / 8 = 0.2,
        // F = (0.1 + 0.3 + 0.6 + 0.4) / 8 = 0.175.
        let p = example1().evaluate(0.5).unwrap();
        assert_eq!(p.position, [4.625, 4.0]);
        let [t, i, f] = p.degrees.to_array();
        assert!(close(t, 0.625, 1e-15) && close(i, 0.2, 1e-15) && close(f, 0.175, 1e-15));
    }

    #[test]
    fn bezier_evaluate_rejects_bad_parameters() {
        let c = example1();
        assert_eq!(
            c.evaluate(1.5).unwrap_err().to_string(),
            "parameter t = 1.5 is outside the domain [0, 1]"
        );
        assert!(matches!(
            c.evaluate(f64::NAN),
            Err(EvalError::ParameterNotFinite { .. })
        ));
        assert!(c.evaluate(-1e-300).is_err());
    }

    #[test]
    fn bezier_endpoints_are_exact() {
        let c = example1();
        assert_eq!(c.evaluate(0.0).unwrap(), c.control_point(0));
        assert_eq!(c.evaluate(1.0).unwrap(), c.control_point(3));
        assert_eq!(c.start().unwrap(), c.control_point(0));
        assert_eq!(c.end().unwrap(), c.control_point(3));
    }

    #[test]
    fn bezier_degree_zero_is_a_point() {
        let d = Degrees::new(0.1, 0.2, 0.3).unwrap();
        let c = Bezier::new(vec![ControlPoint::new([2.0, -1.0, 5.0], d)]).unwrap();
        assert_eq!(c.degree(), 0);
        assert_eq!(
            c.evaluate(0.37).unwrap(),
            ControlPoint::new([2.0, -1.0, 5.0], d)
        );
        let v = c.derivative().evaluate(0.5).unwrap();
        assert_eq!(v.position, [0.0; 3]);
        assert_eq!(c.elevate().degree(), 1);
        let (l, r) = c.split(0.5).unwrap();
        assert_eq!((l.degree(), r.degree()), (0, 0));
    }

    #[test]
    fn bezier_derivative_example1() {
        // Hodograph 3 * [(2, 3), (3, -4), (3, 3)] with degree rates
        // 3 * [(0.5, -0.5, 0), (-0.1, 0, 0.1), (-0.5, 0.3, 0.2)]; at t = 1/2 the weights are
        // (1/4, 1/2, 1/4): dx = 3 (0.5 + 1.5 + 0.75) = 8.25, dy = 3 (0.75 - 2 + 0.75) = -1.5,
        // dT = 3 (0.125 - 0.05 - 0.125) = -0.15, dI = 3 (-0.125 + 0 + 0.075) = -0.15,
        // dF = 3 (0 + 0.05 + 0.05) = 0.3.
        let v = example1().derivative().evaluate(0.5).unwrap();
        assert!(close(v.position[0], 8.25, 1e-14) && close(v.position[1], -1.5, 1e-14));
        assert!(close(v.truth, -0.15, 1e-14));
        assert!(close(v.indeterminacy, -0.15, 1e-14));
        assert!(close(v.falsity, 0.3, 1e-14));
        let second = example1().derivative().derivative();
        assert_eq!(second.degree(), 1);
        // 6 (P_2 - 2 P_1 + P_0) at t = 0: x: 6 (6 - 6 + 1) = 6, y: 6 (2 - 12 + 3) = -42.
        let a = second.evaluate(0.0).unwrap();
        assert!(close(a.position[0], 6.0, 1e-13) && close(a.position[1], -42.0, 1e-13));
    }

    #[test]
    fn bezier_derivative_overflow_is_an_error() {
        let d = Degrees::new(0.0, 0.0, 0.0).unwrap();
        let c = Bezier::new(vec![
            ControlPoint::new([-1.5e308, 0.0], d),
            ControlPoint::new([1.5e308, 0.0], d),
        ])
        .unwrap();
        // The curve itself evaluates fine (convex combinations never overflow).
        assert_eq!(c.evaluate(0.5).unwrap().position, [0.0, 0.0]);
        assert_eq!(
            c.derivative().evaluate(0.5).unwrap_err(),
            EvalError::Overflow { t: 0.5 }
        );
    }

    #[test]
    fn bezier_many_agrees_with_single() {
        let c = example1();
        let ts: Vec<f64> = (0..=10).map(|k| k as f64 / 10.0).collect();
        let mut pts = vec![c.control_point(0); ts.len()];
        c.evaluate_many(&ts, &mut pts).unwrap();
        for (k, &t) in ts.iter().enumerate() {
            assert_eq!(pts[k], c.evaluate(t).unwrap());
        }
        assert!(c.evaluate_many(&[0.5, 2.0], &mut pts[..2]).is_err());
    }

    #[test]
    fn bezier_degree_curve_layout() {
        let c = example1().degree_curve(DegreeKind::Falsity);
        let p = c.control_point(2);
        assert_eq!(p.position, [6.0, 2.0, 0.2]);
        assert_eq!(p.degrees.to_array(), [0.7, 0.1, 0.2]);
    }

    #[test]
    fn bezier_bounding_box_example1() {
        let c = example1();
        let b = c.bounding_box();
        // x is monotone (control x increasing): [1, 9]. T(t) peaks inside; truth control
        // range is [0.2, 0.8]; the curve's truth is at least min(T0, T3) = 0.2 at t = 1.
        assert_eq!((b.position[0].min, b.position[0].max), (1.0, 9.0));
        assert_eq!(b.truth.min, 0.2);
        // T(t) = 0.3 s^3 + 2.4 t s^2 + 2.1 t^2 s + 0.2 t^3; T'(t) = 3 (0.5 s^2 - 0.2 t s - 0.5 t^2)
        // = 0 at t/s = r with 0.5 r^2 + 0.2 r - 0.5 = 0, r = (-0.2 + sqrt(1.04)) / 1.
        let r = -0.2 + 1.04f64.sqrt();
        let t_star = r / (1.0 + r);
        let t_max = c.evaluate(t_star).unwrap().degrees.truth();
        assert!(
            b.truth.max >= t_max && b.truth.max <= t_max + 1e-11,
            "{:?} {t_max}",
            b.truth
        );
        let cb = c.control_bounding_box();
        assert_eq!((cb.truth.min, cb.truth.max), (0.2, 0.8));
        assert_eq!((cb.position[1].min, cb.position[1].max), (2.0, 6.0));
    }
}
