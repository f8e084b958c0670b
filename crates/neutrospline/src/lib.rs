//! # neutrospline
//!
//! Neutrosophic curve and surface modeling: Bézier, B-spline and NURBS curves (2-D and 3-D)
//! and tensor-product surfaces whose control points carry three uncertainty degrees,
//! **truth**, **indeterminacy** and **falsity**, each in \[0, 1\].
//!
//! The model (Mahmud, Wahab, Zulkifly and Broumi, "A Neutrosophic Bézier Curve Model using
//! Control Points", extended to the kinds the paper names as its next steps) blends every
//! degree with the same basis as the positions. For a Bézier curve of degree `n`:
//!
//! ```text
//! C(t) = sum_i B_{n,i}(t) P_i      T(t) = sum_i B_{n,i}(t) T_i
//! I(t) = sum_i B_{n,i}(t) I_i      F(t) = sum_i B_{n,i}(t) F_i,     t in [0, 1]
//! ```
//!
//! and likewise with the B-spline basis `N_{i,p}`, the rational basis
//! `R_i = w_i N_{i,p} / sum_j w_j N_{j,p}` of NURBS, or their tensor products on surfaces.
//! Every such basis is non-negative with unit sum, so every point of a curve or surface is
//! again a valid neutrosophic point (its degrees within the range of the control degrees), the
//! curve lies in the convex hull of its control points, degrees included, and affine maps of
//! the positions commute with evaluation. `docs/model.md` in the repository states the model
//! and the project's decisions; `docs/architecture.md` the crates around this one.
//!
//! ```
//! use neutrospline::{Bezier, ControlPoint, DegreeKind, Degrees, Derivative, Evaluate, Split};
//!
//! let p = |x, y, t, i, f| Ok::<_, neutrospline::DegreeError>(ControlPoint::new([x, y], Degrees::new(t, i, f)?));
//! let curve = Bezier::new(vec![
//!     p(1.0, 3.0, 0.3, 0.6, 0.1)?,
//!     p(3.0, 6.0, 0.8, 0.1, 0.1)?,
//!     p(6.0, 2.0, 0.7, 0.1, 0.2)?,
//!     p(9.0, 5.0, 0.2, 0.4, 0.4)?,
//! ])?;
//! let point = curve.evaluate(0.5)?;
//! assert_eq!(point.position, [4.625, 4.0]);
//! assert!((point.degree(DegreeKind::Falsity) - 0.175).abs() < 1e-15);
//! let (left, _right) = curve.split(0.5)?;          // de Casteljau
//! let end = left.evaluate(1.0)?;                  // the split point, by de Casteljau's steps
//! assert_eq!(end.position, point.position);
//! assert!((end.degree(DegreeKind::Indeterminacy) - point.degree(DegreeKind::Indeterminacy)).abs() < 1e-15);
//! let tangent = curve.derivative().evaluate(0.5)?; // a derivative is a curve too
//! assert_eq!(tangent.position, [8.25, -1.5]);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! ## The pieces
//! - Values: [`Degrees`] with its validity rules [`Family`] (neutrosophic, intuitionistic
//!   fuzzy, fuzzy), [`DegreeKind`]; [`NeutrosophicPoint`] (alias [`ControlPoint`],
//!   [`CurvePoint`]), [`DerivativeValue`], [`Interval`], [`BoundingBox`], [`Affine`].
//! - Relations: [`AxisSet`] and [`PointRelation`], the paper's Def. 4 (the largest admissible
//!   relation and a checker that names the violating pair and degree).
//! - Curves: [`Bezier`], [`BSpline`] and [`Nurbs`] (one generic type [`SplineCurve`] with a
//!   [`Weighting`], [`Polynomial`] or [`Rational`]), [`AnyCurve`] for any of them,
//!   [`KnotVector`], and the derivative of any of them, [`CurveDerivative`].
//! - Capabilities, one small trait each, implemented by every kind where the math allows:
//!   [`ControlPolygon`] (the control points), [`Evaluate`] (domain, point, start and end),
//!   [`Derivative`] (the derivative is again
//!   evaluable and differentiable), [`Split`] (split and subsegment), [`Elevate`],
//!   [`Bounded`] (tight and control bounding boxes).
//! - Geometry along a curve, one body for every kind: [`CurveGeometry`] (arc length by
//!   adaptive Gauss-Legendre quadrature on the pieces, curvature, unit tangent and normal, the
//!   arc-length averages of the degrees and the score in [`ArcAverages`]), errors
//!   [`GeometryError`].
//! - Nearest points: [`NearestPoint`] (`curve.nearest(point)`, the global minimum of the
//!   distance by branch and bound on the Bernstein coefficients of the squared distance, then
//!   safeguarded Newton), [`Projector`] for many queries, [`Nearest`], [`NearestError`].
//! - Intersections of plane curves of any kinds: [`intersections`] and
//!   [`self_intersections`] (Bézier subdivision with a Newton polish, tangential and end-point
//!   intersections included), [`Intersection`], [`IntersectError`] (overlapping curves).
//! - Surfaces: [`Surface`] (Bézier, B-spline, NURBS), [`EvaluateSurface`], partial
//!   derivatives, normals and iso-parameter curves.
//! - Batch evaluation into flat arrays, SIMD with run-time dispatch and threads:
//!   [`CurveBatch`] with [`BatchParams`] and [`BatchOptions`] (fast kernels by default, or
//!   compensated: [`Accuracy`]); [`uniform_parameter`] is the
//!   evenly spaced sampling every front end uses. The tuning constants are in [`batch`].
//! - Fitting data (points with degrees, not control points): [`fit::fit`] interpolates or
//!   fits by weighted least squares (to a number of control points or a tolerance), open or
//!   closed, with smoothing, the degree channels under the membership rule's bounds, and a
//!   [`fit::FitReport`].
//! - The paper's Example 1: [`example1`], [`EXAMPLE1_TABLE`], [`EXAMPLE1_NAMES`].
//!
//! Geometry operations are infallible or return a typed error at the input boundary
//! ([`CurveError`], [`EvalError`], [`GeometryError`], [`KnotError`], [`SurfaceError`], [`DegreeError`],
//! [`RelationError`]); nothing here reads or writes files (the `neutrospline-io` crate does).
//!
//! ## Feature flags
//! - `serde`: `Serialize`/`Deserialize` for [`Degrees`], [`DegreeKind`], [`Family`] and
//!   [`NeutrosophicPoint`] (a point is the control point of the model files: keys `x`, `y`,
//!   `z` for 3-D, `truth`, `indeterminacy`, `falsity`). Deserialization checks exactly like
//!   the constructors.
//! - `proptest`: the module `strategies`, proptest generators of valid degrees, control points,
//!   curves of every kind and surfaces, for property tests of code built on this crate.
//! - `simd`, `avx512`, `parallel`: faster batch evaluation ([`CurveBatch`]): SIMD kernels
//!   chosen at run time (AVX2 + FMA; AVX-512 with `avx512`) and threads (rayon). Without them
//!   the same results come from a portable kernel on the calling thread.
#![deny(missing_docs)]
#![forbid(unsafe_code)]

mod any_curve;
pub mod batch;
mod bernstein;
mod bernstein_scalar;
mod bezier;
pub mod color;
mod compensated;
mod curve;
mod degrees;
mod derivative;
mod dyn_curve;
mod example;
mod family;
pub mod fit;
mod fuzzy;
mod geometry;
mod intersect;
mod knots;
mod layout;
mod nearest;
pub mod options;
mod point;
mod reduce;
mod relation;
pub mod sample;
mod spline;
mod spline_curve;
#[cfg(feature = "proptest")]
pub mod strategies;
mod surface;
mod surface_transform;
mod transform;
mod type_reduction;

pub use any_curve::{AnyCurve, CurveKind};
pub use batch::{uniform_parameter, Accuracy, BatchOptions, BatchParams, CurveBatch};
pub use bezier::Bezier;
pub use curve::{
    Bounded, ControlPolygon, CurveError, Derivative, Elevate, EvalError, Evaluate, Split,
    BOUNDS_TOLERANCE,
};
pub use degrees::{DegreeError, DegreeKind, Degrees, ParseNameError, HESITATION_TOLERANCE};
pub use derivative::CurveDerivative;
pub use dyn_curve::{Dimensional, DynCurve, DynDerivative, DynPoint, NearestRow, RowLengthError};
pub use example::{example1, EXAMPLE1_NAMES, EXAMPLE1_TABLE};
pub use family::{
    Family, FamilyValues, Lane, LaneDegrees, LinearConstraint, ParseFamilyError, PowerRule,
    RuleError, FAMILY_FORMS, MAX_CHANNELS, RULE_TOLERANCE,
};
pub use fuzzy::{alpha_cut, centroid_curve, FuzzyError, Side, Spread};
pub use geometry::{
    ArcAverages, CurveGeometry, GeometryError, DEFAULT_ACCURACY, FINEST_ACCURACY, MAX_SUBINTERVALS,
};
pub use intersect::{
    intersections, self_intersections, Contact, IntersectError, Intersection, TANGENT_SINE,
};
pub use knots::{KnotError, KnotVector};
pub use nearest::{
    Nearest, NearestError, NearestPoint, Projector, SurfaceNearest, SurfaceProjector, TIE_TOLERANCE,
};
pub use point::{
    Affine, BoundingBox, ControlPoint, CurvePoint, DerivativeValue, Interval, NeutrosophicPoint,
};
pub use relation::{AxisSet, AxisSetName, PointRelation, RelationError};
pub use spline_curve::{
    BSpline, BezierSegment, Nurbs, Polynomial, Rational, SplineCurve, Weighting,
};
pub use surface::{
    Direction, EvaluateSurface, Surface, SurfaceDerivatives, SurfaceError, SurfaceKind,
};
pub use transform::{DegreeReduction, KnotRemoval, ReduceError, DEVIATION_SAMPLES_PER_SPAN};
pub use type_reduction::{centroid_interval, CentroidInterval, TypeReductionError};
