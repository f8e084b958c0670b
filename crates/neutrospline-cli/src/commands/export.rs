//! `neutrospline export FILE -o OUT.dxf|.step|.glb|.gltf|.ply|.obj`: the model in the format of a CAD
//! or 3-D program, through `neutrospline-io`'s exporters.

use std::path::PathBuf;

use neutrospline_exchange::{ColorBy, ExportError, ExportFormat, ExportOptions};

use crate::commands::options::ModelArgs;
use crate::input::{self, UsageError};
use crate::output;

fn parse_color_by(text: &str) -> Result<ColorBy, String> {
    text.parse()
}

/// Arguments of `export`.
#[derive(Debug, clap::Args)]
#[command(after_help = "Formats (by the extension of OUT):\n  \
.dxf         DXF R2004: a curve as one exact SPLINE entity (degree, knots, control points,\n               \
weights; a Bezier curve as its clamped B-spline) with the control points' truth,\n               \
indeterminacy and falsity as extended data (application NEUTROSPLINE); a surface\n               \
only with --mesh, as a POLYFACE mesh whose vertices keep their degrees\n  \
.step, .stp  STEP AP214 (ISO 10303-21): the curve or surface as one exact B-spline (a surface\n               \
as a face bounded by its boundary curves); each control point named\n               \
'NAME T=truth I=indeterminacy F=falsity'; unit mm, fixed time stamp\n  \
.glb, .gltf  glTF 2.0 (binary, or JSON with the buffer embedded): a curve as a line strip, a\n               \
surface as triangles with normals; vertex colours and the attributes _TRUTH,\n               \
_INDETERMINACY, _FALSITY\n  \
.ply         PLY (binary little-endian, or --ascii): vertices with x y z, red green blue,\n               \
truth indeterminacy falsity; faces of a surface, edges of a curve\n  \
.obj         OBJ: v x y z r g b, lines of a curve, faces with normals of a surface; the degrees\n               \
in #deg comment lines, one per vertex\n\
Colours are the viridis map of --color-by (score: (2 + truth - indeterminacy - falsity) / 3).")]
pub struct ExportArgs {
    /// The model file: .csv, .toml or .json; `-` reads CSV from standard input
    #[arg(value_name = "FILE")]
    pub file: String,

    /// The file to write: OUT.dxf, OUT.step (or .stp), OUT.glb, OUT.gltf, OUT.ply or OUT.obj
    /// (replaced atomically)
    #[arg(short = 'o', long = "output", value_name = "OUT")]
    pub output: PathBuf,

    /// Points sampled along a curve, or per direction of a surface (N x N); default: as many
    /// as keep the polyline within 1e-3 of the bounding box's diagonal
    #[arg(long, value_name = "N")]
    pub samples: Option<usize>,

    /// What the vertex colours show: truth, indeterminacy, falsity or score
    #[arg(long, value_name = "VALUE", default_value = "truth", value_parser = parse_color_by)]
    pub color_by: ColorBy,

    /// DXF: write a surface as a POLYFACE mesh of its samples
    #[arg(long)]
    pub mesh: bool,

    /// PLY: write ASCII rather than binary little-endian
    #[arg(long)]
    pub ascii: bool,

    #[command(flatten)]
    pub model: ModelArgs,
}

/// Reads the model, exports it and writes the file.
///
/// # Errors
/// An unsupported output extension or an option that does not fit the format or the shape
/// (usage errors), an invalid model file, a surface exported to DXF without --mesh, or a write
/// error naming the file.
pub fn run(args: &ExportArgs) -> anyhow::Result<()> {
    let format = ExportFormat::from_path(&args.output)
        .map_err(|e| UsageError(e.describe(ExportFormat::ACCEPTED)))?;
    let options = ExportOptions::new()
        .with_samples(args.samples)
        .with_color_by(args.color_by)
        .with_mesh(args.mesh)
        .with_ascii(args.ascii);
    let model = input::read_model(&args.file, &args.model)?;
    let bytes = neutrospline_exchange::export(&model, format, &options).map_err(|e| match e {
        e if e.is_usage() => anyhow::Error::new(UsageError(e.to_string())),
        ExportError::SurfaceNeedsMesh { .. } => {
            anyhow::Error::msg(format!("{}: {e}", input::label(&args.file)))
        }
        e => anyhow::Error::msg(e.to_string()),
    })?;
    output::emit(Some(&args.output), |w| {
        w.write_all(&bytes)?;
        Ok(())
    })
}
