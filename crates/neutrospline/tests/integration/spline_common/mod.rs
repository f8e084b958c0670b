//! Shared checks of the spline property tests (`bspline_properties.rs`,
//! `nurbs_properties.rs`): the invariants of docs/model.md section 4 (which carry over to every kind,
//! `docs/model.md`) and the CAGD operations, written once for both spline kinds, and the
//! `curve_properties!` macro that runs them for one kind and dimension.
//!
//! Tolerances are rounding allowances: `u = f64::EPSILON`, `M` the largest |control
//! coordinate| (at least 1), `p` the degree. Degree bounds are checked exactly (every step
//! of the evaluation is a convex combination projected onto its segment).
#![allow(dead_code, unused_imports, unused_macros)]

pub use neutrospline::strategies::{
    self, bspline, control_point, coordinate, degrees, domain_parameter, knot_vector, nurbs, weight,
};
pub use neutrospline::{
    Affine, AnyCurve, BSpline, Bezier, Bounded, ControlPoint, ControlPolygon, CurveError,
    CurveKind, CurvePoint, DegreeKind, Degrees, Derivative, DerivativeValue, Direction, Elevate,
    EvalError, Evaluate, EvaluateSurface, KnotError, KnotVector, Nurbs, Split, Surface,
    SurfaceError, SurfaceKind,
};
pub use proptest::prelude::*;

mod checks;

// ------------------------------------------------------------------------ the curve kinds

/// What the generic checks need from a spline curve kind.
pub trait TestSpline<const D: usize>:
    Clone
    + std::fmt::Debug
    + Evaluate<Point = CurvePoint<D>>
    + Derivative<Output = neutrospline::CurveDerivative<D>>
    + Split
    + Bounded<D>
    + Into<AnyCurve<D>>
{
    fn knot_vector(&self) -> &KnotVector;
    fn points(&self) -> Vec<ControlPoint<D>>;
    /// The weights (1 for B-splines).
    fn weight_list(&self) -> Vec<f64>;
    /// The same kind, knots and weights with other control points.
    fn rebuild(&self, points: Vec<ControlPoint<D>>) -> Self;
    fn insert(&self, u: f64) -> Result<Self, KnotError>;
    fn elevated(&self) -> Self;
    fn derivative_value(&self, t: f64) -> DerivativeValue<D>;
    /// The Bézier pieces: start, end and the piece on \[0, 1\].
    fn pieces(&self) -> Vec<(f64, f64, AnyCurve<D>)>;
    fn mapped(&self, map: &Affine<D>) -> Self;
}

impl<const D: usize> TestSpline<D> for BSpline<D> {
    fn knot_vector(&self) -> &KnotVector {
        self.knots()
    }
    fn points(&self) -> Vec<ControlPoint<D>> {
        self.control_points()
    }
    fn weight_list(&self) -> Vec<f64> {
        vec![1.0; self.len()]
    }
    fn rebuild(&self, points: Vec<ControlPoint<D>>) -> Self {
        BSpline::new(points, self.knots().clone()).unwrap()
    }
    fn insert(&self, u: f64) -> Result<Self, KnotError> {
        self.insert_knot(u)
    }
    fn elevated(&self) -> Self {
        self.elevate()
    }
    fn derivative_value(&self, t: f64) -> DerivativeValue<D> {
        self.derivative().evaluate(t).unwrap()
    }
    fn pieces(&self) -> Vec<(f64, f64, AnyCurve<D>)> {
        self.to_bezier_segments()
            .into_iter()
            .map(|s| (s.start, s.end, AnyCurve::Bezier(s.curve)))
            .collect()
    }
    fn mapped(&self, map: &Affine<D>) -> Self {
        self.transform(map).unwrap()
    }
}

impl<const D: usize> TestSpline<D> for Nurbs<D> {
    fn knot_vector(&self) -> &KnotVector {
        self.knots()
    }
    fn points(&self) -> Vec<ControlPoint<D>> {
        self.control_points()
    }
    fn weight_list(&self) -> Vec<f64> {
        self.weights().unwrap().to_vec()
    }
    fn rebuild(&self, points: Vec<ControlPoint<D>>) -> Self {
        Nurbs::new(
            points,
            self.weights().unwrap().to_vec(),
            self.knots().clone(),
        )
        .unwrap()
    }
    fn insert(&self, u: f64) -> Result<Self, KnotError> {
        self.insert_knot(u)
    }
    fn elevated(&self) -> Self {
        self.elevate()
    }
    fn derivative_value(&self, t: f64) -> DerivativeValue<D> {
        self.derivative().evaluate(t).unwrap()
    }
    fn pieces(&self) -> Vec<(f64, f64, AnyCurve<D>)> {
        self.to_bezier_segments()
            .into_iter()
            .map(|s| (s.start, s.end, AnyCurve::Nurbs(s.curve)))
            .collect()
    }
    fn mapped(&self, map: &Affine<D>) -> Self {
        self.transform(map).unwrap()
    }
}

// ------------------------------------------------------------------------ helpers

pub const EPS: f64 = f64::EPSILON;

pub fn degree<const D: usize, C: TestSpline<D>>(c: &C) -> usize {
    c.knot_vector().degree()
}

/// Largest |control coordinate|, at least 1.
pub fn scale<const D: usize>(points: &[ControlPoint<D>]) -> f64 {
    points
        .iter()
        .flat_map(|p| p.position)
        .fold(1.0_f64, |m, v| m.max(v.abs()))
}

/// `w_max / w_min`.
pub fn weight_ratio(w: &[f64]) -> f64 {
    let hi = w.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let lo = w.iter().copied().fold(f64::INFINITY, f64::min);
    hi / lo
}

/// All channels of a point: coordinates, then truth, indeterminacy, falsity.
pub fn channels<const D: usize>(p: &CurvePoint<D>) -> Vec<f64> {
    p.position
        .iter()
        .copied()
        .chain(p.degrees.to_array())
        .collect()
}

pub fn derivative_channels<const D: usize>(d: &DerivativeValue<D>) -> Vec<f64> {
    d.position
        .iter()
        .copied()
        .chain([d.truth, d.indeterminacy, d.falsity])
        .collect()
}

/// Asserts two points agree within `factor (p + 1) u` times `M` (positions) or 1 (degrees).
pub fn assert_close<const D: usize>(
    what: &str,
    got: &CurvePoint<D>,
    want: &CurvePoint<D>,
    p: usize,
    m: f64,
    factor: f64,
) -> Result<(), TestCaseError> {
    let base = factor * (p as f64 + 1.0) * EPS;
    for (c, (g, w)) in channels(got).iter().zip(channels(want)).enumerate() {
        let tol = if c < D { base * m } else { base };
        prop_assert!(
            (g - w).abs() <= tol,
            "{what}: channel {c}: {g:e} vs {w:e}, error {:e} > {tol:e}",
            (g - w).abs()
        );
    }
    Ok(())
}

/// Indices of the control points that act on the span used at `t`.
pub fn active(knots: &KnotVector, t: f64) -> core::ops::RangeInclusive<usize> {
    let k = knots.span(t);
    k - knots.degree()..=k
}

/// The non-empty knot spans of the domain, as (start, end).
pub fn spans(knots: &KnotVector) -> Vec<(f64, f64)> {
    let (a, b) = (knots.domain().start, knots.domain().end);
    let u = knots.knots();
    u.windows(2)
        .map(|w| (w[0], w[1]))
        .filter(|&(x, y)| x < y && a <= x && y <= b)
        .collect()
}

/// A curve with a parameter of its domain (ends, knots, beside knots, uniform).
pub fn with_parameter<C: std::fmt::Debug + Clone>(
    curves: impl Strategy<Value = C>,
    knots: fn(&C) -> KnotVector,
) -> impl Strategy<Value = (C, f64)> {
    curves.prop_flat_map(move |c| {
        let k = knots(&c);
        (Just(c), domain_parameter(&k))
    })
}

/// A curve with `n` parameters of its domain.
pub fn with_parameters<C: std::fmt::Debug + Clone>(
    curves: impl Strategy<Value = C>,
    knots: fn(&C) -> KnotVector,
    n: core::ops::Range<usize>,
) -> impl Strategy<Value = (C, Vec<f64>)> {
    curves.prop_flat_map(move |c| {
        let k = knots(&c);
        (
            Just(c),
            prop::collection::vec(domain_parameter(&k), n.clone()),
        )
    })
}

pub use checks::*;

/// `p + 1` equal knots at `a`, then at `b`: one Bézier span on `[a, b]`.
pub fn bezier_knots(p: usize, a: f64, b: f64) -> KnotVector {
    let knots = core::iter::repeat_n(a, p + 1)
        .chain(core::iter::repeat_n(b, p + 1))
        .collect();
    KnotVector::new(knots, p, p + 1).unwrap()
}

// ------------------------------------------------------------------------ per kind

macro_rules! curve_properties {
    ($module:ident, $ty:ty, $dim:literal, $strategy:expr, $knots:expr, $kind:expr) => {
        mod $module {
            use super::*;

            fn curves() -> impl Strategy<Value = $ty> {
                $strategy
            }

            proptest! {
                #![proptest_config(ProptestConfig::with_cases(96))]

                #[test]
                fn degrees_stay_in_local_control_range((c, t) in with_parameter(curves(), $knots)) {
                    check_degree_bounds(&c, t)?;
                }

                #[test]
                fn basis_is_a_partition_of_unity((c, t) in with_parameter(curves(), $knots)) {
                    check_partition_of_unity(&c, t)?;
                }

                #[test]
                fn clamped_curves_interpolate_their_ends(c in curves()) {
                    check_endpoints(&c)?;
                }

                #[test]
                fn curve_lies_in_local_convex_hull(
                    (c, t) in with_parameter(curves(), $knots),
                    u in directions($dim + 3),
                ) {
                    check_convex_hull(&c, t, &u)?;
                }

                #[test]
                fn knot_insertion_leaves_the_curve_unchanged(
                    (c, ts) in with_parameters(curves(), $knots, 2..6),
                ) {
                    // ts[0] is the knot (ends, existing knots, beside knots, anywhere).
                    check_insertion(&c, ts[0], &ts[1..])?;
                }

                #[test]
                fn knot_insertion_at_the_domain_ends(
                    (c, ts) in with_parameters(curves(), $knots, 1..5),
                ) {
                    let (a, b) = (c.domain().start, c.domain().end);
                    check_insertion(&c, a, &ts)?;
                    check_insertion(&c, b, &ts)?;
                    // Outside the domain: an error naming it.
                    let outside = b + 1.0;
                    prop_assert_eq!(
                        c.insert(outside).unwrap_err(),
                        KnotError::OutsideDomain { value: outside, start: a, end: b }
                    );
                }

                #[test]
                fn split_and_subsegment_reproduce_the_curve(
                    (c, ts) in with_parameters(curves(), $knots, 2..6),
                ) {
                    check_split(&c, ts[0], &ts[1..])?;
                }

                #[test]
                fn elevation_leaves_the_curve_unchanged(
                    (c, ts) in with_parameters(curves(), $knots, 1..6),
                ) {
                    check_elevation(&c, &ts)?;
                }

                #[test]
                fn bezier_pieces_reproduce_the_curve(
                    (c, ts) in with_parameters(curves(), $knots, 1..8),
                ) {
                    check_pieces(&c, &ts)?;
                }

                #[test]
                fn derivative_matches_finite_differences(
                    c in curves(),
                    span in any::<prop::sample::Index>(),
                    fraction in 0.2..=0.8f64,
                ) {
                    check_derivative(&c, span, fraction)?;
                }

                #[test]
                fn bounding_box_contains_samples(
                    (c, ts) in with_parameters(curves(), $knots, 1..12),
                ) {
                    check_bounding_box(&c, &ts)?;
                }

                #[test]
                fn bounding_box_is_tight(c in curves()) {
                    check_bounding_box_is_tight(&c)?;
                }

                #[test]
                fn affine_maps_commute(
                    (c, t) in with_parameter(curves(), $knots),
                    linear in prop::array::uniform::<_, $dim>(prop::array::uniform::<_, $dim>(-3.0..=3.0f64)),
                    shift in prop::array::uniform::<_, $dim>(-100.0..=100.0f64),
                ) {
                    check_affine(&c, t, linear, shift)?;
                }

                #[test]
                fn any_curve_forwards_consistently(
                    (c, ts) in with_parameters(curves(), $knots, 1..6),
                ) {
                    check_any_curve(&c, &ts, $kind)?;
                }
            }
        }
    };
}
