//! `neutrospline plot FILE -o OUT.svg|OUT.png --view VIEW`: a figure of a curve or surface.

use std::path::{Path, PathBuf};

use neutrospline_plot::{
    render_png, render_svg, DataOverlay, FigureRequest, PlotModel, PlotOptions, View,
};

use crate::commands::options::ModelArgs;
use crate::input::read_data;
use crate::input::{self, UsageError};
use crate::output;
use crate::request::RequestArgs;

/// The figure formats, chosen by the output file's extension.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FigureFormat {
    /// Scalable vector graphics (text stays text).
    Svg,
    /// A raster image, rendered with the bundled fonts.
    Png,
}

impl FigureFormat {
    /// The format of `path`, from its extension (case-insensitive).
    ///
    /// # Errors
    /// A usage error naming the accepted extensions.
    pub fn from_path(path: &Path) -> Result<FigureFormat, UsageError> {
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase);
        match ext.as_deref() {
            Some("svg") => Ok(FigureFormat::Svg),
            Some("png") => Ok(FigureFormat::Png),
            _ => Err(UsageError(format!(
                "{}: unsupported figure extension (accepted: .svg, .png)",
                path.display()
            ))),
        }
    }
}

/// Arguments of `plot`.
#[derive(Debug, clap::Args)]
#[command(after_help = "Views:\n  \
controls       the control points and polygon, each point with its truth, indeterminacy and\n                 \
falsity (paper Fig. 1)\n  \
truth          3-D axes x, y, truth: the space curve (x(t), y(t), truth(t)), its control\n                 \
polygon, and the crisp curve as its shadow (paper Fig. 2; 3-D models and surfaces:\n                 \
coloured by truth)\n  \
indeterminacy  the same for indeterminacy (paper Fig. 3)\n  \
falsity        the same for falsity (paper Fig. 4)\n  \
all            the three together (paper Fig. 5)\n  \
plane          the crisp curve with three bands along it whose widths follow the degrees\n  \
score          the space curve (x(t), y(t), score(t)) above the crisp curve, score =\n                 \
(2 + T - I - F) / 3 (3-D models and surfaces: coloured by the score)\n  \
data           the data points of --data coloured by a degree over the curve, with residual\n                 \
whiskers (curves only)\n  \
band           the fuzzy position (control point spreads): the regions swept by the\n                 \
alpha-cuts at alpha = 0, 0.5, 1 (or --alpha), lighter for lower alpha, the crisp curve\n                 \
on top, the centroid curve dashed (curves only; 3-D: the tube's silhouette)\n\
The format follows the extension of OUT: .svg or .png.")]
pub struct PlotArgs {
    /// The model file: .csv, .toml or .json; `-` reads CSV from standard input
    #[arg(value_name = "FILE")]
    pub file: String,

    /// The figure to write: OUT.svg or OUT.png (replaced atomically)
    #[arg(short = 'o', long = "output", value_name = "OUT")]
    pub output: PathBuf,

    /// Measured points (a CSV data file, as `neutrospline fit` reads) to draw over the curve in
    /// the data view, with whiskers to the curve at their `parameter` column, or to the
    /// nearest point of the curve without one
    #[arg(long, value_name = "DATA.csv")]
    pub data: Option<String>,

    /// The figure's options (defined by the plot crate's `FigureRequest`)
    #[command(flatten)]
    pub figure: RequestArgs<FigureRequest>,

    #[command(flatten)]
    pub model: ModelArgs,
}

/// Renders `model` as `format` and writes it atomically to `path`.
///
/// # Errors
/// A rendering error or a write error naming the file.
pub fn write_figure(
    model: &PlotModel,
    view: View,
    options: &PlotOptions,
    path: &Path,
    format: FigureFormat,
) -> anyhow::Result<()> {
    let bytes = match format {
        FigureFormat::Svg => render_svg(model, view, options)?.into_bytes(),
        FigureFormat::Png => render_png(model, view, options)?,
    };
    output::emit(Some(path), |w| {
        w.write_all(&bytes)?;
        Ok(())
    })
}

/// Reads the model, renders the view and writes the figure.
///
/// # Errors
/// An invalid file, an unsupported output extension or option (usage errors), a rendering
/// error or a write error.
pub fn run(args: &PlotArgs) -> anyhow::Result<()> {
    let format = FigureFormat::from_path(&args.output)?;
    let request = args.figure.request()?;
    let mut options = request
        .plot_options()
        .map_err(|e| UsageError(e.to_string()))?;
    let model = input::read_model(&args.file, &args.model)?;
    let membership = model.membership();
    let mut plot = PlotModel::from_model(&model)?;
    let description = model.description().map(str::to_owned);
    let shape = model.into_shape();
    if shape.is_surface() && request.samples.is_some() {
        options
            .validate_surface()
            .map_err(|e| UsageError(e.to_string()))?;
    }
    if let (None, Some(description)) = (&request.caption, description) {
        options = options.with_caption(description);
    }
    let view = request.view(args.data.is_some());
    match (&args.data, view) {
        (Some(file), View::Data) => {
            let table = read_data(file, membership, &args.model.table_input()?)?;
            if table.dimension() != shape.dimension() {
                return Err(anyhow::anyhow!(
                    "{}: the data is {}-D but the model is {}-D (give z for a 3-D curve, or \
                     none for a 2-D one)",
                    table.file(),
                    table.dimension(),
                    shape.dimension()
                ));
            }
            let overlay = DataOverlay::from_table(&table, request.color_by);
            plot = plot
                .with_data(overlay)
                .map_err(|e| anyhow::anyhow!("{}: {e}", table.file()))?;
        }
        (Some(_), other) => {
            return Err(UsageError(format!(
                "--data is drawn by the data view, not by --view {other} (give --view data or \
                 leave --view out)"
            ))
            .into())
        }
        (None, _) => {}
    }
    write_figure(&plot, view, &options, &args.output, format)
}
