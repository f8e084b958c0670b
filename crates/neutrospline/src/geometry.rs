//! Geometry along a curve: arc length, curvature, the unit tangent and normal, and the
//! arc-length averages of the degrees and the score.
//!
//! Everything here is a default method of [`CurveGeometry`], written once over
//! [`Evaluate`] and [`Derivative`]; a kind only says where its polynomial (or rational) pieces
//! meet ([`CurveGeometry::breakpoints`]). Only the positions enter the geometry; the degrees
//! are what the averages weigh by length. See `docs/model.md` for the formulas.

use core::cmp::Ordering;
use core::ops::Range;
use std::collections::BinaryHeap;

use crate::any_curve::AnyCurve;
use crate::bezier::Bezier;
use crate::curve::{check_parameter, Derivative, EvalError, Evaluate};
use crate::derivative::CurveDerivative;
use crate::point::CurvePoint;
use crate::spline_curve::{SplineCurve, Weighting};

/// The relative accuracy of arc lengths and averages when none is asked for.
pub const DEFAULT_ACCURACY: f64 = 1e-12;

/// The smallest relative accuracy the quadrature aims at: a smaller request is raised to this
/// (rounding in the sums makes finer accuracy meaningless).
pub const FINEST_ACCURACY: f64 = 8.0 * f64::EPSILON;

/// The most halvings the adaptive quadrature makes over a whole range (beyond the curve's own
/// pieces) before it gives up.
pub const MAX_SUBINTERVALS: usize = 200_000;

/// Why a geometric quantity cannot be computed.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum GeometryError {
    /// A parameter is not finite, outside the domain, or a value overflows.
    #[error(transparent)]
    Eval(#[from] EvalError),
    /// The requested accuracy is zero, negative or not finite.
    #[error(
        "accuracy {accuracy} is not a positive finite number (a relative accuracy such as 1e-12)"
    )]
    AccuracyNotPositive {
        /// The requested accuracy.
        accuracy: f64,
    },
    /// The range of an arc length starts after it ends.
    #[error("the range [{start}, {end}] is reversed (arc lengths are taken from a smaller to a larger parameter)")]
    ReversedRange {
        /// Start of the range.
        start: f64,
        /// End of the range.
        end: f64,
    },
    /// The adaptive quadrature did not reach the accuracy within [`MAX_SUBINTERVALS`]
    /// halvings.
    #[error("the quadrature over [{start}, {end}] did not reach the relative accuracy {accuracy} within {MAX_SUBINTERVALS} halvings")]
    NotConverged {
        /// Start of the range.
        start: f64,
        /// End of the range.
        end: f64,
        /// The requested accuracy.
        accuracy: f64,
    },
    /// The curve does not move at `t` (|C'(t)| = 0): no tangent, normal or curvature there.
    #[error(
        "the curve is stationary at t = {t} (|C'(t)| = 0): no tangent, normal or curvature there"
    )]
    Stationary {
        /// The parameter.
        t: f64,
    },
    /// The curve is straight at `t` (C'' parallel to C'): no principal normal there.
    #[error("the curve is straight at t = {t} (zero curvature): no principal normal there")]
    Straight {
        /// The parameter.
        t: f64,
    },
    /// The curve has length zero, so averages per unit of length do not exist.
    #[error(
        "the curve has length zero (all its control positions coincide): no arc-length averages"
    )]
    ZeroLength,
    /// An arc length outside `[0, L]`.
    #[error("arc length {length} is outside [0, {total}] (the curve's length)")]
    LengthOutside {
        /// The arc length asked for.
        length: f64,
        /// The curve's length.
        total: f64,
    },
}

/// The arc-length averages of a curve's degrees: `(1/L) ∫ q(t) |C'(t)| dt` over the domain
/// for `q` = truth, indeterminacy, falsity and score, with the length `L`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ArcAverages {
    /// The length `L` of the curve.
    pub length: f64,
    /// The average truth per unit of length.
    pub truth: f64,
    /// The average indeterminacy per unit of length.
    pub indeterminacy: f64,
    /// The average falsity per unit of length.
    pub falsity: f64,
    /// The average score `(2 + T - I - F) / 3` per unit of length (the score of the averages,
    /// since the score is affine).
    pub score: f64,
}

/// Geometry along a curve of any kind, one body for every kind.
///
/// - Arc length `s(a, b) = ∫_a^b |C'(t)| dt`, by adaptive Gauss-Legendre quadrature
///   (10 points per subinterval) on each polynomial or rational piece, to a relative accuracy.
/// - Curvature `κ(t) = |C'(t) × C''(t)| / |C'(t)|^3` (2-D: the absolute value of the scalar
///   cross product `x' y'' - y' x''`; 3-D: the norm of the cross product).
/// - Unit tangent `C' / |C'|`, principal unit normal: `C''` minus its component along the
///   tangent, normalised (it points towards the centre of curvature).
/// - Arc-length averages `(1/L) ∫ q(t) |C'(t)| dt` of the degrees and the score.
///
/// At an interior knot where C' or C'' jumps, the value from the right is used (from the left
/// at the end of the domain), as by [`Derivative`].
///
/// ```
/// use neutrospline::{CurveGeometry, Evaluate};
/// let curve = neutrospline::example1();
/// let length = curve.length()?;
/// let half = curve.arc_length(0.0..0.5, 1e-12)?;
/// assert!(half > 0.0 && half < length);
/// // The length is at least the chord from (1, 3) to (9, 5).
/// assert!(length >= (64.0_f64 + 4.0).sqrt());
/// let kappa = curve.curvature(0.5)?;
/// assert!(kappa > 0.0);
/// let averages = curve.arc_averages(1e-12)?;
/// assert!((averages.length - length).abs() <= 1e-12 * length);
/// # Ok::<(), neutrospline::GeometryError>(())
/// ```
pub trait CurveGeometry<const D: usize>:
    Evaluate<Point = CurvePoint<D>> + Derivative<Output = CurveDerivative<D>>
{
    /// The parameters strictly inside the domain where the curve's pieces meet (the distinct
    /// interior knots of a spline; none for a Bézier curve), increasing.
    fn breakpoints(&self) -> Vec<f64>;

    /// The arc length `∫ |C'(t)| dt` over `range` (inside the domain, start <= end), to the
    /// relative `accuracy` (for example [`DEFAULT_ACCURACY`]; values below
    /// [`FINEST_ACCURACY`] are raised to it).
    ///
    /// ```
    /// use neutrospline::{Bezier, ControlPoint, CurveGeometry, Degrees};
    /// let d = Degrees::new(0.5, 0.2, 0.1)?;
    /// let line = Bezier::new(vec![
    ///     ControlPoint::new([0.0, 0.0], d),
    ///     ControlPoint::new([1.0, 1.0], d),
    ///     ControlPoint::new([3.0, 4.0], d),
    /// ])?;
    /// // Not a straight line: longer than the chord 5.
    /// assert!(line.arc_length(0.0..1.0, 1e-12)? > 5.0);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// [`GeometryError::AccuracyNotPositive`], [`GeometryError::ReversedRange`], an end
    /// outside the domain or not finite ([`GeometryError::Eval`]), or
    /// [`GeometryError::NotConverged`].
    fn arc_length(&self, range: Range<f64>, accuracy: f64) -> Result<f64, GeometryError> {
        let velocity = self.derivative();
        let [length] = integrate(
            &self.breakpoints(),
            &self.domain(),
            range,
            accuracy,
            |origin, offset| Ok([speed(&velocity.evaluate_sum(origin, offset)?.position)]),
        )?;
        Ok(length)
    }

    /// The length of the whole curve to [`DEFAULT_ACCURACY`].
    ///
    /// ```
    /// use neutrospline::CurveGeometry;
    /// assert!(neutrospline::example1().length()? > 0.0);
    /// # Ok::<(), neutrospline::GeometryError>(())
    /// ```
    ///
    /// # Errors
    /// [`GeometryError::NotConverged`] or an overflow.
    fn length(&self) -> Result<f64, GeometryError> {
        self.arc_length(self.domain(), DEFAULT_ACCURACY)
    }

    /// The parameter at arc length `s` from the start of the domain, `0 <= s <= L`: the `t`
    /// with `∫_a^t |C'| = s`, to `accuracy` relative to the curve's length `L` (the arc length
    /// up to the returned `t` is within `accuracy * L` of `s`). Safeguarded Newton on
    /// `f(t) = ∫_a^t |C'| - s` with `f' = |C'(t)|`, bisecting wherever a step leaves the bracket
    /// or the curve stands still (a cusp); at a stretch where the curve stands still the
    /// smallest such parameter is not guaranteed, any one of them is returned.
    ///
    /// ```
    /// use neutrospline::{Bezier, ControlPoint, CurveGeometry, Degrees};
    /// let d = Degrees::new(0.5, 0.2, 0.1)?;
    /// // A straight line traversed unevenly: x(t) = 0.2 t (1 - t) + t^2 on the x axis.
    /// let line = Bezier::new(vec![
    ///     ControlPoint::new([0.0, 0.0], d),
    ///     ControlPoint::new([0.1, 0.0], d),
    ///     ControlPoint::new([1.0, 0.0], d),
    /// ])?;
    /// let t = line.parameter_at_length(0.5, 1e-14)?;
    /// // 0.8 t^2 + 0.2 t = 0.5, so t = (-0.2 + sqrt(0.04 + 1.6)) / 1.6.
    /// assert!((t - (-0.2 + 1.64_f64.sqrt()) / 1.6).abs() < 1e-13);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// [`GeometryError::LengthOutside`], [`GeometryError::AccuracyNotPositive`], or the
    /// quadrature's errors.
    fn parameter_at_length(&self, s: f64, accuracy: f64) -> Result<f64, GeometryError> {
        let total = self.arc_length(self.domain(), accuracy)?;
        let mut out = self.parameters_at_lengths(&[s], total, accuracy)?;
        Ok(out.remove(0))
    }

    /// The parameters of `count` points evenly spaced along the curve by arc length: the
    /// parameters at `s_k = k L / (count - 1)`, `k = 0..count` (both ends exact; for
    /// `count = 1`, the start), each to `accuracy` relative to `L` as in
    /// [`CurveGeometry::parameter_at_length`].
    ///
    /// ```
    /// use neutrospline::{CurveGeometry, Evaluate};
    /// let curve = neutrospline::example1();
    /// let ts = curve.arc_length_parameters(5, 1e-12)?;
    /// assert_eq!((ts[0], ts[4]), (0.0, 1.0));
    /// let quarter = curve.arc_length(0.0..ts[1], 1e-12)?;
    /// assert!((quarter - curve.length()? / 4.0).abs() < 1e-10);
    /// # Ok::<(), neutrospline::GeometryError>(())
    /// ```
    ///
    /// # Errors
    /// [`GeometryError::AccuracyNotPositive`] or the quadrature's errors.
    fn arc_length_parameters(
        &self,
        count: usize,
        accuracy: f64,
    ) -> Result<Vec<f64>, GeometryError> {
        let domain = self.domain();
        let total = self.arc_length(domain.clone(), accuracy)?;
        let targets: Vec<f64> = (0..count)
            .map(|k| crate::batch::uniform_parameter(k, count, 0.0..total))
            .collect();
        let mut out = self.parameters_at_lengths(&targets, total, accuracy)?;
        if let Some(last) = out.last_mut() {
            if count > 1 {
                *last = domain.end;
            }
        }
        if let Some(first) = out.first_mut() {
            *first = domain.start;
        }
        Ok(out)
    }

    /// The parameters at the increasing arc lengths `targets` (each in `[0, total]`, `total`
    /// the length), found in order, each bracketed from the previous one.
    #[doc(hidden)]
    fn parameters_at_lengths(
        &self,
        targets: &[f64],
        total: f64,
        accuracy: f64,
    ) -> Result<Vec<f64>, GeometryError> {
        let domain = self.domain();
        let velocity = self.derivative();
        let tolerance = accuracy.max(FINEST_ACCURACY) * total.max(f64::MIN_POSITIVE);
        let mut out = Vec::with_capacity(targets.len());
        // The last parameter found and the arc length up to it.
        let (mut base_t, mut base_s) = (domain.start, 0.0);
        for &s in targets {
            if !(0.0..=total).contains(&s) {
                return Err(GeometryError::LengthOutside { length: s, total });
            }
            if s <= base_s {
                out.push(base_t);
                continue;
            }
            // f(t) = base_s + ∫_{base_t}^t |C'| - s, increasing; f(lo) < 0 <= f(hi).
            let (mut lo, mut hi) = (base_t, domain.end);
            let guess =
                base_t + (domain.end - base_t) * ((s - base_s) / (total - base_s)).clamp(0.0, 1.0);
            let mut t = guess.clamp(lo, hi);
            let mut found = None;
            for _ in 0..200 {
                let f = base_s + self.arc_length(base_t..t, accuracy)? - s;
                if f.abs() <= tolerance {
                    found = Some(t);
                    break;
                }
                if f < 0.0 {
                    lo = t;
                } else {
                    hi = t;
                }
                let v = speed(&velocity.evaluate(t)?.position);
                let newton = t - f / v;
                t = if v > 0.0 && newton > lo && newton < hi {
                    newton
                } else {
                    0.5 * (lo + hi)
                };
                if hi - lo <= f64::EPSILON * hi.abs().max(lo.abs()).max(1.0) {
                    found = Some(t);
                    break;
                }
            }
            let t = found.unwrap_or(t);
            base_s += self.arc_length(base_t..t, accuracy)?;
            base_t = t;
            out.push(t);
        }
        Ok(out)
    }

    /// The curvature `|C' × C''| / |C'|^3` at `t`, `>= 0` (the reciprocal of the radius of the
    /// osculating circle).
    ///
    /// ```
    /// use neutrospline::{Bezier, ControlPoint, CurveGeometry, Degrees};
    /// let d = Degrees::new(0.5, 0.2, 0.1)?;
    /// // The parabola (t, t^2) from a quadratic Bézier: curvature 2 at t = 0.
    /// let parabola = Bezier::new(vec![
    ///     ControlPoint::new([0.0, 0.0], d),
    ///     ControlPoint::new([0.5, 0.0], d),
    ///     ControlPoint::new([1.0, 1.0], d),
    /// ])?;
    /// assert!((parabola.curvature(0.0)? - 2.0).abs() < 1e-15);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// `t` not finite or outside the domain, [`GeometryError::Stationary`] where
    /// `|C'(t)| = 0`.
    fn curvature(&self, t: f64) -> Result<f64, GeometryError> {
        let first = self.derivative();
        let second = first.derivative();
        let velocity = first.evaluate(t)?.position;
        let acceleration = second.evaluate(t)?.position;
        let v = speed(&velocity);
        let kappa = cross_norm(&velocity, &acceleration) / (v * v * v);
        if v == 0.0 || !kappa.is_finite() {
            return Err(GeometryError::Stationary { t });
        }
        Ok(kappa)
    }

    /// The unit tangent `C'(t) / |C'(t)|`.
    ///
    /// ```
    /// use neutrospline::CurveGeometry;
    /// // Example 1 starts in the direction 3 (P_1 - P_0) = (6, 9).
    /// let tangent = neutrospline::example1().unit_tangent(0.0)?;
    /// let norm = (36.0_f64 + 81.0).sqrt();
    /// assert!((tangent[0] - 6.0 / norm).abs() < 1e-15);
    /// assert!((tangent[1] - 9.0 / norm).abs() < 1e-15);
    /// # Ok::<(), neutrospline::GeometryError>(())
    /// ```
    ///
    /// # Errors
    /// `t` not finite or outside the domain, [`GeometryError::Stationary`] where
    /// `|C'(t)| = 0`.
    fn unit_tangent(&self, t: f64) -> Result<[f64; D], GeometryError> {
        let velocity = self.derivative().evaluate(t)?.position;
        normalised(velocity).ok_or(GeometryError::Stationary { t })
    }

    /// The principal unit normal at `t`: `C''(t)` minus its component along the unit tangent,
    /// normalised; it points towards the centre of curvature.
    ///
    /// ```
    /// use neutrospline::{Bezier, ControlPoint, CurveGeometry, Degrees};
    /// let d = Degrees::new(0.5, 0.2, 0.1)?;
    /// let parabola = Bezier::new(vec![
    ///     ControlPoint::new([0.0, 0.0], d),
    ///     ControlPoint::new([0.5, 0.0], d),
    ///     ControlPoint::new([1.0, 1.0], d),
    /// ])?;
    /// assert_eq!(parabola.unit_normal(0.0)?, [0.0, 1.0]);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// `t` not finite or outside the domain, [`GeometryError::Stationary`] where
    /// `|C'(t)| = 0`, [`GeometryError::Straight`] where C'' is parallel to C' (zero
    /// curvature, to rounding).
    fn unit_normal(&self, t: f64) -> Result<[f64; D], GeometryError> {
        let first = self.derivative();
        let velocity = first.evaluate(t)?.position;
        let acceleration = first.derivative().evaluate(t)?.position;
        let tangent = normalised(velocity).ok_or(GeometryError::Stationary { t })?;
        let along: f64 = tangent.iter().zip(&acceleration).map(|(a, b)| a * b).sum();
        let mut across = acceleration;
        for (value, direction) in across.iter_mut().zip(&tangent) {
            *value -= along * direction;
        }
        let size = speed(&across);
        if size <= 16.0 * f64::EPSILON * speed(&acceleration) {
            return Err(GeometryError::Straight { t });
        }
        normalised(across).ok_or(GeometryError::Straight { t })
    }

    /// The length and the arc-length averages `(1/L) ∫ q(t) |C'(t)| dt` of truth,
    /// indeterminacy, falsity and score over the whole domain, by the same quadrature as
    /// [`CurveGeometry::arc_length`], to the relative `accuracy` (of the length; the weighted
    /// integrals to the same absolute error).
    ///
    /// ```
    /// use neutrospline::CurveGeometry;
    /// let averages = neutrospline::example1().arc_averages(1e-12)?;
    /// // Averages of degrees lie within the control degrees' range.
    /// assert!(averages.truth >= 0.2 && averages.truth <= 0.8);
    /// let score = (2.0 + averages.truth - averages.indeterminacy - averages.falsity) / 3.0;
    /// assert!((averages.score - score).abs() < 1e-15);
    /// # Ok::<(), neutrospline::GeometryError>(())
    /// ```
    ///
    /// # Errors
    /// [`GeometryError::AccuracyNotPositive`], [`GeometryError::NotConverged`],
    /// [`GeometryError::ZeroLength`].
    fn arc_averages(&self, accuracy: f64) -> Result<ArcAverages, GeometryError> {
        let velocity = self.derivative();
        let [length, truth, indeterminacy, falsity] = integrate(
            &self.breakpoints(),
            &self.domain(),
            self.domain(),
            accuracy,
            |origin, offset| {
                let v = speed(&velocity.evaluate_sum(origin, offset)?.position);
                let degrees = self.evaluate_sum(origin, offset)?.degrees;
                Ok([
                    v,
                    degrees.truth() * v,
                    degrees.indeterminacy() * v,
                    degrees.falsity() * v,
                ])
            },
        )?;
        if length <= 0.0 {
            return Err(GeometryError::ZeroLength);
        }
        let (truth, indeterminacy, falsity) =
            (truth / length, indeterminacy / length, falsity / length);
        Ok(ArcAverages {
            length,
            truth,
            indeterminacy,
            falsity,
            score: (2.0 + truth - indeterminacy - falsity) / 3.0,
        })
    }
}

impl<const D: usize> CurveGeometry<D> for Bezier<D> {
    /// A Bézier curve is one polynomial piece.
    fn breakpoints(&self) -> Vec<f64> {
        Vec::new()
    }
}

impl<const D: usize, W: Weighting> CurveGeometry<D> for SplineCurve<D, W> {
    /// The distinct interior knots.
    fn breakpoints(&self) -> Vec<f64> {
        self.knots().interior_breakpoints()
    }
}

impl<const D: usize> CurveGeometry<D> for AnyCurve<D> {
    fn breakpoints(&self) -> Vec<f64> {
        self.knots()
            .map(crate::knots::KnotVector::interior_breakpoints)
            .unwrap_or_default()
    }
}

/// The Euclidean norm.
fn speed<const D: usize>(v: &[f64; D]) -> f64 {
    v.iter().fold(0.0_f64, |acc, x| acc.hypot(*x))
}

/// `v / |v|`, `None` for a zero or non-finite norm.
fn normalised<const D: usize>(v: [f64; D]) -> Option<[f64; D]> {
    let size = speed(&v);
    (size > 0.0 && size.is_finite()).then(|| v.map(|x| x / size))
}

/// `|a × b|`: in 2-D the absolute scalar cross product, in 3-D the norm of the cross product.
fn cross_norm<const D: usize>(a: &[f64; D], b: &[f64; D]) -> f64 {
    let (a, b): (&[f64], &[f64]) = (a, b);
    match (a, b) {
        ([ax, ay], [bx, by]) => ax.mul_add(*by, -(ay * bx)).abs(),
        ([ax, ay, az], [bx, by, bz]) => {
            let cross = [ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx];
            speed(&cross)
        }
        _ => unreachable!("curves are 2-D or 3-D"),
    }
}

/// Nodes (positive half) and weights of the 10-point Gauss-Legendre rule on [-1, 1].
const GAUSS_NODES: [f64; 5] = [
    0.148_874_338_981_631_2,
    0.433_395_394_129_247_2,
    0.679_409_568_299_024_4,
    0.865_063_366_688_984_5,
    0.973_906_528_517_171_7,
];
const GAUSS_WEIGHTS: [f64; 5] = [
    0.295_524_224_714_752_87,
    0.269_266_719_309_996_35,
    0.219_086_362_515_982_04,
    0.149_451_349_150_580_6,
    0.066_671_344_308_688_14,
];

/// The 10-point Gauss-Legendre rule for the `N` integrands of `f` on `[a, b]`.
///
/// `f` takes a parameter as the exact sum `origin + offset` (see [`Evaluate::evaluate_sum`]):
/// the nodes `(a + b) / 2 ± x_i (b - a) / 2` are not floats, and on a short interval far from
/// zero their rounding (half an ulp of `a`, a part `ulp(a) / (b - a)` of the interval) is
/// enough to move the rule by more than the requested accuracy where the integrand is steep.
/// The origin is the rounded midpoint, the offset carries the rest (the rounding errors of
/// `a + b` and `b - a`, exact by Knuth's two-sum) to the precision of the interval.
fn gauss<const N: usize>(
    f: &impl Fn(f64, f64) -> Result<[f64; N], EvalError>,
    a: f64,
    b: f64,
) -> Result<[f64; N], EvalError> {
    let (sum, sum_error) = two_sum(a, b);
    let (width, width_error) = two_sum(b, -a);
    let middle = 0.5 * sum;
    let middle_error = 0.5 * sum_error;
    let half = 0.5 * width;
    let half_error = 0.5 * width_error;
    let mut total = [0.0; N];
    for (node, weight) in GAUSS_NODES.iter().zip(GAUSS_WEIGHTS) {
        let step = half.mul_add(*node, half_error * node);
        for offset in [middle_error - step, middle_error + step] {
            for (s, value) in total.iter_mut().zip(f(middle, offset)?) {
                *s += weight * value;
            }
        }
    }
    Ok(total.map(|s| s * half))
}

/// Knuth's two-sum: `(s, e)` with `s = fl(a + b)` and `s + e = a + b` exactly.
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    let e = (a - (s - bb)) + (b - bb);
    (s, e)
}

/// A subinterval of the adaptive quadrature: the rule on its halves and quarters (which its
/// halves reuse when it is split), its value (the sum over the quarters) and the error estimate
/// of [`refined`].
struct Subinterval<const N: usize> {
    start: f64,
    end: f64,
    halves: [[f64; N]; 2],
    quarters: [[f64; N]; 4],
    value: [f64; N],
    error: f64,
}

fn subinterval<const N: usize>(
    f: &impl Fn(f64, f64) -> Result<[f64; N], EvalError>,
    start: f64,
    end: f64,
) -> Result<Subinterval<N>, EvalError> {
    let middle = 0.5 * (start + end);
    let whole = gauss(f, start, end)?;
    let halves = [gauss(f, start, middle)?, gauss(f, middle, end)?];
    refined(f, start, end, whole, halves)
}

/// The subinterval whose rule on the whole and on the halves is known: the rule on the
/// quarters gives its value, and the three levels its error estimate.
///
/// With `coarse` the largest change from the whole to the halves and `fine` the one from the
/// halves to the quarters, the rule converges by the ratio `r = fine / coarse` per halving, and
/// the error left in the quarters is about `fine · r / (1 - r)`. The estimate is `fine` while
/// `r <= 1/2` (the smooth case, where it is an upper bound) and `fine · r / (1 - r)` beyond,
/// with `r` held at 0.9 at most: near a pole of a rational piece's speed the halves can be as
/// wrong as the whole, and their difference alone would understate the error. A `fine` at the
/// rounding of the rule (16 ulp of the quarters' sizes) is taken as it is.
fn refined<const N: usize>(
    f: &impl Fn(f64, f64) -> Result<[f64; N], EvalError>,
    start: f64,
    end: f64,
    whole: [f64; N],
    halves: [[f64; N]; 2],
) -> Result<Subinterval<N>, EvalError> {
    let middle = 0.5 * (start + end);
    let quarters = [
        gauss(f, start, 0.5 * (start + middle))?,
        gauss(f, 0.5 * (start + middle), middle)?,
        gauss(f, middle, 0.5 * (middle + end))?,
        gauss(f, 0.5 * (middle + end), end)?,
    ];
    let mut value = [0.0; N];
    let mut coarse = 0.0_f64;
    let mut fine = 0.0_f64;
    let mut rounding = 0.0_f64;
    for k in 0..N {
        let by_halves = halves[0][k] + halves[1][k];
        value[k] = (quarters[0][k] + quarters[1][k]) + (quarters[2][k] + quarters[3][k]);
        coarse = coarse.max((by_halves - whole[k]).abs());
        fine = fine.max((value[k] - by_halves).abs());
        let size: f64 = quarters.iter().map(|q| q[k].abs()).sum();
        rounding = rounding.max(16.0 * f64::EPSILON * size);
    }
    // Differences at the rounding of the rule are noise, not a rate of convergence.
    let ratio = if coarse > 0.0 && fine > rounding {
        (fine / coarse).min(0.9)
    } else {
        0.0
    };
    let error = if ratio <= 0.5 {
        fine
    } else {
        fine * ratio / (1.0 - ratio)
    };
    Ok(Subinterval {
        start,
        end,
        halves,
        quarters,
        value,
        error,
    })
}

/// Globally adaptive Gauss-Legendre quadrature of `f` over `range`, split first at the
/// `breakpoints` inside it; the first integrand sets the relative accuracy, the others are
/// held to the same absolute error.
fn integrate<const N: usize>(
    breakpoints: &[f64],
    domain: &Range<f64>,
    range: Range<f64>,
    accuracy: f64,
    f: impl Fn(f64, f64) -> Result<[f64; N], EvalError>,
) -> Result<[f64; N], GeometryError> {
    if !(accuracy > 0.0 && accuracy.is_finite()) {
        return Err(GeometryError::AccuracyNotPositive { accuracy });
    }
    check_parameter(range.start, domain)?;
    check_parameter(range.end, domain)?;
    if range.start > range.end {
        return Err(GeometryError::ReversedRange {
            start: range.start,
            end: range.end,
        });
    }
    let target = accuracy.max(FINEST_ACCURACY);
    let mut cuts = vec![range.start];
    cuts.extend(
        breakpoints
            .iter()
            .copied()
            .filter(|&b| b > range.start && b < range.end),
    );
    cuts.push(range.end);
    let mut pieces = BinaryHeap::new();
    let mut error = 0.0;
    let mut estimate = 0.0;
    for pair in cuts.windows(2) {
        if pair[1] > pair[0] {
            let piece = subinterval(&f, pair[0], pair[1])?;
            error += piece.error;
            estimate += piece.value[0];
            pieces.push(piece);
        }
    }
    let limit = pieces.len() + MAX_SUBINTERVALS;
    while let Some(worst) = pieces.peek() {
        if error <= target * estimate.abs() || worst.error == 0.0 {
            break;
        }
        if pieces.len() >= limit {
            return Err(GeometryError::NotConverged {
                start: range.start,
                end: range.end,
                accuracy,
            });
        }
        let Some(piece) = pieces.pop() else { break };
        let middle = 0.5 * (piece.start + piece.end);
        error -= piece.error;
        estimate -= piece.value[0];
        if middle <= piece.start || middle >= piece.end {
            // The subinterval cannot be halved in floating point: keep its value as it is.
            pieces.push(Subinterval {
                error: 0.0,
                ..piece
            });
            estimate += piece.value[0];
            continue;
        }
        let [q0, q1, q2, q3] = piece.quarters;
        for (start, end, whole, halves) in [
            (piece.start, middle, piece.halves[0], [q0, q1]),
            (middle, piece.end, piece.halves[1], [q2, q3]),
        ] {
            let half = refined(&f, start, end, whole, halves)?;
            error += half.error;
            estimate += half.value[0];
            pieces.push(half);
        }
        // Recompute the running error now and then so that cancellation cannot stall it.
        if pieces.len() % 1024 == 0 {
            error = pieces.iter().map(|p| p.error).sum();
        }
    }
    // The sum over the subintervals in parameter order (a sum independent of the heap's order).
    let mut ordered = pieces.into_vec();
    ordered.sort_by(|a, b| a.start.total_cmp(&b.start));
    let mut total = [0.0; N];
    for piece in &ordered {
        for (t, v) in total.iter_mut().zip(piece.value) {
            *t += v;
        }
    }
    Ok(total)
}

impl<const N: usize> PartialEq for Subinterval<N> {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}

impl<const N: usize> Eq for Subinterval<N> {}

impl<const N: usize> PartialOrd for Subinterval<N> {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl<const N: usize> Ord for Subinterval<N> {
    /// By error estimate, the largest first out of the heap; ties by position.
    fn cmp(&self, other: &Self) -> Ordering {
        self.error
            .total_cmp(&other.error)
            .then_with(|| other.start.total_cmp(&self.start))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gauss_weights_sum_to_one_and_integrate_degree_19_exactly() {
        let sum: f64 = GAUSS_WEIGHTS.iter().sum();
        assert!((sum - 1.0).abs() < 1e-15);
        // ∫_0^1 t^19 dt = 1/20.
        let [value] = gauss(&|o: f64, d: f64| Ok([(o + d).powi(19)]), 0.0, 1.0).unwrap();
        assert!((value - 0.05).abs() < 1e-15);
    }

    #[test]
    fn cross_norm_in_two_and_three_dimensions() {
        assert_eq!(cross_norm(&[1.0, 0.0], &[0.0, -2.0]), 2.0);
        assert_eq!(cross_norm(&[1.0, 0.0, 0.0], &[0.0, 3.0, 4.0]), 5.0);
    }
}
