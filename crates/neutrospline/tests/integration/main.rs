//! The integration tests of the core, one binary: one module per topic (properties against
//! brute force, references from `tests/data`), the shared spline checks in `spline_common`.
//! Proptest keeps the failures of `tests/integration/X.rs` in `tests/proptest-regressions/X.txt`
//! (`FileFailurePersistence::SourceParallel`, the default: the sibling of the directory holding
//! `main.rs`).

#[macro_use]
mod spline_common;
mod across_kinds;
mod batch_properties;
mod bspline_properties;
mod curve_batch_properties;
mod degree_zero;
mod family_blending;
mod family_fit;
mod family_reference;
mod fit_properties;
mod fit_reference;
mod fuzzy_properties;
mod geometry;
mod higher_derivatives;
mod intersect;
mod knot_kinds;
mod nearest;
mod nurbs_properties;
mod properties;
mod reference;
mod reference_common;
mod spline_reference;
mod surface_fit_reference;
mod surface_properties;
mod surface_transform;
mod transform_reference;
mod wide_fit;
mod wide_surface_transform;
