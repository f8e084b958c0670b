//! The options shared by the commands that read a model file: the membership rule and the
//! shape settings a CSV file cannot hold (kind, degree, knots, grid).

use neutrospline::{CurveKind, Family, SurfaceKind};

use std::path::PathBuf;

use crate::commands::parse_family;
use crate::input::UsageError;
use crate::output;
use crate::request::RequestArgs;
use neutrospline_io::{Kind, KnotSpec, ReadOptions, TableCell, TableInput, TableOutput};

/// Where and how a command that makes a table (`eval`, `query`, `intersect`) writes it.
#[derive(Debug, Clone, clap::Args)]
pub struct TableArgs {
    /// The table's format and digits (defined by neutrospline-io's `TableOutput`)
    #[command(flatten)]
    pub format: RequestArgs<TableOutput>,

    /// Write to OUT instead of standard output (replaced atomically: on error the old file is
    /// left untouched)
    #[arg(short = 'o', long = "output", value_name = "OUT")]
    pub output: Option<PathBuf>,
}

impl TableArgs {
    /// The format and digits, checked.
    ///
    /// # Errors
    /// A [`UsageError`] with the library's message (`--digits` with csv or json, out of
    /// range).
    pub fn table_output(&self) -> Result<TableOutput, UsageError> {
        let output = *self.format.request()?;
        output.validate().map_err(|e| UsageError(e.to_string()))?;
        Ok(output)
    }

    /// Writes the table ([`output::write_table`]) to OUT, atomically, or to standard output.
    ///
    /// # Errors
    /// The options' usage error, the first error of `rows`, or a write error.
    pub fn write<C: TableCell>(
        &self,
        columns: &[String],
        rows: impl IntoIterator<Item = anyhow::Result<Vec<C>>>,
    ) -> anyhow::Result<()> {
        let table_output = self.table_output()?;
        output::emit(self.output.as_deref(), |w| {
            output::write_table(w, &table_output, columns, rows)
        })
    }
}

/// The `--kind` values, mirroring [`Kind`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum KindArg {
    /// Bezier curve (default for CSV): degree n = number of control points - 1, t in [0, 1].
    Bezier,
    /// B-spline curve: needs --degree; --knots optional.
    Bspline,
    /// NURBS curve: as bspline, plus a `weight` column.
    Nurbs,
    /// Bezier surface: needs --rows and --cols; degrees rows - 1 and cols - 1.
    BezierSurface,
    /// B-spline surface: needs --rows, --cols, --degree-u, --degree-v.
    BsplineSurface,
    /// NURBS surface: as bspline-surface, plus a `weight` column.
    NurbsSurface,
}

impl From<KindArg> for Kind {
    fn from(k: KindArg) -> Kind {
        match k {
            KindArg::Bezier => Kind::Curve(CurveKind::Bezier),
            KindArg::Bspline => Kind::Curve(CurveKind::BSpline),
            KindArg::Nurbs => Kind::Curve(CurveKind::Nurbs),
            KindArg::BezierSurface => Kind::Surface(SurfaceKind::Bezier),
            KindArg::BsplineSurface => Kind::Surface(SurfaceKind::BSpline),
            KindArg::NurbsSurface => Kind::Surface(SurfaceKind::Nurbs),
        }
    }
}

/// The largest degree or count accepted on the command line (as in files: larger values are
/// surely mistakes, and the core's `degree + 1` must not overflow).
const MAX: u64 = neutrospline_io::MAX_INTEGER;

/// Parses a `--knots` value.
fn parse_knots(text: &str) -> Result<KnotSpec, String> {
    KnotSpec::parse_option(text)
}

/// The model options of `eval` and `check`.
#[derive(Debug, Clone, clap::Args)]
#[command(next_help_heading = "Model options")]
pub struct ModelArgs {
    /// Membership family of the degrees: neutrosophic, intuitionistic, fuzzy, pythagorean,
    /// fermatean, q-rung:Q, picture, spherical, t-spherical:N. For CSV it chooses the family
    /// (default neutrosophic); a model file's own must agree
    #[arg(long, value_name = "FAMILY", value_parser = parse_family)]
    pub membership: Option<Family>,

    /// Kind of curve or surface (CSV default: bezier)
    #[arg(long, value_enum, value_name = "KIND")]
    pub kind: Option<KindArg>,

    /// Polynomial degree of a curve (required for bspline and nurbs; for bezier it must be the
    /// number of control points - 1)
    #[arg(long, value_name = "P", value_parser = clap::value_parser!(u64).range(..=MAX))]
    pub degree: Option<u64>,

    /// Knots of a bspline or nurbs curve: clamped-uniform (default), chord-length,
    /// centripetal, uniform (unclamped, domain [0, 1]), or the values K0,K1,... (number of
    /// control points + degree + 1 of them, non-decreasing; with --periodic, the breakpoints:
    /// number of control points + 1 of them)
    #[arg(long, value_name = "RULE|K0,K1,...", value_parser = parse_knots, allow_hyphen_values = true)]
    pub knots: Option<KnotSpec>,

    /// A closed (periodic) bspline or nurbs curve: the control points listed are the
    /// distinct ones, the first `degree` of them follow again, and the knots are breakpoints
    /// (default uniform on [0, 1])
    #[arg(long)]
    pub periodic: bool,

    /// Surfaces: control points along u (the control points are listed row by row)
    #[arg(long, value_name = "R", value_parser = clap::value_parser!(u64).range(1..=MAX))]
    pub rows: Option<u64>,

    /// Surfaces: control points along v (per row)
    #[arg(long, value_name = "C", value_parser = clap::value_parser!(u64).range(1..=MAX))]
    pub cols: Option<u64>,

    /// Degree along u of a bspline or nurbs surface (bezier-surface: must be rows - 1)
    #[arg(long, value_name = "P", value_parser = clap::value_parser!(u64).range(..=MAX))]
    pub degree_u: Option<u64>,

    /// Degree along v of a bspline or nurbs surface (bezier-surface: must be cols - 1)
    #[arg(long, value_name = "Q", value_parser = clap::value_parser!(u64).range(..=MAX))]
    pub degree_v: Option<u64>,

    /// Knots along u of a bspline or nurbs surface: clamped-uniform (default) or K0,K1,...
    #[arg(long, value_name = "RULE|K0,K1,...", value_parser = parse_knots, allow_hyphen_values = true)]
    pub knots_u: Option<KnotSpec>,

    /// Knots along v of a bspline or nurbs surface: clamped-uniform (default) or K0,K1,...
    #[arg(long, value_name = "RULE|K0,K1,...", value_parser = parse_knots, allow_hyphen_values = true)]
    pub knots_v: Option<KnotSpec>,

    /// A bspline or nurbs surface closed (periodic) along u, as --periodic for a curve
    #[arg(long)]
    pub periodic_u: bool,

    /// A bspline or nurbs surface closed (periodic) along v, as --periodic for a curve
    #[arg(long)]
    pub periodic_v: bool,

    /// How CSV tables are read (defined by neutrospline-io's `TableInput`)
    #[command(flatten)]
    pub table: RequestArgs<TableInput>,
}

impl ModelArgs {
    /// How CSV tables are read ([`table_input`]).
    ///
    /// # Errors
    /// As [`table_input`].
    pub fn table_input(&self) -> Result<TableInput, UsageError> {
        table_input(&self.table)
    }

    /// The options as the readers take them (with the default limits; see
    /// [`crate::input::read_options`]).
    pub fn read_options(&self) -> ReadOptions {
        let count = |v: Option<u64>| v.map(|v| usize::try_from(v).unwrap_or(usize::MAX));
        let mut options = ReadOptions::default();
        options.membership = self.membership;
        options.kind = self.kind.map(Into::into);
        options.degree = count(self.degree);
        options.knots = self.knots.clone();
        options.rows = count(self.rows);
        options.cols = count(self.cols);
        options.degree_u = count(self.degree_u);
        options.degree_v = count(self.degree_v);
        options.knots_u = self.knots_u.clone();
        options.knots_v = self.knots_v.clone();
        let flag = |given: bool| given.then_some(true);
        options.periodic = flag(self.periodic);
        options.periodic_u = flag(self.periodic_u);
        options.periodic_v = flag(self.periodic_v);
        options
    }
}

/// The table options of `args`, checked.
///
/// # Errors
/// A [`UsageError`] with the library's message (a delimiter that is not one character, a
/// decimal comma with the delimiter `,`).
pub fn table_input(args: &RequestArgs<TableInput>) -> Result<TableInput, UsageError> {
    let input = args.request()?.clone();
    input.validate().map_err(|e| UsageError(e.to_string()))?;
    Ok(input)
}
