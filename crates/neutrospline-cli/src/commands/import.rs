//! `neutrospline import IN.dxf|IN.svg -o MODEL.toml`: the curves of a DXF or SVG drawing as
//! model files, through `neutrospline-exchange`'s importers, with the import report on
//! standard error.

use std::path::{Path, PathBuf};

use neutrospline_exchange::{ImportRequest, SourceFormat};
use neutrospline_io::{Format, Model};

use crate::input::UsageError;
use crate::output;
use crate::request::RequestArgs;

/// The extensions `import` reads.
const ACCEPTED: &str = ".dxf, .svg";

/// Arguments of `import`.
#[derive(Debug, clap::Args)]
#[command(
    after_help = "DXF: every SPLINE, LINE, ARC, CIRCLE, ELLIPSE, LWPOLYLINE and POLYLINE of the \
ENTITIES section, and of the blocks its INSERTs draw, is a curve, exactly (splines as written; \
arcs, circles, ellipses and polyline bulges as rational quadratic NURBS). The degrees, kind, \
membership rule and names come from the extended data that `neutrospline export` writes \
(application NEUTROSPLINE); a curve without it takes --truth, --indeterminacy and --falsity \
for every control point. SVG: every drawn <path>, <polyline>, <polygon>, <line>, <rect>, \
<circle> and <ellipse> (with <use> clones, nested <svg> viewports and CSS transforms) is a \
curve in the root's user units. Standard error gets one line per file: what was imported, and \
what was skipped, hidden or not drawn, by kind; --strict refuses the file instead of skipping \
a drawn shape."
)]
pub struct ImportArgs {
    /// The file to read: IN.dxf or IN.svg
    #[arg(value_name = "IN")]
    pub input: PathBuf,

    /// The model to write: MODEL.toml, MODEL.json or MODEL.csv (replaced atomically); with
    /// --all, MODEL-1.toml, MODEL-2.toml, ...
    #[arg(short = 'o', long = "output", value_name = "MODEL")]
    pub output: PathBuf,

    /// The import's options, defined by the exchange library (`ImportRequest`).
    #[command(flatten)]
    pub request: RequestArgs<ImportRequest>,

    /// Which curve to write when the file holds several (1 is the first)
    #[arg(long, value_name = "K", conflicts_with = "all", value_parser = clap::value_parser!(u64).range(1..))]
    pub index: Option<u64>,

    /// Write every curve, each to its own file: MODEL-1.toml, MODEL-2.toml, ...
    #[arg(long)]
    pub all: bool,
}

/// `MODEL-k.ext` beside `MODEL.ext`.
pub(crate) fn numbered(path: &Path, k: usize) -> PathBuf {
    let stem = path
        .file_stem()
        .map(|s| s.to_string_lossy())
        .unwrap_or_default();
    let name = match path.extension() {
        Some(ext) => format!("{stem}-{k}.{}", ext.to_string_lossy()),
        None => format!("{stem}-{k}"),
    };
    path.with_file_name(name)
}

/// Reads the curves, chooses them and writes the model files.
///
/// # Errors
/// An unsupported extension, default degrees outside their rules, several curves without
/// --index or --all, an --index beyond them (usage errors); an invalid or unreadable file; a
/// write error naming the file.
pub fn run(args: &ImportArgs) -> anyhow::Result<()> {
    let extension = args
        .input
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase());
    if !matches!(extension.as_deref(), Some("dxf" | "svg")) {
        let shown = args.input.display();
        return Err(UsageError(match extension {
            Some(ext) => {
                format!("{shown}: unsupported file extension `.{ext}` (accepted: {ACCEPTED})")
            }
            None => format!("{shown}: the file name has no extension (accepted: {ACCEPTED})"),
        })
        .into());
    }
    let format =
        Format::from_path(&args.output).map_err(|e| UsageError(e.describe(Format::ACCEPTED)))?;
    let request = args.request.request()?;
    let source = if extension.as_deref() == Some("svg") {
        SourceFormat::Svg
    } else {
        SourceFormat::Dxf
    };
    let options = request
        .options(source)
        .map_err(|e| UsageError(e.to_string()))?;
    let limits = crate::limits::current().file_limits();
    let shown = args.input.display();
    // The messages name the file and the cause already: no error chain.
    let imported = match source {
        SourceFormat::Svg => neutrospline_exchange::load_svg(&args.input, &options, &limits),
        SourceFormat::Dxf => neutrospline_exchange::load_dxf(&args.input, &options, &limits),
    }
    .map_err(|e| anyhow::Error::msg(e.to_string()))?;
    // What was read and what was left, before anything is chosen or written.
    eprintln!("{shown}: {}", imported.report.summary());
    let imported = if request.strict {
        imported
            .strict(&shown.to_string())
            .map_err(|e| anyhow::Error::msg(e.to_string()))?
    } else {
        imported
    };
    let models = imported.models;
    let chosen: Vec<(PathBuf, &Model)> = match (args.index, args.all) {
        (_, true) => models
            .iter()
            .enumerate()
            .map(|(k, m)| (numbered(&args.output, k + 1), m))
            .collect(),
        (Some(k), false) => {
            let k = usize::try_from(k).unwrap_or(usize::MAX);
            let model = models.get(k - 1).ok_or_else(|| {
                UsageError(format!(
                    "--index {k}: {shown} holds {} curve{} (give 1 to {})",
                    models.len(),
                    if models.len() == 1 { "" } else { "s" },
                    models.len()
                ))
            })?;
            vec![(args.output.clone(), model)]
        }
        (None, false) if models.len() == 1 => vec![(args.output.clone(), &models[0])],
        (None, false) => {
            return Err(UsageError(format!(
                "{shown} holds {} curves: choose one with --index K (1 to {}) or write each to \
                 its own file with --all",
                models.len(),
                models.len()
            ))
            .into())
        }
    };
    // Every text first, so that a model the format cannot hold writes no file at all.
    let texts = chosen
        .iter()
        .map(|(path, model)| {
            neutrospline_io::to_string(model, format)
                .map(|text| (path, text))
                .map_err(|e| anyhow::Error::msg(format!("{}: {e}", path.display())))
        })
        .collect::<anyhow::Result<Vec<_>>>()?;
    for (path, text) in texts {
        output::emit(Some(path), |w| {
            w.write_all(text.as_bytes())?;
            Ok(())
        })?;
    }
    Ok(())
}
