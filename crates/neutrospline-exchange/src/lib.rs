//! CAD and 3-D exchange of neutrospline models: curves imported from DXF and SVG drawings, and
//! models exported to the formats of CAD and 3-D programs. The models are
//! [`neutrospline_io::Model`]s, read and written as files by `neutrospline-io`; this crate adds
//! the formats that only the command line (`neutrospline import`, `neutrospline export`)
//! needs.
//!
//! - Exporting: [`export`] and [`export_file`] write DXF (a curve as one exact SPLINE entity, a
//!   surface as a POLYFACE mesh), STEP (ISO 10303-21, AP214: exact B-spline curves and
//!   surfaces, the degrees in the control points' names), glTF 2.0 (`.glb`, `.gltf`), PLY and
//!   OBJ (sampled polylines and triangle meshes), with the degrees kept where the format can
//!   carry them ([`ExportFormat`], [`ExportOptions`], [`ColorBy`]).
//! - Importing: [`load_dxf`] and [`parse_dxf`] read the curve entities of a DXF drawing (text or
//!   binary) exactly: SPLINE as written, with the degrees the exporter keeps in its extended
//!   data (a DXF export reads back to an equal model, numbers to the last bit); LINE, ARC,
//!   CIRCLE, ELLIPSE, LWPOLYLINE and POLYLINE as exact NURBS; through the blocks of INSERTs; [`load_svg`] and [`parse_svg`] read the drawn
//!   shapes of an SVG drawing as curves. Each returns an [`Import`]: the models and the
//!   [`ImportReport`] of what was imported and what was skipped, by kind and reason, so that
//!   nothing is dropped without a word. The options are [`ImportRequest`]'s, defined once for
//!   every front end. Errors are `neutrospline-io`'s
//!   [`ReadError`](neutrospline_io::ReadError)s, located at the file's line.
//!
//! ```
//! use neutrospline::{example1, AnyCurve, Degrees};
//! use neutrospline_exchange::{export, parse_dxf, ExportFormat, ExportOptions, ImportOptions};
//! use neutrospline_io::{Limits, Model};
//!
//! let model = Model::new(AnyCurve::Bezier(example1())).with_name("Example 1");
//! let dxf = export(&model, ExportFormat::Dxf, &ExportOptions::new())?;
//! // The degrees of a spline without neutrospline's extended data (another program's).
//! let options = ImportOptions::new(Degrees::new(1.0, 0.0, 0.0)?);
//! let back = parse_dxf("example1.dxf", &dxf, &options, &Limits::default())?;
//! assert_eq!(back.models, [model]);
//! assert_eq!(back.report.summary(), "imported 1 curve (1 SPLINE)");
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
#![deny(missing_docs)]
#![forbid(unsafe_code)]

mod dxf_import;
mod dxf_xdata;
mod export;
mod pieces;
mod report;
pub mod svg_import;

pub use dxf_import::{load_dxf, parse_dxf};
pub use export::{
    export, export_file, ColorBy, ExportError, ExportFormat, ExportOptions, MAX_CURVE_SAMPLES,
    MAX_SURFACE_SAMPLES,
};
pub use report::{
    Import, ImportOptions, ImportReport, ImportRequest, Skip, SkipReason, SourceFormat,
    DXF_ENTITIES, SVG_ELEMENTS,
};
pub use svg_import::{load_svg, parse_svg};
