//! `neutrospline transform MODEL -o OUT --OPERATION`: one CAGD operation on a model (degree
//! elevation, knot insertion, refinement and removal, splitting, a piece, reversal, Bézier
//! pieces, a new domain), written as a model that `eval`, `check` and `plot` read.

use std::path::PathBuf;

use neutrospline_io::{Format, TransformRequest};

use crate::commands::import::numbered;
use crate::commands::options::ModelArgs;
use crate::input::{self, UsageError};
use crate::output;
use crate::request::RequestArgs;

/// Arguments of `transform`.
#[derive(Debug, clap::Args)]
#[command(
    after_help = "One operation per call. Exact operations (all but --remove-knot) leave the \
curve or surface where it was, to rounding; their new control degrees are convex combinations \
of the old ones, so the membership rule holds. Point names are kept by --reverse (reversed) \
and --reparametrize, and dropped by the operations that make new control points (the summary \
says so); spreads follow every exact operation. A Bézier curve becomes its B-spline for \
--insert-knot, --refine and --reparametrize (unless onto 0:1). Surfaces: each operation acts \
in --direction u or v (--to-bezier splits both).\n\
--split writes OUT-1 and OUT-2, --to-bezier OUT-1, OUT-2, ... (one file per piece)."
)]
pub struct TransformArgs {
    /// The model file: .csv, .toml or .json; `-` reads CSV from standard input
    #[arg(value_name = "MODEL")]
    pub file: String,

    /// The model to write: OUT.toml or OUT.json (replaced atomically)
    #[arg(short = 'o', long = "output", value_name = "OUT")]
    pub output: PathBuf,

    /// The operation (defined by the io crate's `TransformRequest`)
    #[command(flatten)]
    pub request: RequestArgs<TransformRequest>,

    #[command(flatten)]
    pub model: ModelArgs,
}

/// Reads the model, applies the operation, writes the result(s) and prints a summary.
///
/// # Errors
/// A usage error (no operation, several, an unsupported output extension), an invalid model
/// file, the operation's own error naming the file, or a write error.
pub fn run(args: &TransformArgs) -> anyhow::Result<()> {
    let format = match Format::from_path(&args.output) {
        Ok(f @ (Format::Toml | Format::Json)) => f,
        _ => {
            return Err(UsageError(format!(
                "{}: unsupported model extension for a transformed model (accepted: .toml, \
                 .json; a CSV file cannot hold the knots)",
                args.output.display()
            ))
            .into())
        }
    };
    let request = args.request.request()?;
    let operation = request.operation().map_err(UsageError)?;
    let model = input::read_model(&args.file, &args.model)?;
    let out = neutrospline_io::transform(&model, &operation, request.direction)
        .map_err(|e| anyhow::anyhow!("{}: {e}", args.file))?;
    let paths: Vec<PathBuf> = if out.models.len() == 1 {
        vec![args.output.clone()]
    } else {
        (1..=out.models.len())
            .map(|k| numbered(&args.output, k))
            .collect()
    };
    for (model, path) in out.models.iter().zip(&paths) {
        let text = neutrospline_io::to_string(model, format)?;
        output::emit(Some(path), |w| {
            w.write_all(text.as_bytes())?;
            Ok(())
        })?;
    }
    let mut err = std::io::stderr().lock();
    use std::io::Write as _;
    let written: Vec<String> = paths.iter().map(|p| p.display().to_string()).collect();
    writeln!(
        err,
        "{}: --{}: wrote {}",
        args.file,
        operation.name(),
        written.join(", ")
    )?;
    if !out.summary.is_empty() {
        writeln!(err, "{}: {}", args.file, out.summary)?;
    }
    Ok(())
}
