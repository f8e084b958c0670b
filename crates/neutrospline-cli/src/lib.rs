//! The `neutrospline` command: evaluate, check, draw, export, import and demonstrate
//! neutrosophic curves (Bézier, B-spline, NURBS) and tensor-product surfaces.
//!
//! A thin layer over the `neutrospline` library: it parses arguments, reads files through
//! `neutrospline-io`, calls the library, writes tables and maps errors to exit codes (0
//! success, 1 invalid input or failure, 2 usage error). Only [`main_with_args`], [`run_with_args`] and the fuzz
//! target bodies ([`fuzzing`]) are public.

mod commands;
pub mod fuzzing;
mod input;
mod limits;
mod output;
mod progress;
mod request;
mod shape;
mod signals;

use std::io::Write;
use std::process::ExitCode;

use clap::{Parser, Subcommand};

use commands::studio::StudioArgs;
use commands::{
    bench::BenchArgs, bench_fit::BenchFitArgs, check::CheckArgs, eval::EvalArgs,
    example::ExampleArgs, export::ExportArgs, fit::FitArgs, import::ImportArgs,
    intersect::IntersectArgs, plot::PlotArgs, query::QueryArgs, relation::RelationArgs,
    transform::TransformArgs,
};

/// Evaluate and check neutrosophic curves and surfaces (Bezier, B-spline, NURBS): control
/// points carrying truth, indeterminacy and falsity degrees.
#[derive(Debug, Parser)]
#[command(
    name = "neutrospline",
    version,
    after_help = "Kinds: bezier, bspline, nurbs (curves, 2-D or 3-D); bezier-surface, \
bspline-surface, nurbs-surface (3-D, control points row by row).\n\
Files: .toml or .json models (kind, optional name, description and membership, degree and knots \
for curves, rows, cols, degree_u, degree_v, knots_u and knots_v for surfaces, and \
control_points with x, y[, z], truth, indeterminacy, falsity[, weight][, name]); .csv tables \
(a header row, one control point per row; the kind, degree, knots and grid come from --kind, \
--degree, --knots, --rows, ...).\n\
Exit status: 0 success, 1 invalid input, including a command-line option that contradicts the \
file (message on stderr starting with `error:`), 2 usage error, 130 / 143 interrupted by SIGINT \
/ SIGTERM (an output file being written is then left as it was)."
)]
pub struct Cli {
    #[command(subcommand)]
    command: Command,

    /// Resource limits (global options).
    #[command(flatten)]
    limits: limits::LimitArgs,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Evaluate a curve or surface at parameters: one row per parameter (t or u, v, then
    /// position and degrees)
    Eval(EvalArgs),
    /// Validate a model file and print its kind, degrees, knots, domain and degree ranges
    Check(CheckArgs),
    /// Draw a figure of a curve or surface (SVG or PNG): the paper's views and a plane view
    Plot(PlotArgs),
    /// One CAGD operation on a model (elevate, insert, refine or remove knots, split, a piece,
    /// reverse, Bézier pieces, a new domain), written as a model
    Transform(TransformArgs),
    /// Fit a curve (or with --surface a surface) to measured data points (CSV with positions
    /// and degrees): interpolation or least squares, the degrees kept within their bounds; the
    /// model to standard output or -o, the error report to standard error
    Fit(FitArgs),
    /// Export a curve or surface to CAD and 3-D programs: DXF (exact splines), glTF, PLY or
    /// OBJ, keeping the degrees where the format can carry them
    Export(ExportArgs),
    /// Import curves as model files: the curves of a DXF drawing (with the degrees `export`
    /// keeps in it) or an SVG drawing, exactly, with a report of what was skipped
    Import(ImportArgs),
    /// For every point of a CSV file, the nearest point of a curve or surface: its parameter,
    /// the distance, the position, the degrees and the score
    Query(QueryArgs),
    /// Every point where two plane curves meet (or where a curve crosses itself, when B is A):
    /// the parameters on both, the point and the degrees of each curve there
    Intersect(IntersectArgs),
    /// The paper's Def. 4: the largest neutrosophic point relation of two axis sets (CSV), as
    /// the control points of a plane curve; or, with --check MODEL, whether a model's control
    /// points form a relation of the two sets
    Relation(RelationArgs),
    /// Run the paper's Example 1 from built-in data: print its control points and curve, and
    /// with --out DIR write the paper's five figures and the curve table
    Example(ExampleArgs),
    /// Time the library's batch evaluator (Mpts/s) on Example 1 or a random curve of a given
    /// degree, next to a memory-bandwidth reference
    Bench(BenchArgs),
    /// Time fitting (least squares to a number of control points, or to a tolerance) of
    /// synthetic noisy data in-process, as one JSON object (bench/compare_fit.py compares it
    /// with scipy in the same run)
    BenchFit(BenchFitArgs),
    /// Edit a curve live in the browser: a local server on 127.0.0.1 with the plane view,
    /// the paper's views, the degrees and the curve table (prints the URL)
    Studio(StudioArgs),
}

fn run(cli: &Cli) -> anyhow::Result<()> {
    match &cli.command {
        Command::Eval(args) => commands::eval::run(args),
        Command::Check(args) => commands::check::run(args),
        Command::Plot(args) => commands::plot::run(args),
        Command::Fit(args) => commands::fit::run(args),
        Command::Transform(args) => commands::transform::run(args),
        Command::Export(args) => commands::export::run(args),
        Command::Import(args) => commands::import::run(args),
        Command::Query(args) => commands::query::run(args),
        Command::Intersect(args) => commands::intersect::run(args),
        Command::Relation(args) => commands::relation::run(args),
        Command::Example(args) => commands::example::run(args),
        Command::Bench(args) => commands::bench::run(args, &mut std::io::stdout().lock()),
        Command::BenchFit(args) => commands::bench_fit::run(args, &mut std::io::stdout().lock()),
        Command::Studio(args) => commands::studio::run(args),
    }
}

/// Parses the command line, runs the command and maps the outcome to the exit status.
pub fn main_with_args() -> ExitCode {
    ExitCode::from(run_with_args(std::env::args_os()))
}

/// Parses `args` (the program name first, as `std::env::args_os` gives them), runs the command
/// and returns the exit status: 0 success, 1 invalid input or failure, 2 usage error, 130 / 143
/// interrupted. The `neutrospline` binary and the Python wheel's `neutrospline` console script
/// both run through here, so they behave the same.
pub fn run_with_args<I, T>(args: I) -> u8
where
    I: IntoIterator<Item = T>,
    T: Into<std::ffi::OsString> + Clone,
{
    let cli = match Cli::try_parse_from(args) {
        Ok(cli) => cli,
        Err(e) => {
            // Help and version exit 0, errors 2; a closed pipe while printing is ignored.
            let _ = e.print();
            return u8::try_from(e.exit_code()).unwrap_or(2);
        }
    };
    limits::install(cli.limits.limits());
    match run(&cli) {
        Ok(()) => 0,
        Err(e) if output::is_broken_pipe(&e) => 0,
        Err(e) => {
            let _ = writeln!(std::io::stderr(), "error: {e:#}");
            if let Some(i) = e
                .chain()
                .find_map(|c| c.downcast_ref::<signals::Interrupted>())
            {
                i.exit_code()
            } else if e.downcast_ref::<input::UsageError>().is_some() {
                2
            } else {
                1
            }
        }
    }
}
