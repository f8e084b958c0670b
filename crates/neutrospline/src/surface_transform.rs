//! The operations of [`crate::transform`] on surfaces, one direction at a time.
//!
//! A surface in direction u is a spline curve whose control "points" are the rows of its
//! net: row `i` holds every control point `(i, j)`, `j = 0..cols` (direction v: the
//! columns). So each operation is the curve operation on that spline, written once in the
//! spline engine: knot insertion, refinement, removal, splitting, reversal, elevation, a new
//! domain. A NURBS surface goes through its homogeneous form `(w P, w T, w I, w F, w)`;
//! afterwards each point is divided by its weight, and degrees within rounding (1e-12) of
//! \[0, 1\] are clamped onto it.

use crate::curve::EvalError;
use crate::knots::{KnotError, KnotVector};
use crate::spline::Spline;
use crate::surface::{homogeneous_rows, Direction, Surface, SurfaceKind, S};
use crate::transform::{
    check_interior_knot, deviation_samples, point_deviation, reduce_within, remove_while,
    KnotRemoval, DEVIATION_SAMPLES_PER_SPAN,
};
use crate::EvaluateSurface;

/// Values within this of the degree box \[0, 1\] are rounding, clamped onto it.
const ROUNDING: f64 = 1e-12;

impl Surface {
    fn count(&self, direction: Direction) -> usize {
        match direction {
            Direction::U => self.rows,
            Direction::V => self.cols,
        }
    }

    fn knots_of(&self, direction: Direction) -> &KnotVector {
        match direction {
            Direction::U => &self.knots_u,
            Direction::V => &self.knots_v,
        }
    }

    /// The surface as a spline in `direction`: one row per line of the net across it, in
    /// homogeneous form for NURBS.
    fn direction_spline(&self, direction: Direction) -> Spline {
        let (point, values) = match &self.weights {
            Some(w) => (S + 1, homogeneous_rows(&self.data, Some(w))),
            None => (S, self.data.clone()),
        };
        let (n, m) = (self.count(direction), self.count(other(direction)));
        let mut data = Vec::with_capacity(values.len());
        for a in 0..n {
            for b in 0..m {
                let k = match direction {
                    Direction::U => a * self.cols + b,
                    Direction::V => b * self.cols + a,
                };
                data.extend_from_slice(&values[k * point..(k + 1) * point]);
            }
        }
        Spline {
            knots: self.knots_of(direction).clone(),
            stride: m * point,
            data,
            weights: None,
        }
    }

    /// The surface of a spline made by [`Surface::direction_spline`] and an operation on it.
    fn with_direction_spline(&self, direction: Direction, spline: Spline) -> Surface {
        let rational = self.weights.is_some();
        let point = if rational { S + 1 } else { S };
        let m = self.count(other(direction));
        let n = spline.data.len() / (m * point);
        let (rows, cols) = match direction {
            Direction::U => (n, m),
            Direction::V => (m, n),
        };
        let mut data = vec![0.0; rows * cols * S];
        let mut weights = rational.then(|| vec![0.0; rows * cols]);
        for a in 0..n {
            for b in 0..m {
                let k = match direction {
                    Direction::U => a * cols + b,
                    Direction::V => b * cols + a,
                };
                let src = &spline.data[(a * m + b) * point..(a * m + b + 1) * point];
                let w = if rational { src[S] } else { 1.0 };
                for c in 0..S {
                    let mut v = if rational { src[c] / w } else { src[c] };
                    if c >= 3 && (-ROUNDING..=1.0 + ROUNDING).contains(&v) {
                        v = v.clamp(0.0, 1.0);
                    }
                    data[k * S + c] = v;
                }
                if let Some(ws) = weights.as_mut() {
                    ws[k] = w;
                }
            }
        }
        let (knots_u, knots_v) = match direction {
            Direction::U => (spline.knots, self.knots_v.clone()),
            Direction::V => (self.knots_u.clone(), spline.knots),
        };
        let bezier = |k: &KnotVector| {
            let u = k.knots();
            u.len() == 2 * (k.degree() + 1) && u[0] == 0.0 && u[u.len() - 1] == 1.0
        };
        let kind = match (self.kind, rational) {
            (SurfaceKind::Bezier, _) if bezier(&knots_u) && bezier(&knots_v) => SurfaceKind::Bezier,
            (_, true) => SurfaceKind::Nurbs,
            (_, false) => SurfaceKind::BSpline,
        };
        Surface::from_parts(kind, rows, cols, knots_u, knots_v, data, weights)
    }

    /// A Bézier surface's piece mapped back onto \[0, 1\] in `direction` (Bézier surfaces
    /// live on the unit square), other kinds as they are.
    fn unit_if_bezier(&self, direction: Direction, piece: Surface) -> Surface {
        if self.kind != SurfaceKind::Bezier {
            return piece;
        }
        let spline = piece.direction_spline(direction);
        let p = spline.degree();
        let unit = Spline {
            knots: crate::spline::bezier_knots(p),
            ..spline
        };
        let mut out = piece.with_direction_spline(direction, unit);
        out.kind = SurfaceKind::Bezier;
        out
    }

    /// The same surface with knot `u` inserted `times` times in `direction` (a Bézier
    /// surface becomes a B-spline surface).
    ///
    /// # Errors
    /// `u` outside the direction's domain, or its multiplicity would exceed the degree + 1.
    ///
    /// ```
    /// use neutrospline::{ControlPoint, Degrees, Direction, EvaluateSurface, Surface};
    /// let d = Degrees::new(0.7, 0.2, 0.1)?;
    /// let net = (0..9).map(|k| ControlPoint::new([(k / 3) as f64, (k % 3) as f64, (k % 2) as f64], d)).collect();
    /// let s = Surface::bezier(3, 3, net)?;
    /// let t = s.insert_knot(Direction::V, 0.5, 2)?;
    /// assert_eq!(t.cols(), s.cols() + 2);
    /// let (a, b) = (t.evaluate(0.3, 0.7)?, s.evaluate(0.3, 0.7)?);
    /// assert!((a.position[2] - b.position[2]).abs() < 1e-15);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn insert_knot(
        &self,
        direction: Direction,
        u: f64,
        times: usize,
    ) -> Result<Surface, KnotError> {
        let mut spline = self.direction_spline(direction);
        for _ in 0..times {
            spline = spline.insert_knot(u)?;
        }
        Ok(self.with_direction_spline(direction, spline))
    }

    /// Knot refinement in `direction`: `per_span` knots inserted evenly inside every
    /// non-empty span (as [`crate::BSpline::refine`]).
    pub fn refine(&self, direction: Direction, per_span: usize) -> Surface {
        let knots = self.knots_of(direction);
        let domain = knots.domain();
        let mut breaks = vec![domain.start];
        breaks.extend(knots.interior_breakpoints());
        breaks.push(domain.end);
        let mut spline = self.direction_spline(direction);
        for w in breaks.windows(2) {
            for k in 1..=per_span {
                let u = w[0] + (w[1] - w[0]) * k as f64 / (per_span + 1) as f64;
                if u > w[0] && u < w[1] {
                    spline = spline
                        .insert_knot(u)
                        .unwrap_or_else(|e| unreachable!("{u} is new inside a span: {e}"));
                }
            }
        }
        self.with_direction_spline(direction, spline)
    }

    /// Degree elevation by one in `direction`: the same surface.
    pub fn elevate(&self, direction: Direction) -> Surface {
        let spline = self.direction_spline(direction).elevate(0..0);
        self.with_direction_spline(direction, spline)
    }

    /// The pieces on `[a, t]` and `[t, b]` of `direction`'s domain `[a, b]`, keeping the
    /// parameters (a Bézier surface's pieces are Bézier surfaces on \[0, 1\]).
    ///
    /// # Errors
    /// `t` not strictly inside the domain.
    pub fn split(&self, direction: Direction, t: f64) -> Result<(Surface, Surface), EvalError> {
        let domain = self.knots_of(direction).domain();
        if !(t > domain.start && t < domain.end) {
            return Err(EvalError::ParameterOutOfDomain {
                t,
                start: domain.start,
                end: domain.end,
            });
        }
        let (left, right) = self.direction_spline(direction).split(t);
        Ok((
            self.unit_if_bezier(direction, self.with_direction_spline(direction, left)),
            self.unit_if_bezier(direction, self.with_direction_spline(direction, right)),
        ))
    }

    /// The piece on `[t0, t1]` of `direction` (reversed when `t0 > t1`).
    ///
    /// # Errors
    /// A parameter outside the domain, or `t0 == t1`.
    pub fn subsegment(&self, direction: Direction, t0: f64, t1: f64) -> Result<Surface, EvalError> {
        let domain = self.knots_of(direction).domain();
        for t in [t0, t1] {
            if !(t >= domain.start && t <= domain.end) {
                return Err(EvalError::ParameterOutOfDomain {
                    t,
                    start: domain.start,
                    end: domain.end,
                });
            }
        }
        if t0 == t1 {
            return Err(EvalError::EmptyPiece { start: t0, end: t1 });
        }
        let spline = self
            .direction_spline(direction)
            .restricted(t0.min(t1), t0.max(t1));
        let piece = self.unit_if_bezier(direction, self.with_direction_spline(direction, spline));
        Ok(if t0 > t1 {
            piece.reversed(direction)
        } else {
            piece
        })
    }

    /// The same surface with `direction` traversed backwards on the same domain.
    pub fn reversed(&self, direction: Direction) -> Surface {
        let spline = self.direction_spline(direction).reversed();
        self.with_direction_spline(direction, spline)
    }

    /// The same surface with `direction`'s domain mapped onto `[start, end]` (a Bézier
    /// surface becomes a B-spline surface unless the interval is \[0, 1\]).
    ///
    /// # Errors
    /// [`KnotError::BadInterval`] unless `start < end`, both finite.
    pub fn reparametrized(
        &self,
        direction: Direction,
        start: f64,
        end: f64,
    ) -> Result<Surface, KnotError> {
        let spline = self.direction_spline(direction).with_domain(start, end)?;
        Ok(self.with_direction_spline(direction, spline))
    }

    /// Removes the interior knot `u` of `direction` up to `times` times while the surface
    /// stays within `tolerance` (Tiller's test on the lines of the net, in homogeneous form
    /// for NURBS, and the deviation measured by [`Surface::deviation_from`]); new degrees
    /// must stay in \[0, 1\].
    ///
    /// # Errors
    /// [`KnotError::NotAnInteriorKnot`] when `u` is not a knot strictly inside the domain.
    pub fn remove_knot(
        &self,
        direction: Direction,
        u: f64,
        times: usize,
        tolerance: f64,
    ) -> Result<KnotRemoval<Surface>, KnotError> {
        check_interior_knot(self.knots_of(direction), u)?;
        let build = |spline: &Spline| {
            let candidate = self.with_direction_spline(direction, spline.clone());
            let in_box = candidate
                .data
                .chunks_exact(S)
                .all(|row| row[3..].iter().all(|v| (0.0..=1.0).contains(v)));
            in_box.then_some(candidate)
        };
        let (_, shape, removed, error) = remove_while(
            self.direction_spline(direction),
            u,
            times,
            tolerance,
            build,
            |c: &Surface| self.deviation_from(c),
        );
        let current = shape.unwrap_or_else(|| self.clone());
        Ok(KnotRemoval {
            curve: current,
            removed,
            error,
        })
    }

    /// The Bézier patches of the surface: split at every interior knot of both directions,
    /// in row-major order of the patches (u first); each patch keeps its parameters.
    pub fn to_bezier_patches(&self) -> Vec<Surface> {
        let mut strips = vec![self.clone()];
        for direction in [Direction::U, Direction::V] {
            let mut next = Vec::new();
            for strip in strips {
                let mut rest = strip;
                for b in self.knots_of(direction).interior_breakpoints() {
                    match rest.split(direction, b) {
                        Ok((left, right)) => {
                            next.push(left);
                            rest = right;
                        }
                        Err(e) => unreachable!("{b} is an interior knot: {e}"),
                    }
                }
                next.push(rest);
            }
            strips = next;
        }
        strips
    }

    /// The largest distance between this surface and `other` on this surface's domain,
    /// sampled on the grid of every distinct knot of either and
    /// [`DEVIATION_SAMPLES_PER_SPAN`] / 4 evenly spaced parameters per span each way: the
    /// larger of the Euclidean distance of the positions and the largest difference of a
    /// degree.
    pub fn deviation_from(&self, other: &Surface) -> f64 {
        let per = DEVIATION_SAMPLES_PER_SPAN / 4;
        let us = deviation_samples(&self.knots_u, &other.knots_u, per);
        let vs = deviation_samples(&self.knots_v, &other.knots_v, per);
        let mut worst: f64 = 0.0;
        for &u in &us {
            for &v in &vs {
                worst = worst.max(match (self.evaluate(u, v), other.evaluate(u, v)) {
                    (Ok(p), Ok(q)) => point_deviation(&p, &q),
                    _ => f64::INFINITY,
                });
            }
        }
        worst
    }
}

fn other(direction: Direction) -> Direction {
    match direction {
        Direction::U => Direction::V,
        Direction::V => Direction::U,
    }
}

impl Surface {
    /// The degree in `direction` lowered by one within `tolerance` of this surface (the curve
    /// reduction, [`crate::BSpline::reduce_degree`], on the lines of the net; the degrees
    /// projected onto `membership`'s rule; then interior knots of that direction removed as
    /// the tolerance allows).
    ///
    /// # Errors
    /// As [`crate::BSpline::reduce_degree`].
    pub fn reduce_degree(
        &self,
        direction: Direction,
        tolerance: f64,
        membership: crate::Family,
    ) -> Result<crate::DegreeReduction<Surface>, crate::ReduceError> {
        let build = |work: &Spline| -> Result<Surface, crate::ReduceError> {
            let mut s = self.with_direction_spline(direction, work.clone());
            if s.weights
                .as_ref()
                .is_some_and(|w| w.iter().any(|&w| !(w > 0.0 && w.is_finite())))
            {
                return Err(crate::ReduceError::NonPositiveWeight);
            }
            crate::transform::project_degrees(&mut s.data, S, 3, membership);
            s.homogeneous = homogeneous_rows(&s.data, s.weights.as_deref());
            Ok(s)
        };
        let layout = crate::reduce::DegreeLayout {
            point: if self.weights.is_some() { S + 1 } else { S },
            truth: 3,
            weight: self.weights.is_some().then_some(S),
            membership,
            second: None,
        };
        reduce_within(
            &self.direction_spline(direction),
            &layout,
            tolerance,
            build,
            |c: &Surface| self.deviation_from(c),
        )
    }
}

/// Degree reduction and knot removal for the two lanes of an interval-valued or bipolar
/// family (`Family::lanes`; docs/model.md, "Lanes"): two surfaces of one geometry (positions,
/// weights, knots), each holding three of the family's channels. In a direction, each lane is
/// the spline of its lines (`Surface::direction_spline`) and the two are stacked point by
/// point (`transform::stack_lanes`, the same stacking as the curves'), so every line
/// of the net is a curve of two lanes, and one spline operation on the stack is the curve
/// operation on every line of both lanes at once: a knot is removed only when Tiller's test
/// passes on every line and channel, and the reduced degree channels of every line are solved
/// jointly under the family's whole rule (`lower <= upper` couples the lanes).
impl Surface {
    /// The stacked work spline of two lanes in `direction`, and the values per point of one
    /// lane (`S`, or `S + 1` in homogeneous form).
    ///
    /// # Panics
    /// If the lanes differ in grid size or rationality.
    fn stack_direction_lanes(lanes: [&Surface; 2], direction: Direction) -> (Spline, usize) {
        assert!(
            lanes[0].rows == lanes[1].rows
                && lanes[0].cols == lanes[1].cols
                && lanes[0].weights.is_some() == lanes[1].weights.is_some(),
            "the lanes of a wide family have one geometry"
        );
        let works = lanes.map(|lane| lane.direction_spline(direction));
        let point = if lanes[0].weights.is_some() { S + 1 } else { S };
        (
            crate::transform::stack_lanes([&works[0], &works[1]], point, 3),
            point,
        )
    }

    /// The two lane surfaces of a stacked work spline in `direction`, their channels brought
    /// under `family`'s rule as `off` says ([`crate::transform::lanes_under_rule`]); `None`
    /// for a weight that is not positive or a refusal.
    fn lanes_from_work(
        lanes: [&Surface; 2],
        direction: Direction,
        work: &Spline,
        family: crate::Family,
        off: crate::transform::OffRule,
    ) -> Option<[Surface; 2]> {
        let point = if lanes[0].weights.is_some() { S + 1 } else { S };
        let [first, second] = crate::transform::unstack_lanes(work, point, 3);
        let mut out = [
            lanes[0].with_direction_spline(direction, first),
            lanes[1].with_direction_spline(direction, second),
        ];
        if out[0]
            .weights
            .as_ref()
            .is_some_and(|w| w.iter().any(|&w| !(w > 0.0 && w.is_finite())))
        {
            return None;
        }
        let [a, b] = &mut out;
        if !crate::transform::lanes_under_rule([&mut a.data, &mut b.data], S, 3, family, off) {
            return None;
        }
        for s in &mut out {
            s.homogeneous = homogeneous_rows(&s.data, s.weights.as_deref());
        }
        Some(out)
    }

    /// The larger deviation of the two lanes from `other` ([`Surface::deviation_from`]): the
    /// positions' distance and the largest difference of any channel, over the sample grid.
    fn lanes_deviation(lanes: [&Surface; 2], other: &[Surface; 2]) -> f64 {
        lanes[0]
            .deviation_from(&other[0])
            .max(lanes[1].deviation_from(&other[1]))
    }

    /// [`Surface::reduce_degree`] for the two lanes of an interval-valued or bipolar family:
    /// the degree in `direction` lowered by one on every line of both lanes' nets (each line a
    /// curve of two lanes, [`crate::BSpline::reduce_degree_lanes`]: every Bézier piece
    /// replaced by the nearest (L2) piece of one degree less with the same ends, the channels
    /// solved jointly under the family's rule), then interior knots of that direction removed
    /// while both lanes stay within `tolerance`. The deviation is the larger of the lanes'
    /// ([`Surface::deviation_from`]).
    ///
    /// # Errors
    /// As [`Surface::reduce_degree`].
    ///
    /// # Panics
    /// If the lanes differ in grid size or rationality, or `family` has one lane.
    pub fn reduce_degree_lanes(
        lanes: [&Surface; 2],
        direction: Direction,
        tolerance: f64,
        family: crate::Family,
    ) -> Result<crate::DegreeReduction<[Surface; 2]>, crate::ReduceError> {
        assert_eq!(family.lane_count(), 2, "{family} rides in one lane");
        let (work, point) = Self::stack_direction_lanes(lanes, direction);
        let rational = lanes[0].weights.is_some();
        let layout = crate::reduce::DegreeLayout {
            point: point + 3,
            truth: 3,
            weight: rational.then_some(S),
            membership: family,
            second: Some(point),
        };
        reduce_within(
            &work,
            &layout,
            tolerance,
            |w| {
                Self::lanes_from_work(
                    lanes,
                    direction,
                    w,
                    family,
                    crate::transform::OffRule::Project,
                )
                .ok_or(crate::ReduceError::NonPositiveWeight)
            },
            |c: &[Surface; 2]| Self::lanes_deviation(lanes, c),
        )
    }

    /// The degree in `direction` lowered `times` times within `tolerance` in all
    /// ([`Surface::reduce_degree_lanes`] each time; the deviation of the result from these
    /// lanes measured again at the end).
    ///
    /// # Errors
    /// As [`Surface::reduce_degree`]; [`crate::ReduceError::NotWithin`] when the reductions
    /// together move a lane further than `tolerance`.
    ///
    /// # Panics
    /// As [`Surface::reduce_degree_lanes`].
    ///
    /// ```
    /// use neutrospline::{ControlPoint, Degrees, Direction, Family, Surface};
    /// let net = |lower: f64| -> Vec<ControlPoint<3>> {
    ///     (0..6)
    ///         .map(|k| {
    ///             let d = Degrees::new(lower + 0.1 * (k % 3) as f64, 0.0, 0.0).unwrap();
    ///             ControlPoint::new([(k / 3) as f64, (k % 3) as f64, 0.0], d)
    ///         })
    ///         .collect()
    /// };
    /// // Truth lower and upper (interval-type2) on a 2 x 3 Bézier net, elevated in v.
    /// let lower = Surface::bezier(2, 3, net(0.1))?.elevate(Direction::V);
    /// let upper = Surface::bezier(2, 3, net(0.3))?.elevate(Direction::V);
    /// let back =
    ///     Surface::reduced_lanes([&lower, &upper], Direction::V, 1, 1e-12, Family::IntervalType2)?;
    /// assert_eq!(back.curve[0].degree_v(), 2);
    /// assert!(back.error < 1e-14);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn reduced_lanes(
        lanes: [&Surface; 2],
        direction: Direction,
        times: usize,
        tolerance: f64,
        family: crate::Family,
    ) -> Result<crate::DegreeReduction<[Surface; 2]>, crate::ReduceError> {
        let mut current = [lanes[0].clone(), lanes[1].clone()];
        for _ in 0..times {
            current = Self::reduce_degree_lanes(
                [&current[0], &current[1]],
                direction,
                tolerance,
                family,
            )?
            .curve;
        }
        let error = Self::lanes_deviation(lanes, &current);
        if error.is_nan() || error > tolerance {
            return Err(crate::ReduceError::NotWithin {
                degree: current[0].knots_of(direction).degree(),
                tolerance,
                error,
            });
        }
        Ok(crate::DegreeReduction {
            curve: current,
            error,
        })
    }

    /// [`Surface::remove_knot`] for the two lanes of an interval-valued or bipolar family:
    /// the interior knot `u` of `direction` removed up to `times` times from both lanes at
    /// once; each removal must pass Tiller's test on every line of both nets and every
    /// channel, keep both lanes within `tolerance` ([`Surface::deviation_from`], the larger
    /// of the two reported), and give channels that obey the family's rule at every control
    /// point (values within 1e-12 of it, rounding, projected onto it).
    ///
    /// # Errors
    /// [`KnotError::NotAnInteriorKnot`] when `u` is not a knot strictly inside the domain.
    ///
    /// # Panics
    /// As [`Surface::reduce_degree_lanes`].
    pub fn remove_knot_lanes(
        lanes: [&Surface; 2],
        direction: Direction,
        u: f64,
        times: usize,
        tolerance: f64,
        family: crate::Family,
    ) -> Result<KnotRemoval<[Surface; 2]>, KnotError> {
        assert_eq!(family.lane_count(), 2, "{family} rides in one lane");
        check_interior_knot(lanes[0].knots_of(direction), u)?;
        let (work, _) = Self::stack_direction_lanes(lanes, direction);
        let (_, shape, removed, error) = remove_while(
            work,
            u,
            times,
            tolerance,
            |s| {
                Self::lanes_from_work(
                    lanes,
                    direction,
                    s,
                    family,
                    crate::transform::OffRule::Refuse,
                )
            },
            |c: &[Surface; 2]| Self::lanes_deviation(lanes, c),
        );
        Ok(KnotRemoval {
            curve: shape.unwrap_or_else(|| [lanes[0].clone(), lanes[1].clone()]),
            removed,
            error,
        })
    }
}
