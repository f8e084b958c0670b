//! Operations that change a spline curve's representation but not the curve (up to a stated
//! tolerance): knots inserted several times, knot refinement, Tiller's knot removal, and
//! the domain mapped onto another interval (docs/model.md, "Operations").
//!
//! Every exact operation here forms each new control point as a convex combination of old
//! ones (for NURBS in rational form), so the degrees stay within the old control values and
//! every membership rule keeps holding. Knot removal solves new points by extrapolation; it
//! keeps a removal only when the curve moves by at most the tolerance and every new degree
//! stays in \[0, 1\] (values within 1e-12 of the box, rounding, are clamped onto it).

use crate::curve::Evaluate;
use crate::knots::{KnotError, KnotVector};
use crate::point::CurvePoint;
use crate::spline::Spline;
use crate::spline_curve::{SplineCurve, Weighting};

/// The result of [`SplineCurve::remove_knot`]: the curve, how many times the knot was
/// removed, and how far the curve moved.
#[derive(Clone, Debug, PartialEq)]
pub struct KnotRemoval<C> {
    /// The curve with the knot removed `removed` times.
    pub curve: C,
    /// How many times the knot was removed (0 when not even once within the tolerance).
    pub removed: usize,
    /// The largest deviation from the original curve found ([`SplineCurve::deviation_from`]).
    pub error: f64,
}

/// Values within this of the degree box \[0, 1\] are rounding, clamped onto it.
const ROUNDING: f64 = 1e-12;

/// Samples per knot span used by [`SplineCurve::deviation_from`] (a quarter of them per
/// direction by `Surface::deviation_from`).
pub const DEVIATION_SAMPLES_PER_SPAN: usize = 32;

/// The distance of two points of a curve or surface: the larger of the Euclidean distance of
/// the positions and the largest difference of a degree.
pub(crate) fn point_deviation<const D: usize>(p: &CurvePoint<D>, q: &CurvePoint<D>) -> f64 {
    let position = p
        .position
        .iter()
        .zip(&q.position)
        .map(|(x, y)| (x - y) * (x - y))
        .sum::<f64>()
        .sqrt();
    p.degrees
        .to_array()
        .iter()
        .zip(q.degrees.to_array())
        .map(|(x, y)| (x - y).abs())
        .fold(position, f64::max)
}

/// The parameters where the deviation of two splines on `mine`'s domain is sampled: the
/// domain's ends, the interior breakpoints of both knot vectors, and `per_span` evenly spaced
/// parameters in each span between them (the last end included), increasing.
pub(crate) fn deviation_samples(
    mine: &KnotVector,
    theirs: &KnotVector,
    per_span: usize,
) -> Vec<f64> {
    let domain = mine.domain();
    let mut breaks = vec![domain.start, domain.end];
    breaks.extend(mine.interior_breakpoints());
    breaks.extend(theirs.interior_breakpoints());
    breaks.retain(|t| (domain.start..=domain.end).contains(t));
    breaks.sort_by(f64::total_cmp);
    breaks.dedup();
    let mut at = Vec::with_capacity(breaks.len() * per_span + 1);
    for w in breaks.windows(2) {
        for k in 0..per_span {
            at.push(w[0] + (w[1] - w[0]) * k as f64 / per_span as f64);
        }
    }
    at.push(domain.end);
    at
}

/// [`KnotError::NotAnInteriorKnot`] unless `u` is a knot strictly inside the domain.
pub(crate) fn check_interior_knot(knots: &KnotVector, u: f64) -> Result<(), KnotError> {
    let interior = knots.interior_breakpoints();
    if interior.contains(&u) {
        return Ok(());
    }
    let knots = if interior.is_empty() {
        "none".to_owned()
    } else {
        interior
            .iter()
            .map(f64::to_string)
            .collect::<Vec<_>>()
            .join(", ")
    };
    Err(KnotError::NotAnInteriorKnot { value: u, knots })
}

/// The knots mapped by the affine map of their domain onto `[start, end]` (the domain's ends
/// exactly onto `start` and `end`).
///
/// # Errors
/// [`KnotError::BadInterval`] unless `start < end`, both finite, and the mapped knots finite
/// and non-decreasing.
pub(crate) fn mapped_knots(
    knots: &KnotVector,
    start: f64,
    end: f64,
) -> Result<KnotVector, KnotError> {
    let bad = KnotError::BadInterval { start, end };
    if !(start.is_finite() && end.is_finite() && start < end) {
        return Err(bad);
    }
    let domain = knots.domain();
    let scale = (end - start) / (domain.end - domain.start);
    let mapped: Vec<f64> = knots
        .knots()
        .iter()
        .map(|&k| {
            if k == domain.start {
                start
            } else if k == domain.end {
                end
            } else {
                start + (k - domain.start) * scale
            }
        })
        .collect();
    if mapped.iter().any(|k| !k.is_finite()) || mapped.windows(2).any(|w| w[0] > w[1]) {
        return Err(bad);
    }
    Ok(KnotVector::from_parts_unchecked(knots.degree(), mapped))
}

/// Removes the interior knot `u` of the spline `work` (the form the shape is computed from:
/// homogeneous for rational ones) up to `times` times: each removal must pass Tiller's test
/// within `tolerance`, give a shape (`build`; `None` when its degrees leave their box) and
/// keep the shape's deviation from the original (`deviation`) within `tolerance`. Returns the
/// last spline, its shape (or `None` when no removal was kept), the removals and the
/// deviation.
pub(crate) fn remove_while<T>(
    mut work: Spline,
    u: f64,
    times: usize,
    tolerance: f64,
    build: impl Fn(&Spline) -> Option<T>,
    deviation: impl Fn(&T) -> f64,
) -> (Spline, Option<T>, usize, f64) {
    let (mut shape, mut removed, mut error) = (None, 0, 0.0);
    while removed < times && work.knots.multiplicity(u) > 0 {
        let Some(next) = work.remove_knot_once(u, tolerance) else {
            break;
        };
        let Some(candidate) = build(&next) else {
            break;
        };
        let d = deviation(&candidate);
        if d.is_nan() || d > tolerance {
            break;
        }
        work = next;
        shape = Some(candidate);
        removed += 1;
        error = d;
    }
    (work, shape, removed, error)
}

/// The degree reduction of the spline `work` (the form the shape is computed from) within
/// `tolerance`: its reduced pieces ([`Spline::reduced_pieces`]), then every interior knot
/// removed as [`remove_while`] allows. `build` makes the shape of a spline (projecting its
/// degrees), `deviation` measures it against the original.
pub(crate) fn reduce_within<T>(
    work: &Spline,
    layout: &crate::reduce::DegreeLayout,
    tolerance: f64,
    build: impl Fn(&Spline) -> Result<T, ReduceError>,
    deviation: impl Fn(&T) -> f64,
) -> Result<DegreeReduction<T>, ReduceError> {
    let p = work.degree();
    if p < 2 {
        return Err(ReduceError::DegreeTooLow { degree: p });
    }
    let mut work = work
        .reduced_pieces(layout)
        .ok_or(ReduceError::DegreeTooLow { degree: p })?;
    let mut current = build(&work)?;
    let mut error = deviation(&current);
    if error.is_nan() || error > tolerance {
        return Err(ReduceError::NotWithin {
            degree: p - 1,
            tolerance,
            error,
        });
    }
    for u in work.knots.interior_breakpoints() {
        let (next, shape, _, e) = remove_while(
            work.clone(),
            u,
            usize::MAX,
            tolerance,
            |s| build(s).ok(),
            &deviation,
        );
        if let Some(shape) = shape {
            work = next;
            current = shape;
            error = e;
        }
    }
    Ok(DegreeReduction {
        curve: current,
        error,
    })
}

/// The degree channels `D..D + 3` of every row clamped onto \[0, 1\] when within rounding of
/// it; `false` when a value lies further out.
fn degrees_in_box<const D: usize>(spline: &mut Spline) -> bool {
    for i in 0..spline.count() {
        for c in D..D + 3 {
            let v = &mut spline.data[i * spline.stride + c];
            if *v < -ROUNDING || *v > 1.0 + ROUNDING || !v.is_finite() {
                return false;
            }
            *v = v.clamp(0.0, 1.0);
        }
    }
    true
}

impl<const D: usize, W: Weighting> SplineCurve<D, W> {
    /// The largest distance between this curve and `other` on this curve's domain, sampled
    /// at every distinct knot of either and [`DEVIATION_SAMPLES_PER_SPAN`] evenly spaced
    /// parameters in each span between them: the larger of the Euclidean distance of the
    /// positions and the largest difference of a degree. (A sample, not a bound: it finds
    /// the deviation of a piece to within its variation between samples.)
    ///
    /// ```
    /// let curve = neutrospline::example1().to_bspline();
    /// let same = curve.insert_knot(0.3)?;
    /// assert!(curve.deviation_from(&same) < 1e-14);
    /// # Ok::<(), neutrospline::KnotError>(())
    /// ```
    pub fn deviation_from<V: Weighting>(&self, other: &SplineCurve<D, V>) -> f64 {
        deviation_samples(self.knots(), other.knots(), DEVIATION_SAMPLES_PER_SPAN)
            .into_iter()
            .map(|t| match (self.evaluate(t), other.evaluate(t)) {
                (Ok(p), Ok(q)) => point_deviation(&p, &q),
                _ => f64::INFINITY,
            })
            .fold(0.0, f64::max)
    }

    /// The same curve with knot `u` inserted `times` times (Boehm's algorithm repeated).
    ///
    /// # Errors
    /// `u` outside the domain, or its multiplicity would exceed `p + 1`.
    ///
    /// ```
    /// use neutrospline::ControlPolygon;
    /// let curve = neutrospline::example1().to_bspline();
    /// let more = curve.insert_knot_times(0.5, 3)?;
    /// assert_eq!(more.knots().multiplicity(0.5), 3);
    /// assert_eq!(more.control_points().len(), 7);
    /// # Ok::<(), neutrospline::KnotError>(())
    /// ```
    pub fn insert_knot_times(&self, u: f64, times: usize) -> Result<Self, KnotError> {
        let mut curve = self.clone();
        for _ in 0..times {
            curve = curve.insert_knot(u)?;
        }
        Ok(curve)
    }

    /// Knot refinement: `per_span` knots inserted evenly inside every non-empty span of the
    /// domain (the span `[a, b]` gets `a + k (b - a) / (per_span + 1)`, k = 1..=per_span).
    ///
    /// ```
    /// let curve = neutrospline::example1().to_bspline();
    /// let fine = curve.refine(3);
    /// assert_eq!(fine.knots().interior_breakpoints(), [0.25, 0.5, 0.75]);
    /// ```
    pub fn refine(&self, per_span: usize) -> Self {
        let domain = self.domain();
        let mut breaks = vec![domain.start];
        breaks.extend(self.knots().interior_breakpoints());
        breaks.push(domain.end);
        let mut curve = self.clone();
        for w in breaks.windows(2) {
            for k in 1..=per_span {
                let u = w[0] + (w[1] - w[0]) * k as f64 / (per_span + 1) as f64;
                if u > w[0] && u < w[1] {
                    curve = curve
                        .insert_knot(u)
                        .unwrap_or_else(|e| unreachable!("{u} is new inside a span: {e}"));
                }
            }
        }
        curve
    }

    /// Removes the interior knot `u` up to `times` times while the curve stays within
    /// `tolerance` of this one (Tiller's algorithm, The NURBS Book A5.8, one removal at a
    /// time). Each removal must pass Tiller's test within `tolerance` (the distance of the
    /// two solutions of the new points, over every channel, in homogeneous form for NURBS),
    /// the curve measured by [`SplineCurve::deviation_from`] must stay within `tolerance` of this one, and
    /// every new degree must lie in \[0, 1\]; the first removal that fails stops.
    ///
    /// # Errors
    /// [`KnotError::NotAnInteriorKnot`] when `u` is not a knot strictly inside the domain.
    ///
    /// ```
    /// let curve = neutrospline::example1().to_bspline();
    /// let inserted = curve.insert_knot_times(0.4, 2)?;
    /// let back = inserted.remove_knot(0.4, 5, 1e-12)?;
    /// assert_eq!(back.removed, 2);
    /// assert_eq!(back.curve.knots(), curve.knots());
    /// assert!(back.error < 1e-14);
    /// # Ok::<(), neutrospline::KnotError>(())
    /// ```
    pub fn remove_knot(
        &self,
        u: f64,
        times: usize,
        tolerance: f64,
    ) -> Result<KnotRemoval<Self>, KnotError> {
        check_interior_knot(self.knots(), u)?;
        let build = |spline: &Spline| {
            let mut spline = spline.clone();
            degrees_in_box::<D>(&mut spline).then(|| SplineCurve::from_spline(spline))
        };
        let (_, shape, removed, error) = remove_while(
            self.spline().clone(),
            u,
            times,
            tolerance,
            build,
            |c: &Self| self.deviation_from(c),
        );
        let current = shape.unwrap_or_else(|| self.clone());
        Ok(KnotRemoval {
            curve: current,
            removed,
            error,
        })
    }

    /// The same curve on the domain `[start, end]`: the knots mapped by the affine map of
    /// the domain onto it, so the point at `start + (end - start) (t - a) / (b - a)` of the
    /// result is this curve's point at `t` (domain `[a, b]`).
    ///
    /// # Errors
    /// [`KnotError::BadInterval`] unless `start < end`, both finite (and the mapped knots
    /// finite).
    ///
    /// ```
    /// use neutrospline::Evaluate;
    /// let curve = neutrospline::example1().to_bspline();
    /// let moved = curve.reparametrized(2.0, 4.0)?;
    /// assert_eq!(moved.domain(), 2.0..4.0);
    /// assert_eq!(moved.evaluate(3.0)?.position, curve.evaluate(0.5)?.position);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn reparametrized(&self, start: f64, end: f64) -> Result<Self, KnotError> {
        Ok(SplineCurve::from_spline(
            self.spline().with_domain(start, end)?,
        ))
    }
}

/// The operations on a curve of any kind, with the kind changing where it must: a Bézier
/// curve becomes its clamped B-spline for the operations that need knots (insertion,
/// refinement, a domain other than \[0, 1\]); a knot removal that leaves one span gives a
/// spline still (the kind is the user's to change).
impl Spline {
    /// The same spline on the domain `[start, end]` (the knots mapped by [`mapped_knots`]); a
    /// periodic one stays periodic, its rounded knots rebuilt from its breakpoints.
    ///
    /// # Errors
    /// As [`mapped_knots`].
    pub(crate) fn with_domain(&self, start: f64, end: f64) -> Result<Spline, KnotError> {
        let mapped = Spline {
            knots: mapped_knots(&self.knots, start, end)?,
            ..self.clone()
        };
        Ok(match self.periodic_count() {
            Some(n) => mapped.periodic_again(n),
            None => mapped,
        })
    }
}

impl<const D: usize> crate::AnyCurve<D> {
    /// A spline of this curve: itself, or a Bézier curve as its clamped B-spline.
    fn as_spline(&self) -> crate::AnyCurve<D> {
        match self {
            crate::AnyCurve::Bezier(b) => crate::AnyCurve::BSpline(b.to_bspline()),
            other => other.clone(),
        }
    }

    /// The degree raised by `times` (exact; the kind kept).
    ///
    /// ```
    /// use neutrospline::{AnyCurve, Evaluate};
    /// let curve = AnyCurve::from(neutrospline::example1());
    /// let up = curve.elevated(2);
    /// assert_eq!(up.degree(), 5);
    /// assert!((up.evaluate(0.3)?.position[0] - curve.evaluate(0.3)?.position[0]).abs() < 1e-14);
    /// # Ok::<(), neutrospline::EvalError>(())
    /// ```
    pub fn elevated(&self, times: usize) -> Self {
        use crate::curve::Elevate;
        let mut curve = self.clone();
        for _ in 0..times {
            curve = curve.elevate();
        }
        curve
    }

    /// The knots `knots` inserted, each once (a value given twice is inserted twice); a
    /// Bézier curve becomes a B-spline.
    ///
    /// # Errors
    /// A value outside the domain, or a multiplicity above the degree + 1.
    pub fn with_knots_inserted(&self, knots: &[f64]) -> Result<Self, KnotError> {
        let mut curve = self.as_spline();
        for &u in knots {
            curve = match &curve {
                crate::AnyCurve::BSpline(c) => c.insert_knot(u)?.into(),
                crate::AnyCurve::Nurbs(c) => c.insert_knot(u)?.into(),
                crate::AnyCurve::Bezier(_) => unreachable!("as_spline gives a spline"),
            };
        }
        Ok(curve)
    }

    /// `per_span` knots inserted evenly in every span (a Bézier curve becomes a B-spline).
    pub fn refined(&self, per_span: usize) -> Self {
        match self.as_spline() {
            crate::AnyCurve::BSpline(c) => c.refine(per_span).into(),
            crate::AnyCurve::Nurbs(c) => c.refine(per_span).into(),
            crate::AnyCurve::Bezier(_) => unreachable!("as_spline gives a spline"),
        }
    }

    /// Tiller's removal of the knot `u` ([`SplineCurve::remove_knot`]).
    ///
    /// # Errors
    /// [`KnotError::NotAnInteriorKnot`], also for a Bézier curve, which has none.
    pub fn without_knot(
        &self,
        u: f64,
        times: usize,
        tolerance: f64,
    ) -> Result<KnotRemoval<Self>, KnotError> {
        match self {
            crate::AnyCurve::Bezier(_) => Err(KnotError::NotAnInteriorKnot {
                value: u,
                knots: "none: a Bézier curve has no knots".to_owned(),
            }),
            crate::AnyCurve::BSpline(c) => {
                c.remove_knot(u, times, tolerance).map(|r| KnotRemoval {
                    curve: r.curve.into(),
                    removed: r.removed,
                    error: r.error,
                })
            }
            crate::AnyCurve::Nurbs(c) => c.remove_knot(u, times, tolerance).map(|r| KnotRemoval {
                curve: r.curve.into(),
                removed: r.removed,
                error: r.error,
            }),
        }
    }

    /// The Bézier pieces, one per non-empty span, each on \[0, 1\]: Bézier curves of a
    /// Bézier curve or a B-spline, one-span NURBS curves (rational Bézier curves) of a NURBS
    /// curve; with the parameter interval each piece covers.
    pub fn bezier_pieces(&self) -> Vec<(core::ops::Range<f64>, Self)> {
        match self {
            crate::AnyCurve::Bezier(_) => vec![(0.0..1.0, self.clone())],
            crate::AnyCurve::BSpline(c) => c
                .to_bezier_segments()
                .into_iter()
                .map(|s| (s.start..s.end, s.curve.into()))
                .collect(),
            crate::AnyCurve::Nurbs(c) => c
                .to_bezier_segments()
                .into_iter()
                .map(|s| (s.start..s.end, s.curve.into()))
                .collect(),
        }
    }

    /// The same curve on the domain `[start, end]` (a Bézier curve becomes a B-spline unless
    /// the interval is \[0, 1\]).
    ///
    /// # Errors
    /// [`KnotError::BadInterval`].
    pub fn reparametrized(&self, start: f64, end: f64) -> Result<Self, KnotError> {
        if let crate::AnyCurve::Bezier(_) = self {
            if start == 0.0 && end == 1.0 {
                return Ok(self.clone());
            }
        }
        match self.as_spline() {
            crate::AnyCurve::BSpline(c) => c.reparametrized(start, end).map(Into::into),
            crate::AnyCurve::Nurbs(c) => c.reparametrized(start, end).map(Into::into),
            crate::AnyCurve::Bezier(_) => unreachable!("as_spline gives a spline"),
        }
    }
}

/// Why a degree reduction gave no curve.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ReduceError {
    /// Degree 0 or 1 has no degree below it that keeps the ends.
    #[error("degree {degree} cannot be reduced (the reduced curve keeps both ends, so it needs degree 1 or more)")]
    DegreeTooLow {
        /// The degree.
        degree: usize,
    },
    /// The nearest curve of lower degree is further than the tolerance.
    #[error("no curve of degree {degree} lies within {tolerance:e} of this one: the nearest found deviates by {error:e}")]
    NotWithin {
        /// The degree asked for.
        degree: usize,
        /// The tolerance.
        tolerance: f64,
        /// The deviation of the best reduction found.
        error: f64,
    },
    /// A reduced rational piece would need a weight that is not positive.
    #[error("the reduced NURBS curve would need a weight that is not positive (reduce the weights' spread first)")]
    NonPositiveWeight,
}

/// The result of a degree reduction: the curve and how far it is from the original.
#[derive(Clone, Debug, PartialEq)]
pub struct DegreeReduction<C> {
    /// The curve of lower degree.
    pub curve: C,
    /// The largest deviation from the original found (as [`KnotRemoval::error`]).
    pub error: f64,
}

/// The degrees of every row (channels `first..first + 3`, stride `stride`) projected onto
/// `membership`'s rule: each onto \[0, 1\]; for intuitionistic degrees, truth + falsity above 1
/// brought onto the line T + F = 1 by the nearest point, and the hesitation 1 - T - F derived;
/// for fuzzy degrees, indeterminacy and falsity 0; for any other family, the carried channels
/// onto the rule by its exact projection ([`crate::Family::project`]), the others 0.
pub(crate) fn project_degrees(
    data: &mut [f64],
    stride: usize,
    first: usize,
    membership: crate::Family,
) {
    for row in data.chunks_exact_mut(stride) {
        let d = &mut row[first..first + 3];
        for v in d.iter_mut() {
            *v = if v.is_nan() { 0.0 } else { v.clamp(0.0, 1.0) };
        }
        match membership {
            crate::Family::Neutrosophic => {}
            crate::Family::Fuzzy => {
                d[1] = 0.0;
                d[2] = 0.0;
            }
            crate::Family::Intuitionistic => {
                let excess = d[0] + d[2] - 1.0;
                if excess > 0.0 {
                    d[0] = (d[0] - excess / 2.0).clamp(0.0, 1.0);
                    d[2] = (1.0 - d[0]).clamp(0.0, 1.0);
                }
                d[1] = (1.0 - d[0] - d[2]).max(0.0);
            }
            family => {
                let carried: Vec<usize> = crate::DegreeKind::ALL
                    .into_iter()
                    .filter(|kind| family.carries(*kind))
                    .map(crate::DegreeKind::index)
                    .collect();
                let mut values: Vec<f64> = carried.iter().map(|&c| d[c]).collect();
                family.project(&mut values);
                d.fill(0.0);
                for (&c, v) in carried.iter().zip(values) {
                    d[c] = v;
                }
            }
        }
    }
}

impl<const D: usize, W: Weighting> SplineCurve<D, W> {
    /// The curve of a spline in the form the reduction works in (homogeneous for NURBS).
    fn from_work(work: &Spline, membership: crate::Family) -> Result<Self, ReduceError> {
        let mut spline = if W::RATIONAL {
            let s = work.euclidean();
            if s.weights
                .as_ref()
                .is_some_and(|w| w.iter().any(|&w| !(w > 0.0 && w.is_finite())))
            {
                return Err(ReduceError::NonPositiveWeight);
            }
            s
        } else {
            work.clone()
        };
        let stride = spline.stride;
        project_degrees(&mut spline.data, stride, D, membership);
        Ok(SplineCurve::from_spline(spline))
    }

    /// The degree lowered by one, within `tolerance` of this curve: each Bézier piece
    /// replaced by the nearest (L2) piece of one degree less with the same end points (for
    /// NURBS in homogeneous form), the pieces joined with C0 continuity, the degrees
    /// projected onto `membership`'s rule (so the result is valid under it), then every
    /// interior knot removed as often as the curve stays within `tolerance` (Tiller). The
    /// deviation is measured as [`SplineCurve::deviation_from`].
    ///
    /// # Errors
    /// [`ReduceError::DegreeTooLow`] for degree below 2, [`ReduceError::NotWithin`] with the
    /// deviation found when the reduction is further than `tolerance`,
    /// [`ReduceError::NonPositiveWeight`].
    ///
    /// ```
    /// use neutrospline::{Elevate, Family};
    /// let curve = neutrospline::example1().to_bspline();
    /// let up = curve.elevate();
    /// let back = up.reduce_degree(1e-12, Family::Neutrosophic)?;
    /// assert_eq!(back.curve.degree(), 3);
    /// assert!(back.error < 1e-13);
    /// # Ok::<(), neutrospline::ReduceError>(())
    /// ```
    pub fn reduce_degree(
        &self,
        tolerance: f64,
        membership: crate::Family,
    ) -> Result<DegreeReduction<Self>, ReduceError> {
        let work = if W::RATIONAL {
            self.spline().homogeneous()
        } else {
            self.spline().clone()
        };
        let layout = crate::reduce::DegreeLayout {
            point: work.stride,
            truth: D,
            weight: W::RATIONAL.then_some(D + 3),
            membership,
            second: None,
        };
        reduce_within(
            &work,
            &layout,
            tolerance,
            |w| Self::from_work(w, membership),
            |c: &Self| self.deviation_from(c),
        )
    }
}

impl<const D: usize> crate::AnyCurve<D> {
    /// The degree lowered `times` times within `tolerance` in all
    /// ([`SplineCurve::reduce_degree`] each time, the tolerance for the whole); a Bézier curve
    /// stays a Bézier curve when the result has one span.
    ///
    /// # Errors
    /// As [`SplineCurve::reduce_degree`].
    pub fn reduced(
        &self,
        times: usize,
        tolerance: f64,
        membership: crate::Family,
    ) -> Result<DegreeReduction<Self>, ReduceError> {
        let original = self.as_spline();
        let mut current = original.clone();
        for _ in 0..times {
            current = match &current {
                crate::AnyCurve::BSpline(c) => c.reduce_degree(tolerance, membership)?.curve.into(),
                crate::AnyCurve::Nurbs(c) => c.reduce_degree(tolerance, membership)?.curve.into(),
                crate::AnyCurve::Bezier(_) => unreachable!("as_spline gives a spline"),
            };
        }
        let error = match (&original, &current) {
            (crate::AnyCurve::BSpline(a), crate::AnyCurve::BSpline(b)) => a.deviation_from(b),
            (crate::AnyCurve::Nurbs(a), crate::AnyCurve::Nurbs(b)) => a.deviation_from(b),
            _ => unreachable!("the kind is kept"),
        };
        if error.is_nan() || error > tolerance {
            return Err(ReduceError::NotWithin {
                degree: current.degree(),
                tolerance,
                error,
            });
        }
        if let (crate::AnyCurve::Bezier(_), crate::AnyCurve::BSpline(b)) = (self, &current) {
            if b.knots().interior_breakpoints().is_empty() {
                let bezier = crate::Bezier::new(crate::ControlPolygon::control_points(b))
                    .unwrap_or_else(|e| unreachable!("a valid spline's points: {e}"));
                return Ok(DegreeReduction {
                    curve: bezier.into(),
                    error,
                });
            }
        }
        Ok(DegreeReduction {
            curve: current,
            error,
        })
    }
}

/// The work splines of the two lanes of an interval-valued or bipolar family
/// (`Family::lanes`) stacked into one: every control point of `point` values (a row of a
/// curve, or one point of a line of a surface's net; homogeneous `(w P, w T, w I, w F, w)`
/// for a rational shape) followed by the second lane's three slots of the same point (the
/// columns `truth..truth + 3`, times `w` in homogeneous form). The lanes share positions,
/// weights and knots, so one spline operation on the stack is the operation on both, and a
/// solve of its degree channels sees every channel of the family.
///
/// # Panics
/// If the lanes' splines differ in size.
pub(crate) fn stack_lanes(works: [&Spline; 2], point: usize, truth: usize) -> Spline {
    let [first, second] = works;
    assert!(
        first.data.len() == second.data.len() && first.stride == second.stride,
        "the lanes of a wide family have one geometry"
    );
    let mut data = Vec::with_capacity(first.data.len() / point * (point + 3));
    for (own, other) in first
        .data
        .chunks_exact(point)
        .zip(second.data.chunks_exact(point))
    {
        data.extend_from_slice(own);
        data.extend_from_slice(&other[truth..truth + 3]);
    }
    Spline {
        knots: first.knots.clone(),
        stride: first.stride / point * (point + 3),
        data,
        weights: None,
    }
}

/// The lanes of a stacked work spline ([`stack_lanes`]; points of `point + 3` values) as two
/// work splines of points of `point` values: the first lane's as stacked, the second lane's
/// slots put back into the columns `truth..truth + 3` of a copy of the first's.
pub(crate) fn unstack_lanes(work: &Spline, point: usize, truth: usize) -> [Spline; 2] {
    let mut rows = [Vec::new(), Vec::new()];
    for stacked in work.data.chunks_exact(point + 3) {
        rows[0].extend_from_slice(&stacked[..point]);
        rows[1].extend_from_slice(&stacked[..truth]);
        rows[1].extend_from_slice(&stacked[point..point + 3]);
        rows[1].extend_from_slice(&stacked[truth + 3..point]);
    }
    rows.map(|data| Spline {
        knots: work.knots.clone(),
        stride: work.stride / (point + 3) * point,
        data,
        weights: None,
    })
}

/// The two lanes of curves as one work spline ([`stack_lanes`] of their rows, homogeneous
/// for a rational curve).
///
/// # Panics
/// If the lanes have different numbers of control points.
fn stack_curve_lanes<const D: usize, W: Weighting>(lanes: [&SplineCurve<D, W>; 2]) -> Spline {
    let works = lanes.map(|lane| {
        if W::RATIONAL {
            lane.spline().homogeneous()
        } else {
            lane.spline().clone()
        }
    });
    stack_lanes([&works[0], &works[1]], works[0].stride, D)
}

/// The lanes of a stacked curve work spline ([`stack_curve_lanes`]) as rational or
/// polynomial splines of rows `(P, T, I, F)`; `None` when a rational lane would have a weight
/// that is not positive.
fn unstack_curve_lanes<const D: usize>(work: &Spline, rational: bool) -> Option<[Spline; 2]> {
    let lanes = unstack_lanes(work, work.stride - 3, D);
    if !rational {
        return Some(lanes);
    }
    let lanes = lanes.map(|lane| lane.euclidean());
    let positive = lanes[0]
        .weights
        .as_ref()
        .is_some_and(|w| w.iter().all(|&w| w > 0.0 && w.is_finite()));
    positive.then_some(lanes)
}

/// How [`lanes_under_rule`] treats channels off the family's rule.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(crate) enum OffRule {
    /// Projected onto the rule (`Family::project`; NaN taken as 0): a solve's result.
    Project,
    /// Projected only when within 1e-12 of the rule (rounding); further off refuses.
    Refuse,
}

/// The channels of every control point of two lanes (the degree slots at
/// `truth..truth + 3` of every `point` values of each lane's `data`, joined by the family's
/// lanes: a negated lane negated back) brought under `family`'s rule as `off` says, written
/// back into the slots (a slot without a channel 0, a negated lane negated). `false` when
/// [`OffRule::Refuse`] met a point off the rule by more than rounding.
pub(crate) fn lanes_under_rule(
    data: [&mut [f64]; 2],
    point: usize,
    truth: usize,
    family: crate::Family,
    off: OffRule,
) -> bool {
    let [first, second] = data;
    for (own, other) in first
        .chunks_exact_mut(point)
        .zip(second.chunks_exact_mut(point))
    {
        let mut slots = [own, other];
        let values = slots.each_ref().map(|lane| {
            let s = &lane[truth..truth + 3];
            [s[0], s[1], s[2]]
        });
        let mut values = family.join_slots(&values).to_vec();
        match off {
            OffRule::Project => {
                for v in &mut values {
                    if v.is_nan() {
                        *v = 0.0;
                    }
                }
            }
            OffRule::Refuse => {
                if family.check(&values).is_ok() {
                    continue;
                }
                if family.check_within(&values, ROUNDING).is_err() {
                    return false;
                }
            }
        }
        family.project(&mut values);
        for (lane, spec) in slots.iter_mut().zip(family.lanes()) {
            for (s, channel) in spec.slots.iter().enumerate() {
                let v = channel.map_or(0.0, |c| values[c]);
                lane[truth + s] = if spec.negated && v != 0.0 { -v } else { v };
            }
        }
    }
    true
}

impl<const D: usize, W: Weighting> SplineCurve<D, W> {
    /// The two lanes of a stacked work spline as curves, their channels brought under the
    /// rule as `off` says ([`lanes_under_rule`]); `None` for a weight that is not positive or
    /// a refusal.
    fn lanes_from_work(work: &Spline, family: crate::Family, off: OffRule) -> Option<[Self; 2]> {
        let mut lanes = unstack_curve_lanes::<D>(work, W::RATIONAL)?;
        let point = lanes[0].stride;
        let [a, b] = &mut lanes;
        lanes_under_rule([&mut a.data, &mut b.data], point, D, family, off)
            .then(|| lanes.map(SplineCurve::from_spline))
    }

    /// The larger deviation of the two lanes from `lanes` ([`SplineCurve::deviation_from`]):
    /// the positions' distance and the largest difference of any channel.
    fn lanes_deviation(lanes: [&Self; 2], other: &[Self; 2]) -> f64 {
        lanes[0]
            .deviation_from(&other[0])
            .max(lanes[1].deviation_from(&other[1]))
    }

    /// The degree reduction of [`SplineCurve::reduce_degree`] for the two lanes of an
    /// interval-valued or bipolar family (`Family::lanes`; the lanes have the same positions,
    /// weights and knots): both reduced as one spline, so they keep one geometry, the degree
    /// channels of every reduced piece solved jointly under the family's whole rule
    /// (docs/model.md section 8; `lower <= upper` couples the lanes, so solving each lane
    /// alone could break it), and every interior knot removed while both lanes stay within
    /// `tolerance`.
    ///
    /// # Errors
    /// As [`SplineCurve::reduce_degree`].
    ///
    /// # Panics
    /// If the lanes have different numbers of control points, or `family` has one lane.
    pub fn reduce_degree_lanes(
        lanes: [&Self; 2],
        tolerance: f64,
        family: crate::Family,
    ) -> Result<DegreeReduction<[Self; 2]>, ReduceError> {
        assert_eq!(family.lane_count(), 2, "{family} rides in one lane");
        let work = stack_curve_lanes(lanes);
        let layout = crate::reduce::DegreeLayout {
            point: work.stride,
            truth: D,
            weight: W::RATIONAL.then_some(D + 3),
            membership: family,
            second: Some(D + 3 + usize::from(W::RATIONAL)),
        };
        reduce_within(
            &work,
            &layout,
            tolerance,
            |w| {
                Self::lanes_from_work(w, family, OffRule::Project)
                    .ok_or(ReduceError::NonPositiveWeight)
            },
            |c: &[Self; 2]| Self::lanes_deviation(lanes, c),
        )
    }

    /// Tiller's knot removal ([`SplineCurve::remove_knot`]) on the two lanes of an
    /// interval-valued or bipolar family as one spline: each removal must pass Tiller's test
    /// on every channel of both lanes, keep both within `tolerance`, and give channels that
    /// obey the family's rule (values within 1e-12 of it, rounding, projected onto it).
    ///
    /// # Errors
    /// [`KnotError::NotAnInteriorKnot`] when `u` is not a knot strictly inside the domain.
    ///
    /// # Panics
    /// If the lanes have different numbers of control points, or `family` has one lane.
    pub fn remove_knot_lanes(
        lanes: [&Self; 2],
        u: f64,
        times: usize,
        tolerance: f64,
        family: crate::Family,
    ) -> Result<KnotRemoval<[Self; 2]>, KnotError> {
        assert_eq!(family.lane_count(), 2, "{family} rides in one lane");
        check_interior_knot(lanes[0].knots(), u)?;
        let (_, shape, removed, error) = remove_while(
            stack_curve_lanes(lanes),
            u,
            times,
            tolerance,
            |s| Self::lanes_from_work(s, family, OffRule::Refuse),
            |c: &[Self; 2]| Self::lanes_deviation(lanes, c),
        );
        Ok(KnotRemoval {
            curve: shape.unwrap_or_else(|| [lanes[0].clone(), lanes[1].clone()]),
            removed,
            error,
        })
    }
}

impl<const D: usize> crate::AnyCurve<D> {
    /// [`crate::AnyCurve::reduced`] for the two lanes of an interval-valued or bipolar family
    /// ([`SplineCurve::reduce_degree_lanes`] each time, the tolerance for the whole; a Bézier
    /// curve stays a Bézier curve when the result has one span).
    ///
    /// # Errors
    /// As [`SplineCurve::reduce_degree`]; [`ReduceError::DegreeTooLow`] also when the lanes
    /// are not of one kind.
    ///
    /// # Panics
    /// As [`SplineCurve::reduce_degree_lanes`].
    pub fn reduced_lanes(
        lanes: [&Self; 2],
        times: usize,
        tolerance: f64,
        family: crate::Family,
    ) -> Result<DegreeReduction<[Self; 2]>, ReduceError> {
        use crate::AnyCurve as C;
        let original = lanes.map(Self::as_spline);
        let mut current = original.clone();
        for _ in 0..times {
            current = match &current {
                [C::BSpline(a), C::BSpline(b)] => {
                    SplineCurve::reduce_degree_lanes([a, b], tolerance, family)?
                        .curve
                        .map(Into::into)
                }
                [C::Nurbs(a), C::Nurbs(b)] => {
                    SplineCurve::reduce_degree_lanes([a, b], tolerance, family)?
                        .curve
                        .map(Into::into)
                }
                _ => {
                    return Err(ReduceError::DegreeTooLow {
                        degree: lanes[0].degree(),
                    })
                }
            };
        }
        let deviation = |a: &Self, b: &Self| match (a, b) {
            (C::BSpline(a), C::BSpline(b)) => a.deviation_from(b),
            (C::Nurbs(a), C::Nurbs(b)) => a.deviation_from(b),
            _ => f64::INFINITY,
        };
        let error = deviation(&original[0], &current[0]).max(deviation(&original[1], &current[1]));
        if error.is_nan() || error > tolerance {
            return Err(ReduceError::NotWithin {
                degree: current[0].degree(),
                tolerance,
                error,
            });
        }
        let curve = current.map(|lane| match (lanes[0], &lane) {
            (C::Bezier(_), C::BSpline(b)) if b.knots().interior_breakpoints().is_empty() => {
                crate::Bezier::new(crate::ControlPolygon::control_points(b))
                    .unwrap_or_else(|e| unreachable!("a valid spline's points: {e}"))
                    .into()
            }
            _ => lane,
        });
        Ok(DegreeReduction { curve, error })
    }

    /// [`crate::AnyCurve::without_knot`] for the two lanes of an interval-valued or bipolar
    /// family ([`SplineCurve::remove_knot_lanes`]).
    ///
    /// # Errors
    /// [`KnotError::NotAnInteriorKnot`], also for a Bézier curve, which has none.
    ///
    /// # Panics
    /// As [`SplineCurve::remove_knot_lanes`].
    pub fn without_knot_lanes(
        lanes: [&Self; 2],
        u: f64,
        times: usize,
        tolerance: f64,
        family: crate::Family,
    ) -> Result<KnotRemoval<[Self; 2]>, KnotError> {
        use crate::AnyCurve as C;
        fn removal<T: Into<crate::AnyCurve<D>>, const D: usize>(
            r: KnotRemoval<[T; 2]>,
        ) -> KnotRemoval<[crate::AnyCurve<D>; 2]> {
            KnotRemoval {
                curve: r.curve.map(Into::into),
                removed: r.removed,
                error: r.error,
            }
        }
        match lanes {
            [C::BSpline(a), C::BSpline(b)] => {
                SplineCurve::remove_knot_lanes([a, b], u, times, tolerance, family).map(removal)
            }
            [C::Nurbs(a), C::Nurbs(b)] => {
                SplineCurve::remove_knot_lanes([a, b], u, times, tolerance, family).map(removal)
            }
            _ => Err(KnotError::NotAnInteriorKnot {
                value: u,
                knots: "none: a Bézier curve has no knots".to_owned(),
            }),
        }
    }
}
