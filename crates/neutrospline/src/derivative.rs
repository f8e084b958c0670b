//! Derivatives of curves of every kind, as curves of their own.

use core::ops::Range;

use crate::curve::{check_parameter, Derivative, EvalError, Evaluate};
use crate::knots::KnotVector;
use crate::layout::{derivative_from_row, stride};
use crate::point::DerivativeValue;
use crate::spline::Spline;

/// The derivative of order `k >= 1` of a neutrosophic curve of any kind (Bézier, B-spline,
/// NURBS), with respect to the curve's parameter: rates of change of the position and of each
/// degree, which may be any real number.
///
/// - Bézier and B-spline curves: the k-th derivative is again a spline (for a Bézier curve
///   of degree `n` the hodograph, degree `n - 1`, control vectors `n (P_{i+1} - P_i)`; for a
///   B-spline of degree `p`, degree `p - 1` on the knots without their first and last, with
///   control values `p (P_{i+1} - P_i) / (u_{i+p+1} - u_{i+1})`), evaluated by the
///   compensated de Boor algorithm of the curves themselves.
/// - NURBS curves: with the homogeneous numerator `A(t) = sum_i N_i(t) w_i (P_i, 1)` (its last
///   channel is the weight function `w(t)`) and `C = A / w`, Leibniz's rule gives
///   `C^(k) = (A^(k) - sum_{i=1..k} binom(k, i) w^(i) C^(k-i)) / w`
///   (The NURBS Book, eq. 4.8); the derivatives of `A` are splines, evaluated the same way.
///
/// At an interior knot where the derivative jumps, the value from the right is returned (from
/// the left at the end of the domain).
///
/// ```
/// use neutrospline::{Derivative, Evaluate};
/// let velocity = neutrospline::example1().derivative();
/// assert_eq!(velocity.order(), 1);
/// assert_eq!(velocity.evaluate(0.0)?.position, [6.0, 9.0]); // 3 (P_1 - P_0)
/// let acceleration = velocity.derivative();
/// assert_eq!(acceleration.evaluate(0.0)?.position, [6.0, -42.0]); // 6 (P_2 - 2 P_1 + P_0)
/// # Ok::<(), neutrospline::EvalError>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct CurveDerivative<const D: usize> {
    order: usize,
    domain: Range<f64>,
    form: Form,
}

#[derive(Clone, Debug, PartialEq)]
enum Form {
    /// The k-th derivative of a non-rational curve: a spline with the curve's channels.
    Polynomial(Spline),
    /// The homogeneous numerator `A` of a rational curve and its derivatives: `chain[j]` is
    /// `A^(j)`, `j = 0 ..= k`, each with the channels `w x, ..., w falsity, w`.
    Rational(Vec<Spline>),
}

/// Derivative orders whose intermediate rows are kept on the stack.
const STACK_ORDERS: usize = 8;
/// Channels of a homogeneous row, at most (`3 + 3 + 1`), rounded up.
const ROW: usize = 8;

impl<const D: usize> CurveDerivative<D> {
    /// The first derivative of the curve with control rows `spline` (rational when it has
    /// weights), on `domain`.
    pub(crate) fn of_spline(spline: &Spline, domain: Range<f64>) -> Self {
        let form = match spline.weights {
            None => Form::Polynomial(spline.derivative()),
            Some(_) => Form::Rational(spline.homogeneous().derivatives(1)),
        };
        CurveDerivative {
            order: 1,
            domain,
            form,
        }
    }

    /// The order `k` of the derivative (1 for the first derivative).
    pub fn order(&self) -> usize {
        self.order
    }

    /// Whether the curve is rational (NURBS): its derivative is then a quotient, not a spline.
    pub fn is_rational(&self) -> bool {
        matches!(self.form, Form::Rational(_))
    }

    /// The polynomial degree of the derivative's spline: `p - k` (at least 0) for a curve of
    /// degree `p`; for a NURBS curve, that of the k-th derivative of its homogeneous numerator.
    pub fn degree(&self) -> usize {
        match &self.form {
            Form::Polynomial(s) => s.degree(),
            Form::Rational(chain) => chain[chain.len() - 1].degree(),
        }
    }

    /// The knots of the derivative's spline (non-rational curves; `None` for NURBS). For a
    /// Bézier curve of degree `n`, `n - k + 1` zeros then as many ones.
    pub fn knots(&self) -> Option<&KnotVector> {
        match &self.form {
            Form::Polynomial(s) => Some(&s.knots),
            Form::Rational(_) => None,
        }
    }

    /// The control values of the derivative's spline (non-rational curves; `None` for NURBS):
    /// for the first derivative of a Bézier curve, the hodograph's `n (P_{i+1} - P_i)` with the
    /// same differences of the degrees.
    ///
    /// ```
    /// use neutrospline::Derivative;
    /// let hodograph = neutrospline::example1().derivative();
    /// let first = hodograph.control_values().unwrap()[0];
    /// assert_eq!(first.position, [6.0, 9.0]);
    /// assert!((first.truth - 1.5).abs() < 1e-15); // 3 (0.8 - 0.3)
    /// ```
    pub fn control_values(&self) -> Option<Vec<DerivativeValue<D>>> {
        match &self.form {
            Form::Polynomial(s) => Some(
                s.data
                    .chunks_exact(stride(D))
                    .map(derivative_from_row)
                    .collect(),
            ),
            Form::Rational(_) => None,
        }
    }

    /// The rational derivative's value at `t` into `out`: Leibniz's rule on the homogeneous
    /// values, with scratch rows on the stack up to order [`STACK_ORDERS`].
    fn rational_value(chain: &[Spline], t: (f64, f64), out: &mut [f64]) {
        let k = chain.len() - 1;
        if k <= STACK_ORDERS {
            let mut rows = [[0.0; ROW]; 2 * (STACK_ORDERS + 1)];
            let mut binomials = [1.0; STACK_ORDERS + 1];
            let (a, c) = rows.split_at_mut(STACK_ORDERS + 1);
            leibniz(chain, t, &mut a[..=k], &mut c[..=k], &mut binomials[..=k]);
            out[..ROW].copy_from_slice(&c[k]);
        } else {
            let mut a = vec![[0.0; ROW]; k + 1];
            let mut c = vec![[0.0; ROW]; k + 1];
            let mut binomials = vec![1.0; k + 1];
            leibniz(chain, t, &mut a, &mut c, &mut binomials);
            out[..ROW].copy_from_slice(&c[k]);
        }
    }
}

/// Evaluates `A^(j)` (`chain[j]`, homogeneous rows whose last channel `s` is the weight) at
/// `t` into `a[j]`, then `C^(j) = (A^(j) - sum_{i=1..j} binom(j, i) w^(i) C^(j-i)) / w` into
/// `c[j]` for `j = 0 ..= k`. `binomials` (length `k + 1`, all ones) is scratch for Pascal's rows.
fn leibniz(
    chain: &[Spline],
    (origin, offset): (f64, f64),
    a: &mut [[f64; ROW]],
    c: &mut [[f64; ROW]],
    binomials: &mut [f64],
) {
    let s = chain[0].stride - 1;
    for (spline, row) in chain.iter().zip(a.iter_mut()) {
        spline.evaluate_sum(origin, offset, row);
    }
    let w = a[0][s];
    for j in 0..a.len() {
        // Pascal's rule turns row j - 1 into row j: binomials[i] = binom(j, i).
        for i in (1..j).rev() {
            binomials[i] += binomials[i - 1];
        }
        for ch in 0..s {
            let mut numerator = a[j][ch];
            for i in 1..=j {
                numerator -= binomials[i] * a[i][s] * c[j - i][ch];
            }
            c[j][ch] = numerator / w;
        }
    }
}

impl<const D: usize> Evaluate for CurveDerivative<D> {
    type Point = DerivativeValue<D>;

    fn domain(&self) -> Range<f64> {
        self.domain.clone()
    }

    /// The derivative at `t` in the curve's domain.
    ///
    /// # Errors
    /// `t` not finite or outside the domain; [`EvalError::Overflow`] when a value is not
    /// representable (control positions near the largest float).
    fn evaluate(&self, t: f64) -> Result<DerivativeValue<D>, EvalError> {
        self.evaluate_sum(t, 0.0)
    }

    /// The derivative at the exact sum `origin + offset`, with every knot difference taken as
    /// `(origin - u_i) + offset`.
    ///
    /// # Errors
    /// As [`Evaluate::evaluate`] at `origin + offset`.
    fn evaluate_sum(&self, origin: f64, offset: f64) -> Result<DerivativeValue<D>, EvalError> {
        let t = origin + offset;
        check_parameter(t, &self.domain)?;
        let mut row = [0.0; ROW];
        match &self.form {
            Form::Polynomial(spline) => {
                spline.evaluate_sum(origin, offset, &mut row);
            }
            Form::Rational(chain) => Self::rational_value(chain, (origin, offset), &mut row),
        }
        if row[..stride(D)].iter().any(|v| !v.is_finite()) {
            return Err(EvalError::Overflow { t });
        }
        Ok(derivative_from_row(&row))
    }
}

impl<const D: usize> Derivative for CurveDerivative<D> {
    type Output = CurveDerivative<D>;

    /// The derivative of order `k + 1`.
    fn derivative(&self) -> CurveDerivative<D> {
        let form = match &self.form {
            Form::Polynomial(s) => Form::Polynomial(s.derivative()),
            Form::Rational(chain) => {
                let mut chain = chain.clone();
                let next = chain[chain.len() - 1].derivative();
                chain.push(next);
                Form::Rational(chain)
            }
        };
        CurveDerivative {
            order: self.order + 1,
            domain: self.domain.clone(),
            form,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::degrees::Degrees;
    use crate::point::ControlPoint;
    use crate::spline_curve::tests::quarter_circle;
    use crate::spline_curve::BSpline;

    #[test]
    fn curve_derivative_rational_orders_satisfy_the_circle_identities() {
        // x^2 + y^2 = 1 along the arc; differentiating once, twice and three times:
        // x x' + y y' = 0, x'^2 + y'^2 + x x'' + y y'' = 0,
        // 3 (x' x'' + y' y'') + x x''' + y y''' = 0.
        let c = quarter_circle();
        let d1 = c.derivative();
        let d2 = d1.derivative();
        let d3 = d2.derivative();
        assert_eq!((d1.order(), d2.order(), d3.order()), (1, 2, 3));
        assert!(d3.is_rational() && d3.knots().is_none() && d3.control_values().is_none());
        for k in 0..=20 {
            let t = k as f64 / 20.0;
            let [x, y] = c.evaluate(t).unwrap().position;
            let [x1, y1] = d1.evaluate(t).unwrap().position;
            let [x2, y2] = d2.evaluate(t).unwrap().position;
            let [x3, y3] = d3.evaluate(t).unwrap().position;
            assert!((x * x1 + y * y1).abs() < 1e-14, "t {t}");
            assert!((x1 * x1 + y1 * y1 + x * x2 + y * y2).abs() < 1e-13, "t {t}");
            assert!(
                (3.0 * (x1 * x2 + y1 * y2) + x * x3 + y * y3).abs() < 1e-12,
                "t {t}"
            );
        }
        // The degrees are blended by the same rational basis: indeterminacy is 1/2 everywhere,
        // so every derivative of it vanishes.
        assert!(d2.evaluate(0.3).unwrap().indeterminacy.abs() < 1e-15);
    }

    #[test]
    fn curve_derivative_of_a_cubic_spline_ends_at_order_four() {
        let d = Degrees::new(0.5, 0.5, 0.5).unwrap();
        let pts: Vec<_> = [[0.0, 0.0], [1.0, 3.0], [2.0, -1.0], [4.0, 2.0], [5.0, 0.0]]
            .map(|p| ControlPoint::new(p, d))
            .to_vec();
        let c = BSpline::clamped_uniform(pts, 3).unwrap();
        let d3 = c.derivative().derivative().derivative();
        let d4 = d3.derivative();
        assert_eq!((d3.degree(), d4.degree()), (0, 0));
        // Third derivative constant on each span [0, 1/2), [1/2, 1]; fourth zero.
        assert_eq!(d3.evaluate(0.1).unwrap(), d3.evaluate(0.4).unwrap());
        assert_eq!(d4.evaluate(0.7).unwrap().position, [0.0, 0.0]);
        // Against central differences of the second derivative.
        let d2 = c.derivative().derivative();
        let h = 1e-6;
        let fd = (d2.evaluate(0.3 + h).unwrap().position[1]
            - d2.evaluate(0.3 - h).unwrap().position[1])
            / (2.0 * h);
        assert!((fd - d3.evaluate(0.3).unwrap().position[1]).abs() < 1e-5);
    }

    #[test]
    fn curve_derivative_errors() {
        let d = quarter_circle().derivative();
        assert_eq!(
            d.evaluate(1.5).unwrap_err(),
            EvalError::ParameterOutOfDomain {
                t: 1.5,
                start: 0.0,
                end: 1.0
            }
        );
        assert!(d.evaluate(f64::NAN).is_err());
        assert_eq!(d.domain(), 0.0..1.0);
    }
}
