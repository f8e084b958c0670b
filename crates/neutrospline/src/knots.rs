//! Knot vectors of B-spline and NURBS curves and surfaces.

/// Why a knot vector is invalid for the given degree and number of control points.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum KnotError {
    /// Too few control points for the degree (a degree-p spline needs at least p + 1).
    #[error("{count} control points are too few for degree {degree} (need at least degree + 1 = {need})", need = degree.saturating_add(1))]
    TooFewControlPoints {
        /// Number of control points.
        count: usize,
        /// Polynomial degree.
        degree: usize,
    },
    /// The knot vector does not have `count + degree + 1` entries.
    #[error(
        "knot vector has {got} knots, expected {expected} (number of control points + degree + 1)"
    )]
    WrongLength {
        /// Number of knots given.
        got: usize,
        /// Number required.
        expected: usize,
    },
    /// A knot is NaN or infinite.
    #[error("knot {index} = {value} is not a finite number")]
    NotFinite {
        /// Index of the knot.
        index: usize,
        /// Its value.
        value: f64,
    },
    /// The knots decrease.
    #[error("knot {index} = {value} is less than knot {prev_index} = {prev} (knots must be non-decreasing)", prev_index = index - 1)]
    Decreasing {
        /// Index of the knot.
        index: usize,
        /// Its value.
        value: f64,
        /// The previous knot's value.
        prev: f64,
    },
    /// A knot value is repeated more than degree + 1 times.
    #[error("knot {value} appears {multiplicity} times, more than degree + 1 = {max}")]
    MultiplicityTooHigh {
        /// The knot value.
        value: f64,
        /// How often it appears.
        multiplicity: usize,
        /// The allowed maximum, degree + 1.
        max: usize,
    },
    /// A knot to insert lies outside the domain (or, for a split, not strictly inside).
    #[error("parameter {value} is outside the domain [{start}, {end}]")]
    OutsideDomain {
        /// The parameter.
        value: f64,
        /// Start of the domain.
        start: f64,
        /// End of the domain.
        end: f64,
    },
    /// A knot to remove is not an interior knot of the curve.
    #[error("{value} is not an interior knot (the interior knots are {knots})")]
    NotAnInteriorKnot {
        /// The value given.
        value: f64,
        /// The distinct interior knots, comma-separated (`none` when there are none).
        knots: String,
    },
    /// A parameter interval to map the domain onto is empty, reversed or not finite.
    #[error("[{start}, {end}] is not a parameter interval (the start must be finite and less than the end)")]
    BadInterval {
        /// The start given.
        start: f64,
        /// The end given.
        end: f64,
    },
    /// A periodic spline's breakpoints are not one more than its distinct control points.
    #[error("a periodic spline of {count} control points takes {expected} breakpoints (the control points + 1, from the start of one period to its end), not {got}", expected = count + 1)]
    BreakpointCount {
        /// Breakpoints given.
        got: usize,
        /// Distinct control points.
        count: usize,
    },
    /// The parameter domain `[knot_p, knot_{m-p}]` is a single point.
    #[error("the domain [knot {p}, knot {end}] = [{start_value}, {start_value}] is empty (the knots there must differ)", end = p_end)]
    EmptyDomain {
        /// Index p of the domain start.
        p: usize,
        /// Index m - p of the domain end.
        p_end: usize,
        /// The common value.
        start_value: f64,
    },
}

/// A non-decreasing knot vector `u_0 <= ... <= u_m` for a spline of degree `p` with
/// `n + 1 = m - p` control points. The curve's domain is `[u_p, u_{m-p}]`.
///
/// ```
/// use neutrospline::KnotVector;
/// let k = KnotVector::clamped_uniform(2, 5)?;
/// assert_eq!(k.knots(), &[0.0, 0.0, 0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0, 1.0, 1.0]);
/// assert_eq!(k.domain(), 0.0..1.0);
/// # Ok::<(), neutrospline::KnotError>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct KnotVector {
    degree: usize,
    knots: Vec<f64>,
}

impl KnotVector {
    /// Checks `knots` for a spline of `degree` with `count` control points: `count >= degree
    /// + 1`, exactly `count + degree + 1` finite non-decreasing knots, no value more than
    /// `degree + 1` times, and a non-empty domain.
    ///
    /// # Errors
    /// The first rule broken, as a [`KnotError`].
    pub fn new(knots: Vec<f64>, degree: usize, count: usize) -> Result<Self, KnotError> {
        if count <= degree {
            return Err(KnotError::TooFewControlPoints { count, degree });
        }
        // count > degree, so count + degree + 1 <= 2 count: no overflow for any real list.
        let expected = count.saturating_add(degree).saturating_add(1);
        if knots.len() != expected {
            return Err(KnotError::WrongLength {
                got: knots.len(),
                expected,
            });
        }
        check_non_decreasing(&knots)?;
        let mut start = 0;
        while start < knots.len() {
            let end = start
                + knots[start..]
                    .iter()
                    .take_while(|&&k| k == knots[start])
                    .count();
            if end - start > degree + 1 {
                return Err(KnotError::MultiplicityTooHigh {
                    value: knots[start],
                    multiplicity: end - start,
                    max: degree + 1,
                });
            }
            start = end;
        }
        let p_end = knots.len() - 1 - degree;
        if knots[degree] >= knots[p_end] {
            return Err(KnotError::EmptyDomain {
                p: degree,
                p_end,
                start_value: knots[degree],
            });
        }
        Ok(KnotVector { degree, knots })
    }

    /// Clamped uniform knots on \[0, 1\]: `degree + 1` zeros, the interior values
    /// `j / (count - degree)`, `degree + 1` ones.
    ///
    /// # Errors
    /// [`KnotError::TooFewControlPoints`] when `count < degree + 1`.
    pub fn clamped_uniform(degree: usize, count: usize) -> Result<Self, KnotError> {
        if count <= degree {
            return Err(KnotError::TooFewControlPoints { count, degree });
        }
        let segments = count - degree;
        let interior = (1..segments).map(|j| j as f64 / segments as f64);
        let knots = core::iter::repeat_n(0.0, degree + 1)
            .chain(interior)
            .chain(core::iter::repeat_n(1.0, degree + 1))
            .collect();
        Ok(KnotVector { degree, knots })
    }

    /// Unclamped uniform knots whose domain is \[0, 1\]: `u_i = (i - p) / (count - p)`,
    /// `i = 0 ..= count + p`, for `count >= degree + 1` control points. The curve does not
    /// pass through its end control points; `knots = "uniform"` in a model file.
    ///
    /// ```
    /// use neutrospline::KnotVector;
    /// let k = KnotVector::uniform(2, 4)?;
    /// assert_eq!(k.knots(), &[-1.0, -0.5, 0.0, 0.5, 1.0, 1.5, 2.0]);
    /// assert_eq!(k.domain(), 0.0..1.0);
    /// # Ok::<(), neutrospline::KnotError>(())
    /// ```
    ///
    /// # Errors
    /// [`KnotError::TooFewControlPoints`] when `count <= degree`.
    pub fn uniform(degree: usize, count: usize) -> Result<Self, KnotError> {
        if count <= degree {
            return Err(KnotError::TooFewControlPoints { count, degree });
        }
        let spans = (count - degree) as f64;
        let knots = (0..=count + degree)
            .map(|i| (i as f64 - degree as f64) / spans)
            .collect();
        KnotVector::new(knots, degree, count)
    }

    /// The knots of a periodic (closed) spline of `degree` over the breakpoints
    /// `tau_0 <= ... <= tau_n` of one period `T = tau_n - tau_0 > 0` (docs/model.md,
    /// "Knot vectors"): the unclamped vector of the `n + p` control points `P_0 .. P_{n-1}`,
    /// `P_0 .. P_{p-1}` that the periodic spline is,
    /// `u_{p+j} = tau_j` for `j = 0 ..= n`, `u_{p+j} = tau_{j-n} + T` above and
    /// `u_{p+j} = tau_{j+n} - T` below. The domain is `[tau_0, tau_n]` and the curve joins
    /// itself there with `C^(p-1)` continuity (less at repeated breakpoints).
    ///
    /// ```
    /// use neutrospline::KnotVector;
    /// let k = KnotVector::periodic(2, &[0.0, 0.25, 0.5, 1.0])?;
    /// assert_eq!(k.knots(), &[-0.75, -0.5, 0.0, 0.25, 0.5, 1.0, 1.25, 1.5]);
    /// assert_eq!(k.control_count(), 5); // 3 distinct control points, then the first 2 again
    /// assert_eq!(k.periodic_breakpoints(), Some(&[0.0, 0.25, 0.5, 1.0][..]));
    /// # Ok::<(), neutrospline::KnotError>(())
    /// ```
    ///
    /// # Errors
    /// [`KnotError::NotFinite`], [`KnotError::Decreasing`] for the breakpoints (indexed among
    /// them), [`KnotError::TooFewControlPoints`] for fewer than two breakpoints,
    /// [`KnotError::EmptyDomain`] when `tau_n = tau_0`, and the checks of [`KnotVector::new`]
    /// on the result (a breakpoint repeated more than `degree + 1` times).
    pub fn periodic(degree: usize, breakpoints: &[f64]) -> Result<Self, KnotError> {
        check_non_decreasing(breakpoints)?;
        let n = breakpoints.len().saturating_sub(1);
        if n == 0 {
            return Err(KnotError::TooFewControlPoints {
                count: n,
                degree: 0,
            });
        }
        let (first, last) = (breakpoints[0], breakpoints[n]);
        if first >= last {
            return Err(KnotError::EmptyDomain {
                p: degree,
                p_end: degree + n,
                start_value: first,
            });
        }
        KnotVector::new(periodic_extension(degree, breakpoints), degree, n + degree)
    }

    /// Periodic knots ([`KnotVector::periodic`]) for the closed control polygon `positions`
    /// (the distinct control points): the breakpoints are spaced like its edges, the closing
    /// one from the last point back to the first included (chord length; with `centripetal`,
    /// like their square roots), on \[0, 1\]. When an edge has length zero the breakpoints are
    /// uniform, as for [`KnotVector::averaged`].
    ///
    /// ```
    /// use neutrospline::KnotVector;
    /// // A unit square: four edges of length 1, so the breakpoints are uniform.
    /// let k = KnotVector::periodic_averaged(2, &[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], false)?;
    /// assert_eq!(k.periodic_breakpoints(), Some(&[0.0, 0.25, 0.5, 0.75, 1.0][..]));
    /// # Ok::<(), neutrospline::KnotError>(())
    /// ```
    ///
    /// # Errors
    /// [`KnotError::TooFewControlPoints`] for no control points.
    pub fn periodic_averaged<const D: usize>(
        degree: usize,
        positions: &[[f64; D]],
        centripetal: bool,
    ) -> Result<Self, KnotError> {
        let n = positions.len();
        if n == 0 {
            return Err(KnotError::TooFewControlPoints { count: 0, degree });
        }
        let uniform: Vec<f64> = (0..=n).map(|j| j as f64 / n as f64).collect();
        let parametrization = if centripetal {
            crate::fit::Parametrization::Centripetal
        } else {
            crate::fit::Parametrization::ChordLength
        };
        match crate::fit::knots::parameters(positions, parametrization, true) {
            Ok(mut breakpoints) if n > 1 => {
                breakpoints.push(1.0);
                KnotVector::periodic(degree, &breakpoints)
                    .or_else(|_| KnotVector::periodic(degree, &uniform))
            }
            _ => KnotVector::periodic(degree, &uniform),
        }
    }

    /// The breakpoints `tau_0 ..= tau_n` (`n = control_count - degree`) when these knots are
    /// exactly (to the last bit) those [`KnotVector::periodic`] makes of them, else `None`.
    /// Degree 0 is never periodic.
    pub fn periodic_breakpoints(&self) -> Option<&[f64]> {
        let p = self.degree;
        if p == 0 {
            return None;
        }
        let n = self.control_count() - p;
        let breakpoints = &self.knots[p..=p + n];
        KnotVector::periodic(p, breakpoints)
            .ok()
            .filter(|k| k.knots == self.knots)
            .map(|_| breakpoints)
    }

    /// Clamped knots on \[0, 1\] from parameters of the control points, by averaging
    /// (de Boor): with parameters `s_0 = 0 <= ... <= s_n = 1`, the interior knots are
    /// `u_{j+p} = (s_j + ... + s_{j+p-1}) / p` for `j = 1 ..= n - p`.
    ///
    /// The parameters follow the control polygon: `s_i - s_{i-1}` proportional to
    /// `|P_i - P_{i-1}|^exponent`, so `exponent = 1` is chord length and `0.5` centripetal
    /// (see [`KnotVector::chord_length`], [`KnotVector::centripetal`]). Coincident points
    /// fall back to uniform spacing: all of them, or enough repeated points that a knot
    /// would appear more than `degree + 1` times (`degree + 1` equal points at an end, for
    /// example); fewer repeated points give repeated knots.
    ///
    /// # Errors
    /// [`KnotError::TooFewControlPoints`]; the result is always a valid clamped vector.
    pub fn averaged<const D: usize>(
        degree: usize,
        positions: &[[f64; D]],
        exponent: f64,
    ) -> Result<Self, KnotError> {
        let count = positions.len();
        if count <= degree {
            return Err(KnotError::TooFewControlPoints { count, degree });
        }
        if degree == 0 {
            return KnotVector::clamped_uniform(0, count);
        }
        let steps: Vec<f64> = positions
            .windows(2)
            .map(|w| {
                let d2: f64 = (0..D).map(|a| (w[1][a] - w[0][a]).powi(2)).sum();
                d2.sqrt().powf(exponent)
            })
            .collect();
        let total: f64 = steps.iter().sum();
        if !(total > 0.0 && total.is_finite()) {
            return KnotVector::clamped_uniform(degree, count);
        }
        let mut params = Vec::with_capacity(count);
        let mut acc = 0.0;
        params.push(0.0);
        for s in &steps[..steps.len() - 1] {
            acc += s;
            params.push((acc / total).min(1.0));
        }
        params.push(1.0);
        // Averages of the same values summed in another order may differ in the last bit:
        // keep the knots non-decreasing (and inside [0, 1]) explicitly.
        let mut previous = 0.0_f64;
        let interior = (1..count - degree).map(|j| {
            let average = params[j..j + degree].iter().sum::<f64>() / degree as f64;
            previous = average.clamp(previous, 1.0);
            previous
        });
        let knots: Vec<f64> = core::iter::repeat_n(0.0, degree + 1)
            .chain(interior)
            .chain(core::iter::repeat_n(1.0, degree + 1))
            .collect();
        // Repeated control points repeat parameters; `degree + 1` equal points at an end (or
        // `2 degree + 1` inside) would repeat a knot more than `degree + 1` times.
        KnotVector::new(knots, degree, count)
            .or_else(|_| KnotVector::clamped_uniform(degree, count))
    }

    /// Chord-length knots: [`KnotVector::averaged`] with exponent 1.
    ///
    /// # Errors
    /// As [`KnotVector::averaged`].
    pub fn chord_length<const D: usize>(
        degree: usize,
        positions: &[[f64; D]],
    ) -> Result<Self, KnotError> {
        KnotVector::averaged(degree, positions, 1.0)
    }

    /// Centripetal knots: [`KnotVector::averaged`] with exponent 1/2.
    ///
    /// # Errors
    /// As [`KnotVector::averaged`].
    pub fn centripetal<const D: usize>(
        degree: usize,
        positions: &[[f64; D]],
    ) -> Result<Self, KnotError> {
        KnotVector::averaged(degree, positions, 0.5)
    }

    /// The knots.
    pub fn knots(&self) -> &[f64] {
        &self.knots
    }

    /// The polynomial degree p these knots are for.
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// Number of control points the knots serve: `len - degree - 1`.
    pub fn control_count(&self) -> usize {
        self.knots.len() - self.degree - 1
    }

    /// The parameter domain `u_p..u_{m-p}` (the curve is defined on the closed interval
    /// `[u_p, u_{m-p}]`).
    pub fn domain(&self) -> core::ops::Range<f64> {
        self.knots[self.degree]..self.knots[self.knots.len() - 1 - self.degree]
    }

    /// Whether the first and last `degree + 1` knots are equal (the curve then interpolates
    /// its end control points).
    pub fn is_clamped(&self) -> bool {
        let p = self.degree;
        let m = self.knots.len() - 1;
        self.knots[..=p].iter().all(|&k| k == self.knots[0])
            && self.knots[m - p..].iter().all(|&k| k == self.knots[m])
    }

    /// How many times `value` appears.
    pub fn multiplicity(&self, value: f64) -> usize {
        self.knots.iter().filter(|&&k| k == value).count()
    }

    /// The knot span of `t` in the domain: the index `k` in `p ..= m - p - 1` with
    /// `u_k <= t < u_{k+1}`, except at the domain end where the last non-empty span is used.
    /// `t` must lie in the domain.
    pub fn span(&self, t: f64) -> usize {
        let p = self.degree;
        let last = self.knots.len() - 2 - p; // m - p - 1
                                             // Largest k in [p, last] with u_k <= t, skipping empty spans at the end.
        let upper = self.knots[p..=last].partition_point(|&k| k <= t) + p;
        let mut k = upper.saturating_sub(1).max(p);
        while k > p && self.knots[k] == self.knots[k + 1] {
            k -= 1;
        }
        k
    }

    /// The distinct knot values strictly inside the domain.
    pub fn interior_breakpoints(&self) -> Vec<f64> {
        let core::ops::Range { start: a, end: b } = self.domain();
        let mut out: Vec<f64> = Vec::new();
        for &k in &self.knots {
            if k > a && k < b && out.last() != Some(&k) {
                out.push(k);
            }
        }
        out
    }

    pub(crate) fn from_parts_unchecked(degree: usize, knots: Vec<f64>) -> Self {
        KnotVector { degree, knots }
    }
}

/// The first value of `values` that is not finite or less than the one before.
fn check_non_decreasing(values: &[f64]) -> Result<(), KnotError> {
    for (index, &value) in values.iter().enumerate() {
        if !value.is_finite() {
            return Err(KnotError::NotFinite { index, value });
        }
        if index > 0 && value < values[index - 1] {
            return Err(KnotError::Decreasing {
                index,
                value,
                prev: values[index - 1],
            });
        }
    }
    Ok(())
}

/// The knots of [`KnotVector::periodic`] without its checks: `breakpoints` has at least two
/// values, the last greater than the first.
pub(crate) fn periodic_extension(degree: usize, breakpoints: &[f64]) -> Vec<f64> {
    let n = breakpoints.len() - 1;
    let period = breakpoints[n] - breakpoints[0];
    (0..=n + 2 * degree)
        .map(|i| {
            let j = i as isize - degree as isize;
            if (0..=n as isize).contains(&j) {
                breakpoints[j as usize]
            } else {
                let shift = j.div_euclid(n as isize);
                breakpoints[j.rem_euclid(n as isize) as usize] + shift as f64 * period
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn knot_vector_validation_messages() {
        assert_eq!(
            KnotVector::new(vec![0.0, 0.0, 1.0, 1.0], 1, 3)
                .unwrap_err()
                .to_string(),
            "knot vector has 4 knots, expected 5 (number of control points + degree + 1)"
        );
        assert_eq!(
            KnotVector::new(vec![0.0, 0.0, 0.7, 0.5, 1.0, 1.0], 1, 4)
                .unwrap_err()
                .to_string(),
            "knot 3 = 0.5 is less than knot 2 = 0.7 (knots must be non-decreasing)"
        );
        assert_eq!(
            KnotVector::new(vec![0.0, 0.0, 0.0, 1.0, 1.0], 1, 3)
                .unwrap_err()
                .to_string(),
            "knot 0 appears 3 times, more than degree + 1 = 2"
        );
        assert!(matches!(
            KnotVector::new(vec![0.0, 1.0, 1.0, 1.0, 1.0], 1, 3),
            Err(KnotError::MultiplicityTooHigh { .. })
        ));
        assert!(matches!(
            KnotVector::new(vec![0.0, 0.0, f64::NAN, 1.0, 1.0], 1, 3),
            Err(KnotError::NotFinite { index: 2, .. })
        ));
        // Absurd degrees are an error, not an arithmetic overflow.
        assert_eq!(
            KnotVector::clamped_uniform(usize::MAX, 3)
                .unwrap_err()
                .to_string(),
            format!(
                "3 control points are too few for degree {} (need at least degree + 1 = {})",
                usize::MAX,
                usize::MAX
            )
        );
        assert!(KnotVector::new(vec![0.0; 4], usize::MAX, 3).is_err());
        assert_eq!(
            KnotVector::new(vec![0.0; 4], 1, 1).unwrap_err().to_string(),
            "1 control points are too few for degree 1 (need at least degree + 1 = 2)"
        );
    }

    #[test]
    fn knot_vector_span() {
        let k = KnotVector::new(vec![0.0, 0.0, 0.0, 0.5, 0.5, 1.0, 1.0, 1.0], 2, 5).unwrap();
        assert_eq!(k.span(0.0), 2);
        assert_eq!(k.span(0.25), 2);
        assert_eq!(k.span(0.5), 4);
        assert_eq!(k.span(0.75), 4);
        assert_eq!(k.span(1.0), 4);
        assert_eq!(k.interior_breakpoints(), vec![0.5]);
        assert!(k.is_clamped());
        // Unclamped: domain [u_2, u_5] = [2, 5].
        let u = KnotVector::new((0..8).map(f64::from).collect(), 2, 5).unwrap();
        assert_eq!(u.domain(), 2.0..5.0);
        assert_eq!(u.span(2.0), 2);
        assert_eq!(u.span(4.999), 4);
        assert_eq!(u.span(5.0), 4);
        assert!(!u.is_clamped());
    }

    #[test]
    fn knot_vector_chord_length() {
        // Control polygon steps 1, 3 (lengths), so parameters 0, 0.25, 1.
        let k = KnotVector::chord_length(1, &[[0.0, 0.0], [1.0, 0.0], [1.0, 3.0]]).unwrap();
        assert_eq!(k.knots(), &[0.0, 0.0, 0.25, 1.0, 1.0]);
        // Centripetal: steps 1, sqrt 3.
        let c = KnotVector::centripetal(1, &[[0.0, 0.0], [1.0, 0.0], [1.0, 3.0]]).unwrap();
        let s = 1.0 / (1.0 + 3f64.sqrt());
        assert!((c.knots()[2] - s).abs() < 1e-15);
        // Quadratic: averages of pairs of parameters (0, 0.25, 1 -> none interior for n=2).
        let q = KnotVector::chord_length(2, &[[0.0], [1.0], [4.0], [5.0]]).unwrap();
        // parameters 0, 0.2, 0.8, 1; interior u_3 = (0.2 + 0.8) / 2 = 0.5.
        assert_eq!(q.knots(), &[0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0]);
        // All points equal: uniform fallback.
        let z = KnotVector::chord_length(1, &[[2.0], [2.0], [2.0]]).unwrap();
        assert_eq!(z.knots(), &[0.0, 0.0, 0.5, 1.0, 1.0]);
        // Regression: the last two points equal made the knot 1 appear three times for
        // degree 1 (MultiplicityTooHigh); now the uniform fallback.
        let e = KnotVector::chord_length(1, &[[0.0], [3.0], [3.0]]).unwrap();
        assert_eq!(e.knots(), &[0.0, 0.0, 0.5, 1.0, 1.0]);
        let c = KnotVector::centripetal(2, &[[1.0], [1.0], [1.0], [4.0], [5.0]]).unwrap();
        assert_eq!(
            c.knots(),
            &[0.0, 0.0, 0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0, 1.0, 1.0]
        );
        // Fewer repeated points keep their (repeated) chord-length knots.
        let r = KnotVector::chord_length(1, &[[0.0], [1.0], [1.0], [4.0]]).unwrap();
        assert_eq!(r.knots(), &[0.0, 0.0, 0.25, 0.25, 1.0, 1.0]);
    }
}
