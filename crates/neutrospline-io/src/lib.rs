//! The file formats of neutrospline: CSV tables of control points and TOML / JSON models of
//! neutrosophic curves and surfaces (Bézier, B-spline, NURBS; tensor-product surfaces), read
//! into the core's types and written back.
//!
//! - Reading: [`load`] a file (format by extension), [`parse`] bytes held in memory, or
//!   [`read_csv`] from a stream. The result is a validated [`Model`]: the core's curve or
//!   surface ([`Shape`]), the membership rule of its degrees, its name, description and
//!   control-point names. [`ReadOptions`] give what a file does not hold (a CSV file's kind,
//!   degree, knots, grid) and the [`Limits`].
//! - Errors name the file, the line and the field, the value and the rule broken
//!   (`bad.csv:2: truth = 1.2 is outside [0, 1] (every degree must be in [0, 1])`): an
//!   [`InputError`] inside a [`ReadError`]. Every check of degrees, knots, weights and grids is
//!   the core's own; this crate locates its errors.
//! - Data for fitting: [`load_data`] / [`read_data`] read measured points (CSV, with optional
//!   `parameter` and `weight` columns) into a [`DataTable`], whose errors and fitting errors
//!   are located by line.
//! - Writing: [`to_toml_string`], [`to_json_string`], [`to_csv_string`] and [`save`], which
//!   replaces a file atomically. Whatever is written reads back to an equal model, numbers to
//!   the last bit.
//! - Tables of results: [`write_table`] writes CSV and JSON with every digit, LaTeX
//!   (booktabs) and Markdown rounded ([`format_justified`], [`format_significant`]), with the
//!   options of [`TableOutput`] (`format`, `digits`).
//! - For programs built on these files (the command line, the studio, the exchange crate
//!   `neutrospline-exchange`, which reads DXF and SVG into a [`Model`] and exports models to
//!   CAD and 3-D formats): [`AtomicFile`] and [`write_atomically`] replace any file atomically;
//!   [`format_number`] and [`push_number`] write a number as every table and message of the
//!   workspace does (shortest round trip, no exponent); [`InputError::new`] locates an error
//!   of another reader, [`Limits::too_many_control_points`] words its refusal, and
//!   [`MAX_INTEGER`] is the largest degree or count a file (or an option) may give.
//!
//! ```
//! use neutrospline_io::{parse, to_json_string, Format, ReadOptions};
//!
//! let csv = "name,x,y,truth,indeterminacy,falsity\n\
//!            C0,1,3,0.3,0.6,0.1\nC1,3,6,0.8,0.1,0.1\nC2,6,2,0.7,0.1,0.2\nC3,9,5,0.2,0.4,0.4\n";
//! let model = parse("example1.csv", Format::Csv, csv.as_bytes(), &ReadOptions::default())?;
//! assert_eq!(model.shape().curve_degree(), Some(3));
//! assert_eq!(model.point_names()[3].as_deref(), Some("C3"));
//!
//! let json = to_json_string(&model.clone().with_name("Example 1"));
//! assert!(json.starts_with("{\n  \"kind\": \"bezier\",\n  \"name\": \"Example 1\""));
//!
//! let error = parse("bad.csv", Format::Csv, b"x,y,truth,indeterminacy,falsity\n1,2,1.2,0,0\n",
//!                   &ReadOptions::default()).unwrap_err();
//! assert_eq!(error.to_string(),
//!            "bad.csv:2: truth = 1.2 is outside [0, 1] (every degree must be in [0, 1])");
//! # Ok::<(), neutrospline_io::ReadError>(())
//! ```
//!
//! The formats are described in the repository's `docs/formats.md`; the
//! messages name a setting by the `neutrospline` command's option for it (`--degree`).
#![deny(missing_docs)]
#![forbid(unsafe_code)]

mod atomic;
mod build;
mod csv;
mod data;
mod degree_view;
mod error;
mod fit_report;
mod format;
mod model;
mod number;
mod options;
mod parsed;
mod path_order;
mod points;
mod read;
mod relation;
mod settings;
mod shape;
mod spreadsheet;
mod table;
mod table_input;
mod text;
mod transform;
mod tree;
mod walker;
mod write;

pub use atomic::{write_atomically, AtomicFile};
pub use data::{load_data, load_data_with, read_data, read_data_with, DataTable};
pub use degree_view::DegreeView;
pub use error::{InputError, ReadError, UnsupportedFormat, WriteError};
pub use fit_report::{surface_fit_report_json, surface_fit_warning, ILL_CONDITIONED};
pub use format::{Format, Limits, DEFAULT_MAX_CONTROL_POINTS, DEFAULT_MAX_FILE_SIZE, MAX_INTEGER};
pub use model::{KnotSource, Model, ModelError};
pub use number::{format_justified, format_number, format_significant, push_number};
pub use options::ReadOptions;
pub use path_order::{path_disorder, PathDisorder, JUMP as PATH_JUMP, SPREAD as PATH_SPREAD};
pub use points::{load_points, load_points_with, read_points, read_points_with, PointTable};
pub use read::{load, parse, read_csv, read_whole};
pub use relation::{
    load_axis_set, load_axis_set_with, load_pairs, load_pairs_with, read_axis_set,
    read_axis_set_with, read_pairs, read_pairs_with, AxisTable, PairTable,
};
pub use settings::{Kind, KnotRule, KnotSpec};
pub use shape::Shape;
pub use table::{
    latex_heading, write_table, Cell, TableCell, TableFormat, TableOutput, MAX_DIGITS,
};
pub use table_input::TableInput;
pub use transform::{transform, Operation, TransformRequest, Transformed};
pub use write::{save, to_csv_string, to_json_string, to_string, to_toml_string};
