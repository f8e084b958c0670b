//! # neutrospline
//!
//! Neutrosophic curve modeling: Bézier curves whose control points carry three uncertainty
//! degrees, **truth**, **indeterminacy** and **falsity**, each in \[0, 1\].
//!
//! The model (Mahmud, Wahab, Zulkifly and Broumi, "A Neutrosophic Bézier Curve Model using
//! Control Points") blends every degree with the same Bernstein basis as the positions:
//!
//! ```text
//! C(t) = sum_i B_{n,i}(t) P_i      T(t) = sum_i B_{n,i}(t) T_i
//! I(t) = sum_i B_{n,i}(t) I_i      F(t) = sum_i B_{n,i}(t) F_i,     t in [0, 1]
//! ```
//!
//! so every point of the curve is again a valid neutrosophic point, the curve interpolates its
//! end control points, and it lies in the convex hull of its control points, degrees included.
//!
//! ```
//! use neutrospline::{Bezier, ControlPoint, DegreeKind, Degrees};
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
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! ## Modules of the model
//! - [`Degrees`], [`Membership`]: the degrees and their three validity rules (neutrosophic,
//!   intuitionistic fuzzy, fuzzy).
//! - [`NeutrosophicPoint`] (alias [`ControlPoint`], [`CurvePoint`]): a position with degrees.
//! - [`AxisSet`], [`PointRelation`]: the paper's Def. 4 point relations and their checker.
//! - [`Bezier`]: the curve, with evaluation, derivative, split, elevation and bounds; the
//!   capabilities are also the traits [`Evaluate`], [`Derivative`], [`Split`], [`Elevate`],
//!   [`Bounded`], shared by every curve kind.
//!
//! ## Feature flags
//! - `serde`: `Serialize`/`Deserialize` for [`Degrees`], [`DegreeKind`], [`Membership`] and
//!   [`NeutrosophicPoint`]. Deserialization checks exactly like the constructors.
//! - `proptest`: the module `strategies`, proptest generators of valid degrees, control points
//!   and curves, for property tests of code built on this crate.
//! - `simd`, `avx512`, `parallel`: faster batch evaluation ([`BezierBatch`], [`evaluate_curves`],
//!   [`CurveBatch`]):
//!   SIMD kernels chosen at run time (AVX2 + FMA; AVX-512 with `avx512`) and threads (rayon).
//!   Without them the same results come from a portable kernel on the calling thread.
#![deny(missing_docs)]
#![forbid(unsafe_code)]

mod any_curve;
mod batch;
mod bernstein;
mod bezier;
mod bspline;
mod curve;
mod degrees;
mod example;
mod knots;
mod layout;
mod nurbs;
mod point;
mod relation;
mod spline;
#[cfg(feature = "proptest")]
pub mod strategies;
mod surface;

pub use any_curve::{AnyCurve, AnyDerivative, CurveKind};
pub use batch::{
    batch_instruction_set, evaluate_curves, uniform_parameter, BatchOptions, BatchParams,
    BezierBatch, CurveBatch, BATCH_DIRECT_MAX_DEGREE, PARALLEL_THRESHOLD,
};
pub use bezier::{Bezier, BezierDerivative};
pub use bspline::{BSpline, BSplineDerivative, BezierSegment};
pub use curve::{
    axis_name, Bounded, CurveError, Derivative, Elevate, EvalError, Evaluate, Split,
    BOUNDS_TOLERANCE,
};
pub use degrees::{
    DegreeError, DegreeKind, Degrees, Membership, ParseNameError, HESITATION_TOLERANCE,
};
pub use example::{example1, EXAMPLE1_NAMES, EXAMPLE1_TABLE};
pub use knots::{KnotError, KnotVector};
pub use nurbs::{Nurbs, NurbsDerivative};
pub use point::{
    Affine, BoundingBox, ControlPoint, CurvePoint, DerivativeValue, NeutrosophicPoint, Range,
};
pub use relation::{AxisSet, AxisSetName, PointRelation, RelationError};
pub use surface::{Direction, Surface, SurfaceDerivatives, SurfaceError, SurfaceKind};
